//! Services and actions on a rosbridge session: the client as caller (`call_service`,
//! `send_action_goal`, `cancel_action_goal`) and as provider (`advertise_service`,
//! `advertise_action`, answering with `service_response`, `action_feedback`,
//! `action_result`), both through the router's call table.
//!
//! Ids: a caller's own `id` is echoed in its answers; calls this client serves carry ids
//! the session makes (`call:<n>` / `goal:<n>`, unique on the session), so two callers
//! using the same id never collide at the provider.

use std::collections::{HashMap, HashSet};
use std::sync::Arc;
use std::time::Duration;

use bytes::Bytes;
use fleetlink_proto::rosbridge::outbound;
use fleetlink_proto::{Encoding, Payload, Schema};
use serde_json::{Value, json};
use tokio_tungstenite::tungstenite::{Message as WsMessage, Utf8Bytes};

use super::session::Session;
use crate::calls::{
    CallEvent, CallId, CallOptions, CallRequest, CallStatus, PeerMsg, goal_id_text,
};
use crate::gate::Op as GateOp;
use crate::link_calls::outcome_text;
use crate::names::TopicName;

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

/// How long a listing of parameter names waits for a robot's own list.
const ROBOT_NAMES_WAIT: Duration = Duration::from_secs(5);

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

    pub(super) async fn call_service(
        &mut self,
        service: &str,
        args: Payload,
        id: Option<&Value>,
        timeout: Option<f64>,
        how: Answering,
    ) {
        let name = match TopicName::parse(service) {
            Ok(n) => n,
            Err(e) => {
                let text = format!("call_service: {e}");
                return self.service_failed(service, id, text, how.cbor).await;
            }
        };
        if let Err(e) = self.check("call_service", name.as_str(), GateOp::CallService) {
            return self.service_failed(service, id, e, how.cbor).await;
        }
        if let Some(e) = self.direct_param_refusal(name.as_str(), &args) {
            return self.service_failed(service, id, e, how.cbor).await;
        }
        if name.as_str().starts_with("/rosapi/") && self.router.calls.service(&name).is_none() {
            return self.call_rosapi(service, &args, id, how).await;
        }
        if !matches!(args.encoding, Encoding::Json | Encoding::Cbor) || !is_map(&args) {
            let text = format!("call_service {name}: field 'args' must be an object");
            return self.service_failed(service, id, text, how.cbor).await;
        }
        let args = match self.completed(&name, "_Request", args) {
            Ok(a) => a,
            Err(e) => {
                let text = format!("call_service {name}: field 'args': {e}");
                return self.service_failed(service, id, text, how.cbor).await;
            }
        };
        let size = args.len();
        let opts = CallOptions {
            timeout: timeout_of(timeout),
            goal: false,
            goal_id: None,
            on_behalf_of: None, // filled by `start`
        };
        let made = Made::service_call(service, id, how, size);
        if let Err(e) = self.start(&name, args, opts, made) {
            let text = format!("call_service {name}: {}", e.text);
            self.service_failed(service, id, text, how.cbor).await
        }
    }

    /// Starts a call or goal of this client; a refusal is audited and returned for the
    /// caller's answer.
    fn start(
        &mut self,
        name: &TopicName,
        args: Payload,
        opts: CallOptions,
        mut made: Made,
    ) -> Result<CallId, crate::calls::CallRefused> {
        let op = if opts.goal {
            GateOp::SendActionGoal
        } else {
            GateOp::CallService
        };
        let opts = CallOptions {
            on_behalf_of: self.gate.as_ref().and_then(|g| g.caller()).map(Arc::new),
            ..opts
        };
        match self.router.calls.call(self.client, name, args, opts) {
            Ok(call) => {
                made.type_name = self
                    .router
                    .calls
                    .service(name)
                    .map(|s| s.schema.type_name.clone())
                    .unwrap_or_default();
                self.calls.made.insert(call, made);
                Ok(call)
            }
            Err(e) => {
                if let Some(g) = self.gate.as_mut() {
                    g.finished(
                        name.as_str(),
                        op,
                        made.size,
                        &outcome_text(e.status, &e.text),
                    );
                }
                Err(e)
            }
        }
    }

    pub(super) fn advertise_service(
        &mut self,
        raw: &str,
        type_name: &str,
        action: bool,
    ) -> Result<(), String> {
        let verb = if action {
            "advertise_action"
        } else {
            "advertise_service"
        };
        let name = TopicName::parse(raw).map_err(|e| format!("{verb}: {e}"))?;
        if name.as_str().starts_with("/rosapi/") {
            return Err(format!(
                "{verb} {name}: /rosapi/ services are the server's own"
            ));
        }
        let op = if action {
            GateOp::AdvertiseAction
        } else {
            GateOp::AdvertiseService
        };
        self.check(verb, name.as_str(), op)?;
        let tc = self.router.transcoder();
        let schema = tc
            .schema_for(type_name)
            .filter(|s| crate::router::same_type(&s.type_name, type_name))
            .unwrap_or_else(|| Schema::named(type_name));
        if let Some(prev) = self
            .router
            .calls
            .advertise(self.client, name.clone(), schema, action)
        {
            tracing::info!(
                "{name} is now provided by client {} (was {prev})",
                self.client
            );
        }
        if let Some(g) = self.gate.as_mut() {
            g.done(name.as_str(), op, 0);
        }
        self.calls.provided.insert((name, action));
        Ok(())
    }

    pub(super) fn unadvertise_service(&mut self, raw: &str, action: bool) -> Result<(), String> {
        let verb = if action {
            "unadvertise_action"
        } else {
            "unadvertise_service"
        };
        let name = TopicName::parse(raw).map_err(|e| format!("{verb}: {e}"))?;
        if !self.calls.provided.remove(&(name.clone(), action)) {
            let what = if action { "action" } else { "service" };
            return Err(format!(
                "{verb} {name}: this client has not advertised that {what}"
            ));
        }
        self.router.calls.unadvertise(self.client, &name);
        Ok(())
    }

    /// The `Serving` entry an answer's `id` names, removed when `end`.
    fn serving(
        &mut self,
        op: &str,
        id: Option<&Value>,
        end: bool,
    ) -> Result<(CallId, TopicName, bool), String> {
        let Some(id) = id else {
            return Err(format!(
                "{op}: missing field 'id' (echo the id of the request you answer)"
            ));
        };
        let key = id_key(id);
        let found = if end {
            self.calls.serving.remove(&key)
        } else {
            self.calls.serving.get(&key).map(|s| Serving {
                call: s.call,
                name: s.name.clone(),
                goal: s.goal,
            })
        };
        let Some(s) = found else {
            return Err(format!(
                "{op}: no request with id {key} is waiting for this client's answer \
                 (answered already, timed out, cancelled, or never sent)"
            ));
        };
        if end {
            self.calls.serving_by_call.remove(&s.call);
        }
        Ok((s.call, s.name, s.goal))
    }

    /// A provider's answer, read as rosbridge reads it: `values` that are an object are
    /// the response, whatever `result` says (rosbridge checks only that `result` is a
    /// boolean and hands the values to the caller; roslibpy sends the callback's return
    /// value there, which is often nothing). Without such values, `result: true` answers
    /// with the type's defaults and anything else fails the call (roslib 2 sends no
    /// values when its callback returns something falsy). See docs/calls.md, "A
    /// provider's answer".
    pub(super) fn service_response(
        &mut self,
        id: Option<&Value>,
        values: Option<Payload>,
        result: Option<bool>,
    ) -> Result<(), String> {
        let (call, name, goal) = self.serving("service_response", id, true)?;
        if goal {
            return Err(format!(
                "service_response: {name} is an action; answer goals with action_result"
            ));
        }
        let (status, payload, text) = match values {
            Some(v) if is_map(&v) => match self.completed(&name, "_Response", v) {
                Ok(v) => (CallStatus::Ok, Some(v), String::new()),
                Err(e) => {
                    let text = format!("the provider of {name} answered a wrong response: {e}");
                    self.router
                        .calls
                        .respond(self.client, call, CallStatus::Failed, None, text);
                    return Err(format!(
                        "service_response {name}: field 'values': {e}; the caller got an error"
                    ));
                }
            },
            None if result == Some(true) => {
                let empty = Payload::json(&b"{}"[..]);
                let defaults = self.completed(&name, "_Response", empty.clone());
                (
                    CallStatus::Ok,
                    Some(defaults.unwrap_or(empty)),
                    String::new(),
                )
            }
            v if result != Some(true) && v.as_ref().is_none_or(is_text) => (
                CallStatus::Failed,
                None,
                failure_text(v.as_ref(), &name, result),
            ),
            _ => {
                let text =
                    format!("the provider of {name} answered with 'values' that are not an object");
                self.router
                    .calls
                    .respond(self.client, call, CallStatus::Failed, None, text);
                return Err(format!(
                    "service_response {name}: field 'values' must be an object (the \
                     response's fields), or a text with result: false; the caller got an error"
                ));
            }
        };
        self.router
            .calls
            .respond(self.client, call, status, payload, text);
        Ok(())
    }

    pub(super) async fn send_action_goal(
        &mut self,
        action: &str,
        args: Payload,
        id: Option<&Value>,
        feedback: bool,
        timeout: Option<f64>,
        how: Answering,
    ) {
        let name = match TopicName::parse(action) {
            Ok(n) => n,
            Err(e) => {
                let text = format!("send_action_goal: {e}");
                return self
                    .goal_failed(action, id, CallStatus::Failed, text, how.cbor)
                    .await;
            }
        };
        if let Err(e) = self.check("send_action_goal", name.as_str(), GateOp::SendActionGoal) {
            return self
                .goal_failed(action, id, CallStatus::Forbidden, e, how.cbor)
                .await;
        }
        if !is_map(&args) {
            let text = format!("send_action_goal {name}: field 'args' must be an object");
            return self
                .goal_failed(action, id, CallStatus::Failed, text, how.cbor)
                .await;
        }
        let args = match self.completed(&name, "_Goal", args) {
            Ok(a) => a,
            Err(e) => {
                let text = format!("send_action_goal {name}: field 'args': {e}");
                return self
                    .goal_failed(action, id, CallStatus::Failed, text, how.cbor)
                    .await;
            }
        };
        let key = id.map(id_key);
        if let Some(k) = &key
            && self.calls.goals.contains_key(k)
        {
            let text = format!(
                "send_action_goal {name}: goal id {k} is already in use by a pending goal of \
                 this client; give each goal its own id"
            );
            return self
                .goal_failed(action, id, CallStatus::Failed, text, how.cbor)
                .await;
        }
        let size = args.len();
        let opts = CallOptions {
            timeout: timeout_of(timeout),
            goal: true,
            goal_id: None,
            on_behalf_of: None, // filled by `start`
        };
        let made = Made {
            goal: true,
            feedback,
            ..Made::service_call(action, id, how, size)
        };
        match self.start(&name, args, opts, made) {
            Ok(call) => {
                if let Some(k) = key {
                    self.calls.goals.insert(k, call);
                }
            }
            Err(e) => {
                let text = format!("send_action_goal {name}: {}", e.text);
                self.goal_failed(action, id, e.status, text, how.cbor).await
            }
        }
    }

    pub(super) fn cancel_action_goal(&mut self, id: Option<&Value>) -> Result<(), String> {
        let Some(id) = id else {
            return Err(
                "cancel_action_goal: missing field 'id' (the id of the goal to cancel)".into(),
            );
        };
        let key = id_key(id);
        let Some(call) = self.calls.goals.get(&key).copied() else {
            return Err(format!(
                "cancel_action_goal: this client has no pending goal with id {key}"
            ));
        };
        let name = self
            .calls
            .made
            .get(&call)
            .map(|m| m.name.clone())
            .unwrap_or_default();
        self.check("cancel_action_goal", &name, GateOp::CancelActionGoal)?;
        self.router.calls.cancel(self.client, call);
        if let Some(g) = self.gate.as_mut() {
            g.finished(&name, GateOp::CancelActionGoal, 0, "requested");
        }
        Ok(())
    }

    pub(super) fn action_feedback(
        &mut self,
        id: Option<&Value>,
        values: Payload,
    ) -> Result<(), String> {
        let (call, name, goal) = self.serving("action_feedback", id, false)?;
        if !goal {
            return Err(format!(
                "action_feedback: {name} is a service; answer it with service_response"
            ));
        }
        self.router.calls.feedback(self.client, call, values);
        Ok(())
    }

    pub(super) fn action_result(
        &mut self,
        id: Option<&Value>,
        values: Option<Payload>,
        status: Option<u32>,
        result: bool,
    ) -> Result<(), String> {
        let (call, name, goal) = self.serving("action_result", id, true)?;
        if !goal {
            return Err(format!(
                "action_result: {name} is a service; answer it with service_response"
            ));
        }
        let st = match status {
            Some(GOAL_SUCCEEDED) => CallStatus::Ok,
            Some(GOAL_CANCELED) => CallStatus::Cancelled,
            Some(GOAL_ABORTED) => CallStatus::Aborted,
            None if result => CallStatus::Ok,
            _ => CallStatus::Aborted,
        };
        let text = if st == CallStatus::Ok {
            String::new()
        } else {
            format!(
                "the goal ended with status {}",
                status.unwrap_or(GOAL_ABORTED)
            )
        };
        let values = values.filter(is_map);
        self.router
            .calls
            .respond(self.client, call, st, values, text);
        Ok(())
    }

    /// Something the call table queued for this client.
    pub(super) async fn on_peer(&mut self, m: PeerMsg) {
        match m {
            PeerMsg::Call(req) => self.serve_call(req).await,
            PeerMsg::Cancel(call) => {
                let Some(key) = self.calls.serving_by_call.remove(&call) else {
                    return;
                };
                let Some(s) = self.calls.serving.get(&key) else {
                    return;
                };
                if s.goal {
                    // The goal stays pending until the provider sends its result.
                    self.calls.serving_by_call.insert(call, key.clone());
                    let fields =
                        json!({"op": "cancel_action_goal", "id": key, "action": s.name.as_str()});
                    self.send(WsMessage::text(fields.to_string())).await;
                } else {
                    // rosbridge has no cancel for a service call: forget it, so a late
                    // answer is reported as such.
                    self.calls.serving.remove(&key);
                }
            }
            PeerMsg::Event(ev) => self.call_event(ev).await,
            PeerMsg::Changed(_) => {}
        }
    }

    async fn serve_call(&mut self, req: CallRequest) {
        let goal = req.goal_id.is_some();
        let info = &req.service;
        let suffix = if goal { "_Goal" } else { "_Request" };
        let cbor = self.calls.binary;
        let body = match self.body_for(&req.payload, &part(&info.schema.type_name, suffix), cbor) {
            Ok(b) => b,
            Err(e) => {
                let text = format!(
                    "{}: cannot hand the request to its provider: {e}",
                    info.name
                );
                self.router
                    .calls
                    .respond(self.client, req.id, CallStatus::Failed, None, text);
                return;
            }
        };
        let key = if goal {
            format!("goal:{}", req.id)
        } else {
            format!("call:{}", req.id)
        };
        let mut fields = if goal {
            json!({"op": "send_action_goal", "id": key, "action": info.name.as_str(),
                   "action_type": info.schema.type_name, "feedback": true,
                   "goal_id": goal_id_text(&req.goal_id.unwrap_or_default())})
        } else {
            json!({"op": "call_service", "id": key, "service": info.name.as_str(),
                   "type": info.schema.type_name})
        };
        if let Some(d) = req.deadline {
            let left = d.saturating_duration_since(std::time::Instant::now());
            fields["timeout"] = json!(left.as_secs_f64());
        }
        self.calls.serving.insert(
            key.clone(),
            Serving {
                call: req.id,
                name: info.name.clone(),
                goal,
            },
        );
        self.calls.serving_by_call.insert(req.id, key);
        let how = Answering {
            fragment_size: None,
            cbor,
        };
        self.send_op(fields, "args", &body, how).await;
    }

    async fn call_event(&mut self, ev: CallEvent) {
        match ev {
            CallEvent::Feedback { id, payload } => {
                let Some(m) = self.calls.made.get(&id) else {
                    return;
                };
                if !m.feedback {
                    return;
                }
                let (how, name) = (m.how, m.name.clone());
                let mut fields = json!({"op": "action_feedback", "action": name});
                if let Some(i) = &m.id {
                    fields["id"] = i.clone();
                }
                match self.body_for(&payload, &part(&m.type_name, "_Feedback"), how.cbor) {
                    Ok(body) => self.send_op(fields, "values", &body, how).await,
                    Err(e) => tracing::debug!("feedback of {name} dropped: {e}"),
                }
            }
            CallEvent::Done {
                id,
                status,
                payload,
                text,
            } => {
                let Some(m) = self.calls.made.remove(&id) else {
                    return;
                };
                if let Some(g) = m.gather {
                    return self.gathered(g, m, status, payload, text).await;
                }
                if let Some(key) = m.id.as_ref().map(id_key)
                    && self.calls.goals.get(&key) == Some(&id)
                {
                    self.calls.goals.remove(&key);
                }
                let op = if m.goal {
                    GateOp::SendActionGoal
                } else {
                    GateOp::CallService
                };
                let outcome = outcome_text(status, &text);
                if let Some(g) = self.gate.as_mut() {
                    g.finished(&m.name, op, m.size, &outcome);
                }
                self.answer_made(m, status, payload, text).await;
            }
        }
    }

    async fn answer_made(
        &mut self,
        m: Made,
        status: CallStatus,
        payload: Option<Payload>,
        text: String,
    ) {
        let (payload, text) = match &m.robot {
            Some(robot) => from_robot(robot, payload, text),
            None => (payload, text),
        };
        let suffix = if m.goal { "_Result" } else { "_Response" };
        let body = match payload {
            Some(p) => match self.body_for(&p, &part(&m.type_name, suffix), m.how.cbor) {
                Ok(b) => Some(b),
                Err(e) => {
                    let text = format!("{}: the answer could not be converted: {e}", m.name);
                    return if m.goal {
                        self.goal_failed(
                            &m.name,
                            m.id.as_ref(),
                            CallStatus::Failed,
                            text,
                            m.how.cbor,
                        )
                        .await
                    } else {
                        self.service_failed(&m.name, m.id.as_ref(), text, m.how.cbor)
                            .await
                    };
                }
            },
            None => None,
        };
        let ok = status == CallStatus::Ok;
        if m.goal {
            if !ok && body.is_none() {
                let text = format!("{} {}: {text}", m.name, status.as_str());
                return self
                    .goal_failed(&m.name, m.id.as_ref(), status, text, m.how.cbor)
                    .await;
            }
            let mut fields = json!({"op": "action_result", "action": m.name,
                "status": goal_status(status), "result": status != CallStatus::Aborted});
            if let Some(i) = &m.id {
                fields["id"] = i.clone();
            }
            let body = body.unwrap_or_else(|| empty_map(m.how.cbor));
            return self.send_op(fields, "values", &body, m.how).await;
        }
        if !ok {
            let text = format!(
                "service {} {}: {text}",
                m.name,
                status.as_str().replace('_', " ")
            );
            return self
                .service_failed(&m.name, m.id.as_ref(), text, m.how.cbor)
                .await;
        }
        let mut fields = json!({"op": "service_response", "service": m.name, "result": true});
        if let Some(i) = &m.id {
            fields["id"] = i.clone();
        }
        let body = body.unwrap_or_else(|| empty_map(m.how.cbor));
        self.send_op(fields, "values", &body, m.how).await;
    }
}

/// The parameter services a robot's agent may answer for names in its namespace.
/// (`get_param_names` has no name to route by: the hub asks every robot that provides
/// parameters, see [`Session::gather_param_names`].)
const FORWARDED_PARAMS: [&str; 5] = [
    "get_param",
    "set_param",
    "has_param",
    "delete_param",
    "search_param",
];

impl Session {
    /// A rosapi parameter call for a name in a robot's namespace (`/robot1/max_speed`),
    /// when that robot's agent provides parameters (`/robot1/rosapi/get_param` is in the
    /// call table): forwarded there with the name relative to the robot (`/max_speed`),
    /// answered when the robot answers. The ACL applies to the full name as for the hub's
    /// own parameters (reading needs `subscribe`, changing `publish`). `None`: not such a
    /// call, the hub answers it from its own store.
    pub(super) fn forward_param(
        &mut self,
        service: &str,
        args: &Value,
        id: Option<&Value>,
        how: Answering,
    ) -> Option<Result<(), String>> {
        let call = service.strip_prefix("/rosapi/")?;
        if !FORWARDED_PARAMS.contains(&call) {
            return None;
        }
        let name = crate::params::param_name(args.get("name")?.as_str()?).ok()?;
        let (robot, rest) = match name[1..].find('/') {
            Some(i) => (&name[1..=i], &name[i + 1..]),
            None => (&name[1..], "/"),
        };
        let provider = TopicName::parse(&format!("/{robot}/rosapi/{call}")).ok()?;
        self.router.calls.service(&provider)?;
        let op = if matches!(call, "set_param" | "delete_param") {
            GateOp::Publish
        } else {
            GateOp::Subscribe
        };
        let gate = self.gate.as_mut()?;
        if !gate.allows(&name, op) {
            let verb = if op == GateOp::Publish {
                "change"
            } else {
                "read"
            };
            return Some(Err(format!("not allowed to {verb} parameter {name}")));
        }
        let mut forwarded = args.clone();
        forwarded["name"] = json!(rest);
        let body = serde_json::to_vec(&forwarded).expect("JSON");
        let size = body.len();
        if op == GateOp::Publish {
            // Audited like a change of the hub's own parameters.
            gate.finished(
                &name,
                GateOp::Publish,
                size,
                &format!("{call} on robot {robot}"),
            );
        }
        let made = Made {
            robot: Some(robot.to_owned()),
            ..Made::service_call(service, id, how, size)
        };
        let opts = CallOptions {
            timeout: timeout_of(None),
            goal: false,
            goal_id: None,
            on_behalf_of: None, // filled by `start`
        };
        Some(
            self.start(&provider, Payload::json(body), opts, made)
                .map(|_| ())
                .map_err(|e| format!("{service} of {name}: robot {robot}: {}", e.text)),
        )
    }
}

impl Session {
    /// `get_param_names` when robots provide parameters: `own` (the hub's names, already
    /// held to the ACL) and, as each robot answers, the robot's names in its namespace
    /// (`/robot1/max_speed`) under the same ACL. Answered once every robot has answered or
    /// [`ROBOT_NAMES_WAIT`] has passed; a robot that fails is left out of the list.
    /// `false`: no robot provides parameters (the caller answers with `own`).
    pub(super) fn gather_param_names(
        &mut self,
        own: Vec<String>,
        id: Option<&Value>,
        how: Answering,
    ) -> bool {
        let providers: Vec<(String, TopicName)> = self
            .router
            .calls
            .services()
            .iter()
            .filter_map(|s| {
                let robot = s
                    .name
                    .as_str()
                    .strip_prefix('/')?
                    .strip_suffix("/rosapi/get_param_names")?;
                (!robot.contains('/')).then(|| (robot.to_owned(), s.name.clone()))
            })
            .collect();
        if providers.is_empty() {
            return false;
        }
        let key = self.calls.next_gathering;
        self.calls.next_gathering += 1;
        let mut pending = 0;
        for (robot, provider) in providers {
            let made = Made {
                robot: Some(robot.clone()),
                gather: Some(key),
                ..Made::service_call("/rosapi/get_param_names", id, how, 2)
            };
            let opts = CallOptions {
                timeout: Some(ROBOT_NAMES_WAIT),
                goal: false,
                goal_id: None,
                on_behalf_of: None, // filled by `start`
            };
            match self.start(&provider, Payload::json(&b"{}"[..]), opts, made) {
                Ok(_) => pending += 1,
                Err(e) => tracing::debug!("parameter names of robot {robot}: {}", e.text),
            }
        }
        if pending == 0 {
            return false;
        }
        let gathering = Gathering {
            id: id.cloned(),
            how,
            names: own,
            pending,
        };
        self.calls.gathering.insert(key, gathering);
        true
    }

    /// One robot's answer to a `get_param_names` listing; the last one sends the list.
    async fn gathered(
        &mut self,
        key: u64,
        m: Made,
        status: CallStatus,
        payload: Option<Payload>,
        text: String,
    ) {
        let robot = m.robot.unwrap_or_default();
        let names = payload
            .filter(|_| status == CallStatus::Ok)
            .and_then(|p| serde_json::from_slice::<Value>(&p.bytes).ok())
            .and_then(|v| match v.get("names") {
                Some(Value::Array(a)) => Some(a.clone()),
                _ => None,
            });
        let Some(g) = self.calls.gathering.get_mut(&key) else {
            return;
        };
        g.pending -= 1;
        match names {
            Some(names) => {
                for n in names.iter().filter_map(Value::as_str) {
                    let full = match n {
                        "/" => format!("/{robot}"),
                        n if n.starts_with('/') => format!("/{robot}{n}"),
                        n => format!("/{robot}/{n}"),
                    };
                    g.names.push(full);
                }
            }
            None => tracing::info!(
                "parameter names of robot {robot} left out of a listing: {}",
                if text.is_empty() {
                    status.as_str().replace('_', " ")
                } else {
                    text
                }
            ),
        }
        if g.pending > 0 {
            return;
        }
        let g = self.calls.gathering.remove(&key).expect("present");
        let mut names = g.names;
        if let Some(gate) = self.gate.as_mut() {
            names.retain(|n| gate.allows(n, GateOp::Subscribe));
        }
        names.sort_unstable();
        names.dedup();
        let reply = outbound::service_response(
            "/rosapi/get_param_names",
            g.id.as_ref(),
            json!({ "names": names }),
            true,
        );
        self.send_value(&reply, g.how.cbor).await;
    }

    /// A robot's parameter service called by its own name (`/robot1/rosapi/set_param`
    /// with `/max_speed`) is held to the ACL the hub's forwarding applies: the parameter's
    /// full name (`/robot1/max_speed`), `subscribe` to read, `publish` to change. The
    /// refusal text, or `None` when the call may go on (or is not such a call).
    fn direct_param_refusal(&mut self, service: &str, args: &Payload) -> Option<String> {
        let (robot, call) = service.strip_prefix('/')?.split_once("/rosapi/")?;
        if robot.contains('/') || !FORWARDED_PARAMS.contains(&call) {
            return None;
        }
        let args = crate::params::call_args(args)?;
        let raw = args.get("name").and_then(Value::as_str).unwrap_or_default();
        // An invalid name is the provider's to refuse.
        let full = match crate::params::param_name_or_root(raw).ok()?.as_str() {
            "/" => format!("/{robot}"),
            rel => format!("/{robot}{rel}"),
        };
        let op = if matches!(call, "set_param" | "delete_param") {
            GateOp::Publish
        } else {
            GateOp::Subscribe
        };
        let gate = self.gate.as_mut()?;
        if gate.allows(&full, op) {
            return None;
        }
        let verb = if op == GateOp::Publish {
            "change"
        } else {
            "read"
        };
        Some(format!("not allowed to {verb} parameter {full}"))
    }
}

/// A robot's answer to a forwarded parameter call, in the hub's names: a found name
/// (`search_param`) gets the robot's namespace back, an error says which robot.
fn from_robot(robot: &str, payload: Option<Payload>, text: String) -> (Option<Payload>, String) {
    let text = if text.is_empty() {
        text
    } else {
        format!("robot {robot}: {text}")
    };
    let payload = payload.map(|p| {
        let json = match p.encoding {
            Encoding::Json => serde_json::from_slice::<Value>(&p.bytes).ok(),
            _ => None,
        };
        match json {
            Some(mut v) => {
                if let Some(found) = v.get("global_name").and_then(Value::as_str)
                    && !found.is_empty()
                {
                    let full = if found == "/" {
                        format!("/{robot}")
                    } else {
                        format!("/{robot}{found}")
                    };
                    v["global_name"] = json!(full);
                    return Payload::json(serde_json::to_vec(&v).expect("JSON"));
                }
                p
            }
            None => p,
        }
    });
    (payload, text)
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

/// Whether a body is a text (a failure's reason).
fn is_text(p: &Payload) -> bool {
    match p.encoding {
        Encoding::Json => p.bytes.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'"'),
        Encoding::Cbor => p.bytes.first().is_some_and(|b| b >> 5 == 3),
        _ => false,
    }
}

/// What a failed answer (no response object) says: its `values` when they are a text,
/// else a line naming the service and what the provider sent.
fn failure_text(values: Option<&Payload>, name: &TopicName, result: Option<bool>) -> String {
    let parsed: Option<Value> = values.and_then(|v| match v.encoding {
        Encoding::Json => serde_json::from_slice(&v.bytes).ok(),
        Encoding::Cbor => ciborium::from_reader(&v.bytes[..]).ok(),
        _ => None,
    });
    match parsed {
        Some(Value::String(s)) if !s.is_empty() => s,
        _ if result.is_none() => {
            format!("the provider of {name} answered without a response (no 'values', no 'result')")
        }
        _ => format!("the provider of {name} answered result: false"),
    }
}
