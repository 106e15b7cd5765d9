//! Frames the server sends to rosbridge clients.
//!
//! A `publish` frame is built by splicing the already-encoded message object into a small
//! envelope, so a message converted once can be framed without being parsed again.

use bytes::{BufMut, Bytes, BytesMut};
use serde_json::{Value, json};

/// `{"op":"publish","topic":T,"msg":<msg_json>}` as JSON text.
pub fn publish_json(topic: &str, msg_json: &[u8]) -> Bytes {
    let mut b = BytesMut::with_capacity(msg_json.len() + topic.len() + 40);
    b.put_slice(br#"{"op":"publish","topic":"#);
    match escaped(topic) {
        None => {
            b.put_u8(b'"');
            b.put_slice(topic.as_bytes());
            b.put_u8(b'"');
        }
        Some(quoted) => b.put_slice(quoted.as_bytes()),
    }
    b.put_slice(br#","msg":"#);
    b.put_slice(msg_json);
    b.put_u8(b'}');
    b.freeze()
}

/// `{"op":"publish","topic":T,"msg":` — what every JSON `publish` frame of `topic` starts
/// with; the frame is this, the message object, and `}`.
pub fn publish_json_head(topic: &str) -> String {
    const HEAD: &str = r#"{"op":"publish","topic":"#;
    const MSG: &str = r#","msg":"#;
    let mut s = String::with_capacity(HEAD.len() + topic.len() + 2 + MSG.len());
    s.push_str(HEAD);
    match escaped(topic) {
        None => {
            s.push('"');
            s.push_str(topic);
            s.push('"');
        }
        Some(quoted) => s.push_str(&quoted),
    }
    s.push_str(MSG);
    s
}

/// A topic name as a JSON string when it needs escapes; `None` when it can be written as
/// it is between quotes. Names never need escapes in practice, and this spares every
/// message the quoted copy serde_json would make.
fn escaped(topic: &str) -> Option<String> {
    if topic.bytes().all(|c| c >= 0x20 && c != b'"' && c != b'\\') {
        None
    } else {
        Some(serde_json::to_string(topic).expect("a string serializes"))
    }
}

/// The same publish as a CBOR map, with `msg_cbor` spliced in as the `msg` value.
pub fn publish_cbor(topic: &str, msg_cbor: &[u8]) -> Bytes {
    let mut b = BytesMut::with_capacity(msg_cbor.len() + topic.len() + 32);
    cbor_head(&mut b, 5, 3);
    cbor_text(&mut b, "op");
    cbor_text(&mut b, "publish");
    cbor_text(&mut b, "topic");
    cbor_text(&mut b, topic);
    cbor_text(&mut b, "msg");
    b.put_slice(msg_cbor);
    b.freeze()
}

/// A `cbor-raw` publish: `msg` is `{secs, nsecs, bytes}` with the raw ROS serialization.
pub fn publish_cbor_raw(topic: &str, stamp_ns: u64, raw: &[u8]) -> Bytes {
    let mut b = BytesMut::with_capacity(raw.len() + topic.len() + 64);
    cbor_head(&mut b, 5, 3);
    cbor_text(&mut b, "op");
    cbor_text(&mut b, "publish");
    cbor_text(&mut b, "topic");
    cbor_text(&mut b, topic);
    cbor_text(&mut b, "msg");
    cbor_head(&mut b, 5, 3);
    cbor_text(&mut b, "secs");
    cbor_head(&mut b, 0, stamp_ns / 1_000_000_000);
    cbor_text(&mut b, "nsecs");
    cbor_head(&mut b, 0, stamp_ns % 1_000_000_000);
    cbor_text(&mut b, "bytes");
    cbor_head(&mut b, 2, raw.len() as u64);
    b.put_slice(raw);
    b.freeze()
}

/// A `status` message: the error/warning reply to a request.
pub fn status(level: &str, msg: &str, id: Option<&Value>) -> String {
    let mut v = json!({"op": "status", "level": level, "msg": msg});
    if let Some(id) = id {
        v["id"] = id.clone();
    }
    v.to_string()
}

/// A `service_response`, echoing the service name and id exactly.
pub fn service_response(service: &str, id: Option<&Value>, values: Value, result: bool) -> Value {
    let mut v =
        json!({"op": "service_response", "service": service, "values": values, "result": result});
    if let Some(id) = id {
        v["id"] = id.clone();
    }
    v
}

/// Splits `text` into rosbridge `fragment` operations of at most `size` characters of data.
/// Fragments are cut on character boundaries so each is valid UTF-8.
pub fn fragments(id: &str, text: &str, size: usize) -> Vec<String> {
    let size = size.max(1);
    let mut pieces = Vec::new();
    let mut start = 0;
    while start < text.len() {
        let mut end = (start + size).min(text.len());
        while !text.is_char_boundary(end) {
            end -= 1;
        }
        if end == start {
            end = start + text[start..].chars().next().map_or(1, char::len_utf8);
        }
        pieces.push(&text[start..end]);
        start = end;
    }
    let total = pieces.len();
    pieces
        .into_iter()
        .enumerate()
        .map(|(num, data)| {
            json!({"op": "fragment", "id": id, "data": data, "num": num, "total": total})
                .to_string()
        })
        .collect()
}

/// An operation object whose `body_key` value is an already encoded JSON value, spliced in
/// without being parsed: `fields` must be a JSON object (without `body_key`).
pub fn op_json(fields: &Value, body_key: &str, body_json: &[u8]) -> Bytes {
    let head = fields.to_string();
    debug_assert!(head.starts_with('{') && head.ends_with('}'));
    let key = serde_json::to_string(body_key).expect("a string serializes");
    let mut b = BytesMut::with_capacity(head.len() + key.len() + body_json.len() + 4);
    b.put_slice(&head.as_bytes()[..head.len() - 1]);
    if head.len() > 2 {
        b.put_u8(b',');
    }
    b.put_slice(key.as_bytes());
    b.put_u8(b':');
    b.put_slice(body_json);
    b.put_u8(b'}');
    b.freeze()
}

/// The same operation as a CBOR map, with `body_cbor` (an encoded CBOR value) spliced in
/// as the `body_key` value. `fields` must be a JSON object of plain values.
pub fn op_cbor(fields: &Value, body_key: &str, body_cbor: &[u8]) -> Bytes {
    let map = fields.as_object().cloned().unwrap_or_default();
    let mut b = BytesMut::with_capacity(body_cbor.len() + 64 * (map.len() + 1));
    cbor_head(&mut b, 5, map.len() as u64 + 1);
    for (k, v) in &map {
        cbor_text(&mut b, k);
        let mut enc = Vec::new();
        ciborium::into_writer(v, &mut enc).expect("a JSON value encodes as CBOR");
        b.put_slice(&enc);
    }
    cbor_text(&mut b, body_key);
    b.put_slice(body_cbor);
    b.freeze()
}

fn cbor_head(b: &mut BytesMut, major: u8, len: u64) {
    let m = major << 5;
    match len {
        0..=23 => b.put_u8(m | len as u8),
        24..=0xff => {
            b.put_u8(m | 24);
            b.put_u8(len as u8);
        }
        0x100..=0xffff => {
            b.put_u8(m | 25);
            b.put_u16(len as u16);
        }
        0x1_0000..=0xffff_ffff => {
            b.put_u8(m | 26);
            b.put_u32(len as u32);
        }
        _ => {
            b.put_u8(m | 27);
            b.put_u64(len);
        }
    }
}

fn cbor_text(b: &mut BytesMut, s: &str) {
    cbor_head(b, 3, s.len() as u64);
    b.put_slice(s.as_bytes());
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn publish_json_is_valid_json_with_escaped_topic() {
        for topic in ["/a/b", "/é_1", "/a\"b", "/a\\b", "/a\u{1}b", "/a\nb"] {
            let f = publish_json(topic, br#"{"x":1}"#);
            let v: Value = serde_json::from_slice(&f).unwrap();
            assert_eq!(v, json!({"op":"publish","topic":topic,"msg":{"x":1}}));
            // The head, the message and a brace are the same frame.
            let spliced = format!("{}{}}}", publish_json_head(topic), r#"{"x":1}"#);
            assert_eq!(spliced.as_bytes(), &f[..]);
        }
    }

    #[test]
    fn publish_cbor_decodes_as_a_map() {
        let mut msg = Vec::new();
        ciborium::into_writer(&ciborium::Value::Bytes(vec![9; 300]), &mut msg).unwrap();
        let f = publish_cbor("/t", &msg);
        let v: ciborium::Value = ciborium::from_reader(&f[..]).unwrap();
        let m = v.as_map().unwrap();
        assert_eq!(m[1].1, ciborium::Value::Text("/t".into()));
        assert_eq!(m[2].1, ciborium::Value::Bytes(vec![9; 300]));
    }

    #[test]
    fn cbor_raw_carries_stamp_and_bytes() {
        let f = publish_cbor_raw("/t", 3_000_000_007, &[1, 2]);
        let v: ciborium::Value = ciborium::from_reader(&f[..]).unwrap();
        let inner = v.as_map().unwrap()[2].1.as_map().unwrap().clone();
        assert_eq!(inner[0].1, ciborium::Value::Integer(3.into()));
        assert_eq!(inner[1].1, ciborium::Value::Integer(7.into()));
        assert_eq!(inner[2].1, ciborium::Value::Bytes(vec![1, 2]));
    }

    #[test]
    fn spliced_operations_decode_to_the_same_object() {
        let fields = json!({"op": "call_service", "id": "c:1", "service": "/s"});
        let j = op_json(&fields, "args", br#"{"a":[1,2]}"#);
        let v: Value = serde_json::from_slice(&j).unwrap();
        assert_eq!(
            v,
            json!({"op":"call_service","id":"c:1","service":"/s","args":{"a":[1,2]}})
        );
        let mut body = Vec::new();
        ciborium::into_writer(&json!({"a": [1, 2]}), &mut body).unwrap();
        let c = op_cbor(&fields, "args", &body);
        let back: Value = ciborium::from_reader(&c[..]).unwrap();
        assert_eq!(back, v);
        let empty = op_json(&json!({}), "values", b"true");
        assert_eq!(&empty[..], br#"{"values":true}"#);
    }

    #[test]
    fn fragments_reassemble_to_the_original() {
        let text = "héllo wörld ✓".repeat(5);
        let parts = fragments("f1", &text, 7);
        let mut joined = String::new();
        for p in &parts {
            let v: Value = serde_json::from_str(p).unwrap();
            assert_eq!(v["total"], parts.len());
            joined.push_str(v["data"].as_str().unwrap());
        }
        assert_eq!(joined, text);
    }
}
