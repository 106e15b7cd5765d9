//! Router topics written into the graph: which ones the bridge subscribes (those the
//! options name, those a local node reads), and a DDS writer per topic that holds its
//! first messages until the local readers are matched ([`Held`]).

use std::collections::HashSet;
use std::sync::atomic::Ordering::Relaxed;
use std::time::Instant;

use bytes::Bytes;
use fleetlink_relay::router::{SubOptions, SubscriptionId, Target};
use fleetlink_relay::{Message, TopicName};
use rustdds::StatusEvented;

use super::{Bridge, RawWriter, Stats};
use crate::names::{self, DdsName};
use crate::raw::RawCdr;

/// A router topic written into the graph.
pub(super) struct Down {
    writer: RawWriter,
    type_name: String,
    /// Set while a new writer waits to be matched (see [`Held`]).
    held: Option<Held>,
}

/// How long a new writer's first messages wait for the local readers DDS discovery knew
/// of when the writer was made.
const DOWN_MATCH_WAIT: std::time::Duration = std::time::Duration::from_millis(1000);

/// How long held messages still wait once the bridge's writer has matched the readers:
/// matching is two-sided, and DDS tells only the writer's side. The reader's side takes
/// the writer's announcement on its own discovery thread (Cyclone: a queue of its own),
/// and until it has, it drops what the writer sends. On a loaded machine that took
/// longer than sending the first message right after the writer's side matched (the
/// ROS 2 suite's step 2c failed once in CI that way).
const DOWN_REMOTE_GRACE: std::time::Duration = std::time::Duration::from_millis(150);

/// A new writer's messages, held until it has matched the local readers of its topic
/// that discovery knew of when it was made, and [`DOWN_REMOTE_GRACE`] more (or until
/// [`DOWN_MATCH_WAIT`] has passed). A volatile reader only gets what is written after it
/// is matched: without this, a node waiting for a hub topic missed its first message,
/// written while DDS was still matching the bridge's new writer with it.
struct Held {
    readers: i32,
    until: Instant,
    /// When the writer's side had matched every known reader.
    matched_at: Option<Instant>,
    bodies: std::collections::VecDeque<Bytes>,
}

impl Down {
    /// Whether held messages may go: every known reader matched, or waited long enough.
    fn matched(&mut self, now: Instant) -> bool {
        let Some(h) = &mut self.held else {
            return true;
        };
        while let Some(ev) = self.writer.try_recv_status() {
            if let rustdds::DataWriterStatus::PublicationMatched { current, .. } = ev
                && current.count() >= h.readers
            {
                h.matched_at.get_or_insert(now);
            }
        }
        h.matched_at
            .is_some_and(|t| now.duration_since(t) >= DOWN_REMOTE_GRACE)
            || now >= h.until
    }

    /// Writes `body`, or holds it while the writer is not matched yet (the oldest held
    /// message is dropped beyond the writer's depth, as its history would).
    fn write(&mut self, body: Bytes, stats: &Stats) {
        let now = Instant::now();
        if !self.matched(now) {
            let h = self.held.as_mut().expect("held while not matched");
            h.bodies.push_back(body);
            if h.bodies.len() > crate::qos::DEPTH as usize {
                h.bodies.pop_front();
                stats.dropped_down.fetch_add(1, Relaxed);
            }
            return;
        }
        for b in self.held.take().map(|h| h.bodies).unwrap_or_default() {
            self.write_now(b, stats);
        }
        self.write_now(body, stats);
    }

    /// Sends what was held once the writer is matched or the wait is over.
    fn release(&mut self, stats: &Stats) {
        if self.held.is_some() && self.matched(Instant::now()) {
            for b in self.held.take().map(|h| h.bodies).unwrap_or_default() {
                self.write_now(b, stats);
            }
        }
    }

    fn write_now(&self, body: Bytes, stats: &Stats) {
        match self.writer.write(RawCdr(body), None) {
            Ok(()) => {
                stats.messages_down.fetch_add(1, Relaxed);
            }
            Err(e) => {
                stats.dropped_down.fetch_add(1, Relaxed);
                tracing::debug!("ros2: writing a {} message: {e:?}", self.type_name);
            }
        }
    }
}

/// Subscribes the router topics the options write into the graph, and lets go of those
/// they no longer do (with their DDS writers).
pub(super) fn follow_subscriptions(bridge: &Bridge) {
    let opts = bridge.live();
    let gone: Vec<(String, SubscriptionId)> = {
        let mut st = bridge.lock();
        let names: Vec<String> = st
            .subscribed
            .keys()
            .filter(|k| !opts.subscribe.iter().any(|n| n.as_str() == k.as_str()))
            .cloned()
            .collect();
        names
            .into_iter()
            .filter_map(|k| {
                st.down.remove(&k);
                st.subscribed.remove_entry(&k)
            })
            .collect()
    };
    for (name, sid) in gone {
        bridge.router.unsubscribe(bridge.client, sid);
        tracing::info!("ros2: no longer writing {name} into the graph");
    }
    for name in &opts.subscribe {
        if bridge.lock().subscribed.contains_key(name.as_str()) {
            continue;
        }
        match bridge.router.subscribe(
            bridge.client,
            Target::Exact(name.clone()),
            SubOptions::default(),
        ) {
            Ok(sid) => {
                bridge.lock().subscribed.insert(name.to_string(), sid);
            }
            Err(e) => tracing::warn!("ros2: cannot subscribe to {name}: {e}"),
        }
    }
}

/// Subscribes the router topics `read` matches that a node of the graph reads (a reader
/// other than the bridge's), and lets go of those whose last reader went: what no node
/// reads is not asked for, so its robot does not send it.
pub(super) fn follow_readers(bridge: &Bridge) {
    let opts = bridge.live();
    if opts.read.is_empty() && bridge.lock().read.is_empty() {
        return;
    }
    let mut readers: HashSet<String> = HashSet::new();
    for r in bridge.dp.discovered_readers() {
        let s = &r.subscription_topic_data;
        if bridge.is_own(s.key()) {
            continue;
        }
        if let Some(DdsName::Topic(ros)) = DdsName::parse(s.topic_name())
            && !names::is_hidden(&ros)
            && opts.read.matches(&ros)
            && !opts.subscribe.iter().any(|n| n.as_str() == ros)
        {
            readers.insert(ros);
        }
    }
    let (gone, new): (Vec<(String, SubscriptionId)>, Vec<String>) = {
        let mut st = bridge.lock();
        let gone: Vec<String> = st
            .read
            .keys()
            .filter(|k| !readers.contains(*k))
            .cloned()
            .collect();
        let gone = gone
            .into_iter()
            .filter_map(|k| st.read.remove_entry(&k))
            .collect();
        let new = readers
            .into_iter()
            .filter(|k| !st.read.contains_key(k))
            .collect();
        (gone, new)
    };
    for (ros, sid) in gone {
        bridge.router.unsubscribe(bridge.client, sid);
        tracing::info!("ros2: no node reads {ros} any more; no longer asking for it");
    }
    for ros in new {
        let name = match TopicName::parse(&ros) {
            Ok(n) => n,
            Err(e) => {
                tracing::debug!("ros2: a reader of {ros}, which is no topic name here: {e}");
                continue;
            }
        };
        match bridge
            .router
            .subscribe(bridge.client, Target::Exact(name), SubOptions::default())
        {
            Ok(sid) => {
                tracing::info!("ros2: a node reads {ros}; asking for it");
                bridge.lock().read.insert(ros, sid);
            }
            Err(e) => tracing::warn!("ros2: cannot ask for {ros}: {e}"),
        }
    }
}

/// A router message for the graph, written by the topic's writer (created on the first
/// message, with the topic's type and latching).
pub(super) fn down(bridge: &Bridge, msg: &Message) {
    let name = msg.topic.name.as_str();
    let mut st = bridge.lock();
    let entry = st
        .down
        .entry(name.to_owned())
        .or_insert_with(|| create_down(bridge, msg));
    let Some(d) = entry else {
        bridge.stats.dropped_down.fetch_add(1, Relaxed);
        return;
    };
    let body = match bridge.to_cdr(&d.type_name, &msg.payload) {
        Ok(b) => b,
        Err(e) => {
            bridge.stats.dropped_down.fetch_add(1, Relaxed);
            tracing::debug!("ros2: dropping a message of {name}: {e}");
            return;
        }
    };
    d.write(body, &bridge.stats);
}

/// Whether a new writer holds messages ([`Held`]).
pub(super) fn holding(bridge: &Bridge) -> bool {
    bridge
        .lock()
        .down
        .values()
        .any(|d| d.as_ref().is_some_and(|d| d.held.is_some()))
}

/// Sends held messages of writers now matched (or done waiting).
pub(super) fn release_held(bridge: &Bridge) {
    let mut st = bridge.lock();
    for d in st.down.values_mut().flatten() {
        d.release(&bridge.stats);
    }
}

/// The writer of a router topic; `None` (remembered, reported once) when its type cannot
/// be written.
fn create_down(bridge: &Bridge, msg: &Message) -> Option<Down> {
    let name = msg.topic.name.as_str();
    let type_name = &msg.topic.schema.type_name;
    let Some(dds_type) = names::dds_type(type_name) else {
        tracing::warn!(
            "ros2: cannot write {name} into the graph: {type_name:?} is not a ROS type name"
        );
        return None;
    };
    let latched = bridge
        .router
        .topic(&msg.topic.name)
        .is_some_and(|t| t.is_latched());
    let dds_topic = names::topic(name);
    match bridge.writer(&dds_topic, &dds_type, crate::qos::writer(latched)) {
        Ok(writer) => {
            // Local readers already waiting for the topic: the first messages wait for
            // them to be matched.
            let readers = bridge
                .dp
                .discovered_readers()
                .iter()
                .filter(|r| {
                    let s = &r.subscription_topic_data;
                    s.topic_name() == &dds_topic && !bridge.is_own(s.key())
                })
                .count();
            tracing::info!(
                "ros2: writing {name} ({type_name}{}) into the graph, {readers} local reader(s) known",
                if latched { ", transient local" } else { "" }
            );
            let held = (readers > 0).then(|| Held {
                readers: i32::try_from(readers).unwrap_or(i32::MAX),
                until: Instant::now() + DOWN_MATCH_WAIT,
                matched_at: None,
                bodies: Default::default(),
            });
            Some(Down {
                writer,
                type_name: type_name.clone(),
                held,
            })
        }
        Err(e) => {
            tracing::warn!("ros2: cannot write {name} into the graph: {e}");
            None
        }
    }
}
