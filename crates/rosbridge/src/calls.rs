//! Services and actions on a rosbridge session: the client as caller (`call_service`,
//! `send_action_goal`, `cancel_action_goal`) and as provider (`advertise_service`,
//! `advertise_action`, answering with `service_response`, `action_feedback`,
//! `action_result`), both through the router's call table.
//!
//! Ids: a caller's own `id` is echoed in its answers; calls this client serves carry ids
//! the session makes (`call:<n>` / `goal:<n>`, unique on the session), so two callers
//! using the same id never collide at the provider.
//!
//! Layout: this file holds what both sides share (the session's call tables, the
//! answers' framing and conversion); `caller` the calls and goals this client makes,
//! `provider` the services and actions it offers and the answers it gives, and
//! `robot_params` the parameter calls the hub forwards to robots' agents.

mod caller;
mod provider;
mod robot_params;

use std::collections::{HashMap, HashSet};
use std::time::Duration;

use bytes::Bytes;
use fleetlink_proto::rosbridge::outbound;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::{CallId, CallStatus, PeerMsg};
use fleetlink_relay::names::TopicName;
use serde_json::{Value, json};
use tokio_tungstenite::tungstenite::{Message as WsMessage, Utf8Bytes};

use super::session::Session;

/// How a caller wants its answers.
#[derive(Debug, Clone, Copy, Default)]
pub struct Answering {
    /// Split a JSON answer into rosbridge fragments of at most this many characters.
    pub fragment_size: Option<u32>,
    /// Answer in a CBOR binary frame (the caller asked for `cbor` or spoke CBOR).
    pub cbor: bool,
}

struct Made {
    id: Option<Value>,
    /// The name as the client wrote it, echoed in answers.
    name: String,
    type_name: String,
    goal: bool,
    feedback: bool,
    how: Answering,
    size: usize,
    /// A parameter call forwarded to this robot's agent: its answer names the robot.
    robot: Option<String>,
    /// Part of a `get_param_names` listing (the key of its [`Gathering`]).
    gather: Option<u64>,
}

impl Made {
    /// A `call_service` of `name` (as the client wrote it).
    fn service_call(name: &str, id: Option<&Value>, how: Answering, size: usize) -> Made {
        Made {
            id: id.cloned(),
            name: name.to_owned(),
            type_name: String::new(),
            goal: false,
            feedback: false,
            how,
            size,
            robot: None,
            gather: None,
        }
    }
}

/// A `get_param_names` waiting for the lists of the robots that provide parameters.
struct Gathering {
    id: Option<Value>,
    how: Answering,
    /// Names so far: the hub's own, then each robot's as it answers.
    names: Vec<String>,
    /// Robots that have not answered yet.
    pending: usize,
}

struct Serving {
    call: CallId,
    name: TopicName,
    goal: bool,
}

/// One session's calls.
#[derive(Default)]
pub struct SessionCalls {
    /// The client speaks CBOR binary frames: calls it serves are sent as CBOR.
    pub binary: bool,
    made: HashMap<CallId, Made>,
    /// Pending goals by the id their caller gave them.
    goals: HashMap<String, CallId>,
    serving: HashMap<String, Serving>,
    serving_by_call: HashMap<CallId, String>,
    provided: HashSet<(TopicName, bool)>,
    gathering: HashMap<u64, Gathering>,
    next_gathering: u64,
}

/// `action_msgs/GoalStatus` codes.
const GOAL_SUCCEEDED: u32 = 4;
const GOAL_CANCELED: u32 = 5;
const GOAL_ABORTED: u32 = 6;

fn goal_status(status: CallStatus) -> u32 {
    match status {
        CallStatus::Ok => GOAL_SUCCEEDED,
        CallStatus::Cancelled => GOAL_CANCELED,
        _ => GOAL_ABORTED,
    }
}

fn id_key(id: &Value) -> String {
    match id {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// Seconds from a client into a duration (0 = no deadline of its own).
fn timeout_of(secs: Option<f64>) -> Option<Duration> {
    secs.filter(|s| *s > 0.0)
        .map(|s| Duration::from_secs_f64(s.min(1e9)))
}

/// The part of a service or action type a payload is: `pkg/srv/T` + `_Request`.
fn part(type_name: &str, suffix: &str) -> String {
    format!("{type_name}{suffix}")
}

impl Session {
    /// A rosbridge body (JSON or CBOR) checked against the part of `name`'s type it is
    /// and completed, as a publish is: missing fields take their defaults, a field the
    /// type does not have is refused naming it. Unchanged when the service or its type is
    /// not known here.
    fn completed(&self, name: &TopicName, suffix: &str, body: Payload) -> Result<Payload, String> {
        let Some(info) = self.router.calls.service(name) else {
            return Ok(body);
        };
        if info.schema.type_name.is_empty() {
            return Ok(body);
        }
        let tc = self.router.transcoder();
        let type_name = part(&info.schema.type_name, suffix);
        let schema = tc
            .schema_for(&type_name)
            .unwrap_or_else(|| Schema::named(&type_name));
        match tc.normalize(&schema, &body) {
            Ok(Some(done)) => Ok(done),
            Ok(None) => Ok(body),
            Err(e) => Err(e.cause_text()),
        }
    }

    /// A payload as the bytes of a JSON (or CBOR) value for this client.
    fn body_for(&self, p: &Payload, type_name: &str, cbor: bool) -> Result<Bytes, String> {
        let to = if cbor { Encoding::Cbor } else { Encoding::Json };
        if p.encoding == to {
            return Ok(p.bytes.clone());
        }
        let tc = self.router.transcoder();
        let schema = tc
            .schema_for(type_name)
            .unwrap_or_else(|| Schema::named(type_name));
        tc.convert(&schema, p, to).map_err(|e| e.to_string())
    }

    /// Sends an operation whose `body_key` is `body` (JSON or CBOR bytes).
    async fn send_op(&self, fields: Value, body_key: &str, body: &Bytes, how: Answering) {
        if how.cbor {
            let b = outbound::op_cbor(&fields, body_key, body);
            return self.send(WsMessage::Binary(b)).await;
        }
        let text = outbound::op_json(&fields, body_key, body);
        let Ok(text) = Utf8Bytes::try_from(text) else {
            let msg = format!("{body_key}: the answer is not valid UTF-8 JSON");
            return self.status("error", msg, fields.get("id")).await;
        };
        match how.fragment_size.map(|s| s as usize).filter(|s| *s > 0) {
            Some(size) if text.len() > size => {
                let fid = fields.get("id").map_or_else(|| "answer".to_owned(), id_key);
                for piece in outbound::fragments(&fid, text.as_str(), size) {
                    self.send(WsMessage::text(piece)).await;
                }
            }
            _ => self.send(WsMessage::Text(text)).await,
        }
    }

    /// A failed `call_service`, answered as rosbridge does: `result: false` and a text.
    async fn service_failed(&self, service: &str, id: Option<&Value>, text: String, cbor: bool) {
        let fields = json!({"op": "service_response", "service": service, "result": false});
        self.refuse(fields, id, text, cbor).await;
    }

    async fn goal_failed(
        &self,
        action: &str,
        id: Option<&Value>,
        status: CallStatus,
        text: String,
        cbor: bool,
    ) {
        let fields = json!({"op": "action_result", "action": action,
            "status": goal_status(status), "result": false});
        self.refuse(fields, id, text, cbor).await;
    }

    /// Sends `fields` with the caller's `id` and `values` = `text`, as JSON or CBOR.
    async fn refuse(&self, mut fields: Value, id: Option<&Value>, text: String, cbor: bool) {
        if let Some(id) = id {
            fields["id"] = id.clone();
        }
        fields["values"] = Value::String(text);
        self.send_value(&fields, cbor).await;
    }

    /// One whole operation, as a CBOR binary frame or JSON text.
    pub(super) async fn send_value(&self, v: &Value, cbor: bool) {
        let mut buf = Vec::new();
        let frame = if cbor && ciborium::into_writer(v, &mut buf).is_ok() {
            WsMessage::Binary(Bytes::from(buf))
        } else {
            WsMessage::text(v.to_string())
        };
        self.send(frame).await;
    }

    /// Something the call table queued for this client.
    pub(super) async fn on_peer(&mut self, m: PeerMsg) {
        match m {
            PeerMsg::Call(req) => self.serve_call(req).await,
            PeerMsg::Cancel(call) => self.cancel_served(call).await,
            PeerMsg::Event(ev) => self.call_event(ev).await,
            PeerMsg::Changed(_) => {}
        }
    }
}

fn empty_map(cbor: bool) -> Bytes {
    if cbor {
        Bytes::from_static(&[0xa0])
    } else {
        Bytes::from_static(b"{}")
    }
}

/// An object (JSON object or CBOR map), as `args` and `values` must be.
fn is_map(p: &Payload) -> bool {
    match p.encoding {
        Encoding::Json => p.bytes.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'{'),
        Encoding::Cbor => p.bytes.first().is_some_and(|b| b >> 5 == 5),
        _ => true,
    }
}
