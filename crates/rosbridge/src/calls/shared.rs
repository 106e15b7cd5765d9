//! The session's methods that both sides of its calls use: a body completed against the
//! part of its type it is, an answer framed for this client (JSON or CBOR) and sent, a
//! failed call or goal answered as rosbridge does, and what the call table queues for the
//! client dispatched to the caller's or the provider's side.

use bytes::Bytes;
use fleetlink_proto::rosbridge::outbound;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::{CallStatus, PeerMsg};
use fleetlink_relay::names::TopicName;
use serde_json::{Value, json};
use tokio_tungstenite::tungstenite::{Message as WsMessage, Utf8Bytes};

use super::{Answering, goal_status, id_key, part};
use crate::session::Session;

impl Session {
    /// A rosbridge body (JSON or CBOR) checked against the part of `name`'s type it is
    /// and completed, as a publish is: missing fields take their defaults, a field the
    /// type does not have is refused naming it. Unchanged when the service or its type is
    /// not known here.
    pub(super) fn completed(
        &self,
        name: &TopicName,
        suffix: &str,
        body: Payload,
    ) -> Result<Payload, String> {
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
    pub(super) fn body_for(
        &self,
        p: &Payload,
        type_name: &str,
        cbor: bool,
    ) -> Result<Bytes, String> {
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
    pub(super) async fn send_op(
        &self,
        fields: Value,
        body_key: &str,
        body: &Bytes,
        how: Answering,
    ) {
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
    pub(super) async fn service_failed(
        &self,
        service: &str,
        id: Option<&Value>,
        text: String,
        cbor: bool,
    ) {
        let fields = json!({"op": "service_response", "service": service, "result": false});
        self.refuse(fields, id, text, cbor).await;
    }

    pub(super) async fn goal_failed(
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
    pub(super) async fn refuse(
        &self,
        mut fields: Value,
        id: Option<&Value>,
        text: String,
        cbor: bool,
    ) {
        if let Some(id) = id {
            fields["id"] = id.clone();
        }
        fields["values"] = Value::String(text);
        self.send_value(&fields, cbor).await;
    }

    /// One whole operation, as a CBOR binary frame or JSON text.
    pub(crate) async fn send_value(&self, v: &Value, cbor: bool) {
        let mut buf = Vec::new();
        let frame = if cbor && ciborium::into_writer(v, &mut buf).is_ok() {
            WsMessage::Binary(Bytes::from(buf))
        } else {
            WsMessage::text(v.to_string())
        };
        self.send(frame).await;
    }

    /// Something the call table queued for this client.
    pub(crate) async fn on_peer(&mut self, m: PeerMsg) {
        match m {
            PeerMsg::Call(req) => self.serve_call(req).await,
            PeerMsg::Cancel(call) => self.cancel_served(call).await,
            PeerMsg::Event(ev) => self.call_event(ev).await,
            PeerMsg::Changed(_) => {}
        }
    }
}
