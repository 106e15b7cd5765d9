//! The full parse of a client frame: a JSON text frame or a CBOR binary frame becomes an
//! envelope (the operation's scalar fields, as JSON) and, for an operation that carries
//! one, its message object as encoded bytes in the frame's own encoding. The fields are
//! then checked once, on the envelope, whichever encoding the frame came in.

use serde_json::{Map, Value};

use super::fields::{Fields, json_kind, preview};
use super::ops::{Op, ParseError, Request};
use crate::payload::{Encoding, Payload};
use crate::rosbridge::convert;

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

/// Reads the operation an envelope names: `obj` holds its scalar fields, `body` the message
/// object taken out of it. The error carries the `id` and `op` once they are known.
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
    match read_op(&fields, body) {
        Ok(op) => Ok(Request { id, op }),
        Err(message) => Err(ParseError {
            id,
            op: Some(op),
            message,
        }),
    }
}

/// The operation `f.op` names, read from its envelope `f` and its message object `body`.
/// The error is the message for the client.
fn read_op(f: &Fields<'_>, body: Option<Payload>) -> Result<Op, String> {
    Ok(match f.op {
        "advertise" => Op::Advertise {
            topic: f.topic("topic")?,
            type_name: f.req_str("type")?,
            latch: f.opt_bool("latch")?.unwrap_or(false),
            queue_size: f.opt_u32("queue_size")?.unwrap_or(100),
        },
        "unadvertise" => Op::Unadvertise {
            topic: f.topic("topic")?,
        },
        "publish" => Op::Publish {
            topic: f.topic("topic")?,
            msg: body.ok_or_else(|| "publish: missing field 'msg'".to_string())?,
        },
        "subscribe" => {
            // Checked before `topic`: a frame wrong in both reports its compression.
            let compression = f.compression()?;
            let regex = f.opt_bool("regex")?.unwrap_or(false);
            Op::Subscribe {
                topic: if regex {
                    f.req_str("topic")?
                } else {
                    f.topic("topic")?
                },
                type_name: f.opt_str("type")?,
                throttle_rate: f.opt_u32("throttle_rate")?.unwrap_or(0),
                queue_length: f.opt_u32("queue_length")?.unwrap_or(0),
                fragment_size: f.opt_u32("fragment_size")?,
                compression,
                regex,
                qos: match f.obj.get("qos") {
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
            topic: f.req_str("topic")?,
        },
        "pull" => Op::Pull {
            topic: f.topic("topic")?,
        },
        "call_service" => Op::CallService {
            service: f.topic("service")?,
            type_name: f.opt_str("type")?,
            args: body.unwrap_or_else(|| Payload::json(&b"{}"[..])),
            timeout: f.opt_seconds("timeout")?,
            fragment_size: f.opt_u32("fragment_size")?,
            compression: f.compression()?,
        },
        "advertise_service" => Op::AdvertiseService {
            service: f.topic("service")?,
            type_name: f.req_type("type")?,
        },
        "unadvertise_service" => Op::UnadvertiseService {
            service: f.topic("service")?,
        },
        "service_response" => Op::ServiceResponse {
            service: f.opt_str("service")?,
            values: body,
            result: f.opt_bool("result")?,
        },
        "advertise_action" => Op::AdvertiseAction {
            action: f.topic("action")?,
            type_name: f.req_type("type")?,
        },
        "unadvertise_action" => Op::UnadvertiseAction {
            action: f.topic("action")?,
        },
        "send_action_goal" => Op::SendActionGoal {
            action: f.topic("action")?,
            action_type: f.opt_str("action_type")?,
            args: body.unwrap_or_else(|| Payload::json(&b"{}"[..])),
            feedback: f.opt_bool("feedback")?.unwrap_or(false),
            timeout: f.opt_seconds("timeout")?,
            compression: f.compression()?,
        },
        "cancel_action_goal" => Op::CancelActionGoal {
            action: f.opt_str("action")?,
        },
        "action_feedback" => Op::ActionFeedback {
            action: f.opt_str("action")?,
            values: body.ok_or_else(|| "action_feedback: missing field 'values'".to_string())?,
        },
        "action_result" => Op::ActionResult {
            action: f.opt_str("action")?,
            values: body,
            status: f.opt_u32("status")?,
            result: f.opt_bool("result")?.unwrap_or(true),
        },
        "auth" => Op::Auth {
            fields: f.obj.clone(),
        },
        "fragment" => Op::Fragment {
            data: f.req_str("data")?,
            num: f.req_u32("num")?,
            total: f.req_u32("total")?,
        },
        "set_level" => Op::SetLevel {
            level: f.req_str("level")?,
        },
        // The name is echoed in the error: at most a preview of it.
        _ => Op::Unknown { op: preview(f.op) },
    })
}
