//! Parsing client operations.
//!
//! Both frame kinds are first turned into a small JSON envelope (the operation's scalar
//! fields) plus, for operations that carry a message, the message object as encoded bytes
//! in the frame's own encoding. Field checks then run once, on the envelope.

use bytes::Bytes;
use serde_json::{Map, Value};

use crate::payload::{Encoding, Payload};
use crate::rosbridge::convert;

/// A parsed client operation with the `id` it carried (echoed verbatim in replies).
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    pub id: Option<Value>,
    pub op: Op,
}

/// How a subscriber wants messages delivered.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Compression {
    #[default]
    None,
    /// The message as CBOR (typed arrays, byte strings) in a binary frame.
    Cbor,
    /// The raw ROS serialization in a CBOR envelope (`secs`, `nsecs`, `bytes`).
    CborRaw,
    /// rosbridge's PNG packing; not supported, served as `none` with a warning.
    Png,
}

impl Compression {
    fn parse(s: &str) -> Option<Compression> {
        Some(match s {
            "none" | "" => Compression::None,
            "cbor" => Compression::Cbor,
            "cbor-raw" => Compression::CborRaw,
            "png" => Compression::Png,
            _ => return None,
        })
    }
}

#[derive(Debug, Clone, PartialEq)]
pub enum Op {
    Advertise {
        topic: String,
        type_name: String,
        latch: bool,
        queue_size: u32,
    },
    Unadvertise {
        topic: String,
    },
    Publish {
        topic: String,
        msg: Payload,
    },
    Subscribe {
        topic: String,
        type_name: Option<String>,
        throttle_rate: u32,
        queue_length: u32,
        fragment_size: Option<u32>,
        compression: Compression,
        /// fleetlink extension: `topic` is a regular expression matched against whole
        /// topic names (field `"regex": true`).
        regex: bool,
        /// fleetlink extension: the subscription's QoS (`priority`, `rate_limit_hz`,
        /// `policy`, `queue`, `no_drop`), an object checked by the server.
        qos: Option<Value>,
    },
    Unsubscribe {
        topic: String,
    },
    /// fleetlink extension: one message of a pull topic, delivered through the caller's
    /// subscription to it.
    Pull {
        topic: String,
    },
    CallService {
        service: String,
        type_name: Option<String>,
        args: Payload,
        /// Seconds the caller waits for the answer (`None`: the server's default).
        timeout: Option<f64>,
        /// Answer in fragments of at most this many characters.
        fragment_size: Option<u32>,
        /// `cbor` answers in a binary frame; anything else as JSON text.
        compression: Compression,
    },
    /// The client provides `service`: calls to it come to this client as `call_service`
    /// operations, answered with `service_response`.
    AdvertiseService {
        service: String,
        type_name: String,
    },
    UnadvertiseService {
        service: String,
    },
    /// A provider's answer to a `call_service` the server sent it (the request's `id`).
    ServiceResponse {
        service: Option<String>,
        /// The response object, or on failure usually a text saying why.
        values: Option<Payload>,
        /// `None` when the field is missing or `null` (roslibjs leaves it out, roslibpy
        /// sends `null`, when the provider's callback returns nothing).
        result: Option<bool>,
    },
    AdvertiseAction {
        action: String,
        type_name: String,
    },
    UnadvertiseAction {
        action: String,
    },
    SendActionGoal {
        action: String,
        action_type: Option<String>,
        args: Payload,
        /// Whether the caller wants `action_feedback` operations.
        feedback: bool,
        timeout: Option<f64>,
        compression: Compression,
    },
    /// Cancels the goal the request's `id` names.
    CancelActionGoal {
        action: Option<String>,
    },
    /// An action provider's progress report for the goal the request's `id` names.
    ActionFeedback {
        action: Option<String>,
        values: Payload,
    },
    /// An action provider's final answer for the goal the request's `id` names.
    ActionResult {
        action: Option<String>,
        values: Option<Payload>,
        /// `action_msgs/GoalStatus` code (4 succeeded, 5 canceled, 6 aborted).
        status: Option<u32>,
        result: bool,
    },
    /// rosbridge's authentication operation; fields kept for the auth layer.
    Auth {
        fields: Map<String, Value>,
    },
    /// One piece of a larger operation the client cut with rosbridge's fragmentation;
    /// the request's `id` names the operation the pieces make up.
    Fragment {
        data: String,
        num: u32,
        total: u32,
    },
    /// Which `status` messages the client wants: `none`, `error` (the default),
    /// `warning` or `info`.
    SetLevel {
        level: String,
    },
    /// Valid envelope, operation name we do not serve.
    Unknown {
        op: String,
    },
}

impl Op {
    pub fn name(&self) -> &str {
        match self {
            Op::Advertise { .. } => "advertise",
            Op::Unadvertise { .. } => "unadvertise",
            Op::Publish { .. } => "publish",
            Op::Subscribe { .. } => "subscribe",
            Op::Unsubscribe { .. } => "unsubscribe",
            Op::Pull { .. } => "pull",
            Op::CallService { .. } => "call_service",
            Op::AdvertiseService { .. } => "advertise_service",
            Op::UnadvertiseService { .. } => "unadvertise_service",
            Op::ServiceResponse { .. } => "service_response",
            Op::AdvertiseAction { .. } => "advertise_action",
            Op::UnadvertiseAction { .. } => "unadvertise_action",
            Op::SendActionGoal { .. } => "send_action_goal",
            Op::CancelActionGoal { .. } => "cancel_action_goal",
            Op::ActionFeedback { .. } => "action_feedback",
            Op::ActionResult { .. } => "action_result",
            Op::Fragment { .. } => "fragment",
            Op::SetLevel { .. } => "set_level",
            Op::Auth { .. } => "auth",
            Op::Unknown { op } => op,
        }
    }
}

/// Why a frame could not be turned into a [`Request`]. Carries the `id` and `op` when the
/// envelope got far enough to have them, so the error reply can reference the request.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct ParseError {
    pub id: Option<Value>,
    pub op: Option<String>,
    pub message: String,
}

impl ParseError {
    fn new(message: impl Into<String>) -> Self {
        ParseError {
            id: None,
            op: None,
            message: message.into(),
        }
    }
}

/// A `publish` read on the short path, its topic borrowed from the frame: the operation
/// that carries nearly all traffic costs no allocation before it reaches the router.
#[derive(Debug)]
pub struct Publish<'a> {
    pub id: PublishId<'a>,
    pub topic: std::borrow::Cow<'a, str>,
    pub msg: Payload,
}

/// A publish's `id`. From JSON it stays text until asked for: roslibpy and roslibjs
/// number every publish, and the id is only wanted when something goes wrong.
#[derive(Debug)]
pub struct PublishId<'a>(IdRepr<'a>);

#[derive(Debug)]
enum IdRepr<'a> {
    None,
    Value(Value),
    /// Checked by the scan, so it parses.
    Json(&'a str),
}

impl PublishId<'_> {
    /// The `id` as the client sent it, for a `status` that echoes it.
    pub fn value(&self) -> Option<Value> {
        match &self.0 {
            IdRepr::None => None,
            IdRepr::Value(v) => Some(v.clone()),
            IdRepr::Json(text) => serde_json::from_str(text).ok(),
        }
    }
}

impl<'a> Publish<'a> {
    /// A well-formed JSON `publish` (object `msg`, valid topic name) from a frame whose
    /// text is known to be UTF-8 (a WebSocket text frame, validated on arrival, so it is
    /// not checked again): its envelope read in one pass, the topic borrowed, the message
    /// a slice of `frame`. `text` must be a view of `frame`'s own bytes. `None` for
    /// anything else, which [`Request::from_json`] then parses with the precise error.
    pub fn from_json_text(text: &'a str, frame: &Bytes) -> Option<Publish<'a>> {
        Self::read_json_text(text, frame, None)
    }

    /// [`Publish::from_json_text`], keeping the envelope's shape in `shapes` for the
    /// client's next publishes ([`super::EnvelopeShapes::fit`]).
    pub fn from_json_text_shaped(
        text: &'a str,
        frame: &Bytes,
        shapes: &mut super::EnvelopeShapes,
    ) -> Option<Publish<'a>> {
        Self::read_json_text(text, frame, Some(shapes))
    }

    fn read_json_text(
        text: &'a str,
        frame: &Bytes,
        shapes: Option<&mut super::EnvelopeShapes>,
    ) -> Option<Publish<'a>> {
        if !std::ptr::eq(text.as_ptr(), frame.as_ptr()) || text.len() != frame.len() {
            return None;
        }
        let e = super::scan::envelope(text)?;
        if e.op? != "publish" {
            return None;
        }
        let topic = e.topic?;
        let msg = e.msg.clone()?;
        if text.as_bytes()[msg.start] != b'{' || !valid_topic(topic) {
            return None;
        }
        if let Some(shapes) = shapes {
            shapes.learn(text, &e, &msg);
        }
        let id = match e.id {
            Some(r) => PublishId(IdRepr::Json(&text[r])),
            None => PublishId(IdRepr::None),
        };
        Some(Publish {
            id,
            topic: topic.into(),
            msg: Payload::json(frame.slice(msg)),
        })
    }

    /// A CBOR `publish` (a definite-length map with text `op`, `topic`, a map `msg`,
    /// maybe `id`), its envelope walked head by head without decoding
    /// the message: `msg` is a slice of `frame`. `None` for anything else (indefinite
    /// lengths, duplicate keys, trailing bytes...), which [`Request::from_cbor`] then
    /// parses with the precise error.
    pub fn from_cbor_frame(frame: &'a Bytes) -> Option<Publish<'a>> {
        let mut c = CborCursor {
            data: frame,
            pos: 0,
        };
        let (5, Some(entries)) = c.header()? else {
            return None;
        };
        let (mut op, mut topic, mut msg, mut id) = (None, None, None, None);
        for _ in 0..entries {
            let slot = match c.text()? {
                "op" => &mut op,
                "topic" => &mut topic,
                "msg" => &mut msg,
                "id" => &mut id,
                _ => {
                    c.skip(0)?;
                    continue;
                }
            };
            if slot.is_some() {
                return None;
            }
            let start = c.pos;
            c.skip(0)?;
            *slot = Some(start..c.pos);
        }
        if c.pos != frame.len() {
            return None;
        }
        let text = |r: std::ops::Range<usize>| {
            let mut t = CborCursor {
                data: &frame[..r.end],
                pos: r.start,
            };
            t.text()
        };
        if text(op?)? != "publish" {
            return None;
        }
        let topic = text(topic?)?;
        let msg = msg?;
        // Major type 5: a map.
        if frame[msg.start] >> 5 != 5 || !valid_topic(topic) {
            return None;
        }
        let id = match id {
            Some(r) => PublishId(IdRepr::Value(
                convert::parse_cbor(&frame[r])
                    .ok()
                    .and_then(|v| convert::cbor_value_to_json(v).ok())?,
            )),
            None => PublishId(IdRepr::None),
        };
        Some(Publish {
            id,
            topic: topic.into(),
            msg: Payload::new(Encoding::Cbor, frame.slice(msg)),
        })
    }
}

/// Walks CBOR items by their headers, keeping the position in the input.
struct CborCursor<'a> {
    data: &'a [u8],
    pos: usize,
}

impl<'a> CborCursor<'a> {
    /// Deepest nesting walked (as for JSON).
    const MAX_DEPTH: usize = 128;

    /// One item's head: its major type and argument (`None` for an indefinite length or
    /// a break).
    fn header(&mut self) -> Option<(u8, Option<u64>)> {
        let h = fleetlink_msg::cbor::read_head(self.data, &mut self.pos)?;
        Some((h.major, h.arg))
    }

    fn take(&mut self, len: usize) -> Option<&'a [u8]> {
        let s = self.data.get(self.pos..self.pos.checked_add(len)?)?;
        self.pos += len;
        Some(s)
    }

    /// A definite-length text item.
    fn text(&mut self) -> Option<&'a str> {
        match self.header()? {
            (3, Some(n)) => std::str::from_utf8(self.take(usize::try_from(n).ok()?)?).ok(),
            _ => None,
        }
    }

    /// Steps over one item; `None` for what only the full parse handles (indefinite
    /// lengths, a stray break, truncation, nesting deeper than `MAX_DEPTH`).
    fn skip(&mut self, depth: usize) -> Option<()> {
        if depth > Self::MAX_DEPTH {
            return None;
        }
        let (major, arg) = self.header()?;
        // Indefinite lengths and breaks are left to the full parse.
        let n = arg?;
        match major {
            0 | 1 | 7 => {}
            2 | 3 => {
                self.take(usize::try_from(n).ok()?)?;
            }
            4 => {
                for _ in 0..n {
                    self.skip(depth + 1)?;
                }
            }
            5 => {
                for _ in 0..n.checked_mul(2)? {
                    self.skip(depth + 1)?;
                }
            }
            _ => self.skip(depth + 1)?, // 6: a tag and its item
        }
        Some(())
    }
}

impl Request {
    /// Parses a JSON text frame.
    pub fn from_json(text: &[u8]) -> Result<Request, ParseError> {
        let value: Value = serde_json::from_slice(text)
            .map_err(|e| ParseError::new(format!("invalid JSON: {e}")))?;
        let Value::Object(mut obj) = value else {
            return Err(ParseError::new("invalid operation: expected a JSON object"));
        };
        let body = match take_body_field(&obj) {
            Some(key) => obj.remove(key).map(|v| {
                let bytes = serde_json::to_vec(&v).expect("a parsed JSON value serializes");
                Payload::new(Encoding::Json, bytes)
            }),
            None => None,
        };
        parse_envelope(obj, body)
    }

    /// Parses a CBOR binary frame.
    pub fn from_cbor(data: &[u8]) -> Result<Request, ParseError> {
        let value = convert::parse_cbor(data).map_err(|e| ParseError::new(e.to_string()))?;
        let ciborium::Value::Map(entries) = value else {
            return Err(ParseError::new("invalid operation: expected a CBOR map"));
        };
        let mut obj = Map::new();
        let mut body_value = None;
        let mut pending = Vec::new();
        for (k, v) in entries {
            let ciborium::Value::Text(key) = k else {
                return Err(ParseError::new(
                    "invalid operation: CBOR map keys must be text",
                ));
            };
            pending.push((key, v));
        }
        let op_name = pending.iter().find_map(|(k, v)| match (k.as_str(), v) {
            ("op", ciborium::Value::Text(s)) => Some(s.clone()),
            _ => None,
        });
        let body_key = op_name.as_deref().and_then(body_field_for);
        for (key, v) in pending {
            if Some(key.as_str()) == body_key {
                body_value = Some(v);
            } else {
                let j = convert::cbor_value_to_json(v)
                    .map_err(|e| ParseError::new(format!("invalid CBOR field '{key}': {e}")))?;
                obj.insert(key, j);
            }
        }
        let body = match body_value {
            Some(v) => {
                let mut out = Vec::new();
                ciborium::into_writer(&v, &mut out)
                    .map_err(|e| ParseError::new(format!("cannot re-encode CBOR message: {e}")))?;
                Some(Payload::new(Encoding::Cbor, out))
            }
            None => None,
        };
        parse_envelope(obj, body)
    }
}

/// A topic name as the protocol accepts it: non-empty, at most 1,024 bytes, no whitespace
/// or control characters.
fn valid_topic(s: &str) -> bool {
    let clean = if s.is_ascii() {
        // ASCII whitespace and control characters are all at or below space, or DEL.
        s.bytes().all(|b| b > b' ' && b != 0x7f)
    } else {
        !s.chars().any(|c| c.is_whitespace() || c.is_control())
    };
    !s.is_empty() && s.len() <= 1024 && clean
}

/// The field that holds a message object, for operations that carry one.
fn body_field_for(op: &str) -> Option<&'static str> {
    match op {
        "publish" => Some("msg"),
        "call_service" | "send_action_goal" => Some("args"),
        "service_response" | "action_feedback" | "action_result" => Some("values"),
        _ => None,
    }
}

fn take_body_field(obj: &Map<String, Value>) -> Option<&'static str> {
    obj.get("op")
        .and_then(Value::as_str)
        .and_then(body_field_for)
}

fn parse_envelope(
    mut obj: Map<String, Value>,
    body: Option<Payload>,
) -> Result<Request, ParseError> {
    let id = obj.remove("id");
    let op = match obj.get("op") {
        Some(Value::String(s)) => s.clone(),
        Some(other) => {
            return Err(ParseError {
                id,
                op: None,
                message: format!("field 'op' must be a string, got {}", json_kind(other)),
            });
        }
        None => {
            return Err(ParseError {
                id,
                op: None,
                message: "missing field 'op'".into(),
            });
        }
    };
    let fields = Fields { obj: &obj, op: &op };
    let result = (|| -> Result<Op, String> {
        Ok(match op.as_str() {
            "advertise" => Op::Advertise {
                topic: fields.topic("topic")?,
                type_name: fields.req_str("type")?,
                latch: fields.opt_bool("latch")?.unwrap_or(false),
                queue_size: fields.opt_u32("queue_size")?.unwrap_or(100),
            },
            "unadvertise" => Op::Unadvertise {
                topic: fields.topic("topic")?,
            },
            "publish" => Op::Publish {
                topic: fields.topic("topic")?,
                msg: body
                    .clone()
                    .ok_or_else(|| "publish: missing field 'msg'".to_string())?,
            },
            "subscribe" => {
                let compression = match fields.opt_str("compression")? {
                    None => Compression::None,
                    Some(s) => Compression::parse(&s).ok_or_else(|| {
                        format!(
                            "subscribe: field 'compression' has unknown value '{}' \
                             (use none, cbor or cbor-raw)",
                            preview(&s)
                        )
                    })?,
                };
                let regex = fields.opt_bool("regex")?.unwrap_or(false);
                Op::Subscribe {
                    topic: if regex {
                        fields.req_str("topic")?
                    } else {
                        fields.topic("topic")?
                    },
                    type_name: fields.opt_str("type")?,
                    throttle_rate: fields.opt_u32("throttle_rate")?.unwrap_or(0),
                    queue_length: fields.opt_u32("queue_length")?.unwrap_or(0),
                    fragment_size: fields.opt_u32("fragment_size")?,
                    compression,
                    regex,
                    qos: match obj.get("qos") {
                        None | Some(Value::Null) => None,
                        Some(v @ Value::Object(_)) => Some(v.clone()),
                        Some(other) => {
                            return Err(format!(
                                "subscribe: field 'qos' must be an object, got {}",
                                json_kind(other)
                            ));
                        }
                    },
                }
            }
            "unsubscribe" => Op::Unsubscribe {
                topic: fields.req_str("topic")?,
            },
            "pull" => Op::Pull {
                topic: fields.topic("topic")?,
            },
            "call_service" => Op::CallService {
                service: fields.topic("service")?,
                type_name: fields.opt_str("type")?,
                args: body.clone().unwrap_or_else(|| Payload::json(&b"{}"[..])),
                timeout: fields.opt_seconds("timeout")?,
                fragment_size: fields.opt_u32("fragment_size")?,
                compression: fields.compression()?,
            },
            "advertise_service" => Op::AdvertiseService {
                service: fields.topic("service")?,
                type_name: fields.req_type("type")?,
            },
            "unadvertise_service" => Op::UnadvertiseService {
                service: fields.topic("service")?,
            },
            "service_response" => Op::ServiceResponse {
                service: fields.opt_str("service")?,
                values: body.clone(),
                result: fields.opt_bool("result")?,
            },
            "advertise_action" => Op::AdvertiseAction {
                action: fields.topic("action")?,
                type_name: fields.req_type("type")?,
            },
            "unadvertise_action" => Op::UnadvertiseAction {
                action: fields.topic("action")?,
            },
            "send_action_goal" => Op::SendActionGoal {
                action: fields.topic("action")?,
                action_type: fields.opt_str("action_type")?,
                args: body.clone().unwrap_or_else(|| Payload::json(&b"{}"[..])),
                feedback: fields.opt_bool("feedback")?.unwrap_or(false),
                timeout: fields.opt_seconds("timeout")?,
                compression: fields.compression()?,
            },
            "cancel_action_goal" => Op::CancelActionGoal {
                action: fields.opt_str("action")?,
            },
            "action_feedback" => Op::ActionFeedback {
                action: fields.opt_str("action")?,
                values: body
                    .clone()
                    .ok_or_else(|| "action_feedback: missing field 'values'".to_string())?,
            },
            "action_result" => Op::ActionResult {
                action: fields.opt_str("action")?,
                values: body.clone(),
                status: fields.opt_u32("status")?,
                result: fields.opt_bool("result")?.unwrap_or(true),
            },
            "auth" => Op::Auth {
                fields: obj.clone(),
            },
            "fragment" => Op::Fragment {
                data: fields.req_str("data")?,
                num: fields.req_u32("num")?,
                total: fields.req_u32("total")?,
            },
            "set_level" => Op::SetLevel {
                level: fields.req_str("level")?,
            },
            // The name is echoed in the error: at most a preview of it.
            _ => Op::Unknown { op: preview(&op) },
        })
    })();
    match result {
        Ok(op) => Ok(Request { id, op }),
        Err(message) => Err(ParseError {
            id,
            op: Some(op),
            message,
        }),
    }
}

struct Fields<'a> {
    obj: &'a Map<String, Value>,
    op: &'a str,
}

impl Fields<'_> {
    fn req_str(&self, key: &str) -> Result<String, String> {
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
    fn topic(&self, key: &str) -> Result<String, String> {
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

    fn opt_str(&self, key: &str) -> Result<Option<String>, String> {
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
    fn req_type(&self, key: &str) -> Result<String, String> {
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
    fn opt_seconds(&self, key: &str) -> Result<Option<f64>, String> {
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

    fn compression(&self) -> Result<Compression, String> {
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

    fn opt_bool(&self, key: &str) -> Result<Option<bool>, String> {
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

    fn req_u32(&self, key: &str) -> Result<u32, String> {
        self.opt_u32(key)?
            .ok_or_else(|| format!("{}: missing field '{key}'", self.op))
    }

    fn opt_u32(&self, key: &str) -> Result<Option<u32>, String> {
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
fn preview(s: &str) -> String {
    const MAX_CHARS: usize = 64;
    match s.char_indices().nth(MAX_CHARS) {
        None => s.to_owned(),
        Some((cut, _)) => format!("{}... ({} bytes)", &s[..cut], s.len()),
    }
}

fn json_kind(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// The `msg` of a publish as a shared slice, for tests and tools.
pub fn payload_bytes(op: &Op) -> Option<&Bytes> {
    match op {
        Op::Publish { msg, .. } => Some(&msg.bytes),
        Op::CallService { args, .. } | Op::SendActionGoal { args, .. } => Some(&args.bytes),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn publish_keeps_message_as_json_bytes() {
        let r =
            Request::from_json(br#"{"op":"publish","id":"p1","topic":"/a","msg":{"data":"hi"}}"#)
                .unwrap();
        assert_eq!(r.id, Some(Value::String("p1".into())));
        let Op::Publish { topic, msg } = r.op else {
            panic!("not a publish")
        };
        assert_eq!(topic, "/a");
        assert_eq!(msg.encoding, Encoding::Json);
        assert_eq!(&msg.bytes[..], br#"{"data":"hi"}"#);
    }

    #[test]
    fn publish_frame_slices_the_message_out_of_the_frame() {
        let frame = Bytes::from_static(
            br#"{"op": "publish", "topic": "/a", "id": {"n": [1]}, "msg": {"data": "h\u00e9"}, "x": 1}"#,
        );
        let r = from_json_frame(&frame).unwrap();
        assert_eq!(r.id, Some(serde_json::json!({"n": [1]})));
        let Op::Publish { topic, msg } = r.op else {
            panic!("not a publish")
        };
        assert_eq!(topic, "/a");
        assert_eq!(&msg.bytes[..], br#"{"data": "h\u00e9"}"#);
        // A slice of the frame's storage, not a copy.
        let start = msg.bytes.as_ptr() as usize - frame.as_ptr() as usize;
        assert_eq!(&frame[start..start + msg.len()], &msg.bytes[..]);
    }

    #[test]
    fn publish_from_validated_text_borrows_the_topic_and_slices_the_message() {
        let text = r#"{"op":"publish","topic":"/a/b","msg":{"data":"h\u00e9"}}"#;
        let frame = Bytes::from(text.to_owned());
        let view = std::str::from_utf8(&frame).unwrap();
        let p = Publish::from_json_text(view, &frame).expect("a publish");
        assert!(matches!(p.topic, std::borrow::Cow::Borrowed("/a/b")));
        assert_eq!(p.id.value(), None);
        let start = p.msg.bytes.as_ptr() as usize - frame.as_ptr() as usize;
        assert_eq!(&frame[start..start + p.msg.len()], br#"{"data":"h\u00e9"}"#);
        // Text that is not a view of the frame is not trusted: the caller parses the
        // frame on the full path instead.
        let copy = text.to_owned();
        assert!(Publish::from_json_text(&copy, &frame).is_none());
        // Anything the short path does not take goes to the full parse, as before.
        let frame = Bytes::from_static(br#"{"op":"publish","topic":"/a b","msg":{}}"#);
        let view = std::str::from_utf8(&frame).unwrap();
        assert!(Publish::from_json_text(view, &frame).is_none());
        // A topic written with escapes cannot be borrowed: the full parse reads it.
        let frame = Bytes::from_static(br#"{"op":"publish","topic":"\/a","msg":{}}"#);
        let view = std::str::from_utf8(&frame).unwrap();
        assert!(Publish::from_json_text(view, &frame).is_none());
        let r = from_json_frame(&frame).unwrap();
        assert!(matches!(r.op, Op::Publish { topic, .. } if topic == "/a"));
    }

    /// What the rosbridge session does with a text frame: the publish short path, else
    /// the full parse.
    fn from_json_frame(frame: &Bytes) -> Result<Request, ParseError> {
        let text = std::str::from_utf8(frame).expect("a text frame");
        match Publish::from_json_text(text, frame) {
            Some(p) => Ok(Request {
                id: p.id.value(),
                op: Op::Publish {
                    topic: p.topic.into_owned(),
                    msg: p.msg,
                },
            }),
            None => Request::from_json(frame),
        }
    }

    fn cbor(v: &ciborium::Value) -> Vec<u8> {
        let mut out = Vec::new();
        ciborium::into_writer(v, &mut out).unwrap();
        out
    }

    #[test]
    fn cbor_publish_slices_the_message_and_agrees_with_the_full_parse() {
        use ciborium::Value as C;
        let text = |s: &str| C::Text(s.into());
        // A message with a nested map, an array, a byte string and a typed array (tag 85,
        // float32 little-endian), as rosbridge CBOR clients write them.
        let msg = C::Map(vec![
            (
                text("header"),
                C::Map(vec![(text("frame_id"), text("map"))]),
            ),
            (text("data"), C::Bytes(vec![1, 2, 3])),
            (
                text("ranges"),
                C::Tag(85, Box::new(C::Bytes(vec![0, 0, 128, 63]))),
            ),
            (
                text("list"),
                C::Array(vec![C::Integer(1.into()), C::Float(2.5), C::Null]),
            ),
        ]);
        let msg_bytes = cbor(&msg);
        let frame = Bytes::from(cbor(&C::Map(vec![
            (text("op"), text("publish")),
            (text("id"), text("p1")),
            (text("extra"), C::Array(vec![C::Bool(true)])),
            (text("topic"), text("/scan")),
            (text("msg"), msg.clone()),
        ])));
        let p = Publish::from_cbor_frame(&frame).expect("the short path takes it");
        assert_eq!(p.topic, "/scan");
        assert_eq!(p.id.value(), Some(serde_json::json!("p1")));
        assert_eq!(p.msg.encoding, Encoding::Cbor);
        assert_eq!(&p.msg.bytes[..], &msg_bytes[..]);
        let start = p.msg.bytes.as_ptr() as usize - frame.as_ptr() as usize;
        assert_eq!(
            &frame[start..start + p.msg.len()],
            &msg_bytes[..],
            "a slice, not a copy"
        );
        let full = Request::from_cbor(&frame).unwrap();
        assert_eq!(full.id, p.id.value());
        let Op::Publish {
            topic,
            msg: full_msg,
        } = full.op
        else {
            panic!("not a publish")
        };
        assert_eq!(topic, "/scan");
        assert_eq!(
            convert::parse_cbor(&full_msg.bytes).unwrap(),
            convert::parse_cbor(&p.msg.bytes).unwrap()
        );
    }

    #[test]
    fn cbor_publish_short_path_leaves_everything_else_to_the_full_parse() {
        use ciborium::Value as C;
        let text = |s: &str| C::Text(s.into());
        let publish = |entries: Vec<(C, C)>| Bytes::from(cbor(&C::Map(entries)));
        let ok_msg = C::Map(vec![(text("data"), C::Integer(1.into()))]);
        let cases = [
            publish(vec![
                (text("op"), text("subscribe")),
                (text("topic"), text("/a")),
            ]),
            publish(vec![
                (text("op"), text("publish")),
                (text("topic"), text("/a")),
                (text("msg"), C::Array(vec![])),
            ]),
            publish(vec![
                (text("op"), text("publish")),
                (text("topic"), text("/a b")),
                (text("msg"), ok_msg.clone()),
            ]),
            publish(vec![
                (text("op"), text("publish")),
                (text("topic"), text("/a")),
                (text("topic"), text("/b")),
                (text("msg"), ok_msg.clone()),
            ]),
            publish(vec![
                (text("op"), text("publish")),
                (C::Integer(7.into()), text("/a")),
                (text("msg"), ok_msg.clone()),
            ]),
            publish(vec![
                (text("op"), text("publish")),
                (text("topic"), text("/a")),
            ]),
        ];
        for frame in cases {
            assert!(Publish::from_cbor_frame(&frame).is_none(), "{frame:?}");
        }
        let good = cbor(&C::Map(vec![
            (text("op"), text("publish")),
            (text("topic"), text("/a")),
            (text("msg"), ok_msg),
        ]));
        assert!(Publish::from_cbor_frame(&Bytes::from(good.clone())).is_some());
        // Trailing bytes, truncation, indefinite lengths: the full parse decides.
        let mut trailing = good.clone();
        trailing.push(0);
        assert!(Publish::from_cbor_frame(&Bytes::from(trailing)).is_none());
        for cut in 0..good.len() {
            assert!(Publish::from_cbor_frame(&Bytes::copy_from_slice(&good[..cut])).is_none());
        }
        let mut indefinite = vec![0xbf];
        indefinite.extend_from_slice(&good[1..]);
        indefinite.push(0xff);
        assert!(Publish::from_cbor_frame(&Bytes::from(indefinite)).is_none());
        // Hostile nesting is bounded, not a stack overflow.
        let mut deep = cbor(&C::Map(vec![
            (text("op"), text("publish")),
            (text("topic"), text("/a")),
        ]));
        deep[0] = 0xa3;
        deep.extend_from_slice(&cbor(&text("msg")));
        deep.extend(std::iter::repeat_n(0x81, 100_000));
        deep.push(0x00);
        assert!(Publish::from_cbor_frame(&Bytes::from(deep)).is_none());
    }

    #[test]
    fn publish_frame_gives_the_same_errors_as_the_full_parse() {
        for text in [
            r#"{"op":"publish","topic":"/a"}"#,
            r#"{"op":"publish","topic":"/a b","msg":{}}"#,
            r#"{"op":"publish","topic":7,"msg":{}}"#,
            r#"{"op":"publish","topic":"/a","msg":[1]}"#,
            r#"{"op":"publish","topic":"/a","msg":{},"msg":{}}"#,
            r#"{"op":"publish","topic":"/a","msg":{"#,
        ] {
            let frame = Bytes::copy_from_slice(text.as_bytes());
            assert_eq!(
                from_json_frame(&frame),
                Request::from_json(text.as_bytes()),
                "{text}"
            );
        }
        let other = br#"{"op":"subscribe","id":7,"topic":"/a"}"#;
        assert_eq!(
            from_json_frame(&Bytes::from_static(other)),
            Request::from_json(other)
        );
    }

    #[test]
    fn topic_check_agrees_with_the_unicode_rules_for_every_ascii_byte() {
        for b in 0u8..128 {
            let c = b as char;
            let name = format!("/a{c}b");
            assert_eq!(
                valid_topic(&name),
                !(c.is_whitespace() || c.is_control()),
                "byte {b:#x}"
            );
        }
        assert!(!valid_topic("/a\u{2003}b"));
        assert!(valid_topic("/caf\u{e9}"));
    }

    #[test]
    fn wrong_type_names_the_field_and_keeps_the_id() {
        let e =
            Request::from_json(br#"{"op":"subscribe","id":7,"topic":"/a","throttle_rate":"fast"}"#)
                .unwrap_err();
        assert_eq!(e.id, Some(Value::from(7)));
        assert!(e.message.contains("throttle_rate"), "{}", e.message);
    }

    #[test]
    fn cbor_publish_keeps_message_as_cbor_bytes() {
        let v = ciborium::Value::Map(vec![
            (
                ciborium::Value::Text("op".into()),
                ciborium::Value::Text("publish".into()),
            ),
            (
                ciborium::Value::Text("topic".into()),
                ciborium::Value::Text("/b".into()),
            ),
            (
                ciborium::Value::Text("msg".into()),
                ciborium::Value::Map(vec![(
                    ciborium::Value::Text("data".into()),
                    ciborium::Value::Bytes(vec![1, 2, 3]),
                )]),
            ),
        ]);
        let mut buf = Vec::new();
        ciborium::into_writer(&v, &mut buf).unwrap();
        let r = Request::from_cbor(&buf).unwrap();
        let Op::Publish { msg, .. } = r.op else {
            panic!("not a publish")
        };
        assert_eq!(msg.encoding, Encoding::Cbor);
        let back: ciborium::Value = ciborium::from_reader(&msg.bytes[..]).unwrap();
        assert_eq!(
            back.as_map().unwrap()[0].1,
            ciborium::Value::Bytes(vec![1, 2, 3])
        );
    }
}
