//! The QoS of the readers and writers the bridge creates (docs/ros2.md has the table).
//!
//! Readers take what the local writer offers, so every local publisher is matched:
//! reliable only from a reliable writer, transient-local (latched on the hub) only from
//! a transient-local writer. Writers are reliable (a best-effort reader matches a
//! reliable writer, not the reverse) and transient-local for latched router topics, so a
//! late local subscriber asking for transient-local gets the last message.

use rustdds::policy::{Durability, History, Reliability, ResourceLimits};
use rustdds::{Duration, QosPolicies, QosPolicyBuilder};

/// How many samples a reader or a volatile writer keeps (the ROS 2 default depth).
pub const DEPTH: i32 = 10;

/// How many samples the bridge's reader of a `ros_type` topic keeps. rustdds keeps the
/// last `depth` samples of a topic alive after they were taken (it trims a topic's
/// cache on every insert once samples exceed 64 KiB, down to the depth, and only now and
/// then for small ones). The bridge takes each sample as it arrives, so for bulk sensor
/// data, whose samples are large, those slots are megabytes held for nothing: ten 1 MB
/// point clouds put the agent at 42.7 MB where two leave it at 35 MB
/// (docs/benchmarks/log.md, "The bridge's readers of bulk sensor data keep two samples").
/// Small samples keep ROS 2's default depth of 10, room for a burst while the bridge is
/// busy.
pub fn reader_depth(ros_type: &str) -> i32 {
    let bulk = matches!(
        ros_type.replace("/msg/", "/").as_str(),
        "sensor_msgs/PointCloud2"
            | "sensor_msgs/PointCloud"
            | "sensor_msgs/Image"
            | "sensor_msgs/CompressedImage"
    );
    if bulk { 2 } else { DEPTH }
}

/// A reader's cache bound: the depth (rustdds' default resource limit of 64 samples
/// would keep up to 64 between its trims).
fn reader_limits(depth: i32) -> ResourceLimits {
    ResourceLimits {
        max_samples: depth,
        max_instances: 1,
        max_samples_per_instance: depth,
    }
}

fn reliable() -> Reliability {
    Reliability::Reliable {
        max_blocking_time: Duration::from_millis(100),
    }
}

/// A reader matching a writer that offers `reliability` and `durability` (either
/// unknown: DDS's defaults for writers, reliable and volatile), keeping `depth` samples
/// ([`reader_depth`]).
pub fn reader_for(
    reliability: Option<Reliability>,
    durability: Option<Durability>,
    depth: i32,
) -> QosPolicies {
    let reliable_writer = !matches!(reliability, Some(Reliability::BestEffort));
    let latched = matches!(
        durability,
        Some(Durability::TransientLocal | Durability::Transient | Durability::Persistent)
    );
    QosPolicyBuilder::new()
        .reliability(if reliable_writer {
            reliable()
        } else {
            Reliability::BestEffort
        })
        .durability(if latched {
            Durability::TransientLocal
        } else {
            Durability::Volatile
        })
        .history(History::KeepLast { depth })
        .resource_limits(reader_limits(depth))
        .build()
}

/// A writer of a router topic; `latched` topics keep their last message for late readers.
pub fn writer(latched: bool) -> QosPolicies {
    QosPolicyBuilder::new()
        .reliability(reliable())
        .durability(if latched {
            Durability::TransientLocal
        } else {
            Durability::Volatile
        })
        .history(History::KeepLast {
            depth: if latched { 1 } else { DEPTH },
        })
        .build()
}

/// How many requests (or replies) of one service may be in flight at once: a keep-last
/// writer forgets unacknowledged samples beyond its depth, so a burst of concurrent
/// calls needs room for all of them (the call table bounds pending calls per provider
/// at 1024 by default).
pub const SERVICE_DEPTH: i32 = 1024;

/// Request and reply topics: reliable and volatile as ROS 2 services are, with room for
/// [`SERVICE_DEPTH`] calls in flight (ROS 2's default depth of 10 would lose the 11th
/// concurrent request).
pub fn service() -> QosPolicies {
    QosPolicyBuilder::new()
        .reliability(reliable())
        .durability(Durability::Volatile)
        .history(History::KeepLast {
            depth: SERVICE_DEPTH,
        })
        .build()
}

/// An action's status topic: transient-local, reliable, depth 1, as ROS 2 publishes it.
pub fn action_status() -> QosPolicies {
    QosPolicyBuilder::new()
        .reliability(reliable())
        .durability(Durability::TransientLocal)
        .history(History::KeepLast { depth: 1 })
        .build()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn readers_follow_what_the_writer_offers() {
        let q = reader_for(
            Some(Reliability::BestEffort),
            Some(Durability::Volatile),
            DEPTH,
        );
        assert!(!q.is_reliable());
        assert!(q.is_volatile());
        let q = reader_for(Some(reliable()), Some(Durability::TransientLocal), DEPTH);
        assert!(q.is_reliable());
        assert_eq!(q.durability(), Some(Durability::TransientLocal));
        let q = reader_for(None, None, 2);
        assert!(q.is_reliable() && q.is_volatile());
        assert_eq!(q.history(), Some(History::KeepLast { depth: 2 }));
        assert_eq!(writer(true).durability(), Some(Durability::TransientLocal));
        assert!(writer(false).is_volatile());
    }

    #[test]
    fn bulk_sensor_readers_keep_two_samples_and_the_rest_ten() {
        assert_eq!(reader_depth("sensor_msgs/msg/PointCloud2"), 2);
        assert_eq!(reader_depth("sensor_msgs/Image"), 2);
        assert_eq!(reader_depth("sensor_msgs/msg/CompressedImage"), 2);
        assert_eq!(reader_depth("sensor_msgs/msg/LaserScan"), DEPTH);
        assert_eq!(reader_depth("fltest_msgs/msg/Battery"), DEPTH);
    }
}
