//! A bench publisher: one `fleetlink.v1` connection sending `MESSAGE`s (or `CHUNK`s for
//! payloads over the chunk size) on its one topic, at a fixed rate or as fast as the
//! subscribers take them.
//!
//! "As fast as possible" is closed-loop: a publisher keeps at most `window` messages in
//! flight (sent, but not yet received by its slowest subscriber, which it can see because
//! both run in this process). Open-loop flooding would only measure how fast the hub
//! drops: the hub never blocks a publisher for a slow subscriber, it evicts from that
//! subscriber's queue. With `window` no larger than the subscribers' queue length the hub
//! never has to drop, so `max` measures the highest lossless delivery rate.
//!
//! Frames are packed into WebSocket messages of about 64 KiB, as the hub's own link
//! writer does, and every frame of one write carries the same `stamp_ns`: they leave
//! together, so that is their send time. The payload is encoded from one shared buffer;
//! the hot loop allocates nothing per message.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::Duration;

use bytes::{Bytes, BytesMut};
use fleetlink_proto::frame::{self, DEFAULT_CHUNK_SIZE, Frame, Level};
use fleetlink_relay::link::{LinkEvent, LinkIn};
use fleetlink_relay::unix_nanos;
use futures_util::stream::{SplitSink, SplitStream};
use futures_util::{SinkExt, StreamExt};
use tokio::sync::{Notify, mpsc, oneshot};
use tokio::time::MissedTickBehavior;
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_util::sync::CancellationToken;

use super::conn::{Conn, Ws, pong, put_ping};
use super::relay_args::{Rate, Window};
use super::subscriber::Shared;

/// Small frames are packed into one WebSocket message up to about this size.
const PACK: usize = 64 * 1024;
/// Alias of the publisher's one topic (see `conn::advertise`).
const ALIAS: u32 = 1;

/// What a publisher sent with a stamp inside the measurement window.
#[derive(Debug, Clone, Copy, Default)]
pub struct Sent {
    pub messages: u64,
    /// Sequence numbers of the first and last of them (meaningful when `messages > 0`).
    pub first_seq: u64,
    pub last_seq: u64,
}

pub struct Plan {
    pub size: usize,
    pub rate: Rate,
    pub window: Window,
    pub flow: Flow,
}

/// What a publisher needs to know about its subscribers' progress (used at `Rate::Max`).
pub struct Flow {
    /// This publisher's index into `Shared::seen` and `wake`.
    pub index: usize,
    pub subscribers: Vec<Arc<Shared>>,
    /// Signalled by subscribers when they received messages of publisher `i`.
    pub wake: Arc<[Notify]>,
    /// Most messages in flight.
    pub in_flight: u64,
}

impl Flow {
    /// Sequence number up to which every subscriber has received (exclusive).
    fn acked(&self) -> u64 {
        self.subscribers
            .iter()
            .map(|s| s.seen[self.index].load(Relaxed))
            .min()
            .unwrap_or(0)
    }
}

/// Sends from now until the window ends, reports what it sent in the window on `done`,
/// then keeps the connection alive (answering pings) until `stop`.
pub async fn run(
    conn: Conn,
    plan: Plan,
    sent_total: Arc<AtomicU64>,
    done: oneshot::Sender<Sent>,
    stop: CancellationToken,
) {
    let keepalive = conn.keepalive;
    let (sink, stream) = conn.ws.split();
    let (ctrl_tx, ctrl_rx) = mpsc::channel::<Bytes>(64);
    let reader = tokio::spawn(read_hub(stream, conn.link, ctrl_tx, stop.clone()));
    let mut w = Writer {
        sink,
        ctrl: ctrl_rx,
        buf: BytesMut::with_capacity(PACK * 2),
        keepalive,
        next_ping: tokio::time::Instant::now() + keepalive,
        ping_id: 0,
    };
    let sent = tokio::select! {
        s = w.send_until(&plan, &sent_total) => s,
        _ = stop.cancelled() => None,
    };
    if let Some(s) = sent {
        let _ = done.send(s);
        tokio::select! {
            _ = w.idle() => {}
            _ = stop.cancelled() => {}
        }
    }
    reader.abort();
}

struct Writer {
    sink: SplitSink<Ws, WsMessage>,
    /// Replies (`PONG`s) the reader wants sent.
    ctrl: mpsc::Receiver<Bytes>,
    buf: BytesMut,
    keepalive: Duration,
    next_ping: tokio::time::Instant,
    ping_id: u64,
}

impl Writer {
    /// The send loop. `None` when the link failed.
    async fn send_until(&mut self, plan: &Plan, sent_total: &AtomicU64) -> Option<Sent> {
        let payload: Bytes = vec![0x5a; plan.size].into();
        let chunked = plan.size > DEFAULT_CHUNK_SIZE;
        let per_write = if chunked {
            1
        } else {
            (PACK / (plan.size + 24)).max(1) as u64
        };
        let start_ns = unix_nanos();
        let mut tick = tokio::time::interval(match plan.rate {
            Rate::Max => Duration::from_millis(1),
            Rate::Hz(hz) => Duration::from_secs_f64((1.0 / hz).max(0.001)),
        });
        tick.set_missed_tick_behavior(MissedTickBehavior::Skip);
        let mut seq = 0u64;
        let mut sent = Sent::default();
        loop {
            while let Ok(b) = self.ctrl.try_recv() {
                self.sink.feed(WsMessage::Binary(b)).await.ok()?;
            }
            let now = unix_nanos();
            if now >= plan.window.end_ns {
                self.sink.flush().await.ok()?;
                return Some(sent);
            }
            if tokio::time::Instant::now() >= self.next_ping {
                self.ping();
            }
            let due = match plan.rate {
                Rate::Max => {
                    let flying = seq.saturating_sub(plan.flow.acked());
                    plan.flow.in_flight.saturating_sub(flying).min(per_write)
                }
                Rate::Hz(hz) => {
                    let target = ((now - start_ns) as f64 * 1e-9 * hz) as u64 + 1;
                    target.saturating_sub(seq).min(per_write)
                }
            };
            if due == 0 {
                if !self.buf.is_empty() {
                    let out = self.buf.split().freeze();
                    self.sink.feed(WsMessage::Binary(out)).await.ok()?;
                }
                self.sink.flush().await.ok()?;
                let wake = &plan.flow.wake[plan.flow.index];
                tokio::select! {
                    _ = tick.tick(), if plan.rate != Rate::Max => {}
                    // Woken when a subscriber made progress; the timeout re-checks the
                    // clock should every subscriber have gone quiet.
                    _ = wake.notified(), if plan.rate == Rate::Max => {}
                    _ = tokio::time::sleep(Duration::from_millis(10)), if plan.rate == Rate::Max => {}
                    c = self.ctrl.recv() => {
                        if let Some(b) = c {
                            self.sink.feed(WsMessage::Binary(b)).await.ok()?;
                        }
                    }
                }
                continue;
            }
            for s in seq..seq + due {
                if chunked {
                    self.send_chunked(s, now, &payload).await.ok()?;
                } else {
                    frame::encode_message(&mut self.buf, ALIAS, s, now, &payload);
                }
            }
            let out = self.buf.split().freeze();
            self.sink.send(WsMessage::Binary(out)).await.ok()?;
            if plan.window.contains(now) {
                if sent.messages == 0 {
                    sent.first_seq = seq;
                }
                sent.messages += due;
                sent.last_seq = seq + due - 1;
            }
            seq += due;
            sent_total.fetch_add(due, Relaxed);
        }
    }

    /// One large message as `CHUNK` frames, each its own WebSocket message (as the hub's
    /// link writer sends them). The last piece stays in `buf` for the caller to send.
    async fn send_chunked(
        &mut self,
        seq: u64,
        stamp_ns: u64,
        payload: &Bytes,
    ) -> Result<(), tokio_tungstenite::tungstenite::Error> {
        let total = payload.len() as u64;
        let pieces = payload.len().div_ceil(DEFAULT_CHUNK_SIZE);
        for (i, data) in payload.chunks(DEFAULT_CHUNK_SIZE).enumerate() {
            let offset = (i * DEFAULT_CHUNK_SIZE) as u64;
            frame::encode_chunk(
                &mut self.buf,
                false,
                ALIAS,
                seq,
                stamp_ns,
                total,
                offset,
                data,
            );
            if i + 1 < pieces {
                let out = self.buf.split().freeze();
                self.sink.feed(WsMessage::Binary(out)).await?;
            }
        }
        Ok(())
    }

    fn ping(&mut self) {
        self.ping_id += 1;
        put_ping(&mut self.buf, self.ping_id);
        self.next_ping = tokio::time::Instant::now() + self.keepalive;
    }

    /// After the window: keep the link alive so the hub keeps the topic.
    async fn idle(&mut self) {
        loop {
            tokio::select! {
                c = self.ctrl.recv() => match c {
                    Some(b) => self.buf.extend_from_slice(&b),
                    None => return,
                },
                _ = tokio::time::sleep_until(self.next_ping) => self.ping(),
            }
            let out = self.buf.split().freeze();
            if self.sink.send(WsMessage::Binary(out)).await.is_err() {
                return;
            }
        }
    }
}

/// Reads what the hub sends a publisher: answers pings, reports problems.
async fn read_hub(
    mut stream: SplitStream<Ws>,
    mut link: LinkIn,
    replies: mpsc::Sender<Bytes>,
    stop: CancellationToken,
) {
    loop {
        let m = tokio::select! {
            m = stream.next() => m,
            _ = stop.cancelled() => return,
        };
        let Some(Ok(m)) = m else {
            if !stop.is_cancelled() {
                eprintln!("bench: the hub closed a publisher's connection");
            }
            return;
        };
        let WsMessage::Binary(b) = m else { continue };
        for f in fleetlink_proto::frame::frames(&b) {
            let Ok(f) = f else { break };
            match link.on_frame(f) {
                Ok(LinkEvent::Control(Frame::Ping { id, sent_ns })) => {
                    // A full channel means replies are already waiting; the hub pings again.
                    let _ = replies.try_send(pong(id, sent_ns));
                }
                Ok(LinkEvent::Control(Frame::Status { level, text, .. }))
                    if level != Level::Info =>
                {
                    eprintln!("bench: hub to publisher: {text}");
                }
                _ => {}
            }
        }
        link.unacked = 0;
    }
}
