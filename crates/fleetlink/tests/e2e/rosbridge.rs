//! rosbridge v2 features as a client sees them on the hub: regex subscriptions across
//! robots, CBOR compression, throttling, fragmentation, rosapi name spellings, and the
//! per-topic remap of robot names.

use std::time::Duration;

use fleetlink_relay::queue::DropReason;
use serde_json::{Value, json};

use crate::util::*;

/// Publishes with `publish` until `pred` accepts a frame from `client`.
async fn pump_until(
    client: &mut Rosbridge,
    mut publish: impl FnMut(u32),
    mut pred: impl FnMut(&Value) -> bool,
) -> Value {
    within("an expected frame", async {
        for i in 0..4000 {
            publish(i);
            if let Ok(Some(v)) =
                tokio::time::timeout(Duration::from_millis(25), client.try_recv()).await
                && pred(&v)
            {
                return v;
            }
        }
        panic!("expected frame never came");
    })
    .await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn regex_subscription_collects_matching_topics_of_every_robot() {
    let hub = start_hub().await;
    let a = start_agent(&hub, "alpha").await;
    let b = start_agent(&hub, "beta").await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/[a-z]+/scan", "regex": true, "id": "all-scans"}))
        .await;
    let mut pa = LocalPublisher::new(&a.router, "/scan", "sensor_msgs/msg/LaserScan");
    let mut pb = LocalPublisher::new(&b.router, "/scan", "sensor_msgs/msg/LaserScan");
    let mut other = LocalPublisher::new(&a.router, "/odom", "nav_msgs/msg/Odometry");
    let mut seen = std::collections::BTreeSet::new();
    within("scans of both robots", async {
        for i in 0..4000u32 {
            pa.publish_json(&json!({"i": i}));
            pb.publish_json(&json!({"i": i}));
            other.publish_json(&json!({"i": i}));
            if let Ok(Some(v)) =
                tokio::time::timeout(Duration::from_millis(25), op.try_recv()).await
                && v["op"] == "publish"
            {
                let t = v["topic"].as_str().unwrap().to_owned();
                assert!(t.ends_with("/scan"), "pattern matched {t}");
                seen.insert(t);
                if seen.len() == 2 {
                    return;
                }
            }
        }
        panic!("saw only {seen:?}");
    })
    .await;
    assert_eq!(
        seen.into_iter().collect::<Vec<_>>(),
        ["/alpha/scan", "/beta/scan"]
    );
    a.shutdown().await;
    b.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn cbor_compression_delivers_binary_frames() {
    let hub = start_hub().await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/c", "compression": "cbor"}))
        .await;
    let mut p = hub_publisher(&hub, "/c", "std_msgs/msg/String");
    // Wait for a binary frame specifically.
    let got = within("a CBOR frame", async {
        for i in 0..4000u32 {
            p.publish_json(&json!({"data": "hello", "n": i}));
            if let Ok(Some(Ok(m))) = tokio::time::timeout(
                Duration::from_millis(25),
                futures_util::StreamExt::next(op.raw()),
            )
            .await
            {
                match m {
                    tokio_tungstenite::tungstenite::Message::Binary(b) => return b,
                    tokio_tungstenite::tungstenite::Message::Text(t) => {
                        panic!("expected binary, got text {t}")
                    }
                    _ => {}
                }
            }
        }
        panic!("no frame");
    })
    .await;
    let v: ciborium::Value = ciborium::from_reader(&got[..]).unwrap();
    let m = v.as_map().unwrap();
    assert_eq!(
        m[0],
        (
            ciborium::Value::Text("op".into()),
            ciborium::Value::Text("publish".into())
        )
    );
    assert_eq!(m[1].1, ciborium::Value::Text("/c".into()));
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn throttle_rate_thins_a_burst_and_counts_rate_limit_drops() {
    let hub = start_hub().await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/t", "throttle_rate": 60000}))
        .await;
    let mut p = hub_publisher(&hub, "/t", "std_msgs/msg/String");
    pump_until(
        &mut op,
        |i| p.publish_json(&json!({"n": i})),
        |v| v["op"] == "publish",
    )
    .await;
    // Within the next minute nothing else may be sent however much is published.
    for i in 0..500 {
        p.publish_json(&json!({"n": 10_000 + i}));
    }
    let extra = tokio::time::timeout(Duration::from_millis(300), op.try_recv()).await;
    assert!(extra.is_err(), "throttled subscription sent {extra:?}");
    let topic = hub
        .state
        .router
        .topic(&fleetlink_relay::TopicName::parse("/t").unwrap())
        .unwrap();
    assert!(topic.stats.drops(DropReason::RateLimit) >= 499);
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn fragment_size_splits_large_messages_into_fragments() {
    let hub = start_hub().await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/f", "fragment_size": 100}))
        .await;
    let mut p = hub_publisher(&hub, "/f", "std_msgs/msg/String");
    let text = "ü".repeat(300);
    let first = pump_until(
        &mut op,
        |_| p.publish_json(&json!({"data": text})),
        |v| v["op"] == "fragment",
    )
    .await;
    let total = first["total"].as_u64().unwrap() as usize;
    assert!(total > 1);
    let mut parts = vec![String::new(); total];
    parts[first["num"].as_u64().unwrap() as usize] = first["data"].as_str().unwrap().to_owned();
    let id = first["id"].clone();
    let mut got = 1;
    while got < total {
        let v = op.recv_op("fragment").await;
        if v["id"] == id {
            parts[v["num"].as_u64().unwrap() as usize] = v["data"].as_str().unwrap().to_owned();
            got += 1;
        }
    }
    let whole: Value = serde_json::from_str(&parts.concat()).unwrap();
    assert_eq!(whole["op"], "publish");
    assert_eq!(whole["msg"]["data"], text);
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn rosapi_answers_either_spelling_and_echoes_names_and_ids() {
    let hub = start_hub().await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    for (service, id) in [
        ("rosapi/topics", json!(17)),
        ("/rosapi/topics", json!("x")),
        ("/rosapi/get_ros_version", json!("v")),
    ] {
        op.send(json!({"op": "call_service", "service": service, "id": id}))
            .await;
        let v = op.recv_op("service_response").await;
        assert_eq!(v["service"], service);
        assert_eq!(v["id"], id);
        assert_eq!(v["result"], true);
    }
    let v = op.call("/rosapi/no_such", json!({}), "n").await;
    assert_eq!(v["result"], false);
    let v = op.call("/other/service", json!({}), "o").await;
    assert_eq!(v["result"], false);
    assert!(
        v["values"]
            .as_str()
            .unwrap()
            .contains("is not advertised by anyone")
    );
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn remapped_topic_appears_under_its_configured_hub_name() {
    let hub = start_hub().await;
    // Outside its own namespace a robot may publish only what a rule grants.
    hub.set_rules(
        "rules:\n  - subject: {robot: robot9}\n    names: \"/fleet/map\"\n    ops: [publish]\n",
    );
    let mut cfg = uplink_config(&hub, "robot9");
    cfg.names.remap.push((
        fleetlink_relay::TopicName::parse("/map").unwrap(),
        fleetlink_relay::TopicName::parse("/fleet/map").unwrap(),
    ));
    let agent = start_agent_with(cfg, false).await;
    agent.wait_connected().await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/fleet/map"}))
        .await;
    let mut m = LocalPublisher::new(&agent.router, "/map", "nav_msgs/msg/OccupancyGrid");
    let mut s = LocalPublisher::new(&agent.router, "/scan", "sensor_msgs/msg/LaserScan");
    let v = pump_until(
        &mut op,
        |i| m.publish_json(&json!({"i": i})),
        |v| v["op"] == "publish",
    )
    .await;
    assert_eq!(v["topic"], "/fleet/map");
    s.publish_json(&json!({}));
    let t = within("both names listed", async {
        loop {
            let t = op.call("/rosapi/topics", json!({}), "t").await;
            let names = t["values"]["topics"].clone();
            if names
                .as_array()
                .unwrap()
                .iter()
                .any(|n| n == "/robot9/scan")
            {
                return names;
            }
        }
    })
    .await;
    assert!(t.as_array().unwrap().iter().any(|n| n == "/fleet/map"));
    assert!(!t.as_array().unwrap().iter().any(|n| n == "/robot9/map"));
    agent.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_client_that_publishes_and_subscribes_on_one_connection_receives_its_own_messages() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "r1").await;
    for url in [hub.ws_url(), agent.local_url()] {
        let mut c = Rosbridge::connect(&url).await;
        c.send(json!({"op": "advertise", "topic": "/selfie", "type": "std_msgs/msg/String"}))
            .await;
        c.send(json!({"op": "subscribe", "topic": "/selfie", "id": "s"}))
            .await;
        c.send(json!({"op": "publish", "topic": "/selfie", "msg": {"data": "me"}}))
            .await;
        let m = c.recv_op("publish").await;
        assert_eq!(m["msg"]["data"], "me", "{url}: {m}");
    }
    // The loop guard stays for link peers: a robot's message goes up to the hub, whose
    // agent session (subscribed to /r1/.*) never sends it back down; a local client that
    // publishes and subscribes sees each of its messages exactly once.
    let mut on_hub = Rosbridge::connect(&hub.ws_url()).await;
    on_hub
        .send(json!({"op": "subscribe", "topic": "/r1/echoes", "id": "h"}))
        .await;
    let mut local = Rosbridge::connect(&agent.local_url()).await;
    local
        .send(json!({"op": "advertise", "topic": "/echoes", "type": "std_msgs/msg/String"}))
        .await;
    local
        .send(json!({"op": "subscribe", "topic": "/echoes", "id": "l"}))
        .await;
    // Until the hub has the topic, messages may not reach it; then send 20 counted ones.
    within("the robot's topic on the hub", async {
        for i in 0.. {
            local
                .send(json!({"op": "publish", "topic": "/echoes", "msg": {"data": format!("warm{i}")}}))
                .await;
            if let Ok(Some(_)) =
                tokio::time::timeout(Duration::from_millis(20), on_hub.try_recv()).await
            {
                return;
            }
        }
    })
    .await;
    for i in 0..20 {
        local
            .send(json!({"op": "publish", "topic": "/echoes", "msg": {"data": format!("n{i}")}}))
            .await;
    }
    let mut counted = std::collections::BTreeMap::<String, usize>::new();
    let deadline = tokio::time::Instant::now() + Duration::from_millis(800);
    while let Ok(Some(m)) = tokio::time::timeout_at(deadline, local.try_recv()).await {
        let d = m["msg"]["data"].as_str().unwrap_or_default().to_owned();
        if d.starts_with('n') {
            *counted.entry(d).or_default() += 1;
        }
    }
    assert_eq!(counted.len(), 20, "{counted:?}");
    assert!(
        counted.values().all(|n| *n == 1),
        "a message came back: {counted:?}"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn rosout_carries_hub_events_and_the_robots_own_logs() {
    let hub = start_hub().await;
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/rosout", "id": "r"}))
        .await;
    op.call("/rosapi/get_time", json!({}), "sync").await;
    let agent = start_agent(&hub, "r7").await;
    let line = within("the robot's arrival on /rosout", async {
        loop {
            let m = op.recv_op("publish").await;
            if m["msg"]["msg"]
                .as_str()
                .unwrap_or_default()
                .contains("robot r7 connected")
            {
                return m;
            }
        }
    })
    .await;
    assert_eq!(line["msg"]["level"], 20);
    assert_eq!(line["msg"]["name"], "fleetlink_hub");
    // A log line the robot publishes on its /rosout joins the hub's /rosout unchanged.
    let mut log = LocalPublisher::new(&agent.router, "/rosout", "rcl_interfaces/msg/Log");
    within("the robot's own log on /rosout", async {
        for i in 0..400u32 {
            log.publish_json(&json!({"stamp": {"sec": 1, "nanosec": i}, "level": 40,
                "name": "planner", "msg": "no path", "file": "", "function": "", "line": 0}));
            if let Ok(Some(m)) =
                tokio::time::timeout(Duration::from_millis(25), op.try_recv()).await
                && m["msg"]["name"] == "planner"
            {
                assert_eq!(m["msg"]["level"], 40);
                return;
            }
        }
        panic!("the robot's log never reached /rosout");
    })
    .await;
    agent.shutdown().await;
    within("the robot's departure on /rosout", async {
        loop {
            let m = op.recv_op("publish").await;
            if m["msg"]["msg"]
                .as_str()
                .unwrap_or_default()
                .contains("robot r7 disconnected")
            {
                return;
            }
        }
    })
    .await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_burst_of_small_messages_reaches_a_default_subscriber_whole() {
    let hub = start_hub().await;
    let mut sub = Rosbridge::connect(&hub.ws_url()).await;
    sub.send(json!({"op": "subscribe", "topic": "/burst", "id": "b"}))
        .await;
    let mut pubr = Rosbridge::connect(&hub.ws_url()).await;
    pubr.send(json!({"op": "advertise", "topic": "/burst", "type": "std_msgs/msg/Int32"}))
        .await;
    sub.call("/rosapi/get_time", json!({}), "sync").await;
    // One WebSocket write with 1,000 publishes: the burst arrives at the hub at once.
    for i in 0..1000 {
        pubr.send(json!({"op": "publish", "topic": "/burst", "msg": {"data": i}}))
            .await;
    }
    let mut seen = Vec::new();
    let deadline = tokio::time::Instant::now() + Duration::from_secs(10);
    while seen.len() < 1000 {
        match tokio::time::timeout_at(deadline, sub.try_recv()).await {
            Ok(Some(m)) if m["op"] == "publish" => seen.push(m["msg"]["data"].as_i64().unwrap()),
            Ok(Some(_)) => {}
            _ => break,
        }
    }
    assert_eq!(
        seen.len(),
        1000,
        "a burst of 1,000 small messages lost {}",
        1000 - seen.len()
    );
    assert!(seen.windows(2).all(|w| w[0] < w[1]), "out of order");
}
