//! rosbridge v2 features as a client sees them on the hub: regex subscriptions across
//! robots, CBOR compression, throttling, fragmentation, rosapi name spellings, and the
//! per-topic remap of robot names.

use std::time::Duration;

use fleetlink_relay::queue::DropReason;
use serde_json::{Value, json};
use tokio_tungstenite::tungstenite::Message as WsMessage;

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
            p.publish_json(&json!({"data": format!("hello {i}")}));
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

/// A client that floods the hub must not starve the delivery of its own messages: the
/// publisher's reader gives way to the subscriber's writer between operations. Before,
/// the reader handled a whole socket read (thousands of publishes) before the writer
/// ran, the subscriber's queue (1,000 messages) overflowed and most were dropped.
///
/// One thread runs the hub and both clients, so the interleaving depends only on where
/// tasks give way, never on how the OS schedules threads on a busy machine.
#[tokio::test(flavor = "current_thread")]
async fn a_flood_of_publishes_in_one_write_is_delivered_not_dropped() {
    const N: i64 = 20_000;
    let hub = start_hub().await;
    let mut sub = Rosbridge::connect(&hub.ws_url()).await;
    sub.send(json!({"op": "subscribe", "topic": "/flood", "id": "f"}))
        .await;
    let mut pubr = Rosbridge::connect(&hub.ws_url()).await;
    pubr.send(json!({"op": "advertise", "topic": "/flood", "type": "std_msgs/msg/Int64"}))
        .await;
    sub.call("/rosapi/get_time", json!({}), "sync").await;
    // The subscriber reads while the flood is written, as a real client would.
    let reader = tokio::spawn(async move {
        let mut seen = Vec::new();
        let deadline = tokio::time::Instant::now() + Duration::from_secs(30);
        while (seen.len() as i64) < N {
            match tokio::time::timeout_at(deadline, sub.try_recv()).await {
                Ok(Some(m)) if m["op"] == "publish" => {
                    seen.push(m["msg"]["data"].as_i64().expect("an Int64"))
                }
                Ok(Some(_)) => {}
                _ => break,
            }
        }
        seen
    });
    pubr.send_all((0..N).map(|i| json!({"op": "publish", "topic": "/flood", "msg": {"data": i}})))
        .await;
    let seen = reader.await.expect("reader");
    assert_eq!(
        seen.len() as i64,
        N,
        "a flood of {N} publishes lost {}",
        N - seen.len() as i64
    );
    assert!(seen.iter().copied().eq(0..N), "in order");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn protocol_odds_and_ends_fragments_set_level_png_and_plain_error_texts() {
    use base64::Engine;
    use tokio_tungstenite::tungstenite::Message as WsMessage;
    let hub = start_hub().await;
    let mut c = Rosbridge::connect(&hub.ws_url()).await;
    // A client's operation cut into rosbridge fragments is put back together.
    let op = json!({"op": "call_service", "service": "/rosapi/get_time", "id": "frag"}).to_string();
    let pieces: Vec<String> = op
        .as_bytes()
        .chunks(10)
        .map(|p| String::from_utf8(p.to_vec()).unwrap())
        .collect();
    let total = pieces.len();
    for (num, data) in pieces.iter().enumerate().rev() {
        c.send(json!({"op": "fragment", "id": "f1", "data": data, "num": num, "total": total}))
            .await;
    }
    let r = c.recv_op("service_response").await;
    assert_eq!(
        (r["id"].clone(), r["result"].clone()),
        (json!("frag"), json!(true)),
        "{r}"
    );
    c.send(json!({"op": "fragment", "id": "f2", "data": "x", "num": 5, "total": 2}))
        .await;
    let s = c.recv_op("status").await;
    assert!(
        s["msg"]
            .as_str()
            .unwrap()
            .contains("'num' 5 is not below 'total' 2"),
        "{s}"
    );
    // png compression: the publish as the pixels of a PNG image.
    c.send(json!({"op": "advertise", "topic": "/pngtest", "type": "std_msgs/msg/String"}))
        .await;
    c.send(json!({"op": "subscribe", "topic": "/pngtest", "compression": "png", "id": "p"}))
        .await;
    c.send(json!({"op": "publish", "topic": "/pngtest", "msg": {"data": "compressed"}}))
        .await;
    let p = c.recv_op("png").await;
    let png_bytes = base64::engine::general_purpose::STANDARD
        .decode(p["data"].as_str().unwrap())
        .unwrap();
    let mut reader = png::Decoder::new(std::io::Cursor::new(png_bytes))
        .read_info()
        .unwrap();
    let mut px = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut px).unwrap();
    px.truncate(info.buffer_size());
    let inner: Value = serde_json::from_slice(px.trim_ascii_end()).unwrap();
    assert_eq!(inner["op"], "publish");
    assert_eq!(inner["msg"]["data"], "compressed");
    // Errors name the problem in the client's terms.
    c.send_raw(WsMessage::Binary(vec![0xa1, 0x62, 0x6f].into()))
        .await
        .unwrap();
    let s = c.recv_op("status").await;
    let msg = s["msg"].as_str().unwrap();
    assert!(!msg.contains("Io(") && !msg.contains("Syntax("), "{msg}");
    assert!(msg.contains("ends in the middle of a value"), "{msg}");
    c.send(json!({"op": "subscribe", "topic": "/(unclosed", "regex": true, "id": "re"}))
        .await;
    let s = c.recv_op("status").await;
    let msg = s["msg"].as_str().unwrap();
    assert!(!msg.contains("^(?:"), "{msg}");
    assert!(msg.contains("unclosed group"), "{msg}");
    c.send(json!({"op": "x".repeat(5000), "id": "long"})).await;
    let s = c.recv_op("status").await;
    assert!(
        s.to_string().len() < 300,
        "{} bytes echoed",
        s.to_string().len()
    );
    // set_level none: even errors stop; info: they come back.
    c.send(json!({"op": "set_level", "level": "none"})).await;
    c.send(json!({"op": "no_such_op", "id": "quiet"})).await;
    c.send(json!({"op": "set_level", "level": "info"})).await;
    c.send(json!({"op": "no_such_op", "id": "loud"})).await;
    let s = c.recv_op("status").await;
    assert_eq!(
        s["id"], "loud",
        "the error sent at level none was not suppressed: {s}"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn json_publishes_are_checked_and_completed_against_their_type_once_at_the_hub() {
    let hub = start_hub().await;
    let mut sub = Rosbridge::connect(&hub.ws_url()).await;
    for t in ["/typed_int", "/typed_pose"] {
        sub.send(json!({"op": "subscribe", "topic": t, "id": t}))
            .await;
    }
    let mut p = Rosbridge::connect(&hub.ws_url()).await;
    p.send(json!({"op": "advertise", "topic": "/typed_int", "type": "std_msgs/msg/Int32"}))
        .await;
    p.send(
        json!({"op": "advertise", "topic": "/typed_pose", "type": "geometry_msgs/msg/PoseStamped"}),
    )
    .await;
    sub.call("/rosapi/get_time", json!({}), "sync").await;
    p.send(
        json!({"op": "publish", "topic": "/typed_int", "msg": {"data": "notanint"}, "id": "bad"}),
    )
    .await;
    let s = p.recv_op("status").await;
    let text = s["msg"].as_str().unwrap();
    assert!(
        text.contains("/typed_int") && text.contains("data"),
        "{text}"
    );
    assert_eq!(s["id"], "bad");
    // Missing fields are filled, integers in float fields become floats.
    p.send(
        json!({"op": "publish", "topic": "/typed_pose", "msg": {"pose": {"position": {"x": 1}}}}),
    )
    .await;
    let m = sub.recv_op("publish").await;
    assert_eq!(
        m["topic"], "/typed_pose",
        "the bad Int32 was not delivered: {m}"
    );
    assert_eq!(m["msg"]["header"]["frame_id"], "");
    assert_eq!(m["msg"]["header"]["stamp"]["sec"], 0);
    assert_eq!(m["msg"]["pose"]["orientation"]["w"], 1.0, "{m}");
    assert!(m["msg"]["pose"]["position"]["x"].is_f64(), "{m}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn parameters_are_kept_by_the_hub_across_restarts_checked_and_audited() {
    let dir = temp_dir("params");
    {
        let hub = start_hub_at(
            "127.0.0.1:0".parse().unwrap(),
            dir.clone(),
            Duration::from_millis(500),
        )
        .await;
        let mut c = Rosbridge::connect(&hub.ws_url()).await;
        let r = c
            .call(
                "/rosapi/set_param",
                json!({"name": "/r1/max_speed", "value": "1.5"}),
                "s",
            )
            .await;
        assert_eq!(r["result"], true, "{r}");
        let r = c
            .call(
                "/rosapi/set_param",
                json!({"name": "r1/nav", "value": "{\"planner\": \"dwa\", \"rate\": 5}"}),
                "t",
            )
            .await;
        assert_eq!(r["result"], true, "{r}");
        let r = c
            .call("/rosapi/get_param", json!({"name": "/r1"}), "g")
            .await;
        let tree: Value = serde_json::from_str(r["values"]["value"].as_str().unwrap()).unwrap();
        assert_eq!(
            tree,
            json!({"max_speed": 1.5, "nav": {"planner": "dwa", "rate": 5}})
        );
        let r = c
            .call(
                "/rosapi/set_param",
                json!({"name": "/x", "value": "not json"}),
                "bad",
            )
            .await;
        assert_eq!(r["result"], false);
        assert!(
            r["values"].as_str().unwrap().contains("not a JSON text"),
            "{r}"
        );
        let r = c
            .call(
                "/rosapi/get_param",
                json!({"name": "/missing", "default": "7"}),
                "d",
            )
            .await;
        assert_eq!(r["values"]["value"], "7");
        // A burst answered just before the stop: every change answered `true` survives it
        // (the disk writes trail the answers; the stopping hub waits for them).
        for i in 0..100 {
            let r = c
                .call(
                    "/rosapi/set_param",
                    json!({"name": format!("/burst/p{i:03}"), "value": i.to_string()}),
                    "b",
                )
                .await;
            assert_eq!(r["result"], true, "{r}");
        }
        hub.shutdown().await;
    };
    // A restarted hub on the same data directory still has them.
    let hub = start_hub_at(
        "127.0.0.1:0".parse().unwrap(),
        dir,
        Duration::from_millis(500),
    )
    .await;
    let mut c = Rosbridge::connect(&hub.ws_url()).await;
    let r = c
        .call("/rosapi/get_param", json!({"name": "/burst"}), "g")
        .await;
    let burst: Value = serde_json::from_str(r["values"]["value"].as_str().unwrap()).unwrap();
    let kept = burst.as_object().map_or(0, |m| m.len());
    assert_eq!(kept, 100, "parameters lost over the restart: {burst}");
    let r = c
        .call("/rosapi/delete_param", json!({"name": "/burst"}), "del")
        .await;
    assert_eq!(r["result"], true, "{r}");
    let r = c.call("/rosapi/get_param_names", json!({}), "n").await;
    assert_eq!(
        r["values"]["names"],
        json!(["/r1/max_speed", "/r1/nav/planner", "/r1/nav/rate"])
    );
    let r = c
        .call("/rosapi/has_param", json!({"name": "/r1/nav/rate"}), "h")
        .await;
    assert_eq!(r["values"]["exists"], true);
    let r = c
        .call("/rosapi/delete_param", json!({"name": "/r1/nav"}), "del")
        .await;
    assert_eq!(r["result"], true, "{r}");
    let r = c.call("/rosapi/get_param_names", json!({}), "n2").await;
    assert_eq!(r["values"]["names"], json!(["/r1/max_speed"]));
    // The changes are in the audit log.
    hub.state.security.audit.flush();
    let page = hub
        .state
        .security
        .store
        .query_audit(&fleetlink_auth::audit::AuditQuery {
            name_prefix: Some("/r1".into()),
            ..Default::default()
        })
        .unwrap();
    assert!(
        page.records
            .iter()
            .any(|r| r.record.name == "/r1/nav"
                && r.record.detail.as_deref() == Some("delete_param")),
        "{:?}",
        page.records
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn publishes_under_another_spelling_arrive_and_bad_ones_are_answered_with_their_id() {
    let hub = start_hub().await;
    let mut c = Rosbridge::connect(&hub.ws_url()).await;
    c.send(json!({"op": "advertise", "topic": "/spelled", "type": "std_msgs/msg/String"}))
        .await;
    c.send(json!({"op": "subscribe", "topic": "/spelled", "id": "s"}))
        .await;
    // The same topic without its leading slash, then as advertised: both are delivered
    // (the short path knows the client's spellings one by one).
    for (i, topic) in ["spelled", "/spelled", "spelled"].iter().enumerate() {
        c.send(json!({"op": "publish", "topic": topic, "msg": {"data": format!("m{i}")}}))
            .await;
        let m = c.recv_op("publish").await;
        assert_eq!(m["topic"], "/spelled", "{m}");
        assert_eq!(m["msg"]["data"], format!("m{i}"), "{m}");
    }
    // A message of the wrong shape on a known topic, and one on a topic nobody
    // advertised: each gets an error naming the topic and echoing the publish's id.
    c.send(json!({"op": "publish", "id": "bad-1", "topic": "/spelled", "msg": {"data": 5}}))
        .await;
    let s = c.recv_op("status").await;
    assert_eq!(s["id"], "bad-1", "{s}");
    let text = s["msg"].as_str().unwrap();
    assert!(text.contains("/spelled") && text.contains("data"), "{text}");
    c.send(json!({"op": "publish", "id": "bad-2", "topic": "nowhere", "msg": {"data": "x"}}))
        .await;
    let s = c.recv_op("status").await;
    assert_eq!(s["id"], "bad-2", "{s}");
    let text = s["msg"].as_str().unwrap();
    assert!(
        text.contains("/nowhere") && text.contains("advertise"),
        "{text}"
    );
    // The session keeps serving after both.
    c.send(json!({"op": "publish", "topic": "/spelled", "msg": {"data": "after"}}))
        .await;
    let m = c.recv_op("publish").await;
    assert_eq!(m["msg"]["data"], "after", "{m}");
    hub.shutdown().await;
}

/// Publishes in one envelope are read by comparing the envelope's text (its shape) and
/// their message is then checked only against its type: every kind of message must still
/// come out as when the envelope is read in full — delivered as sent, completed,
/// refused with the field named and the publish's id, or refused as bad JSON.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn publishes_read_by_their_envelope_shape_are_checked_like_any_other() {
    let hub = start_hub().await;
    let mut c = Rosbridge::connect(&hub.ws_url()).await;
    c.send_all([
        json!({"op": "advertise", "topic": "/shaped", "type": "std_msgs/msg/String"}),
        json!({"op": "advertise", "topic": "/untyped", "type": "no_such_pkg/msg/Thing"}),
        json!({"op": "subscribe", "topic": "/shaped", "id": "s1"}),
        json!({"op": "subscribe", "topic": "/untyped", "id": "s2"}),
    ])
    .await;
    c.call("/rosapi/get_time", json!({}), "sync").await;
    // roslibjs' envelope, the id numbered, only the message changing.
    let frame = |topic: &str, n: u32, msg: &str| {
        WsMessage::text(format!(
            r#"{{"op":"publish","id":"publish:{topic}:{n}","topic":"{topic}","msg":{msg},"latch":false}}"#
        ))
    };
    let mut send = async |topic: &str, n: u32, msg: &str| {
        c.send_raw(frame(topic, n, msg)).await.expect("send");
        c.recv().await
    };
    for n in 1..4 {
        let m = send("/shaped", n, &format!(r#"{{"data":"m{n}"}}"#)).await;
        assert_eq!(
            (m["op"].as_str(), m["msg"]["data"].as_str()),
            (Some("publish"), Some(&*format!("m{n}"))),
            "{m}"
        );
    }
    // A missing field is filled.
    let m = send("/shaped", 4, "{}").await;
    assert_eq!(m["msg"], json!({"data": ""}), "{m}");
    // A wrong type is refused, naming the field and echoing this publish's id.
    let s = send("/shaped", 5, r#"{"data":5}"#).await;
    assert_eq!(s["op"], "status", "{s}");
    assert_eq!(s["id"], "publish:/shaped:5", "{s}");
    assert!(s["msg"].as_str().unwrap().contains("data"), "{s}");
    // Not JSON where the message is: refused as such.
    let s = send("/shaped", 6, r#"{"data":"x",}"#).await;
    assert_eq!(s["op"], "status", "{s}");
    assert_eq!(s["level"], "error", "{s}");
    // A key after the message: ignored, as a full read ignores it.
    c.send_raw(WsMessage::text(
        r#"{"op":"publish","id":"publish:/shaped:7","topic":"/shaped","msg":{"data":"m7"},"latch":false,"extra":1}"#,
    ))
    .await
    .expect("send");
    let m = c.recv().await;
    assert_eq!(m["msg"], json!({"data": "m7"}), "{m}");
    let mut send = async |topic: &str, n: u32, msg: &str| {
        c.send_raw(frame(topic, n, msg)).await.expect("send");
        c.recv().await
    };
    // A type the hub does not know: passed on as sent, but only well-formed JSON.
    for n in 1..3 {
        let m = send("/untyped", n, r#"{"a":[1,2.5,"x"]}"#).await;
        assert_eq!(m["msg"], json!({"a": [1, 2.5, "x"]}), "{m}");
    }
    let s = send("/untyped", 3, r#"{"a":[1,2}"#).await;
    assert_eq!(s["op"], "status", "{s}");
    // Where the message was, a message and another key: the key is ignored, as a full
    // read ignores it.
    let m = send("/untyped", 4, r#"{"a":1},"b":{"c":2}"#).await;
    assert_eq!(m["msg"], json!({"a": 1}), "{m}");
    // Still serving, by shape again.
    let m = send("/shaped", 8, r#"{"data":"m8"}"#).await;
    assert_eq!(m["msg"], json!({"data": "m8"}), "{m}");
    hub.shutdown().await;
}

/// A text frame must be UTF-8 (RFC 6455 closes the connection with 1007 otherwise). The
/// hub checks it while reading a publish by its envelope's shape, not in a pass of its
/// own, so the bytes that are not UTF-8 are put where each check happens: in the
/// message of a typed topic, in the message of an untyped one, in the id.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_text_frame_that_is_not_utf8_closes_the_connection_with_1007() {
    use futures_util::StreamExt;
    use tokio_tungstenite::tungstenite::protocol::frame::Frame;
    use tokio_tungstenite::tungstenite::protocol::frame::coding::{CloseCode, Data, OpCode};
    let hub = start_hub().await;
    let envelope = |topic: &str, id: &[u8], msg: &[u8]| {
        let mut f = br#"{"op":"publish","id":""#.to_vec();
        f.extend_from_slice(id);
        f.extend_from_slice(format!(r#"","topic":"{topic}","msg":"#).as_bytes());
        f.extend_from_slice(msg);
        f.extend_from_slice(b"}");
        f
    };
    for (topic, id, msg) in [
        (
            "/utf8_typed",
            &b"publish:2"[..],
            &b"{\"data\":\"caf\xC3\x28\"}"[..],
        ),
        ("/utf8_untyped", &b"publish:2"[..], &b"{\"a\":\"\xFF\"}"[..]),
        (
            "/utf8_typed",
            &b"publish:\xC3"[..],
            &b"{\"data\":\"ok\"}"[..],
        ),
    ] {
        let mut c = Rosbridge::connect(&hub.ws_url()).await;
        c.send_all([
            json!({"op": "advertise", "topic": "/utf8_typed", "type": "std_msgs/msg/String"}),
            json!({"op": "advertise", "topic": "/utf8_untyped", "type": "no_such_pkg/msg/T"}),
            json!({"op": "subscribe", "topic": topic, "id": "s"}),
        ])
        .await;
        // One good publish in the envelope, so the next is read by its shape.
        let good = if topic == "/utf8_typed" {
            r#"{"data":"ok"}"#
        } else {
            r#"{"a":"ok"}"#
        };
        c.send_raw(WsMessage::text(
            String::from_utf8(envelope(topic, b"publish:1", good.as_bytes())).unwrap(),
        ))
        .await
        .expect("send");
        assert_eq!(c.recv_op("publish").await["topic"], topic);
        let bad = Frame::message(envelope(topic, id, msg), OpCode::Data(Data::Text), true);
        c.send_raw(WsMessage::Frame(bad)).await.expect("send");
        let close = within("the close", async {
            loop {
                match c.raw().next().await {
                    Some(Ok(WsMessage::Close(f))) => return f,
                    Some(Ok(_)) => continue,
                    other => panic!("connection ended without a close: {other:?}"),
                }
            }
        })
        .await;
        let close = close.expect("a close code");
        assert_eq!(close.code, CloseCode::Invalid, "{topic}: {close:?}");
    }
    hub.shutdown().await;
}
