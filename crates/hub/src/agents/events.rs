//! What a robot's link session reports, applied to the hub: its topics advertised and
//! published on the hub's router (checked by the robot's gate), its subscriptions, its
//! no-drop messages checked against the delivery marks, its link figures.
//!
//! Everything here is synchronous: it runs between two reads of the link, and what has
//! to wait (writing delivery marks to the database) is started by the driver.

use std::collections::HashMap;
use std::sync::atomic::Ordering::Relaxed;
use std::sync::{Arc, Mutex};

use fleetlink_proto::frame::{Frame, Level, SUBSCRIBE_REGEX, SUBSCRIBE_SERVICES, status_code};
use fleetlink_relay::gate::Op;
use fleetlink_relay::link::session::{Event, LinkSession};
use fleetlink_relay::link::{InTopic, LinkEvent};
use fleetlink_relay::message::Via;
use fleetlink_relay::router::{
    DemandWatch, Publication, SubOptions, SubscriptionId, Target, TopicView,
};
use fleetlink_relay::stats::StatsBatch;
use fleetlink_relay::{ClientId, DropReason, Message, Router, Topic, TopicId, TopicName};

use crate::delivery::RobotBook;
use crate::registry::LiveRobot;

struct PubTopic {
    topic: Arc<Topic>,
    /// Its id and name, kept for the per-message checks (the topic's own are behind an
    /// ArcSwap, whose load cost 2-4 % of a loaded hub's time when read per message).
    id: TopicId,
    name: TopicName,
    /// The robot's messages not yet added to the topic's counters, and the topic as of
    /// the robot's last message: both kept for one read of the link
    /// ([`RobotLink::end_of_read`]), as a rosbridge publisher keeps them for a burst.
    counts: StatsBatch,
    view: TopicView,
    unflushed: bool,
    /// A video topic: when the robot may next be asked for a keyframe (`PULL`).
    keyframes: Option<std::time::Instant>,
}

/// The most often the hub asks a robot for a keyframe of one video topic.
const KEYFRAME_ASK_EVERY: std::time::Duration = std::time::Duration::from_secs(1);

impl PubTopic {
    /// Asks the robot for a keyframe of this video topic if the hub's router wants one
    /// (its chain broke, or a viewer came with nothing to show: `relay::gop`), at most
    /// once a second; the want stays until it may be asked.
    fn ask_keyframe(&mut self, alias: u32, session: &mut LinkSession) {
        let Some(next) = &mut self.keyframes else {
            return;
        };
        let now = std::time::Instant::now();
        if now >= *next && self.topic.take_keyframe_ask() {
            *next = now + KEYFRAME_ASK_EVERY;
            session.send(Frame::Pull { alias });
        }
    }
}

/// The hub's side of one robot link, besides the session.
pub(super) struct RobotLink {
    pub router: Arc<Router>,
    pub client: ClientId,
    pub live: Arc<LiveRobot>,
    /// The robot's topics by alias (Fx-hashed: looked up per message; see `LinkIn`).
    topics: rustc_hash::FxHashMap<u32, PubTopic>,
    subs: HashMap<u32, SubscriptionId>,
    /// Delivery marks of this robot's no-drop topics.
    pub book: Arc<Mutex<RobotBook>>,
    /// No-drop aliases to confirm once the marks are written, with the highest number.
    pub confirm: HashMap<u32, u64>,
    /// Topics with counts or a view held since the last read (see `PubTopic`).
    unflushed: Vec<u32>,
    /// When the link's last read arrived: the receive time of its messages (one clock
    /// reading per read, not per message).
    read_at: (std::time::Instant, u64),
    /// Tells which of the robot's topics gained or lost their subscribers.
    pub demand: Arc<DemandWatch>,
    /// The robot's aliases by hub topic, for the demand watch's answers.
    by_topic: HashMap<TopicId, u32>,
    /// What the robot was last told of each alias (`INTEREST`).
    interest: HashMap<u32, bool>,
}

impl RobotLink {
    pub fn new(
        router: Arc<Router>,
        client: ClientId,
        live: Arc<LiveRobot>,
        book: Arc<Mutex<RobotBook>>,
    ) -> RobotLink {
        RobotLink {
            demand: router.watch_demand(client),
            router,
            client,
            live,
            topics: rustc_hash::FxHashMap::default(),
            subs: HashMap::new(),
            book,
            confirm: HashMap::new(),
            unflushed: Vec::new(),
            read_at: (std::time::Instant::now(), fleetlink_relay::unix_nanos()),
            by_topic: HashMap::new(),
            interest: HashMap::new(),
        }
    }

    /// Tells the robot whether anyone wants the topic it announced as `alias`, if that is
    /// news to it (always after the `ADVERTISE`).
    fn tell_interest(&mut self, alias: u32, session: &mut LinkSession) {
        let Some(p) = self.topics.get(&alias) else {
            return;
        };
        let wanted = p.topic.wanted_by_others(self.client);
        if self.interest.insert(alias, wanted) != Some(wanted) {
            p.topic.set_idle(!wanted);
            session.send(Frame::Interest { alias, wanted });
        }
    }

    /// Subscribers of some of the robot's topics changed: the robot hears what that
    /// changes for it.
    pub fn on_demand_changed(&mut self, session: &mut LinkSession) {
        for topic in self.demand.take() {
            if let Some(alias) = self.by_topic.get(&topic).copied() {
                self.tell_interest(alias, session);
                if let Some(p) = self.topics.get_mut(&alias) {
                    p.ask_keyframe(alias, session);
                }
            }
        }
        // Someone asked for one message of a pull topic.
        for topic in self.demand.take_pulls() {
            if let Some(alias) = self.by_topic.get(&topic).copied()
                && self.topics.get(&alias).is_some_and(|p| p.topic.is_pull())
            {
                session.send(Frame::Pull { alias });
            }
        }
    }

    /// A read of the link arrived at `at` (the unix clock `unix_ns`): its messages carry
    /// that receive time.
    pub fn read_at(&mut self, at: std::time::Instant, unix_ns: u64) {
        self.read_at = (at, unix_ns);
    }

    /// The read's messages are published: their counts go to the topics' counters and the
    /// views are let go (a subscriber that leaves is not kept alive by them).
    pub fn end_of_read(&mut self) {
        for alias in self.unflushed.drain(..) {
            if let Some(p) = self.topics.get_mut(&alias) {
                p.topic.stats.flush(&mut p.counts);
                p.view.clear();
                p.unflushed = false;
            }
        }
    }

    /// Acts on one event of the session (`Closed` is the driver's).
    pub fn apply(&mut self, ev: Event, session: &mut LinkSession) {
        match ev {
            Event::Link(LinkEvent::Message {
                alias,
                seq,
                stamp_ns,
                payload,
                reliable: true,
                wire_len,
                via,
            }) => {
                let name = session
                    .link_in()
                    .topic(alias)
                    .map_or("", |t| t.name.as_str());
                let fresh = self
                    .book
                    .lock()
                    .unwrap_or_else(|p| p.into_inner())
                    .admit(name, seq);
                let c = self.confirm.entry(alias).or_default();
                *c = (*c).max(seq);
                if fresh {
                    self.publish(alias, seq, stamp_ns, payload, wire_len, via, session);
                }
            }
            Event::Link(ev) => self.on_link(ev, session),
            Event::Pong { rtt, offset_ns, .. } => {
                self.live.on_pong(rtt.as_nanos() as u64, offset_ns);
            }
            Event::Hello { .. } | Event::Opened { .. } | Event::ReportDue | Event::Closed(_) => {}
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn publish(
        &mut self,
        alias: u32,
        seq: u64,
        stamp_ns: u64,
        payload: fleetlink_proto::Payload,
        wire_len: usize,
        via: Option<Arc<Via>>,
        session: &mut LinkSession,
    ) {
        let Some(p) = self.topics.get_mut(&alias) else {
            return;
        };
        let gate = session.gate();
        // Asked per message (a cached answer) so a rule change applies at once.
        if !gate.allows_topic(p.id.0, p.name.as_str(), Op::Publish) {
            return;
        }
        let size = payload.len();
        p.counts.link_raw += size as u64;
        p.counts.link_wire += wire_len as u64;
        let (received, received_ns) = self.read_at;
        if via.is_some() {
            // From a site hub (or the hub upstream): the message keeps the hubs it passed.
            let meta = p.topic.meta();
            let msg = Message::received_at(meta, seq, stamp_ns, self.client, payload, received)
                .with_via(via);
            p.topic.deliver(&Arc::new(msg));
        } else {
            let view = p.topic.view(&mut p.view);
            p.topic.publish_framed(
                view,
                self.client,
                seq,
                stamp_ns,
                payload,
                received,
                false,
                &mut p.counts,
            );
        }
        if !p.unflushed {
            p.unflushed = true;
            self.unflushed.push(alias);
        }
        // End-to-end latency on the hub's clock: origin stamp plus the robot's clock
        // offset, to when the hub received it.
        if let Some(off) = self.live.clock_offset_ns() {
            let origin = stamp_ns as i128 + off as i128;
            if received_ns as i128 >= origin {
                p.topic
                    .stats
                    .record_latency((received_ns as i128 - origin) as u64);
            }
        }
        gate.done(p.name.as_str(), Op::Publish, size);
        p.ask_keyframe(alias, session);
    }

    /// The robot announces a topic it publishes (checked by its gate), bound to `alias`.
    fn advertise(
        &mut self,
        alias: u32,
        topic: InTopic,
        via: Option<Arc<Via>>,
        session: &mut LinkSession,
    ) {
        let name = match TopicName::parse(&topic.name) {
            Ok(n) => n,
            Err(e) => {
                return session.status(
                    Level::Error,
                    status_code::MALFORMED,
                    format!("advertise: {e}"),
                );
            }
        };
        let gate = session.gate();
        if !gate.allows(name.as_str(), Op::Publish) {
            let text = format!("advertise {name}: not allowed for {}", gate.principal());
            return session.status(Level::Error, status_code::FORBIDDEN, text);
        }
        let how = Publication {
            latch: topic.latched,
            no_drop: topic.reliable,
            via,
            encoding: None,
        };
        match self
            .router
            .advertise_as(self.client, &name, topic.schema, how)
        {
            Ok(t) => {
                // Announced further (a site hub's uplink) before a message flows.
                t.note_encoding(topic.encoding);
                self.by_topic.insert(t.id(), alias);
                t.set_pull(topic.pull);
                let epoch = self.book.lock().unwrap_or_else(|p| p.into_inner()).epoch();
                t.set_reliable(topic.reliable.then_some(epoch));
                let video = fleetlink_relay::gop::is_video_type(&t.meta().schema.type_name);
                if let Some(old) = self.topics.insert(
                    alias,
                    PubTopic {
                        id: t.id(),
                        topic: t,
                        name,
                        counts: StatsBatch::default(),
                        view: TopicView::default(),
                        unflushed: false,
                        keyframes: video.then(std::time::Instant::now),
                    },
                ) {
                    // Rebound: what the old binding counted still counts.
                    let mut old = old;
                    old.topic.stats.flush(&mut old.counts);
                }
                // A fresh binding: the robot hears the demand for it anew.
                self.interest.remove(&alias);
                self.tell_interest(alias, session);
            }
            Err(e) => session.status(
                Level::Error,
                status_code::MALFORMED,
                format!("advertise: {e}"),
            ),
        }
    }

    /// The robot no longer publishes the topic bound to `alias`.
    fn unadvertise(&mut self, alias: u32, topic: &InTopic) {
        if let Some(mut p) = self.topics.remove(&alias) {
            p.topic.stats.flush(&mut p.counts);
            p.topic.set_idle(false);
            p.topic.set_pull(false);
            p.topic.set_reliable(None);
            self.by_topic.remove(&p.topic.id());
            self.interest.remove(&alias);
            if let Ok(name) = TopicName::parse(&topic.name) {
                self.router.unadvertise(self.client, &name);
            }
        }
    }

    /// The robot wants to hear of the fleet services it may call that match `pattern`
    /// (filtered by the gate when each is offered).
    fn subscribe_services(&mut self, pattern: String, flags: u8, session: &mut LinkSession) {
        let source = if flags & SUBSCRIBE_REGEX != 0 {
            pattern
        } else {
            regex::escape(&pattern)
        };
        match Router::compile_pattern(&source) {
            Ok(re) => self.router.calls.watch(self.client, re),
            Err(e) => session.status(
                Level::Error,
                status_code::MALFORMED,
                format!("subscribe services: {e}"),
            ),
        }
    }

    fn on_link(&mut self, ev: LinkEvent, session: &mut LinkSession) {
        match ev {
            LinkEvent::Advertise { alias, topic, via } => {
                self.advertise(alias, topic, via, session)
            }
            LinkEvent::Unadvertise { alias, topic } => self.unadvertise(alias, &topic),
            LinkEvent::Message {
                alias,
                seq,
                stamp_ns,
                payload,
                wire_len,
                via,
                ..
            } => self.publish(alias, seq, stamp_ns, payload, wire_len, via, session),
            LinkEvent::Control(Frame::Subscribe { pattern, flags, .. })
                if flags & SUBSCRIBE_SERVICES != 0 =>
            {
                self.subscribe_services(pattern, flags, session)
            }
            LinkEvent::Control(Frame::Subscribe {
                id,
                pattern,
                flags,
                throttle_ms,
                queue_length,
            }) => self.subscribe(id, pattern, flags, throttle_ms, queue_length, session),
            LinkEvent::Control(Frame::Unsubscribe { id }) => {
                if let Some(sid) = self.subs.remove(&id) {
                    self.router.unsubscribe(self.client, sid);
                }
            }
            LinkEvent::Control(Frame::LinkReport {
                demand_bps,
                rate_bps,
                latency_ns,
                capacity_bps,
                measured_at_ms,
            }) => {
                self.live.demand_bps.store(demand_bps, Relaxed);
                self.live.rate_bps.store(rate_bps, Relaxed);
                self.live.latency_ns.store(latency_ns, Relaxed);
                self.live.capacity_bps.store(capacity_bps, Relaxed);
                self.live.measured_at_ms.store(measured_at_ms, Relaxed);
            }
            LinkEvent::Control(Frame::TopicLoad { topics }) => {
                let at_ns = fleetlink_relay::unix_nanos();
                for t in topics {
                    let Some(p) = self.topics.get(&t.alias) else {
                        continue; // not announced (yet): the next report tells again
                    };
                    p.topic
                        .stats
                        .set_robot_offer(fleetlink_relay::stats::RobotOffer {
                            hz: t.rate_mhz as f64 / 1000.0,
                            bytes_per_sec: t.bytes_per_sec as f64,
                            priority: f64::from(t.priority_milli) / 1000.0,
                            queue: t.queue,
                            no_drop: t.flags & fleetlink_proto::frame::TOPIC_LOAD_NO_DROP != 0,
                            at_ns,
                        });
                }
            }
            LinkEvent::Control(Frame::TopicDrops { topics }) => {
                for (alias, counts) in topics {
                    let Some(p) = self.topics.get(&alias) else {
                        continue; // not announced (yet): the next change tells again
                    };
                    for (reason, n) in counts {
                        if let Some(r) = DropReason::ALL.get(reason as usize) {
                            p.topic.stats.set_robot_drops(*r, n);
                        }
                    }
                }
            }
            LinkEvent::Control(Frame::Budget {
                max_bps,
                day_bytes,
                used_bytes,
                thinned,
            }) => {
                let report = crate::registry::RobotBudget {
                    max_bps: (max_bps > 0).then_some(max_bps),
                    day_bytes: (day_bytes > 0).then_some(day_bytes),
                    used_bytes,
                    use_bps: 0.0,
                    thinned: thinned
                        .iter()
                        .filter_map(|a| self.topics.get(a).map(|p| p.name.to_string()))
                        .collect(),
                    at_ns: fleetlink_relay::unix_nanos(),
                };
                let mut b = self.live.budget.lock().unwrap_or_else(|p| p.into_inner());
                *b = Some(match b.take() {
                    Some(prev) => prev.then(report),
                    None => report,
                });
            }
            LinkEvent::Control(Frame::Status { level, text, .. }) => {
                tracing::info!(robot = %self.live.name, level = level.as_str(), "agent status: {text}");
            }
            // Frames only a hub sends, an agent's ACK: nothing to do.
            LinkEvent::Control(_) | LinkEvent::None => {}
        }
    }

    fn subscribe(
        &mut self,
        id: u32,
        pattern: String,
        flags: u8,
        throttle_ms: u32,
        queue_length: u32,
        session: &mut LinkSession,
    ) {
        let target = if flags & SUBSCRIBE_REGEX != 0 {
            match Router::compile_pattern(&pattern) {
                Ok(r) => Target::Pattern(r),
                Err(e) => {
                    return session.status(
                        Level::Error,
                        status_code::MALFORMED,
                        format!("subscribe: {e}"),
                    );
                }
            }
        } else {
            let gate = session.gate();
            match TopicName::parse(&pattern) {
                Ok(n) if gate.allows(n.as_str(), Op::Subscribe) => Target::Exact(n),
                Ok(n) => {
                    let text = format!("subscribe {n}: not allowed for {}", gate.principal());
                    return session.status(Level::Error, status_code::FORBIDDEN, text);
                }
                Err(e) => {
                    return session.status(
                        Level::Error,
                        status_code::MALFORMED,
                        format!("subscribe: {e}"),
                    );
                }
            }
        };
        if let Some(old) = self.subs.remove(&id) {
            self.router.unsubscribe(self.client, old);
        }
        let opts = SubOptions {
            queue_length,
            throttle_ms,
            ..Default::default()
        };
        match self.router.subscribe(self.client, target, opts) {
            Ok(sid) => {
                self.subs.insert(id, sid);
            }
            Err(e) => session.status(
                Level::Error,
                status_code::MALFORMED,
                format!("subscribe: {e}"),
            ),
        }
    }
}
