//! Keyframe asks between federated hubs (issue 60): a keyframe wanted at the hub that
//! receives a video topic is wanted at the hub where it is published, whose robot link
//! then asks the robot; asks are acted upon at most once a second per topic, and only
//! for a hub the rules let subscribe to the topic.

use std::sync::Arc;
use std::sync::atomic::AtomicU64;
use std::sync::atomic::Ordering::Relaxed;
use std::time::{Duration, Instant};

use fleetlink_federation::Counters;
use fleetlink_federation::keys::{self, Offer};
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::router::{ClientKind, SubOptions, Target};
use fleetlink_relay::{ClientId, Topic, TopicName};
use zenoh::liveliness::LivelinessToken;

use crate::util::*;

const VIDEO: &str = "foxglove_msgs/msg/CompressedVideo";

fn name(s: &str) -> TopicName {
    TopicName::parse(s).unwrap()
}

/// A client of `hub` that publishes `topic` as video.
fn camera(hub: &Hub, topic: &str) -> (ClientId, Arc<Topic>) {
    let (cam, _) = hub.router.connect(
        ClientKind::Internal {
            role: "camera".into(),
        },
        None,
    );
    let t = hub
        .router
        .advertise(cam, &name(topic), Schema::named(VIDEO), false)
        .unwrap();
    (cam, t)
}

/// A frame the routers pass as it is (they look into CDR video only), so that neither
/// hub's group of pictures wants a keyframe of its own accord.
fn frame() -> Payload {
    Payload::new(Encoding::Json, br#"{"format":"h264"}"#.to_vec())
}

fn count(hub: &Hub, which: impl Fn(&Counters) -> &AtomicU64) -> u64 {
    which(&hub.federation.shared().counters).load(Relaxed)
}

/// Whether `hub` sends `topic` to another hub.
fn sent_elsewhere(hub: &Hub, topic: &str) -> bool {
    hub.federation
        .shared()
        .exports
        .lock()
        .unwrap()
        .get(topic)
        .is_some_and(|f| f.wanted.load(Relaxed))
}

/// A Zenoh peer that passes for a hub of the fleet: it names itself and wants topics by
/// its tokens, and asks for keyframes as a hub does.
struct FakeHub {
    session: zenoh::Session,
    zid: String,
    _tokens: Vec<LivelinessToken>,
}

impl FakeHub {
    async fn join(endpoint: &str, hub_name: &str, wants: &[&str]) -> FakeHub {
        let (cfg, _) = plain_tcp(&[endpoint.to_owned()], &[]);
        let session = zenoh::open(cfg).await.unwrap();
        let zid = session.zid().to_string();
        let offers = std::iter::once(Offer::Hub {
            name: hub_name.into(),
        })
        .chain(wants.iter().map(|w| Offer::Want { name: (*w).into() }));
        let mut tokens = Vec::new();
        for offer in offers {
            let key = keys::offer_key(FLEET, &zid, &offer).unwrap();
            tokens.push(session.liveliness().declare_token(key).await.unwrap());
        }
        FakeHub {
            session,
            zid,
            _tokens: tokens,
        }
    }

    /// Asks hub `to` for a keyframe of `topic`, `times` times at once.
    async fn ask(&self, to: &Hub, topic: &str, times: usize) {
        let key = keys::keyframe_key(FLEET, &to.federation.shared().me, &self.zid, topic).unwrap();
        for _ in 0..times {
            self.session
                .put(key.clone(), zenoh::bytes::ZBytes::new())
                .await
                .unwrap();
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_keyframe_wanted_where_a_video_is_received_is_wanted_where_it_is_published() {
    let (a, endpoint) = listening_hub("hub-a").await;
    let b = hub_linked_to("hub-b", &endpoint).await;
    let video = "/robot1/camera/video";
    let (cam, on_a) = camera(&a, video);
    eventually("hub B to list the video", || {
        b.router.topic(&name(video)).is_some()
    })
    .await;
    let (viewer, queue) = b.router.connect(ClientKind::Foxglove, None);
    b.router
        .subscribe(viewer, Target::Exact(name(video)), SubOptions::default())
        .unwrap();
    eventually("hub A to send the video to hub B", || {
        sent_elsewhere(&a, video)
    })
    .await;
    // Hub A's federation came as a subscriber with nothing kept to give it: that want is
    // hub A's own.
    let _ = on_a.take_keyframe_ask();
    let acted = count(&a, |c| &c.keyframe_asks_acted);

    // The viewer at hub B keeps losing frames (as in a queue too short): hub B's router
    // wants a keyframe, and hub B looks when the next frame comes from hub A.
    let on_b = b.router.topic(&name(video)).unwrap();
    let started = Instant::now();
    let mut seq = 0;
    within("hub A's topic to want a keyframe", async {
        loop {
            on_b.want_keyframe();
            seq += 1;
            on_a.publish(cam, seq, 0, frame());
            if on_a.take_keyframe_ask() {
                return;
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await;
    assert!(count(&a, |c| &c.keyframe_asks_acted) > acted);
    let asked = count(&b, |c| &c.keyframe_asks_out);
    let seconds = started.elapsed().as_secs();
    assert!(
        (1..=seconds + 2).contains(&asked),
        "hub B asked {asked} times in {seconds} s and a little: at most once a second"
    );
    let got = queue.take(1000, usize::MAX, Instant::now()).items.len();
    assert!(got > 0, "the viewer at hub B got the frames");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn asks_are_acted_upon_at_most_once_a_second_per_topic() {
    let (a, endpoint) = listening_hub("hub-a").await;
    let video = "/robot2/camera/video";
    let (_cam, on_a) = camera(&a, video);
    let fake = FakeHub::join(&endpoint, "hub-f", &[video]).await;
    eventually("hub A to send the video to the other hub", || {
        sent_elsewhere(&a, video)
    })
    .await;
    let _ = on_a.take_keyframe_ask();
    let heard = count(&a, |c| &c.keyframe_asks_in);
    let acted = count(&a, |c| &c.keyframe_asks_acted);

    fake.ask(&a, video, 5).await;
    eventually("hub A to hear the five asks", || {
        count(&a, |c| &c.keyframe_asks_in) == heard + 5
    })
    .await;
    assert_eq!(count(&a, |c| &c.keyframe_asks_acted), acted + 1);
    assert!(on_a.take_keyframe_ask(), "the topic wants a keyframe");
    assert!(!on_a.take_keyframe_ask(), "once");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_hub_the_rules_forbid_to_subscribe_asks_for_nothing() {
    let (a, endpoint) = listening_hub("hub-a").await;
    a.set_rules(
        r#"
rules:
  - subject: {hub: hub-f}
    names: "/robot3/.*"
    ops: [subscribe]
    effect: deny
"#,
    );
    let video = "/robot3/camera/video";
    let (_cam, on_a) = camera(&a, video);
    let fake = FakeHub::join(&endpoint, "hub-f", &[video]).await;
    eventually("hub A to know the other hub by its name", || {
        a.federation.shared().peer_name(&fake.zid) == "hub-f" && sent_elsewhere(&a, video)
    })
    .await;
    let _ = on_a.take_keyframe_ask();
    let refused = count(&a, |c| &c.refused);
    let acted = count(&a, |c| &c.keyframe_asks_acted);

    fake.ask(&a, video, 1).await;
    eventually("hub A to refuse the ask", || {
        count(&a, |c| &c.refused) > refused
    })
    .await;
    assert_eq!(count(&a, |c| &c.keyframe_asks_acted), acted);
    assert!(!on_a.take_keyframe_ask(), "the topic wants nothing");
}
