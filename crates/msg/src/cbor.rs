//! rosbridge CBOR output: the message object as rosbridge's `cbor` compression embeds it.
//!
//! Conventions: a message is a map with text keys; `uint8[]` is a byte string; other
//! numeric sequences are RFC 8746 little-endian typed arrays (tag + byte string: 69
//! uint16, 70 uint32, 71 uint64, 72 int8, 77 int16, 78 int32, 79 int64, 85 float32,
//! 86 float64), as rosbridge's `cbor_conversion` emits them; `bool[]` and arrays of
//! strings or messages are plain arrays; floats keep their width (NaN stays NaN).
//! Design choice: a hand-written encoder, because typed arrays are a `memcpy` of the
//! decoded vector and this path runs once per message per hub.

use crate::value::{Array, Value};

/// One item's head as read from the input: what a walk over CBOR needs without decoding.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Head {
    /// Major type, 0..=7.
    pub major: u8,
    /// The argument (a length, a value, a tag, a float's bits); `None` for an indefinite
    /// length or a break.
    pub arg: Option<u64>,
    /// Whether the argument is written in its shortest form, as [`write_cbor`] writes it.
    pub shortest: bool,
}

/// Reads the head at `data[*pos..]` and steps over it; `None` for truncated input and the
/// reserved additional-information values. Design choice: read by hand, as a generic
/// decoder costs more per head than a whole walk over a small message.
pub fn read_head(data: &[u8], pos: &mut usize) -> Option<Head> {
    let first = *data.get(*pos)?;
    let (major, info) = (first >> 5, first & 0x1f);
    let n = match info {
        0..=23 => {
            *pos += 1;
            return Some(Head {
                major,
                arg: Some(info.into()),
                shortest: true,
            });
        }
        24 => 1,
        25 => 2,
        26 => 4,
        27 => 8,
        31 => {
            *pos += 1;
            return Some(Head {
                major,
                arg: None,
                shortest: true,
            });
        }
        _ => return None,
    };
    let bytes = data.get(*pos + 1..*pos + 1 + n)?;
    *pos += 1 + n;
    let arg = bytes.iter().fold(0u64, |v, b| v << 8 | u64::from(*b));
    let shortest = match n {
        1 => arg >= 24,
        2 => arg > 0xff,
        4 => arg > 0xffff,
        _ => arg > 0xffff_ffff,
    };
    Some(Head {
        major,
        arg: Some(arg),
        shortest,
    })
}

fn head(out: &mut Vec<u8>, major: u8, n: u64) {
    let m = major << 5;
    if n < 24 {
        out.push(m | n as u8);
    } else if n <= u8::MAX.into() {
        out.extend_from_slice(&[m | 24, n as u8]);
    } else if n <= u16::MAX.into() {
        out.push(m | 25);
        out.extend_from_slice(&(n as u16).to_be_bytes());
    } else if n <= u32::MAX.into() {
        out.push(m | 26);
        out.extend_from_slice(&(n as u32).to_be_bytes());
    } else {
        out.push(m | 27);
        out.extend_from_slice(&n.to_be_bytes());
    }
}

fn int(out: &mut Vec<u8>, x: i128) {
    if x >= 0 {
        head(out, 0, x as u64);
    } else {
        head(out, 1, (-1 - x) as u64);
    }
}

fn text(out: &mut Vec<u8>, s: &str) {
    head(out, 3, s.len() as u64);
    out.extend_from_slice(s.as_bytes());
}

macro_rules! typed {
    ($out:expr, $tag:expr, $v:expr, $size:expr) => {{
        head($out, 6, $tag);
        head($out, 2, ($v.len() * $size) as u64);
        $out.reserve($v.len() * $size);
        for x in $v {
            $out.extend_from_slice(&x.to_le_bytes());
        }
    }};
}

/// Appends the CBOR encoding of a message value to `out`.
pub fn write_cbor(value: &Value, out: &mut Vec<u8>) {
    match value {
        Value::Bool(b) => out.push(if *b { 0xf5 } else { 0xf4 }),
        Value::I8(x) => int(out, (*x).into()),
        Value::U8(x) => int(out, (*x).into()),
        Value::I16(x) => int(out, (*x).into()),
        Value::U16(x) => int(out, (*x).into()),
        Value::I32(x) => int(out, (*x).into()),
        Value::U32(x) => int(out, (*x).into()),
        Value::I64(x) => int(out, (*x).into()),
        Value::U64(x) => int(out, (*x).into()),
        Value::F32(x) => {
            out.push(0xfa);
            out.extend_from_slice(&x.to_be_bytes());
        }
        Value::F64(x) => {
            out.push(0xfb);
            out.extend_from_slice(&x.to_be_bytes());
        }
        Value::String(s) => text(out, s),
        Value::Struct(s) => {
            head(out, 5, s.fields.len() as u64);
            for (k, v) in &s.fields {
                text(out, k);
                write_cbor(v, out);
            }
        }
        Value::Array(a) => match a {
            Array::U8(v) => {
                head(out, 2, v.len() as u64);
                out.extend_from_slice(v);
            }
            Array::I8(v) => {
                head(out, 6, 72);
                head(out, 2, v.len() as u64);
                out.extend(v.iter().map(|x| *x as u8));
            }
            Array::U16(v) => typed!(out, 69, v, 2),
            Array::U32(v) => typed!(out, 70, v, 4),
            Array::U64(v) => typed!(out, 71, v, 8),
            Array::I16(v) => typed!(out, 77, v, 2),
            Array::I32(v) => typed!(out, 78, v, 4),
            Array::I64(v) => typed!(out, 79, v, 8),
            Array::F32(v) => typed!(out, 85, v, 4),
            Array::F64(v) => typed!(out, 86, v, 8),
            Array::Bool(v) => {
                head(out, 4, v.len() as u64);
                out.extend(v.iter().map(|b| if *b { 0xf5 } else { 0xf4 }));
            }
            Array::Values(v) => {
                head(out, 4, v.len() as u64);
                for x in v {
                    write_cbor(x, out);
                }
            }
        },
    }
}
