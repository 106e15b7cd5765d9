//! Runtime configuration (issue 40, item 2): a robot's configuration read and changed
//! while its agent runs, through the hub's API and the agent's local listener; checked
//! like the YAML, kept on the robot and by the hub, applied again when the robot
//! reconnects without it.

use std::sync::atomic::Ordering::Relaxed;
use std::time::Duration;

use fleetlink_agent::AgentOptions;
use fleetlink_agent::config::{AgentConfig, ConfigSource, LocalRosbridgeConfig, SimConfig};
use serde_json::{Value, json};

use crate::util::*;

/// The simulated robot's odometry only (20 Hz).
fn odometry_only() -> SimConfig {
    SimConfig {
        laser_scan: None,
        point_cloud: None,
        image: None,
        ..SimConfig::default()
    }
}

/// An agent of `hub` named `robot` from a configuration file's fields, its runtime
/// changes kept in `file`, its local listener's configuration API open with `api_token`.
fn robot_config(
    hub: &TestHub,
    robot: &str,
    file: &std::path::Path,
    api_token: &str,
) -> AgentConfig {
    AgentConfig {
        hub: vec![hub.agent_url()],
        name: fleetlink_auth::RobotName::new(robot).unwrap(),
        token: hub.robot_token(robot),
        heartbeat_ms: 200,
        local_rosbridge: Some(LocalRosbridgeConfig {
            listen: "127.0.0.1:0".parse().unwrap(),
            config_token: api_token.to_owned(),
            ..LocalRosbridgeConfig::default()
        }),
        sim: Some(odometry_only()),
        runtime_file: Some(file.to_owned()),
        ..AgentConfig::default()
    }
}

async fn start(cfg: &AgentConfig) -> TestAgent {
    let source = ConfigSource::default();
    let a = start_agent_opts(AgentOptions::changeable(cfg, &source).expect("options")).await;
    a.wait_connected().await;
    a
}

/// The robot's configuration from the hub at `addr`, once `holds` is true of it (read
/// again while it is not, within the tests' bound).
async fn config_once(
    addr: std::net::SocketAddr,
    path: &str,
    token: &str,
    holds: impl Fn(&Value) -> bool,
) -> Value {
    within("the robot's configuration to hold", async {
        loop {
            let (_, view) = http_json(addr, "GET", path, Some(token), None).await;
            if holds(&view) {
                return view;
            }
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
    })
    .await
}

async fn put(hub: &TestHub, robot: &str, change: &Value) -> (u16, Value) {
    http_json(
        hub.addr,
        "PUT",
        &format!("/api/v1/robots/{robot}/config"),
        Some(&hub.operator_token),
        Some(change),
    )
    .await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_change_through_the_hub_applies_at_once_is_kept_and_applied_again() {
    let hub = start_hub().await;
    let dir = temp_dir("runtime-config");
    let file = dir.join("robot").join("runtime.json");
    let cfg = robot_config(&hub, "cfg1", &file, "");
    let agent = start(&cfg).await;
    let mut watcher = Rosbridge::connect(&hub.ws_url()).await;
    watcher
        .send(json!({"op": "subscribe", "topic": "/cfg1/odom", "id": "w"}))
        .await;
    within("odometry at the watcher", watcher.recv_op("publish")).await;
    let before = messages_in(&hub, "/cfg1/odom", Duration::from_secs(1)).await;
    assert!(
        (12..=30).contains(&before),
        "{before} odometry messages a second"
    );

    // The configuration as the robot runs it.
    let (status, view) = http_json(
        hub.addr,
        "GET",
        "/api/v1/robots/cfg1/config",
        Some(&hub.operator_token),
        None,
    )
    .await;
    assert_eq!(status, 200, "{view}");
    assert!(
        view["effective"].as_str().unwrap().contains("name: cfg1"),
        "{view}"
    );
    assert_eq!(view["overlay"], json!({}));
    assert_eq!(view["may_change"], true);

    // A rate limit set while it runs applies at once, without a reconnect.
    let connects = agent.stats.connects.load(Relaxed);
    let (status, answer) = put(
        &hub,
        "cfg1",
        &json!({"topics": {"/odom": {"rate_limit_hz": 2}}}),
    )
    .await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["changed"], json!(["topics"]));
    assert_eq!(answer["overlay"]["topics"]["/odom"]["rate_limit_hz"], 2.0);
    let limited = messages_in(&hub, "/cfg1/odom", Duration::from_secs(2)).await;
    assert!(
        (2..=6).contains(&limited),
        "{limited} odometry messages in 2 s at 2 Hz"
    );
    assert_eq!(
        agent.stats.connects.load(Relaxed),
        connects,
        "the change reconnected the link"
    );

    // Refused with the YAML's error text, naming the field; nothing changes.
    let bad = json!({"topics": {"/odom": {"rate_limit_hz": 0}}});
    let (status, refusal) = put(&hub, "cfg1", &bad).await;
    assert_eq!(status, 400, "{refusal}");
    let yaml_error = AgentConfig::from_str(&bad.to_string(), "change")
        .unwrap_err()
        .to_string();
    assert_eq!(refusal["error"], yaml_error);
    assert_eq!(refusal["field"], "topics[\"/odom\"].rate_limit_hz");
    let (status, refusal) = put(&hub, "cfg1", &json!({"hub": "ws://elsewhere:8080"})).await;
    assert_eq!(status, 400);
    assert_eq!(refusal["field"], "hub", "{refusal}");

    // Only the hub calls the configuration services, whoever asks (even the admin).
    let call = watcher
        .call(
            "/cfg1/fleetlink/config/set",
            json!({"change": "topics: {}"}),
            "direct",
        )
        .await;
    assert_eq!(call["result"], false, "{call}");

    // Kept on the robot: the file holds the changes in force, each entry with who made it.
    let kept: Value = serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    assert_eq!(
        kept["change"]["topics"]["/odom"]["rate_limit_hz"], 2.0,
        "{kept}"
    );
    assert!(
        kept["entries"]["topics[\"/odom\"].rate_limit_hz"]["by"]
            .as_str()
            .is_some_and(|b| b.starts_with("user:")),
        "{kept}"
    );
    assert!(
        std::fs::read_to_string(fleetlink_agent::runtime::audit_path(&file))
            .unwrap()
            .contains("\"by\":\"user:"),
        "the change is in the robot's audit log"
    );

    // The robot comes back without its file: the hub applies what it keeps again.
    agent.shutdown().await;
    std::fs::remove_file(&file).unwrap();
    let agent = start(&cfg).await;
    let view = config_once(
        hub.addr,
        "/api/v1/robots/cfg1/config",
        &hub.operator_token,
        |view| view["overlay"]["topics"]["/odom"]["rate_limit_hz"] == 2.0,
    )
    .await;
    assert_eq!(
        view["overlay"]["topics"]["/odom"]["rate_limit_hz"], 2.0,
        "{view}"
    );
    assert!(
        view["kept"]["by"].as_str().unwrap().starts_with("user:"),
        "{view}"
    );
    assert!(
        file.exists(),
        "applied again, the changes are kept on the robot again"
    );
    let limited = messages_in(&hub, "/cfg1/odom", Duration::from_secs(2)).await;
    assert!(
        (2..=6).contains(&limited),
        "{limited} odometry messages in 2 s after the return"
    );
    agent.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_local_listener_serves_the_configuration_api_with_its_token() {
    let hub = start_hub().await;
    let dir = temp_dir("runtime-config-local");
    let file = dir.join("runtime.json");
    let cfg = robot_config(&hub, "cfg2", &file, "s3cret");
    let agent = start(&cfg).await;
    let local = agent.local.unwrap();
    let (status, body) = http_json(local, "GET", "/api/v1/config", None, None).await;
    assert_eq!(status, 401, "{body}");
    let (status, body) = http_json(local, "GET", "/api/v1/config", Some("wrong"), None).await;
    assert_eq!(status, 401, "{body}");
    let (status, view) = http_json(local, "GET", "/api/v1/config", Some("s3cret"), None).await;
    assert_eq!(status, 200, "{view}");
    assert!(
        view["effective"]
            .as_str()
            .unwrap()
            .contains("(set, 6 characters)"),
        "the token is not shown: {view}"
    );
    // The same port still speaks rosbridge.
    let mut client = Rosbridge::connect(&agent.local_url()).await;
    client
        .send(json!({"op": "subscribe", "topic": "/odom", "id": "l"}))
        .await;
    within("odometry at the local client", client.recv_op("publish")).await;
    // A local rosbridge client cannot use the hub's way in (no token there).
    let call = client
        .call(
            "/fleetlink/config/set",
            json!({"change": "topics: {}"}),
            "local",
        )
        .await;
    assert_eq!(call["result"], false, "{call}");
    assert!(
        call["values"].to_string().contains("local listener"),
        "{call}"
    );

    // A remap changes the odometry's hub name: the link reconnects to announce it.
    let connects = agent.stats.connects.load(Relaxed);
    let change = json!({"remap": {"/odom": "/cfg2/odometry"}});
    let (status, answer) = http_json(
        local,
        "PUT",
        "/api/v1/config",
        Some("s3cret"),
        Some(&change),
    )
    .await;
    assert_eq!(status, 200, "{answer}");
    let mut watcher = Rosbridge::connect(&hub.ws_url()).await;
    watcher
        .send(json!({"op": "subscribe", "topic": "/cfg2/odometry", "id": "w"}))
        .await;
    let m = within(
        "the remapped odometry at the hub",
        watcher.recv_op("publish"),
    )
    .await;
    assert_eq!(m["topic"], "/cfg2/odometry");
    assert_eq!(
        agent.stats.connects.load(Relaxed),
        connects + 1,
        "a remap reconnects the link once"
    );
    // Bad YAML is refused with its position in the change.
    let (status, refusal) = http_json(
        local,
        "PUT",
        "/api/v1/config",
        Some("s3cret"),
        Some(&json!({"ros2": {"publish": ["/x"]}})),
    )
    .await;
    assert_eq!(status, 400, "{refusal}");
    assert!(
        refusal["error"]
            .as_str()
            .unwrap()
            .contains("no ROS 2 bridge"),
        "{refusal}"
    );

    // Restarted, the agent runs with the change it kept (no hub change involved: the hub
    // keeps only what it applied).
    agent.shutdown().await;
    let agent = start(&cfg).await;
    let (_, view) = http_json(
        agent.local.unwrap(),
        "GET",
        "/api/v1/config",
        Some("s3cret"),
        None,
    )
    .await;
    assert_eq!(
        view["overlay"]["remap"]["/odom"], "/cfg2/odometry",
        "{view}"
    );
    agent.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_site_hubs_robot_is_changed_through_the_cloud_hub() {
    let cloud = start_hub().await;
    let site = start_hub().await;
    let _link = link_site(&cloud, &site, "site7").await;
    let dir = temp_dir("runtime-config-site");
    let file = dir.join("runtime.json");
    let cfg = robot_config(&site, "robot7", &file, "");
    let agent = start(&cfg).await;
    let mut watcher = Rosbridge::connect(&cloud.ws_url()).await;
    watcher
        .send(json!({"op": "subscribe", "topic": "/site7/robot7/odom", "id": "w"}))
        .await;
    within(
        "the site robot's odometry upstream",
        watcher.recv_op("publish"),
    )
    .await;
    let path = "/api/v1/robots/site7/robots/robot7/config";
    let (status, view) =
        http_json(cloud.addr, "GET", path, Some(&cloud.operator_token), None).await;
    assert_eq!(status, 200, "{view}");
    assert!(
        view["effective"].as_str().unwrap().contains("name: robot7"),
        "{view}"
    );
    let change = json!({"topics": {"/odom": {"rate_limit_hz": 2}}});
    let (status, answer) = http_json(
        cloud.addr,
        "PUT",
        path,
        Some(&cloud.operator_token),
        Some(&change),
    )
    .await;
    assert_eq!(status, 200, "{answer}");
    let limited = messages_in(&cloud, "/site7/robot7/odom", Duration::from_secs(2)).await;
    assert!(
        (2..=6).contains(&limited),
        "{limited} odometry messages in 2 s at 2 Hz, upstream"
    );

    // Back without its file: the cloud hub applies what it keeps, across the site hub.
    agent.shutdown().await;
    std::fs::remove_file(&file).unwrap();
    let agent = start(&cfg).await;
    let view = config_once(cloud.addr, path, &cloud.operator_token, |view| {
        view["overlay"]["topics"]["/odom"]["rate_limit_hz"] == 2.0
    })
    .await;
    assert_eq!(
        view["overlay"]["topics"]["/odom"]["rate_limit_hz"], 2.0,
        "{view}"
    );
    agent.shutdown().await;
    site.shutdown().await;
    cloud.shutdown().await;
}
