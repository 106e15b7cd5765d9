//! Link measurement and capacity sharing over real links: robots behind one site's
//! access link get shares of its capacity and keep their sending within them; the hub
//! knows each robot's clock offset and reports end-to-end latency; the offload signal is
//! computed from a robot's measured link.

use std::sync::atomic::Ordering::Relaxed;
use std::time::{Duration, Instant};

use fleetlink_hub::HubConfig;
use serde_json::json;

use crate::util::*;

async fn hub_with_site(capacity_mbit: f64) -> TestHub {
    let cfg = HubConfig {
        listen: "127.0.0.1:0".parse().unwrap(),
        data_dir: temp_dir("site"),
        heartbeat: Duration::from_millis(200),
        sites: vec![format!("lab={capacity_mbit}:lab_[a-z]+").parse().unwrap()],
        ..HubConfig::default()
    };
    start_hub_cfg(cfg).await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn robots_at_one_site_get_shares_of_its_capacity_and_stay_within_them() {
    // 4 Mbit/s = 500 kB/s for the site; each robot wants ~2 MB/s.
    let hub = hub_with_site(4.0).await;
    let capacity = 500_000.0;
    let a = start_agent_with(uplink_config(&hub, "lab_a"), false).await;
    let b = start_agent_with(uplink_config(&hub, "lab_b"), false).await;
    a.wait_connected().await;
    b.wait_connected().await;
    let blob = "z".repeat(20_000);
    // Someone at the hub wants both cameras (a robot sends only what is wanted).
    let _watching = hub_subscriber(&hub, &["/lab_a/cam", "/lab_b/cam"]);
    let mut pa = LocalPublisher::new(&a.router, "/cam", "test_msgs/msg/Blob");
    let mut pb = LocalPublisher::new(&b.router, "/cam", "test_msgs/msg/Blob");
    let load = tokio::spawn(async move {
        let mut tick = tokio::time::interval(Duration::from_millis(10));
        for _ in 0..1500 {
            tick.tick().await;
            pa.publish_json(&json!({"d": blob}));
            pb.publish_json(&json!({"d": blob}));
        }
    });
    // Both robots receive a share; together they do not exceed the site's capacity.
    within("shares for both robots", async {
        while a.stats.share_bps.load(Relaxed) == 0 || b.stats.share_bps.load(Relaxed) == 0 {
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
    })
    .await;
    let (sa, sb) = (
        a.stats.share_bps.load(Relaxed) as f64,
        b.stats.share_bps.load(Relaxed) as f64,
    );
    assert!(
        sa + sb <= capacity * 1.01,
        "shares {sa} + {sb} exceed {capacity}"
    );
    // What the robot's link carries over a while stays within its share (plus one burst
    // and one message): a slow machine can only make it less. (Counted as the link
    // carried it: the camera's repetitive payload goes compressed, so more payload than
    // the share passes.)
    let topic = fleetlink_relay::TopicName::parse("/lab_a/cam").unwrap();
    let stats = hub
        .state
        .router
        .topic(&topic)
        .expect("topic at hub")
        .stats
        .clone();
    let link_bytes = || stats.link_figures().map_or(0, |(wire, _)| wire);
    let (b0, t0) = (link_bytes(), Instant::now());
    tokio::time::sleep(Duration::from_secs(3)).await;
    let (b1, dt) = (link_bytes(), t0.elapsed().as_secs_f64());
    let share_now = a.stats.share_bps.load(Relaxed) as f64;
    let allowed = share_now.max(sa) * dt * 1.2 + 100_000.0;
    let got = (b1 - b0) as f64;
    assert!(
        got <= allowed,
        "robot sent {got} B in {dt:.1} s with a share of {share_now} B/s"
    );
    assert!(got > 0.0, "robot sent nothing at all");
    // The hub's API shows the site and the shares.
    let robots = hub.state.registry.list();
    assert!(robots.iter().all(|r| r.share_bps.load(Relaxed) > 0));
    load.abort();
    a.shutdown().await;
    b.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn hub_learns_clock_offset_and_reports_end_to_end_latency() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "clocky").await;
    let _watching = hub_subscriber(&hub, &["/clocky/tick"]);
    let mut p = LocalPublisher::new(&agent.router, "/tick", "std_msgs/msg/String");
    let topic = fleetlink_relay::TopicName::parse("/clocky/tick").unwrap();
    within("an offset and a latency figure", async {
        loop {
            p.publish_json(&json!({"data": "t"}));
            let offset = hub
                .state
                .registry
                .list()
                .first()
                .and_then(|r| r.clock_offset_ns());
            let lat = hub
                .state
                .router
                .topic(&topic)
                .map_or(0, |t| t.stats.latency_ns.load(Relaxed));
            if let Some(off) = offset
                && lat > 0
            {
                // Same machine, same clock: the estimate is bounded by the round trip.
                assert!(off.unsigned_abs() < 1_000_000_000, "offset {off} ns");
                return;
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await;
    agent.shutdown().await;
    hub.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn offload_signal_follows_inequality_5_for_a_robots_measured_link() {
    let hub = start_hub().await;
    let agent = start_agent(&hub, "worker").await;
    let mut p = LocalPublisher::new(&agent.router, "/data", "test_msgs/msg/Blob");
    // Traffic so the agent reports a measured link rate.
    within("a measured link rate", async {
        loop {
            p.publish_json(&json!({"d": "x".repeat(1000)}));
            if hub
                .state
                .registry
                .list()
                .iter()
                .any(|r| r.rate_bps.load(Relaxed) > 0)
            {
                return;
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await;
    let get = |q: &str| {
        let path = format!("/api/v1/robots/worker/offload?{q}");
        let (addr, token) = (hub.addr, hub.operator_token.clone());
        async move { http_json(addr, "GET", &path, Some(&token), None).await }
    };
    // The server is 10x faster and five robots need the data: offload.
    let (code, v) = get("h=5&s_m=1e9&s_s=1e10&d=1e5&x=1e10").await;
    assert_eq!(code, 200, "{v}");
    assert_eq!(v["offload"], true, "{v}");
    // Same speed, one consumer: the upload only adds time; stay local.
    let (code, v) = get("h=1&s_m=1e9&s_s=1e9&d=1e5&x=1e10").await;
    assert_eq!(code, 200, "{v}");
    assert_eq!(v["offload"], false, "{v}");
    // A missing parameter is named.
    let (code, v) = get("h=1&s_m=1e9").await;
    assert_eq!(code, 400);
    assert!(v["error"].as_str().unwrap().contains("s_s"), "{v}");
    agent.shutdown().await;
    hub.shutdown().await;
}
