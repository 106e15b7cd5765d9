//! The fleet's subscribers: subscriber `j` on robot `j mod N`'s pose topic, on the hub
//! after that robot's, and the optional wildcard subscriber to every fleet topic; what
//! each receives (window messages, gaps, latency) and their start.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use anyhow::bail;
use bytes::BytesMut;
use fleetlink_proto::frame::{Frame, Level, SUBSCRIBE_REGEX};
use fleetlink_relay::link::LinkEvent;
use fleetlink_relay::unix_nanos;
use futures_util::{SinkExt, StreamExt};
use hdrhistogram::Histogram;
use tokio::sync::{mpsc, watch};
use tokio::task::JoinSet;
use tokio::time::Instant;
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_util::sync::CancellationToken;

use super::args::Args;
use super::clients::{
    Counters, Crew, Phase, connect_retrying, heartbeat_of, parse_topic, source_for, topic_name,
};
use crate::conn::{Conn, pong, put_ping};
use crate::relay_args::Window;
use crate::subscriber::new_histogram;

/// Starts every subscriber and waits until each is confirmed subscribed (so before any
/// robot announces a topic); each serves its link (pings) from the moment it is up.
/// Returns what each receives, in order (the wildcard last), and their tasks.
pub async fn start_all(
    args: &Args,
    urls: &[String],
    crew: &Crew,
) -> anyhow::Result<(Vec<Arc<SubStats>>, JoinSet<()>)> {
    let n_subs = args.subscribers + usize::from(args.wildcard);
    let sub_stats: Vec<Arc<SubStats>> = (0..n_subs).map(|_| Arc::new(SubStats::new())).collect();
    let mut sub_tasks = JoinSet::new();
    let (sub_up_tx, mut sub_up_rx) = mpsc::unbounded_channel::<anyhow::Result<()>>();
    for (j, stats) in sub_stats.iter().enumerate() {
        let wildcard = j == args.subscribers;
        let (url, pattern, flags) = if wildcard {
            (
                urls[0].clone(),
                "/fleet_[0-9]+/.*".to_owned(),
                SUBSCRIBE_REGEX,
            )
        } else {
            let r = j % args.robots;
            (urls[(r + 1) % urls.len()].clone(), topic_name(r, 0), 0)
        };
        let who = if wildcard {
            "fleet_wildcard".to_owned()
        } else {
            format!("fleet_sub_{j}")
        };
        let source = source_for(&url, args.robots + j);
        let token = args.subscriber_token.clone().unwrap_or(args.token.clone());
        let queue = args.queue_length;
        let Crew {
            admission,
            deadline,
            counters,
            schedule: sched,
            stop,
        } = crew.clone();
        let (up, stats) = (sub_up_tx.clone(), stats.clone());
        sub_tasks.spawn(async move {
            let connected = async {
                let mut c =
                    connect_retrying(&url, &who, &token, source, &admission, &counters, deadline)
                        .await?;
                let subscribe = Frame::Subscribe {
                    id: 1,
                    pattern,
                    flags,
                    throttle_ms: 0,
                    queue_length: queue,
                };
                c.send_and_sync(&[subscribe], &who).await?;
                anyhow::Ok(c)
            };
            match connected.await {
                Ok(c) => {
                    counters.connected.fetch_add(1, Relaxed);
                    let _ = up.send(Ok(()));
                    subscribe_loop(c, sched, stats, counters, stop).await;
                }
                Err(e) => {
                    let _ = up.send(Err(e));
                }
            }
        });
    }
    drop(sub_up_tx);
    for _ in 0..n_subs {
        match sub_up_rx.recv().await {
            Some(r) => r?,
            None => bail!("the subscribers' tasks ended before they were up"),
        }
    }
    Ok((sub_stats, sub_tasks))
}

/// What one subscriber received.
pub struct SubStats {
    /// Messages stamped inside the window.
    in_window: AtomicU64,
    gaps: AtomicU64,
    latency: Mutex<Histogram<u64>>,
}

impl SubStats {
    fn new() -> SubStats {
        SubStats {
            in_window: AtomicU64::new(0),
            gaps: AtomicU64::new(0),
            latency: Mutex::new(new_histogram()),
        }
    }

    fn latency(&self) -> std::sync::MutexGuard<'_, Histogram<u64>> {
        self.latency.lock().unwrap_or_else(|p| p.into_inner())
    }
}

/// A subscriber's receive loop: per WebSocket message, the clock is read once and the
/// histogram locked once.
async fn subscribe_loop(
    c: Conn,
    schedule: watch::Receiver<Phase>,
    stats: Arc<SubStats>,
    counters: Arc<Counters>,
    stop: CancellationToken,
) {
    let keepalive = heartbeat_of(&c);
    let Conn {
        mut ws, mut link, ..
    } = c;
    // alias → last sequence number seen.
    let mut last: HashMap<u32, Option<u64>> = HashMap::new();
    let mut ping_id = 0u64;
    let mut out = BytesMut::new();
    let mut window: Option<Window> = None;
    let cancelled = stop.cancelled();
    tokio::pin!(cancelled);
    let timer = tokio::time::sleep(keepalive);
    tokio::pin!(timer);
    loop {
        let m = tokio::select! {
            biased;
            _ = &mut cancelled => break,
            _ = &mut timer => {
                ping_id += 1;
                put_ping(&mut out, ping_id);
                timer.as_mut().reset(Instant::now() + keepalive);
                if ws.send(WsMessage::Binary(out.split().freeze())).await.is_err() {
                    break;
                }
                continue;
            }
            m = ws.next() => m,
        };
        let Some(Ok(m)) = m else {
            if !stop.is_cancelled() {
                eprintln!("bench: the hub closed a subscriber's connection");
            }
            break;
        };
        let WsMessage::Binary(b) = m else { continue };
        if window.is_none()
            && let Phase::Publish(s) = *schedule.borrow()
        {
            window = Some(s.window);
        }
        let now = unix_nanos();
        let (mut n, mut in_window, mut gaps) = (0u64, 0u64, 0u64);
        {
            let mut latency = stats.latency();
            for f in fleetlink_proto::frame::frames(&b) {
                let Ok(f) = f else {
                    eprintln!("bench: malformed frame from the hub");
                    break;
                };
                match link.on_frame(f) {
                    Ok(LinkEvent::Message {
                        alias,
                        seq,
                        stamp_ns,
                        ..
                    }) => {
                        let Some(prev) = last.get_mut(&alias) else {
                            continue;
                        };
                        n += 1;
                        match *prev {
                            Some(p) if seq <= p => {}
                            Some(p) => {
                                gaps += seq - p - 1;
                                *prev = Some(seq);
                            }
                            None => *prev = Some(seq),
                        }
                        if window.is_some_and(|w| w.contains(stamp_ns)) {
                            in_window += 1;
                            latency.saturating_record(now.saturating_sub(stamp_ns));
                        }
                    }
                    Ok(LinkEvent::Advertise { alias, topic, .. })
                        if parse_topic(&topic.name).is_some() =>
                    {
                        last.insert(alias, None);
                    }
                    Ok(LinkEvent::Control(Frame::Ping { id, sent_ns })) => {
                        out.extend_from_slice(&pong(id, sent_ns));
                    }
                    Ok(LinkEvent::Control(Frame::Status { level, text, .. }))
                        if level != Level::Info =>
                    {
                        eprintln!("bench: hub to subscriber: {text}");
                    }
                    _ => {}
                }
            }
        }
        link.unacked = 0;
        stats.in_window.fetch_add(in_window, Relaxed);
        if gaps > 0 {
            stats.gaps.fetch_add(gaps, Relaxed);
        }
        counters.delivered.fetch_add(n, Relaxed);
        if !out.is_empty()
            && ws
                .send(WsMessage::Binary(out.split().freeze()))
                .await
                .is_err()
        {
            break;
        }
    }
}

/// Waits until the subscribers have received `expected` window messages, or `limit`.
pub async fn drain(subs: &[Arc<SubStats>], expected: u64, limit: Duration) {
    let deadline = Instant::now() + limit;
    while Instant::now() < deadline {
        let got: u64 = subs.iter().map(|s| s.in_window.load(Relaxed)).sum();
        if got >= expected {
            return;
        }
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
}

/// What the subscribers received in all: their latency histograms merged, the window
/// messages delivered and the gaps.
pub fn totals(subs: &[Arc<SubStats>]) -> (Histogram<u64>, u64, u64) {
    let mut latency = new_histogram();
    let mut delivered = 0;
    let mut gaps = 0;
    for s in subs {
        latency.add(&*s.latency()).ok();
        delivered += s.in_window.load(Relaxed);
        gaps += s.gaps.load(Relaxed);
    }
    (latency, delivered, gaps)
}
