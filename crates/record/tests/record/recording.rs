//! Recordings of an in-process router, read back with the crate's own reader (the
//! interop suite reads them with Python's `mcap` readers).

use std::sync::Arc;
use std::time::Duration;

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_record::read::{Item, McapReader};
use fleetlink_record::{RecordSpec, Recordings, State};
use fleetlink_relay::gate::AllowAll;
use fleetlink_relay::router::ClientKind;
use fleetlink_relay::transcode::RegistryTranscoder;
use fleetlink_relay::{Router, TopicName};

fn router() -> Arc<Router> {
    Arc::new(Router::new(Arc::new(RegistryTranscoder::bundled())))
}

/// A std_msgs String in CDR, as a ROS 2 publisher sends it.
fn cdr_string(s: &str) -> Vec<u8> {
    let mut b = vec![0, 1, 0, 0];
    b.extend(((s.len() + 1) as u32).to_le_bytes());
    b.extend(s.as_bytes());
    b.push(0);
    b
}

fn read_all(path: &std::path::Path) -> (Vec<fleetlink_record::read::Channel>, Vec<(u16, Vec<u8>)>) {
    let mut r = McapReader::open(path).unwrap();
    let (mut channels, mut messages) = (Vec::new(), Vec::new());
    while let Some(item) = r.next_item() {
        match item.unwrap() {
            Item::Channel(c) => channels.push(c),
            Item::Message { channel, data, .. } => messages.push((channel, data)),
        }
    }
    (channels, messages)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn every_topic_is_recorded_in_its_typed_form_and_reads_back() {
    let dir = tempfile::tempdir().unwrap();
    let router = router();
    let recs = Recordings::open(dir.path(), router.clone(), "test-hub").unwrap();
    let info = recs
        .start(
            RecordSpec::topics(["/r1/.*"]),
            "tester".into(),
            Box::new(AllowAll),
        )
        .unwrap();
    assert_eq!(info.state, State::Recording);

    let (me, _) = router.connect(
        ClientKind::Internal {
            role: "test".into(),
        },
        None,
    );
    let json_topic = router
        .advertise(
            me,
            &TopicName::parse("/r1/chatter").unwrap(),
            Schema::named("std_msgs/msg/String"),
            false,
        )
        .unwrap();
    let ros1 = Schema {
        type_name: "std_msgs/UInt8".into(),
        encoding: "ros1msg".into(),
        text: "uint8 data\n".into(),
    };
    let ros1_topic = router
        .advertise(me, &TopicName::parse("/r1/level").unwrap(), ros1, false)
        .unwrap();
    let custom = router
        .advertise(
            me,
            &TopicName::parse("/r1/custom").unwrap(),
            Schema::named("nobody_msgs/msg/Thing"),
            false,
        )
        .unwrap();
    let other = router
        .advertise(
            me,
            &TopicName::parse("/r2/chatter").unwrap(),
            Schema::named("std_msgs/msg/String"),
            false,
        )
        .unwrap();
    for i in 0..50u64 {
        let text = format!(r#"{{"data":"hello {i}"}}"#);
        json_topic.publish(me, i, 0, Payload::new(Encoding::Json, Bytes::from(text)));
        ros1_topic.publish(
            me,
            i,
            0,
            Payload::new(Encoding::Ros1, Bytes::from(vec![i as u8])),
        );
        custom.publish(
            me,
            i,
            0,
            Payload::new(Encoding::Json, Bytes::from(format!(r#"{{"n":{i}}}"#))),
        );
        other.publish(
            me,
            i,
            0,
            Payload::new(Encoding::Json, Bytes::from_static(br#"{"data":"x"}"#)),
        );
        if i % 10 == 9 {
            tokio::time::sleep(Duration::from_millis(5)).await;
        }
    }
    tokio::time::sleep(Duration::from_millis(200)).await;
    let done = recs.stop(&info.id).await.unwrap();
    assert_eq!(done.state, State::Stopped, "{done:?}");
    assert_eq!(done.messages + done.dropped, 150, "{done:?}");
    assert_eq!(done.files.len(), 1);
    let path = recs.file(&info.id, &done.files[0].name).unwrap();
    assert_eq!(std::fs::metadata(&path).unwrap().len(), done.files[0].bytes);

    let (channels, messages) = read_all(&path);
    let by_topic = |t: &str| {
        channels
            .iter()
            .find(|c| c.topic == t)
            .unwrap_or_else(|| panic!("no {t}: {channels:?}"))
    };
    let chatter = by_topic("/r1/chatter");
    assert_eq!(
        (
            chatter.message_encoding.as_str(),
            chatter.schema_encoding.as_str()
        ),
        ("cdr", "ros2msg")
    );
    assert_eq!(chatter.schema_name, "std_msgs/msg/String");
    assert!(String::from_utf8_lossy(&chatter.schema).contains("string data"));
    let level = by_topic("/r1/level");
    assert_eq!(
        (
            level.message_encoding.as_str(),
            level.schema_encoding.as_str()
        ),
        ("ros1", "ros1msg")
    );
    let thing = by_topic("/r1/custom");
    assert_eq!(
        (
            thing.message_encoding.as_str(),
            thing.schema_encoding.as_str()
        ),
        ("json", "")
    );
    assert!(
        channels.iter().all(|c| c.topic != "/r2/chatter"),
        "an unmatched topic was recorded"
    );

    let of = |c: u16| {
        messages
            .iter()
            .filter(move |(id, _)| *id == c)
            .map(|(_, d)| d.clone())
            .collect::<Vec<_>>()
    };
    let texts = of(chatter.id);
    let levels = of(level.id);
    let things = of(thing.id);
    assert_eq!(
        texts.len() + levels.len() + things.len(),
        done.messages as usize
    );
    if done.dropped == 0 {
        assert_eq!(texts.len(), 50);
        for (i, t) in texts.iter().enumerate() {
            assert_eq!(t, &cdr_string(&format!("hello {i}")), "message {i}");
        }
        assert_eq!(levels, (0..50u8).map(|i| vec![i]).collect::<Vec<_>>());
        assert_eq!(things[7], br#"{"n":7}"#.to_vec());
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_recording_splits_by_size_and_stops_by_itself() {
    let dir = tempfile::tempdir().unwrap();
    let router = router();
    let recs = Recordings::open(dir.path(), router.clone(), "test-hub").unwrap();
    let mut spec = RecordSpec::topics(["/big"]);
    spec.split_size_bytes = Some(1 << 20);
    spec.duration_s = Some(1);
    spec.compression = fleetlink_record::Compression::None;
    spec.queue = 1000;
    spec.name = Some("bulk".into());
    let info = recs
        .start(spec, "tester".into(), Box::new(AllowAll))
        .unwrap();
    let (me, _) = router.connect(
        ClientKind::Internal {
            role: "test".into(),
        },
        None,
    );
    let big = router
        .advertise(
            me,
            &TopicName::parse("/big").unwrap(),
            Schema::named("nobody/msg/Blob"),
            false,
        )
        .unwrap();
    // 100 messages of 100 kB: about 10 MB, so about ten files of 1 MiB.
    for i in 0..100u64 {
        big.publish(
            me,
            i,
            0,
            Payload::new(Encoding::Json, Bytes::from(vec![b' '; 100_000])),
        );
        tokio::time::sleep(Duration::from_millis(2)).await;
    }
    // The recording ends by itself after its duration.
    let deadline = tokio::time::Instant::now() + Duration::from_secs(10);
    let done = loop {
        let i = recs.get(&info.id).unwrap();
        if i.state != State::Recording {
            break i;
        }
        assert!(
            tokio::time::Instant::now() < deadline,
            "still recording: {i:?}"
        );
        tokio::time::sleep(Duration::from_millis(50)).await;
    };
    assert_eq!(done.state, State::Stopped);
    assert_eq!(done.messages + done.dropped, 100, "{done:?}");
    assert!(done.files.len() >= 8, "{:?}", done.files);
    assert!(
        done.files[0].name.starts_with("bulk_001"),
        "{:?}",
        done.files[0].name
    );
    let mut total = 0;
    for f in &done.files {
        // Split at the first chunk boundary past the size.
        assert!(f.bytes < (1 << 20) + (5 << 20), "{f:?}");
        let path = recs.file(&info.id, &f.name).unwrap();
        let (_, msgs) = read_all(&path);
        assert_eq!(msgs.len() as u64, f.messages);
        total += f.messages;
    }
    assert_eq!(total, done.messages);

    // Kept across a restart of the hub.
    drop(recs);
    let again = Recordings::open(dir.path(), router, "test-hub").unwrap();
    assert_eq!(again.get(&info.id).unwrap(), done);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn requests_are_checked_and_unknown_recordings_named() {
    let dir = tempfile::tempdir().unwrap();
    let recs = Recordings::open(dir.path(), router(), "h").unwrap();
    let e = recs
        .start(
            RecordSpec::topics(["/a/(("]),
            "t".into(),
            Box::new(AllowAll),
        )
        .unwrap_err();
    assert!(e.to_string().starts_with("topics:"), "{e}");
    assert!(recs.list().is_empty());
    assert_eq!(
        recs.stop("rec-nope").await.unwrap_err().to_string(),
        "no recording rec-nope"
    );
    assert!(recs.file("rec-nope", "x.mcap").is_err());
}
