//! Issue 57: changes kept from an earlier run merge with the agent's YAML file entry by
//! entry. A change to one topic leaves the file's other topics alone (a `no_drop` topic
//! loses nothing through a blackout), no kept change turns `no_drop` on or off, and a file
//! changed since the change was made gets only what still merges — from the robot's own
//! kept file and from the hub's copy alike.

use std::path::Path;
use std::time::Duration;

use fleetlink_agent::AgentOptions;
use fleetlink_agent::config::{AgentConfig, ConfigSource, Overrides};
use serde_json::{Value, json};

use crate::util::*;

/// The agent of `file` (its YAML), as `fleetlink agent --config` starts it.
async fn start_from(file: &Path) -> TestAgent {
    let (cfg, source): (AgentConfig, ConfigSource) =
        AgentConfig::load_source(Some(file), &Overrides::default()).expect("a valid file");
    let agent = start_agent_opts(AgentOptions::changeable(&cfg, &source).expect("options")).await;
    agent.wait_connected().await;
    agent
}

async fn view(hub: &TestHub, robot: &str) -> Value {
    let path = format!("/api/v1/robots/{robot}/config");
    // The robot reports its configuration after it connects: asked for at once, the
    // view may not have it yet.
    within(
        &format!("{robot}'s effective configuration at the hub"),
        async {
            loop {
                let (status, view) =
                    http_json(hub.addr, "GET", &path, Some(&hub.operator_token), None).await;
                assert_eq!(status, 200, "{view}");
                if view["effective"].as_str().is_some_and(|t| !t.is_empty()) {
                    return view;
                }
                tokio::time::sleep(Duration::from_millis(20)).await;
            }
        },
    )
    .await
}

/// The line of `view`'s effective configuration that contains `needle`.
fn effective_line(view: &Value, needle: &str) -> String {
    let text = view["effective"].as_str().unwrap_or_default();
    text.lines()
        .find(|l| l.contains(needle))
        .unwrap_or_else(|| panic!("no {needle:?} in the effective configuration:\n{text}"))
        .to_owned()
}

/// Every number published on `topic` the operator `op` receives until it has seen `last`.
async fn received_until(op: &mut Rosbridge, topic: &str, last: u64) -> Vec<u64> {
    within(&format!("message {last} on {topic}"), async {
        let mut got = Vec::new();
        loop {
            let v = op.recv_op("publish").await;
            if v["topic"] != topic {
                continue;
            }
            let n: u64 = v["msg"]["data"].as_str().unwrap().parse().unwrap();
            got.push(n);
            if n == last {
                return got;
            }
        }
    })
    .await
}

fn publish(p: &mut LocalPublisher, range: std::ops::RangeInclusive<u64>) {
    for n in range {
        p.publish_json(&json!({"data": n.to_string()}));
    }
}

/// The issue's run: the YAML makes `/probe/reliable` no_drop; a change kept from before
/// rate-limits `/pose` (as `PUT …/config` wrote it) and, worse, says `no_drop: false` for
/// the probe. The rate limit applies; the no_drop change is refused, naming the topic; and
/// what the probe publishes during a blackout arrives, every message once.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue57_a_kept_change_to_one_topic_keeps_the_files_no_drop_through_a_blackout() {
    let hub = start_hub().await;
    let proxy = Blackhole::start(hub.addr).await;
    let dir = temp_dir("kept-no-drop");
    let kept = dir.join("runtime.json");
    let file = dir.join("robot.yaml");
    std::fs::write(
        &file,
        format!(
            "hub: ws://{}\nname: kc1\ntoken: {}\nheartbeat_ms: 200\n\
             reconnect: {{ initial_ms: 50, max_ms: 400 }}\nlocal_rosbridge: null\n\
             runtime_file: {}\ntopics:\n  /probe/reliable: {{ no_drop: true, queue: 1000 }}\n  \
             /probe/fast: {{ priority: 10, policy: latest }}\n",
            proxy.addr,
            hub.robot_token("kc1"),
            kept.display()
        ),
    )
    .unwrap();
    std::fs::write(
        &kept,
        json!({"topics": {"/pose": {"rate_limit_hz": 0.5}, "/probe/reliable": {"no_drop": false}}})
            .to_string(),
    )
    .unwrap();
    let agent = start_from(&file).await;

    let v = view(&hub, "kc1").await;
    assert!(
        effective_line(&v, "rate_limit_hz: 0.5").contains("# kept change"),
        "{v}"
    );
    assert!(
        effective_line(&v, "no_drop: true").ends_with("# file"),
        "{v}"
    );
    assert!(
        effective_line(&v, "policy: latest").ends_with("# file"),
        "{v}"
    );
    let aside = v["set_aside"].as_array().expect("set_aside");
    assert_eq!(aside.len(), 1, "{v}");
    assert_eq!(aside[0]["entry"], "topics[\"/probe/reliable\"].no_drop");
    let why = aside[0]["why"].as_str().unwrap();
    assert!(
        why.contains("/probe/reliable") && why.contains("YAML file") && why.contains("restart"),
        "{why}"
    );
    assert_eq!(
        v["overlay"],
        json!({"topics": {"/pose": {"rate_limit_hz": 0.5}}})
    );

    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(json!({"op": "subscribe", "topic": "/kc1/probe/reliable"}))
        .await;
    op.call("/rosapi/get_time", json!({}), "sync").await;
    let mut p = LocalPublisher::new(&agent.router, "/probe/reliable", "std_msgs/msg/String");
    publish(&mut p, 1..=10);
    assert_eq!(
        received_until(&mut op, "/kc1/probe/reliable", 10).await,
        (1..=10).collect::<Vec<_>>()
    );
    proxy.cut();
    publish(&mut p, 11..=60);
    agent.wait_disconnected().await;
    proxy.restore();
    agent.wait_connected().await;
    publish(&mut p, 61..=70);
    assert_eq!(
        received_until(&mut op, "/kc1/probe/reliable", 70).await,
        (11..=70).collect::<Vec<_>>(),
        "what was published during the blackout arrives, once and in order"
    );
    agent.shutdown().await;
    hub.shutdown().await;
}

/// A change made through the hub, then the YAML edited: `/odom`'s priority changed in the
/// file too, its rate limit not. At the next start the rate limit applies and the
/// priority change is set aside (the file's runs), whether the robot kept its changes or
/// comes back without them and gets the hub's copy.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue57_a_file_changed_since_gets_only_what_still_merges() {
    let hub = start_hub().await;
    let dir = temp_dir("kept-file-changed");
    let kept = dir.join("runtime.json");
    let file = dir.join("robot.yaml");
    let yaml = |priority: u32| {
        format!(
            "hub: {}\nname: kc2\ntoken: {}\nheartbeat_ms: 200\nlocal_rosbridge: null\n\
             runtime_file: {}\nsim: {{ laser_scan: null, point_cloud: null, image: null }}\n\
             topics:\n  /odom: {{ priority: {priority} }}\n",
            hub.agent_url(),
            hub.robot_token("kc2"),
            kept.display()
        )
    };
    std::fs::write(&file, yaml(4)).unwrap();
    let agent = start_from(&file).await;
    let (status, answer) = http_json(
        hub.addr,
        "PUT",
        "/api/v1/robots/kc2/config",
        Some(&hub.operator_token),
        Some(&json!({"topics": {"/odom": {"rate_limit_hz": 2, "priority": 9}}})),
    )
    .await;
    assert_eq!(status, 200, "{answer}");
    agent.shutdown().await;

    // The file changes /odom's priority meanwhile.
    std::fs::write(&file, yaml(6)).unwrap();
    let agent = start_from(&file).await;
    let check = |v: &Value| {
        assert!(
            effective_line(v, "rate_limit_hz: 2").contains("# kept change"),
            "{v}"
        );
        assert!(effective_line(v, "priority: 6").ends_with("# file"), "{v}");
        let aside = v["set_aside"].as_array().expect("set_aside");
        assert_eq!(aside.len(), 1, "{v}");
        assert_eq!(aside[0]["entry"], "topics[\"/odom\"].priority");
        let why = aside[0]["why"].as_str().unwrap();
        assert!(why.contains("6") && why.contains("4"), "{why}");
    };
    check(&view(&hub, "kc2").await);
    // A topic goes up while someone watches it.
    let mut watcher = Rosbridge::connect(&hub.ws_url()).await;
    watcher
        .send(json!({"op": "subscribe", "topic": "/kc2/odom", "id": "w"}))
        .await;
    within("odometry at the watcher", watcher.recv_op("publish")).await;
    let limited = messages_in(&hub, "/kc2/odom", Duration::from_secs(2)).await;
    assert!(
        (2..=6).contains(&limited),
        "{limited} odometry messages in 2 s at 2 Hz"
    );
    agent.shutdown().await;

    // Back without its kept changes: the hub's copy merges the same way.
    std::fs::remove_file(&kept).unwrap();
    let agent = start_from(&file).await;
    let v = within("the hub to apply what it keeps", async {
        loop {
            let v = view(&hub, "kc2").await;
            if v["overlay"]["topics"]["/odom"]["rate_limit_hz"] == 2.0 {
                return v;
            }
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
    })
    .await;
    check(&v);
    assert_eq!(
        v["overlay"],
        json!({"topics": {"/odom": {"rate_limit_hz": 2.0}}}),
        "the hub's priority change is not forced back"
    );
    agent.shutdown().await;
    hub.shutdown().await;
}
