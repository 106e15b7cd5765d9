//! The client as provider: `advertise_service` / `advertise_action` and their
//! `unadvertise_*`, the calls and goals handed to it (`call_service`, `send_action_goal`
//! with ids `call:<n>` / `goal:<n>`), and its answers (`service_response`,
//! `action_feedback`, `action_result`) passed back through the call table.

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::{CallId, CallRequest, CallStatus, goal_id_text};
use fleetlink_relay::gate::Op as GateOp;
use fleetlink_relay::names::TopicName;
use serde_json::{Value, json};
use tokio_tungstenite::tungstenite::Message as WsMessage;

use super::{
    Answering, GOAL_ABORTED, GOAL_CANCELED, GOAL_SUCCEEDED, Serving, id_key, is_map, part,
};
use crate::session::Session;

impl Session {
    pub(crate) fn advertise_service(
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
            .filter(|s| fleetlink_relay::router::same_type(&s.type_name, type_name))
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

    pub(crate) fn unadvertise_service(&mut self, raw: &str, action: bool) -> Result<(), String> {
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
    pub(crate) fn service_response(
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

    pub(crate) fn action_feedback(
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

    pub(crate) fn action_result(
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

    /// A caller gave up on a call this client serves: the provider of a goal is asked to
    /// cancel it; a service call is forgotten.
    pub(super) async fn cancel_served(&mut self, call: CallId) {
        let Some(key) = self.calls.serving_by_call.remove(&call) else {
            return;
        };
        let Some(s) = self.calls.serving.get(&key) else {
            return;
        };
        if s.goal {
            // The goal stays pending until the provider sends its result.
            self.calls.serving_by_call.insert(call, key.clone());
            let fields = json!({"op": "cancel_action_goal", "id": key, "action": s.name.as_str()});
            self.send(WsMessage::text(fields.to_string())).await;
        } else {
            // rosbridge has no cancel for a service call: forget it, so a late
            // answer is reported as such.
            self.calls.serving.remove(&key);
        }
    }

    pub(super) async fn serve_call(&mut self, req: CallRequest) {
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
