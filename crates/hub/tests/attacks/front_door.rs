//! Attacks on the front door (issue 9, part 6): slowloris headers, a body that never
//! arrives, an oversized body, connection floods from one address and in total, and a
//! stampede of handshakes. Each asserts the refusal, that it is counted, and that a
//! well-behaved client is still served.

use std::time::{Duration, Instant};

use serde_json::json;
use tokio::net::TcpSocket;
use tokio_tungstenite::tungstenite::Error as WsError;

use crate::*;

/// Raises this process's soft descriptor limit towards `want` (500 attackers need about
/// 1,000 descriptors: their end and the hub's, in one process).
fn raise_fd_limit(want: u64) {
    use rustix::process::{Resource, getrlimit, setrlimit};
    let lim = getrlimit(Resource::Nofile);
    let cap = lim.maximum.unwrap_or(want);
    if lim.current.is_some_and(|c| c < want.min(cap)) {
        let mut new = lim;
        new.current = Some(want.min(cap));
        let _ = setrlimit(Resource::Nofile, new);
    }
}

/// One slowloris connection: sends a request line, then one header byte every 200 ms,
/// and returns how long after its first byte the hub closed it.
async fn trickle(addr: SocketAddr) -> Duration {
    let mut tcp = TcpStream::connect(addr).await.expect("connect");
    let start = Instant::now();
    tcp.write_all(b"GET /healthz HTTP/1.1\r\nHost: x\r\nX-Slow: ")
        .await
        .expect("first bytes");
    let mut buf = [0u8; 512];
    let mut tick = tokio::time::interval(Duration::from_millis(200));
    loop {
        tokio::select! {
            r = tcp.read(&mut buf) => match r {
                // The hub closed (with or without a 408 first).
                Ok(0) | Err(_) => return start.elapsed(),
                Ok(_) => {}
            },
            _ = tick.tick() => {
                if tcp.write_all(b"a").await.is_err() {
                    return start.elapsed();
                }
            }
        }
    }
}

/// A rosbridge publish from `publisher` arrives at `subscriber` (subscribed to `topic`).
async fn relayed(publisher: &mut Ws, subscriber: &mut Ws, topic: &str, text: &str) {
    send(
        publisher,
        json!({"op": "publish", "topic": topic, "msg": {"data": text}}),
    )
    .await;
    loop {
        let m = next_op(subscriber, "publish").await;
        if m["msg"]["data"] == text {
            return;
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn slowloris_headers_are_cut_off_at_the_header_timeout() {
    raise_fd_limit(4096);
    let header_timeout = Duration::from_secs(1);
    let fx = hub_with(|c| c.door.header_timeout = header_timeout).await;

    // A well-behaved rosbridge pair, set up before the attack.
    let mut sub = rosbridge(&fx.ws_url(&fx.operator)).await;
    let mut publ = rosbridge(&fx.ws_url(&fx.operator)).await;
    send(
        &mut publ,
        json!({"op": "advertise", "topic": "/chatter", "type": "std_msgs/String"}),
    )
    .await;
    send(
        &mut sub,
        json!({"op": "subscribe", "topic": "/chatter", "id": "s"}),
    )
    .await;
    relayed(&mut publ, &mut sub, "/chatter", "before").await;

    let attackers: Vec<_> = (0..500).map(|_| tokio::spawn(trickle(fx.addr))).collect();
    // Served during the attack: plain HTTP and the WebSocket pair.
    let r = http(fx.addr, "GET", "/healthz", &[], "").await;
    assert_eq!(r.status, 200, "{}", r.body);
    relayed(&mut publ, &mut sub, "/chatter", "during").await;

    let mut slowest = Duration::ZERO;
    for a in attackers {
        let held = within("every slowloris connection to be closed", a)
            .await
            .expect("attacker task");
        slowest = slowest.max(held);
    }
    // Trickling never finishes a head, so only the timeout can have closed them; the
    // margin is for a slow machine, not part of the claim.
    assert!(
        slowest < header_timeout + Duration::from_secs(10),
        "a slowloris connection was held {slowest:?}"
    );
    // An upgraded WebSocket is not an HTTP request head: it outlives the timeout.
    relayed(&mut publ, &mut sub, "/chatter", "after").await;
    let r = http(fx.addr, "GET", "/healthz", &[], "").await;
    assert_eq!(r.status, 200);
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn body_that_never_arrives_is_dropped_at_the_body_timeout() {
    let body_timeout = Duration::from_secs(1);
    let fx = hub_with(|c| c.door.body_timeout = body_timeout).await;
    let mut tcp = TcpStream::connect(fx.addr).await.expect("connect");
    let start = Instant::now();
    // Promises 100 bytes, sends 8, then waits.
    tcp.write_all(
        b"POST /api/v1/login HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n\
          Content-Length: 100\r\n\r\n{\"user\":",
    )
    .await
    .expect("write");
    let mut raw = Vec::new();
    let _ = within("the hub to drop the request", tcp.read_to_end(&mut raw)).await;
    let held = start.elapsed();
    let text = String::from_utf8_lossy(&raw);
    assert!(text.starts_with("HTTP/1.1 408"), "{text}");
    assert!(text.contains("--body-timeout-secs"), "{text}");
    assert!(
        held < body_timeout + Duration::from_secs(10),
        "held {held:?}"
    );
    let metrics = api(&fx, "GET", "/metrics", &fx.operator, "").await;
    assert!(
        metrics
            .body
            .contains("fleetlink_request_bodies_refused_total{reason=\"too_slow\"} 1"),
        "{}",
        metrics.body
    );
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn oversized_body_is_refused_with_413() {
    let fx = hub_with(|c| c.door.max_body = 4096).await;
    // Declared too large: refused from the head, before any of it is read.
    let mut tcp = TcpStream::connect(fx.addr).await.expect("connect");
    let head = format!(
        "PUT /api/v1/rules HTTP/1.1\r\nHost: x\r\nAuthorization: Bearer {}\r\n\
         Content-Length: {}\r\n\r\n",
        fx.operator,
        64 << 20
    );
    tcp.write_all(head.as_bytes()).await.expect("write");
    let mut raw = Vec::new();
    let _ = within("the 413", tcp.read_to_end(&mut raw)).await;
    let text = String::from_utf8_lossy(&raw);
    assert!(text.starts_with("HTTP/1.1 413"), "{text}");
    assert!(text.contains("--max-body-bytes"), "{text}");
    // A body within the limit is still read.
    let r = api(&fx, "GET", "/api/v1/rules", &fx.operator, "").await;
    assert_eq!(r.status, 200, "{}", r.body);
    assert_eq!(fx.state.limits.bodies_refused().0, 1);
    fx.still_serving().await;
}

/// A TCP connection from `ip` (a loopback address) that sends nothing.
async fn idle_from(ip: [u8; 4], to: SocketAddr) -> TcpStream {
    let s = TcpSocket::new_v4().expect("socket");
    s.bind(SocketAddr::from((ip, 0)))
        .expect("bind loopback alias");
    s.connect(to).await.expect("connect")
}

/// `GET /healthz` from `ip`: status and body.
async fn healthz_from(ip: [u8; 4], to: SocketAddr) -> (u16, String) {
    let mut tcp = idle_from(ip, to).await;
    tcp.write_all(b"GET /healthz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
        .await
        .expect("write");
    let mut raw = Vec::new();
    within("an answer", tcp.read_to_end(&mut raw))
        .await
        .expect("read");
    let text = String::from_utf8_lossy(&raw).into_owned();
    let status = text
        .split_whitespace()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("no status line in {text:?}"));
    (status, text)
}

/// Waits until the hub has seen `n` open connections go (their permits came back).
async fn open_connections(fx: &Fixture, n: usize) {
    within("closed connections to be released", async {
        while fx.state.limits.open() != n {
            tokio::task::yield_now().await;
        }
    })
    .await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn one_address_over_its_limit_gets_429() {
    let fx = hub_with(|c| c.door.max_connections_per_ip = 3).await;
    let mut held = Vec::new();
    for _ in 0..3 {
        held.push(idle_from([127, 0, 0, 1], fx.addr).await);
    }
    let (status, text) = healthz_from([127, 0, 0, 1], fx.addr).await;
    assert_eq!(status, 429, "{text}");
    assert!(text.contains("--max-connections-per-ip"), "{text}");
    assert!(text.contains("127.0.0.1"), "{text}");
    // Another address is not affected.
    let (status, _) = healthz_from([127, 0, 0, 2], fx.addr).await;
    assert_eq!(status, 200);
    let metrics = {
        let auth = format!("Bearer {}", fx.operator);
        let mut tcp = idle_from([127, 0, 0, 3], fx.addr).await;
        let req = format!(
            "GET /metrics HTTP/1.1\r\nHost: x\r\nAuthorization: {auth}\r\nConnection: close\r\n\r\n"
        );
        tcp.write_all(req.as_bytes()).await.expect("write");
        let mut raw = Vec::new();
        within("metrics", tcp.read_to_end(&mut raw))
            .await
            .expect("read");
        String::from_utf8_lossy(&raw).into_owned()
    };
    assert!(
        metrics.contains("fleetlink_connections_refused_total{limit=\"per_ip\"} 1"),
        "{metrics}"
    );
    drop(held);
    open_connections(&fx, 0).await;
    let (status, _) = healthz_from([127, 0, 0, 1], fx.addr).await;
    assert_eq!(
        status, 200,
        "the address is served again once its connections close"
    );
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn hub_over_its_total_limit_gets_503() {
    let fx = hub_with(|c| c.door.max_connections = 3).await;
    let mut held = Vec::new();
    for ip in 1..=3 {
        held.push(idle_from([127, 0, 0, ip], fx.addr).await);
    }
    let (status, text) = healthz_from([127, 0, 0, 9], fx.addr).await;
    assert_eq!(status, 503, "{text}");
    assert!(text.contains("--max-connections"), "{text}");
    assert_eq!(
        fx.state
            .limits
            .refused(fleetlink_hub::limits::Refusal::Total),
        1
    );
    drop(held);
    open_connections(&fx, 0).await;
    let r = api(&fx, "GET", "/metrics", &fx.operator, "").await;
    assert!(
        r.body
            .contains("fleetlink_connections_refused_total{limit=\"total\"} 1"),
        "{}",
        r.body
    );
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn handshake_stampede_gets_503_with_retry_after() {
    let fx = hub_with(|c| c.door.max_handshakes = 1).await;
    // An agent that upgrades and has not sent HELLO yet holds the one handshake slot.
    let mut req = format!("ws://{}/", fx.addr).into_client_request().unwrap();
    req.headers_mut().insert(
        "sec-websocket-protocol",
        fleetlink_proto::SUBPROTOCOL.parse().unwrap(),
    );
    let (mut first, _) = within("agent upgrade", tokio_tungstenite::connect_async(req))
        .await
        .expect("the first upgrade is admitted");

    let err = within(
        "a second upgrade",
        tokio_tungstenite::connect_async(fx.ws_url(&fx.operator)),
    )
    .await
    .expect_err("no handshake slot is free");
    let WsError::Http(res) = err else {
        panic!("expected an HTTP refusal, got {err}");
    };
    assert_eq!(res.status(), 503);
    let retry: u64 = res
        .headers()
        .get("retry-after")
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.parse().ok())
        .expect("a Retry-After in seconds");
    assert!((1..=5).contains(&retry), "Retry-After {retry}");
    let body = String::from_utf8_lossy(res.body().as_deref().unwrap_or_default()).into_owned();
    assert!(body.contains("--max-handshakes"), "{body}");
    assert_eq!(
        fx.state
            .limits
            .refused(fleetlink_hub::limits::Refusal::Handshakes),
        1
    );

    // The agent's HELLO is answered: its slot is free before WELCOME reaches it.
    hello(&mut first, "robot1", &fx.robot_token("robot1", None)).await;
    welcomed(&mut first).await;
    fx.still_serving().await;
}
