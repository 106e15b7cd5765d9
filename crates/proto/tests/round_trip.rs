//! Property tests: encoding then decoding gives back the same value, for every frame kind,
//! for buffers packed with many frames, for chunked payloads and call bodies, and for
//! JSON↔CBOR.

use std::collections::HashMap;

use bytes::{Bytes, BytesMut};
use fleetlink_proto::frame::{
    self, Frame, FrameKind, chunk_frames, encode_chunk, encode_message, split_call_body,
};
use fleetlink_proto::reassembly::{CallReassembler, Reassembler};
use fleetlink_proto::rosbridge::convert;
use proptest::prelude::*;
use serde_json::Value;

use crate::util;

/// Encodes `f` alone, decodes it, and checks the value and the end position.
fn assert_round_trip(f: &Frame) -> Result<(), TestCaseError> {
    let bytes = f.to_bytes();
    let (back, next) = Frame::decode(&bytes, 0).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert_eq!(&back, f);
    prop_assert_eq!(next, bytes.len());
    Ok(())
}

proptest! {
    #[test]
    fn hello(f in util::hello()) { assert_round_trip(&f)?; }

    #[test]
    fn welcome(f in util::welcome()) { assert_round_trip(&f)?; }

    #[test]
    fn advertise(f in util::advertise()) { assert_round_trip(&f)?; }

    #[test]
    fn unadvertise(f in util::unadvertise()) { assert_round_trip(&f)?; }

    #[test]
    fn subscribe(f in util::subscribe()) { assert_round_trip(&f)?; }

    #[test]
    fn unsubscribe(f in util::unsubscribe()) { assert_round_trip(&f)?; }

    #[test]
    fn message(f in util::message()) { assert_round_trip(&f)?; }

    #[test]
    fn chunk(f in util::chunk()) { assert_round_trip(&f)?; }

    #[test]
    fn ping(f in util::ping()) { assert_round_trip(&f)?; }

    #[test]
    fn pong(f in util::pong()) { assert_round_trip(&f)?; }

    #[test]
    fn ack(f in util::ack()) { assert_round_trip(&f)?; }

    #[test]
    fn status(f in util::status()) { assert_round_trip(&f)?; }

    #[test]
    fn share(f in util::share()) { assert_round_trip(&f)?; }

    #[test]
    fn link_report(f in util::link_report()) { assert_round_trip(&f)?; }

    #[test]
    fn delivered(f in util::delivered()) { assert_round_trip(&f)?; }

    #[test]
    fn service_advertise(f in util::service_advertise()) { assert_round_trip(&f)?; }

    #[test]
    fn service_unadvertise(f in util::service_unadvertise()) { assert_round_trip(&f)?; }

    #[test]
    fn call(f in util::call()) { assert_round_trip(&f)?; }

    #[test]
    fn goal(f in util::goal()) { assert_round_trip(&f)?; }

    #[test]
    fn reply(f in util::reply()) { assert_round_trip(&f)?; }

    #[test]
    fn feedback(f in util::feedback()) { assert_round_trip(&f)?; }

    #[test]
    fn cancel(f in util::cancel()) { assert_round_trip(&f)?; }

    #[test]
    fn call_chunk(f in util::call_chunk()) { assert_round_trip(&f)?; }

    #[test]
    fn unknown_kind(f in util::unknown()) { assert_round_trip(&f)?; }

    #[test]
    fn many_frames_in_one_buffer_decode_in_order(
        sent in prop::collection::vec(util::any_frame(), 0..40),
    ) {
        let mut buf = BytesMut::new();
        for f in &sent {
            f.encode(&mut buf);
        }
        let buf = buf.freeze();
        let got: Vec<Frame> = frame::frames(&buf)
            .collect::<Result<_, _>>()
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(got, sent);
    }

    #[test]
    fn encode_message_matches_encoding_the_frame(
        alias in any::<u32>(),
        seq in any::<u64>(),
        stamp_ns in any::<u64>(),
        payload in util::payload(300),
    ) {
        let mut direct = BytesMut::from(&b"prefix"[..]);
        encode_message(&mut direct, alias, seq, stamp_ns, &payload);
        let mut via_frame = BytesMut::from(&b"prefix"[..]);
        Frame::Message { alias, seq, stamp_ns, payload }.encode(&mut via_frame);
        prop_assert_eq!(direct, via_frame);
    }

    #[test]
    fn encode_chunk_matches_encoding_the_frame(f in util::chunk()) {
        let Frame::Chunk { alias, seq, stamp_ns, total_len, offset, data } = &f else {
            unreachable!("util::chunk makes chunks");
        };
        let mut direct = BytesMut::new();
        encode_chunk(&mut direct, false, *alias, *seq, *stamp_ns, *total_len, *offset, data);
        prop_assert_eq!(direct.freeze(), f.to_bytes());
    }

    /// Several topics' payloads are cut into chunks, the chunk streams are interleaved in
    /// an arbitrary order (each stream staying in order, as on the wire), sent through the
    /// codec, and reassembled.
    #[test]
    fn chunked_payloads_reassemble_when_topics_interleave(
        payloads in prop::collection::vec(util::payload(3000), 1..5),
        chunk_size in 1usize..700,
        schedule in prop::collection::vec(any::<u8>(), 0..64),
    ) {
        let mut streams: Vec<Vec<Frame>> = payloads
            .iter()
            .enumerate()
            .map(|(i, p)| chunk_frames(i as u32, 100 + i as u64, 7, p, chunk_size).collect())
            .collect();
        for s in &mut streams {
            s.reverse(); // pop() from the back yields them in order
        }
        let mut wire = BytesMut::new();
        let mut picks = schedule.iter().copied().cycle();
        loop {
            let live: Vec<usize> = (0..streams.len()).filter(|i| !streams[*i].is_empty()).collect();
            if live.is_empty() {
                break;
            }
            let pick = live[usize::from(picks.next().unwrap_or(0)) % live.len()];
            streams[pick].pop().expect("live stream").encode(&mut wire);
        }
        let wire = wire.freeze();

        let mut r = Reassembler::new(4096, 4 * 4096);
        let mut done: HashMap<u32, Bytes> = HashMap::new();
        for f in frame::frames(&wire) {
            let f = f.map_err(|e| TestCaseError::fail(e.to_string()))?;
            let Frame::Chunk { alias, seq, stamp_ns, total_len, offset, data } = f else {
                return Err(TestCaseError::fail("only chunks were sent"));
            };
            if let Some(m) = r
                .push(alias, seq, stamp_ns, total_len, offset, &data)
                .map_err(|e| TestCaseError::fail(e.to_string()))?
            {
                prop_assert_eq!(m.seq, 100 + u64::from(m.alias));
                prop_assert_eq!(m.stamp_ns, 7);
                prop_assert!(done.insert(m.alias, m.payload).is_none());
            }
        }
        for (i, p) in payloads.iter().enumerate() {
            // An empty payload has no chunks (it goes as one MESSAGE).
            if p.is_empty() {
                prop_assert!(!done.contains_key(&(i as u32)));
            } else {
                prop_assert_eq!(done.get(&(i as u32)), Some(p));
            }
        }
        prop_assert_eq!(r.buffered(), 0);
        prop_assert_eq!(r.abandoned, 0);
    }

    /// Several calls' bodies (of every kind that can be cut) are split, each call's pieces
    /// and its header frame kept in order but the calls interleaved arbitrarily, sent
    /// through the codec, and reassembled: every header frame completes its body.
    #[test]
    fn call_bodies_reassemble_when_calls_interleave(
        bodies in prop::collection::vec(
            (prop::sample::select(util::CALL_BODY_KINDS.to_vec()), util::payload(3000)),
            1..5,
        ),
        chunk_size in 1usize..700,
        schedule in prop::collection::vec(any::<u8>(), 0..64),
    ) {
        let mut streams: Vec<Vec<Frame>> = bodies
            .iter()
            .enumerate()
            .map(|(i, (kind, body))| {
                let call_id = 1000 + i as u64;
                let (mut frames, last) = split_call_body(call_id, *kind, body, chunk_size);
                frames.push(call_body_frame(*kind, call_id, last));
                frames.reverse(); // pop() from the back yields them in order
                frames
            })
            .collect();
        let mut wire = BytesMut::new();
        let mut picks = schedule.iter().copied().cycle();
        loop {
            let live: Vec<usize> = (0..streams.len()).filter(|i| !streams[*i].is_empty()).collect();
            if live.is_empty() {
                break;
            }
            let pick = live[usize::from(picks.next().unwrap_or(0)) % live.len()];
            streams[pick].pop().expect("live stream").encode(&mut wire);
        }
        let wire = wire.freeze();

        let mut r = CallReassembler::new(4096, 4 * 4096 + 4 * 64);
        let mut done: HashMap<u64, Bytes> = HashMap::new();
        for f in frame::frames(&wire) {
            let f = f.map_err(|e| TestCaseError::fail(e.to_string()))?;
            let kind = f.kind_byte();
            let (call_id, last) = match f {
                Frame::CallChunk { call_id, kind, total_len, offset, data } => {
                    r.push(call_id, kind, total_len, offset, &data)
                        .map_err(|e| TestCaseError::fail(e.to_string()))?;
                    continue;
                }
                Frame::Call { call_id, payload, .. }
                | Frame::Goal { call_id, payload, .. }
                | Frame::Reply { call_id, payload, .. }
                | Frame::Feedback { call_id, payload, .. } => (call_id, payload),
                other => return Err(TestCaseError::fail(format!("unexpected {other:?}"))),
            };
            let body = r.finish(call_id, kind, last).map_err(|e| TestCaseError::fail(e.to_string()))?;
            prop_assert!(done.insert(call_id, body).is_none());
        }
        for (i, (_, body)) in bodies.iter().enumerate() {
            prop_assert_eq!(done.get(&(1000 + i as u64)), Some(body));
        }
        prop_assert_eq!(r.pending_bytes(), 0);
    }

    #[test]
    fn json_survives_a_trip_through_cbor(v in util::json_value()) {
        let json = serde_json::to_vec(&v).expect("a value serializes");
        let cbor = convert::json_to_cbor(&json).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let back = convert::cbor_to_json(&cbor).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let back: Value = serde_json::from_slice(&back).expect("convert writes valid JSON");
        prop_assert_eq!(back, v);
    }
}

/// The frame of `kind` that ends call `call_id`'s body, carrying its last piece; the other
/// fields are fixed, the test is about the body.
fn call_body_frame(kind: FrameKind, call_id: u64, payload: Bytes) -> Frame {
    let encoding = fleetlink_proto::Encoding::Cbor;
    match kind {
        FrameKind::Call => Frame::Call {
            call_id,
            alias: 1,
            deadline_ms: 100,
            encoding,
            payload,
        },
        FrameKind::Goal => Frame::Goal {
            call_id,
            alias: 1,
            deadline_ms: 100,
            goal_id: [7; 16],
            encoding,
            payload,
        },
        FrameKind::Reply => Frame::Reply {
            call_id,
            status: frame::CallStatus::Ok,
            encoding,
            payload,
        },
        FrameKind::Feedback => Frame::Feedback {
            call_id,
            encoding,
            payload,
        },
        other => panic!("{other:?} carries no call body"),
    }
}

/// The worked example of `docs/protocol.md` §1.11, byte for byte.
#[test]
fn protocol_md_worked_example() {
    let hex = "07 18 03 ac 02 15 cd 85 3d fe 9c 97 17 7b 22 64 61 74 61 22 3a 22 68 69 22 7d";
    let bytes: Vec<u8> = hex
        .split(' ')
        .map(|b| u8::from_str_radix(b, 16).expect("hex byte"))
        .collect();
    let frame = Frame::Message {
        alias: 3,
        seq: 300,
        stamp_ns: 1_700_000_000_123_456_789,
        payload: Bytes::from_static(br#"{"data":"hi"}"#),
    };
    assert_eq!(frame.to_bytes(), Bytes::from(bytes));
}

/// Text where a publish's message goes: JSON objects, and pieces that only look like the
/// end of one (a brace in a string, another key after the message, an unclosed object).
fn message_text() -> impl Strategy<Value = String> {
    prop_oneof![
        util::json_value().prop_map(|v| serde_json::json!({ "v": v }).to_string()),
        proptest::string::string_regex(r#"\{[\]\["{}:,ab1 \\]{0,24}"#).expect("a regex"),
        Just(r#"{"a":1},"op":"advertise""#.to_string()),
        Just(r#"{"a":"}"}"#.to_string()),
        Just(r#"{"a":1} "#.to_string()),
        Just(r#"{"b":[1,2]},"topic":"/other""#.to_string()),
    ]
}

proptest! {
    /// Reading a publish by its envelope's shape is sound: whenever a frame has the shape
    /// and the text where the message lies is one JSON value (the least its reader
    /// checks), the full read of that frame finds the same topic, id and message.
    #[test]
    fn a_publish_read_by_its_shape_is_what_the_full_read_finds(
        id in prop_oneof![
            4 => proptest::string::string_regex("[a-z:/0-9é]{0,12}").expect("a regex"),
            1 => proptest::string::string_regex(r#"[a-z"\\]{0,6}"#).expect("a regex"),
        ],
        msg in message_text(),
        latch in any::<bool>(),
    ) {
        use fleetlink_proto::rosbridge::{EnvelopeShapes, Publish, is_json_value};
        let tail = if latch { r#","latch":false}"# } else { "}" };
        let envelope = |id: &str, msg: &str| {
            format!(r#"{{"op":"publish","id":"{id}","topic":"/shape/t","msg":{msg}{tail}"#)
        };
        let mut shapes = EnvelopeShapes::default();
        let first = Bytes::from(envelope("publish:/shape/t:1", r#"{"data":"x"}"#));
        let first_text = std::str::from_utf8(&first).expect("UTF-8");
        prop_assert!(Publish::from_json_text_shaped(first_text, &first, &mut shapes).is_some());
        let text = envelope(&id, &msg);
        let Some(m) = shapes.fit(text.as_bytes()) else {
            return Ok(());
        };
        if !is_json_value(text[m.msg.clone()].as_bytes()) {
            return Ok(());
        }
        let frame = Bytes::from(text.clone());
        let full = Publish::from_json_text(std::str::from_utf8(&frame).expect("UTF-8"), &frame);
        prop_assert!(full.is_some(), "the full read refuses {}", text);
        let full = full.expect("checked above");
        prop_assert_eq!(&*full.topic, &text[m.topic.clone()]);
        prop_assert_eq!(&full.msg.bytes[..], text[m.msg.clone()].trim_end().as_bytes());
        let id_json = m.id.clone().map(|r| &text[r]);
        prop_assert_eq!(
            full.id.value(),
            id_json.map(|j| serde_json::from_str::<Value>(j).expect("the id is JSON"))
        );
    }
}

#[test]
fn a_link_report_from_an_older_agent_reads_with_no_capacity() {
    // kind 0x0e, body of three u64le (no capacity_bps).
    let mut b = vec![0x0e, 24];
    for v in [2_000_000u64, 480_000, 41_000_000] {
        b.extend_from_slice(&v.to_le_bytes());
    }
    let (f, next) = Frame::decode(&bytes::Bytes::from(b), 0).unwrap();
    assert_eq!(next, 26);
    assert_eq!(
        f,
        Frame::LinkReport {
            demand_bps: 2_000_000,
            rate_bps: 480_000,
            latency_ns: 41_000_000,
            capacity_bps: 0,
            measured_at_ms: 0,
        }
    );
}
