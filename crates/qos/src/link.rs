//! Link estimation (Cloudroid Swarm, Algorithm 1, plus passive measurement): how fast and
//! how late the link to the hub is, the clock offset to the hub, and a pacing rate.
//!
//! Active part: while data waits or is unacknowledged, and until the first answer after
//! the estimator starts, a fixed-size echo probe is emitted every `probe_interval` (T =
//! 200 ms; [`LinkEstimator::poll_probe`]); the hub echoes it with its own clock reading
//! ([`LinkEstimator::handle_echo`]). An idle link is not probed: the heartbeat's own echoes
//! ([`LinkEstimator::handle_heartbeat_echo`]) keep its round trip and clock offset
//! current, and [`LinkEstimator::measured_at`] tells how old the rest of the estimate is.
//! Passive part: every acknowledged data frame reports its size and send time
//! ([`LinkEstimator::handle_ack`]). All feed a sliding window W, giving the rate R(t)
//! (bytes delivered per second in the window, probes included), the latency lat(t) (half
//! the mean echo round trip; from acknowledged frames when no echo came back; the last
//! echo's when the window holds none) and the clock offset (NTP-style, from the echo with
//! the smallest round trip in the window: the least queued one is the least skewed; the
//! last echo's when the window holds none).
//!
//! Pacing: a delay-based controller turns the passive samples into a sending rate that
//! keeps the link's queue short ([`LinkEstimator::pacing_rate`]): slow start (×1.25 per
//! round trip) until the first sign of queueing, then +2 % per round trip (growth is
//! withheld for a 50 ms slot whose smallest round trip shows queueing); when one
//! acknowledged frame's round trip, less its own serialization, exceeds the base round
//! trip by more than max(10 ms, base/8), the rate drops at once to the delivered rate
//! (last 100 ms) times
//! `1 − queue delay / base round trip`, kept within 0.5..0.9, which drains the standing
//! queue in about one round trip (at most once per round trip).
//! While no probe has been answered for max(3 × base round trip, 250 ms) the link is
//! *stalled* (a blackout) and the pacing rate is zero, so the robot stops stuffing a dead
//! link; the first answer resumes the previous rate, and round trips of frames sent
//! before that are not taken as queueing. The agent sends at `min(capacity share,
//! pacing rate)`.
//!
//! Design choice: acknowledgements are aggregated into fixed 50 ms slots (a ring sized by
//! W), so memory and cost per frame stay constant however many frames are acknowledged.

use std::collections::VecDeque;

use crate::time::Nanos;

#[derive(Debug, Clone)]
pub struct LinkConfig {
    /// T: time between echo probes.
    pub probe_interval: Nanos,
    /// Bytes of payload of each probe.
    pub probe_size: usize,
    /// W: width of the sliding window.
    pub window: Nanos,
    /// Horizon of the base (minimum) round-trip estimate.
    pub base_rtt_horizon: Nanos,
    /// Pacing rate before any measurement, bytes/s.
    pub initial_rate: f64,
    /// Pacing never goes below this, bytes/s.
    pub min_rate: f64,
    /// Pacing never goes above this, bytes/s.
    pub max_rate: f64,
}

impl Default for LinkConfig {
    fn default() -> Self {
        LinkConfig {
            probe_interval: Nanos::from_millis(200),
            probe_size: 64,
            window: Nanos::from_secs(2),
            base_rtt_horizon: Nanos::from_secs(30),
            initial_rate: 125_000.0,
            min_rate: 16_000.0,
            max_rate: 1.25e9,
        }
    }
}

/// An echo probe to send now; the hub returns `id` with its clock reading.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Probe {
    pub id: u64,
    pub size: usize,
}

const SLOT: Nanos = Nanos::from_millis(50);

/// Queueing delay above which the pacer backs off: max(10 ms, base round trip / 8).
fn queue_target(base: Nanos) -> Nanos {
    Nanos::from_millis(10).max(Nanos(base.0 / 8))
}

#[derive(Debug, Clone, Copy, Default)]
struct Slot {
    /// Slot number (time / SLOT).
    n: u64,
    bytes: u64,
    rtt_min: Option<Nanos>,
    rtt_sum: u64,
    rtt_count: u32,
}

#[derive(Debug, Clone, Copy)]
struct Echo {
    at: Nanos,
    rtt: Nanos,
    /// Remote clock minus local clock, ns.
    offset: i64,
}

#[derive(Debug, Clone)]
struct Pacer {
    rate: f64,
    slow_start: bool,
    hold_until: Nanos,
}

/// Sliding-window link estimator (see the module docs).
#[derive(Debug, Clone)]
pub struct LinkEstimator {
    config: LinkConfig,
    next_probe: Option<Nanos>,
    next_id: u64,
    outstanding: VecDeque<(u64, Nanos)>,
    echoes: VecDeque<Echo>,
    slots: VecDeque<Slot>,
    /// Per-slot minimum round trips over `base_rtt_horizon`, for the base round trip.
    rtt_mins: VecDeque<(u64, Nanos)>,
    pacer: Pacer,
    now: Nanos,
    started: Option<Nanos>,
    /// Send time of the oldest probe with no answer (echo or ack) heard since.
    unanswered_since: Option<Nanos>,
    /// The latest echo (probe or heartbeat), kept when the window no longer holds it.
    last_echo: Option<Echo>,
    /// When the latest sample (an echo or an acknowledged frame) came in.
    last_sample: Option<Nanos>,
    /// Frames sent before this instant crossed a stall; their round trips are not used.
    stall_ended: Nanos,
}

impl LinkEstimator {
    pub fn new(config: LinkConfig) -> Self {
        let slots = (config.window.0 / SLOT.0 + 2) as usize;
        let probes = (config.window.0 / config.probe_interval.0.max(1) + 2) as usize;
        LinkEstimator {
            pacer: Pacer {
                rate: config.initial_rate,
                slow_start: true,
                hold_until: Nanos::ZERO,
            },
            next_probe: None,
            next_id: 0,
            outstanding: VecDeque::with_capacity(probes),
            echoes: VecDeque::with_capacity(probes),
            slots: VecDeque::with_capacity(slots),
            rtt_mins: VecDeque::with_capacity((config.base_rtt_horizon.0 / SLOT.0 + 2) as usize),
            now: Nanos::ZERO,
            started: None,
            unanswered_since: None,
            last_echo: None,
            last_sample: None,
            stall_ended: Nanos::ZERO,
            config,
        }
    }

    /// A probe to send now: every `probe_interval` while the link is `busy` (data waits
    /// or is unacknowledged) and until the first echo; never on an idle link that has been
    /// measured (see the module docs).
    pub fn poll_probe(&mut self, now: Nanos, busy: bool) -> Option<Probe> {
        self.advance(now);
        if !self.wants_probes(busy) || self.next_probe.is_some_and(|t| now < t) {
            return None;
        }
        let interval = self.config.probe_interval;
        self.next_probe = Some(match self.next_probe {
            Some(t) if now < t + interval => t + interval,
            _ => now + interval,
        });
        let id = self.next_id;
        self.next_id += 1;
        if self.outstanding.len() == self.outstanding.capacity() {
            self.outstanding.pop_front(); // never echoed: lost
        }
        self.outstanding.push_back((id, now));
        self.unanswered_since.get_or_insert(now);
        Some(Probe {
            id,
            size: self.config.probe_size,
        })
    }

    /// When the next probe is due (see [`Self::poll_probe`]); `None` while none will be.
    pub fn poll_timeout(&self, busy: bool) -> Option<Nanos> {
        self.wants_probes(busy)
            .then(|| self.next_probe.unwrap_or(self.now))
    }

    fn wants_probes(&self, busy: bool) -> bool {
        busy || self.last_echo.is_none()
    }

    /// The echo of probe `id` came back at `now`, stamped `remote_ts` by the hub's clock.
    /// Unknown or expired ids are ignored.
    pub fn handle_echo(&mut self, id: u64, remote_ts: Nanos, now: Nanos) {
        self.advance(now);
        let Some(pos) = self.outstanding.iter().position(|&(i, _)| i == id) else {
            return;
        };
        let (_, sent) = self.outstanding.remove(pos).unwrap_or((id, now));
        self.echo(sent, remote_ts, now);
    }

    /// The echo of a heartbeat `PING` (which the session sends and times itself) came
    /// back at `now` after `rtt`, stamped `remote_ts` by the hub's clock: a sample like a
    /// probe's, which is what keeps an idle link's round trip and clock offset current.
    pub fn handle_heartbeat_echo(&mut self, rtt: Nanos, remote_ts: Nanos, now: Nanos) {
        self.advance(now);
        self.echo(now.saturating_sub(rtt), remote_ts, now);
    }

    fn echo(&mut self, sent: Nanos, remote_ts: Nanos, now: Nanos) {
        let rtt = now.saturating_sub(sent);
        let midpoint = sent.0 as i128 + rtt.0 as i128 / 2;
        let offset =
            (remote_ts.0 as i128 - midpoint).clamp(i64::MIN as i128, i64::MAX as i128) as i64;
        if self.echoes.len() == self.echoes.capacity() {
            self.echoes.pop_front();
        }
        let echo = Echo {
            at: now,
            rtt,
            offset,
        };
        self.echoes.push_back(echo);
        self.last_echo = Some(echo);
        let rtt = self.heard(sent, now).then_some(rtt);
        self.record(self.config.probe_size as u64, rtt, now);
    }

    /// When the latest sample (an echo or an acknowledged frame) came in: how old the
    /// estimate is on a link that has been idle. `None` before the first.
    pub fn measured_at(&self) -> Option<Nanos> {
        self.last_sample
    }

    /// A data frame of `bytes`, sent at `sent_at`, was acknowledged at `now`.
    pub fn handle_ack(&mut self, bytes: usize, sent_at: Nanos, now: Nanos) {
        self.advance(now);
        let rtt = self
            .heard(sent_at, now)
            .then(|| now.saturating_sub(sent_at));
        self.record(bytes as u64, rtt, now);
    }

    /// Something sent at `sent` was answered at `now`: ends a stall. True if its round
    /// trip is meaningful (it was not sent before a stall ended).
    fn heard(&mut self, sent: Nanos, now: Nanos) -> bool {
        if self.is_stalled() {
            self.stall_ended = now;
        }
        self.unanswered_since = None;
        sent >= self.stall_ended
    }

    /// No probe answered for max(3 × base round trip, 250 ms): the link is down.
    pub fn is_stalled(&self) -> bool {
        let limit = Nanos::from_millis(250).max(Nanos(self.base_rtt().map_or(0, |r| r.0 * 3)));
        self.unanswered_since
            .is_some_and(|t| self.now.saturating_sub(t) > limit)
    }

    fn record(&mut self, bytes: u64, rtt: Option<Nanos>, now: Nanos) {
        self.last_sample = Some(now);
        if let Some(rtt) = rtt {
            self.on_rtt_sample(bytes, rtt, now);
        }
        let n = now.0 / SLOT.0;
        if self.slots.back().is_none_or(|s| s.n != n) {
            if self.slots.len() == self.slots.capacity() {
                self.slots.pop_front();
            }
            self.slots.push_back(Slot {
                n,
                ..Slot::default()
            });
        }
        let slot = self.slots.back_mut().expect("slot just ensured");
        slot.bytes += bytes;
        if let Some(rtt) = rtt {
            slot.rtt_min = Some(slot.rtt_min.map_or(rtt, |m| m.min(rtt)));
            slot.rtt_sum += rtt.0;
            slot.rtt_count += 1;
            match self.rtt_mins.back_mut() {
                Some((m, v)) if *m == n => *v = (*v).min(rtt),
                _ => {
                    if self.rtt_mins.len() == self.rtt_mins.capacity() {
                        self.rtt_mins.pop_front();
                    }
                    self.rtt_mins.push_back((n, rtt));
                }
            }
        }
    }

    /// Moves the window to `now`, and runs the pacer once per completed slot.
    fn advance(&mut self, now: Nanos) {
        self.started.get_or_insert(now);
        let prev_slot = self.now.0 / SLOT.0;
        self.now = self.now.max(now);
        let horizon = self.now.saturating_sub(self.config.window);
        while self.echoes.front().is_some_and(|e| e.at < horizon) {
            self.echoes.pop_front();
        }
        while self
            .outstanding
            .front()
            .is_some_and(|&(_, at)| at < horizon)
        {
            self.outstanding.pop_front();
        }
        let oldest_slot = horizon.0 / SLOT.0;
        while self.slots.front().is_some_and(|s| s.n < oldest_slot) {
            self.slots.pop_front();
        }
        let base_horizon = self.now.saturating_sub(self.config.base_rtt_horizon).0 / SLOT.0;
        while self
            .rtt_mins
            .front()
            .is_some_and(|&(n, _)| n < base_horizon)
        {
            self.rtt_mins.pop_front();
        }
        if self.now.0 / SLOT.0 != prev_slot {
            self.run_pacer(prev_slot);
        }
    }

    /// One control step at the end of slot `n`.
    fn run_pacer(&mut self, n: u64) {
        let (Some(base), Some(slot)) =
            (self.base_rtt(), self.slots.iter().rev().find(|s| s.n == n))
        else {
            return;
        };
        let Some(slot_min) = slot.rtt_min else { return };
        // Decreases happen per sample (`on_rtt_sample`); a slot with queueing only
        // withholds the increase.
        if slot_min.saturating_sub(base) <= queue_target(base) {
            let p = &mut self.pacer;
            // Growth per slot, so that one round trip compounds to ×1.25 or ×1.02.
            let per_rtt = SLOT.as_secs_f64() / base.as_secs_f64().max(SLOT.as_secs_f64());
            let gain: f64 = if p.slow_start { 1.25 } else { 1.02 };
            p.rate =
                (p.rate * gain.powf(per_rtt)).clamp(self.config.min_rate, self.config.max_rate);
        }
    }

    /// Reacts to one round-trip sample of a `bytes` frame at once: a slot boundary would
    /// add up to 50 ms to the one round trip the signal already lags.
    fn on_rtt_sample(&mut self, bytes: u64, rtt: Nanos, now: Nanos) {
        let Some(base) = self.base_rtt() else { return };
        let delivered = self.recent_rate(2).max(self.config.min_rate);
        // The frame's own serialization is not queueing.
        let own = Nanos::from_secs_f64(bytes as f64 / delivered);
        let queue_delay = rtt.saturating_sub(base).saturating_sub(own);
        let p = &mut self.pacer;
        if queue_delay > queue_target(base) && now >= p.hold_until {
            // Drain the standing queue within about one round trip.
            let cut =
                (1.0 - queue_delay.as_secs_f64() / base.as_secs_f64().max(1e-3)).clamp(0.5, 0.9);
            p.rate = (delivered * cut).max(self.config.min_rate);
            p.slow_start = false;
            p.hold_until = now + base;
        }
    }

    /// Bytes/s delivered over the last two completed slots (100 ms).
    pub fn recent_goodput(&self) -> f64 {
        self.recent_rate(2)
    }

    /// The bytes that may be unacknowledged at once ([`crate::Scheduler::set_window_bytes`]):
    /// the recent goodput times the base round trip, with `headroom` (e.g. 1.2), never
    /// below 16 KiB. `None` — no window — until a base round trip is known, while the link
    /// is stalled, and for two slots after a stall, when the goodput still reflects the
    /// outage rather than the link.
    pub fn window_bytes(&self, headroom: f64) -> Option<usize> {
        let base = self.base_rtt()?;
        if self.is_stalled() || self.now < self.stall_ended + Nanos(2 * SLOT.0) {
            return None;
        }
        let bdp = self.recent_goodput() * base.as_secs_f64();
        Some(((bdp * headroom) as usize).max(16 * 1024))
    }

    /// Bytes/s delivered over the last `k` completed slots.
    fn recent_rate(&self, k: u64) -> f64 {
        let last = self.now.0 / SLOT.0;
        let from = last.saturating_sub(k);
        let bytes: u64 = self
            .slots
            .iter()
            .filter(|s| s.n >= from && s.n < last)
            .map(|s| s.bytes)
            .sum();
        bytes as f64 / (k as f64 * SLOT.as_secs_f64())
    }

    /// R(t): bytes per second delivered (echoed probes and acknowledged frames) over the
    /// window, or over the time since the first event when that is shorter.
    pub fn rate(&self) -> f64 {
        let span = self
            .config
            .window
            .min(self.now.saturating_sub(self.started.unwrap_or(self.now)))
            .as_secs_f64();
        if span <= 0.0 {
            return 0.0;
        }
        self.slots.iter().map(|s| s.bytes).sum::<u64>() as f64 / span
    }

    /// lat(t): one-way latency, half the mean echo round trip in the window; from
    /// acknowledged frames when no echo is in the window; the last echo's when neither is.
    pub fn latency(&self) -> Option<Nanos> {
        self.rtt().map(|r| Nanos(r.0 / 2))
    }

    /// Mean round trip in the window (echoes preferred, see [`Self::latency`]).
    pub fn rtt(&self) -> Option<Nanos> {
        if !self.echoes.is_empty() {
            let sum: u64 = self.echoes.iter().map(|e| e.rtt.0).sum();
            return Some(Nanos(sum / self.echoes.len() as u64));
        }
        let (sum, count) = self.slots.iter().fold((0u64, 0u64), |(s, c), x| {
            (s + x.rtt_sum, c + u64::from(x.rtt_count))
        });
        sum.checked_div(count)
            .map(Nanos)
            .or(self.last_echo.map(|e| e.rtt))
    }

    /// Smallest round trip seen over the base horizon (10 s by default).
    pub fn base_rtt(&self) -> Option<Nanos> {
        self.rtt_mins.iter().map(|&(_, r)| r).min()
    }

    /// Hub clock minus robot clock, in nanoseconds, from the least-delayed echo in the
    /// window (the last echo's when the window holds none); `None` before the first echo.
    pub fn clock_offset(&self) -> Option<i64> {
        self.echoes
            .iter()
            .min_by_key(|e| e.rtt)
            .or(self.last_echo.as_ref())
            .map(|e| e.offset)
    }

    /// A local clock reading expressed on the hub's clock (to stamp messages so the hub
    /// can report end-to-end latency).
    pub fn to_remote(&self, local: Nanos) -> Option<Nanos> {
        self.clock_offset()
            .map(|o| Nanos((local.0 as i128 + o as i128).max(0) as u64))
    }

    /// Sending rate (bytes/s) that keeps the link's queue short, zero while the link is
    /// stalled (see the module docs).
    pub fn pacing_rate(&self) -> f64 {
        if self.is_stalled() {
            0.0
        } else {
            self.pacer.rate
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn probes_are_emitted_every_interval_with_fixed_size() {
        let mut est = LinkEstimator::new(LinkConfig::default());
        let mut sent = Vec::new();
        for ms in (0..1000).step_by(10) {
            if let Some(p) = est.poll_probe(Nanos::from_millis(ms), true) {
                sent.push((ms, p));
            }
        }
        let times: Vec<u64> = sent.iter().map(|(t, _)| *t).collect();
        assert_eq!(times, vec![0, 200, 400, 600, 800]);
        assert!(sent.iter().all(|(_, p)| p.size == 64));
        assert_eq!(sent[4].1.id, 4);
    }

    #[test]
    fn an_idle_measured_link_is_not_probed_and_heartbeats_keep_its_estimate() {
        let mut est = LinkEstimator::new(LinkConfig::default());
        // Until the first echo, probes go out even on an idle link: the first estimate.
        let first = est.poll_probe(Nanos::ZERO, false).expect("first probe");
        assert_eq!(est.poll_timeout(false), Some(Nanos::from_millis(200)));
        est.handle_echo(first.id, Nanos::from_secs(100), Nanos::from_millis(40));
        // Measured and idle: no probe, no timer, for as long as it stays idle.
        for ms in (200..10_000).step_by(100) {
            assert_eq!(
                est.poll_probe(Nanos::from_millis(ms), false),
                None,
                "at {ms} ms"
            );
        }
        assert_eq!(est.poll_timeout(false), None);
        // The window (2 s) holds no echo now; the last one still answers, and says how old.
        assert_eq!(est.rtt(), Some(Nanos::from_millis(40)));
        assert!(est.clock_offset().is_some());
        assert_eq!(est.measured_at(), Some(Nanos::from_millis(40)));
        // A heartbeat echo (50 ms round trip, hub 7 s ahead) is a sample like a probe's.
        let now = Nanos::from_secs(10);
        let remote = now.saturating_sub(Nanos::from_millis(25)) + Nanos::from_secs(7);
        est.handle_heartbeat_echo(Nanos::from_millis(50), remote, now);
        assert_eq!(est.rtt(), Some(Nanos::from_millis(50)));
        assert_eq!(est.clock_offset(), Some(7_000_000_000));
        assert_eq!(est.measured_at(), Some(now));
        // Data waits: probing resumes at once, every interval while it stays busy.
        let t = now + Nanos::from_millis(10);
        assert!(est.poll_probe(t, true).is_some());
        assert_eq!(est.poll_timeout(true), Some(t + Nanos::from_millis(200)));
        assert_eq!(est.poll_probe(t + Nanos::from_millis(100), true), None);
        assert!(est.poll_probe(t + Nanos::from_millis(200), true).is_some());
    }

    #[test]
    fn idle_link_latency_and_clock_offset_come_from_echoes() {
        // One-way 30 ms each way; the hub's clock is 5 s ahead.
        let mut est = LinkEstimator::new(LinkConfig::default());
        let skew = Nanos::from_secs(5);
        for k in 0..20u64 {
            let t = Nanos::from_millis(k * 200);
            let p = est.poll_probe(t, true).expect("probe due");
            let remote = t + Nanos::from_millis(30) + skew;
            est.handle_echo(p.id, remote, t + Nanos::from_millis(60));
        }
        assert_eq!(est.latency(), Some(Nanos::from_millis(30)));
        assert_eq!(est.clock_offset(), Some(5_000_000_000));
        assert_eq!(
            est.to_remote(Nanos::from_secs(1)),
            Some(Nanos::from_secs(6))
        );
        // Only probe bytes flowed: 64 B every 200 ms.
        assert!((est.rate() - 320.0).abs() < 40.0, "{}", est.rate());
    }

    #[test]
    fn busy_link_rate_and_rtt_come_from_acknowledged_frames() {
        let mut est = LinkEstimator::new(LinkConfig::default());
        // 1,000 frames/s of 1,000 B, each acknowledged 40 ms after it was sent.
        for ms in 0..3000u64 {
            let now = Nanos::from_millis(ms);
            if ms >= 40 {
                est.handle_ack(1000, Nanos::from_millis(ms - 40), now);
            }
        }
        let r = est.rate();
        assert!((r - 1_000_000.0).abs() < 30_000.0, "{r}");
        assert_eq!(est.rtt(), Some(Nanos::from_millis(40)));
        assert_eq!(est.clock_offset(), None);
    }

    #[test]
    fn stale_and_unknown_echoes_are_ignored() {
        let mut est = LinkEstimator::new(LinkConfig::default());
        let p = est
            .poll_probe(Nanos::ZERO, true)
            .expect("first probe is due at once");
        est.handle_echo(p.id + 100, Nanos::ZERO, Nanos::from_millis(10));
        assert_eq!(est.latency(), None);
        // Echo arriving after the window: the probe was written off as lost.
        for ms in (0..5000).step_by(200) {
            let _ = est.poll_probe(Nanos::from_millis(ms), true);
        }
        est.handle_echo(p.id, Nanos::ZERO, Nanos::from_secs(5));
        assert_eq!(est.latency(), None);
    }
}
