//! Agents on the hub: one `fleetlink.v1` session per robot, and the registry of robots
//! that are online.
//!
//! A robot that reconnects while its old connection still looks alive (a half-open TCP
//! connection after a Wi-Fi drop) replaces it: the old session is told to close and its
//! topics are withdrawn before the new one advertises, so a robot never appears twice.

use std::collections::HashMap;
use std::net::SocketAddr;
use std::sync::atomic::{AtomicI64, AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, SystemTime};

use bytes::Bytes;
use fleetlink_proto::frame::{Frame, Level, VERSION};
use fleetlink_relay::calls::{ChannelPeer, PeerMsg};
use fleetlink_relay::gate::{Gate, Op};
use fleetlink_relay::link::{Control, LinkEvent, LinkIn, write_link};
use fleetlink_relay::link_calls::{LinkCalls, SameNames};
use fleetlink_relay::router::{SubOptions, SubscriptionId, Target};
use fleetlink_relay::{ClientId, ClientKind, Router, Topic, TopicName};
use futures_util::{Sink, SinkExt, Stream, StreamExt};
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::protocol::CloseFrame;
use tokio_tungstenite::tungstenite::protocol::frame::coding::CloseCode;
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};
use tokio_util::sync::CancellationToken;

use crate::delivery::{DeliveryLedger, RobotBook};
use crate::store::Store;

/// How long a new connection has to send `HELLO`.
const HELLO_TIMEOUT: Duration = Duration::from_secs(10);
/// Heartbeat bounds a robot may ask for.
const MIN_HEARTBEAT_MS: u32 = 50;
const MAX_HEARTBEAT_MS: u32 = 60_000;

/// A robot that is online now.
pub struct LiveRobot {
    pub name: String,
    pub client: ClientId,
    pub session: u64,
    pub addr: Option<SocketAddr>,
    pub connected_at: SystemTime,
    pub heartbeat_ms: u32,
    /// Round trip of the last ping the hub sent, in nanoseconds (0 = none yet).
    pub rtt_ns: AtomicU64,
    pub last_seen_ns: AtomicU64,
    /// From the agent's last `LINK_REPORT`: what it would send, what its link delivered
    /// (bytes/s) and its one-way latency (ns).
    pub demand_bps: AtomicU64,
    pub rate_bps: AtomicU64,
    pub latency_ns: AtomicU64,
    /// The capacity share last sent to it (bytes/s; 0 = none).
    pub share_bps: AtomicU64,
    /// Hub clock minus robot clock, from the least-delayed of the recent heartbeats.
    clock: Mutex<ClockSync>,
    /// The current estimate from `clock` (`i64::MIN` = none yet), read per message
    /// without the lock.
    clock_offset: AtomicI64,
    control: mpsc::Sender<Control>,
}

/// Clock offset from ping/pong exchanges, NTP style: each exchange bounds the offset
/// within its round trip; the exchange with the shortest round trip among the recent
/// ones gives the tightest estimate.
#[derive(Default)]
struct ClockSync {
    samples: std::collections::VecDeque<(u64, i64)>,
}

const CLOCK_SAMPLES: usize = 16;

impl LiveRobot {
    /// Hub clock minus robot clock in nanoseconds, once a heartbeat has been answered.
    pub fn clock_offset_ns(&self) -> Option<i64> {
        match self.clock_offset.load(Relaxed) {
            i64::MIN => None,
            o => Some(o),
        }
    }

    /// Sends the robot its capacity share (bytes/s; 0 = no cap). Never blocks.
    pub fn send_share(&self, bytes_per_sec: u64) {
        self.share_bps.store(bytes_per_sec, Relaxed);
        let _ = self
            .control
            .try_send(Control::Frame(Frame::Share { bytes_per_sec }));
    }
}

/// Robots online, by name.
#[derive(Default)]
pub struct Registry {
    // std Mutex: lookups and swaps only, never held across an await.
    robots: Mutex<HashMap<String, Arc<LiveRobot>>>,
    next_session: AtomicU64,
    /// Bumped whenever a robot comes or goes, so callers can cache [`Registry::is_online`]
    /// answers between changes.
    changes: AtomicU64,
}

impl Registry {
    pub fn list(&self) -> Vec<Arc<LiveRobot>> {
        let mut v: Vec<_> = self
            .robots
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .values()
            .cloned()
            .collect();
        v.sort_by(|a, b| a.name.cmp(&b.name));
        v
    }

    fn insert(&self, robot: Arc<LiveRobot>) -> Option<Arc<LiveRobot>> {
        let mut m = self.robots.lock().unwrap_or_else(|p| p.into_inner());
        self.changes.fetch_add(1, Relaxed);
        m.insert(robot.name.clone(), robot)
    }

    /// Changes whenever the set of robots online changes.
    pub fn generation(&self) -> u64 {
        self.changes.load(Relaxed)
    }

    /// Whether a robot of this name is connected now.
    pub fn is_online(&self, name: &str) -> bool {
        self.robots
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .contains_key(name)
    }

    fn remove_if_session(&self, name: &str, session: u64) {
        let mut m = self.robots.lock().unwrap_or_else(|p| p.into_inner());
        if m.get(name).is_some_and(|r| r.session == session) {
            m.remove(name);
            self.changes.fetch_add(1, Relaxed);
        }
    }
}

/// What an agent session needs from the hub.
pub struct AgentContext {
    pub router: Arc<Router>,
    pub registry: Arc<Registry>,
    pub store: Store,
    pub shutdown: CancellationToken,
    pub security: Arc<fleetlink_auth::Security>,
    /// Heartbeat used when the agent does not ask for one.
    pub default_heartbeat_ms: u32,
    /// How far each robot's no-drop topics were delivered.
    pub ledger: Arc<DeliveryLedger>,
    /// The hub's `/rosout`: robots connecting, leaving, refused.
    pub rosout: Arc<crate::rosout::RosOut>,
}

/// A robot name: letters, digits and `_`, as a ROS namespace segment must be.
pub fn valid_robot_name(name: &str) -> bool {
    !name.is_empty()
        && name.len() <= 64
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !name.starts_with(|c: char| c.is_ascii_digit())
}

/// Runs one agent connection to the end.
pub async fn serve_agent<S>(
    ws: S,
    ctx: Arc<AgentContext>,
    addr: Option<SocketAddr>,
    conn: fleetlink_auth::ConnInfo,
) where
    S: Stream<Item = Result<WsMessage, WsError>>
        + Sink<WsMessage, Error = WsError>
        + Unpin
        + Send
        + 'static,
{
    let (sink, mut stream) = ws.split();
    let mut link = LinkIn::default();

    // HELLO first.
    let hello = tokio::time::timeout(HELLO_TIMEOUT, async {
        while let Some(m) = stream.next().await {
            let Ok(WsMessage::Binary(b)) = m else {
                if matches!(m, Ok(WsMessage::Text(_)) | Err(_) | Ok(WsMessage::Close(_))) {
                    return Err("expected a binary HELLO frame".to_owned());
                }
                continue;
            };
            let frames = fleetlink_relay::link::decode_all(&b)
                .map_err(|e| format!("malformed HELLO: {e}"))?;
            for f in frames {
                if let Ok(LinkEvent::Control(Frame::Hello {
                    version,
                    robot,
                    token,
                    heartbeat_ms,
                    outbox_epoch,
                })) = link.on_frame(f)
                {
                    return Ok((version, robot, token, heartbeat_ms, outbox_epoch));
                }
            }
            return Err("the first frame must be HELLO".to_owned());
        }
        Err("connection closed before HELLO".to_owned())
    })
    .await;
    let who = addr.map_or_else(|| "(unknown address)".to_owned(), |a| a.to_string());
    let (robot, heartbeat_ms, identity, outbox_epoch) = match hello {
        Ok(Ok((version, robot, token, hb, epoch))) => {
            if version != VERSION {
                let reason =
                    format!("unsupported protocol version {version}; this hub speaks {VERSION}");
                return refuse(sink, reason, &who, &ctx.rosout).await;
            }
            if !valid_robot_name(&robot) {
                let reason = format!(
                    "invalid robot name {robot:?}: use letters, digits and '_' (not starting with a digit)"
                );
                return refuse(sink, reason, &who, &ctx.rosout).await;
            }
            let hb = if hb == 0 {
                ctx.default_heartbeat_ms
            } else {
                hb.clamp(MIN_HEARTBEAT_MS, MAX_HEARTBEAT_MS)
            };
            // A robot token (or a certificate, or a trusted robot network) names the robot.
            // An operator token of the admin group may also open an agent link, for tools
            // such as `fleetlink bench relay`.
            // Anything but a robot token (operator, session, OIDC) is a bearer credential;
            // the token module tells them apart, not string prefixes here.
            let operator = !token.is_empty()
                && fleetlink_auth::Token::parse(&token)
                    .map_or(true, |t| t.kind() != fleetlink_auth::TokenKind::Robot);
            let credential = if operator {
                fleetlink_auth::Credential::Bearer(token)
            } else {
                fleetlink_auth::Credential::Agent {
                    robot: robot.clone(),
                    token: (!token.is_empty()).then_some(token),
                }
            };
            let admin = fleetlink_auth::GroupName::new("admin").expect("a valid group name");
            match crate::security::authenticate(&ctx.security, credential, conn).await {
                // Anyone else acting as a robot needs a rule letting it publish under
                // that robot's namespace: otherwise a viewer's token could evict a robot.
                Ok(identity)
                    if operator
                        && !identity.in_group(&admin)
                        && !ctx
                            .security
                            .access(identity.clone())
                            .allows(&format!("/{robot}"), fleetlink_auth::Operation::Publish) =>
                {
                    let reason = format!(
                        "{} may not act as robot {robot}: no rule lets it publish under /{robot}",
                        identity.principal()
                    );
                    return refuse(sink, reason, &format!("{robot} from {who}"), &ctx.rosout).await;
                }
                Ok(identity) => (robot, hb, identity, epoch),
                // The public message alone ("authentication failed", "authentication
                // required", a rate limit): the agent turns it into advice.
                Err(e) => {
                    let who = format!("{robot} from {who}");
                    return refuse(sink, e.public_message(), &who, &ctx.rosout).await;
                }
            }
        }
        Ok(Err(reason)) => return refuse(sink, reason, &who, &ctx.rosout).await,
        Err(_) => return refuse(sink, "no HELLO within 10 s".into(), &who, &ctx.rosout).await,
    };
    let namespace = format!("/{robot}");
    let (ctrl_tx, ctrl_rx) = mpsc::channel::<Control>(1024);
    let book = ctx.ledger.open(&robot, outbox_epoch).await;

    let (client, outbox) = ctx.router.connect(
        ClientKind::Agent {
            robot: robot.clone(),
        },
        addr,
    );
    let (peer, mut peer_rx) = ChannelPeer::new();
    ctx.router.calls.attach(client, peer);
    let session = ctx.registry.next_session.fetch_add(1, Relaxed) + 1;
    let live = Arc::new(LiveRobot {
        name: robot.clone(),
        client,
        session,
        addr,
        connected_at: SystemTime::now(),
        heartbeat_ms,
        rtt_ns: AtomicU64::new(0),
        last_seen_ns: AtomicU64::new(fleetlink_relay::unix_nanos()),
        demand_bps: AtomicU64::new(0),
        rate_bps: AtomicU64::new(0),
        latency_ns: AtomicU64::new(0),
        share_bps: AtomicU64::new(0),
        clock: Mutex::new(ClockSync::default()),
        clock_offset: AtomicI64::new(i64::MIN),
        control: ctrl_tx.clone(),
    });
    if let Some(old) = ctx.registry.insert(live.clone()) {
        tracing::info!(robot = %robot, "robot reconnected; replacing its previous connection");
        ctx.rosout.log(
            crate::rosout::Level::Info,
            "connected",
            format!("robot {robot} reconnected from {who}; its previous connection is closed"),
        );
        let _ = old.control.try_send(Control::Close);
        ctx.router.disconnect(old.client);
    }
    tracing::info!(robot = %robot, ?addr, "robot connected");
    ctx.rosout.log(
        crate::rosout::Level::Info,
        "connected",
        format!("robot {robot} connected from {who}"),
    );
    let store = ctx.store.clone();
    let (r, a) = (
        robot.clone(),
        addr.map(|a| a.to_string()).unwrap_or_default(),
    );
    tokio::task::spawn_blocking(move || {
        if let Err(e) = store.robot_seen(&r, &a, true) {
            tracing::warn!("cannot record robot {r}: {e}");
        }
    });

    let _ = ctrl_tx
        .send(Control::Frame(Frame::Welcome {
            session: format!("{session}"),
            namespace: namespace.clone(),
            hub_time_ns: fleetlink_relay::unix_nanos(),
            heartbeat_ms,
        }))
        .await;
    let heartbeat = Duration::from_millis(u64::from(heartbeat_ms));
    let gate = crate::security::HubGate::for_agent(
        ctx.security.clone(),
        ctx.registry.clone(),
        identity,
        &robot,
    );
    let writer = tokio::spawn(write_link(
        sink,
        outbox,
        ctrl_rx,
        heartbeat,
        Arc::new(|m| Some(m.name.to_string())),
        Vec::new(),
        Some(gate.fork()),
    ));

    let mut st = AgentSession {
        ctx: ctx.clone(),
        client,
        topics: HashMap::new(),
        subs: HashMap::new(),
        ctrl: ctrl_tx.clone(),
        live: live.clone(),
        gate: Box::new(gate),
        book,
        confirm: HashMap::new(),
        calls: LinkCalls::new(ctx.router.calls.clone(), client, Box::new(SameNames)),
    };
    let dead_after = heartbeat * 2;
    let gone = loop {
        let next = tokio::select! {
            _ = ctx.shutdown.cancelled() => break (crate::rosout::Level::Info, "the hub is shutting down".to_owned()),
            n = tokio::time::timeout(dead_after, stream.next()) => n,
            m = peer_rx.recv() => {
                if let Some(m) = m {
                    st.on_peer(m).await;
                }
                continue;
            }
        };
        let msg = match next {
            Err(_) => {
                tracing::warn!(robot = %robot, "no traffic for {dead_after:?}; declaring the link dead");
                break (
                    crate::rosout::Level::Warn,
                    format!(
                        "no traffic for {} ms: link declared dead",
                        dead_after.as_millis()
                    ),
                );
            }
            Ok(None) | Ok(Some(Ok(WsMessage::Close(_)))) => {
                break (
                    crate::rosout::Level::Info,
                    "the robot closed the connection".to_owned(),
                );
            }
            Ok(Some(Err(e))) => break (crate::rosout::Level::Warn, format!("link error: {e}")),
            Ok(Some(Ok(m))) => m,
        };
        live.last_seen_ns
            .store(fleetlink_relay::unix_nanos(), Relaxed);
        match msg {
            WsMessage::Binary(b) => {
                if let Err(e) = st.on_binary(&mut link, &b).await {
                    st.status(Level::Error, 1, e).await;
                }
                st.confirm_delivered(&robot).await;
                // Acknowledge what arrived so the agent's scheduler may send more.
                if let Some(ack) = link.take_ack() {
                    let _ = st.ctrl.send(Control::Frame(ack)).await;
                }
            }
            WsMessage::Text(_) => {
                st.status(
                    Level::Error,
                    2,
                    "fleetlink.v1 carries binary frames only".into(),
                )
                .await
            }
            _ => {}
        }
    };
    ctx.router.disconnect(client);
    ctx.registry.remove_if_session(&robot, session);
    ctx.rosout.log(
        gone.0,
        "disconnected",
        format!("robot {robot} disconnected: {}", gone.1),
    );
    let _ = ctrl_tx.try_send(Control::Close);
    drop(st);
    drop(ctrl_tx);
    let _ = writer.await;
    let store = ctx.store.clone();
    let a = addr.map(|a| a.to_string()).unwrap_or_default();
    tokio::task::spawn_blocking(move || store.robot_seen(&robot, &a, false));
}

/// Tells a connection why it is not accepted, then closes it.
async fn refuse<K>(mut sink: K, reason: String, who: &str, rosout: &crate::rosout::RosOut)
where
    K: Sink<WsMessage, Error = WsError> + Unpin,
{
    tracing::warn!("refusing agent: {reason}");
    rosout.log(
        crate::rosout::Level::Warn,
        "refused",
        format!("refused agent {who}: {reason}"),
    );
    let status = Frame::Status {
        level: Level::Error,
        code: 401,
        alias: 0,
        text: reason.clone(),
    };
    let _ = sink.send(WsMessage::Binary(status.to_bytes())).await;
    let reason: String = reason.chars().take(120).collect();
    let close = CloseFrame {
        code: CloseCode::Policy,
        reason: reason.into(),
    };
    let _ = sink.send(WsMessage::Close(Some(close))).await;
}

struct PubTopic {
    topic: Arc<Topic>,
    /// Its name, kept for the per-message checks (the topic's own is behind an ArcSwap).
    name: TopicName,
}

struct AgentSession {
    ctx: Arc<AgentContext>,
    client: ClientId,
    topics: HashMap<u32, PubTopic>,
    subs: HashMap<u32, SubscriptionId>,
    ctrl: mpsc::Sender<Control>,
    live: Arc<LiveRobot>,
    gate: Box<dyn Gate>,
    /// Delivery marks of this robot's no-drop topics.
    book: Arc<Mutex<RobotBook>>,
    /// No-drop aliases to confirm after this batch, with the highest sequence seen.
    confirm: HashMap<u32, u64>,
    /// Services and calls across this link.
    calls: LinkCalls,
}

impl AgentSession {
    async fn status(&self, level: Level, code: u32, text: String) {
        let _ = self
            .ctrl
            .send(Control::Frame(Frame::Status {
                level,
                code,
                alias: 0,
                text,
            }))
            .await;
    }

    async fn send_all(&self, out: Vec<Control>) {
        for c in out {
            let _ = self.ctrl.send(c).await;
        }
    }

    /// Something the hub's call table queued for this robot's link.
    async fn on_peer(&mut self, m: PeerMsg) {
        let mut out = Vec::new();
        self.calls.on_peer(m, &mut *self.gate, &mut out);
        self.send_all(out).await;
    }

    async fn on_binary(&mut self, link: &mut LinkIn, data: &Bytes) -> Result<(), String> {
        for f in fleetlink_proto::frame::frames(data) {
            let f = f.map_err(|e| format!("malformed frame: {e}"))?;
            if fleetlink_relay::link_calls::is_call_frame(&f) {
                let mut out = Vec::new();
                self.calls.on_frame(f, &mut *self.gate, &mut out);
                self.send_all(out).await;
                continue;
            }
            match link.on_frame(f) {
                Ok(LinkEvent::Message {
                    alias,
                    seq,
                    stamp_ns,
                    payload,
                    reliable: true,
                }) => {
                    let name = link.topic(alias).map_or("", |t| t.name.as_str());
                    let fresh = self
                        .book
                        .lock()
                        .unwrap_or_else(|p| p.into_inner())
                        .admit(name, seq);
                    let c = self.confirm.entry(alias).or_default();
                    *c = (*c).max(seq);
                    if fresh {
                        let ev = LinkEvent::Message {
                            alias,
                            seq,
                            stamp_ns,
                            payload,
                            reliable: true,
                        };
                        self.apply(ev).await;
                    }
                }
                Ok(ev) => self.apply(ev).await,
                Err(e) => self.status(Level::Error, 3, e.to_string()).await,
            }
        }
        Ok(())
    }

    /// Records the delivery marks this batch advanced, then confirms to the agent: once a
    /// `DELIVERED` is sent, a restarted hub still knows not to deliver those again.
    async fn confirm_delivered(&mut self, robot: &str) {
        if self.confirm.is_empty() {
            return;
        }
        self.ctx.ledger.record(robot, &self.book).await;
        for (alias, seq) in self.confirm.drain() {
            let _ = self
                .ctrl
                .send(Control::Frame(Frame::Delivered { alias, seq }))
                .await;
        }
    }

    async fn apply(&mut self, ev: LinkEvent) {
        match ev {
            LinkEvent::Advertise { alias, topic } => {
                let name = match TopicName::parse(&topic.name) {
                    Ok(n) => n,
                    Err(e) => {
                        return self
                            .status(Level::Error, 4, format!("advertise: {e}"))
                            .await;
                    }
                };
                if !self.gate.allows(name.as_str(), Op::Publish) {
                    let text = format!(
                        "advertise {name}: not allowed for {}",
                        self.gate.principal()
                    );
                    return self.status(Level::Error, 403, text).await;
                }
                match self
                    .ctx
                    .router
                    .advertise(self.client, &name, topic.schema, topic.latched)
                {
                    Ok(t) => {
                        self.topics.insert(alias, PubTopic { topic: t, name });
                    }
                    Err(e) => {
                        self.status(Level::Error, 5, format!("advertise: {e}"))
                            .await
                    }
                }
            }
            LinkEvent::Unadvertise { alias, topic } => {
                if self.topics.remove(&alias).is_some()
                    && let Ok(name) = TopicName::parse(&topic.name)
                {
                    self.ctx.router.unadvertise(self.client, &name);
                }
            }
            LinkEvent::Message {
                alias,
                seq,
                stamp_ns,
                payload,
                ..
            } => {
                if let Some(p) = self.topics.get(&alias) {
                    // Asked per message (a cached answer) so a rule change applies at once.
                    if self.gate.allows(p.name.as_str(), Op::Publish) {
                        let size = payload.len();
                        let msg = p.topic.publish(self.client, seq, stamp_ns, payload);
                        // End-to-end latency on the hub's clock: origin stamp plus the
                        // robot's clock offset, to when the hub received it (the
                        // message's own receive time: no second clock read).
                        if let Some(off) = self.live.clock_offset_ns() {
                            let origin = stamp_ns as i128 + off as i128;
                            let at = msg.received_unix_ns() as i128;
                            if at >= origin {
                                p.topic.stats.record_latency((at - origin) as u64);
                            }
                        }
                        self.gate.done(p.name.as_str(), Op::Publish, size);
                    }
                }
            }
            LinkEvent::Control(Frame::Subscribe { pattern, flags, .. })
                if flags & fleetlink_proto::frame::SUBSCRIBE_SERVICES != 0 =>
            {
                // The robot wants to hear of fleet services it may call (filtered by the
                // gate when each is offered).
                let source = if flags & fleetlink_proto::frame::SUBSCRIBE_REGEX != 0 {
                    pattern
                } else {
                    regex::escape(&pattern)
                };
                match Router::compile_pattern(&source) {
                    Ok(re) => self.ctx.router.calls.watch(self.client, re),
                    Err(e) => {
                        self.status(Level::Error, 6, format!("subscribe services: {e}"))
                            .await
                    }
                }
            }
            LinkEvent::Control(Frame::Subscribe {
                id,
                pattern,
                flags,
                throttle_ms,
                queue_length,
            }) => {
                let target = if flags & fleetlink_proto::frame::SUBSCRIBE_REGEX != 0 {
                    match Router::compile_pattern(&pattern) {
                        Ok(r) => Target::Pattern(r),
                        Err(e) => {
                            return self
                                .status(Level::Error, 6, format!("subscribe: {e}"))
                                .await;
                        }
                    }
                } else {
                    match TopicName::parse(&pattern) {
                        Ok(n) if self.gate.allows(n.as_str(), Op::Subscribe) => Target::Exact(n),
                        Ok(n) => {
                            let text =
                                format!("subscribe {n}: not allowed for {}", self.gate.principal());
                            return self.status(Level::Error, 403, text).await;
                        }
                        Err(e) => {
                            return self
                                .status(Level::Error, 6, format!("subscribe: {e}"))
                                .await;
                        }
                    }
                };
                if let Some(old) = self.subs.remove(&id) {
                    self.ctx.router.unsubscribe(self.client, old);
                }
                let opts = SubOptions {
                    queue_length,
                    throttle_ms,
                    ..Default::default()
                };
                match self.ctx.router.subscribe(self.client, target, opts) {
                    Ok(sid) => {
                        self.subs.insert(id, sid);
                    }
                    Err(e) => {
                        self.status(Level::Error, 6, format!("subscribe: {e}"))
                            .await
                    }
                }
            }
            LinkEvent::Control(Frame::Unsubscribe { id }) => {
                if let Some(sid) = self.subs.remove(&id) {
                    self.ctx.router.unsubscribe(self.client, sid);
                }
            }
            LinkEvent::Control(Frame::Ping { id, sent_ns }) => {
                let pong = Frame::Pong {
                    id,
                    echo_ns: sent_ns,
                    responder_ns: fleetlink_relay::unix_nanos(),
                };
                let _ = self.ctrl.send(Control::Frame(pong)).await;
            }
            LinkEvent::Control(Frame::Pong {
                echo_ns,
                responder_ns,
                ..
            }) => {
                let now = fleetlink_relay::unix_nanos();
                let rtt = now.saturating_sub(echo_ns);
                self.live.rtt_ns.store(rtt, Relaxed);
                // The robot read its clock about half a round trip after we sent.
                let offset = (echo_ns as i128 + rtt as i128 / 2 - responder_ns as i128)
                    .clamp(i64::MIN as i128, i64::MAX as i128) as i64;
                let mut c = self.live.clock.lock().unwrap_or_else(|p| p.into_inner());
                if c.samples.len() == CLOCK_SAMPLES {
                    c.samples.pop_front();
                }
                c.samples.push_back((rtt, offset));
                if let Some((_, best)) = c.samples.iter().min_by_key(|(rtt, _)| *rtt) {
                    self.live.clock_offset.store(*best, Relaxed);
                }
            }
            LinkEvent::Control(Frame::LinkReport {
                demand_bps,
                rate_bps,
                latency_ns,
            }) => {
                self.live.demand_bps.store(demand_bps, Relaxed);
                self.live.rate_bps.store(rate_bps, Relaxed);
                self.live.latency_ns.store(latency_ns, Relaxed);
            }
            LinkEvent::Control(Frame::Status { level, text, .. }) => {
                tracing::info!(robot = %self.live.name, level = level.as_str(), "agent status: {text}");
            }
            // A second HELLO, frames only a hub sends, an agent's ACK: nothing to do.
            LinkEvent::Control(_) | LinkEvent::None => {}
        }
    }
}
