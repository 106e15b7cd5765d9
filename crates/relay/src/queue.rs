//! The per-subscription outbound queue.
//!
//! Every subscription owns one bounded queue; what it keeps when full is its policy. This
//! trait is the seam where the QoS engine (`crates/qos`) plugs its policies in; the
//! relay's default is [`DropOldest`], which is what rosbridge's `queue_length` means.
//! Pushing never blocks: a subscriber that cannot keep up loses its own messages and
//! nobody else notices.

use std::collections::VecDeque;
use std::sync::Arc;
use std::time::{Duration, Instant};

use crate::message::Message;

/// Why a message did not reach a subscriber. Stable label values for metrics.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DropReason {
    /// The subscriber's queue was full and the policy evicted a message.
    QueueFull,
    /// The subscription's `throttle_rate` or rate limit skipped it.
    RateLimit,
    /// It could not be converted to the encoding the subscriber asked for.
    Encode,
}

impl DropReason {
    pub const ALL: [DropReason; 3] = [
        DropReason::QueueFull,
        DropReason::RateLimit,
        DropReason::Encode,
    ];

    pub fn as_str(self) -> &'static str {
        match self {
            DropReason::QueueFull => "queue_full",
            DropReason::RateLimit => "rate_limit",
            DropReason::Encode => "encode_error",
        }
    }

    pub fn index(self) -> usize {
        self as usize
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
    /// The message that has waited longest (for lag reporting).
    fn oldest(&self) -> Option<&Arc<Message>>;
    /// When a non-empty queue that refused to pop will next allow it (throttling).
    fn ready_at(&self, now: Instant) -> Instant {
        now
    }
}

/// Bounded FIFO that evicts the oldest message when full.
pub struct DropOldest {
    items: VecDeque<Arc<Message>>,
    capacity: usize,
}

impl DropOldest {
    pub fn new(capacity: usize) -> Self {
        let capacity = capacity.max(1);
        DropOldest {
            items: VecDeque::with_capacity(capacity.min(64)),
            capacity,
        }
    }
}

impl OutboundQueue for DropOldest {
    fn push(&mut self, msg: Arc<Message>, _now: Instant) -> Option<(Arc<Message>, DropReason)> {
        let dropped = if self.items.len() >= self.capacity {
            self.items.pop_front().map(|m| (m, DropReason::QueueFull))
        } else {
            None
        };
        self.items.push_back(msg);
        dropped
    }

    fn pop(&mut self, _now: Instant) -> Option<Arc<Message>> {
        self.items.pop_front()
    }

    fn len(&self) -> usize {
        self.items.len()
    }

    fn oldest(&self) -> Option<&Arc<Message>> {
        self.items.front()
    }
}

/// rosbridge `throttle_rate`: at most one message per `period`. With no queue
/// (`queue_length` 0) only the newest waiting message is kept.
pub struct Throttled<Q> {
    inner: Q,
    period: Duration,
    last_sent: Option<Instant>,
}

impl<Q: OutboundQueue> Throttled<Q> {
    pub fn new(inner: Q, period: Duration) -> Self {
        Throttled {
            inner,
            period,
            last_sent: None,
        }
    }
}

impl<Q: OutboundQueue> OutboundQueue for Throttled<Q> {
    fn push(&mut self, msg: Arc<Message>, now: Instant) -> Option<(Arc<Message>, DropReason)> {
        self.inner
            .push(msg, now)
            .map(|(m, _)| (m, DropReason::RateLimit))
    }

    fn pop(&mut self, now: Instant) -> Option<Arc<Message>> {
        if let Some(last) = self.last_sent
            && now < last + self.period
        {
            return None;
        }
        let m = self.inner.pop(now)?;
        self.last_sent = Some(now);
        Some(m)
    }

    fn len(&self) -> usize {
        self.inner.len()
    }

    fn oldest(&self) -> Option<&Arc<Message>> {
        self.inner.oldest()
    }

    fn ready_at(&self, now: Instant) -> Instant {
        self.last_sent.map_or(now, |l| (l + self.period).max(now))
    }
}

/// The queue a subscription gets from its rosbridge-style options.
pub fn for_options(
    queue_length: u32,
    throttle_ms: u32,
    default_capacity: usize,
) -> Box<dyn OutboundQueue> {
    let cap = if queue_length > 0 {
        queue_length as usize
    } else {
        default_capacity
    };
    if throttle_ms == 0 {
        return Box::new(DropOldest::new(cap));
    }
    let cap = if queue_length > 0 {
        queue_length as usize
    } else {
        1
    };
    Box::new(Throttled::new(
        DropOldest::new(cap),
        Duration::from_millis(u64::from(throttle_ms)),
    ))
}
