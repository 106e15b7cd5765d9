//! Local topics sent up: a DDS reader per bridged topic, feeding the router.
//!
//! Discovery ([`super::discover`]) starts a topic when local writers of it appear and
//! stops it when they are gone; in between, its reader is dropped while nobody wants the
//! topic ([`follow_interest`]) and made again from what its [`Reading`] kept.

use std::collections::HashSet;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::Instant;

use fleetlink_proto::{Encoding, Payload};
use fleetlink_relay::read_interest::Look;
use fleetlink_relay::router::RouteError;
use fleetlink_relay::{Topic, TopicName};
use futures::StreamExt;
use rustdds::{GUID, QosPolicies};
use tokio::task::AbortHandle;

use super::{Bridge, RawReader};
use crate::names;

/// A local topic sent up: its router topic, the writers feeding it, its reader task
/// (none while nobody wants the topic read), and what makes its reader again.
pub(super) struct Up {
    pub(super) writers: HashSet<GUID>,
    pub(super) task: Option<AbortHandle>,
    reading: Arc<Reading>,
    /// Since when nobody has wanted it, while that lasts.
    unwanted_since: Option<Instant>,
}

/// What a bridged-up topic's reader is made from, kept while the topic is not read.
pub(super) struct Reading {
    dds_topic: String,
    dds_type: String,
    qos: QosPolicies,
    topic: Arc<Topic>,
    /// Numbers of the messages put into the router, across readers.
    seq: AtomicU64,
}

/// Drops the reader of each topic nobody has wanted for a while
/// ([`ReadInterest::look`](fleetlink_relay::read_interest::ReadInterest::look); the local
/// writers then stop sending to the agent) and makes one again for each topic wanted
/// again.
pub(super) fn follow_interest(bridge: &Arc<Bridge>, now: Instant) {
    let Some(interest) = &bridge.interest else {
        return;
    };
    let mut resume = Vec::new();
    {
        let mut st = bridge.lock();
        for (ros, up) in st.up.iter_mut() {
            let name = up.reading.topic.name();
            match interest.look(&name, bridge.client, &mut up.unwanted_since, now) {
                Look::Read if up.task.is_none() => resume.push(ros.clone()),
                Look::Stop => {
                    if let Some(task) = up.task.take() {
                        task.abort(); // the reader goes with its task
                        interest.stopped_reading(&name);
                        bridge.stats.paused_reading.fetch_add(1, Relaxed);
                        tracing::info!("ros2: nobody wants {ros}; no longer reading it");
                    }
                }
                _ => {}
            }
        }
    }
    for ros in resume {
        let Some(reading) = bridge.lock().up.get(&ros).map(|u| u.reading.clone()) else {
            continue;
        };
        match bridge.reader(&reading.dds_topic, &reading.dds_type, reading.qos.clone()) {
            Ok(reader) => {
                let task = tokio::spawn(pump_up(bridge.clone(), reading, reader)).abort_handle();
                if let Some(up) = bridge.lock().up.get_mut(&ros) {
                    up.task = Some(task);
                }
                tracing::info!("ros2: {ros} is wanted again; reading it");
            }
            Err(e) => tracing::warn!("ros2: cannot read {ros} again: {e}"),
        }
    }
}

/// Starts bridging local topic `ros` up, with a reader matching its first writer.
pub(super) fn start_up(
    bridge: &Arc<Bridge>,
    ros: &str,
    writers: &[rustdds::discovery::DiscoveredWriterData],
) {
    let p = &writers[0].publication_topic_data;
    let Some(ros_type) = names::ros_type(&p.type_name) else {
        bridge.report_once(ros, &bridge.stats.unknown_types, || {
            format!(
                "ros2: not bridging {ros}: its DDS type {:?} is not a ROS 2 type name (pkg::msg::dds_::T_)",
                p.type_name
            )
        });
        return;
    };
    let Some(schema) = bridge.schema(&ros_type) else {
        bridge.report_once(ros, &bridge.stats.unknown_types, || {
            format!(
                "ros2: not bridging {ros}: type {ros_type} is unknown to the agent's registry; \
                 give the agent its package with --msg-path DIR (DIR/<package>/msg/<Type>.msg)"
            )
        });
        return;
    };
    let Ok(name) = TopicName::parse(ros) else {
        return;
    };
    // Latched when any writer keeps its last message for late readers.
    let latched = writers.iter().any(|w| {
        matches!(
            w.publication_topic_data.durability,
            Some(rustdds::policy::Durability::TransientLocal)
        )
    });
    let reliable = writers.iter().all(|w| {
        !matches!(
            w.publication_topic_data.reliability,
            Some(rustdds::policy::Reliability::BestEffort)
        )
    });
    let qos = crate::qos::reader_for(
        Some(if reliable {
            rustdds::policy::Reliability::Reliable {
                max_blocking_time: rustdds::Duration::from_millis(100),
            }
        } else {
            rustdds::policy::Reliability::BestEffort
        }),
        latched.then_some(rustdds::policy::Durability::TransientLocal),
        crate::qos::reader_depth(&ros_type),
    );
    let topic = match bridge
        .router
        .advertise(bridge.client, &name, schema, latched)
    {
        Ok(t) => t,
        Err(RouteError::TypeConflict { existing, .. }) => {
            bridge.report_once(ros, &bridge.stats.type_mismatches, || {
                format!(
                    "ros2: type mismatch on {ros}: the agent's topic is {existing}, local writers send {ros_type}; \
                     {ros} is not bridged, other topics are unaffected"
                )
            });
            return;
        }
        Err(e) => {
            tracing::warn!("ros2: cannot bridge {ros}: {e}");
            return;
        }
    };
    let reader = match bridge.reader(&p.topic_name, &p.type_name, qos.clone()) {
        Ok(r) => r,
        Err(e) => {
            tracing::warn!("ros2: cannot bridge {ros}: {e}");
            bridge.router.unadvertise(bridge.client, &name);
            return;
        }
    };
    tracing::info!(
        "ros2: receiving {ros} ({ros_type}{}{})",
        if latched { ", latched" } else { "" },
        if reliable { "" } else { ", best effort" }
    );
    let reading = Arc::new(Reading {
        dds_topic: p.topic_name.clone(),
        dds_type: p.type_name.clone(),
        qos,
        topic,
        seq: AtomicU64::new(0),
    });
    let task = tokio::spawn(pump_up(bridge.clone(), reading.clone(), reader)).abort_handle();
    bridge.lock().up.insert(
        ros.to_owned(),
        Up {
            writers: writers
                .iter()
                .map(|w| w.publication_topic_data.key)
                .collect(),
            task: Some(task),
            reading,
            unwanted_since: None,
        },
    );
}

/// `ros` is no longer bridged (its local writers are gone, or `publish` no longer has it):
/// stop reading it and unadvertise it.
pub(super) fn stop_up(bridge: &Bridge, ros: &str) {
    let Some(up) = bridge.lock().up.remove(ros) else {
        return;
    };
    if let Some(task) = up.task {
        task.abort();
    }
    if let Ok(name) = TopicName::parse(ros) {
        bridge.router.unadvertise(bridge.client, &name);
    }
}

/// Forwards a reader's samples to the router as they arrived.
async fn pump_up(bridge: Arc<Bridge>, reading: Arc<Reading>, reader: RawReader) {
    let topic = &reading.topic;
    let mut samples = reader.async_sample_stream();
    while let Some(r) = samples.next().await {
        match r {
            Ok(sample) => {
                // Our own writer on the same topic (bridged both ways): never back up.
                if bridge.is_own(sample.sample_info().writer_guid()) {
                    continue;
                }
                let seq = reading.seq.fetch_add(1, Relaxed) + 1;
                topic.publish(
                    bridge.client,
                    seq,
                    fleetlink_relay::unix_nanos(),
                    Payload::new(Encoding::Cdr, sample.into_value().0),
                );
                bridge.stats.messages_up.fetch_add(1, Relaxed);
            }
            Err(e) => tracing::debug!("ros2: reading {}: {e}", topic.name()),
        }
    }
}
