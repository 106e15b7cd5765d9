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
//! if TCP has not noticed. Reconnects back off exponentially with jitter.

use std::collections::HashMap;
use std::sync::Arc;
use std::time::Duration;

use fleetlink_proto::frame::{Frame, SUBSCRIBE_REGEX, VERSION};
use fleetlink_proto::{Encoding, SUBPROTOCOL};
use fleetlink_qos::{SchedulerConfig, TopicQos, TopicQosSpec};
use fleetlink_relay::link::{Control, LinkEvent, LinkIn, LinkNamer, write_link};
use fleetlink_relay::message::TopicMeta;
use fleetlink_relay::outbox::QosFor;
use fleetlink_relay::router::{SubOptions, Target};
use fleetlink_relay::{ClientId, ClientKind, Outbox, Router, Topic, TopicName};
use futures_util::{SinkExt, StreamExt};
use tokio::sync::{mpsc, watch};
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_tungstenite::tungstenite::client::IntoClientRequest;
use tokio_tungstenite::tungstenite::http::HeaderValue;
use tokio_util::sync::CancellationToken;

/// How often the agent reports its demand and link figures to the hub.
const LINK_REPORT_INTERVAL: Duration = Duration::from_secs(1);

/// How long connecting plus the `HELLO`/`WELCOME` exchange may take.
const HANDSHAKE_TIMEOUT: Duration = Duration::from_secs(10);

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
    pub hub_url: String,
    pub robot: String,
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
}

/// The link's state, observable by tests and the CLI.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LinkState {
    Connecting { attempt: u32 },
    Connected { session: String, namespace: String },
    Disconnected { reason: String },
}

/// Counters of the uplink, for status display and tests.
#[derive(Debug, Default)]
pub struct UplinkStats {
    pub connects: std::sync::atomic::AtomicU64,
    pub rtt_ns: std::sync::atomic::AtomicU64,
    /// The hub's capacity share for this robot, bytes/s (0 = none received / no cap).
    pub share_bps: std::sync::atomic::AtomicU64,
}

pub struct Uplink {
    cfg: UplinkConfig,
    router: Arc<Router>,
    client: ClientId,
    outbox: Arc<Outbox>,
    state: watch::Sender<LinkState>,
    pub stats: Arc<UplinkStats>,
}

impl Uplink {
    /// Attaches the uplink to the local router: from now on every local topic is queued
    /// for the hub.
    pub fn new(cfg: UplinkConfig, router: Arc<Router>) -> Uplink {
        let specs = cfg.topic_qos.clone();
        let qos_for: QosFor = Arc::new(move |meta: &TopicMeta| {
            let base = TopicQos::default_for_topic(meta.name.as_str(), &meta.schema.type_name);
            match specs.iter().find(|(n, _)| *n == meta.name) {
                Some((_, spec)) => spec.resolve(&base).unwrap_or_else(|e| {
                    tracing::warn!("topic {}: {e}; using the defaults for its type", meta.name);
                    base
                }),
                None => base,
            }
        });
        let sched = SchedulerConfig {
            max_in_flight: cfg.max_in_flight,
            ..SchedulerConfig::default()
        };
        let (client, outbox) = router.connect_with(
            ClientKind::Internal {
                role: "uplink".into(),
            },
            None,
            |id| Outbox::scheduled(id, sched, qos_for),
        );
        let all = Router::compile_pattern(".*").expect("a constant pattern compiles");
        let opts = SubOptions::default();
        router
            .subscribe(client, Target::Pattern(all), opts)
            .expect("the uplink client was just connected");
        let (state, _) = watch::channel(LinkState::Connecting { attempt: 0 });
        Uplink {
            cfg,
            router,
            client,
            outbox,
            state,
            stats: Arc::default(),
        }
    }

    pub fn watch(&self) -> watch::Receiver<LinkState> {
        self.state.subscribe()
    }

    /// Connects, serves, reconnects — until `shutdown`.
    pub async fn run(self, shutdown: CancellationToken) {
        let mut backoff = self.cfg.reconnect_initial;
        let mut attempt = 0u32;
        loop {
            attempt += 1;
            self.state.send_replace(LinkState::Connecting { attempt });
            let outcome = tokio::select! {
                r = self.connect_and_serve() => r,
                _ = shutdown.cancelled() => break,
            };
            let reason = match outcome {
                Ok(reason) => {
                    // The link was up: start backing off from the beginning again.
                    backoff = self.cfg.reconnect_initial;
                    attempt = 0;
                    reason
                }
                Err(e) => e,
            };
            tracing::warn!(robot = %self.cfg.robot, "hub link down: {reason}");
            self.state.send_replace(LinkState::Disconnected { reason });
            // Full jitter in [backoff/2, backoff] so a fleet does not reconnect in step.
            let wait = backoff.mul_f64(0.5 + fastrand::f64() * 0.5);
            tokio::select! {
                _ = tokio::time::sleep(wait) => {}
                _ = shutdown.cancelled() => break,
            }
            backoff = (backoff * 2).min(self.cfg.reconnect_max);
        }
        self.router.disconnect(self.client);
    }

    /// One connection. `Err` if it never came up, `Ok(reason)` when it ended after
    /// `WELCOME`.
    async fn connect_and_serve(&self) -> Result<String, String> {
        let mut req = self
            .cfg
            .hub_url
            .as_str()
            .into_client_request()
            .map_err(|e| format!("bad hub URL {}: {e}", self.cfg.hub_url))?;
        req.headers_mut().insert(
            "Sec-WebSocket-Protocol",
            HeaderValue::from_static(SUBPROTOCOL),
        );
        let (ws, response) = tokio::time::timeout(
            HANDSHAKE_TIMEOUT,
            tokio_tungstenite::connect_async_tls_with_config(
                req,
                None,
                true,
                self.cfg
                    .tls
                    .clone()
                    .map(tokio_tungstenite::Connector::Rustls),
            ),
        )
        .await
        .map_err(|_| format!("connecting to {} timed out", self.cfg.hub_url))?
        .map_err(|e| format!("cannot connect to {}: {e}", self.cfg.hub_url))?;
        let agreed = response
            .headers()
            .get("Sec-WebSocket-Protocol")
            .and_then(|v| v.to_str().ok());
        if agreed != Some(SUBPROTOCOL) {
            return Err(format!(
                "{} does not speak {SUBPROTOCOL} (is it a fleetlink hub?)",
                self.cfg.hub_url
            ));
        }
        if let tokio_tungstenite::MaybeTlsStream::Plain(s) = ws.get_ref() {
            let _ = s.set_nodelay(true);
        }
        let (mut sink, mut stream) = ws.split();
        let hello = Frame::Hello {
            version: VERSION,
            robot: self.cfg.robot.clone(),
            token: self.cfg.token.clone(),
            heartbeat_ms: self.cfg.heartbeat.as_millis() as u32,
        };
        sink.send(WsMessage::Binary(hello.to_bytes()))
            .await
            .map_err(|e| format!("sending HELLO: {e}"))?;
        let mut link = LinkIn::default();
        let (session, namespace, heartbeat_ms) = tokio::time::timeout(HANDSHAKE_TIMEOUT, async {
            while let Some(m) = stream.next().await {
                match m {
                    Ok(WsMessage::Binary(b)) => {
                        for f in fleetlink_proto::frame::frames(&b) {
                            match link
                                .on_frame(f.map_err(|e| format!("malformed frame from hub: {e}"))?)
                            {
                                Ok(LinkEvent::Control(Frame::Welcome {
                                    session,
                                    namespace,
                                    heartbeat_ms,
                                    ..
                                })) => {
                                    return Ok((session, namespace, heartbeat_ms));
                                }
                                Ok(LinkEvent::Control(Frame::Status { text, .. })) => {
                                    return Err(format!("hub refused: {text}"));
                                }
                                _ => {}
                            }
                        }
                    }
                    Ok(WsMessage::Close(c)) => {
                        return Err(format!("hub closed the connection: {c:?}"));
                    }
                    Ok(_) => {}
                    Err(e) => return Err(format!("reading WELCOME: {e}")),
                }
            }
            Err("hub closed before WELCOME".to_owned())
        })
        .await
        .map_err(|_| "no WELCOME from hub".to_owned())??;
        self.stats
            .connects
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        tracing::info!(robot = %self.cfg.robot, %namespace, "connected to hub");

        // Everything the hub must know, exactly once on this connection.
        let names = self.cfg.names.clone();
        let ns = namespace.clone();
        let me = self.client;
        let router = self.router.clone();
        let namer: LinkNamer =
            Arc::new(move |meta: &TopicMeta| Some(names.to_hub(&meta.name, &ns).to_string()));
        let announce: Vec<(Arc<TopicMeta>, Encoding)> = router
            .topics()
            .into_iter()
            .filter(|t| t.publishers.iter().any(|p| *p != me))
            .map(|t| {
                (
                    t.meta.clone(),
                    t.topic.last_encoding().unwrap_or(Encoding::Json),
                )
            })
            .collect();
        let (ctrl_tx, ctrl_rx) = mpsc::channel::<Control>(1024);
        let mut subs = vec![(
            1u32,
            format!("{}/.*", regex::escape(&namespace)),
            SUBSCRIBE_REGEX,
        )];
        for (i, (hub, _)) in self.cfg.names.subscribe.iter().enumerate() {
            subs.push((i as u32 + 2, hub.to_string(), 0));
        }
        for (id, pattern, flags) in subs {
            let f = Frame::Subscribe {
                id,
                pattern,
                flags,
                throttle_ms: 0,
                queue_length: 0,
            };
            let _ = ctrl_tx.send(Control::Frame(f)).await;
        }
        let heartbeat = Duration::from_millis(u64::from(heartbeat_ms.max(10)));
        let writer = tokio::spawn(write_link(
            sink,
            self.outbox.clone(),
            ctrl_rx,
            heartbeat,
            namer,
            announce,
            None,
        ));
        self.state.send_replace(LinkState::Connected {
            session,
            namespace: namespace.clone(),
        });

        let mut down: HashMap<u32, Arc<Topic>> = HashMap::new();
        let dead_after = heartbeat * 2;
        // Once a second the hub hears what this robot would send and what its link
        // carries, for sharing a site's access link among its robots.
        let reporter = {
            let (outbox, ctrl) = (self.outbox.clone(), ctrl_tx.clone());
            tokio::spawn(async move {
                let mut tick = tokio::time::interval(LINK_REPORT_INTERVAL);
                tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
                loop {
                    tick.tick().await;
                    let Some(f) = outbox.link_figures(std::time::Instant::now()) else {
                        return;
                    };
                    let report = Frame::LinkReport {
                        demand_bps: f.demand_bps as u64,
                        rate_bps: f.rate_bps as u64,
                        latency_ns: f.latency.map_or(0, |l| l.as_nanos() as u64),
                    };
                    if ctrl.send(Control::Frame(report)).await.is_err() {
                        return;
                    }
                }
            })
        };
        let reason = loop {
            let m = match tokio::time::timeout(dead_after, stream.next()).await {
                Err(_) => {
                    break format!("no traffic from hub for {dead_after:?}: link declared dead");
                }
                Ok(None) => break "hub closed the connection".to_owned(),
                Ok(Some(Err(e))) => break format!("link error: {e}"),
                Ok(Some(Ok(WsMessage::Close(c)))) => {
                    break format!("hub closed the connection: {c:?}");
                }
                Ok(Some(Ok(m))) => m,
            };
            let WsMessage::Binary(b) = m else { continue };
            for f in fleetlink_proto::frame::frames(&b) {
                let f = match f {
                    Ok(f) => f,
                    Err(e) => {
                        tracing::warn!("malformed frame from hub: {e}");
                        break;
                    }
                };
                match link.on_frame(f) {
                    Ok(ev) => self.on_event(ev, &namespace, &mut down, &ctrl_tx).await,
                    Err(e) => tracing::warn!("from hub: {e}"),
                }
            }
        };
        reporter.abort();
        let _ = ctrl_tx.try_send(Control::Close);
        drop(ctrl_tx);
        writer.abort();
        let _ = writer.await;
        Ok(reason)
    }

    async fn on_event(
        &self,
        ev: LinkEvent,
        namespace: &str,
        down: &mut HashMap<u32, Arc<Topic>>,
        ctrl: &mpsc::Sender<Control>,
    ) {
        match ev {
            LinkEvent::Advertise { alias, topic } => {
                let Ok(hub) = TopicName::parse(&topic.name) else {
                    return;
                };
                let Some(local) = self.cfg.names.to_local(&hub, namespace) else {
                    tracing::debug!("hub sent {hub}, which has no local name here");
                    return;
                };
                match self
                    .router
                    .advertise(self.client, &local, topic.schema, topic.latched)
                {
                    Ok(t) => {
                        down.insert(alias, t);
                    }
                    Err(e) => tracing::warn!("cannot deliver {hub} locally: {e}"),
                }
            }
            LinkEvent::Unadvertise { alias, .. } => {
                down.remove(&alias);
            }
            LinkEvent::Message {
                alias,
                seq,
                stamp_ns,
                payload,
            } => {
                if let Some(t) = down.get(&alias) {
                    t.publish(self.client, seq, stamp_ns, payload);
                }
            }
            LinkEvent::Control(Frame::Ping { id, sent_ns }) => {
                let pong = Frame::Pong {
                    id,
                    echo_ns: sent_ns,
                    responder_ns: fleetlink_relay::unix_nanos(),
                };
                let _ = ctrl.send(Control::Frame(pong)).await;
            }
            LinkEvent::Control(Frame::Pong {
                id,
                echo_ns,
                responder_ns,
            }) => {
                if id < fleetlink_relay::link::HEARTBEAT_ID_BASE {
                    self.outbox
                        .on_echo(id, responder_ns, std::time::Instant::now());
                }
                let rtt = fleetlink_relay::unix_nanos().saturating_sub(echo_ns);
                self.stats
                    .rtt_ns
                    .store(rtt, std::sync::atomic::Ordering::Relaxed);
            }
            LinkEvent::Control(Frame::Status { level, text, .. }) => {
                tracing::warn!(level = level.as_str(), "hub: {text}");
            }
            LinkEvent::Control(Frame::Ack { frames: messages }) => {
                self.outbox
                    .on_acked(messages as usize, std::time::Instant::now());
            }
            LinkEvent::Control(Frame::Share { bytes_per_sec }) => {
                let share = (bytes_per_sec > 0).then_some(bytes_per_sec as f64);
                self.outbox.set_share(share, std::time::Instant::now());
                self.stats
                    .share_bps
                    .store(bytes_per_sec, std::sync::atomic::Ordering::Relaxed);
            }
            _ => {}
        }
    }
}
