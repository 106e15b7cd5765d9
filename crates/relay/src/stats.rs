//! Per-topic counters, written on the publish path with relaxed atomics and read by the
//! metrics endpoint and the API. Rates come from a small ring of one-second buckets, so
//! reading a rate needs no lock and no history kept by the reader.

use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

use crate::queue::DropReason;

const BUCKETS: usize = 8;
/// Seconds averaged for a rate (complete seconds only).
const RATE_WINDOW: u64 = 5;

/// Drops recorded by any topic of this process: whoever reports drops looks at the
/// topics only when it moved (a hub of 100,000 idle topics sorted and walked them all every
/// few seconds to find none). A hint, shared by every router of the process: it may say
/// "maybe" for another router's drops, never "no" for this one's.
static DROPS_ANYWHERE: AtomicU64 = AtomicU64::new(0);

/// [`TopicStats::record_drop`]s so far, in every topic of the process.
pub fn drops_anywhere() -> u64 {
    DROPS_ANYWHERE.load(Relaxed)
}

#[derive(Default)]
struct Bucket {
    second: AtomicU64,
    messages: AtomicU64,
    bytes: AtomicU64,
}

/// No-drop flow control of a topic: set while a subscriber's no-drop queue for it is full
/// (the agent's uplink during an outage, without a durable outbox). A publisher that can
/// wait — a local rosbridge client's session — waits for room instead of having its
/// message refused; the uplink clears it as the queue drains. Lives with the counters
/// because both are the per-topic state every subscriber's slot shares.
#[derive(Default)]
pub struct NoDropFlow {
    full: std::sync::atomic::AtomicBool,
    room: tokio::sync::Notify,
}

impl NoDropFlow {
    pub fn is_full(&self) -> bool {
        self.full.load(std::sync::atomic::Ordering::Acquire)
    }

    pub fn set_full(&self) {
        self.full.store(true, std::sync::atomic::Ordering::Release);
    }

    /// There is room again: wakes every waiting publisher.
    pub fn set_room(&self) {
        if self.full.swap(false, std::sync::atomic::Ordering::AcqRel) {
            self.room.notify_waiters();
        }
    }

    /// Returns once the topic has room (at once if it has).
    pub async fn wait_room(&self) {
        loop {
            let notified = self.room.notified();
            if !self.is_full() {
                return;
            }
            notified.await;
        }
    }
}

/// What one publisher published on one topic since it last added it to the topic's
/// [`TopicStats`] ([`TopicStats::flush`]): a busy publisher then updates the shared
/// counters (five atomic additions a message) once per batch. Its owner flushes it
/// before it waits for more to publish, and at least every few dozen messages.
#[derive(Debug, Default)]
pub struct StatsBatch {
    messages: u64,
    bytes: u64,
    /// Deliveries to subscribers' queues.
    pub deliveries: u64,
    /// Of the counted messages, those that came over a robot's link: their payload bytes,
    /// and the bytes they took on the link (less, where they came compressed).
    pub link_raw: u64,
    pub link_wire: u64,
    /// The second the counted messages fall in.
    second: u64,
    last_ns: u64,
}

impl StatsBatch {
    /// Whether nothing is counted yet.
    pub fn is_empty(&self) -> bool {
        self.messages == 0 && self.deliveries == 0
    }
}

#[derive(Default)]
pub struct TopicStats {
    pub messages: AtomicU64,
    pub bytes: AtomicU64,
    /// Deliveries that reached a subscriber's queue.
    pub deliveries: AtomicU64,
    drops: [AtomicU64; DropReason::ALL.len()],
    pub last_message_ns: AtomicU64,
    /// Origin-to-hub latency of messages from robots, an exponential average (ns; 0 =
    /// not measured).
    pub latency_ns: AtomicU64,
    /// The second of the first message (+1; 0 = none yet): a young topic's rate is
    /// averaged over the seconds it has existed, not the whole window.
    first_second: AtomicU64,
    /// Made with the topic's first message: most of a large fleet's topics are idle, and
    /// 10,000 idle robots' topics held 18 MB of empty buckets.
    buckets: std::sync::OnceLock<Box<[Bucket; BUCKETS]>>,
    pub no_drop_flow: NoDropFlow,
    /// Messages a demand-driven uplink kept back because nobody wanted the topic.
    pub held_back: AtomicU64,
    /// A video topic's subscriber lost a frame and skips to the next keyframe: one is
    /// wanted from the publisher (taken by [`crate::Topic::take_keyframe_ask`]).
    pub keyframe_wanted: std::sync::atomic::AtomicBool,
    /// Payload bytes of the messages that came over a robot's link, and the bytes they
    /// took there ([`TopicStats::link_figures`]).
    link_raw: AtomicU64,
    link_wire: AtomicU64,
    /// Messages of a robot's topic its agent lost before the link, by reason, as the
    /// agent last reported them (`TOPIC_DROPS`).
    robot_drops: [AtomicU64; DropReason::ALL.len()],
    /// What the robot's agent last reported offering of it (`TOPIC_LOAD`).
    robot_offer: std::sync::Mutex<Option<RobotOffer>>,
}

/// What a robot offers of one topic and how its uplink queues it, as its agent reported
/// (`TOPIC_LOAD`), for the receive-rate prediction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RobotOffer {
    /// Messages per second its publishers offer (within the topic's rate limit).
    pub hz: f64,
    /// Payload bytes per second of those, before compression.
    pub bytes_per_sec: f64,
    pub priority: f64,
    /// Messages its uplink queue holds.
    pub queue: u32,
    pub no_drop: bool,
    /// When the hub heard it (Unix ns).
    pub at_ns: u64,
}

impl TopicStats {
    pub fn record_publish(&self, bytes: usize, now_ns: u64) {
        self.add_publishes(1, bytes as u64, now_ns);
    }

    /// `messages` published in the second of `now_ns`, `bytes` in all, the newest at
    /// `now_ns`.
    fn add_publishes(&self, messages: u64, bytes: u64, now_ns: u64) {
        self.messages.fetch_add(messages, Relaxed);
        self.bytes.fetch_add(bytes, Relaxed);
        self.last_message_ns.store(now_ns, Relaxed);
        let second = now_ns / 1_000_000_000;
        if self.first_second.load(Relaxed) == 0 {
            self.first_second.store(second + 1, Relaxed);
        }
        let buckets = self.buckets.get_or_init(Box::default);
        let b = &buckets[(second % BUCKETS as u64) as usize];
        if b.second.load(Relaxed) != second {
            // First message of a new second resets the bucket; a concurrent publisher may
            // lose one count here, which a rate display tolerates.
            b.second.store(second, Relaxed);
            b.messages.store(0, Relaxed);
            b.bytes.store(0, Relaxed);
        }
        b.messages.fetch_add(messages, Relaxed);
        b.bytes.fetch_add(bytes, Relaxed);
    }

    /// Counts one message of `bytes` published at `now_ns` in a publisher's `batch`,
    /// adding the batch to these counters first when the message falls in another second.
    pub fn batch_publish(&self, batch: &mut StatsBatch, bytes: usize, now_ns: u64) {
        let second = now_ns / 1_000_000_000;
        if batch.messages > 0 && batch.second != second {
            self.flush(batch);
        }
        batch.messages += 1;
        batch.bytes += bytes as u64;
        batch.second = second;
        batch.last_ns = now_ns;
    }

    /// Adds what `batch` counted to these counters and empties it.
    pub fn flush(&self, batch: &mut StatsBatch) {
        if batch.messages > 0 {
            self.add_publishes(batch.messages, batch.bytes, batch.last_ns);
        }
        if batch.deliveries > 0 {
            self.deliveries.fetch_add(batch.deliveries, Relaxed);
        }
        if batch.link_wire > 0 {
            self.link_raw.fetch_add(batch.link_raw, Relaxed);
            self.link_wire.fetch_add(batch.link_wire, Relaxed);
        }
        *batch = StatsBatch::default();
    }

    /// Folds one end-to-end latency sample into the average (weight 1/8).
    pub fn record_latency(&self, ns: u64) {
        let old = self.latency_ns.load(Relaxed);
        let new = if old == 0 {
            ns
        } else {
            (old as i128 + (ns as i128 - old as i128) / 8) as u64
        };
        self.latency_ns.store(new, Relaxed);
    }

    /// Bytes of the messages that came over a robot's link: as the link carried them,
    /// and their payloads (`None` when none came so). Their ratio is the compression
    /// ratio on the link.
    pub fn link_figures(&self) -> Option<(u64, u64)> {
        let wire = self.link_wire.load(Relaxed);
        (wire > 0).then(|| (wire, self.link_raw.load(Relaxed)))
    }

    pub fn record_held(&self) {
        self.held_back.fetch_add(1, Relaxed);
    }

    pub fn record_drop(&self, reason: DropReason) {
        self.drops[reason.index()].fetch_add(1, Relaxed);
        DROPS_ANYWHERE.fetch_add(1, Relaxed);
    }

    pub fn drops(&self, reason: DropReason) -> u64 {
        self.drops[reason.index()].load(Relaxed)
    }

    /// What the robot reports it lost of this topic for `reason` (a count since its agent
    /// started).
    pub fn set_robot_drops(&self, reason: DropReason, n: u64) {
        self.robot_drops[reason.index()].store(n, Relaxed);
    }

    pub fn robot_drops(&self, reason: DropReason) -> u64 {
        self.robot_drops[reason.index()].load(Relaxed)
    }

    pub fn set_robot_offer(&self, offer: RobotOffer) {
        *self.robot_offer.lock().unwrap_or_else(|p| p.into_inner()) = Some(offer);
    }

    /// The robot's last report about this topic, if it came after `since_ns`.
    pub fn robot_offer(&self, since_ns: u64) -> Option<RobotOffer> {
        let o = *self.robot_offer.lock().unwrap_or_else(|p| p.into_inner());
        o.filter(|o| o.at_ns >= since_ns)
    }

    /// Messages per second and bytes per second over the last complete seconds.
    pub fn rates(&self, now_ns: u64) -> (f64, f64) {
        let now_s = now_ns / 1_000_000_000;
        let (mut m, mut b) = (0u64, 0u64);
        let Some(buckets) = self.buckets.get() else {
            return (0.0, 0.0);
        };
        for bucket in buckets.iter() {
            let s = bucket.second.load(Relaxed);
            if s < now_s && s + RATE_WINDOW >= now_s {
                m += bucket.messages.load(Relaxed);
                b += bucket.bytes.load(Relaxed);
            }
        }
        let span = match self.first_second.load(Relaxed) {
            0 => RATE_WINDOW,
            first => now_s.saturating_sub(first - 1).clamp(1, RATE_WINDOW),
        };
        (m as f64 / span as f64, b as f64 / span as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_young_topic_is_averaged_over_the_seconds_it_has_existed() {
        let s = TopicStats::default();
        let base = 1_000 * 1_000_000_000u64;
        for sec in 0..2u64 {
            for i in 0..10u64 {
                s.record_publish(1, base + sec * 1_000_000_000 + i * 1_000_000);
            }
        }
        assert_eq!(s.rates(base + 2 * 1_000_000_000).0, 10.0);
    }

    #[test]
    fn rate_averages_complete_seconds() {
        let s = TopicStats::default();
        let base = 1_000 * 1_000_000_000u64;
        for sec in 0..6u64 {
            for i in 0..10u64 {
                s.record_publish(100, base + sec * 1_000_000_000 + i * 1_000_000);
            }
        }
        let (m, b) = s.rates(base + 6 * 1_000_000_000);
        assert_eq!(m, 10.0);
        assert_eq!(b, 1000.0);
    }
}

/// What one of the agent's adapters (ROS 1, ROS 2) tells about itself on the agent's
/// status topic: its counters, and the problems it found that a user must act on.
pub trait AdapterReport: Send + Sync {
    /// `(name, value)` of each counter, in a fixed order.
    fn counters(&self) -> Vec<(&'static str, u64)>;
    /// The distinct problems found so far (type mismatches, unknown types), oldest
    /// first, at most [`Problems::CAP`].
    fn problems(&self) -> Vec<String>;
}

/// The distinct problems an adapter found, as one line each, for its status. Bounded: the
/// oldest go when more than [`Problems::CAP`] distinct ones were seen.
#[derive(Default, Debug)]
pub struct Problems(std::sync::Mutex<std::collections::VecDeque<String>>);

impl Problems {
    pub const CAP: usize = 16;

    /// Records `text` unless it is already recorded.
    pub fn note(&self, text: &str) {
        let mut list = self.0.lock().unwrap_or_else(|p| p.into_inner());
        if list.iter().any(|t| t == text) {
            return;
        }
        if list.len() == Self::CAP {
            list.pop_front();
        }
        list.push_back(text.to_owned());
    }

    pub fn list(&self) -> Vec<String> {
        let list = self.0.lock().unwrap_or_else(|p| p.into_inner());
        list.iter().cloned().collect()
    }
}

#[cfg(test)]
mod problems_tests {
    use super::Problems;

    #[test]
    fn problems_are_kept_once_each_and_bounded() {
        let p = Problems::default();
        p.note("a");
        p.note("a");
        p.note("b");
        assert_eq!(p.list(), ["a", "b"]);
        for i in 0..Problems::CAP {
            p.note(&format!("x{i}"));
        }
        let list = p.list();
        assert_eq!(list.len(), Problems::CAP);
        assert_eq!(list[0], "x0");
        assert_eq!(list.last().map(String::as_str), Some("x15"));
    }
}
