//! The JSON envelope of a `publish`, read in place.
//!
//! Nearly every frame a rosbridge client sends is a `publish`, and its envelope is a
//! handful of keys around the message. Reading it through a serde struct spent more time
//! in serde's machinery (field matching, `Option` visitors, the raw value's validation
//! pass) than the message's own check against its type does. [`envelope`] walks the
//! object once: it takes the keys and the string values it needs as slices of the text
//! and steps over every other value while checking its syntax, so whatever it passes on
//! is well-formed JSON. It gives up (`None`) on anything unusual — escapes in a key or in
//! `op`/`topic`, a repeated key, nesting past serde_json's limit — and the caller then
//! takes the full parse, which gives the precise error or the exact reading.

use std::ops::Range;

use fleetlink_msg::json_scan::string_stop;

/// Most levels of nesting taken, the envelope's own included: serde_json refuses the
/// 128th.
const MAX_DEPTH: usize = 127;

/// What a `publish` envelope holds: `op` and `topic` as written (no escapes), the
/// positions of `msg` and `id` in the text. Other keys are checked and ignored.
#[derive(Debug, Default, PartialEq)]
pub(crate) struct Envelope<'a> {
    pub op: Option<&'a str>,
    pub topic: Option<&'a str>,
    pub msg: Option<Range<usize>>,
    pub id: Option<Range<usize>>,
}

/// Reads `text` as one JSON object with [`Envelope`]'s keys; `None` when it is not one or
/// when it holds something this reader leaves to the full parse.
pub(crate) fn envelope(text: &str) -> Option<Envelope<'_>> {
    let mut c = Cursor {
        text,
        b: text.as_bytes(),
        pos: 0,
    };
    let mut e = Envelope::default();
    if !c.eat(b'{') {
        return None;
    }
    if !c.eat(b'}') {
        loop {
            let key = c.plain_string()?;
            if !c.eat(b':') {
                return None;
            }
            match key {
                "op" => set(&mut e.op, c.plain_string()?)?,
                "topic" => set(&mut e.topic, c.plain_string()?)?,
                "msg" => set(&mut e.msg, c.value_range()?)?,
                "id" => set(&mut e.id, c.value_range()?)?,
                _ => c.value(MAX_DEPTH - 1)?,
            }
            if c.eat(b',') {
                continue;
            }
            if c.eat(b'}') {
                break;
            }
            return None;
        }
    }
    c.ws();
    (c.pos == c.b.len()).then_some(e)
}

/// Whether `text` is exactly one JSON value (whitespace around it allowed), by the same
/// rules as the envelope's: what serde_json would read, without reading it.
pub fn is_json_value(text: &[u8]) -> bool {
    let Ok(text) = std::str::from_utf8(text) else {
        return false;
    };
    let mut c = Cursor {
        text,
        b: text.as_bytes(),
        pos: 0,
    };
    if c.value(MAX_DEPTH).is_none() {
        return false;
    }
    c.ws();
    c.pos == c.b.len()
}

/// A key seen twice is left to the full parse (serde refuses it).
fn set<T>(slot: &mut Option<T>, v: T) -> Option<()> {
    if slot.is_some() {
        return None;
    }
    *slot = Some(v);
    Some(())
}

struct Cursor<'a> {
    text: &'a str,
    b: &'a [u8],
    pos: usize,
}

impl<'a> Cursor<'a> {
    #[inline(always)]
    fn ws(&mut self) {
        while let Some(b' ' | b'\t' | b'\n' | b'\r') = self.b.get(self.pos) {
            self.pos += 1;
        }
    }

    #[inline(always)]
    fn peek(&mut self) -> Option<u8> {
        self.ws();
        self.b.get(self.pos).copied()
    }

    #[inline(always)]
    fn eat(&mut self, byte: u8) -> bool {
        if self.peek() == Some(byte) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    /// A string with no escapes, as a slice of the text.
    #[inline(always)]
    fn plain_string(&mut self) -> Option<&'a str> {
        if !self.eat(b'"') {
            return None;
        }
        let start = self.pos;
        let end = string_stop(self.b, start);
        if self.b.get(end) != Some(&b'"') {
            return None;
        }
        self.pos = end + 1;
        // Both ends are ASCII quotes, so both are character boundaries.
        Some(&self.text[start..end])
    }

    /// Steps over one value and gives where it lies.
    fn value_range(&mut self) -> Option<Range<usize>> {
        self.ws();
        let start = self.pos;
        self.value(MAX_DEPTH - 1)?;
        Some(start..self.pos)
    }

    /// Steps over one value, checking its syntax. `depth` is how many more levels of
    /// nesting may open.
    fn value(&mut self, depth: usize) -> Option<()> {
        match self.peek()? {
            open @ (b'{' | b'[') => {
                // An object's members are `key: value`, an array's just values; `}` and
                // `]` are two code points after their openers.
                let (object, close) = (open == b'{', open + 2);
                self.pos += 1;
                let depth = depth.checked_sub(1)?;
                if self.eat(close) {
                    return Some(());
                }
                loop {
                    if object && (self.string().is_none() || !self.eat(b':')) {
                        return None;
                    }
                    self.value(depth)?;
                    if !self.eat(b',') {
                        return self.eat(close).then_some(());
                    }
                }
            }
            b'"' => self.string(),
            b't' => self.word(b"true"),
            b'f' => self.word(b"false"),
            b'n' => self.word(b"null"),
            b'-' | b'0'..=b'9' => self.number(),
            _ => None,
        }
    }

    fn word(&mut self, w: &[u8]) -> Option<()> {
        let end = self.pos + w.len();
        (self.b.get(self.pos..end)? == w).then(|| self.pos = end)
    }

    /// Any string: escapes checked, raw control characters refused (the text is already
    /// known to be UTF-8).
    #[inline(always)]
    fn string(&mut self) -> Option<()> {
        if !self.eat(b'"') {
            return None;
        }
        loop {
            self.pos = string_stop(self.b, self.pos);
            match *self.b.get(self.pos)? {
                b'"' => {
                    self.pos += 1;
                    return Some(());
                }
                b'\\' => match *self.b.get(self.pos + 1)? {
                    b'"' | b'\\' | b'/' | b'b' | b'f' | b'n' | b'r' | b't' => self.pos += 2,
                    b'u' => {
                        let code = self.hex4(self.pos + 2)?;
                        self.pos += 6;
                        // serde_json refuses a surrogate that is not half of a pair.
                        if (0xDC00..0xE000).contains(&code) {
                            return None;
                        }
                        if (0xD800..0xDC00).contains(&code) {
                            if self.b.get(self.pos..self.pos + 2)? != b"\\u" {
                                return None;
                            }
                            let low = self.hex4(self.pos + 2)?;
                            if !(0xDC00..0xE000).contains(&low) {
                                return None;
                            }
                            self.pos += 6;
                        }
                    }
                    _ => return None,
                },
                // A raw control character.
                _ => return None,
            }
        }
    }

    /// The value of the four hex digits of a `\u` escape at `at`.
    fn hex4(&self, at: usize) -> Option<u32> {
        let hex = self.b.get(at..at + 4)?;
        hex.iter()
            .try_fold(0u32, |v, &b| Some(v << 4 | (b as char).to_digit(16)?))
    }

    /// `-? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)?`, and within `f64`'s range
    /// as serde_json requires (it refuses `1e400` as out of range).
    fn number(&mut self) -> Option<()> {
        let start = self.pos;
        if self.b.get(self.pos) == Some(&b'-') {
            self.pos += 1;
        }
        match self.b.get(self.pos)? {
            b'0' => self.pos += 1,
            b'1'..=b'9' => self.digits(),
            _ => return None,
        }
        if self.b.get(self.pos) == Some(&b'.') {
            self.pos += 1;
            self.some_digits()?;
        }
        let mut exponent = false;
        if let Some(b'e' | b'E') = self.b.get(self.pos) {
            exponent = true;
            self.pos += 1;
            if let Some(b'+' | b'-') = self.b.get(self.pos) {
                self.pos += 1;
            }
            self.some_digits()?;
        }
        // Only an exponent or more than 300 digits can leave the range: then the value is
        // read (correctly rounded, as serde_json with `float_roundtrip` reads it).
        if exponent || self.pos - start > 300 {
            let v: f64 = self.text[start..self.pos].parse().ok()?;
            return v.is_finite().then_some(());
        }
        Some(())
    }

    fn digits(&mut self) {
        while self.b.get(self.pos).is_some_and(u8::is_ascii_digit) {
            self.pos += 1;
        }
    }

    fn some_digits(&mut self) -> Option<()> {
        let start = self.pos;
        self.digits();
        (self.pos > start).then_some(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reading this module replaced, kept as the oracle: serde over a borrowed struct.
    #[derive(serde::Deserialize)]
    struct Fields<'a> {
        #[serde(borrow)]
        op: std::borrow::Cow<'a, str>,
        #[serde(borrow, default)]
        topic: Option<&'a str>,
        #[serde(borrow, default)]
        msg: Option<&'a serde_json::value::RawValue>,
        #[serde(borrow, default)]
        id: Option<&'a serde_json::value::RawValue>,
    }

    fn span<'t>(text: &'t str, r: &Option<Range<usize>>) -> Option<&'t str> {
        r.clone().map(|r| &text[r])
    }

    /// Whatever the scan reads, serde reads the same; and it reads the usual envelopes.
    fn agrees(text: &str) -> bool {
        // serde needs `op`; the scan leaves that check to its caller, which needs it too.
        let mine = envelope(text).filter(|e| e.op.is_some());
        let theirs = serde_json::from_str::<Fields>(text).ok();
        if let Some(e) = &mine {
            let Some(f) = &theirs else {
                panic!("scan took what serde refuses: {text:?}");
            };
            // And the full parse, which reads every value (surrogate pairs, number range).
            assert!(
                serde_json::from_str::<serde_json::Value>(text).is_ok(),
                "scan took what the full parse refuses: {text:?}"
            );
            assert_eq!(e.op, Some(&*f.op), "op of {text:?}");
            assert_eq!(e.topic, f.topic, "topic of {text:?}");
            assert_eq!(
                span(text, &e.msg),
                f.msg.map(|m| m.get()),
                "msg of {text:?}"
            );
            assert_eq!(span(text, &e.id), f.id.map(|m| m.get()), "id of {text:?}");
        }
        mine.is_some()
    }

    #[test]
    fn reads_publish_envelopes_as_serde_does() {
        for text in [
            r#"{"op":"publish","topic":"/a","msg":{"data":"x"}}"#,
            r#" { "op" : "publish" , "id" : "publish:/a:1" , "topic" : "/a" , "msg" : { "data" : 1 } } "#,
            r#"{"op":"publish","topic":"/a","msg":{"a":[1,-2.5e3,0.0,true,false,null,"\u00e9\n\""],"b":{}},"latch":false}"#,
            r#"{"msg":{},"topic":"/a","op":"publish","id":{"n":[1,{"x":null}]}}"#,
            r#"{"op":"publish","topic":"/é","msg":{"s":"日本"},"extra":[[],[[]],{"k":"v"}]}"#,
            r#"{"op":"publish","topic":"/a","msg":{"emoji":"\ud83d\ude00","x":"\uFFFF"}}"#,
            "{\"op\":\"publish\",\r\n\t\"topic\":\"/a\",\"msg\":{\"e\":1E+2,\"f\":-0.5e-1}}",
        ] {
            assert!(agrees(text), "not read: {text}");
        }
    }

    #[test]
    fn leaves_what_it_does_not_take_to_the_full_parse() {
        for text in [
            // Escapes where the scan hands out slices.
            r#"{"op":"publish","topic":"\/a","msg":{}}"#,
            r#"{"o\u0070":"publish","topic":"/a","msg":{}}"#,
            // Repeated keys, trailing text, broken syntax.
            r#"{"op":"publish","topic":"/a","topic":"/b","msg":{}}"#,
            r#"{"op":"publish","topic":"/a","msg":{}} x"#,
            r#"{"op":"publish","topic":"/a","msg":{}},"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":01}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":1.}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":.5}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":-}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":1e}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":-2.5e400}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":tru}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":truex}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":"\x"}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":"\u12g4"}}"#,
            // Surrogates that are not half of a pair.
            r#"{"op":"publish","topic":"/a","msg":{"a":"\ud800"}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":"\ud800\u0041"}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":"\udc00"}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":"\ud800x"}}"#,
            "{\"op\":\"publish\",\"topic\":\"/a\",\"msg\":{\"a\":\"tab\there\"}}",
            r#"{"op":"publish","topic":"/a","msg":{"a":[1,]}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":1,}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a" 1}}"#,
            r#"{"op":"publish","topic":"/a","msg":{1:1}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"a":1}"#,
            r#"{"op":"publish","topic":"/a","msg":"#,
            r#"{"op":"publish","topic":null,"msg":{}}"#,
            r#"["op","publish"]"#,
            "",
        ] {
            assert!(!agrees(text), "read: {text}");
        }
        // Nesting: up to serde_json's limit, not past it.
        let deep = |n: usize| {
            format!(
                r#"{{"op":"publish","topic":"/a","msg":{}1{}}}"#,
                "[".repeat(n),
                "]".repeat(n)
            )
        };
        assert!(agrees(&deep(126)));
        assert!(!agrees(&deep(127)));
        assert!(!agrees(&deep(100_000)));
    }

    /// Every cut and every one-byte change of some envelopes: the scan never takes what
    /// serde refuses, nor reads anything differently.
    #[test]
    fn never_reads_what_serde_refuses() {
        let seeds = [
            r#"{"op":"publish","id":"p:1","topic":"/a/b","msg":{"data":"hi \"x\" \u00e9","n":[1,-2,3.5e-2],"o":{"t":true,"f":false,"z":null}},"latch":true}"#,
            r#" {"msg" : {"a":[[],{}]} , "op":"publish", "topic" : "/c" } "#,
        ];
        let swaps = b"{}[]\":,\\ -+.0123456789eEtfnu\n\x01aZ";
        let mut read = 0;
        for seed in seeds {
            for cut in 0..=seed.len() {
                if seed.is_char_boundary(cut) {
                    agrees(&seed[..cut]);
                }
            }
            for i in 0..seed.len() {
                for &s in swaps {
                    let mut b = seed.as_bytes().to_vec();
                    b[i] = s;
                    if let Ok(text) = std::str::from_utf8(&b) {
                        read += usize::from(agrees(text));
                    }
                }
            }
        }
        // Not a vacuous check: many of the changed envelopes are still read.
        assert!(read > 500, "only {read} read");
    }
}
