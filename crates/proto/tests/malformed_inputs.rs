//! One test per attack on the decoders. Each asserts a clean error: no panic, no stack
//! overflow, and no allocation sized by a number the peer wrote (a test that allocated
//! 2^40 bytes would abort the binary, so passing is the evidence).

use bytes::{Bytes, BytesMut};
use fleetlink_proto::ErrorKind;
use fleetlink_proto::frame::{self, CallStatus, Frame, FrameKind, Level};
use fleetlink_proto::reassembly::{CallReassembler, Reassembler, ReassemblyError};
use fleetlink_proto::rosbridge::{Op, ParseError, Request, convert};
use serde_json::{Value, json};

use crate::util::{self, Body, raw_frame};

const HELLO: u8 = 0x01;
const ADVERTISE: u8 = 0x03;
const MESSAGE: u8 = 0x07;
const CHUNK: u8 = 0x08;
const CALL: u8 = 0x12;
const REPLY: u8 = 0x14;
const CALL_CHUNK: u8 = 0x17;
const DEPTH: usize = 10_000;

fn decode_err(buf: &Bytes) -> fleetlink_proto::DecodeError {
    match Frame::decode(buf, 0) {
        Ok((f, _)) => panic!("decoded {f:?} from hostile input"),
        Err(e) => e,
    }
}

// ---- fleetlink.v1 frames ------------------------------------------------------------

#[test]
fn truncated_frame_of_every_kind_at_every_byte_is_incomplete() {
    for f in util::one_of_each_kind() {
        let whole = f.to_bytes();
        for cut in 0..whole.len() {
            let part = whole.slice(..cut);
            let e = decode_err(&part);
            assert_eq!(e.kind, ErrorKind::Incomplete, "{f:?} cut at {cut}: {e}");
            // The iterator reports the same error once and stops.
            let mut it = frame::frames(&part);
            if cut > 0 {
                assert!(it.next().expect("an error").is_err());
            }
            assert!(it.next().is_none());
        }
    }
}

#[test]
fn body_len_larger_than_the_buffer_is_incomplete() {
    let mut b = BytesMut::from(&[MESSAGE][..]);
    fleetlink_proto::wire::put_varint(&mut b, 1 << 40);
    b.extend_from_slice(&[0; 16]);
    let e = decode_err(&b.freeze());
    assert_eq!(e.kind, ErrorKind::Incomplete);
    assert_eq!(e.context, "frame.body_len");
}

#[test]
fn body_len_varint_overflowing_64_bits_is_invalid() {
    let mut b = vec![MESSAGE];
    b.extend_from_slice(&[0xff; 9]);
    b.push(0x7f); // tenth byte may carry only one bit
    let e = decode_err(&Bytes::from(b));
    assert_eq!(e.kind, ErrorKind::Invalid);
}

#[test]
fn varint_longer_than_ten_bytes_is_invalid() {
    let mut b = vec![MESSAGE];
    b.extend_from_slice(&[0x80; 11]);
    b.push(0);
    let e = decode_err(&Bytes::from(b));
    assert_eq!(e.kind, ErrorKind::Invalid);
}

#[test]
fn field_varint_overflow_inside_a_body_is_invalid() {
    let body = Body::default().raw(&[0xff; 11]);
    let e = decode_err(&raw_frame(HELLO, &body.0));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "HELLO.version"));
}

#[test]
fn alias_above_32_bits_is_invalid() {
    let body = Body::default().varint(1 << 33).varint(1).u64_le(0);
    let e = decode_err(&raw_frame(MESSAGE, &body.0));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "MESSAGE.alias"));
}

#[test]
fn string_length_claiming_2_pow_40_bytes_is_refused() {
    // Inside a complete body: the claim can never be met.
    let body = Body::default().varint(1).varint(1 << 40).raw(b"robot");
    let e = decode_err(&raw_frame(HELLO, &body.0));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "HELLO.robot"));
    // As the last thing in a truncated buffer: more bytes could in principle follow.
    let bytes = Body::default().varint(1 << 40).raw(b"robot").0.freeze();
    let e = fleetlink_proto::wire::Reader::new(&bytes)
        .string("s")
        .expect_err("2^40 bytes are not there");
    assert_eq!(e.kind, ErrorKind::Incomplete);
}

#[test]
fn body_shorter_than_its_fields_is_invalid_not_incomplete() {
    // A PING body needs 16 bytes; this one says (truthfully) that it has 4.
    let e = decode_err(&raw_frame(0x09, &[1, 2, 3, 4]));
    assert_eq!(e.kind, ErrorKind::Invalid, "{e}");
    assert_eq!(e.context, "PING.id");
}

#[test]
fn invalid_utf8_in_topic_is_invalid() {
    let body = Body::default().varint(1).bytes(&[b'/', 0xff, 0xfe]);
    let e = decode_err(&raw_frame(ADVERTISE, &body.0));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "ADVERTISE.topic"));
    assert!(e.reason.contains("UTF-8"), "{e}");
}

#[test]
fn invalid_utf8_in_schema_text_is_invalid() {
    let body = Body::default()
        .varint(1)
        .str("/t")
        .str("std_msgs/String")
        .str("ros1msg")
        .bytes(&[0xc3, 0x28]);
    let e = decode_err(&raw_frame(ADVERTISE, &body.0));
    assert_eq!(e.context, "ADVERTISE.schema_text");
}

#[test]
fn unknown_encoding_byte_is_invalid() {
    let body = Body::default()
        .varint(1)
        .str("/t")
        .str("std_msgs/String")
        .str("ros1msg")
        .str("string data")
        .raw(&[9, 0]);
    let e = decode_err(&raw_frame(ADVERTISE, &body.0));
    assert_eq!(
        (e.kind, e.context),
        (ErrorKind::Invalid, "ADVERTISE.encoding")
    );
    assert!(e.reason.contains('9'), "{e}");
}

fn chunk_body(total_len: u64, offset: u64, data: &[u8]) -> Bytes {
    let body = Body::default()
        .varint(1)
        .varint(1)
        .u64_le(0)
        .varint(total_len)
        .varint(offset)
        .raw(data);
    raw_frame(CHUNK, &body.0)
}

#[test]
fn chunk_whose_offset_plus_len_overruns_total_len_is_invalid() {
    let e = decode_err(&chunk_body(10, 8, b"abc"));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "CHUNK.offset"));
}

#[test]
fn chunk_whose_offset_plus_len_overflows_u64_is_invalid() {
    let e = decode_err(&chunk_body(u64::MAX, u64::MAX, b"a"));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "CHUNK.offset"));
}

#[test]
fn unknown_frame_kind_is_skipped_and_the_next_frame_still_decodes() {
    let mut b = BytesMut::new();
    b.extend_from_slice(&raw_frame(0x7e, b"a body from a future version"));
    Frame::Ack {
        frames: 3,
        bytes: 0,
    }
    .encode(&mut b);
    let got: Vec<Frame> = frame::frames(&b.freeze()).map(Result::unwrap).collect();
    assert_eq!(
        got,
        vec![
            Frame::Unknown { kind: 0x7e },
            Frame::Ack {
                frames: 3,
                bytes: 0
            }
        ]
    );
}

#[test]
fn trailing_fields_from_a_newer_version_are_ignored() {
    for f in util::one_of_each_kind() {
        if rest_of_body(&f).is_some() {
            continue; // their last field is "the rest of the body"
        }
        let plain = f.to_bytes();
        let mut body = plain[1..].to_vec();
        let mut len_reader = fleetlink_proto::wire::Reader::new(&plain);
        len_reader.u8("kind").unwrap();
        let body_len = len_reader.varint("len").unwrap() as usize;
        body.drain(..body.len() - body_len);
        body.extend_from_slice(b"\x05extra");
        let (back, _) = Frame::decode(&raw_frame(f.kind_byte(), &body), 0).unwrap();
        assert_eq!(back, f);
    }
}

/// The last field of frames that end with "the rest of the body", if `f` is one.
fn rest_of_body(f: &Frame) -> Option<&Bytes> {
    match f {
        Frame::Message { payload, .. }
        | Frame::ZMessage { payload, .. }
        | Frame::Call { payload, .. }
        | Frame::Goal { payload, .. }
        | Frame::Reply { payload, .. }
        | Frame::Feedback { payload, .. } => Some(payload),
        Frame::Chunk { data, .. } | Frame::ZChunk { data, .. } | Frame::CallChunk { data, .. } => {
            Some(data)
        }
        _ => None,
    }
}

#[test]
fn call_frame_bodies_cut_short_are_invalid_not_incomplete() {
    let call_frames: Vec<Frame> = util::one_of_each_kind()
        .into_iter()
        .filter(|f| (0x10..=0x17).contains(&f.kind_byte()))
        .collect();
    assert_eq!(call_frames.len(), 8, "one frame of each call kind");
    for f in call_frames {
        let whole = f.to_bytes();
        let (_, body_start) = {
            let mut r = fleetlink_proto::wire::Reader::new(&whole);
            r.u8("kind").unwrap();
            (r.varint("len").unwrap(), r.position())
        };
        let body = &whole[body_start..];
        // Cutting the payload ("rest") only shortens it; any cut before it loses a field.
        let fields_end = body.len() - rest_of_body(&f).map_or(0, Bytes::len);
        for cut in 0..fields_end {
            let e = decode_err(&raw_frame(f.kind_byte(), &body[..cut]));
            assert_eq!(e.kind, ErrorKind::Invalid, "{f:?} cut at {cut}: {e}");
        }
    }
}

fn call_body(encoding: u8) -> Bytes {
    let body = Body::default()
        .varint(1)
        .varint(2)
        .varint(3000)
        .raw(&[encoding])
        .raw(b"{}");
    raw_frame(CALL, &body.0)
}

#[test]
fn unknown_encoding_byte_in_a_call_frame_is_invalid() {
    assert!(Frame::decode(&call_body(0), 0).is_ok());
    let e = decode_err(&call_body(9));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "CALL.encoding"));
    assert!(e.reason.contains('9'), "{e}");

    let goal = Body::default()
        .varint(1)
        .varint(2)
        .varint(0)
        .raw(&[0; 16])
        .raw(&[200]);
    let e = decode_err(&raw_frame(FrameKind::Goal as u8, &goal.0));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "GOAL.encoding"));

    let reply = Body::default().varint(1).raw(&[0, 4]);
    let e = decode_err(&raw_frame(REPLY, &reply.0));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "REPLY.encoding"));

    let feedback = Body::default().varint(1).raw(&[4]);
    let e = decode_err(&raw_frame(FrameKind::Feedback as u8, &feedback.0));
    assert_eq!(
        (e.kind, e.context),
        (ErrorKind::Invalid, "FEEDBACK.encoding")
    );
}

#[test]
fn unknown_reply_status_is_read_as_failed() {
    let body = Body::default().varint(1).raw(&[99, 0]).raw(b"later");
    let (f, _) = Frame::decode(&raw_frame(REPLY, &body.0), 0).unwrap();
    assert!(matches!(
        f,
        Frame::Reply {
            status: CallStatus::Failed,
            ..
        }
    ));
}

fn call_chunk_body(kind: u8, total_len: u64, offset: u64, data: &[u8]) -> Bytes {
    let body = Body::default()
        .varint(7)
        .raw(&[kind])
        .varint(total_len)
        .varint(offset)
        .raw(data);
    raw_frame(CALL_CHUNK, &body.0)
}

#[test]
fn call_chunk_continuing_a_frame_without_a_body_is_invalid() {
    for kind in [0x00, 0x07, 0x08, 0x10, 0x11, 0x16, CALL_CHUNK, 0x18, 0xff] {
        let e = decode_err(&call_chunk_body(kind, 10, 0, b"abc"));
        assert_eq!(
            (e.kind, e.context),
            (ErrorKind::Invalid, "CALL_CHUNK.kind"),
            "kind {kind:#04x}"
        );
    }
    for kind in util::CALL_BODY_KINDS {
        assert!(Frame::decode(&call_chunk_body(kind as u8, 10, 0, b"abc"), 0).is_ok());
    }
}

#[test]
fn call_chunk_whose_offset_plus_len_overruns_total_len_is_invalid() {
    for (total_len, offset) in [(10, 8), (u64::MAX, u64::MAX), (0, 0)] {
        let e = decode_err(&call_chunk_body(REPLY, total_len, offset, b"abc"));
        assert_eq!(
            (e.kind, e.context),
            (ErrorKind::Invalid, "CALL_CHUNK.offset")
        );
    }
}

#[test]
fn unknown_status_level_is_read_as_error() {
    let body = Body::default().raw(&[200]).varint(1).varint(0).str("?");
    let (f, _) = Frame::decode(&raw_frame(0x0c, &body.0), 0).unwrap();
    assert!(matches!(
        f,
        Frame::Status {
            level: Level::Error,
            ..
        }
    ));
}

#[test]
fn decoding_past_the_end_of_the_buffer_is_an_error_not_a_panic() {
    let b = Frame::Ack {
        frames: 1,
        bytes: 0,
    }
    .to_bytes();
    assert!(Frame::decode(&b, b.len()).is_err());
    assert!(Frame::decode(&b, b.len() + 100).is_err());
}

#[test]
fn a_bad_frame_stops_the_iterator() {
    let mut b = BytesMut::new();
    Frame::Ack {
        frames: 1,
        bytes: 0,
    }
    .encode(&mut b);
    b.extend_from_slice(&chunk_body(1, 0, b"too long"));
    Frame::Ack {
        frames: 2,
        bytes: 0,
    }
    .encode(&mut b);
    let got: Vec<_> = frame::frames(&b.freeze()).collect();
    assert_eq!(got.len(), 2);
    assert!(got[0].is_ok() && got[1].is_err());
}

// ---- reassembly ---------------------------------------------------------------------

#[test]
fn forged_total_len_of_2_pow_40_is_refused_before_allocating() {
    let wire = chunk_body(1 << 40, 0, b"tiny");
    let (f, _) = Frame::decode(&wire, 0).expect("the frame itself is well formed");
    let Frame::Chunk {
        alias,
        seq,
        stamp_ns,
        total_len,
        offset,
        data,
    } = f
    else {
        panic!("not a chunk");
    };
    let mut r = Reassembler::new(16 << 20, 64 << 20);
    let e = r
        .push(alias, seq, stamp_ns, total_len, offset, &data)
        .unwrap_err();
    assert!(matches!(e, ReassemblyError::TooLarge { total_len, .. } if total_len == 1 << 40));
    assert_eq!(r.buffered(), 0);
}

#[test]
fn out_of_order_chunk_discards_the_partial_message() {
    let mut r = Reassembler::new(100, 100);
    r.push(1, 1, 0, 9, 0, b"abc").unwrap();
    let e = r.push(1, 1, 0, 9, 6, b"ghi").unwrap_err();
    assert!(matches!(
        e,
        ReassemblyError::OutOfOrder {
            offset: 6,
            expected: 3,
            ..
        }
    ));
    assert_eq!(r.buffered(), 0);
    // The piece that was skipped arrives late: there is nothing left to continue.
    assert!(r.push(1, 1, 0, 9, 3, b"def").is_err());
}

#[test]
fn chunk_that_does_not_start_a_message_is_refused() {
    let mut r = Reassembler::new(100, 100);
    let e = r.push(5, 1, 0, 10, 4, b"xy").unwrap_err();
    assert!(matches!(e, ReassemblyError::OutOfOrder { expected: 0, .. }));
}

#[test]
fn chunk_of_another_seq_in_the_middle_of_a_message_is_refused() {
    let mut r = Reassembler::new(100, 100);
    r.push(1, 1, 0, 6, 0, b"abc").unwrap();
    assert!(r.push(1, 2, 0, 6, 3, b"def").is_err());
    assert_eq!(r.buffered(), 0);
}

#[test]
fn reassembly_budget_exhaustion_is_refused_and_recovers() {
    let mut r = Reassembler::new(600, 1000);
    r.push(1, 1, 0, 600, 0, b"a").unwrap();
    let e = r.push(2, 1, 0, 600, 0, b"b").unwrap_err();
    assert_eq!(e, ReassemblyError::BudgetExceeded { limit: 1000 });
    assert_eq!(r.buffered(), 600);
    // Many small starts cannot exceed the budget either.
    let accepted = (10..1000u32)
        .filter(|alias| r.push(*alias, 1, 0, 100, 0, b"c").is_ok())
        .count();
    assert_eq!(accepted, 4);
    assert!(r.buffered() <= 1000);
    // Giving up partial messages frees their share.
    for alias in (1..1000).chain([1]) {
        r.forget(alias);
    }
    assert_eq!(r.buffered(), 0);
    assert!(r.push(2, 1, 0, 600, 0, b"b").is_ok());
}

#[test]
fn call_chunk_with_forged_total_len_of_2_pow_40_is_refused_before_allocating() {
    let wire = call_chunk_body(REPLY, 1 << 40, 0, b"tiny");
    let (f, _) = Frame::decode(&wire, 0).expect("the frame itself is well formed");
    let Frame::CallChunk {
        call_id,
        kind,
        total_len,
        offset,
        data,
    } = f
    else {
        panic!("not a CALL_CHUNK");
    };
    let mut r = CallReassembler::new(16 << 20, 64 << 20);
    let e = r.push(call_id, kind, total_len, offset, &data).unwrap_err();
    assert!(matches!(e, ReassemblyError::CallTooLarge { total_len, .. } if total_len == 1 << 40));
    assert_eq!(r.pending_bytes(), 0);
    // The REPLY that would end the body is refused too, not taken for the whole body.
    assert!(r.finish(call_id, kind, Bytes::from_static(b"end")).is_err());
}

#[test]
fn call_bodies_beyond_the_budget_are_refused_and_the_budget_recovers() {
    let mut r = CallReassembler::new(600, 1000);
    r.push(1, REPLY, 600, 0, b"a").unwrap();
    let e = r.push(2, REPLY, 600, 0, b"b").unwrap_err();
    assert_eq!(e, ReassemblyError::BudgetExceeded { limit: 1000 });
    // Many call ids cannot be used to get around it.
    let accepted = (10..1000u64)
        .filter(|id| r.push(*id, REPLY, 10, 0, b"c").is_ok())
        .count();
    assert!(accepted < 10, "{accepted} more bodies accepted");
    for id in (1..1000).chain([1]) {
        r.forget(id);
    }
    assert_eq!(r.pending_bytes(), 0);
    assert!(r.push(2, REPLY, 600, 0, b"b").is_ok());
}

#[test]
fn a_new_message_on_the_same_alias_abandons_the_old_one() {
    let mut r = Reassembler::new(100, 100);
    r.push(1, 1, 0, 60, 0, b"old").unwrap();
    r.push(1, 2, 0, 60, 0, b"new").unwrap();
    assert_eq!((r.abandoned, r.buffered()), (1, 60));
}

// ---- rosbridge ----------------------------------------------------------------------

fn json_err(text: &str) -> ParseError {
    match Request::from_json(text.as_bytes()) {
        Ok(r) => panic!("accepted {text}: {r:?}"),
        Err(e) => e,
    }
}

fn cbor_err(bytes: &[u8]) -> ParseError {
    match Request::from_cbor(bytes) {
        Ok(r) => panic!("accepted CBOR: {r:?}"),
        Err(e) => e,
    }
}

#[test]
fn invalid_json_is_refused() {
    for text in ["", "{", r#"{"op":"publish""#, "{op:1}", "\u{0}", "[1,]"] {
        let e = json_err(text);
        assert!(e.message.starts_with("invalid JSON"), "{text:?}: {e}");
    }
    let e = Request::from_json(&[b'"', 0xff, b'"']).unwrap_err();
    assert!(e.message.starts_with("invalid JSON"), "{e}");
}

#[test]
fn invalid_cbor_is_refused() {
    // Empty; a reserved additional-info value; a map cut short; a text claiming 2^40 bytes.
    let huge_text = [0x7b, 0, 0, 1, 0, 0, 0, 0, 0, b'x'];
    for bytes in [&[][..], &[0x1c], &[0xa2, 0x62, b'o', b'p'], &huge_text] {
        let e = cbor_err(bytes);
        assert!(e.message.starts_with("invalid CBOR"), "{bytes:?}: {e}");
    }
}

#[test]
fn cbor_array_claiming_2_pow_40_elements_is_refused() {
    let bytes = [0x9b, 0, 0, 1, 0, 0, 0, 0, 0, 0x01];
    assert!(cbor_err(&bytes).message.starts_with("invalid CBOR"));
}

#[test]
fn non_object_json_is_refused() {
    for text in ["[]", "1", r#""publish""#, "null", "true"] {
        let e = json_err(text);
        assert!(e.message.contains("expected a JSON object"), "{text}: {e}");
    }
}

#[test]
fn non_map_cbor_is_refused() {
    for json in ["[]", "1", r#""publish""#] {
        let e = cbor_err(&util::cbor_of(json));
        assert!(e.message.contains("expected a CBOR map"), "{json}: {e}");
    }
}

#[test]
fn cbor_map_with_non_text_keys_is_refused() {
    // {1: "publish"} and {h'6f70': "publish"}
    for bytes in [
        &[0xa1, 0x01, 0x67, b'p', b'u', b'b', b'l', b'i', b's', b'h'][..],
        &[0xa1, 0x42, b'o', b'p', 0x61, b'x'],
    ] {
        let e = cbor_err(bytes);
        assert!(e.message.contains("keys must be text"), "{e}");
    }
}

#[test]
fn missing_op_is_refused_and_keeps_the_id() {
    let text = r#"{"id":"r1","topic":"/a"}"#;
    for e in [json_err(text), cbor_err(&util::cbor_of(text))] {
        assert_eq!(e.id, Some(json!("r1")));
        assert!(e.message.contains("'op'"), "{e}");
    }
}

#[test]
fn op_of_wrong_type_is_refused_and_keeps_the_id() {
    for text in [
        r#"{"id":2,"op":7}"#,
        r#"{"id":2,"op":["publish"]}"#,
        r#"{"id":2,"op":null}"#,
    ] {
        for e in [json_err(text), cbor_err(&util::cbor_of(text))] {
            assert_eq!(e.id, Some(json!(2)));
            assert!(e.message.contains("'op' must be a string"), "{e}");
        }
    }
}

#[test]
fn unknown_op_parses_to_op_unknown() {
    let text = r#"{"op":"teleport","id":"x","level":"info"}"#;
    for r in [
        Request::from_json(text.as_bytes()).unwrap(),
        Request::from_cbor(&util::cbor_of(text)).unwrap(),
    ] {
        assert_eq!(
            r.op,
            Op::Unknown {
                op: "teleport".into()
            }
        );
        assert_eq!(r.id, Some(json!("x")));
    }
}

#[test]
fn an_unknown_op_name_is_kept_only_as_a_short_preview() {
    let long = "x".repeat(5000);
    let r = Request::from_json(json!({"op": long}).to_string().as_bytes()).unwrap();
    let Op::Unknown { op } = r.op else {
        panic!("not unknown")
    };
    assert!(op.len() < 120, "{} bytes echoed", op.len());
    assert!(op.contains("5000 bytes"), "{op}");
}

/// Requests missing a required field or carrying one of the wrong type, with the field
/// the error must name.
const BAD_FIELDS: &[(&str, &str)] = &[
    (r#"{"op":"advertise","type":"std_msgs/String"}"#, "topic"),
    (r#"{"op":"advertise","topic":"/a"}"#, "type"),
    (
        r#"{"op":"advertise","topic":5,"type":"std_msgs/String"}"#,
        "topic",
    ),
    (r#"{"op":"advertise","topic":"/a","type":["x"]}"#, "type"),
    (
        r#"{"op":"advertise","topic":"/a","type":"t","latch":"yes"}"#,
        "latch",
    ),
    (
        r#"{"op":"advertise","topic":"/a","type":"t","queue_size":-1}"#,
        "queue_size",
    ),
    (
        r#"{"op":"advertise","topic":"/a","type":"t","queue_size":1e12}"#,
        "queue_size",
    ),
    (r#"{"op":"unadvertise"}"#, "topic"),
    (r#"{"op":"unadvertise","topic":{}}"#, "topic"),
    (r#"{"op":"publish","msg":{}}"#, "topic"),
    (r#"{"op":"publish","topic":"/a"}"#, "msg"),
    (r#"{"op":"publish","topic":true,"msg":{}}"#, "topic"),
    (r#"{"op":"subscribe"}"#, "topic"),
    (r#"{"op":"subscribe","topic":1}"#, "topic"),
    (r#"{"op":"subscribe","topic":"/a","type":3}"#, "type"),
    (
        r#"{"op":"subscribe","topic":"/a","throttle_rate":"fast"}"#,
        "throttle_rate",
    ),
    (
        r#"{"op":"subscribe","topic":"/a","queue_length":-2}"#,
        "queue_length",
    ),
    (
        r#"{"op":"subscribe","topic":"/a","fragment_size":1.5}"#,
        "fragment_size",
    ),
    (
        r#"{"op":"subscribe","topic":"/a","compression":1}"#,
        "compression",
    ),
    (
        r#"{"op":"subscribe","topic":"/a","compression":"zstd"}"#,
        "compression",
    ),
    (r#"{"op":"subscribe","topic":"/a","regex":"yes"}"#, "regex"),
    (r#"{"op":"subscribe","topic":7,"regex":true}"#, "topic"),
    (r#"{"op":"unsubscribe"}"#, "topic"),
    (r#"{"op":"unsubscribe","topic":[]}"#, "topic"),
    (r#"{"op":"call_service"}"#, "service"),
    (r#"{"op":"call_service","service":2}"#, "service"),
    (
        r#"{"op":"call_service","service":"/s","type":false}"#,
        "type",
    ),
];

/// `text` with `"id":"req-9"` added.
fn with_id(text: &str) -> String {
    let mut v: Value = serde_json::from_str(text).unwrap();
    v["id"] = json!("req-9");
    v.to_string()
}

#[test]
fn missing_or_wrongly_typed_field_of_each_op_is_named_and_keeps_the_id() {
    for (text, field) in BAD_FIELDS {
        let text = with_id(text);
        let op: Value = serde_json::from_str::<Value>(&text).unwrap()["op"].clone();
        for (form, e) in [
            ("JSON", json_err(&text)),
            ("CBOR", cbor_err(&util::cbor_of(&text))),
        ] {
            assert!(
                e.message.contains(&format!("'{field}'")),
                "{form} {text}: {e}"
            );
            assert_eq!(e.id, Some(json!("req-9")), "{form} {text}");
            assert_eq!(e.op.as_deref(), op.as_str(), "{form} {text}");
        }
    }
}

#[test]
fn topic_with_whitespace_or_control_characters_is_refused() {
    let long = format!("/{}", "a".repeat(1024));
    for topic in [
        "",
        "/a b",
        "/a\tb",
        "/a\n",
        "/a\u{0}",
        "/a\u{7f}",
        "/\u{2028}x",
        &long,
    ] {
        for op in ["advertise", "unadvertise", "publish", "subscribe"] {
            let v = json!({"op": op, "id": 1, "topic": topic, "type": "t", "msg": {}});
            let text = v.to_string();
            for e in [json_err(&text), cbor_err(&util::cbor_of(&text))] {
                assert!(
                    e.message.contains("not a valid topic name"),
                    "{op} {topic:?}: {e}"
                );
                assert!(e.message.len() < 200, "error message grows with the input");
            }
        }
    }
}

#[test]
fn regex_subscribe_takes_the_pattern_as_is() {
    let r =
        Request::from_json(br#"{"op":"subscribe","topic":"/cam/.*|/scan","regex":true}"#).unwrap();
    assert!(
        matches!(r.op, Op::Subscribe { regex: true, ref topic, .. } if topic == "/cam/.*|/scan")
    );
}

fn nested_json_arrays(depth: usize) -> String {
    format!("{}{}", "[".repeat(depth), "]".repeat(depth))
}

fn nested_cbor_arrays(depth: usize) -> Vec<u8> {
    let mut v = vec![0x81; depth]; // array of one element, again and again
    v.push(0x00);
    v
}

/// `{"op":"publish","topic":"/a","msg":<inner>}` in CBOR with `inner` spliced in.
fn cbor_publish_with(inner: &[u8]) -> Vec<u8> {
    let mut v = util::cbor_of(r#"{"op":"publish","topic":"/a"}"#);
    v[0] = 0xa3; // the map now has three entries
    v.extend_from_slice(&[0x63, b'm', b's', b'g']);
    v.extend_from_slice(inner);
    v
}

#[test]
fn json_nested_10000_deep_is_refused_without_overflowing_the_stack() {
    util::on_small_stack(|| {
        let deep = nested_json_arrays(DEPTH);
        let in_msg = format!(r#"{{"op":"publish","topic":"/a","msg":{deep}}}"#);
        let in_id = format!(r#"{{"op":"publish","topic":"/a","msg":{{}},"id":{deep}}}"#);
        for text in [deep.clone(), in_msg, in_id] {
            let e = json_err(&text);
            assert!(e.message.contains("recursion limit"), "{e}");
        }
        let objects = format!("{}{}", r#"{"a":"#.repeat(DEPTH), "}".repeat(DEPTH));
        assert!(json_err(&objects).message.contains("recursion limit"));
        assert!(matches!(
            convert::json_to_cbor(deep.as_bytes()),
            Err(convert::ConvertError::Json(_))
        ));
    });
}

#[test]
fn cbor_nested_10000_deep_is_refused_without_overflowing_the_stack() {
    util::on_small_stack(|| {
        let deep = nested_cbor_arrays(DEPTH);
        let mut deep_maps = [0xa1, 0x61, b'a'].repeat(DEPTH);
        deep_maps.push(0x00);
        // Tag 85 (little-endian float32 typed array) wrapped around itself.
        let mut deep_tags = [0xd8, 85].repeat(DEPTH);
        deep_tags.push(0x00);
        for inner in [&deep, &deep_maps, &deep_tags] {
            let e = cbor_err(inner);
            assert!(e.message.starts_with("invalid CBOR"), "{e}");
            let e = cbor_err(&cbor_publish_with(inner));
            assert!(e.message.starts_with("invalid CBOR"), "{e}");
            assert!(matches!(
                convert::cbor_to_json(inner),
                Err(convert::ConvertError::Cbor(_))
            ));
        }
    });
}

#[test]
fn nesting_just_inside_the_limits_is_still_served() {
    util::on_small_stack(|| {
        let json = format!(
            r#"{{"op":"publish","topic":"/a","msg":{}}}"#,
            nested_json_arrays(100)
        );
        assert!(Request::from_json(json.as_bytes()).is_ok());
        let cbor = cbor_publish_with(&nested_cbor_arrays(100));
        let r = Request::from_cbor(&cbor).unwrap();
        let msg = fleetlink_proto::rosbridge::inbound::payload_bytes(&r.op).unwrap();
        assert!(convert::cbor_to_json(msg).is_ok());
    });
}

#[test]
fn json_and_cbor_accept_the_same_nesting_depth() {
    util::on_small_stack(|| {
        for depth in 1..300 {
            let json = convert::json_to_cbor(nested_json_arrays(depth).as_bytes()).is_ok();
            let cbor = convert::cbor_to_json(&nested_cbor_arrays(depth)).is_ok();
            assert_eq!(json, cbor, "depth {depth}");
            assert_eq!(json, depth <= convert::MAX_DEPTH, "depth {depth}");
        }
    });
}

const BIG: usize = 64 << 20;

#[test]
fn string_field_of_64_mib_is_handled_in_linear_time() {
    let big = "x".repeat(BIG);
    // As a topic: refused, and the error does not quote 64 MiB back.
    let text = format!(r#"{{"op":"publish","id":1,"topic":"/{big}","msg":{{}}}}"#);
    let e = json_err(&text);
    assert!(e.message.contains("not a valid topic name") && e.message.len() < 200);
    let e = cbor_err(&util::cbor_of(&text));
    assert!(e.message.contains("not a valid topic name") && e.message.len() < 200);
    // As an unknown compression: same.
    let text = format!(r#"{{"op":"subscribe","topic":"/a","compression":"{big}"}}"#);
    assert!(json_err(&text).message.len() < 200);
    // Inside a message: accepted and kept whole.
    let text = format!(r#"{{"op":"publish","topic":"/a","msg":{{"data":"{big}"}}}}"#);
    let r = Request::from_json(text.as_bytes()).unwrap();
    let msg = fleetlink_proto::rosbridge::inbound::payload_bytes(&r.op).unwrap();
    assert_eq!(msg.len(), BIG + r#"{"data":""}"#.len());
    let r = Request::from_cbor(&util::cbor_of(&text)).unwrap();
    let msg = fleetlink_proto::rosbridge::inbound::payload_bytes(&r.op).unwrap();
    assert!(msg.len() > BIG);
}

#[test]
fn interest_with_a_flag_other_than_0_or_1_is_invalid() {
    let e = decode_err(&raw_frame(0x18, &[5, 2]));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "INTEREST.wanted"));
    let (f, _) = Frame::decode(&raw_frame(0x18, &[5, 1]), 0).expect("valid");
    assert_eq!(
        f,
        Frame::Interest {
            alias: 5,
            wanted: true
        }
    );
}

#[test]
fn via_listing_more_hubs_than_a_chain_may_have_is_refused_before_allocating() {
    // 2^40 hubs claimed in a body of a few bytes: refused by the count, not by running out.
    let body = Body::default().varint(1 << 40).u64_le(1);
    let e = decode_err(&raw_frame(FrameKind::Via as u8, &body.0));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "VIA.count"));
    let body = Body::default().varint(frame::MAX_VIA as u64 + 1);
    let e = decode_err(&raw_frame(FrameKind::Via as u8, &body.0));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "VIA.count"));
    // Two hubs said, one there.
    let body = Body::default().varint(2).u64_le(1);
    let e = decode_err(&raw_frame(FrameKind::Via as u8, &body.0));
    assert_eq!((e.kind, e.context), (ErrorKind::Invalid, "VIA.hub"));
}
