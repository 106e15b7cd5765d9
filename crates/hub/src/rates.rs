//! Receive-rate prediction for a robot's topics (docs/qos.md, "Receive-rate prediction"):
//! from what its agent reports offering (`TOPIC_LOAD`), what its link may carry
//! (`LINK_REPORT.capacity_bps`) and how large each message is on the link (the hub's own
//! byte counts), the messages per second the hub can expect of each topic.
//!
//! The order follows the agent's uplink:
//! 1. `no_drop` topics go before all others (one FIFO): they are predicted first, sharing
//!    the link in proportion to what they offer when even they do not fit.
//! 2. Messages no larger than a chunk (about 2 ms of the link, `link_control`) are never
//!    held back by the link's window or the capacity share: they get what they offer
//!    while the link has room, else they share it as the scheduler does.
//! 3. What is left goes to the bulk topics. Their messages go out a chunk of each in turn,
//!    so the link is shared byte for byte among them: each gets what it offers if that is
//!    less than an equal share of what is left, the others split the rest
//!    ([`fleetlink_qos::predict::byte_fair_rates`]). Small messages that do not fit are
//!    shared as the scheduler picks them ([`fleetlink_qos::predict::receive_rates`]).

use std::collections::HashMap;
use std::sync::atomic::Ordering::Relaxed;

use fleetlink_qos::predict::{TopicLoad, byte_fair_rates, receive_rates};
use fleetlink_relay::ClientId;
use fleetlink_relay::router::TopicSnapshot;
use fleetlink_relay::stats::RobotOffer;

use crate::registry::LiveRobot;

/// A report older than this is stale: the topic stopped flowing or the robot went quiet.
pub const FRESH_NS: u64 = 5_000_000_000;

/// One topic's figures and prediction.
#[derive(Debug, Clone, PartialEq)]
pub struct TopicRate {
    pub name: String,
    pub offer: RobotOffer,
    /// Bytes one message takes on the link (its payload, times the topic's compression
    /// ratio on the link when it has one).
    pub wire_bytes: f64,
    /// What the link could carry of this topic alone: capacity / wire bytes (eq. 4).
    pub link_limit_hz: Option<f64>,
    /// What the hub can expect, sharing the link with the robot's other topics.
    pub predicted_hz: Option<f64>,
}

/// A robot's link capacity and its topics' predictions.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotRates {
    pub capacity_bps: Option<f64>,
    pub topics: Vec<TopicRate>,
}

/// The listed topics by publishing client, for [`robot_rates`].
pub fn by_publisher(topics: &[TopicSnapshot]) -> HashMap<ClientId, Vec<&TopicSnapshot>> {
    let mut out: HashMap<ClientId, Vec<&TopicSnapshot>> = HashMap::new();
    for t in topics.iter().filter(|t| t.listed()) {
        for p in &t.publishers {
            out.entry(*p).or_default().push(t);
        }
    }
    out
}

/// Predictions for the topics `robot` publishes (`own`, from [`by_publisher`]) that its
/// agent reported on lately.
pub fn robot_rates(robot: &LiveRobot, own: &[&TopicSnapshot], now_ns: u64) -> RobotRates {
    let capacity = match robot.capacity_bps.load(Relaxed) {
        0 => None,
        c => Some(c as f64),
    };
    let since = now_ns.saturating_sub(FRESH_NS);
    let mut topics: Vec<TopicRate> = own
        .iter()
        .filter_map(|t| {
            let offer = t.stats.robot_offer(since)?;
            let raw = if offer.hz > 0.0 {
                offer.bytes_per_sec / offer.hz
            } else {
                0.0
            };
            let ratio = t
                .stats
                .link_figures()
                .map_or(1.0, |(wire, raw)| wire as f64 / raw.max(1) as f64);
            let wire_bytes = raw * ratio;
            Some(TopicRate {
                name: t.meta.name.to_string(),
                offer,
                wire_bytes,
                link_limit_hz: capacity
                    .filter(|_| wire_bytes > 0.0)
                    .map(|c| c / wire_bytes),
                predicted_hz: None,
            })
        })
        .collect();
    if let Some(c) = capacity {
        let predicted = predict(c, &topics);
        for (t, p) in topics.iter_mut().zip(predicted) {
            t.predicted_hz = Some(p);
        }
    }
    RobotRates {
        capacity_bps: capacity,
        topics,
    }
}

/// The largest message the link sends whole at `capacity` (larger ones are cut into
/// chunks and paced: `link_control`'s chunk size).
fn chunk_bytes(capacity: f64) -> f64 {
    use fleetlink_relay::link_control::{CHUNK_TIME, MAX_CHUNK, MIN_CHUNK};
    (capacity * CHUNK_TIME.as_secs_f64()).clamp(MIN_CHUNK as f64, MAX_CHUNK as f64)
}

/// No-drop topics first, then small messages, then the scheduler's share of what is left
/// for the bulk topics (see the module docs).
fn predict(capacity: f64, topics: &[TopicRate]) -> Vec<f64> {
    let bytes = |t: &TopicRate| t.offer.hz * t.wire_bytes;
    let mut out = vec![0.0; topics.len()];
    let no_drop_need: f64 = topics.iter().filter(|t| t.offer.no_drop).map(bytes).sum();
    let no_drop_share = if no_drop_need > capacity {
        capacity / no_drop_need
    } else {
        1.0
    };
    for (o, t) in out.iter_mut().zip(topics) {
        if t.offer.no_drop {
            *o = t.offer.hz * no_drop_share;
        }
    }
    let mut left = (capacity - no_drop_need).max(0.0);
    let chunk = chunk_bytes(capacity);
    for small in [true, false] {
        let members: Vec<usize> = (0..topics.len())
            .filter(|&i| !topics[i].offer.no_drop && (topics[i].wire_bytes <= chunk) == small)
            .collect();
        let loads: Vec<TopicLoad> = members
            .iter()
            .map(|&i| TopicLoad {
                offered_hz: topics[i].offer.hz,
                wire_bytes: topics[i].wire_bytes,
                priority: topics[i].offer.priority,
                queue: topics[i].offer.queue,
            })
            .collect();
        let rates = if small {
            receive_rates(left, &loads)
        } else {
            byte_fair_rates(left, &loads)
        };
        for (&i, r) in members.iter().zip(rates) {
            out[i] = r;
            left = (left - r * topics[i].wire_bytes).max(0.0);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn topic(hz: f64, wire_bytes: f64, priority: f64, no_drop: bool) -> TopicRate {
        TopicRate {
            name: String::new(),
            offer: RobotOffer {
                hz,
                bytes_per_sec: hz * wire_bytes,
                priority,
                queue: 16,
                no_drop,
                at_ns: 0,
            },
            wire_bytes,
            link_limit_hz: None,
            predicted_hz: None,
        }
    }

    #[test]
    fn no_drop_topics_are_served_first_and_the_rest_share_what_is_left() {
        // A 40 kB/s no-drop log and two 100 kB/s cameras over 100 kB/s.
        let topics = [
            topic(10.0, 4000.0, 1.0, true),
            topic(10.0, 10_000.0, 1.0, false),
            topic(10.0, 10_000.0, 1.0, false),
        ];
        let r = predict(100_000.0, &topics);
        assert_eq!(r[0], 10.0);
        assert!(
            (r[1] - 3.0).abs() < 0.1 && (r[2] - 3.0).abs() < 0.1,
            "{r:?}"
        );
    }

    #[test]
    fn small_messages_go_whole_and_bulk_topics_share_the_rest() {
        // A pose of 60 bytes at 40 Hz beside a 10 kB camera and a 5 kB scan at 20 Hz over
        // 250 kB/s: the pose is never held.
        let topics = [
            topic(20.0, 10_000.0, 5.0, false),
            topic(40.0, 60.0, 5.0, false),
            topic(20.0, 5000.0, 5.0, false),
        ];
        let r = predict(250_000.0, &topics);
        assert_eq!(r[1], 40.0);
        // The rest split byte for byte: the scan fits half (100 kB/s), the camera gets
        // the remainder.
        let left = 250_000.0 - 40.0 * 60.0;
        assert!((r[2] - 20.0).abs() < 1e-9, "{r:?}");
        assert!((r[0] - (left - 100_000.0) / 10_000.0).abs() < 1e-9, "{r:?}");
    }

    #[test]
    fn no_drop_topics_that_do_not_fit_share_in_proportion_and_starve_the_rest() {
        let topics = [
            topic(10.0, 10_000.0, 1.0, true),
            topic(30.0, 10_000.0, 1.0, true),
            topic(10.0, 100.0, 9.0, false),
        ];
        let r = predict(200_000.0, &topics);
        assert!(
            (r[0] - 5.0).abs() < 1e-9 && (r[1] - 15.0).abs() < 1e-9,
            "{r:?}"
        );
        assert_eq!(r[2], 0.0);
    }
}
