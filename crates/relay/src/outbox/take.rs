//! The writer's side of the outbox: batches taken round-robin across ready slots, or in
//! the scheduler's order with demand, age limits and no-drop bookkeeping applied. Apart
//! from the publishers' side (`push`) and the link's.

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
            Service::Scheduled {
                sched,
                origin,
                by_topic,
                reliable,
                demand,
                pulled,
                ..
            } => {
                let t = Nanos::since(*origin, now);
                while items.len() < max_items
                    && let Some(m) = pulled.pop_front()
                {
                    let slot = by_topic.get(&m.topic.id.0).copied().unwrap_or(SlotId(0));
                    bytes += m.wire_len();
                    sched.debit_data(wire_cost(m.wire_len()), t);
                    items.push((slot, Delivery::default(), m));
                }
                while items.len() < max_items && bytes < max_bytes {
                    let Some((tid, m)) = sched.poll_next(t) else {
                        break;
                    };
                    st.queued = st.queued.saturating_sub(1);
                    // Counted against the data budget now, so one batch cannot overdraw
                    // it (given back below when the message is not sent after all).
                    let cost = wire_cost(m.wire_len());
                    sched.debit_data(cost, t);
                    if !demand.flows(tid.0) {
                        // Queued before interest went: not sent, and no longer counted
                        // in flight.
                        sched.on_acked(1, t);
                        sched.credit_data(cost);
                        continue;
                    }
                    if sched.is_no_drop(tid) {
                        // Sent even when its publisher has gone: it was promised delivery.
                        reliable.sent(tid.0, m.clone());
                        let slot = by_topic.get(&tid.0).copied().unwrap_or(SlotId(0));
                        if sched.no_drop_room(tid)
                            && let Some(s) = st.slots.get(&slot)
                        {
                            s.stats.no_drop_flow.set_room();
                        }
                        bytes += m.wire_len();
                        items.push((slot, Delivery::default(), m));
                        continue;
                    }
                    let Some(slot) = by_topic.get(&tid.0) else {
                        // Unsubscribed while queued: it was in flight by the scheduler's
                        // count, so acknowledge it locally.
                        sched.on_acked(1, t);
                        sched.credit_data(cost);
                        continue;
                    };
                    if demand.too_old(tid.0, &m, now) {
                        // Stale by the time its turn came (after a blackout, say): a
                        // reconnect does not flood the hub with it.
                        sched.on_acked(1, t);
                        sched.credit_data(cost);
                        if let Some(s) = st.slots.get(slot) {
                            s.stats.record_drop(DropReason::TooOld);
                        }
                        self.dropped.fetch_add(1, Relaxed);
                        continue;
                    }
                    let delivery = st.slots.get(slot).map(|s| s.delivery).unwrap_or_default();
                    bytes += m.wire_len();
                    items.push((*slot, delivery, m));
                }
                if items.is_empty()
                    && let Some(at) = sched.poll_timeout(t)
                {
                    wake_at = Some(*origin + std::time::Duration::from_nanos(at.0));
                }
            }
        }
        self.sent.fetch_add((items.len() - before) as u64, Relaxed);
        wake_at
    }
}
