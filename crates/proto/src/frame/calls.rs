//! The service and action frames (`0x10`–`0x17`): writing and reading their bodies, and
//! cutting a large call body into `CALL_CHUNK` frames.
//!
//! A large body's pieces travel *before* the frame they belong to, which carries the last
//! piece. Unlike a topic's `CHUNK`s, whose last piece completes the message, a call body
//! is then complete exactly when its `CALL`/`GOAL`/`REPLY`/`FEEDBACK` frame arrives: the
//! receiver handles one frame per body, whether or not the body was cut, and the header
//! fields (alias, deadline, status, encoding) are read in one place.

use bytes::{BufMut, Bytes};

use super::shared::{check_piece_fits, read_encoding};
use super::types::{CallStatus, Frame, FrameKind};
use crate::error::DecodeError;
use crate::payload::Schema;
use crate::wire::{Reader, put_str, put_varint};

/// Whether `kind` is a frame whose body may be cut into `CALL_CHUNK`s.
fn is_body_kind(kind: u8) -> bool {
    [
        FrameKind::Call,
        FrameKind::Goal,
        FrameKind::Reply,
        FrameKind::Feedback,
    ]
    .iter()
    .any(|k| *k as u8 == kind)
}

/// Writes the body of a service or action frame. The codec sends only those frames here.
pub(super) fn encode_body(frame: &Frame, b: &mut impl BufMut) {
    match frame {
        Frame::ServiceAdvertise {
            alias,
            name,
            schema,
            flags,
        } => {
            put_varint(b, u64::from(*alias));
            put_str(b, name);
            put_str(b, &schema.type_name);
            put_str(b, &schema.encoding);
            put_str(b, &schema.text);
            b.put_u8(*flags);
        }
        Frame::ServiceUnadvertise { alias } => put_varint(b, u64::from(*alias)),
        Frame::Call {
            call_id,
            alias,
            deadline_ms,
            encoding,
            payload,
        } => {
            put_varint(b, *call_id);
            put_varint(b, u64::from(*alias));
            put_varint(b, *deadline_ms);
            b.put_u8(*encoding as u8);
            b.put_slice(payload);
        }
        Frame::Goal {
            call_id,
            alias,
            deadline_ms,
            goal_id,
            encoding,
            payload,
        } => {
            put_varint(b, *call_id);
            put_varint(b, u64::from(*alias));
            put_varint(b, *deadline_ms);
            b.put_slice(goal_id);
            b.put_u8(*encoding as u8);
            b.put_slice(payload);
        }
        Frame::Reply {
            call_id,
            status,
            encoding,
            payload,
        } => {
            put_varint(b, *call_id);
            b.put_u8(*status as u8);
            b.put_u8(*encoding as u8);
            b.put_slice(payload);
        }
        Frame::Feedback {
            call_id,
            encoding,
            payload,
        } => {
            put_varint(b, *call_id);
            b.put_u8(*encoding as u8);
            b.put_slice(payload);
        }
        Frame::Cancel { call_id } => put_varint(b, *call_id),
        Frame::CallChunk {
            call_id,
            kind,
            total_len,
            offset,
            data,
        } => {
            put_varint(b, *call_id);
            b.put_u8(*kind);
            put_varint(b, *total_len);
            put_varint(b, *offset);
            b.put_slice(data);
        }
        other => unreachable!("{other:?} is not a service or action frame"),
    }
}

/// Decodes the body of a frame of kind `0x10`–`0x17`.
pub(super) fn decode_body(kind: u8, r: &mut Reader<'_>) -> Result<Frame, DecodeError> {
    let frame = match kind {
        0x10 => Frame::ServiceAdvertise {
            alias: r.varint_u32("SERVICE_ADVERTISE.alias")?,
            name: r.string("SERVICE_ADVERTISE.name")?,
            schema: Schema {
                type_name: r.string("SERVICE_ADVERTISE.type")?,
                encoding: r.string("SERVICE_ADVERTISE.schema_encoding")?,
                text: r.string("SERVICE_ADVERTISE.schema_text")?,
            },
            flags: r.u8("SERVICE_ADVERTISE.flags")?,
        },
        0x11 => Frame::ServiceUnadvertise {
            alias: r.varint_u32("SERVICE_UNADVERTISE.alias")?,
        },
        0x12 => Frame::Call {
            call_id: r.varint("CALL.call_id")?,
            alias: r.varint_u32("CALL.alias")?,
            deadline_ms: r.varint("CALL.deadline_ms")?,
            encoding: read_encoding(r, "CALL.encoding")?,
            payload: r.rest(),
        },
        0x13 => Frame::Goal {
            call_id: r.varint("GOAL.call_id")?,
            alias: r.varint_u32("GOAL.alias")?,
            deadline_ms: r.varint("GOAL.deadline_ms")?,
            goal_id: {
                let mut id = [0u8; 16];
                id.copy_from_slice(r.take(16, "GOAL.goal_id")?);
                id
            },
            encoding: read_encoding(r, "GOAL.encoding")?,
            payload: r.rest(),
        },
        0x14 => Frame::Reply {
            call_id: r.varint("REPLY.call_id")?,
            status: CallStatus::from_u8(r.u8("REPLY.status")?),
            encoding: read_encoding(r, "REPLY.encoding")?,
            payload: r.rest(),
        },
        0x15 => Frame::Feedback {
            call_id: r.varint("FEEDBACK.call_id")?,
            encoding: read_encoding(r, "FEEDBACK.encoding")?,
            payload: r.rest(),
        },
        0x16 => Frame::Cancel {
            call_id: r.varint("CANCEL.call_id")?,
        },
        0x17 => {
            let call_id = r.varint("CALL_CHUNK.call_id")?;
            let kind = r.u8("CALL_CHUNK.kind")?;
            if !is_body_kind(kind) {
                return Err(DecodeError::invalid(
                    "CALL_CHUNK.kind",
                    format!("kind {kind:#04x} is not CALL, GOAL, REPLY or FEEDBACK"),
                ));
            }
            let total_len = r.varint("CALL_CHUNK.total_len")?;
            let offset = r.varint("CALL_CHUNK.offset")?;
            let data = r.rest();
            check_piece_fits(total_len, offset, &data, "CALL_CHUNK.offset")?;
            Frame::CallChunk {
                call_id,
                kind,
                total_len,
                offset,
                data,
            }
        }
        other => Frame::Unknown { kind: other },
    };
    Ok(frame)
}

/// Cuts the body of a `kind` frame (`Call`, `Goal`, `Reply` or `Feedback`) of call
/// `call_id` into pieces of at most `chunk_size` bytes. Returns the `CALL_CHUNK` frames to
/// send first, in order, and the last piece, which becomes the payload of the `kind` frame
/// sent after them. A body that fits in one piece comes back whole, with no chunks. The
/// pieces share `payload`'s storage.
pub fn split_call_body(
    call_id: u64,
    kind: FrameKind,
    payload: &Bytes,
    chunk_size: usize,
) -> (Vec<Frame>, Bytes) {
    debug_assert!(
        is_body_kind(kind as u8),
        "{kind:?} frames carry no call body"
    );
    let step = chunk_size.max(1);
    let total = payload.len();
    if total <= step {
        return (Vec::new(), payload.clone());
    }
    // The last piece is the final 1..=step bytes, so the header frame never goes empty
    // while chunks precede it.
    let last_start = (total - 1) / step * step;
    let chunks = (0..last_start)
        .step_by(step)
        .map(|start| Frame::CallChunk {
            call_id,
            kind: kind as u8,
            total_len: total as u64,
            offset: start as u64,
            data: payload.slice(start..start + step),
        })
        .collect();
    (chunks, payload.slice(last_start..))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn status_bytes_round_trip_and_unknown_reads_as_failed() {
        for v in 0..=7u8 {
            assert_eq!(CallStatus::from_u8(v) as u8, v);
        }
        assert_eq!(CallStatus::from_u8(8), CallStatus::Failed);
        assert_eq!(CallStatus::from_u8(255), CallStatus::Failed);
        assert_eq!(CallStatus::NoProvider.as_str(), "no_provider");
    }

    #[test]
    fn a_small_body_is_not_cut() {
        let body = Bytes::from(vec![1; 100]);
        let (chunks, last) = split_call_body(1, FrameKind::Call, &body, 100);
        assert!(chunks.is_empty());
        assert_eq!(last.as_ptr(), body.as_ptr());
        assert_eq!(last.len(), 100);
        let (chunks, last) = split_call_body(1, FrameKind::Reply, &Bytes::new(), 100);
        assert!(chunks.is_empty() && last.is_empty());
    }

    #[test]
    fn pieces_cover_the_body_in_order_and_share_its_storage() {
        let body = Bytes::from((0..250u32).map(|i| i as u8).collect::<Vec<_>>());
        let (chunks, last) = split_call_body(9, FrameKind::Feedback, &body, 100);
        let mut offsets = Vec::new();
        for (i, f) in chunks.iter().enumerate() {
            let Frame::CallChunk {
                call_id,
                kind,
                total_len,
                offset,
                data,
            } = f
            else {
                panic!("not a CALL_CHUNK: {f:?}");
            };
            assert_eq!((*call_id, *kind, *total_len), (9, 0x15, 250));
            assert_eq!(data.as_ptr(), body[i * 100..].as_ptr());
            assert_eq!(&data[..], &body[i * 100..i * 100 + 100]);
            offsets.push(*offset);
        }
        assert_eq!(offsets, [0, 100]);
        assert_eq!(&last[..], &body[200..]);
    }

    #[test]
    fn a_body_of_whole_pieces_keeps_a_full_last_piece() {
        let body = Bytes::from(vec![3; 300]);
        let (chunks, last) = split_call_body(1, FrameKind::Goal, &body, 100);
        assert_eq!((chunks.len(), last.len()), (2, 100));
    }
}
