//! The agent's link to the hub: reconnect after a hub restart, re-advertise and
//! re-subscribe exactly once, and dead-link detection when TCP does not notice.

use std::time::{Duration, Instant};

use serde_json::json;

use crate::util::*;

/// Publishes `payload` repeatedly until `client` sees a publish on `topic`.
async fn until_received(
    client: &mut Rosbridge,
    topic: &str,
    mut publish: impl FnMut(u32),
) -> serde_json::Value {
    within(&format!("a message on {topic}"), async {
        for i in 0..4000 {
            publish(i);
            if let Ok(Some(v)) =
                tokio::time::timeout(Duration::from_millis(25), client.try_recv()).await
                && v["op"] == "publish"
                && v["topic"] == topic
            {
                return v;
            }
        }
        panic!("nothing on {topic} after 4000 publishes");
    })
    .await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn agent_reconnects_after_hub_restart_and_resubscribes_exactly_once() {
    let hub = start_hub().await;
    let (addr, dir) = (hub.addr, hub.data_dir.clone());
    let agent = start_agent(&hub, "robot1").await;
    let mut pubr = LocalPublisher::new(&agent.router, "/chatter", "std_msgs/msg/String");
    let mut local = Rosbridge::connect(&agent.local_url()).await;
    local
        .send(json!({"op": "subscribe", "topic": "/cmd_vel", "id": "l"}))
        .await;

    hub.shutdown().await;
    let reason = agent.wait_disconnected().await;
    assert!(!reason.is_empty());

    // Same port, same data directory: a restarted hub.
    let hub = start_hub_at(addr, dir, Duration::from_millis(500)).await;
    agent.wait_connected().await;
    assert_eq!(
        agent
            .stats
            .connects
            .load(std::sync::atomic::Ordering::Relaxed),
        2
    );

    // Re-advertised: the robot's topic is listed with one publisher, before any message.
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    let listed = within("topic re-advertised", async {
        loop {
            let t = op.call("/rosapi/topics", json!({}), "t").await;
            if t["values"]["topics"]
                .as_array()
                .unwrap()
                .iter()
                .any(|n| n == "/robot1/chatter")
            {
                return t;
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await;
    assert!(listed["result"].as_bool().unwrap());
    let pubs = op
        .call(
            "/rosapi/publishers",
            json!({"topic": "/robot1/chatter"}),
            "p",
        )
        .await;
    assert_eq!(pubs["values"]["publishers"], json!(["/robot1"]));

    // Data flows up again.
    op.send(json!({"op": "subscribe", "topic": "/robot1/chatter"}))
        .await;
    until_received(&mut op, "/robot1/chatter", |i| {
        pubr.publish_json(&json!({"data": format!("m{i}")}))
    })
    .await;

    // Re-subscribed exactly once: every operator command arrives once, none twice.
    op.send(
        json!({"op": "advertise", "topic": "/robot1/cmd_vel", "type": "geometry_msgs/msg/Twist"}),
    )
    .await;
    let first = within("first command", async {
        let mut n = 0u32;
        loop {
            n += 1;
            op.send(json!({"op": "publish", "topic": "/robot1/cmd_vel", "msg": {"linear": {"x": f64::from(n)}}})).await;
            if let Ok(Some(v)) = tokio::time::timeout(Duration::from_millis(25), local.try_recv()).await
                && v["op"] == "publish"
            {
                return v["msg"]["linear"]["x"].as_f64().unwrap() as u32;
            }
            assert!(n < 4000, "no command arrived");
        }
    })
    .await;
    let base = 100_000u32;
    for k in 0..50 {
        op.send(json!({"op": "publish", "topic": "/robot1/cmd_vel", "msg": {"linear": {"x": f64::from(base + k)}}})).await;
    }
    let mut seen = Vec::new();
    within("50 commands", async {
        while seen.len() < 50 {
            let v = local.recv_op("publish").await;
            let x = v["msg"]["linear"]["x"].as_f64().unwrap() as u32;
            if x >= base {
                seen.push(x);
            } else {
                assert!(x >= first, "stale command {x}");
            }
        }
    })
    .await;
    assert_eq!(
        seen,
        (0..50).map(|k| base + k).collect::<Vec<_>>(),
        "each command exactly once, in order"
    );
    // And nothing more arrives (a duplicate subscription would deliver a second copy).
    let extra = tokio::time::timeout(Duration::from_millis(300), local.try_recv()).await;
    assert!(extra.is_err(), "unexpected extra frame: {extra:?}");

    agent.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn dead_link_is_detected_within_two_heartbeats_when_tcp_does_not_notice() {
    let hub = start_hub().await;
    let proxy = Blackhole::start(hub.addr).await;
    let mut cfg = uplink_config(&hub, "robot_dl");
    cfg.hub_urls = vec![format!("ws://{}", proxy.addr)];
    let heartbeat = Duration::from_millis(300);
    cfg.heartbeat = heartbeat;
    cfg.reconnect_initial = Duration::from_secs(30); // keep it down once it is down
    let agent = start_agent_with(cfg, false).await;
    agent.wait_connected().await;

    proxy.cut();
    let cut_at = Instant::now();
    let reason = agent.wait_disconnected().await;
    let took = cut_at.elapsed();
    assert!(reason.contains("declared dead"), "reason: {reason}");
    // Silence is measured from the last frame received, which came at most one heartbeat
    // before the cut: detection lands between 1× and 2× the interval after the cut, plus
    // scheduling slack on a busy machine.
    assert!(took >= heartbeat, "declared dead too early: {took:?}");
    assert!(
        took <= heartbeat * 2 + Duration::from_secs(2),
        "took {took:?}"
    );

    // The hub also notices and takes the robot offline.
    within("hub to drop the robot", async {
        while hub
            .state
            .registry
            .list()
            .iter()
            .any(|r| r.name == "robot_dl")
        {
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await;
    agent.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue14_a_refused_token_says_how_to_fix_it_and_is_not_retried_at_once() {
    let hub = start_hub().await;
    let mut cfg = uplink_config(&hub, "robot4");
    cfg.token = "flk_robot_not_a_real_token_at_all".into();
    let agent = start_agent_with(cfg, false).await;
    let reason = agent.wait_disconnected().await;
    assert!(
        reason.contains("refused the token of robot robot4"),
        "{reason}"
    );
    assert!(reason.contains("token robot robot4"), "{reason}");
    assert!(
        !reason.contains("not_a_real_token"),
        "the token leaked: {reason}"
    );
    // A permanent refusal waits the long interval instead of hammering the hub.
    let mut rx = agent.state.clone();
    let retried = tokio::time::timeout(
        Duration::from_secs(2),
        rx.wait_for(|s| matches!(s, fleetlink_agent::uplink::LinkState::Connecting { .. })),
    )
    .await;
    assert!(retried.is_err(), "retried within 2 s of a refused token");
    agent.shutdown().await;
    hub.shutdown().await;
}
