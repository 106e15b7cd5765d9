//! A log line of a chatty dependency, shown at most once a minute per place in its code.
//!
//! rustdds logs some conditions on every send or receive: with no multicast-capable
//! interface (an agent started before the robot's network is up) it warns about its own
//! discovery readers several times a second, each line over a kilobyte, about 5 GB a day
//! of a robot's disk. The agent cannot stop the cause from outside, and the first line
//! says what there is to say.

use std::collections::HashMap;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use tracing::{Event, Metadata};
use tracing_log::NormalizeEvent;
use tracing_subscriber::layer::{Context, Filter};

/// Passes each event of targets under `prefix` at most once per `every` for each place
/// (source file and line) that logs it; everything else passes untouched.
///
/// Decided per event as it is dispatched, so both `tracing` events and `log` records
/// (rustdds logs through `log`; they arrive through `tracing-log`, all of one level under
/// one call site, their own target, file and line in the normalized metadata) count once.
pub struct Repeats {
    prefix: &'static str,
    shown: Mutex<Shown<(String, u32)>>,
}

impl Repeats {
    pub fn new(prefix: &'static str, every: Duration) -> Repeats {
        Repeats {
            prefix,
            shown: Mutex::new(Shown {
                every,
                last: HashMap::new(),
            }),
        }
    }

    fn limited(&self, meta: &Metadata<'_>) -> bool {
        meta.target().starts_with(self.prefix)
    }
}

/// When each place last had a line shown.
struct Shown<K> {
    every: Duration,
    last: HashMap<K, Instant>,
}

impl<K: std::hash::Hash + Eq> Shown<K> {
    /// Whether a line from `site` at `now` is shown.
    fn pass(&mut self, site: K, now: Instant) -> bool {
        match self.last.get_mut(&site) {
            Some(t) if now.saturating_duration_since(*t) < self.every => false,
            Some(t) => {
                *t = now;
                true
            }
            None => {
                self.last.insert(site, now);
                true
            }
        }
    }
}

impl<S> Filter<S> for Repeats {
    fn enabled(&self, _: &Metadata<'_>, _: &Context<'_, S>) -> bool {
        // Asked more than once for one event (a `log` record is asked about before it
        // becomes an event): the decision is `event_enabled`'s.
        true
    }

    fn event_enabled(&self, event: &Event<'_>, _: &Context<'_, S>) -> bool {
        let normalized = event.normalized_metadata();
        let meta = normalized.as_ref().unwrap_or_else(|| event.metadata());
        if !self.limited(meta) {
            return true;
        }
        // Only the lines of the limited dependency get here: one small key each.
        let site = (
            meta.file().unwrap_or(meta.name()).to_owned(),
            meta.line().unwrap_or(0),
        );
        self.shown
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .pass(site, Instant::now())
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;
    use std::sync::atomic::{AtomicUsize, Ordering};

    use tracing_subscriber::layer::{Layer, SubscriberExt};

    use super::*;

    #[test]
    fn a_flood_from_one_place_in_rustdds_shows_one_line_and_nothing_else_is_held_back() {
        // rustdds logs through `log`: its records take the same road as here.
        let _ = tracing_log::LogTracer::init();
        struct Count(Arc<AtomicUsize>);
        impl<S: tracing::Subscriber> Layer<S> for Count {
            fn on_event(
                &self,
                _: &tracing::Event<'_>,
                _: tracing_subscriber::layer::Context<'_, S>,
            ) {
                self.0.fetch_add(1, Ordering::Relaxed);
            }
        }
        let seen = Arc::new(AtomicUsize::new(0));
        let subscriber = tracing_subscriber::registry().with(
            Count(seen.clone()).with_filter(Repeats::new("rustdds", Duration::from_secs(60))),
        );
        tracing::subscriber::with_default(subscriber, || {
            for i in 0..1000 {
                log::warn!(target: "rustdds::rtps::writer", "no locators for reader {i}");
            }
            for i in 0..1000 {
                tracing::warn!(target: "rustdds::rtps::writer", "no locators for reader {i}");
            }
            log::warn!(target: "rustdds::network::udp_listener", "another place");
            for i in 0..10 {
                tracing::warn!(target: "fleetlink_ros2::bridge", "ours {i}");
            }
        });
        assert_eq!(seen.load(Ordering::Relaxed), 1 + 1 + 1 + 10);
    }

    #[test]
    fn a_place_shows_a_line_again_once_the_period_is_over() {
        let mut shown = Shown {
            every: Duration::from_secs(60),
            last: HashMap::new(),
        };
        let t0 = Instant::now();
        let at = |s: u64| t0 + Duration::from_secs(s);
        assert!(shown.pass(1, at(0)));
        assert!(!shown.pass(1, at(59)));
        assert!(shown.pass(2, at(59)), "each place has its own period");
        assert!(shown.pass(1, at(61)));
        assert!(!shown.pass(1, at(62)));
        assert!(!shown.pass(1, at(120)));
        assert!(shown.pass(1, at(121)));
    }
}
