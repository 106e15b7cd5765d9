//! What the hub wants of a demand-driven uplink: `Demand` (wanted topics, each topic's
//! latest message, pull topics, age limits) and the outbox's calls that set or read it.
//! Apart because only a scheduled outbox has any of it.

use std::collections::{HashMap, HashSet};

use super::*;

/// Most payload bytes of all topics' latest messages kept, unless the owner sets another
/// bound ([`Outbox::set_latest_limit`]).
pub const LATEST_DEFAULT_LIMIT: usize = 64 << 20;

/// A demand-driven uplink (issue 37): while the hub says nobody wants a topic, its
/// messages are not sent; the latest one is kept and goes out at once when interest
/// comes, so a viewer does not wait for the next publish. Until the hub says it speaks
/// interest (`WELCOME_INTEREST`), everything flows.
#[derive(Default)]
pub(super) struct Demand {
    pub(super) driven: bool,
    /// Topics the hub wants.
    pub(super) wanted: HashSet<u32, IdHash>,
    /// Topics that flow whatever the demand: `always: true` and no-drop.
    pub(super) always: HashSet<u32, IdHash>,
    /// Each topic's latest message, all of them within `latest_limit` payload bytes
    /// (`latest_bytes` now): a topic whose newest message does not fit has none kept.
    pub(super) latest: HashMap<u32, Arc<Message>, IdHash>,
    pub(super) latest_bytes: usize,
    pub(super) latest_limit: usize,
    /// Held-back topics the writer has yet to announce on this connection (an idle topic
    /// still appears at the hub, which cannot want what it has not heard of), with a
    /// message of theirs to announce them by; and those already handed to it.
    pub(super) unannounced: HashMap<u32, Arc<Message>, IdHash>,
    pub(super) announced: HashSet<u32, IdHash>,
    /// Topics with an age limit (`max_age`): older messages are not sent.
    pub(super) max_age: HashMap<u32, Duration, IdHash>,
    /// Pull topics: sent only when asked ([`Outbox::pull`]).
    pub(super) pull: HashSet<u32, IdHash>,
    /// How each topic is compressed on the link (`compression: none` topics are absent),
    /// and whether the peer takes compressed messages at all (`WELCOME_COMPRESSION`).
    pub(super) compression: HashMap<u32, fleetlink_qos::Compression, IdHash>,
    pub(super) compress_allowed: bool,
}

impl Demand {
    /// Notes what `topic`'s QoS `q` asks of the demand (flows always, an age limit, pull,
    /// compression), replacing what an earlier QoS asked; returns `q` as the scheduler
    /// takes it.
    pub(super) fn follow_qos(&mut self, topic: u32, mut q: TopicQos, durable: bool) -> TopicQos {
        self.always.remove(&topic);
        self.max_age.remove(&topic);
        self.pull.remove(&topic);
        self.compression.remove(&topic);
        if q.always || q.no_drop {
            self.always.insert(topic);
        }
        if let Some(ms) = q.max_age_ms.filter(|_| !q.no_drop) {
            self.max_age.insert(topic, Duration::from_millis(ms));
        }
        if q.mode == fleetlink_qos::Mode::Pull && !q.no_drop {
            self.pull.insert(topic);
        }
        if q.compression != fleetlink_qos::Compression::None {
            self.compression.insert(topic, q.compression);
        }
        if q.no_drop && durable {
            // Waiting messages are on disk too: the journal's byte bound limits them,
            // not a count.
            q.queue = usize::MAX;
        }
        q
    }

    /// Keeps `msg` as its topic's latest, if it fits the bound with the others.
    pub(super) fn keep_latest(&mut self, topic: u32, msg: &Arc<Message>) {
        if let Some(old) = self.latest.remove(&topic) {
            self.latest_bytes -= old.payload.len();
        }
        let size = msg.payload.len();
        if self.latest_bytes + size <= self.latest_limit {
            self.latest_bytes += size;
            self.latest.insert(topic, msg.clone());
        }
    }

    pub(super) fn flows(&self, topic: u32) -> bool {
        if self.pull.contains(&topic) {
            return false;
        }
        !self.driven || self.wanted.contains(&topic) || self.always.contains(&topic)
    }

    /// Whether `msg` of `topic` is past its topic's age limit at `now`.
    pub(super) fn too_old(&self, topic: u32, msg: &Message, now: Instant) -> bool {
        self.max_age
            .get(&topic)
            .is_some_and(|age| now.saturating_duration_since(msg.received()) > *age)
    }

    /// See [`Outbox::set_latest_limit`].
    fn set_latest_limit(&mut self, bytes: usize) {
        self.latest_limit = bytes;
        if self.latest_bytes > bytes {
            self.latest.clear();
            self.latest_bytes = 0;
        }
    }

    /// See [`Outbox::take_unannounced`].
    fn take_unannounced(&mut self, out: &mut Vec<Arc<Message>>) {
        let Demand {
            unannounced,
            announced,
            ..
        } = self;
        for (t, m) in unannounced.drain() {
            announced.insert(t);
            out.push(m);
        }
    }

    /// See [`Outbox::reads`].
    fn reads(&self, alias: u32) -> bool {
        self.flows(alias) || self.pull.contains(&alias)
    }

    /// See [`Outbox::asked_for`].
    fn asked_for(&self, alias: u32) -> bool {
        (self.driven && self.flows(alias)) || self.pull.contains(&alias)
    }

    /// See [`Outbox::forget_latest`].
    fn forget_latest(&mut self, alias: u32) {
        if let Some(old) = self.latest.remove(&alias) {
            self.latest_bytes -= old.payload.len();
        }
    }
}

impl Outbox {
    /// Most payload bytes of topics' latest messages this (scheduled) outbox keeps, all
    /// topics together; 0 keeps none.
    pub fn set_latest_limit(&self, bytes: usize) {
        self.with_uplink(|u| u.demand.set_latest_limit(bytes));
    }

    /// Whether the peer tells this (scheduled) outbox which topics it wants: from now on a
    /// topic nobody wants is held back. `false` (an older hub) lets everything flow.
    pub fn set_demand_driven(&self, driven: bool) {
        self.with_uplink(|u| u.demand.driven = driven);
        self.notify.notify_one();
        self.interest.notify_waiters();
    }

    /// The peer wants the topic with link alias `alias` (or no longer does). When it
    /// starts to, the topic's latest message goes out at once unless one is queued.
    pub fn set_wanted(&self, alias: u32, wanted: bool, now: Instant) {
        let mut st = self.lock();
        let st = &mut *st;
        if let Service::Scheduled(u) = &mut st.service {
            u.set_wanted(
                alias,
                wanted,
                now,
                &mut st.queued,
                &self.interest,
                &self.notify,
            );
        }
    }

    /// The peer asks for one message of the pull topic with link alias `alias`: its latest
    /// goes out (unless it has none, or none within its age limit). Pulled messages are
    /// taken even though the topic does not flow.
    pub fn pull(&self, alias: u32, now: Instant) {
        let mut st = self.lock();
        if let Service::Scheduled(u) = &mut st.service
            && u.pull(alias, now)
        {
            self.notify.notify_one();
        }
    }

    /// A message of each held-back topic not yet announced on this connection: the writer
    /// announces their topics (`ADVERTISE`) without sending them.
    pub fn take_unannounced(&self, out: &mut Vec<Arc<Message>>) {
        if !self.scheduled {
            return;
        }
        self.with_uplink(|u| u.demand.take_unannounced(out));
    }

    /// The writer withdrew the topic with link alias `alias` (`UNADVERTISE`): if it is
    /// published again while held back, it is announced again.
    pub fn forget_announced(&self, alias: u32) {
        self.with_uplink(|u| {
            u.demand.announced.remove(&alias);
        });
    }

    /// Whether the topic with link alias `alias` needs reading from its source for this
    /// link: it is sent (wanted, `always`, no-drop, or a peer that does not say what it
    /// wants) or a pull topic (its latest message must be at hand).
    pub fn reads(&self, alias: u32) -> bool {
        self.with_uplink(|u| u.demand.reads(alias)).unwrap_or(true)
    }

    /// Whether the peer has asked for `alias`: [`Outbox::reads`], but a peer that has not
    /// said what it wants (not connected yet, or a hub that sends everything) asks for
    /// nothing. For what costs the robot to make, not merely to read (a video encoder).
    pub fn asked_for(&self, alias: u32) -> bool {
        self.with_uplink(|u| u.demand.asked_for(alias))
            .unwrap_or(true)
    }

    /// [`Outbox::reads`] of the topic a slot of this outbox receives (false for a slot it
    /// no longer has).
    pub fn reads_slot(&self, slot: SlotId) -> bool {
        let st = self.lock();
        let Some(topic) = st.slots.get(&slot).map(|s| s.topic) else {
            return false;
        };
        match &st.service {
            Service::Scheduled(u) => u.demand.reads(topic),
            Service::RoundRobin { .. } => true,
        }
    }

    /// Returns when the peer's demand next changes (a topic wanted or let go, interest
    /// turned on or off).
    pub async fn interest_changed(&self) {
        self.interest.notified().await
    }

    /// Lets go of the latest message kept for topic `alias`.
    pub fn forget_latest(&self, alias: u32) {
        self.with_uplink(|u| u.demand.forget_latest(alias));
    }

    /// Whether the topic with link alias `alias` is held back (nobody wants it).
    pub fn is_held_back(&self, alias: u32) -> bool {
        self.with_uplink(|u| !u.demand.flows(alias))
            .unwrap_or(false)
    }
}
