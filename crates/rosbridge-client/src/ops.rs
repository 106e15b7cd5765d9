//! The rosbridge v2 operations the client sends and the ones it reads from the server,
//! as JSON text. No I/O.
//!
//! What the server sends is read by its envelope only: a message object or a service's
//! values stay the text that arrived ([`RawValue`]), so a message goes into the router as
//! the server encoded it, never parsed and written again.

use serde::Deserialize;
use serde_json::value::RawValue;
use serde_json::{Value, json};

/// One operation from the server, the fields this client reads.
#[derive(Debug, Deserialize)]
pub struct ServerOp<'a> {
    pub op: String,
    #[serde(default)]
    pub id: Option<Value>,
    #[serde(default)]
    pub topic: Option<String>,
    #[serde(default)]
    pub service: Option<String>,
    #[serde(default)]
    pub action: Option<String>,
    /// A publish's message object, or a `status` operation's text.
    #[serde(default, borrow)]
    pub msg: Option<&'a RawValue>,
    /// A `service_response`'s or an action's values (or the text of a failure).
    #[serde(default, borrow)]
    pub values: Option<&'a RawValue>,
    /// A `call_service`'s request.
    #[serde(default, borrow)]
    pub args: Option<&'a RawValue>,
    #[serde(default)]
    pub result: Option<bool>,
    #[serde(default)]
    pub status: Option<u32>,
    #[serde(default)]
    pub level: Option<String>,
}

impl<'a> ServerOp<'a> {
    pub fn parse(text: &'a str) -> Result<ServerOp<'a>, serde_json::Error> {
        serde_json::from_str(text)
    }

    /// The id as the client wrote it (a string), if it is one.
    pub fn id_str(&self) -> Option<&str> {
        self.id.as_ref().and_then(Value::as_str)
    }
}

/// The text of a failure's `values` or a status's `msg`: the string itself, or the
/// JSON as sent when it is not a string.
pub fn text_of(raw: Option<&RawValue>) -> String {
    match raw {
        None => String::new(),
        Some(r) => serde_json::from_str::<String>(r.get()).unwrap_or_else(|_| r.get().to_owned()),
    }
}

fn quoted(s: &str) -> String {
    Value::from(s).to_string()
}

pub fn subscribe(topic: &str, type_name: &str) -> String {
    json!({"op": "subscribe", "id": format!("sub:{topic}"), "topic": topic, "type": type_name})
        .to_string()
}

pub fn unsubscribe(topic: &str) -> String {
    json!({"op": "unsubscribe", "id": format!("sub:{topic}"), "topic": topic}).to_string()
}

pub fn advertise(topic: &str, type_name: &str) -> String {
    json!({"op": "advertise", "id": format!("adv:{topic}"), "topic": topic, "type": type_name})
        .to_string()
}

/// `call_service` with `args` given as JSON text (an object).
pub fn call_service(id: &str, service: &str, type_name: Option<&str>, args: &[u8]) -> Vec<u8> {
    let mut out = format!(
        r#"{{"op":"call_service","id":{},"service":{}"#,
        quoted(id),
        quoted(service)
    );
    if let Some(t) = type_name.filter(|t| !t.is_empty()) {
        out.push_str(&format!(r#","type":{}"#, quoted(t)));
    }
    out.push_str(r#","args":"#);
    let mut out = out.into_bytes();
    out.extend_from_slice(args);
    out.push(b'}');
    out
}

/// `send_action_goal` with the goal given as JSON text (an object).
pub fn send_action_goal(id: &str, action: &str, action_type: &str, args: &[u8]) -> Vec<u8> {
    let mut out = format!(
        r#"{{"op":"send_action_goal","id":{},"action":{},"action_type":{},"feedback":true,"args":"#,
        quoted(id),
        quoted(action),
        quoted(action_type)
    )
    .into_bytes();
    out.extend_from_slice(args);
    out.push(b'}');
    out
}

pub fn cancel_action_goal(id: &str, action: &str) -> String {
    json!({"op": "cancel_action_goal", "id": id, "action": action}).to_string()
}

pub fn advertise_service(service: &str, type_name: &str) -> String {
    json!({"op": "advertise_service", "service": service, "type": type_name}).to_string()
}

pub fn unadvertise_service(service: &str) -> String {
    json!({"op": "unadvertise_service", "service": service}).to_string()
}

/// The answer to a server program's call of a service this client advertised: `values`
/// is the response object as JSON text, or (when `result` is false) the reason.
pub fn service_response(id: Option<&Value>, service: &str, values: &[u8], result: bool) -> Vec<u8> {
    let mut out = format!(
        r#"{{"op":"service_response","service":{},"result":{result}"#,
        quoted(service)
    );
    if let Some(id) = id {
        out.push_str(&format!(r#","id":{id}"#));
    }
    out.push_str(r#","values":"#);
    let mut out = out.into_bytes();
    out.extend_from_slice(values);
    out.push(b'}');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn built_operations_are_json_with_the_raw_parts_spliced_in() {
        let v: Value =
            serde_json::from_slice(&call_service("c:1", "/add", Some("a/srv/B"), br#"{"a":1}"#))
                .unwrap();
        assert_eq!(
            v,
            json!({"op":"call_service","id":"c:1","service":"/add","type":"a/srv/B","args":{"a":1}})
        );
        let v: Value =
            serde_json::from_slice(&service_response(Some(&json!(7)), "/s", br#""no""#, false))
                .unwrap();
        assert_eq!(
            v,
            json!({"op":"service_response","service":"/s","result":false,"id":7,"values":"no"})
        );
        let v: Value =
            serde_json::from_slice(&send_action_goal("g:1", "/nav", "a/action/N", b"{}")).unwrap();
        assert_eq!(v["feedback"], json!(true));
        assert_eq!(v["action_type"], json!("a/action/N"));
    }

    #[test]
    fn server_operations_keep_their_message_text() {
        let text = r#"{"op":"publish","topic":"/chatter","msg":{"data": "hi"}}"#;
        let op = ServerOp::parse(text).unwrap();
        assert_eq!(op.op, "publish");
        assert_eq!(op.topic.as_deref(), Some("/chatter"));
        assert_eq!(op.msg.unwrap().get(), r#"{"data": "hi"}"#);
        let status = ServerOp::parse(
            r#"{"op":"status","level":"error","id":"sub:/x","msg":"unknown type"}"#,
        )
        .unwrap();
        assert_eq!(text_of(status.msg), "unknown type");
        assert_eq!(status.id_str(), Some("sub:/x"));
        assert!(ServerOp::parse("[1]").is_err());
    }
}
