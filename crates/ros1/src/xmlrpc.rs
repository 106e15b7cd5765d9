//! XML-RPC values, method calls and responses: the encoding of the ROS 1 master and slave
//! APIs.
//!
//! Design choice: a small encoder/decoder of our own rather than a crate. The maintained
//! Rust XML-RPC crates are blocking HTTP clients (reqwest/ureq) with no server side; the
//! ROS APIs use a handful of value types (`int`, `boolean`, `string`, `double`, `array`,
//! `struct`) in messages of a few hundred bytes, which a strict little parser covers. Input
//! comes from the network, so nothing here panics on bad data: every problem is a
//! [`XmlRpcError`] saying what was expected where, and nesting is capped.
//!
//! ```text
//! <methodCall><methodName>requestTopic</methodName>
//!   <params><param><value><string>/caller</string></value></param>…</params>
//! </methodCall>
//! <methodResponse><params><param><value><array><data>
//!   <value><int>1</int></value> <value>ready</value> <value>…</value>
//! </data></array></value></param></params></methodResponse>
//! ```

use std::fmt::Write as _;

/// Deepest nesting of arrays/structs accepted (ROS values nest three levels at most).
const MAX_DEPTH: usize = 32;

/// An XML-RPC value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Int(i32),
    Bool(bool),
    Str(String),
    Double(f64),
    Array(Vec<Value>),
    Struct(Vec<(String, Value)>),
    /// `base64`, `dateTime.iso8601` and `nil` are kept as their text: ROS never sends
    /// them to a node, and a caller that does gets a clear "wrong type" later.
    Other(String),
}

impl Value {
    pub fn as_i32(&self) -> Option<i32> {
        match self {
            Value::Int(i) => Some(*i),
            _ => None,
        }
    }

    pub fn as_str(&self) -> Option<&str> {
        match self {
            Value::Str(s) => Some(s),
            _ => None,
        }
    }

    pub fn as_array(&self) -> Option<&[Value]> {
        match self {
            Value::Array(a) => Some(a),
            _ => None,
        }
    }

    /// An array of strings (`["/a", "/b"]`), `None` if anything else is in it.
    pub fn as_str_list(&self) -> Option<Vec<String>> {
        self.as_array()?
            .iter()
            .map(|v| v.as_str().map(str::to_owned))
            .collect()
    }
}

impl From<&str> for Value {
    fn from(s: &str) -> Value {
        Value::Str(s.to_owned())
    }
}

impl From<String> for Value {
    fn from(s: String) -> Value {
        Value::Str(s)
    }
}

impl From<i32> for Value {
    fn from(i: i32) -> Value {
        Value::Int(i)
    }
}

/// A decoded `methodCall`.
#[derive(Debug, Clone, PartialEq)]
pub struct Call {
    pub method: String,
    pub params: Vec<Value>,
}

/// Why a document could not be decoded. `Incomplete` means the text ended early (a
/// truncated body); `Invalid` means it can never be valid.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum XmlRpcError {
    #[error("XML-RPC document ends early: {0}")]
    Incomplete(String),
    #[error("invalid XML-RPC at byte {at}: {reason}")]
    Invalid { at: usize, reason: String },
    #[error("XML-RPC fault {code}: {text}")]
    Fault { code: i32, text: String },
}

// ---------------------------------------------------------------------------------------
// Encoding

fn escape_into(out: &mut String, text: &str) {
    for c in text.chars() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '"' => out.push_str("&quot;"),
            c => out.push(c),
        }
    }
}

fn value_into(out: &mut String, v: &Value) {
    out.push_str("<value>");
    match v {
        Value::Int(i) => {
            let _ = write!(out, "<i4>{i}</i4>");
        }
        Value::Bool(b) => {
            let _ = write!(out, "<boolean>{}</boolean>", u8::from(*b));
        }
        Value::Str(s) | Value::Other(s) => {
            out.push_str("<string>");
            escape_into(out, s);
            out.push_str("</string>");
        }
        Value::Double(d) => {
            let _ = write!(out, "<double>{d:?}</double>");
        }
        Value::Array(items) => {
            out.push_str("<array><data>");
            for i in items {
                value_into(out, i);
            }
            out.push_str("</data></array>");
        }
        Value::Struct(members) => {
            out.push_str("<struct>");
            for (name, v) in members {
                out.push_str("<member><name>");
                escape_into(out, name);
                out.push_str("</name>");
                value_into(out, v);
                out.push_str("</member>");
            }
            out.push_str("</struct>");
        }
    }
    out.push_str("</value>");
}

/// A `methodCall` document.
pub fn encode_call(method: &str, params: &[Value]) -> String {
    let mut out = String::with_capacity(256);
    out.push_str("<?xml version=\"1.0\"?>\n<methodCall><methodName>");
    escape_into(&mut out, method);
    out.push_str("</methodName><params>");
    for p in params {
        out.push_str("<param>");
        value_into(&mut out, p);
        out.push_str("</param>");
    }
    out.push_str("</params></methodCall>\n");
    out
}

/// A successful `methodResponse` carrying `value`.
pub fn encode_response(value: &Value) -> String {
    let mut out = String::with_capacity(256);
    out.push_str("<?xml version=\"1.0\"?>\n<methodResponse><params><param>");
    value_into(&mut out, value);
    out.push_str("</param></params></methodResponse>\n");
    out
}

/// A fault `methodResponse` (an unknown method, unusable parameters).
pub fn encode_fault(code: i32, text: &str) -> String {
    let mut out = String::with_capacity(256);
    out.push_str("<?xml version=\"1.0\"?>\n<methodResponse><fault>");
    value_into(
        &mut out,
        &Value::Struct(vec![
            ("faultCode".into(), Value::Int(code)),
            ("faultString".into(), Value::Str(text.into())),
        ]),
    );
    out.push_str("</fault></methodResponse>\n");
    out
}

// ---------------------------------------------------------------------------------------
// Decoding

#[derive(Debug, PartialEq)]
enum Token<'a> {
    Open(&'a str),
    Close(&'a str),
    /// `<tag/>`
    Empty(&'a str),
    Text(&'a str),
}

struct Lexer<'a> {
    src: &'a str,
    pos: usize,
    peeked: Option<(usize, Token<'a>)>,
}

impl<'a> Lexer<'a> {
    fn new(src: &'a str) -> Self {
        Lexer {
            src,
            pos: 0,
            peeked: None,
        }
    }

    fn invalid<T>(&self, at: usize, reason: impl Into<String>) -> Result<T, XmlRpcError> {
        Err(XmlRpcError::Invalid {
            at,
            reason: reason.into(),
        })
    }

    fn raw_next(&mut self) -> Result<Option<(usize, Token<'a>)>, XmlRpcError> {
        loop {
            let rest = &self.src[self.pos..];
            if rest.is_empty() {
                return Ok(None);
            }
            let start = self.pos;
            if let Some(after) = rest.strip_prefix('<') {
                if after.starts_with('?') || after.starts_with("!--") {
                    let end = if after.starts_with('?') { "?>" } else { "-->" };
                    match rest.find(end) {
                        Some(i) => {
                            self.pos += i + end.len();
                            continue;
                        }
                        None => return Err(XmlRpcError::Incomplete("unclosed <? or <!--".into())),
                    }
                }
                let Some(close) = rest.find('>') else {
                    return Err(XmlRpcError::Incomplete("unclosed tag".into()));
                };
                let inner = &rest[1..close];
                self.pos += close + 1;
                if let Some(name) = inner.strip_prefix('/') {
                    return Ok(Some((start, Token::Close(name.trim()))));
                }
                if let Some(name) = inner.strip_suffix('/') {
                    return Ok(Some((start, Token::Empty(tag_name(name)))));
                }
                return Ok(Some((start, Token::Open(tag_name(inner)))));
            }
            let end = rest.find('<').unwrap_or(rest.len());
            self.pos += end;
            return Ok(Some((start, Token::Text(&rest[..end]))));
        }
    }

    fn next(&mut self) -> Result<Option<(usize, Token<'a>)>, XmlRpcError> {
        if let Some(t) = self.peeked.take() {
            return Ok(Some(t));
        }
        self.raw_next()
    }

    fn peek(&mut self) -> Result<Option<&(usize, Token<'a>)>, XmlRpcError> {
        if self.peeked.is_none() {
            self.peeked = self.raw_next()?;
        }
        Ok(self.peeked.as_ref())
    }

    /// The next token that is not whitespace-only text.
    fn next_tag(&mut self) -> Result<(usize, Token<'a>), XmlRpcError> {
        loop {
            match self.next()? {
                None => return Err(XmlRpcError::Incomplete("expected a tag".into())),
                Some((_, Token::Text(t))) if t.trim().is_empty() => continue,
                Some(t) => return Ok(t),
            }
        }
    }

    fn skip_space(&mut self) -> Result<(), XmlRpcError> {
        while let Some((_, Token::Text(t))) = self.peek()? {
            if !t.trim().is_empty() {
                break;
            }
            self.peeked = None;
        }
        Ok(())
    }

    fn expect_open(&mut self, name: &str) -> Result<(), XmlRpcError> {
        match self.next_tag()? {
            (_, Token::Open(n)) if n == name => Ok(()),
            (at, t) => self.invalid(at, format!("expected <{name}>, found {t:?}")),
        }
    }

    fn expect_close(&mut self, name: &str) -> Result<(), XmlRpcError> {
        match self.next_tag()? {
            (_, Token::Close(n)) if n == name => Ok(()),
            (at, t) => self.invalid(at, format!("expected </{name}>, found {t:?}")),
        }
    }

    /// Text up to `</name>` (which is consumed); empty if the element closes at once.
    fn text_until_close(&mut self, name: &str) -> Result<String, XmlRpcError> {
        let mut out = String::new();
        loop {
            match self.next()? {
                None => return Err(XmlRpcError::Incomplete(format!("expected </{name}>"))),
                Some((at, Token::Text(t))) => out.push_str(&unescape(t, at)?),
                Some((_, Token::Close(n))) if n == name => return Ok(out),
                Some((at, t)) => {
                    return self.invalid(at, format!("expected text in <{name}>, found {t:?}"));
                }
            }
        }
    }
}

fn tag_name(inner: &str) -> &str {
    inner.split_whitespace().next().unwrap_or("")
}

fn unescape(text: &str, at: usize) -> Result<String, XmlRpcError> {
    if !text.contains('&') {
        return Ok(text.to_owned());
    }
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find('&') {
        out.push_str(&rest[..i]);
        let after = &rest[i + 1..];
        let Some(semi) = after.find(';') else {
            return Err(XmlRpcError::Invalid {
                at: at + i,
                reason: "unterminated character reference".into(),
            });
        };
        let entity = &after[..semi];
        let c = match entity {
            "lt" => '<',
            "gt" => '>',
            "amp" => '&',
            "quot" => '"',
            "apos" => '\'',
            e => {
                let code = if let Some(hex) = e.strip_prefix("#x") {
                    u32::from_str_radix(hex, 16).ok()
                } else if let Some(dec) = e.strip_prefix('#') {
                    dec.parse().ok()
                } else {
                    None
                };
                code.and_then(char::from_u32)
                    .ok_or_else(|| XmlRpcError::Invalid {
                        at: at + i,
                        reason: format!("unknown character reference &{e};"),
                    })?
            }
        };
        out.push(c);
        rest = &after[semi + 1..];
    }
    out.push_str(rest);
    Ok(out)
}

/// Parses `<value>…</value>` (the opening tag already read when `opened`).
fn parse_value(lx: &mut Lexer<'_>, depth: usize) -> Result<Value, XmlRpcError> {
    if depth > MAX_DEPTH {
        return lx.invalid(lx.pos, format!("values nested deeper than {MAX_DEPTH}"));
    }
    // `<value>text</value>` is a string; `<value><type>…</type></value>` is typed.
    let mut leading = String::new();
    let v = loop {
        match lx.next()? {
            None => return Err(XmlRpcError::Incomplete("expected </value>".into())),
            Some((at, Token::Text(t))) => leading.push_str(&unescape(t, at)?),
            Some((_, Token::Close("value"))) => return Ok(Value::Str(leading)),
            Some((_, Token::Empty(ty))) => {
                break match ty {
                    "string" => Value::Str(String::new()),
                    "array" | "struct" | "data" => {
                        return lx.invalid(lx.pos, format!("empty <{ty}/>"));
                    }
                    _ => Value::Other(String::new()),
                };
            }
            Some((at, Token::Open(ty))) => {
                if !leading.trim().is_empty() {
                    return lx.invalid(at, "text before a typed value");
                }
                break parse_typed(lx, ty, at, depth)?;
            }
            Some((at, t)) => return lx.invalid(at, format!("unexpected {t:?} in <value>")),
        }
    };
    lx.expect_close("value")?;
    Ok(v)
}

fn parse_typed(
    lx: &mut Lexer<'_>,
    ty: &str,
    at: usize,
    depth: usize,
) -> Result<Value, XmlRpcError> {
    let bad = |reason: String| XmlRpcError::Invalid { at, reason };
    Ok(match ty {
        "i4" | "int" | "i8" => {
            let t = lx.text_until_close(ty)?;
            let n: i64 = t
                .trim()
                .parse()
                .map_err(|_| bad(format!("{t:?} is not an integer")))?;
            Value::Int(i32::try_from(n).map_err(|_| bad(format!("{n} does not fit an i4")))?)
        }
        "boolean" => match lx.text_until_close(ty)?.trim() {
            "1" | "true" => Value::Bool(true),
            "0" | "false" => Value::Bool(false),
            t => return Err(bad(format!("{t:?} is not a boolean"))),
        },
        "string" => Value::Str(lx.text_until_close(ty)?),
        "double" => {
            let t = lx.text_until_close(ty)?;
            Value::Double(
                t.trim()
                    .parse()
                    .map_err(|_| bad(format!("{t:?} is not a double")))?,
            )
        }
        "array" => {
            let mut items = Vec::new();
            match lx.next_tag()? {
                (_, Token::Empty("data")) => {}
                (_, Token::Open("data")) => loop {
                    match lx.next_tag()? {
                        (_, Token::Open("value")) => items.push(parse_value(lx, depth + 1)?),
                        (_, Token::Close("data")) => break,
                        (at, t) => {
                            return Err(XmlRpcError::Invalid {
                                at,
                                reason: format!("expected <value> in <data>, found {t:?}"),
                            });
                        }
                    }
                },
                (at, t) => {
                    return Err(XmlRpcError::Invalid {
                        at,
                        reason: format!("expected <data>, found {t:?}"),
                    });
                }
            }
            lx.expect_close("array")?;
            Value::Array(items)
        }
        "struct" => {
            let mut members = Vec::new();
            loop {
                match lx.next_tag()? {
                    (_, Token::Open("member")) => {
                        lx.expect_open("name")?;
                        let name = lx.text_until_close("name")?;
                        lx.expect_open("value")?;
                        let v = parse_value(lx, depth + 1)?;
                        lx.expect_close("member")?;
                        members.push((name, v));
                    }
                    (_, Token::Close("struct")) => break,
                    (at, t) => {
                        return Err(XmlRpcError::Invalid {
                            at,
                            reason: format!("expected <member> in <struct>, found {t:?}"),
                        });
                    }
                }
            }
            Value::Struct(members)
        }
        "base64" | "dateTime.iso8601" | "nil" => Value::Other(lx.text_until_close(ty)?),
        other => return Err(bad(format!("unknown value type <{other}>"))),
    })
}

fn parse_params(lx: &mut Lexer<'_>) -> Result<Vec<Value>, XmlRpcError> {
    let mut params = Vec::new();
    match lx.next_tag()? {
        (_, Token::Empty("params")) => return Ok(params),
        (_, Token::Open("params")) => {}
        (at, t) => return lx.invalid(at, format!("expected <params>, found {t:?}")),
    }
    loop {
        match lx.next_tag()? {
            (_, Token::Open("param")) => {
                lx.expect_open("value")?;
                params.push(parse_value(lx, 0)?);
                lx.expect_close("param")?;
            }
            (_, Token::Close("params")) => return Ok(params),
            (at, t) => return lx.invalid(at, format!("expected <param>, found {t:?}")),
        }
    }
}

/// Decodes a `methodCall` document.
pub fn decode_call(text: &str) -> Result<Call, XmlRpcError> {
    let mut lx = Lexer::new(text);
    lx.expect_open("methodCall")?;
    lx.expect_open("methodName")?;
    let method = lx.text_until_close("methodName")?.trim().to_owned();
    lx.skip_space()?;
    let params = match lx.peek()? {
        Some((_, Token::Close("methodCall"))) => Vec::new(),
        _ => parse_params(&mut lx)?,
    };
    lx.expect_close("methodCall")?;
    Ok(Call { method, params })
}

/// Decodes a `methodResponse`: its value, or [`XmlRpcError::Fault`].
pub fn decode_response(text: &str) -> Result<Value, XmlRpcError> {
    let mut lx = Lexer::new(text);
    lx.expect_open("methodResponse")?;
    lx.skip_space()?;
    if let Some((_, Token::Open("fault"))) = lx.peek()? {
        lx.next()?;
        lx.expect_open("value")?;
        let v = parse_value(&mut lx, 0)?;
        let field = |k: &str| match &v {
            Value::Struct(m) => m.iter().find(|(n, _)| n == k).map(|(_, v)| v.clone()),
            _ => None,
        };
        return Err(XmlRpcError::Fault {
            code: field("faultCode").and_then(|v| v.as_i32()).unwrap_or(0),
            text: field("faultString")
                .and_then(|v| v.as_str().map(str::to_owned))
                .unwrap_or_default(),
        });
    }
    let mut params = parse_params(&mut lx)?;
    lx.expect_close("methodResponse")?;
    match params.len() {
        1 => Ok(params.remove(0)),
        n => lx.invalid(0, format!("a response has one param, not {n}")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Value {
        Value::Array(vec![
            Value::Int(1),
            Value::Str("ready on <host> & \"port\"".into()),
            Value::Array(vec![
                Value::Str("TCPROS".into()),
                Value::Str("robot".into()),
                Value::Int(40213),
            ]),
            Value::Bool(true),
            Value::Double(-1.5),
            Value::Struct(vec![("a".into(), Value::Array(vec![]))]),
            Value::Str(String::new()),
        ])
    }

    #[test]
    fn call_round_trips() {
        let params = vec![Value::from("/fleetlink"), sample()];
        let text = encode_call("requestTopic", &params);
        let call = decode_call(&text).unwrap();
        assert_eq!(call.method, "requestTopic");
        assert_eq!(call.params, params);
    }

    #[test]
    fn response_round_trips() {
        assert_eq!(
            decode_response(&encode_response(&sample())).unwrap(),
            sample()
        );
    }

    #[test]
    fn fault_is_an_error_with_its_text() {
        let err = decode_response(&encode_fault(-1, "no such method")).unwrap_err();
        assert_eq!(
            err,
            XmlRpcError::Fault {
                code: -1,
                text: "no such method".into()
            }
        );
    }

    /// What Python's xmlrpc.client (rospy, rosmaster) sends: untyped strings, `<int>`,
    /// whitespace between tags, `<nil/>`-free.
    #[test]
    fn decodes_python_style_documents() {
        let text = "<?xml version='1.0'?>\n<methodResponse>\n<params>\n<param>\n<value><array><data>\n\
                    <value><int>1</int></value>\n<value><string>Subscribed to [/chatter]</string></value>\n\
                    <value><array><data>\n<value><string>http://host:4567/</string></value>\n\
                    </data></array></value>\n</data></array></value>\n</param>\n</params>\n</methodResponse>\n";
        let v = decode_response(text).unwrap();
        let a = v.as_array().unwrap();
        assert_eq!(a[0], Value::Int(1));
        assert_eq!(a[2].as_str_list().unwrap(), vec!["http://host:4567/"]);
        let call = decode_call(
            "<?xml version='1.0'?><methodCall><methodName>getPid</methodName>\
             <params><param><value>/rostopic</value></param></params></methodCall>",
        )
        .unwrap();
        assert_eq!(call.params, vec![Value::from("/rostopic")]);
        let empty = decode_call("<methodCall><methodName>x</methodName></methodCall>").unwrap();
        assert!(empty.params.is_empty());
        let e = decode_response(
            "<methodResponse><params><param><value><array><data/></array></value></param></params></methodResponse>",
        )
        .unwrap();
        assert_eq!(e, Value::Array(vec![]));
    }

    #[test]
    fn character_references_decode() {
        let v = decode_response(
            "<methodResponse><params><param><value>&lt;a&#62;&#x26;</value></param></params></methodResponse>",
        )
        .unwrap();
        assert_eq!(v, Value::from("<a>&"));
    }

    #[test]
    fn truncated_documents_are_incomplete() {
        let text = encode_response(&sample());
        for cut in [10, text.len() / 2, text.len() - 5] {
            let r = decode_response(&text[..cut]);
            assert!(
                matches!(r, Err(XmlRpcError::Incomplete(_))),
                "cut at {cut}: {r:?}"
            );
        }
    }

    #[test]
    fn malformed_documents_are_invalid() {
        for bad in [
            "<methodResponse><params><param><value><i4>x</i4></value></param></params></methodResponse>",
            "<methodResponse><params><param><value><i4>99999999999</i4></value></param></params></methodResponse>",
            "<methodResponse><params><param><value><blob>1</blob></value></param></params></methodResponse>",
            "<methodResponse><params><param><value>&bogus;</value></param></params></methodResponse>",
            "<methodCall><params></params></methodCall>",
            "<methodResponse><params></params></methodResponse>",
        ] {
            assert!(
                matches!(
                    decode_response(bad).or_else(|_| decode_call(bad).map(|_| Value::Int(0))),
                    Err(XmlRpcError::Invalid { .. })
                ),
                "{bad}"
            );
        }
    }

    #[test]
    fn deep_nesting_is_refused() {
        let mut text = String::from("<methodResponse><params><param>");
        for _ in 0..100 {
            text.push_str("<value><array><data>");
        }
        let r = decode_response(&text);
        assert!(matches!(r, Err(XmlRpcError::Invalid { .. })), "{r:?}");
    }
}
