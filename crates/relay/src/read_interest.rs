//! Whether a robot's ROS bridges need to read a topic from the graph at all: a topic that
//! no local subscriber wants and the hub's link holds back (nobody at the hub watches it)
//! costs the robot's CPU for nothing — the bridge deserializes nothing, but it still
//! receives every message, and its publisher serializes them for it. The bridges ask
//! [`ReadInterest::look`] and stop reading a topic unwanted for [`UNWANTED_BEFORE_PAUSE`]
//! (docs/qos.md, "Reading only what is wanted").

use std::sync::Arc;
use std::time::{Duration, Instant};

use crate::names::{ClientId, TopicName};
use crate::outbox::Outbox;
use crate::router::Router;

/// How long a topic goes unwanted before a bridge stops reading it. A topic that a viewer
/// opens and closes now and then stays read (connecting again costs more than reading a
/// few seconds more); one nobody looks at stops costing the robot.
pub const UNWANTED_BEFORE_PAUSE: Duration = Duration::from_secs(10);

/// What a bridge should do about a topic it reads ([`ReadInterest::look`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Look {
    /// Someone wants it: read it (again, if reading was stopped).
    Read,
    /// Nobody wants it, for less than [`UNWANTED_BEFORE_PAUSE`]: leave it as it is.
    Wait,
    /// Nobody has wanted it for [`UNWANTED_BEFORE_PAUSE`]: stop reading it.
    Stop,
}

/// The agent's answer to "does anyone want this topic read?" (see the module docs).
pub struct ReadInterest {
    router: Arc<Router>,
    /// The agent's uplink: its subscription to everything counts only as far as its
    /// outbox sends the topic.
    uplink: ClientId,
    outbox: Arc<Outbox>,
}

impl ReadInterest {
    pub fn new(router: Arc<Router>, uplink: ClientId, outbox: Arc<Outbox>) -> ReadInterest {
        ReadInterest {
            router,
            uplink,
            outbox,
        }
    }

    /// How the uplink carries `topic` now: its messages waiting in the link's queue, and
    /// what the link may carry by rule (bytes/s: [`Outbox::send_limit`]). A video
    /// stream's bitrate follows it.
    pub fn link_load(&self, topic: &crate::Topic) -> (usize, Option<f64>) {
        (
            self.outbox.queued_for(topic.meta().id.0),
            self.outbox.send_limit(),
        )
    }

    /// Whether `topic`, which `reader` publishes into the router, is wanted: it is latched
    /// (its one message must be at hand), a local subscriber other than `reader` and the
    /// uplink has it, or the uplink sends it (the hub wants it, `always`, no-drop, a pull
    /// topic, or a hub that does not say what it wants). A topic the router does not know
    /// yet is wanted (nothing is known against it).
    pub fn wanted(&self, topic: &TopicName, reader: ClientId) -> bool {
        let Some(t) = self.router.topic(topic) else {
            return true;
        };
        if t.is_latched() || t.has_subscriber_besides(&[reader, self.uplink]) {
            return true;
        }
        self.outbox.reads(t.id().0)
    }

    /// Whether someone has asked for `topic`, which `reader` makes: a local subscriber
    /// other than `reader` and the uplink, or the hub's interest ([`Outbox::asked_for`]).
    /// Unlike [`ReadInterest::wanted`], a link that has not said what it wants asks for
    /// nothing: for what costs the robot to make, not merely to read (a video encoder).
    pub fn asked_for(&self, topic: &TopicName, reader: ClientId) -> bool {
        let Some(t) = self.router.topic(topic) else {
            return false;
        };
        t.has_subscriber_besides(&[reader, self.uplink]) || self.outbox.asked_for(t.id().0)
    }

    /// [`ReadInterest::wanted`], with the wait before stopping: `unwanted_since` is the
    /// topic's own record of when it was last found unwanted (kept by the bridge).
    pub fn look(
        &self,
        topic: &TopicName,
        reader: ClientId,
        unwanted_since: &mut Option<Instant>,
        now: Instant,
    ) -> Look {
        Self::after_wait(self.wanted(topic, reader), unwanted_since, now)
    }

    /// [`ReadInterest::asked_for`], with the wait before stopping of [`ReadInterest::look`].
    pub fn look_asked(
        &self,
        topic: &TopicName,
        reader: ClientId,
        unwanted_since: &mut Option<Instant>,
        now: Instant,
    ) -> Look {
        Self::after_wait(self.asked_for(topic, reader), unwanted_since, now)
    }

    fn after_wait(wanted: bool, unwanted_since: &mut Option<Instant>, now: Instant) -> Look {
        if wanted {
            *unwanted_since = None;
            return Look::Read;
        }
        let since = *unwanted_since.get_or_insert(now);
        if now.saturating_duration_since(since) >= UNWANTED_BEFORE_PAUSE {
            Look::Stop
        } else {
            Look::Wait
        }
    }

    /// Returns when the link's demand changes (the hub started or stopped wanting a
    /// topic); never without an uplink (`None`). Local subscribers coming and going are
    /// not signalled; bridges also look now and then.
    pub async fn changed(interest: &Option<Arc<ReadInterest>>) {
        match interest {
            Some(i) => i.outbox.interest_changed().await,
            None => std::future::pending().await,
        }
    }

    /// The bridge stopped reading `topic`: its latest message, kept for a viewer to come,
    /// would be stale by then, so it is let go (the viewer gets the next one read).
    pub fn stopped_reading(&self, topic: &TopicName) {
        if let Some(t) = self.router.topic(topic) {
            self.outbox.forget_latest(t.id().0);
        }
    }
}
