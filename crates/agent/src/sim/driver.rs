//! Runs a [`Sim`] in real time: publishes its messages into the agent's local router at
//! their due times, as an in-process participant. The simulator itself stays sans-IO;
//! this is the only part that looks at a clock.

use std::sync::Arc;
use std::time::{Duration, Instant};

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::{ClientKind, Router, TopicName};
use tokio_util::sync::CancellationToken;

use super::Sim;
use crate::config::SimConfig;

pub async fn drive(
    cfg: SimConfig,
    robot: String,
    router: Arc<Router>,
    shutdown: CancellationToken,
) {
    let mut sim = Sim::new(&cfg, &robot, fleetlink_relay::unix_nanos());
    let (client, _) = router.connect(ClientKind::Internal { role: "sim".into() }, None);
    let mut topics = Vec::new();
    for t in sim.topics() {
        let topic = TopicName::parse(&t.name)
            .map_err(|e| e.to_string())
            .and_then(|n| {
                router
                    .advertise(client, &n, Schema::named(t.type_name), false)
                    .map_err(|e| e.to_string())
            });
        match topic {
            Ok(topic) => topics.push(Some((topic, 0u64))),
            Err(e) => {
                tracing::warn!("simulator cannot publish {}: {e}", t.name);
                topics.push(None);
            }
        }
    }
    let start = Instant::now();
    let mut due = Vec::new();
    loop {
        let wait = sim.next_due().saturating_sub(start.elapsed());
        tokio::select! {
            _ = tokio::time::sleep(wait.max(Duration::from_micros(100))) => {}
            _ = shutdown.cancelled() => break,
        }
        due.clear();
        sim.poll_into(start.elapsed(), &mut due);
        for m in due.drain(..) {
            if let Some(Some((topic, seq))) = topics.get_mut(m.topic_index) {
                *seq += 1;
                // A ROS 2 robot publishes CDR; do the same when the type is known, so the
                // hub converts once per subscriber encoding and `cbor-raw` has raw bytes.
                let json = Payload::json(m.json);
                let payload = router
                    .transcoder()
                    .convert(&topic.meta().schema, &json, Encoding::Cdr)
                    .map(|b| Payload::new(Encoding::Cdr, b))
                    .unwrap_or(json);
                topic.publish(client, *seq, m.stamp_ns, payload);
            }
        }
    }
    router.disconnect(client);
}
