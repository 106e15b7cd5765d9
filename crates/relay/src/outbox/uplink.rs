//! The agent uplink's scheduler side of an outbox: the state and logic a scheduled outbox
//! has and a plain one does not. It owns the Robofleet scheduler (which holds the queued
//! messages and picks what goes next), the link's pacing (`LinkControl`), the no-drop
//! journal (`ReliableOut`), what the hub wants of the uplink (`Demand`: wanted topics,
//! pull, each topic's latest message, age limits, compression), the per-topic QoS
//! function, and the uplink's topic table (`by_topic`, `known`). The hub's plain outboxes
//! have none of it: their slots hold their own queues, served in turn by `Outbox`.
//!
//! `Outbox` keeps the lock, the slots, the queued count, the counters and the writer's
//! wake-up; its calls hand the uplink what it needs of them, so nothing here points back
//! at the outbox.

use std::collections::{HashMap, HashSet, VecDeque};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::{Duration, Instant};

use tokio::sync::Notify;

use fleetlink_qos::budget::wire_cost;
use fleetlink_qos::{
    LinkConfig, LinkEstimator, Nanos, Push, Scheduler, SchedulerConfig, TopicId as QosTopic,
    TopicQos,
};

use super::demand::Demand;
use super::{Delivery, IdHash, LATEST_DEFAULT_LIMIT, QosFor, Slot, SlotId, Taken};
use crate::link_control::{Hold, LinkControl};
use crate::message::{Message, TopicMeta};
use crate::queue::DropReason;
use crate::reliable::ReliableOut;

/// The agent uplink: the Robofleet scheduler picks what goes next (no-drop first, then
/// priority × time waited), paused while too many messages are unacknowledged.
pub(super) struct Uplink {
    pub(super) sched: Scheduler<Arc<Message>>,
    pub(super) origin: Instant,
    pub(super) qos_for: QosFor,
    by_topic: HashMap<u32, SlotId, IdHash>,
    known: HashSet<u32>,
    pub(super) link: LinkControl,
    /// No-drop topics (the scheduler's no-drop lanes): numbered, kept until confirmed,
    /// resent after a reconnect.
    reliable: ReliableOut,
    /// When a no-drop refusal was last logged (they are counted always, logged at
    /// most once per [`REFUSAL_LOG_INTERVAL`]).
    refusal_logged: Option<Instant>,
    /// What the hub wants, and each topic's latest message.
    pub(super) demand: Demand,
    /// Messages of pull topics asked for, waiting for the writer.
    pub(super) pulled: VecDeque<Arc<Message>>,
}

/// Pull requests waiting for the writer at most (more are dropped: the peer asks again).
const MAX_PULLED: usize = 64;

const REFUSAL_LOG_INTERVAL: Duration = Duration::from_secs(5);

/// Logs that a no-drop message was refused, at most once per interval (every refusal is
/// counted in the topic's drop statistics regardless).
fn log_refusal(last: &mut Option<Instant>, now: Instant, topic: &crate::TopicName, why: &str) {
    if last.is_some_and(|at| now.saturating_duration_since(at) < REFUSAL_LOG_INTERVAL) {
        return;
    }
    *last = Some(now);
    tracing::error!("no_drop topic {topic}: message refused: {why}");
}

/// How long after it last lost a message to the data budget a topic counts as thinned.
const THINNED_RECENT: Duration = Duration::from_secs(2);

/// A data budget's figures ([`Outbox::budget_figures`](super::Outbox::budget_figures)).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BudgetFigures {
    pub max_bytes_per_sec: Option<f64>,
    pub bytes_per_day: Option<f64>,
    /// Bytes counted against the budget since it was set.
    pub used_bytes: u64,
    /// Link aliases of the topics that lost a message to the budget in the last two
    /// seconds.
    pub thinned: Vec<u32>,
}

impl Uplink {
    pub(super) fn new(config: SchedulerConfig, qos_for: QosFor, reliable: ReliableOut) -> Uplink {
        Uplink {
            sched: Scheduler::new(config),
            origin: Instant::now(),
            qos_for,
            by_topic: HashMap::default(),
            known: HashSet::new(),
            link: LinkControl::new(LinkEstimator::new(LinkConfig::default()), Nanos::ZERO),
            reliable,
            refusal_logged: None,
            demand: Demand {
                latest_limit: LATEST_DEFAULT_LIMIT,
                ..Demand::default()
            },
            pulled: VecDeque::new(),
        }
    }

    /// Slot `id` receives `topic`: the topic gets a scheduler lane the first time it
    /// flows, with the QoS `qos_for` gives it (the agent's per-topic configuration wins).
    pub(super) fn add_topic(&mut self, topic: &TopicMeta, id: SlotId) {
        let tid = topic.id.0;
        if self.known.insert(tid) {
            let q = self
                .demand
                .follow_qos(tid, (self.qos_for)(topic), self.reliable.is_durable());
            if let Err(e) = self.sched.add_topic(QosTopic(tid), q) {
                tracing::warn!("topic {}: invalid QoS ({e}); using defaults", topic.name);
                let _ = self.sched.add_topic(QosTopic(tid), TopicQos::default());
            }
        }
        self.by_topic.insert(tid, id);
    }

    /// Slot `id`, which received `topic`, is gone.
    pub(super) fn remove_slot(&mut self, id: SlotId, topic: u32) {
        // The scheduler keeps the topic's lane; whatever is still queued is
        // discarded when taken (see `take`).
        if self.by_topic.get(&topic) == Some(&id) {
            self.by_topic.remove(&topic);
        }
    }

    /// Offers `msg`, published on slot `s`, to the scheduler (or keeps it back while its
    /// topic does not flow); counts it in `queued` when queued. Returns why it was lost, if
    /// it was, and whether to wake the writer.
    pub(super) fn push(
        &mut self,
        s: &Slot,
        msg: Arc<Message>,
        now: Instant,
        queued: &mut usize,
    ) -> (Option<DropReason>, bool) {
        let Uplink {
            sched,
            origin,
            link,
            reliable,
            refusal_logged,
            demand,
            ..
        } = self;
        demand.keep_latest(s.topic, &msg);
        if !demand.flows(s.topic) {
            // Held back: kept as the latest, announced once per connection.
            s.stats.record_held();
            let wake = !demand.announced.contains(&s.topic)
                && demand.unannounced.insert(s.topic, msg).is_none();
            return (None, wake);
        }
        let t = Nanos::since(*origin, now);
        link.offered += msg.wire_len() as u64;
        let mut msg = msg;
        let no_drop = sched.is_no_drop(QosTopic(s.topic));
        if no_drop {
            match reliable.admit(&msg) {
                Ok(m) => msg = m,
                Err(e) => {
                    log_refusal(refusal_logged, now, &msg.topic.name, &e.to_string());
                    return (Some(DropReason::Backpressure), false);
                }
            }
        }
        match sched.offer(QosTopic(s.topic), msg, t) {
            Push::Queued => {
                *queued += 1;
                if no_drop && !sched.no_drop_room(QosTopic(s.topic)) {
                    s.stats.no_drop_flow.set_full();
                }
                (None, true)
            }
            Push::Dropped { reason, .. } => (Some(DropReason::from_qos(reason)), true),
            Push::Backpressure(m) => {
                if no_drop {
                    let why = "its no_drop queue is full (the publisher outpaces the \
                               link); raise its `queue` or set `outbox.dir` so \
                               waiting messages spill to disk";
                    log_refusal(refusal_logged, now, &m.topic.name, why);
                }
                (Some(DropReason::Backpressure), false)
            }
        }
    }

    /// Takes up to `max_items` (counting what `items` already holds) / about `max_bytes`
    /// of messages in the scheduler's order, pulled messages first, appending them to
    /// `items`; what is no longer wanted, unsubscribed or too old is dropped on the way
    /// (counted in `dropped`). `slots` and `queued` are the outbox's. Returns when to look
    /// again if nothing could be taken.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn take_into(
        &mut self,
        items: &mut Vec<Taken>,
        max_items: usize,
        max_bytes: usize,
        now: Instant,
        slots: &HashMap<SlotId, Slot, IdHash>,
        queued: &mut usize,
        dropped: &AtomicU64,
    ) -> Option<Instant> {
        let Uplink {
            sched,
            origin,
            by_topic,
            reliable,
            demand,
            pulled,
            ..
        } = self;
        let mut bytes = 0usize;
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
            *queued = queued.saturating_sub(1);
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
                    && let Some(s) = slots.get(&slot)
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
                if let Some(s) = slots.get(slot) {
                    s.stats.record_drop(DropReason::TooOld);
                }
                dropped.fetch_add(1, Relaxed);
                continue;
            }
            let delivery = slots.get(slot).map(|s| s.delivery).unwrap_or_default();
            bytes += m.wire_len();
            items.push((*slot, delivery, m));
        }
        if items.is_empty()
            && let Some(at) = sched.poll_timeout(t)
        {
            return Some(*origin + std::time::Duration::from_nanos(at.0));
        }
        None
    }

    /// The peer acknowledged `messages` whole messages and `bytes` payload bytes.
    pub(super) fn on_acked(&mut self, messages: usize, bytes: u64, now: Instant) {
        let t = Nanos::since(self.origin, now);
        self.sched.on_acked(messages, t);
        self.link.on_acked_bytes(bytes, t);
    }

    /// The writer put a frame carrying `bytes` of payload on the link.
    pub(super) fn on_written(&mut self, bytes: usize) {
        let t = Nanos::since(self.origin, Instant::now());
        self.link.on_written(bytes, t);
    }

    /// A message counted against the data budget at `raw` payload bytes went out as
    /// `sent` (compressed): the difference goes back to the budget.
    pub(super) fn on_compressed(&mut self, raw: usize, sent: usize) {
        self.sched
            .credit_data(wire_cost(raw).saturating_sub(wire_cost(sent)));
    }

    /// Sets (or lifts) the robot's data budget (see [`fleetlink_qos::budget`]).
    pub(super) fn set_data_budget(
        &mut self,
        budget: Option<fleetlink_qos::BudgetConfig>,
        now: Instant,
    ) {
        let t = Nanos::since(self.origin, now);
        self.sched
            .set_data_budget(budget.map(|b| fleetlink_qos::DataBudget::new(b, t)));
    }

    /// The data budget's figures for the hub, if a budget is set: the bytes per second it
    /// allows, the bytes it counted, and the topics (link aliases) it thinned lately.
    pub(super) fn budget_figures(&self, now: Instant) -> Option<BudgetFigures> {
        let b = self.sched.data_budget()?;
        let since = Nanos::since(self.origin, now).saturating_sub(THINNED_RECENT.into());
        Some(BudgetFigures {
            max_bytes_per_sec: b.config().max_bytes_per_sec,
            bytes_per_day: b.config().bytes_per_day,
            used_bytes: b.used(),
            thinned: self.sched.thinned_since(since).map(|t| t.0).collect(),
        })
    }

    /// Gives `topic` its owner's per-topic configuration anew (it changed while the topic
    /// flows: [`Scheduler::set_qos`]); what the scheduler drops for it is counted in
    /// `dropped`. Returns whether the topic had flowed (a topic that has not flowed yet
    /// gets its configuration when it does).
    pub(super) fn requalify(
        &mut self,
        topic: &TopicMeta,
        now: Instant,
        dropped: &AtomicU64,
    ) -> Result<bool, fleetlink_qos::QosError> {
        let tid = topic.id.0;
        if !self.known.contains(&tid) {
            return Ok(false);
        }
        let q = (self.qos_for)(topic);
        if self.sched.is_no_drop(QosTopic(tid)) != q.no_drop {
            return Err(fleetlink_qos::QosError::NoDropChange(QosTopic(tid)));
        }
        let q = self.demand.follow_qos(tid, q, self.reliable.is_durable());
        let lost = self
            .sched
            .set_qos(QosTopic(tid), q, Nanos::since(self.origin, now))?;
        dropped.fetch_add(lost.len() as u64, Relaxed);
        Ok(true)
    }

    /// Whether `topic` (a router topic id) flows as a no-drop topic; `None` before it
    /// first flowed.
    pub(super) fn known_no_drop(&self, topic: u32) -> Option<bool> {
        if self.known.contains(&topic) {
            Some(self.sched.is_no_drop(QosTopic(topic)))
        } else {
            None
        }
    }

    /// Whether a bulk frame may be written now; if not, when it may (`None`: once an
    /// acknowledgement arrives, which wakes the writer).
    pub(super) fn bulk_check(&mut self, now: Instant) -> Result<(), Option<Instant>> {
        let origin = self.origin;
        let t = Nanos::since(origin, now);
        self.link.bulk_check(t).map_err(|hold| match hold {
            Hold::Window | Hold::Share(None) => None,
            Hold::Share(Some(at)) => Some(origin + Duration::from_nanos(at.0)),
        })
    }

    /// The size to cut large payloads into for this link now: one that follows the
    /// measured rate (see [`crate::link_control`]).
    pub(super) fn chunk_size(&self) -> usize {
        self.link
            .chunk_size(Nanos::since(self.origin, Instant::now()))
    }

    /// Holds back (or releases) topic `alias` in the scheduler while one of its large
    /// messages is going out in chunks (see `Scheduler::set_held`).
    pub(super) fn hold(&mut self, alias: u32, held: bool, now: Instant) {
        let t = Nanos::since(self.origin, now);
        self.sched.set_held(QosTopic(alias), held, t);
    }

    /// A new connection: nothing is in flight any more. No-drop messages the old
    /// connection carried but the peer never confirmed go first again, in their order
    /// (counted in the outbox's `queued`; the `slots` whose queue they fill are told).
    pub(super) fn on_link_reset(
        &mut self,
        slots: &HashMap<SlotId, Slot, IdHash>,
        queued: &mut usize,
    ) {
        let Uplink {
            sched,
            link,
            reliable,
            demand,
            origin,
            ..
        } = self;
        sched.on_link_reset();
        // A topic held for a large message the old connection was sending in chunks
        // would stay held for good: its lane died with that connection's writer.
        sched.release_all_held(Nanos::since(*origin, Instant::now()));
        link.reset();
        // A new connection has announced nothing yet.
        demand.announced.clear();
        demand.unannounced = demand.latest.iter().map(|(t, m)| (*t, m.clone())).collect();
        let again = reliable.take_unconfirmed();
        let mut topics = HashSet::new();
        for (alias, m) in again.into_iter().rev() {
            if sched.requeue_no_drop(QosTopic(alias), m).is_ok() {
                *queued += 1;
                topics.insert(alias);
            }
        }
        // Requeued messages may fill a queue: its publishers wait for room again.
        for s in slots.values() {
            if topics.contains(&s.topic) && !sched.no_drop_room(QosTopic(s.topic)) {
                s.stats.no_drop_flow.set_full();
            }
        }
    }

    /// The peer confirmed every no-drop message of link alias `alias` up to `seq`.
    pub(super) fn on_delivered(&mut self, alias: u32, seq: u64) {
        self.reliable.confirm(alias, seq);
    }

    /// The agent is stopping: the durable outbox, if any, writes and syncs what it holds
    /// and lets go of its file.
    pub(super) fn close_journal(&mut self) {
        self.reliable.close_journal();
    }

    /// Periodic housekeeping of the durable outbox, if any (about once a second).
    pub(super) fn tick_journal(&mut self) {
        self.reliable.tick();
    }

    /// `ADVERTISE` flags for topic `alias` on this link.
    pub(super) fn advertise_flags(&self, alias: u32) -> u8 {
        use fleetlink_proto::frame::{ADVERTISE_PULL, ADVERTISE_RELIABLE};
        if self.sched.is_no_drop(QosTopic(alias)) {
            ADVERTISE_RELIABLE
        } else if self.demand.pull.contains(&alias) {
            ADVERTISE_PULL
        } else {
            0
        }
    }

    /// Whether the peer takes compressed messages (`WELCOME_COMPRESSION`): until it says
    /// so, nothing is compressed.
    pub(super) fn set_compression_allowed(&mut self, allowed: bool) {
        self.demand.compress_allowed = allowed;
    }

    /// How the topic with link alias `alias` is compressed on this link, if it is.
    pub(super) fn compression(&self, alias: u32) -> Option<fleetlink_qos::Compression> {
        if self.demand.compress_allowed {
            self.demand.compression.get(&alias).copied()
        } else {
            None
        }
    }

    /// Messages of the topic with link alias `alias` waiting to be taken.
    pub(super) fn queued(&self, alias: u32) -> usize {
        self.sched.queued(QosTopic(alias))
    }

    /// The numbering epoch of this uplink's no-drop streams.
    pub(super) fn epoch(&self) -> u64 {
        self.reliable.epoch()
    }

    /// Queues a no-drop message read back from the durable outbox after a restart (already
    /// numbered and journaled), counting it in `queued`. Its topic must be a no-drop
    /// topic; returns false otherwise, or if the scheduler did not queue it.
    pub(super) fn restore(&mut self, msg: Arc<Message>, now: Instant, queued: &mut usize) -> bool {
        let tid = msg.topic.id.0;
        if !self.sched.is_no_drop(QosTopic(tid)) {
            return false;
        }
        self.reliable.restored(&msg.topic.name, msg.seq);
        let t = Nanos::since(self.origin, now);
        let taken = matches!(self.sched.offer(QosTopic(tid), msg, t), Push::Queued);
        if taken {
            *queued += 1;
        }
        taken
    }

    /// The peer wants the topic with link alias `alias` (or no longer does). When it
    /// starts to, the topic's latest message goes out at once unless one is queued
    /// (counted in `queued`). `interest` is woken when the demand changes, `notify` (the
    /// writer) when the latest message was queued.
    pub(super) fn set_wanted(
        &mut self,
        alias: u32,
        wanted: bool,
        now: Instant,
        queued: &mut usize,
        interest: &Notify,
        notify: &Notify,
    ) {
        let Uplink {
            sched,
            origin,
            link,
            demand,
            ..
        } = self;
        if !wanted {
            if demand.wanted.remove(&alias) {
                interest.notify_waiters();
            }
            return;
        }
        if !demand.wanted.insert(alias) {
            return;
        }
        interest.notify_waiters();
        if demand.always.contains(&alias) {
            return;
        }
        demand.unannounced.remove(&alias);
        let Some(latest) = demand.latest.get(&alias).cloned() else {
            return;
        };
        if sched.queued(QosTopic(alias)) > 0 || demand.too_old(alias, &latest, now) {
            return;
        }
        link.offered += latest.wire_len() as u64;
        let t = Nanos::since(*origin, now);
        if let Push::Queued = sched.offer(QosTopic(alias), latest, t) {
            *queued += 1;
            notify.notify_one();
        }
    }

    /// The peer asks for one message of the pull topic with link alias `alias`: its latest
    /// is put aside for the writer (unless it has none, or none within its age limit).
    /// Returns whether it was, so the writer is to be woken.
    pub(super) fn pull(&mut self, alias: u32, now: Instant) -> bool {
        let Uplink { demand, pulled, .. } = self;
        if !demand.pull.contains(&alias) {
            return false;
        }
        let Some(latest) = demand.latest.get(&alias).cloned() else {
            return false;
        };
        if demand.too_old(alias, &latest, now) {
            return false;
        }
        // Queued beside the scheduler (a request is rare and small in number): the writer
        // takes it with the next batch.
        if pulled.len() < MAX_PULLED {
            pulled.push_back(latest);
            return true;
        }
        false
    }
}
