//! A video topic's frames since its last keyframe (its group of pictures), kept so that a
//! subscriber who comes in the middle of a stream gets the keyframe and what followed at
//! once and decodes from its first message, as a latched topic's subscriber gets its one
//! message (docs/video.md).
//!
//! Only `foxglove_msgs/msg/CompressedVideo` in CDR is looked into (the access unit's
//! leading NAL headers, [`fleetlink_msg::h264::is_keyframe`]); a group that grows past
//! [`MAX_FRAMES`] or [`MAX_BYTES`] is let go whole, and the next keyframe starts a new one.

use std::sync::{Arc, Mutex, MutexGuard};

use fleetlink_proto::Encoding;

use crate::message::Message;

/// Most frames kept: 20 s at 15 fps, longer than any keyframe interval worth sending.
pub const MAX_FRAMES: usize = 300;
/// Most payload bytes kept per topic.
pub const MAX_BYTES: usize = 16 << 20;

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
#[derive(Default)]
pub struct Gop {
    kept: Mutex<Kept>,
}

/// The group, behind [`Gop::lock`].
#[derive(Default)]
pub struct Kept {
    frames: Vec<Arc<Message>>,
    bytes: usize,
}

impl Gop {
    /// The group, locked. The router holds this while it fans a frame out (keeping it,
    /// then queueing it for the subscribers it reads under the lock) and while it adds a
    /// subscriber (replaying the group into its queue): so a frame reaches a new
    /// subscriber either in the replay or after it, once, in order.
    pub fn lock(&self) -> MutexGuard<'_, Kept> {
        self.kept.lock().unwrap_or_else(|p| p.into_inner())
    }
}

impl Kept {
    /// Takes a message published on the topic: a keyframe starts the group afresh, any
    /// other frame joins a group that has begun.
    pub fn keep(&mut self, msg: &Arc<Message>) {
        if is_keyframe(msg) {
            self.frames.clear();
            self.bytes = 0;
        } else if self.frames.is_empty() {
            return;
        }
        self.bytes += msg.payload.len();
        self.frames.push(msg.clone());
        if self.frames.len() > MAX_FRAMES || self.bytes > MAX_BYTES {
            // Too long to give whole: nobody gets a part of it.
            self.frames = Vec::new();
            self.bytes = 0;
        }
    }

    /// The group so far, keyframe first (empty before a keyframe was seen).
    pub fn frames(&self) -> &[Arc<Message>] {
        &self.frames
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

    /// What a new subscriber of `/cam/video` finds in its queue at once.
    fn late_joiner_gets(router: &Router) -> Vec<u8> {
        let (c, outbox) = router.connect(ClientKind::Foxglove, None);
        let name = TopicName::parse("/cam/video").unwrap();
        router
            .subscribe(c, Target::Exact(name), SubOptions::default())
            .unwrap();
        let got = outbox.take(1000, usize::MAX, Instant::now());
        router.disconnect(c);
        // The last byte of each access unit: its number.
        got.items
            .iter()
            .map(|(_, _, m)| *m.payload.bytes.last().unwrap())
            .collect()
    }

    #[test]
    fn a_late_subscriber_gets_the_last_keyframe_and_the_frames_since() {
        let router = Router::default();
        let (robot, _) = router.connect(
            ClientKind::Internal {
                role: "video".into(),
            },
            None,
        );
        let name = TopicName::parse("/cam/video").unwrap();
        let schema = Schema::named("foxglove_msgs/msg/CompressedVideo");
        let topic = router.advertise(robot, &name, schema, false).unwrap();
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
