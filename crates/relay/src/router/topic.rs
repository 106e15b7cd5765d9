//! A topic: its metadata, its subscribers (an immutable snapshot swapped whenever a
//! subscription changes), its latched message and video group, and the fan-out of one
//! message to every subscriber's queue.

use super::*;

#[derive(Clone)]
pub(crate) struct SubscriberRef {
    pub(super) client: ClientId,
    pub(super) outbox: Arc<Outbox>,
    pub(super) slot: SlotId,
    /// Receives its own publishes: rosbridge clients do, as rosbridge delivers to the
    /// publishing connection when it subscribed. Link peers (agents, an agent's uplink)
    /// and in-process participants do not: that is the loop guard between robot and hub.
    pub(super) own: bool,
    /// Counts as demand only while its outbox sends the topic on (`SubOptions::passive`).
    pub(super) passive: bool,
}

impl SubscriberRef {
    /// Whether this subscriber wants what is published now.
    pub(super) fn wants(&self) -> bool {
        !self.passive || self.outbox.reads_slot(self.slot)
    }
}

pub struct Topic {
    pub(super) meta: ArcSwap<TopicMeta>,
    pub stats: Arc<TopicStats>,
    pub(super) subscribers: ArcSwap<Vec<SubscriberRef>>,
    /// Counts changes of `meta` and `subscribers` (each stored first, then counted), so a
    /// publisher's [`TopicView`] knows when to read them again.
    pub(super) version: AtomicU64,
    pub(super) latched: Mutex<Option<Arc<Message>>>,
    pub(super) latch: std::sync::atomic::AtomicBool,
    /// Encoding of the last message published (an `Encoding` as u8), so a link can
    /// announce the topic before its next message.
    pub(super) last_encoding: std::sync::atomic::AtomicU8,
    /// Its publisher (a robot's link) was told that nobody wants it, so it does not
    /// flow: listings show it idle.
    pub(super) idle: std::sync::atomic::AtomicBool,
    /// Its publisher sends it only when asked ([`Router::request_pull`]).
    pub(super) pull: std::sync::atomic::AtomicBool,
    /// A video topic's frames since its last keyframe, for subscribers who come in the
    /// middle ([`crate::gop`]); set once its type is known to be video.
    pub(super) gop: std::sync::OnceLock<Box<crate::gop::Gop>>,
    /// The router's bound on what its video topics' groups keep together.
    pub(super) video_pool: Arc<crate::gop::Pool>,
    /// A robot publishes it as a no-drop stream: the epoch of that stream plus one (0:
    /// not reliable). Its messages' `seq` are the stream's numbers, so a far side that
    /// may see one twice (federated hubs, after a robot moved) can tell.
    pub(super) reliable: AtomicU64,
}

/// A publisher's copy of what a topic is and who subscribes to it, read again only when
/// the topic has changed ([`Topic::view`]): a burst of publishes reads one counter per
/// message instead of two shared snapshots. Its owner drops what it holds
/// ([`TopicView::clear`]) when it stops publishing for a while, so that subscribers who
/// left are not kept alive by it.
#[derive(Default)]
pub struct TopicView {
    pub(super) version: u64,
    pub(super) held: Option<(Arc<TopicMeta>, Arc<Vec<SubscriberRef>>)>,
}

impl TopicView {
    /// The topic's metadata as of the last [`Topic::view`].
    pub fn meta(&self) -> &Arc<TopicMeta> {
        &self.held.as_ref().expect("read by Topic::view").0
    }

    /// Lets go of the snapshots; the next [`Topic::view`] reads them again.
    pub fn clear(&mut self) {
        self.held = None;
    }
}

impl Topic {
    /// `view`, brought up to date with the topic.
    pub fn view<'v>(&self, view: &'v mut TopicView) -> &'v TopicView {
        let version = self.version.load(Acquire);
        if view.held.is_none() || view.version != version {
            view.held = Some((self.meta.load_full(), self.subscribers.load_full()));
            view.version = version;
        }
        view
    }

    pub(super) fn set_meta(&self, meta: TopicMeta) {
        self.follow_type(&meta);
        self.meta.store(Arc::new(meta));
        self.version.fetch_add(1, Release);
    }

    /// A video topic keeps its frames since the last keyframe, from the moment its type
    /// is known.
    pub(super) fn follow_type(&self, meta: &TopicMeta) {
        if crate::gop::is_video_type(&meta.schema.type_name) {
            let _ = self
                .gop
                .set(Box::new(crate::gop::Gop::new(self.video_pool.clone())));
        }
    }

    pub(super) fn set_subscribers(&self, list: Vec<SubscriberRef>) {
        self.subscribers.store(Arc::new(list));
        self.version.fetch_add(1, Release);
    }

    /// Whether a video topic wants a keyframe from its publisher since the last call (its
    /// chain broke, a subscriber came with nothing to show, or one lost a frame;
    /// [`crate::gop`]).
    pub fn take_keyframe_ask(&self) -> bool {
        let Some(gop) = self.gop.get() else {
            return false;
        };
        let lost = self.stats.keyframe_wanted.swap(false, Relaxed);
        gop.lock().take_ask() || lost
    }

    /// Marks a video topic as wanting a keyframe from its publisher, as a subscriber's
    /// lost frame does: the next [`Topic::take_keyframe_ask`] says so. For a want heard
    /// from elsewhere (another hub's viewers, a hub upstream); other topics ignore it.
    pub fn want_keyframe(&self) {
        if self.gop.get().is_some() {
            self.stats.keyframe_wanted.store(true, Relaxed);
        }
    }

    /// Encoding of the most recent message, if any was published.
    pub fn last_encoding(&self) -> Option<fleetlink_proto::Encoding> {
        match self.last_encoding.load(Relaxed) {
            u8::MAX => None,
            v => fleetlink_proto::Encoding::from_u8(v),
        }
    }

    pub fn meta(&self) -> Arc<TopicMeta> {
        self.meta.load_full()
    }

    pub fn name(&self) -> TopicName {
        self.meta.load().name.clone()
    }

    pub fn id(&self) -> TopicId {
        self.meta.load().id
    }

    /// True if a publisher advertised the topic latched (new subscribers get the last
    /// message).
    pub fn is_latched(&self) -> bool {
        self.latch.load(Relaxed)
    }

    pub fn subscriber_count(&self) -> usize {
        self.subscribers.load().len()
    }

    /// Whether anyone but `publisher` itself receives what `publisher` publishes here
    /// (the same rule as the fan-out: a link does not receive its own messages).
    pub fn wanted_by_others(&self, publisher: ClientId) -> bool {
        self.subscribers
            .load()
            .iter()
            .any(|s| (s.client != publisher || s.own) && s.wants())
    }

    /// Whether a client other than `me` wants what is published here by others than
    /// itself: a subscriber that is not one of `publishers` (which never receive their own
    /// messages), or a rosbridge client (which does, see `SubscriberRef::own`).
    pub fn demand_besides(&self, me: ClientId, publishers: &[ClientId]) -> bool {
        self.subscribers
            .load()
            .iter()
            .any(|s| s.client != me && (s.own || !publishers.contains(&s.client)) && s.wants())
    }

    /// Whether a client other than those in `but` subscribes to the topic (a passive
    /// subscriber only while it sends the topic on).
    pub fn has_subscriber_besides(&self, but: &[ClientId]) -> bool {
        self.subscribers
            .load()
            .iter()
            .any(|s| !but.contains(&s.client) && s.wants())
    }

    /// Remembers the encoding its publisher announced, until a message says otherwise: a
    /// link can then announce the topic before any message of it has flowed.
    pub fn note_encoding(&self, encoding: fleetlink_proto::Encoding) {
        let _ = self
            .last_encoding
            .compare_exchange(u8::MAX, encoding as u8, Relaxed, Relaxed);
    }

    /// Marks the topic idle (its publisher was told nobody wants it) or flowing.
    pub fn set_idle(&self, idle: bool) {
        self.idle.store(idle, Relaxed);
    }

    /// True while its publisher holds it back because nobody wants it.
    pub fn is_idle(&self) -> bool {
        self.idle.load(Relaxed)
    }

    /// Marks the topic as one its publisher sends only when asked.
    pub fn set_pull(&self, pull: bool) {
        self.pull.store(pull, Relaxed);
    }

    /// True if its publisher sends it only when asked ([`Router::request_pull`]).
    pub fn is_pull(&self) -> bool {
        self.pull.load(Relaxed)
    }

    /// Marks the topic as a robot's no-drop stream of `epoch` (its messages' `seq` number
    /// the stream), or not reliable (`None`).
    pub fn set_reliable(&self, epoch: Option<u64>) {
        self.reliable
            .store(epoch.map_or(0, |e| e.wrapping_add(1).max(1)), Relaxed);
    }

    /// The epoch of the no-drop stream its robot publishes, if it is one.
    pub fn reliable_epoch(&self) -> Option<u64> {
        match self.reliable.load(Relaxed) {
            0 => None,
            e => Some(e - 1),
        }
    }

    /// Fans `payload` out to every subscriber (its origin only if that is a rosbridge
    /// client, see `SubscriberRef::own`). The hot path: one
    /// allocation for the message, one queue push per subscriber.
    pub fn publish(
        &self,
        origin: ClientId,
        seq: u64,
        stamp_ns: u64,
        payload: Payload,
    ) -> Arc<Message> {
        let now = std::time::Instant::now();
        self.publish_at(self.meta(), origin, seq, stamp_ns, payload, now)
    }

    /// [`Topic::publish`] of a message received at `received`, with the topic as the
    /// publisher saw it when it checked the message (`meta`, from [`Topic::meta`]).
    pub fn publish_at(
        &self,
        meta: Arc<TopicMeta>,
        origin: ClientId,
        seq: u64,
        stamp_ns: u64,
        payload: Payload,
        received: std::time::Instant,
    ) -> Arc<Message> {
        let msg = Arc::new(Message::received_at(
            meta, seq, stamp_ns, origin, payload, received,
        ));
        self.deliver(&msg);
        msg
    }

    /// A rosbridge client's publish: [`Topic::publish_at`] of a message that may be the
    /// JSON text the client sent (`json_text`, see [`Message::framed`]), without handing
    /// the message back. The last subscriber's queue takes the message without a new
    /// reference to it, and the topic's counters are added up in the publisher's
    /// `counts` until it flushes them ([`TopicStats::flush`]).
    #[allow(clippy::too_many_arguments)]
    pub fn publish_framed(
        &self,
        view: &TopicView,
        origin: ClientId,
        seq: u64,
        stamp_ns: u64,
        payload: Payload,
        received: std::time::Instant,
        json_text: bool,
        counts: &mut StatsBatch,
    ) {
        let (meta, subscribers) = view.held.as_ref().expect("read by Topic::view");
        let msg = Arc::new(Message::framed(
            meta.clone(),
            seq,
            stamp_ns,
            origin,
            payload,
            received,
            json_text,
        ));
        self.stats
            .batch_publish(counts, msg.payload.len(), msg.received_unix_ns());
        counts.deliveries += self.fan_out(subscribers, msg, received);
    }

    /// Fans an existing message out (used when a message is re-published unchanged).
    pub fn deliver(&self, msg: &Arc<Message>) {
        self.stats
            .record_publish(msg.payload.len(), msg.received_unix_ns());
        let pushed = self.fan_out(&self.subscribers.load(), msg.clone(), msg.received());
        // One shared counter update per message, not one per subscriber.
        self.stats.deliveries.fetch_add(pushed, Relaxed);
    }

    /// Queues `msg` for every one of `subscribers` but its origin (unless they asked for
    /// their own messages), the last one taking `msg` itself rather than a new reference,
    /// and keeps it as the topic's latest (its encoding; the message itself when latched).
    /// Gives the number of queues it went to.
    // Inlined into both callers: a call of its own costs the publish path ~25
    // instructions a message (session bench).
    #[inline(always)]
    pub(super) fn fan_out(
        &self,
        subscribers: &[SubscriberRef],
        msg: Arc<Message>,
        now: Instant,
    ) -> u64 {
        self.last_encoding
            .store(msg.payload.encoding as u8, Relaxed);
        if self.latch.load(Relaxed) {
            *self.latched.lock().unwrap_or_else(|p| p.into_inner()) = Some(msg.clone());
        }
        if let Some(gop) = self.gop.get() {
            return self.fan_out_video(gop, msg, now);
        }
        let mut targets = subscribers
            .iter()
            .filter(|s| s.client != msg.origin || s.own);
        let Some(mut last) = targets.next() else {
            return 0;
        };
        let mut pushed = 1;
        for s in targets {
            last.outbox.push(last.slot, msg.clone(), now);
            pushed += 1;
            last = s;
        }
        last.outbox.push(last.slot, msg, now);
        pushed
    }

    /// [`Topic::fan_out`] of a video topic: the frame is kept in the topic's group and
    /// queued for the subscribers read under the group's lock, so that a subscriber being
    /// added meanwhile gets it once, in order ([`crate::gop::Gop::lock`]).
    #[cold]
    pub(super) fn fan_out_video(
        &self,
        gop: &crate::gop::Gop,
        msg: Arc<Message>,
        now: Instant,
    ) -> u64 {
        let mut group = gop.lock();
        if !group.keep(&msg) {
            // Its chain is broken: held back from everyone until the next keyframe.
            self.stats.record_drop(crate::queue::DropReason::Policy);
            return 0;
        }
        let mut pushed = 0;
        for s in self.subscribers.load().iter() {
            if s.client != msg.origin || s.own {
                s.outbox.push(s.slot, msg.clone(), now);
                pushed += 1;
            }
        }
        pushed
    }
}

/// A read-only view of one topic for listings.
#[derive(Clone)]
pub struct TopicSnapshot {
    pub topic: Arc<Topic>,
    pub meta: Arc<TopicMeta>,
    pub publishers: Vec<ClientId>,
    pub subscribers: Vec<ClientId>,
    pub stats: Arc<TopicStats>,
    /// Someone subscribed to this topic by its name (not only through a pattern).
    pub named_subscription: bool,
}

impl TopicSnapshot {
    /// Whether listings show the topic: it has a publisher, or a subscriber that asked
    /// for it by name. A topic kept only by pattern subscriptions (a robot's link
    /// subscribes to its whole namespace) after its last publisher left is gone for a
    /// user, as in ROS, where a topic exists while it has an endpoint.
    pub fn listed(&self) -> bool {
        !self.publishers.is_empty() || self.named_subscription
    }
}

/// `name`'s listing entry. Whether someone subscribed by name (not through a pattern, and
/// not quietly, see [`SubOptions::unlisted`]) is asked of the topic's subscribers only.
pub(super) fn snapshot_of(st: &State, name: &TopicName, t: &Arc<Topic>) -> TopicSnapshot {
    let subscribers: Vec<ClientId> = t.subscribers.load().iter().map(|s| s.client).collect();
    let named_subscription = subscribers.iter().any(|cid| {
        st.clients.get(cid).is_some_and(|c| {
            c.slots.get(name).is_some_and(|(_, holders)| {
                holders
                    .iter()
                    .any(|h| matches!(c.subs.get(h), Some((Target::Exact(_), o)) if !o.unlisted))
            })
        })
    });
    TopicSnapshot {
        topic: t.clone(),
        meta: t.meta(),
        publishers: st.publishers.get(name).cloned().unwrap_or_default(),
        subscribers,
        stats: t.stats.clone(),
        named_subscription,
    }
}

pub(super) fn detach(topic: &Topic, client: ClientId) {
    let list: Vec<SubscriberRef> = topic
        .subscribers
        .load()
        .iter()
        .filter(|s| s.client != client)
        .cloned()
        .collect();
    if let Some(gop) = topic.gop.get() {
        let mut group = gop.lock();
        // Nobody left but the publisher itself (a robot's link subscribes to its whole
        // namespace, its own topics included, and is not given them): it stops sending
        // to nobody, and what is kept now would be stale by the time someone comes, who
        // then gets a fresh keyframe instead (crate::gop).
        let publisher = group.publisher();
        if list.iter().all(|s| Some(s.client) == publisher && !s.own) {
            group.nobody_watches();
        }
    }
    topic.set_subscribers(list);
}

/// A publisher of `name` went: a video topic lets go of the group of pictures it kept of
/// that publisher's stream (a later subscriber would be given frames of a stream that has
/// ended; the publisher's next stream starts with a keyframe).
pub(super) fn publisher_left(st: &State, name: &TopicName, client: ClientId) {
    if let Some(gop) = st.topics.get(name).and_then(|t| t.gop.get()) {
        gop.lock().forget(client);
    }
}

#[cfg(test)]
mod keyframe_tests {
    use super::*;

    #[test]
    fn a_keyframe_wanted_from_elsewhere_is_asked_once_and_only_of_video() {
        let router = Router::default();
        let (c, _) = router.connect(ClientKind::Foxglove, None);
        let advertise = |name: &str, type_name: &str| {
            let name = TopicName::parse(name).unwrap();
            router
                .advertise(c, &name, Schema::named(type_name), false)
                .unwrap()
        };
        let video = advertise("/cam/video", "foxglove_msgs/msg/CompressedVideo");
        let _ = video.take_keyframe_ask();
        video.want_keyframe();
        assert!(video.take_keyframe_ask());
        assert!(!video.take_keyframe_ask(), "asked once");
        let scan = advertise("/scan", "sensor_msgs/msg/LaserScan");
        scan.want_keyframe();
        assert!(!scan.take_keyframe_ask(), "not a video topic");
    }
}
