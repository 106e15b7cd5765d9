//! Hubs federated over Zenoh.
//!
//! Each hub joins one Zenoh session (peer, router or client mode; no multicast needed)
//! and takes part in its router as one more participant, the federation client
//! (`ClientKind::Internal { role: "federation" }`). Two loops do the work:
//!
//! - **Topics** ([`topics`]): every topic published here is offered to the fleet as a
//!   liveliness token (name, type, flags); the others' offers become topics here,
//!   advertised by the federation, so listings show the whole fleet. While someone here
//!   subscribes to a topic, this hub holds one Zenoh subscriber for it and a *want*
//!   token; while another hub wants a topic, this hub subscribes to it on its router —
//!   which is what a robot's link hears as interest (`INTEREST`): a robot topic nobody on
//!   any hub wants does not leave the robot — and puts each message into Zenoh once,
//!   whatever the number of hubs and subscribers, as its payload bytes in the encoding it
//!   arrived in.
//! - **Calls** ([`calls`]): services and actions provided on this hub are offered as
//!   tokens; the others' are advertised here with the federation as their provider, so a
//!   call (or action goal) goes as a Zenoh query to the hub where the provider is, its
//!   feedback and answer coming back as replies, a cancel as a message to that hub.
//! - **Keyframes** ([`keyframes`]): a video topic received from another hub whose chain
//!   broke here, or whose new viewer found nothing kept, asks that hub for a keyframe (at
//!   most once a second per topic, acted upon at most once a second there), which asks
//!   its robot as for a viewer of its own.
//!
//! **No loops, by construction.** A message enters Zenoh only from the hub where it was
//! published by a local client: the federation's own subscription never receives what
//! the federation published (the router does not deliver a message to its origin), and
//! the federation offers only topics that have a local publisher besides itself. So a
//! message crosses at most one Zenoh hop, from the hub it was published on to each hub
//! with subscribers, whatever the shape of the mesh (a triangle, a chain through Zenoh
//! routers). Interest cannot loop either: the federation counts as demand at its hub
//! only for remote subscribers, and declares a remote subscriber only for subscribers at
//! its hub other than itself.

pub mod calls;
mod inlet;
pub mod keyframes;
pub mod keys;
pub mod topics;
pub mod trust;

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};

use fleetlink_auth::{HubName, Security};
use fleetlink_hub::federated::{Federated, RemoteRobot};
use fleetlink_hub::registry::Registry;
use fleetlink_hub::security::HubGate;
use fleetlink_relay::router::ClientKind;
use fleetlink_relay::{ClientId, Router};
use serde_json::{Value, json};
use tokio_util::sync::CancellationToken;

pub use trust::{Admission, Trust};

/// Why the federation could not start.
#[derive(Debug, thiserror::Error)]
pub enum FederationError {
    #[error("Zenoh configuration: {0}")]
    Config(String),
    #[error(
        "cannot open the Zenoh session: {0} (check --zenoh-connect/--zenoh-listen endpoints, e.g. tcp/10.0.0.2:7447)"
    )]
    Open(String),
    #[error("Zenoh: {0}")]
    Zenoh(String),
    #[error(
        "hubs must prove who they are before anything crosses between them: give this hub \
         the fleet's CA and its own certificate (--zenoh-ca, --zenoh-cert, --zenoh-key; \
         `fleetlink admin cert federation --fleet {fleet} --hub NAME --ip ADDRESS` makes \
         them) and tls/ endpoints, e.g. --zenoh-listen tls/0.0.0.0:7447 (docs/scaling.md, \
         \"Secure federation in five minutes\"); on a private network only, \
         --zenoh-insecure-tcp federates over plain TCP"
    )]
    Unauthenticated { fleet: String },
    #[error("federation certificate: {0}")]
    Certificate(#[from] fleetlink_auth::tls::federation::FederationCertError),
}

fn zerr(e: impl std::fmt::Display) -> FederationError {
    FederationError::Zenoh(e.to_string())
}

/// How a hub joins its fleet's federation.
#[derive(Debug, Clone)]
pub struct Settings {
    /// Hubs federate with the hubs of the same fleet name (the first chunk of every key).
    pub fleet: String,
    /// This hub's name as the others list it (over TLS: its certificate's).
    pub hub_name: String,
    pub zenoh: zenoh::Config,
    pub trust: Trust,
}

/// Where a hub's federation certificates come from, and whether it may go without.
#[derive(Debug, Clone, Default)]
pub struct TrustArgs {
    /// The fleet's CA, this hub's certificate (chain) and key (`--zenoh-ca`, …); each
    /// may instead come from the Zenoh file's `transport/link/tls` section.
    pub ca: Option<std::path::PathBuf>,
    pub cert: Option<std::path::PathBuf>,
    pub key: Option<std::path::PathBuf>,
    /// `--zenoh-insecure-tcp`: plain TCP, every peer believed.
    pub insecure_tcp: bool,
}

/// A Zenoh configuration from a file (JSON5, Zenoh's own format) and/or flags: `mode`
/// (`peer`, `router`, `client`), endpoints to connect to and listen on, and how hubs
/// authenticate each other ([`trust`]). Multicast scouting is off unless the file turns
/// it on: hubs find each other through the endpoints given, not by whoever answers on the
/// local network. A hub listens only on the endpoints it is given; with certificates
/// every endpoint must be `tls/…` and links are mutual TLS with the fleet's CA.
pub fn zenoh_config(
    file: Option<&Path>,
    mode: Option<&str>,
    connect: &[String],
    listen: &[String],
    fleet: &str,
    trust: &TrustArgs,
) -> Result<(zenoh::Config, Trust), FederationError> {
    let cfg_err =
        |what: &str, e: &dyn std::fmt::Display| FederationError::Config(format!("{what}: {e}"));
    let mut cfg = match file {
        Some(path) => zenoh::Config::from_file(path)
            .map_err(|e| cfg_err(&format!("reading {}", path.display()), &e))?,
        None => {
            let mut c = zenoh::Config::default();
            c.insert_json5("scouting/multicast/enabled", "false")
                .map_err(|e| cfg_err("scouting", &e))?;
            c
        }
    };
    if let Some(mode) = mode {
        if !matches!(mode, "peer" | "router" | "client") {
            return Err(FederationError::Config(format!(
                "mode {mode:?}: expected peer, router or client"
            )));
        }
        cfg.insert_json5("mode", &format!("{mode:?}"))
            .map_err(|e| cfg_err("mode", &e))?;
    }
    for (key, list) in [("connect/endpoints", connect), ("listen/endpoints", listen)] {
        if list.is_empty() {
            continue;
        }
        for ep in list {
            if !ep.contains('/') {
                return Err(FederationError::Config(format!(
                    "endpoint {ep:?}: expected PROTOCOL/ADDRESS, e.g. tls/10.0.0.2:7447"
                )));
            }
        }
        let value = serde_json::to_string(list).expect("strings serialize");
        cfg.insert_json5(key, &value)
            .map_err(|e| cfg_err(&format!("{key} {value}"), &e))?;
    }
    // Never Zenoh's default listener (`tcp/[::]:0`, every interface): only what is given.
    let default = zenoh::Config::default();
    if listen.is_empty()
        && cfg.get_json("listen/endpoints").ok() == default.get_json("listen/endpoints").ok()
    {
        cfg.insert_json5("listen/endpoints", "[]")
            .map_err(|e| cfg_err("listen/endpoints", &e))?;
    }
    // Room for bursts between hubs. Zenoh's default is two batches per priority and a
    // best-effort message waiting 1 ms for one before it is dropped; on a busy machine two
    // batches fill while one is being encrypted, and a burst of small messages lost some.
    // What a configuration file sets stays.
    for (key, value) in [
        ("transport/link/tx/queue/size/data", "16"),
        (
            "transport/link/tx/queue/congestion_control/drop/wait_before_drop",
            "10000",
        ),
    ] {
        if cfg.get_json(key).ok() == default.get_json(key).ok() {
            cfg.insert_json5(key, value).map_err(|e| cfg_err(key, &e))?;
        }
    }
    let trust = trust::resolve(&mut cfg, fleet, trust)?;
    let plain_ok = matches!(trust, Trust::PlainTcp);
    for key in ["connect/endpoints", "listen/endpoints"] {
        for ep in endpoints(&cfg, key) {
            let protocol = ep.split('/').next().unwrap_or("");
            match protocol {
                "tls" => {}
                "tcp" if plain_ok => {}
                "tcp" => {
                    return Err(FederationError::Config(format!(
                        "endpoint {ep}: links between hubs use TLS (tls/{}); plain tcp/ needs \
                         --zenoh-insecure-tcp, for a private network only",
                        ep.split_once('/').map_or("", |(_, a)| a)
                    )));
                }
                other => {
                    return Err(FederationError::Config(format!(
                        "endpoint {ep}: protocol {other:?} is not available (tls/ only, or tcp/ \
                         with --zenoh-insecure-tcp)"
                    )));
                }
            }
        }
    }
    Ok((cfg, trust))
}

/// The endpoints under `key` (a list, or a list per mode).
fn endpoints(cfg: &zenoh::Config, key: &str) -> Vec<String> {
    let Some(v) = cfg
        .get_json(key)
        .ok()
        .and_then(|j| serde_json::from_str::<Value>(&j).ok())
    else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let mut take = |list: &Value| {
        if let Some(a) = list.as_array() {
            out.extend(a.iter().filter_map(|e| e.as_str().map(str::to_owned)));
        }
    };
    match &v {
        Value::Object(by_mode) => by_mode.values().for_each(&mut take),
        other => take(other),
    }
    out
}

/// Counters of what crossed between this hub and the others.
#[derive(Debug, Default)]
pub struct Counters {
    /// Messages this hub put into Zenoh, and their payload bytes.
    pub sent: AtomicU64,
    pub sent_bytes: AtomicU64,
    /// Messages put that Zenoh refused (congestion on a best-effort topic).
    pub send_failed: AtomicU64,
    /// Messages heard from other hubs and published here, and their payload bytes.
    pub received: AtomicU64,
    pub received_bytes: AtomicU64,
    /// No-drop messages heard a second time (from a robot's old and new hub): not
    /// published again.
    pub duplicates: AtomicU64,
    /// Messages heard that could not be read (a bad header).
    pub malformed: AtomicU64,
    /// Calls and goals sent to other hubs, and received from them.
    pub calls_out: AtomicU64,
    pub calls_in: AtomicU64,
    /// Messages, calls and keyframe asks from other hubs that this hub's rules refused.
    pub refused: AtomicU64,
    /// Keyframe asks of video topics sent to the hubs that send them here.
    pub keyframe_asks_out: AtomicU64,
    /// Keyframe asks heard for video topics this hub sends, and those acted upon (the
    /// others came within a second of one, or a rule refused them).
    pub keyframe_asks_in: AtomicU64,
    pub keyframe_asks_acted: AtomicU64,
}

/// One exported topic's figures.
#[derive(Debug, Default)]
pub struct ExportFigures {
    /// A subscriber on another hub exists (Zenoh's matching status).
    pub wanted: AtomicBool,
    pub sent: AtomicU64,
}

/// One imported topic's figures.
#[derive(Debug, Default)]
pub struct ImportFigures {
    /// This hub has a Zenoh subscriber for it (someone here subscribes).
    pub subscribed: AtomicBool,
    pub received: AtomicU64,
    /// The hubs offering it (their names).
    pub from: Mutex<Vec<String>>,
}

/// A hub of the fleet as this one sees it.
#[derive(Debug, Default, Clone)]
pub struct Peer {
    pub name: String,
    pub robots: std::collections::BTreeSet<String>,
}

/// What the loops share with the HTTP surface.
pub struct Shared {
    pub fleet: String,
    /// This hub's Zenoh id (the `<hub>` chunk of its keys).
    pub me: String,
    pub hub_name: String,
    pub client: ClientId,
    pub counters: Counters,
    /// Figures of each topic sent and received: one per topic the topics loop keeps an
    /// entry for (kept and let go with it).
    pub exports: Mutex<BTreeMap<String, Arc<ExportFigures>>>,
    pub imports: Mutex<BTreeMap<String, Arc<ImportFigures>>>,
    /// The hubs heard of, by Zenoh id: one per admitted hub that offered its name or a
    /// robot, removed with its name token (robots and all).
    pub peers: Mutex<BTreeMap<String, Peer>>,
    /// Which hubs are admitted, by the certificates their links show.
    pub admission: Arc<Admission>,
    pub security: Arc<Security>,
    pub registry: Arc<Registry>,
}

impl Shared {
    /// Hub `zid`'s name for rules and the audit log: its certificate's (over TLS), else
    /// the name it gave itself.
    pub fn hub_name_of(&self, zid: &str) -> HubName {
        let name = match self.admission.admitted(zid) {
            Some(a) if !a.name.is_empty() => a.name,
            _ => self.peer_name(zid),
        };
        HubName::new(&name)
            .or_else(|_| HubName::new(&keys::chunk(&name)))
            .unwrap_or_else(|_| HubName::new("unnamed").expect("a valid name"))
    }

    /// A gate for what hub `zid` does acting for itself (the topics it forwards here).
    pub fn hub_gate(&self, zid: &str) -> HubGate {
        let identity = fleetlink_hub::security::hub_identity(
            &self.hub_name_of(zid),
            self.admission.address(zid),
        );
        HubGate::new(self.security.clone(), self.registry.clone(), identity)
    }

    /// The name of hub `id`, or its id while its name token has not arrived.
    pub fn peer_name(&self, id: &str) -> String {
        self.peers
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .get(id)
            .map(|p| p.name.clone())
            .filter(|n| !n.is_empty())
            .unwrap_or_else(|| id.to_owned())
    }
}

/// A running federation; stops with the hub's shutdown token.
#[derive(Clone)]
pub struct Federation {
    shared: Arc<Shared>,
}

impl Federation {
    /// Opens the Zenoh session and starts the loops on the current runtime.
    pub async fn start(
        settings: Settings,
        router: Arc<Router>,
        registry: Arc<Registry>,
        security: Arc<Security>,
        shutdown: CancellationToken,
    ) -> Result<Federation, FederationError> {
        let fleet = keys::chunk(&settings.fleet);
        if matches!(settings.trust, Trust::PlainTcp) {
            tracing::warn!(
                "federation over PLAIN TCP (--zenoh-insecure-tcp): hubs do not authenticate \
                 each other, and any process that reaches a Zenoh endpoint of this hub can list, \
                 read and drive the fleet. Use it on a private network only; see docs/scaling.md, \
                 \"Secure federation in five minutes\""
            );
        }
        let admission = Admission::new(settings.trust.clone(), &fleet);
        let session = zenoh::open(settings.zenoh)
            .await
            .map_err(|e| FederationError::Open(e.to_string()))?;
        let me = session.zid().to_string();
        let links = admission.clone();
        session
            .info()
            .link_events_listener()
            .history(true)
            .callback(move |event| {
                let link = event.link();
                let zid = link.zid().to_string();
                match event.kind() {
                    zenoh::sample::SampleKind::Put => {
                        let remote = link.dst().to_string();
                        let _ = links.link_up(&zid, link.auth_identifier(), &remote);
                    }
                    zenoh::sample::SampleKind::Delete => links.link_down(&zid),
                }
            })
            .background()
            .await
            .map_err(zerr)?;
        let (client, outbox) = router.connect(
            ClientKind::Internal {
                role: "federation".into(),
            },
            None,
        );
        let shared = Arc::new(Shared {
            fleet,
            me,
            hub_name: settings.hub_name,
            client,
            counters: Counters::default(),
            exports: Mutex::new(BTreeMap::new()),
            imports: Mutex::new(BTreeMap::new()),
            peers: Mutex::new(BTreeMap::new()),
            admission,
            security,
            registry: registry.clone(),
        });
        // This hub's name token first, so the others can name it in their listings.
        let hub_key = keys::offer_key(
            &shared.fleet,
            &shared.me,
            &keys::Offer::Hub {
                name: keys::chunk(&shared.hub_name),
            },
        )
        .expect("a chunk is a valid name");
        let hub_token = session
            .liveliness()
            .declare_token(hub_key)
            .await
            .map_err(zerr)?;
        let topics =
            topics::Topics::start(session.clone(), router.clone(), shared.clone(), outbox).await?;
        let callers = calls::CallBridge::start(
            session.clone(),
            router.clone(),
            shared.clone(),
            topics.providers(),
        )
        .await?;
        tracing::info!(
            "federation: hub {} ({}) joined fleet {:?} over Zenoh",
            shared.hub_name,
            shared.me,
            shared.fleet
        );
        let fed_shared = shared.clone();
        tokio::spawn(async move {
            let stop = shutdown.clone();
            tokio::join!(
                topics.run(registry, stop.clone()),
                callers.run(stop.clone())
            );
            drop(hub_token);
            router.disconnect(fed_shared.client);
            if let Err(e) = session.close().await {
                tracing::debug!("federation: closing the Zenoh session: {e}");
            }
        });
        Ok(Federation { shared })
    }

    pub fn shared(&self) -> &Arc<Shared> {
        &self.shared
    }
}

impl Federated for Federation {
    fn remote_robots(&self) -> Vec<RemoteRobot> {
        let peers = self.shared.peers.lock().unwrap_or_else(|p| p.into_inner());
        let mut out: Vec<RemoteRobot> = peers
            .iter()
            .flat_map(|(id, p)| {
                let hub = if p.name.is_empty() { id } else { &p.name };
                p.robots.iter().map(move |r| RemoteRobot {
                    name: r.clone(),
                    hub: hub.clone(),
                })
            })
            .collect();
        out.sort_by(|a, b| a.name.cmp(&b.name));
        out.dedup_by(|a, b| a.name == b.name);
        out
    }

    fn status(&self) -> Value {
        let s = &self.shared;
        let c = &s.counters;
        let peers: Vec<Value> = s
            .peers
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .iter()
            .map(|(id, p)| {
                json!({
                    "id": id,
                    "name": p.name,
                    "robots": p.robots,
                    "admitted": s.admission.is_admitted(id),
                })
            })
            .collect();
        let refused: Vec<Value> = s
            .admission
            .refused()
            .into_iter()
            .map(|(id, why)| json!({ "id": id, "reason": why }))
            .collect();
        let exported: Vec<Value> = s
            .exports
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .iter()
            .map(|(name, f)| {
                json!({
                    "topic": name,
                    "wanted_remotely": f.wanted.load(Relaxed),
                    "sent": f.sent.load(Relaxed),
                })
            })
            .collect();
        let imported: Vec<Value> = s
            .imports
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .iter()
            .map(|(name, f)| {
                json!({
                    "topic": name,
                    "from": *f.from.lock().unwrap_or_else(|p| p.into_inner()),
                    "subscribed": f.subscribed.load(Relaxed),
                    "received": f.received.load(Relaxed),
                })
            })
            .collect();
        json!({
            "federated": true,
            "fleet": s.fleet,
            "hub": { "id": s.me, "name": s.hub_name },
            "authenticated": !s.admission.is_plain_tcp(),
            "peers": peers,
            "refused": refused,
            "exported": exported,
            "imported": imported,
            "counters": {
                "sent": c.sent.load(Relaxed),
                "sent_bytes": c.sent_bytes.load(Relaxed),
                "send_failed": c.send_failed.load(Relaxed),
                "received": c.received.load(Relaxed),
                "received_bytes": c.received_bytes.load(Relaxed),
                "duplicates": c.duplicates.load(Relaxed),
                "malformed": c.malformed.load(Relaxed),
                "calls_out": c.calls_out.load(Relaxed),
                "calls_in": c.calls_in.load(Relaxed),
                "refused": c.refused.load(Relaxed),
                "keyframe_asks_out": c.keyframe_asks_out.load(Relaxed),
                "keyframe_asks_in": c.keyframe_asks_in.load(Relaxed),
                "keyframe_asks_acted": c.keyframe_asks_acted.load(Relaxed),
            },
        })
    }

    fn counters(&self) -> Vec<(&'static str, &'static str, u64)> {
        let c = &self.shared.counters;
        vec![
            (
                "fleetlink_federation_sent_messages",
                "Messages this hub sent to other hubs (once per message, whatever the number of hubs)",
                c.sent.load(Relaxed),
            ),
            (
                "fleetlink_federation_sent_bytes",
                "Payload bytes of the messages sent to other hubs",
                c.sent_bytes.load(Relaxed),
            ),
            (
                "fleetlink_federation_send_failed",
                "Messages Zenoh refused to send (congestion on a best-effort topic)",
                c.send_failed.load(Relaxed),
            ),
            (
                "fleetlink_federation_received_messages",
                "Messages heard from other hubs and published here",
                c.received.load(Relaxed),
            ),
            (
                "fleetlink_federation_received_bytes",
                "Payload bytes of the messages heard from other hubs",
                c.received_bytes.load(Relaxed),
            ),
            (
                "fleetlink_federation_duplicates",
                "No-drop messages heard twice (a robot moved between hubs) and delivered once",
                c.duplicates.load(Relaxed),
            ),
            (
                "fleetlink_federation_malformed",
                "Messages from other hubs that could not be read",
                c.malformed.load(Relaxed),
            ),
            (
                "fleetlink_federation_calls_out",
                "Service calls and action goals sent to other hubs",
                c.calls_out.load(Relaxed),
            ),
            (
                "fleetlink_federation_calls_in",
                "Service calls and action goals received from other hubs",
                c.calls_in.load(Relaxed),
            ),
            (
                "fleetlink_federation_refused",
                "Messages, calls and keyframe asks from other hubs refused here (hub not admitted, or a rule)",
                c.refused.load(Relaxed),
            ),
            (
                "fleetlink_federation_keyframe_asks_out",
                "Keyframe asks of video topics sent to the hubs they come from",
                c.keyframe_asks_out.load(Relaxed),
            ),
            (
                "fleetlink_federation_keyframe_asks_in",
                "Keyframe asks heard from other hubs for video topics sent from here",
                c.keyframe_asks_in.load(Relaxed),
            ),
            (
                "fleetlink_federation_keyframe_asks_acted",
                "Keyframe asks from other hubs acted upon (at most one a second per topic)",
                c.keyframe_asks_acted.load(Relaxed),
            ),
        ]
    }
}

#[cfg(test)]
#[path = "config_tests.rs"]
mod config_tests;
