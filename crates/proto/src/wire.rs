//! Primitives of the `fleetlink.v1` encoding.
//!
//! Integers that are usually small (aliases, sequence numbers, lengths) are unsigned
//! LEB128 varints; timestamps are fixed 8-byte little-endian so they can be patched in
//! place. Strings and byte runs are a varint length followed by the bytes. The reader
//! never allocates on behalf of a length prefix: a length is checked against the bytes
//! actually present before anything is sliced.

use bytes::{BufMut, Bytes};

use crate::error::DecodeError;

/// The longest varint we accept: 10 bytes hold any `u64`.
const MAX_VARINT_LEN: usize = 10;

pub fn put_varint(buf: &mut impl BufMut, mut v: u64) {
    while v >= 0x80 {
        buf.put_u8((v as u8) | 0x80);
        v >>= 7;
    }
    buf.put_u8(v as u8);
}

/// Encoded size of `v` as a varint.
pub fn varint_len(v: u64) -> usize {
    let bits = 64 - (v | 1).leading_zeros() as usize;
    bits.div_ceil(7)
}

pub fn put_str(buf: &mut impl BufMut, s: &str) {
    put_bytes(buf, s.as_bytes());
}

pub fn put_bytes(buf: &mut impl BufMut, b: &[u8]) {
    put_varint(buf, b.len() as u64);
    buf.put_slice(b);
}

/// A bounds-checked cursor over one received buffer. Slices it hands out share the
/// buffer's storage ([`Bytes::slice`]), so payloads are never copied while decoding.
pub struct Reader<'a> {
    buf: &'a Bytes,
    pos: usize,
    end: usize,
}

impl<'a> Reader<'a> {
    pub fn new(buf: &'a Bytes) -> Self {
        Reader {
            buf,
            pos: 0,
            end: buf.len(),
        }
    }

    /// A reader limited to `pos..pos+len` of the same buffer.
    pub fn sub(buf: &'a Bytes, pos: usize, len: usize) -> Self {
        Reader {
            buf,
            pos,
            end: pos + len,
        }
    }

    pub fn position(&self) -> usize {
        self.pos
    }

    pub fn remaining(&self) -> usize {
        self.end - self.pos
    }

    pub fn is_empty(&self) -> bool {
        self.pos >= self.end
    }

    pub fn u8(&mut self, ctx: &'static str) -> Result<u8, DecodeError> {
        if self.pos >= self.end {
            return Err(DecodeError::incomplete(ctx, 1, 0));
        }
        let b = self.buf[self.pos];
        self.pos += 1;
        Ok(b)
    }

    pub fn u64_le(&mut self, ctx: &'static str) -> Result<u64, DecodeError> {
        let raw = self.take(8, ctx)?;
        let mut a = [0u8; 8];
        a.copy_from_slice(raw);
        Ok(u64::from_le_bytes(a))
    }

    pub fn varint(&mut self, ctx: &'static str) -> Result<u64, DecodeError> {
        let mut v: u64 = 0;
        for i in 0..MAX_VARINT_LEN {
            let b = self.u8(ctx)?;
            let part = u64::from(b & 0x7f);
            if i == MAX_VARINT_LEN - 1 && part > 1 {
                return Err(DecodeError::invalid(ctx, "varint overflows 64 bits"));
            }
            v |= part << (7 * i);
            if b & 0x80 == 0 {
                return Ok(v);
            }
        }
        Err(DecodeError::invalid(ctx, "varint longer than 10 bytes"))
    }

    /// A varint that must fit in `u32` (aliases, subscription ids).
    pub fn varint_u32(&mut self, ctx: &'static str) -> Result<u32, DecodeError> {
        let v = self.varint(ctx)?;
        u32::try_from(v)
            .map_err(|_| DecodeError::invalid(ctx, format!("{v} does not fit in 32 bits")))
    }

    /// A length prefix, checked against what is left in this reader.
    pub fn len_prefix(&mut self, ctx: &'static str) -> Result<usize, DecodeError> {
        let v = self.varint(ctx)?;
        let have = self.remaining();
        if v > have as u64 {
            return Err(DecodeError::incomplete(
                ctx,
                (v - have as u64).min(usize::MAX as u64) as usize,
                have,
            ));
        }
        Ok(v as usize)
    }

    pub fn take(&mut self, n: usize, ctx: &'static str) -> Result<&'a [u8], DecodeError> {
        if n > self.remaining() {
            return Err(DecodeError::incomplete(
                ctx,
                n - self.remaining(),
                self.remaining(),
            ));
        }
        let s = &self.buf[self.pos..self.pos + n];
        self.pos += n;
        Ok(s)
    }

    /// `n` bytes as a shared slice of the buffer (no copy).
    pub fn take_bytes(&mut self, n: usize, ctx: &'static str) -> Result<Bytes, DecodeError> {
        if n > self.remaining() {
            return Err(DecodeError::incomplete(
                ctx,
                n - self.remaining(),
                self.remaining(),
            ));
        }
        let b = self.buf.slice(self.pos..self.pos + n);
        self.pos += n;
        Ok(b)
    }

    /// Everything left, shared.
    pub fn rest(&mut self) -> Bytes {
        let b = self.buf.slice(self.pos..self.end);
        self.pos = self.end;
        b
    }

    pub fn bytes(&mut self, ctx: &'static str) -> Result<Bytes, DecodeError> {
        let n = self.len_prefix(ctx)?;
        self.take_bytes(n, ctx)
    }

    pub fn string(&mut self, ctx: &'static str) -> Result<String, DecodeError> {
        let n = self.len_prefix(ctx)?;
        let raw = self.take(n, ctx)?;
        std::str::from_utf8(raw)
            .map(str::to_owned)
            .map_err(|e| DecodeError::invalid(ctx, format!("not UTF-8: {e}")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use bytes::BytesMut;

    #[test]
    fn varint_round_trips_edges() {
        for v in [0u64, 1, 127, 128, 300, u32::MAX as u64, u64::MAX] {
            let mut b = BytesMut::new();
            put_varint(&mut b, v);
            assert_eq!(b.len(), varint_len(v), "length of {v}");
            let bytes = b.freeze();
            let mut r = Reader::new(&bytes);
            assert_eq!(r.varint("v").unwrap(), v);
            assert!(r.is_empty());
        }
    }

    #[test]
    fn varint_overflow_is_invalid_not_incomplete() {
        let bytes = Bytes::from_static(&[0xff; 11]);
        let err = Reader::new(&bytes).varint("v").unwrap_err();
        assert_eq!(err.kind, crate::ErrorKind::Invalid);
    }

    #[test]
    fn huge_length_prefix_is_rejected_without_allocating() {
        let mut b = BytesMut::new();
        put_varint(&mut b, 1 << 40);
        b.extend_from_slice(b"abc");
        let bytes = b.freeze();
        let err = Reader::new(&bytes).string("s").unwrap_err();
        assert!(err.is_incomplete());
    }
}
