//! The topic table and the fan-out.
//!
//! Control operations (advertise, subscribe, disconnect) take the router's one mutex;
//! they are rare. Publishing does not: a publisher holds an `Arc<Topic>` from its
//! advertise and fans out over the topic's subscriber list, which is an immutable
//! snapshot swapped atomically whenever a subscription changes ([`ArcSwap`]). A message is
//! one `Arc<Message>` pushed into each subscriber's queue — no copy, no encoding here.

use std::collections::{HashMap, HashSet};
use std::net::SocketAddr;
use std::sync::atomic::{
    AtomicU32, AtomicU64, Ordering::Acquire, Ordering::Relaxed, Ordering::Release,
};
use std::sync::{Arc, Mutex};
use std::time::{Instant, SystemTime};

use arc_swap::ArcSwap;
use fleetlink_proto::{Payload, Schema};
use regex::Regex;

use crate::message::{Message, TopicMeta};
use crate::names::{ClientId, TopicId, TopicName};
use crate::outbox::{Delivery, Outbox, SlotId};
use crate::stats::{StatsBatch, TopicStats};
use crate::transcode::{GenericTranscoder, Transcoder};

/// Largest compiled regex accepted for a pattern subscription, in bytes of program.
const REGEX_SIZE_LIMIT: usize = 256 * 1024;
/// Longest pattern accepted.
const MAX_PATTERN_LEN: usize = 1024;

#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RouteError {
    #[error("topic {topic} is already advertised with type {existing}, not {requested}")]
    TypeConflict {
        topic: TopicName,
        existing: String,
        requested: String,
    },
    #[error("invalid subscription pattern {pattern:?}: {reason}")]
    BadPattern { pattern: String, reason: String },
    #[error("unknown client {0}")]
    UnknownClient(ClientId),
}

/// What kind of participant a client is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ClientKind {
    /// A rosbridge v2 client (browser, roslibpy, viewer).
    Rosbridge,
    /// A Foxglove WebSocket client (Foxglove, Lichtblick).
    Foxglove,
    /// A robot's agent on a `fleetlink.v1` link.
    Agent { robot: String },
    /// Something inside this process (simulator, hub link of an agent).
    Internal { role: String },
}

#[derive(Debug, Clone)]
pub struct ClientInfo {
    pub id: ClientId,
    pub kind: ClientKind,
    pub addr: Option<SocketAddr>,
    pub connected_at: SystemTime,
    /// The client negotiated permessage-deflate: large messages go to it compressed.
    pub deflate: bool,
}

/// What a publisher says of its publication when it advertises a topic.
#[derive(Debug, Clone, Default)]
pub struct Publication {
    /// New subscribers get the last message.
    pub latch: bool,
    /// A robot's no-drop stream (`ADVERTISE_RELIABLE`).
    pub no_drop: bool,
    /// The hubs the publisher is behind, when it is another hub's link (`VIA`).
    pub via: Option<Arc<crate::message::Via>>,
    /// The encoding its messages will have, when the publisher knows before the first
    /// ([`Topic::note_encoding`]): a link announces the topic at once.
    pub encoding: Option<fleetlink_proto::Encoding>,
}

/// A subscription's identity within its client.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct SubscriptionId(pub u64);

/// What a subscription asks for.
#[derive(Debug, Clone)]
pub enum Target {
    Exact(TopicName),
    Pattern(Regex),
}

/// Options that shape a subscription's queue and framing.
#[derive(Debug, Clone, Default)]
pub struct SubOptions {
    /// rosbridge `queue_length` (0 = the router's default).
    pub queue_length: u32,
    /// rosbridge `throttle_rate` in milliseconds (0 = none).
    pub throttle_ms: u32,
    /// Full QoS for the subscription's queue; overrides the two fields above.
    pub qos: Option<fleetlink_qos::TopicQos>,
    pub delivery: Delivery,
    /// The subscription does not make the topic appear in listings (a federation's
    /// subscription on behalf of another hub: the topic exists here only once someone
    /// publishes it).
    pub unlisted: bool,
    /// The subscriber wants a topic only while its outbox sends it on ([`Outbox::reads`]):
    /// an uplink that carries everything its own peer asks for subscribes to every topic
    /// this way, so that the topics' publishers hear only that peer's interest, not a
    /// subscription to everything.
    pub passive: bool,
}

#[derive(Clone)]
struct SubscriberRef {
    client: ClientId,
    outbox: Arc<Outbox>,
    slot: SlotId,
    /// Receives its own publishes: rosbridge clients do, as rosbridge delivers to the
    /// publishing connection when it subscribed. Link peers (agents, an agent's uplink)
    /// and in-process participants do not: that is the loop guard between robot and hub.
    own: bool,
    /// Counts as demand only while its outbox sends the topic on (`SubOptions::passive`).
    passive: bool,
}

impl SubscriberRef {
    /// Whether this subscriber wants what is published now.
    fn wants(&self) -> bool {
        !self.passive || self.outbox.reads_slot(self.slot)
    }
}

pub struct Topic {
    meta: ArcSwap<TopicMeta>,
    pub stats: Arc<TopicStats>,
    subscribers: ArcSwap<Vec<SubscriberRef>>,
    /// Counts changes of `meta` and `subscribers` (each stored first, then counted), so a
    /// publisher's [`TopicView`] knows when to read them again.
    version: AtomicU64,
    latched: Mutex<Option<Arc<Message>>>,
    latch: std::sync::atomic::AtomicBool,
    /// Encoding of the last message published (an `Encoding` as u8), so a link can
    /// announce the topic before its next message.
    last_encoding: std::sync::atomic::AtomicU8,
    /// Its publisher (a robot's link) was told that nobody wants it, so it does not
    /// flow: listings show it idle.
    idle: std::sync::atomic::AtomicBool,
    /// Its publisher sends it only when asked ([`Router::request_pull`]).
    pull: std::sync::atomic::AtomicBool,
    /// A video topic's frames since its last keyframe, for subscribers who come in the
    /// middle ([`crate::gop`]); set once its type is known to be video.
    gop: std::sync::OnceLock<Box<crate::gop::Gop>>,
    /// The router's bound on what its video topics' groups keep together.
    video_pool: Arc<crate::gop::Pool>,
    /// A robot publishes it as a no-drop stream: the epoch of that stream plus one (0:
    /// not reliable). Its messages' `seq` are the stream's numbers, so a far side that
    /// may see one twice (federated hubs, after a robot moved) can tell.
    reliable: AtomicU64,
}

/// Where a publisher hears that the demand for its topics may have changed: the topics
/// whose subscribers changed since it last looked, coalesced (a set of ids, bounded by
/// the topics there are), and a wake-up. What the demand now is, it asks
/// [`Router::wanted`]; a burst of subscription churn costs it one look per topic.
#[derive(Default)]
pub struct DemandWatch {
    changed: Mutex<HashSet<TopicId>>,
    /// Pull requests since the last look, coalesced per topic.
    pulls: Mutex<HashSet<TopicId>>,
    notify: tokio::sync::Notify,
}

impl DemandWatch {
    fn mark(&self, topic: TopicId) {
        let fresh = self
            .changed
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .insert(topic);
        if fresh {
            self.notify.notify_one();
        }
    }

    fn pull(&self, topic: TopicId) {
        self.pulls
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .insert(topic);
        self.notify.notify_one();
    }

    /// The topics someone asked to pull since the last call.
    pub fn take_pulls(&self) -> Vec<TopicId> {
        self.pulls
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .drain()
            .collect()
    }

    /// The topics whose subscribers changed since the last call.
    pub fn take(&self) -> Vec<TopicId> {
        self.changed
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .drain()
            .collect()
    }

    /// Resolves once something was marked since the last `take` (at once if something
    /// is waiting).
    pub async fn changed(&self) {
        self.notify.notified().await;
    }
}

/// Where a participant that mirrors the router hears which topics changed: their names
/// since it last looked, coalesced, and a wake-up ([`Router::watch_topics`]).
#[derive(Default)]
pub struct TopicsWatch {
    changed: Mutex<HashSet<TopicName>>,
    notify: tokio::sync::Notify,
}

impl TopicsWatch {
    fn mark(&self, name: &TopicName) {
        let mut set = self.changed.lock().unwrap_or_else(|p| p.into_inner());
        if set.is_empty() {
            self.notify.notify_one();
        }
        set.insert(name.clone());
    }

    /// The topics that changed since the last call.
    pub fn take(&self) -> Vec<TopicName> {
        self.changed
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .drain()
            .collect()
    }

    /// Resolves once something was marked since the last `take` (at once if something
    /// is waiting).
    pub async fn changed(&self) {
        self.notify.notified().await;
    }
}

/// A publisher's copy of what a topic is and who subscribes to it, read again only when
/// the topic has changed ([`Topic::view`]): a burst of publishes reads one counter per
/// message instead of two shared snapshots. Its owner drops what it holds
/// ([`TopicView::clear`]) when it stops publishing for a while, so that subscribers who
/// left are not kept alive by it.
#[derive(Default)]
pub struct TopicView {
    version: u64,
    held: Option<(Arc<TopicMeta>, Arc<Vec<SubscriberRef>>)>,
}

impl TopicView {
    /// The topic's metadata as of the last [`Topic::view`].
    pub fn meta(&self) -> &Arc<TopicMeta> {
        &self.held.as_ref().expect("read by Topic::view").0
    }

    /// Lets go of the snapshots; the next [`Topic::view`] reads them again.
    pub fn clear(&mut self) {
        self.held = None;
    }
}

impl Topic {
    /// `view`, brought up to date with the topic.
    pub fn view<'v>(&self, view: &'v mut TopicView) -> &'v TopicView {
        let version = self.version.load(Acquire);
        if view.held.is_none() || view.version != version {
            view.held = Some((self.meta.load_full(), self.subscribers.load_full()));
            view.version = version;
        }
        view
    }

    fn set_meta(&self, meta: TopicMeta) {
        self.follow_type(&meta);
        self.meta.store(Arc::new(meta));
        self.version.fetch_add(1, Release);
    }

    /// A video topic keeps its frames since the last keyframe, from the moment its type
    /// is known.
    fn follow_type(&self, meta: &TopicMeta) {
        if crate::gop::is_video_type(&meta.schema.type_name) {
            let _ = self
                .gop
                .set(Box::new(crate::gop::Gop::new(self.video_pool.clone())));
        }
    }

    fn set_subscribers(&self, list: Vec<SubscriberRef>) {
        self.subscribers.store(Arc::new(list));
        self.version.fetch_add(1, Release);
    }

    /// Whether a video topic wants a keyframe from its publisher since the last call (its
    /// chain broke, a subscriber came with nothing to show, or one lost a frame;
    /// [`crate::gop`]).
    pub fn take_keyframe_ask(&self) -> bool {
        let Some(gop) = self.gop.get() else {
            return false;
        };
        let lost = self.stats.keyframe_wanted.swap(false, Relaxed);
        gop.lock().take_ask() || lost
    }

    /// Marks a video topic as wanting a keyframe from its publisher, as a subscriber's
    /// lost frame does: the next [`Topic::take_keyframe_ask`] says so. For a want heard
    /// from elsewhere (another hub's viewers, a hub upstream); other topics ignore it.
    pub fn want_keyframe(&self) {
        if self.gop.get().is_some() {
            self.stats.keyframe_wanted.store(true, Relaxed);
        }
    }

    /// Encoding of the most recent message, if any was published.
    pub fn last_encoding(&self) -> Option<fleetlink_proto::Encoding> {
        match self.last_encoding.load(Relaxed) {
            u8::MAX => None,
            v => fleetlink_proto::Encoding::from_u8(v),
        }
    }

    pub fn meta(&self) -> Arc<TopicMeta> {
        self.meta.load_full()
    }

    pub fn name(&self) -> TopicName {
        self.meta.load().name.clone()
    }

    pub fn id(&self) -> TopicId {
        self.meta.load().id
    }

    /// True if a publisher advertised the topic latched (new subscribers get the last
    /// message).
    pub fn is_latched(&self) -> bool {
        self.latch.load(Relaxed)
    }

    pub fn subscriber_count(&self) -> usize {
        self.subscribers.load().len()
    }

    /// Whether anyone but `publisher` itself receives what `publisher` publishes here
    /// (the same rule as the fan-out: a link does not receive its own messages).
    pub fn wanted_by_others(&self, publisher: ClientId) -> bool {
        self.subscribers
            .load()
            .iter()
            .any(|s| (s.client != publisher || s.own) && s.wants())
    }

    /// Whether a client other than `me` wants what is published here by others than
    /// itself: a subscriber that is not one of `publishers` (which never receive their own
    /// messages), or a rosbridge client (which does, see `SubscriberRef::own`).
    pub fn demand_besides(&self, me: ClientId, publishers: &[ClientId]) -> bool {
        self.subscribers
            .load()
            .iter()
            .any(|s| s.client != me && (s.own || !publishers.contains(&s.client)) && s.wants())
    }

    /// Whether a client other than those in `but` subscribes to the topic (a passive
    /// subscriber only while it sends the topic on).
    pub fn has_subscriber_besides(&self, but: &[ClientId]) -> bool {
        self.subscribers
            .load()
            .iter()
            .any(|s| !but.contains(&s.client) && s.wants())
    }

    /// Remembers the encoding its publisher announced, until a message says otherwise: a
    /// link can then announce the topic before any message of it has flowed.
    pub fn note_encoding(&self, encoding: fleetlink_proto::Encoding) {
        let _ = self
            .last_encoding
            .compare_exchange(u8::MAX, encoding as u8, Relaxed, Relaxed);
    }

    /// Marks the topic idle (its publisher was told nobody wants it) or flowing.
    pub fn set_idle(&self, idle: bool) {
        self.idle.store(idle, Relaxed);
    }

    /// True while its publisher holds it back because nobody wants it.
    pub fn is_idle(&self) -> bool {
        self.idle.load(Relaxed)
    }

    /// Marks the topic as one its publisher sends only when asked.
    pub fn set_pull(&self, pull: bool) {
        self.pull.store(pull, Relaxed);
    }

    /// True if its publisher sends it only when asked ([`Router::request_pull`]).
    pub fn is_pull(&self) -> bool {
        self.pull.load(Relaxed)
    }

    /// Marks the topic as a robot's no-drop stream of `epoch` (its messages' `seq` number
    /// the stream), or not reliable (`None`).
    pub fn set_reliable(&self, epoch: Option<u64>) {
        self.reliable
            .store(epoch.map_or(0, |e| e.wrapping_add(1).max(1)), Relaxed);
    }

    /// The epoch of the no-drop stream its robot publishes, if it is one.
    pub fn reliable_epoch(&self) -> Option<u64> {
        match self.reliable.load(Relaxed) {
            0 => None,
            e => Some(e - 1),
        }
    }

    /// Fans `payload` out to every subscriber (its origin only if that is a rosbridge
    /// client, see `SubscriberRef::own`). The hot path: one
    /// allocation for the message, one queue push per subscriber.
    pub fn publish(
        &self,
        origin: ClientId,
        seq: u64,
        stamp_ns: u64,
        payload: Payload,
    ) -> Arc<Message> {
        let now = std::time::Instant::now();
        self.publish_at(self.meta(), origin, seq, stamp_ns, payload, now)
    }

    /// [`Topic::publish`] of a message received at `received`, with the topic as the
    /// publisher saw it when it checked the message (`meta`, from [`Topic::meta`]).
    pub fn publish_at(
        &self,
        meta: Arc<TopicMeta>,
        origin: ClientId,
        seq: u64,
        stamp_ns: u64,
        payload: Payload,
        received: std::time::Instant,
    ) -> Arc<Message> {
        let msg = Arc::new(Message::received_at(
            meta, seq, stamp_ns, origin, payload, received,
        ));
        self.deliver(&msg);
        msg
    }

    /// A rosbridge client's publish: [`Topic::publish_at`] of a message that may be the
    /// JSON text the client sent (`json_text`, see [`Message::framed`]), without handing
    /// the message back. The last subscriber's queue takes the message without a new
    /// reference to it, and the topic's counters are added up in the publisher's
    /// `counts` until it flushes them ([`TopicStats::flush`]).
    #[allow(clippy::too_many_arguments)]
    pub fn publish_framed(
        &self,
        view: &TopicView,
        origin: ClientId,
        seq: u64,
        stamp_ns: u64,
        payload: Payload,
        received: std::time::Instant,
        json_text: bool,
        counts: &mut StatsBatch,
    ) {
        let (meta, subscribers) = view.held.as_ref().expect("read by Topic::view");
        let msg = Arc::new(Message::framed(
            meta.clone(),
            seq,
            stamp_ns,
            origin,
            payload,
            received,
            json_text,
        ));
        self.stats
            .batch_publish(counts, msg.payload.len(), msg.received_unix_ns());
        counts.deliveries += self.fan_out(subscribers, msg, received);
    }

    /// Fans an existing message out (used when a message is re-published unchanged).
    pub fn deliver(&self, msg: &Arc<Message>) {
        self.stats
            .record_publish(msg.payload.len(), msg.received_unix_ns());
        let pushed = self.fan_out(&self.subscribers.load(), msg.clone(), msg.received());
        // One shared counter update per message, not one per subscriber.
        self.stats.deliveries.fetch_add(pushed, Relaxed);
    }

    /// Queues `msg` for every one of `subscribers` but its origin (unless they asked for
    /// their own messages), the last one taking `msg` itself rather than a new reference,
    /// and keeps it as the topic's latest (its encoding; the message itself when latched).
    /// Gives the number of queues it went to.
    // Inlined into both callers: a call of its own costs the publish path ~25
    // instructions a message (session bench).
    #[inline(always)]
    fn fan_out(&self, subscribers: &[SubscriberRef], msg: Arc<Message>, now: Instant) -> u64 {
        self.last_encoding
            .store(msg.payload.encoding as u8, Relaxed);
        if self.latch.load(Relaxed) {
            *self.latched.lock().unwrap_or_else(|p| p.into_inner()) = Some(msg.clone());
        }
        if let Some(gop) = self.gop.get() {
            return self.fan_out_video(gop, msg, now);
        }
        let mut targets = subscribers
            .iter()
            .filter(|s| s.client != msg.origin || s.own);
        let Some(mut last) = targets.next() else {
            return 0;
        };
        let mut pushed = 1;
        for s in targets {
            last.outbox.push(last.slot, msg.clone(), now);
            pushed += 1;
            last = s;
        }
        last.outbox.push(last.slot, msg, now);
        pushed
    }

    /// [`Topic::fan_out`] of a video topic: the frame is kept in the topic's group and
    /// queued for the subscribers read under the group's lock, so that a subscriber being
    /// added meanwhile gets it once, in order ([`crate::gop::Gop::lock`]).
    #[cold]
    fn fan_out_video(&self, gop: &crate::gop::Gop, msg: Arc<Message>, now: Instant) -> u64 {
        let mut group = gop.lock();
        if !group.keep(&msg) {
            // Its chain is broken: held back from everyone until the next keyframe.
            self.stats.record_drop(crate::queue::DropReason::Policy);
            return 0;
        }
        let mut pushed = 0;
        for s in self.subscribers.load().iter() {
            if s.client != msg.origin || s.own {
                s.outbox.push(s.slot, msg.clone(), now);
                pushed += 1;
            }
        }
        pushed
    }
}

struct ClientEntry {
    info: ClientInfo,
    outbox: Arc<Outbox>,
    subs: HashMap<SubscriptionId, (Target, SubOptions)>,
    /// Topics this client receives, with the subscriptions that want each one.
    slots: HashMap<TopicName, (SlotId, Vec<SubscriptionId>)>,
    advertised: HashSet<TopicName>,
}

#[derive(Default)]
struct State {
    topics: HashMap<TopicName, Arc<Topic>>,
    /// The topics' names by id (a link's alias is its topic's id).
    names: HashMap<TopicId, TopicName>,
    publishers: HashMap<TopicName, Vec<ClientId>>,
    clients: HashMap<ClientId, ClientEntry>,
    /// Publishers that follow the demand for their topics.
    demand: HashMap<ClientId, Arc<DemandWatch>>,
    /// Participants that follow every topic ([`Router::watch_topics`]).
    watchers: Vec<Arc<TopicsWatch>>,
}

impl State {
    /// Tells those who follow every topic that `name` changed.
    fn topic_changed(&self, name: &TopicName) {
        for w in &self.watchers {
            // A watch only the router holds belongs to a participant that left.
            if Arc::strong_count(w) == 1 {
                continue;
            }
            w.mark(name);
        }
    }

    /// Tells the publishers of `topic` that watch demand that its subscribers changed.
    fn demand_changed(&self, topic: &Topic) {
        if !self.watchers.is_empty() {
            self.topic_changed(&topic.meta.load().name);
        }
        if self.demand.is_empty() {
            return;
        }
        let meta = topic.meta.load();
        for p in self.publishers.get(&meta.name).into_iter().flatten() {
            if let Some(w) = self.demand.get(p) {
                w.mark(meta.id);
            }
        }
    }
}

/// The routing table. Shared as `Arc<Router>` by every connection task.
pub struct Router {
    state: Mutex<State>,
    transcoder: Arc<dyn Transcoder>,
    next_client: AtomicU64,
    next_sub: AtomicU64,
    next_topic: AtomicU32,
    /// Queue length for subscriptions that do not ask for one.
    pub default_queue: usize,
    /// And the most payload bytes such a queue holds: a burst of small messages arrives
    /// whole, a slow subscriber of large ones keeps only the newest few.
    pub default_queue_bytes: usize,
    pub started: Instant,
    /// Services and actions, and the calls in flight between this router's clients.
    pub calls: Arc<crate::calls::Calls>,
    /// Parameters (`/rosapi/get_param` ...); in memory unless the owner supplies a
    /// durable store.
    pub params: Arc<dyn crate::params::ParamStore>,
    /// What the video topics' groups keep, all together ([`crate::gop::Pool`]).
    pub video_pool: Arc<crate::gop::Pool>,
}

/// A read-only view of one topic for listings.
#[derive(Clone)]
pub struct TopicSnapshot {
    pub topic: Arc<Topic>,
    pub meta: Arc<TopicMeta>,
    pub publishers: Vec<ClientId>,
    pub subscribers: Vec<ClientId>,
    pub stats: Arc<TopicStats>,
    /// Someone subscribed to this topic by its name (not only through a pattern).
    pub named_subscription: bool,
}

impl TopicSnapshot {
    /// Whether listings show the topic: it has a publisher, or a subscriber that asked
    /// for it by name. A topic kept only by pattern subscriptions (a robot's link
    /// subscribes to its whole namespace) after its last publisher left is gone for a
    /// user, as in ROS, where a topic exists while it has an endpoint.
    pub fn listed(&self) -> bool {
        !self.publishers.is_empty() || self.named_subscription
    }
}

impl Default for Router {
    fn default() -> Self {
        Router::new(Arc::new(GenericTranscoder))
    }
}

impl Router {
    pub fn new(transcoder: Arc<dyn Transcoder>) -> Router {
        Router::with_call_limits(transcoder, crate::calls::CallLimits::default())
    }

    pub fn with_call_limits(
        transcoder: Arc<dyn Transcoder>,
        limits: crate::calls::CallLimits,
    ) -> Router {
        Router {
            calls: Arc::new(crate::calls::Calls::new(limits)),
            params: Arc::new(crate::params::MemoryParams::default()),
            state: Mutex::new(State::default()),
            transcoder,
            next_client: AtomicU64::new(1),
            next_sub: AtomicU64::new(1),
            next_topic: AtomicU32::new(1),
            default_queue: 1000,
            default_queue_bytes: 2 << 20,
            started: Instant::now(),
            video_pool: Arc::default(),
        }
    }

    /// From now on the returned watch hears of every topic whose publishers, subscribers
    /// or type change (or that goes away): for a participant that mirrors this router
    /// elsewhere (federation), which reads each such topic with [`Router::snapshot`].
    pub fn watch_topics(&self) -> Arc<TopicsWatch> {
        let w = Arc::new(TopicsWatch::default());
        let mut st = self.lock();
        for name in st.topics.keys() {
            w.mark(name);
        }
        // Watches of participants that left (only the router holds them) go now, so a
        // hub whose viewers come and go keeps no list that grows with them.
        st.watchers.retain(|w| Arc::strong_count(w) > 1);
        st.watchers.push(w.clone());
        w
    }

    /// One topic as [`Router::topics`] lists it.
    pub fn snapshot(&self, name: &TopicName) -> Option<TopicSnapshot> {
        let st = self.lock();
        let t = st.topics.get(name)?;
        Some(snapshot_of(&st, name, t))
    }

    pub fn transcoder(&self) -> &dyn Transcoder {
        &*self.transcoder
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Registers a participant; its outbox receives what it subscribes to.
    pub fn connect(&self, kind: ClientKind, addr: Option<SocketAddr>) -> (ClientId, Arc<Outbox>) {
        self.connect_with(kind, addr, Outbox::new)
    }

    /// Registers a participant whose outbox is built by `make` (e.g. a scheduled one).
    pub fn connect_with(
        &self,
        kind: ClientKind,
        addr: Option<SocketAddr>,
        make: impl FnOnce(ClientId) -> Arc<Outbox>,
    ) -> (ClientId, Arc<Outbox>) {
        let id = ClientId(self.next_client.fetch_add(1, Relaxed));
        let outbox = make(id);
        let info = ClientInfo {
            id,
            kind,
            addr,
            connected_at: SystemTime::now(),
            deflate: false,
        };
        let entry = ClientEntry {
            info,
            outbox: outbox.clone(),
            subs: HashMap::new(),
            slots: HashMap::new(),
            advertised: HashSet::new(),
        };
        self.lock().clients.insert(id, entry);
        (id, outbox)
    }

    /// Removes a participant with everything it advertised and subscribed, its services
    /// and its calls.
    pub fn disconnect(&self, id: ClientId) {
        self.calls.detach(id);
        let mut st = self.lock();
        let Some(entry) = st.clients.remove(&id) else {
            return;
        };
        st.demand.remove(&id);
        for (name, (slot, _)) in &entry.slots {
            if let Some(t) = st.topics.get(name) {
                detach(t, id);
                st.demand_changed(t);
            }
            entry.outbox.remove_slot(*slot);
        }
        for name in &entry.advertised {
            if let Some(p) = st.publishers.get_mut(name) {
                p.retain(|c| *c != id);
            }
            publisher_left(&st, name, id);
        }
        entry.outbox.close();
        let names: Vec<TopicName> = entry
            .advertised
            .iter()
            .chain(entry.slots.keys())
            .cloned()
            .collect();
        for name in names {
            gc_topic(&mut st, &name);
        }
        for name in &entry.advertised {
            st.topic_changed(name);
        }
    }

    /// Declares `client` a publisher of `name`. A topic's type is fixed by its first
    /// publisher; a later advertise may fill in the schema text.
    pub fn advertise(
        &self,
        client: ClientId,
        name: &TopicName,
        schema: Schema,
        latch: bool,
    ) -> Result<Arc<Topic>, RouteError> {
        let how = Publication {
            latch,
            ..Publication::default()
        };
        self.advertise_as(client, name, schema, how)
    }

    /// [`Router::advertise`] with everything the publisher says of its publication. A
    /// no-drop stream is one from the topic's creation, so the subscribers who attach
    /// then (a hub's uplink) see it as one.
    pub fn advertise_as(
        &self,
        client: ClientId,
        name: &TopicName,
        schema: Schema,
        how: Publication,
    ) -> Result<Arc<Topic>, RouteError> {
        let Publication {
            latch,
            no_drop,
            via,
            encoding,
        } = how;
        // Definitions travel with topics: learn what the publisher sent, or fill in what
        // the registry knows so listings and viewers get the full text.
        let schema = if schema.text.is_empty() {
            self.transcoder
                .schema_for(&schema.type_name)
                .unwrap_or(schema)
        } else {
            self.transcoder.learn(&schema);
            schema
        };
        let mut st = self.lock();
        if !st.clients.contains_key(&client) {
            return Err(RouteError::UnknownClient(client));
        }
        let meta_before: Arc<TopicMeta>;
        let others_publish = st
            .publishers
            .get(name)
            .is_some_and(|p| p.iter().any(|c| *c != client));
        let topic = match st.topics.get(name).cloned() {
            Some(t) => {
                let meta = t.meta();
                meta_before = meta.clone();
                let known = &meta.schema.type_name;
                if others_publish && !known.is_empty() && !same_type(known, &schema.type_name) {
                    return Err(RouteError::TypeConflict {
                        topic: name.clone(),
                        existing: known.clone(),
                        requested: schema.type_name,
                    });
                }
                let schema_news = known.is_empty()
                    || !same_type(known, &schema.type_name)
                    || (meta.schema.text.is_empty() && !schema.text.is_empty());
                // A publisher here makes it a topic of this hub's own; the first publisher
                // that is another hub's link says which hubs it is behind.
                let topic_via = match via {
                    None => None,
                    Some(_) if others_publish => meta.via.clone(),
                    Some(v) => Some(v),
                };
                if schema_news || (no_drop && !meta.no_drop) || topic_via != meta.via {
                    let schema = if schema_news {
                        schema
                    } else {
                        meta.schema.clone()
                    };
                    t.set_meta(
                        TopicMeta::new(meta.id, name.clone(), schema, meta.latched)
                            .with_no_drop(meta.no_drop || no_drop)
                            .with_topic_via(topic_via),
                    );
                }
                t
            }
            None => {
                let t = self.create_topic(&mut st, name, schema, no_drop, via);
                meta_before = t.meta();
                t
            }
        };
        // Before the watchers look (they do once the state's lock is let go).
        if let Some(e) = encoding {
            topic.note_encoding(e);
        }
        if latch {
            topic.latch.store(true, Relaxed);
            // Messages carry the flag from now on, so links announce the topic latched.
            let meta = topic.meta();
            if !meta.latched {
                topic.set_meta(
                    TopicMeta::new(meta.id, meta.name.clone(), meta.schema.clone(), true)
                        .with_no_drop(meta.no_drop)
                        .with_topic_via(meta.via.clone()),
                );
            }
        }
        let pubs = st.publishers.entry(name.clone()).or_default();
        let fresh = !pubs.contains(&client);
        if fresh {
            pubs.push(client);
        }
        if let Some(c) = st.clients.get_mut(&client) {
            c.advertised.insert(name.clone());
        }
        if fresh || !Arc::ptr_eq(&meta_before, &topic.meta()) {
            st.topic_changed(name);
        }
        Ok(topic)
    }

    pub fn unadvertise(&self, client: ClientId, name: &TopicName) {
        let mut st = self.lock();
        let was = st
            .clients
            .get_mut(&client)
            .is_some_and(|c| c.advertised.remove(name));
        if let Some(p) = st.publishers.get_mut(name) {
            p.retain(|c| *c != client);
        }
        publisher_left(&st, name, client);
        gc_topic(&mut st, name);
        if was {
            st.topic_changed(name);
        }
    }

    /// The topic with id `id`, if it exists.
    pub fn topic_by_id(&self, id: TopicId) -> Option<Arc<Topic>> {
        let st = self.lock();
        st.names.get(&id).and_then(|n| st.topics.get(n)).cloned()
    }

    /// A passive subscriber of the topic with id `id` started or stopped sending it on:
    /// its publishers hear that the demand for it may have changed.
    pub fn note_demand(&self, id: TopicId) {
        let st = self.lock();
        if let Some(t) = st.names.get(&id).and_then(|n| st.topics.get(n)) {
            st.demand_changed(t);
        }
    }

    /// From now on `client` hears (through the returned watch) whenever the subscribers of
    /// a topic it publishes change; it asks [`Topic::wanted_by_others`] what that means.
    /// Forgotten when the client disconnects.
    pub fn watch_demand(&self, client: ClientId) -> Arc<DemandWatch> {
        self.lock().demand.entry(client).or_default().clone()
    }

    /// Asks the publishers of `name` that send it only on request for one message (which
    /// then reaches the topic's subscribers). False if no such publisher has it.
    pub fn request_pull(&self, name: &TopicName) -> bool {
        let st = self.lock();
        let Some(topic) = st.topics.get(name) else {
            return false;
        };
        let mut asked = false;
        for p in st.publishers.get(name).into_iter().flatten() {
            if let Some(w) = st.demand.get(p) {
                w.pull(topic.id());
                asked = true;
            }
        }
        asked && topic.is_pull()
    }

    /// The topic if it exists (publishing to a topic someone else advertised).
    pub fn topic(&self, name: &TopicName) -> Option<Arc<Topic>> {
        self.lock().topics.get(name).cloned()
    }

    fn create_topic(
        &self,
        st: &mut State,
        name: &TopicName,
        schema: Schema,
        no_drop: bool,
        via: Option<Arc<crate::message::Via>>,
    ) -> Arc<Topic> {
        let id = TopicId(self.next_topic.fetch_add(1, Relaxed));
        let meta = TopicMeta::new(id, name.clone(), schema, false)
            .with_no_drop(no_drop)
            .with_topic_via(via);
        let topic = Arc::new(Topic {
            meta: ArcSwap::from_pointee(meta),
            stats: Arc::new(TopicStats::default()),
            subscribers: ArcSwap::from_pointee(Vec::new()),
            version: AtomicU64::new(0),
            latched: Mutex::new(None),
            gop: Default::default(),
            video_pool: self.video_pool.clone(),
            latch: Default::default(),
            last_encoding: std::sync::atomic::AtomicU8::new(u8::MAX),
            idle: Default::default(),
            pull: Default::default(),
            reliable: AtomicU64::new(0),
        });
        topic.follow_type(&topic.meta());
        st.topics.insert(name.clone(), topic.clone());
        st.names.insert(id, name.clone());
        st.topic_changed(name);
        // Pattern subscriptions pick up new topics as they appear.
        let mut matches = Vec::new();
        for (cid, c) in &st.clients {
            for (sid, (target, opts)) in &c.subs {
                if let Target::Pattern(re) = target
                    && re.is_match(name.as_str())
                {
                    matches.push((*cid, *sid, opts.clone()));
                }
            }
        }
        for (cid, sid, opts) in matches {
            self.attach(st, cid, sid, &topic, &opts);
        }
        topic
    }

    /// Compiles a whole-name pattern with limits that keep a hostile pattern cheap: the
    /// regex engine has no backtracking, and the compiled size is capped.
    pub fn compile_pattern(pattern: &str) -> Result<Regex, RouteError> {
        let bad = |reason: String| RouteError::BadPattern {
            pattern: pattern.chars().take(100).collect(),
            reason,
        };
        if pattern.len() > MAX_PATTERN_LEN {
            return Err(bad(format!("longer than {MAX_PATTERN_LEN} bytes")));
        }
        // Errors speak of the client's pattern, not of the anchors added around it.
        let why = |e: regex::Error| match e {
            regex::Error::Syntax(text) => text
                .lines()
                .rev()
                .find_map(|l| l.trim().strip_prefix("error: "))
                .unwrap_or("not a valid regular expression")
                .to_owned(),
            regex::Error::CompiledTooBig(_) => {
                format!("compiles to more than {} KiB", REGEX_SIZE_LIMIT >> 10)
            }
            _ => "not a valid regular expression".to_owned(),
        };
        let limits = |p: &str| {
            regex::RegexBuilder::new(p)
                .size_limit(REGEX_SIZE_LIMIT)
                .dfa_size_limit(REGEX_SIZE_LIMIT)
                .nest_limit(64)
                .build()
        };
        limits(pattern).map_err(|e| bad(why(e)))?;
        limits(&format!("^(?:{pattern})$")).map_err(|e| bad(why(e)))
    }

    /// Subscribes `client` to a topic or a pattern. Subscribing to a topic nobody
    /// publishes yet is allowed: messages flow once a publisher appears.
    pub fn subscribe(
        &self,
        client: ClientId,
        target: Target,
        opts: SubOptions,
    ) -> Result<SubscriptionId, RouteError> {
        let sid = SubscriptionId(self.next_sub.fetch_add(1, Relaxed));
        let mut st = self.lock();
        let st = &mut *st;
        let Some(c) = st.clients.get_mut(&client) else {
            return Err(RouteError::UnknownClient(client));
        };
        c.subs.insert(sid, (target.clone(), opts.clone()));
        let topics: Vec<Arc<Topic>> = match &target {
            Target::Exact(name) => {
                let t = match st.topics.get(name) {
                    Some(t) => t.clone(),
                    None => self.create_topic(st, name, Schema::default(), false, None),
                };
                vec![t]
            }
            Target::Pattern(re) => st
                .topics
                .iter()
                .filter(|(n, _)| re.is_match(n.as_str()))
                .map(|(_, t)| t.clone())
                .collect(),
        };
        for t in topics {
            self.attach(st, client, sid, &t, &opts);
        }
        Ok(sid)
    }

    fn attach(
        &self,
        st: &mut State,
        client: ClientId,
        sid: SubscriptionId,
        topic: &Arc<Topic>,
        opts: &SubOptions,
    ) {
        let Some(c) = st.clients.get_mut(&client) else {
            return;
        };
        let name = topic.name();
        if let Some((_, holders)) = c.slots.get_mut(&name) {
            if !holders.contains(&sid) {
                holders.push(sid);
            }
            return;
        }
        let qos = opts.qos.clone().unwrap_or_else(|| {
            crate::queue::qos_for_options(opts.queue_length, opts.throttle_ms, self.default_queue)
        });
        // The byte bound applies where the subscriber did not choose its queue.
        let max_bytes =
            (opts.qos.is_none() && opts.queue_length == 0).then_some(self.default_queue_bytes);
        let slot = c.outbox.add_slot(
            &topic.meta(),
            &qos,
            topic.stats.clone(),
            opts.delivery,
            max_bytes,
        );
        c.slots.insert(name, (slot, vec![sid]));
        let own = c.info.kind == ClientKind::Rosbridge;
        let r = SubscriberRef {
            client,
            outbox: c.outbox.clone(),
            slot,
            own,
            passive: opts.passive,
        };
        let mut list = Vec::clone(&topic.subscribers.load());
        list.push(r);
        // A video topic's group is replayed to the new subscriber under the lock its
        // publishes take (crate::gop).
        let mut group = topic.gop.get().map(|g| g.lock());
        if let Some(g) = group.as_mut() {
            g.joined();
        }
        topic.set_subscribers(list);
        for m in group.iter().flat_map(|g| g.frames()) {
            if m.origin != client || own {
                c.outbox.push(slot, m.clone(), Instant::now());
            }
        }
        drop(group);
        let latched = topic
            .latched
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .clone();
        if let Some(m) = latched
            && (m.origin != client || own)
        {
            c.outbox.push(slot, m, Instant::now());
        }

        st.demand_changed(topic);
    }

    pub fn unsubscribe(&self, client: ClientId, sid: SubscriptionId) {
        let mut st = self.lock();
        let st = &mut *st;
        let Some(c) = st.clients.get_mut(&client) else {
            return;
        };
        c.subs.remove(&sid);
        let mut emptied = Vec::new();
        for (name, (slot, holders)) in c.slots.iter_mut() {
            holders.retain(|h| *h != sid);
            if holders.is_empty() {
                emptied.push((name.clone(), *slot));
            }
        }
        for (name, slot) in &emptied {
            c.slots.remove(name);
            c.outbox.remove_slot(*slot);
        }
        for (name, _) in emptied {
            if let Some(t) = st.topics.get(&name) {
                detach(t, client);
                st.demand_changed(t);
            }
            gc_topic(st, &name);
        }
    }

    /// Notes that client `id` negotiated permessage-deflate (shown in listings).
    pub fn note_deflate(&self, id: ClientId) {
        if let Some(c) = self.lock().clients.get_mut(&id) {
            c.info.deflate = true;
        }
    }

    pub fn client_info(&self, id: ClientId) -> Option<ClientInfo> {
        self.lock().clients.get(&id).map(|c| c.info.clone())
    }

    /// Every client with its outbox (for metrics and the API).
    pub fn clients(&self) -> Vec<(ClientInfo, Arc<Outbox>, usize)> {
        self.lock()
            .clients
            .values()
            .map(|c| (c.info.clone(), c.outbox.clone(), c.slots.len()))
            .collect()
    }

    /// Every topic, sorted by name.
    pub fn topics(&self) -> Vec<TopicSnapshot> {
        let st = self.lock();
        let mut out: Vec<TopicSnapshot> = st
            .topics
            .iter()
            .map(|(name, t)| snapshot_of(&st, name, t))
            .collect();
        out.sort_by(|a, b| a.meta.name.cmp(&b.meta.name));
        out
    }
}

/// `name`'s listing entry. Whether someone subscribed by name (not through a pattern, and
/// not quietly, see [`SubOptions::unlisted`]) is asked of the topic's subscribers only.
fn snapshot_of(st: &State, name: &TopicName, t: &Arc<Topic>) -> TopicSnapshot {
    let subscribers: Vec<ClientId> = t.subscribers.load().iter().map(|s| s.client).collect();
    let named_subscription = subscribers.iter().any(|cid| {
        st.clients.get(cid).is_some_and(|c| {
            c.slots.get(name).is_some_and(|(_, holders)| {
                holders
                    .iter()
                    .any(|h| matches!(c.subs.get(h), Some((Target::Exact(_), o)) if !o.unlisted))
            })
        })
    });
    TopicSnapshot {
        topic: t.clone(),
        meta: t.meta(),
        publishers: st.publishers.get(name).cloned().unwrap_or_default(),
        subscribers,
        stats: t.stats.clone(),
        named_subscription,
    }
}

/// ROS 1 and ROS 2 spell types `pkg/T` and `pkg/msg/T`; both name the same type.
pub fn same_type(a: &str, b: &str) -> bool {
    fn norm(s: &str) -> String {
        s.replace("/msg/", "/")
    }
    a == b || norm(a) == norm(b)
}

fn detach(topic: &Topic, client: ClientId) {
    let list: Vec<SubscriberRef> = topic
        .subscribers
        .load()
        .iter()
        .filter(|s| s.client != client)
        .cloned()
        .collect();
    if list.is_empty()
        && let Some(gop) = topic.gop.get()
    {
        // Its publisher stops sending to nobody: what is kept now would be stale by the
        // time someone comes, who then gets a fresh keyframe instead (crate::gop).
        gop.lock().nobody_watches();
    }
    topic.set_subscribers(list);
}

/// A publisher of `name` went: a video topic lets go of the group of pictures it kept of
/// that publisher's stream (a later subscriber would be given frames of a stream that has
/// ended; the publisher's next stream starts with a keyframe).
fn publisher_left(st: &State, name: &TopicName, client: ClientId) {
    if let Some(gop) = st.topics.get(name).and_then(|t| t.gop.get()) {
        gop.lock().forget(client);
    }
}

/// Forgets a topic nobody publishes or subscribes to any more.
fn gc_topic(st: &mut State, name: &TopicName) {
    let has_pub = st.publishers.get(name).is_some_and(|p| !p.is_empty());
    let has_sub = st
        .topics
        .get(name)
        .is_some_and(|t| t.subscriber_count() > 0);
    if !has_pub && !has_sub {
        st.publishers.remove(name);
        if let Some(t) = st.topics.remove(name) {
            st.names.remove(&t.id());
            st.topic_changed(name);
        }
    }
}

#[cfg(test)]
mod watch_tests {
    use super::*;

    #[test]
    fn a_topics_watch_nobody_holds_is_let_go() {
        // Viewers that come and go (each Foxglove session holds one watch) leave nothing
        // behind in the router.
        let router = Router::default();
        for _ in 0..10 {
            drop(router.watch_topics());
        }
        let kept = router.watch_topics();
        assert_eq!(router.lock().watchers.len(), 1);
        let (c, _) = router.connect(ClientKind::Foxglove, None);
        let name = TopicName::parse("/a").unwrap();
        router
            .advertise(c, &name, Schema::named("std_msgs/msg/Empty"), false)
            .unwrap();
        assert_eq!(kept.take(), vec![name]);
    }
}

#[cfg(test)]
mod keyframe_tests {
    use super::*;

    #[test]
    fn a_keyframe_wanted_from_elsewhere_is_asked_once_and_only_of_video() {
        let router = Router::default();
        let (c, _) = router.connect(ClientKind::Foxglove, None);
        let advertise = |name: &str, type_name: &str| {
            let name = TopicName::parse(name).unwrap();
            router
                .advertise(c, &name, Schema::named(type_name), false)
                .unwrap()
        };
        let video = advertise("/cam/video", "foxglove_msgs/msg/CompressedVideo");
        let _ = video.take_keyframe_ask();
        video.want_keyframe();
        assert!(video.take_keyframe_ask());
        assert!(!video.take_keyframe_ask(), "asked once");
        let scan = advertise("/scan", "sensor_msgs/msg/LaserScan");
        scan.want_keyframe();
        assert!(!scan.take_keyframe_ask(), "not a video topic");
    }
}
