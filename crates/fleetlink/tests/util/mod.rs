//! Test plumbing: start hubs and agents on port 0, a small rosbridge client, and waits
//! bounded by a timeout (never a bare sleep).

#![allow(dead_code)]

use std::future::Future;
use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use fleetlink_agent::uplink::{LinkState, NameMap, UplinkConfig};
use fleetlink_agent::{Agent, AgentOptions};
use fleetlink_hub::{Hub, HubConfig};
use futures_util::{SinkExt, StreamExt};
use serde_json::{Value, json};
use tokio::net::TcpStream;
use tokio::sync::watch;
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_tungstenite::{MaybeTlsStream, WebSocketStream};
use tokio_util::sync::CancellationToken;

/// Upper bound for anything a test waits for.
pub const WAIT: Duration = Duration::from_secs(20);

pub async fn within<T>(what: &str, f: impl Future<Output = T>) -> T {
    match tokio::time::timeout(WAIT, f).await {
        Ok(v) => v,
        Err(_) => panic!("timed out after {WAIT:?} waiting for {what}"),
    }
}

pub struct TestHub {
    pub addr: SocketAddr,
    /// A token of the `admin` group: rosbridge clients in tests connect with it.
    pub operator_token: String,
    pub stop: CancellationToken,
    pub state: Arc<fleetlink_hub::state::HubState>,
    pub task: tokio::task::JoinHandle<()>,
    pub data_dir: PathBuf,
}

pub fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "fleetlink-test-{tag}-{}-{}",
        std::process::id(),
        fastrand_u64()
    ));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// The `fleetlink` binary with its state in `dir`: what an agent keeps by default under
/// the user's state directory (`$XDG_STATE_HOME/fleetlink/<robot>/runtime.json`: changes
/// made while it ran) is `dir/state/...`, so a test never reads or writes the user's.
pub fn fleetlink_in(dir: &std::path::Path) -> std::process::Command {
    let mut c = std::process::Command::new(env!("CARGO_BIN_EXE_fleetlink"));
    c.env("XDG_STATE_HOME", dir.join("state"))
        .env_remove("STATE_DIRECTORY");
    c
}

fn fastrand_u64() -> u64 {
    use std::hash::{BuildHasher, RandomState};
    RandomState::new().hash_one(std::time::Instant::now())
}

pub async fn start_hub_at(addr: SocketAddr, data_dir: PathBuf, heartbeat: Duration) -> TestHub {
    start_hub_cfg(HubConfig {
        listen: addr,
        data_dir,
        heartbeat,
        ..HubConfig::default()
    })
    .await
}

/// A hub on port 0 with settings changed by `tweak` (TLS, anonymous read, ...).
pub async fn start_hub_with(tweak: impl FnOnce(&mut HubConfig)) -> TestHub {
    let mut cfg = HubConfig {
        listen: "127.0.0.1:0".parse().unwrap(),
        data_dir: temp_dir("hub"),
        heartbeat: Duration::from_millis(500),
        ..HubConfig::default()
    };
    tweak(&mut cfg);
    start_hub_cfg(cfg).await
}

pub async fn start_hub_cfg(cfg: HubConfig) -> TestHub {
    let data_dir = cfg.data_dir.clone();
    let hub = Hub::bind(
        cfg,
        Arc::new(fleetlink_relay::transcode::RegistryTranscoder::bundled()),
    )
    .await
    .expect("hub binds");
    let addr = hub.local_addr();
    let state = hub.state();
    let now = fleetlink_auth::UnixTime::now();
    let operator_token = state
        .security
        .store
        .mint_operator_token(
            &fleetlink_auth::UserName::new("tester").unwrap(),
            &[fleetlink_auth::GroupName::new("admin").unwrap()],
            None,
            now,
        )
        .expect("mint operator token")
        .expose()
        .to_owned();
    let stop = CancellationToken::new();
    let s = stop.clone();
    let task = tokio::spawn(async move {
        hub.run(async move { s.cancelled().await })
            .await
            .expect("hub runs");
    });
    TestHub {
        addr,
        operator_token,
        stop,
        state,
        task,
        data_dir,
    }
}

pub async fn start_hub() -> TestHub {
    start_hub_at(
        "127.0.0.1:0".parse().unwrap(),
        temp_dir("hub"),
        Duration::from_millis(500),
    )
    .await
}

impl TestHub {
    /// The rosbridge URL with the operator token (browsers' way of authenticating).
    pub fn ws_url(&self) -> String {
        format!("ws://{}/?token={}", self.addr, self.operator_token)
    }

    /// The URL without credentials: agents authenticate in HELLO.
    pub fn agent_url(&self) -> String {
        format!("ws://{}", self.addr)
    }

    /// Replaces the hub's access rules with a YAML document, as the operator.
    pub fn set_rules(&self, yaml: &str) {
        let now = fleetlink_auth::UnixTime::now();
        let sec = &self.state.security;
        let me = sec
            .authenticate(
                fleetlink_auth::Credential::Bearer(self.operator_token.clone()),
                fleetlink_auth::ConnInfo::new([127, 0, 0, 1].into()),
                now,
            )
            .expect("operator token is valid");
        sec.import_rules_yaml(&me, yaml, now).expect("rules import");
    }

    /// A fresh token for robot `name`.
    pub fn robot_token(&self, name: &str) -> String {
        let robot = fleetlink_auth::RobotName::new(name).unwrap();
        self.state
            .security
            .store
            .add_robot_token(&robot, None, fleetlink_auth::UnixTime::now())
            .expect("mint robot token")
            .expose()
            .to_owned()
    }

    pub async fn shutdown(self) {
        self.stop.cancel();
        let _ = within("hub shutdown", self.task).await;
    }
}

pub struct TestAgent {
    pub router: Arc<fleetlink_relay::Router>,
    pub local: Option<SocketAddr>,
    pub state: watch::Receiver<LinkState>,
    pub stats: Arc<fleetlink_agent::uplink::UplinkStats>,
    pub stop: CancellationToken,
    pub task: tokio::task::JoinHandle<()>,
}

/// An uplink for robot `robot` of `hub`, with a token minted for it.
pub fn uplink_config(hub: &TestHub, robot: &str) -> UplinkConfig {
    UplinkConfig {
        hub_urls: vec![hub.agent_url()],
        robot: fleetlink_auth::RobotName::new(robot).expect("a valid robot name"),
        token: hub.robot_token(robot),
        heartbeat: Duration::from_millis(200),
        reconnect_initial: Duration::from_millis(50),
        reconnect_max: Duration::from_millis(400),
        names: NameMap::default(),
        topic_qos: Vec::new(),
        max_in_flight: 32,
        tls: None,
        outbox: None,
        latest_cache_bytes: 64 << 20,
        budget: None,
        hub_id: None,
        upstream_gate: None,
        mirror: None,
    }
}

pub async fn start_agent_with(uplink: UplinkConfig, local: bool) -> TestAgent {
    start_agent_sim(uplink, local, None).await
}

/// An agent that also runs a simulated robot (`sim`).
pub async fn start_agent_sim(
    uplink: UplinkConfig,
    local: bool,
    sim: Option<fleetlink_agent::config::SimConfig>,
) -> TestAgent {
    start_agent_opts(AgentOptions {
        uplink,
        local_listen: local.then(|| "127.0.0.1:0".parse().unwrap()),
        sim,
        ros1: None,
        ros2: None,
        rosbridge: None,
        blackbox: None,
        video: Vec::new(),
        runtime: None,
    })
    .await
}

/// An agent with any options.
pub async fn start_agent_opts(opts: AgentOptions) -> TestAgent {
    let agent = Agent::bind(
        opts,
        Arc::new(fleetlink_relay::transcode::RegistryTranscoder::bundled()),
    )
    .await
    .expect("agent binds");
    let router = agent.router();
    let local = agent.local_addr();
    let state = agent.link_state();
    let stats = agent.uplink_stats();
    let stop = CancellationToken::new();
    let s = stop.clone();
    let task = tokio::spawn(agent.run(s));
    TestAgent {
        router,
        local,
        state,
        stats,
        stop,
        task,
    }
}

pub async fn start_agent(hub: &TestHub, robot: &str) -> TestAgent {
    let a = start_agent_with(uplink_config(hub, robot), true).await;
    a.wait_connected().await;
    a
}

impl TestAgent {
    pub async fn wait_connected(&self) {
        let mut rx = self.state.clone();
        within(
            "agent to connect",
            rx.wait_for(|s| matches!(s, LinkState::Connected { .. })),
        )
        .await
        .expect("state channel open");
    }

    pub async fn wait_disconnected(&self) -> String {
        let mut rx = self.state.clone();
        let s = within(
            "agent to notice the link is down",
            rx.wait_for(|s| matches!(s, LinkState::Disconnected { .. })),
        )
        .await
        .expect("state channel open")
        .clone();
        match s {
            LinkState::Disconnected { reason } => reason,
            _ => unreachable!(),
        }
    }

    pub fn local_url(&self) -> String {
        format!("ws://{}", self.local.expect("local listener enabled"))
    }

    pub async fn shutdown(self) {
        self.stop.cancel();
        let _ = within("agent shutdown", self.task).await;
    }
}

/// A minimal rosbridge client for tests that run in Rust.
pub struct Rosbridge {
    ws: WebSocketStream<MaybeTlsStream<TcpStream>>,
}

impl Rosbridge {
    pub async fn connect(url: &str) -> Rosbridge {
        let (ws, _) = within("rosbridge connect", tokio_tungstenite::connect_async(url))
            .await
            .expect("connects");
        Rosbridge { ws }
    }

    /// Sends all of `ops` with one flush, so they reach the server together.
    pub async fn send_all(&mut self, ops: impl IntoIterator<Item = Value>) {
        for v in ops {
            self.ws
                .feed(WsMessage::text(v.to_string()))
                .await
                .expect("send");
        }
        self.ws.flush().await.expect("flush");
    }

    pub async fn send(&mut self, v: Value) {
        self.ws
            .send(WsMessage::text(v.to_string()))
            .await
            .expect("send");
    }

    pub async fn send_raw(
        &mut self,
        m: WsMessage,
    ) -> Result<(), tokio_tungstenite::tungstenite::Error> {
        self.ws.send(m).await
    }

    /// Next JSON text or CBOR binary frame, decoded to JSON.
    pub async fn recv(&mut self) -> Value {
        self.try_recv().await.expect("connection open")
    }

    pub async fn try_recv(&mut self) -> Option<Value> {
        loop {
            let m = within("a rosbridge frame", self.ws.next()).await?;
            match m {
                Ok(WsMessage::Text(t)) => {
                    return Some(serde_json::from_str(t.as_str()).expect("server sends JSON"));
                }
                Ok(WsMessage::Binary(b)) => {
                    let j = fleetlink_proto::rosbridge::convert::cbor_to_json(&b)
                        .expect("server sends CBOR");
                    return Some(serde_json::from_slice(&j).expect("converted JSON parses"));
                }
                Ok(WsMessage::Close(_)) | Err(_) => return None,
                Ok(_) => continue,
            }
        }
    }

    /// Next frame with `op` equal to `op`, skipping others.
    pub async fn recv_op(&mut self, op: &str) -> Value {
        loop {
            let v = self.recv().await;
            if v["op"] == op {
                return v;
            }
        }
    }

    pub async fn call(&mut self, service: &str, args: Value, id: &str) -> Value {
        self.send(json!({"op": "call_service", "service": service, "args": args, "id": id}))
            .await;
        loop {
            let v = self.recv_op("service_response").await;
            if v["id"] == id {
                return v;
            }
        }
    }

    pub fn raw(&mut self) -> &mut WebSocketStream<MaybeTlsStream<TcpStream>> {
        &mut self.ws
    }
}

/// Publishes on the agent's local router as an in-process participant.
pub struct LocalPublisher {
    topic: Arc<fleetlink_relay::Topic>,
    client: fleetlink_relay::ClientId,
    seq: u64,
}

impl LocalPublisher {
    pub fn new(router: &fleetlink_relay::Router, name: &str, type_name: &str) -> LocalPublisher {
        let (client, _) = router.connect(
            fleetlink_relay::ClientKind::Internal {
                role: "test".into(),
            },
            None,
        );
        let n = fleetlink_relay::TopicName::parse(name).unwrap();
        let topic = router
            .advertise(client, &n, fleetlink_proto::Schema::named(type_name), false)
            .unwrap();
        LocalPublisher {
            topic,
            client,
            seq: 0,
        }
    }

    pub fn publish_json(&mut self, v: &Value) {
        self.seq += 1;
        let payload = fleetlink_proto::Payload::json(serde_json::to_vec(v).unwrap());
        self.topic.publish(
            self.client,
            self.seq,
            fleetlink_relay::unix_nanos(),
            payload,
        );
    }
}

/// A TCP proxy between a client and a server that a test can "blackhole": traffic stops
/// flowing (in both directions, or only server → client) while both sockets stay open, as
/// when a Wi-Fi link drops and TCP has not noticed. [`Blackhole::restore`] lets traffic
/// through again, as when the link comes back.
pub struct Blackhole {
    pub addr: SocketAddr,
    up: Arc<std::sync::atomic::AtomicBool>,
    down: Arc<std::sync::atomic::AtomicBool>,
    task: tokio::task::JoinHandle<()>,
}

impl Blackhole {
    pub async fn start(target: SocketAddr) -> Blackhole {
        let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
            .await
            .expect("proxy binds");
        let addr = listener.local_addr().unwrap();
        let up = Arc::new(std::sync::atomic::AtomicBool::new(false));
        let down = Arc::new(std::sync::atomic::AtomicBool::new(false));
        let (u, d) = (up.clone(), down.clone());
        let task = tokio::spawn(async move {
            while let Ok((inbound, _)) = listener.accept().await {
                if u.load(std::sync::atomic::Ordering::SeqCst) {
                    // A dead link: the connection attempt goes nowhere.
                    drop(inbound);
                    continue;
                }
                let Ok(outbound) = TcpStream::connect(target).await else {
                    continue;
                };
                let (ri, wi) = inbound.into_split();
                let (ro, wo) = outbound.into_split();
                tokio::spawn(pump(ri, wo, u.clone()));
                tokio::spawn(pump(ro, wi, d.clone()));
            }
        });
        Blackhole {
            addr,
            up,
            down,
            task,
        }
    }

    /// Stops forwarding both ways; bytes read afterwards are discarded, sockets stay open.
    pub fn cut(&self) {
        self.up.store(true, std::sync::atomic::Ordering::SeqCst);
        self.down.store(true, std::sync::atomic::Ordering::SeqCst);
    }

    /// Stops forwarding server → client only: the server gets everything, the client
    /// hears nothing back (no acknowledgements).
    pub fn cut_downstream(&self) {
        self.down.store(true, std::sync::atomic::Ordering::SeqCst);
    }

    /// Forwards again, for new connections and the ones still open.
    pub fn restore(&self) {
        self.up.store(false, std::sync::atomic::Ordering::SeqCst);
        self.down.store(false, std::sync::atomic::Ordering::SeqCst);
    }
}

impl Drop for Blackhole {
    fn drop(&mut self) {
        self.task.abort();
    }
}

async fn pump(
    mut from: tokio::net::tcp::OwnedReadHalf,
    mut to: tokio::net::tcp::OwnedWriteHalf,
    cut: Arc<std::sync::atomic::AtomicBool>,
) {
    use tokio::io::{AsyncReadExt, AsyncWriteExt};
    let mut buf = vec![0u8; 64 * 1024];
    loop {
        let n = match from.read(&mut buf).await {
            Ok(0) | Err(_) => {
                if cut.load(std::sync::atomic::Ordering::SeqCst) {
                    // A dead link carries no FIN either: hold the other side open.
                    let _keep = to;
                    std::future::pending::<()>().await;
                }
                return;
            }
            Ok(n) => n,
        };
        if cut.load(std::sync::atomic::Ordering::SeqCst) {
            // Keep reading so the sender's TCP sees nothing wrong; forward nothing.
            continue;
        }
        if to.write_all(&buf[..n]).await.is_err() {
            return;
        }
    }
}

/// Publishes on the hub's router directly, as an in-process participant.
pub fn hub_publisher(hub: &TestHub, name: &str, type_name: &str) -> LocalPublisher {
    LocalPublisher::new(&hub.state.router, name, type_name)
}

/// An in-process subscriber at the hub to each of `topics`: interest that makes robots
/// send them. Its queue is never read (it keeps the newest messages); it leaves when
/// dropped.
pub struct HubSubscriber {
    router: Arc<fleetlink_relay::Router>,
    client: fleetlink_relay::ClientId,
}

pub fn hub_subscriber(hub: &TestHub, topics: &[&str]) -> HubSubscriber {
    let router = hub.state.router.clone();
    let (client, _) = router.connect(
        fleetlink_relay::ClientKind::Internal {
            role: "test-subscriber".into(),
        },
        None,
    );
    for t in topics {
        let name = fleetlink_relay::TopicName::parse(t).unwrap();
        router
            .subscribe(
                client,
                fleetlink_relay::router::Target::Exact(name),
                Default::default(),
            )
            .unwrap();
    }
    HubSubscriber { router, client }
}

impl Drop for HubSubscriber {
    fn drop(&mut self) {
        self.router.disconnect(self.client);
    }
}

/// One JSON API call over a plain HTTP/1.1 connection: `(status, body as JSON)`.
pub async fn http_json(
    addr: SocketAddr,
    method: &str,
    path: &str,
    token: Option<&str>,
    body: Option<&Value>,
) -> (u16, Value) {
    use tokio::io::{AsyncReadExt, AsyncWriteExt};
    let body = body.map(Value::to_string).unwrap_or_default();
    let mut req = format!(
        "{method} {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\nContent-Type: application/json\r\nContent-Length: {}\r\n",
        body.len()
    );
    if let Some(t) = token {
        req.push_str(&format!("Authorization: Bearer {t}\r\n"));
    }
    req.push_str("\r\n");
    req.push_str(&body);
    let mut tcp = within("HTTP connect", TcpStream::connect(addr))
        .await
        .expect("connect");
    tcp.write_all(req.as_bytes()).await.expect("write request");
    let mut raw = Vec::new();
    within("HTTP response", tcp.read_to_end(&mut raw))
        .await
        .expect("read response");
    let text = String::from_utf8_lossy(&raw);
    let (head, rest) = text.split_once("\r\n\r\n").unwrap_or((&text, ""));
    let status: u16 = head
        .split_whitespace()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .expect("status line");
    let json = if head
        .to_ascii_lowercase()
        .contains("transfer-encoding: chunked")
    {
        let mut out = String::new();
        let mut r = rest;
        while let Some((len, tail)) = r.split_once("\r\n") {
            let n = usize::from_str_radix(len.trim(), 16).unwrap_or(0);
            if n == 0 || tail.len() < n {
                break;
            }
            out.push_str(&tail[..n]);
            r = tail[n..].trim_start_matches("\r\n");
        }
        out
    } else {
        rest.to_owned()
    };
    let v = if json.trim().is_empty() {
        Value::Null
    } else {
        serde_json::from_str(&json).unwrap_or_else(|e| panic!("body is not JSON ({e}): {json:?}"))
    };
    (status, v)
}

/// `site`'s link to `cloud` as site `name`, running until the returned token is cancelled.
pub async fn link_site(cloud: &TestHub, site: &TestHub, name: &str) -> CancellationToken {
    let mut cfg = uplink_config(cloud, name);
    cfg.hub_id = Some(site.state.agents.hub_id);
    let uplink = fleetlink_agent::uplink::Uplink::new(cfg, site.state.router.clone())
        .expect("the site's uplink");
    let mut state = uplink.watch();
    let stop = CancellationToken::new();
    tokio::spawn(uplink.run(stop.clone()));
    within(
        "the site to connect upstream",
        state.wait_for(|s| matches!(s, fleetlink_agent::uplink::LinkState::Connected { .. })),
    )
    .await
    .expect("the uplink's state");
    stop
}

/// Messages of topic `name` the hub receives in `window` (once the topic exists).
pub async fn messages_in(hub: &TestHub, name: &str, window: Duration) -> u64 {
    let name = fleetlink_relay::TopicName::parse(name).unwrap();
    let mut topic = None;
    eventually("the topic at the hub", || {
        topic = hub.state.router.topic(&name);
        topic.is_some()
    })
    .await;
    let topic = topic.unwrap();
    let before = topic
        .stats
        .messages
        .load(std::sync::atomic::Ordering::Relaxed);
    tokio::time::sleep(window).await;
    topic
        .stats
        .messages
        .load(std::sync::atomic::Ordering::Relaxed)
        - before
}

/// Waits until `cond` holds, checking every few milliseconds, for at most [`WAIT`].
pub async fn eventually(what: &str, mut cond: impl FnMut() -> bool) {
    within(what, async {
        while !cond() {
            tokio::time::sleep(Duration::from_millis(2)).await;
        }
    })
    .await
}
