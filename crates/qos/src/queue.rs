//! One bounded per-topic queue with its drop policy and rate limit: [`TopicQueue`].
//!
//! Used as-is for the hub's per-subscriber queues, and inside the scheduler for each
//! topic of the agent's uplink. Design choice: a full queue is an *outcome*, not an error —
//! [`TopicQueue::push`] always returns exactly what happened ([`Push`]) and hands back the
//! item that did not make it, so the caller counts it by [`DropReason`] and no message
//! disappears silently. Items are moved, never cloned (the hub queues `Arc<Message>`).
//! The policies are an enum, not trait objects: one predictable branch per message.
//!
//! Memory follows what is queued, not the bound: a queue starts empty and grows as items
//! wait, and once a backlog has drained it lets a large buffer go
//! ([`KEEP_EMPTY_CAPACITY`]). A hub holds one queue per subscriber and topic, most of
//! them empty most of the time: with the default bound of 1,000 messages, reserving the
//! bound up front cost 8 kB per subscription before anything was sent.

use std::collections::VecDeque;

use crate::afr::{Afr, AfrPush};
use crate::config::{Policy, TopicQos};
use crate::rate_limit::RateLimiter;
pub use crate::ring::KEEP_EMPTY_CAPACITY;
use crate::ring::release_if_drained;
use crate::rng::SplitMix64;
use crate::time::Nanos;

/// Why a message was not (or is no longer) queued.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DropReason {
    /// Over the topic's `rate_limit_hz`.
    RateLimit,
    /// The drop policy chose it (`latest`, `drop_oldest`, `drop_newest`, `random`, `afr`).
    Policy,
    /// A `fifo` queue was full and the caller gave up on the item it got back.
    Backpressure,
    /// Offered for a topic the scheduler does not know.
    UnknownTopic,
}

impl DropReason {
    /// Stable label for metrics.
    pub fn as_str(self) -> &'static str {
        match self {
            DropReason::RateLimit => "rate_limit",
            DropReason::Policy => "policy",
            DropReason::Backpressure => "backpressure",
            DropReason::UnknownTopic => "unknown_topic",
        }
    }
}

/// Outcome of offering one item.
#[derive(Debug, PartialEq, Eq)]
#[must_use = "a dropped or refused item must be counted or retried"]
pub enum Push<T> {
    /// The item is queued and nothing was dropped.
    Queued,
    /// One item was dropped: either the offered one, or (for `latest`, `drop_oldest`,
    /// `random`, `afr`) an older one evicted to make room for it.
    Dropped { item: T, reason: DropReason },
    /// `fifo` queue full: the offered item is handed back; the source must wait (retry
    /// after the next `pop`) or give up and count it as [`DropReason::Backpressure`].
    Backpressure(T),
}

#[derive(Debug, Clone)]
enum Store<T> {
    /// `fifo`, `drop_oldest`, `drop_newest`: a ring; they differ only when full.
    Ring(VecDeque<T>),
    Latest(Option<T>),
    Random {
        ring: VecDeque<T>,
        rng: SplitMix64,
    },
    Afr(Afr<T>),
}

/// A bounded queue for one topic (see the module docs).
#[derive(Debug, Clone)]
pub struct TopicQueue<T> {
    store: Store<T>,
    policy: Policy,
    capacity: usize,
    limiter: Option<RateLimiter>,
}

/// Seed of the `random` policy when the caller does not choose one.
pub const DEFAULT_RANDOM_SEED: u64 = 0x5EED_F1EE_71A2_0001;

impl<T> TopicQueue<T> {
    /// A queue for an already validated `qos` (`TopicQos::validate`); a zero `queue` is
    /// treated as 1.
    pub fn new(qos: &TopicQos) -> Self {
        Self::with_seed(qos, DEFAULT_RANDOM_SEED)
    }

    /// As [`TopicQueue::new`], with the seed of the `random` policy.
    pub fn with_seed(qos: &TopicQos, seed: u64) -> Self {
        let capacity = if qos.policy == Policy::Latest {
            1
        } else {
            qos.queue.max(1)
        };
        let store = match qos.policy {
            Policy::Fifo | Policy::DropOldest | Policy::DropNewest => Store::Ring(VecDeque::new()),
            Policy::Latest => Store::Latest(None),
            Policy::Random => Store::Random {
                ring: VecDeque::new(),
                rng: SplitMix64::new(seed),
            },
            Policy::Afr => Store::Afr(Afr::new(capacity)),
        };
        TopicQueue {
            store,
            policy: qos.policy,
            capacity,
            limiter: qos.rate_limit_hz.map(RateLimiter::new),
        }
    }

    pub fn policy(&self) -> Policy {
        self.policy
    }

    pub fn capacity(&self) -> usize {
        self.capacity
    }

    pub fn len(&self) -> usize {
        match &self.store {
            Store::Ring(r) | Store::Random { ring: r, .. } => r.len(),
            Store::Latest(slot) => usize::from(slot.is_some()),
            Store::Afr(a) => a.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Offers `item` arriving at `now`.
    pub fn push(&mut self, item: T, now: Nanos) -> Push<T> {
        if let Some(limiter) = &mut self.limiter
            && !limiter.admit(now)
        {
            return Push::Dropped {
                item,
                reason: DropReason::RateLimit,
            };
        }
        self.push_kept(item)
    }

    /// Queues `item` under the drop policy, past the rate limit (an item that was admitted
    /// once, moved to a queue with new settings).
    pub fn push_kept(&mut self, item: T) -> Push<T> {
        let cap = self.capacity;
        let policy = self.policy;
        let dropped = |item| Push::Dropped {
            item,
            reason: DropReason::Policy,
        };
        match &mut self.store {
            Store::Ring(ring) => {
                if ring.len() < cap {
                    ring.push_back(item);
                    return Push::Queued;
                }
                match policy {
                    Policy::Fifo => Push::Backpressure(item),
                    Policy::DropNewest => dropped(item),
                    _ => {
                        let oldest = ring.pop_front();
                        ring.push_back(item);
                        oldest.map_or(Push::Queued, dropped)
                    }
                }
            }
            Store::Latest(slot) => slot.replace(item).map_or(Push::Queued, dropped),
            Store::Random { ring, rng } => {
                if ring.len() < cap {
                    ring.push_back(item);
                    return Push::Queued;
                }
                // The newcomer always enters; the victim is uniform over the queued ones.
                let victim = ring.remove(rng.below(ring.len()));
                ring.push_back(item);
                victim.map_or(Push::Queued, dropped)
            }
            Store::Afr(afr) => match afr.push(item) {
                AfrPush::Queued => Push::Queued,
                AfrPush::Decimated(item) | AfrPush::Evicted(item) => dropped(item),
            },
        }
    }

    /// The item `pop` would return next, without taking it.
    pub fn peek(&self) -> Option<&T> {
        match &self.store {
            Store::Ring(r) | Store::Random { ring: r, .. } => r.front(),
            Store::Latest(slot) => slot.as_ref(),
            Store::Afr(a) => a.iter().next(),
        }
    }

    /// Takes the oldest queued item. `now` is accepted for symmetry with `push` and
    /// future time-based policies; no policy here depends on it.
    pub fn pop(&mut self, _now: Nanos) -> Option<T> {
        match &mut self.store {
            Store::Ring(r) | Store::Random { ring: r, .. } => {
                let item = r.pop_front();
                release_if_drained(r);
                item
            }
            Store::Latest(slot) => slot.take(),
            Store::Afr(a) => a.pop(),
        }
    }

    /// Room held for items now (not the bound): what the queue costs in memory.
    pub fn reserved(&self) -> usize {
        match &self.store {
            Store::Ring(r) | Store::Random { ring: r, .. } => r.capacity(),
            Store::Latest(_) => 1,
            Store::Afr(a) => a.reserved(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn memory_follows_what_waits_not_the_bound() {
        for policy in [
            Policy::DropOldest,
            Policy::Fifo,
            Policy::Random,
            Policy::Afr,
        ] {
            let mut q = q(policy, 1000);
            assert_eq!(
                q.reserved(),
                0,
                "{policy:?}: nothing reserved before a push"
            );
            for m in 0..600 {
                let _ = q.push(m, Nanos::ZERO);
            }
            assert!(q.reserved() >= 600, "{policy:?}: a backlog has its room");
            while q.pop(Nanos::ZERO).is_some() {}
            assert!(
                q.reserved() <= KEEP_EMPTY_CAPACITY,
                "{policy:?}: a drained queue keeps {} slots",
                q.reserved()
            );
            // It still works after letting go.
            assert_eq!(q.push(7, Nanos::ZERO), Push::Queued);
            assert_eq!(q.pop(Nanos::ZERO), Some(7));
        }
    }

    fn q(policy: Policy, queue: usize) -> TopicQueue<u32> {
        TopicQueue::new(&TopicQos {
            policy,
            queue,
            ..TopicQos::default()
        })
    }

    fn drain(q: &mut TopicQueue<u32>) -> Vec<u32> {
        std::iter::from_fn(|| q.pop(Nanos::ZERO)).collect()
    }

    #[test]
    fn each_policy_keeps_what_its_name_says_when_full() {
        let fill =
            |q: &mut TopicQueue<u32>| (1..=5).map(|m| q.push(m, Nanos::ZERO)).collect::<Vec<_>>();
        let mut oldest = q(Policy::DropOldest, 3);
        fill(&mut oldest);
        assert_eq!(drain(&mut oldest), vec![3, 4, 5]);

        let mut newest = q(Policy::DropNewest, 3);
        let out = fill(&mut newest);
        assert_eq!(
            out[3],
            Push::Dropped {
                item: 4,
                reason: DropReason::Policy
            }
        );
        assert_eq!(drain(&mut newest), vec![1, 2, 3]);

        let mut latest = q(Policy::Latest, 1);
        fill(&mut latest);
        assert_eq!(drain(&mut latest), vec![5]);

        let mut fifo = q(Policy::Fifo, 3);
        let out = fill(&mut fifo);
        assert_eq!(out[3], Push::Backpressure(4));
        assert_eq!(drain(&mut fifo), vec![1, 2, 3]);

        let mut random = q(Policy::Random, 3);
        fill(&mut random);
        let kept = drain(&mut random);
        assert_eq!((kept.len(), kept[2]), (3, 5));
    }

    #[test]
    fn random_policy_is_reproducible_from_its_seed() {
        let qos = TopicQos {
            policy: Policy::Random,
            queue: 4,
            ..TopicQos::default()
        };
        let run = |seed| {
            let mut q = TopicQueue::with_seed(&qos, seed);
            for m in 0..50u32 {
                let _ = q.push(m, Nanos::ZERO);
            }
            drain(&mut q)
        };
        assert_eq!(run(7), run(7));
        assert_ne!(run(7), run(8));
    }

    #[test]
    fn rate_limited_messages_are_reported_with_their_reason() {
        let qos = TopicQos {
            rate_limit_hz: Some(1.0),
            ..TopicQos::default()
        };
        let mut q = TopicQueue::new(&qos);
        assert_eq!(q.push(1u32, Nanos::ZERO), Push::Queued);
        assert_eq!(
            q.push(2, Nanos::from_millis(100)),
            Push::Dropped {
                item: 2,
                reason: DropReason::RateLimit
            }
        );
        assert_eq!(q.push(3, Nanos::from_secs(1)), Push::Queued);
        assert_eq!(DropReason::RateLimit.as_str(), "rate_limit");
    }
}
