//! rosbridge JSON and CBOR that are already in normal form are passed on as they came
//! (`normalize_json_bytes` / `normalize_cbor_resolved` return `None`); everything else is
//! converted. Either way the result must be exactly what the full conversion gives.

use fleetlink_msg::{Dialect, Registry, Wire, decode, from_json_bytes, normalize_json_bytes};
use serde_json::{Value as Json, json};

use crate::util::{registry, vectors};

/// The full conversion: parse into a message value and write it out.
fn converted(reg: &Registry, ty: &str, text: &str) -> Json {
    let v = from_json_bytes(reg, ty, Dialect::Ros2, text.as_bytes()).expect("valid message");
    serde_json::from_slice(&fleetlink_msg::to_json_bytes(&v)).expect("our output is JSON")
}

/// What the normalizer gives, as a JSON value, and whether it kept the input as it was.
fn normalized(reg: &Registry, ty: &str, text: &str) -> (Json, bool) {
    match normalize_json_bytes(reg, ty, Dialect::Ros2, text.as_bytes()).expect("valid") {
        Some(out) => (serde_json::from_slice(&out).expect("JSON"), false),
        None => (serde_json::from_str(text).expect("JSON"), true),
    }
}

#[test]
fn output_of_every_vector_is_already_normal() {
    let reg = registry();
    let mut checked = 0;
    for v in vectors("cdr.jsonl") {
        let ty = v["type"].as_str().expect("type");
        let cdr = (0..v["cdr"].as_str().expect("hex").len())
            .step_by(2)
            .map(|i| u8::from_str_radix(&v["cdr"].as_str().unwrap()[i..i + 2], 16).unwrap())
            .collect::<Vec<u8>>();
        let value = decode(&reg, ty, Wire::Cdr, &cdr).expect("vector decodes");
        let text = fleetlink_msg::to_json_bytes(&value);
        let (_, kept) = normalized(&reg, ty, std::str::from_utf8(&text).unwrap());
        // NaN is written as null, which reads back as a default to fill: not normal.
        if !String::from_utf8_lossy(&text).contains("null") {
            assert!(kept, "{ty}: our own JSON output was converted again");
        }
        checked += 1;
    }
    assert!(checked > 300, "only {checked} vectors");
}

#[test]
fn normalizing_gives_what_full_conversion_gives() {
    let reg = registry();
    let mut kept_any = false;
    let mut converted_any = false;
    let mut inputs: Vec<(String, String)> = vectors("cdr.jsonl")
        .iter()
        .map(|v| {
            (
                v["type"].as_str().unwrap().to_owned(),
                v["json"].to_string(),
            )
        })
        .collect();
    for (ty, msg) in [
        ("std_msgs/msg/String", json!({"data": "hi \" \u{e9}"})),
        ("std_msgs/msg/Float64", json!({"data": 1})),
        ("std_msgs/msg/Float64", json!({"data": 1.5})),
        ("std_msgs/msg/Int32", json!({"data": 7.0})),
        ("std_msgs/msg/Int32", json!({})),
        (
            "geometry_msgs/msg/Twist",
            json!({"linear": {"x": 1.0, "y": 0.0, "z": 0.0}}),
        ),
        (
            "geometry_msgs/msg/Twist",
            json!({"linear": {"x": 1.0, "y": 0.0, "z": 0.0}, "angular": {"x": 0.0, "y": 0.0, "z": 2}}),
        ),
        (
            "std_msgs/msg/Float64MultiArray",
            json!({"layout": {"dim": [], "data_offset": 0}, "data": [1.5, 2]}),
        ),
        (
            "std_msgs/msg/Float64MultiArray",
            json!({"layout": {"dim": [], "data_offset": 0}, "data": [1.5, 2.0]}),
        ),
        (
            "std_msgs/msg/Header",
            json!({"stamp": {"secs": 1, "nsecs": 2}, "frame_id": "m"}),
        ),
        (
            "std_msgs/msg/Header",
            json!({"stamp": {"sec": 1, "nanosec": 2}, "frame_id": "m"}),
        ),
        (
            "std_msgs/msg/UInt8MultiArray",
            json!({"layout": {"dim": [], "data_offset": 0}, "data": [1, 2, 3]}),
        ),
        (
            "std_msgs/msg/UInt8MultiArray",
            json!({"layout": {"dim": [], "data_offset": 0}, "data": "AQID"}),
        ),
    ] {
        inputs.push((ty.to_owned(), msg.to_string()));
    }
    for (ty, text) in &inputs {
        let (got, kept) = normalized(&reg, ty, text);
        assert_eq!(got, converted(&reg, ty, text), "{ty}: {text}");
        kept_any |= kept;
        converted_any |= !kept;
    }
    assert!(kept_any && converted_any, "both paths were taken");
}

#[test]
fn wrong_types_are_refused_on_either_path() {
    let reg = registry();
    for text in [
        r#"{"data":"notanint"}"#,
        r#"{"data":1e40}"#,
        r#"[1]"#,
        r#"{"data":"#,
    ] {
        assert!(
            normalize_json_bytes(&reg, "std_msgs/msg/Int32", Dialect::Ros2, text.as_bytes())
                .is_err(),
            "{text}"
        );
    }
}

/// What the CBOR normalizer gives, and whether it kept the input as it was.
fn normalized_cbor(reg: &Registry, ty: &str, cbor: &[u8]) -> (Vec<u8>, bool) {
    let resolved = reg.resolve(ty, Dialect::Ros2).expect("known type");
    match fleetlink_msg::normalize_cbor_resolved(&resolved, cbor).expect("valid") {
        Some(out) => (out, false),
        None => (cbor.to_vec(), true),
    }
}

fn cbor_of(v: &Json) -> Vec<u8> {
    let mut out = Vec::new();
    ciborium::into_writer(v, &mut out).expect("encodes");
    out
}

#[test]
fn our_cbor_output_of_every_vector_is_kept_as_it_came() {
    let reg = registry();
    let (mut kept, mut nan) = (0, 0);
    for v in vectors("cdr.jsonl") {
        let ty = v["type"].as_str().expect("type");
        let hex = v["cdr"].as_str().expect("hex");
        let cdr: Vec<u8> = (0..hex.len())
            .step_by(2)
            .map(|i| u8::from_str_radix(&hex[i..i + 2], 16).unwrap())
            .collect();
        let value = decode(&reg, ty, Wire::Cdr, &cdr).expect("vector decodes");
        let cbor = fleetlink_msg::to_cbor_bytes(&value);
        let (out, was_kept) = normalized_cbor(&reg, ty, &cbor);
        assert_eq!(out, cbor, "{ty}: the normal form of our own CBOR differs");
        if was_kept {
            kept += 1;
        } else {
            // Only a NaN scalar sends our own output down the full path.
            assert!(
                format!("{value:?}").contains("NaN"),
                "{ty}: converted again"
            );
            nan += 1;
        }
    }
    assert!(kept > 300, "only {kept} vectors kept ({nan} with NaN)");
}

#[test]
fn cbor_not_in_normal_form_is_converted_as_the_full_path_does() {
    let reg = registry();
    for (ty, msg) in [
        // An integer in a float field, a float in an integer field.
        ("std_msgs/msg/Float64", json!({"data": 1})),
        ("std_msgs/msg/Int32", json!({"data": 7.0})),
        // A missing field, fields out of order, ROS 1's `seq` in a ROS 2 header.
        ("std_msgs/msg/Int32", json!({})),
        (
            "std_msgs/msg/Header",
            json!({"seq": 4, "stamp": {"sec": 1, "nanosec": 2}, "frame_id": "m"}),
        ),
        (
            "geometry_msgs/msg/Vector3",
            json!({"z": 3.0, "y": 2.0, "x": 1.0}),
        ),
        // A plain array where rosbridge writes a typed one, and text for bytes.
        (
            "std_msgs/msg/Float64MultiArray",
            json!({"layout": {"dim": [], "data_offset": 0}, "data": [1.5, 2.5]}),
        ),
        (
            "std_msgs/msg/UInt8MultiArray",
            json!({"layout": {"dim": [], "data_offset": 0}, "data": "AQID"}),
        ),
        // ROS 1 names for a time.
        (
            "std_msgs/msg/Header",
            json!({"stamp": {"secs": 1, "nsecs": 2}, "frame_id": "m"}),
        ),
    ] {
        let cbor = cbor_of(&msg);
        let (out, kept) = normalized_cbor(&reg, ty, &cbor);
        assert!(!kept, "{ty}: {msg} was kept as it came");
        let full = fleetlink_msg::from_cbor(&reg, ty, Dialect::Ros2, &cbor).expect("valid");
        assert_eq!(out, fleetlink_msg::to_cbor_bytes(&full), "{ty}: {msg}");
        // And what comes out is normal: a second pass keeps it.
        assert!(normalized_cbor(&reg, ty, &out).1, "{ty}: output not normal");
    }
    // A shorter head than needed is the same value but not the writer's bytes.
    let long_head = [0xa1, 0x64, b'd', b'a', b't', b'a', 0x18, 0x07];
    let (out, kept) = normalized_cbor(&reg, "std_msgs/msg/Int32", &long_head);
    assert!(!kept);
    assert_eq!(out, [0xa1, 0x64, b'd', b'a', b't', b'a', 0x07]);
}

#[test]
fn wrong_cbor_is_refused_on_either_path() {
    let reg = registry();
    let resolved = reg.resolve("std_msgs/msg/Int32", Dialect::Ros2).unwrap();
    for msg in [
        json!({"data": "notanint"}),
        json!({"data": 1u64 << 40}),
        json!([1]),
    ] {
        let cbor = cbor_of(&msg);
        assert!(
            fleetlink_msg::normalize_cbor_resolved(&resolved, &cbor).is_err(),
            "{msg}"
        );
    }
}

/// A field the type does not have is refused, as rosbridge refuses it, naming the field
/// and where it is; from JSON text, a JSON value and CBOR alike.
#[test]
fn unknown_fields_are_refused_naming_them() {
    let reg = registry();
    for (ty, msg, path, key) in [
        (
            "geometry_msgs/msg/Twist",
            json!({"linear": {"x": 1}, "bogus": 3}),
            "",
            "bogus",
        ),
        (
            "geometry_msgs/msg/Twist",
            json!({"linear": {"x": 1, "w": 2}}),
            "linear",
            "w",
        ),
        (
            "visualization_msgs/msg/MarkerArray",
            json!({"markers": [{"ns": "a"}, {"ns": "b", "colour": {}}]}),
            "markers[1]",
            "colour",
        ),
    ] {
        let text = msg.to_string();
        let json_text = normalize_json_bytes(&reg, ty, Dialect::Ros2, text.as_bytes());
        let json_value = fleetlink_msg::from_json(&reg, ty, Dialect::Ros2, &msg).map(|_| ());
        let mut cbor = Vec::new();
        ciborium::into_writer(&msg, &mut cbor).unwrap();
        let cbor = fleetlink_msg::from_cbor(&reg, ty, Dialect::Ros2, &cbor).map(|_| ());
        for (how, err) in [
            ("JSON text", json_text.map(|_| ()).unwrap_err().to_string()),
            ("JSON value", json_value.unwrap_err().to_string()),
            ("CBOR", cbor.unwrap_err().to_string()),
        ] {
            assert!(
                err.contains(&format!("no field '{key}'")),
                "{how} {ty}: {err}"
            );
            assert!(err.contains(path), "{how} {ty}: {err} should name {path}");
        }
    }
}

/// A partial message of a bundled ROS 1 style type gets its defaults, nested ones too.
#[test]
fn partial_messages_get_their_defaults() {
    let reg = registry();
    let (out, kept) = normalized(&reg, "actionlib_msgs/GoalID", r#"{"id": "g1"}"#);
    assert!(!kept);
    assert_eq!(out, json!({"stamp": {"sec": 0, "nanosec": 0}, "id": "g1"}));
    let (out, _) = normalized(
        &reg,
        "trajectory_msgs/msg/JointTrajectory",
        r#"{"joint_names": ["a"], "points": [{"positions": [1]}]}"#,
    );
    assert_eq!(out["header"]["frame_id"], "");
    assert_eq!(
        out["points"][0],
        json!({"positions": [1.0], "velocities": [], "accelerations": [], "effort": [],
               "time_from_start": {"sec": 0, "nanosec": 0}})
    );
    let (out, _) = normalized(&reg, "geometry_msgs/msg/PoseWithCovariance", "{}");
    assert_eq!(out["covariance"].as_array().map(Vec::len), Some(36));
    assert_eq!(out["pose"]["orientation"]["w"], 1.0);
}
