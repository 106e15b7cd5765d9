//! The participant and its loop: the shared [`Bridge`], the discovery tick, and making
//! the participant again when it stops carrying anything.
//!
//! One task ([`run`]) owns the router client's outbox, the call-table channel and the
//! discovery tick; each bridged-up topic has a task reading its DDS reader, each exposed
//! service or action a task reading its replies ([`crate::services`]). rustdds runs its
//! own network threads; its readers are polled as async streams here, its writers are
//! written without waiting (keep-last history never blocks).
//!
//! # Layout
//!
//! - [`endpoints`]: the bridge's own readers and writers, listed while they live.
//! - [`up`]: local topics read from the graph and sent to the router.
//! - [`down`](mod@down): router topics written into the graph.
//! - [`rejoin`]: why a participant ends and is made again.

mod down;
mod endpoints;
mod rejoin;
mod up;

use std::collections::{HashMap, HashSet};
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Instant;

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::ChannelPeer;
use fleetlink_relay::names::ClientId;
use fleetlink_relay::read_interest::ReadInterest;
use fleetlink_relay::router::SubscriptionId;
use fleetlink_relay::stats::{AdapterReport, Problems};
use fleetlink_relay::{ClientKind, Router};
use futures::StreamExt;
use rustdds::no_key::{DataReader, DataWriter};
use rustdds::{
    DomainParticipant, GUID, Publisher, QosPolicies, RTPSEntity, StatusEvented, Subscriber,
    TopicKind,
};
use tokio_util::sync::CancellationToken;

use crate::names::{self, DdsName};
use crate::offered_actions::OfferedAction;
use crate::options::Ros2Options;
use crate::raw::{RawAdapter, RawCdr};
use crate::services::{self, Offered, Remote};
use down::{Down, down, follow_readers, follow_subscriptions, holding, release_held};
use rejoin::{DdsAddresses, End, LIVENESS_PERIOD};
use up::{Up, follow_interest, start_up, stop_up};

pub(crate) use endpoints::OwnEndpoints;
pub use endpoints::{RawReader, RawWriter, Tracked};

#[derive(Debug, thiserror::Error)]
pub enum Ros2Error {
    #[error(
        "ros2: cannot join DDS domain {domain}: {cause} (is another program holding the \
         ports, or is there no network interface up?)"
    )]
    Participant { domain: u16, cause: String },
    #[error("ros2: cannot create a DDS publisher or subscriber: {0}")]
    Endpoint(String),
}

/// Counters and problems of the bridge (logged at exit; on the agent's status topic).
#[derive(Debug, Default)]
pub struct Stats {
    pub messages_up: AtomicU64,
    pub messages_down: AtomicU64,
    pub dropped_down: AtomicU64,
    pub unknown_types: AtomicU64,
    pub type_mismatches: AtomicU64,
    /// Times the participant was rebuilt after rustdds' threads ended ([`run`]).
    pub participant_restarts: AtomicU64,
    /// Times the bridge rejoined the graph because a network address appeared ([`run`]).
    pub network_rejoins: AtomicU64,
    /// Times it rejoined because rustdds had lost a participant that still announced
    /// itself ([`crate::lost_peers`]).
    pub stranded_peer_rejoins: AtomicU64,
    /// Times a topic's reader was dropped because nobody wanted the topic.
    pub paused_reading: AtomicU64,
    /// Each unknown type and type mismatch as its log line says it.
    pub problems: Problems,
}

impl AdapterReport for Stats {
    fn counters(&self) -> Vec<(&'static str, u64)> {
        let get = |c: &AtomicU64| c.load(Relaxed);
        vec![
            ("messages_up", get(&self.messages_up)),
            ("messages_down", get(&self.messages_down)),
            ("dropped_down", get(&self.dropped_down)),
            ("unknown_types", get(&self.unknown_types)),
            ("type_mismatches", get(&self.type_mismatches)),
            ("participant_restarts", get(&self.participant_restarts)),
            ("network_rejoins", get(&self.network_rejoins)),
            ("stranded_peer_rejoins", get(&self.stranded_peer_rejoins)),
            ("paused_reading", get(&self.paused_reading)),
        ]
    }

    fn problems(&self) -> Vec<String> {
        self.problems.list()
    }
}

#[derive(Default)]
pub(crate) struct State {
    up: HashMap<String, Up>,
    down: HashMap<String, Option<Down>>,
    /// Router topics subscribed because a node of the graph reads them (`read`).
    read: HashMap<String, SubscriptionId>,
    /// Router topics subscribed to be written into the graph (`subscribe`).
    subscribed: HashMap<String, SubscriptionId>,
    /// Topics and services already reported (unknown type, mismatch): once each.
    reported: HashSet<String>,
    pub(crate) remotes: HashMap<String, Arc<Remote>>,
    pub(crate) offered: HashMap<String, Arc<Offered>>,
    /// Local callers' calls of fleet services, by call id: where the answer goes.
    pub(crate) local_calls: HashMap<u64, services::LocalCall>,
    /// Fleet goals sent to local action servers, by call id.
    pub(crate) goals: HashMap<u64, (Arc<Remote>, [u8; 16])>,
    /// Fleet actions served to local clients, by name.
    pub(crate) offered_actions: HashMap<String, Arc<OfferedAction>>,
    /// Local clients' goals of fleet actions, by call id.
    pub(crate) offered_goals: HashMap<u64, Arc<OfferedAction>>,
    /// Endpoints for nodes' parameter services, by node name and service.
    pub(crate) params: HashMap<(String, crate::params::Srv), crate::params::ParamEndpoint>,
}

/// The bridge's shared half: the participant, the router client and the state.
pub struct Bridge {
    /// The options the bridge started with (what crosses is [`Bridge::live`]'s).
    pub opts: Ros2Options,
    /// The options in force: `opts`, or the last runtime change of them.
    live: std::sync::RwLock<Arc<Ros2Options>>,
    pub router: Arc<Router>,
    pub client: ClientId,
    pub stats: Arc<Stats>,
    pub(crate) dp: DomainParticipant,
    pub(crate) publisher: Publisher,
    pub(crate) subscriber: Subscriber,
    /// This participant's GUID prefix: endpoints and samples of its own are never bridged.
    pub(crate) own: GUID,
    /// The readers and writers the bridge has made.
    pub(crate) endpoints: Arc<OwnEndpoints>,
    state: Mutex<State>,
    /// Asked whether a topic needs reading at all (with an agent's uplink).
    interest: Option<Arc<ReadInterest>>,
}

impl Bridge {
    pub(crate) fn lock(&self) -> MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// The options in force (what crosses may change while the bridge runs).
    pub(crate) fn live(&self) -> Arc<Ros2Options> {
        self.live.read().unwrap_or_else(|p| p.into_inner()).clone()
    }

    pub(crate) fn is_own(&self, guid: GUID) -> bool {
        guid.prefix == self.own.prefix
    }

    /// The DDS topic `dds_topic` of type `dds_type` (no key, as ROS 2 topics are).
    fn topic(
        &self,
        dds_topic: &str,
        dds_type: &str,
        qos: &QosPolicies,
    ) -> Result<rustdds::Topic, String> {
        self.dp
            .create_topic(
                dds_topic.to_owned(),
                dds_type.to_owned(),
                qos,
                TopicKind::NoKey,
            )
            .map_err(|e| format!("topic {dds_topic}: {e}"))
    }

    /// A DDS reader of raw samples on `dds_topic`.
    pub(crate) fn reader(
        &self,
        dds_topic: &str,
        dds_type: &str,
        qos: QosPolicies,
    ) -> Result<RawReader, String> {
        let reader = self.untracked_reader(dds_topic, dds_type, qos)?;
        Ok(self.track(reader.guid(), false, reader))
    }

    /// A reader that is not one of the node's endpoints (the bridge's own bookkeeping).
    pub(crate) fn untracked_reader(
        &self,
        dds_topic: &str,
        dds_type: &str,
        qos: QosPolicies,
    ) -> Result<DataReader<RawCdr, RawAdapter>, String> {
        let topic = self.topic(dds_topic, dds_type, &qos)?;
        self.subscriber
            .create_datareader_no_key::<RawCdr, RawAdapter>(&topic, Some(qos))
            .map_err(|e| format!("reader of {dds_topic}: {e}"))
    }

    fn track<T>(&self, guid: GUID, writer: bool, inner: T) -> Tracked<T> {
        self.endpoints.track(guid, writer, inner)
    }

    /// A DDS writer of raw samples on `dds_topic`.
    pub(crate) fn writer(
        &self,
        dds_topic: &str,
        dds_type: &str,
        qos: QosPolicies,
    ) -> Result<RawWriter, String> {
        let writer = self.untracked_writer(dds_topic, dds_type, qos)?;
        Ok(self.track(writer.guid(), true, writer))
    }

    /// A writer that is not one of the node's endpoints (the bridge's own bookkeeping).
    pub(crate) fn untracked_writer(
        &self,
        dds_topic: &str,
        dds_type: &str,
        qos: QosPolicies,
    ) -> Result<DataWriter<RawCdr, RawAdapter>, String> {
        let topic = self.topic(dds_topic, dds_type, &qos)?;
        self.publisher
            .create_datawriter_no_key::<RawCdr, RawAdapter>(&topic, Some(qos))
            .map_err(|e| format!("writer of {dds_topic}: {e}"))
    }

    /// `payload` as little-endian CDR of `type_name`: as it is when it already is, else
    /// converted once by the registry.
    pub(crate) fn to_cdr(&self, type_name: &str, payload: &Payload) -> Result<Bytes, String> {
        if payload.encoding == Encoding::Cdr && RawCdr::is_le(&payload.bytes) {
            return Ok(payload.bytes.clone());
        }
        let schema = ros2_schema(type_name);
        let t = self.router.transcoder();
        let converted = if payload.encoding == Encoding::Cdr {
            // Big-endian CDR (rare): through JSON, since writers here are little-endian.
            t.convert(&schema, payload, Encoding::Json)
                .and_then(|j| t.convert(&schema, &Payload::new(Encoding::Json, j), Encoding::Cdr))
        } else {
            t.convert(&schema, payload, Encoding::Cdr)
        };
        converted.map_err(|e| e.to_string())
    }

    /// A message of `type_name` as a JSON value (normalized when it was JSON already).
    pub(crate) fn json_of(
        &self,
        type_name: &str,
        payload: &Payload,
    ) -> Result<serde_json::Value, String> {
        let t = self.router.transcoder();
        let s = ros2_schema(type_name);
        let bytes = match payload.encoding {
            Encoding::Json => match t.normalize(&s, payload).map_err(|e| e.to_string())? {
                Some(p) => p.bytes,
                None => payload.bytes.clone(),
            },
            _ => t
                .convert(&s, payload, Encoding::Json)
                .map_err(|e| e.to_string())?,
        };
        serde_json::from_slice(&bytes).map_err(|e| e.to_string())
    }

    /// `value` as CDR of `type_name`.
    pub(crate) fn cdr_of(
        &self,
        type_name: &str,
        value: &serde_json::Value,
    ) -> Result<Bytes, String> {
        let json = serde_json::to_vec(value).map_err(|e| e.to_string())?;
        self.to_cdr(type_name, &Payload::new(Encoding::Json, json))
    }

    /// Logs `text` once per `key` (unknown types, mismatches): a robot left running
    /// must not repeat the same line every discovery period.
    pub(crate) fn report_once(
        &self,
        key: &str,
        counter: &AtomicU64,
        text: impl FnOnce() -> String,
    ) {
        if self.lock().reported.insert(key.to_owned()) {
            counter.fetch_add(1, Relaxed);
            let text = text();
            tracing::warn!("{text}");
            self.stats
                .problems
                .note(text.strip_prefix("ros2: ").unwrap_or(&text));
        }
    }

    /// The full ROS 2 definition of `ros_type`, if the registry knows it.
    pub(crate) fn schema(&self, ros_type: &str) -> Option<Schema> {
        self.router.transcoder().schema_for(ros_type)
    }
}

/// The schema of ROS 2 type `type_name` as the registry knows it (no text of its own).
fn ros2_schema(type_name: &str) -> Schema {
    Schema {
        type_name: type_name.to_owned(),
        encoding: "ros2msg".into(),
        text: String::new(),
    }
}

/// Bridges the ROS 2 graph of `opts.domain_id` with `router` until `shutdown`.
///
/// The participant is made again (the router's topics and services go and come back) when:
/// - rustdds' threads have ended. rustdds ends its network and discovery threads at the
///   first `poll` that returns an error, and `poll` returns `EINTR` when the agent is
///   stopped and continued (Ctrl-Z and `fg`, SIGSTOP and SIGCONT, a suspend and resume, a
///   container paused) or a debugger or `strace` attaches; the participant then looks
///   alive but carries nothing. The bridge checks every [`LIVENESS_PERIOD`] that the
///   discovery thread still takes commands.
/// - a network address appeared ([`DdsAddresses`]).
/// - rustdds lost a participant by lease that still announces itself, as after a short
///   outage of the robot's network ([`crate::lost_peers`]).
/// - making it failed (no port free, for example): tried again.
///
/// Each time after 1 s, doubling to 30 s while participants keep ending within a minute.
pub async fn run(
    opts: Ros2Options,
    router: Arc<Router>,
    stats: Arc<Stats>,
    interest: Option<Arc<ReadInterest>>,
    shutdown: CancellationToken,
) -> Result<(), Ros2Error> {
    const FIRST_PAUSE: std::time::Duration = std::time::Duration::from_secs(1);
    let mut pause = FIRST_PAUSE;
    loop {
        let started = Instant::now();
        let ended = run_participant(opts.clone(), &router, &stats, &interest, &shutdown).await;
        if started.elapsed() > std::time::Duration::from_secs(60) {
            pause = FIRST_PAUSE;
        }
        let (domain, secs) = (opts.domain_id, pause.as_secs());
        match ended {
            Ok(End::Shutdown) => return Ok(()),
            Ok(End::ParticipantStopped) => {
                stats.participant_restarts.fetch_add(1, Relaxed);
                let text = format!(
                    "the DDS participant's threads stopped (rustdds ends them when a poll is \
                     interrupted: the agent stopped and continued, the machine suspended and \
                     resumed, a debugger or strace attached); rejoining DDS domain {domain}"
                );
                tracing::error!("ros2: {text} in {secs} s");
                // One entry however often it happens (the counter says how often).
                stats.problems.note(&text);
            }
            Ok(End::NetworkChanged(new)) => {
                stats.network_rejoins.fetch_add(1, Relaxed);
                let new: Vec<String> = new.iter().map(ToString::to_string).collect();
                tracing::info!(
                    "ros2: network address {} appeared: rejoining DDS domain {domain} in \
                     {secs} s, so that participants there and the agent discover each other",
                    new.join(", ")
                );
            }
            Ok(End::StrandedPeer(prefix)) => {
                stats.stranded_peer_rejoins.fetch_add(1, Relaxed);
                let prefix: String = prefix.iter().map(|b| format!("{b:02x}")).collect();
                tracing::warn!(
                    "ros2: participant {prefix} still announces itself, but rustdds dropped it \
                     when its lease ran out (a network outage?) and does not take it back: \
                     rejoining DDS domain {domain} in {secs} s so that it is discovered again"
                );
            }
            Err(e @ Ros2Error::Participant { .. }) => {
                tracing::error!("{e}; trying again in {secs} s");
                stats
                    .problems
                    .note(e.to_string().trim_start_matches("ros2: "));
            }
            Err(e) => return Err(e),
        }
        tokio::select! {
            _ = shutdown.cancelled() => return Ok(()),
            _ = tokio::time::sleep(pause) => {}
        }
        pause = (pause * 2).min(std::time::Duration::from_secs(30));
    }
}

/// One participant's bridging, from joining the domain until it ends ([`End`]).
async fn run_participant(
    opts: Ros2Options,
    router: &Arc<Router>,
    stats: &Arc<Stats>,
    interest: &Option<Arc<ReadInterest>>,
    shutdown: &CancellationToken,
) -> Result<End, Ros2Error> {
    let domain = opts.domain_id;
    // Before the participant looks: an address that appears in between is taken for new
    // at the first check (one rejoin too many), never missed.
    let mut addresses = DdsAddresses::now().unwrap_or_default();
    let dp = DomainParticipant::new(domain).map_err(|e| Ros2Error::Participant {
        domain,
        cause: e.to_string(),
    })?;
    let defaults = QosPolicies::qos_none();
    let publisher = dp
        .create_publisher(&defaults)
        .map_err(|e| Ros2Error::Endpoint(e.to_string()))?;
    let subscriber = dp
        .create_subscriber(&defaults)
        .map_err(|e| Ros2Error::Endpoint(e.to_string()))?;
    let (client, outbox) = router.connect(
        ClientKind::Internal {
            role: "ros2".into(),
        },
        None,
    );
    let (peer, peer_rx) = ChannelPeer::new();
    router.calls.attach(client, peer);
    let own = dp.guid();
    let mut changes = opts.changes.clone();
    // A change made while the participant was away is in force from the start.
    let live = match &mut changes {
        Some(rx) => Arc::new(rx.borrow_and_update().clone()),
        None => Arc::new(opts.clone()),
    };
    let bridge = Arc::new(Bridge {
        opts,
        live: std::sync::RwLock::new(live),
        router: router.clone(),
        client,
        stats: stats.clone(),
        dp,
        publisher,
        subscriber,
        own,
        endpoints: Arc::default(),
        state: Mutex::new(State::default()),
        interest: interest.clone(),
    });
    let mut node_info = crate::node_info::NodeInfo::new(&bridge).map_err(Ros2Error::Endpoint)?;
    tracing::info!(
        "ros2: joined DDS domain {domain} as participant {:?}, node {}",
        bridge.dp.guid().prefix,
        node_info.full_name()
    );
    if bridge.opts.parameters {
        fleetlink_relay::params::advertise_services(&router.calls, client);
    }
    services::follow_offers(&bridge);
    follow_subscriptions(&bridge);
    let mut tick = tokio::time::interval(bridge.opts.discovery_period);
    tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    // While a new writer holds messages for its readers to be matched.
    let mut held_tick = tokio::time::interval(std::time::Duration::from_millis(10));
    held_tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    let mut alive_tick = tokio::time::interval(LIVENESS_PERIOD);
    alive_tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    let status = bridge.dp.status_listener();
    let mut events = status.as_async_status_stream();
    let mut lost = crate::lost_peers::LostPeers::default();
    let mut announcements = listen_to_announcements(domain, &addresses);
    let end = loop {
        tokio::select! {
            _ = shutdown.cancelled() => break End::Shutdown,
            _ = alive_tick.tick() => {
                // A command to the discovery thread (it only marks the participant's
                // manual liveliness as asserted); refused once that thread has ended.
                if bridge.dp.assert_liveliness().is_err() {
                    break End::ParticipantStopped;
                }
                let new = addresses.appeared(DdsAddresses::now());
                if !new.is_empty() {
                    break End::NetworkChanged(new);
                }
                if let Some(p) = lost.stranded(Instant::now()) {
                    break End::StrandedPeer(p);
                }
            }
            _ = tick.tick() => {
                discover(&bridge);
                node_info.refresh(&bridge);
            }
            new = fleetlink_relay::live::next_change(&mut changes) => {
                tracing::info!("ros2: what crosses changed (runtime configuration)");
                *bridge.live.write().unwrap_or_else(|p| p.into_inner()) = Arc::new(new);
                services::follow_offers(&bridge);
                follow_subscriptions(&bridge);
                discover(&bridge);
            }
            // (A change between two turns of this loop is seen at the next tick.)
            _ = ReadInterest::changed(interest) => follow_interest(&bridge, Instant::now()),
            _ = outbox.ready() => loop {
                let batch = outbox.take(64, 8 << 20, Instant::now());
                if batch.items.is_empty() {
                    break;
                }
                for (_, _, msg) in batch.items {
                    down(&bridge, &msg);
                }
            },
            Some(m) = peer_rx.recv() => services::on_peer(&bridge, m),
            Some(ev) = events.next() => lost.on_event(&ev, Instant::now()),
            heard = crate::lost_peers::next(&mut announcements) => match heard {
                Ok(sender) => lost.heard(sender, Instant::now()),
                Err(e) => {
                    tracing::debug!("ros2: discovery announcements: {e}; not listening any more");
                    announcements = None;
                }
            },
            _ = held_tick.tick(), if holding(&bridge) => release_held(&bridge),
        }
    };
    leave(&bridge, domain);
    Ok(end)
}

/// The discovery announcements of domain `domain` heard on `addresses`, to notice peers
/// rustdds lost ([`crate::lost_peers`]); `None` when they cannot be heard.
fn listen_to_announcements(
    domain: u16,
    addresses: &DdsAddresses,
) -> Option<crate::lost_peers::Announcements> {
    match crate::lost_peers::Announcements::open(domain, addresses.seen.iter().map(|a| a.addr)) {
        Ok(a) => Some(a),
        Err(e) => {
            // Without a network there is nothing to lose; the rejoin on a new address
            // opens it again.
            tracing::debug!("ros2: not listening to discovery announcements: {e}");
            None
        }
    }
}

/// Ends a participant's bridging: stops the tasks of its topics, services and actions,
/// leaves the router, and logs what crossed.
fn leave(bridge: &Bridge, domain: u16) {
    let st = std::mem::take(&mut *bridge.lock());
    for task in st.up.values().filter_map(|u| u.task.as_ref()) {
        task.abort();
    }
    for r in st.remotes.values() {
        r.abort();
    }
    for o in st.offered.values() {
        o.task.abort();
    }
    for a in st.offered_actions.values() {
        a.abort();
    }
    bridge.router.disconnect(bridge.client);
    let s = &bridge.stats;
    tracing::info!(
        "ros2: left domain {domain}: {} messages up, {} down ({} dropped)",
        s.messages_up.load(Relaxed),
        s.messages_down.load(Relaxed),
        s.dropped_down.load(Relaxed)
    );
}

/// One look at what discovery knows: starts and stops bridged topics, exposed services
/// and actions.
fn discover(bridge: &Arc<Bridge>) {
    let mut writers: HashMap<String, Vec<rustdds::discovery::DiscoveredWriterData>> =
        HashMap::new();
    let opts = bridge.live();
    for w in bridge.dp.discovered_writers() {
        let p = &w.publication_topic_data;
        if bridge.is_own(p.key) {
            continue;
        }
        if let Some(DdsName::Topic(ros)) = DdsName::parse(&p.topic_name)
            && !names::is_hidden(&ros)
            && opts.publish.matches(&ros)
        {
            writers.entry(ros).or_default().push(w);
        }
    }
    let gone: Vec<String> = {
        let mut st = bridge.lock();
        for (ros, ws) in &writers {
            if let Some(up) = st.up.get_mut(ros) {
                up.writers = ws.iter().map(|w| w.publication_topic_data.key).collect();
            }
        }
        st.up
            .keys()
            .filter(|k| !writers.contains_key(*k))
            .cloned()
            .collect()
    };
    for ros in gone {
        stop_up(bridge, &ros);
        if opts.publish.matches(&ros) {
            tracing::info!("ros2: {ros} has no local writers any more: unadvertised");
        } else {
            tracing::info!("ros2: {ros} is no longer in ros2.publish: unadvertised");
        }
    }
    for (ros, ws) in writers {
        if !bridge.lock().up.contains_key(&ros) {
            start_up(bridge, &ros, &ws);
        }
    }
    follow_interest(bridge, Instant::now());
    follow_readers(bridge);
    services::discover(bridge);
}
