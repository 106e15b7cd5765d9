//! How the queues' rings give memory back. A ring grows as items wait; once a backlog
//! has drained, a buffer larger than [`KEEP_EMPTY_CAPACITY`] is let go, so an idle
//! queue holds little. Shared by the per-topic queue and the AFR buffer, which both keep
//! their items in `VecDeque` rings.

use std::collections::VecDeque;

/// Items an empty queue keeps room for; a larger buffer, left by a backlog, is let go
/// when the backlog has drained, so an idle subscription holds little.
pub const KEEP_EMPTY_CAPACITY: usize = 32;

/// Lets a drained ring's large buffer go.
pub(crate) fn release_if_drained<T>(ring: &mut VecDeque<T>) {
    if ring.is_empty() && ring.capacity() > KEEP_EMPTY_CAPACITY {
        *ring = VecDeque::new();
    }
}
