//! The per-subscription outbound queue.
//!
//! Every subscription owns one bounded queue whose drop policy comes from the QoS engine
//! (`crates/qos`: `fifo`, `latest`, `drop_oldest`, `drop_newest`, `random`, `afr`, with an
//! optional rate limit). rosbridge's own options map onto it: `queue_length` is
//! `drop_oldest(queue_length)` and `throttle_rate` is a rate limit. Pushing never blocks: a
//! subscriber that cannot keep up loses its own messages and nobody else notices — even a
//! `fifo` (no-drop) subscriber on the hub, whose refused message is counted as
//! `backpressure` rather than stalling the publisher and every other subscriber.

use std::sync::Arc;
use std::time::Instant;

use fleetlink_qos::{Nanos, Policy, Push, TopicQos, TopicQueue, WireLen};

use crate::message::Message;

/// Why a message did not reach a subscriber. Stable label values for metrics.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DropReason {
    /// Over the subscription's rate limit (`throttle_rate`, `rate_limit_hz`).
    RateLimit,
    /// The queue's drop policy evicted it (queue full, `latest`, `afr`, ...).
    Policy,
    /// A no-drop queue was full; the relay never stalls other clients for it.
    Backpressure,
    /// It could not be converted to the encoding the subscriber asked for.
    Encode,
}

impl DropReason {
    pub const ALL: [DropReason; 4] = [
        DropReason::RateLimit,
        DropReason::Policy,
        DropReason::Backpressure,
        DropReason::Encode,
    ];

    pub fn as_str(self) -> &'static str {
        match self {
            DropReason::RateLimit => "rate_limit",
            DropReason::Policy => "policy",
            DropReason::Backpressure => "backpressure",
            DropReason::Encode => "encode_error",
        }
    }

    pub fn index(self) -> usize {
        self as usize
    }

    pub fn from_qos(r: fleetlink_qos::DropReason) -> DropReason {
        match r {
            fleetlink_qos::DropReason::RateLimit => DropReason::RateLimit,
            fleetlink_qos::DropReason::Backpressure => DropReason::Backpressure,
            fleetlink_qos::DropReason::Policy | fleetlink_qos::DropReason::UnknownTopic => {
                DropReason::Policy
            }
        }
    }
}

impl WireLen for Message {
    fn wire_len(&self) -> usize {
        self.payload.len()
    }
}

pub trait OutboundQueue: Send {
    /// Adds `msg`; returns what was dropped to make room (possibly `msg` itself).
    fn push(&mut self, msg: Arc<Message>, now: Instant) -> Option<(Arc<Message>, DropReason)>;
    /// The next message to send, if one may be sent at `now`.
    fn pop(&mut self, now: Instant) -> Option<Arc<Message>>;
    fn len(&self) -> usize;
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// When the oldest queued message arrived (for lag reporting).
    fn oldest(&self) -> Option<Instant>;
}

/// A QoS-engine queue behind the relay's queue seam.
pub struct QosQueue {
    queue: TopicQueue<Arc<Message>>,
    origin: Instant,
}

impl QosQueue {
    pub fn new(qos: &TopicQos) -> QosQueue {
        QosQueue {
            queue: TopicQueue::new(qos),
            origin: Instant::now(),
        }
    }

    fn nanos(&self, now: Instant) -> Nanos {
        Nanos::since(self.origin, now)
    }
}

impl OutboundQueue for QosQueue {
    fn push(&mut self, msg: Arc<Message>, now: Instant) -> Option<(Arc<Message>, DropReason)> {
        let t = self.nanos(now);
        match self.queue.push(msg, t) {
            Push::Queued => None,
            Push::Dropped { item, reason } => Some((item, DropReason::from_qos(reason))),
            Push::Backpressure(item) => Some((item, DropReason::Backpressure)),
        }
    }

    fn pop(&mut self, now: Instant) -> Option<Arc<Message>> {
        let t = self.nanos(now);
        self.queue.pop(t)
    }

    fn len(&self) -> usize {
        self.queue.len()
    }

    fn oldest(&self) -> Option<Instant> {
        self.queue.peek().map(|m| m.received)
    }
}

/// The QoS of a subscription from rosbridge-style options: `queue_length` (0 = the
/// server's default) and `throttle_rate` in milliseconds (0 = none).
pub fn qos_for_options(queue_length: u32, throttle_ms: u32, default_capacity: usize) -> TopicQos {
    TopicQos {
        priority: 1.0,
        rate_limit_hz: (throttle_ms > 0).then(|| 1000.0 / f64::from(throttle_ms)),
        policy: Policy::DropOldest,
        queue: if queue_length > 0 {
            queue_length as usize
        } else {
            default_capacity.max(1)
        },
        no_drop: false,
    }
}
