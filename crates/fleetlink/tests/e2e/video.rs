//! Video through a real hub and agent (docs/video.md): a subscriber who lost frames skips to
//! a keyframe, which the hub asks the robot for (`PULL`), so it comes long before the
//! stream's own keyframe interval, also for a viewer upstream of a site hub; a subscriber
//! who comes mid-stream starts at a keyframe; and nobody is given a frame whose
//! predecessor it lacks.

use std::sync::Arc;
use std::time::{Duration, Instant};

use fleetlink_agent::AgentOptions;
use fleetlink_agent::config::AgentConfig;
use fleetlink_qos::{Policy, TopicQos};
use fleetlink_relay::router::{SubOptions, Target};
use fleetlink_relay::{ClientKind, Message, Outbox, Router, TopicName};

use crate::util::*;

/// A robot whose simulated camera (320x240 JPEG, 15 Hz) is offered as video with a
/// keyframe only every 60 s of its own accord.
const ROBOT: &str = "\
sim:
  laser_scan: null
  odometry: null
  pose: null
  point_cloud: null
  image: { rate_hz: 15 }
video:
  /camera/image/compressed: { topic: /camera/video, fps: 15, keyframe_s: 60 }
";

/// The robot's video at its hub.
const VIDEO: &str = "/robot1/camera/video";

/// A subscriber at a hub to the video `name` with a queue of `room` frames.
fn viewer(router: &Arc<Router>, name: &str, room: usize) -> Arc<Outbox> {
    let (client, outbox) = router.connect(
        ClientKind::Internal {
            role: "viewer".into(),
        },
        None,
    );
    let opts = SubOptions {
        qos: Some(TopicQos {
            policy: Policy::DropOldest,
            queue: room,
            ..TopicQos::default()
        }),
        ..SubOptions::default()
    };
    let name = TopicName::parse(name).unwrap();
    router.subscribe(client, Target::Exact(name), opts).unwrap();
    outbox
}

/// Frames the viewer receives until it has `at_least` of them, or `within` has passed.
async fn frames(outbox: &Outbox, at_least: usize, within: Duration) -> Vec<Arc<Message>> {
    let until = Instant::now() + within;
    let mut got = Vec::new();
    while got.len() < at_least && Instant::now() < until {
        let batch = outbox.take(100, usize::MAX, Instant::now());
        got.extend(batch.items.into_iter().map(|(_, _, m)| m));
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
    got
}

/// The frames start at a keyframe and every later one follows its predecessor or is a
/// keyframe.
fn assert_whole_chain(what: &str, got: &[Arc<Message>]) {
    assert!(!got.is_empty(), "{what}: no frames");
    assert!(
        fleetlink_relay::gop::is_keyframe(&got[0]),
        "{what}: the first frame is not a keyframe"
    );
    for w in got.windows(2) {
        assert!(
            w[1].seq == w[0].seq + 1 || fleetlink_relay::gop::is_keyframe(&w[1]),
            "{what}: frame {} came after {} without a keyframe",
            w[1].seq,
            w[0].seq
        );
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_viewer_that_lost_frames_resumes_at_a_keyframe_asked_of_the_robot() {
    let hub = start_hub().await;
    let cfg = AgentConfig::from_str(ROBOT, "robot.yaml").unwrap();
    let mut opts = AgentOptions::from_config(&cfg).unwrap();
    opts.uplink = uplink_config(&hub, "robot1");
    opts.local_listen = None;
    let agent = start_agent_opts(opts).await;
    agent.wait_connected().await;
    let router = hub.state.router.clone();

    // A viewer who reads: from its first frame, a whole chain.
    let steady = viewer(&router, VIDEO, 64);
    let first = frames(&steady, 15, Duration::from_secs(20)).await;
    assert!(first.len() >= 15, "{} frames in 20 s", first.len());
    assert_whole_chain("a steady viewer", &first);

    // A slow viewer: a queue of two, not read for a second. Its queue drops frames, and
    // the stream's keyframe (with keyframe_s: 60) was long ago: what it gets must start at
    // a keyframe the hub asked the robot for, well within the 60 s.
    let slow = viewer(&router, VIDEO, 2);
    tokio::time::sleep(Duration::from_secs(1)).await;
    let resumed = frames(&slow, 20, Duration::from_secs(20)).await;
    assert!(resumed.len() >= 20, "{} frames in 20 s", resumed.len());
    assert_whole_chain("a viewer that lost frames", &resumed);

    // One who comes mid-stream starts at the kept keyframe.
    let late = viewer(&router, VIDEO, 64);
    let got = frames(&late, 5, Duration::from_secs(20)).await;
    assert_whole_chain("a viewer who came mid-stream", &got);

    // The steady viewer lost nothing meanwhile.
    let more = frames(&steady, 1, Duration::from_secs(20)).await;
    let all: Vec<_> = first.into_iter().chain(more).collect();
    assert_whole_chain("the steady viewer throughout", &all);
    agent.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_viewer_upstream_of_a_site_hub_that_lost_frames_resumes_at_a_keyframe() {
    // The cloud's PULL reaches the site hub's link upstream, which marks the topic there;
    // the site's link to the robot asks the robot.
    let cloud = start_hub().await;
    let site = start_hub().await;
    let _link = link_site(&cloud, &site, "site7").await;
    let cfg = AgentConfig::from_str(ROBOT, "robot.yaml").unwrap();
    let mut opts = AgentOptions::from_config(&cfg).unwrap();
    opts.uplink = uplink_config(&site, "robot1");
    opts.local_listen = None;
    let agent = start_agent_opts(opts).await;
    agent.wait_connected().await;
    let router = cloud.state.router.clone();
    let upstream = "/site7/robot1/camera/video";

    let steady = viewer(&router, upstream, 64);
    let first = frames(&steady, 15, Duration::from_secs(20)).await;
    assert!(first.len() >= 15, "{} frames in 20 s", first.len());
    assert_whole_chain("a steady viewer upstream", &first);

    let slow = viewer(&router, upstream, 2);
    tokio::time::sleep(Duration::from_secs(1)).await;
    let resumed = frames(&slow, 20, Duration::from_secs(20)).await;
    assert!(resumed.len() >= 20, "{} frames in 20 s", resumed.len());
    assert_whole_chain("a viewer upstream that lost frames", &resumed);
    agent.shutdown().await;
    site.shutdown().await;
    cloud.shutdown().await;
}
