//! Property tests: every XML-RPC value and every TCPROS header the agent can encode
//! decodes back to itself.

use fleetlink_ros1::tcpros::Header;
use fleetlink_ros1::xmlrpc::{Value, decode_call, decode_response, encode_call, encode_response};
use proptest::prelude::*;

fn value() -> impl Strategy<Value = Value> {
    let leaf = prop_oneof![
        any::<i32>().prop_map(Value::Int),
        any::<bool>().prop_map(Value::Bool),
        "\\PC{0,20}".prop_map(Value::Str),
        (-1e300f64..1e300).prop_map(Value::Double),
    ];
    leaf.prop_recursive(4, 64, 8, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..6).prop_map(Value::Array),
            prop::collection::vec(("[a-zA-Z_]{1,8}", inner), 0..4).prop_map(Value::Struct),
        ]
    })
}

proptest! {
    #[test]
    fn xmlrpc_responses_round_trip(v in value()) {
        prop_assert_eq!(decode_response(&encode_response(&v)).unwrap(), v);
    }

    #[test]
    fn xmlrpc_calls_round_trip(method in "[a-zA-Z]{1,16}", params in prop::collection::vec(value(), 0..4)) {
        let call = decode_call(&encode_call(&method, &params)).unwrap();
        prop_assert_eq!(call.method, method);
        prop_assert_eq!(call.params, params);
    }

    #[test]
    fn tcpros_headers_round_trip(fields in prop::collection::vec(("[a-z_]{1,12}", "\\PC{0,40}"), 0..8)) {
        let mut h = Header::new();
        for (k, v) in &fields {
            h = h.with(k, v.clone());
        }
        let bytes = h.encode();
        prop_assert_eq!(Header::decode(&bytes[4..]).unwrap(), h);
    }
}
