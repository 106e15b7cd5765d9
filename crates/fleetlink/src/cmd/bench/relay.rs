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

use std::str::FromStr;
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

#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Hub URL, e.g. ws://127.0.0.1:8080 (a bare host:port works too).
    #[arg(long)]
    pub hub: String,
    /// An operator token of the hub's admin group (the bench opens agent links under
    /// made-up robot names). Also read from FLEETLINK_TOKEN.
    #[arg(long, env = "FLEETLINK_TOKEN", default_value = "")]
    pub token: String,
    /// Number of publisher connections, each with its own topic.
    #[arg(long, default_value_t = 1)]
    pub publishers: usize,
    /// Number of subscriber connections, each subscribed to every publisher's topic.
    #[arg(long, default_value_t = 1)]
    pub subscribers: usize,
    /// Payload size in bytes.
    #[arg(long, default_value_t = 64)]
    pub size: usize,
    /// Messages per second per publisher, or `max` to send as fast as the link takes them.
    #[arg(long, default_value = "max")]
    pub rate: Rate,
    /// Measured time in seconds (after the warm-up).
    #[arg(long, default_value_t = 5.0)]
    pub duration: f64,
    /// Seconds of sending before the measurement starts.
    #[arg(long, default_value_t = 1.0)]
    pub warmup: f64,
    /// Longest wait, in seconds, for messages still in flight when publishing stops.
    #[arg(long, default_value_t = 10.0)]
    pub drain: f64,
    /// Queue length the subscribers ask the hub for (0: the hub's default).
    #[arg(long, default_value_t = 1024)]
    pub queue_length: u32,
    /// At `--rate max`: most messages a publisher keeps in flight (sent, not yet received
    /// by every subscriber). Default: the queue length, capped at 8 MiB of payload.
    #[arg(long)]
    pub window: Option<u64>,
    /// Print the final summary as one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    /// Worker threads of the bench's runtime (default: one per core).
    #[arg(long)]
    pub threads: Option<usize>,
}

/// `--rate`: a number of messages per second, or as fast as possible.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rate {
    Max,
    Hz(f64),
}

impl FromStr for Rate {
    type Err = String;

    fn from_str(s: &str) -> Result<Rate, String> {
        if s.eq_ignore_ascii_case("max") {
            return Ok(Rate::Max);
        }
        match s.parse::<f64>() {
            Ok(hz) if hz.is_finite() && hz > 0.0 => Ok(Rate::Hz(hz)),
            _ => Err(format!(
                "expected messages per second (> 0) or `max`, got {s:?}"
            )),
        }
    }
}

/// The measurement window, in Unix nanoseconds: messages stamped in `[start, end)`.
#[derive(Debug, Clone, Copy)]
pub struct Window {
    pub start_ns: u64,
    pub end_ns: u64,
}

impl Window {
    pub fn contains(&self, stamp_ns: u64) -> bool {
        stamp_ns >= self.start_ns && stamp_ns < self.end_ns
    }
}

pub fn run(args: Args) -> anyhow::Result<()> {
    check(&args)?;
    super::run_measurement(args.threads, args.json, relay(&args))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rate_parses_max_and_positive_numbers_only() {
        assert_eq!("max".parse::<Rate>(), Ok(Rate::Max));
        assert_eq!("MAX".parse::<Rate>(), Ok(Rate::Max));
        assert_eq!("10000".parse::<Rate>(), Ok(Rate::Hz(10000.0)));
        assert_eq!("0.5".parse::<Rate>(), Ok(Rate::Hz(0.5)));
        for bad in ["0", "-1", "inf", "NaN", "fast", ""] {
            assert!(bad.parse::<Rate>().is_err(), "{bad:?} accepted");
        }
    }

    #[test]
    fn window_is_half_open() {
        let w = Window {
            start_ns: 10,
            end_ns: 20,
        };
        assert!(!w.contains(9));
        assert!(w.contains(10));
        assert!(w.contains(19));
        assert!(!w.contains(20));
    }
}
