//! QoS on the uplink, end to end: when a 2 MB point cloud and a small high-priority pose
//! wait together, the pose reaches the hub's subscribers first. (That a small message also
//! overtakes a large one whose chunks are already on the wire is tested deterministically
//! at the link level, `crates/relay/tests/relay/link_writer.rs`.)
//!
//! One thread runs hub, agent and test, so both messages are queued before the uplink's
//! writer can run: the order is decided by the scheduler, not by how the OS interleaves
//! threads on a busy machine.

use serde_json::json;

use crate::util::*;

#[tokio::test(flavor = "current_thread")]
async fn priority_topic_overtakes_a_2mb_point_cloud() {
    let hub = start_hub().await;
    let mut cfg = uplink_config(&hub, "robot_p");
    // The tests' short heartbeat (200 ms: a link silent for 400 ms is dead) is about
    // noticing outages quickly; on a starved machine this one thread can be silent that
    // long while it encodes 2 MB, and a link declared dead loses the cloud. What is tested
    // here is the order, so the link gets the default heartbeat.
    cfg.heartbeat = std::time::Duration::from_secs(1);
    let spec = |p: f32| fleetlink_qos::TopicQosSpec {
        priority: Some(p),
        ..Default::default()
    };
    cfg.topic_qos = vec![
        (
            fleetlink_relay::TopicName::parse("/points").unwrap(),
            spec(1.0),
        ),
        (
            fleetlink_relay::TopicName::parse("/pose").unwrap(),
            spec(100.0),
        ),
    ];
    let agent = start_agent_with(cfg, false).await;
    agent.wait_connected().await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/robot_p/points"}))
        .await;
    op.send(json!({"op": "subscribe", "topic": "/robot_p/pose"}))
        .await;
    // Blob types the registry does not know travel as they are (no conversion cost).
    let mut cloud = LocalPublisher::new(&agent.router, "/points", "test_msgs/msg/Blob");
    let mut pose = LocalPublisher::new(&agent.router, "/pose", "test_msgs/msg/Pose");
    let blob = "p".repeat(2 << 20);

    // Warm up until both subscriptions deliver, so the measured round starts clean.
    let mut saw = (false, false);
    within("both topics flowing", async {
        while saw != (true, true) {
            cloud.publish_json(&json!({"round": -1, "data": "small"}));
            pose.publish_json(&json!({"round": -1}));
            while let Ok(Some(v)) =
                tokio::time::timeout(std::time::Duration::from_millis(50), op.try_recv()).await
            {
                match v["topic"].as_str() {
                    Some("/robot_p/points") => saw.0 = true,
                    Some("/robot_p/pose") => saw.1 = true,
                    _ => {}
                }
            }
        }
    })
    .await;

    for round in 0..3 {
        // The cloud is queued first, the pose right behind it, with no await in between.
        cloud.publish_json(&json!({"round": round, "data": blob}));
        pose.publish_json(&json!({"round": round}));
        let mut order = Vec::new();
        within("the round's two messages", async {
            while order.len() < 2 {
                let v = op.recv_op("publish").await;
                if v["msg"]["round"] == round {
                    order.push(v["topic"].as_str().unwrap().to_owned());
                }
            }
        })
        .await;
        assert_eq!(
            order,
            ["/robot_p/pose", "/robot_p/points"],
            "round {round}: the pose must overtake the cloud"
        );
    }
    agent.shutdown().await;
    hub.shutdown().await;
}
