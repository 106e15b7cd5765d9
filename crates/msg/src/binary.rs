//! Binary codecs: ROS 2 CDR and ROS 1 serialization, driven by a [`MsgLayout`].
//!
//! Wire layouts (all integers in the stated byte order):
//!
//! ```text
//! CDR (ROS 2):   [0x00, 0x01 (LE) | 0x00 (BE), 0x00, 0x00] then the fields, each
//!                aligned to its own size (max 8) relative to the byte after the header;
//!                string = u32 length incl. NUL, bytes, NUL; sequence = u32 count, items;
//!                fixed array = items only; an empty message is one zero byte.
//! ROS 1:         fields back to back, little-endian, no alignment; string = u32 length,
//!                bytes (no NUL); array = u32 count, items; time = u32 sec, u32 nsec.
//! ```
//!
//! Design choice: one reader and one writer serve both formats, switching on [`Wire`]
//! only where the formats differ (alignment, string terminator, empty messages), so
//! there is a single implementation of field walking per direction. Lengths read from
//! the input are checked against the bytes left *before* anything is allocated.

use crate::error::CodecError;
use crate::layout::{Elem, FieldLayout, MsgLayout, Scalar, default_field, time_value};
use crate::spec::ArrayKind;
use crate::value::{Array, Struct, Value};

/// A binary wire format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Wire {
    /// ROS 2 / DDS CDR (XCDR1) with the 4-byte encapsulation header.
    Cdr,
    /// ROS 1 serialization (TCPROS payload, without the 4-byte frame length).
    Ros1,
}

/// Prepends a field name to an error's path while the error travels up.
pub(crate) fn in_field(e: CodecError, name: &str) -> CodecError {
    let join = |p: String| {
        if p.is_empty() {
            name.to_owned()
        } else if p.starts_with('[') {
            format!("{name}{p}")
        } else {
            format!("{name}.{p}")
        }
    };
    match e {
        CodecError::Incomplete {
            path,
            offset,
            needed,
            available,
        } => CodecError::Incomplete {
            path: join(path),
            offset,
            needed,
            available,
        },
        CodecError::Invalid {
            path,
            offset,
            reason,
        } => CodecError::Invalid {
            path: join(path),
            offset,
            reason,
        },
        CodecError::Mismatch { path, reason } => CodecError::Mismatch {
            path: join(path),
            reason,
        },
        other => other,
    }
}

/// Prepends an array index (`[3]`) to an error's path.
pub(crate) fn in_index(e: CodecError, i: usize) -> CodecError {
    in_field(e, &format!("[{i}]"))
}

/// Cursor over an input buffer.
#[derive(Clone)]
pub(crate) struct Reader<'a> {
    pub(crate) buf: &'a [u8],
    pub(crate) pos: usize,
    /// Alignment origin (the byte after the CDR header).
    origin: usize,
    big_endian: bool,
    wire: Wire,
}

macro_rules! read_num {
    ($fn:ident, $t:ty, $n:expr) => {
        #[inline]
        pub(crate) fn $fn(&mut self) -> Result<$t, CodecError> {
            self.align($n)?;
            let b = self.take($n)?;
            let mut a = [0u8; $n];
            a.copy_from_slice(b);
            Ok(if self.big_endian {
                <$t>::from_be_bytes(a)
            } else {
                <$t>::from_le_bytes(a)
            })
        }
    };
}

macro_rules! read_vec {
    ($fn:ident, $t:ty, $n:expr) => {
        fn $fn(&mut self, count: usize) -> Result<Vec<$t>, CodecError> {
            if count == 0 {
                return Ok(Vec::new());
            }
            self.align($n)?;
            let bytes = self.take(
                count
                    .checked_mul($n)
                    .ok_or_else(|| self.invalid("element count overflows"))?,
            )?;
            let be = self.big_endian;
            Ok(bytes
                .chunks_exact($n)
                .map(|c| {
                    let mut a = [0u8; $n];
                    a.copy_from_slice(c);
                    if be {
                        <$t>::from_be_bytes(a)
                    } else {
                        <$t>::from_le_bytes(a)
                    }
                })
                .collect())
        }
    };
}

impl<'a> Reader<'a> {
    /// Starts reading a message: checks and skips the CDR header if `wire` is CDR.
    pub(crate) fn new(buf: &'a [u8], wire: Wire) -> Result<Self, CodecError> {
        let mut r = Reader {
            buf,
            pos: 0,
            origin: 0,
            big_endian: false,
            wire,
        };
        if wire == Wire::Cdr {
            let h = r.take(4)?;
            r.big_endian = match (h[0], h[1]) {
                (0x00, 0x01) => false,
                (0x00, 0x00) => true,
                (a, b) => {
                    return Err(CodecError::Invalid {
                        path: String::new(),
                        offset: 0,
                        reason: format!(
                            "unsupported CDR encapsulation {a:#04x}{b:02x} (expected plain CDR, 0x0000 or 0x0001)"
                        ),
                    });
                }
            };
            r.origin = 4;
        }
        Ok(r)
    }

    pub(crate) fn is_big_endian(&self) -> bool {
        self.big_endian
    }

    pub(crate) fn remaining(&self) -> usize {
        self.buf.len() - self.pos
    }

    pub(crate) fn invalid(&self, reason: impl Into<String>) -> CodecError {
        CodecError::Invalid {
            path: String::new(),
            offset: self.pos,
            reason: reason.into(),
        }
    }

    #[inline]
    pub(crate) fn take(&mut self, n: usize) -> Result<&'a [u8], CodecError> {
        if n > self.remaining() {
            return Err(CodecError::Incomplete {
                path: String::new(),
                offset: self.pos,
                needed: n,
                available: self.remaining(),
            });
        }
        let s = &self.buf[self.pos..self.pos + n];
        self.pos += n;
        Ok(s)
    }

    #[inline]
    pub(crate) fn align(&mut self, n: usize) -> Result<(), CodecError> {
        if self.wire == Wire::Cdr {
            let rel = self.pos - self.origin;
            let pad = (n - rel % n) % n;
            self.take(pad)?;
        }
        Ok(())
    }

    read_num!(read_u16, u16, 2);
    read_num!(read_i16, i16, 2);
    read_num!(read_u32, u32, 4);
    read_num!(read_i32, i32, 4);
    read_num!(read_u64, u64, 8);
    read_num!(read_i64, i64, 8);
    read_num!(read_f32, f32, 4);
    read_num!(read_f64, f64, 8);
    read_vec!(vec_u16, u16, 2);
    read_vec!(vec_i16, i16, 2);
    read_vec!(vec_u32, u32, 4);
    read_vec!(vec_i32, i32, 4);
    read_vec!(vec_u64, u64, 8);
    read_vec!(vec_i64, i64, 8);
    read_vec!(vec_f32, f32, 4);
    read_vec!(vec_f64, f64, 8);

    /// Reads a sequence length and checks it against the bound and the bytes left.
    pub(crate) fn read_count(
        &mut self,
        bound: Option<u32>,
        min_elem_size: usize,
    ) -> Result<usize, CodecError> {
        let at = self.pos;
        let n = self.read_u32()? as usize;
        if let Some(b) = bound
            && n > b as usize
        {
            return Err(CodecError::Invalid {
                path: String::new(),
                offset: at,
                reason: format!("sequence of {n} exceeds its bound of {b}"),
            });
        }
        let needed = n.saturating_mul(min_elem_size.max(1));
        if needed > self.remaining() {
            return Err(CodecError::Incomplete {
                path: String::new(),
                offset: self.pos,
                needed,
                available: self.remaining(),
            });
        }
        Ok(n)
    }

    /// Reads a string as a borrowed slice of the input.
    pub(crate) fn read_str(&mut self, bound: Option<u32>) -> Result<&'a str, CodecError> {
        let at = self.pos;
        let n = self.read_u32()? as usize;
        let bytes = self.take(n)?;
        let bytes = match (self.wire, bytes.split_last()) {
            (Wire::Cdr, Some((0, rest))) => rest,
            (Wire::Cdr, Some(_)) => {
                return Err(CodecError::Invalid {
                    path: String::new(),
                    offset: at,
                    reason: "CDR string is not NUL-terminated".into(),
                });
            }
            _ => bytes,
        };
        if let Some(b) = bound
            && bytes.len() > b as usize
        {
            return Err(CodecError::Invalid {
                path: String::new(),
                offset: at,
                reason: format!("string of {} bytes exceeds its bound of {b}", bytes.len()),
            });
        }
        std::str::from_utf8(bytes).map_err(|e| CodecError::Invalid {
            path: String::new(),
            offset: at + 4 + e.valid_up_to(),
            reason: format!("string is not UTF-8: {e}"),
        })
    }

    /// A wide string: u32 count of UTF-16 code units, then the units (no terminator).
    pub(crate) fn read_wstr(&mut self, bound: Option<u32>) -> Result<String, CodecError> {
        let at = self.pos;
        let n = self.read_count(bound, 2)?;
        let units = self.vec_u16(n)?;
        String::from_utf16(&units).map_err(|e| CodecError::Invalid {
            path: String::new(),
            offset: at,
            reason: format!("wstring is not UTF-16: {e}"),
        })
    }

    pub(crate) fn read_bool(&mut self) -> Result<bool, CodecError> {
        match self.take(1)?[0] {
            0 => Ok(false),
            1 => Ok(true),
            b => Err(CodecError::Invalid {
                path: String::new(),
                offset: self.pos - 1,
                reason: format!("bool byte is {b}, not 0 or 1"),
            }),
        }
    }
}

/// Decodes one message of `layout` from `buf`.
pub(crate) fn decode_message(
    layout: &MsgLayout,
    wire: Wire,
    buf: &[u8],
) -> Result<Value, CodecError> {
    let mut r = Reader::new(buf, wire)?;
    read_struct(&mut r, layout).map(Value::Struct)
}

pub(crate) fn read_struct(r: &mut Reader<'_>, layout: &MsgLayout) -> Result<Struct, CodecError> {
    if layout.fields.is_empty() && r.wire == Wire::Cdr {
        r.take(1)?;
        return Ok(Struct::default());
    }
    let mut fields = Vec::with_capacity(layout.fields.len());
    for f in &layout.fields {
        let v = read_field(r, f).map_err(|e| in_field(e, &f.name))?;
        fields.push((f.name.clone(), v));
    }
    Ok(Struct { fields })
}

pub(crate) fn read_field(r: &mut Reader<'_>, f: &FieldLayout) -> Result<Value, CodecError> {
    let count = match f.array {
        ArrayKind::Single => return read_elem(r, &f.elem, f.string_bound),
        ArrayKind::Fixed(n) => n as usize,
        ArrayKind::Bounded(b) => r.read_count(Some(b), min_size(&f.elem))?,
        ArrayKind::Unbounded => r.read_count(None, min_size(&f.elem))?,
    };
    if let ArrayKind::Fixed(_) = f.array {
        let needed = count.saturating_mul(min_size(&f.elem));
        if needed > r.remaining() {
            return Err(CodecError::Incomplete {
                path: String::new(),
                offset: r.pos,
                needed,
                available: r.remaining(),
            });
        }
    }
    read_array(r, &f.elem, f.string_bound, count).map(Value::Array)
}

/// Lower bound of one element's size, used to reject absurd counts before allocating.
pub(crate) fn min_size(elem: &Elem) -> usize {
    match elem {
        Elem::Scalar(s) => s.fixed_size().unwrap_or(4),
        Elem::Msg(_) => 1,
    }
}

fn read_array(
    r: &mut Reader<'_>,
    elem: &Elem,
    bound: Option<u32>,
    n: usize,
) -> Result<Array, CodecError> {
    Ok(match elem {
        Elem::Scalar(Scalar::U8) => Array::U8(r.take(n)?.to_vec()),
        Elem::Scalar(Scalar::I8) => Array::I8(r.take(n)?.iter().map(|b| *b as i8).collect()),
        Elem::Scalar(Scalar::Bool) => {
            let mut v = Vec::with_capacity(n);
            for _ in 0..n {
                v.push(r.read_bool()?);
            }
            Array::Bool(v)
        }
        Elem::Scalar(Scalar::U16) => Array::U16(r.vec_u16(n)?),
        Elem::Scalar(Scalar::I16) => Array::I16(r.vec_i16(n)?),
        Elem::Scalar(Scalar::U32) => Array::U32(r.vec_u32(n)?),
        Elem::Scalar(Scalar::I32) => Array::I32(r.vec_i32(n)?),
        Elem::Scalar(Scalar::U64) => Array::U64(r.vec_u64(n)?),
        Elem::Scalar(Scalar::I64) => Array::I64(r.vec_i64(n)?),
        Elem::Scalar(Scalar::F32) => Array::F32(r.vec_f32(n)?),
        Elem::Scalar(Scalar::F64) => Array::F64(r.vec_f64(n)?),
        _ => {
            let mut v = Vec::with_capacity(n.min(4096));
            for i in 0..n {
                v.push(read_elem(r, elem, bound).map_err(|e| in_index(e, i))?);
            }
            Array::Values(v)
        }
    })
}

fn read_elem(r: &mut Reader<'_>, elem: &Elem, bound: Option<u32>) -> Result<Value, CodecError> {
    let s = match elem {
        Elem::Msg(m) => return read_struct(r, m).map(Value::Struct),
        Elem::Scalar(s) => *s,
    };
    Ok(match s {
        Scalar::Bool => Value::Bool(r.read_bool()?),
        Scalar::I8 => Value::I8(r.take(1)?[0] as i8),
        Scalar::U8 => Value::U8(r.take(1)?[0]),
        Scalar::I16 => Value::I16(r.read_i16()?),
        Scalar::U16 => Value::U16(r.read_u16()?),
        Scalar::I32 => Value::I32(r.read_i32()?),
        Scalar::U32 => Value::U32(r.read_u32()?),
        Scalar::I64 => Value::I64(r.read_i64()?),
        Scalar::U64 => Value::U64(r.read_u64()?),
        Scalar::F32 => Value::F32(r.read_f32()?),
        Scalar::F64 => Value::F64(r.read_f64()?),
        Scalar::String => Value::String(r.read_str(bound)?.to_owned()),
        Scalar::WString => Value::String(r.read_wstr(bound)?),
        Scalar::Time => {
            let sec = r.read_u32()?;
            time_value(Value::U32(sec), Value::U32(r.read_u32()?))
        }
        Scalar::Duration => {
            let sec = r.read_i32()?;
            time_value(Value::I32(sec), Value::I32(r.read_i32()?))
        }
    })
}

/// Output buffer with CDR alignment bookkeeping (always little-endian).
pub(crate) struct Writer {
    pub(crate) out: Vec<u8>,
    origin: usize,
    wire: Wire,
}

impl Writer {
    pub(crate) fn new(wire: Wire, capacity: usize) -> Self {
        let mut out = Vec::with_capacity(capacity + 4);
        let mut origin = 0;
        if wire == Wire::Cdr {
            out.extend_from_slice(&[0x00, 0x01, 0x00, 0x00]);
            origin = 4;
        }
        Writer { out, origin, wire }
    }

    #[inline]
    pub(crate) fn align(&mut self, n: usize) {
        if self.wire == Wire::Cdr {
            let rel = self.out.len() - self.origin;
            let pad = (n - rel % n) % n;
            self.out.resize(self.out.len() + pad, 0);
        }
    }

    #[inline]
    pub(crate) fn put<const N: usize>(&mut self, bytes: [u8; N]) {
        self.align(N);
        self.out.extend_from_slice(&bytes);
    }

    pub(crate) fn put_str(&mut self, s: &str) {
        let nul = usize::from(self.wire == Wire::Cdr);
        self.put(((s.len() + nul) as u32).to_le_bytes());
        self.out.extend_from_slice(s.as_bytes());
        if nul == 1 {
            self.out.push(0);
        }
    }
}

/// Encodes `value` (a struct of `layout`) in `wire`.
pub(crate) fn encode_message(
    layout: &MsgLayout,
    wire: Wire,
    value: &Value,
) -> Result<Vec<u8>, CodecError> {
    let s = value.as_struct().ok_or_else(|| CodecError::Mismatch {
        path: String::new(),
        reason: "expected a message (struct) value".into(),
    })?;
    let mut w = Writer::new(wire, 256);
    write_struct(&mut w, layout, s)?;
    Ok(w.out)
}

fn mismatch(reason: impl Into<String>) -> CodecError {
    CodecError::Mismatch {
        path: String::new(),
        reason: reason.into(),
    }
}

fn write_struct(w: &mut Writer, layout: &MsgLayout, s: &Struct) -> Result<(), CodecError> {
    if layout.fields.is_empty() && w.wire == Wire::Cdr {
        w.out.push(0);
        return Ok(());
    }
    let is_time = layout.name.package() == "builtin_interfaces";
    for (i, f) in layout.fields.iter().enumerate() {
        let found = match s.fields.get(i) {
            Some((n, v)) if *n == f.name => Some(v),
            // A ROS 1 time (`{secs, nsecs}`) written as a ROS 2 one.
            _ => s.get(&f.name).or_else(|| match (&*f.name, is_time) {
                ("sec", true) => s.get("secs"),
                ("nanosec", true) => s.get("nsecs"),
                _ => None,
            }),
        };
        let r = match found {
            Some(v) => write_field(w, f, v),
            None => write_field(w, f, &default_field(f)),
        };
        r.map_err(|e| in_field(e, &f.name))?;
    }
    Ok(())
}

fn write_field(w: &mut Writer, f: &FieldLayout, v: &Value) -> Result<(), CodecError> {
    if f.array == ArrayKind::Single {
        return write_elem(w, &f.elem, f.string_bound, v);
    }
    let Value::Array(a) = v else {
        return Err(mismatch("expected an array"));
    };
    let n = a.len();
    match f.array {
        ArrayKind::Fixed(len) if n != len as usize => {
            return Err(mismatch(format!(
                "array has {n} elements, the type needs exactly {len}"
            )));
        }
        ArrayKind::Bounded(b) if n > b as usize => {
            return Err(mismatch(format!(
                "sequence has {n} elements, more than its bound of {b}"
            )));
        }
        ArrayKind::Bounded(_) | ArrayKind::Unbounded => {
            let n32 = u32::try_from(n).map_err(|_| mismatch("sequence longer than 2^32-1"))?;
            w.put(n32.to_le_bytes());
        }
        _ => {}
    }
    write_array(w, &f.elem, f.string_bound, a)
}

macro_rules! put_all {
    ($w:expr, $v:expr, $n:expr) => {{
        if !$v.is_empty() {
            $w.align($n);
            $w.out.reserve($v.len() * $n);
            for x in $v {
                $w.out.extend_from_slice(&x.to_le_bytes());
            }
        }
    }};
}

fn write_array(
    w: &mut Writer,
    elem: &Elem,
    bound: Option<u32>,
    a: &Array,
) -> Result<(), CodecError> {
    match (elem, a) {
        (Elem::Scalar(Scalar::U8), Array::U8(v)) => w.out.extend_from_slice(v),
        (Elem::Scalar(Scalar::I8), Array::I8(v)) => w.out.extend(v.iter().map(|x| *x as u8)),
        (Elem::Scalar(Scalar::Bool), Array::Bool(v)) => {
            w.out.extend(v.iter().map(|x| u8::from(*x)))
        }
        (Elem::Scalar(Scalar::U16), Array::U16(v)) => put_all!(w, v, 2),
        (Elem::Scalar(Scalar::I16), Array::I16(v)) => put_all!(w, v, 2),
        (Elem::Scalar(Scalar::U32), Array::U32(v)) => put_all!(w, v, 4),
        (Elem::Scalar(Scalar::I32), Array::I32(v)) => put_all!(w, v, 4),
        (Elem::Scalar(Scalar::U64), Array::U64(v)) => put_all!(w, v, 8),
        (Elem::Scalar(Scalar::I64), Array::I64(v)) => put_all!(w, v, 8),
        (Elem::Scalar(Scalar::F32), Array::F32(v)) => put_all!(w, v, 4),
        (Elem::Scalar(Scalar::F64), Array::F64(v)) => put_all!(w, v, 8),
        (_, Array::Values(v)) => {
            for (i, x) in v.iter().enumerate() {
                write_elem(w, elem, bound, x).map_err(|e| in_index(e, i))?;
            }
        }
        (_, other) => {
            // A typed array of another element type: convert element by element.
            for i in 0..other.len() {
                let x = array_item(other, i);
                write_elem(w, elem, bound, &x).map_err(|e| in_index(e, i))?;
            }
        }
    }
    Ok(())
}

/// Element `i` of a typed array as a [`Value`] (slow path for mismatched array kinds).
pub(crate) fn array_item(a: &Array, i: usize) -> Value {
    match a {
        Array::Bool(v) => Value::Bool(v[i]),
        Array::I8(v) => Value::I8(v[i]),
        Array::U8(v) => Value::U8(v[i]),
        Array::I16(v) => Value::I16(v[i]),
        Array::U16(v) => Value::U16(v[i]),
        Array::I32(v) => Value::I32(v[i]),
        Array::U32(v) => Value::U32(v[i]),
        Array::I64(v) => Value::I64(v[i]),
        Array::U64(v) => Value::U64(v[i]),
        Array::F32(v) => Value::F32(v[i]),
        Array::F64(v) => Value::F64(v[i]),
        Array::Values(v) => v[i].clone(),
    }
}

/// Integer view of a numeric value, for range-checked conversion.
pub(crate) fn as_int(v: &Value) -> Option<i128> {
    Some(match v {
        Value::Bool(b) => i128::from(*b),
        Value::I8(x) => (*x).into(),
        Value::U8(x) => (*x).into(),
        Value::I16(x) => (*x).into(),
        Value::U16(x) => (*x).into(),
        Value::I32(x) => (*x).into(),
        Value::U32(x) => (*x).into(),
        Value::I64(x) => (*x).into(),
        Value::U64(x) => (*x).into(),
        _ => return None,
    })
}

pub(crate) fn as_float(v: &Value) -> Option<f64> {
    match v {
        Value::F32(x) => Some(f64::from(*x)),
        Value::F64(x) => Some(*x),
        other => as_int(other).map(|i| i as f64),
    }
}

fn int_in<T: TryFrom<i128>>(v: &Value, what: &str) -> Result<T, CodecError> {
    let i = as_int(v).ok_or_else(|| mismatch(format!("expected {what}, got {}", kind_of(v))))?;
    T::try_from(i).map_err(|_| mismatch(format!("{i} is out of range for {what}")))
}

pub(crate) fn kind_of(v: &Value) -> &'static str {
    match v {
        Value::Bool(_) => "a bool",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Struct(_) => "a message",
        Value::F32(_) | Value::F64(_) => "a float",
        _ => "an integer",
    }
}

fn write_elem(
    w: &mut Writer,
    elem: &Elem,
    bound: Option<u32>,
    v: &Value,
) -> Result<(), CodecError> {
    let s = match elem {
        Elem::Msg(m) => {
            let st = v
                .as_struct()
                .ok_or_else(|| mismatch(format!("expected a message, got {}", kind_of(v))))?;
            return write_struct(w, m, st);
        }
        Elem::Scalar(s) => *s,
    };
    match s {
        Scalar::Bool => match v {
            Value::Bool(b) => w.out.push(u8::from(*b)),
            _ => w.out.push(int_in::<u8>(v, "a bool (0 or 1)").and_then(|b| {
                if b <= 1 {
                    Ok(b)
                } else {
                    Err(mismatch("bool must be 0 or 1"))
                }
            })?),
        },
        Scalar::I8 => w.out.push(int_in::<i8>(v, "int8")? as u8),
        Scalar::U8 => w.out.push(int_in::<u8>(v, "uint8")?),
        Scalar::I16 => w.put(int_in::<i16>(v, "int16")?.to_le_bytes()),
        Scalar::U16 => w.put(int_in::<u16>(v, "uint16")?.to_le_bytes()),
        Scalar::I32 => w.put(int_in::<i32>(v, "int32")?.to_le_bytes()),
        Scalar::U32 => w.put(int_in::<u32>(v, "uint32")?.to_le_bytes()),
        Scalar::I64 => w.put(int_in::<i64>(v, "int64")?.to_le_bytes()),
        Scalar::U64 => w.put(int_in::<u64>(v, "uint64")?.to_le_bytes()),
        Scalar::F32 => w.put(
            (as_float(v)
                .ok_or_else(|| mismatch(format!("expected a number, got {}", kind_of(v))))?
                as f32)
                .to_le_bytes(),
        ),
        Scalar::F64 => w.put(
            as_float(v)
                .ok_or_else(|| mismatch(format!("expected a number, got {}", kind_of(v))))?
                .to_le_bytes(),
        ),
        Scalar::String | Scalar::WString => {
            let Value::String(text) = v else {
                return Err(mismatch(format!("expected a string, got {}", kind_of(v))));
            };
            let len = if s == Scalar::WString {
                text.encode_utf16().count()
            } else {
                text.len()
            };
            if let Some(b) = bound
                && len > b as usize
            {
                return Err(mismatch(format!(
                    "string of {len} exceeds its bound of {b}"
                )));
            }
            if s == Scalar::String {
                w.put_str(text);
            } else {
                w.put((len as u32).to_le_bytes());
                for u in text.encode_utf16() {
                    w.put(u.to_le_bytes());
                }
            }
        }
        Scalar::Time | Scalar::Duration => {
            let st = v
                .as_struct()
                .ok_or_else(|| mismatch(format!("expected {{secs, nsecs}}, got {}", kind_of(v))))?;
            let part = |names: [&str; 2]| {
                names
                    .iter()
                    .find_map(|n| st.get(n))
                    .cloned()
                    .unwrap_or(Value::U32(0))
            };
            let (sec, nsec) = (part(["sec", "secs"]), part(["nanosec", "nsecs"]));
            if s == Scalar::Time {
                w.put(int_in::<u32>(&sec, "time.sec (uint32)")?.to_le_bytes());
                w.put(int_in::<u32>(&nsec, "time.nanosec (uint32)")?.to_le_bytes());
            } else {
                w.put(int_in::<i32>(&sec, "duration.sec (int32)")?.to_le_bytes());
                w.put(int_in::<i32>(&nsec, "duration.nanosec (int32)")?.to_le_bytes());
            }
        }
    }
    Ok(())
}
