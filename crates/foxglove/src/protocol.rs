//! The Foxglove WebSocket protocol (v1) as the hub speaks it: the JSON operations a client
//! sends, the JSON operations the hub sends, and the binary messages both ways. No I/O.
//!
//! Why these types are our own and not the `foxglove` crate's: that crate's protocol
//! types (`foxglove::protocol::v1`) come with the Foxglove SDK, which brings its own
//! server, logging context, generated schemas and protobuf support — a large build for a
//! dozen small JSON shapes. And the one hot path, `MessageData`, must not be built as a
//! message of its own per subscriber here: the hub writes a 13-byte header per
//! subscription in front of payload bytes shared by every subscriber
//! ([`message_data_header`]), which no message type expresses.
//!
//! Binary layouts (all integers little-endian):
//!
//! ```text
//! server MessageData        0x01 | subscription u32 | receive time ns u64 | payload
//! server ServiceCallResponse 0x03 | service u32 | call u32 | encoding length u32 | encoding | payload
//! client MessageData        0x01 | channel u32 | payload
//! client ServiceCallRequest 0x02 | service u32 | call u32 | encoding length u32 | encoding | payload
//! ```

use bytes::{Buf, BufMut, Bytes, BytesMut};
use serde::{Deserialize, Serialize};
use serde_json::{Value, json};

/// The subprotocols a Foxglove session answers to: the current Foxglove app offers the
/// first, Lichtblick and older clients the second; they are the same protocol today.
pub const SUBPROTOCOLS: [&str; 2] = ["foxglove.sdk.v1", "foxglove.websocket.v1"];

/// The first of the client's offered subprotocols that is a Foxglove one (the client's
/// order is its preference), as the hub echoes it in the 101 answer.
pub fn choose_subprotocol<'a>(offered: impl IntoIterator<Item = &'a str>) -> Option<&'static str> {
    offered
        .into_iter()
        .find_map(|p| SUBPROTOCOLS.iter().find(|s| **s == p.trim()).copied())
}

/// Server binary opcode: a message on a subscription.
pub const MESSAGE_DATA: u8 = 0x01;
/// Server binary opcode: the answer to a service call.
pub const SERVICE_CALL_RESPONSE: u8 = 0x03;
/// Client binary opcode: a message on one of the client's advertised channels.
pub const CLIENT_MESSAGE_DATA: u8 = 0x01;
/// Client binary opcode: a service call.
pub const SERVICE_CALL_REQUEST: u8 = 0x02;

/// Bytes of a `MessageData` before its payload.
pub const MESSAGE_DATA_HEADER: usize = 13;

/// The part of a `MessageData` that differs per subscription; the payload behind it is
/// the same bytes for every subscriber.
pub fn message_data_header(subscription: u32, receive_ns: u64) -> [u8; MESSAGE_DATA_HEADER] {
    let mut h = [0u8; MESSAGE_DATA_HEADER];
    h[0] = MESSAGE_DATA;
    h[1..5].copy_from_slice(&subscription.to_le_bytes());
    h[5..13].copy_from_slice(&receive_ns.to_le_bytes());
    h
}

/// A service call's answer as one binary message.
pub fn service_call_response(service: u32, call: u32, encoding: &str, payload: &[u8]) -> Bytes {
    let mut b = BytesMut::with_capacity(13 + encoding.len() + payload.len());
    b.put_u8(SERVICE_CALL_RESPONSE);
    b.put_u32_le(service);
    b.put_u32_le(call);
    b.put_u32_le(encoding.len() as u32);
    b.put_slice(encoding.as_bytes());
    b.put_slice(payload);
    b.freeze()
}

/// A binary message from a client.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ClientBinary {
    MessageData { channel: u32, payload: Bytes },
    ServiceCallRequest(ServiceCall),
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ServiceCall {
    pub service: u32,
    pub call: u32,
    pub encoding: String,
    pub payload: Bytes,
}

/// Why a client's binary message was not read. A WebSocket message is whole when it
/// arrives, so a short one is cut, not waiting for more: `Truncated` says how much the
/// layout needs.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BinaryError {
    #[error("an empty binary message (no opcode)")]
    Empty,
    #[error("binary opcode 0x{op:02x}: {need} bytes needed, the message has {have}")]
    Truncated { op: u8, need: usize, have: usize },
    #[error("unknown binary opcode 0x{0:02x}")]
    UnknownOpcode(u8),
    #[error("service call request: the encoding name is not UTF-8")]
    EncodingNotUtf8,
}

/// Reads a client's binary message; payloads are slices of `b`, not copies.
pub fn parse_client_binary(b: &Bytes) -> Result<ClientBinary, BinaryError> {
    let Some(&op) = b.first() else {
        return Err(BinaryError::Empty);
    };
    let need = |n: usize| {
        if b.len() < n {
            Err(BinaryError::Truncated {
                op,
                need: n,
                have: b.len(),
            })
        } else {
            Ok(())
        }
    };
    let mut r = &b[1..];
    match op {
        CLIENT_MESSAGE_DATA => {
            need(5)?;
            let channel = r.get_u32_le();
            Ok(ClientBinary::MessageData {
                channel,
                payload: b.slice(5..),
            })
        }
        SERVICE_CALL_REQUEST => {
            need(13)?;
            let service = r.get_u32_le();
            let call = r.get_u32_le();
            let len = r.get_u32_le() as usize;
            let end = 13usize.saturating_add(len);
            need(end)?;
            let encoding = std::str::from_utf8(&b[13..end])
                .map_err(|_| BinaryError::EncodingNotUtf8)?
                .to_owned();
            Ok(ClientBinary::ServiceCallRequest(ServiceCall {
                service,
                call,
                encoding,
                payload: b.slice(end..),
            }))
        }
        other => Err(BinaryError::UnknownOpcode(other)),
    }
}

/// A JSON operation from a client.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(
    tag = "op",
    rename_all = "camelCase",
    rename_all_fields = "camelCase",
    deny_unknown_fields
)]
pub enum ClientOp {
    Subscribe {
        subscriptions: Vec<Subscription>,
    },
    Unsubscribe {
        subscription_ids: Vec<u32>,
    },
    Advertise {
        channels: Vec<ClientChannel>,
    },
    Unadvertise {
        channel_ids: Vec<u32>,
    },
    GetParameters {
        parameter_names: Vec<String>,
        #[serde(default)]
        id: Option<String>,
    },
}

/// Operations of the protocol this hub does not implement (their capability is not
/// announced): refused by name rather than as unknown.
const NOT_IMPLEMENTED: [&str; 7] = [
    "setParameters",
    "subscribeParameterUpdates",
    "unsubscribeParameterUpdates",
    "subscribeConnectionGraph",
    "unsubscribeConnectionGraph",
    "fetchAsset",
    "playbackControl",
];

#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Subscription {
    pub id: u32,
    pub channel_id: u32,
}

/// A channel a client advertises to publish on.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct ClientChannel {
    pub id: u32,
    pub topic: String,
    pub encoding: String,
    pub schema_name: String,
    #[serde(default)]
    pub schema: Option<String>,
    #[serde(default)]
    pub schema_encoding: Option<String>,
}

/// Why a client's text message was not read, for its `status` answer.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TextError {
    #[error("malformed JSON: {0}")]
    Malformed(String),
    #[error("a text message must be a JSON object with a string field 'op'")]
    NoOp,
    #[error("unknown operation '{0}'")]
    UnknownOp(String),
    #[error("operation '{0}' is not supported by this server (its capability is not announced)")]
    NotSupported(String),
    #[error("{op}: {cause}")]
    BadFields { op: String, cause: String },
}

/// Reads a client's text message.
pub fn parse_client_text(text: &[u8]) -> Result<ClientOp, TextError> {
    let v: Value = serde_json::from_slice(text).map_err(|e| TextError::Malformed(e.to_string()))?;
    let Some(op) = v.get("op").and_then(Value::as_str).map(str::to_owned) else {
        return Err(TextError::NoOp);
    };
    match op.as_str() {
        "subscribe" | "unsubscribe" | "advertise" | "unadvertise" | "getParameters" => {
            serde_json::from_value(v).map_err(|e| TextError::BadFields {
                op,
                cause: e.to_string(),
            })
        }
        o if NOT_IMPLEMENTED.contains(&o) => Err(TextError::NotSupported(op)),
        _ => Err(TextError::UnknownOp(op.chars().take(64).collect())),
    }
}

/// A channel as the hub advertises it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Channel {
    pub id: u32,
    pub topic: String,
    pub encoding: &'static str,
    pub schema_name: String,
    pub schema: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub schema_encoding: Option<&'static str>,
}

/// One side (request or response) of a service's definition.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct ServicePart {
    pub encoding: &'static str,
    pub schema_name: String,
    pub schema_encoding: &'static str,
    pub schema: String,
}

/// A service as the hub advertises it: both the `request`/`response` objects of the
/// current protocol and the older `requestSchema`/`responseSchema` strings, so old and
/// new clients read it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Service {
    pub id: u32,
    pub name: String,
    #[serde(rename = "type")]
    pub type_name: String,
    pub request: ServicePart,
    pub response: ServicePart,
    pub request_schema: String,
    pub response_schema: String,
}

/// Capabilities this hub implements, as `serverInfo` names them.
pub const CAP_CLIENT_PUBLISH: &str = "clientPublish";
pub const CAP_SERVICES: &str = "services";
pub const CAP_PARAMETERS: &str = "parameters";

pub fn server_info(
    name: &str,
    capabilities: &[&str],
    encodings: &[&str],
    session_id: &str,
) -> String {
    json!({
        "op": "serverInfo",
        "name": name,
        "capabilities": capabilities,
        "supportedEncodings": encodings,
        "metadata": {},
        "sessionId": session_id,
    })
    .to_string()
}

/// Severity of a `status`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Level {
    Info = 0,
    Warning = 1,
    Error = 2,
}

pub fn status(level: Level, message: &str) -> String {
    json!({ "op": "status", "level": level as u8, "message": message }).to_string()
}

pub fn advertise(channels: &[Channel]) -> String {
    json!({ "op": "advertise", "channels": channels }).to_string()
}

pub fn unadvertise(ids: &[u32]) -> String {
    json!({ "op": "unadvertise", "channelIds": ids }).to_string()
}

pub fn advertise_services(services: &[Service]) -> String {
    json!({ "op": "advertiseServices", "services": services }).to_string()
}

pub fn unadvertise_services(ids: &[u32]) -> String {
    json!({ "op": "unadvertiseServices", "serviceIds": ids }).to_string()
}

pub fn service_call_failure(service: u32, call: u32, message: &str) -> String {
    json!({
        "op": "serviceCallFailure",
        "serviceId": service,
        "callId": call,
        "message": message,
    })
    .to_string()
}

/// `parameterValues`: `(name, value)` pairs, answering the request `id` when it had one.
pub fn parameter_values(params: &[(String, Value)], id: Option<&str>) -> String {
    let list: Vec<Value> = params
        .iter()
        .map(|(n, v)| json!({ "name": n, "value": v }))
        .collect();
    let mut v = json!({ "op": "parameterValues", "parameters": list });
    if let Some(id) = id {
        v["id"] = json!(id);
    }
    v.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_client_s_first_foxglove_subprotocol_is_chosen() {
        assert_eq!(
            choose_subprotocol(["x", "foxglove.websocket.v1", "foxglove.sdk.v1"]),
            Some("foxglove.websocket.v1")
        );
        assert_eq!(
            choose_subprotocol([" foxglove.sdk.v1"]),
            Some("foxglove.sdk.v1")
        );
        assert_eq!(choose_subprotocol(["fleetlink.v1"]), None);
    }

    #[test]
    fn message_data_header_lays_out_opcode_subscription_and_time_little_endian() {
        let h = message_data_header(0x0102_0304, 0x1122_3344_5566_7788);
        assert_eq!(
            h,
            [
                0x01, 0x04, 0x03, 0x02, 0x01, 0x88, 0x77, 0x66, 0x55, 0x44, 0x33, 0x22, 0x11
            ]
        );
    }

    #[test]
    fn service_call_request_and_response_round_trip() {
        let mut b = BytesMut::new();
        b.put_u8(SERVICE_CALL_REQUEST);
        b.put_u32_le(7);
        b.put_u32_le(9);
        b.put_u32_le(4);
        b.put_slice(b"json");
        b.put_slice(b"{}");
        let got = parse_client_binary(&b.freeze()).expect("reads");
        assert_eq!(
            got,
            ClientBinary::ServiceCallRequest(ServiceCall {
                service: 7,
                call: 9,
                encoding: "json".into(),
                payload: Bytes::from_static(b"{}"),
            })
        );
        let resp = service_call_response(7, 9, "json", b"{\"a\":1}");
        assert_eq!(resp[0], SERVICE_CALL_RESPONSE);
        assert_eq!(&resp[1..5], &7u32.to_le_bytes());
        assert_eq!(&resp[5..9], &9u32.to_le_bytes());
        assert_eq!(&resp[9..13], &4u32.to_le_bytes());
        assert_eq!(&resp[13..17], b"json");
        assert_eq!(&resp[17..], b"{\"a\":1}");
    }

    #[test]
    fn client_message_data_keeps_its_payload_as_a_slice() {
        let b = Bytes::from_static(&[0x01, 5, 0, 0, 0, 0xaa, 0xbb]);
        assert_eq!(
            parse_client_binary(&b),
            Ok(ClientBinary::MessageData {
                channel: 5,
                payload: Bytes::from_static(&[0xaa, 0xbb]),
            })
        );
    }

    #[test]
    fn malformed_binary_messages_are_named() {
        let p = |b: &'static [u8]| parse_client_binary(&Bytes::from_static(b));
        assert_eq!(p(&[]), Err(BinaryError::Empty));
        assert_eq!(
            p(&[0x01, 1, 2]),
            Err(BinaryError::Truncated {
                op: 1,
                need: 5,
                have: 3
            })
        );
        // An encoding length that runs past the end (and one that would overflow).
        assert!(matches!(
            p(&[0x02, 0, 0, 0, 0, 0, 0, 0, 0, 9, 0, 0, 0, b'j']),
            Err(BinaryError::Truncated { need: 22, .. })
        ));
        assert!(matches!(
            p(&[0x02, 0, 0, 0, 0, 0, 0, 0, 0, 0xff, 0xff, 0xff, 0xff]),
            Err(BinaryError::Truncated { .. })
        ));
        assert_eq!(
            p(&[0x02, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0xff]),
            Err(BinaryError::EncodingNotUtf8)
        );
        assert_eq!(p(&[0x7f]), Err(BinaryError::UnknownOpcode(0x7f)));
    }

    mod any_input {
        use super::*;
        use proptest::prelude::*;

        proptest! {
            /// Whatever a client sends, reading it gives an operation or an error, never a
            /// panic.
            #[test]
            fn any_bytes_read_or_fail_cleanly(b in proptest::collection::vec(any::<u8>(), 0..64)) {
                let _ = parse_client_binary(&Bytes::from(b.clone()));
                let _ = parse_client_text(&b);
            }

            /// A service call request as a client lays it out reads back field for field.
            #[test]
            fn a_service_call_request_reads_back(
                service in any::<u32>(),
                call in any::<u32>(),
                encoding in "[a-z0-9]{0,12}",
                payload in proptest::collection::vec(any::<u8>(), 0..256),
            ) {
                let mut b = BytesMut::new();
                b.put_u8(SERVICE_CALL_REQUEST);
                b.put_u32_le(service);
                b.put_u32_le(call);
                b.put_u32_le(encoding.len() as u32);
                b.put_slice(encoding.as_bytes());
                b.put_slice(&payload);
                let got = parse_client_binary(&b.freeze());
                prop_assert_eq!(got, Ok(ClientBinary::ServiceCallRequest(ServiceCall {
                    service,
                    call,
                    encoding,
                    payload: Bytes::from(payload),
                })));
            }
        }
    }

    #[test]
    fn client_text_operations_are_read_and_errors_say_what_is_wrong() {
        assert_eq!(
            parse_client_text(br#"{"op":"subscribe","subscriptions":[{"id":1,"channelId":4}]}"#),
            Ok(ClientOp::Subscribe {
                subscriptions: vec![Subscription {
                    id: 1,
                    channel_id: 4
                }]
            })
        );
        assert_eq!(
            parse_client_text(br#"{"op":"getParameters","parameterNames":["/a"],"id":"r"}"#),
            Ok(ClientOp::GetParameters {
                parameter_names: vec!["/a".into()],
                id: Some("r".into())
            })
        );
        let adv = parse_client_text(
            br#"{"op":"advertise","channels":[{"id":2,"topic":"/t","encoding":"json","schemaName":"std_msgs/msg/String"}]}"#,
        );
        assert!(
            matches!(adv, Ok(ClientOp::Advertise { channels }) if channels[0].schema.is_none())
        );
        assert!(matches!(
            parse_client_text(b"{"),
            Err(TextError::Malformed(_))
        ));
        assert_eq!(parse_client_text(b"[1]"), Err(TextError::NoOp));
        assert_eq!(
            parse_client_text(br#"{"op":"dance"}"#),
            Err(TextError::UnknownOp("dance".into()))
        );
        assert_eq!(
            parse_client_text(br#"{"op":"setParameters","parameters":[]}"#),
            Err(TextError::NotSupported("setParameters".into()))
        );
        let bad =
            parse_client_text(br#"{"op":"subscribe","subscriptions":[{"id":-1,"channelId":4}]}"#);
        assert!(
            matches!(&bad, Err(TextError::BadFields { op, .. }) if op == "subscribe"),
            "{bad:?}"
        );
    }

    #[test]
    fn server_operations_carry_the_protocol_s_field_names() {
        let ch = Channel {
            id: 3,
            topic: "/r/scan".into(),
            encoding: "cdr",
            schema_name: "sensor_msgs/msg/LaserScan".into(),
            schema: "float32 x".into(),
            schema_encoding: Some("ros2msg"),
        };
        let v: Value = serde_json::from_str(&advertise(&[ch])).unwrap();
        assert_eq!(v["op"], "advertise");
        assert_eq!(v["channels"][0]["schemaName"], "sensor_msgs/msg/LaserScan");
        assert_eq!(v["channels"][0]["schemaEncoding"], "ros2msg");
        let v: Value = serde_json::from_str(&status(Level::Error, "no")).unwrap();
        assert_eq!(
            (v["level"].as_u64(), v["message"].as_str()),
            (Some(2), Some("no"))
        );
        let v: Value =
            serde_json::from_str(&parameter_values(&[("/a".into(), json!(1))], Some("q"))).unwrap();
        assert_eq!(v["parameters"][0]["name"], "/a");
        assert_eq!(v["id"], "q");
    }
}
