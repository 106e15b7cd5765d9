//! Cross-checks against vectors the real peers produced (see tests/interop/msg).
//!
//! `cdr.jsonl`: values and the CDR bytes rosbags serialized (little-endian, and
//! big-endian for one value per type); `rihs01.json`: rosbags'
//! REP-2016 hashes; `ros1.jsonl` / `ros1_types.json`: bytes, md5sums and full texts of
//! Debian's rospy message classes.

use std::collections::BTreeSet;

use fleetlink_msg::{Dialect, Registry, Wire, decode, encode, from_json, md5sum, type_hash};

use crate::util::{assert_none, hex, json_file, registry, vectors};

fn check_vector(
    reg: &Registry,
    ty: &str,
    wire: Wire,
    json: &serde_json::Value,
    bytes: &[u8],
) -> Result<(), String> {
    let dialect = fleetlink_msg::dialect_of(wire);
    let value = from_json(reg, ty, dialect, json).map_err(|e| format!("{ty}: from_json: {e}"))?;
    let ours = encode(reg, ty, wire, &value).map_err(|e| format!("{ty}: encode: {e}"))?;
    if ours != bytes {
        let at = ours
            .iter()
            .zip(bytes)
            .position(|(a, b)| a != b)
            .unwrap_or(ours.len().min(bytes.len()));
        let show = |b: &[u8]| {
            b[at.saturating_sub(4)..(at + 8).min(b.len())]
                .iter()
                .map(|x| format!("{x:02x}"))
                .collect::<String>()
        };
        return Err(format!(
            "{ty}: bytes differ at {at} (lengths {} vs {}): ours ..{}.. theirs ..{}..",
            ours.len(),
            bytes.len(),
            show(&ours),
            show(bytes)
        ));
    }
    let back = decode(reg, ty, wire, bytes).map_err(|e| format!("{ty}: decode: {e}"))?;
    if !back.same_as(&value) {
        return Err(format!(
            "{ty}: decoded value differs from the vector's value"
        ));
    }
    Ok(())
}

#[test]
fn cdr_bytes_are_identical_to_rosbags_and_decode_to_the_same_values() {
    let reg = registry();
    let mut failures = Vec::new();
    let all = vectors("cdr.jsonl");
    assert!(all.len() > 500, "only {} CDR vectors", all.len());
    for v in &all {
        let ty = v["type"].as_str().expect("type");
        if let Err(e) = check_vector(
            &reg,
            ty,
            Wire::Cdr,
            &v["json"],
            &hex(v["cdr"].as_str().expect("cdr")),
        ) {
            failures.push(format!("[{}] {e}", v["mode"]));
        }
    }
    assert_none(&failures, "CDR");
}

#[test]
fn big_endian_cdr_from_rosbags_decodes_to_the_same_values() {
    let reg = registry();
    let mut failures = Vec::new();
    let mut checked = 0;
    for v in vectors("cdr.jsonl")
        .iter()
        .filter(|v| v.get("cdr_be").is_some())
    {
        let ty = v["type"].as_str().expect("type");
        let value = from_json(&reg, ty, Dialect::Ros2, &v["json"]).expect("vector JSON fits");
        match decode(
            &reg,
            ty,
            Wire::Cdr,
            &hex(v["cdr_be"].as_str().expect("hex")),
        ) {
            Ok(back) if back.same_as(&value) => {}
            Ok(_) => failures.push(format!("{ty}: big-endian decode differs")),
            Err(e) => failures.push(format!("{ty}: {e}")),
        }
        checked += 1;
    }
    assert!(checked > 150, "only {checked} big-endian vectors");
    assert_none(&failures, "big-endian CDR");
}

#[test]
fn every_bundled_ros2_type_is_in_the_cdr_corpus() {
    let reg = Registry::bundled();
    let covered: BTreeSet<String> = vectors("cdr.jsonl")
        .iter()
        .map(|v| v["type"].as_str().expect("type").to_owned())
        .collect();
    let missing: Vec<String> = reg
        .message_names()
        .into_iter()
        .filter(|n| reg.message(&n.to_string(), Dialect::Ros2).is_ok())
        .map(|n| n.to_string())
        .filter(|n| !covered.contains(n))
        .collect();
    assert!(
        missing.is_empty(),
        "bundled types without vectors: {missing:?}"
    );
}

#[test]
fn type_hashes_match_rosbags() {
    let reg = registry();
    let hashes = json_file("rihs01.json");
    let mut failures = Vec::new();
    for (ty, expected) in hashes.as_object().expect("object") {
        // rosbags hashes `.msg` `char` as IDL char; rosidl (and we) as uint8. Everything
        // else about the algorithm is compared by hashing the way rosbags does.
        match fleetlink_msg::ident::type_hash_char_as_idl_char(&reg, ty) {
            Ok(h) if h == expected.as_str().unwrap_or_default() => {}
            Ok(h) => failures.push(format!("{ty}: ours {h}, rosbags {expected}")),
            Err(e) => failures.push(format!("{ty}: {e}")),
        }
    }
    assert_none(&failures, "RIHS01");
    // Without `char` fields both ways of hashing agree.
    let point = "geometry_msgs/msg/Point";
    assert_eq!(
        type_hash(&reg, point).ok(),
        hashes[point].as_str().map(str::to_owned)
    );
}

#[test]
fn ros1_bytes_are_identical_to_rospy_and_decode_to_the_same_values() {
    let reg = registry();
    let mut failures = Vec::new();
    let all = vectors("ros1.jsonl");
    assert!(all.len() > 400, "only {} ROS 1 vectors", all.len());
    for v in &all {
        let ty = v["type"].as_str().expect("type");
        if let Err(e) = check_vector(
            &reg,
            ty,
            Wire::Ros1,
            &v["json"],
            &hex(v["ros1"].as_str().expect("bytes")),
        ) {
            failures.push(format!("[{}] {e}", v["mode"]));
        }
    }
    assert_none(&failures, "ROS 1");
}

#[test]
fn ros1_md5sums_of_bundled_types_match_rospy() {
    let reg = Registry::bundled();
    let types = json_file("ros1_types.json");
    let mut failures = Vec::new();
    for (ty, info) in types["messages"].as_object().expect("messages") {
        let expected = info["md5"].as_str().expect("md5");
        match md5sum(&reg, ty) {
            Ok(m) if m == expected => {}
            Ok(m) => failures.push(format!("{ty}: ours {m}, rospy {expected}")),
            Err(e) => failures.push(format!("{ty}: {e}")),
        }
    }
    for (ty, expected) in types["services"].as_object().expect("services") {
        match md5sum(&reg, &ty.replace('/', "/srv/")) {
            Ok(m) if m == expected.as_str().unwrap_or_default() => {}
            Ok(m) => failures.push(format!("service {ty}: ours {m}, rospy {expected}")),
            Err(e) => failures.push(format!("service {ty}: {e}")),
        }
    }
    assert_none(&failures, "md5sum");
}

#[test]
fn ros1_definitions_received_at_run_time_give_rospy_md5sums_and_bytes() {
    let types = json_file("ros1_types.json");
    let mut failures = Vec::new();
    let by_type = types["messages"].as_object().expect("messages");
    for v in vectors("ros1.jsonl")
        .iter()
        .filter(|v| v["mode"] == "rand1")
    {
        let ty = v["type"].as_str().expect("type");
        // A fresh registry per type, as a hub learning a robot's type from TCPROS.
        let reg = Registry::empty();
        let info = &by_type[ty];
        if let Err(e) =
            reg.add_full_text(ty, info["full_text"].as_str().expect("text"), Dialect::Ros1)
        {
            failures.push(format!("{ty}: add_full_text: {e}"));
            continue;
        }
        match md5sum(&reg, ty) {
            Ok(m) if m == info["md5"].as_str().unwrap_or_default() => {}
            Ok(m) => failures.push(format!("{ty}: md5 from full text {m} != {}", info["md5"])),
            Err(e) => failures.push(format!("{ty}: {e}")),
        }
        if let Err(e) = check_vector(
            &reg,
            ty,
            Wire::Ros1,
            &v["json"],
            &hex(v["ros1"].as_str().expect("bytes")),
        ) {
            failures.push(e);
        }
    }
    assert_none(&failures, "ROS 1 full text");
}
