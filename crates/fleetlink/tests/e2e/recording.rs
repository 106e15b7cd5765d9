//! `/api/v1/recordings` on a running hub: who may record, what a recording holds under
//! the access rules, refusals that name the problem, downloads, the audit log, and a
//! recording finished cleanly when the hub stops.

use std::time::Duration;

use fleetlink_auth::audit::{AuditAction, AuditQuery};
use fleetlink_record::read::{Item, McapReader};
use serde_json::json;

use crate::util::*;

/// A GET whose body is returned as bytes: `(status, body)`.
async fn http_bytes(addr: std::net::SocketAddr, path: &str, token: &str) -> (u16, Vec<u8>) {
    use tokio::io::{AsyncReadExt, AsyncWriteExt};
    let mut tcp = tokio::net::TcpStream::connect(addr).await.expect("connect");
    let req = format!(
        "GET {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\nAuthorization: Bearer {token}\r\n\r\n"
    );
    tcp.write_all(req.as_bytes()).await.expect("write");
    let mut raw = Vec::new();
    within("download", tcp.read_to_end(&mut raw))
        .await
        .expect("read");
    let split = raw.windows(4).position(|w| w == b"\r\n\r\n").expect("head");
    let head = String::from_utf8_lossy(&raw[..split]).to_string();
    let status = head.split_whitespace().nth(1).unwrap().parse().unwrap();
    assert!(
        !head
            .to_ascii_lowercase()
            .contains("transfer-encoding: chunked"),
        "a download has a length: {head}"
    );
    (status, raw[split + 4..].to_vec())
}

const RULES: &str = r#"
rules:
  - subject: {user: recorder}
    names: "/recordings"
    ops: [admin]
  - subject: {user: recorder}
    names: "/rec/.*"
    ops: [subscribe]
"#;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_recording_holds_what_its_starter_may_read_and_is_refused_with_reasons() {
    let hub = start_hub().await;
    hub.set_rules(RULES);
    let now = fleetlink_auth::UnixTime::now();
    let mint = |user: &str| {
        hub.state
            .security
            .store
            .mint_operator_token(
                &fleetlink_auth::UserName::new(user).unwrap(),
                &[],
                None,
                now,
            )
            .unwrap()
            .expose()
            .to_owned()
    };
    let recorder = mint("recorder");
    let nobody = mint("nobody");
    let admin = hub.operator_token.clone();

    // Refusals: no credential, no right, a bad request.
    let (s, _) = http_json(hub.addr, "GET", "/api/v1/recordings", None, None).await;
    assert_eq!(s, 401);
    let (s, v) = http_json(
        hub.addr,
        "POST",
        "/api/v1/recordings",
        Some(&nobody),
        Some(&json!({"topics": ["/rec/.*"]})),
    )
    .await;
    assert_eq!(s, 403, "{v}");
    for (body, field) in [
        (json!({"topics": []}), "topics:"),
        (json!({"topics": ["/rec/(("]}), "topics:"),
        (
            json!({"topics": ["/a"], "split_size_bytes": 5}),
            "split_size_bytes:",
        ),
        (
            json!({"topics": ["/a"], "splits": 5}),
            "unknown field `splits`",
        ),
        (json!({"topics": ["/a"], "name": "../x"}), "name:"),
    ] {
        let (s, v) = http_json(
            hub.addr,
            "POST",
            "/api/v1/recordings",
            Some(&admin),
            Some(&body),
        )
        .await;
        assert_eq!(s, 400, "{body} → {v}");
        assert!(v["error"].as_str().unwrap().contains(field), "{body} → {v}");
    }
    let (s, v) = http_json(
        hub.addr,
        "GET",
        "/api/v1/recordings/rec-none",
        Some(&admin),
        None,
    )
    .await;
    assert_eq!(
        (s, v["error"].as_str()),
        (404, Some("no recording rec-none"))
    );

    // The recorder may record, but only sees /rec/*: /secret is refused, not written.
    let mut open = hub_publisher(&hub, "/rec/a", "std_msgs/msg/String");
    let mut secret = hub_publisher(&hub, "/secret/b", "std_msgs/msg/String");
    let (s, rec) = http_json(
        hub.addr,
        "POST",
        "/api/v1/recordings",
        Some(&recorder),
        Some(&json!({"topics": [".*"], "name": "mine"})),
    )
    .await;
    assert_eq!(s, 201, "{rec}");
    let id = rec["id"].as_str().unwrap().to_owned();
    assert_eq!(rec["started_by"], "user:recorder");
    for i in 0..20 {
        open.publish_json(&json!({"data": format!("open {i}")}));
        secret.publish_json(&json!({"data": "hidden"}));
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    tokio::time::sleep(Duration::from_millis(300)).await;
    let (s, done) = http_json(
        hub.addr,
        "POST",
        &format!("/api/v1/recordings/{id}/stop"),
        Some(&recorder),
        None,
    )
    .await;
    assert_eq!(s, 200, "{done}");
    assert_eq!(done["state"], "stopped");
    assert_eq!(done["messages"], 20, "{done}");
    assert_eq!(done["refused"], 20, "{done}");
    let file = done["files"][0]["name"].as_str().unwrap().to_owned();
    assert!(file.starts_with("mine_001"), "{file}");

    // Downloaded whole, with its length, by someone who may read recordings.
    let (s, body) = http_bytes(
        hub.addr,
        &format!("/api/v1/recordings/{id}/files/{file}"),
        &recorder,
    )
    .await;
    assert_eq!(s, 200);
    assert_eq!(
        body.len() as u64,
        done["files"][0]["bytes"].as_u64().unwrap()
    );
    assert_eq!(&body[..8], b"\x89MCAP0\r\n");
    let (s, _) = http_bytes(
        hub.addr,
        &format!("/api/v1/recordings/{id}/files/../hub.sqlite3"),
        &admin,
    )
    .await;
    assert_eq!(s, 404);
    let (s, _) = http_bytes(
        hub.addr,
        &format!("/api/v1/recordings/{id}/files/{file}"),
        &nobody,
    )
    .await;
    assert_eq!(s, 403);

    // Audited: the start and stop, and the refused start.
    let sec = &hub.state.security;
    sec.audit.flush();
    let page = sec
        .store
        .query_audit(&AuditQuery {
            action: Some(AuditAction::Recording),
            limit: 100,
            ..Default::default()
        })
        .unwrap();
    let seen: Vec<(String, bool, String)> = page
        .records
        .iter()
        .map(|r| {
            (
                r.record.principal.clone(),
                r.record.allowed,
                r.record.detail.clone().unwrap_or_default(),
            )
        })
        .collect();
    assert!(
        seen.iter()
            .any(|(p, ok, d)| p == "user:recorder" && *ok && d.starts_with("started")),
        "{seen:?}"
    );
    assert!(
        seen.iter()
            .any(|(p, ok, d)| p == "user:recorder" && *ok && d == "stopped"),
        "{seen:?}"
    );
    assert!(
        seen.iter().any(|(p, ok, _)| p == "user:nobody" && !*ok),
        "{seen:?}"
    );

    // Removed with its files.
    let (s, _) = http_json(
        hub.addr,
        "DELETE",
        &format!("/api/v1/recordings/{id}"),
        Some(&admin),
        None,
    )
    .await;
    assert_eq!(s, 204);
    let (_, list) = http_json(hub.addr, "GET", "/api/v1/recordings", Some(&admin), None).await;
    assert_eq!(list["recordings"], json!([]));
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_hub_that_stops_finishes_its_recordings_and_lists_them_after_a_restart() {
    let dir = temp_dir("rec-restart");
    let hub = start_hub_at(
        "127.0.0.1:0".parse().unwrap(),
        dir.clone(),
        Duration::from_millis(500),
    )
    .await;
    let admin = hub.operator_token.clone();
    let mut p = hub_publisher(&hub, "/r/x", "std_msgs/msg/String");
    let (s, rec) = http_json(
        hub.addr,
        "POST",
        "/api/v1/recordings",
        Some(&admin),
        Some(&json!({"topics": ["/r/.*"]})),
    )
    .await;
    assert_eq!(s, 201, "{rec}");
    let id = rec["id"].as_str().unwrap().to_owned();
    for i in 0..10 {
        p.publish_json(&json!({"data": format!("{i}")}));
    }
    tokio::time::sleep(Duration::from_millis(300)).await;
    drop(p);
    hub.shutdown().await;

    let hub = start_hub_at(
        "127.0.0.1:0".parse().unwrap(),
        dir.clone(),
        Duration::from_millis(500),
    )
    .await;
    let (s, v) = http_json(
        hub.addr,
        "GET",
        &format!("/api/v1/recordings/{id}"),
        Some(&hub.operator_token),
        None,
    )
    .await;
    assert_eq!(s, 200, "{v}");
    assert_eq!(v["state"], "stopped", "{v}");
    assert_eq!(v["messages"], 10, "{v}");
    // Finished: the reader gets every message and the end of the data section.
    let path = dir
        .join("recordings")
        .join(&id)
        .join(v["files"][0]["name"].as_str().unwrap());
    let mut r = McapReader::open(&path).unwrap();
    let mut n = 0;
    while let Some(item) = r.next_item() {
        if let Item::Message { .. } = item.expect("a finished file reads to its end") {
            n += 1;
        }
    }
    assert_eq!(n, 10);
    let size = std::fs::metadata(&path).unwrap().len();
    let bytes = std::fs::read(&path).unwrap();
    assert_eq!(
        &bytes[size as usize - 8..],
        b"\x89MCAP0\r\n",
        "the file ends with its footer magic"
    );
    hub.shutdown().await;
}
