//! Fuzz target for the binary decoders: CDR and ROS 1, plus the zero-copy CDR view.
//!
//! The first input byte picks the message type (from every bundled type) and the wire
//! format; the rest is the payload. Any panic, or an allocation the input merely
//! claims, is a bug: decoders must answer with `CodecError`.
#![no_main]

use std::sync::LazyLock;

use fleetlink_msg::{CdrView, Registry, Wire, decode};
use libfuzzer_sys::fuzz_target;

static REGISTRY: LazyLock<(Registry, Vec<String>)> = LazyLock::new(|| {
    let reg = Registry::bundled();
    let names = reg
        .message_names()
        .into_iter()
        .map(|n| n.to_string())
        .collect();
    (reg, names)
});

fuzz_target!(|data: &[u8]| {
    let Some((&selector, payload)) = data.split_first() else {
        return;
    };
    let (reg, names) = &*REGISTRY;
    let ty = &names[usize::from(selector >> 1) % names.len()];
    if selector & 1 == 0 {
        let _ = decode(reg, ty, Wire::Cdr, payload);
        let _ = CdrView::new(reg, ty, payload);
    } else {
        let _ = decode(reg, ty, Wire::Ros1, payload);
    }
});
