//! Mirrors (issue 40, item 4): an agent beside offloaded nodes in the cloud presents its
//! robot's topics and services under the robot's own local names, sends the nodes'
//! outputs to the robot, and asks for each robot topic only while a local node reads it.

use std::sync::atomic::Ordering::Relaxed;
use std::time::Duration;

use fleetlink_agent::config::SimConfig;
use fleetlink_agent::uplink::LinkState;
use fleetlink_relay::TopicName;
use serde_json::json;

use crate::util::*;

/// The robot's simulated odometry (20 Hz) and pose, and its `set_mode` service.
fn odometry_only() -> SimConfig {
    SimConfig {
        laser_scan: None,
        point_cloud: None,
        image: None,
        ..SimConfig::default()
    }
}

/// A mirror of `robot` named `name`, with a robot token of its own.
fn mirror_config(hub: &TestHub, name: &str, robot: &str) -> fleetlink_agent::uplink::UplinkConfig {
    let mut cfg = uplink_config(hub, name);
    cfg.mirror = Some(fleetlink_auth::RobotName::new(robot).unwrap());
    cfg
}

/// The hub's subscribers of `name`, and whether the topic is idle (its robot holds it back).
fn at_hub(hub: &TestHub, name: &str) -> Option<(usize, bool)> {
    let name = TopicName::parse(name).unwrap();
    let snap = hub.state.router.snapshot(&name)?;
    Some((snap.subscribers.len(), snap.topic.is_idle()))
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_mirror_presents_its_robot_under_local_names_and_asks_only_for_what_is_read() {
    let hub = start_hub().await;
    hub.set_rules(
        "rules:\n  - subject: {robot: robot3_mirror}\n    names: \"/robot3/.*\"\n    ops: [publish, subscribe, call_service]\n",
    );
    let robot = start_agent_sim(uplink_config(&hub, "robot3"), true, Some(odometry_only())).await;
    robot.wait_connected().await;
    let mirror = start_agent_with(mirror_config(&hub, "robot3_mirror", "robot3"), true).await;
    mirror.wait_connected().await;
    match &*mirror.state.borrow() {
        LinkState::Connected { namespace, .. } => assert_eq!(namespace, "/robot3"),
        other => panic!("{other:?}"),
    }
    // The mirror is listed beside its robot, which it did not replace.
    let robots: Vec<String> = hub
        .state
        .registry
        .list()
        .iter()
        .map(|r| r.name.clone())
        .collect();
    assert_eq!(robots, ["robot3"]);
    let mirrors: Vec<String> = hub
        .state
        .registry
        .mirrors_of("robot3")
        .iter()
        .map(|r| r.name.clone())
        .collect();
    assert_eq!(mirrors, ["robot3_mirror"]);

    // Nobody reads the odometry: the robot holds it back.
    eventually("the robot's odometry at the hub", || {
        at_hub(&hub, "/robot3/odom").is_some()
    })
    .await;
    tokio::time::sleep(Duration::from_millis(300)).await;
    // (The robot's own link subscribes to its namespace, for commands.)
    let (base, idle) = at_hub(&hub, "/robot3/odom").unwrap();
    assert!(idle, "the robot sends its odometry with nobody reading it");

    // Two nodes beside the mirror read /odom, the robot's own name for it: both get it,
    // and the hub has one subscriber for it (the mirror), so it crosses the robot's link
    // once.
    let mut nodes = Vec::new();
    for i in 0..2 {
        let mut n = Rosbridge::connect(&mirror.local_url()).await;
        n.send(json!({"op": "subscribe", "topic": "/odom", "id": format!("n{i}")}))
            .await;
        nodes.push(n);
    }
    for n in &mut nodes {
        let m = within("the robot's odometry at the node", n.recv_op("publish")).await;
        assert_eq!(m["topic"], "/odom");
        assert!(m["msg"]["pose"]["pose"]["position"]["x"].is_number(), "{m}");
    }
    assert_eq!(at_hub(&hub, "/robot3/odom"), Some((base + 1, false)));
    let per_sec = messages_in(&hub, "/robot3/odom", Duration::from_secs(1)).await;
    // The simulator's 20 Hz cross the robot's link once, and the mirror is the hub's one
    // subscriber besides the robot: its two readers share one copy.
    assert!(
        (10..=30).contains(&per_sec),
        "{per_sec} odometry messages a second"
    );

    // The hub lists the mirror with its robot, what it reads and the offload signal.
    let (status, robots) = http_json(
        hub.addr,
        "GET",
        "/api/v1/robots",
        Some(&hub.operator_token),
        None,
    )
    .await;
    assert_eq!(status, 200, "{robots}");
    let listed = robots["robots"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["name"] == "robot3")
        .cloned()
        .unwrap();
    let m = &listed["mirrors"][0];
    assert_eq!(m["name"], "robot3_mirror", "{listed}");
    assert_eq!(m["reads"], json!(["/robot3/odom"]), "{listed}");
    assert!(m["inputs_bps"].as_f64().unwrap() > 0.0, "{listed}");
    assert!(
        m["offload"]["rule"]
            .as_str()
            .unwrap()
            .contains("capacity_bps"),
        "{m}"
    );

    // The robot's service, by its local name.
    let r = nodes[0]
        .call("/set_mode", json!({"data": true}), "mode")
        .await;
    assert_eq!(r["result"], true, "{r}");

    // A node's output reaches the robot under the name the robot's nodes expect.
    let mut on_robot = Rosbridge::connect(&robot.local_url()).await;
    on_robot
        .send(json!({"op": "subscribe", "topic": "/map", "id": "m"}))
        .await;
    nodes[0]
        .send(json!({"op": "advertise", "topic": "/map", "type": "std_msgs/msg/String"}))
        .await;
    let got = within("the cloud node's /map on the robot", async {
        loop {
            nodes[0]
                .send(json!({"op": "publish", "topic": "/map", "msg": {"data": "grid"}}))
                .await;
            if let Ok(m) =
                tokio::time::timeout(Duration::from_millis(100), on_robot.recv_op("publish")).await
            {
                return m;
            }
        }
    })
    .await;
    assert_eq!(
        (got["topic"].as_str(), got["msg"]["data"].as_str()),
        (Some("/map"), Some("grid"))
    );

    // The nodes stop reading: the mirror lets the topic go, the robot holds it back again.
    drop(nodes);
    eventually("the odometry let go at the hub", || {
        at_hub(&hub, "/robot3/odom") == Some((base, true))
    })
    .await;
    // The robot kept its one connection throughout.
    assert_eq!(robot.stats.connects.load(Relaxed), 1);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_mirror_without_rights_on_its_robot_is_refused_and_the_robot_keeps_its_link() {
    let hub = start_hub().await;
    let robot = start_agent(&hub, "robot3").await;
    // A robot token of its own, and no rule letting it act under /robot3.
    let mirror = start_agent_with(mirror_config(&hub, "robot3_mirror", "robot3"), false).await;
    let reason = mirror.wait_disconnected().await;
    assert!(
        reason.contains("may not mirror robot robot3")
            && reason.contains("no rule lets it publish under /robot3"),
        "{reason}"
    );
    // A mirror of itself is no mirror.
    let selfish = start_agent_with(mirror_config(&hub, "robot3", "robot3"), false).await;
    let reason = selfish.wait_disconnected().await;
    assert!(reason.contains("a name of its own"), "{reason}");
    assert_eq!(robot.stats.connects.load(Relaxed), 1);
    assert!(matches!(*robot.state.borrow(), LinkState::Connected { .. }));
    assert!(hub.state.registry.mirrors_of("robot3").is_empty());
}
