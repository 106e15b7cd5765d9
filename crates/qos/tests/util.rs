//! Test helpers: a sized message type.

use fleetlink_qos::WireLen;

/// A test message: topic-local sequence number and wire size.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Msg {
    pub seq: u64,
    pub len: usize,
    /// Virtual time it was published, ns.
    pub born: u64,
}

impl WireLen for Msg {
    fn wire_len(&self) -> usize {
        self.len
    }
}
