//! Access control as clients see it over the wire: a matrix of identities × topics ×
//! operations with the expected allow/deny outcome of each cell, and a rule change that
//! reaches a live subscription.

use serde_json::{Value, json};

use crate::util::*;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Outcome {
    Allowed,
    Denied,
}
use Outcome::{Allowed as A, Denied as D};

const RULES: &str = r#"
rules:
  - subject: {group: operators}
    names: "/.*"
    ops: [subscribe, call_service]
  - subject: {group: operators}
    names: "/r[0-9]+/cmd_vel"
    ops: [publish]
  - subject: any_user
    names: "/rosapi/.*"
    ops: [call_service]
  - subject: any_robot
    names: "/fleet/.*"
    ops: [subscribe]
"#;

const TOPICS: [&str; 4] = ["/r1/odom", "/r2/odom", "/r1/cmd_vel", "/fleet/plan"];

/// Latched topics an admin publishes once, so a new subscriber's first frame is either
/// the message (allowed) or a status error (denied): no waiting for an absence. Returns
/// the publisher (kept open) and a second admin connection subscribed to every topic,
/// which sees what the matrix's publishers get through (the relay never echoes a
/// client's own messages back to it).
async fn seed_topics(hub: &TestHub) -> (Rosbridge, Rosbridge) {
    let mut seeder = Rosbridge::connect(&hub.ws_url()).await;
    for t in TOPICS {
        seeder
            .send(json!({"op": "advertise", "topic": t, "type": "std_msgs/String", "latch": true}))
            .await;
        seeder
            .send(json!({"op": "publish", "topic": t, "msg": {"data": format!("seed {t}")}}))
            .await;
    }
    // Ops on one connection run in order: once this answers, the seeds are latched.
    let r = seeder.call("/rosapi/topics", json!({}), "sync").await;
    assert_eq!(r["result"], true, "{r}");
    let mut watcher = Rosbridge::connect(&hub.ws_url()).await;
    for t in TOPICS {
        watcher.send(json!({"op": "subscribe", "topic": t})).await;
    }
    for _ in TOPICS {
        watcher.recv_op("publish").await;
    }
    (seeder, watcher)
}

async fn subscribe_outcome(url: &str, topic: &str) -> Outcome {
    let mut c = Rosbridge::connect(url).await;
    c.send(json!({"op": "subscribe", "topic": topic, "id": "s"}))
        .await;
    loop {
        let v = c.recv().await;
        match v["op"].as_str() {
            Some("publish") if v["topic"] == topic => return A,
            Some("status") if v["level"] == "error" => return D,
            _ => {}
        }
    }
}

async fn publish_outcome(url: &str, topic: &str, admin: &mut Rosbridge, who: &str) -> Outcome {
    let mut c = Rosbridge::connect(url).await;
    let marker = format!("{who} on {topic}");
    c.send(json!({"op": "advertise", "topic": topic, "type": "std_msgs/String", "id": "a"}))
        .await;
    c.send(json!({"op": "publish", "topic": topic, "msg": {"data": marker}, "id": "p"}))
        .await;
    // Either the admin, subscribed to every topic, receives the marker, or the publisher
    // is told no. Exactly one of the two can happen.
    let delivered = async {
        loop {
            let v = admin.recv_op("publish").await;
            if v["msg"]["data"] == marker.as_str() {
                return;
            }
        }
    };
    let refused = async {
        loop {
            let v = c.recv_op("status").await;
            if v["level"] == "error" {
                return;
            }
        }
    };
    tokio::select! {
        _ = delivered => A,
        _ = refused => D,
    }
}

async fn call_outcome(url: &str) -> Outcome {
    let mut c = Rosbridge::connect(url).await;
    let r = c.call("/rosapi/topics", json!({}), "ls").await;
    if r["result"] == true { A } else { D }
}

/// `(identity, url, [subscribe per topic], [publish per topic], call /rosapi/topics)`.
type Row = (&'static str, String, [Outcome; 4], [Outcome; 4], Outcome);

async fn check_rows(hub: &TestHub, rows: Vec<Row>) {
    let (_seeder, mut admin) = seed_topics(hub).await;
    let mut wrong = Vec::new();
    for (who, url, subs, pubs, call) in rows {
        for (i, t) in TOPICS.iter().enumerate() {
            let got = subscribe_outcome(&url, t).await;
            if got != subs[i] {
                wrong.push(format!(
                    "{who} subscribe {t}: got {got:?}, want {:?}",
                    subs[i]
                ));
            }
            let got = publish_outcome(&url, t, &mut admin, who).await;
            if got != pubs[i] {
                wrong.push(format!(
                    "{who} publish {t}: got {got:?}, want {:?}",
                    pubs[i]
                ));
            }
        }
        let got = call_outcome(&url).await;
        if got != call {
            wrong.push(format!(
                "{who} call /rosapi/topics: got {got:?}, want {call:?}"
            ));
        }
    }
    assert!(
        wrong.is_empty(),
        "ACL matrix mismatches:\n{}",
        wrong.join("\n")
    );
}

fn url(hub: &TestHub, token: &str) -> String {
    format!("ws://{}/?token={token}", hub.addr)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn acl_matrix_over_the_wire() {
    let hub = start_hub().await;
    hub.set_rules(RULES);
    let (s, created) = http_json(
        hub.addr,
        "POST",
        "/api/v1/users",
        Some(&hub.operator_token),
        Some(&json!({"name": "olga", "password": "operator pass", "groups": ["operators"]})),
    )
    .await;
    assert_eq!(s, 201, "{created}");
    let (s, login) = http_json(
        hub.addr,
        "POST",
        "/api/v1/login",
        None,
        Some(&json!({"user": "olga", "password": "operator pass"})),
    )
    .await;
    assert_eq!(s, 200, "{login}");
    let olga = login["token"].as_str().unwrap().to_owned();
    let plain = hub
        .state
        .security
        .store
        .mint_operator_token(
            &fleetlink_auth::UserName::new("pat").unwrap(),
            &[],
            None,
            fleetlink_auth::UnixTime::now(),
        )
        .unwrap()
        .expose()
        .to_owned();
    // Topics:                       r1/odom r2/odom r1/cmd_vel fleet/plan
    let rows: Vec<Row> = vec![
        ("admin", hub.ws_url(), [A, A, A, A], [A, A, A, A], A),
        (
            "operator olga",
            url(&hub, &olga),
            [A, A, A, A],
            [D, D, A, D],
            A,
        ),
        (
            "plain user pat",
            url(&hub, &plain),
            [D, D, D, D],
            [D, D, D, D],
            A,
        ),
        (
            "robot r1",
            url(&hub, &hub.robot_token("r1")),
            [A, D, A, A],
            [A, D, A, D],
            D,
        ),
        (
            "robot r2",
            url(&hub, &hub.robot_token("r2")),
            [D, A, D, A],
            [D, A, D, D],
            D,
        ),
    ];
    check_rows(&hub, rows).await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn acl_matrix_anonymous_read() {
    let hub = start_hub_with(|cfg| {
        cfg.auth = fleetlink_auth::AuthPolicy::demo();
        cfg.acl = fleetlink_auth::AclDefaults::demo();
    })
    .await;
    let anon = format!("ws://{}/", hub.addr);
    let rows: Vec<Row> = vec![("anonymous", anon, [A, A, A, A], [D, D, D, D], A)];
    check_rows(&hub, rows).await;
    hub.shutdown().await;
}

/// Messages on `/live/feed` reach `pat` exactly while a rule grants it.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn rule_change_applies_to_a_live_subscription() {
    let hub = start_hub().await;
    let op = hub.operator_token.clone();
    let api = |method: &'static str, path: String, body: Option<Value>| {
        let op = op.clone();
        let addr = hub.addr;
        async move { http_json(addr, method, &path, Some(&op), body.as_ref()).await }
    };
    let grant =
        json!({"subject": {"group": "watchers"}, "names": "/live/.*", "ops": ["subscribe"]});
    let (s, r) = api("POST", "/api/v1/rules".into(), Some(grant.clone())).await;
    assert_eq!(s, 201, "{r}");
    let rule_id = r["id"].as_i64().unwrap();
    let (s, r) = api(
        "POST",
        "/api/v1/rules".into(),
        Some(json!({"subject": "any_user", "names": "/rosapi/.*", "ops": ["call_service"]})),
    )
    .await;
    assert_eq!(s, 201, "{r}");
    let pat = hub
        .state
        .security
        .store
        .mint_operator_token(
            &fleetlink_auth::UserName::new("pat").unwrap(),
            &[fleetlink_auth::GroupName::new("watchers").unwrap()],
            None,
            fleetlink_auth::UnixTime::now(),
        )
        .unwrap()
        .expose()
        .to_owned();
    let mut admin = Rosbridge::connect(&hub.ws_url()).await;
    admin
        .send(json!({"op": "advertise", "topic": "/live/feed", "type": "std_msgs/String"}))
        .await;
    let mut watcher = Rosbridge::connect(&url(&hub, &pat)).await;
    watcher
        .send(json!({"op": "subscribe", "topic": "/live/feed", "id": "w"}))
        .await;
    // Subscribed (the subscribe ran before this answer) and receiving.
    assert_eq!(
        watcher.call("/rosapi/get_time", json!({}), "t0").await["result"],
        true
    );
    admin
        .send(json!({"op": "publish", "topic": "/live/feed", "msg": {"data": "before"}}))
        .await;
    assert_eq!(watcher.recv_op("publish").await["msg"]["data"], "before");

    // Revoke the grant; publish while revoked.
    let (s, r) = api("DELETE", format!("/api/v1/rules/{rule_id}"), None).await;
    assert_eq!(s, 204, "{r}");
    for i in 0..5 {
        admin
            .send(json!({"op": "publish", "topic": "/live/feed", "msg": {"data": format!("hidden {i}")}}))
            .await;
    }
    // The admin's own call answers after its publishes were queued for the watcher...
    assert_eq!(
        admin.call("/rosapi/get_time", json!({}), "sync").await["result"],
        true
    );
    // ...then the watcher's writer takes them off its queue (and the gate drops them)...
    let router = hub.state.router.clone();
    eventually("the watcher's queue to drain", || {
        router
            .clients()
            .iter()
            .all(|(_, outbox, _)| outbox.depth() == 0)
    })
    .await;
    // ...and a reply the watcher asks for now is written after that batch: nothing
    // published while the rule was gone may come before it.
    watcher
        .send(json!({"op": "call_service", "service": "/rosapi/get_time", "id": "t1"}))
        .await;
    loop {
        let v = watcher.recv().await;
        assert_ne!(v["op"], "publish", "delivered while not allowed: {v}");
        if v["op"] == "service_response" && v["id"] == "t1" {
            break;
        }
    }

    // Re-grant: deliveries resume on the same subscription.
    let (s, r) = api("POST", "/api/v1/rules".into(), Some(grant)).await;
    assert_eq!(s, 201, "{r}");
    admin
        .send(json!({"op": "publish", "topic": "/live/feed", "msg": {"data": "after"}}))
        .await;
    let m = watcher.recv_op("publish").await;
    assert_eq!(
        m["msg"]["data"], "after",
        "a hidden message leaked or order broke: {m}"
    );
    hub.shutdown().await;
}
