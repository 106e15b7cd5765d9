//! A rosbridge publish → subscribe through two whole sessions, in process: the
//! publisher's frames go in as masked WebSocket bytes through an in-memory pipe, the
//! subscriber's come out of its writer as bytes through another. This is the hub's own
//! work per JSON delivery (WebSocket framing, envelope scan, type check, authorization,
//! topic statistics, outbox, output frame, both tasks' scheduling); the kernel is left
//! out, so the figure is steadier than the socket benchmark's (`fleetlink bench
//! delivery`) and shows small changes.
//!
//! - `rosbridge_session/json_64B`: bursts of 300 publishes of a 64-byte `std_msgs/String`
//!   with roslibjs' envelope (an `id`, a `latch`), one subscriber. Per element: one
//!   delivery.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

use criterion::{Criterion, Throughput, criterion_group};
use fleetlink_relay::Router;
use fleetlink_relay::gate::SessionAuth;
use fleetlink_relay::transcode::RegistryTranscoder;
use fleetlink_relay::websocket;
use fleetlink_rosbridge::{SessionConfig, serve};
use tokio::io::{AsyncReadExt, AsyncWriteExt, DuplexStream, WriteHalf};
use tokio_util::sync::CancellationToken;

const BURST: usize = 300;

/// The client's end of one session's connection.
struct Client {
    tx: WriteHalf<DuplexStream>,
    /// Whole frames the session has sent this client.
    received: Arc<AtomicU64>,
    arrived: Arc<tokio::sync::Notify>,
}

fn connect(router: &Arc<Router>, shutdown: &CancellationToken) -> Client {
    let (client, server) = tokio::io::duplex(1 << 20);
    let (sink, stream) = websocket::server(server, 16 << 20);
    tokio::spawn(serve(
        sink,
        stream,
        router.clone(),
        None,
        Arc::new(SessionConfig::default()),
        shutdown.clone(),
        SessionAuth::open(),
    ));
    let (mut rx, tx) = tokio::io::split(client);
    let received = Arc::new(AtomicU64::new(0));
    let arrived = Arc::new(tokio::sync::Notify::new());
    let (count, notify) = (received.clone(), arrived.clone());
    // Counts the server's (unmasked) frames as they come.
    tokio::spawn(async move {
        let mut buf = Vec::with_capacity(1 << 16);
        let mut chunk = vec![0u8; 1 << 16];
        while let Ok(n) = rx.read(&mut chunk).await {
            if n == 0 {
                return;
            }
            buf.extend_from_slice(&chunk[..n]);
            let mut at = 0;
            let mut frames = 0;
            while let Some(len) = frame_len(&buf[at..]) {
                at += len;
                frames += 1;
            }
            buf.drain(..at);
            if frames > 0 {
                count.fetch_add(frames, Ordering::Relaxed);
                notify.notify_one();
            }
        }
    });
    Client {
        tx,
        received,
        arrived,
    }
}

/// The length of the whole server frame at the front of `b`, if it is all there.
fn frame_len(b: &[u8]) -> Option<usize> {
    let (head, len) = match *b.get(1)? & 0x7F {
        126 => (4, u16::from_be_bytes([*b.get(2)?, *b.get(3)?]) as usize),
        127 => (
            10,
            u64::from_be_bytes(b.get(2..10)?.try_into().ok()?) as usize,
        ),
        n => (2, n as usize),
    };
    (b.len() >= head + len).then_some(head + len)
}

/// `text` as a masked client frame.
fn client_frame(text: &str) -> Vec<u8> {
    const KEY: [u8; 4] = [0x11, 0x22, 0x33, 0x44];
    let n = text.len();
    let mut out = vec![0x81];
    if n < 126 {
        out.push(0x80 | n as u8);
    } else {
        out.push(0x80 | 126);
        out.extend_from_slice(&(n as u16).to_be_bytes());
    }
    out.extend_from_slice(&KEY);
    out.extend(text.bytes().enumerate().map(|(i, b)| b ^ KEY[i % 4]));
    out
}

impl Client {
    async fn send(&mut self, text: &str) {
        self.send_bytes(&client_frame(text)).await;
    }

    async fn send_bytes(&mut self, bytes: &[u8]) {
        self.tx.write_all(bytes).await.expect("session open");
    }

    /// Waits until `n` frames in all have been sent to this client.
    async fn received(&self, n: u64) {
        while self.received.load(Ordering::Relaxed) < n {
            let _ = tokio::time::timeout(Duration::from_millis(50), self.arrived.notified()).await;
        }
    }
}

/// Both sessions on one router, set up and with one message through.
fn setup(rt: &tokio::runtime::Runtime, shutdown: &CancellationToken) -> (Client, Client) {
    let router = Arc::new(Router::new(Arc::new(RegistryTranscoder::bundled())));
    rt.block_on(async {
        let mut p = connect(&router, shutdown);
        let mut s = connect(&router, shutdown);
        p.send(r#"{"op":"advertise","topic":"/bench","type":"std_msgs/String"}"#)
            .await;
        s.send(
            r#"{"op":"subscribe","topic":"/bench","type":"std_msgs/String","queue_length":1000}"#,
        )
        .await;
        // One message through, so that both sessions are set up before timing starts.
        loop {
            p.send(r#"{"op":"publish","topic":"/bench","msg":{"data":"x"}}"#)
                .await;
            tokio::time::sleep(Duration::from_millis(5)).await;
            if s.received.load(Ordering::Relaxed) > 0 {
                break;
            }
        }
        (p, s)
    })
}

/// The publishes of one burst, as the bytes of one socket write.
fn burst() -> Vec<u8> {
    let data = "x".repeat(64 - 12);
    (0..BURST)
        .flat_map(|i| {
            client_frame(&format!(
                r#"{{"op":"publish","id":"publish:/bench:{i}","topic":"/bench","msg":{{"data":"{data}"}},"latch":false}}"#
            ))
        })
        .collect()
}

/// Sends `bursts` bursts, each waited for at the subscriber.
async fn run(publisher: &mut Client, subscriber: &Client, bytes: &[u8], bursts: u64) {
    let base = subscriber.received.load(Ordering::Relaxed);
    for k in 1..=bursts {
        publisher.send_bytes(bytes).await;
        subscriber.received(base + k * BURST as u64).await;
    }
}

fn runtime() -> tokio::runtime::Runtime {
    tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .expect("runtime")
}

fn json_session(c: &mut Criterion) {
    let rt = runtime();
    let shutdown = CancellationToken::new();
    let (mut publisher, subscriber) = setup(&rt, &shutdown);
    let bytes = burst();
    let mut g = c.benchmark_group("rosbridge_session");
    g.throughput(Throughput::Elements(BURST as u64));
    g.bench_function("json_64B", |b| {
        b.iter_custom(|iters| {
            rt.block_on(async {
                let start = Instant::now();
                run(&mut publisher, &subscriber, &bytes, iters).await;
                start.elapsed()
            })
        });
    });
    g.finish();
    shutdown.cancel();
}

criterion_group!(benches, json_session);

/// With `SESSION_BENCH_BURSTS=N` set, sends N bursts without criterion and exits: for
/// counting instructions (`valgrind --tool=callgrind`), which unlike time on a shared
/// machine gives the same figure every run. Two counts, N and 2N, differ by the cost of
/// N bursts alone.
fn main() {
    if let Some(n) = std::env::var("SESSION_BENCH_BURSTS")
        .ok()
        .and_then(|n| n.parse().ok())
    {
        let rt = runtime();
        let shutdown = CancellationToken::new();
        let (mut publisher, subscriber) = setup(&rt, &shutdown);
        let bytes = burst();
        rt.block_on(run(&mut publisher, &subscriber, &bytes, n));
        shutdown.cancel();
        return;
    }
    benches();
    Criterion::default().configure_from_args().final_summary();
}
