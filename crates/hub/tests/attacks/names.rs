//! Attacks on authorization by name: publishing into another robot's namespace,
//! regex subscriptions reaching for hidden topics, and hostile regexes in rule imports.

use fleetlink_auth::audit::AuditAction;
use fleetlink_proto::frame::Frame;
use fleetlink_proto::{Encoding, Schema};
use serde_json::json;

use crate::*;

fn advertise(alias: u32, topic: &str) -> Frame {
    Frame::Advertise {
        alias,
        topic: topic.into(),
        schema: Schema::named("std_msgs/String"),
        encoding: Encoding::Json,
        flags: 0,
    }
}

fn message(alias: u32, seq: u64, text: &str) -> Frame {
    Frame::Message {
        alias,
        seq,
        stamp_ns: 0,
        payload: payload(json!({"data": text})),
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn robot_cannot_publish_into_another_robots_namespace() {
    let fx = hub().await;
    // robot2 owns /robot2/x and publishes on it; an operator listens.
    let mut r2 = agent(fx.addr, "robot2", &fx.robot_token("robot2", None), None).await;
    welcomed(&mut r2).await;
    send_frame(&mut r2, advertise(1, "/robot2/x")).await;
    let mut sub = rosbridge(&fx.ws_url(&fx.operator)).await;
    send(
        &mut sub,
        json!({"op": "subscribe", "topic": "/robot2/x", "id": "s"}),
    )
    .await;
    // The subscription is in place before robot2's message below, which it must receive
    // (under load the hub could otherwise read that message first, and it would be lost).
    let x = fleetlink_relay::TopicName::parse("/robot2/x").unwrap();
    for _ in 0..500 {
        if fx
            .state
            .router
            .topic(&x)
            .is_some_and(|t| t.subscriber_count() > 0)
        {
            break;
        }
        tokio::time::sleep(std::time::Duration::from_millis(10)).await;
    }
    // robot1 tries to advertise and publish there.
    let mut r1 = agent(fx.addr, "robot1", &fx.robot_token("robot1", None), None).await;
    welcomed(&mut r1).await;
    send_frame(&mut r1, advertise(7, "/robot2/x")).await;
    refused(
        &mut r1,
        403,
        "advertise /robot2/x: not allowed for robot:robot1",
    )
    .await;
    for seq in 1..=5 {
        send_frame(&mut r1, message(7, seq, "forged")).await;
    }
    // robot1's link stays up: its own namespace still works.
    send_frame(&mut r1, advertise(8, "/robot1/ok")).await;
    // The subscriber's first message is robot2's, sent after every forged one.
    send_frame(&mut r2, message(1, 1, "genuine")).await;
    let m = tokio::time::timeout(
        std::time::Duration::from_secs(10),
        next_op(&mut sub, "publish"),
    )
    .await
    .expect("robot2's message reaches the subscriber within 10 s");
    assert_eq!(m["topic"], "/robot2/x");
    assert_eq!(
        m["msg"]["data"], "genuine",
        "a forged message got through: {m}"
    );
    let rec = fx.assert_audited(AuditAction::Publish, "/robot2/x").await;
    assert_eq!(rec.record.principal, "robot:robot1");
    fx.still_serving().await;
}

/// Issue 36, item 6: the hub parses HELLO's robot name with the one rule
/// (`fleetlink_auth::RobotName`) the agent's config and the CLI use, so `_bot` (which the
/// agent's own checks once let through) and `1robot` are refused with the rule's text, not
/// a bare "authentication failed". The name is refused before any credential is looked
/// at, so there is no `auth_failure` record to find: only the STATUS and the close.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue36_hello_with_a_robot_name_breaking_the_rule_is_refused_with_the_rule() {
    let fx = hub().await;
    let rule = "(robot names are [A-Za-z][A-Za-z0-9_]*, at most 63 bytes)";
    let too_long = format!("r{}", "0".repeat(63));
    for (name, problem) in [
        ("_bot", "must start with an ASCII letter"),
        ("1robot", "must start with an ASCII letter"),
        ("robot-1", "only ASCII letters, digits and '_' are allowed"),
        (too_long.as_str(), "longer than 63 bytes"),
    ] {
        let mut a = agent(fx.addr, name, "", None).await;
        refused(
            &mut a,
            401,
            &format!("invalid robot name {name:?}: {problem} {rule}"),
        )
        .await;
        assert!(next_frame(&mut a).await.is_none(), "{name}: link closes");
    }
    // The longest valid name gets as far as authentication.
    let longest = format!("r{}", "0".repeat(62));
    let mut a = agent(fx.addr, &longest, &fx.robot_token(&longest, None), None).await;
    welcomed(&mut a).await;
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn regex_subscription_only_reaches_visible_topics() {
    let fx = hub().await;
    let viewer = mint_operator(&fx.state, "viewer", &["viewers"]);
    let rules = "rules:
  - subject: {group: viewers}
    names: \"/public/.*\"
    ops: [subscribe]
  - subject: {group: viewers}
    names: \"/rosapi/.*\"
    ops: [call_service]
";
    let put = http(
        fx.addr,
        "PUT",
        "/api/v1/rules",
        &[
            ("Authorization", &format!("Bearer {}", fx.operator)),
            ("Content-Type", "application/yaml"),
        ],
        rules,
    )
    .await;
    assert_eq!(put.status, 200, "{}", put.body);
    // The admin publishes on a hidden and a visible topic.
    let mut admin = rosbridge(&fx.ws_url(&fx.operator)).await;
    for t in ["/secret/plans", "/public/news"] {
        send(
            &mut admin,
            json!({"op": "advertise", "topic": t, "type": "std_msgs/String"}),
        )
        .await;
    }
    // The admin's own listing answers after its advertisements took effect.
    send(
        &mut admin,
        json!({"op": "call_service", "service": "/rosapi/topics", "id": "ls"}),
    )
    .await;
    let all = next_op(&mut admin, "service_response").await;
    // Both topics, and the hub's /rosout.
    assert_eq!(
        all["values"]["topics"].as_array().map(Vec::len),
        Some(3),
        "{all}"
    );
    let mut v = rosbridge(&fx.ws_url(&viewer)).await;
    send(
        &mut v,
        json!({"op": "subscribe", "topic": "/.*", "regex": true, "id": "all"}),
    )
    .await;
    // Listing shows only what the viewer may see.
    send(
        &mut v,
        json!({"op": "call_service", "service": "/rosapi/topics", "id": "ls"}),
    )
    .await;
    let ls = next_op(&mut v, "service_response").await;
    let topics: Vec<&str> = ls["values"]["topics"]
        .as_array()
        .unwrap_or_else(|| panic!("no topic list in {ls}"))
        .iter()
        .filter_map(|t| t.as_str())
        .collect();
    assert!(topics.contains(&"/public/news"), "{ls}");
    assert!(
        !topics.contains(&"/secret/plans"),
        "hidden topic listed: {ls}"
    );
    // Secrets first, then one public message: the viewer's first delivery is the public
    // one, and nothing secret ever arrives before it.
    for i in 0..5 {
        send(
            &mut admin,
            json!({"op": "publish", "topic": "/secret/plans", "msg": {"data": format!("s{i}")}}),
        )
        .await;
    }
    send(
        &mut admin,
        json!({"op": "publish", "topic": "/public/news", "msg": {"data": "hello"}}),
    )
    .await;
    let m = next_op(&mut v, "publish").await;
    assert_eq!(m["topic"], "/public/news", "hidden topic delivered: {m}");
    // A direct subscription to the hidden topic is refused outright, and audited.
    send(
        &mut v,
        json!({"op": "subscribe", "topic": "/secret/plans", "id": "x"}),
    )
    .await;
    let s = next_op(&mut v, "status").await;
    assert_eq!(s["level"], "error", "{s}");
    fx.assert_audited(AuditAction::Subscribe, "/secret/plans")
        .await;
    fx.still_serving().await;
}

/// A rule import with `pattern` is refused with 400 naming the problem; the rules in
/// force stay as they were.
async fn hostile_rule_refused(fx: &Fixture, pattern: &str, needle: &str) {
    let rule = json!({"subject": "anyone", "names": pattern, "ops": ["subscribe"]});
    let post = api(fx, "POST", "/api/v1/rules", &fx.operator, &rule.to_string()).await;
    assert_eq!(post.status, 400, "{}", post.body);
    let err = post.json()["error"].as_str().unwrap().to_owned();
    assert!(
        err.contains(needle),
        "error {err:?} should mention {needle:?}"
    );
    let yaml =
        format!("rules:\n  - subject: anyone\n    names: '{pattern}'\n    ops: [subscribe]\n");
    let put = http(
        fx.addr,
        "PUT",
        "/api/v1/rules",
        &[
            ("Authorization", &format!("Bearer {}", fx.operator)),
            ("Content-Type", "application/yaml"),
        ],
        &yaml,
    )
    .await;
    assert_eq!(put.status, 400, "{}", put.body);
    assert!(
        put.json()["error"].as_str().unwrap().contains(needle),
        "{}",
        put.body
    );
    let list = api(fx, "GET", "/api/v1/rules", &fx.operator, "").await;
    assert_eq!(list.json()["rules"], json!([]), "nothing was imported");
    fx.assert_audited(AuditAction::RuleChange, needle).await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn catastrophic_backtracking_regex_rule_is_refused() {
    let fx = hub().await;
    // Nested quantifiers that blow up a backtracking engine. The regex crate has no
    // backtracking, but its compiled program would be huge: the size limit refuses it.
    hostile_rule_refused(&fx, "(a|aa|aaa){100}{100}", "exceeds size limit").await;
    // Deep nesting is refused by the nesting limit.
    let deep = format!("{}a{}", "(".repeat(40), ")*".repeat(40));
    hostile_rule_refused(&fx, &deep, "nest").await;
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn gigantic_regex_rule_is_refused() {
    let fx = hub().await;
    let giant = format!("/{}", "a".repeat(100_000));
    hostile_rule_refused(&fx, &giant, "512").await;
    fx.still_serving().await;
}
