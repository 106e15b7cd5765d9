//! The relay bench's options (`fleetlink bench relay --help`), the `--rate` they take
//! and the measurement window its publishers, subscribers and report count in. Apart
//! from `relay` so those modules need not import the subcommand that runs them.

use std::str::FromStr;

#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Hub URL, e.g. ws://127.0.0.1:8080 (a bare host:port works too).
    #[arg(long)]
    pub hub: String,
    /// An operator token of the hub's admin group (the bench opens agent links under
    /// made-up robot names). Also read from FLEETLINK_TOKEN.
    #[arg(long, env = "FLEETLINK_TOKEN", default_value = "")]
    pub token: String,
    /// Number of publisher connections, each with its own topic.
    #[arg(long, default_value_t = 1)]
    pub publishers: usize,
    /// Number of subscriber connections, each subscribed to every publisher's topic.
    #[arg(long, default_value_t = 1)]
    pub subscribers: usize,
    /// Payload size in bytes.
    #[arg(long, default_value_t = 64)]
    pub size: usize,
    /// Messages per second per publisher, or `max` to send as fast as the link takes them.
    #[arg(long, default_value = "max")]
    pub rate: Rate,
    /// Measured time in seconds (after the warm-up).
    #[arg(long, default_value_t = 5.0)]
    pub duration: f64,
    /// Seconds of sending before the measurement starts.
    #[arg(long, default_value_t = 1.0)]
    pub warmup: f64,
    /// Longest wait, in seconds, for messages still in flight when publishing stops.
    #[arg(long, default_value_t = 10.0)]
    pub drain: f64,
    /// Queue length the subscribers ask the hub for (0: the hub's default).
    #[arg(long, default_value_t = 1024)]
    pub queue_length: u32,
    /// At `--rate max`: most messages a publisher keeps in flight (sent, not yet received
    /// by every subscriber). Default: the queue length, capped at 8 MiB of payload.
    #[arg(long)]
    pub window: Option<u64>,
    /// Print the final summary as one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    /// Worker threads of the bench's runtime (default: one per core).
    #[arg(long)]
    pub threads: Option<usize>,
}

/// `--rate`: a number of messages per second, or as fast as possible.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rate {
    Max,
    Hz(f64),
}

impl FromStr for Rate {
    type Err = String;

    fn from_str(s: &str) -> Result<Rate, String> {
        if s.eq_ignore_ascii_case("max") {
            return Ok(Rate::Max);
        }
        match s.parse::<f64>() {
            Ok(hz) if hz.is_finite() && hz > 0.0 => Ok(Rate::Hz(hz)),
            _ => Err(format!(
                "expected messages per second (> 0) or `max`, got {s:?}"
            )),
        }
    }
}

/// The measurement window, in Unix nanoseconds: messages stamped in `[start, end)`.
#[derive(Debug, Clone, Copy)]
pub struct Window {
    pub start_ns: u64,
    pub end_ns: u64,
}

impl Window {
    pub fn contains(&self, stamp_ns: u64) -> bool {
        stamp_ns >= self.start_ns && stamp_ns < self.end_ns
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rate_parses_max_and_positive_numbers_only() {
        assert_eq!("max".parse::<Rate>(), Ok(Rate::Max));
        assert_eq!("MAX".parse::<Rate>(), Ok(Rate::Max));
        assert_eq!("10000".parse::<Rate>(), Ok(Rate::Hz(10000.0)));
        assert_eq!("0.5".parse::<Rate>(), Ok(Rate::Hz(0.5)));
        for bad in ["0", "-1", "inf", "NaN", "fast", ""] {
            assert!(bad.parse::<Rate>().is_err(), "{bad:?} accepted");
        }
    }

    #[test]
    fn window_is_half_open() {
        let w = Window {
            start_ns: 10,
            end_ns: 20,
        };
        assert!(!w.contains(9));
        assert!(w.contains(10));
        assert!(w.contains(19));
        assert!(!w.contains(20));
    }
}
