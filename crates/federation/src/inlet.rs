//! What this hub takes of a topic other hubs send it, while someone here wants it.
//!
//! One Zenoh subscriber per wanted topic listens to every hub's key for it
//! (`t/*/<topic>`), so that a robot moving to another hub is heard from its first message
//! there: a subscriber declared only once that hub's offer arrived would miss what it
//! sends meanwhile — the no-drop messages the robot resends on arrival first. Each
//! message is then taken by the hub it came from ([`Inlet::take`]):
//!
//! - from a hub **admitted and offering** the topic: through this hub's gate for that hub
//!   (a rule naming the hub can deny it), once per no-drop number, published here, and
//!   audited when it acts on a robot here;
//! - from a hub **admitted but not offering it (yet)**: held, in order, for at most
//!   [`HOLD`] and [`HOLD_MAX`] messages, then published if its offer comes, dropped if
//!   not — a hub publishes into a topic only what it offers;
//! - from anyone else: dropped and counted.
//!
//! A video topic whose chain broke here, or whose new viewer found nothing kept, asks the
//! offering hubs for a keyframe ([`crate::keyframes`]): looked at after each message
//! published and whenever the topics loop sets the offering hubs.

use std::collections::{HashMap, VecDeque};
use std::sync::atomic::Ordering::Relaxed;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use bytes::Bytes;
use fleetlink_hub::security::HubGate;
use fleetlink_proto::Payload;
use fleetlink_relay::gate::{Gate, Op};
use fleetlink_relay::{Topic, TopicName};

use crate::keyframes::Asker;
use crate::keys::{MessageHeader, StreamMark};
use crate::{ImportFigures, Shared};

/// How long messages of a hub wait for its offer.
pub const HOLD: Duration = Duration::from_secs(5);
/// How many messages of one hub wait for its offer.
pub const HOLD_MAX: usize = 4096;

/// One wanted topic's intake (shared by its Zenoh callback and the topics loop).
pub struct Inlet {
    topic: Arc<Topic>,
    name: TopicName,
    shared: Arc<Shared>,
    figures: Arc<ImportFigures>,
    asker: Arc<Asker>,
    // std Mutex: taken by the Zenoh callback per message and by the topics loop when
    // offers change; never held across an await.
    state: Mutex<State>,
}

#[derive(Default)]
struct State {
    /// No-drop numbering: a robot that moved between hubs is heard from both, and each
    /// message is published once.
    mark: StreamMark,
    /// The admitted hubs offering the topic (as the topics loop sets them), each with
    /// this hub's gate for it.
    from: HashMap<String, HubGate>,
    /// Messages of admitted hubs whose offer has not arrived yet, oldest first. Only
    /// admitted hubs are held, at most [`HOLD_MAX`] messages each (past it the oldest is
    /// dropped and counted); what waited longer than [`HOLD`] is dropped the next time a
    /// hub not offering sends or the offering hubs are set.
    held: HashMap<String, VecDeque<(Instant, MessageHeader, Bytes)>>,
    /// Hubs whose messages a rule refused, told once: at most one per hub that offered
    /// the topic while it was wanted here.
    told: std::collections::HashSet<String>,
}

impl Inlet {
    pub fn new(
        topic: Arc<Topic>,
        shared: Arc<Shared>,
        figures: Arc<ImportFigures>,
        asker: Arc<Asker>,
    ) -> Arc<Inlet> {
        Arc::new(Inlet {
            name: topic.name(),
            topic,
            shared,
            figures,
            asker,
            state: Mutex::new(State::default()),
        })
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Whether any hub's messages are taken now.
    pub fn has_sources(&self) -> bool {
        !self.lock().from.is_empty()
    }

    /// The admitted hubs that offer the topic now: new ones get a gate, and what they
    /// sent before their offer arrived is published in order. A keyframe wanted here
    /// (a viewer came with nothing to show) is asked of them.
    pub fn set_offerers<'h>(&self, hubs: impl IntoIterator<Item = &'h String>, now: Instant) {
        let hubs: Vec<&String> = hubs
            .into_iter()
            .filter(|h| self.shared.admission.is_admitted(h))
            .collect();
        let mut st = self.lock();
        st.from.retain(|h, _| hubs.contains(&h));
        for hub in hubs {
            if st.from.contains_key(hub) {
                continue;
            }
            st.from.insert(hub.clone(), self.shared.hub_gate(hub));
            let held = st.held.remove(hub).unwrap_or_default();
            for (at, header, bytes) in held {
                if now.duration_since(at) <= HOLD {
                    self.deliver(&mut st, hub, header, bytes);
                } else {
                    self.shared.counters.refused.fetch_add(1, Relaxed);
                }
            }
        }
        self.expire(&mut st, now);
        self.ask_keyframe(&st);
    }

    /// A message hub `hub` put under the topic's key.
    pub fn take(&self, hub: &str, header: MessageHeader, bytes: Bytes, now: Instant) {
        let mut st = self.lock();
        if st.from.contains_key(hub) {
            self.deliver(&mut st, hub, header, bytes);
            self.ask_keyframe(&st);
            return;
        }
        self.expire(&mut st, now);
        if !self.shared.admission.is_admitted(hub) {
            self.shared.counters.refused.fetch_add(1, Relaxed);
            return;
        }
        let queue = st.held.entry(hub.to_owned()).or_default();
        if queue.len() >= HOLD_MAX {
            queue.pop_front();
            self.shared.counters.refused.fetch_add(1, Relaxed);
        }
        queue.push_back((now, header, bytes));
    }

    /// Asks the offering hubs for a keyframe if the router here wants one.
    fn ask_keyframe(&self, st: &State) {
        self.asker
            .ask_if_wanted(&self.topic, &self.name, st.from.keys());
    }

    /// Drops what waited longer than [`HOLD`] for an offer that did not come.
    fn expire(&self, st: &mut State, now: Instant) {
        let counters = &self.shared.counters;
        st.held.retain(|_, q| {
            while q
                .front()
                .is_some_and(|(at, _, _)| now.duration_since(*at) > HOLD)
            {
                q.pop_front();
                counters.refused.fetch_add(1, Relaxed);
            }
            !q.is_empty()
        });
    }

    /// Publishes a message of offering hub `hub` here, if this hub's rules let that hub.
    fn deliver(&self, st: &mut State, hub: &str, header: MessageHeader, bytes: Bytes) {
        let counters = &self.shared.counters;
        let State {
            mark, from, told, ..
        } = st;
        let Some(gate) = from.get_mut(hub) else {
            return;
        };
        if !gate.allows_topic(self.topic.id().0, self.name.as_str(), Op::Publish) {
            counters.refused.fetch_add(1, Relaxed);
            if told.insert(hub.to_owned()) {
                tracing::warn!(
                    "federation: {} may not publish {} here (a rule denies it): its messages are dropped",
                    gate.principal(),
                    self.name
                );
            }
            return;
        }
        if let Some(epoch) = header.reliable
            && !mark.admit(epoch, header.seq)
        {
            counters.duplicates.fetch_add(1, Relaxed);
            return;
        }
        let size = bytes.len();
        counters.received.fetch_add(1, Relaxed);
        counters.received_bytes.fetch_add(size as u64, Relaxed);
        self.figures.received.fetch_add(1, Relaxed);
        self.topic.publish(
            self.shared.client,
            header.seq,
            header.stamp_ns,
            Payload::new(header.encoding, bytes),
        );
        gate.done(self.name.as_str(), Op::Publish, size);
    }
}
