//! Shared helpers: the test registry and the generated vectors.

use std::path::PathBuf;

use fleetlink_msg::Registry;

pub fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Bundled definitions plus the `test_msgs` fixture package.
pub fn registry() -> Registry {
    let reg = Registry::bundled();
    let n = reg
        .add_package_dir(crate_dir().join("tests/fixtures"))
        .expect("fixture package loads");
    assert!(n >= 5, "fixtures found: {n}");
    reg
}

pub fn hex(text: &str) -> Vec<u8> {
    (0..text.len())
        .step_by(2)
        .map(|i| u8::from_str_radix(&text[i..i + 2], 16).expect("vector hex"))
        .collect()
}

/// One JSON object per line of `tests/vectors/<name>`.
pub fn vectors(name: &str) -> Vec<serde_json::Value> {
    let path = crate_dir().join("tests/vectors").join(name);
    let text = std::fs::read_to_string(&path)
        .expect("vectors exist; regenerate with tests/interop/msg/gen_vectors.py");
    text.lines()
        .map(|l| serde_json::from_str(l).expect("vector line is JSON"))
        .collect()
}

pub fn json_file(name: &str) -> serde_json::Value {
    let path = crate_dir().join("tests/vectors").join(name);
    serde_json::from_str(&std::fs::read_to_string(path).expect("vector file")).expect("JSON")
}

/// Asserts no failures, showing the first few.
pub fn assert_none(failures: &[String], what: &str) {
    assert!(
        failures.is_empty(),
        "{} {what} failures, first ones:\n{}",
        failures.len(),
        failures
            .iter()
            .take(8)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n")
    );
}
