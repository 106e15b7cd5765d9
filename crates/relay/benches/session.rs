//! A rosbridge publish → subscribe through two whole sessions, without sockets: the
//! publisher's frames go in as WebSocket messages, the subscriber's come out of its
//! writer. This is the hub's own work per JSON delivery (envelope scan, type check,
//! authorization, topic statistics, outbox, output frame, both tasks' scheduling); the
//! WebSocket library and the kernel are left out, so the figure is steadier than the
//! socket benchmark's (`fleetlink bench delivery`) and shows small changes.
//!
//! - `rosbridge_session/json_64B`: bursts of 300 publishes of a 64-byte `std_msgs/String`
//!   with roslibjs' envelope (an `id`, a `latch`), one subscriber. Per element: one
//!   delivery.

use std::pin::Pin;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::task::{Context, Poll};
use std::time::{Duration, Instant};

use criterion::{Criterion, Throughput, criterion_group};
use fleetlink_relay::Router;
use fleetlink_relay::gate::SessionAuth;
use fleetlink_relay::rosbridge::{SessionConfig, serve};
use fleetlink_relay::transcode::RegistryTranscoder;
use futures_channel::mpsc;
use futures_util::{Sink, Stream};
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};
use tokio_util::sync::CancellationToken;

const BURST: usize = 300;

/// A client's WebSocket seen from the server: frames come from `rx`; sent frames are
/// counted and dropped.
struct Pipe {
    rx: mpsc::UnboundedReceiver<WsMessage>,
    sent: Arc<AtomicU64>,
    waiting: Arc<tokio::sync::Notify>,
}

impl Stream for Pipe {
    type Item = Result<WsMessage, WsError>;

    fn poll_next(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<Option<Self::Item>> {
        Pin::new(&mut self.rx).poll_next(cx).map(|m| m.map(Ok))
    }
}

impl Sink<WsMessage> for Pipe {
    type Error = WsError;

    fn poll_ready(self: Pin<&mut Self>, _: &mut Context<'_>) -> Poll<Result<(), WsError>> {
        Poll::Ready(Ok(()))
    }

    fn start_send(self: Pin<&mut Self>, item: WsMessage) -> Result<(), WsError> {
        std::hint::black_box(item);
        self.sent.fetch_add(1, Ordering::Relaxed);
        Ok(())
    }

    fn poll_flush(self: Pin<&mut Self>, _: &mut Context<'_>) -> Poll<Result<(), WsError>> {
        self.waiting.notify_one();
        Poll::Ready(Ok(()))
    }

    fn poll_close(self: Pin<&mut Self>, _: &mut Context<'_>) -> Poll<Result<(), WsError>> {
        Poll::Ready(Ok(()))
    }
}

struct Client {
    tx: mpsc::UnboundedSender<WsMessage>,
    sent: Arc<AtomicU64>,
    flushed: Arc<tokio::sync::Notify>,
}

fn connect(router: &Arc<Router>, shutdown: &CancellationToken) -> Client {
    let (tx, rx) = mpsc::unbounded();
    let sent = Arc::new(AtomicU64::new(0));
    let flushed = Arc::new(tokio::sync::Notify::new());
    let pipe = Pipe {
        rx,
        sent: sent.clone(),
        waiting: flushed.clone(),
    };
    tokio::spawn(serve(
        pipe,
        router.clone(),
        None,
        Arc::new(SessionConfig::default()),
        shutdown.clone(),
        SessionAuth::open(),
    ));
    Client { tx, sent, flushed }
}

impl Client {
    fn send(&self, text: String) {
        self.send_frame(WsMessage::text(text));
    }

    fn send_frame(&self, frame: WsMessage) {
        self.tx.unbounded_send(frame).expect("session open");
    }

    /// Waits until `n` frames in all have been sent to this client.
    async fn received(&self, n: u64) {
        while self.sent.load(Ordering::Relaxed) < n {
            let _ = tokio::time::timeout(Duration::from_millis(50), self.flushed.notified()).await;
        }
    }
}

/// Both sessions on one router, set up and with one message through.
fn setup(rt: &tokio::runtime::Runtime, shutdown: &CancellationToken) -> (Client, Client) {
    let router = Arc::new(Router::new(Arc::new(RegistryTranscoder::bundled())));
    rt.block_on(async {
        let p = connect(&router, shutdown);
        let s = connect(&router, shutdown);
        p.send(r#"{"op":"advertise","topic":"/bench","type":"std_msgs/String"}"#.to_string());
        s.send(
            r#"{"op":"subscribe","topic":"/bench","type":"std_msgs/String","queue_length":1000}"#
                .to_string(),
        );
        // One message through, so that both sessions are set up before timing starts.
        loop {
            p.send(r#"{"op":"publish","topic":"/bench","msg":{"data":"x"}}"#.to_string());
            tokio::time::sleep(Duration::from_millis(5)).await;
            if s.sent.load(Ordering::Relaxed) > 0 {
                break;
            }
        }
        (p, s)
    })
}

/// The publishes of one burst. Built once: a clone shares the text, as a socket read's
/// frames share its buffer.
fn burst() -> Vec<WsMessage> {
    let data = "x".repeat(64 - 12);
    (0..BURST)
        .map(|i| {
            WsMessage::text(format!(
                r#"{{"op":"publish","id":"publish:/bench:{i}","topic":"/bench","msg":{{"data":"{data}"}},"latch":false}}"#
            ))
        })
        .collect()
}

/// Sends `bursts` bursts, each waited for at the subscriber.
async fn run(publisher: &Client, subscriber: &Client, frames: &[WsMessage], bursts: u64) {
    let base = subscriber.sent.load(Ordering::Relaxed);
    for k in 1..=bursts {
        for f in frames {
            publisher.send_frame(f.clone());
        }
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
    let (publisher, subscriber) = setup(&rt, &shutdown);
    let frames = burst();
    let mut g = c.benchmark_group("rosbridge_session");
    g.throughput(Throughput::Elements(BURST as u64));
    g.bench_function("json_64B", |b| {
        b.iter_custom(|iters| {
            rt.block_on(async {
                let start = Instant::now();
                run(&publisher, &subscriber, &frames, iters).await;
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
        let (publisher, subscriber) = setup(&rt, &shutdown);
        let frames = burst();
        rt.block_on(run(&publisher, &subscriber, &frames, n));
        shutdown.cancel();
        return;
    }
    benches();
    Criterion::default().configure_from_args().final_summary();
}
