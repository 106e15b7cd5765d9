//! Config parsing and error reporting: every error names file, line, column and field.

use super::*;
use std::path::Path;

fn err(text: &str) -> ConfigError {
    match AgentConfig::from_str(text, "robot.yaml") {
        Ok(cfg) => panic!("expected an error for {text:?}, got {cfg:?}"),
        Err(e) => e,
    }
}

/// Asserts the error's full text, which is what a user sees.
fn assert_err(text: &str, expected: &str) {
    assert_eq!(err(text).to_string(), expected, "for {text:?}");
}

const FULL: &str = "\
hub: wss://hub.example.com:443
name: robot_7
token: s3cret
heartbeat_ms: 500
reconnect: { initial_ms: 100, max_ms: 5000 }
local_rosbridge: { listen: 0.0.0.0:9191 }
remap:
  /map: /fleet/map
subscribe:
  - { hub: /fleet/announcements, local: /announcements }
sim:
  seed: 42
  frame_prefix: r7/
  laser_scan:   { topic: /scan, rate_hz: 10, ranges: 360 }
  point_cloud:  { rate_hz: 2.5 }
";

#[test]
fn empty_file_is_the_default() {
    assert_eq!(
        AgentConfig::from_str("", "a.yaml").expect("empty is valid"),
        AgentConfig::default()
    );
    assert_eq!(
        AgentConfig::from_str("# only a comment\n", "a.yaml").expect("valid"),
        AgentConfig::default()
    );
    AgentConfig::default()
        .validate()
        .expect("the default is valid");
}

#[test]
fn full_example_parses() {
    let cfg = AgentConfig::from_str(FULL, "robot.yaml").expect("valid");
    assert_eq!(cfg.hub, ["wss://hub.example.com:443"]);
    assert_eq!(cfg.name.as_str(), "robot_7");
    assert_eq!(cfg.token, "s3cret");
    assert_eq!(cfg.heartbeat(), Duration::from_millis(500));
    assert_eq!(cfg.link_timeout(), Duration::from_secs(1));
    assert_eq!(cfg.reconnect.initial(), Duration::from_millis(100));
    assert_eq!(cfg.reconnect.max(), Duration::from_secs(5));
    assert_eq!(
        cfg.local_rosbridge_listen(),
        Some("0.0.0.0:9191".parse().expect("addr"))
    );
    assert_eq!(cfg.hub_topic("/map"), "/fleet/map");
    assert_eq!(cfg.hub_topic("/scan"), "/robot_7/scan");
    assert_eq!(
        cfg.subscribe,
        vec![Subscription {
            hub: "/fleet/announcements".into(),
            local: "/announcements".into()
        }]
    );
    let sim = cfg.sim.expect("sim configured");
    assert_eq!((sim.seed, sim.frame_prefix.as_str()), (42, "r7/"));
    let scan = sim.laser_scan.expect("scan enabled");
    assert_eq!((scan.topic.as_str(), scan.ranges), ("/scan", 360));
    assert_eq!(scan.period(), Duration::from_millis(100));
    let cloud = sim.point_cloud.expect("cloud enabled");
    assert_eq!((cloud.topic.as_str(), cloud.points), ("/points", 10_000));
    assert_eq!(cloud.period(), Duration::from_millis(400));
    assert!(sim.odometry.is_none() && sim.pose.is_none() && sim.image.is_none());
}

#[test]
fn sim_without_sensors_means_all_sensors() {
    let cfg = AgentConfig::from_str("sim: {}\n", "a.yaml").expect("valid");
    assert_eq!(cfg.sim, Some(SimConfig::default()));
    let cfg = AgentConfig::from_str("sim: { seed: 9 }\n", "a.yaml").expect("valid");
    let sim = cfg.sim.expect("sim");
    assert_eq!(sim.seed, 9);
    assert_eq!(sim.enabled_topics().len(), 5);
    let cfg = AgentConfig::from_str("sim: { pose: {} }\n", "a.yaml").expect("valid");
    assert_eq!(
        cfg.sim.expect("sim").enabled_topics(),
        vec![("pose", "/pose", 10.0)]
    );
}

#[test]
fn sim_markers_are_opt_in() {
    let cfg = AgentConfig::from_str("sim: { markers: { rate_hz: 1 } }\n", "a.yaml").expect("valid");
    let sim = cfg.sim.expect("sim");
    assert_eq!(sim.enabled_topics(), vec![("markers", "/markers", 1.0)]);
    let cfg = AgentConfig::from_str("sim: { pose: {}, markers: { topic: /room } }\n", "a.yaml")
        .expect("valid");
    assert_eq!(
        cfg.sim.expect("sim").enabled_topics(),
        vec![("pose", "/pose", 10.0), ("markers", "/room", 1.0)]
    );
    let e =
        AgentConfig::from_str("sim:\n  markers: { rate_hz: 0 }\n", "a.yaml").expect_err("rate 0");
    assert_eq!(e.field(), Some("sim.markers.rate_hz"));
}

#[test]
fn local_rosbridge_can_be_disabled_two_ways() {
    for text in [
        "local_rosbridge: null\n",
        "local_rosbridge: ~\n",
        "local_rosbridge: { enabled: false }\n",
    ] {
        let cfg = AgentConfig::from_str(text, "a.yaml").expect("valid");
        assert_eq!(cfg.local_rosbridge_listen(), None, "{text}");
    }
    let cfg = AgentConfig::from_str("local_rosbridge: {}\n", "a.yaml").expect("valid");
    assert_eq!(
        cfg.local_rosbridge_listen(),
        Some("127.0.0.1:9090".parse().expect("addr"))
    );
}

#[test]
fn semantic_error_names_file_line_and_field() {
    let text = "\
name: r1
sim:
  seed: 3
  point_cloud:
    topic: /points
    rate_hz: 0
";
    let e = err(text);
    assert_eq!(
        e.to_string(),
        "robot.yaml:6:14: sim.point_cloud.rate_hz: must be > 0, got 0"
    );
    assert_eq!(e.field(), Some("sim.point_cloud.rate_hz"));
    assert_eq!(e.position().map(|p| (p.line, p.column)), Some((6, 14)));
}

#[test]
fn semantic_errors() {
    assert_err(
        "sim: { laser_scan: { topic: '' } }\n",
        "robot.yaml:1:29: sim.laser_scan.topic: must not be empty",
    );
    assert_err(
        "sim:\n  odometry: { topic: odom }\n",
        "robot.yaml:2:22: sim.odometry.topic: must start with '/', got \"odom\"",
    );
    assert_err(
        "sim:\n  odometry: {}\n  pose: { topic: /odom }\n",
        "robot.yaml:3:18: sim.pose.topic: \"/odom\" is already used by sim.odometry; sim topics must be unique",
    );
    assert_err(
        "local_rosbridge:\n  listen: localhost\n",
        "robot.yaml:2:11: local_rosbridge.listen: expected IP:PORT like 127.0.0.1:9090, got \"localhost\" (invalid socket address syntax)",
    );
    assert_err(
        "hub: http://x\n",
        "robot.yaml:1:6: hub: must be a ws:// or wss:// URL such as ws://hub.example:8080, got \"http://x\"",
    );
    assert_err(
        "heartbeat_ms: 0\n",
        "robot.yaml:1:15: heartbeat_ms: must be > 0, got 0",
    );
    assert_err(
        "reconnect:\n  initial_ms: 500\n  max_ms: 100\n",
        "robot.yaml:3:11: reconnect.max_ms: must be >= reconnect.initial_ms (500), got 100",
    );
    assert_err(
        "remap:\n  /ok: /fine\n  map: /fleet/map\n",
        "robot.yaml:3:3: remap.map: local topic must start with '/', got \"map\"",
    );
    assert_err(
        "remap:\n  /map: fleet//map\n",
        "robot.yaml:2:9: remap[\"/map\"]: must start with '/', got \"fleet//map\"",
    );
    assert_err(
        "subscribe:\n  - { hub: /a, local: /b }\n  - hub: /c/\n    local: /d\n",
        "robot.yaml:3:10: subscribe[1].hub: must be '/'-separated non-empty names, got \"/c/\"",
    );
    assert_err(
        "sim: { image: { width: 8 } }\n",
        "robot.yaml:1:24: sim.image.width: must be in 16..=4096, got 8",
    );
    assert_err(
        "sim: { image: { quality: 0 } }\n",
        "robot.yaml:1:26: sim.image.quality: must be in 1..=100, got 0",
    );
}

/// The camera's old `bytes` (the size of the noise it sent) is refused with the keys
/// that replaced it, not silently ignored or refused as merely unknown.
#[test]
fn camera_bytes_is_refused_with_the_keys_that_replace_it() {
    let e = err("name: r1\nsim:\n  image: { rate_hz: 5, bytes: 30000 }\n");
    assert_eq!(e.field(), Some("sim.image.bytes"), "{e}");
    let text = e.to_string();
    assert!(
        text.starts_with("robot.yaml:3:24: sim.image.bytes: is no longer read"),
        "{text}"
    );
    for key in ["`width`", "`height`", "`quality`", "remove `bytes`"] {
        assert!(text.contains(key), "{key} in {text}");
    }
    let cfg = AgentConfig::from_str(
        "sim:\n  image: { width: 640, height: 480, quality: 90 }\n",
        "robot.yaml",
    )
    .expect("the new keys");
    let image = cfg.sim.and_then(|s| s.image).expect("image");
    assert_eq!((image.width, image.height, image.quality), (640, 480, 90));
}

#[test]
fn type_errors_name_the_field() {
    let e = err("name: r1\nsim:\n  laser_scan:\n    rate_hz: fast\n");
    assert_eq!(e.field(), Some("sim.laser_scan.rate_hz"), "{e}");
    assert_eq!(
        e.position().map(|p| (p.line, p.column)),
        Some((4, 14)),
        "{e}"
    );
    assert!(
        e.to_string()
            .starts_with("robot.yaml:4:14: sim.laser_scan.rate_hz: "),
        "{e}"
    );

    let e = err("subscribe:\n  - { hub: /a, local: [1, 2] }\n");
    assert_eq!(e.field(), Some("subscribe[0].local"), "{e}");

    let e = err("heartbeat_ms: -5\n");
    assert_eq!(e.field(), Some("heartbeat_ms"), "{e}");
    assert_eq!(e.position().map(|p| p.line), Some(1));
}

#[test]
fn unknown_fields_are_rejected_with_their_path() {
    let e = err("name: r1\nsim:\n  laser_scan: { topic: /scan, beams: 10 }\n");
    assert_eq!(e.field(), Some("sim.laser_scan.beams"), "{e}");
    assert!(
        e.to_string()
            .starts_with("robot.yaml:3:31: sim.laser_scan.beams: unknown field `beams`"),
        "{e}"
    );

    let e = err("heartbeat: 5\n");
    assert_eq!(
        e.to_string().split(": unknown").next(),
        Some("robot.yaml:1:1: heartbeat"),
        "{e}"
    );
}

#[test]
fn topics_key_takes_per_topic_qos() {
    let cfg = AgentConfig::from_str(
        "name: r1\ntopics:\n  /scan: { policy: latest, priority: 5 }\n",
        "robot.yaml",
    )
    .expect("valid");
    let spec = &cfg.topics["/scan"];
    assert_eq!(spec.priority, Some(5.0));
}

#[test]
fn bad_topic_qos_names_the_field() {
    let e = err("name: r1\ntopics:\n  /scan:\n    priority: -1\n");
    let text = e.to_string();
    assert!(text.starts_with("robot.yaml:4:"), "{text}");
    assert!(text.contains("topics[\"/scan\"].priority"), "{text}");
}

#[test]
fn syntax_errors_have_a_position() {
    let e = err("name: r1\nsim: [a\n");
    match &e {
        ConfigError::Syntax { at, .. } => {
            assert_eq!((at.file.as_str(), at.line), ("robot.yaml", 2))
        }
        other => panic!("expected a syntax error, got {other:?}"),
    }
    assert_eq!(
        e.to_string(),
        "robot.yaml:2:6: invalid YAML: unclosed bracket '['"
    );
    let e = err("name: a\nname: b\n");
    assert!(e.to_string().starts_with("robot.yaml:2:1: "), "{e}");
}

#[test]
fn load_reads_files_and_names_them() {
    let dir = std::env::temp_dir().join(format!("fleetlink-config-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("robot.yaml");
    std::fs::write(&path, "sim:\n  pose: { rate_hz: 0 }\n").expect("write");
    let e = AgentConfig::load(&path).expect_err("rate 0");
    assert_eq!(
        e.to_string(),
        format!(
            "{}:2:20: sim.pose.rate_hz: must be > 0, got 0",
            path.display()
        )
    );
    let missing = dir.join("missing.yaml");
    let e = AgentConfig::load(&missing).expect_err("missing");
    assert!(matches!(e, ConfigError::Read { .. }), "{e:?}");
    assert!(
        e.to_string()
            .starts_with(&format!("{}: cannot read config: ", missing.display())),
        "{e}"
    );
    std::fs::remove_dir_all(&dir).expect("cleanup");
}

#[test]
fn example_files_parse() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let cfg = AgentConfig::load(&root.join("examples/agent.yaml")).expect("examples/agent.yaml");
    assert_eq!(cfg.sim.map(|s| s.enabled_topics().len()), Some(5));

    // The "Full example" block in the reference.
    let doc = std::fs::read_to_string(root.join("docs/config.md")).expect("docs/config.md");
    let block = doc
        .split("```yaml\n")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .expect("a yaml block in docs/config.md");
    let cfg = AgentConfig::from_str(block, "docs/config.md").expect("docs example is valid");
    assert_eq!(cfg.name.as_str(), "robot7");
}

#[test]
fn validate_reports_the_field_without_position() {
    let cfg = AgentConfig {
        hub: vec!["http://x".into()],
        ..AgentConfig::default()
    };
    let e = cfg.validate().expect_err("bad hub");
    assert_eq!(
        e.to_string(),
        "config field hub: must be a ws:// or wss:// URL such as ws://hub.example:8080, got \"http://x\""
    );
}

/// Issue 14: `--hub` is applied before the checks, and is checked like `hub:`.
#[test]
fn command_line_overrides_are_checked_together_with_the_file() {
    let dir = std::env::temp_dir().join(format!("fleetlink-overrides-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("robot.yaml");
    std::fs::write(
        &path,
        "name: robot7\ntls: { ca: /etc/fleetlink/hub-ca.pem }\n",
    )
    .unwrap();
    let hub = |h: &str| Overrides {
        hub: Some(vec![h.to_owned()]),
        name: None,
        mirror: None,
    };
    // The README's pattern: the wss:// hub on the command line, tls: in the file.
    let cfg = AgentConfig::load_with(Some(&path), &hub("wss://hub.example:8080")).expect("valid");
    assert_eq!(cfg.hub, ["wss://hub.example:8080"]);
    // Not a WebSocket URL, or no host: refused, naming the flag.
    for bad in ["http://x", "hub.example:8080", "ws://"] {
        let e = AgentConfig::load_with(None, &hub(bad)).expect_err(bad);
        assert!(e.to_string().starts_with("--hub: "), "{bad}: {e}");
        assert_eq!(e.field(), Some("--hub"));
    }
    // A plain ws:// hub with tls: in the file is still a mistake in the file.
    let e = AgentConfig::load_with(Some(&path), &hub("ws://127.0.0.1:8080")).expect_err("tls");
    assert_eq!(e.field(), Some("tls"), "{e}");
    assert!(e.position().is_some());
    // --name overrides `name:` (it was parsed as a robot name on the command line).
    let cfg = AgentConfig::load_with(
        Some(&path),
        &Overrides {
            hub: Some(vec!["wss://hub.example:8080".into()]),
            name: Some(RobotName::new("robot8").unwrap()),
            mirror: None,
        },
    )
    .expect("valid");
    assert_eq!(cfg.name.as_str(), "robot8");
    let _ = std::fs::remove_dir_all(dir);
}

/// Issue 10: the `ros1:` section, from the commented example and the reference's snippet.
#[test]
fn ros1_examples_parse_and_become_options() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let cfg = AgentConfig::load(&root.join("examples/ros1-robot.yaml"))
        .expect("examples/ros1-robot.yaml");
    let r = cfg.ros1.clone().expect("a ros1 section");
    assert_eq!(r.master_uri.as_deref(), Some("http://localhost:11311"));
    assert_eq!(r.subscribe, ["/cmd_vel", "/announcements"]);
    let opts = crate::AgentOptions::from_config(&cfg).expect("options");
    let ros1 = opts.ros1.expect("ros1 options");
    assert_eq!(ros1.node_name, "/fleetlink_robot7");
    assert!(ros1.publish.matches("/scan"));
    assert!(!ros1.publish.matches("/camera/raw"));
    assert!(ros1.expose.matches("/set_mode"));
    assert!(!ros1.expose.matches("/node/set_logger_level"));
    assert!(ros1.offer.matches("/cloud/plan"));

    let doc = std::fs::read_to_string(root.join("docs/config.md")).expect("docs/config.md");
    let block = doc
        .split("```yaml\nros1:")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .expect("the ros1 block in docs/config.md");
    let cfg = AgentConfig::from_str(&format!("ros1:{block}"), "docs/config.md")
        .expect("docs ros1 example is valid");
    let opts = crate::AgentOptions::from_config(&cfg).expect("options");
    let ros1 = opts.ros1.expect("ros1 options");
    assert_eq!(ros1.node_name, "/fleetlink_robot1");
    assert!(ros1.publish.matches("/odom") && !ros1.publish.matches("/camera/raw"));
}

#[test]
fn ros1_errors_name_the_field() {
    assert_err(
        "ros1: { master_uri: 'localhost:11311' }\n",
        "robot.yaml:1:21: ros1.master_uri: must be http://HOST:PORT such as http://localhost:11311, got \"localhost:11311\"",
    );
    assert_err(
        "ros1:\n  publish: { include: ['/scan(' ] }\n",
        "robot.yaml:2:24: ros1.publish.include[0]: is not a valid pattern (error: unclosed group): \"/scan(\"",
    );
    assert_err(
        "ros1: { subscribe: [cmd_vel] }\n",
        "robot.yaml:1:21: ros1.subscribe[0]: must start with '/', got \"cmd_vel\"",
    );
    assert_err(
        "ros1: { node_name: '9lives' }\n",
        "robot.yaml:1:20: ros1.node_name: must be a ROS name such as /fleetlink_agent, got \"9lives\"",
    );
    assert_err(
        "ros1: { discovery_ms: 0 }\n",
        "robot.yaml:1:23: ros1.discovery_ms: must be > 0, got 0",
    );
    assert_err(
        "ros1: { publish: { names: [/a] } }\n",
        "robot.yaml:1:20: ros1.publish.names: unknown field `names`, expected one of include, exclude",
    );
}

#[test]
fn ros2_section_becomes_bridge_options() {
    let cfg = AgentConfig::from_str(
        "ros2:\n  domain_id: 7\n  publish: { include: ['.*'], exclude: [/camera/raw] }\n  subscribe: [/cmd_vel]\n  services: { expose: [/add_two_ints], offer: ['/cloud/.*'] }\n  actions: { expose: [/fibonacci] }\n",
        "robot.yaml",
    )
    .expect("valid ros2 section");
    let ros2 = crate::AgentOptions::from_config(&cfg)
        .expect("options")
        .ros2
        .expect("ros2 options");
    assert_eq!(ros2.domain_id, 7);
    assert!(ros2.publish.matches("/scan") && !ros2.publish.matches("/camera/raw"));
    assert!(ros2.expose.matches("/add_two_ints") && !ros2.expose.matches("/other"));
    assert!(ros2.offer.matches("/cloud/greet"));
    assert!(ros2.expose_actions.matches("/fibonacci"));
    assert_eq!(ros2.subscribe.len(), 1);
    assert_eq!(ros2.discovery_period, std::time::Duration::from_millis(250));
    assert!(ros2.parameters, "nodes' parameters are offered by default");
    let off = AgentConfig::from_str("ros2:\n  parameters: false\n", "robot.yaml").expect("valid");
    let off = crate::AgentOptions::from_config(&off)
        .expect("options")
        .ros2
        .expect("ros2");
    assert!(!off.parameters);
    assert_eq!(
        ros2.node_name, "/fleetlink_robot1",
        "named after the robot by default"
    );
    let named = AgentConfig::from_str(
        "ros2:\n  node_name: /robot/bridge\n  distro: humble\n",
        "robot.yaml",
    )
    .expect("valid");
    let named = crate::AgentOptions::from_config(&named)
        .expect("options")
        .ros2
        .expect("ros2");
    assert_eq!(named.node_name, "/robot/bridge");
    assert_eq!(named.distro.as_deref(), Some("humble"));
}

#[test]
fn ros2_errors_name_the_field() {
    assert_err(
        "ros2: { domain_id: 300 }\n",
        "robot.yaml:1:20: ros2.domain_id: must be a DDS domain id 0..=232 (ROS 2's usable range), got 300",
    );
    assert_err(
        "ros2:\n  actions: { expose: ['/fib('] }\n",
        "robot.yaml:2:23: ros2.actions.expose[0]: is not a valid pattern (error: unclosed group): \"/fib(\"",
    );
    assert_err(
        "ros2: { node_name: 9lives }\n",
        "robot.yaml:1:20: ros2.node_name: must be a ROS 2 node name such as fleetlink_agent or /robot/fleetlink_agent (letters, digits and _, not starting with a digit), got \"9lives\"",
    );
    assert_err(
        "ros2: { distro: noetic }\n",
        "robot.yaml:1:17: ros2.distro: is not a ROS 2 distribution the agent knows, got \"noetic\" (humble, iron, jazzy, kilted, rolling, ...; leave it out to learn it from the graph)",
    );
    assert_err(
        "ros2: { subscribe: [cmd_vel] }\n",
        "robot.yaml:1:21: ros2.subscribe[0]: must start with '/', got \"cmd_vel\"",
    );
    assert_err(
        "ros2: { qos: 1 }\n",
        "robot.yaml:1:9: ros2.qos: unknown field `qos`, expected one of domain_id, publish, subscribe, read, services, actions, discovery_ms, call_timeout_ms, node_name, distro, parameters",
    );
}

/// Issue 11: the `ros2:` section, from the commented example and the reference's snippet.
#[test]
fn ros2_examples_parse_and_become_options() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let cfg = AgentConfig::load(&root.join("examples/ros2-robot.yaml"))
        .expect("examples/ros2-robot.yaml");
    let ros2 = crate::AgentOptions::from_config(&cfg)
        .expect("options")
        .ros2
        .expect("ros2 options");
    assert_eq!(ros2.domain_id, 0);
    assert!(ros2.publish.matches("/scan") && !ros2.publish.matches("/camera/raw"));
    assert!(ros2.expose.matches("/set_mode") && !ros2.expose.matches("/node/list_parameters"));
    assert!(ros2.parameters, "the example offers the nodes' parameters");
    assert!(ros2.expose_actions.matches("/navigate_to_pose"));
    assert!(ros2.offer.matches("/cloud/plan") && ros2.offer_actions.matches("/cloud/dock"));

    let doc = std::fs::read_to_string(root.join("docs/config.md")).expect("docs/config.md");
    let block = doc
        .split("```yaml\nros2:")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .expect("the ros2 block in docs/config.md");
    let cfg = AgentConfig::from_str(&format!("ros2:{block}"), "docs/config.md")
        .expect("docs ros2 example is valid");
    let ros2 = crate::AgentOptions::from_config(&cfg)
        .expect("options")
        .ros2
        .expect("ros2 options");
    assert!(ros2.publish.matches("/odom") && !ros2.publish.matches("/camera/raw"));
    assert!(ros2.offer_actions.matches("/cloud/dock"));
}

#[test]
fn issue14_a_wrong_scalar_type_names_the_value_it_got() {
    assert_err(
        "name: r1\nheartbeat_ms: fast\n",
        "robot.yaml:2:15: heartbeat_ms: expected a whole number, 0 or more (u64), got `fast`",
    );
    assert_err(
        "name: r1\nsim:\n  odometry: { rate_hz: \"quick\" }\n",
        "robot.yaml:3:24: sim.odometry.rate_hz: expected a number, got `\"quick\"`",
    );
    assert_err(
        "name: r1\nlocal_rosbridge: { enabled: maybe }\n",
        "robot.yaml:2:29: local_rosbridge.enabled: expected true or false, got `maybe`",
    );
}

#[test]
fn issue14_example_topics_section_is_applied_and_not_called_rejected() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let path = root.join("examples/agent.yaml");
    let cfg = AgentConfig::load(&path).expect("examples/agent.yaml");
    assert_eq!(cfg.topics.len(), 3, "{:?}", cfg.topics);
    let text = std::fs::read_to_string(&path).expect("examples/agent.yaml");
    for stale in ["rejected", "not supported yet", "for now"] {
        assert!(!text.contains(stale), "examples/agent.yaml says {stale:?}");
    }
}

/// Issue 36, item 6: `name:` follows the one robot name rule (`fleetlink_auth::RobotName`),
/// so a name the hub would refuse at HELLO is refused here, at its line, with the rule.
#[test]
fn issue36_name_starting_with_a_digit_or_underscore_is_refused_with_the_rule() {
    for (text, name) in [("name: 1robot\n", "1robot"), ("name: _bot\n", "_bot")] {
        assert_err(
            text,
            &format!(
                "robot.yaml:1:7: name: invalid robot name \"{name}\": must start with an ASCII \
                 letter (robot names are [A-Za-z][A-Za-z0-9_]*, at most 63 bytes)"
            ),
        );
    }
}

#[test]
fn issue36_name_longer_than_63_bytes_or_with_a_dash_is_refused_with_the_rule() {
    let long = format!("name: r{}\n", "0".repeat(63));
    let e = err(&long);
    assert_eq!(e.field(), Some("name"), "{e}");
    assert!(e.to_string().contains("longer than 63 bytes"), "{e}");
    let e = err("sim: {}\nname: robot-1\n");
    assert_eq!(
        e.position().map(|p| (p.line, p.column)),
        Some((2, 7)),
        "{e}"
    );
    assert!(
        e.to_string()
            .contains("(robot names are [A-Za-z][A-Za-z0-9_]*, at most 63 bytes)"),
        "{e}"
    );
    // The longest name is fine.
    let cfg = AgentConfig::from_str(&format!("name: r{}\n", "0".repeat(62)), "robot.yaml")
        .expect("63 bytes");
    assert_eq!(cfg.name.as_str().len(), 63);
}

#[test]
fn topics_take_always_and_an_age_limit_with_its_unit() {
    let cfg = AgentConfig::from_str(
        "name: r1\ntopics:\n  /scan: { max_age: 500ms, always: true }\n  /odom: { max_age: 2s }\n  /tf: { max_age: 250 }\n",
        "robot.yaml",
    )
    .expect("valid");
    assert_eq!(
        cfg.topics["/scan"].max_age,
        Some(std::time::Duration::from_millis(500))
    );
    assert_eq!(cfg.topics["/scan"].always, Some(true));
    assert_eq!(
        cfg.topics["/odom"].max_age,
        Some(std::time::Duration::from_secs(2))
    );
    assert_eq!(
        cfg.topics["/tf"].max_age,
        Some(std::time::Duration::from_millis(250))
    );
}

#[test]
fn a_bad_age_limit_says_how_to_write_one() {
    let text = err("name: r1\ntopics:\n  /scan: { max_age: soon }\n").to_string();
    assert!(text.starts_with("robot.yaml:3:"), "{text}");
    assert!(text.contains("500ms"), "{text}");
    let text = err("name: r1\ntopics:\n  /map: { no_drop: true, max_age: 1s }\n").to_string();
    assert!(text.contains("max_age"), "{text}");
    assert!(text.contains("no_drop"), "{text}");
}

#[test]
fn the_latest_message_cache_has_a_bound_in_megabytes() {
    assert_eq!(AgentConfig::default().latest_cache_mb, 64);
    let cfg =
        AgentConfig::from_str("name: r1\nlatest_cache_mb: 16\n", "robot.yaml").expect("valid");
    assert_eq!(cfg.latest_cache_mb, 16);
    let text = err("name: r1\nlatest_cache_mb: lots\n").to_string();
    assert!(text.contains("latest_cache_mb"), "{text}");
}

#[test]
fn a_data_budget_is_a_rate_and_or_a_daily_allowance() {
    let cfg = AgentConfig::from_str(
        "name: r1\nlink:\n  budget: { mb_per_day: 500, max_kbps: 400 }\n",
        "robot.yaml",
    )
    .expect("valid");
    let b = cfg.link.budget.as_ref().expect("a budget").to_config();
    assert_eq!(b.max_bytes_per_sec, Some(50_000.0));
    assert_eq!(b.bytes_per_day, Some(500e6));
    assert_eq!(b.protect_priority, 10.0);
    assert!(AgentConfig::default().link.budget.is_none());
    let text = err("name: r1\nlink:\n  budget: { protect_priority: 8 }\n").to_string();
    assert!(
        text.contains("link.budget") && text.contains("max_kbps"),
        "{text}"
    );
    let text = err("name: r1\nlink:\n  budget: { max_kbps: -3 }\n").to_string();
    assert!(text.starts_with("robot.yaml:3:"), "{text}");
    assert!(text.contains("max_kbps") && text.contains("> 0"), "{text}");
    let text = err("name: r1\nlink:\n  budget: { mb_a_day: 5 }\n").to_string();
    assert!(text.contains("mb_a_day"), "{text}");
}

/// Issue 38: `hub:` is one URL or a list of them, tried in order.
#[test]
fn issue38_hub_is_one_url_or_a_list() {
    let one = AgentConfig::from_str("hub: ws://a.example:8080\n", "a.yaml").expect("valid");
    assert_eq!(one.hub, ["ws://a.example:8080"]);
    let flow = AgentConfig::from_str(
        "hub: [wss://a.example:8443, wss://b.example:8443]\n",
        "a.yaml",
    )
    .expect("valid");
    assert_eq!(flow.hub, ["wss://a.example:8443", "wss://b.example:8443"]);
    let block = AgentConfig::from_str(
        "hub:\n  - ws://a.example:8080\n  - ws://b.example:8080\n  - wss://c.example:8443\n",
        "a.yaml",
    )
    .expect("valid");
    assert_eq!(
        block.hub,
        [
            "ws://a.example:8080",
            "ws://b.example:8080",
            "wss://c.example:8443"
        ]
    );
    // `tls:` with a list of wss:// hubs applies to all of them.
    AgentConfig::from_str(
        "hub: [wss://a.example:8443, wss://b.example:8443]\ntls: { ca: ca.pem }\n",
        "a.yaml",
    )
    .expect("valid");
}

/// Issue 38: a bad URL in the list is named by its index, at its line and column; an
/// empty list says what to write.
#[test]
fn issue38_a_bad_hub_in_the_list_is_named_by_its_index() {
    assert_err(
        "hub: [ws://a.example:8080, http://b.example]\n",
        "robot.yaml:1:28: hub[1]: must be a ws:// or wss:// URL such as ws://hub.example:8080, \
         got \"http://b.example\"",
    );
    assert_err(
        "name: r1\nhub:\n  - ws://a.example:8080\n  - ws://\n",
        "robot.yaml:4:5: hub[1]: is not a valid URL (empty string): \"ws://\"",
    );
    assert_err(
        "hub: [ws://a.example:8080, ws://a.example:8080]\n",
        "robot.yaml:1:28: hub[1]: \"ws://a.example:8080\" is already hub[0]; list each hub once",
    );
    let e = err("hub: []\n");
    assert_eq!(e.field(), Some("hub"), "{e}");
    assert!(
        e.to_string()
            .starts_with("robot.yaml:1:6: hub: lists no hub: "),
        "{e}"
    );
    assert!(e.to_string().contains("hub: [wss://a.example:8443"), "{e}");
    // Wrong types: the whole value, or one element.
    let e = err("hub: 8080\n");
    assert_eq!(e.field(), Some("hub"), "{e}");
    assert!(e.to_string().contains("a hub URL"), "{e}");
    let e = err("hub:\n  - ws://a.example:8080\n  - { url: ws://b }\n");
    assert_eq!(e.field(), Some("hub[1]"), "{e}");
    assert_eq!(e.position().map(|p| p.line), Some(3), "{e}");
    // `tls:` needs every hub to be wss://.
    assert_err(
        "hub: [wss://a.example:8443, ws://b.example:8080]\ntls: { ca: ca.pem }\n",
        "robot.yaml:2:6: tls: applies to every hub, so each must be wss://, but hub[1] is \
         \"ws://b.example:8080\"",
    );
}

/// Issue 38: `--hub`, given once per hub, replaces the file's list and is checked like it.
#[test]
fn issue38_hub_flags_replace_the_files_list() {
    let dir = std::env::temp_dir().join(format!("fleetlink-hub-list-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("robot.yaml");
    std::fs::write(
        &path,
        "hub: [wss://a.example:8443, wss://b.example:8443]\ntls: { ca: ca.pem }\n",
    )
    .unwrap();
    let hubs = |h: &[&str]| Overrides {
        hub: Some(h.iter().map(|u| u.to_string()).collect()),
        name: None,
        mirror: None,
    };
    let cfg = AgentConfig::load_with(Some(&path), &hubs(&["wss://c.example:8443"])).expect("one");
    assert_eq!(cfg.hub, ["wss://c.example:8443"]);
    let both = ["wss://c.example:8443", "wss://d.example:8443"];
    let cfg = AgentConfig::load_with(Some(&path), &hubs(&both)).expect("two");
    assert_eq!(cfg.hub, both);
    let cfg = AgentConfig::load_with(Some(&path), &Overrides::default()).expect("the file's");
    assert_eq!(cfg.hub, ["wss://a.example:8443", "wss://b.example:8443"]);
    // A bad second flag is the flag's fault, and the message quotes it.
    let e = AgentConfig::load_with(None, &hubs(&["ws://c.example:8080", "http://d"]))
        .expect_err("http");
    assert_eq!(e.field(), Some("--hub"), "{e}");
    assert_eq!(
        e.to_string(),
        "--hub: must be a ws:// or wss:// URL such as ws://hub.example:8080, got \"http://d\""
    );
    // The file's tls: with a plain hub among the flags is still the file's mistake.
    let e = AgentConfig::load_with(Some(&path), &hubs(&["wss://c.example:8443", "ws://d:80"]))
        .expect_err("tls");
    assert_eq!(e.field(), Some("tls"), "{e}");
    assert!(e.to_string().contains("hub[1] is \"ws://d:80\""), "{e}");
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn lists_are_short_for_the_main_key_of_a_section() {
    let list = AgentConfig::from_str(
        "ros1:\n  publish: [/chatter, '/tf.*']\n  services: [/add_two_ints]\n\
         ros2:\n  publish: [/scan]\n  services: [/set_mode]\n  actions: [/navigate]\n",
        "robot.yaml",
    )
    .unwrap();
    let long = AgentConfig::from_str(
        "ros1:\n  publish: { include: [/chatter, '/tf.*'] }\n  services: { expose: [/add_two_ints] }\n\
         ros2:\n  publish: { include: [/scan] }\n  services: { expose: [/set_mode] }\n\
         \x20 actions: { expose: [/navigate] }\n",
        "robot.yaml",
    )
    .unwrap();
    assert_eq!(list.ros1, long.ros1);
    assert_eq!(list.ros2, long.ros2);
    let opts = crate::AgentOptions::from_config(&list).expect("options");
    let ros1 = opts.ros1.expect("ros1 options");
    assert!(ros1.publish.matches("/chatter") && ros1.publish.matches("/tf_static"));
    assert!(!ros1.publish.matches("/camera/raw"));
    assert!(ros1.expose.matches("/add_two_ints"));
    // One name is a list of one; an empty key is the default.
    let one = AgentConfig::from_str("ros2:\n  publish: /scan\n  actions:\n", "robot.yaml").unwrap();
    let ros2 = one.ros2.unwrap();
    assert_eq!(ros2.publish.include, vec!["/scan"]);
    assert_eq!(ros2.actions, Ros2Actions::default());
}

#[test]
fn shape_errors_show_the_right_spelling() {
    for (text, field, example) in [
        (
            "ros1:\n  publish: 5\n",
            "ros1.publish",
            "`publish: [/chatter, /tf]`",
        ),
        (
            "ros2:\n  services: true\n",
            "ros2.services",
            "`services: [/set_mode]`",
        ),
        (
            "ros2:\n  actions: 3\n",
            "ros2.actions",
            "`actions: [/navigate]`",
        ),
        (
            "ros1: [/chatter]\n",
            "ros1",
            "`ros1: { publish: [/chatter], subscribe: [/cmd_vel] }`",
        ),
        ("sim: on\n", "sim", "`sim: { laser_scan: { rate_hz: 10 } }`"),
        ("remap: [/a]\n", "remap", "`remap: { /map: /fleet/map }`"),
        (
            "subscribe: /a\n",
            "subscribe",
            "`subscribe: [{ hub: /fleet/announcements, local: /announcements }]`",
        ),
        (
            "topics: [/scan]\n",
            "topics",
            "`topics: { /scan: { priority: 5 } }`",
        ),
        (
            "reconnect: 5\n",
            "reconnect",
            "`reconnect: { initial_ms: 500, max_ms: 30000 }`",
        ),
    ] {
        let e = err(text);
        assert_eq!(e.field(), Some(field), "{text:?}: {e}");
        assert!(e.to_string().contains(example), "{text:?}: {e}");
    }
}

// --- ROS Gateway (rosgw) JSON files

fn rosgw_err(json: &str) -> String {
    match AgentConfig::from_str(json, "rosgw.json") {
        Ok(cfg) => panic!("expected an error for {json:?}, got {cfg:?}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn rosgw_example_from_its_repository_loads() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let cfg = AgentConfig::load(&root.join("examples/rosgw/example_cfg.json"))
        .expect("rosgw's example_cfg.json");
    assert_eq!(cfg.hub, vec!["ws://172.28.165.227:9001".to_owned()]);
    assert_eq!(cfg.name.to_string(), "jackal1");
    let ros2 = cfg.ros2.expect("a rosgw file configures the ROS 2 bridge");
    assert_eq!(
        ros2.publish.include,
        vec!["/kitti/camera_color_left/image_raw"]
    );
    assert_eq!(ros2.subscribe, vec!["/cmd_vel"]);
    // cbor-raw: the link carries the raw serialization anyway, nothing to set.
    assert!(cfg.topics.is_empty(), "{:?}", cfg.topics);
    assert!(ros1_is_unset(&cfg.ros1));
}

fn ros1_is_unset(ros1: &Option<Ros1Config>) -> bool {
    ros1.is_none()
}

#[test]
fn rosgw_file_and_its_yaml_twin_are_the_same_agent() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let json = AgentConfig::load(&root.join("examples/rosgw/robot.json")).expect("robot.json");
    let yaml = AgentConfig::load(&root.join("examples/rosgw/robot.yaml")).expect("robot.yaml");
    assert_eq!(json, yaml);
    // The inactive entry (another address, /debug) is skipped, as rosgw skips it.
    let ros2 = json.ros2.as_ref().unwrap();
    assert!(!ros2.publish.include.iter().any(|p| p.contains("debug")));
}

#[test]
fn rosgw_single_entry_object_and_overrides() {
    let json = r#"{"address": "ws://gw:9001", "publish": [{"name": "/a", "messageType": "std_msgs/msg/String"}]}"#;
    let overrides = Overrides {
        hub: Some(vec!["wss://hub.example:8443".into()]),
        name: None,
        mirror: None,
    };
    let cfg = AgentConfig::parse_with(json, "rosgw.json", &overrides).unwrap();
    assert_eq!(cfg.hub, vec!["wss://hub.example:8443".to_owned()]);
    assert_eq!(cfg.name.to_string(), "robot1", "no title: the default name");
    assert_eq!(cfg.ros2.unwrap().publish.include, vec!["/a"]);
}

#[test]
fn rosgw_errors_name_the_field_and_why() {
    let at = |json: &str| rosgw_err(json);
    // Unknown key in an entry, with the known ones.
    let e = at(r#"[{"address": "ws://gw:9001", "publsh": []}]"#);
    assert!(e.starts_with("rosgw.json:1:30: [0].publsh:"), "{e}");
    assert!(e.contains("trans-publish"), "{e}");
    // Unknown key in an item, at its line.
    let e =
        at("[{\"address\": \"ws://gw:9001\",\n  \"publish\": [{\"name\": \"/a\", \"qos\": 1}]}]");
    assert!(e.starts_with("rosgw.json:2:30: [0].publish[0].qos:"), "{e}");
    assert!(
        e.contains("name, messageType, type, israw, compression"),
        "{e}"
    );
    // A missing name.
    let e = at(r#"[{"address": "ws://gw:9001", "subscribe": [{"type": "std_msgs/msg/String"}]}]"#);
    assert!(
        e.contains("[0].subscribe[0].name: `name` is missing"),
        "{e}"
    );
    // A bad ROS name.
    let e = at(r#"[{"address": "ws://gw:9001", "publish": [{"name": "/bad name"}]}]"#);
    assert!(e.contains("[0].publish[0].name:"), "{e}");
    // Two gateways: one link to one hub.
    let e = at(r#"[{"address": "ws://a:9001"}, {"address": "ws://b:9001"}]"#);
    assert!(
        e.contains("[1].address: [0].address is \"ws://a:9001\""),
        "{e}"
    );
    assert!(e.contains("one agent per hub"), "{e}");
    // Not a WebSocket URL.
    let e = at(r#"[{"address": "http://gw:9001"}]"#);
    assert!(e.contains("[0].address:"), "{e}");
    // ROS-to-REST bindings have no counterpart.
    let e = at(
        r#"[{"service_name": "detect", "service_uri": "http://x/detect/", "service_method": "POST", "request_rule": {}, "response_rule": {}}]"#,
    );
    assert!(e.contains("ROS-to-REST binding"), "{e}");
    // An unknown compression.
    let e =
        at(r#"[{"address": "ws://gw:9001", "publish": [{"name": "/a", "compression": "png"}]}]"#);
    assert!(
        e.contains("[0].publish[0].compression: compression \"png\""),
        "{e}"
    );
    // Nothing active.
    let e = at(r#"[{"address": "ws://gw:9001", "active": false}]"#);
    assert!(e.contains("no active rosgw entry"), "{e}");
    // A title that cannot be a robot name.
    let e = at(r#"[{"address": "ws://gw:9001", "title": "my robot"}]"#);
    assert!(
        e.contains("[0].title: the agent takes the title as the robot's name"),
        "{e}"
    );
}

#[test]
fn rosgw_compression_and_trans_publish() {
    let json = r#"[{"address": "ws://gw:9001", "compression": "rawzip",
        "trans-publish": [{"name": "/odom", "messageType": "nav_msgs/msg/Odometry", "remote_name": "odom_remote"}],
        "publish": [{"name": "/scan", "compression": "cbor"}]}]"#;
    let cfg = AgentConfig::from_str(json, "rosgw.json").unwrap();
    assert_eq!(
        cfg.remap.get("/odom").map(String::as_str),
        Some("/odom_remote")
    );
    // The entry's compression is every item's unless the item says otherwise.
    assert_eq!(
        cfg.topics.get("/odom").and_then(|q| q.compression),
        Some(fleetlink_qos::Compression::Zstd)
    );
    assert!(!cfg.topics.contains_key("/scan"), "cbor: nothing to set");
}

#[test]
fn yaml_is_not_mistaken_for_rosgw() {
    // JSON that is an agent config (a mapping of the agent's keys) is read as one.
    let cfg = AgentConfig::from_str(r#"{"name": "r2", "hub": "ws://h:1"}"#, "a.json").unwrap();
    assert_eq!(cfg.name.to_string(), "r2");
    assert!(cfg.ros2.is_none());
}

/// Issue 40 part 5: the `rosbridge:` section (the agent as a client of the robot's own
/// rosbridge server), from the commented example, the reference's snippet and inline.
#[test]
fn rosbridge_section_becomes_client_options() {
    let cfg = AgentConfig::from_str(
        "rosbridge:\n  url: ws://192.168.1.10:9090\n  token: abc\n  publish: { include: ['.*'], exclude: ['/rosout', /cmd_vel] }\n  subscribe: [/cmd_vel]\n  services: { expose: [/add_two_ints], offer: ['/cloud/.*'] }\n  actions: [/fibonacci]\n  discovery_ms: 2000\n",
        "robot.yaml",
    )
    .expect("valid rosbridge section");
    let r = crate::AgentOptions::from_config(&cfg)
        .expect("options")
        .rosbridge
        .expect("rosbridge options");
    assert_eq!(r.url, "ws://192.168.1.10:9090");
    assert_eq!(
        r.connect_url().expect("url"),
        "ws://192.168.1.10:9090?token=abc"
    );
    assert!(r.publish.matches("/chatter") && !r.publish.matches("/rosout"));
    assert!(r.expose.matches("/add_two_ints") && !r.expose.matches("/other"));
    assert!(r.offer.matches("/cloud/plan"));
    assert!(r.expose_actions.matches("/fibonacci"));
    assert_eq!(r.subscribe.len(), 1);
    assert_eq!(r.discovery_period, Duration::from_secs(2));
    assert_eq!(r.call_timeout, Duration::from_secs(10));
    assert_eq!(r.reconnect_initial, Duration::from_millis(250));
    assert_eq!(r.reconnect_max, Duration::from_secs(10));
    assert!(r.tls.is_none(), "ws:// needs no TLS");
    // `--check` shows the section, but not the token.
    let shown = cfg.effective_yaml();
    assert!(shown.contains("url: ws://192.168.1.10:9090"), "{shown}");
    assert!(
        shown.contains("(set, 3 characters)") && !shown.contains("abc"),
        "{shown}"
    );

    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let cfg = AgentConfig::load(&root.join("examples/rosbridge-robot.yaml"))
        .expect("examples/rosbridge-robot.yaml");
    let r = crate::AgentOptions::from_config(&cfg)
        .expect("options")
        .rosbridge
        .expect("rosbridge options");
    assert!(r.publish.matches("/odom") && r.expose.matches("/set_mode"));
    let doc = std::fs::read_to_string(root.join("docs/config.md")).expect("docs/config.md");
    let block = doc
        .split("```yaml\nrosbridge:")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .expect("the rosbridge block in docs/config.md");
    let cfg = AgentConfig::from_str(&format!("rosbridge:{block}"), "docs/config.md")
        .expect("docs rosbridge example is valid");
    assert!(cfg.rosbridge.is_some());
}

#[test]
fn rosbridge_errors_name_the_field() {
    assert_err(
        "rosbridge: { publish: [/odom] }\n",
        "robot.yaml:1:12: rosbridge.url: is required: the robot's rosbridge server, such as ws://192.168.1.10:9090",
    );
    assert_err(
        "rosbridge: { url: 'http://robot:9090' }\n",
        "robot.yaml:1:19: rosbridge.url: must be a ws:// or wss:// URL such as ws://192.168.1.10:9090, got \"http://robot:9090\"",
    );
    assert_err(
        "rosbridge:\n  url: ws://robot:9090\n  publish: { include: ['/odom('] }\n",
        "robot.yaml:3:24: rosbridge.publish.include[0]: is not a valid pattern (error: unclosed group): \"/odom(\"",
    );
    assert_err(
        "rosbridge:\n  url: ws://robot:9090\n  publish: ['.*']\n  subscribe: [/cmd_vel]\n",
        "robot.yaml:4:15: rosbridge.subscribe[0]: \"/cmd_vel\" also matches rosbridge.publish: it would be sent to the server and read back from it in a loop; exclude it there (publish.exclude)",
    );
    assert_err(
        "rosbridge:\n  url: ws://robot:9090\n  actions: { offer: [/dock] }\n",
        "robot.yaml:3:21: rosbridge.actions.offer: is not supported by the rosbridge client: fleet actions cannot be offered on a rosbridge server yet (expose the server's actions with actions.expose)",
    );
    assert_err(
        "rosbridge: { url: 'ws://robot:9090', discovery_ms: 0 }\n",
        "robot.yaml:1:52: rosbridge.discovery_ms: must be > 0, got 0",
    );
    assert_err(
        "rosbridge: { url: 'ws://robot:9090', reconnect: { initial_ms: 500, max_ms: 100 } }\n",
        "robot.yaml:1:76: rosbridge.reconnect.max_ms: must be >= rosbridge.reconnect.initial_ms (500), got 100",
    );
    assert_err(
        "rosbridge: { url: 'ws://robot:9090', password: x }\n",
        "robot.yaml:1:38: rosbridge.password: unknown field `password`, expected one of url, token, publish, subscribe, services, actions, discovery_ms, call_timeout_ms, reconnect",
    );
    assert_err(
        "rosbridge: [ws://robot:9090]\n",
        "robot.yaml:1:12: rosbridge: expected mapping start; write it as, for example, `rosbridge: { url: ws://192.168.1.10:9090, publish: [/odom] }`",
    );
}

#[test]
fn blackbox_section_becomes_ring_options_and_its_errors_name_the_field() {
    let cfg = AgentConfig::from_str(
        "blackbox: { dir: /var/lib/fleetlink/bb, max_mb: 64, topics: [/scan, '/camera/.*'] }\n",
        "robot.yaml",
    )
    .expect("valid blackbox section");
    let b = crate::AgentOptions::from_config(&cfg)
        .expect("options")
        .blackbox
        .expect("ring options");
    assert_eq!(b.dir, Path::new("/var/lib/fleetlink/bb"));
    assert_eq!(b.max_bytes, 64 << 20);
    assert_eq!(b.topics, ["/scan", "/camera/.*"]);
    assert_eq!(b.compression, fleetlink_record::Compression::Zstd);
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let doc = std::fs::read_to_string(root.join("docs/config.md")).expect("docs/config.md");
    let block = doc
        .split("```yaml\nblackbox:")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .expect("the blackbox block in docs/config.md");
    let cfg = AgentConfig::from_str(&format!("blackbox:{block}"), "docs/config.md")
        .expect("docs blackbox example is valid");
    assert_eq!(cfg.blackbox.expect("set").max_mb, 2048);

    assert_err(
        "blackbox: { topics: [/scan] }\n",
        "robot.yaml:1:11: blackbox.dir: is required: a directory on the robot for the ring, such as /var/lib/fleetlink/blackbox",
    );
    assert_err(
        "blackbox: { dir: /bb, max_mb: 4, topics: [/scan] }\n",
        "robot.yaml:1:31: blackbox.max_mb: must be at least 8 (MiB), got 4",
    );
    assert_err(
        "blackbox: { dir: /bb }\n",
        "robot.yaml:1:11: blackbox.topics: is required: the local topics to keep, such as [/scan, /odom, /camera/.*]",
    );
    assert_err(
        "blackbox: { dir: /bb, topics: ['/scan('] }\n",
        "robot.yaml:1:32: blackbox.topics[0]: is not a valid pattern (error: unclosed group): \"/scan(\"",
    );
    assert_err(
        "blackbox: { dir: /bb, topics: [/scan], compression: gzip }\n",
        "robot.yaml:1:53: blackbox.compression: unknown variant `gzip`, expected one of zstd, lz4, none",
    );
}

#[test]
fn a_mirror_lives_in_its_robots_namespace_under_a_name_of_its_own() {
    // `mirror:` alone: the mirror is named after its robot, its topics go under the robot.
    let cfg = AgentConfig::from_str("mirror: robot3\n", "m.yaml").expect("valid");
    assert_eq!(cfg.name.as_str(), "robot3_mirror");
    assert_eq!(cfg.namespace_robot().as_str(), "robot3");
    assert_eq!(cfg.hub_topic("/map"), "/robot3/map");
    // A name of its own is kept; --mirror overrides the file's.
    let cfg = AgentConfig::parse_with(
        "name: slam_cloud\nmirror: robot3\n",
        "m.yaml",
        &Overrides {
            mirror: Some(RobotName::new("robot4").unwrap()),
            ..Overrides::default()
        },
    )
    .expect("valid");
    assert_eq!(
        (cfg.name.as_str(), cfg.namespace_robot().as_str()),
        ("slam_cloud", "robot4")
    );
    // A mirror is no simulator: refused at the field, saying what to do.
    let e = AgentConfig::from_str("mirror: robot3\nsim: {}\n", "m.yaml").expect_err("sim");
    assert_eq!(e.field(), Some("sim"), "{e}");
    assert!(e.to_string().contains("remove sim: or mirror:"), "{e}");
    // Its own name may not be its robot's.
    let e = AgentConfig::from_str("name: robot3\nmirror: robot3\n", "m.yaml").expect_err("self");
    assert_eq!(e.field(), Some("name"), "{e}");
    assert!(e.to_string().contains("robot3_mirror"), "{e}");
    // And the robot name rule applies to the robot it mirrors, at its line.
    let e = AgentConfig::from_str("name: a\nmirror: 3robot\n", "m.yaml").expect_err("name");
    assert!(e.to_string().starts_with("m.yaml:2:"), "{e}");
}

#[test]
fn video_section_becomes_stream_options_and_its_errors_name_the_field() {
    let cfg = AgentConfig::from_str(
        "video:\n  /camera/image_raw: { topic: /camera/video, fps: 10, keyframe_s: 3 }\n",
        "robot.yaml",
    )
    .expect("valid video section");
    let v = crate::AgentOptions::from_config(&cfg)
        .expect("options")
        .video;
    assert_eq!(v.len(), 1);
    assert_eq!(v[0].camera.as_str(), "/camera/image_raw");
    assert_eq!(v[0].topic.as_str(), "/camera/video");
    assert_eq!(v[0].settings.fps, 10.0);
    assert_eq!(v[0].settings.bitrate_bps, 1_000_000, "the default bitrate");
    assert_eq!(v[0].min_bitrate_bps, 250_000, "a quarter of it, by default");
    assert_eq!(v[0].settings.keyframe_every, 30, "3 s at 10 fps");
    assert_eq!(v[0].library, None);
    // The docs' example is valid (but for the library, which is not on this machine).
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let doc = std::fs::read_to_string(root.join("docs/config.md")).expect("docs/config.md");
    let block = doc
        .split("```yaml\nvideo:")
        .nth(1)
        .and_then(|rest| rest.split("openh264_library").next())
        .expect("the video block in docs/config.md");
    let cfg = AgentConfig::from_str(&format!("video:{block}"), "docs/config.md")
        .expect("docs video example is valid");
    assert_eq!(cfg.video["/camera/image_raw"].bitrate_kbps, 1000);

    for (text, want) in [
        (
            "video: { /cam: { topic: /cam } }\n",
            "video[\"/cam\"].topic: is the camera topic itself",
        ),
        (
            "video: { /a: { topic: /v }, /b: { topic: /v } }\n",
            "video[\"/b\"].topic: /v is already the video of /a",
        ),
        (
            "video: { /a: { topic: /b }, /b: { topic: /c } }\n",
            "video[\"/a\"].topic: /b is a camera topic of video: too",
        ),
        (
            "video: { /a: { topic: /v, fps: 0 } }\n",
            "video[\"/a\"].fps: must be 1 to 60 (frames a second), got 0",
        ),
        (
            "video: { /a: { topic: /v, bitrate_kbps: 10 } }\n",
            "video[\"/a\"].bitrate_kbps: must be 50 to 50000",
        ),
        (
            "video: { /a: { topic: /v, bitrate_kbps: 500, min_bitrate_kbps: 600 } }\n",
            "video[\"/a\"].min_bitrate_kbps: must be 50 to bitrate_kbps (500), got 600",
        ),
        (
            "video: { /a: { topic: /v, keyframe_s: 0 } }\n",
            "video[\"/a\"].keyframe_s: must be 0.2 to 60",
        ),
        (
            "video: { a: { topic: /v } }\n",
            "video.a: camera topic must start with '/'",
        ),
        ("video: { /a: { fps: 5 } }\n", "missing field `topic`"),
        (
            "video: { /a: { topic: /v, crf: 5 } }\n",
            "unknown field `crf`",
        ),
        (
            "openh264_library: /nonexistent/libopenh264.so\n",
            "openh264_library: /nonexistent/libopenh264.so is not a file",
        ),
    ] {
        let e = err(text).to_string();
        assert!(e.contains(want), "for {text:?}: {e}");
    }
}
