//! `fleetlink bench fleet`: a whole fleet of simulated robots on `fleetlink.v1` links, from
//! one process, against one hub or several federated hubs.
//!
//! Each robot is one connection and two tasks on a shared runtime (a reader and a writer;
//! no thread, no timer wheel of its own): it says `HELLO`, announces `--topics` topics
//! (`/fleet_<i>/pose`, `/fleet_<i>/t1`, …) and, once the whole fleet is up and a quiet
//! `--idle` phase has been measured, publishes each topic at `--rate` Hz. Its topics are
//! spread evenly over the period and robots are phase-shifted from one another, as a real
//! fleet's sensors are, so the hub sees a steady stream rather than synchronized bursts.
//! Robots honour the hub's `INTEREST` frames like agents do: a topic nobody wants is not
//! sent. Connections that the hub's handshake admission refuses (HTTP 503) are retried
//! with jittered exponential backoff, never sooner than its `Retry-After`, as agents do.
//!
//! Subscribers: `--subscribers S` connections, subscriber `j` on robot `j mod N`'s pose
//! topic, and with `--wildcard` one more subscribed to every fleet topic. With several
//! `--hub` URLs robot `i` connects to hub `i mod H` and its pose subscriber to the next
//! hub, so every pose message crosses between hubs; the wildcard subscriber is on the
//! first hub.
//!
//! What counts: as in `bench relay`, a message belongs to the measurement when its send
//! stamp falls inside `[start + warmup, start + warmup + duration)`; `expected` is what
//! the subscribers should receive of those, `delivered` what arrived, latency is send
//! stamp to receipt. Hubs on this machine (a loopback URL, or `--hub-pid`) are measured
//! from /proc: resident memory before the fleet connects, with the fleet connected and
//! idle, and loaded; CPU while idle and while loaded. The bench's own CPU is reported
//! beside them: on one machine the load generator competes for the same cores.
//!
//! Layout: [`args`] (the options), [`clients`] (what robots and subscribers share),
//! [`robot`], [`subscriber`], [`hubs`] (the hubs' processes in /proc) and [`summary`] (the
//! result); this module runs the phases in order. Imports run one way: this module →
//! `robot`/`subscriber` → `clients`, and `hubs` → `summary`.

mod args;
mod clients;
mod hubs;
mod robot;
mod subscriber;
mod summary;

use std::sync::Arc;
use std::sync::atomic::Ordering::Relaxed;
use std::time::Duration;

use fleetlink_relay::unix_nanos;
use tokio::sync::{mpsc, watch};
use tokio::time::Instant;
use tokio_util::sync::CancellationToken;

pub use args::Args;
use args::check;
use clients::{Counters, Crew, Phase, RobotSent, Schedule};
use hubs::{HubProcs, Sample};
use summary::{Summary, cpu_pct, round};

use crate::calls::stat_cpu_seconds;
use crate::conn::hub_url;
use crate::host::Host;
use crate::relay_args::Window;
use crate::report::Latency;

pub fn run(args: Args, host: &Host) -> anyhow::Result<()> {
    check(&args)?;
    let conns = args.robots + args.subscribers + usize::from(args.wildcard);
    (host.raise_open_files)(conns as u64 + 256)?;
    crate::measure::run_measurement(args.threads, args.json, fleet(&args))
}

async fn fleet(args: &Args) -> anyhow::Result<Summary> {
    let urls: Vec<String> = args.hubs.iter().map(|h| hub_url(h)).collect();
    let hubs = HubProcs::find(&urls, &args.hub_pids);
    let before = hubs.sample();
    let counters = Arc::new(Counters::default());
    let stop = CancellationToken::new();
    let _guard = stop.clone().drop_guard();
    let conns_total = args.robots + args.subscribers + usize::from(args.wildcard);
    let admission = Arc::new(tokio::sync::Semaphore::new(args.connect_concurrency));
    let connect_deadline = Instant::now() + Duration::from_secs_f64(args.connect_timeout);
    let t_connect = Instant::now();
    let progress = tokio::spawn(progress(counters.clone(), conns_total, stop.clone()));
    let (sched_tx, sched_rx) = watch::channel(Phase::Wait);
    let crew = Crew {
        admission,
        deadline: connect_deadline,
        counters: counters.clone(),
        schedule: sched_rx,
        stop: stop.clone(),
    };

    // 1. Subscribers, each confirmed subscribed before any robot announces a topic, and
    // each serving its link (pings) from the moment it is up.
    let n_subs = args.subscribers + usize::from(args.wildcard);
    let (sub_stats, mut sub_tasks) = subscriber::start_all(args, &urls, &crew).await?;

    // 2. Robots: connect, announce, wait for the schedule, publish.
    let (mut robots, mut done_rx) = robot::start_all(args, &urls, &crew).await?;
    let connect_s = t_connect.elapsed().as_secs_f64();
    let busy = counters.busy.load(Relaxed);
    let retries = counters.retries.load(Relaxed);
    eprintln!(
        "bench: {} robots and {n_subs} subscribers connected in {connect_s:.1} s \
         ({busy} refused busy, {retries} retries)",
        args.robots
    );

    // 3. The connected fleet, idle.
    let idle0 = hubs.sample();
    let self0 = stat_cpu_seconds("/proc/self/stat");
    tokio::time::sleep(Duration::from_secs_f64(args.idle)).await;
    let idle1 = hubs.sample();
    let self1 = stat_cpu_seconds("/proc/self/stat");
    let idle_cpu = cpu_pct(self0, self1, args.idle);

    // 4. Publishing.
    let (loaded, bench_cpu_loaded) = publish(args, &hubs, &sched_tx).await;
    let (sent_by_robot, reported) = collect_sent(args, &counters, &mut done_rx).await;
    let lost = args.robots - reported;
    let expected = expected_deliveries(args, &sent_by_robot);
    subscriber::drain(&sub_stats, expected, Duration::from_secs(5)).await;
    stop.cancel();
    let _ = progress.await;
    while sub_tasks.join_next().await.is_some() {}
    while robots.join_next().await.is_some() {}

    let (latency, delivered, gaps) = subscriber::totals(&sub_stats);
    let sent: u64 = sent_by_robot.iter().flatten().sum();
    let hub_figures = hubs.figures(&before, &idle0, &idle1, loaded.as_ref(), args);
    Ok(Summary {
        hubs: urls.len(),
        robots: args.robots,
        connected: args.robots - lost,
        topics: args.topics,
        rate: args.rate,
        size: args.size,
        subscribers: args.subscribers,
        wildcard: args.wildcard,
        connect_s: round(connect_s, 2),
        refused_busy: busy,
        retries,
        duration_s: args.duration,
        sent_per_s: round(sent as f64 / args.duration, 0),
        expected,
        delivered,
        delivered_per_s: round(delivered as f64 / args.duration, 0),
        drops: expected.saturating_sub(delivered),
        gaps,
        latency_us: (delivered > 0).then(|| Latency::of(&latency)),
        hub: hub_figures,
        bench_cpu_idle_pct: idle_cpu,
        bench_cpu_loaded_pct: bench_cpu_loaded,
    })
}

/// Starts the robots' schedule (none with `--rate 0`) and measures the window: the hubs'
/// samples at its start and end, and this process's CPU over it.
async fn publish(
    args: &Args,
    hubs: &HubProcs,
    sched_tx: &watch::Sender<Phase>,
) -> (Option<(Sample, Sample)>, Option<f64>) {
    let mut loaded = None;
    let mut bench_cpu_loaded = None;
    if args.rate > 0.0 {
        // Robots read the phase when they wake, at least every heartbeat: two
        // heartbeats' notice reaches every one before the start.
        let start = Instant::now() + Duration::from_secs(2);
        let start_ns = unix_nanos() + 2_000_000_000;
        let secs = |s: f64| Duration::from_secs_f64(s);
        let window = Window {
            start_ns: start_ns + secs(args.warmup).as_nanos() as u64,
            end_ns: start_ns + secs(args.warmup + args.duration).as_nanos() as u64,
        };
        let schedule = Schedule {
            start,
            end: start + secs(args.warmup + args.duration),
            step: secs(1.0 / (args.rate * args.topics as f64)),
            window,
        };
        sched_tx.send_replace(Phase::Publish(schedule));
        tokio::time::sleep_until(start + secs(args.warmup)).await;
        let l0 = hubs.sample();
        let s0 = stat_cpu_seconds("/proc/self/stat");
        tokio::time::sleep(secs(args.duration)).await;
        let l1 = hubs.sample();
        let s1 = stat_cpu_seconds("/proc/self/stat");
        loaded = Some((l0, l1));
        bench_cpu_loaded = cpu_pct(s0, s1, args.duration);
    } else {
        sched_tx.send_replace(Phase::Done);
    }
    (loaded, bench_cpu_loaded)
}

/// What each robot sent in the window, and how many robots reported it.
async fn collect_sent(
    args: &Args,
    counters: &Counters,
    done_rx: &mut mpsc::UnboundedReceiver<(usize, RobotSent)>,
) -> (Vec<RobotSent>, usize) {
    let mut sent_by_robot: Vec<RobotSent> = vec![vec![0; args.topics]; args.robots];
    // The robots report what they sent once their schedule is over; a robot that lost
    // its link never does.
    let mut reported = 0;
    while reported + (counters.lost.load(Relaxed) as usize) < args.robots {
        match tokio::time::timeout(Duration::from_secs(1), done_rx.recv()).await {
            Ok(Some((i, sent))) => {
                sent_by_robot[i] = sent;
                reported += 1;
            }
            Ok(None) => break,
            Err(_) => {}
        }
    }
    (sent_by_robot, reported)
}

/// Deliveries the subscribers should see of the window's messages.
fn expected_deliveries(args: &Args, sent: &[RobotSent]) -> u64 {
    let pose: u64 = (0..args.subscribers)
        .map(|j| sent[j % args.robots][0])
        .sum();
    let all: u64 = if args.wildcard {
        sent.iter().flatten().sum()
    } else {
        0
    };
    pose + all
}

/// Prints a progress line on stderr once per second.
async fn progress(counters: Arc<Counters>, conns: usize, stop: CancellationToken) {
    let mut tick = tokio::time::interval(Duration::from_secs(1));
    tick.tick().await;
    let (mut sent0, mut got0) = (0, 0);
    loop {
        tokio::select! {
            _ = tick.tick() => {}
            _ = stop.cancelled() => return,
        }
        let sent = counters.sent.load(Relaxed);
        let got = counters.delivered.load(Relaxed);
        eprintln!(
            "bench: connected {}/{conns} (busy {}, retries {}, lost {})  in {} msg/s  out {} msg/s",
            counters.connected.load(Relaxed),
            counters.busy.load(Relaxed),
            counters.retries.load(Relaxed),
            counters.lost.load(Relaxed),
            sent - sent0,
            got - got0,
        );
        (sent0, got0) = (sent, got);
    }
}

#[cfg(test)]
mod tests {
    use std::net::IpAddr;

    use super::clients::{parse_topic, source_for, topic_name};
    use super::*;

    #[test]
    fn fleet_topic_names_round_trip() {
        for (i, k) in [(0, 0), (7, 1), (999, 9)] {
            assert_eq!(parse_topic(&topic_name(i, k)), Some((i, k)));
        }
        assert_eq!(parse_topic("/fleet_1/t0"), None);
        assert_eq!(parse_topic("/fleet_x/pose"), None);
        assert_eq!(parse_topic("/bench_pub_1/data"), None);
    }

    #[test]
    fn sources_are_distinct_loopback_addresses_and_only_for_loopback_hubs() {
        let a: Vec<IpAddr> = (0..2000)
            .map(|n| source_for("ws://127.0.0.1:8080", n).expect("loopback"))
            .collect();
        let mut d = a.clone();
        d.sort();
        d.dedup();
        assert_eq!(d.len(), a.len());
        for ip in &a {
            let IpAddr::V4(v4) = ip else { panic!("v4") };
            assert!(v4.is_loopback());
            assert!(v4.octets()[3] != 0 && v4.octets()[3] != 255, "{v4}");
        }
        assert_eq!(source_for("ws://10.0.0.5:8080", 0), None);
        assert_eq!(source_for("wss://hub.example", 0), None);
    }

    #[test]
    fn expected_counts_pose_subscribers_and_the_wildcard() {
        let args = Args {
            hubs: vec!["x".into()],
            token: String::new(),
            subscriber_token: None,
            robots: 2,
            topics: 3,
            rate: 10.0,
            size: 8,
            subscribers: 3,
            wildcard: true,
            duration: 1.0,
            warmup: 0.0,
            idle: 0.0,
            connect_timeout: 1.0,
            connect_concurrency: 1,
            queue_length: 0,
            probe_ms: 200,
            hub_pids: vec![],
            json: false,
            threads: None,
        };
        let sent = vec![vec![10, 5, 5], vec![7, 1, 1]];
        // Subscribers 0 and 2 on robot 0's pose (10 each), 1 on robot 1's (7); all 29.
        assert_eq!(expected_deliveries(&args, &sent), 10 + 7 + 10 + 29);
    }
}
