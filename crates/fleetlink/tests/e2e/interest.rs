//! The demand-driven uplink: a robot's topic goes up the link only while someone at the
//! hub wants it; it stays listed meanwhile (idle), its latest message reaches a new
//! subscriber at once, and many subscribers at the hub cost one copy on the link; after a
//! blackout, an age limit keeps stale messages off the link.

use std::sync::atomic::Ordering::Relaxed;
use std::time::Duration;

use fleetlink_qos::TopicQosSpec;
use fleetlink_relay::{Topic, TopicName};
use serde_json::json;

use crate::util::*;

fn hub_topic(hub: &TestHub, name: &str) -> Option<std::sync::Arc<Topic>> {
    hub.state.router.topic(&TopicName::parse(name).unwrap())
}

/// True if `client` receives no publish within `wait`.
async fn nothing_within(client: &mut Rosbridge, wait: Duration) -> bool {
    tokio::time::timeout(wait, client.recv_op("publish"))
        .await
        .is_err()
}

/// Messages of `name` the hub received from the robot.
fn received(hub: &TestHub, name: &str) -> u64 {
    hub_topic(hub, name).map_or(0, |t| t.stats.messages.load(Relaxed))
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_robot_topic_flows_only_while_someone_at_the_hub_wants_it() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "robot1").await;
    let mut scan = LocalPublisher::new(&agent.router, "/scan", "std_msgs/msg/String");
    let mut other = LocalPublisher::new(&agent.router, "/other", "std_msgs/msg/String");
    for i in 0..20 {
        scan.publish_json(&json!({ "data": format!("scan {i}") }));
        other.publish_json(&json!({ "data": format!("other {i}") }));
    }
    // Announced but held back: listed at the hub, idle, nothing received.
    eventually("both topics listed idle at the hub", || {
        ["/robot1/scan", "/robot1/other"]
            .iter()
            .all(|n| hub_topic(&hub, n).is_some_and(|t| t.is_idle()))
    })
    .await;
    tokio::time::sleep(Duration::from_millis(300)).await;
    assert_eq!(
        received(&hub, "/robot1/scan"),
        0,
        "sent with nobody subscribed"
    );
    assert_eq!(received(&hub, "/robot1/other"), 0);

    // A subscriber gets the latest message at once, without waiting for a publish.
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/robot1/scan", "id": "s1"}))
        .await;
    let first = within("the cached latest message", op.recv_op("publish")).await;
    assert_eq!(first["msg"]["data"], "scan 19");
    assert!(!hub_topic(&hub, "/robot1/scan").unwrap().is_idle());

    // Three subscribers at the hub: each message crosses the link once.
    let mut more = Vec::new();
    for i in 0..2 {
        let mut c = Rosbridge::connect(&hub.ws_url()).await;
        c.send(json!({"op": "subscribe", "topic": "/robot1/scan", "id": format!("m{i}")}))
            .await;
        more.push(c);
    }
    // Their subscriptions are in place once the hub's topic has four subscribers: the
    // three clients and the robot's own link (it receives what is sent to its namespace,
    // never its own messages).
    eventually("three subscribers", || {
        hub_topic(&hub, "/robot1/scan").unwrap().subscriber_count() >= 4
    })
    .await;
    let before = received(&hub, "/robot1/scan");
    for i in 20..30 {
        scan.publish_json(&json!({ "data": format!("scan {i}") }));
    }
    eventually("ten more messages at the hub", || {
        received(&hub, "/robot1/scan") >= before + 10
    })
    .await;
    for c in [&mut op].into_iter().chain(more.iter_mut()) {
        let mut last = String::new();
        while last != "scan 29" {
            let m = within("every subscriber's copy", c.recv_op("publish")).await;
            last = m["msg"]["data"].as_str().unwrap().to_owned();
        }
    }
    tokio::time::sleep(Duration::from_millis(200)).await;
    assert_eq!(
        received(&hub, "/robot1/scan"),
        before + 10,
        "three subscribers, one copy per message on the link"
    );
    // The other topic never moved.
    assert_eq!(received(&hub, "/robot1/other"), 0);

    // Everyone leaves: the topic is held back again within a second.
    drop(op);
    drop(more);
    within("the topic goes idle", async {
        while !hub_topic(&hub, "/robot1/scan").is_some_and(|t| t.is_idle()) {
            tokio::time::sleep(Duration::from_millis(10)).await;
        }
    })
    .await;
    // Give the agent the INTEREST before counting.
    tokio::time::sleep(Duration::from_millis(300)).await;
    let idle_since = received(&hub, "/robot1/scan");
    for i in 30..50 {
        scan.publish_json(&json!({ "data": format!("scan {i}") }));
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    tokio::time::sleep(Duration::from_millis(300)).await;
    assert_eq!(
        received(&hub, "/robot1/scan"),
        idle_since,
        "sent while idle"
    );
    agent.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn always_topics_flow_and_interest_survives_a_reconnect() {
    let hub = start_hub().await;
    let mut cfg = uplink_config(&hub, "robot2");
    cfg.topic_qos = vec![(
        TopicName::parse("/heartbeat").unwrap(),
        TopicQosSpec {
            always: Some(true),
            ..Default::default()
        },
    )];
    let agent = start_agent_with(cfg, false).await;
    agent.wait_connected().await;
    let mut beat = LocalPublisher::new(&agent.router, "/heartbeat", "std_msgs/msg/String");
    let mut pose = LocalPublisher::new(&agent.router, "/pose", "std_msgs/msg/String");
    for i in 0..5 {
        beat.publish_json(&json!({ "data": format!("beat {i}") }));
        pose.publish_json(&json!({ "data": format!("pose {i}") }));
    }
    eventually("the always topic arrives with nobody subscribed", || {
        received(&hub, "/robot2/heartbeat") == 5
    })
    .await;
    eventually("pose listed", || hub_topic(&hub, "/robot2/pose").is_some()).await;
    assert_eq!(received(&hub, "/robot2/pose"), 0);

    // A subscriber, then a hub restart: after the reconnect the subscriber's resubscribe
    // is interest again, and the robot's latest pose reaches it.
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/robot2/pose", "id": "p"}))
        .await;
    let m = within("pose", op.recv_op("publish")).await;
    assert_eq!(m["msg"]["data"], "pose 4");
    let (addr, dir) = (hub.addr, hub.data_dir.clone());
    drop(op);
    hub.shutdown().await;
    agent.wait_disconnected().await;
    pose.publish_json(&json!({ "data": "pose while down" }));
    let hub = start_hub_at(addr, dir, Duration::from_millis(500)).await;
    agent.wait_connected().await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/robot2/pose", "id": "p"}))
        .await;
    let m = within("pose after the reconnect", op.recv_op("publish")).await;
    assert_eq!(m["msg"]["data"], "pose while down");
    agent.shutdown().await;
    hub.shutdown().await;
}

/// A blackout with `max_age: 1s` on one topic and `no_drop` on another: after the link
/// returns, no message of the first arrives more than its age limit after it was
/// published, and the second loses nothing.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn after_a_blackout_nothing_older_than_its_age_limit_arrives() {
    let hub = start_hub().await;
    let proxy = Blackhole::start(hub.addr).await;
    let mut cfg = uplink_config(&hub, "robot3");
    cfg.hub_urls = vec![format!("ws://{}", proxy.addr)];
    cfg.topic_qos = vec![
        (
            TopicName::parse("/pose").unwrap(),
            TopicQosSpec {
                max_age: Some(Duration::from_secs(1)),
                ..Default::default()
            },
        ),
        (
            TopicName::parse("/log").unwrap(),
            TopicQosSpec {
                no_drop: Some(true),
                ..Default::default()
            },
        ),
    ];
    let agent = start_agent_with(cfg, false).await;
    agent.wait_connected().await;
    let mut pose = LocalPublisher::new(&agent.router, "/pose", "std_msgs/msg/String");
    let mut log = LocalPublisher::new(&agent.router, "/log", "std_msgs/msg/String");
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    for (topic, id) in [("/robot3/pose", "p"), ("/robot3/log", "l")] {
        op.send(json!({"op": "subscribe", "topic": topic, "id": id}))
            .await;
    }
    let now_ms = || {
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .unwrap()
            .as_millis() as u64
    };
    // Flowing before the blackout.
    pose.publish_json(&json!({ "data": now_ms().to_string() }));
    within("a pose before the blackout", op.recv_op("publish")).await;

    // 3 s without a link, a pose and a log line every 250 ms: the pose queue (16) keeps
    // all of them, so only the age limit can keep the old ones off the link (checked:
    // without `max_age` the oldest arrives about 3 s old and this test fails).
    proxy.cut();
    let mut logged = 0u64;
    for _ in 0..12 {
        pose.publish_json(&json!({ "data": now_ms().to_string() }));
        logged += 1;
        log.publish_json(&json!({ "data": logged.to_string() }));
        tokio::time::sleep(Duration::from_millis(250)).await;
    }
    proxy.restore();
    let (mut poses, mut logs, mut worst) = (0, Vec::new(), 0u64);
    within("the log's lines after the blackout", async {
        while logs.len() < logged as usize {
            let m = op.recv_op("publish").await;
            let data: u64 = m["msg"]["data"].as_str().unwrap().parse().unwrap();
            if m["topic"] == "/robot3/pose" {
                poses += 1;
                worst = worst.max(now_ms().saturating_sub(data));
            } else if !logs.contains(&data) {
                logs.push(data);
            }
        }
    })
    .await;
    // The link is back within a fraction of a second; a pose kept longer than its
    // limit would have arrived about 3 s old.
    assert!(
        worst <= 1_500,
        "a pose arrived {worst} ms after it was published ({poses} poses)"
    );
    logs.sort_unstable();
    assert_eq!(logs, (1..=logged).collect::<Vec<_>>(), "no_drop lost lines");
    // The hub hears what the age limit dropped on the robot (TOPIC_DROPS), and the log
    // topic lost nothing there either.
    let too_old = |name: &str| {
        hub_topic(&hub, name).map_or(0, |t| {
            t.stats.robot_drops(fleetlink_relay::DropReason::TooOld)
        })
    };
    eventually(
        "the robot's too_old drops of /robot3/pose at the hub",
        || too_old("/robot3/pose") > 0,
    )
    .await;
    assert_eq!(too_old("/robot3/log"), 0);
    agent.shutdown().await;
    hub.shutdown().await;
}

/// A pull topic (`mode: pull`): never sent by itself, even with a subscriber; each pull
/// (the rosbridge `pull` op, or the REST call) brings exactly one message, the latest.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_pull_topic_sends_exactly_one_message_per_request() {
    let hub = start_hub().await;
    let mut cfg = uplink_config(&hub, "robot4");
    cfg.topic_qos = vec![(
        TopicName::parse("/map").unwrap(),
        TopicQosSpec {
            mode: Some(fleetlink_qos::Mode::Pull),
            ..Default::default()
        },
    )];
    let agent = start_agent_with(cfg, false).await;
    agent.wait_connected().await;
    let mut map = LocalPublisher::new(&agent.router, "/map", "std_msgs/msg/String");
    let mut odom = LocalPublisher::new(&agent.router, "/odom", "std_msgs/msg/String");
    for i in 0..5 {
        map.publish_json(&json!({ "data": format!("map {i}") }));
        odom.publish_json(&json!({ "data": format!("odom {i}") }));
    }
    eventually("the pull topic listed", || {
        hub_topic(&hub, "/robot4/map").is_some_and(|t| t.is_pull())
    })
    .await;
    let (status, listing) = http_json(
        hub.addr,
        "GET",
        "/api/v1/topics",
        Some(&hub.operator_token),
        None,
    )
    .await;
    assert_eq!(status, 200);
    let state = listing["topics"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["name"] == "/robot4/map")
        .map(|t| t["state"].clone());
    assert_eq!(state, Some(json!("pull")));

    // Subscribed, nothing comes by itself.
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "pull", "topic": "/robot4/map", "id": "early"}))
        .await;
    let refused = within("a refusal", op.recv_op("status")).await;
    assert!(
        refused["msg"]
            .as_str()
            .unwrap()
            .contains("subscribe to it first"),
        "{refused}"
    );
    op.send(json!({"op": "subscribe", "topic": "/robot4/map", "id": "m"}))
        .await;
    assert!(
        nothing_within(&mut op, Duration::from_millis(300)).await,
        "a pull topic flowed by itself"
    );
    assert_eq!(received(&hub, "/robot4/map"), 0);

    // One pull, one message: the latest.
    op.send(json!({"op": "pull", "topic": "/robot4/map", "id": "p1"}))
        .await;
    let m = within("the pulled message", op.recv_op("publish")).await;
    assert_eq!(m["msg"]["data"], "map 4");
    assert!(
        nothing_within(&mut op, Duration::from_millis(300)).await,
        "more than one message per pull"
    );
    map.publish_json(&json!({ "data": "map 5" }));
    op.send(json!({"op": "pull", "topic": "/robot4/map", "id": "p2"}))
        .await;
    let m = within("the second pull", op.recv_op("publish")).await;
    assert_eq!(m["msg"]["data"], "map 5");
    assert_eq!(received(&hub, "/robot4/map"), 2);

    // Over REST: the message in the answer; a streaming topic is refused with the reason.
    let (status, v) = http_json(
        hub.addr,
        "POST",
        "/api/v1/robots/robot4/topics/map/pull",
        Some(&hub.operator_token),
        None,
    )
    .await;
    assert_eq!(status, 200, "{v}");
    assert_eq!(v["msg"]["data"], "map 5");
    assert_eq!(v["topic"], "/robot4/map");
    let (status, v) = http_json(
        hub.addr,
        "POST",
        "/api/v1/robots/robot4/topics/odom/pull",
        Some(&hub.operator_token),
        None,
    )
    .await;
    assert_eq!(status, 409, "{v}");
    assert!(
        v["error"].as_str().unwrap().contains("not a pull topic"),
        "{v}"
    );
    agent.shutdown().await;
    hub.shutdown().await;
}
