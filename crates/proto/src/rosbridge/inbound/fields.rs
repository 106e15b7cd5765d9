//! Reading an operation's fields out of its envelope, each checked for its type (and
//! topic and type names for their form), with error messages that name the operation and
//! the field and never grow with what the client sent.

use serde_json::{Map, Value};

use super::ops::Compression;

/// A topic name as the protocol accepts it: non-empty, at most 1,024 bytes, no whitespace
/// or control characters.
pub(super) fn valid_topic(s: &str) -> bool {
    let clean = if s.is_ascii() {
        // ASCII whitespace and control characters are all at or below space, or DEL.
        s.bytes().all(|b| b > b' ' && b != 0x7f)
    } else {
        !s.chars().any(|c| c.is_whitespace() || c.is_control())
    };
    !s.is_empty() && s.len() <= 1024 && clean
}

/// The fields of one operation's envelope, and the operation's name for error messages.
pub(super) struct Fields<'a> {
    pub(super) obj: &'a Map<String, Value>,
    pub(super) op: &'a str,
}

impl Fields<'_> {
    pub(super) fn req_str(&self, key: &str) -> Result<String, String> {
        match self.obj.get(key) {
            Some(Value::String(s)) => Ok(s.clone()),
            Some(other) => Err(format!(
                "{}: field '{key}' must be a string, got {}",
                self.op,
                json_kind(other)
            )),
            None => Err(format!("{}: missing field '{key}'", self.op)),
        }
    }

    /// A topic name: non-empty, no whitespace or control characters.
    pub(super) fn topic(&self, key: &str) -> Result<String, String> {
        let s = self.req_str(key)?;
        if !valid_topic(&s) {
            return Err(format!(
                "{}: field '{key}' is not a valid topic name: {:?}",
                self.op,
                preview(&s)
            ));
        }
        Ok(s)
    }

    pub(super) fn opt_str(&self, key: &str) -> Result<Option<String>, String> {
        match self.obj.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(Value::String(s)) => Ok(Some(s.clone())),
            Some(other) => Err(format!(
                "{}: field '{key}' must be a string, got {}",
                self.op,
                json_kind(other)
            )),
        }
    }

    /// A type name such as `std_srvs/srv/SetBool`: non-empty, no whitespace.
    pub(super) fn req_type(&self, key: &str) -> Result<String, String> {
        let s = self.req_str(key)?;
        if s.trim().is_empty() || s.len() > 256 || s.chars().any(|c| c.is_whitespace()) {
            return Err(format!(
                "{}: field '{key}' is not a valid type name: {:?}",
                self.op,
                preview(&s)
            ));
        }
        Ok(s)
    }

    /// A duration in seconds: a non-negative finite number.
    pub(super) fn opt_seconds(&self, key: &str) -> Result<Option<f64>, String> {
        match self.obj.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(Value::Number(n)) => match n.as_f64() {
                Some(f) if f.is_finite() && f >= 0.0 => Ok(Some(f)),
                _ => Err(format!(
                    "{}: field '{key}' must be a non-negative number of seconds, got {n}",
                    self.op
                )),
            },
            Some(other) => Err(format!(
                "{}: field '{key}' must be a number of seconds, got {}",
                self.op,
                json_kind(other)
            )),
        }
    }

    pub(super) fn compression(&self) -> Result<Compression, String> {
        match self.opt_str("compression")? {
            None => Ok(Compression::None),
            Some(s) => Compression::parse(&s).ok_or_else(|| {
                format!(
                    "{}: field 'compression' has unknown value '{}' (use none, cbor or cbor-raw)",
                    self.op,
                    preview(&s)
                )
            }),
        }
    }

    pub(super) fn opt_bool(&self, key: &str) -> Result<Option<bool>, String> {
        match self.obj.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(Value::Bool(b)) => Ok(Some(*b)),
            Some(other) => Err(format!(
                "{}: field '{key}' must be a boolean, got {}",
                self.op,
                json_kind(other)
            )),
        }
    }

    pub(super) fn req_u32(&self, key: &str) -> Result<u32, String> {
        self.opt_u32(key)?
            .ok_or_else(|| format!("{}: missing field '{key}'", self.op))
    }

    pub(super) fn opt_u32(&self, key: &str) -> Result<Option<u32>, String> {
        match self.obj.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(Value::Number(n)) => {
                let v = n
                    .as_u64()
                    .or_else(|| {
                        n.as_f64()
                            .filter(|f| *f >= 0.0 && f.fract() == 0.0)
                            .map(|f| f as u64)
                    })
                    .ok_or_else(|| {
                        format!(
                            "{}: field '{key}' must be a non-negative integer, got {n}",
                            self.op
                        )
                    })?;
                u32::try_from(v)
                    .map(Some)
                    .map_err(|_| format!("{}: field '{key}' is too large: {v}", self.op))
            }
            Some(other) => Err(format!(
                "{}: field '{key}' must be a number, got {}",
                self.op,
                json_kind(other)
            )),
        }
    }
}

/// At most the first 64 characters of a client-supplied string, for error messages: the
/// message is echoed back in a `status` reply, so it must not grow with the input.
pub(super) fn preview(s: &str) -> String {
    const MAX_CHARS: usize = 64;
    match s.char_indices().nth(MAX_CHARS) {
        None => s.to_owned(),
        Some((cut, _)) => format!("{}... ({} bytes)", &s[..cut], s.len()),
    }
}

pub(super) fn json_kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}
