//! The envelope of a compressed message on a `fleetlink.v1` link: the payload of a
//! `ZMESSAGE`, or what a run of `ZCHUNK`s reassembles to (a message that does not pay to
//! compress goes as a plain `MESSAGE`/`CHUNK`, its bytes untouched):
//!
//! ```text
//! codec u8 | raw_len varint | compressed (rest)
//! ```
//!
//! codec 1 is an LZ4 block, 2 a zstd frame; `raw_len` is the payload's size before compression,
//! which the receiver checks against its message size limit before it decompresses a
//! byte. The sender decides per message; the receiver decompresses once, before fan-out.

use bytes::{BufMut, Bytes, BytesMut};

use crate::error::DecodeError;
use crate::wire::{Reader, put_varint, varint_len};

/// How one message in an envelope is compressed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum Codec {
    /// An LZ4 block (no frame header; `raw_len` gives the size).
    Lz4 = 1,
    /// A zstd frame.
    Zstd = 2,
}

impl Codec {
    pub fn from_u8(v: u8) -> Option<Codec> {
        match v {
            1 => Some(Codec::Lz4),
            2 => Some(Codec::Zstd),
            _ => None,
        }
    }

    pub fn as_str(self) -> &'static str {
        match self {
            Codec::Lz4 => "lz4",
            Codec::Zstd => "zstd",
        }
    }
}

/// zstd's level for `compression: zstd` (its own default) ...
pub const ZSTD_LEVEL: i32 = 3;
/// ... and for `auto`, which compresses everything that pays and must stay cheap on a
/// robot's CPU.
pub const ZSTD_AUTO_LEVEL: i32 = 1;

/// `raw` compressed with `codec` (zstd at `level`) in an envelope; `None` when the
/// envelope would not be smaller than `raw` (the caller then sends `raw` as it is).
pub fn compress(codec: Codec, raw: &[u8], level: i32) -> Option<Bytes> {
    let head = 1 + varint_len(raw.len() as u64);
    let mut b = BytesMut::new();
    match codec {
        Codec::Lz4 => {
            let bound = lz4_flex::block::get_maximum_output_size(raw.len());
            b.resize(head + bound, 0);
            let n = lz4_flex::block::compress_into(raw, &mut b[head..]).ok()?;
            b.truncate(head + n);
        }
        Codec::Zstd => {
            let bound = zstd::zstd_safe::compress_bound(raw.len());
            b.resize(head + bound, 0);
            let n = zstd::bulk::compress_to_buffer(raw, &mut b[head..], level).ok()?;
            b.truncate(head + n);
        }
    }
    if b.len() >= raw.len() {
        return None;
    }
    let mut h = &mut b[..head];
    h.put_u8(codec as u8);
    put_varint(&mut h, raw.len() as u64);
    Some(b.freeze())
}

/// The codec an envelope says it uses, without opening it.
pub fn codec_of(envelope: &[u8]) -> Option<Codec> {
    envelope.first().and_then(|c| Codec::from_u8(*c))
}

/// Opens an envelope: the payload, decompressed. A `raw_len` over `max_len` is refused
/// before anything is decompressed, and the output must be exactly `raw_len` bytes.
pub fn open(envelope: &Bytes, max_len: usize) -> Result<Bytes, DecodeError> {
    const CTX: &str = "compressed message";
    let mut r = Reader::new(envelope);
    let code = r.u8(CTX)?;
    let codec = Codec::from_u8(code).ok_or_else(|| {
        DecodeError::invalid(CTX, format!("unknown codec {code} (known: 1 lz4, 2 zstd)"))
    })?;
    let raw_len = r.varint("compressed message raw_len")?;
    if raw_len > max_len as u64 {
        return Err(DecodeError::invalid(
            CTX,
            format!("decompresses to {raw_len} bytes, over the {max_len}-byte message limit"),
        ));
    }
    let raw_len = raw_len as usize;
    let data = r.rest();
    let out = match codec {
        Codec::Lz4 => lz4_flex::block::decompress(&data, raw_len)
            .map_err(|e| DecodeError::invalid(CTX, format!("lz4: {e}")))?,
        Codec::Zstd => zstd::bulk::decompress(&data, raw_len)
            .map_err(|e| DecodeError::invalid(CTX, format!("zstd: {e}")))?,
    };
    if out.len() != raw_len {
        return Err(DecodeError::invalid(
            CTX,
            format!(
                "{} decompressed to {} bytes, said {raw_len}",
                codec.as_str(),
                out.len()
            ),
        ));
    }
    Ok(Bytes::from(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(n: usize) -> Vec<u8> {
        // A point-cloud-like payload: repeated structure with slowly varying floats.
        (0..n)
            .map(|i| ((i / 16) as u8).wrapping_mul((i % 16) as u8))
            .collect()
    }

    #[test]
    fn every_codec_round_trips() {
        let raw = sample(100_000);
        for codec in [Codec::Lz4, Codec::Zstd] {
            let env = compress(codec, &raw, ZSTD_LEVEL).expect("compressible");
            assert!(env.len() < raw.len() / 2, "{codec:?}: {} bytes", env.len());
            assert_eq!(codec_of(&env), Some(codec));
            assert_eq!(open(&env, 1 << 20).unwrap(), raw);
        }
    }

    #[test]
    fn incompressible_input_is_not_grown() {
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        let raw: Vec<u8> = (0..50_000)
            .map(|_| {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                x as u8
            })
            .collect();
        assert_eq!(compress(Codec::Zstd, &raw, ZSTD_LEVEL), None);
        assert_eq!(compress(Codec::Lz4, &raw, 0), None);
    }

    #[test]
    fn a_size_over_the_limit_is_refused_before_decompressing() {
        let raw = vec![0u8; 1 << 20];
        let env = compress(Codec::Zstd, &raw, ZSTD_LEVEL).unwrap();
        assert!(env.len() < 1000);
        let e = open(&env, 1000).unwrap_err();
        assert!(e.reason.contains("over the 1000-byte message limit"), "{e}");
    }

    #[test]
    fn lies_and_garbage_are_errors() {
        let raw = sample(10_000);
        // raw_len claims more than the data holds.
        let env = compress(Codec::Zstd, &raw, ZSTD_LEVEL).unwrap();
        let mut lie = BytesMut::new();
        lie.put_u8(2);
        put_varint(&mut lie, 20_000);
        lie.put_slice(&env[1 + varint_len(10_000)..]);
        assert!(open(&lie.freeze(), 1 << 20).is_err());
        for bad in [
            &b"\x07abc"[..],
            b"\x00abc",
            b"\x01",
            b"\x01\x10garbage",
            b"\x02\x05\x00\x00",
        ] {
            assert!(
                open(&Bytes::copy_from_slice(bad), 1 << 20).is_err(),
                "{bad:?}"
            );
        }
        assert!(open(&Bytes::new(), 10).is_err());
    }
}
