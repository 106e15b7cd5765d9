//! One client's outbound side.
//!
//! Each of the client's subscriptions has a slot holding its bounded queue. Publishers
//! push into slots from their own tasks (never blocking, never waiting on this client);
//! the one task that writes the client's socket takes batches round-robin across the
//! slots that have something ready, so a busy topic cannot starve a quiet one.
//!
//! The state is behind a `std::sync::Mutex`: every critical section is a few pointer
//! moves, never an `.await`, and an async mutex would cost more than it saves.

use std::collections::{HashMap, VecDeque};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use fleetlink_proto::rosbridge::Compression;
use tokio::sync::Notify;

use crate::message::Message;
use crate::names::ClientId;
use crate::queue::{DropReason, OutboundQueue};
use crate::stats::TopicStats;

/// A slot's key; never reused within one outbox, so a stale reference cannot reach a new
/// subscription.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct SlotId(pub u64);

/// How a subscription wants its messages framed (used by rosbridge sessions).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Delivery {
    pub compression: Compression,
    pub fragment_size: Option<u32>,
}

struct Slot {
    queue: Box<dyn OutboundQueue>,
    stats: Arc<TopicStats>,
    delivery: Delivery,
    in_ready: bool,
}

#[derive(Default)]
struct State {
    slots: HashMap<SlotId, Slot>,
    /// Slots with queued messages, in service order.
    ready: VecDeque<SlotId>,
    next_slot: u64,
    queued: usize,
}

pub struct Outbox {
    pub client: ClientId,
    state: Mutex<State>,
    notify: Notify,
    closed: AtomicBool,
    /// Messages this client lost, all topics and reasons together.
    pub dropped: AtomicU64,
    /// Messages handed to this client's writer.
    pub sent: AtomicU64,
}

/// A batch taken by the writer.
pub struct Batch {
    pub items: Vec<(SlotId, Delivery, Arc<Message>)>,
    /// When throttled slots will next have something (if any are waiting).
    pub wake_at: Option<Instant>,
}

impl Outbox {
    pub fn new(client: ClientId) -> Arc<Outbox> {
        Arc::new(Outbox {
            client,
            state: Mutex::new(State::default()),
            notify: Notify::new(),
            closed: AtomicBool::new(false),
            dropped: AtomicU64::new(0),
            sent: AtomicU64::new(0),
        })
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        // A panic while holding this lock leaves only queue contents behind; keep serving.
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    pub fn add_slot(
        &self,
        queue: Box<dyn OutboundQueue>,
        stats: Arc<TopicStats>,
        delivery: Delivery,
    ) -> SlotId {
        let mut st = self.lock();
        st.next_slot += 1;
        let id = SlotId(st.next_slot);
        st.slots.insert(
            id,
            Slot {
                queue,
                stats,
                delivery,
                in_ready: false,
            },
        );
        id
    }

    pub fn remove_slot(&self, id: SlotId) {
        let mut st = self.lock();
        if let Some(slot) = st.slots.remove(&id) {
            st.queued -= slot.queue.len();
        }
        st.ready.retain(|s| *s != id);
    }

    /// Queues `msg` for the subscription in `slot`. Never blocks.
    pub fn push(&self, slot: SlotId, msg: Arc<Message>, now: Instant) {
        let mut st = self.lock();
        let st = &mut *st;
        let Some(s) = st.slots.get_mut(&slot) else {
            return;
        };
        let before = s.queue.len();
        let dropped = s.queue.push(msg, now);
        let after = s.queue.len();
        if let Some((_, reason)) = dropped {
            s.stats.record_drop(reason);
            self.dropped.fetch_add(1, Relaxed);
        }
        s.stats.deliveries.fetch_add(1, Relaxed);
        let wake = !s.in_ready && after > 0;
        if wake {
            s.in_ready = true;
            st.ready.push_back(slot);
        }
        st.queued = st.queued + after - before;
        if wake {
            self.notify.notify_one();
        }
    }

    /// Counts a message the writer had to give up on (e.g. it could not be encoded).
    pub fn record_drop(&self, slot: SlotId, reason: DropReason) {
        self.dropped.fetch_add(1, Relaxed);
        if let Some(s) = self.lock().slots.get(&slot) {
            s.stats.record_drop(reason);
        }
    }

    /// Takes up to `max_items` / about `max_bytes` of messages, one per ready slot per round.
    pub fn take(&self, max_items: usize, max_bytes: usize, now: Instant) -> Batch {
        let mut st = self.lock();
        let st = &mut *st;
        let mut items = Vec::new();
        let mut bytes = 0usize;
        let mut waiting: Vec<SlotId> = Vec::new();
        let mut wake_at: Option<Instant> = None;
        while items.len() < max_items && bytes < max_bytes {
            let Some(id) = st.ready.pop_front() else {
                break;
            };
            let Some(s) = st.slots.get_mut(&id) else {
                continue;
            };
            match s.queue.pop(now) {
                Some(m) => {
                    bytes += m.wire_len();
                    items.push((id, s.delivery, m));
                    st.queued -= 1;
                    if s.queue.is_empty() {
                        s.in_ready = false;
                    } else {
                        st.ready.push_back(id);
                    }
                }
                None if s.queue.is_empty() => s.in_ready = false,
                None => {
                    let at = s.queue.ready_at(now);
                    wake_at = Some(wake_at.map_or(at, |w| w.min(at)));
                    waiting.push(id);
                }
            }
        }
        st.ready.extend(waiting);
        self.sent.fetch_add(items.len() as u64, Relaxed);
        Batch { items, wake_at }
    }

    /// Messages queued across all slots.
    pub fn depth(&self) -> usize {
        self.lock().queued
    }

    /// How long the oldest queued message has waited.
    pub fn lag(&self, now: Instant) -> Duration {
        let st = self.lock();
        st.slots
            .values()
            .filter_map(|s| s.queue.oldest())
            .map(|m| now.saturating_duration_since(m.received))
            .max()
            .unwrap_or_default()
    }

    /// Waits until something may be ready. Returns immediately if a push happened since
    /// the last call.
    pub async fn ready(&self) {
        self.notify.notified().await;
    }

    /// Wakes the writer for good: the client is going away.
    pub fn close(&self) {
        self.closed.store(true, Relaxed);
        self.notify.notify_one();
    }

    pub fn is_closed(&self) -> bool {
        self.closed.load(Relaxed)
    }
}
