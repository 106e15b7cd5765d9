//! A robot's data budget (`link: { budget: … }` in the agent's configuration): a cap on
//! the bytes its link may carry, as a rate (`max_kbps`) and/or a daily allowance
//! (`mb_per_day`).
//!
//! Each limit is a token bucket the link's bytes are taken from: every message the agent
//! sends, protected or not, counted when the scheduler lets it go (so one batch cannot
//! overdraw the budget) and corrected when it leaves smaller (compressed). A rate limit's
//! bucket holds a second of it (at least 64 KiB, and deeper when a message needs it, up to
//! five seconds), so the rate holds over any minute; the
//! daily allowance refills at its pace (a day's bytes spread over 86,400 s) and starts
//! with, and saves up to, an hour of it, so a robot may burst after a quiet spell but not
//! outrun the day's pace for long.
//!
//! Protected topics — no-drop ones and those of priority at or above
//! [`BudgetConfig::protect_priority`] (motion commands and emergency stops by default) —
//! always go. Under a budget the scheduler serves the highest priority that has
//! something ready first (instead of `priority × wait`), and a message of any other topic
//! goes only when it fits what the budget has left (a message larger than a bucket, when
//! the bucket is full). So what the budget allows goes to the highest priorities first,
//! and the lowest give way: rate-limited by their queues' drop policies while some bytes
//! are left for them, paused when none are. Protected traffic is never held back, even
//! when it alone exceeds the budget (the budget report says so).

use crate::bucket::TokenBucket;
use crate::time::Nanos;

/// Seconds in the day a `mb_per_day` allowance is spread over.
const DAY_SECS: f64 = 86_400.0;
/// Depth of the rate limit's bucket, in seconds of its rate ...
const RATE_BURST_SECS: f64 = 1.0;
/// ... but never less than this many bytes, so an ordinary large message fits ...
const RATE_BURST_MIN: f64 = 64.0 * 1024.0;
/// ... and deepened to fit the largest message asked for (with a quarter to spare), up to
/// this many seconds of its rate: a message larger than the bucket would overdraw it and
/// hold the next messages of higher priorities back until the overdraft is paid.
const RATE_BURST_MAX_SECS: f64 = 5.0;
/// Depth of the daily allowance's bucket, in seconds of its pace (an hour).
const DAY_BURST_SECS: f64 = 3_600.0;

/// What a message of `len` payload bytes costs on the wire, as a data plan counts it: its
/// frame header (about 16 bytes) and, per full-size segment, TCP, IP and Ethernet headers
/// (66 bytes with TCP timestamps, 1,448 bytes of data a segment). Small messages share
/// segments and WebSocket messages, so this overcounts them a little.
pub fn wire_cost(len: usize) -> usize {
    let framed = len + 16;
    framed + framed.div_ceil(1448) * 66
}

/// A data budget as configured (validated by the agent's configuration).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BudgetConfig {
    /// At most this many bytes per second on the link.
    pub max_bytes_per_sec: Option<f64>,
    /// At most this many bytes per day, at an even pace.
    pub bytes_per_day: Option<f64>,
    /// Topics of this priority or more are never held back by the budget.
    pub protect_priority: f32,
}

/// The default [`BudgetConfig::protect_priority`]: motion commands (10) and emergency
/// stops (100) keep flowing (docs/qos.md, defaults by type).
pub const DEFAULT_PROTECT_PRIORITY: f32 = 10.0;

/// What a message costing `cost` needs in `b`: all of it, or a full bucket for one
/// larger than the bucket (it then overdraws, and the bucket pays it back).
fn need(b: &TokenBucket, cost: f64) -> f64 {
    cost.min(b.depth()).max(f64::MIN_POSITIVE)
}

/// A data budget in force (see the module docs).
#[derive(Debug, Clone)]
pub struct DataBudget {
    config: BudgetConfig,
    rate: Option<TokenBucket>,
    day: Option<TokenBucket>,
    /// Bytes taken from the budget in all.
    used: u64,
    /// The cost of the message the last refusal was for.
    want: f64,
}

impl DataBudget {
    pub fn new(config: BudgetConfig, now: Nanos) -> DataBudget {
        let rate = config
            .max_bytes_per_sec
            .map(|r| TokenBucket::new(r, (r * RATE_BURST_SECS).max(RATE_BURST_MIN), now));
        let day = config.bytes_per_day.map(|d| {
            let pace = d / DAY_SECS;
            TokenBucket::new(pace, pace * DAY_BURST_SECS, now)
        });
        DataBudget {
            config,
            rate,
            day,
            used: 0,
            want: 0.0,
        }
    }

    pub fn config(&self) -> &BudgetConfig {
        &self.config
    }

    /// `bytes` left on the link at `now`.
    pub fn debit(&mut self, bytes: usize, now: Nanos) {
        self.used += bytes as u64;
        for b in [&mut self.rate, &mut self.day].into_iter().flatten() {
            b.spend(bytes as f64, now);
        }
    }

    /// `bytes` counted by [`DataBudget::debit`] that did not leave after all (a message
    /// that went compressed, smaller than it was counted).
    pub fn credit(&mut self, bytes: usize) {
        self.used = self.used.saturating_sub(bytes as u64);
        for b in [&mut self.rate, &mut self.day].into_iter().flatten() {
            b.give_back(bytes as f64);
        }
    }

    /// Whether a message of a topic that is not protected, costing `cost` bytes, may go
    /// at `now`: only when it fits what is left, so a large message of a low priority
    /// does not overdraw the budget that the next messages of higher priorities need.
    pub fn admits(&mut self, cost: usize, now: Nanos) -> bool {
        let cost = cost as f64;
        if let Some(r) = &mut self.rate {
            r.deepen_for(cost, r.bytes_per_sec() * RATE_BURST_MAX_SECS);
        }
        let ok = [&mut self.rate, &mut self.day]
            .into_iter()
            .flatten()
            .all(|b| {
                b.refill(now);
                b.tokens() >= need(b, cost)
            });
        if !ok {
            self.want = cost;
        }
        ok
    }

    /// Whether anything that is not protected may go at `now` (the budget is not spent).
    pub fn is_open(&mut self, now: Nanos) -> bool {
        self.admits(0, now)
    }

    /// When the message the budget last refused fits (call after a refusal).
    pub fn opens_at(&self) -> Option<Nanos> {
        [&self.rate, &self.day]
            .into_iter()
            .flatten()
            .filter(|b| b.tokens() < need(b, self.want))
            .map(|b| b.holds_at(need(b, self.want)))
            .max()
    }

    /// Whether a topic of `priority` is exempt (no-drop topics always are).
    pub fn protects(&self, priority: f32) -> bool {
        priority >= self.config.protect_priority
    }

    /// Bytes taken from the budget in all.
    pub fn used(&self) -> u64 {
        self.used
    }

    /// The rate the budget allows over the long run, bytes per second: the lower of the
    /// rate limit and the day's pace.
    pub fn allowed_bytes_per_sec(&self) -> f64 {
        [&self.rate, &self.day]
            .into_iter()
            .flatten()
            .map(|b| b.bytes_per_sec())
            .fold(f64::INFINITY, f64::min)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn secs(s: f64) -> Nanos {
        Nanos::from_secs_f64(s)
    }

    #[test]
    fn a_rate_limit_holds_over_a_minute() {
        let mut b = DataBudget::new(
            BudgetConfig {
                max_bytes_per_sec: Some(50_000.0),
                bytes_per_day: None,
                protect_priority: 10.0,
            },
            Nanos::ZERO,
        );
        // A sender that writes 10 kB messages whenever the budget is open, polled every
        // millisecond for a minute.
        let mut sent = 0usize;
        for ms in 0..60_000u64 {
            let now = Nanos(ms * 1_000_000);
            if b.is_open(now) {
                b.debit(10_000, now);
                sent += 10_000;
            }
        }
        let rate = sent as f64 / 60.0;
        assert!((rate - 50_000.0).abs() < 0.05 * 50_000.0, "{rate} B/s");
        assert_eq!(b.used(), sent as u64);
    }

    #[test]
    fn a_daily_allowance_lets_an_hour_of_pace_burst_then_holds_the_pace() {
        let day = 864_000_000.0; // 10 kB/s on average
        let mut b = DataBudget::new(
            BudgetConfig {
                max_bytes_per_sec: None,
                bytes_per_day: Some(day),
                protect_priority: 10.0,
            },
            Nanos::ZERO,
        );
        // An hour's pace (36 MB) may go at once ...
        b.debit(35_000_000, Nanos::ZERO);
        assert!(b.is_open(Nanos::ZERO));
        b.debit(2_000_000, Nanos::ZERO);
        assert!(!b.is_open(Nanos::ZERO));
        // ... then the budget opens again when the pace has paid the overdraft back.
        let at = b.opens_at().unwrap();
        assert!((at.as_secs_f64() - 100.0).abs() < 1.0, "{at}");
        assert!(!b.is_open(secs(99.0)));
        assert!(b.is_open(secs(101.0)));
        assert!((b.allowed_bytes_per_sec() - 10_000.0).abs() < 1e-6);
    }

    #[test]
    fn both_limits_apply_and_the_lower_rate_is_the_allowance() {
        let mut b = DataBudget::new(
            BudgetConfig {
                max_bytes_per_sec: Some(100_000.0),
                bytes_per_day: Some(864_000_000.0),
                protect_priority: 8.0,
            },
            Nanos::ZERO,
        );
        assert_eq!(b.allowed_bytes_per_sec(), 10_000.0);
        b.debit(150_000, Nanos::ZERO);
        assert!(
            !b.is_open(Nanos::ZERO),
            "the rate bucket (a second, 100 kB) is empty"
        );
        assert!(b.protects(8.0) && !b.protects(7.9));
    }

    #[test]
    fn a_message_goes_only_when_it_fits_and_one_larger_than_the_bucket_when_it_is_full() {
        let mut b = DataBudget::new(
            BudgetConfig {
                max_bytes_per_sec: Some(100_000.0),
                bytes_per_day: None,
                protect_priority: 10.0,
            },
            Nanos::ZERO,
        );
        b.debit(90_000, Nanos::ZERO); // 10 kB left
        assert!(b.admits(9_000, Nanos::ZERO));
        assert!(!b.admits(20_000, Nanos::ZERO));
        // 20 kB fit after 0.1 s more.
        let at = b.opens_at().unwrap();
        assert!((at.as_secs_f64() - 0.1).abs() < 1e-3, "{at}");
        assert!(b.admits(20_000, secs(0.1001)));
        // A 200 kB message deepens the bucket to fit it (250 kB, within 5 s of the rate),
        // and goes when that much is saved ...
        // (10 kB left at 0 s, 100 kB/s: 200 kB saved at 1.9 s).
        assert!(!b.admits(200_000, secs(0.5)));
        assert!(!b.admits(200_000, secs(1.8)));
        assert!(b.admits(200_000, secs(1.91)));
        // ... but 1 MB never fits (500 kB at most): it goes when the bucket is full.
        b.debit(200_000, secs(1.91)); // 1 kB left
        assert!(!b.admits(1_000_000, secs(5.0)));
        assert!(b.admits(1_000_000, secs(6.91)));
    }
}
