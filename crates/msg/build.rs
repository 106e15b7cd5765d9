//! Lists the bundled interface files under `defs/` so `src/bundled.rs` can embed them
//! with `include_str!` without a hand-kept list that could drift from the directory.

use std::fmt::Write as _;
use std::path::Path;
use std::{env, fs};

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("defs");
    println!("cargo:rerun-if-changed={}", root.display());
    let mut entries = Vec::new();
    for dialect in ["ros2", "ros1"] {
        let dialect_dir = root.join(dialect);
        for pkg in sorted_dirs(&dialect_dir) {
            for kind in ["msg", "srv", "action"] {
                let dir = dialect_dir.join(&pkg).join(kind);
                for file in sorted_files(&dir) {
                    println!("cargo:rerun-if-changed={}", dir.join(&file).display());
                    let Some((stem, ext)) = file.rsplit_once('.') else {
                        continue;
                    };
                    if ext != kind {
                        continue;
                    }
                    entries.push(format!(
                        "    ({dialect:?}, {pkg:?}, {kind:?}, {stem:?}, include_str!({path:?})),\n",
                        path = dir.join(&file).display().to_string()
                    ));
                }
            }
        }
    }
    let mut out = String::from("&[\n");
    for e in entries {
        let _ = write!(out, "{e}");
    }
    out.push(']');
    let dest = Path::new(&env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("bundled_list.rs");
    fs::write(dest, out).expect("write bundled_list.rs");
}

fn sorted_dirs(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .filter(|e| e.path().is_dir())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

fn sorted_files(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .filter(|e| e.path().is_file())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}
