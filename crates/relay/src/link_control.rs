//! What a scheduled outbox knows about its link, and the gate that keeps bulk data from
//! queueing below the scheduler.
//!
//! Design choice: the link is accounted for *per frame written*, not per message. The
//! writer reports every frame it puts on the socket ([`LinkControl::on_written`]); the hub
//! acknowledges payload bytes in arrival order (`ACK.bytes`), so each written frame gets
//! its own round-trip sample for the estimator — a 2 MB point cloud gives one sample per
//! chunk, not one late sample for the whole cloud.
//!
//! Large frames (bulk chunks) go out only while the [`BulkGate`] has tokens: a token
//! bucket refilled at `min(pacing rate, capacity share)`. The pacing rate is the link
//! estimator's delay-based controller, which backs off as soon as frames take longer than
//! the base round trip — so what sits in the kernel and in the bottleneck's queue stays a
//! few milliseconds' worth, and a priority message waits behind at most the chunk being
//! written. Small frames are never held back by the gate (they consume its tokens, so bulk
//! yields to them): the message-level scheduler orders them, and holding them would put
//! them behind the bulk data the gate exists to delay.

use std::collections::VecDeque;

use fleetlink_qos::{LinkEstimator, Nanos};

/// Frames up to this size pass the bulk gate unconditionally.
pub const SMALL_FRAME: usize = 16 * 1024;
/// Bytes the gate lets out back to back after an idle spell, at least.
const MIN_BURST: f64 = SMALL_FRAME as f64;
/// The gate's burst, as time at its rate (above `MIN_BURST`).
const BURST_SECS: f64 = 0.005;

/// A token bucket for bulk frames.
#[derive(Debug, Clone)]
pub struct BulkGate {
    rate: f64,
    tokens: f64,
    at: Nanos,
}

impl BulkGate {
    pub fn new(rate: f64, now: Nanos) -> BulkGate {
        BulkGate {
            rate,
            tokens: burst(rate),
            at: now,
        }
    }

    fn refill(&mut self, now: Nanos) {
        let dt = now.saturating_sub(self.at).as_secs_f64();
        self.tokens = (self.tokens + dt * self.rate).min(burst(self.rate));
        self.at = self.at.max(now);
    }

    pub fn set_rate(&mut self, rate: f64, now: Nanos) {
        self.refill(now);
        self.rate = rate.max(0.0);
    }

    /// `Ok` if a bulk frame may go now, else when it may (`None`: not until the rate is
    /// raised, e.g. while the link is stalled).
    pub fn check(&mut self, now: Nanos) -> Result<(), Option<Nanos>> {
        self.refill(now);
        if self.tokens > 0.0 {
            return Ok(());
        }
        if self.rate <= 0.0 {
            return Err(None);
        }
        Err(Some(
            now + Nanos::from_secs_f64(-self.tokens / self.rate) + Nanos(1),
        ))
    }

    pub fn spend(&mut self, bytes: usize, now: Nanos) {
        self.refill(now);
        self.tokens -= bytes as f64;
    }
}

fn burst(rate: f64) -> f64 {
    (rate * BURST_SECS).max(MIN_BURST)
}

/// The link state of a scheduled outbox (see the module docs).
pub struct LinkControl {
    pub est: LinkEstimator,
    /// Bytes and write time of every frame written and not yet acknowledged, in order.
    written: VecDeque<(usize, Nanos)>,
    /// The hub's capacity share for this robot, bytes/s.
    pub share: Option<f64>,
    pub gate: BulkGate,
    /// Bytes offered by publishers since the last link report (the robot's demand).
    pub offered: u64,
    pub offered_since: Nanos,
}

impl LinkControl {
    pub fn new(est: LinkEstimator, now: Nanos) -> LinkControl {
        let rate = est.pacing_rate();
        LinkControl {
            est,
            written: VecDeque::new(),
            share: None,
            gate: BulkGate::new(rate, now),
            offered: 0,
            offered_since: now,
        }
    }

    /// A frame of `bytes` payload went onto the socket.
    pub fn on_written(&mut self, bytes: usize, now: Nanos) {
        if bytes == 0 {
            return;
        }
        self.written.push_back((bytes, now));
        self.gate.spend(bytes, now);
    }

    /// The peer acknowledged `bytes` more payload bytes, oldest first.
    pub fn on_acked_bytes(&mut self, mut bytes: u64, now: Nanos) {
        while bytes > 0 {
            let Some((len, at)) = self.written.front_mut() else {
                break;
            };
            if (*len as u64) <= bytes {
                bytes -= *len as u64;
                let (len, at) = (*len, *at);
                self.written.pop_front();
                self.est.handle_ack(len, at, now);
            } else {
                *len -= bytes as usize;
                break;
            }
        }
        self.apply(now);
    }

    /// Payload bytes written and not yet acknowledged.
    pub fn unacked_bytes(&self) -> usize {
        self.written.iter().map(|(b, _)| b).sum()
    }

    /// A new connection: nothing it carries is outstanding yet.
    pub fn reset(&mut self, now: Nanos) {
        self.written.clear();
        self.apply(now);
    }

    /// Re-derives the gate's rate from the estimator and the share.
    pub fn apply(&mut self, now: Nanos) {
        let pacing = self.est.pacing_rate();
        let rate = match self.share {
            Some(s) => pacing.min(s),
            None => pacing,
        };
        self.gate.set_rate(rate, now);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fleetlink_qos::LinkConfig;

    #[test]
    fn the_gate_paces_bulk_at_its_rate_after_a_burst() {
        let mut g = BulkGate::new(1_000_000.0, Nanos::ZERO);
        // A full burst goes at once.
        assert!(g.check(Nanos::ZERO).is_ok());
        g.spend(16 * 1024, Nanos::ZERO);
        // Then it waits as long as the overdraft takes to refill at 1 MB/s.
        let wake = g.check(Nanos::ZERO).unwrap_err().unwrap();
        assert!(wake <= Nanos::from_micros(400), "{wake:?}");
        g.spend(100_000, Nanos::ZERO);
        let wake = g.check(Nanos::ZERO).unwrap_err().unwrap();
        assert!(
            wake >= Nanos::from_millis(100) && wake <= Nanos::from_millis(101),
            "{wake:?}"
        );
        assert!(g.check(wake).is_ok());
    }

    #[test]
    fn a_stopped_gate_names_no_wake_time() {
        let mut g = BulkGate::new(0.0, Nanos::ZERO);
        g.spend(1, Nanos::ZERO);
        g.spend(MIN_BURST as usize, Nanos::ZERO);
        assert_eq!(g.check(Nanos::from_secs(5)), Err(None));
    }

    #[test]
    fn acknowledged_bytes_retire_written_frames_in_order_across_partial_acks() {
        let mut c = LinkControl::new(LinkEstimator::new(LinkConfig::default()), Nanos::ZERO);
        c.on_written(1000, Nanos::ZERO);
        c.on_written(500, Nanos::from_millis(1));
        c.on_acked_bytes(600, Nanos::from_millis(10));
        assert_eq!(c.unacked_bytes(), 900);
        c.on_acked_bytes(400, Nanos::from_millis(11));
        assert_eq!(c.unacked_bytes(), 500);
        c.on_acked_bytes(10_000, Nanos::from_millis(12));
        assert_eq!(c.unacked_bytes(), 0);
        // Round trips were measured per frame.
        assert!(c.est.rtt().is_some());
        c.on_written(10, Nanos::from_millis(20));
        c.reset(Nanos::from_millis(21));
        assert_eq!(c.unacked_bytes(), 0);
    }

    #[test]
    fn the_share_caps_the_gate_below_the_pacing_rate() {
        let mut c = LinkControl::new(LinkEstimator::new(LinkConfig::default()), Nanos::ZERO);
        c.share = Some(10_000.0);
        c.apply(Nanos::ZERO);
        c.gate.spend(1_000_000, Nanos::ZERO);
        let wake = c.gate.check(Nanos::ZERO).unwrap_err().unwrap();
        assert!(wake >= Nanos::from_secs(90), "{wake:?}");
    }
}
