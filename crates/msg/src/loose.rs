//! Building a typed [`Value`] from loosely typed input (rosbridge JSON or CBOR).
//!
//! Design choice: the rosbridge conventions (defaults for missing fields, integers in
//! float fields, `null` for NaN, base64 or byte strings for `uint8[]`, `secs`/`nsecs`
//! for time, typed-array tags) are implemented once here over the small [`Loose`]
//! trait, which JSON and CBOR documents both implement, so the two front ends cannot
//! drift apart.

use base64::Engine as _;

use crate::binary::in_field;
use crate::binary::in_index;
use crate::error::CodecError;
use crate::layout::{Elem, FieldLayout, MsgLayout, Scalar, default_field, pack, time_value};
use crate::spec::ArrayKind;
use crate::value::{Array, Struct, Value};

/// What an input node looks like.
pub(crate) enum View<'a, T> {
    Null,
    Bool(bool),
    Int(i128),
    Float(f64),
    Str(&'a str),
    Bytes(&'a [u8]),
    /// An RFC 8746 typed array: tag and little/big-endian payload.
    Typed(u64, &'a [u8]),
    Array(&'a [T]),
    /// A compact array of numbers (`null` already turned into NaN).
    Floats(&'a [f64]),
    /// A compact array of integers.
    Ints(&'a [i64]),
    Map,
    Other(&'static str),
}

/// A loosely typed document node.
pub(crate) trait Loose: Sized {
    fn view(&self) -> View<'_, Self>;
    /// Field of a map node (`None` for a missing field or a non-map node).
    fn field(&self, name: &str) -> Option<&Self>;
    /// The first key of a map node that `known` does not accept (a key that is not
    /// text is described as such).
    fn unknown_key(&self, known: &dyn Fn(&str) -> bool) -> Option<String>;
}

impl Loose for serde_json::Value {
    fn view(&self) -> View<'_, Self> {
        use serde_json::Value as J;
        match self {
            J::Null => View::Null,
            J::Bool(b) => View::Bool(*b),
            J::Number(n) => {
                if let Some(i) = n.as_i64() {
                    View::Int(i.into())
                } else if let Some(u) = n.as_u64() {
                    View::Int(u.into())
                } else {
                    View::Float(n.as_f64().unwrap_or(f64::NAN))
                }
            }
            J::String(s) => View::Str(s),
            J::Array(a) => View::Array(a),
            J::Object(_) => View::Map,
        }
    }
    fn field(&self, name: &str) -> Option<&Self> {
        self.get(name)
    }
    fn unknown_key(&self, known: &dyn Fn(&str) -> bool) -> Option<String> {
        let map = self.as_object()?;
        map.keys().find(|k| !known(k)).cloned()
    }
}

impl Loose for ciborium::Value {
    fn view(&self) -> View<'_, Self> {
        use ciborium::Value as C;
        match self {
            C::Null => View::Null,
            C::Bool(b) => View::Bool(*b),
            C::Integer(i) => View::Int(i128::from(*i)),
            C::Float(f) => View::Float(*f),
            C::Text(s) => View::Str(s),
            C::Bytes(b) => View::Bytes(b),
            C::Array(a) => View::Array(a),
            C::Map(_) => View::Map,
            C::Tag(tag, inner) => match &**inner {
                C::Bytes(b) => View::Typed(*tag, b),
                _ => View::Other("a tagged value"),
            },
            _ => View::Other("an unsupported CBOR item"),
        }
    }
    fn field(&self, name: &str) -> Option<&Self> {
        match self {
            ciborium::Value::Map(entries) => entries
                .iter()
                .find(|(k, _)| matches!(k, ciborium::Value::Text(t) if t == name))
                .map(|(_, v)| v),
            _ => None,
        }
    }
    fn unknown_key(&self, known: &dyn Fn(&str) -> bool) -> Option<String> {
        let ciborium::Value::Map(entries) = self else {
            return None;
        };
        entries.iter().find_map(|(k, _)| match k {
            ciborium::Value::Text(t) if known(t) => None,
            ciborium::Value::Text(t) => Some(t.clone()),
            _ => Some("(a key that is not text)".to_owned()),
        })
    }
}

fn mismatch(reason: impl Into<String>) -> CodecError {
    CodecError::Mismatch {
        path: String::new(),
        reason: reason.into(),
    }
}

fn describe<T>(v: &View<'_, T>) -> &'static str {
    match v {
        View::Null => "null",
        View::Bool(_) => "a bool",
        View::Int(_) => "an integer",
        View::Float(_) => "a float",
        View::Str(_) => "a string",
        View::Bytes(_) => "a byte string",
        View::Typed(..) => "a typed array",
        View::Array(_) | View::Floats(_) | View::Ints(_) => "an array",
        View::Map => "an object",
        View::Other(what) => what,
    }
}

/// Converts a document node into a message value of `layout`.
pub(crate) fn to_struct<T: Loose>(layout: &MsgLayout, node: &T) -> Result<Struct, CodecError> {
    match node.view() {
        View::Map | View::Null => {}
        other => {
            return Err(mismatch(format!(
                "expected an object for {}, got {}",
                layout.name,
                describe(&other)
            )));
        }
    }
    let is_time = layout.name.package() == "builtin_interfaces";
    let mut fields = Vec::with_capacity(layout.fields.len());
    for f in &layout.fields {
        let mut input = node.field(&f.name);
        if input.is_none() && is_time {
            input = node.field(ros1_alias(&f.name));
        }
        let v = match input {
            Some(x) if !matches!(x.view(), View::Null) || f.array == ArrayKind::Single => {
                to_field(f, x).map_err(|e| in_field(e, &f.name))?
            }
            _ => default_field(f),
        };
        fields.push((f.name.clone(), v));
    }
    // A key the type does not have is refused, as rosbridge refuses it (a misspelt field
    // would otherwise vanish without a word). Accepted besides the type's own fields:
    // ROS 1's spellings of time, and ROS 1's `seq` in a ROS 2 header, so a client written
    // for one ROS talks to robots of the other.
    let is_header = layout.name.package() == "std_msgs" && layout.name.name() == "Header";
    let known = |k: &str| {
        layout.fields.iter().any(|f| *f.name == *k)
            || (is_time && matches!(k, "secs" | "nsecs"))
            || (is_header && k == "seq")
    };
    if let Some(key) = node.unknown_key(&known) {
        return Err(mismatch(format!(
            "{} has no field '{key}' (its fields: {}); remove it or check its spelling",
            layout.name,
            field_list(layout)
        )));
    }
    Ok(Struct { fields })
}

fn field_list(layout: &MsgLayout) -> String {
    if layout.fields.is_empty() {
        return "none".to_owned();
    }
    let names: Vec<&str> = layout.fields.iter().map(|f| &*f.name).collect();
    names.join(", ")
}

fn ros1_alias(name: &str) -> &str {
    match name {
        "sec" => "secs",
        "nanosec" => "nsecs",
        other => other,
    }
}

fn to_field<T: Loose>(f: &FieldLayout, node: &T) -> Result<Value, CodecError> {
    if f.array == ArrayKind::Single {
        return to_elem(&f.elem, node);
    }
    let arr = to_array(&f.elem, node)?;
    let n = arr.len();
    match f.array {
        ArrayKind::Fixed(len) if n != len as usize => Err(mismatch(format!(
            "array has {n} elements, the type needs exactly {len}"
        ))),
        ArrayKind::Bounded(b) if n > b as usize => Err(mismatch(format!(
            "sequence has {n} elements, more than its bound of {b}"
        ))),
        _ => Ok(Value::Array(arr)),
    }
}

fn to_array<T: Loose>(elem: &Elem, node: &T) -> Result<Array, CodecError> {
    let view = node.view();
    if let Elem::Scalar(s) = elem {
        match (&view, s) {
            (View::Str(text), Scalar::U8) => {
                return base64::engine::general_purpose::STANDARD
                    .decode(text.trim())
                    .map(Array::U8)
                    .map_err(|e| mismatch(format!("uint8[] string is not base64: {e}")));
            }
            (View::Bytes(b), Scalar::U8) => return Ok(Array::U8(b.to_vec())),
            (View::Typed(tag, bytes), _) => return typed_array(*s, *tag, bytes),
            _ => {}
        }
    }
    match (&view, elem) {
        (View::Floats(fs), Elem::Scalar(s)) => {
            return compact_array(*s, fs.iter().map(|f| Value::F64(*f)));
        }
        (View::Ints(is), Elem::Scalar(s)) => {
            return compact_array(*s, is.iter().map(|i| Value::I64(*i)));
        }
        (View::Floats(_) | View::Ints(_), Elem::Msg(m)) => {
            return Err(mismatch(format!(
                "expected an array of {} objects, got numbers",
                m.name
            )));
        }
        _ => {}
    }
    let View::Array(items) = view else {
        return Err(mismatch(format!(
            "expected an array, got {}",
            describe(&view)
        )));
    };
    if let Elem::Scalar(s) = elem
        && let Some(typed) = numeric_array(*s, items)
    {
        return typed;
    }
    let mut values = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        values.push(to_elem(elem, item).map_err(|e| in_index(e, i))?);
    }
    Ok(match elem {
        Elem::Scalar(s) => pack(*s, values),
        Elem::Msg(_) => Array::Values(values),
    })
}

/// Converts a compact number array into the field's element type.
fn compact_array(
    s: Scalar,
    items: impl ExactSizeIterator<Item = Value>,
) -> Result<Array, CodecError> {
    let as_f64 = |v: Value| match v {
        Value::F64(f) => f,
        Value::I64(n) => n as f64,
        _ => f64::NAN,
    };
    let as_int = |v: Value, i: usize| -> Result<i128, CodecError> {
        match v {
            Value::I64(n) => Ok(n.into()),
            Value::F64(f) if f.fract() == 0.0 && f.abs() < 1e38 => Ok(f as i128),
            _ => Err(in_index(
                mismatch("expected an integer, got a fraction or null"),
                i,
            )),
        }
    };
    macro_rules! ints {
        ($variant:ident, $t:ty) => {{
            let mut out: Vec<$t> = Vec::with_capacity(items.len());
            for (i, v) in items.enumerate() {
                let n = as_int(v, i)?;
                out.push(
                    <$t>::try_from(n)
                        .map_err(|_| in_index(mismatch(format!("{n} is out of range")), i))?,
                );
            }
            Array::$variant(out)
        }};
    }
    Ok(match s {
        Scalar::F32 => Array::F32(items.map(|v| as_f64(v) as f32).collect()),
        Scalar::F64 => Array::F64(items.map(as_f64).collect()),
        Scalar::I8 => ints!(I8, i8),
        Scalar::U8 => ints!(U8, u8),
        Scalar::I16 => ints!(I16, i16),
        Scalar::U16 => ints!(U16, u16),
        Scalar::I32 => ints!(I32, i32),
        Scalar::U32 => ints!(U32, u32),
        Scalar::I64 => ints!(I64, i64),
        Scalar::U64 => ints!(U64, u64),
        Scalar::Bool => {
            let mut out = Vec::with_capacity(items.len());
            for (i, v) in items.enumerate() {
                out.push(match v {
                    Value::I64(0) => false,
                    Value::I64(1) => true,
                    _ => return Err(in_index(mismatch("expected a bool"), i)),
                });
            }
            Array::Bool(out)
        }
        _ => return Err(mismatch(format!("expected an array of {s:?}, got numbers"))),
    })
}

/// Fast path for arrays of numbers: converts straight into the typed vector.
/// `None` for element types that need the general path.
fn numeric_array<T: Loose>(s: Scalar, items: &[T]) -> Option<Result<Array, CodecError>> {
    fn floats<T: Loose, F>(items: &[T], conv: impl Fn(f64) -> F) -> Result<Vec<F>, CodecError> {
        let mut out = Vec::with_capacity(items.len());
        for (i, item) in items.iter().enumerate() {
            let f = match item.view() {
                View::Float(f) => f,
                View::Int(n) => n as f64,
                View::Null => f64::NAN,
                // The general path words the error (and accepts "NaN"-style strings).
                _ => match to_elem(&Elem::Scalar(Scalar::F64), item) {
                    Ok(Value::F64(f)) => f,
                    Ok(_) => f64::NAN,
                    Err(e) => return Err(in_index(e, i)),
                },
            };
            out.push(conv(f));
        }
        Ok(out)
    }
    fn ints<T: Loose, I: TryFrom<i128>>(items: &[T], s: Scalar) -> Result<Vec<I>, CodecError> {
        let mut out = Vec::with_capacity(items.len());
        for (i, item) in items.iter().enumerate() {
            let direct = match item.view() {
                View::Int(n) => I::try_from(n).ok(),
                _ => None,
            };
            let x = match direct {
                Some(x) => x,
                // The general path accepts integral floats and bools and words errors.
                None => {
                    let v = to_elem(&Elem::Scalar(s), item).map_err(|e| in_index(e, i))?;
                    crate::binary::as_int(&v)
                        .and_then(|n| I::try_from(n).ok())
                        .ok_or_else(|| in_index(mismatch("integer out of range"), i))?
                }
            };
            out.push(x);
        }
        Ok(out)
    }
    Some(match s {
        Scalar::F32 => floats(items, |f| f as f32).map(Array::F32),
        Scalar::F64 => floats(items, |f| f).map(Array::F64),
        Scalar::I8 => ints(items, s).map(Array::I8),
        Scalar::U8 => ints(items, s).map(Array::U8),
        Scalar::I16 => ints(items, s).map(Array::I16),
        Scalar::U16 => ints(items, s).map(Array::U16),
        Scalar::I32 => ints(items, s).map(Array::I32),
        Scalar::U32 => ints(items, s).map(Array::U32),
        Scalar::I64 => ints(items, s).map(Array::I64),
        Scalar::U64 => ints(items, s).map(Array::U64),
        _ => return None,
    })
}

/// Decodes an RFC 8746 typed array whose tag matches the element type.
fn typed_array(s: Scalar, tag: u64, b: &[u8]) -> Result<Array, CodecError> {
    macro_rules! le {
        ($t:ty, $n:expr, $variant:ident) => {{
            if b.len() % $n != 0 {
                return Err(mismatch(format!(
                    "typed array of {} bytes is not a multiple of {}",
                    b.len(),
                    $n
                )));
            }
            Array::$variant(
                b.chunks_exact($n)
                    .map(|c| {
                        let mut a = [0u8; $n];
                        a.copy_from_slice(c);
                        <$t>::from_le_bytes(a)
                    })
                    .collect(),
            )
        }};
    }
    Ok(match (s, tag) {
        (Scalar::U8, 64) => Array::U8(b.to_vec()),
        (Scalar::I8, 72) => Array::I8(b.iter().map(|x| *x as i8).collect()),
        (Scalar::U16, 69) => le!(u16, 2, U16),
        (Scalar::U32, 70) => le!(u32, 4, U32),
        (Scalar::U64, 71) => le!(u64, 8, U64),
        (Scalar::I16, 77) => le!(i16, 2, I16),
        (Scalar::I32, 78) => le!(i32, 4, I32),
        (Scalar::I64, 79) => le!(i64, 8, I64),
        (Scalar::F32, 85) => le!(f32, 4, F32),
        (Scalar::F64, 86) => le!(f64, 8, F64),
        _ => {
            return Err(mismatch(format!(
                "typed array tag {tag} does not match the element type {s:?}"
            )));
        }
    })
}

fn to_elem<T: Loose>(elem: &Elem, node: &T) -> Result<Value, CodecError> {
    let s = match elem {
        Elem::Msg(m) => return to_struct(m, node).map(Value::Struct),
        Elem::Scalar(s) => *s,
    };
    let view = node.view();
    let int = |lo: i128, hi: i128| -> Result<i128, CodecError> {
        let i = match view {
            View::Int(i) => i,
            View::Bool(b) => i128::from(b),
            View::Float(f) if f.fract() == 0.0 && f.abs() < 1e38 => f as i128,
            ref other => {
                return Err(mismatch(format!(
                    "expected an integer, got {}",
                    describe(other)
                )));
            }
        };
        if i < lo || i > hi {
            return Err(mismatch(format!("{i} is out of range [{lo}, {hi}]")));
        }
        Ok(i)
    };
    let float = || -> Result<f64, CodecError> {
        match view {
            View::Float(f) => Ok(f),
            View::Int(i) => Ok(i as f64),
            View::Null => Ok(f64::NAN),
            View::Str("NaN" | "nan") => Ok(f64::NAN),
            View::Str("Infinity" | "inf") => Ok(f64::INFINITY),
            View::Str("-Infinity" | "-inf") => Ok(f64::NEG_INFINITY),
            ref other => Err(mismatch(format!(
                "expected a number, got {}",
                describe(other)
            ))),
        }
    };
    // Ranges are checked by `int`, so the casts below are exact.
    Ok(match s {
        Scalar::Bool => match view {
            View::Bool(b) => Value::Bool(b),
            _ => Value::Bool(int(0, 1)? == 1),
        },
        Scalar::I8 => Value::I8(int(i8::MIN.into(), i8::MAX.into())? as i8),
        Scalar::U8 => match view {
            View::Str(c) if c.len() == 1 => Value::U8(c.as_bytes()[0]),
            _ => Value::U8(int(0, u8::MAX.into())? as u8),
        },
        Scalar::I16 => Value::I16(int(i16::MIN.into(), i16::MAX.into())? as i16),
        Scalar::U16 => Value::U16(int(0, u16::MAX.into())? as u16),
        Scalar::I32 => Value::I32(int(i32::MIN.into(), i32::MAX.into())? as i32),
        Scalar::U32 => Value::U32(int(0, u32::MAX.into())? as u32),
        Scalar::I64 => Value::I64(int(i64::MIN.into(), i64::MAX.into())? as i64),
        Scalar::U64 => Value::U64(int(0, u64::MAX.into())? as u64),
        Scalar::F32 => Value::F32(float()? as f32),
        Scalar::F64 => Value::F64(float()?),
        Scalar::String | Scalar::WString => match view {
            View::Str(t) => Value::String(t.to_owned()),
            ref other => {
                return Err(mismatch(format!(
                    "expected a string, got {}",
                    describe(other)
                )));
            }
        },
        Scalar::Time | Scalar::Duration => {
            if !matches!(view, View::Map | View::Null) {
                return Err(mismatch(format!(
                    "expected {{secs, nsecs}}, got {}",
                    describe(&view)
                )));
            }
            let part = |a: &str, b: &str| node.field(a).or_else(|| node.field(b));
            let sec = part("sec", "secs");
            let nsec = part("nanosec", "nsecs");
            let get = |n: Option<&T>, what: &str, lo: i128, hi: i128| -> Result<i128, CodecError> {
                match n {
                    None => Ok(0),
                    Some(n) => to_elem(&Elem::Scalar(Scalar::I64), n)
                        .map_err(|e| in_field(e, what))
                        .and_then(|v| match v {
                            Value::I64(i) if i128::from(i) >= lo && i128::from(i) <= hi => {
                                Ok(i128::from(i))
                            }
                            _ => Err(in_field(mismatch("out of range"), what)),
                        }),
                }
            };
            if s == Scalar::Time {
                let hi = u32::MAX.into();
                time_value(
                    Value::U32(get(sec, "sec", 0, hi)? as u32),
                    Value::U32(get(nsec, "nanosec", 0, hi)? as u32),
                )
            } else {
                let (lo, hi) = (i32::MIN.into(), i32::MAX.into());
                time_value(
                    Value::I32(get(sec, "sec", lo, hi)? as i32),
                    Value::I32(get(nsec, "nanosec", lo, hi)? as i32),
                )
            }
        }
    })
}
