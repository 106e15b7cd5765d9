//! Pieces of the frame layout that more than one family of frames uses: the kind and
//! length every frame starts with, the payload encoding byte, and the check that a piece
//! of a cut body lies inside the whole.

use bytes::{BufMut, BytesMut};

use crate::error::DecodeError;
use crate::payload::Encoding;
use crate::wire::{Reader, put_varint, varint_len};

/// Writes a frame's `kind u8 | body_len varint`, with room reserved for the body after it.
pub(super) fn put_frame_head(buf: &mut BytesMut, kind: u8, body_len: usize) {
    buf.reserve(1 + varint_len(body_len as u64) + body_len);
    buf.put_u8(kind);
    put_varint(buf, body_len as u64);
}

/// Reads a payload encoding byte. An unknown value is invalid rather than skipped: the
/// receiver could not interpret the payloads it describes.
pub(super) fn read_encoding(
    r: &mut Reader<'_>,
    ctx: &'static str,
) -> Result<Encoding, DecodeError> {
    let enc = r.u8(ctx)?;
    Encoding::from_u8(enc)
        .ok_or_else(|| DecodeError::invalid(ctx, format!("unknown encoding {enc}")))
}

/// Checks that a piece of `data` at `offset` lies inside a body of `total_len` bytes,
/// without overflowing: a reassembler can then trust the numbers it is given.
pub(super) fn check_piece_fits(
    total_len: u64,
    offset: u64,
    data: &[u8],
    ctx: &'static str,
) -> Result<(), DecodeError> {
    if offset
        .checked_add(data.len() as u64)
        .is_none_or(|end| end > total_len)
    {
        return Err(DecodeError::invalid(
            ctx,
            format!(
                "{} bytes at offset {offset} overrun total length {total_len}",
                data.len()
            ),
        ));
    }
    Ok(())
}
