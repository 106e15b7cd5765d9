//! The fleet bench's result: the summary (`--json` keys) and its text, and the rounding
//! its figures share.

use serde::Serialize;

use crate::report::Latency;

/// The final result. Field names are the `--json` keys.
#[derive(Debug, Serialize)]
pub struct Summary {
    pub hubs: usize,
    pub robots: usize,
    /// Robots still connected at the end.
    pub connected: usize,
    pub topics: usize,
    pub rate: f64,
    pub size: usize,
    pub subscribers: usize,
    pub wildcard: bool,
    /// Seconds from the first connection attempt until every robot had announced.
    pub connect_s: f64,
    /// Connection attempts the hubs refused busy (503), and retries of all kinds.
    pub refused_busy: u64,
    pub retries: u64,
    pub duration_s: f64,
    /// Messages per second the robots sent in the window (all topics).
    pub sent_per_s: f64,
    /// Deliveries of window messages the subscribers should see, and saw.
    pub expected: u64,
    pub delivered: u64,
    pub delivered_per_s: f64,
    pub drops: u64,
    /// Messages missing between consecutive sequence numbers, any stamp.
    pub gaps: u64,
    pub latency_us: Option<Latency>,
    pub hub: Vec<HubFigures>,
    pub bench_cpu_idle_pct: Option<f64>,
    pub bench_cpu_loaded_pct: Option<f64>,
}

/// One hub process's figures (percent of one core).
#[derive(Debug, Serialize)]
pub struct HubFigures {
    pub pid: u32,
    pub rss_before_kb: Option<u64>,
    pub rss_idle_kb: Option<u64>,
    pub rss_loaded_kb: Option<u64>,
    /// Resident memory the connected idle fleet added, per connection (robots and
    /// subscribers) on this hub.
    pub kb_per_connection: Option<f64>,
    pub cpu_idle_pct: Option<f64>,
    pub cpu_loaded_pct: Option<f64>,
}

impl crate::measure::Report for Summary {
    fn text(&self) -> String {
        use std::fmt::Write;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "fleet: {} robots on {} hub(s), {} topics at {} Hz, {} B; {} pose subscribers{}",
            self.robots,
            self.hubs,
            self.topics,
            self.rate,
            self.size,
            self.subscribers,
            if self.wildcard { " + 1 wildcard" } else { "" }
        );
        let _ = writeln!(
            s,
            "connected {}/{} in {:.2} s ({} refused busy, {} retries)",
            self.connected, self.robots, self.connect_s, self.refused_busy, self.retries
        );
        if self.rate > 0.0 {
            let _ = writeln!(
                s,
                "in {:.0} msg/s, delivered {:.0} msg/s ({} of {} expected, {} dropped, {} gaps)",
                self.sent_per_s,
                self.delivered_per_s,
                self.delivered,
                self.expected,
                self.drops,
                self.gaps
            );
            if let Some(l) = &self.latency_us {
                let _ = writeln!(
                    s,
                    "latency µs: p50 {} p99 {} p999 {} max {}",
                    l.p50, l.p99, l.p999, l.max
                );
            }
        }
        for h in &self.hub {
            let opt = |v: Option<f64>| v.map_or("-".to_owned(), |v| format!("{v}"));
            let kb =
                |v: Option<u64>| v.map_or("-".to_owned(), |v| format!("{:.1}", v as f64 / 1024.0));
            let _ = writeln!(
                s,
                "hub pid {}: RSS MB before {} idle {} loaded {}; {} kB per connection; CPU % idle {} loaded {}",
                h.pid,
                kb(h.rss_before_kb),
                kb(h.rss_idle_kb),
                kb(h.rss_loaded_kb),
                opt(h.kb_per_connection),
                opt(h.cpu_idle_pct),
                opt(h.cpu_loaded_pct)
            );
        }
        let opt = |v: Option<f64>| v.map_or("-".to_owned(), |v| format!("{v}"));
        let _ = writeln!(
            s,
            "bench CPU % idle {} loaded {}",
            opt(self.bench_cpu_idle_pct),
            opt(self.bench_cpu_loaded_pct)
        );
        s
    }
}

/// CPU percent of one core between two readings of CPU seconds `secs` apart.
pub fn cpu_pct(a: Option<f64>, b: Option<f64>, secs: f64) -> Option<f64> {
    Some(round((b? - a?) / secs * 100.0, 1))
}

/// `x` rounded to `places` decimals.
pub fn round(x: f64, places: i32) -> f64 {
    let m = 10f64.powi(places);
    (x * m).round() / m
}
