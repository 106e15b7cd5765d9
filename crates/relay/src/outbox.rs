//! One client's outbound side.
//!
//! Each of the client's subscriptions has a slot holding its bounded queue. Publishers
//! push into slots from their own tasks (never blocking, never waiting on this client);
//! the one task that writes the client's socket takes batches round-robin across the
//! slots that have something ready, so a busy topic cannot starve a quiet one.
//!
//! The state is behind a `std::sync::Mutex`: every critical section is a few pointer
//! moves, never an `.await`, and an async mutex would cost more than it saves.

use std::collections::{HashMap, HashSet, VecDeque};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use fleetlink_proto::rosbridge::Compression;
use tokio::sync::Notify;

use fleetlink_qos::budget::wire_cost;
use fleetlink_qos::{
    LinkConfig, LinkEstimator, Nanos, Push, Scheduler, SchedulerConfig, TopicId as QosTopic,
    TopicQos,
};

use crate::link_control::{Hold, LinkControl};
use crate::message::{Message, TopicMeta};
use crate::names::ClientId;
use crate::queue::{DropReason, OutboundQueue, QosQueue};
use crate::reliable::ReliableOut;
use crate::stats::TopicStats;

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
}

/// How the writer is served.
enum Service {
    /// Hub subscribers: every slot has its own queue, served round-robin so a busy topic
    /// cannot starve a quiet one.
    RoundRobin { ready: VecDeque<SlotId> },
    /// The agent uplink: the Robofleet scheduler picks what goes next (no-drop first, then
    /// priority × time waited), paused while too many messages are unacknowledged.
    Scheduled {
        sched: Box<Scheduler<Arc<Message>>>,
        origin: Instant,
        qos_for: QosFor,
        by_topic: HashMap<u32, SlotId, IdHash>,
        known: HashSet<u32>,
        link: Box<LinkControl>,
        /// No-drop topics (the scheduler's no-drop lanes): numbered, kept until confirmed,
        /// resent after a reconnect.
        reliable: Box<ReliableOut>,
        /// When a no-drop refusal was last logged (they are counted always, logged at
        /// most once per [`REFUSAL_LOG_INTERVAL`]).
        refusal_logged: Option<Instant>,
        /// What the hub wants, and each topic's latest message.
        demand: Box<Demand>,
        /// Messages of pull topics asked for, waiting for the writer.
        pulled: VecDeque<Arc<Message>>,
    },
}

/// Whether an uplink has something to measure its link with: data waiting (queued, or
/// pulled for the peer) or sent and not yet acknowledged.
fn link_busy(
    sched: &Scheduler<Arc<Message>>,
    link: &LinkControl,
    pulled: &VecDeque<Arc<Message>>,
) -> bool {
    sched.has_queued() || link.unacked_bytes() > 0 || !pulled.is_empty()
}

/// Pull requests waiting for the writer at most (more are dropped: the peer asks again).
const MAX_PULLED: usize = 64;

/// Most payload bytes of all topics' latest messages kept, unless the owner sets another
/// bound ([`Outbox::set_latest_limit`]).
pub const LATEST_DEFAULT_LIMIT: usize = 64 << 20;

/// A demand-driven uplink (issue 37): while the hub says nobody wants a topic, its
/// messages are not sent; the latest one is kept and goes out at once when interest
/// comes, so a viewer does not wait for the next publish. Until the hub says it speaks
/// interest (`WELCOME_INTEREST`), everything flows.
#[derive(Default)]
struct Demand {
    driven: bool,
    /// Topics the hub wants.
    wanted: HashSet<u32, IdHash>,
    /// Topics that flow whatever the demand: `always: true` and no-drop.
    always: HashSet<u32, IdHash>,
    /// Each topic's latest message, all of them within `latest_limit` payload bytes
    /// (`latest_bytes` now): a topic whose newest message does not fit has none kept.
    latest: HashMap<u32, Arc<Message>, IdHash>,
    latest_bytes: usize,
    latest_limit: usize,
    /// Held-back topics the writer has yet to announce on this connection (an idle topic
    /// still appears at the hub, which cannot want what it has not heard of), with a
    /// message of theirs to announce them by; and those already handed to it.
    unannounced: HashMap<u32, Arc<Message>, IdHash>,
    announced: HashSet<u32, IdHash>,
    /// Topics with an age limit (`max_age`): older messages are not sent.
    max_age: HashMap<u32, Duration, IdHash>,
    /// Pull topics: sent only when asked ([`Outbox::pull`]).
    pull: HashSet<u32, IdHash>,
    /// How each topic is compressed on the link (`compression: none` topics are absent),
    /// and whether the peer takes compressed messages at all (`WELCOME_COMPRESSION`).
    compression: HashMap<u32, fleetlink_qos::Compression, IdHash>,
    compress_allowed: bool,
}

impl Demand {
    /// Notes what `topic`'s QoS `q` asks of the demand (flows always, an age limit, pull,
    /// compression), replacing what an earlier QoS asked; returns `q` as the scheduler
    /// takes it.
    fn follow_qos(&mut self, topic: u32, mut q: TopicQos, durable: bool) -> TopicQos {
        self.always.remove(&topic);
        self.max_age.remove(&topic);
        self.pull.remove(&topic);
        self.compression.remove(&topic);
        if q.always || q.no_drop {
            self.always.insert(topic);
        }
        if let Some(ms) = q.max_age_ms.filter(|_| !q.no_drop) {
            self.max_age.insert(topic, Duration::from_millis(ms));
        }
        if q.mode == fleetlink_qos::Mode::Pull && !q.no_drop {
            self.pull.insert(topic);
        }
        if q.compression != fleetlink_qos::Compression::None {
            self.compression.insert(topic, q.compression);
        }
        if q.no_drop && durable {
            // Waiting messages are on disk too: the journal's byte bound limits them,
            // not a count.
            q.queue = usize::MAX;
        }
        q
    }

    /// Keeps `msg` as its topic's latest, if it fits the bound with the others.
    fn keep_latest(&mut self, topic: u32, msg: &Arc<Message>) {
        if let Some(old) = self.latest.remove(&topic) {
            self.latest_bytes -= old.payload.len();
        }
        let size = msg.payload.len();
        if self.latest_bytes + size <= self.latest_limit {
            self.latest_bytes += size;
            self.latest.insert(topic, msg.clone());
        }
    }

    fn flows(&self, topic: u32) -> bool {
        if self.pull.contains(&topic) {
            return false;
        }
        !self.driven || self.wanted.contains(&topic) || self.always.contains(&topic)
    }

    /// Whether `msg` of `topic` is past its topic's age limit at `now`.
    fn too_old(&self, topic: u32, msg: &Message, now: Instant) -> bool {
        self.max_age
            .get(&topic)
            .is_some_and(|age| now.saturating_duration_since(msg.received()) > *age)
    }
}

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

/// A data budget's figures ([`Outbox::budget_figures`]).
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

/// A link report for the hub: demand, delivered rate and one-way latency.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LinkFigures {
    pub demand_bps: f64,
    pub rate_bps: f64,
    pub latency: Option<Duration>,
    pub rtt: Option<Duration>,
    /// Hub clock minus robot clock.
    pub clock_offset_ns: Option<i64>,
    pub share_bps: Option<f64>,
    pub in_flight_bytes: usize,
    /// What the robot may send now, bytes/s: the smallest of its capacity share, its data
    /// budget's rate and the link's best measured rate (the rate over the estimator's
    /// window or the best 50 ms of the last half second, whichever is higher, when data
    /// last flowed); `None` until something was measured.
    pub capacity_bps: Option<f64>,
    /// When the link's rate was last measured with data on it (`None`: never). An idle
    /// link is not probed: its capacity figure is the one measured then.
    pub measured_at: Option<Instant>,
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

/// A message taken by the writer: its slot, how to deliver it, the message.
pub type Taken = (SlotId, Delivery, Arc<Message>);

/// A batch taken by the writer.
pub struct Batch {
    pub items: Vec<Taken>,
    /// When throttled slots will next have something (if any are waiting).
    pub wake_at: Option<Instant>,
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
            Service::Scheduled {
                sched: Box::new(Scheduler::new(config)),
                origin: Instant::now(),
                qos_for,
                by_topic: HashMap::default(),
                known: HashSet::new(),
                link: Box::new(LinkControl::new(
                    LinkEstimator::new(LinkConfig::default()),
                    Nanos::ZERO,
                )),
                reliable: Box::new(reliable),
                refusal_logged: None,
                demand: Box::new(Demand {
                    latest_limit: LATEST_DEFAULT_LIMIT,
                    ..Demand::default()
                }),
                pulled: VecDeque::new(),
            },
        )
    }

    fn with_service(client: ClientId, service: Service) -> Arc<Outbox> {
        let scheduled = matches!(service, Service::Scheduled { .. });
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
            Service::Scheduled {
                sched,
                qos_for,
                by_topic,
                known,
                reliable,
                demand,
                ..
            } => {
                if known.insert(tid) {
                    let q = demand.follow_qos(tid, qos_for(topic), reliable.is_durable());
                    if let Err(e) = sched.add_topic(QosTopic(tid), q) {
                        tracing::warn!("topic {}: invalid QoS ({e}); using defaults", topic.name);
                        let _ = sched.add_topic(QosTopic(tid), TopicQos::default());
                    }
                }
                by_topic.insert(tid, id);
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
                Service::Scheduled { by_topic, .. } => {
                    // The scheduler keeps the topic's lane; whatever is still queued is
                    // discarded when taken (see `take`).
                    if by_topic.get(&slot.topic) == Some(&id) {
                        by_topic.remove(&slot.topic);
                    }
                }
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
                let dropped = q.push(msg, now);
                let evicted = q.take_evicted();
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
            Service::Scheduled {
                sched,
                origin,
                link,
                reliable,
                refusal_logged,
                demand,
                ..
            } => {
                demand.keep_latest(s.topic, &msg);
                if !demand.flows(s.topic) {
                    // Held back: kept as the latest, announced once per connection.
                    s.stats.record_held();
                    if !demand.announced.contains(&s.topic)
                        && demand.unannounced.insert(s.topic, msg).is_none()
                    {
                        self.notify.notify_one();
                    }
                    return;
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
                            s.stats.record_drop(DropReason::Backpressure);
                            self.dropped.fetch_add(1, Relaxed);
                            return;
                        }
                    }
                }
                match sched.offer(QosTopic(s.topic), msg, t) {
                    Push::Queued => {
                        st.queued += 1;
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
        let mut st = self.lock();
        if let Service::Scheduled {
            sched,
            origin,
            link,
            ..
        } = &mut st.service
        {
            let t = Nanos::since(*origin, now);
            sched.on_acked(messages, t);
            link.on_acked_bytes(bytes, t);
            drop(st);
            self.notify.notify_one();
        }
    }

    /// The writer put a frame carrying `bytes` of payload on the link.
    pub fn on_written(&self, bytes: usize) {
        if !self.scheduled {
            return;
        }
        if let Service::Scheduled { origin, link, .. } = &mut self.lock().service {
            let t = Nanos::since(*origin, Instant::now());
            link.on_written(bytes, t);
        }
    }

    /// A message counted against the data budget at `raw` payload bytes went out as
    /// `sent` (compressed): the difference goes back to the budget.
    pub fn on_compressed(&self, raw: usize, sent: usize) {
        if let Service::Scheduled { sched, .. } = &mut self.lock().service {
            sched.credit_data(wire_cost(raw).saturating_sub(wire_cost(sent)));
        }
    }

    /// Sets (or lifts) the robot's data budget (see [`fleetlink_qos::budget`]).
    pub fn set_data_budget(&self, budget: Option<fleetlink_qos::BudgetConfig>, now: Instant) {
        if let Service::Scheduled { origin, sched, .. } = &mut self.lock().service {
            let t = Nanos::since(*origin, now);
            sched.set_data_budget(budget.map(|b| fleetlink_qos::DataBudget::new(b, t)));
        }
        self.notify.notify_one();
    }

    /// The data budget's figures for the hub, if a budget is set: the bytes per second it
    /// allows, the bytes it counted, and the topics (link aliases) it thinned lately.
    pub fn budget_figures(&self, now: Instant) -> Option<BudgetFigures> {
        let st = self.lock();
        let Service::Scheduled { origin, sched, .. } = &st.service else {
            return None;
        };
        let b = sched.data_budget()?;
        let since = Nanos::since(*origin, now).saturating_sub(THINNED_RECENT.into());
        Some(BudgetFigures {
            max_bytes_per_sec: b.config().max_bytes_per_sec,
            bytes_per_day: b.config().bytes_per_day,
            used_bytes: b.used(),
            thinned: sched.thinned_since(since).map(|t| t.0).collect(),
        })
    }

    /// Gives `topic` its owner's per-topic configuration anew (it changed while the topic
    /// flows: [`Scheduler::set_qos`]). A topic that has not flowed yet gets it when it
    /// does; a plain outbox has no per-topic configuration.
    pub fn requalify(
        &self,
        topic: &TopicMeta,
        now: Instant,
    ) -> Result<(), fleetlink_qos::QosError> {
        let mut st = self.lock();
        let Service::Scheduled {
            sched,
            origin,
            qos_for,
            known,
            reliable,
            demand,
            ..
        } = &mut st.service
        else {
            return Ok(());
        };
        let tid = topic.id.0;
        if !known.contains(&tid) {
            return Ok(());
        }
        let q = qos_for(topic);
        if sched.is_no_drop(QosTopic(tid)) != q.no_drop {
            return Err(fleetlink_qos::QosError::NoDropChange(QosTopic(tid)));
        }
        let q = demand.follow_qos(tid, q, reliable.is_durable());
        let dropped = sched.set_qos(QosTopic(tid), q, Nanos::since(*origin, now))?;
        self.dropped.fetch_add(dropped.len() as u64, Relaxed);
        drop(st);
        // The demand may have changed (a topic that flows always now).
        self.interest.notify_waiters();
        self.notify.notify_one();
        Ok(())
    }

    /// Whether `topic` (a router topic id) flows as a no-drop topic; `None` before it
    /// first flowed, and for a plain outbox.
    pub fn known_no_drop(&self, topic: u32) -> Option<bool> {
        match &self.lock().service {
            Service::Scheduled { sched, known, .. } if known.contains(&topic) => {
                Some(sched.is_no_drop(QosTopic(topic)))
            }
            _ => None,
        }
    }

    /// The QoS a scheduled outbox gives `topic` (its owner's per-topic configuration);
    /// `None` for a plain outbox.
    pub fn topic_qos(&self, topic: &TopicMeta) -> Option<TopicQos> {
        let qos_for = match &self.lock().service {
            Service::Scheduled { qos_for, .. } => qos_for.clone(),
            Service::RoundRobin { .. } => return None,
        };
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
        match &mut self.lock().service {
            Service::Scheduled { origin, link, .. } => {
                let t = Nanos::since(*origin, now);
                link.bulk_check(t).map_err(|hold| match hold {
                    Hold::Window | Hold::Share(None) => None,
                    Hold::Share(Some(at)) => Some(*origin + Duration::from_nanos(at.0)),
                })
            }
            Service::RoundRobin { .. } => Ok(()),
        }
    }

    /// The size to cut large payloads into for this link now: `None` for a plain outbox,
    /// whose links use each message's cached frames; a size that follows the measured rate
    /// for a scheduled one (see [`crate::link_control`]).
    pub fn chunk_size(&self) -> Option<usize> {
        if !self.scheduled {
            return None;
        }
        match &self.lock().service {
            Service::Scheduled { origin, link, .. } => {
                Some(link.chunk_size(Nanos::since(*origin, Instant::now())))
            }
            Service::RoundRobin { .. } => None,
        }
    }

    /// Holds back (or releases) topic `alias` in the scheduler while one of its large
    /// messages is going out in chunks (see `Scheduler::set_held`).
    pub fn hold(&self, alias: u32, held: bool, now: Instant) {
        let mut st = self.lock();
        if let Service::Scheduled { sched, origin, .. } = &mut st.service {
            let t = Nanos::since(*origin, now);
            sched.set_held(QosTopic(alias), held, t);
            if !held {
                drop(st);
                self.notify.notify_one();
            }
        }
    }

    /// A new connection: nothing is in flight any more. No-drop messages the old
    /// connection carried but the peer never confirmed go first again, in their order.
    pub fn on_link_reset(&self) {
        let mut st = self.lock();
        let st = &mut *st;
        if let Service::Scheduled {
            sched,
            link,
            reliable,
            demand,
            origin,
            ..
        } = &mut st.service
        {
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
                    st.queued += 1;
                    topics.insert(alias);
                }
            }
            // Requeued messages may fill a queue: its publishers wait for room again.
            for s in st.slots.values() {
                if topics.contains(&s.topic) && !sched.no_drop_room(QosTopic(s.topic)) {
                    s.stats.no_drop_flow.set_full();
                }
            }
        }
    }

    /// Most payload bytes of topics' latest messages this (scheduled) outbox keeps, all
    /// topics together; 0 keeps none.
    pub fn set_latest_limit(&self, bytes: usize) {
        if let Service::Scheduled { demand, .. } = &mut self.lock().service {
            demand.latest_limit = bytes;
            if demand.latest_bytes > bytes {
                demand.latest.clear();
                demand.latest_bytes = 0;
            }
        }
    }

    /// Whether the peer tells this (scheduled) outbox which topics it wants: from now on a
    /// topic nobody wants is held back. `false` (an older hub) lets everything flow.
    pub fn set_demand_driven(&self, driven: bool) {
        if let Service::Scheduled { demand, .. } = &mut self.lock().service {
            demand.driven = driven;
        }
        self.notify.notify_one();
        self.interest.notify_waiters();
    }

    /// The peer wants the topic with link alias `alias` (or no longer does). When it
    /// starts to, the topic's latest message goes out at once unless one is queued.
    pub fn set_wanted(&self, alias: u32, wanted: bool, now: Instant) {
        let mut st = self.lock();
        let st = &mut *st;
        let Service::Scheduled {
            sched,
            origin,
            link,
            demand,
            ..
        } = &mut st.service
        else {
            return;
        };
        if !wanted {
            if demand.wanted.remove(&alias) {
                self.interest.notify_waiters();
            }
            return;
        }
        if !demand.wanted.insert(alias) {
            return;
        }
        self.interest.notify_waiters();
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
            st.queued += 1;
            self.notify.notify_one();
        }
    }

    /// The peer asks for one message of the pull topic with link alias `alias`: its latest
    /// goes out (unless it has none, or none within its age limit). Pulled messages are
    /// taken even though the topic does not flow.
    pub fn pull(&self, alias: u32, now: Instant) {
        let mut st = self.lock();
        let st = &mut *st;
        let Service::Scheduled { demand, pulled, .. } = &mut st.service else {
            return;
        };
        if !demand.pull.contains(&alias) {
            return;
        }
        let Some(latest) = demand.latest.get(&alias).cloned() else {
            return;
        };
        if demand.too_old(alias, &latest, now) {
            return;
        }
        // Queued beside the scheduler (a request is rare and small in number): the writer
        // takes it with the next batch.
        if pulled.len() < MAX_PULLED {
            pulled.push_back(latest);
            self.notify.notify_one();
        }
    }

    /// A message of each held-back topic not yet announced on this connection: the writer
    /// announces their topics (`ADVERTISE`) without sending them.
    pub fn take_unannounced(&self, out: &mut Vec<Arc<Message>>) {
        if !self.scheduled {
            return;
        }
        if let Service::Scheduled { demand, .. } = &mut self.lock().service {
            let Demand {
                unannounced,
                announced,
                ..
            } = &mut **demand;
            for (t, m) in unannounced.drain() {
                announced.insert(t);
                out.push(m);
            }
        }
    }

    /// The writer withdrew the topic with link alias `alias` (`UNADVERTISE`): if it is
    /// published again while held back, it is announced again.
    pub fn forget_announced(&self, alias: u32) {
        if let Service::Scheduled { demand, .. } = &mut self.lock().service {
            demand.announced.remove(&alias);
        }
    }

    /// Whether the topic with link alias `alias` needs reading from its source for this
    /// link: it is sent (wanted, `always`, no-drop, or a peer that does not say what it
    /// wants) or a pull topic (its latest message must be at hand).
    pub fn reads(&self, alias: u32) -> bool {
        match &self.lock().service {
            Service::Scheduled { demand, .. } => {
                demand.flows(alias) || demand.pull.contains(&alias)
            }
            Service::RoundRobin { .. } => true,
        }
    }

    /// [`Outbox::reads`] of the topic a slot of this outbox receives (false for a slot it
    /// no longer has).
    pub fn reads_slot(&self, slot: SlotId) -> bool {
        let st = self.lock();
        let Some(topic) = st.slots.get(&slot).map(|s| s.topic) else {
            return false;
        };
        match &st.service {
            Service::Scheduled { demand, .. } => {
                demand.flows(topic) || demand.pull.contains(&topic)
            }
            Service::RoundRobin { .. } => true,
        }
    }

    /// Returns when the peer's demand next changes (a topic wanted or let go, interest
    /// turned on or off).
    pub async fn interest_changed(&self) {
        self.interest.notified().await
    }

    /// Lets go of the latest message kept for topic `alias`.
    pub fn forget_latest(&self, alias: u32) {
        if let Service::Scheduled { demand, .. } = &mut self.lock().service
            && let Some(old) = demand.latest.remove(&alias)
        {
            demand.latest_bytes -= old.payload.len();
        }
    }

    /// Whether the topic with link alias `alias` is held back (nobody wants it).
    pub fn is_held_back(&self, alias: u32) -> bool {
        match &self.lock().service {
            Service::Scheduled { demand, .. } => !demand.flows(alias),
            Service::RoundRobin { .. } => false,
        }
    }

    /// The peer confirmed every no-drop message of link alias `alias` up to `seq`.
    pub fn on_delivered(&self, alias: u32, seq: u64) {
        if let Service::Scheduled { reliable, .. } = &mut self.lock().service {
            reliable.confirm(alias, seq);
        }
    }

    /// The agent is stopping: the durable outbox, if any, writes and syncs what it holds
    /// and lets go of its file.
    pub fn close_journal(&self) {
        if let Service::Scheduled { reliable, .. } = &mut self.lock().service {
            reliable.close_journal();
        }
    }

    /// Periodic housekeeping of the durable outbox, if any (about once a second).
    pub fn tick_journal(&self) {
        if let Service::Scheduled { reliable, .. } = &mut self.lock().service {
            reliable.tick();
        }
    }

    /// `ADVERTISE` flags for topic `alias` on this outbox's link.
    pub fn advertise_flags(&self, alias: u32) -> u8 {
        use fleetlink_proto::frame::{ADVERTISE_PULL, ADVERTISE_RELIABLE};
        match &self.lock().service {
            Service::Scheduled { sched, demand, .. } => {
                if sched.is_no_drop(QosTopic(alias)) {
                    ADVERTISE_RELIABLE
                } else if demand.pull.contains(&alias) {
                    ADVERTISE_PULL
                } else {
                    0
                }
            }
            _ => 0,
        }
    }

    /// Whether the peer takes compressed messages (`WELCOME_COMPRESSION`): until it says
    /// so, nothing is compressed.
    pub fn set_compression_allowed(&self, allowed: bool) {
        if let Service::Scheduled { demand, .. } = &mut self.lock().service {
            demand.compress_allowed = allowed;
        }
    }

    /// How the topic with link alias `alias` is compressed on this link, if it is.
    pub fn compression(&self, alias: u32) -> Option<fleetlink_qos::Compression> {
        match &self.lock().service {
            Service::Scheduled { demand, .. } if demand.compress_allowed => {
                demand.compression.get(&alias).copied()
            }
            _ => None,
        }
    }

    /// Messages of the topic with link alias `alias` waiting to be taken.
    pub fn queued_for(&self, alias: u32) -> usize {
        let st = self.lock();
        match &st.service {
            Service::Scheduled { sched, .. } => sched.queued(QosTopic(alias)),
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
        match &self.lock().service {
            Service::Scheduled { reliable, .. } => reliable.epoch(),
            Service::RoundRobin { .. } => 0,
        }
    }

    /// Queues a no-drop message read back from the durable outbox after a restart (already
    /// numbered and journaled). Its topic must have a slot here (advertised locally) and
    /// be a no-drop topic; returns false otherwise.
    pub fn restore(&self, msg: Arc<Message>, now: Instant) -> bool {
        let mut st = self.lock();
        let st = &mut *st;
        let Service::Scheduled {
            sched,
            origin,
            reliable,
            ..
        } = &mut st.service
        else {
            return false;
        };
        let tid = msg.topic.id.0;
        if !sched.is_no_drop(QosTopic(tid)) {
            return false;
        }
        reliable.restored(&msg.topic.name, msg.seq);
        let t = Nanos::since(*origin, now);
        let queued = matches!(sched.offer(QosTopic(tid), msg, t), Push::Queued);
        if queued {
            st.queued += 1;
            self.notify.notify_one();
        }
        queued
    }

    /// The hub's capacity share for this robot (bytes per second; `None` = no cap): the
    /// scheduler keeps the sending rate within it.
    pub fn set_share(&self, bytes_per_sec: Option<f64>, now: Instant) {
        let mut st = self.lock();
        if let Service::Scheduled { origin, link, .. } = &mut st.service {
            let t = Nanos::since(*origin, now);
            link.set_share(bytes_per_sec, t);
            drop(st);
            self.notify.notify_one();
        }
    }

    /// An echo probe due now, if any (scheduled outboxes only): its id goes out in a PING.
    /// Probes go out while data waits or is unacknowledged (and until the first echo); an
    /// idle link is measured by its heartbeat alone ([`Self::on_heartbeat_echo`]).
    pub fn poll_probe(&self, now: Instant) -> Option<u64> {
        self.with_estimator(|est, origin, busy| {
            est.poll_probe(Nanos::since(origin, now), busy)
                .map(|p| p.id)
        })
        .flatten()
    }

    /// When the writer should look for a probe next ([`Self::poll_probe`]); `None` while
    /// the link is idle (new data wakes the writer through [`Self::ready`]).
    pub fn probe_timeout(&self) -> Option<Instant> {
        self.with_estimator(|est, origin, busy| {
            let at = est.poll_timeout(busy)?;
            Some(origin + Duration::from_nanos(at.0))
        })
        .flatten()
    }

    /// Runs `f` on the uplink's estimator with the outbox's clock origin and whether the
    /// link is busy (data queued, pulled or unacknowledged); `None` for a round-robin
    /// outbox, which has no link.
    fn with_estimator<R>(
        &self,
        f: impl FnOnce(&mut fleetlink_qos::LinkEstimator, Instant, bool) -> R,
    ) -> Option<R> {
        let mut st = self.lock();
        match &mut st.service {
            Service::Scheduled {
                origin,
                link,
                sched,
                pulled,
                ..
            } => {
                let busy = link_busy(sched, link, pulled);
                Some(f(&mut link.est, *origin, busy))
            }
            Service::RoundRobin { .. } => None,
        }
    }

    /// The hub echoed probe `id`, reading `hub_ns` (Unix ns) on its clock.
    pub fn on_echo(&self, id: u64, hub_ns: u64, now: Instant) {
        self.echoed(now, hub_ns, |est, t, hub| est.handle_echo(id, hub, t));
    }

    /// The hub answered a heartbeat `PING` after `rtt`, reading `hub_ns` on its clock: on
    /// an idle link, the sample that keeps the round trip and clock offset current.
    pub fn on_heartbeat_echo(&self, rtt: Duration, hub_ns: u64, now: Instant) {
        let rtt = Nanos(rtt.as_nanos().min(u128::from(u64::MAX)) as u64);
        self.echoed(now, hub_ns, |est, t, hub| {
            est.handle_heartbeat_echo(rtt, hub, t)
        });
    }

    fn echoed(
        &self,
        now: Instant,
        hub_ns: u64,
        f: impl FnOnce(&mut fleetlink_qos::LinkEstimator, Nanos, Nanos),
    ) {
        self.with_estimator(|est, origin, _| {
            let t = Nanos::since(origin, now);
            // The estimator runs on this outbox's clock (ns since `origin`); the hub's
            // reading is put on the same scale, so the offset it finds is hub − robot.
            let origin_unix = crate::instant_to_unix_nanos(origin);
            f(est, t, Nanos(hub_ns.saturating_sub(origin_unix)));
        });
    }

    /// What the link looks like now; restarts the demand measurement (call about once a
    /// second, for the hub's capacity sharing).
    pub fn link_figures(&self, now: Instant) -> Option<LinkFigures> {
        let mut st = self.lock();
        let Service::Scheduled {
            origin,
            link,
            sched,
            ..
        } = &mut st.service
        else {
            return None;
        };
        let t = Nanos::since(*origin, now);
        // Measured only while data flows; an idle link keeps its last figure, and its age.
        if std::mem::take(&mut link.acked_since_report) {
            link.measured = Some((link.est.rate().max(link.delivered_rate(t)), t));
        }
        let capacity = [
            link.measured.map(|(r, _)| r).filter(|r| *r > 0.0),
            link.share,
            sched
                .data_budget()
                .and_then(|b| b.config().max_bytes_per_sec),
        ]
        .into_iter()
        .flatten()
        .reduce(f64::min);
        let span = t.saturating_sub(link.offered_since).as_secs_f64();
        let demand = if span > 0.0 {
            link.offered as f64 / span
        } else {
            0.0
        };
        link.offered = 0;
        link.offered_since = t;
        let d = |n: Nanos| Duration::from_nanos(n.0);
        Some(LinkFigures {
            demand_bps: demand,
            rate_bps: link.est.rate(),
            latency: link.est.latency().map(d),
            rtt: link.est.rtt().map(d),
            clock_offset_ns: link.est.clock_offset(),
            share_bps: link.share,
            in_flight_bytes: link.unacked_bytes(),
            capacity_bps: capacity,
            measured_at: link.measured.map(|(_, at)| *origin + d(at)),
        })
    }

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
                        Some(m) => {
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
