//! One pass over rosbridge CBOR, without building a tree, that says whether a message is
//! already exactly what [`crate::cbor::write_cbor`] would write for it after the check
//! against its type: every field of the layout present, in order, under its own name, each
//! value with the item kind and width the writer uses, in range, with minimal heads. Such a
//! message can be forwarded as it came. Anything else (a missing field, a plain array where
//! the writer puts a typed one, an integer in a float field, a NaN, an indefinite length)
//! answers `false`, and the full path decodes and rewrites it, or refuses it with its
//! precise error.

use crate::layout::{Elem, FieldLayout, MsgLayout, Scalar};
use crate::spec::ArrayKind;

/// Whether `bytes` is one message of `layout` in normal form, and nothing after it.
pub(crate) fn is_normal(layout: &MsgLayout, bytes: &[u8]) -> bool {
    let mut c = Cursor {
        data: bytes,
        pos: 0,
    };
    c.message(layout, 0).is_some() && c.pos == bytes.len()
}

/// Deepest nesting of messages accepted on this path (the full path decides deeper ones).
const MAX_DEPTH: usize = 64;

struct Cursor<'a> {
    data: &'a [u8],
    pos: usize,
}

impl<'a> Cursor<'a> {
    /// One head: major type and argument. `None` for indefinite lengths, reserved
    /// values, truncation, and arguments not written in their shortest form.
    fn head(&mut self) -> Option<(u8, u64)> {
        let h = crate::cbor::read_head(self.data, &mut self.pos)?;
        // The shortest form: what the writer produces, and what makes the bytes unique.
        h.shortest.then_some((h.major, h.arg?))
    }

    fn take(&mut self, n: usize) -> Option<&'a [u8]> {
        let s = self.data.get(self.pos..self.pos.checked_add(n)?)?;
        self.pos += n;
        Some(s)
    }

    fn byte(&mut self) -> Option<u8> {
        let b = *self.data.get(self.pos)?;
        self.pos += 1;
        Some(b)
    }

    fn len_of(&mut self, major: u8) -> Option<usize> {
        match self.head()? {
            (m, n) if m == major => usize::try_from(n).ok(),
            _ => None,
        }
    }

    fn text(&mut self) -> Option<&'a str> {
        let n = self.len_of(3)?;
        std::str::from_utf8(self.take(n)?).ok()
    }

    fn message(&mut self, layout: &MsgLayout, depth: usize) -> Option<()> {
        if depth > MAX_DEPTH || self.len_of(5)? != layout.fields.len() {
            return None;
        }
        for f in &layout.fields {
            if self.text()? != &*f.name {
                return None;
            }
            self.field(f, depth)?;
        }
        Some(())
    }

    fn field(&mut self, f: &FieldLayout, depth: usize) -> Option<()> {
        let n = match f.array {
            ArrayKind::Single => return self.elem(&f.elem, depth),
            _ => self.array(&f.elem, depth)?,
        };
        match f.array {
            ArrayKind::Fixed(len) if n != len as usize => None,
            ArrayKind::Bounded(b) if n > b as usize => None,
            _ => Some(()),
        }
    }

    /// A sequence in the writer's form; its number of elements.
    fn array(&mut self, elem: &Elem, depth: usize) -> Option<usize> {
        let typed = |c: &mut Self, tag: u64, size: usize| -> Option<usize> {
            if c.head()? != (6, tag) {
                return None;
            }
            let n = c.len_of(2)?;
            c.take(n)?;
            (n % size == 0).then_some(n / size)
        };
        match elem {
            Elem::Scalar(s) => match s {
                Scalar::U8 => {
                    let n = self.len_of(2)?;
                    self.take(n).map(|_| n)
                }
                Scalar::I8 => typed(self, 72, 1),
                Scalar::U16 => typed(self, 69, 2),
                Scalar::U32 => typed(self, 70, 4),
                Scalar::U64 => typed(self, 71, 8),
                Scalar::I16 => typed(self, 77, 2),
                Scalar::I32 => typed(self, 78, 4),
                Scalar::I64 => typed(self, 79, 8),
                Scalar::F32 => typed(self, 85, 4),
                Scalar::F64 => typed(self, 86, 8),
                Scalar::Bool
                | Scalar::String
                | Scalar::WString
                | Scalar::Time
                | Scalar::Duration => self.items(elem, depth),
            },
            Elem::Msg(_) => self.items(elem, depth),
        }
    }

    fn items(&mut self, elem: &Elem, depth: usize) -> Option<usize> {
        let n = self.len_of(4)?;
        for _ in 0..n {
            self.elem(elem, depth)?;
        }
        Some(n)
    }

    fn elem(&mut self, elem: &Elem, depth: usize) -> Option<()> {
        let s = match elem {
            Elem::Msg(m) => return self.message(m, depth + 1),
            Elem::Scalar(s) => *s,
        };
        let int = |c: &mut Self, lo: i128, hi: i128| -> Option<()> {
            let v = match c.head()? {
                (0, n) => i128::from(n),
                (1, n) => -1 - i128::from(n),
                _ => return None,
            };
            (lo..=hi).contains(&v).then_some(())
        };
        match s {
            Scalar::Bool => matches!(self.byte()?, 0xf4 | 0xf5).then_some(()),
            Scalar::I8 => int(self, i8::MIN.into(), i8::MAX.into()),
            Scalar::U8 => int(self, 0, u8::MAX.into()),
            Scalar::I16 => int(self, i16::MIN.into(), i16::MAX.into()),
            Scalar::U16 => int(self, 0, u16::MAX.into()),
            Scalar::I32 => int(self, i32::MIN.into(), i32::MAX.into()),
            Scalar::U32 => int(self, 0, u32::MAX.into()),
            Scalar::I64 => int(self, i64::MIN.into(), i64::MAX.into()),
            Scalar::U64 => int(self, 0, u64::MAX.into()),
            // A NaN may not come back with the same bits: the full path decides.
            Scalar::F32 => {
                let b = self.take_float(0xfa, 4)?;
                let x = f32::from_be_bytes(b.try_into().ok()?);
                (!x.is_nan()).then_some(())
            }
            Scalar::F64 => {
                let b = self.take_float(0xfb, 8)?;
                let x = f64::from_be_bytes(b.try_into().ok()?);
                (!x.is_nan()).then_some(())
            }
            Scalar::String | Scalar::WString => self.text().map(|_| ()),
            Scalar::Time | Scalar::Duration => {
                let (lo, hi) = if s == Scalar::Time {
                    (0, u32::MAX.into())
                } else {
                    (i32::MIN.into(), i32::MAX.into())
                };
                if self.len_of(5)? != 2 || self.text()? != "secs" {
                    return None;
                }
                int(self, lo, hi)?;
                if self.text()? != "nsecs" {
                    return None;
                }
                int(self, lo, hi)
            }
        }
    }

    fn take_float(&mut self, first: u8, n: usize) -> Option<&'a [u8]> {
        (self.byte()? == first).then_some(())?;
        self.take(n)
    }
}
