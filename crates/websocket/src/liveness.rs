//! Liveness of a WebSocket client (a rosbridge or Foxglove viewer): the server pings it,
//! and a client that shows no progress for the silence limit is taken as gone, so that
//! whatever it held (subscriptions and the demand they make, advertisements, calls and
//! goals) is released at once instead of when the kernel gives up on the socket, hours
//! later.
//!
//! The rule is the robot link's (docs/ARCHITECTURE.md, "Links going bad"): one deadline,
//! moved only by the client's own progress. Two things count as progress:
//!
//! - **bytes read from it**: any frame, the pong to the server's ping among them;
//! - **its connection draining**: a pong can sit behind megabytes the server queued
//!   before the ping, which a viewer behind a slow link takes minutes to read. While the
//!   client is overdue the driver samples its socket ([`TcpProgress`], from the kernel's
//!   `TCP_INFO`), and the client made progress when the right edge of the window it
//!   advertises (bytes acknowledged + its receive window) moved on by a fair share of
//!   what it acknowledged. A frozen process's kernel still acknowledges what fits in its
//!   receive buffer, but each acknowledgement shrinks the window by as much: the edge
//!   stands still. Only an application reading its socket moves it.
//!
//! A sample that shows progress proves the client alive at the previous sample (it read
//! some time after that), never later: a client is dropped at most the silence limit
//! after its last sign of life, never later than that plus the sampling period.
//!
//! [`Liveness`] is sans-IO (every input carries `now`) and tested on virtual time;
//! [`Watch`] drives it for a session's reader: it sends the pings through the session's
//! reply queue, samples the socket through the session's [`ProgressProbe`], and resolves
//! when the client is gone.

use std::net::SocketAddr;
use std::time::{Duration, Instant};

use bytes::Bytes;
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::Message as WsMessage;

use super::replies::Reply;

/// How often a client is pinged and how long it may show no progress.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LivenessConfig {
    /// A WebSocket ping every this long (`--viewer-ping-secs`).
    pub ping_every: Duration,
    /// A client with no progress for this long is closed (`--viewer-silence-secs`).
    pub silence: Duration,
}

impl Default for LivenessConfig {
    fn default() -> Self {
        LivenessConfig {
            ping_every: Duration::from_secs(10),
            silence: Duration::from_secs(30),
        }
    }
}

impl LivenessConfig {
    /// How often an overdue client's socket is sampled: a second, or the ping period
    /// when that is shorter.
    fn sample_every(&self) -> Duration {
        self.ping_every.min(Duration::from_secs(1))
    }
}

/// One sample of a client's TCP connection, as the kernel counts it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct TcpProgress {
    /// Bytes the client acknowledged since the connection opened.
    pub acked: u64,
    /// `acked` plus the receive window the client advertises: how far the server may
    /// send. It moves on as the client's application reads.
    pub window_end: u64,
    /// Segments with data sent to the client so far.
    pub segments: u64,
    /// The scale of the client's advertised window (its unit is `1 << window_scale`
    /// bytes).
    pub window_scale: u8,
}

impl TcpProgress {
    /// Whether the client read between `before` and `self`: its window's right edge
    /// moved on by more than rounding explains, and by at least an eighth of what it
    /// acknowledged meanwhile.
    ///
    /// Rounding: a receiver that does not read never shrinks the window it offered, and
    /// rounds it up to its unit, so each acknowledgement may move the edge by up to a
    /// unit less a byte — as far as the data it acknowledges when that is a ping's
    /// few bytes. The share: a receiver may also widen its window as data comes, before
    /// its application reads, but only up to its buffer, while an application reading
    /// its socket moves the edge as far as it acknowledges, for as long as it reads.
    pub fn progressed_since(&self, before: &TcpProgress) -> bool {
        let moved = self.window_end.saturating_sub(before.window_end);
        let acked = self.acked.saturating_sub(before.acked);
        let unit = (1u64 << self.window_scale.min(14)) - 1;
        let rounding = (self.segments.saturating_sub(before.segments) + 1).saturating_mul(unit);
        moved > rounding && moved.saturating_mul(8) >= acked
    }
}

/// Samples a client's connection; `None` when it cannot be read (the session then goes
/// by what it reads alone).
pub type ProgressProbe = Box<dyn FnMut() -> Option<TcpProgress> + Send>;

/// The client side of a session's connection, as a session needs it: its address, and
/// how to sample its socket (`None` over channels in tests).
#[derive(Default)]
pub struct Peer {
    pub addr: Option<SocketAddr>,
    pub progress: Option<ProgressProbe>,
}

impl From<Option<SocketAddr>> for Peer {
    fn from(addr: Option<SocketAddr>) -> Peer {
        Peer {
            addr,
            progress: None,
        }
    }
}

impl std::fmt::Debug for Peer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Peer")
            .field("addr", &self.addr)
            .field("progress", &self.progress.is_some())
            .finish()
    }
}

/// What is due at a [`Liveness::handle_timeout`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Due {
    /// Send a ping.
    pub ping: bool,
    /// Sample the connection and hand the sample to [`Liveness::on_sample`].
    pub sample: bool,
    /// The client showed no progress for this long, the silence limit or more: it is gone.
    pub gone: Option<Duration>,
}

/// A client's liveness: the deadline and the timers that serve it. Sans-IO.
#[derive(Debug)]
pub struct Liveness {
    cfg: LivenessConfig,
    /// The latest moment the client is known to have been alive.
    alive_at: Instant,
    next_ping: Instant,
    /// While the client is overdue: when the next sample is due, and the last one.
    sampling: Option<Sampling>,
}

#[derive(Debug)]
struct Sampling {
    next: Instant,
    last: Option<(Instant, TcpProgress)>,
}

impl Liveness {
    pub fn new(cfg: LivenessConfig, now: Instant) -> Liveness {
        Liveness {
            cfg,
            alive_at: now,
            next_ping: now + cfg.ping_every,
            sampling: None,
        }
    }

    /// Bytes were read from the client at `now`.
    pub fn on_read(&mut self, now: Instant) {
        if now > self.alive_at {
            self.alive_at = now;
        }
        self.sampling = None;
    }

    /// A sample of the connection taken at `now` (`None`: it could not be read).
    pub fn on_sample(&mut self, now: Instant, sample: Option<TcpProgress>) {
        let Some(s) = self.sampling.as_mut() else {
            return;
        };
        let Some(sample) = sample else {
            return;
        };
        if let Some((at, before)) = s.last
            && sample.progressed_since(&before)
            && at > self.alive_at
        {
            self.alive_at = at;
        }
        s.last = Some((now, sample));
    }

    /// When the client is overdue: nothing read for a ping period and a sample period,
    /// so its answer to the last ping is late.
    fn overdue_at(&self) -> Instant {
        self.alive_at + self.cfg.ping_every + self.cfg.sample_every()
    }

    /// The deadline: the silence limit after the client's last sign of life.
    pub fn deadline(&self) -> Instant {
        self.alive_at + self.cfg.silence
    }

    /// When [`Liveness::handle_timeout`] must be called next.
    pub fn poll_timeout(&self) -> Instant {
        let sample = match &self.sampling {
            Some(s) => s.next,
            None => self.overdue_at(),
        };
        self.next_ping.min(sample).min(self.deadline())
    }

    /// Acts on every timer due at `now`.
    pub fn handle_timeout(&mut self, now: Instant) -> Due {
        let mut due = Due::default();
        if now >= self.deadline() {
            due.gone = Some(now.saturating_duration_since(self.alive_at));
            return due;
        }
        if now >= self.next_ping {
            due.ping = true;
            self.next_ping = now + self.cfg.ping_every;
        }
        let every = self.cfg.sample_every();
        let overdue = now >= self.overdue_at();
        match self.sampling.as_mut() {
            Some(s) if now >= s.next => {
                due.sample = true;
                s.next = now + every;
            }
            Some(_) => {}
            None if overdue => {
                due.sample = true;
                self.sampling = Some(Sampling {
                    next: now + every,
                    last: None,
                });
            }
            None => {}
        }
        due
    }
}

/// Drives a [`Liveness`] for a session's reader: pings go into the session's reply
/// queue (none when it is full: the client is behind anyway), samples come from the
/// connection's probe.
pub struct Watch {
    live: Liveness,
    probe: Option<ProgressProbe>,
    replies: mpsc::Sender<Reply>,
    timer: crate::timer::Timer,
}

impl Watch {
    pub fn new(
        cfg: LivenessConfig,
        probe: Option<ProgressProbe>,
        replies: mpsc::Sender<Reply>,
    ) -> Watch {
        Watch {
            live: Liveness::new(cfg, now()),
            probe,
            replies,
            timer: crate::timer::Timer::default(),
        }
    }

    /// Something was read from the client just now.
    pub fn read(&mut self) {
        self.live.on_read(now());
    }

    /// Pings and samples what is due now; `Some(silent)` when the client is gone. For a
    /// reader that does not wait (a client sending without pause), between frames.
    pub fn check(&mut self) -> Option<Duration> {
        let now = now();
        if now < self.live.poll_timeout() {
            return None;
        }
        self.act(now)
    }

    fn act(&mut self, now: Instant) -> Option<Duration> {
        let due = self.live.handle_timeout(now);
        if due.gone.is_some() {
            return due.gone;
        }
        if due.ping {
            let payload = Bytes::copy_from_slice(&unix_nanos().to_be_bytes());
            let _ = self
                .replies
                .try_send(Reply::Frame(WsMessage::Ping(payload)));
        }
        if due.sample {
            let sample = self.probe.as_mut().and_then(|p| p());
            self.live.on_sample(now, sample);
        }
        None
    }

    /// Pings and samples as they fall due; resolves when the client is gone, with how
    /// long it showed no progress. Cancel-safe: a select may drop it at any await.
    pub async fn gone(&mut self) -> Duration {
        loop {
            self.timer.wait(Some(self.live.poll_timeout())).await;
            if let Some(silent) = self.act(now()) {
                return silent;
            }
        }
    }

    /// Runs `work` unless the client turns out gone first: `Err(silent)` then. For the
    /// steps of a reader that may wait on the client (a full reply queue).
    pub async fn race<F: std::future::Future>(&mut self, work: F) -> Result<F::Output, Duration> {
        tokio::select! {
            biased;
            r = work => Ok(r),
            silent = self.gone() => Err(silent),
        }
    }
}

/// The driver's clock: tokio's, so that a session under paused time sees it advance.
fn now() -> Instant {
    tokio::time::Instant::now().into_std()
}

/// Nanoseconds since the Unix epoch: a ping's payload, so its pong says when it was sent.
fn unix_nanos() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_nanos() as u64)
        .unwrap_or(0)
}

#[cfg(test)]
#[path = "liveness_tests.rs"]
mod tests;
