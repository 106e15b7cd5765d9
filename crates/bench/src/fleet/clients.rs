//! What the fleet's clients (robots and subscribers) share: their names and source
//! addresses, the counters they add to, the phase they follow, their connection with
//! retries and their ping period, and the [`Crew`] bundle each client task is given.

use std::net::{IpAddr, Ipv4Addr};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::Duration;

use anyhow::Context;
use tokio::sync::watch;
use tokio::time::Instant;
use tokio_util::sync::CancellationToken;

use crate::conn::{self, Busy, Conn};
use crate::relay_args::Window;

/// Robot `i`'s name.
pub fn robot_name(i: usize) -> String {
    format!("fleet_{i}")
}

/// Topic `k` of robot `i`: topic 0 is the pose.
pub fn topic_name(i: usize, k: usize) -> String {
    if k == 0 {
        format!("/fleet_{i}/pose")
    } else {
        format!("/fleet_{i}/t{k}")
    }
}

/// Robot and topic index of a fleet topic name.
pub fn parse_topic(name: &str) -> Option<(usize, usize)> {
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
pub fn source_for(url: &str, n: usize) -> Option<IpAddr> {
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
pub struct Counters {
    pub connected: AtomicU64,
    pub busy: AtomicU64,
    pub retries: AtomicU64,
    pub lost: AtomicU64,
    pub sent: AtomicU64,
    pub delivered: AtomicU64,
}

/// What the robots are told to do, shared by all of them.
#[derive(Clone, Copy)]
pub enum Phase {
    /// Connected, keeping the link alive.
    Wait,
    Publish(Schedule),
    /// No publishing (an idle run); report and keep the link alive.
    Done,
}

/// When and how fast the robots publish.
#[derive(Clone, Copy)]
pub struct Schedule {
    pub start: Instant,
    pub end: Instant,
    /// Time between two messages of one robot (its topics take turns).
    pub step: Duration,
    pub window: Window,
}

/// A robot's outcome: messages sent per topic with a stamp inside the window.
pub type RobotSent = Vec<u64>;

/// What every client task of one run shares: the admission that bounds the handshakes in
/// progress, the deadline for connecting, the counters, the phase and the stop.
#[derive(Clone)]
pub struct Crew {
    pub admission: Arc<tokio::sync::Semaphore>,
    pub deadline: Instant,
    pub counters: Arc<Counters>,
    pub schedule: watch::Receiver<Phase>,
    pub stop: CancellationToken,
}

/// Connects (from `source`), retrying refusals and failures with full-jitter exponential
/// backoff (250 ms doubling to 8 s, never sooner than a `Retry-After`) until `deadline`.
pub async fn connect_retrying(
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

/// How often a fleet client pings: once per agreed heartbeat, as the agent does (the
/// hub pings too, and declares a link dead after two heartbeats without a byte).
pub fn heartbeat_of(c: &Conn) -> Duration {
    c.keepalive * 2
}
