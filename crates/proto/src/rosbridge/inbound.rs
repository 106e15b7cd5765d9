//! Parsing client operations.
//!
//! Both frame kinds are first turned into a small JSON envelope (the operation's scalar
//! fields) plus, for operations that carry a message, the message object as encoded bytes
//! in the frame's own encoding. Field checks then run once, on the envelope.
//!
//! The parts, all re-exported here:
//!
//! - `ops`: the operations as values ([`Request`], [`Op`], [`ParseError`]).
//! - `parse`: the full parse of a JSON or CBOR frame ([`Request::from_json`],
//!   [`Request::from_cbor`]).
//! - `publish`: the short path for `publish` ([`Publish`]), which borrows from the frame.
//! - `fields`: typed, checked reading of an envelope's fields.

mod fields;
mod ops;
mod parse;
mod publish;

pub use ops::{Compression, Op, ParseError, Request, payload_bytes};
pub use publish::{Publish, PublishId};

#[cfg(test)]
mod tests {
    use bytes::Bytes;
    use serde_json::Value;

    use super::fields::valid_topic;
    use super::*;
    use crate::payload::Encoding;
    use crate::rosbridge::convert;

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
