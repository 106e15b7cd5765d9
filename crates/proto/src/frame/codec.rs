//! One frame to bytes and back: the `kind u8 | body_len varint` head every frame starts
//! with, and the hand-off of each body to the file of its family (`link`, `topics`,
//! `message`, `reports`, `calls`). Also the iterator over the frames packed in one
//! WebSocket message.

use bytes::{BufMut, Bytes, BytesMut};

use super::shared::put_frame_head;
use super::types::Frame;
use super::{calls, link, message, reports, topics};
use crate::error::{DecodeError, ErrorKind};
use crate::wire::Reader;

impl Frame {
    /// Appends this frame to `buf`.
    pub fn encode(&self, buf: &mut BytesMut) {
        let mut body = BytesMut::new();
        self.encode_body(&mut body);
        put_frame_head(buf, self.kind_byte(), body.len());
        buf.put_slice(&body);
    }

    /// This frame alone, as the bytes of one WebSocket message.
    pub fn to_bytes(&self) -> Bytes {
        let mut b = BytesMut::new();
        self.encode(&mut b);
        b.freeze()
    }

    fn encode_body(&self, b: &mut BytesMut) {
        match self {
            Frame::Hello { .. }
            | Frame::Welcome { .. }
            | Frame::Ping { .. }
            | Frame::Pong { .. }
            | Frame::Ack { .. }
            | Frame::Status { .. }
            | Frame::Share { .. }
            | Frame::LinkReport { .. } => link::encode_body(self, b),
            Frame::Advertise { .. }
            | Frame::Unadvertise { .. }
            | Frame::Subscribe { .. }
            | Frame::Unsubscribe { .. }
            | Frame::Delivered { .. }
            | Frame::Interest { .. }
            | Frame::Pull { .. }
            | Frame::Via { .. } => topics::encode_body(self, b),
            Frame::Message {
                alias,
                seq,
                stamp_ns,
                payload,
            }
            | Frame::ZMessage {
                alias,
                seq,
                stamp_ns,
                payload,
            } => message::put_message_body(b, *alias, *seq, *stamp_ns, payload),
            Frame::Chunk {
                alias,
                seq,
                stamp_ns,
                total_len,
                offset,
                data,
            }
            | Frame::ZChunk {
                alias,
                seq,
                stamp_ns,
                total_len,
                offset,
                data,
            } => message::put_chunk_body(b, *alias, *seq, *stamp_ns, *total_len, *offset, data),
            Frame::Budget {
                max_bps,
                day_bytes,
                used_bytes,
                thinned,
            } => reports::put_budget(b, *max_bps, *day_bytes, *used_bytes, thinned),
            Frame::TopicDrops { topics } => reports::put_topic_drops(b, topics),
            Frame::TopicLoad { topics } => reports::put_topic_load(b, topics),
            Frame::ServiceAdvertise { .. }
            | Frame::ServiceUnadvertise { .. }
            | Frame::Call { .. }
            | Frame::Goal { .. }
            | Frame::Reply { .. }
            | Frame::Feedback { .. }
            | Frame::Cancel { .. }
            | Frame::CallChunk { .. } => calls::encode_body(self, b),
            Frame::Unknown { .. } => {}
        }
    }

    /// Decodes the frame starting at `pos` in `buf`; returns it and where the next frame
    /// starts. Payload bytes are shared slices of `buf`.
    pub fn decode(buf: &Bytes, pos: usize) -> Result<(Frame, usize), DecodeError> {
        if pos > buf.len() {
            return Err(DecodeError::incomplete(
                "frame.kind",
                pos - buf.len() + 1,
                0,
            ));
        }
        let mut head = Reader::sub(buf, pos, buf.len() - pos);
        let kind = head.u8("frame.kind")?;
        let len = head.len_prefix("frame.body_len")?;
        let start = head.position();
        let mut r = Reader::sub(buf, start, len);
        // The body is complete (its length was checked above), so a field running past
        // its end can never be fixed by more bytes: that is invalid, not incomplete.
        let frame = decode_body(kind, &mut r).map_err(|e| match e.kind {
            ErrorKind::Incomplete => DecodeError::invalid(
                e.context,
                format!(
                    "field runs past the end of a {len}-byte body ({})",
                    e.reason
                ),
            ),
            ErrorKind::Invalid => e,
        })?;
        Ok((frame, start + len))
    }
}

/// Decodes the body of a frame of kind `kind`; a kind no family knows is skipped.
fn decode_body(kind: u8, r: &mut Reader<'_>) -> Result<Frame, DecodeError> {
    match kind {
        0x01 | 0x02 | 0x09..=0x0e => link::decode_body(kind, r),
        0x03..=0x06 | 0x0f | 0x18 | 0x19 | 0x1f => topics::decode_body(kind, r),
        0x07 => message::read_message(r, false),
        0x08 => message::read_chunk(r, false),
        0x1a => message::read_message(r, true),
        0x1b => message::read_chunk(r, true),
        0x10..=0x17 => calls::decode_body(kind, r),
        0x1c => reports::read_budget(r),
        0x1d => reports::read_topic_drops(r),
        0x1e => reports::read_topic_load(r),
        other => Ok(Frame::Unknown { kind: other }),
    }
}

/// Iterates over the frames packed in one WebSocket message. Stops at the first error.
pub fn frames(buf: &Bytes) -> Frames<'_> {
    Frames {
        buf,
        pos: 0,
        failed: false,
    }
}

pub struct Frames<'a> {
    buf: &'a Bytes,
    pos: usize,
    failed: bool,
}

impl Iterator for Frames<'_> {
    type Item = Result<Frame, DecodeError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.failed || self.pos >= self.buf.len() {
            return None;
        }
        match Frame::decode(self.buf, self.pos) {
            Ok((frame, next)) => {
                self.pos = next;
                Some(Ok(frame))
            }
            Err(e) => {
                self.failed = true;
                Some(Err(e))
            }
        }
    }
}
