//! Arbitrary bytes as a rosbridge client frame, both as JSON text and as CBOR, and through
//! the schema-less JSON/CBOR conversion. Errors are fine; panics, stack overflows and
//! runaway allocations are the bugs this looks for.

#![no_main]

use fleetlink_proto::rosbridge::inbound::payload_bytes;
use fleetlink_proto::rosbridge::{Request, convert};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
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
