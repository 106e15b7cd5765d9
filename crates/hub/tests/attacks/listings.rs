//! Attacks on the REST listings and metrics (issue 9, part 6): an operator without
//! rights reading robots, their addresses, topics, clients and metrics that `/rosapi`
//! would hide; and refused admin reads audited as what they were.

use fleetlink_auth::audit::AuditAction;
use fleetlink_auth::{AclDefaults, AuthPolicy};
use fleetlink_proto::frame::Frame;
use fleetlink_proto::{Encoding, Schema};
use serde_json::json;

use crate::*;

/// robot1 online, publishing `/robot1/scan`; returns once the hub lists the topic.
async fn robot_with_topic(fx: &Fixture) -> Ws {
    let mut r1 = agent(fx.addr, "robot1", &fx.robot_token("robot1", None), None).await;
    welcomed(&mut r1).await;
    send_frame(
        &mut r1,
        Frame::Advertise {
            alias: 1,
            topic: "/robot1/scan".into(),
            schema: Schema::named("std_msgs/String"),
            encoding: Encoding::Json,
            flags: 0,
        },
    )
    .await;
    within("the hub to list /robot1/scan", async {
        loop {
            let names: Vec<String> = fx
                .state
                .router
                .topics()
                .iter()
                .map(|t| t.meta.name.as_str().to_owned())
                .collect();
            if names.iter().any(|n| n == "/robot1/scan") {
                return;
            }
            tokio::task::yield_now().await;
        }
    })
    .await;
    r1
}

fn names(v: &Value, list: &str) -> Vec<String> {
    v[list]
        .as_array()
        .unwrap_or_else(|| panic!("no {list} in {v}"))
        .iter()
        .map(|x| x["name"].as_str().unwrap_or_default().to_owned())
        .collect()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn operator_without_rights_sees_no_robots_topics_clients_or_metrics() {
    let fx = hub().await;
    let _r1 = robot_with_topic(&fx).await;
    let nobody = mint_operator(&fx.state, "nobody", &[]);

    let robots = api(&fx, "GET", "/api/v1/robots", &nobody, "").await;
    assert_eq!(robots.status, 200);
    assert!(
        names(&robots.json(), "robots").is_empty(),
        "{}",
        robots.body
    );
    let topics = api(&fx, "GET", "/api/v1/topics", &nobody, "").await;
    assert!(
        names(&topics.json(), "topics").is_empty(),
        "{}",
        topics.body
    );
    let clients = api(&fx, "GET", "/api/v1/clients", &nobody, "").await;
    assert_eq!(clients.status, 403, "{}", clients.body);
    let metrics = api(&fx, "GET", "/metrics", &nobody, "").await;
    assert_eq!(metrics.status, 403, "{}", metrics.body);
    assert!(!metrics.body.contains("robot1"), "{}", metrics.body);
    fx.assert_audited(AuditAction::AccessDenied, "/clients")
        .await;
    fx.assert_audited(AuditAction::AccessDenied, "/metrics")
        .await;

    // The admin sees everything, addresses included.
    let robots = api(&fx, "GET", "/api/v1/robots", &fx.operator, "")
        .await
        .json();
    let r1 = &robots["robots"][0];
    assert_eq!(r1["name"], "robot1", "{robots}");
    assert!(
        r1["addr"]
            .as_str()
            .is_some_and(|a| a.starts_with("127.0.0.1")),
        "{r1}"
    );
    let topics = api(&fx, "GET", "/api/v1/topics", &fx.operator, "")
        .await
        .json();
    assert!(names(&topics, "topics").contains(&"/robot1/scan".to_owned()));
    let clients = api(&fx, "GET", "/api/v1/clients", &fx.operator, "").await;
    assert_eq!(clients.status, 200, "{}", clients.body);
    let metrics = api(&fx, "GET", "/metrics", &fx.operator, "").await;
    assert_eq!(metrics.status, 200);
    assert!(metrics.body.contains("/robot1/scan"), "{}", metrics.body);
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_viewer_sees_its_robots_without_addresses_and_metrics_need_the_metrics_group() {
    let fx = hub().await;
    let _r1 = robot_with_topic(&fx).await;
    let rule =
        json!({"subject": {"group": "viewers"}, "names": "/robot1/.*", "ops": ["subscribe"]});
    let r = api(
        &fx,
        "POST",
        "/api/v1/rules",
        &fx.operator,
        &rule.to_string(),
    )
    .await;
    assert_eq!(r.status, 201, "{}", r.body);
    let viewer = mint_operator(&fx.state, "viewer", &["viewers"]);

    let robots = api(&fx, "GET", "/api/v1/robots", &viewer, "").await.json();
    assert_eq!(names(&robots, "robots"), ["robot1"], "{robots}");
    assert!(robots["robots"][0]["addr"].is_null(), "{robots}");
    let topics = api(&fx, "GET", "/api/v1/topics", &viewer, "").await.json();
    assert_eq!(names(&topics, "topics"), ["/robot1/scan"]);
    assert_eq!(api(&fx, "GET", "/metrics", &viewer, "").await.status, 403);

    // A Prometheus token: the metrics group reads /metrics and nothing else.
    let scraper = mint_operator(&fx.state, "prometheus", &["metrics"]);
    let m = api(&fx, "GET", "/metrics", &scraper, "").await;
    assert_eq!(m.status, 200, "{}", m.body);
    assert!(m.body.contains("fleetlink_connections_open"), "{}", m.body);
    assert_eq!(
        api(&fx, "GET", "/api/v1/clients", &scraper, "")
            .await
            .status,
        403
    );
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn refused_audit_read_is_audited_as_access_denied() {
    let fx = hub().await;
    let nobody = mint_operator(&fx.state, "nobody", &[]);
    let r = api(&fx, "GET", "/api/v1/audit", &nobody, "").await;
    assert_eq!(r.status, 403, "{}", r.body);
    let rec = fx.assert_audited(AuditAction::AccessDenied, "/audit").await;
    assert_eq!(rec.record.principal, "user:nobody");
    let wrong = fx.audited(AuditAction::CredentialChange).await;
    assert!(
        wrong.is_empty(),
        "a read is no credential change: {wrong:#?}"
    );
    fx.still_serving().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn anonymous_local_viewer_of_the_demo_still_sees_the_fleet() {
    let fx = hub_with(|c| {
        c.auth = AuthPolicy::demo();
        c.acl = AclDefaults::demo();
    })
    .await;
    let _r1 = robot_with_topic(&fx).await;
    let robots = http(fx.addr, "GET", "/api/v1/robots", &[], "").await;
    assert_eq!(robots.status, 200, "{}", robots.body);
    let robots = robots.json();
    assert_eq!(names(&robots, "robots"), ["robot1"], "{robots}");
    assert!(robots["robots"][0]["addr"].is_null(), "{robots}");
    let topics = http(fx.addr, "GET", "/api/v1/topics", &[], "").await.json();
    // The hub's own /rosout is there for every reader, as rosbridge's is.
    assert_eq!(names(&topics, "topics"), ["/robot1/scan", "/rosout"]);
    let metrics = http(fx.addr, "GET", "/metrics", &[], "").await;
    assert_eq!(metrics.status, 200, "{}", metrics.body);
    assert_eq!(
        http(fx.addr, "GET", "/api/v1/clients", &[], "")
            .await
            .status,
        403
    );
    let page = http(fx.addr, "GET", "/", &[], "").await;
    assert_eq!(page.status, 200);
    fx.still_serving().await;
}
