//! The agent's link to the hub.
//!
//! The uplink is a participant of the agent's local router like any other: it subscribes
//! to every local topic (its outbox is what goes up the link) and publishes what comes
//! down from the hub under local names. Its outbox lives across reconnects, so messages
//! produced while the link is down wait in bounded queues instead of vanishing.
//!
//! Each connection: `HELLO` → `WELCOME` (the hub names the robot's namespace), then every
//! local topic is advertised and every subscription sent exactly once; a heartbeat `PING`
//! goes out every interval and a link silent for twice the interval is declared dead even
//! if TCP has not noticed.
//!
//! Every connection starts from a clean slate of in-flight state ([`Outbox::on_link_reset`]):
//! what the dead connection carried is no longer counted against the window, and no-drop
//! messages it carried without a `DELIVERED` go first again, in order.
//!
//! Reconnecting distinguishes whose fault a failure is. When the robot's own link is down
//! an attempt is cheap — with no route at all it fails in the local kernel (retried every
//! 50–100 ms), otherwise it costs one SYN (retried every 125–500 ms) — so the agent is back
//! within a fraction of a second of the link returning. When the hub refuses, fails or is
//! overloaded, attempts back off exponentially with full jitter (and never sooner than a
//! `Retry-After` the hub sent), so a fleet does not stampede a restarted hub.
//!
//! With several hub URLs the agent fails over between them (`failover`): it stays on the
//! hub it is connected to, moves on to the next at once when an attempt fails, and waits
//! only after a full round through the list.

mod connect;
mod connection;
mod events;
mod failover;
mod failure;
mod report;

use std::collections::{HashMap, HashSet};
use std::sync::Arc;
use std::sync::atomic::Ordering::Relaxed;
use std::time::{Duration, Instant};

use fleetlink_proto::frame::{
    CallStatus, Frame, SUBSCRIBE_REGEX, SUBSCRIBE_SERVICES, WELCOME_COMPRESSION, WELCOME_INTEREST,
};
use fleetlink_proto::{Encoding, SUBPROTOCOL};
use fleetlink_qos::{SchedulerConfig, TopicQos, TopicQosSpec};
use fleetlink_relay::calls::{ChannelPeer, PeerMsg, PeerReceiver, ServiceChange};
use fleetlink_relay::link::session::{
    AgentHello, CloseReason, Event, LinkSession, Role, SessionConfig, system_wall_clock,
};
use fleetlink_relay::link::{
    Control, ControlSender, LinkEvent, LinkNamer, ViaOut, drive, write_link,
};
use fleetlink_relay::link_calls::{LinkCalls, LinkNames};
use fleetlink_relay::message::TopicMeta;
use fleetlink_relay::outbox::QosFor;
use fleetlink_relay::reliable::ReliableOut;
use fleetlink_relay::router::{SubOptions, Target, TopicsWatch};
use fleetlink_relay::websocket::ClientMessage;
use fleetlink_relay::{
    ClientId, ClientKind, DropReason, Outbox, Router, Topic, TopicId, TopicName,
};
use futures_util::{SinkExt, StreamExt};
use tokio::sync::{mpsc, watch};
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_tungstenite::tungstenite::client::IntoClientRequest;
use tokio_tungstenite::tungstenite::http::HeaderValue;
use tokio_util::sync::CancellationToken;

use connect::connect_staggered;
use events::restore;
use failover::{Backoff, Failover};
pub use failure::retry_after;
use failure::{Failure, FailureLog, handshake_failure, refusal};
use report::Told;

/// Messages a robot's no-drop stream may have waiting in a hub's uplink without a durable
/// outbox (with one, only its byte bound counts).
const INHERITED_NO_DROP_QUEUE: usize = 100_000;

/// How often the agent looks whether its demand and link figures changed enough to tell
/// the hub ([`link_figures_moved`]).
const LINK_REPORT_INTERVAL: Duration = Duration::from_secs(1);

/// How long connecting plus the `HELLO`/`WELCOME` exchange may take.
const HANDSHAKE_TIMEOUT: Duration = Duration::from_secs(10);
/// How long a TCP connect may take before the link is taken to be down (one SYN
/// retransmission fits; a healthy 4G link answers well within it).
const CONNECT_TIMEOUT: Duration = Duration::from_secs(3);
/// While a TCP connect has not completed, another is started this often (at most
/// [`CONNECT_RACE`] at once; the first to complete is kept). A link that has just come
/// back often loses its first packets, and the kernel resends a lost SYN only after 1 s
/// (then 1 s or 2 s later, by kernel version); a fresh SYN every quarter second bounds the
/// wait once the path is back.
const CONNECT_STAGGER: Duration = Duration::from_millis(250);
/// Most TCP connects in flight at once for one connection attempt.
const CONNECT_RACE: usize = 8;
/// Unsent bytes the kernel may hold for the link (`TCP_NOTSENT_LOWAT`): the rest waits in
/// the scheduler, where a priority message can still overtake it.
const NOTSENT_LOWAT: u32 = 16 * 1024;
/// How often the durable outbox gets a chance to sync pending writes.
const JOURNAL_TICK: Duration = Duration::from_secs(1);
/// Frames between the session and the link's writer (see the hub's agent driver: the
/// session keeps what does not fit, and stops taking call-table news meanwhile).
const WRITER_QUEUE: usize = 1024;

/// The WebSocket settings of the link to the hub.
///
/// tungstenite zeroes the free part of its read buffer before every read, including the
/// reads that find nothing: with its 128 KiB default, an agent sending 10 MB/s of point
/// clouds zeroed about 25 MB/s to read the hub's small acknowledgements (3 % of its
/// thread). 16 KiB reads still take a large hub message in a few reads: a frame's whole
/// length is reserved once its header is read.
fn uplink_ws_config() -> tokio_tungstenite::tungstenite::protocol::WebSocketConfig {
    tokio_tungstenite::tungstenite::protocol::WebSocketConfig::default()
        .read_buffer_size(UPLINK_READ_BUFFER)
}

/// Bytes the agent's link to the hub reads at most at a time.
const UPLINK_READ_BUFFER: usize = 16 * 1024;

/// Local ↔ hub topic names.
#[derive(Debug, Clone, Default)]
pub struct NameMap {
    /// Local name → hub name, overriding the namespace rule.
    pub remap: Vec<(TopicName, TopicName)>,
    /// Hub topics the robot receives, with their local names.
    pub subscribe: Vec<(TopicName, TopicName)>,
}

impl NameMap {
    /// The hub name of a local topic: a remap if one is configured, else the topic under
    /// the robot's namespace.
    pub fn to_hub(&self, local: &TopicName, namespace: &str) -> TopicName {
        self.remap
            .iter()
            .find(|(l, _)| l == local)
            .map(|(_, h)| h.clone())
            .unwrap_or_else(|| local.in_namespace(namespace))
    }

    /// The local name of a hub topic, if the robot receives it.
    pub fn to_local(&self, hub: &TopicName, namespace: &str) -> Option<TopicName> {
        if let Some((_, l)) = self.subscribe.iter().find(|(h, _)| h == hub) {
            return Some(l.clone());
        }
        if let Some((l, _)) = self.remap.iter().find(|(_, h)| h == hub) {
            return Some(l.clone());
        }
        hub.strip_namespace(namespace)
    }
}

/// Uplink settings.
#[derive(Debug, Clone)]
pub struct UplinkConfig {
    /// The hubs, in the order to try them (the agent stays on the one it is connected to
    /// and moves on when it fails; docs/config.md, "Several hubs"); at least one.
    pub hub_urls: Vec<String>,
    pub robot: fleetlink_auth::RobotName,
    pub token: String,
    pub heartbeat: Duration,
    pub reconnect_initial: Duration,
    pub reconnect_max: Duration,
    pub names: NameMap,
    /// Per-topic QoS of what goes up (priority, rate limit, drop policy, queue length);
    /// topics not listed get the defaults for their type.
    pub topic_qos: Vec<(TopicName, TopicQosSpec)>,
    /// Messages sent but not yet acknowledged by the hub at which sending pauses (nT).
    pub max_in_flight: usize,
    /// TLS for a `wss://` hub: trusted roots and, for mutual TLS, the robot's
    /// certificate. `None` with `wss://` fails the handshake (no roots are built in).
    pub tls: Option<Arc<rustls::ClientConfig>>,
    /// The durable outbox for no-drop topics; `None` keeps them in memory only.
    pub outbox: Option<crate::outbox_store::OutboxStoreConfig>,
    /// Most bytes of topics' latest messages kept (see [`Outbox::set_latest_limit`]).
    pub latest_cache_bytes: usize,
    /// The robot's data budget, if any (`link.budget`).
    pub budget: Option<fleetlink_qos::BudgetConfig>,
    /// Set when the router is a hub's (a site hub's link upstream): that hub's id. What
    /// goes up is marked with the hubs it passed (`VIA`), and what comes back down having
    /// passed this hub is dropped.
    pub hub_id: Option<u64>,
    /// What the hub upstream may do here, when the router is a hub's: see and call its
    /// services, publish down to it, receive its topics. `None` lets it do everything (a
    /// robot's hub acts for its operators, whose rights it checks itself).
    pub upstream_gate: Option<GateFactory>,
    /// The robot this agent mirrors (docs/mirror.md): `robot` is the mirror's own name,
    /// the hub puts its topics in the mirrored robot's namespace, and it asks the hub for
    /// each of that robot's topics only while a local subscriber wants it.
    pub mirror: Option<fleetlink_auth::RobotName>,
}

/// A mirror's subscriptions at the hub: the robot's topics local subscribers want, by
/// local name, with the `SUBSCRIBE` id of each (on one connection).
#[derive(Default)]
struct MirrorSubs {
    by_name: HashMap<TopicName, u32>,
    next_id: u32,
}

/// Ids of a mirror's `SUBSCRIBE`s (clear of the fixed ones and the services').
const MIRROR_SUBSCRIPTIONS: u32 = 1 << 20;

/// Makes the gate a connection upstream checks the hub upstream's doings with (one for the
/// session, one for the link's writer).
#[derive(Clone)]
pub struct GateFactory(pub Arc<dyn Fn() -> Box<dyn fleetlink_relay::gate::Gate> + Send + Sync>);

impl std::fmt::Debug for GateFactory {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("GateFactory")
    }
}

/// The link's state, observable by tests, the CLI and the status topic. `hub` is the URL
/// being tried or connected to (one of [`UplinkConfig::hub_urls`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LinkState {
    Connecting {
        attempt: u32,
        hub: String,
    },
    Connected {
        session: String,
        namespace: String,
        hub: String,
    },
    Disconnected {
        reason: String,
    },
}

/// Counters of the uplink, for status display and tests.
#[derive(Debug, Default)]
pub struct UplinkStats {
    pub connects: std::sync::atomic::AtomicU64,
    pub rtt_ns: std::sync::atomic::AtomicU64,
    /// The hub's capacity share for this robot, bytes/s (0 = none received / no cap).
    pub share_bps: std::sync::atomic::AtomicU64,
}

/// Service names between the robot and the hub: the robot's own services go up under its
/// namespace (or their remap); fleet services come down under their hub names, or
/// relative to the robot when they lie in its namespace.
struct AgentNames {
    names: NameMap,
    namespace: String,
}

impl LinkNames for AgentNames {
    fn remote_name(&self, local: &TopicName) -> Option<String> {
        Some(self.names.to_hub(local, &self.namespace).to_string())
    }
    fn local_name(&self, remote: &str) -> Option<TopicName> {
        let hub = TopicName::parse(remote).ok()?;
        Some(hub.strip_namespace(&self.namespace).unwrap_or(hub))
    }
}

/// Why a connection ends when the names changed at run time (the next one uses them).
const RENAMED: &str = "the topic names changed (runtime configuration)";

/// The QoS the uplink gives a local topic: the defaults for its type (or the black box's
/// data topic's), made no-drop for a no-drop stream from below, then `specs`' entry.
fn uplink_qos(meta: &TopicMeta, specs: &[(TopicName, TopicQosSpec)]) -> TopicQos {
    let mut base = if meta.name.as_str() == fleetlink_record::blackbox::DATA_TOPIC {
        crate::blackbox::data_qos()
    } else {
        TopicQos::default_for_topic(meta.name.as_str(), &meta.schema.type_name)
    };
    if meta.no_drop {
        // A robot's no-drop stream (on a site hub, carried upstream by this uplink) stays
        // no-drop on the next hop. The hub cannot slow the robot's link down for it, so its
        // queue is long (a durable outbox, which a site hub has by default, holds any
        // number, up to its byte bound).
        base.no_drop = true;
        base.policy = fleetlink_qos::Policy::Fifo;
        base.rate_limit_hz = None;
        base.queue = base.queue.max(INHERITED_NO_DROP_QUEUE);
    }
    match specs.iter().find(|(n, _)| *n == meta.name) {
        Some((_, spec)) => spec.resolve(&base).unwrap_or_else(|e| {
            tracing::warn!("topic {}: {e}; using the defaults for its type", meta.name);
            base
        }),
        None => base,
    }
}

/// The uplink's part of a runtime configuration change (crate::runtime): per-topic QoS,
/// applied to flowing topics at once, and the topic names, applied by reconnecting.
pub struct UplinkControl {
    specs: Arc<std::sync::RwLock<Vec<(TopicName, TopicQosSpec)>>>,
    names: std::sync::RwLock<NameMap>,
    /// Woken when `names` changed: the connection ends and the next one uses them.
    renamed: tokio::sync::Notify,
    router: Arc<Router>,
    client: ClientId,
    outbox: Arc<Outbox>,
}

impl UplinkControl {
    /// The uplink's client of the local router: what the hub calls arrives as its calls.
    pub fn client(&self) -> ClientId {
        self.client
    }

    pub fn names(&self) -> NameMap {
        self.names.read().unwrap_or_else(|p| p.into_inner()).clone()
    }

    /// The local topics the uplink carries up now.
    fn carried(&self) -> Vec<Arc<TopicMeta>> {
        self.router
            .topics()
            .into_iter()
            .filter(|t| t.subscribers.contains(&self.client))
            .map(|t| t.meta.clone())
            .collect()
    }

    /// Whether `specs` can replace the per-topic QoS: a topic already flowing keeps its
    /// `no_drop` (its messages are numbered for the hub's confirmation, or not). `Err`
    /// names the topic.
    pub fn check_topic_qos(&self, specs: &[(TopicName, TopicQosSpec)]) -> Result<(), String> {
        for meta in self.carried() {
            let Some(now) = self.outbox.known_no_drop(meta.id.0) else {
                continue;
            };
            if uplink_qos(&meta, specs).no_drop != now {
                return Err(format!(
                    "topics[\"{}\"].no_drop: cannot change while {} flows (its messages are {} \
                     numbered for the hub's confirmation); change it in the agent's YAML and \
                     restart it",
                    meta.name,
                    meta.name,
                    if now { "" } else { "not " }
                ));
            }
        }
        Ok(())
    }

    /// Replaces the per-topic QoS (checked with [`UplinkControl::check_topic_qos`]) and
    /// gives every flowing topic its new QoS at once.
    pub fn set_topic_qos(&self, specs: Vec<(TopicName, TopicQosSpec)>) {
        *self.specs.write().unwrap_or_else(|p| p.into_inner()) = specs;
        let now = Instant::now();
        for meta in self.carried() {
            if let Err(e) = self.outbox.requalify(&meta, now) {
                tracing::warn!("topic {}: the new QoS was not applied: {e}", meta.name);
            }
        }
    }

    /// Replaces the topic names (`remap`, `subscribe`); if they changed, the link
    /// reconnects at once to announce them.
    pub fn set_names(&self, names: NameMap) {
        let mut now = self.names.write().unwrap_or_else(|p| p.into_inner());
        if now.remap == names.remap && now.subscribe == names.subscribe {
            return;
        }
        *now = names;
        drop(now);
        self.renamed.notify_one();
    }
}

/// Id of the `SUBSCRIBE` that asks the hub for the fleet services this robot may call.
const SERVICES_SUBSCRIPTION: u32 = 0x7fff_0000;

pub struct Uplink {
    cfg: UplinkConfig,
    /// What a runtime change of the configuration changes here.
    control: Arc<UplinkControl>,
    router: Arc<Router>,
    client: ClientId,
    outbox: Arc<Outbox>,
    /// What the local call table tells the uplink: calls to fleet services, their
    /// answers, and local services coming and going. Read by one connection at a time.
    calls_rx: PeerReceiver,
    state: watch::Sender<LinkState>,
    pub stats: Arc<UplinkStats>,
}

impl Uplink {
    /// What the robot's ROS bridges ask before reading a topic from the graph.
    pub fn read_interest(&self) -> Arc<fleetlink_relay::read_interest::ReadInterest> {
        Arc::new(fleetlink_relay::read_interest::ReadInterest::new(
            self.router.clone(),
            self.client,
            self.outbox.clone(),
        ))
    }

    /// Attaches the uplink to the local router: from now on every local topic is queued
    /// for the hub. With a durable outbox, what a previous run left unconfirmed is queued
    /// first.
    pub fn new(
        cfg: UplinkConfig,
        router: Arc<Router>,
    ) -> Result<Uplink, crate::outbox_store::StoreError> {
        let (reliable, recovered) = match &cfg.outbox {
            Some(store) => {
                let o = crate::outbox_store::open(store)?;
                if !o.recovered.is_empty() {
                    tracing::info!(
                        "durable outbox {}: {} unconfirmed no_drop messages from the last run \
                         go first",
                        store.dir.display(),
                        o.recovered.len()
                    );
                }
                let journal: Box<dyn fleetlink_relay::reliable::Journal> = Box::new(o.journal);
                (
                    ReliableOut::new(o.epoch, o.next_seq, Some(journal)),
                    o.recovered,
                )
            }
            None => (ReliableOut::in_memory(), Vec::new()),
        };
        let specs = Arc::new(std::sync::RwLock::new(cfg.topic_qos.clone()));
        let qos_for: QosFor = {
            let specs = specs.clone();
            Arc::new(move |meta: &TopicMeta| {
                uplink_qos(meta, &specs.read().unwrap_or_else(|p| p.into_inner()))
            })
        };
        let sched = SchedulerConfig {
            max_in_flight: cfg.max_in_flight,
            ..SchedulerConfig::default()
        };
        let (client, outbox) = router.connect_with(
            ClientKind::Internal {
                role: "uplink".into(),
            },
            None,
            |id| Outbox::scheduled(id, sched, qos_for, reliable),
        );
        outbox.set_latest_limit(cfg.latest_cache_bytes);
        outbox.set_data_budget(cfg.budget, Instant::now());
        let all = Router::compile_pattern(".*").expect("a constant pattern compiles");
        // Passive: the local publishers (a site hub's robots) hear the hub's interest,
        // not this subscription to everything.
        let opts = SubOptions {
            passive: true,
            ..SubOptions::default()
        };
        router
            .subscribe(client, Target::Pattern(all), opts)
            .expect("the uplink client was just connected");
        restore(&router, client, &outbox, recovered);
        // Every local service is offered to the fleet, as every local topic is.
        let (peer, calls_rx) = ChannelPeer::new();
        router.calls.attach(client, peer);
        router.calls.watch(
            client,
            Router::compile_pattern(".*").expect("a constant pattern compiles"),
        );
        let first = cfg.hub_urls.first().cloned().unwrap_or_default();
        let (state, _) = watch::channel(LinkState::Connecting {
            attempt: 0,
            hub: first,
        });
        let control = Arc::new(UplinkControl {
            specs,
            names: std::sync::RwLock::new(cfg.names.clone()),
            renamed: tokio::sync::Notify::new(),
            router: router.clone(),
            client,
            outbox: outbox.clone(),
        });
        Ok(Uplink {
            cfg,
            router,
            client,
            outbox,
            control,
            calls_rx,
            state,
            stats: Arc::default(),
        })
    }

    pub fn watch(&self) -> watch::Receiver<LinkState> {
        self.state.subscribe()
    }

    /// What changes the uplink's names and per-topic QoS while it runs.
    pub fn control(&self) -> Arc<UplinkControl> {
        self.control.clone()
    }

    /// Connects, serves, reconnects — until `shutdown`.
    pub async fn run(mut self, shutdown: CancellationToken) {
        let journal = {
            let outbox = self.outbox.clone();
            tokio::spawn(async move {
                let mut tick = tokio::time::interval(JOURNAL_TICK);
                loop {
                    tick.tick().await;
                    outbox.tick_journal();
                }
            })
        };
        let hubs = &self.cfg.hub_urls;
        let mut failover = Failover::new(
            hubs.len(),
            Backoff::new(self.cfg.reconnect_initial, self.cfg.reconnect_max),
        );
        let mut log = FailureLog::default();
        let mut attempt = 0u32;
        loop {
            let Some(url) = hubs.get(failover.hub()) else {
                tracing::error!(robot = %self.cfg.robot, "the uplink has no hub URL to connect to");
                shutdown.cancelled().await;
                break;
            };
            attempt += 1;
            // Names changed at run time apply from the next connection on. A change made
            // while no connection was up needs no reconnect of its own: its wake-up is
            // taken first, then the names read (a change in between wakes the connection).
            let _ = futures_util::FutureExt::now_or_never(self.control.renamed.notified());
            self.cfg.names = self.control.names();
            tracing::debug!(robot = %self.cfg.robot, "trying hub {url} (attempt {attempt})");
            self.state.send_replace(LinkState::Connecting {
                attempt,
                hub: url.clone(),
            });
            // Cancellation is handled inside, so a connection's tasks are ended and awaited
            // (and release the outbox) before `run` returns.
            let outcome = self.connect_and_serve(url, &shutdown).await;
            if shutdown.is_cancelled() {
                break;
            }
            let (reason, wait) = match outcome {
                Ok(reason) if reason == RENAMED => {
                    attempt = 0;
                    tracing::info!(robot = %self.cfg.robot, "{RENAMED}: reconnecting to {url} at once");
                    continue;
                }
                Ok(reason) => {
                    attempt = 0;
                    (format!("{reason} (hub {url})"), failover.after_session())
                }
                Err(failure) => {
                    let wait = failover.after_failure(&failure);
                    (failure.into_reason(), wait)
                }
            };
            // Attempts repeat every 100 ms while there is no route: say so once, then
            // only when the reason changes or every 10 s, with the count in between.
            if log.due(&reason) {
                let again = std::mem::take(&mut log.repeats);
                let repeats = if again > 0 {
                    format!(" ({again} more attempts failed since the last report)")
                } else {
                    String::new()
                };
                // With several hubs, which one is next (the same after a session ended,
                // the next at once after a failed attempt).
                let to = match hubs.len() {
                    1 => String::new(),
                    _ => format!(" to {}", hubs[failover.hub()]),
                };
                tracing::warn!(
                    robot = %self.cfg.robot,
                    "hub link down: {reason}; next attempt{to} in {} ms{repeats}",
                    wait.as_millis()
                );
            } else {
                log.repeats += 1;
            }
            self.state.send_replace(LinkState::Disconnected { reason });
            tokio::select! {
                _ = tokio::time::sleep(wait) => {}
                _ = shutdown.cancelled() => break,
            }
        }
        journal.abort();
        // Awaited so its handle on the outbox (and the outbox file's lock) is gone when
        // `run` returns.
        let _ = journal.await;
        // What the durable outbox was handed is written and synced before `run` returns.
        self.outbox.close_journal();
        self.router.disconnect(self.client);
    }
}
