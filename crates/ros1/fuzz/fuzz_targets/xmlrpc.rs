//! XML-RPC documents from the master or another node: decoding never panics, and what
//! decodes re-encodes to a document that decodes again (values equal except the kept-as-text
//! `Other` kinds and NaN, which the round-trip tests cover separately).
#![no_main]
use fleetlink_ros1::xmlrpc::{decode_call, decode_response, encode_call, encode_response};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(v) = decode_response(text) {
        assert!(decode_response(&encode_response(&v)).is_ok());
    }
    if let Ok(c) = decode_call(text) {
        let again = decode_call(&encode_call(&c.method, &c.params)).expect("re-encoded call");
        assert_eq!(again.params, c.params);
    }
});
