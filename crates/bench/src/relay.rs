//! `fleetlink bench relay`: publishers and subscribers on real `fleetlink.v1` links to a
//! running hub, measuring what the hub delivers.
//!
//! Order of events: every subscriber connects and subscribes (by pattern) and waits for
//! the hub to confirm it processed the `SUBSCRIBE`; then every publisher connects and
//! advertises, likewise confirmed, so no message is published before all subscriptions
//! exist. Publishers then send for `warmup + duration`.
//!
//! What counts: a message belongs to the measurement when its `stamp_ns` (send time)
//! falls inside the window `[start + warmup, start + warmup + duration)`. `sent` counts
//! such messages; `delivered` counts their arrivals at every subscriber, including ones
//! that arrive after the window closed (the bench waits for the last one, up to
//! `--drain`). So without drops `delivered == subscribers × sent` exactly, and `drops`
//! is the number of window messages a subscriber never received (gaps in `seq`).

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::Duration;

use anyhow::{Context, bail};
use fleetlink_relay::unix_nanos;
use tokio::sync::{Notify, oneshot};
use tokio::task::JoinSet;
use tokio_util::sync::CancellationToken;

use super::conn::{self, hub_url};
use super::publisher::{self, Flow, Plan, Sent};
use super::report::{self, Progress, Summary};
use super::subscriber::{self, Shared};
use crate::relay_args::{Args, Window};

pub fn run(args: Args) -> anyhow::Result<()> {
    check(&args)?;
    crate::measure::run_measurement(args.threads, args.json, relay(&args))
}

fn check(args: &Args) -> anyhow::Result<()> {
    if args.publishers == 0 || args.subscribers == 0 {
        bail!("--publishers and --subscribers must be at least 1");
    }
    if !(args.duration > 0.0 && args.duration.is_finite()) {
        bail!("--duration must be a positive number of seconds");
    }
    if !(args.warmup >= 0.0 && args.warmup.is_finite() && args.drain >= 0.0) {
        bail!("--warmup and --drain must be non-negative numbers of seconds");
    }
    Ok(())
}

/// `--window`, or its default: the queue length (so the hub never has to drop), at most
/// 8 MiB of payload, at least 2 messages.
fn in_flight(args: &Args) -> u64 {
    args.window.unwrap_or_else(|| {
        let queue = if args.queue_length == 0 {
            100
        } else {
            u64::from(args.queue_length)
        };
        queue.min((8 << 20) / args.size.max(1) as u64).max(2)
    })
}

fn secs_ns(s: f64) -> u64 {
    (s * 1e9) as u64
}

/// Runs one measurement against the hub at `args.hub`.
pub async fn relay(args: &Args) -> anyhow::Result<Summary> {
    let url = hub_url(&args.hub);
    let stop = CancellationToken::new();
    // Cancel everything however this function ends (an error included).
    let _guard = stop.clone().drop_guard();

    // 1. Subscribers, confirmed subscribed before anyone publishes.
    let subs = connect_all(args.subscribers, |i| {
        let url = url.clone();
        let queue = args.queue_length;
        let token = args.token.clone();
        async move {
            let who = format!("bench_sub_{i}");
            let mut c = conn::connect(&url, &who, &token).await?;
            c.send_and_sync(&[subscriber::subscribe(queue)], &who)
                .await?;
            Ok(c)
        }
    })
    .await?;
    // 2. Publishers, their topics confirmed created (which attaches the subscriptions).
    let pubs = connect_all(args.publishers, |i| {
        let url = url.clone();
        let token = args.token.clone();
        async move {
            let who = format!("bench_pub_{i}");
            let mut c = conn::connect(&url, &who, &token).await?;
            c.send_and_sync(&[conn::advertise(i)], &who).await?;
            Ok(c)
        }
    })
    .await?;

    let start_ns = unix_nanos();
    let window = Window {
        start_ns: start_ns + secs_ns(args.warmup),
        end_ns: start_ns + secs_ns(args.warmup + args.duration),
    };
    let shared: Vec<Arc<Shared>> = (0..args.subscribers)
        .map(|_| Arc::new(Shared::new(args.publishers)))
        .collect();
    let wake: Arc<[Notify]> = (0..args.publishers).map(|_| Notify::new()).collect();
    let mut sub_tasks = JoinSet::new();
    for (i, c) in subs.into_iter().enumerate() {
        let task = subscriber::run(c, window, shared[i].clone(), wake.clone(), stop.clone());
        sub_tasks.spawn(async move { (i, task.await) });
    }
    let sent_total: Vec<Arc<AtomicU64>> = (0..args.publishers)
        .map(|_| Arc::new(AtomicU64::new(0)))
        .collect();
    let mut done = Vec::new();
    let mut pub_tasks = JoinSet::new();
    for (i, c) in pubs.into_iter().enumerate() {
        let (tx, rx) = oneshot::channel();
        done.push(rx);
        let plan = Plan {
            size: args.size,
            rate: args.rate,
            window,
            flow: Flow {
                index: i,
                subscribers: shared.clone(),
                wake: wake.clone(),
                in_flight: in_flight(args),
            },
        };
        pub_tasks.spawn(publisher::run(
            c,
            plan,
            sent_total[i].clone(),
            tx,
            stop.clone(),
        ));
    }
    let progress = tokio::spawn(
        Progress {
            subscribers: shared.clone(),
            sent: sent_total.clone(),
            window,
            started_ns: start_ns,
        }
        .run(stop.clone()),
    );

    // 3. Publishing ends with the window; then wait for what is in flight.
    let mut sent: Vec<Sent> = Vec::new();
    for (i, rx) in done.into_iter().enumerate() {
        sent.push(
            rx.await
                .with_context(|| format!("publisher {i} lost its link to the hub"))?,
        );
    }
    let drained = drain(&sent, &shared, Duration::from_secs_f64(args.drain)).await;
    if !drained {
        eprintln!(
            "bench: some messages had not arrived {:.1} s after publishing stopped; counted as drops",
            args.drain
        );
    }
    stop.cancel();
    let _ = progress.await;
    let mut received = vec![Vec::new(); args.subscribers];
    while let Some(r) = sub_tasks.join_next().await {
        let (i, counts) = r.context("a subscriber task failed")?;
        received[i] = counts;
    }
    while pub_tasks.join_next().await.is_some() {}
    Ok(report::summarize(args, &sent, &received, &shared))
}

/// Opens `n` connections concurrently (a hundred subscribers should not connect one by
/// one); fails with the first error.
async fn connect_all<F, Fut>(n: usize, open: F) -> anyhow::Result<Vec<conn::Conn>>
where
    F: Fn(usize) -> Fut,
    Fut: Future<Output = anyhow::Result<conn::Conn>> + Send + 'static,
{
    let mut set = JoinSet::new();
    for i in 0..n {
        let f = open(i);
        set.spawn(async move { (i, f.await) });
    }
    let mut out: Vec<Option<conn::Conn>> = (0..n).map(|_| None).collect();
    while let Some(r) = set.join_next().await {
        let (i, c) = r.context("a connection task failed")?;
        out[i] = Some(c?);
    }
    Ok(out.into_iter().flatten().collect())
}

/// Waits until every subscriber has received each publisher's last message, or `limit`.
/// Polls: this is the end of a measurement, not a hot path.
async fn drain(sent: &[Sent], shared: &[Arc<Shared>], limit: Duration) -> bool {
    let deadline = tokio::time::Instant::now() + limit;
    loop {
        let complete = shared.iter().all(|s| {
            sent.iter()
                .zip(s.seen.iter())
                .all(|(p, seen)| p.messages == 0 || seen.load(Relaxed) > p.last_seq)
        });
        if complete {
            return true;
        }
        if tokio::time::Instant::now() >= deadline {
            return false;
        }
        tokio::time::sleep(Duration::from_millis(10)).await;
    }
}
