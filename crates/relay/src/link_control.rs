//! What a scheduled outbox knows about its link, and the window that keeps bulk data from
//! queueing below the scheduler.
//!
//! Design choice: the link is accounted for *per frame written*, not per message. The
//! writer reports every frame it puts on the socket ([`LinkControl::on_written`]); the hub
//! acknowledges payload bytes in arrival order (`ACK.bytes`), so each written frame gets
//! its own round-trip sample and the delivered rate is measured chunk by chunk.
//!
//! Bulk frames (anything larger than the current chunk size) go out only while the bytes
//! written and not yet acknowledged stay under a **window** of
//!
//! ```text
//! window = max(2 × chunk, delivered rate × (base round trip + QUEUE_TARGET))
//! ```
//!
//! where the delivered rate is the best 50 ms of the last half second and `QUEUE_TARGET`
//! is 5 ms. The window is
//! clocked by acknowledgements: while the link is faster than what is sent, the base round
//! trip is all it takes and the window grows by `QUEUE_TARGET / base` each round trip;
//! when the link is the bottleneck, the window settles where about `QUEUE_TARGET` of data
//! waits in the network. A bandwidth drop shows up as a lower delivered rate within half
//! a second, a blackout as no acknowledgements (the window simply stays full). Unlike a
//! delay-triggered rate cut, nothing here collapses when round trips wobble (a busy CPU, a
//! radio retransmission): a late acknowledgement only delays the next chunk.
//!
//! Chunks are sized to the link too: about [`CHUNK_TIME`] (2 ms) of the delivered rate,
//! between 1 and 64 KiB (16 KiB until a rate is measured), so a priority message waits
//! behind at most a few milliseconds of bulk data even at 4 Mbit/s, and a fast link is
//! not cut into more pieces than it needs. Small frames are never held back (they count in the window, so
//! bulk yields to them).
//!
//! The hub's capacity share, when set, caps bulk frames further with a token bucket.

use std::collections::VecDeque;

use fleetlink_proto::frame::DEFAULT_CHUNK_SIZE;
use fleetlink_qos::{LinkEstimator, Nanos, TokenBucket};

/// Queueing delay the window allows in the network.
pub const QUEUE_TARGET: Nanos = Nanos::from_millis(5);
/// Link time one chunk should take at the delivered rate.
pub const CHUNK_TIME: Nanos = Nanos::from_millis(2);
/// Smallest chunk.
pub const MIN_CHUNK: usize = 1024;
/// Largest chunk: 2 ms at 32 MB/s and more.
pub const MAX_CHUNK: usize = 64 * 1024;
/// The chunk size before any rate is measured.
pub const FIRST_CHUNK: usize = DEFAULT_CHUNK_SIZE;
/// Delivered-rate slots: 50 ms each, the best of the last ten counts.
const SLOT: Nanos = Nanos::from_millis(50);
const SLOTS: usize = 10;
/// Base round trip assumed before one is measured.
const DEFAULT_BASE_RTT: Nanos = Nanos::from_millis(1);

/// A token bucket for bulk frames (the capacity share).
#[derive(Debug, Clone)]
pub struct ShareBucket(TokenBucket);

impl ShareBucket {
    pub fn new(rate: f64, now: Nanos) -> ShareBucket {
        ShareBucket(TokenBucket::new(rate, burst(rate), now))
    }

    /// `Ok` if a bulk frame may go now, else when it may (`None`: never at rate 0).
    pub fn check(&mut self, now: Nanos) -> Result<(), Option<Nanos>> {
        self.0.refill(now);
        if self.0.tokens() > 0.0 {
            return Ok(());
        }
        if self.0.bytes_per_sec() <= 0.0 {
            return Err(None);
        }
        Err(Some(self.0.holds_at(0.0)))
    }

    pub fn spend(&mut self, bytes: usize, now: Nanos) {
        self.0.spend(bytes as f64, now);
    }
}

fn burst(rate: f64) -> f64 {
    (rate * 0.005).max(FIRST_CHUNK as f64)
}

/// Why a bulk frame may not go now.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Hold {
    /// The window is full: wait for an acknowledgement.
    Window,
    /// The capacity share is spent until this time (`None`: a zero share).
    Share(Option<Nanos>),
}

/// The link state of a scheduled outbox (see the module docs).
pub struct LinkControl {
    pub est: LinkEstimator,
    /// Bytes and write time of every frame written and not yet acknowledged, in order.
    written: VecDeque<(usize, Nanos)>,
    unacked: usize,
    /// Acknowledged bytes per 50 ms slot: (slot number, bytes), newest last.
    delivered: VecDeque<(u64, u64)>,
    /// The hub's capacity share for this robot, bytes/s.
    pub share: Option<f64>,
    bucket: Option<ShareBucket>,
    /// Bytes offered by publishers since the last link report (the robot's demand).
    pub offered: u64,
    pub offered_since: Nanos,
    /// Data was acknowledged since the last link report: its rate measures the link.
    pub acked_since_report: bool,
    /// The link's best measured rate when data last flowed, and when (an idle link is
    /// not probed, so this is what the robot knows of its link then, and how old it is).
    pub measured: Option<(f64, Nanos)>,
}

impl LinkControl {
    pub fn new(est: LinkEstimator, now: Nanos) -> LinkControl {
        LinkControl {
            est,
            written: VecDeque::new(),
            unacked: 0,
            delivered: VecDeque::with_capacity(SLOTS + 1),
            share: None,
            bucket: None,
            offered: 0,
            offered_since: now,
            acked_since_report: false,
            measured: None,
        }
    }

    /// A frame of `bytes` payload went onto the socket.
    pub fn on_written(&mut self, bytes: usize, now: Nanos) {
        if bytes == 0 {
            return;
        }
        self.written.push_back((bytes, now));
        self.unacked += bytes;
        if let Some(b) = &mut self.bucket {
            b.spend(bytes, now);
        }
    }

    /// The peer acknowledged `bytes` more payload bytes, oldest first.
    pub fn on_acked_bytes(&mut self, bytes: u64, now: Nanos) {
        self.acked_since_report |= bytes > 0;
        let mut left = bytes;
        while left > 0 {
            let Some((len, at)) = self.written.front_mut() else {
                break;
            };
            if (*len as u64) <= left {
                left -= *len as u64;
                let (len, at) = (*len, *at);
                self.written.pop_front();
                self.unacked -= len;
                self.est.handle_ack(len, at, now);
            } else {
                *len -= left as usize;
                self.unacked -= left as usize;
                break;
            }
        }
        let slot = now.0 / SLOT.0;
        match self.delivered.back_mut() {
            Some((s, b)) if *s == slot => *b += bytes,
            _ => {
                if self.delivered.len() > SLOTS {
                    self.delivered.pop_front();
                }
                self.delivered.push_back((slot, bytes));
            }
        }
    }

    /// Payload bytes written and not yet acknowledged.
    pub fn unacked_bytes(&self) -> usize {
        self.unacked
    }

    /// Bytes/s: the best complete 50 ms slot of the last half second (0 = not measured).
    pub fn delivered_rate(&self, now: Nanos) -> f64 {
        let current = now.0 / SLOT.0;
        self.delivered
            .iter()
            .filter(|(s, _)| *s < current && current - *s <= SLOTS as u64)
            .map(|(_, b)| *b as f64 / SLOT.as_secs_f64())
            .fold(0.0, f64::max)
    }

    /// The size to cut bulk payloads into now.
    pub fn chunk_size(&self, now: Nanos) -> usize {
        let rate = self.delivered_rate(now);
        if rate <= 0.0 {
            return FIRST_CHUNK;
        }
        ((rate * CHUNK_TIME.as_secs_f64()) as usize).clamp(MIN_CHUNK, MAX_CHUNK)
    }

    /// Bytes that may be unacknowledged before bulk frames wait.
    pub fn window(&self, now: Nanos) -> usize {
        let base = self.est.base_rtt().unwrap_or(DEFAULT_BASE_RTT);
        let bdp = self.delivered_rate(now) * (base + QUEUE_TARGET).as_secs_f64();
        (bdp as usize).max(2 * self.chunk_size(now))
    }

    /// Whether a bulk frame may go now.
    pub fn bulk_check(&mut self, now: Nanos) -> Result<(), Hold> {
        if self.unacked >= self.window(now) {
            return Err(Hold::Window);
        }
        match &mut self.bucket {
            Some(b) => b.check(now).map_err(Hold::Share),
            None => Ok(()),
        }
    }

    /// A new connection: nothing it carries is outstanding yet, and the link it runs on
    /// may not be the old one's: its rate is measured afresh.
    pub fn reset(&mut self) {
        self.written.clear();
        self.unacked = 0;
        self.delivered.clear();
    }

    /// Applies a new capacity share.
    pub fn set_share(&mut self, share: Option<f64>, now: Nanos) {
        self.share = share;
        self.bucket = match (share, self.bucket.take()) {
            (Some(rate), Some(mut b)) => {
                let rate = rate.max(0.0);
                b.0.set_rate(rate, burst(rate), now);
                Some(b)
            }
            (Some(rate), None) => Some(ShareBucket::new(rate.max(0.0), now)),
            (None, _) => None,
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fleetlink_qos::LinkConfig;

    fn control() -> LinkControl {
        LinkControl::new(LinkEstimator::new(LinkConfig::default()), Nanos::ZERO)
    }

    #[test]
    fn acknowledged_bytes_retire_written_frames_in_order_across_partial_acks() {
        let mut c = control();
        c.on_written(1000, Nanos::ZERO);
        c.on_written(500, Nanos::from_millis(1));
        c.on_acked_bytes(600, Nanos::from_millis(10));
        assert_eq!(c.unacked_bytes(), 900);
        c.on_acked_bytes(400, Nanos::from_millis(11));
        assert_eq!(c.unacked_bytes(), 500);
        c.on_acked_bytes(10_000, Nanos::from_millis(12));
        assert_eq!(c.unacked_bytes(), 0);
        assert!(c.est.rtt().is_some(), "round trips are measured per frame");
        c.on_written(10, Nanos::from_millis(20));
        c.reset();
        assert_eq!(c.unacked_bytes(), 0);
    }

    /// Drives a link of `rate` bytes/s with `one_way` delay each way and an unbounded
    /// bottleneck queue, the sender keeping the window full of `chunk`-sized frames; returns
    /// the queueing delay at the end and the delivered rate.
    fn saturate(rate: f64, one_way: Nanos, secs: u64) -> (Nanos, f64) {
        let mut c = control();
        // Frames in the bottleneck: (bytes, time they leave it).
        let mut queue: VecDeque<(usize, Nanos)> = VecDeque::new();
        let mut acks: VecDeque<(u64, Nanos)> = VecDeque::new();
        let mut link_free = Nanos::ZERO;
        let step = Nanos::from_micros(100);
        let mut now = Nanos::ZERO;
        let mut last_delay = Nanos::ZERO;
        while now < Nanos::from_secs(secs) {
            while acks.front().is_some_and(|(_, at)| *at <= now) {
                let (b, _) = acks.pop_front().unwrap();
                c.on_acked_bytes(b, now);
            }
            while queue.front().is_some_and(|(_, at)| *at <= now) {
                let (b, at) = queue.pop_front().unwrap();
                acks.push_back((b as u64, at + one_way + one_way));
            }
            while c.bulk_check(now).is_ok() {
                let chunk = c.chunk_size(now);
                c.on_written(chunk, now);
                let start = link_free.max(now);
                link_free = start + Nanos::from_secs_f64(chunk as f64 / rate);
                last_delay = start.saturating_sub(now);
                queue.push_back((chunk, link_free));
            }
            now = Nanos(now.0 + step.0);
        }
        (last_delay, c.delivered_rate(now))
    }

    #[test]
    fn a_saturated_link_is_kept_busy_with_a_short_queue() {
        for (mbit, one_way_ms) in [(4.0, 0), (10.0, 20), (100.0, 0), (100.0, 25)] {
            let rate = mbit * 1e6 / 8.0;
            let (delay, delivered) = saturate(rate, Nanos::from_millis(one_way_ms), 3);
            assert!(
                delivered > 0.9 * rate,
                "{mbit} Mbit/s, {one_way_ms} ms: delivered {:.2} Mbit/s",
                delivered * 8.0 / 1e6
            );
            // A priority message arriving now waits behind this much: the target plus
            // about a chunk.
            assert!(
                delay <= QUEUE_TARGET + Nanos::from_millis(4),
                "{mbit} Mbit/s, {one_way_ms} ms: queue {delay:?}"
            );
        }
    }

    #[test]
    fn chunks_follow_the_delivered_rate() {
        let mut c = control();
        assert_eq!(c.chunk_size(Nanos::ZERO), FIRST_CHUNK);
        // 4 Mbit/s delivered over a full slot.
        for i in 0..50u64 {
            c.on_written(500, Nanos::from_millis(i));
            c.on_acked_bytes(500, Nanos::from_millis(i));
        }
        let now = Nanos::from_millis(60);
        assert_eq!(c.chunk_size(now), MIN_CHUNK);
        assert!(c.window(now) >= 2 * MIN_CHUNK);
    }

    #[test]
    fn a_share_caps_bulk_with_a_token_bucket() {
        let mut c = control();
        c.set_share(Some(10_000.0), Nanos::ZERO);
        assert!(c.bulk_check(Nanos::ZERO).is_ok());
        c.on_written(FIRST_CHUNK, Nanos::ZERO);
        c.on_acked_bytes(FIRST_CHUNK as u64, Nanos::ZERO);
        c.on_written(100_000, Nanos::ZERO);
        c.on_acked_bytes(100_000, Nanos::ZERO);
        match c.bulk_check(Nanos::ZERO) {
            Err(Hold::Share(Some(at))) => assert!(at >= Nanos::from_secs(9), "{at:?}"),
            other => panic!("expected the share to hold bulk back, got {other:?}"),
        }
        c.set_share(None, Nanos::ZERO);
        assert!(c.bulk_check(Nanos::ZERO).is_ok());
    }
}
