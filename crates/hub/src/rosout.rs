//! The hub's `/rosout`: what happens to the fleet, as `rcl_interfaces/msg/Log`.
//!
//! rosbridge servers always carry `/rosout`, and tools rely on it: Lichtblick, for one,
//! decides that a rosbridge server is ROS 2 by finding `rcl_interfaces/msg/Log` among its
//! topic types. The hub's `/rosout` is a real log, not a placeholder: robots connecting,
//! leaving and being refused, links degrading and recovering, messages dropped for slow
//! subscribers, and every robot's own `/<robot>/rosout` (of that type) republished as it
//! arrived, unchanged.

use std::collections::{HashMap, HashSet};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::{Duration, Instant};

use fleetlink_proto::{Payload, Schema};
use fleetlink_relay::queue::DropReason;
use fleetlink_relay::router::{SubOptions, Target, same_type};
use fleetlink_relay::{ClientId, ClientKind, Router, Topic, TopicName};
use serde_json::json;
use tokio_util::sync::CancellationToken;

use crate::registry::Registry;

/// The log's type (ROS 2).
pub const LOG_TYPE: &str = "rcl_interfaces/msg/Log";
/// How often link quality and drops are looked at.
const WATCH_EVERY: Duration = Duration::from_secs(5);
/// A robot whose heartbeat round trip exceeds this is reported as degraded.
const DEGRADED_RTT: Duration = Duration::from_millis(1000);

/// `rcl_interfaces/msg/Log` levels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum Level {
    Info = 20,
    Warn = 30,
    Error = 40,
}

/// Publishes the hub's events on `/rosout`.
pub struct RosOut {
    router: Arc<Router>,
    client: ClientId,
    topic: Arc<Topic>,
    seq: AtomicU64,
}

impl RosOut {
    /// Joins `router` as the `rosout` participant and advertises `/rosout`.
    pub fn start(router: Arc<Router>) -> Arc<RosOut> {
        let (client, _) = router.connect(
            ClientKind::Internal {
                role: "rosout".into(),
            },
            None,
        );
        let name = TopicName::parse("/rosout").expect("a constant name");
        let topic = router
            .advertise(client, &name, Schema::named(LOG_TYPE), false)
            .expect("the rosout client was just connected and nobody else owns /rosout");
        Arc::new(RosOut {
            router,
            client,
            topic,
            seq: AtomicU64::new(0),
        })
    }

    /// One log line from the hub (node name `fleetlink_hub`).
    pub fn log(&self, level: Level, function: &str, msg: impl Into<String>) {
        let now = fleetlink_relay::unix_nanos();
        let body = json!({
            "stamp": {"sec": now / 1_000_000_000, "nanosec": now % 1_000_000_000},
            "level": level as u8,
            "name": "fleetlink_hub",
            "msg": msg.into(),
            "file": "",
            "function": function,
            "line": 0,
        });
        let seq = self.seq.fetch_add(1, Relaxed) + 1;
        self.topic.publish(
            self.client,
            seq,
            now,
            Payload::json(body.to_string().into_bytes()),
        );
    }

    /// Republishes every robot's `/<robot>/rosout` of type [`LOG_TYPE`] on `/rosout`, and
    /// watches links and drops, until `shutdown`.
    pub async fn run(self: Arc<Self>, registry: Arc<Registry>, shutdown: CancellationToken) {
        let (relay, outbox) = self.router.connect(
            ClientKind::Internal {
                role: "rosout_relay".into(),
            },
            None,
        );
        let pattern = Router::compile_pattern("/[^/]+/rosout").expect("a constant pattern");
        let _ = self
            .router
            .subscribe(relay, Target::Pattern(pattern), SubOptions::default());
        let mut watch = Watch::default();
        let mut tick = tokio::time::interval(WATCH_EVERY);
        tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
        loop {
            let batch = outbox.take(256, 4 << 20, Instant::now());
            for (_, _, m) in &batch.items {
                if same_type(&m.topic.schema.type_name, LOG_TYPE) {
                    let seq = self.seq.fetch_add(1, Relaxed) + 1;
                    self.topic
                        .publish(self.client, seq, m.stamp_ns, m.payload.clone());
                }
            }
            if !batch.items.is_empty() {
                continue;
            }
            tokio::select! {
                _ = outbox.ready() => {}
                _ = tick.tick() => watch.look(&self, &registry),
                _ = shutdown.cancelled() => break,
            }
        }
        self.router.disconnect(relay);
    }
}

/// What was reported already, so a state is logged when it changes, not every tick.
#[derive(Default)]
struct Watch {
    degraded: HashSet<String>,
    drops: HashMap<(TopicName, DropReason), u64>,
    /// [`fleetlink_relay::stats::drops_anywhere`] at the last walk of the topics.
    drops_seen: u64,
}

impl Watch {
    fn look(&mut self, out: &RosOut, registry: &Registry) {
        for r in registry.list() {
            let rtt = Duration::from_nanos(r.rtt_ns.load(Relaxed));
            let bad = rtt > DEGRADED_RTT;
            if bad && self.degraded.insert(r.name.clone()) {
                out.log(
                    Level::Warn,
                    "link",
                    format!(
                        "robot {} link degraded: heartbeat round trip {} ms",
                        r.name,
                        rtt.as_millis()
                    ),
                );
            } else if !bad && self.degraded.remove(&r.name) {
                out.log(
                    Level::Info,
                    "link",
                    format!(
                        "robot {} link recovered: round trip {} ms",
                        r.name,
                        rtt.as_millis()
                    ),
                );
            }
        }
        let online: HashSet<String> = registry.list().iter().map(|r| r.name.clone()).collect();
        self.degraded.retain(|n| online.contains(n));
        // The topics are walked only when some topic lost a message since the last look.
        let drops = fleetlink_relay::stats::drops_anywhere();
        if drops == self.drops_seen {
            return;
        }
        self.drops_seen = drops;
        let topics = out.router.topics();
        let names: HashSet<&TopicName> = topics.iter().map(|t| &t.meta.name).collect();
        self.drops.retain(|(n, _), _| names.contains(n));
        for t in &topics {
            if t.meta.name.as_str() == "/rosout" {
                continue;
            }
            for reason in DropReason::ALL {
                let now = t.stats.drops(reason);
                if now == 0 {
                    // Nothing lost, nothing to remember: most topics of a large fleet.
                    continue;
                }
                let before = self
                    .drops
                    .insert((t.meta.name.clone(), reason), now)
                    .unwrap_or(0);
                // Rate limits are what subscribers asked for; only losses are news.
                if now > before && reason != DropReason::RateLimit {
                    out.log(
                        Level::Warn,
                        "drops",
                        format!(
                            "{} messages of {} dropped in the last {} s ({})",
                            now - before,
                            t.meta.name,
                            WATCH_EVERY.as_secs(),
                            reason.as_str()
                        ),
                    );
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fleetlink_relay::transcode::RegistryTranscoder;

    /// The `/rosout` lines about drops published since the last call.
    fn drop_lines(outbox: &fleetlink_relay::Outbox) -> Vec<String> {
        let mut items = Vec::new();
        outbox.take_into(&mut items, 1000, usize::MAX, Instant::now());
        items
            .iter()
            .map(|(_, _, m)| String::from_utf8_lossy(&m.payload.bytes).into_owned())
            .filter(|t| t.contains("dropped"))
            .collect()
    }

    #[test]
    fn drops_are_told_once_and_topics_are_walked_only_after_some() {
        let router = Arc::new(Router::new(Arc::new(RegistryTranscoder::bundled())));
        let out = RosOut::start(router.clone());
        let (reader, outbox) = router.connect(
            ClientKind::Internal {
                role: "test".into(),
            },
            None,
        );
        let rosout = TopicName::parse("/rosout").unwrap();
        router
            .subscribe(reader, Target::Exact(rosout), SubOptions::default())
            .unwrap();
        let (robot, _) = router.connect(ClientKind::Internal { role: "sim".into() }, None);
        let name = TopicName::parse("/r1/scan").unwrap();
        let topic = router
            .advertise(robot, &name, Schema::named("std_msgs/String"), false)
            .unwrap();
        let registry = Registry::default();
        let mut watch = Watch::default();
        watch.look(&out, &registry);
        assert!(drop_lines(&outbox).is_empty());
        for _ in 0..3 {
            topic.stats.record_drop(DropReason::Policy);
        }
        watch.look(&out, &registry);
        let lines = drop_lines(&outbox);
        assert_eq!(lines.len(), 1, "{lines:?}");
        assert!(
            lines[0].contains("3 messages of /r1/scan dropped"),
            "{lines:?}"
        );
        // Nothing new: nothing said, and the topics were not walked for it.
        watch.look(&out, &registry);
        assert!(drop_lines(&outbox).is_empty());
        assert_eq!(
            watch.drops_seen,
            fleetlink_relay::stats::drops_anywhere(),
            "the walk is remembered by the drop count it saw"
        );
    }
}
