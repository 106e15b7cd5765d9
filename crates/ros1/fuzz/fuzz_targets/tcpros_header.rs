//! TCPROS connection headers from any peer that connects: decoding never panics, and what
//! decodes re-encodes to the same bytes.
#![no_main]
use fleetlink_ros1::tcpros::Header;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(h) = Header::decode(data) {
        assert_eq!(&h.encode()[4..], data);
    }
});
