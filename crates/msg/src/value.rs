//! Dynamic message values: what the codecs decode into and encode from.
//!
//! Design choice: primitive arrays are typed vectors ([`Array::F32`], [`Array::U8`], ...)
//! rather than `Vec<Value>`, so a 1 MB `uint8[]` is one allocation and one `memcpy`, and
//! the JSON/CBOR writers can emit typed arrays without inspecting each element. Struct
//! fields keep definition order (a `Vec`, names shared with the layout through `Arc`).

use std::sync::Arc;

/// One field value of a message.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Bool(bool),
    I8(i8),
    U8(u8),
    I16(i16),
    U16(u16),
    I32(i32),
    U32(u32),
    I64(i64),
    U64(u64),
    F32(f32),
    F64(f64),
    /// `string` and `wstring`.
    String(String),
    Array(Array),
    /// A nested message; also ROS 1 `time`/`duration` as `{sec, nanosec}`.
    Struct(Struct),
}

/// A sequence or fixed array. Primitive elements are stored unboxed.
#[derive(Debug, Clone, PartialEq)]
pub enum Array {
    Bool(Vec<bool>),
    I8(Vec<i8>),
    /// `uint8[]`, `char[]` and ROS 2 `byte[]`: base64 in JSON, a byte string in CBOR.
    U8(Vec<u8>),
    I16(Vec<i16>),
    U16(Vec<u16>),
    I32(Vec<i32>),
    U32(Vec<u32>),
    I64(Vec<i64>),
    U64(Vec<u64>),
    F32(Vec<f32>),
    F64(Vec<f64>),
    /// Strings, nested messages and times.
    Values(Vec<Value>),
}

impl Array {
    /// Number of elements.
    pub fn len(&self) -> usize {
        match self {
            Array::Bool(v) => v.len(),
            Array::I8(v) => v.len(),
            Array::U8(v) => v.len(),
            Array::I16(v) => v.len(),
            Array::U16(v) => v.len(),
            Array::I32(v) => v.len(),
            Array::U32(v) => v.len(),
            Array::I64(v) => v.len(),
            Array::U64(v) => v.len(),
            Array::F32(v) => v.len(),
            Array::F64(v) => v.len(),
            Array::Values(v) => v.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

impl From<Array> for Value {
    fn from(a: Array) -> Self {
        Value::Array(a)
    }
}

/// A message: named fields in definition order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Struct {
    pub fields: Vec<(Arc<str>, Value)>,
}

impl Struct {
    /// The value of field `name`, if present.
    pub fn get(&self, name: &str) -> Option<&Value> {
        self.fields
            .iter()
            .find(|(n, _)| &**n == name)
            .map(|(_, v)| v)
    }

    /// Follows a dotted path such as `header.stamp.sec`.
    pub fn get_path(&self, path: &str) -> Option<&Value> {
        let mut parts = path.split('.');
        let mut current = self.get(parts.next()?)?;
        for part in parts {
            match current {
                Value::Struct(s) => current = s.get(part)?,
                _ => return None,
            }
        }
        Some(current)
    }
}

impl Value {
    /// The nested message, if this value is one.
    pub fn as_struct(&self) -> Option<&Struct> {
        match self {
            Value::Struct(s) => Some(s),
            _ => None,
        }
    }

    /// Equality that treats two NaNs as equal (useful for round-trip checks, where
    /// `PartialEq` would call a message holding NaN unequal to itself).
    pub fn same_as(&self, other: &Value) -> bool {
        match (self, other) {
            (Value::F32(a), Value::F32(b)) => a == b || (a.is_nan() && b.is_nan()),
            (Value::F64(a), Value::F64(b)) => a == b || (a.is_nan() && b.is_nan()),
            (Value::Array(Array::F32(a)), Value::Array(Array::F32(b))) => {
                a.len() == b.len()
                    && a.iter()
                        .zip(b)
                        .all(|(x, y)| x == y || (x.is_nan() && y.is_nan()))
            }
            (Value::Array(Array::F64(a)), Value::Array(Array::F64(b))) => {
                a.len() == b.len()
                    && a.iter()
                        .zip(b)
                        .all(|(x, y)| x == y || (x.is_nan() && y.is_nan()))
            }
            (Value::Array(Array::Values(a)), Value::Array(Array::Values(b))) => {
                a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.same_as(y))
            }
            (Value::Struct(a), Value::Struct(b)) => {
                a.fields.len() == b.fields.len()
                    && a.fields
                        .iter()
                        .zip(&b.fields)
                        .all(|((na, va), (nb, vb))| na == nb && va.same_as(vb))
            }
            _ => self == other,
        }
    }
}
