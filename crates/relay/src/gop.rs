//! A video topic's frames since its last keyframe (its group of pictures), kept so that a
//! subscriber who comes in the middle of a stream gets the keyframe and what followed at
//! once and decodes from its first message, as a latched topic's subscriber gets its one
//! message; and the chain of frames checked, so that no subscriber is ever given a frame
//! whose predecessors it cannot have (docs/video.md).
//!
//! Only `foxglove_msgs/msg/CompressedVideo` in CDR is looked into (the access unit's
//! leading NAL headers, [`fleetlink_msg::h264::is_keyframe`]); other encodings pass as they
//! are. A frame is delivered only while the chain since the last keyframe is whole: its
//! publisher numbers frames one by one, so a number skipped means a frame was lost on the
//! way (the robot's link queue, its budget or age limit, a blackout). From then on the
//! frames are held back from everyone until the next keyframe, and one is asked for
//! ([`Kept::take_ask`]: the robot's link sends it as `PULL`). A group that grows past
//! [`MAX_FRAMES`] or [`MAX_BYTES`] is let go whole, and the next keyframe starts a new one;
//! so is one that would take a router's groups together past [`MAX_BYTES_ALL`] ([`Pool`]).

use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};
use std::sync::{Arc, Mutex, MutexGuard};

use fleetlink_proto::Encoding;

use crate::message::Message;
use crate::names::ClientId;

/// Most frames kept: 20 s at 15 fps, longer than any keyframe interval worth sending.
pub const MAX_FRAMES: usize = 300;
/// Most payload bytes kept per topic.
pub const MAX_BYTES: usize = 16 << 20;
/// Most payload bytes kept by all the video topics of one router together: a hub with a
/// thousand robots' cameras keeps a thousand groups of a few hundred kilobytes each, and
/// no more than this whatever they send.
pub const MAX_BYTES_ALL: usize = 256 << 20;

/// The bytes the groups of one router's video topics keep together, against a bound.
#[derive(Debug)]
pub struct Pool {
    used: AtomicUsize,
    limit: usize,
}

impl Default for Pool {
    fn default() -> Pool {
        Pool::new(MAX_BYTES_ALL)
    }
}

impl Pool {
    pub fn new(limit: usize) -> Pool {
        Pool {
            used: AtomicUsize::new(0),
            limit,
        }
    }

    /// The bytes kept now.
    pub fn used(&self) -> usize {
        self.used.load(Relaxed)
    }

    /// Takes `n` bytes from the pool; false (and nothing taken) past its bound.
    fn take(&self, n: usize) -> bool {
        self.used
            .fetch_update(Relaxed, Relaxed, |used| {
                used.checked_add(n).filter(|total| *total <= self.limit)
            })
            .is_ok()
    }

    fn give_back(&self, n: usize) {
        self.used.fetch_sub(n, Relaxed);
    }
}

/// Whether a ROS type is a video stream's (either spelling).
pub fn is_video_type(type_name: &str) -> bool {
    matches!(
        type_name,
        "foxglove_msgs/msg/CompressedVideo" | "foxglove_msgs/CompressedVideo"
    )
}

/// Whether a video message can start a decoder: its access unit is a keyframe.
pub fn is_keyframe(msg: &Message) -> bool {
    msg.payload.encoding == Encoding::Cdr
        && fleetlink_msg::h264::compressed_video_data(&msg.payload.bytes)
            .is_some_and(fleetlink_msg::h264::is_keyframe)
}

/// The frames of the current group (see the module docs). Its lock also orders a new
/// subscriber's replay against the topic's publishes ([`Gop::lock`]).
pub struct Gop {
    kept: Mutex<Kept>,
}

/// The group, behind [`Gop::lock`].
pub struct Kept {
    frames: Vec<Arc<Message>>,
    /// The payload bytes of `frames`, taken from `pool`.
    bytes: usize,
    pool: Arc<Pool>,
    /// The last frame seen: its publisher and number.
    last: Option<(ClientId, u64)>,
    /// The frames since the last keyframe all came: the next one can be delivered.
    whole: bool,
    /// A keyframe is wanted (the chain broke, or a subscriber came with nothing to show).
    ask: bool,
}

impl Gop {
    /// An empty group whose bytes count against `pool` (the router's).
    pub fn new(pool: Arc<Pool>) -> Gop {
        Gop {
            kept: Mutex::new(Kept {
                frames: Vec::new(),
                bytes: 0,
                pool,
                last: None,
                whole: false,
                ask: false,
            }),
        }
    }

    /// The group, locked. The router holds this while it fans a frame out (keeping it,
    /// then queueing it for the subscribers it reads under the lock) and while it adds a
    /// subscriber (replaying the group into its queue): so a frame reaches a new
    /// subscriber either in the replay or after it, once, in order.
    pub fn lock(&self) -> MutexGuard<'_, Kept> {
        self.kept.lock().unwrap_or_else(|p| p.into_inner())
    }
}

impl Kept {
    /// Takes a frame published on the topic. False if it must not be delivered: it is not
    /// a keyframe and the chain since the last one is broken (see the module docs), or it
    /// is a frame seen already.
    pub fn keep(&mut self, msg: &Arc<Message>) -> bool {
        if msg.payload.encoding != Encoding::Cdr {
            return true;
        }
        let previous = self.last.filter(|(origin, _)| *origin == msg.origin);
        if is_keyframe(msg) {
            self.last = Some((msg.origin, msg.seq));
            self.whole = true;
            self.let_go();
            self.add(msg);
            return true;
        }
        if previous.is_some_and(|(_, seq)| msg.seq <= seq) {
            return false;
        }
        self.last = Some((msg.origin, msg.seq));
        if !(self.whole && previous.is_some_and(|(_, seq)| msg.seq == seq + 1)) {
            if self.whole || self.frames.is_empty() {
                self.ask = true;
            }
            self.whole = false;
            self.let_go();
            return false;
        }
        if !self.frames.is_empty() {
            self.add(msg);
        }
        true
    }

    fn add(&mut self, msg: &Arc<Message>) {
        let len = msg.payload.len();
        let fits = self.frames.len() < MAX_FRAMES && self.bytes + len <= MAX_BYTES;
        if fits && self.pool.take(len) {
            self.bytes += len;
            self.frames.push(msg.clone());
        } else {
            // Too long to give whole (for the topic, or beside the router's other
            // groups): nobody gets a part of it.
            self.let_go();
        }
    }

    /// Lets go of the group's frames and gives their bytes back to the pool.
    fn let_go(&mut self) {
        self.pool.give_back(std::mem::take(&mut self.bytes));
        self.frames = Vec::new();
    }

    /// Publisher `client` went: its frames are let go, and its next frame must be a
    /// keyframe.
    pub fn forget(&mut self, client: ClientId) {
        if self.last.is_some_and(|(origin, _)| origin == client) {
            self.let_go();
            self.whole = false;
            self.last = None;
        }
    }

    /// The publisher of the frames seen last.
    pub fn publisher(&self) -> Option<ClientId> {
        self.last.map(|(origin, _)| origin)
    }

    /// The last subscriber went: the group is let go (see [`Router`]'s detach); frames
    /// that still come are delivered as before, and kept again from the next keyframe.
    ///
    /// [`Router`]: crate::Router
    pub fn nobody_watches(&mut self) {
        self.let_go();
    }

    /// A subscriber came: with no group to give it, a keyframe is wanted.
    pub fn joined(&mut self) {
        if self.frames.is_empty() {
            self.ask = true;
        }
    }

    /// Whether a keyframe is wanted since the last call (the publisher's link asks its
    /// robot for one).
    pub fn take_ask(&mut self) -> bool {
        std::mem::take(&mut self.ask)
    }

    /// The group so far, keyframe first (empty before a keyframe was seen).
    pub fn frames(&self) -> &[Arc<Message>] {
        &self.frames
    }
}

impl Drop for Kept {
    fn drop(&mut self) {
        self.let_go();
    }
}

#[cfg(test)]
mod tests {
    use std::time::Instant;

    use fleetlink_proto::{Payload, Schema};

    use crate::names::TopicName;
    use crate::router::{ClientKind, Router, SubOptions, Target};

    /// A CompressedVideo message (CDR) around an access unit: a keyframe (SPS, PPS, IDR
    /// slice) or a P slice, with `n` in the slice so frames differ.
    fn frame(key: bool, n: u8) -> Payload {
        let au: Vec<u8> = if key {
            vec![
                0, 0, 0, 1, 0x67, 0x42, 0, 0, 0, 1, 0x68, 0xCE, 0, 0, 1, 0x65, n,
            ]
        } else {
            vec![0, 0, 0, 1, 0x61, n]
        };
        let mut b = vec![0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0];
        b.extend_from_slice(&(au.len() as u32).to_le_bytes());
        b.extend_from_slice(&au);
        Payload::new(fleetlink_proto::Encoding::Cdr, b)
    }

    /// A subscriber of `/cam/video` (with `opts`): its client and queue.
    fn viewer(
        router: &Router,
        opts: SubOptions,
    ) -> (
        crate::names::ClientId,
        std::sync::Arc<crate::outbox::Outbox>,
    ) {
        let (c, outbox) = router.connect(ClientKind::Foxglove, None);
        let name = TopicName::parse("/cam/video").unwrap();
        router.subscribe(c, Target::Exact(name), opts).unwrap();
        (c, outbox)
    }

    /// The numbers (last byte) of the frames waiting in a subscriber's queue.
    fn numbers(outbox: &crate::outbox::Outbox) -> Vec<u8> {
        let got = outbox.take(1000, usize::MAX, Instant::now());
        got.items
            .iter()
            .map(|(_, _, m)| *m.payload.bytes.last().unwrap())
            .collect()
    }

    /// What a new subscriber of `/cam/video` finds in its queue at once.
    fn late_joiner_gets(router: &Router) -> Vec<u8> {
        let (c, outbox) = viewer(router, SubOptions::default());
        let got = numbers(&outbox);
        router.disconnect(c);
        got
    }

    /// A robot's video topic on a router.
    fn video_topic(
        router: &Router,
    ) -> (crate::names::ClientId, std::sync::Arc<crate::router::Topic>) {
        let (robot, _) = router.connect(
            ClientKind::Internal {
                role: "video".into(),
            },
            None,
        );
        let name = TopicName::parse("/cam/video").unwrap();
        let schema = Schema::named("foxglove_msgs/msg/CompressedVideo");
        (
            robot,
            router.advertise(robot, &name, schema, false).unwrap(),
        )
    }

    #[test]
    fn a_late_subscriber_gets_the_last_keyframe_and_the_frames_since() {
        let router = Router::default();
        let (robot, topic) = video_topic(&router);
        // Someone watches throughout (else the robot would not send).
        let (_, _watching) = viewer(&router, SubOptions::default());
        let mut seq = 0;
        let mut send = |key, n| {
            seq += 1;
            topic.publish(robot, seq, 0, frame(key, n));
        };
        // Frames before any keyframe cannot be decoded: nothing to give.
        send(false, 1);
        assert_eq!(late_joiner_gets(&router), Vec::<u8>::new());
        send(true, 2);
        send(false, 3);
        send(false, 4);
        assert_eq!(late_joiner_gets(&router), [2, 3, 4]);
        // A new keyframe starts the group afresh.
        send(true, 5);
        send(false, 6);
        assert_eq!(late_joiner_gets(&router), [5, 6]);
        // A group longer than the bound is let go whole until the next keyframe.
        for n in 0..super::MAX_FRAMES {
            send(false, n as u8);
        }
        assert_eq!(late_joiner_gets(&router), Vec::<u8>::new());
        send(true, 7);
        assert_eq!(late_joiner_gets(&router), [7]);
    }

    #[test]
    fn the_routers_groups_together_keep_no_more_than_its_pool() {
        let (key, p) = (frame(true, 0).len(), frame(false, 0).len());
        let mut router = Router::default();
        // Room for a keyframe and one frame after it, all topics together.
        router.video_pool = std::sync::Arc::new(super::Pool::new(key + p));
        let (robot, topic) = video_topic(&router);
        let (_, outbox) = viewer(&router, SubOptions::default());
        let mut seq = 0;
        let mut send = |key, n| {
            seq += 1;
            topic.publish(robot, seq, 0, frame(key, n));
        };
        send(true, 1);
        send(false, 2);
        assert_eq!(late_joiner_gets(&router), [1, 2]);
        assert_eq!(router.video_pool.used(), key + p);
        // The next frame does not fit: the group is let go whole, its bytes given back,
        // and the frames still flow to subscribers.
        assert_eq!(numbers(&outbox), [1, 2]);
        send(false, 3);
        assert_eq!(numbers(&outbox), [3]);
        assert_eq!(router.video_pool.used(), 0);
        assert_eq!(late_joiner_gets(&router), Vec::<u8>::new());
        send(true, 4);
        assert_eq!(late_joiner_gets(&router), [4]);
        assert_eq!(router.video_pool.used(), key);
        // A publisher that goes gives its group's bytes back.
        router.disconnect(robot);
        assert_eq!(router.video_pool.used(), 0);
        drop(outbox);
    }

    #[test]
    fn the_group_goes_when_the_last_subscriber_does() {
        let router = Router::default();
        let (robot, topic) = video_topic(&router);
        // As a hub's link to its robot does: it hears its whole namespace, its own video
        // topic included, which it is not given, and which is no viewer.
        let all = Target::Pattern(regex::Regex::new("^/cam/.*").unwrap());
        router.subscribe(robot, all, SubOptions::default()).unwrap();
        let (viewer_id, _) = viewer(&router, SubOptions::default());
        topic.publish(robot, 1, 0, frame(true, 1));
        topic.publish(robot, 2, 0, frame(false, 2));
        // Nobody watches: the robot stops sending, and the group would be stale.
        router.disconnect(viewer_id);
        assert_eq!(router.video_pool.used(), 0);
        let (_, outbox) = viewer(&router, SubOptions::default());
        assert_eq!(numbers(&outbox), Vec::<u8>::new());
        assert!(
            topic.take_keyframe_ask(),
            "the newcomer asks for a keyframe"
        );
        // The newcomer starts at the next keyframe, which starts a group.
        topic.publish(robot, 3, 0, frame(false, 3));
        topic.publish(robot, 4, 0, frame(true, 4));
        assert_eq!(numbers(&outbox), [4]);
        assert_eq!(late_joiner_gets(&router), [4]);
    }

    #[test]
    fn a_frame_lost_before_the_router_holds_the_rest_of_its_group_back_from_everyone() {
        let router = Router::default();
        let (robot, topic) = video_topic(&router);
        let (_, outbox) = viewer(&router, SubOptions::default());
        assert!(
            topic.take_keyframe_ask(),
            "a viewer came with nothing to show"
        );
        assert!(!topic.take_keyframe_ask(), "asked once");
        let send = |seq: u64, key| topic.publish(robot, seq, 0, frame(key, seq as u8));
        // A group's later frame first (the robot's link kept it from before): held back.
        send(7, false);
        assert!(topic.take_keyframe_ask());
        send(8, true);
        send(9, false);
        send(9, false); // seen already
        // 10 never came: 11 and 12 are held back, and a keyframe is asked for.
        send(11, false);
        send(12, false);
        assert!(topic.take_keyframe_ask());
        send(13, true);
        send(14, false);
        assert_eq!(numbers(&outbox), [8, 9, 13, 14]);
        // A late joiner gets only the whole group.
        assert_eq!(late_joiner_gets(&router), [13, 14]);
        // A publisher that starts again (its numbers from 1) starts with a keyframe.
        send(1, true);
        send(2, false);
        assert_eq!(numbers(&outbox), [1, 2]);
        // Video in another encoding is not looked into.
        topic.publish(robot, 50, 0, Payload::json(&b"{}"[..]));
        assert_eq!(numbers(&outbox).len(), 1);
    }

    #[test]
    fn a_subscriber_that_lost_a_frame_skips_to_the_next_keyframe() {
        let router = Router::default();
        let (robot, topic) = video_topic(&router);
        let small = fleetlink_qos::TopicQos {
            policy: fleetlink_qos::Policy::DropOldest,
            queue: 4,
            ..fleetlink_qos::TopicQos::default()
        };
        let opts = SubOptions {
            qos: Some(small),
            ..SubOptions::default()
        };
        let (_, outbox) = viewer(&router, opts);
        let _ = topic.take_keyframe_ask();
        let send = |seq: u64, key| topic.publish(robot, seq, 0, frame(key, seq as u8));
        // A slow viewer: six frames into a queue of four. The frames that do not fit are
        // the ones refused (evicting the keyframe would spoil all four).
        send(1, true);
        for seq in 2..=6 {
            send(seq, false);
        }
        assert!(
            topic.take_keyframe_ask(),
            "the lost frame asks for a keyframe"
        );
        assert_eq!(
            numbers(&outbox),
            [1, 2, 3, 4],
            "the whole part of the chain"
        );
        // With room again, the rest of the group is still refused: 5 never came.
        send(7, false);
        assert_eq!(numbers(&outbox), Vec::<u8>::new());
        send(8, true);
        send(9, false);
        assert_eq!(numbers(&outbox), [8, 9]);
        // Another viewer with room lost nothing.
        assert_eq!(late_joiner_gets(&router), [8, 9]);
        // A keyframe coming to a full queue evicts its oldest frame: the frames queued
        // after that one are skipped, the keyframe is given.
        for seq in 10..=14 {
            send(seq, false);
        }
        send(15, true);
        assert_eq!(numbers(&outbox), [15]);
    }

    #[test]
    fn a_throttled_subscriber_is_given_keyframes_past_its_rate_limit() {
        let router = Router::default();
        let (robot, topic) = video_topic(&router);
        let throttled = fleetlink_qos::TopicQos {
            policy: fleetlink_qos::Policy::DropOldest,
            queue: 10,
            rate_limit_hz: Some(5.0),
            ..fleetlink_qos::TopicQos::default()
        };
        let opts = SubOptions {
            qos: Some(throttled),
            ..SubOptions::default()
        };
        let (_, outbox) = viewer(&router, opts);
        let _ = topic.take_keyframe_ask();
        let send = |seq: u64, key| topic.publish(robot, seq, 0, frame(key, seq as u8));
        // Faster than 5 a second: the first frame passes, the second is over the limit and
        // the rest of the group is worthless; the next keyframe passes all the same.
        send(1, true);
        send(2, false);
        assert!(topic.take_keyframe_ask(), "a keyframe is asked for");
        send(3, false);
        send(4, true);
        send(5, false);
        send(6, false);
        assert_eq!(numbers(&outbox), [1, 4]);
    }

    #[test]
    fn the_group_goes_with_its_publisher() {
        let router = Router::default();
        let (robot, topic) = video_topic(&router);
        // A viewer keeps the topic alive after the robot goes.
        let (_, _outbox) = viewer(&router, SubOptions::default());
        topic.publish(robot, 1, 0, frame(true, 1));
        topic.publish(robot, 2, 0, frame(false, 2));
        assert_eq!(late_joiner_gets(&router), [1, 2]);
        router.disconnect(robot);
        assert_eq!(
            late_joiner_gets(&router),
            Vec::<u8>::new(),
            "a stream that ended"
        );
    }

    #[test]
    fn other_topics_keep_nothing() {
        let router = Router::default();
        let (robot, _) = router.connect(ClientKind::Internal { role: "cam".into() }, None);
        let name = TopicName::parse("/cam/video").unwrap();
        let schema = Schema::named("sensor_msgs/msg/CompressedImage");
        let topic = router.advertise(robot, &name, schema, false).unwrap();
        topic.publish(robot, 1, 0, frame(true, 1));
        assert_eq!(late_joiner_gets(&router), Vec::<u8>::new());
    }
}
