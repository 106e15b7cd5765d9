//! The robot's black box fetched through the hub's API: the slice holds the chosen topics
//! in the range and is byte for byte the robot's; the access rules cut what the requester
//! may not read; bad requests, and a robot without a black box, are refused with reasons.

use std::time::Duration;

use fleetlink_agent::AgentOptions;
use fleetlink_agent::config::SimConfig;
use fleetlink_record::blackbox::ring::RingOptions;
use fleetlink_record::read::{Item, McapReader};
use serde_json::{Value, json};

use crate::util::*;

/// Waits until recording `id` is no longer fetching; returns it.
async fn finished(hub: &TestHub, id: &str) -> Value {
    let path = format!("/api/v1/recordings/{id}");
    within("the fetch to end", async {
        loop {
            let (s, v) = http_json(hub.addr, "GET", &path, Some(&hub.operator_token), None).await;
            assert_eq!(s, 200, "{v}");
            if v["state"] != "fetching" {
                return v;
            }
            tokio::time::sleep(Duration::from_millis(100)).await;
        }
    })
    .await
}

fn messages_by_topic(path: &std::path::Path) -> std::collections::BTreeMap<String, Vec<u64>> {
    let mut r = McapReader::open(path).expect("open");
    let mut topics = std::collections::HashMap::new();
    let mut out = std::collections::BTreeMap::<String, Vec<u64>>::new();
    while let Some(item) = r.next_item() {
        match item.expect("a finished file reads to its end") {
            Item::Channel(c) => {
                topics.insert(c.id, c.topic);
            }
            Item::Message {
                channel, log_time, ..
            } => out
                .entry(topics[&channel].clone())
                .or_default()
                .push(log_time),
        }
    }
    out
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_black_box_slice_arrives_whole_with_the_chosen_topics_and_range() {
    let hub = start_hub().await;
    hub.set_rules(
        r#"
rules:
  - subject: {user: viewer}
    names: "/recordings"
    ops: [admin]
  - subject: {user: viewer}
    names: "/bb1/odom"
    ops: [subscribe]
"#,
    );
    let dir = temp_dir("blackbox");
    let sim = SimConfig {
        point_cloud: None,
        image: None,
        ..SimConfig::default()
    };
    let agent = start_agent_opts(AgentOptions {
        uplink: uplink_config(&hub, "bb1"),
        local_listen: None,
        sim: Some(sim.clone()),
        ros1: None,
        ros2: None,
        rosbridge: None,
        blackbox: Some(RingOptions {
            dir: dir.clone(),
            max_bytes: 16 << 20,
            topics: vec!["/scan".into(), "/odom".into()],
            // lz4 on the robot; the slice it cuts is zstd.
            compression: fleetlink_record::Compression::Lz4,
        }),
        video: Vec::new(),
        runtime: None,
    })
    .await;
    agent.wait_connected().await;
    // Nobody subscribes at the hub: the ring keeps the topics all the same.
    tokio::time::sleep(Duration::from_secs(3)).await;
    let admin = hub.operator_token.clone();

    // Bad requests name the field.
    for (body, field) in [
        (json!({"robot": "bb1"}), "last_s"),
        (
            json!({"robot": "bb1", "last_s": 1, "from_ns": 5}),
            "not both",
        ),
        (json!({"robot": "", "last_s": 1}), "robot"),
        (
            json!({"robot": "bb1", "last_s": 1, "topics": ["(("]}),
            "topics",
        ),
        (json!({"robot": "bb1", "last": 1}), "unknown field"),
    ] {
        let (s, v) = http_json(
            hub.addr,
            "POST",
            "/api/v1/recordings/blackbox",
            Some(&admin),
            Some(&body),
        )
        .await;
        assert_eq!(s, 400, "{body}: {v}");
        assert!(v["error"].as_str().unwrap().contains(field), "{body}: {v}");
    }

    // The last two seconds of the scan.
    let asked_at = fleetlink_relay::unix_nanos();
    let (s, v) = http_json(
        hub.addr,
        "POST",
        "/api/v1/recordings/blackbox",
        Some(&admin),
        Some(&json!({"robot": "bb1", "last_s": 2, "topics": ["/scan"], "name": "scan_slice"})),
    )
    .await;
    assert_eq!(s, 201, "{v}");
    assert_eq!(v["state"], "fetching");
    let id = v["id"].as_str().unwrap().to_owned();
    assert!(id.starts_with("bb-bb1-"), "{id}");
    let done = finished(&hub, &id).await;
    assert_eq!(done["state"], "stopped", "{done}");
    let file = &done["files"][0];
    assert_eq!(file["name"], "scan_slice.mcap");
    let path = hub
        .state
        .recordings
        .file(&id, "scan_slice.mcap")
        .expect("the slice is one of the recording's files");
    let got = std::fs::read(&path).unwrap();
    assert_eq!(got.len() as u64, done["blackbox"]["size"].as_u64().unwrap());
    // Byte for byte the robot's slice.
    let on_robot = std::fs::read(dir.join("slices").join(format!("{id}.mcap"))).unwrap();
    assert_eq!(got, on_robot);
    let by_topic = messages_by_topic(&path);
    assert_eq!(
        by_topic.keys().collect::<Vec<_>>(),
        ["/scan"],
        "{by_topic:?}"
    );
    let times = &by_topic["/scan"];
    // The simulated scan runs at 10 Hz: about 20 in two seconds.
    assert!((15..=25).contains(&times.len()), "{} scans", times.len());
    let span = (asked_at - 2_500_000_000)..=(asked_at + 1_000_000_000);
    assert!(
        times.iter().all(|t| span.contains(t)),
        "{times:?} outside {span:?}"
    );
    assert_eq!(done["messages"].as_u64().unwrap() as usize, times.len());

    // A requester who may read only /bb1/odom gets only that, the rest counted as refused.
    let viewer = hub
        .state
        .security
        .store
        .mint_operator_token(
            &fleetlink_auth::UserName::new("viewer").unwrap(),
            &[],
            None,
            fleetlink_auth::UnixTime::now(),
        )
        .unwrap()
        .expose()
        .to_owned();
    let (s, v) = http_json(
        hub.addr,
        "POST",
        "/api/v1/recordings/blackbox",
        Some(&viewer),
        Some(&json!({"robot": "bb1", "last_s": 2})),
    )
    .await;
    assert_eq!(s, 201, "{v}");
    let done = finished(&hub, v["id"].as_str().unwrap()).await;
    assert_eq!(done["state"], "stopped", "{done}");
    assert!(done["refused"].as_u64().unwrap() > 0, "{done}");
    let name = done["files"][0]["name"].as_str().unwrap();
    let path = hub
        .state
        .recordings
        .file(done["id"].as_str().unwrap(), name)
        .unwrap();
    let by_topic = messages_by_topic(&path);
    assert_eq!(
        by_topic.keys().collect::<Vec<_>>(),
        ["/odom"],
        "{by_topic:?}"
    );

    // A robot with no black box: refused within seconds, not retried for ever.
    let plain = start_agent_sim(uplink_config(&hub, "plain"), false, None).await;
    plain.wait_connected().await;
    let (s, v) = http_json(
        hub.addr,
        "POST",
        "/api/v1/recordings/blackbox",
        Some(&admin),
        Some(&json!({"robot": "plain", "last_s": 5})),
    )
    .await;
    assert_eq!(s, 201, "{v}");
    let done = finished(&hub, v["id"].as_str().unwrap()).await;
    assert_eq!(done["state"], "failed", "{done}");
    assert!(
        done["error"]
            .as_str()
            .unwrap()
            .contains("keeps no black box"),
        "{done}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
