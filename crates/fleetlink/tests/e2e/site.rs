//! Site hubs (issue 40, item 1): a hub that is itself an agent of an upstream hub. Its
//! robots appear upstream as `/SITE/<robot>/…`; a robot's topic crosses both hops only
//! while someone upstream subscribes; calls and action goals cross both hops; a no-drop
//! stream keeps its guarantee on the second hop.

use std::sync::atomic::Ordering::Relaxed;
use std::time::Duration;

use fleetlink_agent::config::SimConfig;
use fleetlink_agent::uplink::Uplink;
use fleetlink_relay::{Topic, TopicName};
use serde_json::{Value, json};
use tokio_util::sync::CancellationToken;

use crate::util::*;

fn topic(hub: &TestHub, name: &str) -> Option<std::sync::Arc<Topic>> {
    hub.state.router.topic(&TopicName::parse(name).unwrap())
}

/// Messages of `name` the hub received from its publisher.
fn received(hub: &TestHub, name: &str) -> u64 {
    topic(hub, name).map_or(0, |t| t.stats.messages.load(Relaxed))
}

async fn call_when_ready(client: &mut Rosbridge, service: &str, args: Value) -> Value {
    within("the service to be reachable across both hops", async {
        for i in 0.. {
            let r = client
                .call(service, args.clone(), &format!("ready-{i}"))
                .await;
            let text = r["values"].as_str().unwrap_or_default();
            if r["result"] == true || !text.contains("not advertised") {
                return r;
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
        unreachable!()
    })
    .await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_site_robots_topic_crosses_both_hops_only_while_wanted_upstream() {
    let cloud = start_hub().await;
    let site = start_hub().await;
    let _link = link_site(&cloud, &site, "site7").await;
    let robot = start_agent(&site, "robot3").await;
    let mut scan = LocalPublisher::new(&robot.router, "/scan", "std_msgs/msg/String");
    for i in 0..5 {
        scan.publish_json(&json!({ "data": format!("scan {i}") }));
    }
    // Announced at both hubs, before any message flowed; nobody wants it, so the robot
    // holds it back and nothing reaches either hub.
    eventually("the robot's topic listed upstream under the site", || {
        topic(&cloud, "/site7/robot3/scan").is_some()
    })
    .await;
    assert!(topic(&site, "/robot3/scan").unwrap().is_idle());
    tokio::time::sleep(Duration::from_millis(300)).await;
    assert_eq!(
        received(&site, "/robot3/scan"),
        0,
        "sent to the site unwanted"
    );
    assert_eq!(received(&cloud, "/site7/robot3/scan"), 0);

    // Someone upstream subscribes: the interest goes down both hops, the robot's latest
    // message comes up at once, then each new one.
    let mut op = Rosbridge::connect(&cloud.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/site7/robot3/scan", "id": "s"}))
        .await;
    let first = within("the latest scan", op.recv_op("publish")).await;
    assert_eq!(first["msg"]["data"], "scan 4");
    scan.publish_json(&json!({ "data": "scan 5" }));
    let next = within("the next scan", op.recv_op("publish")).await;
    assert_eq!(next["msg"]["data"], "scan 5");
    assert!(!topic(&site, "/robot3/scan").unwrap().is_idle());

    // Three subscribers upstream: one copy crosses each hop.
    let mut more = Vec::new();
    for i in 0..2 {
        let mut c = Rosbridge::connect(&cloud.ws_url()).await;
        c.send(json!({"op": "subscribe", "topic": "/site7/robot3/scan", "id": format!("m{i}")}))
            .await;
        more.push(c);
    }
    eventually("three subscribers upstream", || {
        topic(&cloud, "/site7/robot3/scan")
            .unwrap()
            .subscriber_count()
            >= 4
    })
    .await;
    let (at_site, upstream) = (
        received(&site, "/robot3/scan"),
        received(&cloud, "/site7/robot3/scan"),
    );
    for i in 6..16 {
        scan.publish_json(&json!({ "data": format!("scan {i}") }));
    }
    for c in more.iter_mut().chain(std::iter::once(&mut op)) {
        loop {
            let m = within("every subscriber's copy", c.recv_op("publish")).await;
            if m["msg"]["data"] == "scan 15" {
                break;
            }
        }
    }
    assert_eq!(received(&site, "/robot3/scan") - at_site, 10);
    assert_eq!(received(&cloud, "/site7/robot3/scan") - upstream, 10);

    // Everyone upstream leaves: the robot holds the topic back again.
    drop(op);
    drop(more);
    eventually("the robot's topic idle again", || {
        topic(&site, "/robot3/scan").is_some_and(|t| t.is_idle())
    })
    .await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn calls_and_goals_cross_both_hops_and_commands_come_down() {
    let cloud = start_hub().await;
    let site = start_hub().await;
    let _link = link_site(&cloud, &site, "site7").await;
    let sim = SimConfig {
        laser_scan: None,
        point_cloud: None,
        image: None,
        ..SimConfig::default()
    };
    let robot = start_agent_sim(uplink_config(&site, "robot3"), true, Some(sim)).await;
    robot.wait_connected().await;
    let mut op = Rosbridge::connect(&cloud.ws_url()).await;
    let r = call_when_ready(&mut op, "/site7/robot3/set_mode", json!({"data": false})).await;
    assert_eq!(r["values"]["success"], true, "{r}");
    assert_eq!(r["values"]["message"], "mode: idle");
    let s = op.call("/site7/robot3/get_status", json!({}), "s").await;
    let status: Value = serde_json::from_str(s["values"]["message"].as_str().unwrap()).unwrap();
    let (x, y) = (status["x"].as_f64().unwrap(), status["y"].as_f64().unwrap());
    // A goal with feedback, and a cancelled one, through both hops.
    let gx = x + 0.4_f64.copysign(-x);
    op.send(json!({"op": "send_action_goal", "id": "nav",
        "action": "/site7/robot3/navigate_to_pose", "args": {"x": gx, "y": y}, "feedback": true}))
        .await;
    let f = within("feedback across both hops", op.recv_op("action_feedback")).await;
    assert!(f["values"]["distance_remaining"].as_f64().is_some(), "{f}");
    let r = within("the result", op.recv_op("action_result")).await;
    assert_eq!(
        (r["status"].clone(), r["values"]["reached"].clone()),
        (json!(4), json!(true)),
        "{r}"
    );
    op.send(json!({"op": "send_action_goal", "id": "far",
        "action": "/site7/robot3/navigate_to_pose", "args": {"x": -gx, "y": y}, "feedback": true}))
        .await;
    within("feedback of the far goal", op.recv_op("action_feedback")).await;
    op.send(json!({"op": "cancel_action_goal", "id": "far"}))
        .await;
    let r = within("the cancelled goal's result", op.recv_op("action_result")).await;
    assert_eq!(
        (r["id"].clone(), r["status"].clone()),
        (json!("far"), json!(5)),
        "{r}"
    );

    // An operator's command upstream reaches a program on the robot under its local name.
    let mut local = Rosbridge::connect(&robot.local_url()).await;
    local
        .send(json!({"op": "subscribe", "topic": "/cmd_vel", "id": "c"}))
        .await;
    op.send(json!({"op": "advertise", "topic": "/site7/robot3/cmd_vel",
        "type": "geometry_msgs/msg/Twist"}))
        .await;
    let got = within("the command down both hops", async {
        loop {
            op.send(json!({"op": "publish", "topic": "/site7/robot3/cmd_vel",
                "msg": {"linear": {"x": 0.25}}}))
                .await;
            let next = tokio::time::timeout(Duration::from_millis(100), local.recv_op("publish"));
            if let Ok(m) = next.await {
                break m;
            }
        }
    })
    .await;
    assert_eq!(got["topic"], "/cmd_vel");
    assert_eq!(got["msg"]["linear"]["x"], 0.25);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_robots_no_drop_stream_loses_nothing_upstream_across_a_wan_cut() {
    let cloud = start_hub().await;
    let site = start_hub().await;
    // The WAN: a proxy that can silently drop everything, both ways.
    let wan = Blackhole::start(cloud.addr).await;
    let mut cfg = uplink_config(&cloud, "site7");
    cfg.hub_urls = vec![format!("ws://{}", wan.addr)];
    cfg.hub_id = Some(site.state.agents.hub_id);
    // As `fleetlink hub --upstream` sets it up: no-drop streams wait on disk.
    cfg.outbox = Some(fleetlink_agent::outbox_store::OutboxStoreConfig {
        dir: site.data_dir.join("upstream-outbox"),
        max_bytes: 64 << 20,
        fsync: fleetlink_agent::outbox_store::Fsync::Never,
    });
    let uplink = Uplink::new(cfg, site.state.router.clone()).expect("the site's uplink");
    let stop = CancellationToken::new();
    let running = tokio::spawn(uplink.run(stop.clone()));
    let mut robot_cfg = uplink_config(&site, "robot3");
    robot_cfg.topic_qos = vec![(
        TopicName::parse("/log").unwrap(),
        fleetlink_qos::TopicQosSpec {
            no_drop: Some(true),
            queue: Some(1000),
            ..Default::default()
        },
    )];
    let robot = start_agent_with(robot_cfg, false).await;
    robot.wait_connected().await;
    let mut op = Rosbridge::connect(&cloud.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/site7/robot3/log"}))
        .await;
    // Ops run in order: once this answers, the subscription exists.
    op.call("/rosapi/get_time", json!({}), "sync").await;
    let mut log = LocalPublisher::new(&robot.router, "/log", "std_msgs/msg/String");
    log.publish_json(&json!({ "data": "0" }));
    // A no-drop stream flows whether or not anyone wants it, and stays one upstream.
    let first = within("the stream's first message upstream", op.recv_op("publish")).await;
    assert_eq!(first["msg"]["data"], "0");
    assert!(
        topic(&cloud, "/site7/robot3/log")
            .unwrap()
            .reliable_epoch()
            .is_some()
    );
    for i in 1..100 {
        log.publish_json(&json!({ "data": i.to_string() }));
        if i == 30 {
            wan.cut();
        }
        if i == 70 {
            // Long enough for both ends to declare the link dead (heartbeat 200 ms).
            tokio::time::sleep(Duration::from_millis(800)).await;
            wan.restore();
        }
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    let mut seen = vec![0u32];
    while seen.len() < 100 {
        let next = tokio::time::timeout(Duration::from_secs(10), op.recv_op("publish")).await;
        let Ok(m) = next else {
            panic!(
                "after the WAN returned, {} of 100 arrived: {seen:?}",
                seen.len()
            );
        };
        seen.push(m["msg"]["data"].as_str().unwrap().parse().unwrap());
    }
    assert_eq!(seen, (0..100).collect::<Vec<u32>>(), "each once, in order");
    assert!(
        nothing_more(&mut op).await,
        "a message came twice after the stream was complete"
    );
    stop.cancel();
    running.await.unwrap();
}

/// True if no further publish arrives within half a second.
async fn nothing_more(client: &mut Rosbridge) -> bool {
    tokio::time::timeout(Duration::from_millis(500), client.recv_op("publish"))
        .await
        .is_err()
}

/// Hub `site`'s link to hub `up` as `name`, carrying `/chat` both ways under its own name.
fn chat_link(site: &TestHub, up: &TestHub, name: &str) -> CancellationToken {
    let mut cfg = uplink_config(up, name);
    cfg.hub_id = Some(site.state.agents.hub_id);
    let chat = TopicName::parse("/chat").unwrap();
    cfg.names = fleetlink_agent::uplink::NameMap {
        remap: vec![(chat.clone(), chat.clone())],
        subscribe: vec![(chat.clone(), chat)],
    };
    let uplink = Uplink::new(cfg, site.state.router.clone()).expect("an uplink");
    let stop = CancellationToken::new();
    tokio::spawn(uplink.run(stop.clone()));
    stop
}

/// The `/chat` messages `client` receives until none comes for `quiet`.
async fn chats(client: &mut Rosbridge, quiet: Duration) -> Vec<String> {
    let mut got = Vec::new();
    while let Ok(m) = tokio::time::timeout(quiet, client.recv_op("publish")).await {
        got.push(m["msg"]["data"].as_str().unwrap_or_default().to_owned());
    }
    got
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_topic_bridged_both_ways_around_a_triangle_of_hubs_never_comes_back() {
    // Hub 0's upstream is hub 1, hub 1's is hub 2, hub 2's is hub 0: a cycle, and /chat
    // bridged both ways at every link. Without the hubs each message passed, a message
    // would go round for ever (and topics named /site0/site2/site1/... would grow).
    let hubs = [start_hub().await, start_hub().await, start_hub().await];
    for h in &hubs {
        h.set_rules(
            "rules:\n  - subject: any_robot\n    names: \"/chat\"\n    ops: [publish, subscribe]\n",
        );
    }
    let _links: Vec<_> = (0..3)
        .map(|i| chat_link(&hubs[i], &hubs[(i + 1) % 3], &format!("site{i}")))
        .collect();
    let mut subs = Vec::new();
    for h in &hubs {
        let mut c = Rosbridge::connect(&h.ws_url()).await;
        c.send(json!({"op": "subscribe", "topic": "/chat", "id": "s"}))
            .await;
        c.call("/rosapi/get_time", json!({}), "sync").await;
        subs.push(c);
    }
    // Each hub's interest has reached the others once /chat flows all round: wait for a
    // probe published on hub 0 to reach hubs 1 and 2.
    let mut talker = Rosbridge::connect(&hubs[0].ws_url()).await;
    talker
        .send(json!({"op": "advertise", "topic": "/chat", "type": "std_msgs/msg/String"}))
        .await;
    within("the bridges to carry /chat round the triangle", async {
        loop {
            talker
                .send(json!({"op": "publish", "topic": "/chat", "msg": {"data": "probe"}}))
                .await;
            let heard =
                tokio::time::timeout(Duration::from_millis(300), subs[2].recv_op("publish"));
            if heard.await.is_ok() {
                break;
            }
        }
    })
    .await;
    for s in subs.iter_mut() {
        chats(s, Duration::from_millis(500)).await;
    }
    // Now ten messages on hub 0.
    for i in 0..10 {
        talker
            .send(json!({"op": "publish", "topic": "/chat", "msg": {"data": format!("m{i}")}}))
            .await;
    }
    let quiet = Duration::from_millis(1500);
    let mut counts = Vec::new();
    for s in subs.iter_mut() {
        let got = chats(s, quiet).await;
        let mut per = std::collections::BTreeMap::new();
        for m in got {
            *per.entry(m).or_insert(0u32) += 1;
        }
        counts.push(per);
    }
    let expected: Vec<String> = (0..10).map(|i| format!("m{i}")).collect();
    // The publishing hub: each message once (its own subscriber), never again from the
    // far side of the triangle.
    assert_eq!(
        counts[0].keys().cloned().collect::<Vec<_>>(),
        expected,
        "{counts:?}"
    );
    assert!(
        counts[0].values().all(|n| *n == 1),
        "came back to hub 0: {counts:?}"
    );
    // The other two: each message by each of the two ways round, at most — no more.
    for (h, c) in counts.iter().enumerate().skip(1) {
        assert_eq!(
            c.keys().cloned().collect::<Vec<_>>(),
            expected,
            "hub {h}: {counts:?}"
        );
        assert!(
            c.values().all(|n| (1..=2).contains(n)),
            "hub {h}: {counts:?}"
        );
    }
    // Nothing keeps circling: the topic's publish count at each hub stays put.
    let totals =
        |hubs: &[TestHub]| -> Vec<u64> { hubs.iter().map(|h| received(h, "/chat")).collect() };
    let before = totals(&hubs);
    tokio::time::sleep(Duration::from_millis(500)).await;
    assert_eq!(totals(&hubs), before, "messages still circling");
    // Topics travel round the cycle once, not for ever: hub 1's /rosout is at hub 2 as
    // /site1/rosout and at hub 0 as /site2/site1/rosout, and is refused when hub 0 would
    // announce it back to hub 1 (as /site0/site2/site1/rosout). No hub holds a topic
    // named after its own way back, nor one that passed more than the other two.
    for (i, h) in hubs.iter().enumerate() {
        let me = format!("/site{i}/");
        let looped = h
            .state
            .router
            .topics()
            .into_iter()
            .map(|t| t.meta.name.to_string())
            .filter(|n| n.contains(&me) || n.matches("/site").count() > 2)
            .collect::<Vec<_>>();
        assert!(looped.is_empty(), "hub {i}: {looped:?}");
    }
    assert!(topic(&hubs[0], "/site2/site1/rosout").is_some());
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_sites_rules_decide_what_the_hub_upstream_may_do_there() {
    let cloud = start_hub().await;
    let site = start_hub().await;
    // At the site, the hub upstream (the user `upstream` of group `upstream`) may watch
    // robot3's topics, nothing more.
    site.set_rules(
        "rules:\n  - subject: {group: upstream}\n    names: \"/robot3/.*\"\n    ops: [subscribe]\n",
    );
    let mut cfg = uplink_config(&cloud, "site7");
    cfg.hub_id = Some(site.state.agents.hub_id);
    let state = site.state.clone();
    let local = std::net::IpAddr::from([127, 0, 0, 1]);
    let identity = fleetlink_auth::Identity {
        kind: fleetlink_auth::IdentityKind::User {
            name: fleetlink_auth::UserName::new("upstream").unwrap(),
            groups: vec![fleetlink_auth::GroupName::new("upstream").unwrap()],
        },
        source: fleetlink_auth::ConnInfo::new(local),
        client_ip: local,
    };
    cfg.upstream_gate = Some(fleetlink_agent::uplink::GateFactory(std::sync::Arc::new(
        move || {
            Box::new(fleetlink_hub::security::HubGate::new(
                state.security.clone(),
                state.registry.clone(),
                identity.clone(),
            ))
        },
    )));
    let uplink = Uplink::new(cfg, site.state.router.clone()).expect("the site's uplink");
    let stop = CancellationToken::new();
    tokio::spawn(uplink.run(stop.clone()));
    let _stop = stop.drop_guard();
    let sim = SimConfig {
        laser_scan: None,
        point_cloud: None,
        image: None,
        ..SimConfig::default()
    };
    let robot = start_agent_sim(uplink_config(&site, "robot3"), true, Some(sim)).await;
    robot.wait_connected().await;
    // Watching works.
    let mut op = Rosbridge::connect(&cloud.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/site7/robot3/odom", "id": "o"}))
        .await;
    let odom = within("odometry upstream", op.recv_op("publish")).await;
    assert_eq!(odom["topic"], "/site7/robot3/odom");
    // Only what it may watch is announced upstream: robot3's topics, not the site's own.
    eventually("robot3's topics announced upstream", || {
        topic(&cloud, "/site7/robot3/odom").is_some()
    })
    .await;
    assert!(
        topic(&cloud, "/site7/rosout").is_none(),
        "the site's /rosout announced upstream"
    );
    // The robot's services are not offered upstream: the upstream may not call them.
    assert!(
        cloud
            .state
            .router
            .calls
            .service(&TopicName::parse("/site7/robot3/set_mode").unwrap())
            .is_none()
    );
    let r = op
        .call("/site7/robot3/set_mode", json!({"data": true}), "c")
        .await;
    assert_eq!(r["result"], false, "{r}");
    // A command from upstream does not reach the robot.
    let mut listener = Rosbridge::connect(&robot.local_url()).await;
    listener
        .send(json!({"op": "subscribe", "topic": "/cmd_vel", "id": "c"}))
        .await;
    op.send(json!({"op": "advertise", "topic": "/site7/robot3/cmd_vel",
        "type": "geometry_msgs/msg/Twist"}))
        .await;
    for _ in 0..10 {
        op.send(json!({"op": "publish", "topic": "/site7/robot3/cmd_vel",
            "msg": {"linear": {"x": 0.25}}}))
            .await;
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    let got = tokio::time::timeout(Duration::from_millis(500), listener.recv_op("publish")).await;
    assert!(
        got.is_err(),
        "a command the site's rules refuse reached the robot: {got:?}"
    );
    assert!(
        topic(&site, "/robot3/cmd_vel").is_none_or(|t| t.stats.messages.load(Relaxed) == 0),
        "published at the site"
    );
}
