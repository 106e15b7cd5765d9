//! A small JSON text parser for the hot path JSON text → message value.
//!
//! Design choice: rosbridge clients send large numeric arrays (laser ranges, costmaps)
//! and building a `serde_json::Value` for them costs more than converting them. This
//! parser builds a light borrowed tree (strings without escapes are not copied, objects
//! are small vectors) and parses numbers with the standard library's correctly rounded
//! parser; the tree then goes through the same `loose` rules as any other input. Nesting
//! is limited so hostile input cannot exhaust the stack.

use std::borrow::Cow;

use crate::error::CodecError;
use crate::layout::{Elem, FieldLayout, MsgLayout, Scalar};
use crate::loose::{Loose, View};
use crate::spec::ArrayKind;

/// Deepest nesting accepted (serde_json uses the same limit).
const MAX_DEPTH: usize = 128;

/// One parsed JSON node, borrowing from the input where possible.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Node<'a> {
    Null,
    Bool(bool),
    Int(i128),
    Float(f64),
    Str(Cow<'a, str>),
    Array(Vec<Node<'a>>),
    /// An array of numbers with at least one fraction, exponent or `null` (NaN). The flag
    /// says every element was written with a fraction or exponent (no integer, no `null`),
    /// which is how JSON output writes a float array.
    Floats(Vec<f64>, bool),
    /// An array of integers that all fit `i64`.
    Ints(Vec<i64>),
    Object(Vec<(Cow<'a, str>, Node<'a>)>),
}

impl Loose for Node<'_> {
    fn view(&self) -> View<'_, Self> {
        match self {
            Node::Null => View::Null,
            Node::Bool(b) => View::Bool(*b),
            Node::Int(i) => View::Int(*i),
            Node::Float(f) => View::Float(*f),
            Node::Str(s) => View::Str(s),
            Node::Array(a) => View::Array(a),
            Node::Floats(f, _) => View::Floats(f),
            Node::Ints(i) => View::Ints(i),
            Node::Object(_) => View::Map,
        }
    }
    fn field(&self, name: &str) -> Option<&Self> {
        match self {
            Node::Object(fields) => fields.iter().find(|(k, _)| k == name).map(|(_, v)| v),
            _ => None,
        }
    }
    fn unknown_key(&self, known: &dyn Fn(&str) -> bool) -> Option<String> {
        let Node::Object(fields) = self else {
            return None;
        };
        fields
            .iter()
            .find(|(k, _)| !known(k))
            .map(|(k, _)| k.to_string())
    }
}

/// Parses one JSON document (surrounding whitespace allowed).
pub(crate) fn parse(text: &[u8]) -> Result<Node<'_>, CodecError> {
    let text =
        std::str::from_utf8(text).map_err(|e| syntax(e.valid_up_to(), "JSON text is not UTF-8"))?;
    let mut p = Parser {
        s: text,
        b: text.as_bytes(),
        pos: 0,
    };
    let node = p.value(0)?;
    p.ws();
    if p.pos != p.b.len() {
        return Err(syntax(p.pos, "trailing characters after the JSON value"));
    }
    Ok(node)
}

/// True when `node` already is what the JSON output of a `layout` message carries: an
/// object with exactly the type's fields, each holding a value of its exact kind
/// (integers in range for integer fields, numbers written as floats for float fields,
/// base64 text for `uint8[]`, arrays of the right length). Such text can be passed on as
/// it is: converting it would only reproduce it. Anything else (a missing field to fill
/// with its default, an integer to turn into a float, an extra field, a wrong type) is
/// not normal, and goes through the converting path, which also finds the errors.
pub(crate) fn is_normal(layout: &MsgLayout, node: &Node<'_>) -> bool {
    let Node::Object(fields) = node else {
        return false;
    };
    // Equal counts and every declared field found: no extra or repeated key.
    fields.len() == layout.fields.len()
        && layout.fields.iter().all(|f| {
            fields
                .iter()
                .find(|(k, _)| *k == *f.name)
                .is_some_and(|(_, v)| field_is_normal(f, v))
        })
}

fn field_is_normal(f: &FieldLayout, node: &Node<'_>) -> bool {
    let len_ok = |n: usize| match f.array {
        ArrayKind::Fixed(len) => n == len as usize,
        ArrayKind::Bounded(b) => n <= b as usize,
        _ => true,
    };
    match (f.array, &f.elem, node) {
        (ArrayKind::Single, elem, node) => elem_is_normal(elem, node),
        (_, Elem::Scalar(Scalar::U8), Node::Str(text)) => {
            use base64::Engine as _;
            base64::engine::general_purpose::STANDARD
                .decode(text.as_bytes())
                .is_ok_and(|b| len_ok(b.len()))
        }
        // JSON writes uint8[] as base64 text, never as numbers.
        (_, Elem::Scalar(Scalar::U8), _) => false,
        (_, Elem::Scalar(s), Node::Ints(items)) => {
            len_ok(items.len())
                && int_range(*s).is_some_and(|(lo, hi)| {
                    items.iter().all(|i| (lo..=hi).contains(&i128::from(*i)))
                })
        }
        (_, Elem::Scalar(s @ (Scalar::F32 | Scalar::F64)), Node::Floats(items, all_fractions)) => {
            *all_fractions
                && len_ok(items.len())
                && (*s == Scalar::F64 || items.iter().all(|f| f32_is_normal(*f)))
        }
        (_, elem, Node::Array(items)) => {
            len_ok(items.len()) && items.iter().all(|n| elem_is_normal(elem, n))
        }
        _ => false,
    }
}

fn elem_is_normal(elem: &Elem, node: &Node<'_>) -> bool {
    let s = match elem {
        Elem::Msg(m) => return is_normal(m, node),
        Elem::Scalar(s) => *s,
    };
    match (s, node) {
        (Scalar::Bool, Node::Bool(_)) => true,
        (Scalar::F64, Node::Float(f)) => f.is_finite(),
        (Scalar::F32, Node::Float(f)) => f32_is_normal(*f),
        (Scalar::String | Scalar::WString, Node::Str(_)) => true,
        (Scalar::Time | Scalar::Duration, Node::Object(fields)) => {
            let range = if s == Scalar::Time {
                (0, i128::from(u32::MAX))
            } else {
                (i128::from(i32::MIN), i128::from(i32::MAX))
            };
            let part = |name: &str| {
                fields.iter().find(|(k, _)| k == name).is_some_and(
                    |(_, v)| matches!(v, Node::Int(i) if (range.0..=range.1).contains(i)),
                )
            };
            fields.len() == 2 && part("secs") && part("nsecs")
        }
        (s, Node::Int(i)) => int_range(s).is_some_and(|(lo, hi)| (lo..=hi).contains(i)),
        _ => false,
    }
}

/// A `float32` value is written in its shortest `f32` form: `0.1`, never
/// `0.10000000149011612`, and never a value `f32` cannot hold.
fn f32_is_normal(f: f64) -> bool {
    f.is_finite() && crate::json::f32_as_f64(f as f32) == f
}

/// The range of an integer scalar; `None` for the others.
fn int_range(s: Scalar) -> Option<(i128, i128)> {
    Some(match s {
        Scalar::I8 => (i8::MIN.into(), i8::MAX.into()),
        Scalar::U8 => (0, u8::MAX.into()),
        Scalar::I16 => (i16::MIN.into(), i16::MAX.into()),
        Scalar::U16 => (0, u16::MAX.into()),
        Scalar::I32 => (i32::MIN.into(), i32::MAX.into()),
        Scalar::U32 => (0, u32::MAX.into()),
        Scalar::I64 => (i64::MIN.into(), i64::MAX.into()),
        Scalar::U64 => (0, u64::MAX.into()),
        _ => return None,
    })
}

fn syntax(offset: usize, reason: &str) -> CodecError {
    CodecError::JsonSyntax {
        offset,
        reason: reason.to_owned(),
    }
}

struct Parser<'a> {
    s: &'a str,
    b: &'a [u8],
    pos: usize,
}

impl<'a> Parser<'a> {
    fn ws(&mut self) {
        while let Some(b' ' | b'\n' | b'\r' | b'\t') = self.b.get(self.pos) {
            self.pos += 1;
        }
    }

    fn eat(&mut self, lit: &str) -> bool {
        if self.s[self.pos..].starts_with(lit) {
            self.pos += lit.len();
            true
        } else {
            false
        }
    }

    fn value(&mut self, depth: usize) -> Result<Node<'a>, CodecError> {
        if depth > MAX_DEPTH {
            return Err(syntax(self.pos, "JSON nested too deeply"));
        }
        self.ws();
        match self.b.get(self.pos) {
            None => Err(CodecError::Incomplete {
                path: String::new(),
                offset: self.pos,
                needed: 1,
                available: 0,
            }),
            Some(b'{') => self.object(depth),
            Some(b'[') => self.array(depth),
            Some(b'"') => self.string().map(Node::Str),
            Some(b'-' | b'0'..=b'9') => self.number(),
            Some(_) if self.eat("null") => Ok(Node::Null),
            Some(_) if self.eat("true") => Ok(Node::Bool(true)),
            Some(_) if self.eat("false") => Ok(Node::Bool(false)),
            // Python's json module writes these for non-finite floats.
            Some(_) if self.eat("NaN") => Ok(Node::Float(f64::NAN)),
            Some(_) if self.eat("Infinity") => Ok(Node::Float(f64::INFINITY)),
            Some(_) => Err(syntax(self.pos, "expected a JSON value")),
        }
    }

    fn array(&mut self, depth: usize) -> Result<Node<'a>, CodecError> {
        self.pos += 1;
        let mut items = Vec::new();
        self.ws();
        if self.eat("]") {
            return Ok(Node::Array(items));
        }
        let start = self.pos;
        if let Some(numbers) = self.numbers()? {
            return Ok(numbers);
        }
        self.pos = start;
        loop {
            items.push(self.value(depth + 1)?);
            self.ws();
            if self.eat(",") {
                continue;
            }
            if self.eat("]") {
                return Ok(Node::Array(items));
            }
            return Err(self.end_or(", or ] in an array"));
        }
    }

    /// Parses the rest of an array as plain numbers (and `null` as NaN) into a compact
    /// vector; `None` (position unspecified) if an element is anything else.
    fn numbers(&mut self) -> Result<Option<Node<'a>>, CodecError> {
        // Integers beyond this are not exact as f64, so they stay on the general path.
        const EXACT: i64 = 1 << 53;
        let mut ints: Vec<i64> = Vec::new();
        let mut floats: Option<Vec<f64>> = None;
        let mut all_fractions = true;
        loop {
            self.ws();
            let float = if self.eat("null") {
                all_fractions = false;
                f64::NAN
            } else {
                let start = self.pos;
                let mut is_float = false;
                while let Some(&c) = self.b.get(self.pos) {
                    match c {
                        b'0'..=b'9' | b'-' | b'+' => {}
                        b'.' | b'e' | b'E' => is_float = true,
                        _ => break,
                    }
                    self.pos += 1;
                }
                let text = &self.s[start..self.pos];
                if text.is_empty() {
                    return Ok(None);
                }
                if is_float {
                    match text.parse::<f64>() {
                        Ok(f) => f,
                        Err(_) => return Ok(None),
                    }
                } else {
                    let Ok(i) = text.parse::<i64>() else {
                        return Ok(None);
                    };
                    match &mut floats {
                        None => {
                            ints.push(i);
                            self.ws();
                            if self.eat(",") {
                                continue;
                            }
                            if self.eat("]") {
                                return Ok(Some(Node::Ints(ints)));
                            }
                            return Ok(None);
                        }
                        Some(_) if i.abs() > EXACT => return Ok(None),
                        Some(_) => {
                            all_fractions = false;
                            i as f64
                        }
                    }
                }
            };
            let fs = match &mut floats {
                Some(fs) => fs,
                None => {
                    if ints.iter().any(|i| i.abs() > EXACT) {
                        return Ok(None);
                    }
                    all_fractions &= ints.is_empty();
                    floats.insert(ints.iter().map(|i| *i as f64).collect())
                }
            };
            fs.push(float);
            self.ws();
            if self.eat(",") {
                continue;
            }
            if self.eat("]") {
                return Ok(floats.map(|f| Node::Floats(f, all_fractions)));
            }
            return Ok(None);
        }
    }

    fn object(&mut self, depth: usize) -> Result<Node<'a>, CodecError> {
        self.pos += 1;
        let mut fields = Vec::new();
        self.ws();
        if self.eat("}") {
            return Ok(Node::Object(fields));
        }
        loop {
            self.ws();
            if self.b.get(self.pos) != Some(&b'"') {
                return Err(self.end_or("a string key in an object"));
            }
            let key = self.string()?;
            self.ws();
            if !self.eat(":") {
                return Err(self.end_or(": after an object key"));
            }
            let v = self.value(depth + 1)?;
            fields.push((key, v));
            self.ws();
            if self.eat(",") {
                continue;
            }
            if self.eat("}") {
                return Ok(Node::Object(fields));
            }
            return Err(self.end_or(", or } in an object"));
        }
    }

    fn end_or(&self, expected: &str) -> CodecError {
        if self.pos >= self.b.len() {
            CodecError::Incomplete {
                path: String::new(),
                offset: self.pos,
                needed: 1,
                available: 0,
            }
        } else {
            syntax(self.pos, &format!("expected {expected}"))
        }
    }

    fn number(&mut self) -> Result<Node<'a>, CodecError> {
        let start = self.pos;
        if self.eat("-Infinity") {
            return Ok(Node::Float(f64::NEG_INFINITY));
        }
        let mut float = false;
        while let Some(&c) = self.b.get(self.pos) {
            match c {
                b'0'..=b'9' | b'-' | b'+' => {}
                b'.' | b'e' | b'E' => float = true,
                _ => break,
            }
            self.pos += 1;
        }
        let text = &self.s[start..self.pos];
        if !float && let Ok(i) = text.parse::<i128>() {
            return Ok(Node::Int(i));
        }
        text.parse::<f64>()
            .map(Node::Float)
            .map_err(|_| syntax(start, "invalid number"))
    }

    fn string(&mut self) -> Result<Cow<'a, str>, CodecError> {
        let start = self.pos + 1;
        let mut i = start;
        // Fast path: no escapes, borrow the slice.
        while let Some(&c) = self.b.get(i) {
            match c {
                b'"' => {
                    self.pos = i + 1;
                    return Ok(Cow::Borrowed(&self.s[start..i]));
                }
                b'\\' => break,
                0x00..=0x1f => return Err(syntax(i, "control character in a string")),
                _ => i += 1,
            }
        }
        let mut out = String::from(&self.s[start..i.min(self.b.len())]);
        loop {
            let Some(&c) = self.b.get(i) else {
                return Err(CodecError::Incomplete {
                    path: String::new(),
                    offset: i,
                    needed: 1,
                    available: 0,
                });
            };
            match c {
                b'"' => {
                    self.pos = i + 1;
                    return Ok(Cow::Owned(out));
                }
                b'\\' => {
                    let esc = *self
                        .b
                        .get(i + 1)
                        .ok_or_else(|| syntax(i, "unterminated escape"))?;
                    i += 2;
                    match esc {
                        b'"' => out.push('"'),
                        b'\\' => out.push('\\'),
                        b'/' => out.push('/'),
                        b'b' => out.push('\u{8}'),
                        b'f' => out.push('\u{c}'),
                        b'n' => out.push('\n'),
                        b'r' => out.push('\r'),
                        b't' => out.push('\t'),
                        b'u' => {
                            let hi = self.hex4(i)?;
                            i += 4;
                            let code = if (0xD800..0xDC00).contains(&hi) {
                                if self.b.get(i..i + 2) != Some(b"\\u") {
                                    return Err(syntax(i, "lone high surrogate"));
                                }
                                let lo = self.hex4(i + 2)?;
                                i += 6;
                                if !(0xDC00..0xE000).contains(&lo) {
                                    return Err(syntax(i, "invalid low surrogate"));
                                }
                                0x10000 + ((hi - 0xD800) << 10) + (lo - 0xDC00)
                            } else {
                                hi
                            };
                            out.push(
                                char::from_u32(code)
                                    .ok_or_else(|| syntax(i, "invalid \\u escape"))?,
                            );
                        }
                        _ => return Err(syntax(i - 1, "invalid escape")),
                    }
                }
                0x00..=0x1f => return Err(syntax(i, "control character in a string")),
                _ => {
                    // Copy one UTF-8 character (the input is valid UTF-8).
                    let ch = self.s[i..]
                        .chars()
                        .next()
                        .ok_or_else(|| syntax(i, "bad UTF-8"))?;
                    out.push(ch);
                    i += ch.len_utf8();
                }
            }
        }
    }

    fn hex4(&self, at: usize) -> Result<u32, CodecError> {
        let h = self
            .s
            .get(at..at + 4)
            .ok_or_else(|| syntax(at, "short \\u escape"))?;
        u32::from_str_radix(h, 16).map_err(|_| syntax(at, "invalid \\u escape"))
    }
}

/// [`parse`] and [`is_normal`] in one pass over the text, building nothing: `true` only
/// when the text is a JSON object in normal form for `layout`. It is stricter than the
/// two together (it also wants the JSON number grammar, finite floats everywhere) and
/// gives up on what it does not handle — escapes in strings, `NaN`/`Infinity`, integers
/// too long for `i128`, layouts of more than 64 fields — so `false` means "take the full
/// path", which then decides. The publish hot path: most messages are in normal form.
pub(crate) fn is_normal_text(layout: &MsgLayout, text: &[u8]) -> bool {
    let mut c = Check { b: text, pos: 0 };
    let ok = c.msg(layout, 0);
    c.ws();
    ok && c.pos == text.len()
}

struct Check<'a> {
    b: &'a [u8],
    pos: usize,
}

impl<'a> Check<'a> {
    #[inline(always)]
    fn ws(&mut self) {
        while let Some(b' ' | b'\n' | b'\r' | b'\t') = self.b.get(self.pos) {
            self.pos += 1;
        }
    }

    /// Skips whitespace, then takes `byte` if it is next.
    #[inline(always)]
    fn eat(&mut self, byte: u8) -> bool {
        self.ws();
        if self.b.get(self.pos) == Some(&byte) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    fn lit(&mut self, word: &[u8]) -> bool {
        if self.b[self.pos..].starts_with(word) {
            self.pos += word.len();
            true
        } else {
            false
        }
    }

    /// The bytes of a string without escapes or control characters, not checked as UTF-8:
    /// for keys and names compared with ASCII ones, which need no check.
    #[inline(always)]
    fn plain_bytes(&mut self) -> Option<&'a [u8]> {
        self.ws();
        if self.b.get(self.pos) != Some(&b'"') {
            return None;
        }
        let start = self.pos + 1;
        let end = crate::json_scan::string_stop(self.b, start);
        if self.b.get(end) != Some(&b'"') {
            return None;
        }
        self.pos = end + 1;
        Some(&self.b[start..end])
    }

    /// A number in JSON's grammar: its text, and whether it has a fraction or exponent.
    fn number(&mut self) -> Option<(&'a str, bool)> {
        self.ws();
        let start = self.pos;
        let digits = |c: &mut Self| {
            let from = c.pos;
            while c.b.get(c.pos).is_some_and(u8::is_ascii_digit) {
                c.pos += 1;
            }
            c.pos > from
        };
        if self.b.get(self.pos) == Some(&b'-') {
            self.pos += 1;
        }
        match self.b.get(self.pos) {
            Some(b'0') => self.pos += 1,
            Some(b'1'..=b'9') => {
                digits(self);
            }
            _ => return None,
        }
        let mut float = false;
        if self.b.get(self.pos) == Some(&b'.') {
            self.pos += 1;
            float = true;
            if !digits(self) {
                return None;
            }
        }
        if let Some(b'e' | b'E') = self.b.get(self.pos) {
            self.pos += 1;
            float = true;
            if let Some(b'+' | b'-') = self.b.get(self.pos) {
                self.pos += 1;
            }
            if !digits(self) {
                return None;
            }
        }
        // ASCII by construction.
        Some((std::str::from_utf8(&self.b[start..self.pos]).ok()?, float))
    }

    /// A number written as a float, finite.
    fn float(&mut self) -> Option<f64> {
        match self.number()? {
            (text, true) => text.parse::<f64>().ok().filter(|f| f.is_finite()),
            _ => None,
        }
    }

    fn int(&mut self) -> Option<i128> {
        match self.number()? {
            (text, false) => text.parse().ok(),
            _ => None,
        }
    }

    /// An object with exactly the layout's fields, once each, every one normal.
    fn msg(&mut self, layout: &MsgLayout, depth: usize) -> bool {
        if depth > MAX_DEPTH || layout.fields.len() > 64 || !self.eat(b'{') {
            return false;
        }
        let mut seen = 0u64;
        if !self.eat(b'}') {
            loop {
                let Some(key) = self.plain_bytes() else {
                    return false;
                };
                let Some(i) = layout.fields.iter().position(|f| f.name.as_bytes() == key) else {
                    return false;
                };
                if seen & (1 << i) != 0 || !self.eat(b':') {
                    return false;
                }
                seen |= 1 << i;
                if !self.field(&layout.fields[i], depth) {
                    return false;
                }
                if self.eat(b',') {
                    continue;
                }
                if self.eat(b'}') {
                    break;
                }
                return false;
            }
        }
        seen.count_ones() as usize == layout.fields.len()
    }

    fn field(&mut self, f: &FieldLayout, depth: usize) -> bool {
        if matches!(f.array, ArrayKind::Single) {
            return self.elem(&f.elem, depth);
        }
        let len_ok = |n: usize| match f.array {
            ArrayKind::Fixed(len) => n == len as usize,
            ArrayKind::Bounded(b) => n <= b as usize,
            _ => true,
        };
        if let Elem::Scalar(Scalar::U8) = f.elem {
            // JSON writes uint8[] as base64 text.
            use base64::Engine as _;
            return self.plain_bytes().is_some_and(|text| {
                base64::engine::general_purpose::STANDARD
                    .decode(text)
                    .is_ok_and(|b| len_ok(b.len()))
            });
        }
        if !self.eat(b'[') {
            return false;
        }
        let mut n = 0usize;
        if !self.eat(b']') {
            loop {
                if !self.elem(&f.elem, depth) {
                    return false;
                }
                n += 1;
                if self.eat(b',') {
                    continue;
                }
                if self.eat(b']') {
                    break;
                }
                return false;
            }
        }
        len_ok(n)
    }

    fn elem(&mut self, elem: &Elem, depth: usize) -> bool {
        let s = match elem {
            Elem::Msg(m) => return self.msg(m, depth + 1),
            Elem::Scalar(s) => *s,
        };
        self.ws();
        match s {
            Scalar::Bool => self.lit(b"true") || self.lit(b"false"),
            Scalar::F64 => self.float().is_some(),
            Scalar::F32 => self.float().is_some_and(f32_is_normal),
            // ASCII, as most strings are, needs no UTF-8 check.
            Scalar::String | Scalar::WString => self
                .plain_bytes()
                .is_some_and(|s| s.is_ascii() || std::str::from_utf8(s).is_ok()),
            Scalar::Time | Scalar::Duration => {
                let (lo, hi) = if s == Scalar::Time {
                    (0, i128::from(u32::MAX))
                } else {
                    (i128::from(i32::MIN), i128::from(i32::MAX))
                };
                let part = |c: &mut Self| c.int().is_some_and(|i| (lo..=hi).contains(&i));
                if !self.eat(b'{') {
                    return false;
                }
                let (mut secs, mut nsecs) = (false, false);
                for i in 0..2 {
                    let slot = match self.plain_bytes() {
                        Some(b"secs") if !secs => &mut secs,
                        Some(b"nsecs") if !nsecs => &mut nsecs,
                        _ => return false,
                    };
                    if !self.eat(b':') || !part(self) {
                        return false;
                    }
                    *slot = true;
                    if i == 0 && !self.eat(b',') {
                        return false;
                    }
                }
                self.eat(b'}')
            }
            s => match (int_range(s), self.int()) {
                (Some((lo, hi)), Some(i)) => (lo..=hi).contains(&i),
                _ => false,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    impl Node<'_> {
        /// NaN != NaN; swap NaN for a marker so test comparisons work.
        fn clone_nan_free(self) -> Self {
            match self {
                Node::Floats(v, exact) => Node::Floats(
                    v.into_iter()
                        .map(|f| if f.is_nan() { -0.123 } else { f })
                        .collect(),
                    exact,
                ),
                other => other,
            }
        }
    }

    #[test]
    fn parses_what_serde_json_parses() {
        let text = br#" {"a": [1, -2, 3.5e2, null, true, false], "s": "x\"\u00e9\ud83d\ude80", "o": {}, "e": []} "#;
        let ours = parse(text).expect("parses");
        let theirs: serde_json::Value = serde_json::from_slice(text).expect("parses");
        assert_eq!(
            ours.field("s")
                .map(|n| n.view())
                .and_then(|v| match v {
                    View::Str(s) => Some(s.to_owned()),
                    _ => None,
                })
                .as_deref(),
            theirs["s"].as_str()
        );
        let Some(Node::Array(a)) = ours.field("a") else {
            panic!("mixed array")
        };
        assert_eq!(a[2], Node::Float(350.0));
        assert_eq!(a[1], Node::Int(-2));
        assert_eq!(
            parse(b"[1, 2.5, null]").expect("floats").clone_nan_free(),
            Node::Floats(vec![1.0, 2.5, f64::NAN], false).clone_nan_free()
        );
        assert_eq!(parse(b"[1, -2]").expect("ints"), Node::Ints(vec![1, -2]));
        let big = parse(b"[9007199254740993, 0.5]").expect("parses");
        assert!(
            matches!(big, Node::Array(_)),
            "inexact integers keep the general form"
        );
    }

    /// The one-pass check against parse + `is_normal`: never more lenient, and equal on
    /// text without the things it leaves to the full path.
    #[test]
    fn one_pass_normal_check_agrees_with_the_tree() {
        let reg = crate::Registry::bundled();
        let layout = |ty: &str, d| reg.resolve(ty, d).expect(ty).layout;
        let ros2 = crate::Dialect::Ros2;
        let cases: &[(&str, crate::Dialect, &str, bool)] = &[
            ("std_msgs/msg/String", ros2, r#"{"data":"hi"}"#, true),
            ("std_msgs/msg/String", ros2, r#" { "data" : "hi" } "#, true),
            ("std_msgs/msg/String", ros2, r#"{}"#, false),
            (
                "std_msgs/msg/String",
                ros2,
                r#"{"data":"hi","data":"x"}"#,
                false,
            ),
            ("std_msgs/msg/String", ros2, r#"{"data":"hi","x":1}"#, false),
            ("std_msgs/msg/String", ros2, r#"{"data":7}"#, false),
            ("std_msgs/msg/String", ros2, r#"{"data":"hi"} x"#, false),
            ("std_msgs/msg/String", ros2, r#"{"data":"hi""#, false),
            ("std_msgs/msg/Int32", ros2, r#"{"data":-5}"#, true),
            ("std_msgs/msg/Int32", ros2, r#"{"data":2147483648}"#, false),
            ("std_msgs/msg/Int32", ros2, r#"{"data":5.0}"#, false),
            ("std_msgs/msg/Int32", ros2, r#"{"data":"5"}"#, false),
            (
                "std_msgs/msg/UInt64",
                ros2,
                r#"{"data":18446744073709551615}"#,
                true,
            ),
            ("std_msgs/msg/Float64", ros2, r#"{"data":1.5e3}"#, true),
            ("std_msgs/msg/Float64", ros2, r#"{"data":1}"#, false),
            ("std_msgs/msg/Float32", ros2, r#"{"data":0.1}"#, true),
            (
                "std_msgs/msg/Float32",
                ros2,
                r#"{"data":0.10000000149011612}"#,
                false,
            ),
            ("std_msgs/msg/Bool", ros2, r#"{"data":true}"#, true),
            ("std_msgs/msg/Bool", ros2, r#"{"data":1}"#, false),
            (
                "geometry_msgs/msg/Twist",
                ros2,
                r#"{"linear":{"x":1.0,"y":0.0,"z":0.0},"angular":{"x":0.0,"y":0.0,"z":-0.5}}"#,
                true,
            ),
            (
                "geometry_msgs/msg/Twist",
                ros2,
                r#"{"linear":{"x":1,"y":0.0,"z":0.0},"angular":{"x":0.0,"y":0.0,"z":-0.5}}"#,
                false,
            ),
            (
                "geometry_msgs/msg/Twist",
                ros2,
                r#"{"linear":{"x":1.0,"y":0.0,"z":0.0}}"#,
                false,
            ),
            (
                "std_msgs/msg/Header",
                ros2,
                r#"{"stamp":{"sec":1,"nanosec":2},"frame_id":"map"}"#,
                true,
            ),
            (
                "std_msgs/msg/Float64MultiArray",
                ros2,
                r#"{"layout":{"dim":[],"data_offset":0},"data":[1.5,2.0,-3e-2]}"#,
                true,
            ),
            (
                "std_msgs/msg/Float64MultiArray",
                ros2,
                r#"{"layout":{"dim":[],"data_offset":0},"data":[1.5,2]}"#,
                false,
            ),
            (
                "std_msgs/msg/Float64MultiArray",
                ros2,
                r#"{"layout":{"dim":[],"data_offset":0},"data":[1.5,null]}"#,
                false,
            ),
            (
                "std_msgs/msg/Float64MultiArray",
                ros2,
                r#"{"layout":{"dim":[],"data_offset":0},"data":[]}"#,
                true,
            ),
            (
                "std_msgs/msg/Int8MultiArray",
                ros2,
                r#"{"layout":{"dim":[{"label":"a","size":2,"stride":2}],"data_offset":0},"data":[1,-128]}"#,
                true,
            ),
            (
                "std_msgs/msg/Int8MultiArray",
                ros2,
                r#"{"layout":{"dim":[],"data_offset":0},"data":[1,128]}"#,
                false,
            ),
            (
                "std_msgs/msg/UInt8MultiArray",
                ros2,
                r#"{"layout":{"dim":[],"data_offset":0},"data":"AQID"}"#,
                true,
            ),
            (
                "std_msgs/msg/UInt8MultiArray",
                ros2,
                r#"{"layout":{"dim":[],"data_offset":0},"data":[1,2,3]}"#,
                false,
            ),
            (
                "std_msgs/msg/UInt8MultiArray",
                ros2,
                r#"{"layout":{"dim":[],"data_offset":0},"data":"A!ID"}"#,
                false,
            ),
            (
                "geometry_msgs/msg/PoseWithCovariance",
                ros2,
                &format!(
                    r#"{{"pose":{{"position":{{"x":0.0,"y":0.0,"z":0.0}},"orientation":{{"x":0.0,"y":0.0,"z":0.0,"w":1.0}}}},"covariance":[{}]}}"#,
                    vec!["0.5"; 36].join(",")
                ),
                true,
            ),
            (
                "geometry_msgs/msg/PoseWithCovariance",
                ros2,
                &format!(
                    r#"{{"pose":{{"position":{{"x":0.0,"y":0.0,"z":0.0}},"orientation":{{"x":0.0,"y":0.0,"z":0.0,"w":1.0}}}},"covariance":[{}]}}"#,
                    vec!["0.5"; 35].join(",")
                ),
                false,
            ),
        ];
        for (ty, d, text, expect) in cases {
            let l = layout(ty, *d);
            let quick = is_normal_text(&l, text.as_bytes());
            let tree = parse(text.as_bytes()).is_ok_and(|n| is_normal(&l, &n));
            assert_eq!(quick, *expect, "{ty}: {text}");
            assert_eq!(quick, tree, "the tree disagrees on {ty}: {text}");
        }
        // Left to the full path (which accepts them): escapes, integers beyond i128.
        let s = layout("std_msgs/msg/String", ros2);
        assert!(!is_normal_text(&s, br#"{"data":"a\nb"}"#));
        assert!(parse(br#"{"data":"a\nb"}"#).is_ok_and(|n| is_normal(&s, &n)));
        // ROS 1 time, written as rosbridge on ROS 1 writes it; ROS 2's names are not
        // its normal form (they are rewritten).
        let h1 = layout("std_msgs/Header", crate::Dialect::Ros1);
        let text = br#"{"seq":3,"stamp":{"secs":1,"nsecs":2},"frame_id":""}"#;
        assert!(is_normal_text(&h1, text));
        assert!(parse(text).is_ok_and(|n| is_normal(&h1, &n)));
        let ros2_names = br#"{"seq":3,"stamp":{"sec":1,"nanosec":2},"frame_id":""}"#;
        assert!(!is_normal_text(&h1, ros2_names));
        assert!(!parse(ros2_names).is_ok_and(|n| is_normal(&h1, &n)));
        assert!(!is_normal_text(
            &h1,
            br#"{"seq":3,"stamp":{"secs":1},"frame_id":""}"#
        ));
        assert!(!is_normal_text(
            &h1,
            br#"{"seq":3,"stamp":{"secs":1,"secs":2},"frame_id":""}"#
        ));
    }

    #[test]
    fn rejects_bad_json_and_deep_nesting() {
        for bad in [
            &b"{"[..],
            b"[1,]",
            b"{\"a\" 1}",
            b"\"\\x\"",
            b"01x",
            b"[1] 2",
            b"\"\\ud800\"",
        ] {
            assert!(parse(bad).is_err(), "{}", String::from_utf8_lossy(bad));
        }
        let deep = "[".repeat(100_000);
        assert!(parse(deep.as_bytes()).is_err());
        assert!(parse(b"[1, 2").expect_err("short").is_incomplete());
    }
}
