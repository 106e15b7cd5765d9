//! The robots online now, by name, and what the hub knows of each link.
//!
//! A robot that reconnects while its old connection still looks alive (a half-open TCP
//! connection after a Wi-Fi drop) replaces it: [`Registry::insert`] hands back the old
//! entry, whose session the caller ends ([`LiveRobot::replace`]) and whose topics it
//! withdraws before the new one advertises, so a robot never appears twice.
//!
//! A leaf of the crate (it imports none of its modules): the agent sessions
//! ([`crate::agents`]) fill it, and `/rosout`, the access checks, capacity sharing and the
//! HTTP API read it, none of them through the sessions.

use std::collections::{HashMap, VecDeque};
use std::net::SocketAddr;
use std::sync::atomic::{AtomicI64, AtomicU64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::SystemTime;

use fleetlink_relay::ClientId;
use tokio::sync::Notify;
use tokio_util::sync::CancellationToken;

/// What an agent link speaks for: a robot of its own, or a mirror of another robot
/// (`HELLO.mirror`, docs/mirror.md) that acts in that robot's namespace. (A peer that is
/// a site hub shows itself later, by sending `VIA`: `LinkIn::peer_hub`.)
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LinkKind {
    Robot,
    Mirror { of: String },
}

impl LinkKind {
    /// The robot whose namespace a link named `name` acts in.
    pub fn acts_in<'a>(&'a self, name: &'a str) -> &'a str {
        match self {
            LinkKind::Robot => name,
            LinkKind::Mirror { of } => of,
        }
    }

    /// How the hub's logs name a link called `name`.
    pub fn describe(&self, name: &str) -> String {
        match self {
            LinkKind::Robot => format!("robot {name}"),
            LinkKind::Mirror { of } => format!("mirror {name} of robot {of}"),
        }
    }
}

/// A robot that is online now.
pub struct LiveRobot {
    pub name: String,
    /// What the link speaks for: the robot `name`, or a mirror (named `name`) of another
    /// robot.
    pub kind: LinkKind,
    pub client: ClientId,
    pub session: u64,
    pub addr: Option<SocketAddr>,
    pub connected_at: SystemTime,
    pub heartbeat_ms: u32,
    /// Round trip of the last ping the hub sent, in nanoseconds (0 = none yet).
    pub rtt_ns: AtomicU64,
    pub last_seen_ns: AtomicU64,
    /// From the agent's last `LINK_REPORT`: what it would send, what its link delivered
    /// (bytes/s) and its one-way latency (ns).
    pub demand_bps: AtomicU64,
    pub rate_bps: AtomicU64,
    pub latency_ns: AtomicU64,
    /// What the robot may send now, bytes/s, from the same report (0 = not known).
    pub capacity_bps: AtomicU64,
    /// When the robot's link rate was last measured with data on it, Unix ms on this
    /// hub's clock (0 = never): an idle link is not probed, so the figure ages.
    pub measured_at_ms: AtomicU64,
    /// The capacity share last sent to it (bytes/s; 0 = none).
    pub share_bps: AtomicU64,
    /// Hub clock minus robot clock, from the least-delayed of the recent heartbeats.
    clock: Mutex<ClockSync>,
    /// The current estimate from `clock` (`i64::MIN` = none yet), read per message
    /// without the lock.
    clock_offset: AtomicI64,
    /// Rung when a new capacity share is in `share_bps`: the link's driver sends it
    /// through the session (`SHARE`); shares set meanwhile coalesce into the latest.
    pub share_news: Notify,
    /// Cancelled when a newer connection of the robot replaces this one.
    replaced: CancellationToken,
    /// From the agent's last `BUDGET`, if the robot has a data budget.
    pub budget: Mutex<Option<RobotBudget>>,
}

/// A robot's data budget as its agent last reported it.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RobotBudget {
    /// The rate limit and the daily allowance, bytes (per second, per day), if set.
    pub max_bps: Option<u64>,
    pub day_bytes: Option<u64>,
    /// Bytes counted against the budget since the agent set it, and the rate at which
    /// they grew between the last two reports (bytes/s).
    pub used_bytes: u64,
    pub use_bps: f64,
    /// Hub topic names the budget held back lately.
    pub thinned: Vec<String>,
    /// When this report came (unix ns).
    pub at_ns: u64,
}

impl RobotBudget {
    /// `next` (what the agent reports now) with the rate since this one.
    pub fn then(&self, mut next: RobotBudget) -> RobotBudget {
        let dt = next.at_ns.saturating_sub(self.at_ns) as f64 / 1e9;
        if dt > 0.2 && next.used_bytes >= self.used_bytes {
            let now = (next.used_bytes - self.used_bytes) as f64 / dt;
            // Smoothed over a few reports, as the dashboard shows it.
            next.use_bps = if self.use_bps == 0.0 {
                now
            } else {
                self.use_bps + (now - self.use_bps) / 4.0
            };
        } else {
            next.use_bps = self.use_bps;
        }
        next
    }
}

/// Clock offset from ping/pong exchanges, NTP style: each exchange bounds the offset
/// within its round trip; the exchange with the shortest round trip among the recent
/// ones gives the tightest estimate.
#[derive(Default)]
struct ClockSync {
    samples: VecDeque<(u64, i64)>,
}

const CLOCK_SAMPLES: usize = 16;

/// What a new [`LiveRobot`] starts from.
pub struct LiveLink {
    pub name: String,
    pub kind: LinkKind,
    pub client: ClientId,
    pub session: u64,
    pub addr: Option<SocketAddr>,
    pub heartbeat_ms: u32,
    pub replaced: CancellationToken,
}

impl LiveRobot {
    pub fn new(l: LiveLink) -> LiveRobot {
        LiveRobot {
            name: l.name,
            kind: l.kind,
            client: l.client,
            session: l.session,
            addr: l.addr,
            connected_at: SystemTime::now(),
            heartbeat_ms: l.heartbeat_ms,
            rtt_ns: AtomicU64::new(0),
            last_seen_ns: AtomicU64::new(fleetlink_relay::unix_nanos()),
            demand_bps: AtomicU64::new(0),
            rate_bps: AtomicU64::new(0),
            latency_ns: AtomicU64::new(0),
            capacity_bps: AtomicU64::new(0),
            measured_at_ms: AtomicU64::new(0),
            share_bps: AtomicU64::new(0),
            clock: Mutex::new(ClockSync::default()),
            clock_offset: AtomicI64::new(i64::MIN),
            share_news: Notify::new(),
            replaced: l.replaced,
            budget: Mutex::new(None),
        }
    }

    /// Hub clock minus robot clock in nanoseconds, once a heartbeat has been answered.
    pub fn clock_offset_ns(&self) -> Option<i64> {
        match self.clock_offset.load(Relaxed) {
            i64::MIN => None,
            o => Some(o),
        }
    }

    /// One ping exchange: its round trip and the offset it implies.
    pub fn on_pong(&self, rtt_ns: u64, offset_ns: i64) {
        self.rtt_ns.store(rtt_ns, Relaxed);
        let mut c = self.clock.lock().unwrap_or_else(|p| p.into_inner());
        if c.samples.len() == CLOCK_SAMPLES {
            c.samples.pop_front();
        }
        c.samples.push_back((rtt_ns, offset_ns));
        if let Some((_, best)) = c.samples.iter().min_by_key(|(rtt, _)| *rtt) {
            self.clock_offset.store(*best, Relaxed);
        }
    }

    /// Sends the robot its capacity share (bytes/s; 0 = no cap): its link's driver puts
    /// it through the session. Never blocks; a share set before the last one went out
    /// is replaced by it.
    pub fn send_share(&self, bytes_per_sec: u64) {
        self.share_bps.store(bytes_per_sec, Relaxed);
        self.share_news.notify_one();
    }

    /// Ends this connection's session: a newer one of the same robot took its place.
    pub fn replace(&self) {
        self.replaced.cancel();
    }
}

/// Robots online, by name.
#[derive(Default)]
pub struct Registry {
    // std Mutex: lookups and swaps only, never held across an await.
    robots: Mutex<HashMap<String, Arc<LiveRobot>>>,
    /// Mirrors online, by their own names (a robot's list and checks do not see them).
    mirrors: Mutex<HashMap<String, Arc<LiveRobot>>>,
    next_session: AtomicU64,
    /// Bumped whenever a robot comes or goes; watchers ([`Registry::watch`]) are woken by
    /// it instead of polling the list.
    changes: tokio::sync::watch::Sender<u64>,
}

impl Registry {
    pub fn list(&self) -> Vec<Arc<LiveRobot>> {
        let mut v: Vec<_> = self
            .robots
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .values()
            .cloned()
            .collect();
        v.sort_by(|a, b| a.name.cmp(&b.name));
        v
    }

    /// A number for a new session, unique in this hub process.
    pub fn next_session(&self) -> u64 {
        self.next_session.fetch_add(1, Relaxed) + 1
    }

    /// Lists `robot` as online; returns the entry it replaces, if the robot was online.
    /// The caller ends that entry's session.
    pub fn insert(&self, robot: Arc<LiveRobot>) -> Option<Arc<LiveRobot>> {
        let mut m = self.robots.lock().unwrap_or_else(|p| p.into_inner());
        let old = m.insert(robot.name.clone(), robot);
        drop(m);
        self.changed();
        old
    }

    /// Lists a mirror as online; returns the entry of the same name it replaces.
    pub fn insert_mirror(&self, mirror: Arc<LiveRobot>) -> Option<Arc<LiveRobot>> {
        let mut m = self.mirrors.lock().unwrap_or_else(|p| p.into_inner());
        m.insert(mirror.name.clone(), mirror)
    }

    /// Removes mirror `name` if its entry is still that of `session`.
    pub fn remove_mirror_if_session(&self, name: &str, session: u64) {
        let mut m = self.mirrors.lock().unwrap_or_else(|p| p.into_inner());
        if m.get(name).is_some_and(|r| r.session == session) {
            m.remove(name);
        }
    }

    /// The mirrors of `robot` online now, by name.
    pub fn mirrors_of(&self, robot: &str) -> Vec<Arc<LiveRobot>> {
        let m = self.mirrors.lock().unwrap_or_else(|p| p.into_inner());
        let mut v: Vec<_> = m
            .values()
            .filter(|r| matches!(&r.kind, LinkKind::Mirror { of } if of == robot))
            .cloned()
            .collect();
        v.sort_by(|a, b| a.name.cmp(&b.name));
        v
    }

    /// Changes whenever the set of robots online changes.
    pub fn generation(&self) -> u64 {
        *self.changes.borrow()
    }

    /// Wakes its holder whenever the set of robots online changes (several changes in a
    /// row may wake it once).
    pub fn watch(&self) -> tokio::sync::watch::Receiver<u64> {
        self.changes.subscribe()
    }

    fn changed(&self) {
        self.changes.send_modify(|g| *g += 1);
    }

    /// Whether a robot of this name is connected now.
    pub fn is_online(&self, name: &str) -> bool {
        self.robots
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .contains_key(name)
    }

    /// Removes `name` if its entry is still that of `session` (not a newer connection's).
    pub fn remove_if_session(&self, name: &str, session: u64) {
        let mut m = self.robots.lock().unwrap_or_else(|p| p.into_inner());
        if m.get(name).is_some_and(|r| r.session == session) {
            m.remove(name);
            drop(m);
            self.changed();
        }
    }
}
