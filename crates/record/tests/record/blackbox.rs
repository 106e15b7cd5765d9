//! The robot's black box in-process: the ring keeps its topics in segments within its
//! size and finds them again after a restart; slices hold the range and topics asked for.

use std::sync::Arc;
use std::time::Duration;

use fleetlink_proto::{Payload, Schema};
use fleetlink_record::Compression;
use fleetlink_record::blackbox::ring::{Ring, RingOptions};
use fleetlink_record::blackbox::slice::{cut, digest, overlapping};
use fleetlink_record::read::{Item, McapReader};
use fleetlink_relay::router::ClientKind;
use fleetlink_relay::transcode::RegistryTranscoder;
use fleetlink_relay::{Router, TopicName};

fn router() -> Arc<Router> {
    Arc::new(Router::new(Arc::new(RegistryTranscoder::bundled())))
}

/// A std_msgs String in CDR of `n` bytes of text.
fn cdr_string(n: usize, fill: u8) -> Vec<u8> {
    let mut b = vec![0, 1, 0, 0];
    b.extend(((n + 1) as u32).to_le_bytes());
    b.extend(std::iter::repeat_n(fill, n));
    b.push(0);
    b
}

fn topics_in(path: &std::path::Path) -> Vec<(String, u64)> {
    let mut r = McapReader::open(path).unwrap();
    let mut names = std::collections::HashMap::new();
    let mut out = Vec::new();
    while let Some(item) = r.next_item() {
        match item.unwrap() {
            Item::Channel(c) => {
                names.insert(c.id, c.topic);
            }
            Item::Message {
                channel, log_time, ..
            } => out.push((names[&channel].clone(), log_time)),
        }
    }
    out
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_ring_stays_within_its_size_and_slices_hold_what_was_asked() {
    let dir = tempfile::tempdir().unwrap();
    let router = router();
    let opts = RingOptions {
        dir: dir.path().to_owned(),
        max_bytes: 8 << 20,
        topics: vec!["/scan".into(), "/odom".into()],
        compression: Compression::None,
    };
    let ring = Ring::start(
        router.clone(),
        opts.clone(),
        tokio::runtime::Handle::current(),
    )
    .unwrap();
    let (me, _) = router.connect(
        ClientKind::Internal {
            role: "test".into(),
        },
        None,
    );
    let schema = || Schema::named("std_msgs/msg/String");
    let scan = router
        .advertise(me, &TopicName::parse("/scan").unwrap(), schema(), false)
        .unwrap();
    let odom = router
        .advertise(me, &TopicName::parse("/odom").unwrap(), schema(), false)
        .unwrap();
    let other = router
        .advertise(me, &TopicName::parse("/camera").unwrap(), schema(), false)
        .unwrap();
    // 24 MiB of scans through an 8 MiB ring (1 MiB segments), a small odom beside them.
    let first = fleetlink_relay::unix_nanos();
    for i in 0..384u64 {
        scan.publish(
            me,
            i,
            0,
            Payload::new(fleetlink_proto::Encoding::Cdr, cdr_string(64 << 10, b'a')),
        );
        odom.publish(
            me,
            i,
            0,
            Payload::new(fleetlink_proto::Encoding::Cdr, cdr_string(10, b'o')),
        );
        other.publish(
            me,
            i,
            0,
            Payload::new(fleetlink_proto::Encoding::Cdr, cdr_string(10, b'c')),
        );
        if i % 16 == 15 {
            // The disk keeps up; the queue (64 per topic) never overflows.
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    }
    let segments = ring.rotate().await;
    assert_eq!(
        ring.stats()
            .dropped
            .load(std::sync::atomic::Ordering::Relaxed),
        0
    );
    let total: u64 = segments.iter().map(|s| s.bytes).sum();
    assert!(
        total <= 8 << 20,
        "{} segments, {total} bytes",
        segments.len()
    );
    assert!(
        total >= 6 << 20,
        "the ring keeps most of its size: {total} bytes"
    );
    assert!(
        ring.stats()
            .deleted
            .load(std::sync::atomic::Ordering::Relaxed)
            > 0
    );
    let on_disk: u64 = std::fs::read_dir(dir.path().join("ring"))
        .unwrap()
        .map(|e| e.unwrap().metadata().unwrap().len())
        .sum();
    assert_eq!(on_disk, total, "deleted segments are gone from the disk");
    // The oldest messages were deleted: nothing from the first moments is left.
    assert!(segments[0].start_ns > first);

    // A slice of the odometry alone, over everything the ring holds.
    let last = segments.last().unwrap();
    let inputs: Vec<&std::path::Path> = overlapping(&segments, 0, u64::MAX)
        .iter()
        .map(|s| s.path.as_path())
        .collect();
    assert_eq!(inputs.len(), segments.len());
    let out = dir.path().join("odom.mcap");
    let reply = cut(&inputs, 0, u64::MAX, &mut |t| t == "/odom", &out).unwrap();
    let got = topics_in(&out);
    assert!(got.iter().all(|(t, _)| t == "/odom"));
    assert_eq!(got.len() as u64, reply.messages);
    assert_eq!(reply.topics, ["/odom"]);
    assert_eq!(digest(&out).unwrap(), (reply.size, reply.sha256.clone()));
    // A range inside the newest segment picks that segment only, and messages in range.
    let from = last.start_ns;
    let picked = overlapping(&segments, from, u64::MAX);
    assert_eq!(picked.len(), 1);
    let out2 = dir.path().join("tail.mcap");
    let tail = cut(
        &[picked[0].path.as_path()],
        from,
        u64::MAX,
        &mut |_| true,
        &out2,
    )
    .unwrap();
    assert!(
        topics_in(&out2)
            .iter()
            .all(|(t, at)| *at >= from && t != "/camera")
    );
    assert!(tail.start_ns >= from);
    // Nothing in a range before the ring: an error that says so.
    let none = cut(&inputs, 0, 1, &mut |_| true, &dir.path().join("none.mcap")).unwrap_err();
    assert!(none.contains("no messages"), "{none}");

    // After a restart the ring finds its segments again.
    ring.stop().await;
    drop(ring);
    let again = Ring::start(router.clone(), opts, tokio::runtime::Handle::current()).unwrap();
    assert_eq!(again.segments(), segments);
    again.stop().await;
}
