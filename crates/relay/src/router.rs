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

mod topic;
mod watch;

use topic::SubscriberRef;
pub use topic::{Topic, TopicSnapshot, TopicView};
use topic::{detach, publisher_left, snapshot_of};
pub use watch::{DemandWatch, TopicsWatch};

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

/// ROS 1 and ROS 2 spell types `pkg/T` and `pkg/msg/T`; both name the same type.
pub fn same_type(a: &str, b: &str) -> bool {
    fn norm(s: &str) -> String {
        s.replace("/msg/", "/")
    }
    a == b || norm(a) == norm(b)
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
