//! A bench subscriber: one `fleetlink.v1` connection subscribed to every bench topic by
//! pattern, measuring what arrives.
//!
//! Per message it looks up the topic, checks the sequence number for gaps and, if the
//! message was stamped inside the measurement window, counts it and records its latency.
//! The clock is read once per WebSocket message (its frames arrived together), and the
//! shared histogram is locked once per WebSocket message, so the progress display can
//! read it without slowing the hot path.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};

use bytes::{Bytes, BytesMut};
use fleetlink_proto::frame::{Frame, Level, SUBSCRIBE_REGEX};
use fleetlink_relay::link::LinkEvent;
use fleetlink_relay::unix_nanos;
use futures_util::stream::SplitSink;
use futures_util::{SinkExt, StreamExt};
use hdrhistogram::Histogram;
use tokio::sync::{Notify, mpsc};
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_util::sync::CancellationToken;

use super::conn::{Conn, Ws, pong, publisher_of, put_ping};
use super::relay_args::Window;

/// The pattern every subscriber asks for.
pub const PATTERN: &str = "/bench_pub_[0-9]+/data";

/// Latency histogram: nanoseconds, 1 ns to 60 s, three significant figures.
pub fn new_histogram() -> Histogram<u64> {
    Histogram::new_with_bounds(1, 60_000_000_000, 3).expect("constant bounds are valid")
}

/// The `SUBSCRIBE` every subscriber sends. `queue_length` 0 takes the hub's default.
pub fn subscribe(queue_length: u32) -> Frame {
    Frame::Subscribe {
        id: 1,
        pattern: PATTERN.into(),
        flags: SUBSCRIBE_REGEX,
        throttle_ms: 0,
        queue_length,
    }
}

/// What a subscriber has seen so far, read by the progress display and the controller.
pub struct Shared {
    /// Messages received, any stamp (for the progress rate).
    pub delivered: AtomicU64,
    /// Payload bytes received, any stamp.
    pub bytes: AtomicU64,
    /// Messages missing between consecutive sequence numbers, any stamp.
    pub gaps: AtomicU64,
    /// Latency of messages stamped inside the window.
    pub latency: Mutex<Histogram<u64>>,
    /// Per publisher: highest sequence number received plus one (0: none yet). Updated
    /// once per WebSocket message; publishers read it for flow control.
    pub seen: Box<[AtomicU64]>,
}

impl Shared {
    pub fn new(publishers: usize) -> Shared {
        Shared {
            delivered: AtomicU64::new(0),
            bytes: AtomicU64::new(0),
            gaps: AtomicU64::new(0),
            latency: Mutex::new(new_histogram()),
            seen: (0..publishers).map(|_| AtomicU64::new(0)).collect(),
        }
    }

    pub fn latency(&self) -> std::sync::MutexGuard<'_, Histogram<u64>> {
        self.latency.lock().unwrap_or_else(|p| p.into_inner())
    }
}

#[derive(Clone, Copy, Default)]
struct TopicRx {
    last_seq: Option<u64>,
    in_window: u64,
}

/// Receives until `stop`; returns how many messages of each publisher stamped inside the
/// window arrived.
pub async fn run(
    conn: Conn,
    window: Window,
    shared: Arc<Shared>,
    wake: Arc<[Notify]>,
    stop: CancellationToken,
) -> Vec<u64> {
    let Conn {
        ws,
        mut link,
        keepalive,
    } = conn;
    let (sink, mut stream) = ws.split();
    let (reply_tx, reply_rx) = mpsc::channel::<Bytes>(64);
    let writer = tokio::spawn(write_replies(sink, reply_rx, keepalive));
    let mut topics: HashMap<u32, usize> = HashMap::new();
    let mut rx = vec![TopicRx::default(); shared.seen.len()];
    // Publishers with messages in the current WebSocket message.
    let mut touched: Vec<usize> = Vec::new();
    loop {
        let m = tokio::select! {
            biased;
            _ = stop.cancelled() => break,
            m = stream.next() => m,
        };
        let Some(Ok(m)) = m else {
            if !stop.is_cancelled() {
                eprintln!("bench: the hub closed a subscriber's connection");
            }
            break;
        };
        let WsMessage::Binary(b) = m else { continue };
        let now = unix_nanos();
        let (mut n, mut bytes, mut gaps) = (0u64, 0u64, 0u64);
        let mut latency = shared.latency();
        for f in fleetlink_proto::frame::frames(&b) {
            let f = match f {
                Ok(f) => f,
                Err(e) => {
                    eprintln!("bench: malformed frame from the hub: {e}");
                    break;
                }
            };
            match link.on_frame(f) {
                Ok(LinkEvent::Message {
                    alias,
                    seq,
                    stamp_ns,
                    payload,
                    ..
                }) => {
                    let Some(&p) = topics.get(&alias) else {
                        continue;
                    };
                    let t = &mut rx[p];
                    if touched.last() != Some(&p) && !touched.contains(&p) {
                        touched.push(p);
                    }
                    n += 1;
                    bytes += payload.bytes.len() as u64;
                    match t.last_seq {
                        Some(last) if seq <= last => {}
                        Some(last) => {
                            gaps += seq - last - 1;
                            t.last_seq = Some(seq);
                        }
                        None => t.last_seq = Some(seq),
                    }
                    if window.contains(stamp_ns) {
                        t.in_window += 1;
                        latency.saturating_record(now.saturating_sub(stamp_ns));
                    }
                }
                Ok(LinkEvent::Advertise { alias, topic, .. }) => {
                    if let Some(p) = publisher_of(&topic.name).filter(|p| *p < rx.len()) {
                        topics.insert(alias, p);
                    }
                }
                Ok(LinkEvent::Control(Frame::Ping { id, sent_ns })) => {
                    // A full channel means replies are already waiting; the hub pings again.
                    let _ = reply_tx.try_send(pong(id, sent_ns));
                }
                Ok(LinkEvent::Control(Frame::Status { level, text, .. }))
                    if level != Level::Info =>
                {
                    eprintln!("bench: hub to subscriber: {text}");
                }
                Ok(_) => {}
                Err(e) => eprintln!("bench: {e}"),
            }
        }
        drop(latency);
        link.unacked = 0;
        for p in touched.drain(..) {
            if let Some(last) = rx[p].last_seq {
                shared.seen[p].store(last + 1, Relaxed);
            }
            wake[p].notify_one();
        }
        shared.delivered.fetch_add(n, Relaxed);
        shared.bytes.fetch_add(bytes, Relaxed);
        if gaps > 0 {
            shared.gaps.fetch_add(gaps, Relaxed);
        }
    }
    writer.abort();
    rx.iter().map(|t| t.in_window).collect()
}

/// Sends the subscriber's replies and a keepalive `PING` every `keepalive`, so the hub
/// hears from this link even though it sends no data.
async fn write_replies(
    mut sink: SplitSink<Ws, WsMessage>,
    mut replies: mpsc::Receiver<Bytes>,
    keepalive: std::time::Duration,
) {
    let mut tick = tokio::time::interval(keepalive);
    let mut ping_id = 0u64;
    loop {
        let out = tokio::select! {
            r = replies.recv() => match r {
                Some(b) => b,
                None => return,
            },
            _ = tick.tick() => {
                ping_id += 1;
                let mut buf = BytesMut::new();
                put_ping(&mut buf, ping_id);
                buf.freeze()
            }
        };
        if sink.send(WsMessage::Binary(out)).await.is_err() {
            return;
        }
    }
}
