//! Attacks on the hub's security, one named test per attack, each over the real wire
//! against an in-process hub on port 0. Every test asserts three things: the refusal the
//! attacker sees (status, HTTP code, close), that the refusal is in the audit log, and
//! that the hub keeps serving a legitimate client afterwards.
//!
//! Plumbing is here; the attacks are grouped by what they target.

mod credentials;
mod front_door;
mod listings;
mod malformed_inputs;
mod names;
mod transport;

use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use bytes::Bytes;
use fleetlink_auth::audit::{AuditAction, AuditQuery, StoredAudit};
use fleetlink_auth::{GroupName, UnixTime, UserName};
use fleetlink_hub::state::HubState;
use fleetlink_hub::{Hub, HubConfig};
use fleetlink_proto::frame::Frame;
use futures_util::{SinkExt, StreamExt};
use serde_json::{Value, json};
use tokio::io::{AsyncRead, AsyncReadExt, AsyncWrite, AsyncWriteExt};
use tokio::net::TcpStream;
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::tungstenite::client::IntoClientRequest;
use tokio_tungstenite::{MaybeTlsStream, WebSocketStream};
use tokio_util::sync::CancellationToken;

pub type Ws = WebSocketStream<MaybeTlsStream<TcpStream>>;

/// Upper bound for anything a test waits for.
pub const WAIT: Duration = Duration::from_secs(20);

pub async fn within<T>(what: &str, f: impl Future<Output = T>) -> T {
    match tokio::time::timeout(WAIT, f).await {
        Ok(v) => v,
        Err(_) => panic!("timed out after {WAIT:?} waiting for {what}"),
    }
}

pub struct Fixture {
    pub addr: SocketAddr,
    pub state: Arc<HubState>,
    /// A token of the `admin` group.
    pub operator: String,
    stop: CancellationToken,
}

impl Drop for Fixture {
    fn drop(&mut self) {
        self.stop.cancel();
    }
}

pub fn temp_dir(tag: &str) -> PathBuf {
    use std::hash::{BuildHasher, RandomState};
    let d = std::env::temp_dir().join(format!(
        "fleetlink-attacks-{tag}-{}-{}",
        std::process::id(),
        RandomState::new().hash_one(std::time::Instant::now())
    ));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// A hub on port 0 with the default (locked-down) policy, changed by `tweak`.
pub async fn hub_with(tweak: impl FnOnce(&mut HubConfig)) -> Fixture {
    let mut cfg = HubConfig {
        listen: "127.0.0.1:0".parse().unwrap(),
        data_dir: temp_dir("hub"),
        ..HubConfig::default()
    };
    tweak(&mut cfg);
    let hub = Hub::bind(cfg, Arc::new(fleetlink_relay::GenericTranscoder))
        .await
        .expect("hub binds");
    let addr = hub.local_addr();
    let state = hub.state();
    let operator = mint_operator(&state, "operator", &["admin"]);
    let stop = CancellationToken::new();
    let s = stop.clone();
    tokio::spawn(hub.run(async move { s.cancelled().await }));
    Fixture {
        addr,
        state,
        operator,
        stop,
    }
}

pub async fn hub() -> Fixture {
    hub_with(|_| {}).await
}

pub fn mint_operator(state: &HubState, user: &str, groups: &[&str]) -> String {
    let groups: Vec<GroupName> = groups.iter().map(|g| GroupName::new(g).unwrap()).collect();
    state
        .security
        .store
        .mint_operator_token(
            &UserName::new(user).unwrap(),
            &groups,
            None,
            UnixTime::now(),
        )
        .expect("mint operator token")
        .expose()
        .to_owned()
}

impl Fixture {
    pub fn robot_token(&self, robot: &str, expires: Option<UnixTime>) -> String {
        self.state
            .security
            .store
            .add_robot_token(
                &fleetlink_auth::RobotName::new(robot).unwrap(),
                expires,
                UnixTime::now(),
            )
            .expect("mint robot token")
            .expose()
            .to_owned()
    }

    pub fn ws_url(&self, token: &str) -> String {
        format!("ws://{}/?token={token}", self.addr)
    }

    /// Audit records matching `q`, after everything queued so far is written.
    pub async fn audit(&self, q: AuditQuery) -> Vec<StoredAudit> {
        let sec = self.state.security.clone();
        tokio::task::spawn_blocking(move || {
            sec.audit.flush();
            sec.store.query_audit(&q).expect("audit query").records
        })
        .await
        .expect("audit task")
    }

    /// Every audit record of `action`, allowed or not.
    pub async fn audited(&self, action: AuditAction) -> Vec<StoredAudit> {
        self.audit(AuditQuery {
            action: Some(action),
            limit: 1000,
            ..AuditQuery::default()
        })
        .await
    }

    /// Asserts a denied record of `action` exists whose `field` contains `needle`.
    pub async fn assert_audited(&self, action: AuditAction, needle: &str) -> StoredAudit {
        let recs = self
            .audit(AuditQuery {
                action: Some(action),
                allowed: Some(false),
                limit: 1000,
                ..AuditQuery::default()
            })
            .await;
        let hit = recs.iter().find(|r| {
            let text = serde_json::to_string(&r.record).unwrap();
            text.contains(needle)
        });
        match hit {
            Some(r) => r.clone(),
            None => panic!("no denied {action:?} record mentioning {needle:?} in {recs:#?}"),
        }
    }

    /// A legitimate operator still gets answers: a rosbridge `rosapi` call succeeds.
    pub async fn still_serving(&self) {
        let mut ws = rosbridge(&self.ws_url(&self.operator)).await;
        send(
            &mut ws,
            json!({"op": "call_service", "service": "/rosapi/get_time", "id": "alive"}),
        )
        .await;
        loop {
            let v = next(&mut ws).await.expect("operator connection open");
            if v["op"] == "service_response" && v["id"] == "alive" {
                assert_eq!(v["result"], true, "{v}");
                return;
            }
        }
    }
}

pub async fn rosbridge(url: &str) -> Ws {
    within("rosbridge connect", tokio_tungstenite::connect_async(url))
        .await
        .expect("rosbridge client connects")
        .0
}

pub async fn send(ws: &mut Ws, v: Value) {
    ws.send(Message::text(v.to_string())).await.expect("send");
}

/// The next JSON frame; `None` once the connection is closed.
pub async fn next(ws: &mut Ws) -> Option<Value> {
    loop {
        match within("a rosbridge frame", ws.next()).await? {
            Ok(Message::Text(t)) => return Some(serde_json::from_str(t.as_str()).unwrap()),
            Ok(Message::Close(_)) | Err(_) => return None,
            Ok(_) => {}
        }
    }
}

/// Next frame with `op` == `op`, skipping others.
pub async fn next_op(ws: &mut Ws, op: &str) -> Value {
    loop {
        let v = next(ws).await.expect("connection open");
        if v["op"] == op {
            return v;
        }
    }
}

/// Opens a `fleetlink.v1` agent link and sends HELLO.
pub async fn agent(addr: SocketAddr, robot: &str, token: &str, xff: Option<&str>) -> Ws {
    let mut req = format!("ws://{addr}/").into_client_request().unwrap();
    let h = req.headers_mut();
    h.insert(
        "sec-websocket-protocol",
        fleetlink_proto::SUBPROTOCOL.parse().unwrap(),
    );
    if let Some(x) = xff {
        h.insert("x-forwarded-for", x.parse().unwrap());
    }
    let (mut ws, _) = within("agent connect", tokio_tungstenite::connect_async(req))
        .await
        .expect("agent upgrade");
    hello(&mut ws, robot, token).await;
    ws
}

pub async fn hello<S>(ws: &mut WebSocketStream<S>, robot: &str, token: &str)
where
    S: AsyncRead + AsyncWrite + Unpin,
{
    let f = Frame::Hello {
        version: fleetlink_proto::frame::VERSION,
        robot: robot.into(),
        token: token.into(),
        heartbeat_ms: 0,
        outbox_epoch: 0,
        mirror: String::new(),
    };
    ws.send(Message::Binary(f.to_bytes()))
        .await
        .expect("send HELLO");
}

pub async fn send_frame<S>(ws: &mut WebSocketStream<S>, f: Frame)
where
    S: AsyncRead + AsyncWrite + Unpin,
{
    ws.send(Message::Binary(f.to_bytes()))
        .await
        .expect("send frame");
}

/// The next fleetlink frame that is not a ping or ack; `None` once closed.
pub async fn next_frame<S>(ws: &mut WebSocketStream<S>) -> Option<Frame>
where
    S: AsyncRead + AsyncWrite + Unpin,
{
    loop {
        match within("a fleetlink frame", ws.next()).await? {
            Ok(Message::Binary(b)) => {
                for f in fleetlink_proto::frame::frames(&b) {
                    match f.expect("hub sends well-formed frames") {
                        Frame::Ping { id, sent_ns } => {
                            let pong = Frame::Pong {
                                id,
                                echo_ns: sent_ns,
                                responder_ns: 0,
                            };
                            let _ = ws.send(Message::Binary(pong.to_bytes())).await;
                        }
                        Frame::Ack { .. } | Frame::Pong { .. } => {}
                        f => return Some(f),
                    }
                }
            }
            Ok(Message::Close(_)) | Err(_) => return None,
            Ok(_) => {}
        }
    }
}

/// Waits for WELCOME: the link is accepted.
pub async fn welcomed<S>(ws: &mut WebSocketStream<S>)
where
    S: AsyncRead + AsyncWrite + Unpin,
{
    match next_frame(ws).await {
        Some(Frame::Welcome { .. }) => {}
        other => panic!("expected WELCOME, got {other:?}"),
    }
}

/// Expects `STATUS` with `code` (text containing `needle`) and then, if `closes`, the end
/// of the connection.
pub async fn refused<S>(ws: &mut WebSocketStream<S>, code: u32, needle: &str)
where
    S: AsyncRead + AsyncWrite + Unpin,
{
    match next_frame(ws).await {
        Some(Frame::Status { code: c, text, .. }) => {
            assert_eq!(c, code, "status {text:?}");
            assert!(
                text.contains(needle),
                "status {text:?} should mention {needle:?}"
            );
        }
        other => panic!("expected STATUS {code}, got {other:?}"),
    }
}

/// One raw HTTP/1.1 exchange: the request line is sent exactly as given (no client-side
/// path normalisation), the whole response read until the server closes.
pub struct HttpReply {
    pub status: u16,
    pub head: String,
    pub body: String,
}

impl HttpReply {
    pub fn json(&self) -> Value {
        serde_json::from_str(&self.body)
            .unwrap_or_else(|e| panic!("body is not JSON ({e}): {:?}", self.body))
    }

    pub fn header(&self, name: &str) -> Option<&str> {
        self.head.lines().find_map(|l| {
            let (k, v) = l.split_once(':')?;
            k.trim().eq_ignore_ascii_case(name).then_some(v.trim())
        })
    }
}

pub async fn http(
    addr: SocketAddr,
    method: &str,
    path: &str,
    headers: &[(&str, &str)],
    body: &str,
) -> HttpReply {
    let mut tcp = within("HTTP connect", TcpStream::connect(addr))
        .await
        .expect("connect");
    let mut req = format!(
        "{method} {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\nContent-Length: {}\r\n",
        body.len()
    );
    for (k, v) in headers {
        req.push_str(&format!("{k}: {v}\r\n"));
    }
    req.push_str("\r\n");
    req.push_str(body);
    tcp.write_all(req.as_bytes()).await.expect("write request");
    let mut raw = Vec::new();
    within("HTTP response", tcp.read_to_end(&mut raw))
        .await
        .expect("read response");
    let text = String::from_utf8_lossy(&raw).into_owned();
    let (head, body) = text.split_once("\r\n\r\n").unwrap_or((&text, ""));
    let status = head
        .split_whitespace()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("no status line in {head:?}"));
    // Chunked bodies: this API answers small JSON, so one chunk is enough to undo.
    let body = if head
        .to_ascii_lowercase()
        .contains("transfer-encoding: chunked")
    {
        body.split_once("\r\n")
            .map(|(_, rest)| rest.rsplit_once("\r\n0\r\n").map_or(rest, |(b, _)| b))
            .unwrap_or(body)
            .trim_end_matches("\r\n")
            .to_owned()
    } else {
        body.to_owned()
    };
    HttpReply {
        status,
        head: head.to_owned(),
        body,
    }
}

/// A JSON API call with a bearer token.
pub async fn api(fx: &Fixture, method: &str, path: &str, token: &str, body: &str) -> HttpReply {
    let auth = format!("Bearer {token}");
    http(
        fx.addr,
        method,
        path,
        &[
            ("Authorization", &auth),
            ("Content-Type", "application/json"),
        ],
        body,
    )
    .await
}

pub fn payload(v: Value) -> Bytes {
    Bytes::from(serde_json::to_vec(&v).unwrap())
}
