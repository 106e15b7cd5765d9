//! Malformed inputs: each test names the attack it feeds. None may panic or allocate
//! in proportion to a length the input merely claims.

use std::time::Instant;

use fleetlink_msg::{
    CodecError, Dialect, Registry, RegistryError, Wire, decode, from_cbor, from_json,
};
use proptest::prelude::*;
use serde_json::json;

use crate::util::registry;

fn cloud_cdr(reg: &Registry) -> Vec<u8> {
    let v = from_json(
        reg,
        "sensor_msgs/PointCloud2",
        Dialect::Ros2,
        &json!({"header": {"frame_id": "lidar"}, "width": 4, "height": 1,
                "fields": [{"name": "x", "offset": 0, "datatype": 7, "count": 1}],
                "data": "AAECAwQFBgcICQoLDA0ODw==", "is_dense": true}),
    )
    .expect("valid cloud");
    fleetlink_msg::encode(reg, "sensor_msgs/PointCloud2", Wire::Cdr, &v).expect("encodes")
}

#[test]
fn every_truncation_of_a_message_is_reported_as_incomplete() {
    let reg = registry();
    let full = cloud_cdr(&reg);
    for cut in 0..full.len() {
        let e = decode(&reg, "sensor_msgs/PointCloud2", Wire::Cdr, &full[..cut])
            .expect_err("truncated");
        assert!(e.is_incomplete(), "cut at {cut}: {e}");
    }
    assert!(decode(&reg, "sensor_msgs/PointCloud2", Wire::Cdr, &full).is_ok());
}

#[test]
fn length_prefix_claiming_four_gigabytes_fails_fast_without_allocating() {
    let reg = registry();
    let mut bytes = vec![0x00, 0x01, 0x00, 0x00];
    bytes.extend_from_slice(&u32::MAX.to_le_bytes());
    let start = Instant::now();
    for ty in [
        "std_msgs/UInt8MultiArray",
        "sensor_msgs/JointState",
        "visualization_msgs/MarkerArray",
        "std_msgs/String",
    ] {
        let e = decode(&reg, ty, Wire::Cdr, &bytes).expect_err("claims too much");
        assert!(matches!(e, CodecError::Incomplete { .. }), "{ty}: {e}");
        let e = decode(&reg, ty, Wire::Ros1, &bytes[4..]).expect_err("claims too much");
        assert!(matches!(e, CodecError::Incomplete { .. }), "{ty}: {e}");
    }
    // Not a benchmark: a 4 GB allocation or loop would take seconds, not milliseconds.
    assert!(start.elapsed().as_secs() < 2);
}

#[test]
fn invalid_utf8_in_a_string_is_invalid_with_its_field_path() {
    let reg = registry();
    let bytes = [0x00, 0x01, 0x00, 0x00, 3, 0, 0, 0, 0xff, 0xfe, 0x00];
    let e = decode(&reg, "std_msgs/String", Wire::Cdr, &bytes).expect_err("not UTF-8");
    match &e {
        CodecError::Invalid { path, .. } => assert_eq!(path, "std_msgs/String.data"),
        other => panic!("expected Invalid, got {other}"),
    }
}

#[test]
fn missing_cdr_nul_terminator_is_invalid() {
    let reg = registry();
    let bytes = [0x00, 0x01, 0x00, 0x00, 2, 0, 0, 0, b'h', b'i'];
    let e = decode(&reg, "std_msgs/String", Wire::Cdr, &bytes).expect_err("no NUL");
    assert!(matches!(e, CodecError::Invalid { .. }), "{e}");
}

#[test]
fn unknown_encapsulation_kind_is_invalid() {
    let reg = registry();
    let e = decode(&reg, "std_msgs/Bool", Wire::Cdr, &[0x00, 0x07, 0, 0, 1]).expect_err("XCDR2");
    assert!(matches!(e, CodecError::Invalid { .. }), "{e}");
}

#[test]
fn bool_byte_other_than_zero_or_one_is_invalid() {
    let reg = registry();
    let e = decode(&reg, "std_msgs/Bool", Wire::Ros1, &[2]).expect_err("bool 2");
    assert!(e.to_string().contains("std_msgs/Bool.data"), "{e}");
}

#[test]
fn bounded_sequence_longer_than_its_bound_is_invalid() {
    let reg = registry();
    // test_msgs/Bounded: string<=8 name (empty), int32[<=4] small with 5 elements.
    let mut b = vec![0x00, 0x01, 0x00, 0x00, 1, 0, 0, 0, 0, 0, 0, 0, 5, 0, 0, 0];
    b.extend_from_slice(&[0u8; 20]);
    let e = decode(&reg, "test_msgs/Bounded", Wire::Cdr, &b).expect_err("over bound");
    assert!(
        matches!(&e, CodecError::Invalid { path, .. } if path == "test_msgs/Bounded.small"),
        "{e}"
    );
}

#[test]
fn unknown_type_names_the_type() {
    let reg = registry();
    let e = decode(&reg, "nope_msgs/Missing", Wire::Cdr, &[0, 1, 0, 0]).expect_err("unknown");
    assert!(e.to_string().contains("nope_msgs/msg/Missing"), "{e}");
}

#[test]
fn definition_using_an_unknown_type_names_the_field() {
    let reg = Registry::bundled();
    reg.add_definition("demo_msgs/Broken", "int32 a\nGhost g\n", Dialect::Ros2)
        .expect("parses");
    let e = decode(&reg, "demo_msgs/Broken", Wire::Cdr, &[0, 1, 0, 0]).expect_err("unresolved");
    match e {
        CodecError::Registry(RegistryError::UnknownType { name, from }) => {
            assert_eq!(name, "demo_msgs/Ghost");
            assert_eq!(from, "demo_msgs/msg/Broken.g");
        }
        other => panic!("{other}"),
    }
}

#[test]
fn recursive_definitions_are_rejected() {
    let reg = Registry::bundled();
    reg.add_definition("demo_msgs/A", "B[] children\n", Dialect::Ros2)
        .expect("parses");
    reg.add_definition("demo_msgs/B", "A parent\n", Dialect::Ros2)
        .expect("parses");
    let e =
        decode(&reg, "demo_msgs/A", Wire::Cdr, &[0, 1, 0, 0, 0, 0, 0, 0]).expect_err("recursive");
    assert!(
        matches!(e, CodecError::Registry(RegistryError::Recursive { .. })),
        "{e}"
    );
    assert!(fleetlink_msg::md5sum(&reg, "demo_msgs/A").is_err());
}

#[test]
fn json_of_the_wrong_shape_names_the_field() {
    let reg = registry();
    let e = from_json(
        &reg,
        "geometry_msgs/Pose",
        Dialect::Ros2,
        &json!({"position": {"x": "one"}}),
    )
    .expect_err("string");
    assert!(
        e.to_string().contains("geometry_msgs/Pose.position.x"),
        "{e}"
    );
    let e =
        from_json(&reg, "std_msgs/UInt8", Dialect::Ros2, &json!({"data": 300})).expect_err("range");
    assert!(e.to_string().contains("out of range"), "{e}");
    let e = from_json(
        &reg,
        "sensor_msgs/Image",
        Dialect::Ros2,
        &json!({"data": "***"}),
    )
    .expect_err("base64");
    assert!(e.to_string().contains("base64"), "{e}");
    let e = from_json(
        &reg,
        "geometry_msgs/PoseWithCovariance",
        Dialect::Ros2,
        &json!({"covariance": [1.0]}),
    )
    .expect_err("length");
    assert!(e.to_string().contains("exactly 36"), "{e}");
}

#[test]
fn cbor_garbage_and_mismatched_typed_arrays_are_errors() {
    let reg = registry();
    assert!(from_cbor(&reg, "std_msgs/String", Dialect::Ros2, &[0xff, 0x00]).is_err());
    // {"data": tag 85 (float32 LE) of 4 bytes} for a float64[] field.
    let mut doc = vec![0xa1, 0x64, b'd', b'a', b't', b'a', 0xd8, 85, 0x44];
    doc.extend_from_slice(&1.5f32.to_le_bytes());
    let e =
        from_cbor(&reg, "std_msgs/Float64MultiArray", Dialect::Ros2, &doc).expect_err("wrong tag");
    assert!(e.to_string().contains("tag 85"), "{e}");
}

proptest! {
    #[test]
    fn random_bytes_never_panic_any_decoder(bytes in proptest::collection::vec(any::<u8>(), 0..256), idx in 0usize..64) {
        let reg = registry();
        let names = reg.message_names();
        let ty = names[idx % names.len()].to_string();
        let _ = decode(&reg, &ty, Wire::Ros1, &bytes);
        let mut cdr = vec![0x00, 0x01, 0x00, 0x00];
        cdr.extend_from_slice(&bytes);
        let _ = decode(&reg, &ty, Wire::Cdr, &cdr);
        let _ = fleetlink_msg::CdrView::new(&reg, &ty, &cdr);
        let _ = from_cbor(&reg, &ty, Dialect::Ros2, &bytes);
    }
}

proptest! {
    #[test]
    fn arbitrary_definition_text_never_panics_the_parser(text in "(\\PC|[ \\t\\n#=<>\\[\\]/\"'-])*", kind in 0usize..3) {
        let reg = Registry::empty();
        let name = ["fuzz_msgs/msg/T", "fuzz_msgs/srv/T", "fuzz_msgs/action/T"][kind];
        if reg.add_definition(name, &text, Dialect::Ros2).is_ok() {
            let _ = reg.layout("fuzz_msgs/T", Dialect::Ros2);
            let _ = fleetlink_msg::md5sum(&reg, name);
        }
        let _ = reg.add_full_text("fuzz_msgs/U", &text, Dialect::Ros1);
    }

    #[test]
    fn arbitrary_json_text_never_panics(text in "(\\PC|[\\[\\]{}\",:0-9.eE+-])*") {
        let reg = registry();
        let _ = fleetlink_msg::from_json_bytes(&reg, "sensor_msgs/LaserScan", Dialect::Ros2, text.as_bytes());
        let _ = fleetlink_msg::from_json_bytes(&reg, "test_msgs/Nested", Dialect::Ros1, text.as_bytes());
    }
}

#[test]
fn non_ascii_after_a_field_name_is_a_parse_error_not_a_panic() {
    let reg = Registry::empty();
    let e = reg
        .add_definition("demo_msgs/U", "int32 aé\n", Dialect::Ros2)
        .expect_err("bad name");
    assert!(e.to_string().contains(":1:8:"), "{e}");
}
