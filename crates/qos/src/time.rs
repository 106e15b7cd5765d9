//! Virtual time for the sans-IO cores: [`Nanos`], nanoseconds on a caller-chosen clock.
//!
//! Design choice: every core takes `now: Nanos` instead of `std::time::Instant`, so tests
//! run on virtual time (start at zero, jump by any amount) and the numbers in traces are
//! readable. A driver converts with [`Nanos::since`] from one `Instant` it took at start-up.
//! Only differences between two `Nanos` of the same clock carry meaning.

use std::ops::{Add, AddAssign};
use std::time::{Duration, Instant};

/// A point on (or a span of) a monotonic clock, in nanoseconds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Nanos(pub u64);

impl Nanos {
    pub const ZERO: Nanos = Nanos(0);
    pub const MAX: Nanos = Nanos(u64::MAX);

    pub const fn from_secs(s: u64) -> Self {
        Nanos(s * 1_000_000_000)
    }

    pub const fn from_millis(ms: u64) -> Self {
        Nanos(ms * 1_000_000)
    }

    pub const fn from_micros(us: u64) -> Self {
        Nanos(us * 1_000)
    }

    /// Seconds as a float; negative or non-finite input gives zero.
    pub fn from_secs_f64(s: f64) -> Self {
        if s.is_finite() && s > 0.0 {
            Nanos((s * 1e9).min(u64::MAX as f64) as u64)
        } else {
            Nanos(0)
        }
    }

    /// Time elapsed from `origin` to `instant` (zero if `instant` is earlier).
    pub fn since(origin: Instant, instant: Instant) -> Self {
        Nanos(
            instant
                .saturating_duration_since(origin)
                .as_nanos()
                .min(u64::MAX as u128) as u64,
        )
    }

    pub fn as_secs_f64(self) -> f64 {
        self.0 as f64 / 1e9
    }

    pub fn as_millis_f64(self) -> f64 {
        self.0 as f64 / 1e6
    }

    /// `self - earlier`, or zero when `earlier` is later (clocks never run backwards here,
    /// but a caller mixing two sources must not make us panic).
    pub fn saturating_sub(self, earlier: Nanos) -> Nanos {
        Nanos(self.0.saturating_sub(earlier.0))
    }
}

impl Add for Nanos {
    type Output = Nanos;
    fn add(self, rhs: Nanos) -> Nanos {
        Nanos(self.0.saturating_add(rhs.0))
    }
}

impl AddAssign for Nanos {
    fn add_assign(&mut self, rhs: Nanos) {
        *self = *self + rhs;
    }
}

impl From<Duration> for Nanos {
    fn from(d: Duration) -> Self {
        Nanos(d.as_nanos().min(u64::MAX as u128) as u64)
    }
}

impl From<Nanos> for Duration {
    fn from(n: Nanos) -> Self {
        Duration::from_nanos(n.0)
    }
}

impl std::fmt::Display for Nanos {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{:.3} ms", self.as_millis_f64())
    }
}
