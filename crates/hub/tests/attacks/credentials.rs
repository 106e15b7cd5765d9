//! Attacks on authentication: missing, forged, expired, revoked and replayed
//! credentials, oversized credentials, password guessing, and a spoofed client address.

use fleetlink_auth::audit::AuditAction;
use fleetlink_auth::authn::RobotNetwork;
use fleetlink_auth::{TrustedProxies, UnixTime};
use serde_json::json;
use tokio_tungstenite::tungstenite::Error as WsError;

use crate::*;

/// A rosbridge upgrade with this token is answered 401 before switching protocols.
async fn upgrade_refused(fx: &Fixture, token: &str) {
    let err = within(
        "rosbridge upgrade",
        tokio_tungstenite::connect_async(fx.ws_url(token)),
    )
    .await
    .expect_err("upgrade must be refused");
    match err {
        WsError::Http(res) => assert_eq!(res.status(), 401, "{res:?}"),
        other => panic!("expected HTTP 401, got {other}"),
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn no_token_is_refused_for_agents_and_rosbridge() {
    let fx = hub().await;
    // Agent: HELLO without a token from an address that is no robot network.
    let mut a = agent(fx.addr, "r1", "", None).await;
    refused(&mut a, 401, "authentication failed").await;
    assert!(next_frame(&mut a).await.is_none(), "link closes");
    fx.assert_audited(AuditAction::AuthFailure, "claimed-robot:r1")
        .await;
    // rosbridge: the session opens but nothing is allowed until `auth`.
    let mut r = rosbridge(&format!("ws://{}/", fx.addr)).await;
    send(&mut r, json!({"op": "subscribe", "topic": "/r1/odom"})).await;
    let s = next_op(&mut r, "status").await;
    assert_eq!(s["level"], "error", "{s}");
    assert!(
        s["msg"]
            .as_str()
            .unwrap()
            .contains("authentication required"),
        "{s}"
    );
    fx.assert_audited(AuditAction::AuthFailure, "no credential presented")
        .await;
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn invalid_token_is_refused() {
    let fx = hub().await;
    let forged = format!("flk_robot_{}", "A".repeat(43));
    upgrade_refused(&fx, &forged).await;
    upgrade_refused(&fx, "not-even-a-token").await;
    let mut a = agent(fx.addr, "r1", &forged, None).await;
    refused(&mut a, 401, "authentication failed").await;
    fx.assert_audited(AuditAction::AuthFailure, "unknown token")
        .await;
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn expired_token_is_refused() {
    let fx = hub().await;
    let expired = fx.robot_token("r1", Some(UnixTime::now().plus_secs(-60)));
    let mut a = agent(fx.addr, "r1", &expired, None).await;
    refused(&mut a, 401, "authentication failed").await;
    upgrade_refused(&fx, &expired).await;
    fx.assert_audited(AuditAction::AuthFailure, "expired").await;
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn revoked_token_is_refused_in_hello_and_rosbridge() {
    let fx = hub().await;
    let token = fx.robot_token("r1", None);
    // It works before revocation...
    let mut a = agent(fx.addr, "r1", &token, None).await;
    welcomed(&mut a).await;
    drop(a);
    // ...an admin revokes it over the REST API...
    let list = api(&fx, "GET", "/api/v1/tokens", &fx.operator, "").await;
    assert_eq!(list.status, 200, "{}", list.body);
    let id = list.json()["tokens"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["kind"] == "robot" && t["subject"] == "r1")
        .expect("the robot token is listed")["id"]
        .as_i64()
        .unwrap();
    let del = api(
        &fx,
        "DELETE",
        &format!("/api/v1/tokens/{id}"),
        &fx.operator,
        "",
    )
    .await;
    assert_eq!(del.status, 204, "{}", del.body);
    // ...and both transports refuse it afterwards.
    let mut a = agent(fx.addr, "r1", &token, None).await;
    refused(&mut a, 401, "authentication failed").await;
    upgrade_refused(&fx, &token).await;
    fx.assert_audited(AuditAction::AuthFailure, "revoked").await;
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn session_token_replayed_after_logout_is_refused() {
    let fx = hub().await;
    let body = json!({"name": "alice", "password": "correct horse", "groups": ["operators"]});
    let add = api(
        &fx,
        "POST",
        "/api/v1/users",
        &fx.operator,
        &body.to_string(),
    )
    .await;
    assert_eq!(add.status, 201, "{}", add.body);
    let login = http(
        fx.addr,
        "POST",
        "/api/v1/login",
        &[("Content-Type", "application/json")],
        &json!({"user": "alice", "password": "correct horse"}).to_string(),
    )
    .await;
    assert_eq!(login.status, 200, "{}", login.body);
    let session = login.json()["token"].as_str().unwrap().to_owned();
    assert!(session.starts_with("flk_session_"));
    // The session works for the API and for rosbridge.
    assert_eq!(
        api(&fx, "GET", "/api/v1/topics", &session, "").await.status,
        200
    );
    let out = api(&fx, "POST", "/api/v1/logout", &session, "").await;
    assert_eq!(out.status, 204, "{}", out.body);
    // Replayed afterwards: refused everywhere.
    let replay = api(&fx, "GET", "/api/v1/topics", &session, "").await;
    assert_eq!(replay.status, 401, "{}", replay.body);
    assert!(
        replay.json()["error"]
            .as_str()
            .unwrap()
            .contains("authentication")
    );
    upgrade_refused(&fx, &session).await;
    fx.assert_audited(AuditAction::AuthFailure, "revoked").await;
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn oversized_auth_frame_gets_a_status_error() {
    let fx = hub().await;
    let mut r = rosbridge(&format!("ws://{}/", fx.addr)).await;
    let huge = "x".repeat(1 << 20);
    send(&mut r, json!({"op": "auth", "token": huge})).await;
    let s = next_op(&mut r, "status").await;
    assert_eq!(s["level"], "error", "{s}");
    assert!(s["msg"].as_str().unwrap().contains("limit"), "{s}");
    fx.assert_audited(AuditAction::AuthFailure, "over the limit")
        .await;
    // The same connection is still usable: a proper `auth` then a rosapi call.
    send(&mut r, json!({"op": "auth", "token": fx.operator})).await;
    send(
        &mut r,
        json!({"op": "call_service", "service": "/rosapi/get_time", "id": "t"}),
    )
    .await;
    let v = next_op(&mut r, "service_response").await;
    assert_eq!(v["result"], true, "{v}");
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn login_brute_force_engages_the_rate_limit() {
    let fx = hub().await;
    let body = json!({"name": "bob", "password": "s3cret-enough", "groups": []});
    assert_eq!(
        api(
            &fx,
            "POST",
            "/api/v1/users",
            &fx.operator,
            &body.to_string()
        )
        .await
        .status,
        201
    );
    let guess = |pw: &str| json!({"user": "bob", "password": pw}).to_string();
    let mut limited = None;
    // 5 failures per user name lock the name; the loop is bounded well past that.
    for i in 0..10 {
        let r = http(
            fx.addr,
            "POST",
            "/api/v1/login",
            &[("Content-Type", "application/json")],
            &guess(&format!("guess{i}")),
        )
        .await;
        match r.status {
            401 => continue,
            429 => {
                limited = Some(r);
                break;
            }
            s => panic!("unexpected {s}: {}", r.body),
        }
    }
    let r = limited.expect("the rate limit engages within 10 guesses");
    let retry: i64 = r
        .header("retry-after")
        .expect("429 carries Retry-After")
        .parse()
        .unwrap();
    assert!(retry > 0);
    assert!(
        r.json()["error"].as_str().unwrap().contains("retry"),
        "{}",
        r.body
    );
    // Even the right password is refused while locked.
    let right = http(
        fx.addr,
        "POST",
        "/api/v1/login",
        &[("Content-Type", "application/json")],
        &guess("s3cret-enough"),
    )
    .await;
    assert_eq!(right.status, 429, "{}", right.body);
    fx.assert_audited(AuditAction::AuthFailure, "too many failed logins")
        .await;
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn spoofed_x_forwarded_for_grants_nothing() {
    // Trusted proxies and a robot network exist, but neither matches 127.0.0.1.
    let fx = hub_with(|cfg| {
        cfg.auth.trusted_proxies = TrustedProxies::new(vec!["10.99.0.0/16".parse().unwrap()]);
        cfg.auth.robot_networks = vec![RobotNetwork {
            net: "192.168.50.0/24".parse().unwrap(),
            robot: None,
        }];
    })
    .await;
    // An agent without a token claims, through the header, to be on the robot network.
    let mut a = agent(fx.addr, "r1", "", Some("192.168.50.7")).await;
    refused(&mut a, 401, "authentication failed").await;
    let rec = fx
        .assert_audited(AuditAction::AuthFailure, "claimed-robot:r1")
        .await;
    assert_eq!(
        rec.record.client_ip.to_string(),
        "127.0.0.1",
        "the audit names the real peer, not the header: {rec:?}"
    );
    // A header that also lists a trusted proxy hop changes nothing either: the peer
    // itself is not a trusted proxy, so the header is not read at all.
    let mut a = agent(fx.addr, "r1", "", Some("192.168.50.7, 10.99.0.1")).await;
    refused(&mut a, 401, "authentication failed").await;
    // The same holds on the HTTP API (anonymous is off; the header does not help).
    let r = http(
        fx.addr,
        "GET",
        "/api/v1/topics",
        &[("X-Forwarded-For", "192.168.50.7")],
        "",
    )
    .await;
    assert_eq!(r.status, 401, "{}", r.body);
    fx.still_serving().await;
}
