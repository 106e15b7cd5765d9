//! What the audit log records about traffic: commands sent to a robot's inputs, with who
//! sent them and their size; never the robot's own output (which would flood the log).

use std::time::Duration;

use fleetlink_auth::audit::{AuditAction, AuditQuery};
use serde_json::json;

use crate::util::*;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn commands_to_a_robot_are_audited_and_its_own_output_is_not() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "rover").await;
    let mut local = Rosbridge::connect(&agent.local_url()).await;
    local
        .send(json!({"op": "subscribe", "topic": "/cmd_vel"}))
        .await;
    let mut scan = LocalPublisher::new(&agent.router, "/scan", "sensor_msgs/msg/LaserScan");
    let mut op = Rosbridge::connect(&hub.ws_url()).await;
    op.send(
        json!({"op": "advertise", "topic": "/rover/cmd_vel", "type": "geometry_msgs/msg/Twist"}),
    )
    .await;
    within("a command at the robot", async {
        loop {
            scan.publish_json(&json!({"ranges": [1.0, 2.0]}));
            op.send(
                json!({"op": "publish", "topic": "/rover/cmd_vel", "msg": {"linear": {"x": 0.2}}}),
            )
            .await;
            if let Ok(Some(v)) =
                tokio::time::timeout(Duration::from_millis(25), local.try_recv()).await
                && v["op"] == "publish"
            {
                return;
            }
        }
    })
    .await;
    let sec = &hub.state.security;
    sec.audit.flush();
    let page = sec
        .store
        .query_audit(&AuditQuery {
            action: Some(AuditAction::Publish),
            limit: 1000,
            ..Default::default()
        })
        .unwrap();
    let cmds: Vec<_> = page
        .records
        .iter()
        .filter(|r| r.record.name == "/rover/cmd_vel")
        .collect();
    assert!(!cmds.is_empty(), "no command recorded: {:?}", page.records);
    assert!(cmds.iter().all(|r| r.record.principal == "user:tester"
        && r.record.allowed
        && r.record.size.unwrap_or(0) > 0));
    assert!(
        page.records.iter().all(|r| r.record.name != "/rover/scan"),
        "the robot's own output was audited"
    );
    agent.shutdown().await;
    hub.shutdown().await;
}

/// `GET path` with a bearer token over HTTP/1.0: the body as text.
async fn get_text(addr: std::net::SocketAddr, path: &str, token: &str) -> String {
    use tokio::io::{AsyncReadExt, AsyncWriteExt};
    let mut s = within("connect", tokio::net::TcpStream::connect(addr))
        .await
        .unwrap();
    s.write_all(
        format!("GET {path} HTTP/1.0\r\nHost: {addr}\r\nAuthorization: Bearer {token}\r\n\r\n")
            .as_bytes(),
    )
    .await
    .unwrap();
    let mut out = String::new();
    within("response", s.read_to_string(&mut out))
        .await
        .unwrap();
    out
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue14_audit_counters_are_exported_as_metrics() {
    let hub = start_hub().await;
    // A refused credential is audited (auth_failure).
    let refused = get_text(hub.addr, "/metrics", "flk_op_not-a-real-token").await;
    assert!(
        refused.starts_with("HTTP/1.0 401") || refused.starts_with("HTTP/1.1 401"),
        "{refused}"
    );
    hub.state.security.audit.flush();
    let metrics = get_text(hub.addr, "/metrics", &hub.operator_token).await;
    let value = |line: &str| -> Option<u64> {
        metrics
            .lines()
            .find_map(|l| l.strip_prefix(line)?.trim().parse().ok())
    };
    let written = value("fleetlink_audit_records_written_total ");
    assert!(
        written >= Some(1),
        "no written audit records in:\n{metrics}"
    );
    for reason in ["queue_full", "database_error"] {
        let line = format!("fleetlink_audit_records_lost_total{{reason=\"{reason}\"}} ");
        assert_eq!(value(&line), Some(0), "{line} in:\n{metrics}");
    }
    hub.shutdown().await;
}
