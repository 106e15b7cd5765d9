//! The client as caller: `call_service`, `send_action_goal` and `cancel_action_goal`,
//! started in the router's call table, and the answers and feedback sent back to it.

use std::sync::Arc;

use fleetlink_proto::{Encoding, Payload};
use fleetlink_relay::calls::{CallEvent, CallId, CallOptions, CallStatus};
use fleetlink_relay::gate::Op as GateOp;
use fleetlink_relay::link_calls::outcome_text;
use fleetlink_relay::names::TopicName;
use serde_json::{Value, json};

use super::robot_params::from_robot;
use super::{Answering, Made, empty_map, goal_status, id_key, is_map, part, timeout_of};
use crate::session::Session;

impl Session {
    pub(crate) async fn call_service(
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
    pub(super) fn start(
        &mut self,
        name: &TopicName,
        args: Payload,
        opts: CallOptions,
        mut made: Made,
    ) -> Result<CallId, fleetlink_relay::calls::CallRefused> {
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

    pub(crate) async fn send_action_goal(
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

    pub(crate) fn cancel_action_goal(&mut self, id: Option<&Value>) -> Result<(), String> {
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

    pub(super) async fn call_event(&mut self, ev: CallEvent) {
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
