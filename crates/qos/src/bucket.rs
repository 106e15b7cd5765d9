//! A token bucket: `bytes_per_sec` flow into a bucket `depth` deep, starting full. What
//! is spent may overdraw it; the debt is paid back before the bucket holds anything
//! again. The one bucket behind the agent's data budget ([`crate::DataBudget`]: a rate
//! limit and a day's allowance) and a robot's share of its site's uplink
//! (`fleetlink_relay::link_control::ShareBucket`).

use crate::time::Nanos;

#[derive(Debug, Clone, Copy)]
pub struct TokenBucket {
    bytes_per_sec: f64,
    depth: f64,
    tokens: f64,
    at: Nanos,
}

impl TokenBucket {
    /// A full bucket.
    pub fn new(bytes_per_sec: f64, depth: f64, now: Nanos) -> TokenBucket {
        TokenBucket {
            bytes_per_sec,
            depth,
            tokens: depth,
            at: now,
        }
    }

    pub fn bytes_per_sec(&self) -> f64 {
        self.bytes_per_sec
    }

    pub fn depth(&self) -> f64 {
        self.depth
    }

    /// Tokens held at the last refill (negative: a debt).
    pub fn tokens(&self) -> f64 {
        self.tokens
    }

    /// Adds what flowed in since the last refill, up to the depth. Time never runs back.
    pub fn refill(&mut self, now: Nanos) {
        let dt = now.saturating_sub(self.at).as_secs_f64();
        self.tokens = (self.tokens + dt * self.bytes_per_sec).min(self.depth);
        self.at = self.at.max(now);
    }

    /// A new rate and depth from `now` on; what it holds stays (up to the new depth).
    pub fn set_rate(&mut self, bytes_per_sec: f64, depth: f64, now: Nanos) {
        self.refill(now);
        self.bytes_per_sec = bytes_per_sec;
        self.depth = depth;
        self.tokens = self.tokens.min(depth);
    }

    /// Takes `bytes` at `now`, into debt if need be.
    pub fn spend(&mut self, bytes: f64, now: Nanos) {
        self.refill(now);
        self.tokens -= bytes;
    }

    /// Gives back `bytes` taken that were not used after all, up to the depth.
    pub fn give_back(&mut self, bytes: f64) {
        self.tokens = (self.tokens + bytes).min(self.depth);
    }

    /// Deepens the bucket (not its tokens) so `cost` fits, within `max_depth`.
    pub fn deepen_for(&mut self, cost: f64, max_depth: f64) {
        if cost > self.depth {
            self.depth = (cost * 1.25).min(max_depth).max(self.depth);
        }
    }

    /// When the bucket holds `need` (it holds less at its last refill). At a rate of
    /// zero that is never: the caller asks only while the rate is positive.
    pub fn holds_at(&self, need: f64) -> Nanos {
        self.at + Nanos::from_secs_f64((need - self.tokens) / self.bytes_per_sec) + Nanos(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_debt_is_paid_back_before_the_bucket_holds_again() {
        let mut b = TokenBucket::new(1000.0, 500.0, Nanos::ZERO);
        b.spend(1500.0, Nanos::ZERO);
        assert_eq!(b.tokens(), -1000.0);
        // One second pays the debt; a token more needs a millisecond beyond it.
        let at = b.holds_at(1.0);
        assert!(at > Nanos::from_secs_f64(1.0) && at <= Nanos::from_secs_f64(1.002));
        b.refill(Nanos::from_secs_f64(10.0));
        assert_eq!(b.tokens(), 500.0, "never past its depth");
        b.give_back(100.0);
        assert_eq!(b.tokens(), 500.0);
        b.deepen_for(800.0, 900.0);
        assert_eq!(b.depth(), 900.0);
    }
}
