//! Keyframe asks between hubs (docs/video.md): viewers of a video topic on this hub, which
//! another hub sends here, are back within a round trip when they lose a frame, not a
//! whole keyframe interval.
//!
//! - **Asking** ([`Asker`]). This hub's router wants a keyframe of a video topic when its
//!   chain broke (a frame lost between the hubs, or in a viewer's queue) or a viewer came
//!   with nothing kept to give it ([`Topic::take_keyframe_ask`]). The intake of each
//!   wanted topic ([`crate::inlet`]) reads that after each message it publishes and
//!   whenever the topics loop looks at the topic (its subscribers changed), and asks the
//!   hubs that offer the topic: a put on `keyframe/<hub>/<me>/<topic>` without payload
//!   (an ask names only a topic). At most one ask a second leaves per topic; one wanted
//!   sooner waits for its second, so a viewer who comes to a stalled stream is served too.
//! - **Answering** ([`Answerer`]). An ask heard counts only if it comes from an admitted
//!   hub, for a video topic this hub sends to other hubs, and this hub's rules let that
//!   hub subscribe to it. Then, at most once a second per topic whoever asks, the topic is
//!   marked as wanting a keyframe ([`Topic::want_keyframe`]): the robot's link asks its
//!   robot (`PULL`) as it does for viewers here, and a topic this hub itself receives
//!   from elsewhere (through a site hub's link, or from another hub) asks on by the same
//!   rule.
//!
//! Design choice: the pacing of both sides is kept apart from Zenoh and the clock
//! ([`Outgoing`], [`Answers`], handed the time), so tests drive it on made-up instants.

use std::collections::HashMap;
use std::sync::atomic::Ordering::Relaxed;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use fleetlink_auth::HubName;
use fleetlink_hub::security::HubGate;
use fleetlink_relay::gate::{Gate, Op};
use fleetlink_relay::{Router, Topic, TopicId, TopicName};
use tokio::sync::Notify;
use tokio_util::sync::CancellationToken;
use zenoh::Session;
use zenoh::pubsub::Subscriber;
use zenoh::qos::CongestionControl;
use zenoh::sample::Locality;

use crate::keys;
use crate::{FederationError, Shared, zerr};

/// The most often a keyframe of one topic is asked for, and acted upon when asked: as
/// often as a hub asks its robot (`hub::agents::events`).
pub const EVERY: Duration = Duration::from_secs(1);

/// Hubs whose gates the answering side keeps; past this it starts afresh.
const GATES_KEPT: usize = 1024;

/// Asks waiting to leave, by topic (the sans-IO part of [`Asker`]).
#[derive(Debug, Default)]
pub struct Outgoing {
    /// One per topic wanted here that asks, or asked within the last second: let go
    /// once its second is over and nothing more is wanted ([`Outgoing::take_due`]).
    topics: HashMap<TopicName, Waiting>,
}

#[derive(Debug)]
struct Waiting {
    /// The hubs to ask, as of the latest want.
    hubs: Vec<String>,
    /// A keyframe is wanted and was not asked for yet.
    wanted: bool,
    /// The earliest the next ask of this topic may leave.
    next: Option<Instant>,
}

impl Outgoing {
    /// A keyframe of `name` is wanted from `hubs`.
    pub fn want(&mut self, name: &TopicName, hubs: Vec<String>) {
        let w = self.topics.entry(name.clone()).or_insert(Waiting {
            hubs: Vec::new(),
            wanted: false,
            next: None,
        });
        w.hubs = hubs;
        w.wanted = true;
    }

    /// The asks that may leave at `now` (each topic's hubs), and when the next one that
    /// waits for its second may.
    pub fn take_due(&mut self, now: Instant) -> (Vec<(TopicName, Vec<String>)>, Option<Instant>) {
        let mut due = Vec::new();
        for (name, w) in &mut self.topics {
            if w.wanted && w.next.is_none_or(|next| next <= now) {
                w.wanted = false;
                w.next = Some(now + EVERY);
                due.push((name.clone(), std::mem::take(&mut w.hubs)));
            }
        }
        // A topic whose second is over and that wants nothing is as if never asked.
        self.topics
            .retain(|_, w| w.wanted || w.next.is_some_and(|next| next > now));
        let deadline = self
            .topics
            .values()
            .filter(|w| w.wanted)
            .filter_map(|w| w.next)
            .min();
        (due, deadline)
    }
}

/// The asks this hub sends, shared by the intakes of its wanted topics (on Zenoh's
/// threads, which must not wait) and the loop that puts them into Zenoh ([`ask_loop`]).
#[derive(Default)]
pub struct Asker {
    // std Mutex: taken per want and per round of the loop; never held across an await.
    outgoing: Mutex<Outgoing>,
    ready: Notify,
}

impl Asker {
    /// Topic `topic` wants a keyframe, if its router says so: asked of `hubs` (those
    /// that send it here). Nothing without hubs: the want stays with the topic until one
    /// offers it.
    pub fn ask_if_wanted<'h>(
        &self,
        topic: &Topic,
        name: &TopicName,
        hubs: impl ExactSizeIterator<Item = &'h String>,
    ) {
        if hubs.len() == 0 || !topic.take_keyframe_ask() {
            return;
        }
        let hubs = hubs.cloned().collect();
        self.outgoing
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .want(name, hubs);
        self.ready.notify_one();
    }

    fn take_due(&self, now: Instant) -> (Vec<(TopicName, Vec<String>)>, Option<Instant>) {
        self.outgoing
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .take_due(now)
    }
}

/// Puts the asks into Zenoh as they become due, until `stop`.
pub async fn ask_loop(
    session: Session,
    asker: Arc<Asker>,
    shared: Arc<Shared>,
    stop: CancellationToken,
) {
    loop {
        let (due, deadline) = asker.take_due(Instant::now());
        for (name, hubs) in due {
            for hub in hubs {
                send(&session, &shared, &hub, &name).await;
            }
        }
        let wait = async {
            match deadline {
                Some(at) => tokio::time::sleep_until(at.into()).await,
                None => std::future::pending().await,
            }
        };
        tokio::select! {
            _ = stop.cancelled() => return,
            () = asker.ready.notified() => {}
            () = wait => {}
        }
    }
}

/// One ask of `hub` for a keyframe of `name`. Dropped under congestion: the next lost
/// frame asks again.
async fn send(session: &Session, shared: &Shared, hub: &str, name: &TopicName) {
    let Some(key) = keys::keyframe_key(&shared.fleet, hub, &shared.me, name.as_str()) else {
        return;
    };
    let put = session
        .put(key, zenoh::bytes::ZBytes::new())
        .congestion_control(CongestionControl::Drop)
        .allowed_destination(Locality::Remote)
        .await;
    match put {
        Ok(()) => {
            shared.counters.keyframe_asks_out.fetch_add(1, Relaxed);
        }
        Err(e) => tracing::debug!("federation: asking a keyframe of {name}: {e}"),
    }
}

/// What became of an ask heard from another hub.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Heard {
    /// From a hub not admitted, or one a rule does not let subscribe to the topic.
    Refused,
    /// For a topic that is not a video this hub sends to other hubs.
    NotSent,
    /// Within a second of the topic's last ask acted upon.
    Paced,
    /// The topic now wants a keyframe from its publisher.
    Marked,
}

/// The asks acted upon, by topic (the sans-IO part of [`Answerer`]).
#[derive(Debug, Default)]
pub struct Answers {
    /// When each topic may next be marked: one per video topic sent from here that was
    /// acted upon within the last second (those whose second is over are let go
    /// whenever an ask is acted upon).
    next: HashMap<TopicId, Instant>,
}

impl Answers {
    /// Whether an ask of topic `id` heard at `now` is acted upon (one a second per topic).
    pub fn take(&mut self, id: TopicId, now: Instant) -> bool {
        if self.next.get(&id).is_some_and(|next| *next > now) {
            return false;
        }
        self.next.retain(|_, next| *next > now);
        self.next.insert(id, now + EVERY);
        true
    }
}

/// The answering side: what an ask heard from another hub does here.
pub struct Answerer {
    router: Arc<Router>,
    shared: Arc<Shared>,
    // std Mutex: taken by the Zenoh callback per ask; never held across an await.
    state: Mutex<AnswerState>,
}

#[derive(Default)]
struct AnswerState {
    answers: Answers,
    /// This hub's gate for each asking hub, kept so that a refusal is audited once, with
    /// the name it was made for (over plain TCP a hub's name comes with its token).
    /// Admitted hubs only, at most [`GATES_KEPT`] (then it starts afresh).
    gates: HashMap<String, (HubName, HubGate)>,
}

impl Answerer {
    pub fn new(router: Arc<Router>, shared: Arc<Shared>) -> Answerer {
        Answerer {
            router,
            shared,
            state: Mutex::default(),
        }
    }

    /// Hub `from` asks for a keyframe of topic `name` (as it came, not checked yet).
    pub fn hear(&self, from: &str, name: &str, now: Instant) -> Heard {
        let counters = &self.shared.counters;
        if !self.shared.admission.is_admitted(from) {
            counters.refused.fetch_add(1, Relaxed);
            return Heard::Refused;
        }
        let Some(topic) = self.sent_video(name) else {
            return Heard::NotSent;
        };
        counters.keyframe_asks_in.fetch_add(1, Relaxed);
        let hub = self.shared.hub_name_of(from);
        let mut st = self.state.lock().unwrap_or_else(|p| p.into_inner());
        if st
            .gates
            .get(from)
            .is_none_or(|(made_for, _)| *made_for != hub)
        {
            if st.gates.len() >= GATES_KEPT {
                st.gates.clear();
            }
            st.gates
                .insert(from.to_owned(), (hub, self.shared.hub_gate(from)));
        }
        let (_, gate) = st.gates.get_mut(from).expect("inserted above");
        if !gate.allows_topic(topic.id().0, name, Op::Subscribe) {
            counters.refused.fetch_add(1, Relaxed);
            return Heard::Refused;
        }
        if !st.answers.take(topic.id(), now) {
            return Heard::Paced;
        }
        drop(st);
        topic.want_keyframe();
        counters.keyframe_asks_acted.fetch_add(1, Relaxed);
        Heard::Marked
    }

    /// Topic `name` if it is a video topic this hub sends to other hubs.
    fn sent_video(&self, name: &str) -> Option<Arc<Topic>> {
        let wanted = self
            .shared
            .exports
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .get(name)
            .is_some_and(|f| f.wanted.load(Relaxed));
        if !wanted {
            return None;
        }
        let topic = self.router.topic(&TopicName::parse(name).ok()?)?;
        fleetlink_relay::gop::is_video_type(&topic.meta().schema.type_name).then_some(topic)
    }
}

/// Listens for the asks other hubs make of this one.
pub async fn answer(
    session: &Session,
    answerer: Arc<Answerer>,
) -> Result<Subscriber<()>, FederationError> {
    let shared = answerer.shared.clone();
    let key = format!("{}/keyframe/{}/**", keys::root(&shared.fleet), shared.me);
    session
        .declare_subscriber(key)
        .allowed_origin(Locality::Remote)
        .callback(move |sample| {
            let Some((from, name)) =
                keys::parse_keyframe_key(&shared.fleet, &shared.me, sample.key_expr().as_str())
            else {
                shared.counters.malformed.fetch_add(1, Relaxed);
                return;
            };
            let heard = answerer.hear(&from, &name, Instant::now());
            tracing::trace!("federation: keyframe of {name} asked by hub {from}: {heard:?}");
        })
        .await
        .map_err(zerr)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn name(s: &str) -> TopicName {
        TopicName::parse(s).unwrap()
    }

    fn hubs(h: &[&str]) -> Vec<String> {
        h.iter().map(|s| (*s).to_owned()).collect()
    }

    #[test]
    fn an_ask_leaves_at_once_then_at_most_once_a_second_per_topic() {
        let t0 = Instant::now();
        let at = |ms: u64| t0 + Duration::from_millis(ms);
        let mut out = Outgoing::default();
        out.want(&name("/cam"), hubs(&["a"]));
        let (due, deadline) = out.take_due(at(0));
        assert_eq!(due, vec![(name("/cam"), hubs(&["a"]))]);
        assert_eq!(deadline, None, "nothing waits");

        // Wanted again within the second: it waits for it, however often it is wanted.
        for ms in [100, 200, 300] {
            out.want(&name("/cam"), hubs(&["a"]));
            let (due, deadline) = out.take_due(at(ms));
            assert!(due.is_empty(), "at {ms} ms");
            assert_eq!(deadline, Some(at(1000)));
        }
        // Another topic is not held up by the first.
        out.want(&name("/other"), hubs(&["b"]));
        let (due, _) = out.take_due(at(400));
        assert_eq!(due, vec![(name("/other"), hubs(&["b"]))]);

        let (due, deadline) = out.take_due(at(1000));
        assert_eq!(
            due,
            vec![(name("/cam"), hubs(&["a"]))],
            "once, at its second"
        );
        assert_eq!(deadline, None);
        assert!(
            out.take_due(at(5000)).0.is_empty(),
            "nothing more was wanted"
        );
        assert!(
            out.topics.is_empty(),
            "nothing kept once the seconds are over"
        );
    }

    #[test]
    fn asks_heard_are_acted_upon_once_a_second_per_topic_whoever_asks() {
        let t0 = Instant::now();
        let at = |ms: u64| t0 + Duration::from_millis(ms);
        let mut answers = Answers::default();
        let (cam, other) = (TopicId(1), TopicId(2));
        assert!(answers.take(cam, at(0)));
        for ms in [1, 10, 500, 999] {
            assert!(!answers.take(cam, at(ms)), "at {ms} ms");
        }
        assert!(
            answers.take(other, at(500)),
            "another topic has its own second"
        );
        assert!(answers.take(cam, at(1000)));
        assert!(!answers.take(cam, at(1500)));
        assert!(answers.take(cam, at(9000)));
        assert_eq!(
            answers.next.len(),
            1,
            "topics whose second is over are let go"
        );
    }
}
