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

/// Hex text that does not compress much: the link carries about what is published.
fn noise(len: usize, seed: &mut u64) -> String {
    let mut s = String::with_capacity(len);
    while s.len() < len {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        s.push_str(&format!("{:016x}", *seed));
    }
    s.truncate(len);
    s
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn predicted_receive_rates_match_what_a_capped_link_delivers() {
    // 1.5 Mbit/s = 187.5 kB/s for the robot; it offers a 400 kB/s camera and a 200 kB/s
    // scan (about half that on the link: hex compresses 2:1) and a 2 kB/s pose, all at
    // one priority.
    let hub = hub_with_site(1.5).await;
    let agent = start_agent_with(uplink_config(&hub, "lab_r"), false).await;
    agent.wait_connected().await;
    let _watching = hub_subscriber(&hub, &["/lab_r/cam", "/lab_r/scan", "/lab_r/pose"]);
    let mut cam = LocalPublisher::new(&agent.router, "/cam", "test_msgs/msg/Blob");
    let mut scan = LocalPublisher::new(&agent.router, "/scan", "test_msgs/msg/Blob");
    let mut pose = LocalPublisher::new(&agent.router, "/pose", "test_msgs/msg/Blob");
    let load = tokio::spawn(async move {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut tick = tokio::time::interval(Duration::from_millis(50));
        loop {
            tick.tick().await;
            cam.publish_json(&json!({"d": noise(20_000, &mut seed)}));
            scan.publish_json(&json!({"d": noise(10_000, &mut seed)}));
            for _ in 0..2 {
                pose.publish_json(&json!({"d": noise(50, &mut seed)}));
            }
        }
    });
    let rates = || {
        let (addr, token) = (hub.addr, hub.operator_token.clone());
        async move {
            let (code, v) = http_json(
                addr,
                "GET",
                "/api/v1/robots/lab_r/rates",
                Some(&token),
                None,
            )
            .await;
            assert_eq!(code, 200, "{v}");
            v
        }
    };
    let predicted = |v: &serde_json::Value, name: &str| {
        v["topics"]
            .as_array()
            .and_then(|ts| ts.iter().find(|t| t["name"] == name))
            .and_then(|t| t["predicted_rate_hz"].as_f64())
    };
    // Let the share settle and the link fill before taking figures.
    within("a prediction for all three topics", async {
        loop {
            let v = rates().await;
            if ["/lab_r/cam", "/lab_r/scan", "/lab_r/pose"]
                .iter()
                .all(|n| predicted(&v, n).is_some())
            {
                return;
            }
            tokio::time::sleep(Duration::from_millis(200)).await;
        }
    })
    .await;
    tokio::time::sleep(Duration::from_secs(3)).await;
    // Measured at the hub over 4 s, beside the prediction in the middle of that window.
    let count = |name: &str| {
        let t = fleetlink_relay::TopicName::parse(name).unwrap();
        hub.state
            .router
            .topic(&t)
            .map_or(0, |t| t.stats.messages.load(Relaxed))
    };
    let names = ["/lab_r/cam", "/lab_r/scan", "/lab_r/pose"];
    let before: Vec<u64> = names.iter().map(|n| count(n)).collect();
    let t0 = Instant::now();
    tokio::time::sleep(Duration::from_secs(2)).await;
    let v = rates().await;
    tokio::time::sleep(Duration::from_secs(2)).await;
    let dt = t0.elapsed().as_secs_f64();
    let measured: Vec<f64> = names
        .iter()
        .zip(&before)
        .map(|(n, b)| (count(n) - b) as f64 / dt)
        .collect();
    println!("measured {measured:?} over {dt:.1} s; prediction {v}");
    let capacity = v["capacity_bps"].as_f64().expect("a capacity");
    assert!(capacity <= 187_500.0 * 1.05, "{v}");
    for (n, m) in names.iter().zip(&measured) {
        let p = predicted(&v, n).unwrap();
        assert!(
            (m - p).abs() <= p * 0.3 + 0.5,
            "{n}: measured {m:.2}/s, predicted {p:.2}/s\n{v}"
        );
    }
    // The link cannot carry the camera and the scan: both are thinned, sharing the link
    // byte for byte (their chunks go in turn), so the scan's half-size messages come
    // about twice as often; the pose fits whole.
    let (pc, ps, pp) = (
        predicted(&v, "/lab_r/cam").unwrap(),
        predicted(&v, "/lab_r/scan").unwrap(),
        predicted(&v, "/lab_r/pose").unwrap(),
    );
    assert!(pc < 16.0 && ps < 19.5, "{v}");
    assert!(ps > 1.5 * pc, "{v}");
    assert!(pp > 35.0, "{v}");
    // The listing carries the same figures.
    let (code, list) = http_json(
        hub.addr,
        "GET",
        "/api/v1/topics",
        Some(&hub.operator_token),
        None,
    )
    .await;
    assert_eq!(code, 200);
    let cam_row = list["topics"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["name"] == "/lab_r/cam")
        .unwrap()
        .clone();
    assert!(
        cam_row["offered_rate_hz"].as_f64().unwrap() > 15.0,
        "{cam_row}"
    );
    assert!(
        cam_row["predicted_rate_hz"].as_f64().unwrap() < 16.0,
        "{cam_row}"
    );
    load.abort();
    agent.shutdown().await;
    hub.shutdown().await;
}
