//! Arbitrary bytes as a rosbridge client frame, both as JSON text and as CBOR, and through
//! the schema-less JSON/CBOR conversion. Errors are fine; panics, stack overflows and
//! runaway allocations are the bugs this looks for. The publish short paths must read
//! nothing the full parse refuses, and read it the same way.

#![no_main]

use fleetlink_proto::rosbridge::inbound::payload_bytes;
use fleetlink_proto::rosbridge::{Op, Publish, Request, convert};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let frame = bytes::Bytes::copy_from_slice(data);
    let short = match std::str::from_utf8(&frame) {
        Ok(text) => Publish::from_json_text(text, &frame).map(|p| (p, Request::from_json(data))),
        Err(_) => None,
    };
    let short = short.or_else(|| Publish::from_cbor_frame(&frame).map(|p| (p, Request::from_cbor(data))));
    if let Some((p, full)) = short {
        let full = full.expect("the full parse takes what the short path takes");
        assert_eq!(p.id.value(), full.id);
        let Op::Publish { topic, msg } = full.op else {
            panic!("the short path read a publish, the full parse something else")
        };
        assert_eq!(p.topic, topic);
        assert_eq!(p.msg.encoding, msg.encoding);
        // The full parse writes the message out again; the short path keeps it as sent.
        // Compared as values, through the other encoding.
        let same = match msg.encoding {
            fleetlink_proto::Encoding::Json => {
                convert::json_to_cbor(&p.msg.bytes).ok() == convert::json_to_cbor(&msg.bytes).ok()
            }
            _ => convert::cbor_to_json(&p.msg.bytes).ok() == convert::cbor_to_json(&msg.bytes).ok(),
        };
        assert!(same, "the short path read another message than the full parse");
    }
    if let Ok(req) = Request::from_json(data)
        && let Some(msg) = payload_bytes(&req.op)
    {
        // A message the parser accepted converts to CBOR.
        convert::json_to_cbor(msg).expect("accepted JSON message converts to CBOR");
    }
    if let Ok(req) = Request::from_cbor(data)
        && let Some(msg) = payload_bytes(&req.op)
    {
        let _ = convert::cbor_to_json(msg);
    }
    let _ = convert::cbor_to_json(data);
    let _ = convert::json_to_cbor(data);
});
