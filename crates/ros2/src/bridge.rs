//! The participant and its loop: discovery, topics up and down, the call table's side.
//!
//! One task ([`run`]) owns the router client's outbox, the call-table channel and the
//! discovery tick; each bridged-up topic has a task reading its DDS reader, each exposed
//! service or action a task reading its replies ([`crate::services`]). rustdds runs its
//! own network threads; its readers are polled as async streams here, its writers are
//! written without waiting (keep-last history never blocks).

use std::collections::{HashMap, HashSet};
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Instant;

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::ChannelPeer;
use fleetlink_relay::names::ClientId;
use fleetlink_relay::read_interest::{Look, ReadInterest};
use fleetlink_relay::router::{RouteError, SubOptions, SubscriptionId, Target};
use fleetlink_relay::stats::{AdapterReport, Problems};
use fleetlink_relay::{ClientKind, Message, Router, Topic, TopicName};
use futures::StreamExt;
use rustdds::no_key::{DataReader, DataWriter};
use rustdds::{
    DomainParticipant, GUID, Publisher, QosPolicies, RTPSEntity, StatusEvented, Subscriber,
    TopicKind,
};
use tokio::task::AbortHandle;
use tokio_util::sync::CancellationToken;

use crate::names::{self, DdsName};
use crate::offered_actions::OfferedAction;
use crate::options::Ros2Options;
use crate::raw::{RawAdapter, RawCdr};
use crate::services::{self, Offered, Remote};

/// A reader or writer of this bridge, listed among its node's endpoints while it lives.
pub type RawReader = Tracked<DataReader<RawCdr, RawAdapter>>;
pub type RawWriter = Tracked<DataWriter<RawCdr, RawAdapter>>;

/// The GUIDs of the bridge's own readers and writers (`true`: a writer): what its node
/// lists in `ros_discovery_info` ([`crate::node_info`]).
#[derive(Debug, Default)]
pub(crate) struct OwnEndpoints(Mutex<HashMap<GUID, bool>>);

impl OwnEndpoints {
    fn lock(&self) -> MutexGuard<'_, HashMap<GUID, bool>> {
        self.0.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// The readers' and the writers' GUIDs, each sorted.
    pub(crate) fn list(&self) -> (Vec<GUID>, Vec<GUID>) {
        let all = self.lock();
        let mut readers: Vec<GUID> = all.iter().filter(|(_, w)| !**w).map(|(g, _)| *g).collect();
        let mut writers: Vec<GUID> = all.iter().filter(|(_, w)| **w).map(|(g, _)| *g).collect();
        readers.sort_by_key(|g| g.to_bytes());
        writers.sort_by_key(|g| g.to_bytes());
        (readers, writers)
    }
}

/// A DDS entity of the bridge with its entry in [`OwnEndpoints`], removed when it is
/// dropped (with the entity).
pub struct Tracked<T> {
    inner: T,
    _entry: Entry,
}

#[derive(Debug)]
struct Entry(Arc<OwnEndpoints>, GUID);

impl Drop for Entry {
    fn drop(&mut self) {
        self.0.lock().remove(&self.1);
    }
}

impl<T> std::ops::Deref for Tracked<T> {
    type Target = T;
    fn deref(&self) -> &T {
        &self.inner
    }
}

impl<T> std::ops::DerefMut for Tracked<T> {
    fn deref_mut(&mut self) -> &mut T {
        &mut self.inner
    }
}

impl RawReader {
    /// The reader's samples as a stream, which keeps the reader listed while it lives.
    pub fn async_sample_stream(
        self,
    ) -> Tracked<rustdds::no_key::DataReaderStream<RawCdr, RawAdapter>> {
        Tracked {
            inner: self.inner.async_sample_stream(),
            _entry: self._entry,
        }
    }
}

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

/// A local topic sent up: its router topic, the writers feeding it, its reader task
/// (none while nobody wants the topic read), and what makes its reader again.
struct Up {
    writers: HashSet<GUID>,
    task: Option<AbortHandle>,
    reading: Arc<Reading>,
    /// Since when nobody has wanted it, while that lasts.
    unwanted_since: Option<Instant>,
}

/// What a bridged-up topic's reader is made from, kept while the topic is not read.
struct Reading {
    dds_topic: String,
    dds_type: String,
    qos: QosPolicies,
    topic: Arc<Topic>,
    /// Numbers of the messages put into the router, across readers.
    seq: AtomicU64,
}

/// A router topic written into the graph.
struct Down {
    writer: RawWriter,
    type_name: String,
    /// Set while a new writer waits to be matched (see [`Held`]).
    held: Option<Held>,
}

/// How long a new writer's first messages wait for the local readers DDS discovery knew
/// of when the writer was made.
const DOWN_MATCH_WAIT: std::time::Duration = std::time::Duration::from_millis(1000);

/// How long held messages still wait once the bridge's writer has matched the readers:
/// matching is two-sided, and DDS tells only the writer's side. The reader's side takes
/// the writer's announcement on its own discovery thread (Cyclone: a queue of its own),
/// and until it has, it drops what the writer sends. On a loaded machine that took
/// longer than sending the first message right after the writer's side matched (the
/// ROS 2 suite's step 2c failed once in CI that way).
const DOWN_REMOTE_GRACE: std::time::Duration = std::time::Duration::from_millis(150);

/// A new writer's messages, held until it has matched the local readers of its topic
/// that discovery knew of when it was made, and [`DOWN_REMOTE_GRACE`] more (or until
/// [`DOWN_MATCH_WAIT`] has passed). A volatile reader only gets what is written after it
/// is matched: without this, a node waiting for a hub topic missed its first message,
/// written while DDS was still matching the bridge's new writer with it.
struct Held {
    readers: i32,
    until: Instant,
    /// When the writer's side had matched every known reader.
    matched_at: Option<Instant>,
    bodies: std::collections::VecDeque<Bytes>,
}

impl Down {
    /// Whether held messages may go: every known reader matched, or waited long enough.
    fn matched(&mut self, now: Instant) -> bool {
        let Some(h) = &mut self.held else {
            return true;
        };
        while let Some(ev) = self.writer.try_recv_status() {
            if let rustdds::DataWriterStatus::PublicationMatched { current, .. } = ev
                && current.count() >= h.readers
            {
                h.matched_at.get_or_insert(now);
            }
        }
        h.matched_at
            .is_some_and(|t| now.duration_since(t) >= DOWN_REMOTE_GRACE)
            || now >= h.until
    }

    /// Writes `body`, or holds it while the writer is not matched yet (the oldest held
    /// message is dropped beyond the writer's depth, as its history would).
    fn write(&mut self, body: Bytes, stats: &Stats) {
        let now = Instant::now();
        if !self.matched(now) {
            let h = self.held.as_mut().expect("held while not matched");
            h.bodies.push_back(body);
            if h.bodies.len() > crate::qos::DEPTH as usize {
                h.bodies.pop_front();
                stats.dropped_down.fetch_add(1, Relaxed);
            }
            return;
        }
        for b in self.held.take().map(|h| h.bodies).unwrap_or_default() {
            self.write_now(b, stats);
        }
        self.write_now(body, stats);
    }

    /// Sends what was held once the writer is matched or the wait is over.
    fn release(&mut self, stats: &Stats) {
        if self.held.is_some() && self.matched(Instant::now()) {
            for b in self.held.take().map(|h| h.bodies).unwrap_or_default() {
                self.write_now(b, stats);
            }
        }
    }

    fn write_now(&self, body: Bytes, stats: &Stats) {
        match self.writer.write(RawCdr(body), None) {
            Ok(()) => {
                stats.messages_down.fetch_add(1, Relaxed);
            }
            Err(e) => {
                stats.dropped_down.fetch_add(1, Relaxed);
                tracing::debug!("ros2: writing a {} message: {e:?}", self.type_name);
            }
        }
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
        self.endpoints.lock().insert(guid, writer);
        Tracked {
            inner,
            _entry: Entry(self.endpoints.clone(), guid),
        }
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

/// How often the bridge checks that rustdds' threads still run.
const LIVENESS_PERIOD: std::time::Duration = std::time::Duration::from_secs(2);

/// How one participant's bridging ended.
enum End {
    Shutdown,
    /// rustdds' own threads have ended: nothing more arrives or leaves.
    ParticipantStopped,
    /// Addresses appeared that the participant does not use (see [`DdsAddresses`]).
    NetworkChanged(Vec<DdsAddress>),
    /// rustdds lost this participant by lease and does not take it back, though it still
    /// announces itself (see [`crate::lost_peers`]).
    StrandedPeer(crate::lost_peers::Prefix),
}

/// One IPv4 address of a multicast-capable interface: where rustdds joins DDS discovery.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
struct DdsAddress {
    interface: String,
    /// The interface's index: a device removed and added again is a new one (its
    /// multicast memberships went with the old device).
    index: u32,
    addr: std::net::Ipv4Addr,
}

impl std::fmt::Display for DdsAddress {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} {}", self.interface, self.addr)
    }
}

/// The host's addresses as rustdds sees them when a participant starts.
///
/// rustdds joins DDS multicast and picks the unicast addresses it announces once, when a
/// participant is created, from the interfaces then up. An agent started before the robot's
/// network (at boot, before DHCP; a USB Ethernet plugged in later; a Wi-Fi address that
/// changed) would never discover the participants on the new network, nor be discovered by
/// them. The bridge compares the addresses with the last look every [`LIVENESS_PERIOD`]
/// and rejoins the graph when one appeared. One that only went away changes nothing.
#[derive(Debug, Default)]
struct DdsAddresses {
    seen: std::collections::BTreeSet<DdsAddress>,
}

impl DdsAddresses {
    /// The addresses now; `None` when the system cannot say (nothing is concluded then).
    fn now() -> Option<DdsAddresses> {
        use nix::net::if_::InterfaceFlags;
        let mut seen = std::collections::BTreeSet::new();
        // getifaddrs(3): tens of microseconds (netdev, which rustdds uses, also reads
        // each interface's files in /sys: ten times that).
        for a in nix::ifaddrs::getifaddrs().ok()? {
            // As rustdds chooses where to join multicast: the flag, IPv4 only.
            if !a.flags.contains(InterfaceFlags::IFF_MULTICAST) {
                continue;
            }
            let Some(v4) = a.address.as_ref().and_then(|s| s.as_sockaddr_in()) else {
                continue;
            };
            let index = nix::net::if_::if_nametoindex(a.interface_name.as_str()).unwrap_or(0);
            seen.insert(DdsAddress {
                interface: a.interface_name,
                index,
                addr: v4.ip(),
            });
        }
        Some(DdsAddresses { seen })
    }

    /// Takes a new look; returns the addresses that appeared since the last one.
    fn appeared(&mut self, now: Option<DdsAddresses>) -> Vec<DdsAddress> {
        let Some(now) = now else {
            return Vec::new();
        };
        let new = now.seen.difference(&self.seen).cloned().collect();
        *self = now;
        new
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
    follow_offers(&bridge);
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
    let mut announcements =
        match crate::lost_peers::Announcements::open(domain, addresses.seen.iter().map(|a| a.addr))
        {
            Ok(a) => Some(a),
            Err(e) => {
                // Without a network there is nothing to lose; the rejoin on a new address
                // opens it again.
                tracing::debug!("ros2: not listening to discovery announcements: {e}");
                None
            }
        };
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
                follow_offers(&bridge);
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
    router.disconnect(client);
    let s = &bridge.stats;
    tracing::info!(
        "ros2: left domain {domain}: {} messages up, {} down ({} dropped)",
        s.messages_up.load(Relaxed),
        s.messages_down.load(Relaxed),
        s.dropped_down.load(Relaxed)
    );
    Ok(end)
}

/// Watches the fleet services and actions the options offer to local nodes, and stops
/// offering those they no longer do (after a runtime change).
fn follow_offers(bridge: &Arc<Bridge>) {
    let opts = bridge.live();
    let (services, actions) = {
        let mut st = bridge.lock();
        let services: Vec<_> = st
            .offered
            .keys()
            .filter(|n| !opts.offer.matches(n))
            .cloned()
            .collect();
        let actions: Vec<_> = st
            .offered_actions
            .keys()
            .filter(|n| !opts.offer_actions.matches(n))
            .cloned()
            .collect();
        (
            services
                .into_iter()
                .filter_map(|n| st.offered.remove(&n).map(|o| (n, o)))
                .collect::<Vec<_>>(),
            actions
                .into_iter()
                .filter_map(|n| st.offered_actions.remove(&n).map(|a| (n, a)))
                .collect::<Vec<_>>(),
        )
    };
    for (name, o) in services {
        o.task.abort();
        tracing::info!("ros2: fleet service {name} no longer offered to local nodes");
    }
    for (name, a) in actions {
        a.abort();
        tracing::info!("ros2: fleet action {name} no longer offered to local nodes");
    }
    // Watched anew: the services that match now are told at once (those offered already
    // stay as they are).
    bridge.router.calls.unwatch(bridge.client);
    for re in opts.offer.include.iter().chain(&opts.offer_actions.include) {
        bridge.router.calls.watch(bridge.client, re.clone());
    }
}

/// Subscribes the router topics the options write into the graph, and lets go of those
/// they no longer do (with their DDS writers).
fn follow_subscriptions(bridge: &Bridge) {
    let opts = bridge.live();
    let gone: Vec<(String, SubscriptionId)> = {
        let mut st = bridge.lock();
        let names: Vec<String> = st
            .subscribed
            .keys()
            .filter(|k| !opts.subscribe.iter().any(|n| n.as_str() == k.as_str()))
            .cloned()
            .collect();
        names
            .into_iter()
            .filter_map(|k| {
                st.down.remove(&k);
                st.subscribed.remove_entry(&k)
            })
            .collect()
    };
    for (name, sid) in gone {
        bridge.router.unsubscribe(bridge.client, sid);
        tracing::info!("ros2: no longer writing {name} into the graph");
    }
    for name in &opts.subscribe {
        if bridge.lock().subscribed.contains_key(name.as_str()) {
            continue;
        }
        match bridge.router.subscribe(
            bridge.client,
            Target::Exact(name.clone()),
            SubOptions::default(),
        ) {
            Ok(sid) => {
                bridge.lock().subscribed.insert(name.to_string(), sid);
            }
            Err(e) => tracing::warn!("ros2: cannot subscribe to {name}: {e}"),
        }
    }
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

/// Subscribes the router topics `read` matches that a node of the graph reads (a reader
/// other than the bridge's), and lets go of those whose last reader went: what no node
/// reads is not asked for, so its robot does not send it.
fn follow_readers(bridge: &Bridge) {
    let opts = bridge.live();
    if opts.read.is_empty() && bridge.lock().read.is_empty() {
        return;
    }
    let mut readers: HashSet<String> = HashSet::new();
    for r in bridge.dp.discovered_readers() {
        let s = &r.subscription_topic_data;
        if bridge.is_own(s.key()) {
            continue;
        }
        if let Some(DdsName::Topic(ros)) = DdsName::parse(s.topic_name())
            && !names::is_hidden(&ros)
            && opts.read.matches(&ros)
            && !opts.subscribe.iter().any(|n| n.as_str() == ros)
        {
            readers.insert(ros);
        }
    }
    let (gone, new): (Vec<(String, SubscriptionId)>, Vec<String>) = {
        let mut st = bridge.lock();
        let gone: Vec<String> = st
            .read
            .keys()
            .filter(|k| !readers.contains(*k))
            .cloned()
            .collect();
        let gone = gone
            .into_iter()
            .filter_map(|k| st.read.remove_entry(&k))
            .collect();
        let new = readers
            .into_iter()
            .filter(|k| !st.read.contains_key(k))
            .collect();
        (gone, new)
    };
    for (ros, sid) in gone {
        bridge.router.unsubscribe(bridge.client, sid);
        tracing::info!("ros2: no node reads {ros} any more; no longer asking for it");
    }
    for ros in new {
        let name = match TopicName::parse(&ros) {
            Ok(n) => n,
            Err(e) => {
                tracing::debug!("ros2: a reader of {ros}, which is no topic name here: {e}");
                continue;
            }
        };
        match bridge
            .router
            .subscribe(bridge.client, Target::Exact(name), SubOptions::default())
        {
            Ok(sid) => {
                tracing::info!("ros2: a node reads {ros}; asking for it");
                bridge.lock().read.insert(ros, sid);
            }
            Err(e) => tracing::warn!("ros2: cannot ask for {ros}: {e}"),
        }
    }
}

/// Drops the reader of each topic nobody has wanted for a while ([`ReadInterest::look`]; the
/// local writers then stop sending to the agent) and makes one again for each topic
/// wanted again.
fn follow_interest(bridge: &Arc<Bridge>, now: Instant) {
    let Some(interest) = &bridge.interest else {
        return;
    };
    let mut resume = Vec::new();
    {
        let mut st = bridge.lock();
        for (ros, up) in st.up.iter_mut() {
            let name = up.reading.topic.name();
            match interest.look(&name, bridge.client, &mut up.unwanted_since, now) {
                Look::Read if up.task.is_none() => resume.push(ros.clone()),
                Look::Stop => {
                    if let Some(task) = up.task.take() {
                        task.abort(); // the reader goes with its task
                        interest.stopped_reading(&name);
                        bridge.stats.paused_reading.fetch_add(1, Relaxed);
                        tracing::info!("ros2: nobody wants {ros}; no longer reading it");
                    }
                }
                _ => {}
            }
        }
    }
    for ros in resume {
        let Some(reading) = bridge.lock().up.get(&ros).map(|u| u.reading.clone()) else {
            continue;
        };
        match bridge.reader(&reading.dds_topic, &reading.dds_type, reading.qos.clone()) {
            Ok(reader) => {
                let task = tokio::spawn(pump_up(bridge.clone(), reading, reader)).abort_handle();
                if let Some(up) = bridge.lock().up.get_mut(&ros) {
                    up.task = Some(task);
                }
                tracing::info!("ros2: {ros} is wanted again; reading it");
            }
            Err(e) => tracing::warn!("ros2: cannot read {ros} again: {e}"),
        }
    }
}

/// Starts bridging local topic `ros` up, with a reader matching its first writer.
fn start_up(bridge: &Arc<Bridge>, ros: &str, writers: &[rustdds::discovery::DiscoveredWriterData]) {
    let p = &writers[0].publication_topic_data;
    let Some(ros_type) = names::ros_type(&p.type_name) else {
        bridge.report_once(ros, &bridge.stats.unknown_types, || {
            format!(
                "ros2: not bridging {ros}: its DDS type {:?} is not a ROS 2 type name (pkg::msg::dds_::T_)",
                p.type_name
            )
        });
        return;
    };
    let Some(schema) = bridge.schema(&ros_type) else {
        bridge.report_once(ros, &bridge.stats.unknown_types, || {
            format!(
                "ros2: not bridging {ros}: type {ros_type} is unknown to the agent's registry; \
                 give the agent its package with --msg-path DIR (DIR/<package>/msg/<Type>.msg)"
            )
        });
        return;
    };
    let Ok(name) = TopicName::parse(ros) else {
        return;
    };
    // Latched when any writer keeps its last message for late readers.
    let latched = writers.iter().any(|w| {
        matches!(
            w.publication_topic_data.durability,
            Some(rustdds::policy::Durability::TransientLocal)
        )
    });
    let reliable = writers.iter().all(|w| {
        !matches!(
            w.publication_topic_data.reliability,
            Some(rustdds::policy::Reliability::BestEffort)
        )
    });
    let qos = crate::qos::reader_for(
        Some(if reliable {
            rustdds::policy::Reliability::Reliable {
                max_blocking_time: rustdds::Duration::from_millis(100),
            }
        } else {
            rustdds::policy::Reliability::BestEffort
        }),
        latched.then_some(rustdds::policy::Durability::TransientLocal),
        crate::qos::reader_depth(&ros_type),
    );
    let topic = match bridge
        .router
        .advertise(bridge.client, &name, schema, latched)
    {
        Ok(t) => t,
        Err(RouteError::TypeConflict { existing, .. }) => {
            bridge.report_once(ros, &bridge.stats.type_mismatches, || {
                format!(
                    "ros2: type mismatch on {ros}: the agent's topic is {existing}, local writers send {ros_type}; \
                     {ros} is not bridged, other topics are unaffected"
                )
            });
            return;
        }
        Err(e) => {
            tracing::warn!("ros2: cannot bridge {ros}: {e}");
            return;
        }
    };
    let reader = match bridge.reader(&p.topic_name, &p.type_name, qos.clone()) {
        Ok(r) => r,
        Err(e) => {
            tracing::warn!("ros2: cannot bridge {ros}: {e}");
            bridge.router.unadvertise(bridge.client, &name);
            return;
        }
    };
    tracing::info!(
        "ros2: receiving {ros} ({ros_type}{}{})",
        if latched { ", latched" } else { "" },
        if reliable { "" } else { ", best effort" }
    );
    let reading = Arc::new(Reading {
        dds_topic: p.topic_name.clone(),
        dds_type: p.type_name.clone(),
        qos,
        topic,
        seq: AtomicU64::new(0),
    });
    let task = tokio::spawn(pump_up(bridge.clone(), reading.clone(), reader)).abort_handle();
    bridge.lock().up.insert(
        ros.to_owned(),
        Up {
            writers: writers
                .iter()
                .map(|w| w.publication_topic_data.key)
                .collect(),
            task: Some(task),
            reading,
            unwanted_since: None,
        },
    );
}

/// `ros` is no longer bridged (its local writers are gone, or `publish` no longer has it):
/// stop reading it and unadvertise it.
fn stop_up(bridge: &Bridge, ros: &str) {
    let Some(up) = bridge.lock().up.remove(ros) else {
        return;
    };
    if let Some(task) = up.task {
        task.abort();
    }
    if let Ok(name) = TopicName::parse(ros) {
        bridge.router.unadvertise(bridge.client, &name);
    }
}

/// Forwards a reader's samples to the router as they arrived.
async fn pump_up(bridge: Arc<Bridge>, reading: Arc<Reading>, reader: RawReader) {
    let topic = &reading.topic;
    let mut samples = reader.async_sample_stream();
    while let Some(r) = samples.next().await {
        match r {
            Ok(sample) => {
                // Our own writer on the same topic (bridged both ways): never back up.
                if bridge.is_own(sample.sample_info().writer_guid()) {
                    continue;
                }
                let seq = reading.seq.fetch_add(1, Relaxed) + 1;
                topic.publish(
                    bridge.client,
                    seq,
                    fleetlink_relay::unix_nanos(),
                    Payload::new(Encoding::Cdr, sample.into_value().0),
                );
                bridge.stats.messages_up.fetch_add(1, Relaxed);
            }
            Err(e) => tracing::debug!("ros2: reading {}: {e}", topic.name()),
        }
    }
}

/// A router message for the graph, written by the topic's writer (created on the first
/// message, with the topic's type and latching).
fn down(bridge: &Bridge, msg: &Message) {
    let name = msg.topic.name.as_str();
    let mut st = bridge.lock();
    let entry = st
        .down
        .entry(name.to_owned())
        .or_insert_with(|| create_down(bridge, msg));
    let Some(d) = entry else {
        bridge.stats.dropped_down.fetch_add(1, Relaxed);
        return;
    };
    let body = match bridge.to_cdr(&d.type_name, &msg.payload) {
        Ok(b) => b,
        Err(e) => {
            bridge.stats.dropped_down.fetch_add(1, Relaxed);
            tracing::debug!("ros2: dropping a message of {name}: {e}");
            return;
        }
    };
    d.write(body, &bridge.stats);
}

/// Whether a new writer holds messages ([`Held`]).
fn holding(bridge: &Bridge) -> bool {
    bridge
        .lock()
        .down
        .values()
        .any(|d| d.as_ref().is_some_and(|d| d.held.is_some()))
}

/// Sends held messages of writers now matched (or done waiting).
fn release_held(bridge: &Bridge) {
    let mut st = bridge.lock();
    for d in st.down.values_mut().flatten() {
        d.release(&bridge.stats);
    }
}

/// The writer of a router topic; `None` (remembered, reported once) when its type cannot
/// be written.
fn create_down(bridge: &Bridge, msg: &Message) -> Option<Down> {
    let name = msg.topic.name.as_str();
    let type_name = &msg.topic.schema.type_name;
    let Some(dds_type) = names::dds_type(type_name) else {
        tracing::warn!(
            "ros2: cannot write {name} into the graph: {type_name:?} is not a ROS type name"
        );
        return None;
    };
    let latched = bridge
        .router
        .topic(&msg.topic.name)
        .is_some_and(|t| t.is_latched());
    let dds_topic = names::topic(name);
    match bridge.writer(&dds_topic, &dds_type, crate::qos::writer(latched)) {
        Ok(writer) => {
            // Local readers already waiting for the topic: the first messages wait for
            // them to be matched.
            let readers = bridge
                .dp
                .discovered_readers()
                .iter()
                .filter(|r| {
                    let s = &r.subscription_topic_data;
                    s.topic_name() == &dds_topic && !bridge.is_own(s.key())
                })
                .count();
            tracing::info!(
                "ros2: writing {name} ({type_name}{}) into the graph, {readers} local reader(s) known",
                if latched { ", transient local" } else { "" }
            );
            let held = (readers > 0).then(|| Held {
                readers: i32::try_from(readers).unwrap_or(i32::MAX),
                until: Instant::now() + DOWN_MATCH_WAIT,
                matched_at: None,
                bodies: Default::default(),
            });
            Some(Down {
                writer,
                type_name: type_name.clone(),
                held,
            })
        }
        Err(e) => {
            tracing::warn!("ros2: cannot write {name} into the graph: {e}");
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{DdsAddress, DdsAddresses};

    fn set(list: &[(&str, u32, [u8; 4])]) -> Option<DdsAddresses> {
        let seen = list
            .iter()
            .map(|(interface, index, a)| DdsAddress {
                interface: (*interface).into(),
                index: *index,
                addr: (*a).into(),
            })
            .collect();
        Some(DdsAddresses { seen })
    }

    #[test]
    fn an_address_that_appears_is_reported_once_and_one_that_goes_is_not() {
        let mut a = DdsAddresses::default();
        let lo = ("lo", 1, [127, 0, 0, 1]);
        let wlan = ("wlan0", 3, [10, 0, 0, 5]);
        assert_eq!(
            a.appeared(set(&[lo])).len(),
            1,
            "the first look after an empty one"
        );
        assert!(a.appeared(set(&[lo])).is_empty());
        let new = a.appeared(set(&[lo, wlan]));
        assert_eq!(new.len(), 1);
        assert_eq!(new[0].to_string(), "wlan0 10.0.0.5");
        assert!(a.appeared(set(&[lo, wlan])).is_empty(), "reported once");
        assert!(a.appeared(set(&[lo])).is_empty(), "gone: nothing to join");
        assert_eq!(a.appeared(set(&[lo, wlan])).len(), 1, "back: joined again");
        let replugged = ("wlan0", 4, [10, 0, 0, 5]);
        assert_eq!(
            a.appeared(set(&[lo, replugged])).len(),
            1,
            "the same address on a new device (its memberships went with the old one)"
        );
        assert!(
            a.appeared(None).is_empty(),
            "no answer from the system: no conclusion"
        );
        assert!(a.appeared(set(&[lo, replugged])).is_empty());
    }
}
