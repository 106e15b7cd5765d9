//! The binary as a user runs it: the demo fleet comes up and stops cleanly on SIGTERM;
//! a bad agent configuration is reported with file, line and field.

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};
use std::time::Duration;

use serde_json::Value;
use tokio::io::{AsyncReadExt, AsyncWriteExt};

use crate::util::*;

const BIN: &str = env!("CARGO_BIN_EXE_fleetlink");

/// `GET path` over plain HTTP/1.0; returns the body.
async fn http_get(addr: &str, path: &str) -> String {
    let mut s = tokio::net::TcpStream::connect(addr).await.expect("connect");
    s.write_all(format!("GET {path} HTTP/1.0\r\nHost: {addr}\r\n\r\n").as_bytes())
        .await
        .unwrap();
    let mut out = String::new();
    s.read_to_string(&mut out).await.unwrap();
    out.split_once("\r\n\r\n")
        .map(|(_, b)| b.to_owned())
        .unwrap_or_default()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn demo_fleet_comes_up_and_stops_on_sigterm() {
    let dir = temp_dir("demo");
    let mut child = fleetlink_in(&dir)
        .args(["demo", "--listen", "127.0.0.1:0", "--data-dir"])
        .arg(&dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("demo starts");
    let stdout = child.stdout.take().unwrap();
    let (tx, mut rx) = tokio::sync::mpsc::unbounded_channel();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            let _ = tx.send(line);
        }
    });
    let addr = within("the demo to print its URL", async {
        loop {
            let line = rx
                .recv()
                .await
                .expect("demo printed its URL before exiting");
            if let Some(rest) = line.trim().strip_prefix("open http://") {
                return rest
                    .trim_end_matches(|c| c != '/')
                    .trim_end_matches('/')
                    .split('/')
                    .next()
                    .unwrap()
                    .to_owned();
            }
        }
    })
    .await;

    // Three robots online, each with its simulated topics listed (idle: nobody watches).
    within("three robots with their topics", async {
        loop {
            let robots: Value = serde_json::from_str(&http_get(&addr, "/api/v1/robots").await)
                .unwrap_or(Value::Null);
            let topics: Value = serde_json::from_str(&http_get(&addr, "/api/v1/topics").await)
                .unwrap_or(Value::Null);
            let online = robots["robots"]
                .as_array()
                .map_or(0, |r| r.iter().filter(|r| r["online"] == true).count());
            let flowing = topics["topics"].as_array().map_or(0, |t| {
                t.iter()
                    .filter(|t| {
                        t["name"].as_str().is_some_and(|n| n.ends_with("/scan"))
                            && t["state"] == "idle"
                            && t["messages"].as_u64() == Some(0)
                    })
                    .count()
            });
            if online == 3 && flowing == 3 {
                return;
            }
            tokio::time::sleep(Duration::from_millis(100)).await;
        }
    })
    .await;
    // A viewer's subscription makes one robot's scan flow, and only that topic.
    let mut viewer = Rosbridge::connect(&format!("ws://{addr}")).await;
    viewer
        .send(serde_json::json!({"op": "subscribe", "topic": "/robot1/scan", "id": "v"}))
        .await;
    let m = within("a scan", viewer.recv_op("publish")).await;
    assert_eq!(m["topic"], "/robot1/scan");
    let topics: Value =
        serde_json::from_str(&http_get(&addr, "/api/v1/topics").await).expect("JSON");
    for t in topics["topics"].as_array().expect("topics") {
        let name = t["name"].as_str().unwrap_or_default();
        if name.ends_with("/scan") {
            let want = if name == "/robot1/scan" {
                "flowing"
            } else {
                "idle"
            };
            assert_eq!(t["state"], want, "{name}");
        }
    }
    let page = http_get(&addr, "/").await;
    // The dashboard is served at /.
    assert!(
        page.contains("<title>fleetlink</title>") && page.contains("app.js"),
        "{page}"
    );
    let metrics = http_get(&addr, "/metrics").await;
    assert!(
        metrics.contains("fleetlink_topic_messages_total{topic=\"/robot1/scan\"}"),
        "{metrics}"
    );

    let status = Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success());
    let exit = within("the demo to stop", async {
        loop {
            if let Some(s) = child.try_wait().unwrap() {
                return s;
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await;
    assert!(exit.success(), "demo exited with {exit}");
}

#[test]
fn agent_config_error_names_file_line_and_field() {
    let dir = temp_dir("badcfg");
    let path = dir.join("robot.yaml");
    std::fs::write(
        &path,
        "name: robot1\nsim:\n  point_cloud:\n    rate_hz: 0\n",
    )
    .unwrap();
    let out = fleetlink_in(&dir)
        .args(["agent", "--config"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("robot.yaml:4:"), "{err}");
    assert!(err.contains("sim.point_cloud.rate_hz"), "{err}");
}

#[test]
fn issue14_admin_refuses_a_missing_database_for_reading_commands() {
    let dir = temp_dir("admin-typo");
    let typo = dir.join("fleetlink-dta");
    for args in [
        &["token", "list"][..],
        &["token", "revoke", "1"],
        &["rules", "list"],
        &["users", "list"],
        &["audit", "--limit", "5"],
    ] {
        let out = fleetlink_in(&dir)
            .arg("admin")
            .arg("--data-dir")
            .arg(&typo)
            .args(args)
            .output()
            .unwrap();
        assert!(
            !out.status.success(),
            "admin {args:?} on a missing database succeeded"
        );
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("no hub database at"), "{args:?}: {err}");
        assert!(
            err.contains("fleetlink-dta"),
            "{args:?} names the path: {err}"
        );
        assert!(!typo.exists(), "admin {args:?} created {}", typo.display());
    }
    // Minting the first token creates the database, and says so.
    let out = fleetlink_in(&dir)
        .arg("admin")
        .arg("--data-dir")
        .arg(&typo)
        .args(["token", "robot", "r1"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains("created a new hub database"));
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("flk_"));
}

/// Starts the demo on `dir` and returns the operator token it prints; then stops it.
async fn demo_operator_token(dir: &std::path::Path) -> String {
    let mut child = tokio::process::Command::from(fleetlink_in(dir))
        .args([
            "demo",
            "--robots",
            "1",
            "--listen",
            "127.0.0.1:0",
            "--data-dir",
        ])
        .arg(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .kill_on_drop(true)
        .spawn()
        .expect("demo starts");
    use tokio::io::AsyncBufReadExt;
    let mut lines = tokio::io::BufReader::new(child.stdout.take().unwrap()).lines();
    let token = within("the demo to print its operator token", async {
        while let Some(l) = lines.next_line().await.unwrap() {
            if let Some((_, t)) = l.split_once("valid 7 days): ") {
                return t.trim().to_owned();
            }
        }
        panic!("the demo exited without printing a token");
    })
    .await;
    let _ = child.kill().await;
    let _ = child.wait().await;
    token
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue14_demo_reuses_its_tokens_and_they_expire() {
    let dir = temp_dir("demo-tokens");
    let first = demo_operator_token(&dir).await;
    let second = demo_operator_token(&dir).await;
    assert_eq!(
        first, second,
        "a second demo run minted another operator token"
    );
    let out = fleetlink_in(&dir)
        .arg("admin")
        .arg("--data-dir")
        .arg(&dir)
        .args(["token", "list"])
        .output()
        .unwrap();
    let list = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        list.lines().count(),
        2,
        "one operator and one robot token:\n{list}"
    );
}

/// Issue 14, finding 2: a user's error is one line naming the problem — no backtrace even
/// with RUST_BACKTRACE set, no `Debug` dump, no cause repeated ("X: X").
#[test]
fn issue14_user_errors_are_one_line_without_backtrace_or_repeated_causes() {
    let dir = temp_dir("one-line-errors");
    let missing = dir.join("robot.yaml");
    let out = fleetlink_in(&dir)
        .args(["agent", "--config"])
        .arg(&missing)
        .env("RUST_BACKTRACE", "full")
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = err.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 1, "one line, got: {err}");
    let line = lines[0];
    assert!(line.starts_with("error: "), "{line}");
    assert!(line.contains("robot.yaml"), "names the file: {line}");
    assert!(
        !line.contains("backtrace") && !line.contains("Os {"),
        "{line}"
    );
    // Every cause once: no segment of the message repeats right after itself.
    let parts: Vec<&str> = line.split(": ").collect();
    for pair in parts.windows(2) {
        assert_ne!(pair[0], pair[1], "a repeated cause in {line}");
    }
    let out = fleetlink_in(&dir)
        .args(["agent", "--hub", "http://x"])
        .env("RUST_BACKTRACE", "1")
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(err.contains("--hub") && err.contains("ws://"), "{err}");
}

/// Issue 14, finding 2: output piped into `head` that stops reading is not an error (no
/// "Broken pipe" message, exit status 0).
#[test]
fn issue14_output_piped_into_head_ends_quietly() {
    for args in [&["msg", "list"][..], &["msg", "list", "--full-texts"]] {
        let mut child = Command::new(BIN)
            .args(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let mut first = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut first)
            .unwrap();
        assert!(!first.is_empty(), "{args:?} printed nothing");
        // The reader is dropped here: the pipe closes with most of the output unread.
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{args:?}: {:?} {err}", out.status);
        assert!(err.is_empty(), "{args:?} wrote to stderr: {err}");
    }
}

/// Issue 36, item 6: a robot name breaking the one rule (`fleetlink_auth::RobotName`) is
/// refused where it is typed, with the rule, before anything is written: no database
/// created, no token minted, no certificate issued, no agent started.
#[test]
fn issue36_cli_refuses_a_robot_name_breaking_the_rule() {
    let dir = temp_dir("bad-robot-name");
    let data = dir.join("hub-data");
    let certs = dir.join("tls");
    let rule = "(robot names are [A-Za-z][A-Za-z0-9_]*, at most 63 bytes)";
    let runs: [(Vec<std::ffi::OsString>, &str); 3] = [
        (
            vec![
                "admin".into(),
                "--data-dir".into(),
                data.clone().into(),
                "token".into(),
                "robot".into(),
                "1robot".into(),
            ],
            "1robot",
        ),
        (
            vec![
                "admin".into(),
                "cert".into(),
                "--dir".into(),
                certs.clone().into(),
                "robot".into(),
                "_bot".into(),
            ],
            "_bot",
        ),
        (
            vec!["agent".into(), "--name".into(), "1robot".into()],
            "1robot",
        ),
    ];
    for (args, name) in runs {
        let out = fleetlink_in(&dir).args(&args).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?} succeeded: {err}");
        assert!(
            err.contains(&format!(
                "invalid robot name \"{name}\": must start with an ASCII letter {rule}"
            )),
            "{args:?}: {err}"
        );
    }
    assert!(!data.exists(), "a database was created for a refused name");
    assert!(!certs.exists(), "a certificate directory was created");
}

/// `fleetlink agent --check` validates without connecting (the hub in the file does not
/// exist), prints the effective configuration with defaults filled in and the token
/// hidden, and exits 0; a bad file exits 1 naming the problem and its right spelling.
#[test]
fn agent_check_validates_and_prints_the_effective_configuration() {
    let dir = temp_dir("agentcheck");
    let good = dir.join("robot.yaml");
    std::fs::write(
        &good,
        "hub: ws://127.0.0.1:1/\nname: robot1\ntoken: s3cret-token\n\
         ros1:\n  publish: [/chatter]\n",
    )
    .unwrap();
    let out = fleetlink_in(&dir)
        .args(["agent", "--check", "--config"])
        .arg(&good)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("the configuration is valid"), "{text}");
    // Defaults filled in, the shorthand expanded, the token not shown.
    assert!(text.contains("heartbeat_ms: 1000"), "{text}");
    assert!(
        text.contains("include:\n") && text.contains("- /chatter"),
        "{text}"
    );
    assert!(text.contains("discovery_ms: 1000"), "{text}");
    assert!(!text.contains("s3cret-token"), "{text}");
    assert!(text.contains("--config: "), "{text}");

    let bad = dir.join("bad.yaml");
    std::fs::write(&bad, "name: robot1\nros2:\n  actions: 3\n").unwrap();
    let out = fleetlink_in(&dir)
        .args(["agent", "--check", "--config"])
        .arg(&bad)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("bad.yaml:3:"), "{text}");
    assert!(text.contains("`actions: [/navigate]`"), "{text}");
    assert!(!text.contains("the configuration is valid"), "{text}");
}

/// Issue 57: `--check` prints the configuration that will run — the file with the changes
/// kept from an earlier run (in the default place, the state directory) merged in — each
/// field marked with where it comes from, and says which kept change it refuses and why.
#[test]
fn issue57_agent_check_prints_what_will_run_with_each_fields_origin() {
    let dir = temp_dir("agentcheck-kept");
    let file = dir.join("robot.yaml");
    std::fs::write(
        &file,
        "hub: ws://127.0.0.1:1/\nname: robot1\ntopics:\n  /probe/reliable: { no_drop: true }\n  \
         /pose: { priority: 8 }\n",
    )
    .unwrap();
    let kept = dir.join("state/fleetlink/robot1/runtime.json");
    std::fs::create_dir_all(kept.parent().unwrap()).unwrap();
    std::fs::write(
        &kept,
        r#"{"topics": {"/pose": {"rate_limit_hz": 0.5}, "/probe/reliable": {"no_drop": false}}}"#,
    )
    .unwrap();
    let out = fleetlink_in(&dir)
        .args(["agent", "--check", "--config"])
        .arg(&file)
        .env("ROS_DOMAIN_ID", "7")
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let line = |needle: &str| {
        text.lines()
            .find(|l| l.contains(needle))
            .unwrap_or_else(|| panic!("no {needle:?} in\n{text}"))
            .to_owned()
    };
    assert!(
        line("rate_limit_hz: 0.5").contains("# kept change"),
        "{text}"
    );
    assert!(line("priority: 8").ends_with("# file"), "{text}");
    assert!(line("no_drop: true").ends_with("# file"), "{text}");
    assert!(line("heartbeat_ms: 1000").ends_with("# default"), "{text}");
    assert!(
        line("runtime_file:").ends_with("# environment: XDG_STATE_HOME"),
        "{text}"
    );
    let refused = line("note: the kept change topics[\"/probe/reliable\"].no_drop");
    assert!(
        refused.contains("YAML file") && refused.contains("restart"),
        "{refused}"
    );
    assert!(
        line("do not record which configuration").contains("runtime.json"),
        "{text}"
    );
}

/// A ROS Gateway JSON file is checked like a YAML file: `--check` prints the agent it
/// describes (the token from `--token-file`, hidden), and a bad entry is named by its
/// field and line; an empty token file is refused with what to put in it.
#[test]
fn agent_check_takes_a_rosgw_file_and_a_token_file() {
    let dir = temp_dir("rosgwcheck");
    let file = dir.join("rosgw.json");
    std::fs::write(
        &file,
        r#"[{"title": "jackal1", "address": "ws://127.0.0.1:1/",
  "publish": [{"name": "/scan", "messageType": "sensor_msgs/msg/LaserScan"}],
  "expose-service": [{"service": "add_two_ints"}]}]"#,
    )
    .unwrap();
    let token = dir.join("robot.token");
    std::fs::write(&token, "  s3cret-token\n").unwrap();
    let out = fleetlink_in(&dir)
        .args(["agent", "--check", "--config"])
        .arg(&file)
        .arg("--token-file")
        .arg(&token)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("name: jackal1"), "{text}");
    assert!(
        text.contains("- /scan") && text.contains("- /add_two_ints"),
        "{text}"
    );
    assert!(text.contains("token: (set, 12 characters)"), "{text}");
    assert!(!text.contains("s3cret-token"), "{text}");

    std::fs::write(&token, "\n").unwrap();
    let out = fleetlink_in(&dir)
        .args(["agent", "--check", "--config"])
        .arg(&file)
        .arg("--token-file")
        .arg(&token)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("the file is empty"), "{text}");

    std::fs::write(
        &file,
        "[{\"address\": \"ws://127.0.0.1:1/\",\n  \"publish\": [{\"name\": \"/scan\", \"rate\": 5}]}]",
    )
    .unwrap();
    let out = fleetlink_in(&dir)
        .args(["agent", "--check", "--config"])
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("rosgw.json:2:"), "{text}");
    assert!(text.contains("[0].publish[0].rate"), "{text}");
}

/// `fleetlink hub --check` reads what the hub would read (here a missing TLS key and a
/// bad database URL) without binding its port, and lists every option with its value.
#[test]
fn hub_check_finds_bad_files_without_starting() {
    let dir = temp_dir("hubcheck");
    // Something already listens on the port: a check must not need it.
    let busy = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let port = busy.local_addr().unwrap().to_string();
    let out = fleetlink_in(&dir)
        .args(["hub", "--check", "--listen", &port, "--data-dir"])
        .arg(dir.join("data"))
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        text.contains(&format!("--listen: {port}  # given")),
        "{text}"
    );
    assert!(text.contains("--heartbeat-ms: 1000  # default"), "{text}");
    assert!(!dir.join("data").exists(), "a check creates nothing");

    let out = fleetlink_in(&dir)
        .args([
            "hub",
            "--check",
            "--database",
            "mysql://u:pw@db/x",
            "--tls-cert",
        ])
        .arg(dir.join("none.pem"))
        .arg("--tls-key")
        .arg(dir.join("none.key"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("none.pem"), "{text}");
    assert!(text.contains("postgres://"), "{text}");
    assert!(
        !text.contains(":pw@"),
        "the password is not printed: {text}"
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("2 problems"), "{err}");
}
