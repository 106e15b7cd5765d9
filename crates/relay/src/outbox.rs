//! One client's outbound side.
//!
//! Each of the client's subscriptions has a slot holding its bounded queue. Publishers
//! push into slots from their own tasks (never blocking, never waiting on this client);
//! the one task that writes the client's socket takes batches round-robin across the
//! slots that have something ready, so a busy topic cannot starve a quiet one.
//!
//! The state is behind a `std::sync::Mutex`: every critical section is a few pointer
//! moves, never an `.await`, and an async mutex would cost more than it saves.

mod demand;
mod estimator;
mod take;
mod uplink;

use std::collections::{HashMap, VecDeque};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use fleetlink_proto::rosbridge::Compression;
use tokio::sync::Notify;

use fleetlink_qos::{SchedulerConfig, TopicQos};

use crate::message::{Message, TopicMeta};
use crate::names::ClientId;
use crate::queue::{DropReason, OutboundQueue, QosQueue};
use crate::reliable::ReliableOut;
use crate::stats::TopicStats;

pub use demand::LATEST_DEFAULT_LIMIT;
pub use estimator::LinkFigures;
pub use take::{Batch, Taken};
pub use uplink::BudgetFigures;
use uplink::Uplink;

/// Chooses the QoS of each topic a scheduled outbox carries (the agent's per-topic
/// configuration, or defaults by type).
pub type QosFor = Arc<dyn Fn(&TopicMeta) -> TopicQos + Send + Sync>;

/// Internal ids (never chosen by a peer) need no DoS-resistant hashing.
type IdHash = rustc_hash::FxBuildHasher;

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
    /// The slot's own queue; `None` in a scheduled outbox, whose scheduler holds them.
    queue: Option<Box<dyn OutboundQueue>>,
    topic: u32,
    stats: Arc<TopicStats>,
    delivery: Delivery,
    in_ready: bool,
    /// The video chain of this round-robin slot broke at the newest end (a frame was
    /// refused on the way in): later frames are refused too until a keyframe, which
    /// enters past the rate limit. So the subscriber's decoder is never given a frame
    /// whose predecessor it lacks ([`crate::gop`]).
    hole: bool,
    /// The chain broke inside the queue (an older frame was evicted): what is queued
    /// before the next keyframe is skipped when taken.
    skip: bool,
}

/// Queues a video frame in the round-robin slot `s`, keeping the chain of frames the
/// subscriber will be given whole: a frame that does not fit is refused rather than
/// evicting the older frames it depends on; after a refusal, frames up to the next
/// keyframe are refused too and that keyframe enters past the rate limit (a throttled
/// video subscriber sees keyframes, which it asks for); an eviction all the same (a policy
/// that evicts at random; the byte bound, checked by the caller) skips what follows it in
/// the queue up to a keyframe. Every break asks for a keyframe.
fn push_video(s: &mut Slot, msg: Arc<Message>, now: Instant) -> Option<(Arc<Message>, DropReason)> {
    let key = crate::gop::is_keyframe(&msg);
    let q = s.queue.as_mut().expect("round-robin slots own a queue");
    let (dropped, refused) = if !key && (s.hole || q.is_full()) {
        (Some((msg, DropReason::Policy)), true)
    } else {
        let pushed = match q.push(msg.clone(), now) {
            // Over the rate limit; a keyframe ending a gap goes in all the same.
            Some((m, DropReason::RateLimit)) if key && s.hole => q.push_past_limit(m, now),
            pushed => pushed,
        };
        let refused = pushed.as_ref().is_some_and(|(m, _)| Arc::ptr_eq(m, &msg));
        (pushed, refused)
    };
    let evicted = dropped.is_some() && !refused;
    if refused {
        s.hole = true;
    } else if key {
        s.hole = false;
    }
    if evicted {
        s.skip = true;
    }
    if refused || evicted {
        s.stats.keyframe_wanted.store(true, Relaxed);
    }
    dropped
}

/// How the writer is served.
enum Service {
    /// Hub subscribers: every slot has its own queue, served round-robin so a busy topic
    /// cannot starve a quiet one.
    RoundRobin { ready: VecDeque<SlotId> },
    /// The agent uplink: the Robofleet scheduler and all that goes with it ([`Uplink`]).
    Scheduled(Box<Uplink>),
}

struct State {
    slots: HashMap<SlotId, Slot, IdHash>,
    service: Service,
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
    /// Served by the scheduler (the agent's uplink); fixed at construction, so the
    /// per-frame link calls of a plain outbox return without taking the lock.
    scheduled: bool,
    /// Woken when the peer's demand changes ([`Outbox::interest_changed`]).
    interest: Notify,
}

impl Outbox {
    pub fn new(client: ClientId) -> Arc<Outbox> {
        Self::with_service(
            client,
            Service::RoundRobin {
                ready: VecDeque::new(),
            },
        )
    }

    /// An outbox served by the Robofleet scheduler, for a link whose peer acknowledges
    /// messages ([`Outbox::on_acked`]).
    pub fn scheduled(
        client: ClientId,
        config: SchedulerConfig,
        qos_for: QosFor,
        reliable: ReliableOut,
    ) -> Arc<Outbox> {
        Self::with_service(
            client,
            Service::Scheduled(Box::new(Uplink::new(config, qos_for, reliable))),
        )
    }

    fn with_service(client: ClientId, service: Service) -> Arc<Outbox> {
        let scheduled = matches!(service, Service::Scheduled(_));
        Arc::new(Outbox {
            client,
            state: Mutex::new(State {
                slots: HashMap::default(),
                service,
                next_slot: 0,
                queued: 0,
            }),
            notify: Notify::new(),
            closed: AtomicBool::new(false),
            dropped: AtomicU64::new(0),
            sent: AtomicU64::new(0),
            scheduled,
            interest: Notify::new(),
        })
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        // A panic while holding this lock leaves only queue contents behind; keep serving.
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Runs `f` on the uplink's side under the lock; `None` for a plain outbox, which has
    /// none.
    fn with_uplink<R>(&self, f: impl FnOnce(&mut Uplink) -> R) -> Option<R> {
        match &mut self.lock().service {
            Service::Scheduled(u) => Some(f(u)),
            Service::RoundRobin { .. } => None,
        }
    }

    /// Adds a subscription's slot. `qos` shapes its queue; a scheduled outbox asks its
    /// own `qos_for` instead, so the agent's per-topic configuration wins.
    /// `max_bytes` bounds a round-robin slot's queue in payload bytes as well.
    pub fn add_slot(
        &self,
        topic: &TopicMeta,
        qos: &TopicQos,
        stats: Arc<TopicStats>,
        delivery: Delivery,
        max_bytes: Option<usize>,
    ) -> SlotId {
        let mut st = self.lock();
        let st = &mut *st;
        st.next_slot += 1;
        let id = SlotId(st.next_slot);
        let tid = topic.id.0;
        let queue = match &mut st.service {
            Service::RoundRobin { .. } => Some(Box::new(QosQueue::with_max_bytes(
                qos,
                max_bytes.unwrap_or(usize::MAX),
            )) as Box<dyn OutboundQueue>),
            Service::Scheduled(u) => {
                u.add_topic(topic, id);
                None
            }
        };
        st.slots.insert(
            id,
            Slot {
                queue,
                topic: tid,
                stats,
                delivery,
                in_ready: false,
                // A video subscriber starts at a keyframe: the group the router replays
                // to it, or the one its first refusal asks for.
                hole: true,
                skip: false,
            },
        );
        id
    }

    pub fn remove_slot(&self, id: SlotId) {
        let mut st = self.lock();
        let st = &mut *st;
        if let Some(slot) = st.slots.remove(&id) {
            match &mut st.service {
                Service::RoundRobin { ready } => {
                    st.queued -= slot.queue.as_ref().map_or(0, |q| q.len());
                    ready.retain(|s| *s != id);
                }
                Service::Scheduled(u) => u.remove_slot(id, slot.topic),
            }
        }
    }

    /// Queues `msg` for the subscription in `slot`. Never blocks.
    pub fn push(&self, slot: SlotId, msg: Arc<Message>, now: Instant) {
        let mut st = self.lock();
        let st = &mut *st;
        let Some(s) = st.slots.get_mut(&slot) else {
            return;
        };
        let (dropped, wake) = match &mut st.service {
            Service::RoundRobin { ready } => {
                let q = s.queue.as_mut().expect("round-robin slots own a queue");
                let before = q.len();
                // Only CDR video is looked into, as by the router (`crate::gop`).
                let video = crate::gop::is_video_type(&msg.topic.schema.type_name)
                    && msg.payload.encoding == fleetlink_proto::Encoding::Cdr;
                let dropped = if video {
                    push_video(s, msg, now)
                } else {
                    q.push(msg, now)
                };
                let q = s.queue.as_mut().expect("round-robin slots own a queue");
                let evicted = q.take_evicted();
                if video && evicted > 0 {
                    // Past the byte bound: what follows the evicted frames is skipped.
                    s.skip = true;
                    s.stats.keyframe_wanted.store(true, Relaxed);
                }
                if evicted > 0 {
                    for _ in 0..evicted {
                        s.stats.record_drop(DropReason::Policy);
                    }
                    self.dropped.fetch_add(evicted, Relaxed);
                }
                let after = q.len();
                st.queued = st.queued + after - before;
                let wake = !s.in_ready && after > 0;
                if wake {
                    s.in_ready = true;
                    ready.push_back(slot);
                }
                (dropped.map(|(_, r)| r), wake)
            }
            Service::Scheduled(u) => u.push(s, msg, now, &mut st.queued),
        };
        if let Some(reason) = dropped {
            s.stats.record_drop(reason);
            self.dropped.fetch_add(1, Relaxed);
        }
        if wake {
            self.notify.notify_one();
        }
    }

    /// The peer acknowledged `messages` whole messages and `bytes` payload bytes: a
    /// scheduled outbox may send more.
    pub fn on_acked(&self, messages: usize, bytes: u64, now: Instant) {
        if self
            .with_uplink(|u| u.on_acked(messages, bytes, now))
            .is_some()
        {
            self.notify.notify_one();
        }
    }

    /// The writer put a frame carrying `bytes` of payload on the link.
    pub fn on_written(&self, bytes: usize) {
        if !self.scheduled {
            return;
        }
        self.with_uplink(|u| u.on_written(bytes));
    }

    /// A message counted against the data budget at `raw` payload bytes went out as
    /// `sent` (compressed): the difference goes back to the budget.
    pub fn on_compressed(&self, raw: usize, sent: usize) {
        self.with_uplink(|u| u.on_compressed(raw, sent));
    }

    /// Sets (or lifts) the robot's data budget (see [`fleetlink_qos::budget`]).
    pub fn set_data_budget(&self, budget: Option<fleetlink_qos::BudgetConfig>, now: Instant) {
        self.with_uplink(|u| u.set_data_budget(budget, now));
        self.notify.notify_one();
    }

    /// The data budget's figures for the hub, if a budget is set: the bytes per second it
    /// allows, the bytes it counted, and the topics (link aliases) it thinned lately.
    pub fn budget_figures(&self, now: Instant) -> Option<BudgetFigures> {
        self.with_uplink(|u| u.budget_figures(now)).flatten()
    }

    /// Gives `topic` its owner's per-topic configuration anew (it changed while the topic
    /// flows: [`fleetlink_qos::Scheduler::set_qos`]). A topic that has not flowed yet gets
    /// it when it does; a plain outbox has no per-topic configuration.
    pub fn requalify(
        &self,
        topic: &TopicMeta,
        now: Instant,
    ) -> Result<(), fleetlink_qos::QosError> {
        let requalified = self
            .with_uplink(|u| u.requalify(topic, now, &self.dropped))
            .transpose()?;
        if requalified == Some(true) {
            // The demand may have changed (a topic that flows always now).
            self.interest.notify_waiters();
            self.notify.notify_one();
        }
        Ok(())
    }

    /// Whether `topic` (a router topic id) flows as a no-drop topic; `None` before it
    /// first flowed, and for a plain outbox.
    pub fn known_no_drop(&self, topic: u32) -> Option<bool> {
        self.with_uplink(|u| u.known_no_drop(topic)).flatten()
    }

    /// The QoS a scheduled outbox gives `topic` (its owner's per-topic configuration);
    /// `None` for a plain outbox.
    pub fn topic_qos(&self, topic: &TopicMeta) -> Option<TopicQos> {
        let qos_for = self.with_uplink(|u| u.qos_for.clone())?;
        Some(qos_for(topic))
    }

    /// Whether this outbox schedules its link (the agent's uplink) rather than serving
    /// queues in turn (the hub's links).
    pub fn is_scheduled(&self) -> bool {
        self.scheduled
    }

    /// Whether a bulk frame may be written now; if not, when it may (`None`: once an
    /// acknowledgement arrives, which wakes the writer). Always yes for a plain outbox.
    pub fn bulk_check(&self, now: Instant) -> Result<(), Option<Instant>> {
        if !self.scheduled {
            return Ok(());
        }
        self.with_uplink(|u| u.bulk_check(now)).unwrap_or(Ok(()))
    }

    /// The size to cut large payloads into for this link now: `None` for a plain outbox,
    /// whose links use each message's cached frames; a size that follows the measured rate
    /// for a scheduled one (see [`crate::link_control`]).
    pub fn chunk_size(&self) -> Option<usize> {
        if !self.scheduled {
            return None;
        }
        self.with_uplink(|u| u.chunk_size())
    }

    /// Holds back (or releases) topic `alias` in the scheduler while one of its large
    /// messages is going out in chunks (see `Scheduler::set_held`).
    pub fn hold(&self, alias: u32, held: bool, now: Instant) {
        if self.with_uplink(|u| u.hold(alias, held, now)).is_some() && !held {
            self.notify.notify_one();
        }
    }

    /// A new connection: nothing is in flight any more. No-drop messages the old
    /// connection carried but the peer never confirmed go first again, in their order.
    pub fn on_link_reset(&self) {
        let mut st = self.lock();
        let st = &mut *st;
        if let Service::Scheduled(u) = &mut st.service {
            u.on_link_reset(&st.slots, &mut st.queued);
        }
    }

    /// The peer confirmed every no-drop message of link alias `alias` up to `seq`.
    pub fn on_delivered(&self, alias: u32, seq: u64) {
        self.with_uplink(|u| u.on_delivered(alias, seq));
    }

    /// The agent is stopping: the durable outbox, if any, writes and syncs what it holds
    /// and lets go of its file.
    pub fn close_journal(&self) {
        self.with_uplink(|u| u.close_journal());
    }

    /// Periodic housekeeping of the durable outbox, if any (about once a second).
    pub fn tick_journal(&self) {
        self.with_uplink(|u| u.tick_journal());
    }

    /// `ADVERTISE` flags for topic `alias` on this outbox's link.
    pub fn advertise_flags(&self, alias: u32) -> u8 {
        self.with_uplink(|u| u.advertise_flags(alias)).unwrap_or(0)
    }

    /// Whether the peer takes compressed messages (`WELCOME_COMPRESSION`): until it says
    /// so, nothing is compressed.
    pub fn set_compression_allowed(&self, allowed: bool) {
        self.with_uplink(|u| u.set_compression_allowed(allowed));
    }

    /// How the topic with link alias `alias` is compressed on this link, if it is.
    pub fn compression(&self, alias: u32) -> Option<fleetlink_qos::Compression> {
        self.with_uplink(|u| u.compression(alias)).flatten()
    }

    /// Messages of the topic with link alias `alias` waiting to be taken.
    pub fn queued_for(&self, alias: u32) -> usize {
        let st = self.lock();
        match &st.service {
            Service::Scheduled(u) => u.queued(alias),
            Service::RoundRobin { .. } => st
                .slots
                .values()
                .filter(|s| s.topic == alias)
                .map(|s| s.queue.as_ref().map_or(0, |q| q.len()))
                .sum(),
        }
    }

    /// The numbering epoch of this outbox's no-drop streams (0 for a plain outbox).
    pub fn outbox_epoch(&self) -> u64 {
        self.with_uplink(|u| u.epoch()).unwrap_or(0)
    }

    /// Queues a no-drop message read back from the durable outbox after a restart (already
    /// numbered and journaled). Its topic must have a slot here (advertised locally) and
    /// be a no-drop topic; returns false otherwise.
    pub fn restore(&self, msg: Arc<Message>, now: Instant) -> bool {
        let mut st = self.lock();
        let st = &mut *st;
        let Service::Scheduled(u) = &mut st.service else {
            return false;
        };
        let queued = u.restore(msg, now, &mut st.queued);
        if queued {
            self.notify.notify_one();
        }
        queued
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
            .filter_map(|s| s.queue.as_ref().and_then(|q| q.oldest()))
            .map(|at| now.saturating_duration_since(at))
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
