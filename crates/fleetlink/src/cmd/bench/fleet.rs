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

use std::collections::HashMap;
use std::net::{IpAddr, Ipv4Addr};
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use anyhow::{Context, bail};
use bytes::{Bytes, BytesMut};
use fleetlink_proto::frame::{self, Frame, Level, SUBSCRIBE_REGEX};
use fleetlink_proto::{Encoding, Schema};
use fleetlink_relay::link::LinkEvent;
use fleetlink_relay::unix_nanos;
use futures_util::{SinkExt, StreamExt};
use hdrhistogram::Histogram;
use serde::Serialize;
use tokio::sync::{mpsc, watch};
use tokio::task::JoinSet;
use tokio::time::Instant;
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_util::sync::CancellationToken;

use super::calls::{proc_figures, stat_cpu_seconds};
use super::conn::{self, BARRIER_PING, Busy, Conn, Ws, hub_url, pong, put_ping};
use super::relay::Window;
use super::report::Latency;
use super::subscriber::new_histogram;

/// Most topics a simulated robot announces (its interest is one 64-bit mask).
const MAX_TOPICS: usize = 64;
/// Type the fleet's topics are announced with; the hub never looks inside.
const FLEET_TYPE: &str = "fleetlink_bench/msg/Blob";

#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Hub URL (ws://host:port or host:port). Give it several times to spread the robots
    /// over federated hubs: robot i connects to hub i mod H.
    #[arg(long = "hub", required = true)]
    pub hubs: Vec<String>,
    /// Token sent in every robot's HELLO and by the subscribers (empty: the hub trusts
    /// robots from this address, `--robot-network`). Also read from FLEETLINK_TOKEN.
    #[arg(long, env = "FLEETLINK_TOKEN", default_value = "")]
    pub token: String,
    /// Token of the subscribers (operators: they may read every robot's topics); default
    /// the `--token`. Also read from FLEETLINK_SUBSCRIBER_TOKEN.
    #[arg(long, env = "FLEETLINK_SUBSCRIBER_TOKEN")]
    pub subscriber_token: Option<String>,
    /// Number of robots.
    #[arg(long, default_value_t = 100)]
    pub robots: usize,
    /// Topics per robot (at most 64).
    #[arg(long, default_value_t = 10)]
    pub topics: usize,
    /// Messages per second per topic; 0 connects the fleet and measures it idle only.
    #[arg(long, default_value_t = 10.0)]
    pub rate: f64,
    /// Payload bytes per message.
    #[arg(long, default_value_t = 64)]
    pub size: usize,
    /// Subscriber connections, subscriber j on robot (j mod robots)'s pose topic.
    #[arg(long, default_value_t = 0)]
    pub subscribers: usize,
    /// One more subscriber, to every topic of the fleet.
    #[arg(long)]
    pub wildcard: bool,
    /// Measured seconds of publishing (after the warm-up).
    #[arg(long, default_value_t = 10.0)]
    pub duration: f64,
    /// Seconds of publishing before the measurement starts.
    #[arg(long, default_value_t = 2.0)]
    pub warmup: f64,
    /// Seconds the connected fleet is measured idle before publishing starts.
    #[arg(long, default_value_t = 5.0)]
    pub idle: f64,
    /// Longest time, in seconds, for the whole fleet to connect.
    #[arg(long, default_value_t = 300.0)]
    pub connect_timeout: f64,
    /// Handshakes this bench has in progress at once (the hub admits what it can and
    /// answers the rest 503; those retry with backoff).
    #[arg(long, default_value_t = 1024)]
    pub connect_concurrency: usize,
    /// Milliseconds between a robot's pings while it publishes: the agent's link
    /// estimator sends an echo probe every 200 ms besides its heartbeat ping while data
    /// waits or is unacknowledged, and so do these robots while their schedule runs. An
    /// idle agent pings at its heartbeat only, and so do these robots before and after
    /// their schedule (and throughout with `--rate 0`). 0: heartbeat pings only.
    #[arg(long, default_value_t = 200)]
    pub probe_ms: u64,
    /// Queue length the subscribers ask the hub for (0: the hub's default).
    #[arg(long, default_value_t = 4096)]
    pub queue_length: u32,
    /// Process id of a hub to measure (repeat per hub); hubs on loopback URLs are found
    /// by their listening port without it.
    #[arg(long = "hub-pid")]
    pub hub_pids: Vec<u32>,
    /// Print the final summary as one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    /// Worker threads of the bench's runtime (default: one per core).
    #[arg(long)]
    pub threads: Option<usize>,
}

pub fn run(args: Args) -> anyhow::Result<()> {
    check(&args)?;
    let conns = args.robots + args.subscribers + usize::from(args.wildcard);
    crate::cmd::raise_open_files(conns as u64 + 256)?;
    super::run_measurement(args.threads, args.json, fleet(&args))
}

fn check(args: &Args) -> anyhow::Result<()> {
    if args.robots == 0 {
        bail!("--robots must be at least 1");
    }
    if args.topics == 0 || args.topics > MAX_TOPICS {
        bail!("--topics must be 1 to {MAX_TOPICS}, got {}", args.topics);
    }
    if !(args.rate >= 0.0 && args.rate.is_finite()) {
        bail!("--rate must be a number of messages per second (0 for an idle fleet)");
    }
    if !(args.duration > 0.0 && args.duration.is_finite()) {
        bail!("--duration must be a positive number of seconds");
    }
    for (name, v) in [
        ("--warmup", args.warmup),
        ("--idle", args.idle),
        ("--connect-timeout", args.connect_timeout),
    ] {
        if !(v >= 0.0 && v.is_finite()) {
            bail!("{name} must be a non-negative number of seconds");
        }
    }
    if args.connect_concurrency == 0 {
        bail!("--connect-concurrency must be at least 1");
    }
    Ok(())
}

/// Robot `i`'s name.
fn robot_name(i: usize) -> String {
    format!("fleet_{i}")
}

/// Topic `k` of robot `i`: topic 0 is the pose.
fn topic_name(i: usize, k: usize) -> String {
    if k == 0 {
        format!("/fleet_{i}/pose")
    } else {
        format!("/fleet_{i}/t{k}")
    }
}

/// Robot and topic index of a fleet topic name.
fn parse_topic(name: &str) -> Option<(usize, usize)> {
    let rest = name.strip_prefix("/fleet_")?;
    let (robot, topic) = rest.split_once('/')?;
    let robot = robot.parse().ok()?;
    let k = if topic == "pose" {
        0
    } else {
        topic.strip_prefix('t')?.parse().ok().filter(|k| *k > 0)?
    };
    Some((robot, k))
}

/// The local address connection `n` of this bench comes from, when the hub is on
/// loopback: one per connection across 127.0.0.0/8, as a fleet comes from many addresses.
fn source_for(url: &str, n: usize) -> Option<IpAddr> {
    let host = url.split("://").nth(1)?.split(['/', ':']).next()?;
    let loopback = host == "localhost" || host.parse::<Ipv4Addr>().is_ok_and(|a| a.is_loopback());
    if !loopback {
        return None;
    }
    // 127.0.1.1 upwards (127.0.0.x is left to everything else), skipping .0 and .255.
    let n = n as u32;
    let base = u32::from(Ipv4Addr::new(127, 0, 1, 0));
    let host_part = (n / 254) * 256 + n % 254 + 1;
    Some(IpAddr::V4(Ipv4Addr::from(
        base + host_part.min(0x00fe_fefe),
    )))
}

/// Counters the progress display and the summary read.
#[derive(Default)]
struct Counters {
    connected: AtomicU64,
    busy: AtomicU64,
    retries: AtomicU64,
    lost: AtomicU64,
    sent: AtomicU64,
    delivered: AtomicU64,
}

/// What the robots are told to do, shared by all of them.
#[derive(Clone, Copy)]
enum Phase {
    /// Connected, keeping the link alive.
    Wait,
    Publish(Schedule),
    /// No publishing (an idle run); report and keep the link alive.
    Done,
}

/// When and how fast the robots publish.
#[derive(Clone, Copy)]
struct Schedule {
    start: Instant,
    end: Instant,
    /// Time between two messages of one robot (its topics take turns).
    step: Duration,
    window: Window,
}

/// A robot's outcome: messages sent per topic with a stamp inside the window.
type RobotSent = Vec<u64>;

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

    // 1. Subscribers, each confirmed subscribed before any robot announces a topic, and
    // each serving its link (pings) from the moment it is up.
    let (sched_tx, sched_rx) = watch::channel(Phase::Wait);
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
        let (admission, counters) = (admission.clone(), counters.clone());
        let (up, stats, sched, stop) = (
            sub_up_tx.clone(),
            stats.clone(),
            sched_rx.clone(),
            stop.clone(),
        );
        sub_tasks.spawn(async move {
            let connected = async {
                let mut c = connect_retrying(
                    &url,
                    &who,
                    &token,
                    source,
                    &admission,
                    &counters,
                    connect_deadline,
                )
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

    // 2. Robots: connect, announce, wait for the schedule, publish.
    let payload = Bytes::from(vec![0x5a; args.size]);
    let mut robots = JoinSet::new();
    let (up_tx, mut up_rx) = mpsc::unbounded_channel::<anyhow::Result<()>>();
    let (done_tx, mut done_rx) = mpsc::unbounded_channel::<(usize, RobotSent)>();
    for i in 0..args.robots {
        let url = urls[i % urls.len()].clone();
        let plan = RobotPlan {
            probe: (args.probe_ms > 0).then(|| Duration::from_millis(args.probe_ms)),
            index: i,
            topics: args.topics,
            source: source_for(&url, i),
            url,
            token: args.token.clone(),
            payload: payload.clone(),
            phase: phase_of(i),
        };
        robots.spawn(robot(
            plan,
            admission.clone(),
            connect_deadline,
            counters.clone(),
            sched_rx.clone(),
            up_tx.clone(),
            done_tx.clone(),
            stop.clone(),
        ));
    }
    drop((up_tx, done_tx));
    for _ in 0..args.robots {
        match up_rx.recv().await {
            Some(Ok(())) => {}
            Some(Err(e)) => return Err(e),
            None => bail!("the robots' tasks ended before the fleet was up"),
        }
    }
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
    let mut loaded = None;
    let mut bench_cpu_loaded = None;
    let mut sent_by_robot: Vec<RobotSent> = vec![vec![0; args.topics]; args.robots];
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
    let lost = args.robots - reported;
    let expected = expected_deliveries(args, &sent_by_robot);
    drain(&sub_stats, expected, Duration::from_secs(5)).await;
    stop.cancel();
    let _ = progress.await;
    while sub_tasks.join_next().await.is_some() {}
    while robots.join_next().await.is_some() {}

    let mut latency = new_histogram();
    let mut delivered = 0;
    let mut gaps = 0;
    for s in &sub_stats {
        latency.add(&*s.latency()).ok();
        delivered += s.in_window.load(Relaxed);
        gaps += s.gaps.load(Relaxed);
    }
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

/// A fraction in [0, 1) for robot `i`, spread evenly (golden ratio): its phase within the
/// message period, so robots do not publish in step.
fn phase_of(i: usize) -> f64 {
    (i as f64 * 0.618_033_988_749_895).fract()
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

/// Waits until the subscribers have received `expected` window messages, or `limit`.
async fn drain(subs: &[Arc<SubStats>], expected: u64, limit: Duration) {
    let deadline = Instant::now() + limit;
    while Instant::now() < deadline {
        let got: u64 = subs.iter().map(|s| s.in_window.load(Relaxed)).sum();
        if got >= expected {
            return;
        }
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
}

fn cpu_pct(a: Option<f64>, b: Option<f64>, secs: f64) -> Option<f64> {
    Some(round((b? - a?) / secs * 100.0, 1))
}

fn round(x: f64, places: i32) -> f64 {
    let m = 10f64.powi(places);
    (x * m).round() / m
}

/// Connects (from `source`), retrying refusals and failures with full-jitter exponential
/// backoff (250 ms doubling to 8 s, never sooner than a `Retry-After`) until `deadline`.
async fn connect_retrying(
    url: &str,
    who: &str,
    token: &str,
    source: Option<IpAddr>,
    admission: &tokio::sync::Semaphore,
    counters: &Counters,
    deadline: Instant,
) -> anyhow::Result<Conn> {
    let mut backoff = Duration::from_millis(250);
    loop {
        let attempt = {
            let _permit = admission
                .acquire()
                .await
                .context("bench admission closed")?;
            conn::connect_from(url, who, token, source).await
        };
        let e = match attempt {
            Ok(c) => return Ok(c),
            Err(e) => e,
        };
        let floor = match e.downcast_ref::<Busy>() {
            Some(b) => {
                counters.busy.fetch_add(1, Relaxed);
                b.retry_after.unwrap_or_default()
            }
            None => Duration::ZERO,
        };
        let wait = floor.max(backoff.mul_f64(fastrand::f64()));
        if Instant::now() + wait > deadline {
            return Err(e.context(format!("{who}: still not connected at --connect-timeout")));
        }
        counters.retries.fetch_add(1, Relaxed);
        tokio::time::sleep(wait).await;
        backoff = (backoff * 2).min(Duration::from_secs(8));
    }
}

struct RobotPlan {
    /// Ping period when shorter than the heartbeat (the agent's probes).
    probe: Option<Duration>,
    index: usize,
    topics: usize,
    url: String,
    source: Option<IpAddr>,
    token: String,
    payload: Bytes,
    phase: f64,
}

/// One robot from connection until the bench stops. Reports on `up` once its topics are
/// announced (or why it could not connect), and on `done` what it sent in the window once
/// its schedule is over.
///
/// One task owns the robot's WebSocket: it reads (interest, pings) and writes (messages
/// when due, keepalive pings) in turn, with one timer re-armed in place. A robot costs
/// the bench no lock shared with the other robots on its hot path: it reads the phase
/// when it wakes (at least every keepalive), it is never woken by a change of it.
#[allow(clippy::too_many_arguments)]
async fn robot(
    plan: RobotPlan,
    admission: Arc<tokio::sync::Semaphore>,
    deadline: Instant,
    counters: Arc<Counters>,
    schedule: watch::Receiver<Phase>,
    up: mpsc::UnboundedSender<anyhow::Result<()>>,
    done: mpsc::UnboundedSender<(usize, RobotSent)>,
    stop: CancellationToken,
) {
    let name = robot_name(plan.index);
    let c = match connect_retrying(
        &plan.url,
        &name,
        &plan.token,
        plan.source,
        &admission,
        &counters,
        deadline,
    )
    .await
    {
        Ok(c) => c,
        Err(e) => {
            let _ = up.send(Err(e));
            return;
        }
    };
    let heartbeat = heartbeat_of(&c);
    // While it publishes, a robot pings as often as the agent's estimator probes.
    let busy_ping = heartbeat.min(plan.probe.unwrap_or(Duration::MAX));
    let mut r = Robot {
        ws: c.ws,
        link: c.link,
        wanted: 0,
        buf: BytesMut::new(),
        keepalive: heartbeat,
        next_ping: Instant::now() + heartbeat,
        ping_id: 0,
    };
    match tokio::time::timeout(Duration::from_secs(30), r.announce(&plan)).await {
        Ok(Ok(())) => {}
        Ok(Err(e)) => {
            let _ = up.send(Err(e.context(format!("{name}: announcing topics"))));
            return;
        }
        Err(_) => {
            let _ = up.send(Err(anyhow::anyhow!(
                "{name}: no answer from the hub to its topic announcements in 30 s"
            )));
            return;
        }
    }
    counters.connected.fetch_add(1, Relaxed);
    let _ = up.send(Ok(()));
    drop(up);

    let mut sent: RobotSent = vec![0; plan.topics];
    let mut m: u64 = 0;
    let mut reported = false;
    let cancelled = stop.cancelled();
    tokio::pin!(cancelled);
    let timer = tokio::time::sleep_until(r.next_ping);
    tokio::pin!(timer);
    let ok = loop {
        let phase = *schedule.borrow();
        let next_msg = match phase {
            Phase::Publish(s) => {
                Some(s.start + s.step.mul_f64(plan.phase + m as f64)).filter(|at| *at < s.end)
            }
            Phase::Wait | Phase::Done => None,
        };
        let over = match phase {
            Phase::Publish(s) => next_msg.is_none() || Instant::now() >= s.end,
            Phase::Done => true,
            Phase::Wait => false,
        };
        r.keepalive = if next_msg.is_some() {
            busy_ping
        } else {
            heartbeat
        };
        if !reported && over {
            // The schedule is over (or there was none): report, keep the link up.
            reported = true;
            let _ = done.send((plan.index, std::mem::take(&mut sent)));
        }
        timer
            .as_mut()
            .reset(next_msg.map_or(r.next_ping, |at| at.min(r.next_ping)));
        tokio::select! {
            biased;
            _ = &mut cancelled => return,
            m = r.ws.next() => match m {
                Some(Ok(WsMessage::Binary(b))) => {
                    r.on_hub(&b);
                }
                Some(Ok(_)) => {}
                _ => break false,
            },
            _ = &mut timer => {}
        }
        let now = Instant::now();
        if let (Phase::Publish(s), Some(_)) = (phase, next_msg) {
            let stamp = unix_nanos();
            let mut n = 0;
            loop {
                let at = s.start + s.step.mul_f64(plan.phase + m as f64);
                if at > now || at >= s.end {
                    break;
                }
                let k = (m % plan.topics as u64) as usize;
                if r.wanted & (1 << k) != 0 {
                    let seq = m / plan.topics as u64;
                    frame::encode_message(&mut r.buf, k as u32 + 1, seq, stamp, &plan.payload);
                    n += 1;
                    if s.window.contains(stamp) {
                        sent[k] += 1;
                    }
                }
                m += 1;
            }
            if n > 0 {
                counters.sent.fetch_add(n, Relaxed);
            }
        }
        if now >= r.next_ping {
            r.ping();
        }
        if !r.buf.is_empty() {
            let out = r.buf.split().freeze();
            if r.ws.send(WsMessage::Binary(out)).await.is_err() {
                break false;
            }
        }
    };
    if !ok && !stop.is_cancelled() {
        counters.lost.fetch_add(1, Relaxed);
        eprintln!("bench: {name} lost its link to the hub");
    }
}

/// How often a fleet client pings: once per agreed heartbeat, as the agent does (the
/// hub pings too, and declares a link dead after two heartbeats without a byte).
fn heartbeat_of(c: &Conn) -> Duration {
    c.keepalive * 2
}

/// A simulated robot's link.
struct Robot {
    ws: Ws,
    link: fleetlink_relay::link::LinkIn,
    /// Bit k: the hub wants topic k (alias k + 1).
    wanted: u64,
    /// What goes out with the next write.
    buf: BytesMut,
    keepalive: Duration,
    next_ping: Instant,
    ping_id: u64,
}

impl Robot {
    /// Sends the `ADVERTISE`s and a barrier `PING`, and reads until its `PONG`.
    async fn announce(&mut self, plan: &RobotPlan) -> anyhow::Result<()> {
        for k in 0..plan.topics {
            Frame::Advertise {
                alias: k as u32 + 1,
                topic: topic_name(plan.index, k),
                schema: Schema {
                    type_name: FLEET_TYPE.into(),
                    encoding: "ros2msg".into(),
                    text: "uint8[] data\n".into(),
                },
                encoding: Encoding::Cdr,
                flags: 0,
            }
            .encode(&mut self.buf);
        }
        Frame::Ping {
            id: BARRIER_PING,
            sent_ns: unix_nanos(),
        }
        .encode(&mut self.buf);
        let out = self.buf.split().freeze();
        self.ws.send(WsMessage::Binary(out)).await?;
        loop {
            let Some(m) = self.ws.next().await else {
                bail!("the hub closed the link");
            };
            let WsMessage::Binary(b) = m? else { continue };
            if self.on_hub(&b) {
                break;
            }
        }
        if !self.buf.is_empty() {
            let out = self.buf.split().freeze();
            self.ws.send(WsMessage::Binary(out)).await?;
        }
        Ok(())
    }

    /// Handles what the hub sent: interest, pings (answered with the next write), errors.
    /// True when it held the announcement barrier's `PONG`.
    fn on_hub(&mut self, b: &Bytes) -> bool {
        let mut barrier = false;
        for f in fleetlink_proto::frame::frames(b) {
            let Ok(f) = f else { break };
            match self.link.on_frame(f) {
                Ok(LinkEvent::Control(Frame::Interest { alias, wanted })) => {
                    if let Some(bit) = alias.checked_sub(1).filter(|b| *b < 64) {
                        if wanted {
                            self.wanted |= 1 << bit;
                        } else {
                            self.wanted &= !(1 << bit);
                        }
                    }
                }
                Ok(LinkEvent::Control(Frame::Pong { id, .. })) if id == BARRIER_PING => {
                    barrier = true;
                }
                Ok(LinkEvent::Control(Frame::Ping { id, sent_ns })) => {
                    self.buf.extend_from_slice(&pong(id, sent_ns));
                }
                Ok(LinkEvent::Control(Frame::Status { level, text, .. }))
                    if level != Level::Info =>
                {
                    eprintln!("bench: hub to robot: {text}");
                }
                _ => {}
            }
        }
        self.link.unacked = 0;
        barrier
    }

    fn ping(&mut self) {
        self.ping_id += 1;
        put_ping(&mut self.buf, self.ping_id);
        self.next_ping = Instant::now() + self.keepalive;
    }
}

/// What one subscriber received.
struct SubStats {
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

/// The hubs this bench can see in /proc.
struct HubProcs {
    pids: Vec<u32>,
}

/// CPU seconds and resident kB of every measured hub at one moment.
type Sample = Vec<Option<(f64, u64)>>;

impl HubProcs {
    fn find(urls: &[String], given: &[u32]) -> HubProcs {
        let mut pids: Vec<u32> = given.to_vec();
        if pids.is_empty() {
            pids = urls.iter().filter_map(|u| local_hub_pid(u)).collect();
        }
        pids.dedup();
        HubProcs { pids }
    }

    fn sample(&self) -> Sample {
        self.pids.iter().map(|p| proc_figures(*p)).collect()
    }

    fn figures(
        &self,
        before: &Sample,
        idle0: &Sample,
        idle1: &Sample,
        loaded: Option<&(Sample, Sample)>,
        args: &Args,
    ) -> Vec<HubFigures> {
        let conns = args.robots + args.subscribers + usize::from(args.wildcard);
        let conns_per_hub = conns as f64 / self.pids.len().max(1) as f64;
        let pct = |a: Option<(f64, u64)>, b: Option<(f64, u64)>, secs: f64| {
            cpu_pct(a.map(|x| x.0), b.map(|x| x.0), secs)
        };
        self.pids
            .iter()
            .enumerate()
            .map(|(i, &pid)| {
                let rss = |s: &Sample| s[i].map(|x| x.1);
                let kb_per_connection = match (rss(before), rss(idle1)) {
                    (Some(a), Some(b)) => Some(round((b as f64 - a as f64) / conns_per_hub, 1)),
                    _ => None,
                };
                HubFigures {
                    pid,
                    rss_before_kb: rss(before),
                    rss_idle_kb: rss(idle1),
                    rss_loaded_kb: loaded.and_then(|l| rss(&l.1)),
                    kb_per_connection,
                    cpu_idle_pct: pct(idle0[i], idle1[i], args.idle),
                    cpu_loaded_pct: loaded.and_then(|l| pct(l.0[i], l.1[i], args.duration)),
                }
            })
            .collect()
    }
}

/// The process listening on a loopback URL's port, from /proc/net/tcp and the processes'
/// open sockets (needs the right to read other processes' fds: the same user, or root).
fn local_hub_pid(url: &str) -> Option<u32> {
    let authority = url.split("://").nth(1)?.split('/').next()?;
    let (host, port) = authority.rsplit_once(':')?;
    let port: u16 = port.parse().ok()?;
    let loopback = host == "localhost"
        || host
            .parse::<Ipv4Addr>()
            .is_ok_and(|a| a.is_loopback() || a.is_unspecified());
    if !loopback {
        return None;
    }
    let mut inodes = Vec::new();
    for table in ["/proc/net/tcp", "/proc/net/tcp6"] {
        let Ok(text) = std::fs::read_to_string(table) else {
            continue;
        };
        for line in text.lines().skip(1) {
            let f: Vec<&str> = line.split_whitespace().collect();
            let (Some(local), Some(state), Some(inode)) = (f.get(1), f.get(3), f.get(9)) else {
                continue;
            };
            let listening = *state == "0A";
            let port_hex = local.rsplit(':').next().unwrap_or_default();
            if listening && u16::from_str_radix(port_hex, 16).ok() == Some(port) {
                inodes.push(format!("socket:[{inode}]"));
            }
        }
    }
    if inodes.is_empty() {
        return None;
    }
    let me = std::process::id();
    for entry in std::fs::read_dir("/proc").ok()?.flatten() {
        let Some(pid) = entry
            .file_name()
            .to_str()
            .and_then(|s| s.parse::<u32>().ok())
        else {
            continue;
        };
        if pid == me {
            continue;
        }
        let Ok(fds) = std::fs::read_dir(entry.path().join("fd")) else {
            continue;
        };
        for fd in fds.flatten() {
            if let Ok(target) = std::fs::read_link(fd.path())
                && inodes.iter().any(|i| target.as_os_str() == i.as_str())
            {
                return Some(pid);
            }
        }
    }
    None
}

/// The final result. Field names are the `--json` keys.
#[derive(Debug, Serialize)]
pub struct Summary {
    pub hubs: usize,
    pub robots: usize,
    /// Robots still connected at the end.
    pub connected: usize,
    pub topics: usize,
    pub rate: f64,
    pub size: usize,
    pub subscribers: usize,
    pub wildcard: bool,
    /// Seconds from the first connection attempt until every robot had announced.
    pub connect_s: f64,
    /// Connection attempts the hubs refused busy (503), and retries of all kinds.
    pub refused_busy: u64,
    pub retries: u64,
    pub duration_s: f64,
    /// Messages per second the robots sent in the window (all topics).
    pub sent_per_s: f64,
    /// Deliveries of window messages the subscribers should see, and saw.
    pub expected: u64,
    pub delivered: u64,
    pub delivered_per_s: f64,
    pub drops: u64,
    /// Messages missing between consecutive sequence numbers, any stamp.
    pub gaps: u64,
    pub latency_us: Option<Latency>,
    pub hub: Vec<HubFigures>,
    pub bench_cpu_idle_pct: Option<f64>,
    pub bench_cpu_loaded_pct: Option<f64>,
}

/// One hub process's figures (percent of one core).
#[derive(Debug, Serialize)]
pub struct HubFigures {
    pub pid: u32,
    pub rss_before_kb: Option<u64>,
    pub rss_idle_kb: Option<u64>,
    pub rss_loaded_kb: Option<u64>,
    /// Resident memory the connected idle fleet added, per connection (robots and
    /// subscribers) on this hub.
    pub kb_per_connection: Option<f64>,
    pub cpu_idle_pct: Option<f64>,
    pub cpu_loaded_pct: Option<f64>,
}

impl super::Report for Summary {
    fn text(&self) -> String {
        use std::fmt::Write;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "fleet: {} robots on {} hub(s), {} topics at {} Hz, {} B; {} pose subscribers{}",
            self.robots,
            self.hubs,
            self.topics,
            self.rate,
            self.size,
            self.subscribers,
            if self.wildcard { " + 1 wildcard" } else { "" }
        );
        let _ = writeln!(
            s,
            "connected {}/{} in {:.2} s ({} refused busy, {} retries)",
            self.connected, self.robots, self.connect_s, self.refused_busy, self.retries
        );
        if self.rate > 0.0 {
            let _ = writeln!(
                s,
                "in {:.0} msg/s, delivered {:.0} msg/s ({} of {} expected, {} dropped, {} gaps)",
                self.sent_per_s,
                self.delivered_per_s,
                self.delivered,
                self.expected,
                self.drops,
                self.gaps
            );
            if let Some(l) = &self.latency_us {
                let _ = writeln!(
                    s,
                    "latency µs: p50 {} p99 {} p999 {} max {}",
                    l.p50, l.p99, l.p999, l.max
                );
            }
        }
        for h in &self.hub {
            let opt = |v: Option<f64>| v.map_or("-".to_owned(), |v| format!("{v}"));
            let kb =
                |v: Option<u64>| v.map_or("-".to_owned(), |v| format!("{:.1}", v as f64 / 1024.0));
            let _ = writeln!(
                s,
                "hub pid {}: RSS MB before {} idle {} loaded {}; {} kB per connection; CPU % idle {} loaded {}",
                h.pid,
                kb(h.rss_before_kb),
                kb(h.rss_idle_kb),
                kb(h.rss_loaded_kb),
                opt(h.kb_per_connection),
                opt(h.cpu_idle_pct),
                opt(h.cpu_loaded_pct)
            );
        }
        let opt = |v: Option<f64>| v.map_or("-".to_owned(), |v| format!("{v}"));
        let _ = writeln!(
            s,
            "bench CPU % idle {} loaded {}",
            opt(self.bench_cpu_idle_pct),
            opt(self.bench_cpu_loaded_pct)
        );
        s
    }
}

#[cfg(test)]
mod tests {
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
