//! Round-trip property tests: random message values of every registered type through
//! CDR, ROS 1, rosbridge JSON and CBOR and back.

use std::sync::LazyLock;

use fleetlink_msg::spec::{ArrayKind, Element, Primitive};
use fleetlink_msg::{
    Dialect, Registry, Value, Wire, decode, encode, from_cbor, from_json, from_json_bytes,
    to_cbor_bytes, to_json, to_json_bytes,
};
use proptest::prelude::*;
use proptest::test_runner::{RngAlgorithm, TestRng};
use serde_json::{Value as J, json};

use crate::util::registry;

static REG: LazyLock<Registry> = LazyLock::new(registry);
static TYPES: LazyLock<Vec<String>> = LazyLock::new(|| {
    REG.message_names()
        .into_iter()
        .map(|n| n.to_string())
        .filter(|n| REG.message(n, Dialect::Ros2).is_ok())
        .collect()
});

/// Random rosbridge JSON for `type_name`, built from its parsed definition.
fn random_json(
    reg: &Registry,
    type_name: &str,
    dialect: Dialect,
    rng: &mut TestRng,
    depth: usize,
) -> J {
    let spec = reg.message(type_name, dialect).expect("registered");
    if spec.name.package() == "builtin_interfaces" {
        // Times valid in both generations (ROS 1 time is unsigned, ROS 2's signed).
        return random_scalar(Primitive::Time, None, rng);
    }
    let mut obj = serde_json::Map::new();
    for f in &spec.fields {
        let n = match f.ty.array {
            ArrayKind::Single => None,
            ArrayKind::Fixed(n) => Some(n as usize),
            ArrayKind::Bounded(b) => Some(rng.random_range(0..=b as usize)),
            ArrayKind::Unbounded => Some(if depth > 2 { 0 } else { rng.random_range(0..4) }),
        };
        let one = |rng: &mut TestRng| -> J {
            match &f.ty.element {
                Element::Primitive(p) => random_scalar(*p, f.ty.string_bound, rng),
                Element::Named { package, name } => {
                    let pkg = package
                        .clone()
                        .unwrap_or_else(|| spec.name.package().to_owned());
                    let full = if name == "Header"
                        && package.is_none()
                        && !reg.contains(&format!("{pkg}/Header"))
                    {
                        "std_msgs/Header".to_owned()
                    } else {
                        format!("{pkg}/{name}")
                    };
                    random_json(reg, &full, dialect, rng, depth + 1)
                }
            }
        };
        let v = match n {
            None => one(rng),
            Some(n) => J::Array((0..n).map(|_| one(rng)).collect()),
        };
        obj.insert(f.name.clone(), v);
    }
    J::Object(obj)
}

fn random_scalar(p: Primitive, bound: Option<u32>, rng: &mut TestRng) -> J {
    match p {
        Primitive::Bool => json!(rng.random::<bool>()),
        // `byte` is signed in ROS 1 and unsigned in ROS 2: stay in the common range.
        Primitive::Byte => json!(rng.random_range(0..128u8)),
        Primitive::Char | Primitive::UInt8 => json!(rng.random::<u8>()),
        Primitive::Int8 => json!(rng.random::<i8>()),
        Primitive::Int16 => json!(rng.random::<i16>()),
        Primitive::UInt16 => json!(rng.random::<u16>()),
        Primitive::Int32 => json!(rng.random::<i32>()),
        Primitive::UInt32 => json!(rng.random::<u32>()),
        Primitive::Int64 => json!(rng.random::<i64>()),
        Primitive::UInt64 => json!(rng.random::<u64>()),
        Primitive::Float32 => match rng.random_range(0..10) {
            0 => J::Null,
            _ => json!(rng.random::<f32>() * 1e4 - 5e3),
        },
        Primitive::Float64 => match rng.random_range(0..10) {
            0 => J::Null,
            _ => json!(rng.random::<f64>() * 1e9 - 5e8),
        },
        Primitive::String | Primitive::WString => {
            let pool = ["", "x", "héllo", "日本", "🤖 robot", "quote\" and \\ back"];
            let s = pool[rng.random_range(0..pool.len())];
            match bound {
                Some(b) => json!(
                    s.chars()
                        .filter(char::is_ascii)
                        .take(b as usize)
                        .collect::<String>()
                ),
                None => json!(s),
            }
        }
        Primitive::Time | Primitive::Duration => {
            json!({"sec": rng.random_range(0..i32::MAX), "nanosec": rng.random_range(0..1_000_000_000u32)})
        }
    }
}

/// A random message of a random type, in the JSON shape of `dialect`'s definition.
fn sample(seed: u64, idx: usize, dialect: Dialect) -> (String, J) {
    let ty = TYPES[idx % TYPES.len()].clone();
    let mut bytes = [0u8; 32];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    let mut rng = TestRng::from_seed(RngAlgorithm::ChaCha, &bytes);
    let j = random_json(&REG, &ty, dialect, &mut rng, 0);
    (ty, j)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn value_to_cdr_to_value(seed in any::<u64>(), idx in any::<usize>()) {
        let (ty, j) = sample(seed, idx, Dialect::Ros2);
        let v = from_json(&REG, &ty, Dialect::Ros2, &j).expect("random JSON fits");
        let cdr = encode(&REG, &ty, Wire::Cdr, &v).expect("encodes");
        let back = decode(&REG, &ty, Wire::Cdr, &cdr).expect("decodes");
        prop_assert!(back.same_as(&v), "{ty}: CDR round trip changed the value");
    }

    #[test]
    fn value_to_ros1_to_value(seed in any::<u64>(), idx in any::<usize>()) {
        let (ty, j) = sample(seed, idx, Dialect::Ros1);
        let v = from_json(&REG, &ty, Dialect::Ros1, &j).expect("random JSON fits");
        let bytes = encode(&REG, &ty, Wire::Ros1, &v).expect("encodes");
        let back = decode(&REG, &ty, Wire::Ros1, &bytes).expect("decodes");
        prop_assert!(back.same_as(&v), "{ty}: ROS 1 round trip changed the value");
    }

    #[test]
    fn value_to_json_to_value(seed in any::<u64>(), idx in any::<usize>()) {
        let (ty, j) = sample(seed, idx, Dialect::Ros2);
        let v = from_json(&REG, &ty, Dialect::Ros2, &j).expect("random JSON fits");
        let text = to_json_bytes(&v);
        let back = from_json_bytes(&REG, &ty, Dialect::Ros2, &text).expect("our JSON parses");
        prop_assert!(back.same_as(&v), "{ty}: JSON text round trip changed the value");
        let back = from_json(&REG, &ty, Dialect::Ros2, &to_json(&v)).expect("our JSON value parses");
        prop_assert!(back.same_as(&v), "{ty}: JSON value round trip changed the value");
    }

    #[test]
    fn json_to_cdr_to_json(seed in any::<u64>(), idx in any::<usize>()) {
        let (ty, j) = sample(seed, idx, Dialect::Ros2);
        let v = from_json(&REG, &ty, Dialect::Ros2, &j).expect("random JSON fits");
        let first = to_json(&v);
        let cdr = encode(&REG, &ty, Wire::Cdr, &v).expect("encodes");
        let direct = fleetlink_msg::cdr_to_json_bytes(&REG, &ty, &cdr).expect("converts");
        let second: J = serde_json::from_slice(&direct).expect("valid JSON text");
        let reparsed = from_json(&REG, &ty, Dialect::Ros2, &second).expect("parses");
        prop_assert!(reparsed.same_as(&v), "{ty}: JSON -> CDR -> JSON changed the value");
        prop_assert_eq!(&to_json(&decode(&REG, &ty, Wire::Cdr, &cdr).expect("decodes")), &first);
    }

    #[test]
    fn value_to_cbor_to_value(seed in any::<u64>(), idx in any::<usize>()) {
        let (ty, j) = sample(seed, idx, Dialect::Ros2);
        let v = from_json(&REG, &ty, Dialect::Ros2, &j).expect("random JSON fits");
        let cbor = to_cbor_bytes(&v);
        let back = from_cbor(&REG, &ty, Dialect::Ros2, &cbor).expect("our CBOR parses");
        prop_assert!(back.same_as(&v), "{ty}: CBOR round trip changed the value");
        let cdr = encode(&REG, &ty, Wire::Cdr, &v).expect("encodes");
        prop_assert_eq!(fleetlink_msg::cdr_to_cbor_bytes(&REG, &ty, &cdr).expect("converts"), cbor);
    }
}

#[test]
fn round_trips_cover_every_registered_type() {
    // The property tests pick types by index; make sure the list is the full registry.
    assert!(TYPES.len() > 150, "{} types", TYPES.len());
    assert!(TYPES.iter().any(|t| t == "test_msgs/msg/Bounded"));
    let v: Value =
        from_json(&REG, "test_msgs/msg/AllTypes", Dialect::Ros2, &json!({})).expect("defaults");
    assert!(encode(&REG, "test_msgs/msg/AllTypes", Wire::Cdr, &v).is_ok());
}
