//! `fleetlink bench relay` against an in-process hub: the binary runs as a user would run
//! it and its `--json` summary is checked for what the bench promises (every message
//! stamped in the window reaches every subscriber, nothing is lost at a modest rate,
//! latency percentiles are filled in). No assertion depends on how fast the machine is.

use std::time::Duration;

use serde_json::Value;

use crate::util::*;

/// Runs `fleetlink bench <args> --json` as a user would and gives its one-line summary.
async fn bench_json(args: &[&str]) -> Value {
    let out = tokio::time::timeout(
        Duration::from_secs(60),
        tokio::process::Command::new(env!("CARGO_BIN_EXE_fleetlink"))
            .arg("bench")
            .args(args)
            .arg("--json")
            .kill_on_drop(true)
            .output(),
    )
    .await
    .unwrap_or_else(|_| panic!("fleetlink bench {} finishes", args[0]))
    .expect("the binary runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "bench failed: {stderr}");
    let stdout = String::from_utf8(out.stdout).expect("UTF-8 output");
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines.len(), 1, "one JSON object on stdout, got {stdout:?}");
    serde_json::from_str(lines[0]).expect("valid JSON")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bench_relay_json_summary_counts_every_delivery() {
    let hub = start_hub().await;
    let url = hub.agent_url();
    let s = bench_json(&[
        "relay",
        "--hub",
        &url,
        "--token",
        &hub.operator_token,
        "--publishers",
        "1",
        "--subscribers",
        "2",
        "--size",
        "64",
        "--rate",
        "1000",
        "--duration",
        "1",
        "--warmup",
        "0.2",
        // A queue that holds the whole run: a stalled test machine may delay messages
        // but must not make the hub drop them.
        "--queue-length",
        "100000",
    ])
    .await;

    assert_eq!(s["publishers"], 1);
    assert_eq!(s["subscribers"], 2);
    assert_eq!(s["size"], 64);
    assert_eq!(s["rate"], 1000.0);
    assert_eq!(s["duration_s"], 1.0);
    let sent = s["sent"].as_u64().expect("sent");
    let delivered = s["delivered"].as_u64().expect("delivered");
    assert!(sent > 0, "something was sent in the window: {s}");
    assert_eq!(
        delivered,
        2 * sent,
        "each subscriber got every message: {s}"
    );
    assert_eq!(s["drops"], 0, "{s}");
    assert!(s["delivered_per_s"].as_f64().expect("delivered_per_s") > 0.0);
    assert!(s["mb_per_s"].as_f64().expect("mb_per_s") > 0.0);
    let lat = &s["latency_us"];
    let q = |k: &str| {
        lat[k]
            .as_f64()
            .unwrap_or_else(|| panic!("latency_us.{k}: {s}"))
    };
    assert!(q("p50") > 0.0, "{s}");
    assert!(q("p50") <= q("p99") && q("p99") <= q("p999") && q("p999") <= q("max"));

    // An operator-token link speaking for bench_pub_0 publishes its own output: nothing
    // of it is a command to a robot, so none of it is in the audit log.
    let sec = &hub.state.security;
    sec.audit.flush();
    let q = fleetlink_auth::audit::AuditQuery {
        action: Some(fleetlink_auth::audit::AuditAction::Publish),
        ..Default::default()
    };
    let audited = sec.store.query_audit(&q).unwrap().records;
    assert!(
        audited.is_empty(),
        "bench traffic was audited: {} records",
        audited.len()
    );
    hub.shutdown().await;
}

#[tokio::test]
async fn bench_relay_reports_an_unreachable_hub() {
    // A port that was just free: bind on port 0, note the address, close it.
    let addr = std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("bind port 0");
    let url = format!("ws://{addr}");
    let out = tokio::process::Command::new(env!("CARGO_BIN_EXE_fleetlink"))
        .args(["bench", "relay", "--hub", &url, "--duration", "1"])
        .output()
        .await
        .expect("the binary runs");
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("cannot connect"), "{stderr}");
}

/// `bench copy-floor` (the floor rows of scripts/bench-ros1.sh and bench-ros2.sh): the
/// messages go through in the window and both measured threads are reported. (The CPU
/// figures themselves are clock ticks and may be zero over one second.)
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bench_copy_floor_reports_the_relay_and_the_sender() {
    let s = bench_json(&[
        "copy-floor",
        "--size",
        "200000",
        "--rate",
        "20",
        "--seconds",
        "1",
    ])
    .await;
    assert_eq!(s["size"], 200000, "{s}");
    assert!(s["messages"].as_u64().expect("messages") > 0, "{s}");
    for field in ["relay_cpu_percent", "sender_cpu_percent"] {
        let v = s[field].as_f64().unwrap_or(-1.0);
        assert!(
            (0.0..=400.0).contains(&v),
            "{field} missing or out of range: {s}"
        );
    }
}

/// The floor relay serves rosbridge's publish and subscribe well enough for the delivery
/// bench to measure it, on both WebSocket layers: every message reaches the subscriber,
/// and the relay's CPU is read.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bench_ws_floor_relays_the_delivery_bench_and_its_cpu_is_measured() {
    use tokio::io::AsyncBufReadExt;
    for layer in ["fleetlink", "tungstenite"] {
        let mut floor = tokio::process::Command::new(env!("CARGO_BIN_EXE_fleetlink"))
            .args([
                "bench",
                "ws-floor",
                "--listen",
                "127.0.0.1:0",
                "--websocket",
                layer,
            ])
            .stdout(std::process::Stdio::piped())
            .kill_on_drop(true)
            .spawn()
            .expect("the binary runs");
        let pid = floor.id().expect("running").to_string();
        let mut lines = tokio::io::BufReader::new(floor.stdout.take().expect("piped")).lines();
        let line = tokio::time::timeout(Duration::from_secs(10), lines.next_line())
            .await
            .expect("the floor relay says where it listens")
            .expect("readable")
            .expect("a line");
        let addr = line
            .strip_prefix("listening on ")
            .unwrap_or_else(|| panic!("unexpected first line {line:?}"));
        let s = bench_json(&[
            "delivery",
            "--protocol",
            "rosbridge-json",
            "--server",
            &format!("ws://{addr}"),
            "--server-pid",
            &pid,
            "--rate",
            "2000",
            "--duration",
            "1",
            "--warmup",
            "1",
        ])
        .await;
        let sent = s["sent_per_sec"].as_f64().expect("sent");
        let delivered = s["delivered_per_sec"].as_f64().expect("delivered");
        assert!(sent > 500.0, "{layer}: {s}");
        // Nothing is dropped on the way: what arrives in the window is what was sent in
        // it, give or take the messages in flight at its edges.
        assert!((delivered - sent).abs() <= sent * 0.1, "{layer}: {s}");
        let us = s["server_cpu_us_per_delivery"].as_f64().unwrap_or(-1.0);
        assert!(us >= 0.0, "{layer}: no CPU figure for the floor relay: {s}");
    }
}

/// `fleetlink bench viewer`: a robot's point cloud reaches every viewer over both
/// protocols, counted by its header stamp, with latency filled in.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bench_viewer_counts_every_cloud_over_foxglove_and_rosbridge_cbor() {
    let hub = start_hub().await;
    let url = hub.agent_url();
    let robot_token = hub.robot_token("bench_cloud");
    for protocol in ["foxglove", "rosbridge-cbor"] {
        let s = bench_json(&[
            "viewer",
            "--protocol",
            protocol,
            "--hub",
            &url,
            "--token",
            &hub.operator_token,
            "--robot-token",
            &robot_token,
            "--size",
            "65536",
            "--rate",
            "20",
            "--viewers",
            "2",
            "--duration",
            "1",
            "--warmup",
            "0.3",
        ])
        .await;
        let sent = s["sent"].as_u64().unwrap();
        assert!(sent >= 5, "{protocol}: {s}");
        assert_eq!(s["delivered"].as_u64(), Some(sent * 2), "{protocol}: {s}");
        assert_eq!(s["delivery_ratio"].as_f64(), Some(1.0), "{protocol}: {s}");
        assert!(
            s["latency_ms"]["p50"].as_f64().unwrap() > 0.0,
            "{protocol}: {s}"
        );
        assert!(s["hub_cpu_percent"].is_null(), "no --hub-pid: {s}");
    }
    hub.shutdown().await;
}
