//! Front-door limits: how long a client may take to say what it wants, how much it may
//! send, and how many connections the hub holds — in total, from one address, and still
//! handshaking.
//!
//! Design choice: every limit on *how many* is a permit, taken when a connection (or a
//! handshake) starts and moved into the task that serves it, so it comes back when that
//! task ends however it ends — no counter to forget to decrement. The total and the
//! handshakes are tokio semaphores; per-address counts live in a `std` map whose entry a
//! guard decrements on drop. A refused connection is counted per limit (exported in
//! `/metrics`) and reported in a warning at most every [`WARN_EVERY`], not once per
//! socket, so a flood cannot flood the log too.

use std::collections::HashMap;
use std::net::IpAddr;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use axum::http::StatusCode;
use tokio::sync::{OwnedSemaphorePermit, Semaphore};

/// How often at most the hub warns that it refused connections.
pub const WARN_EVERY: Duration = Duration::from_secs(10);

/// Front-door settings (`fleetlink hub` flags; defaults and reasons in docs/security.md).
#[derive(Debug, Clone)]
pub struct FrontDoor {
    /// Time to receive a whole request head, from when the hub starts waiting for it
    /// (on a keep-alive connection: from the previous response).
    pub header_timeout: Duration,
    /// An HTTP connection (not yet a WebSocket) on which nothing moves either way for
    /// this long is closed: a client that stops reading its response, a stuck exchange.
    pub idle_timeout: Duration,
    /// Time to receive a whole request body, from the request head.
    pub body_timeout: Duration,
    /// Largest request body; larger ones are answered 413.
    pub max_body: u64,
    /// Time for a TLS handshake, including any wait for an admission slot.
    pub tls_handshake_timeout: Duration,
    /// Connections open at once, all addresses together.
    pub max_connections: usize,
    /// Connections open at once from one client address.
    pub max_connections_per_ip: usize,
    /// TLS handshakes and WebSocket upgrades (agents until their HELLO is answered) in
    /// progress at once; above it upgrades get 503 with `Retry-After`.
    pub max_handshakes: usize,
}

impl Default for FrontDoor {
    fn default() -> FrontDoor {
        FrontDoor {
            header_timeout: Duration::from_secs(10),
            idle_timeout: Duration::from_secs(60),
            body_timeout: Duration::from_secs(30),
            max_body: 1 << 20,
            tls_handshake_timeout: Duration::from_secs(10),
            max_connections: 20_000,
            max_connections_per_ip: 2_000,
            max_handshakes: 256,
        }
    }
}

/// Which limit refused a connection.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refusal {
    /// `max_connections` reached.
    Total,
    /// `max_connections_per_ip` reached for this address.
    PerIp,
    /// `max_handshakes` reached.
    Handshakes,
}

impl Refusal {
    pub const ALL: [Refusal; 3] = [Refusal::Total, Refusal::PerIp, Refusal::Handshakes];

    /// The metric label.
    pub fn as_str(self) -> &'static str {
        match self {
            Refusal::Total => "total",
            Refusal::PerIp => "per_ip",
            Refusal::Handshakes => "handshakes",
        }
    }

    /// The `fleetlink hub` flag that raises this limit.
    pub fn flag(self) -> &'static str {
        match self {
            Refusal::Total => "--max-connections",
            Refusal::PerIp => "--max-connections-per-ip",
            Refusal::Handshakes => "--max-handshakes",
        }
    }

    /// 429 when one address asks too much, 503 when the hub as a whole is full.
    pub fn status(self) -> StatusCode {
        match self {
            Refusal::PerIp => StatusCode::TOO_MANY_REQUESTS,
            Refusal::Total | Refusal::Handshakes => StatusCode::SERVICE_UNAVAILABLE,
        }
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// The live counts behind [`FrontDoor`]'s limits, shared by every connection task.
pub struct Limits {
    pub cfg: FrontDoor,
    total: Arc<Semaphore>,
    handshakes: Arc<Semaphore>,
    /// Refusal answers being written; beyond this many a refused socket is just closed,
    /// so answering a flood costs a bounded amount.
    refusing: Arc<Semaphore>,
    // std Mutex: each use bumps or drops one count and never awaits; contention is one
    // short critical section per connection opened or closed.
    per_ip: Arc<Mutex<HashMap<IpAddr, usize>>>,
    refused: [AtomicU64; Refusal::ALL.len()],
    bodies_too_large: AtomicU64,
    bodies_timed_out: AtomicU64,
    // std Mutex: taken only on a refusal, for a few arithmetic operations.
    warn: Mutex<WarnState>,
}

/// Refusals not yet reported in a warning.
#[derive(Default)]
struct WarnState {
    last: Option<Instant>,
    pending: [u64; Refusal::ALL.len()],
}

/// Simultaneous refusal answers at most (see [`Limits::refusing`]).
const MAX_REFUSING: usize = 64;

/// One open connection's share of the total and of its address's count; both come back
/// when this is dropped.
pub struct ConnPermit {
    _total: OwnedSemaphorePermit,
    _ip: IpCount,
}

/// Decrements one address's count on drop (and forgets the address at zero).
struct IpCount {
    ip: IpAddr,
    map: Arc<Mutex<HashMap<IpAddr, usize>>>,
}

impl Drop for IpCount {
    fn drop(&mut self) {
        let mut map = self.map.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(n) = map.get_mut(&self.ip) {
            *n -= 1;
            if *n == 0 {
                map.remove(&self.ip);
            }
        }
    }
}

/// A handshake in progress; dropping it admits the next.
pub struct HandshakePermit {
    _permit: OwnedSemaphorePermit,
}

/// A slot for writing one refusal answer.
pub struct RefusalPermit {
    _permit: OwnedSemaphorePermit,
}

impl Limits {
    pub fn new(cfg: FrontDoor) -> Limits {
        let permits = |n: usize| Arc::new(Semaphore::new(n.clamp(1, Semaphore::MAX_PERMITS)));
        Limits {
            total: permits(cfg.max_connections),
            handshakes: permits(cfg.max_handshakes),
            refusing: permits(MAX_REFUSING),
            per_ip: Default::default(),
            refused: Default::default(),
            bodies_too_large: AtomicU64::new(0),
            bodies_timed_out: AtomicU64::new(0),
            warn: Default::default(),
            cfg,
        }
    }

    /// Admits one more connection from `ip`, or says which limit is in the way.
    pub fn admit(&self, ip: IpAddr) -> Result<ConnPermit, Refusal> {
        let total = self
            .total
            .clone()
            .try_acquire_owned()
            .map_err(|_| Refusal::Total)?;
        let mut map = self.per_ip.lock().unwrap_or_else(|p| p.into_inner());
        let n = map.entry(ip).or_insert(0);
        if *n >= self.cfg.max_connections_per_ip {
            return Err(Refusal::PerIp);
        }
        *n += 1;
        drop(map);
        Ok(ConnPermit {
            _total: total,
            _ip: IpCount {
                ip,
                map: self.per_ip.clone(),
            },
        })
    }

    /// A handshake slot now, or [`Refusal::Handshakes`].
    pub fn try_handshake(&self) -> Result<HandshakePermit, Refusal> {
        self.handshakes
            .clone()
            .try_acquire_owned()
            .map(|p| HandshakePermit { _permit: p })
            .map_err(|_| Refusal::Handshakes)
    }

    /// A handshake slot, waiting for one (callers bound the wait with a timeout).
    /// `None` only if the semaphore were closed, which this type never does.
    pub async fn handshake(&self) -> Option<HandshakePermit> {
        let p = self.handshakes.clone().acquire_owned().await.ok()?;
        Some(HandshakePermit { _permit: p })
    }

    /// A slot to write a refusal answer, if fewer than a handful are being written.
    pub fn try_refusing(&self) -> Option<RefusalPermit> {
        self.refusing
            .clone()
            .try_acquire_owned()
            .ok()
            .map(|p| RefusalPermit { _permit: p })
    }

    /// Counts a refusal and warns if the last warning is old enough.
    pub fn note_refused(&self, r: Refusal) {
        self.refused[r.index()].fetch_add(1, Ordering::Relaxed);
        let mut w = self.warn.lock().unwrap_or_else(|p| p.into_inner());
        w.pending[r.index()] += 1;
        let now = Instant::now();
        if w.last.is_some_and(|t| now.duration_since(t) < WARN_EVERY) {
            return;
        }
        let parts: Vec<String> = Refusal::ALL
            .iter()
            .filter(|r| w.pending[r.index()] > 0)
            .map(|r| {
                format!(
                    "{} over the {} limit of {} ({})",
                    w.pending[r.index()],
                    r.as_str(),
                    self.limit(*r),
                    r.flag()
                )
            })
            .collect();
        tracing::warn!(
            "refused connections since the last report ({}s window): {}",
            WARN_EVERY.as_secs(),
            parts.join(", ")
        );
        w.pending = Default::default();
        w.last = Some(now);
    }

    /// The configured value of the limit behind `r`.
    pub fn limit(&self, r: Refusal) -> usize {
        match r {
            Refusal::Total => self.cfg.max_connections,
            Refusal::PerIp => self.cfg.max_connections_per_ip,
            Refusal::Handshakes => self.cfg.max_handshakes,
        }
    }

    /// Connections refused by `r` since start.
    pub fn refused(&self, r: Refusal) -> u64 {
        self.refused[r.index()].load(Ordering::Relaxed)
    }

    /// Counts a request body refused for its size (`true`) or for arriving too slowly.
    pub fn note_body(&self, too_large: bool) {
        let c = if too_large {
            &self.bodies_too_large
        } else {
            &self.bodies_timed_out
        };
        c.fetch_add(1, Ordering::Relaxed);
    }

    /// Request bodies refused since start: (too large, too slow).
    pub fn bodies_refused(&self) -> (u64, u64) {
        (
            self.bodies_too_large.load(Ordering::Relaxed),
            self.bodies_timed_out.load(Ordering::Relaxed),
        )
    }

    /// Connections open now.
    pub fn open(&self) -> usize {
        self.cfg
            .max_connections
            .saturating_sub(self.total.available_permits())
    }

    /// Handshakes in progress now.
    pub fn handshaking(&self) -> usize {
        self.cfg
            .max_handshakes
            .saturating_sub(self.handshakes.available_permits())
    }

    /// Seconds for `Retry-After` on a handshake refusal: 1 to 5, drawn per answer so a
    /// fleet refused together comes back spread over a few seconds.
    pub fn retry_after_secs(&self) -> u64 {
        use std::hash::BuildHasher;
        let draw = std::hash::RandomState::new().hash_one(Instant::now());
        1 + draw % 5
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn limits(total: usize, per_ip: usize) -> Limits {
        Limits::new(FrontDoor {
            max_connections: total,
            max_connections_per_ip: per_ip,
            max_handshakes: 1,
            ..FrontDoor::default()
        })
    }

    #[test]
    fn per_address_count_comes_back_on_drop() {
        let l = limits(10, 2);
        let ip: IpAddr = [10, 0, 0, 1].into();
        let a = l.admit(ip).unwrap();
        let _b = l.admit(ip).unwrap();
        assert_eq!(l.admit(ip).err(), Some(Refusal::PerIp));
        assert!(
            l.admit([10, 0, 0, 2].into()).is_ok(),
            "other addresses unaffected"
        );
        drop(a);
        assert!(l.admit(ip).is_ok());
        assert_eq!(l.open(), 1, "refused and dropped permits are not open");
    }

    #[test]
    fn total_limit_refuses_before_per_address() {
        let l = limits(1, 5);
        let _a = l.admit([10, 0, 0, 1].into()).unwrap();
        assert_eq!(l.admit([10, 0, 0, 2].into()).err(), Some(Refusal::Total));
    }

    #[test]
    fn handshake_slots_and_refusal_counts() {
        let l = limits(10, 10);
        let h = l.try_handshake().unwrap();
        assert_eq!(l.try_handshake().err(), Some(Refusal::Handshakes));
        assert_eq!(l.handshaking(), 1);
        drop(h);
        assert!(l.try_handshake().is_ok());
        l.note_refused(Refusal::Handshakes);
        l.note_refused(Refusal::Handshakes);
        assert_eq!(l.refused(Refusal::Handshakes), 2);
        assert_eq!(l.refused(Refusal::Total), 0);
        assert!((1..=5).contains(&l.retry_after_secs()));
    }
}
