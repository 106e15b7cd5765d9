//! Per-topic rate limiting: at most `rate_limit_hz` messages per second enter a queue.
//!
//! Design choice: a GCRA (virtual-scheduling) limiter with a tolerance of half a period.
//! The long-run rate never exceeds the limit, yet a 10 Hz source with jitter passing a
//! 10 Hz limit is not cut to 5 Hz, which a plain "minimum gap" rule would do.

use crate::time::Nanos;

#[derive(Debug, Clone)]
pub struct RateLimiter {
    period: u64,
    /// Theoretical arrival time of the next conforming message.
    tat: u64,
}

impl RateLimiter {
    /// `hz` must be finite and > 0 (checked by `TopicQos::validate`).
    pub fn new(hz: f64) -> Self {
        RateLimiter {
            period: (1e9 / hz).max(1.0) as u64,
            tat: 0,
        }
    }

    /// True if a message arriving at `now` conforms (and is counted).
    pub fn admit(&mut self, now: Nanos) -> bool {
        if now.0.saturating_add(self.period / 2) < self.tat {
            return false;
        }
        self.tat = self.tat.max(now.0).saturating_add(self.period);
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limiter_passes_a_jittery_source_at_its_own_rate_and_halves_a_double_rate_one() {
        let mut lim = RateLimiter::new(10.0);
        let jitter = [0i64, 20, -20, 10, -10];
        let passed = (0..100)
            .filter(|&i| {
                let t = i * 100_000_000 + jitter[i as usize % 5] * 1_000_000;
                lim.admit(Nanos(t.max(0) as u64))
            })
            .count();
        assert_eq!(passed, 100);

        let mut lim = RateLimiter::new(10.0);
        let passed = (0..200)
            .filter(|&i| lim.admit(Nanos(i * 50_000_000)))
            .count();
        assert!((100..=101).contains(&passed), "{passed}");
    }
}
