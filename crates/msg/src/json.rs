//! rosbridge JSON output: a [`Value`] as the JSON object rosbridge would send.
//!
//! Conventions: `uint8[]`/`char[]` (and ROS 2 `byte[]`) are base64 strings, NaN and
//! infinities are `null`, a ROS 1 time is `{secs, nsecs}` (a ROS 2 one is the message
//! `{sec, nanosec}`), `float32` is printed in its shortest form that reads back to the
//! same `float32`. Design choice: besides building a
//! `serde_json::Value`, [`write_json`] prints straight into a byte buffer with `itoa`/
//! `ryu`, which is what the hub uses to turn one CDR message into one JSON text.

use base64::Engine as _;

use crate::value::{Array, Value};

/// Builds the rosbridge JSON object for a message value.
pub fn to_json(value: &Value) -> serde_json::Value {
    use serde_json::Value as J;
    let num = |f: f64| {
        serde_json::Number::from_f64(f)
            .map(J::Number)
            .unwrap_or(J::Null)
    };
    match value {
        Value::Bool(b) => J::Bool(*b),
        Value::I8(x) => (*x).into(),
        Value::U8(x) => (*x).into(),
        Value::I16(x) => (*x).into(),
        Value::U16(x) => (*x).into(),
        Value::I32(x) => (*x).into(),
        Value::U32(x) => (*x).into(),
        Value::I64(x) => (*x).into(),
        Value::U64(x) => (*x).into(),
        Value::F32(x) => num(f32_as_f64(*x)),
        Value::F64(x) => num(*x),
        Value::String(s) => J::String(s.clone()),
        Value::Struct(s) => J::Object(
            s.fields
                .iter()
                .map(|(k, v)| (k.to_string(), to_json(v)))
                .collect(),
        ),
        Value::Array(a) => match a {
            Array::U8(v) => J::String(base64::engine::general_purpose::STANDARD.encode(v)),
            Array::Bool(v) => v.iter().map(|x| J::Bool(*x)).collect(),
            Array::I8(v) => v.iter().map(|x| J::from(*x)).collect(),
            Array::I16(v) => v.iter().map(|x| J::from(*x)).collect(),
            Array::U16(v) => v.iter().map(|x| J::from(*x)).collect(),
            Array::I32(v) => v.iter().map(|x| J::from(*x)).collect(),
            Array::U32(v) => v.iter().map(|x| J::from(*x)).collect(),
            Array::I64(v) => v.iter().map(|x| J::from(*x)).collect(),
            Array::U64(v) => v.iter().map(|x| J::from(*x)).collect(),
            Array::F32(v) => v.iter().map(|x| num(f32_as_f64(*x))).collect(),
            Array::F64(v) => v.iter().map(|x| num(*x)).collect(),
            Array::Values(v) => v.iter().map(to_json).collect(),
        },
    }
}

/// The `f64` whose shortest decimal form equals the `f32`'s shortest form, so JSON
/// shows `0.1` rather than `0.10000000149011612`.
pub(crate) fn f32_as_f64(x: f32) -> f64 {
    if !x.is_finite() {
        return f64::from(x);
    }
    let mut b = ryu::Buffer::new();
    b.format_finite(x).parse().unwrap_or(f64::from(x))
}

/// Prints a message value as compact rosbridge JSON into `out`.
pub fn write_json(value: &Value, out: &mut Vec<u8>) {
    match value {
        Value::Bool(b) => out.extend_from_slice(if *b { b"true" } else { b"false" }),
        Value::I8(x) => int(out, *x),
        Value::U8(x) => int(out, *x),
        Value::I16(x) => int(out, *x),
        Value::U16(x) => int(out, *x),
        Value::I32(x) => int(out, *x),
        Value::U32(x) => int(out, *x),
        Value::I64(x) => int(out, *x),
        Value::U64(x) => int(out, *x),
        Value::F32(x) => f32_out(out, *x),
        Value::F64(x) => f64_out(out, *x),
        Value::String(s) => string(out, s),
        Value::Struct(s) => {
            out.push(b'{');
            for (i, (k, v)) in s.fields.iter().enumerate() {
                if i > 0 {
                    out.push(b',');
                }
                string(out, k);
                out.push(b':');
                write_json(v, out);
            }
            out.push(b'}');
        }
        Value::Array(Array::U8(v)) => {
            out.push(b'"');
            let start = out.len();
            out.resize(start + v.len().div_ceil(3) * 4, 0);
            let n = base64::engine::general_purpose::STANDARD
                .encode_slice(v, &mut out[start..])
                .unwrap_or(0);
            out.truncate(start + n);
            out.push(b'"');
        }
        Value::Array(a) => {
            out.push(b'[');
            macro_rules! each {
                ($v:expr, $f:expr) => {
                    for (i, x) in $v.iter().enumerate() {
                        if i > 0 {
                            out.push(b',');
                        }
                        $f(&mut *out, *x);
                    }
                };
            }
            match a {
                Array::Bool(v) => each!(v, |o: &mut Vec<u8>, b: bool| o.extend_from_slice(if b {
                    b"true"
                } else {
                    b"false"
                })),
                Array::I8(v) => each!(v, int),
                Array::U8(v) => each!(v, int),
                Array::I16(v) => each!(v, int),
                Array::U16(v) => each!(v, int),
                Array::I32(v) => each!(v, int),
                Array::U32(v) => each!(v, int),
                Array::I64(v) => each!(v, int),
                Array::U64(v) => each!(v, int),
                Array::F32(v) => each!(v, f32_out),
                Array::F64(v) => each!(v, f64_out),
                Array::Values(v) => {
                    for (i, x) in v.iter().enumerate() {
                        if i > 0 {
                            out.push(b',');
                        }
                        write_json(x, out);
                    }
                }
            }
            out.push(b']');
        }
    }
}

fn int<I: itoa::Integer>(out: &mut Vec<u8>, x: I) {
    out.extend_from_slice(itoa::Buffer::new().format(x).as_bytes());
}

fn f32_out(out: &mut Vec<u8>, x: f32) {
    if x.is_finite() {
        out.extend_from_slice(ryu::Buffer::new().format_finite(x).as_bytes());
    } else {
        out.extend_from_slice(b"null");
    }
}

fn f64_out(out: &mut Vec<u8>, x: f64) {
    if x.is_finite() {
        out.extend_from_slice(ryu::Buffer::new().format_finite(x).as_bytes());
    } else {
        out.extend_from_slice(b"null");
    }
}

fn string(out: &mut Vec<u8>, s: &str) {
    if s.bytes().all(|b| b >= 0x20 && b != b'"' && b != b'\\') {
        out.push(b'"');
        out.extend_from_slice(s.as_bytes());
        out.push(b'"');
    } else {
        // Writing JSON to a Vec cannot fail.
        let _ = serde_json::to_writer(&mut *out, s);
    }
}
