//! The frames that carry a topic's messages. `MESSAGE` and `ZMESSAGE` have one layout, and
//! so have `CHUNK` and `ZCHUNK`: a message's head (alias, seq, stamp), for a piece its
//! place in the whole, then the bytes. Each layout is written by one function and read by
//! one function here, told only whether the frame is the compressed twin, so the plain
//! and compressed frames cannot drift apart on the wire.
//!
//! Also here: writing these frames straight from borrowed bytes (the send path's shortcut
//! past building a [`Frame`]), and cutting a payload into `CHUNK`s.

use bytes::{BufMut, Bytes, BytesMut};

use super::shared::{check_piece_fits, put_frame_head};
use super::types::{Frame, FrameKind};
use crate::error::DecodeError;
use crate::wire::{Reader, put_varint, varint_len};

/// Writes a `MESSAGE` (or `ZMESSAGE`) body: `alias varint | seq varint | stamp_ns u64le |
/// payload (rest)`.
pub(super) fn put_message_body(
    b: &mut impl BufMut,
    alias: u32,
    seq: u64,
    stamp_ns: u64,
    payload: &[u8],
) {
    put_head(b, alias, seq, stamp_ns);
    b.put_slice(payload);
}

/// Writes a `CHUNK` (or `ZCHUNK`) body: the head of [`put_message_body`], then
/// `total_len varint | offset varint | data (rest)`.
pub(super) fn put_chunk_body(
    b: &mut impl BufMut,
    alias: u32,
    seq: u64,
    stamp_ns: u64,
    total_len: u64,
    offset: u64,
    data: &[u8],
) {
    put_head(b, alias, seq, stamp_ns);
    put_varint(b, total_len);
    put_varint(b, offset);
    b.put_slice(data);
}

/// Writes the fields `MESSAGE` and `CHUNK` start with.
fn put_head(b: &mut impl BufMut, alias: u32, seq: u64, stamp_ns: u64) {
    put_varint(b, u64::from(alias));
    put_varint(b, seq);
    b.put_u64_le(stamp_ns);
}

/// The encoded size of the fields [`put_head`] writes.
fn head_len(alias: u32, seq: u64) -> usize {
    varint_len(u64::from(alias)) + varint_len(seq) + 8
}

/// Appends a `MESSAGE` frame whose payload is `payload`, copying it once into `buf`.
/// Same bytes as `Frame::Message{..}.encode` without building the frame first.
pub fn encode_message(buf: &mut BytesMut, alias: u32, seq: u64, stamp_ns: u64, payload: &[u8]) {
    encode_message_kind(buf, false, alias, seq, stamp_ns, payload);
}

/// [`encode_message`], or `ZMESSAGE` when `compressed` (`payload` is then an envelope).
pub fn encode_message_kind(
    buf: &mut BytesMut,
    compressed: bool,
    alias: u32,
    seq: u64,
    stamp_ns: u64,
    payload: &[u8],
) {
    let kind = if compressed {
        FrameKind::ZMessage
    } else {
        FrameKind::Message
    };
    put_frame_head(buf, kind as u8, head_len(alias, seq) + payload.len());
    put_message_body(buf, alias, seq, stamp_ns, payload);
}

/// Appends a `CHUNK` frame carrying `data`, which starts at `offset` of a message of
/// `total_len` bytes (`ZCHUNK` when `compressed`: the message is an envelope).
#[allow(clippy::too_many_arguments)]
pub fn encode_chunk(
    buf: &mut BytesMut,
    compressed: bool,
    alias: u32,
    seq: u64,
    stamp_ns: u64,
    total_len: u64,
    offset: u64,
    data: &[u8],
) {
    let kind = if compressed {
        FrameKind::ZChunk
    } else {
        FrameKind::Chunk
    };
    let body_len = head_len(alias, seq) + varint_len(total_len) + varint_len(offset) + data.len();
    put_frame_head(buf, kind as u8, body_len);
    put_chunk_body(buf, alias, seq, stamp_ns, total_len, offset, data);
}

/// Splits `payload` into `CHUNK` frames of at most `chunk_size` data bytes each. The
/// pieces share `payload`'s storage.
pub fn chunk_frames(
    alias: u32,
    seq: u64,
    stamp_ns: u64,
    payload: &Bytes,
    chunk_size: usize,
) -> impl Iterator<Item = Frame> + '_ {
    let total = payload.len();
    let step = chunk_size.max(1);
    (0..total.div_ceil(step)).map(move |i| {
        let start = i * step;
        let end = (start + step).min(total);
        Frame::Chunk {
            alias,
            seq,
            stamp_ns,
            total_len: total as u64,
            offset: start as u64,
            data: payload.slice(start..end),
        }
    })
}

/// The names a decoding error gives a message's fields, so an error says which of the
/// two frames sharing a layout it was reading.
struct HeadFields {
    alias: &'static str,
    seq: &'static str,
    stamp_ns: &'static str,
}

struct ChunkFields {
    head: HeadFields,
    total_len: &'static str,
    offset: &'static str,
}

const MESSAGE_FIELDS: HeadFields = HeadFields {
    alias: "MESSAGE.alias",
    seq: "MESSAGE.seq",
    stamp_ns: "MESSAGE.stamp_ns",
};
const ZMESSAGE_FIELDS: HeadFields = HeadFields {
    alias: "ZMESSAGE.alias",
    seq: "ZMESSAGE.seq",
    stamp_ns: "ZMESSAGE.stamp_ns",
};
const CHUNK_FIELDS: ChunkFields = ChunkFields {
    head: HeadFields {
        alias: "CHUNK.alias",
        seq: "CHUNK.seq",
        stamp_ns: "CHUNK.stamp_ns",
    },
    total_len: "CHUNK.total_len",
    offset: "CHUNK.offset",
};
const ZCHUNK_FIELDS: ChunkFields = ChunkFields {
    head: HeadFields {
        alias: "ZCHUNK.alias",
        seq: "ZCHUNK.seq",
        stamp_ns: "ZCHUNK.stamp_ns",
    },
    total_len: "ZCHUNK.total_len",
    offset: "ZCHUNK.offset",
};

/// Reads the fields [`put_head`] writes: alias, seq and stamp.
fn read_head(r: &mut Reader<'_>, f: &HeadFields) -> Result<(u32, u64, u64), DecodeError> {
    Ok((
        r.varint_u32(f.alias)?,
        r.varint(f.seq)?,
        r.u64_le(f.stamp_ns)?,
    ))
}

/// Reads a `MESSAGE` body, or a `ZMESSAGE` body when `compressed`.
pub(super) fn read_message(r: &mut Reader<'_>, compressed: bool) -> Result<Frame, DecodeError> {
    let f = if compressed {
        &ZMESSAGE_FIELDS
    } else {
        &MESSAGE_FIELDS
    };
    let (alias, seq, stamp_ns) = read_head(r, f)?;
    let payload = r.rest();
    Ok(if compressed {
        Frame::ZMessage {
            alias,
            seq,
            stamp_ns,
            payload,
        }
    } else {
        Frame::Message {
            alias,
            seq,
            stamp_ns,
            payload,
        }
    })
}

/// Reads a `CHUNK` body, or a `ZCHUNK` body when `compressed`, its piece checked to lie
/// inside the whole.
pub(super) fn read_chunk(r: &mut Reader<'_>, compressed: bool) -> Result<Frame, DecodeError> {
    let f = if compressed {
        &ZCHUNK_FIELDS
    } else {
        &CHUNK_FIELDS
    };
    let (alias, seq, stamp_ns) = read_head(r, &f.head)?;
    let total_len = r.varint(f.total_len)?;
    let offset = r.varint(f.offset)?;
    let data = r.rest();
    check_piece_fits(total_len, offset, &data, f.offset)?;
    Ok(if compressed {
        Frame::ZChunk {
            alias,
            seq,
            stamp_ns,
            total_len,
            offset,
            data,
        }
    } else {
        Frame::Chunk {
            alias,
            seq,
            stamp_ns,
            total_len,
            offset,
            data,
        }
    })
}
