//! The writer's side of the outbox: batches taken round-robin across ready slots, or in
//! the scheduler's order with demand, age limits and no-drop bookkeeping applied (the
//! uplink's part, `Uplink::take_into`). Apart from the publishers' side (`push`) and the
//! link's.

use super::*;

/// A message taken by the writer: its slot, how to deliver it, the message.
pub type Taken = (SlotId, Delivery, Arc<Message>);

/// A batch taken by the writer.
pub struct Batch {
    pub items: Vec<Taken>,
    /// When throttled slots will next have something (if any are waiting).
    pub wake_at: Option<Instant>,
}

impl Outbox {
    /// Counts a message the writer had to give up on (e.g. it could not be encoded).
    pub fn record_drop(&self, slot: SlotId, reason: DropReason) {
        self.dropped.fetch_add(1, Relaxed);
        if let Some(s) = self.lock().slots.get(&slot) {
            s.stats.record_drop(reason);
        }
    }

    /// Takes up to `max_items` / about `max_bytes` of messages: one per ready slot per
    /// round (round-robin), or in the scheduler's order.
    pub fn take(&self, max_items: usize, max_bytes: usize, now: Instant) -> Batch {
        let mut items = Vec::new();
        let wake_at = self.take_into(&mut items, max_items, max_bytes, now);
        Batch { items, wake_at }
    }

    /// [`Outbox::take`] appending to `items`, a vector the writer keeps across batches so
    /// a busy writer does not allocate one per batch. Returns the batch's `wake_at`.
    pub fn take_into(
        &self,
        items: &mut Vec<Taken>,
        max_items: usize,
        max_bytes: usize,
        now: Instant,
    ) -> Option<Instant> {
        let max_items = max_items.saturating_add(items.len());
        let before = items.len();
        let mut st = self.lock();
        let st = &mut *st;
        items.reserve((max_items - before).min(st.queued));
        let mut bytes = 0usize;
        let mut wake_at: Option<Instant> = None;
        match &mut st.service {
            Service::RoundRobin { ready } => {
                while items.len() < max_items && bytes < max_bytes {
                    let Some(id) = ready.pop_front() else { break };
                    let Some(s) = st.slots.get_mut(&id) else {
                        continue;
                    };
                    let q = s.queue.as_mut().expect("round-robin slots own a queue");
                    match q.pop(now) {
                        Some(m) if s.skip && !crate::gop::is_keyframe(&m) => {
                            // After a lost video frame: skipped to the next keyframe,
                            // which is wanted until it comes (the one asked for may
                            // have been lost too, to a queue this slow).
                            st.queued -= 1;
                            s.stats.keyframe_wanted.store(true, Relaxed);
                            s.stats.record_drop(DropReason::Policy);
                            self.dropped.fetch_add(1, Relaxed);
                            if q.is_empty() {
                                s.in_ready = false;
                            } else {
                                ready.push_front(id);
                            }
                        }
                        Some(m) => {
                            s.skip = false;
                            bytes += m.wire_len();
                            items.push((id, s.delivery, m));
                            st.queued -= 1;
                            if q.is_empty() {
                                s.in_ready = false;
                            } else {
                                ready.push_back(id);
                            }
                        }
                        None => s.in_ready = false,
                    }
                }
            }
            Service::Scheduled(u) => {
                wake_at = u.take_into(
                    items,
                    max_items,
                    max_bytes,
                    now,
                    &st.slots,
                    &mut st.queued,
                    &self.dropped,
                );
            }
        }
        self.sent.fetch_add((items.len() - before) as u64, Relaxed);
        wake_at
    }
}
