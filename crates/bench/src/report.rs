//! What `fleetlink bench relay` prints: a progress line on stderr once per second while
//! it runs, and the final summary (text, or one JSON object with `--json`).

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::Duration;

use fleetlink_relay::unix_nanos;
use hdrhistogram::Histogram;
use serde::Serialize;
use tokio_util::sync::CancellationToken;

use super::publisher::Sent;
use super::relay_args::{Args, Rate, Window};
use super::subscriber::{Shared, new_histogram};

/// The final result. Field names are the `--json` keys.
#[derive(Debug, Serialize)]
pub struct Summary {
    pub publishers: usize,
    pub subscribers: usize,
    /// Payload bytes per message.
    pub size: usize,
    /// Messages per second per publisher, or `"max"`.
    pub rate: serde_json::Value,
    pub warmup_s: f64,
    pub duration_s: f64,
    /// Messages stamped inside the window, all publishers.
    pub sent: u64,
    /// Arrivals of those messages, all subscribers (`subscribers × sent` without drops).
    pub delivered: u64,
    pub delivered_per_s: f64,
    /// Delivered payload megabytes (10^6 bytes) per second.
    pub mb_per_s: f64,
    pub latency_us: Latency,
    /// Window messages a subscriber never received.
    pub drops: u64,
}

/// Latency from the publisher's send stamp to the subscriber's receipt, microseconds.
#[derive(Debug, Serialize)]
pub struct Latency {
    pub p50: f64,
    pub p99: f64,
    pub p999: f64,
    pub max: f64,
}

impl Latency {
    pub fn of(h: &Histogram<u64>) -> Latency {
        let us = |ns: u64| (ns as f64 / 100.0).round() / 10.0;
        Latency {
            p50: us(h.value_at_quantile(0.50)),
            p99: us(h.value_at_quantile(0.99)),
            p999: us(h.value_at_quantile(0.999)),
            max: us(h.max()),
        }
    }
}

pub fn summarize(
    args: &Args,
    sent: &[Sent],
    received: &[Vec<u64>],
    shared: &[Arc<Shared>],
) -> Summary {
    let sent_total: u64 = sent.iter().map(|s| s.messages).sum();
    let mut delivered = 0u64;
    let mut drops = 0u64;
    for counts in received {
        for (p, s) in sent.iter().enumerate() {
            let got = counts.get(p).copied().unwrap_or(0);
            delivered += got;
            if s.messages > 0 {
                drops += (s.last_seq - s.first_seq + 1).saturating_sub(got);
            }
        }
    }
    let mut latency = new_histogram();
    for s in shared {
        let _ = latency.add(&*s.latency());
    }
    let per_s = delivered as f64 / args.duration;
    Summary {
        publishers: args.publishers,
        subscribers: args.subscribers,
        size: args.size,
        rate: match args.rate {
            Rate::Max => "max".into(),
            Rate::Hz(hz) => hz.into(),
        },
        warmup_s: args.warmup,
        duration_s: args.duration,
        sent: sent_total,
        delivered,
        delivered_per_s: per_s.round(),
        mb_per_s: (per_s * args.size as f64 / 1e4).round() / 100.0,
        latency_us: Latency::of(&latency),
        drops,
    }
}

impl crate::measure::Report for Summary {
    fn text(&self) -> String {
        let rate = match &self.rate {
            serde_json::Value::Number(n) => match n.as_f64() {
                Some(hz) if hz.fract() == 0.0 => format!("{hz:.0} Hz"),
                _ => format!("{n} Hz"),
            },
            v => v.as_str().unwrap_or("?").to_owned(),
        };
        let l = &self.latency_us;
        format!(
            "fleetlink bench relay: {} publisher(s) -> {} subscriber(s), {} B at {rate}, \
             {} s measured after {} s warm-up\n\
             \x20 sent       {:>14} msg\n\
             \x20 delivered  {:>14} msg  ({} msg/s, {} MB/s)\n\
             \x20 latency    p50 {} us  p99 {} us  p999 {} us  max {} us\n\
             \x20 drops      {:>14}\n",
            self.publishers,
            self.subscribers,
            self.size,
            self.duration_s,
            self.warmup_s,
            self.sent,
            self.delivered,
            self.delivered_per_s,
            self.mb_per_s,
            l.p50,
            l.p99,
            l.p999,
            l.max,
            self.drops,
        )
    }
}

/// The once-per-second progress line.
pub struct Progress {
    pub subscribers: Vec<Arc<Shared>>,
    pub sent: Vec<Arc<AtomicU64>>,
    pub window: Window,
    pub started_ns: u64,
}

impl Progress {
    pub async fn run(self, stop: CancellationToken) {
        let mut tick = tokio::time::interval(Duration::from_secs(1));
        tick.tick().await;
        let mut last = (self.totals(), unix_nanos());
        loop {
            tokio::select! {
                _ = tick.tick() => {}
                _ = stop.cancelled() => return,
            }
            let now = unix_nanos();
            let t = self.totals();
            let dt = (now - last.1) as f64 * 1e-9;
            let rate = |a: u64, b: u64| (a - b) as f64 / dt;
            let phase = if now < self.window.start_ns {
                "warm-up"
            } else if now < self.window.end_ns {
                "measure"
            } else {
                "drain"
            };
            let p99 = self
                .p99_us()
                .map_or("-".to_owned(), |v| format!("{v:.0} us"));
            eprintln!(
                "[{:>5.1} s {phase:<7}] sent {:>9.0}/s  delivered {:>9.0} msg/s  {:>8.1} MB/s  p99 {p99}  gaps {}",
                (now - self.started_ns) as f64 * 1e-9,
                rate(t.sent, last.0.sent),
                rate(t.delivered, last.0.delivered),
                rate(t.bytes, last.0.bytes) / 1e6,
                t.gaps,
            );
            last = (t, now);
        }
    }

    fn totals(&self) -> Totals {
        let mut t = Totals {
            sent: self.sent.iter().map(|s| s.load(Relaxed)).sum(),
            ..Totals::default()
        };
        for s in &self.subscribers {
            t.delivered += s.delivered.load(Relaxed);
            t.bytes += s.bytes.load(Relaxed);
            t.gaps += s.gaps.load(Relaxed);
        }
        t
    }

    /// p99 of the window so far, all subscribers.
    fn p99_us(&self) -> Option<f64> {
        let mut h = new_histogram();
        for s in &self.subscribers {
            let _ = h.add(&*s.latency());
        }
        (!h.is_empty()).then(|| h.value_at_quantile(0.99) as f64 / 1e3)
    }
}

#[derive(Default, Clone, Copy)]
struct Totals {
    sent: u64,
    delivered: u64,
    bytes: u64,
    gaps: u64,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args() -> Args {
        Args {
            hub: "127.0.0.1:1".into(),
            token: String::new(),
            publishers: 2,
            subscribers: 2,
            size: 100,
            rate: Rate::Max,
            duration: 2.0,
            warmup: 1.0,
            drain: 1.0,
            queue_length: 1024,
            window: None,
            json: true,
            threads: None,
        }
    }

    #[test]
    fn drops_are_window_messages_a_subscriber_missed() {
        let sent = [
            Sent {
                messages: 10,
                first_seq: 5,
                last_seq: 14,
            },
            Sent::default(),
        ];
        // Subscriber 0 got all 10, subscriber 1 missed 3; nothing from the idle publisher.
        let received = [vec![10, 0], vec![7, 0]];
        let shared: Vec<Arc<Shared>> = (0..2).map(|_| Arc::new(Shared::new(2))).collect();
        shared[0].latency().record(1_500).expect("in range");
        let s = summarize(&args(), &sent, &received, &shared);
        assert_eq!(s.sent, 10);
        assert_eq!(s.delivered, 17);
        assert_eq!(s.drops, 3);
        assert_eq!(s.delivered_per_s, 9.0); // 17 / 2 s, rounded
        assert_eq!(s.latency_us.p50, 1.5);
        let json = serde_json::to_value(&s).expect("serializes");
        assert_eq!(json["rate"], "max");
        assert!(json["latency_us"]["p999"].is_number());
    }
}
