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
    /// Older than its topic's `max_age` when its turn on the link came.
    TooOld,
}

impl DropReason {
    pub const ALL: [DropReason; 5] = [
        DropReason::RateLimit,
        DropReason::Policy,
        DropReason::Backpressure,
        DropReason::Encode,
        DropReason::TooOld,
    ];

    pub fn as_str(self) -> &'static str {
        match self {
            DropReason::RateLimit => "rate_limit",
            DropReason::Policy => "policy",
            DropReason::Backpressure => "backpressure",
            DropReason::Encode => "encode_error",
            DropReason::TooOld => "too_old",
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
    /// [`OutboundQueue::push`] past the rate limit, which neither refuses `msg` nor counts
    /// it: for a video keyframe that ends a gap, without which the frames after it are
    /// worthless.
    fn push_past_limit(
        &mut self,
        msg: Arc<Message>,
        now: Instant,
    ) -> Option<(Arc<Message>, DropReason)>;
    /// Whether the next push would have to drop a message to make room.
    fn is_full(&self) -> bool;
    /// The next message to send, if one may be sent at `now`.
    fn pop(&mut self, now: Instant) -> Option<Arc<Message>>;
    fn len(&self) -> usize;
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// When the oldest queued message arrived (for lag reporting).
    fn oldest(&self) -> Option<Instant>;
    /// Messages evicted since the last call to keep a byte bound (beyond what `push`
    /// returned), counted as policy drops.
    fn take_evicted(&mut self) -> u64 {
        0
    }
}

/// A QoS-engine queue behind the relay's queue seam.
pub struct QosQueue {
    queue: TopicQueue<Arc<Message>>,
    origin: Instant,
    /// The last time read on the queue's clock ([`QosQueue::nanos`]).
    last: Option<(Instant, Nanos)>,
    /// Payload bytes queued, and the most allowed (the oldest messages go first; the
    /// newest one always stays).
    bytes: usize,
    max_bytes: usize,
    evicted: u64,
}

impl QosQueue {
    pub fn new(qos: &TopicQos) -> QosQueue {
        QosQueue::with_max_bytes(qos, usize::MAX)
    }

    /// A queue bounded in bytes as well as in messages: a burst of small messages fits
    /// whole, while a subscriber of large ones that falls behind keeps only the newest
    /// few.
    pub fn with_max_bytes(qos: &TopicQos, max_bytes: usize) -> QosQueue {
        QosQueue {
            queue: TopicQueue::new(qos),
            origin: Instant::now(),
            last: None,
            bytes: 0,
            max_bytes,
            evicted: 0,
        }
    }

    /// `now` on the queue's clock. A burst's messages share their arrival time and a
    /// writer's batch its `now`, so the last reading is kept.
    fn nanos(&mut self, now: Instant) -> Nanos {
        match self.last {
            Some((at, t)) if at == now => t,
            _ => {
                let t = Nanos::since(self.origin, now);
                self.last = Some((now, t));
                t
            }
        }
    }
}

impl OutboundQueue for QosQueue {
    fn push(&mut self, msg: Arc<Message>, now: Instant) -> Option<(Arc<Message>, DropReason)> {
        let t = self.nanos(now);
        let len = msg.payload.len();
        let pushed = self.queue.push(msg, t);
        self.settle(pushed, len, t)
    }

    fn push_past_limit(
        &mut self,
        msg: Arc<Message>,
        now: Instant,
    ) -> Option<(Arc<Message>, DropReason)> {
        let t = self.nanos(now);
        let len = msg.payload.len();
        let pushed = self.queue.push_kept(msg);
        self.settle(pushed, len, t)
    }

    fn is_full(&self) -> bool {
        self.queue.len() >= self.queue.capacity()
    }

    fn pop(&mut self, now: Instant) -> Option<Arc<Message>> {
        let t = self.nanos(now);
        let m = self.queue.pop(t)?;
        self.bytes -= m.payload.len().min(self.bytes);
        Some(m)
    }

    fn take_evicted(&mut self) -> u64 {
        std::mem::take(&mut self.evicted)
    }

    fn len(&self) -> usize {
        self.queue.len()
    }

    fn oldest(&self) -> Option<Instant> {
        self.queue.peek().map(|m| m.received())
    }
}

impl QosQueue {
    /// Accounts for a push of a message of `len` bytes, then evicts the oldest messages
    /// over the byte bound. Returns what the push dropped.
    fn settle(
        &mut self,
        pushed: Push<Arc<Message>>,
        len: usize,
        t: Nanos,
    ) -> Option<(Arc<Message>, DropReason)> {
        let out = match pushed {
            Push::Queued => {
                self.bytes += len;
                None
            }
            Push::Dropped { item, reason } => {
                // The queue made room: either this message was refused, or it went in
                // and an older one came out.
                let gone = item.payload.len();
                self.bytes = self.bytes + len - gone;
                Some((item, DropReason::from_qos(reason)))
            }
            Push::Backpressure(item) => Some((item, DropReason::Backpressure)),
        };
        while self.bytes > self.max_bytes && self.queue.len() > 1 {
            match self.queue.pop(t) {
                Some(old) => {
                    self.bytes -= old.payload.len().min(self.bytes);
                    self.evicted += 1;
                }
                None => break,
            }
        }
        out
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
        always: false,
        max_age_ms: None,
        mode: fleetlink_qos::Mode::Stream,
        compression: fleetlink_qos::Compression::None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::message::TopicMeta;
    use crate::names::{ClientId, TopicId, TopicName};
    use fleetlink_proto::{Encoding, Payload, Schema};

    fn msg(size: usize, seq: u64) -> Arc<Message> {
        let meta = Arc::new(TopicMeta::new(
            TopicId(1),
            TopicName::parse("/t").unwrap(),
            Schema::default(),
            false,
        ));
        let body = bytes::Bytes::from(vec![b'x'; size]);
        Arc::new(Message::new(
            meta,
            seq,
            0,
            ClientId(1),
            Payload::new(Encoding::Json, body),
        ))
    }

    #[test]
    fn the_default_queue_takes_a_burst_of_small_messages_whole() {
        let mut q = QosQueue::with_max_bytes(&qos_for_options(0, 0, 1000), 2 << 20);
        let now = Instant::now();
        for i in 0..1000 {
            assert!(q.push(msg(64, i), now).is_none());
        }
        assert_eq!((q.len(), q.take_evicted()), (1000, 0));
        // The 1,001st evicts the oldest, by count.
        assert!(q.push(msg(64, 1000), now).is_some());
        assert_eq!(q.pop(now).unwrap().seq, 1);
    }

    #[test]
    fn a_slow_subscriber_of_large_messages_keeps_only_the_newest_few() {
        let mut q = QosQueue::with_max_bytes(&qos_for_options(0, 0, 1000), 2 << 20);
        let now = Instant::now();
        for i in 0..10 {
            q.push(msg(1 << 20, i), now);
        }
        assert_eq!(q.len(), 2);
        assert_eq!(q.take_evicted(), 8);
        assert_eq!(q.pop(now).unwrap().seq, 8);
        assert_eq!(q.pop(now).unwrap().seq, 9);
        // One message larger than the bound is still delivered.
        q.push(msg(5 << 20, 10), now);
        assert_eq!(q.len(), 1);
        assert_eq!(q.pop(now).unwrap().seq, 10);
        assert_eq!(q.bytes, 0);
    }
}
