//! The link writer over an in-memory sink: a small message on another topic overtakes a
//! large message whose chunks are already being sent, pieces of one message keep their
//! order, and a topic whose publisher left is unadvertised after its last message (and
//! drops out of the router's listings). The sink is a one-slot channel, so the test
//! decides exactly when the writer may send its next WebSocket message.

use std::sync::Arc;
use std::time::Duration;

use bytes::Bytes;
use fleetlink_proto::frame::{self, Frame};
use fleetlink_proto::{Payload, Schema};
use fleetlink_relay::link::{Control, write_link};
use fleetlink_relay::router::{SubOptions, Target};
use fleetlink_relay::{ClientId, ClientKind, Outbox, Router, TopicName};
use futures_util::{SinkExt, StreamExt};
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};

/// Every frame in the next WebSocket message the writer sends.
async fn next_frames(rx: &mut futures_channel::mpsc::Receiver<WsMessage>) -> Vec<Frame> {
    let m = tokio::time::timeout(Duration::from_secs(10), rx.next())
        .await
        .expect("writer sends")
        .expect("open");
    let WsMessage::Binary(b) = m else {
        panic!("binary frames only, got {m:?}")
    };
    frame::frames(&b)
        .collect::<Result<_, _>>()
        .expect("valid frames")
}

/// A link client subscribed to `pattern` (its outbox is what the writer sends) and a
/// publisher, both on `router`.
fn link_and_publisher(router: &Router, pattern: &str) -> (Arc<Outbox>, ClientId) {
    let (link, outbox) = router.connect(
        ClientKind::Internal {
            role: "link".into(),
        },
        None,
    );
    router
        .subscribe(
            link,
            Target::Pattern(Router::compile_pattern(pattern).unwrap()),
            SubOptions::default(),
        )
        .unwrap();
    let (publisher, _) = router.connect(ClientKind::Internal { role: "pub".into() }, None);
    (outbox, publisher)
}

/// An agent-style uplink (a scheduled outbox) subscribed to everything on `router`, and a
/// publisher.
fn uplink_and_publisher(router: &Router) -> (Arc<Outbox>, ClientId) {
    uplink_with_qos(router, fleetlink_qos::TopicQos::default())
}

/// [`uplink_and_publisher`] with `qos` for every topic.
fn uplink_with_qos(router: &Router, qos: fleetlink_qos::TopicQos) -> (Arc<Outbox>, ClientId) {
    use fleetlink_qos::SchedulerConfig;
    use fleetlink_relay::reliable::ReliableOut;
    let (link, outbox) = router.connect_with(
        ClientKind::Internal {
            role: "uplink".into(),
        },
        None,
        |id| {
            Outbox::scheduled(
                id,
                SchedulerConfig::default(),
                Arc::new(move |_| qos.clone()),
                ReliableOut::in_memory(),
            )
        },
    );
    router
        .subscribe(
            link,
            Target::Pattern(Router::compile_pattern(".*").unwrap()),
            SubOptions::default(),
        )
        .unwrap();
    let (publisher, _) = router.connect(ClientKind::Internal { role: "pub".into() }, None);
    (outbox, publisher)
}

/// The writer of `outbox` over a sink holding `slots` WebSocket messages: its control
/// channel, what it sends, its task.
fn spawn_writer(
    outbox: Arc<Outbox>,
    slots: usize,
) -> (
    tokio::sync::mpsc::Sender<Box<Control>>,
    futures_channel::mpsc::Receiver<WsMessage>,
    tokio::task::JoinHandle<()>,
) {
    let (tx, rx) = futures_channel::mpsc::channel::<WsMessage>(slots);
    let sink = tx.sink_map_err(|_| WsError::ConnectionClosed);
    let (ctrl_tx, ctrl_rx) = tokio::sync::mpsc::channel::<Box<Control>>(8);
    let writer = tokio::spawn(write_link(
        sink,
        outbox,
        ctrl_rx,
        Arc::new(|m| Some(m.name.to_string())),
        Vec::new(),
        None,
        None,
    ));
    (ctrl_tx, rx, writer)
}

#[tokio::test]
async fn small_message_overtakes_a_large_one_mid_transfer() {
    let router = Arc::new(Router::default());
    let (outbox, publisher) = link_and_publisher(&router, ".*");
    let big = router
        .advertise(
            publisher,
            &TopicName::parse("/cloud").unwrap(),
            Schema::named("t/Blob"),
            false,
        )
        .unwrap();
    let small = router
        .advertise(
            publisher,
            &TopicName::parse("/pose").unwrap(),
            Schema::named("t/Pose"),
            false,
        )
        .unwrap();

    let (_ctrl_tx, mut rx, writer) = spawn_writer(outbox, 0);

    // 2 MiB: 128 chunks of 16 KiB.
    let payload = Bytes::from(vec![7u8; 2 << 20]);
    let total = payload.len().div_ceil(frame::DEFAULT_CHUNK_SIZE);
    big.publish(publisher, 1, 0, Payload::json(payload.clone()));

    // The writer announces the topic and sends the first chunk, then waits on the sink.
    let mut first = next_frames(&mut rx).await;
    first.extend(next_frames(&mut rx).await);
    let chunks_before = first
        .iter()
        .filter(|f| matches!(f, Frame::Chunk { .. }))
        .count();
    assert!(
        (1..total).contains(&chunks_before),
        "{chunks_before} chunks before the pose was published"
    );

    small.publish(publisher, 1, 0, Payload::json(&b"{\"x\":1}"[..]));

    // Read until the pose shows up; count the cloud's chunks on the way.
    let mut chunks = chunks_before;
    let mut offsets = Vec::new();
    loop {
        let frames = next_frames(&mut rx).await;
        let mut pose_seen = false;
        for f in frames {
            match f {
                Frame::Chunk { offset, .. } => {
                    chunks += 1;
                    offsets.push(offset);
                }
                Frame::Message { payload, .. } => {
                    assert_eq!(&payload[..], b"{\"x\":1}");
                    pose_seen = true;
                }
                _ => {}
            }
        }
        if pose_seen {
            break;
        }
    }
    assert!(
        chunks < total,
        "the pose waited for the whole cloud ({chunks} chunks sent first)"
    );
    // The rest of the cloud follows, in order.
    while chunks < total {
        for f in next_frames(&mut rx).await {
            if let Frame::Chunk {
                offset, total_len, ..
            } = f
            {
                assert_eq!(total_len, payload.len() as u64);
                offsets.push(offset);
                chunks += 1;
            }
        }
    }
    assert!(
        offsets.windows(2).all(|w| w[0] < w[1]),
        "chunks out of order: {offsets:?}"
    );
    writer.abort();
}

/// A scheduled outbox (the agent's uplink) that may not send bulk data (a capacity share of
/// 1 kB/s, and no acknowledgements): the first chunks of a large message go, the next
/// ones wait, and a small message published meanwhile goes at once instead of queueing
/// behind them. Once bulk may go again, the rest of the large message follows in order.
#[tokio::test]
async fn small_messages_pass_the_bulk_gate_that_holds_back_chunks() {
    use std::time::Instant;

    let router = Arc::new(Router::default());
    let (outbox, publisher) = uplink_and_publisher(&router);
    let advertise = |name: &str, ty: &str| {
        router
            .advertise(
                publisher,
                &TopicName::parse(name).unwrap(),
                Schema::named(ty),
                false,
            )
            .unwrap()
    };
    let (big, small) = (advertise("/cloud", "t/Blob"), advertise("/pose", "t/Pose"));
    // 1 kB/s: after its burst the gate would take many seconds to let a chunk through.
    outbox.set_share(Some(1000.0), Instant::now());

    let (tx, mut rx) = futures_channel::mpsc::channel::<WsMessage>(64);
    let sink = tx.sink_map_err(|_| WsError::ConnectionClosed);
    let (_ctrl_tx, ctrl_rx) = tokio::sync::mpsc::channel::<Box<Control>>(8);
    let writer = tokio::spawn(write_link(
        sink,
        outbox.clone(),
        ctrl_rx,
        Arc::new(|m| Some(m.name.to_string())),
        Vec::new(),
        None,
        None,
    ));
    let payload = Bytes::from(vec![7u8; 4 * frame::DEFAULT_CHUNK_SIZE]);
    big.publish(publisher, 1, 0, Payload::json(payload.clone()));
    let mut chunks = Vec::new();
    while chunks.is_empty() {
        for f in next_frames(&mut rx).await {
            if let Frame::Chunk { offset, .. } = f {
                chunks.push(offset);
            }
        }
    }
    small.publish(publisher, 1, 0, Payload::json(&b"{\"x\":1}"[..]));
    let mut pose = false;
    while !pose {
        for f in next_frames(&mut rx).await {
            match f {
                Frame::Chunk { offset, .. } => chunks.push(offset),
                Frame::Message { .. } => pose = true,
                _ => {}
            }
        }
    }
    assert!(
        chunks.len() < 4,
        "the small message waited for the whole large one: {chunks:?}"
    );
    // Lift the share and acknowledge what was written (as the hub would): the rest
    // follows, in order.
    outbox.set_share(None, Instant::now());
    outbox.on_acked(0, 1 << 20, Instant::now());
    while chunks.len() < 4 {
        for f in next_frames(&mut rx).await {
            if let Frame::Chunk { offset, .. } = f {
                chunks.push(offset);
            }
        }
    }
    assert!(chunks.windows(2).all(|w| w[0] < w[1]), "{chunks:?}");
    writer.abort();
}

/// Issue 10: a latched topic is announced latched on the link, so the far side latches it
/// too (a hub topic published latched reaches a late ROS 1 subscriber on the robot).
#[tokio::test]
async fn latched_topics_are_announced_latched() {
    let router = Arc::new(Router::default());
    let (outbox, publisher) = link_and_publisher(&router, ".*");
    let mut topics = Vec::new();
    for (name, latch) in [("/announce", true), ("/plain", false)] {
        let t = router
            .advertise(
                publisher,
                &TopicName::parse(name).unwrap(),
                Schema::named("std_msgs/String"),
                latch,
            )
            .unwrap();
        assert_eq!(t.meta().latched, latch, "{name}");
        assert_eq!(t.is_latched(), latch, "{name}");
        topics.push(t);
    }
    let (_ctrl_tx, mut rx, writer) = spawn_writer(outbox, 8);
    for t in &topics {
        t.publish(publisher, 1, 0, Payload::json(Bytes::from_static(b"{}")));
    }
    let mut flags = std::collections::HashMap::new();
    while flags.len() < 2 {
        for f in next_frames(&mut rx).await {
            if let Frame::Advertise {
                topic, flags: f, ..
            } = f
            {
                flags.insert(topic, f);
            }
        }
    }
    assert_ne!(flags["/announce"] & frame::ADVERTISE_LATCHED, 0);
    assert_eq!(flags["/plain"] & frame::ADVERTISE_LATCHED, 0);
    writer.abort();
}

/// A topic whose publisher left is unadvertised to the peer only after everything of it
/// that was queued, including a large message still going out chunk by chunk; a later
/// message advertises it again.
#[tokio::test]
async fn unadvertise_follows_the_topics_last_message_and_a_new_message_readvertises() {
    let router = Arc::new(Router::default());
    let (outbox, publisher) = link_and_publisher(&router, ".*");
    let name = TopicName::parse("/cloud").unwrap();
    let topic = router
        .advertise(publisher, &name, Schema::named("t/Blob"), false)
        .unwrap();
    let alias = topic.id().0;

    let (ctrl_tx, mut rx, writer) = spawn_writer(outbox, 0);

    let mut seen = Vec::new(); // "A", "C", "M", "U" in the order sent
    let record = |frames: Vec<Frame>, seen: &mut Vec<&str>| {
        for f in frames {
            match f {
                Frame::Advertise { alias: a, .. } if a == alias => seen.push("A"),
                Frame::Chunk { alias: a, .. } if a == alias => seen.push("C"),
                Frame::Message { alias: a, .. } if a == alias => seen.push("M"),
                Frame::Unadvertise { alias: a } if a == alias => seen.push("U"),
                _ => {}
            }
        }
    };
    // A large message (128 chunks) under way, a small one queued behind it, then the
    // publisher leaves.
    let big = Bytes::from(vec![7u8; 2 << 20]);
    topic.publish(publisher, 1, 0, Payload::json(big.clone()));
    while !seen.contains(&"C") {
        record(next_frames(&mut rx).await, &mut seen);
    }
    topic.publish(publisher, 2, 0, Payload::json(&b"{\"last\":1}"[..]));
    router.unadvertise(publisher, &name);
    ctrl_tx
        .send(Box::new(Control::Unadvertise {
            topic: topic.id(),
            since: std::time::Instant::now(),
        }))
        .await
        .unwrap();
    while !seen.contains(&"U") {
        record(next_frames(&mut rx).await, &mut seen);
    }
    let chunks = seen.iter().filter(|s| **s == "C").count();
    assert_eq!(seen.first(), Some(&"A"));
    assert_eq!(chunks, big.len().div_ceil(frame::DEFAULT_CHUNK_SIZE));
    assert_eq!(
        seen.last(),
        Some(&"U"),
        "UNADVERTISE after every chunk and message"
    );
    assert_eq!(seen.iter().filter(|s| **s == "M").count(), 1);

    // A second UNADVERTISE of a topic no longer advertised is not sent; neither is one
    // overtaken by a new publisher's message, which advertises the topic again.
    ctrl_tx
        .send(Box::new(Control::Unadvertise {
            topic: topic.id(),
            since: std::time::Instant::now(),
        }))
        .await
        .unwrap();
    let again = router
        .advertise(publisher, &name, Schema::named("t/Blob"), false)
        .unwrap();
    again.publish(publisher, 3, 0, Payload::json(&b"{\"back\":1}"[..]));
    let mut after = Vec::new();
    while !after.contains(&"M") {
        record(next_frames(&mut rx).await, &mut after);
    }
    assert_eq!(after, ["A", "M"]);
    writer.abort();
}

/// Listings show a topic while it has an endpoint: a topic kept only by a pattern
/// subscription (a robot link's namespace) is not listed once its publisher left; one a
/// client subscribed to by name is; a publisher coming back lists it again.
#[test]
fn a_topic_kept_only_by_a_pattern_subscription_is_not_listed() {
    let router = Router::default();
    let (_outbox, publisher) = link_and_publisher(&router, "/robot1/.*");
    let name = TopicName::parse("/robot1/late").unwrap();
    let listed = |router: &Router| {
        router
            .topics()
            .iter()
            .find(|t| t.meta.name == name)
            .map(|t| t.listed())
    };
    router
        .advertise(publisher, &name, Schema::named("std_msgs/String"), false)
        .unwrap();
    assert_eq!(listed(&router), Some(true));
    router.unadvertise(publisher, &name);
    // Still in the router (the pattern subscription holds it), not listed.
    assert_eq!(listed(&router), Some(false));

    let (viewer, _) = router.connect(ClientKind::Internal { role: "ui".into() }, None);
    let sid = router
        .subscribe(viewer, Target::Exact(name.clone()), SubOptions::default())
        .unwrap();
    assert_eq!(listed(&router), Some(true), "a named subscriber lists it");
    router.unsubscribe(viewer, sid);
    assert_eq!(listed(&router), Some(false));

    router
        .advertise(publisher, &name, Schema::named("std_msgs/String"), false)
        .unwrap();
    assert_eq!(listed(&router), Some(true));
}

/// What a federation on this router hears and asks: each topic whose publishers or
/// subscribers change, once per burst; who besides it wants a topic; and its own quiet
/// subscription (on another hub's behalf) neither lists the topic nor counts as demand.
#[test]
fn a_topics_watch_hears_each_change_and_quiet_subscriptions_stay_unlisted() {
    let router = Router::default();
    let watch = router.watch_topics();
    let (fed, _) = router.connect(
        ClientKind::Internal {
            role: "federation".into(),
        },
        None,
    );
    let (robot, _) = router.connect(ClientKind::Agent { robot: "r".into() }, None);
    let (viewer, _) = router.connect(ClientKind::Rosbridge, None);
    let name = TopicName::parse("/r/odom").unwrap();
    assert!(watch.take().is_empty());

    // A quiet subscription for another hub creates the topic, unlisted.
    let quiet = router
        .subscribe(
            fed,
            Target::Exact(name.clone()),
            SubOptions {
                unlisted: true,
                ..SubOptions::default()
            },
        )
        .unwrap();
    assert_eq!(watch.take(), vec![name.clone()]);
    let snap = router.snapshot(&name).unwrap();
    assert!(!snap.listed(), "a quiet subscription does not list a topic");
    assert!(!snap.topic.demand_besides(fed, &snap.publishers));

    // The robot publishes it: listed, and its own link is not demand for it.
    router
        .advertise(robot, &name, Schema::named("nav_msgs/Odometry"), false)
        .unwrap();
    router
        .advertise(robot, &name, Schema::named("nav_msgs/Odometry"), false)
        .unwrap();
    assert_eq!(watch.take(), vec![name.clone()], "a burst is one change");
    let snap = router.snapshot(&name).unwrap();
    assert!(snap.listed());
    assert!(
        snap.topic.wanted_by_others(robot),
        "the quiet subscriber wants it"
    );
    let robot_sub = router
        .subscribe(robot, Target::Exact(name.clone()), SubOptions::default())
        .unwrap();
    assert!(
        !snap.topic.demand_besides(fed, &snap.publishers),
        "a publisher's own subscription is not demand"
    );
    router.unsubscribe(robot, robot_sub);

    // A viewer here is demand.
    let v = router
        .subscribe(viewer, Target::Exact(name.clone()), SubOptions::default())
        .unwrap();
    let snap = router.snapshot(&name).unwrap();
    assert!(snap.topic.demand_besides(fed, &snap.publishers));
    watch.take();
    router.unsubscribe(viewer, v);
    router.unsubscribe(fed, quiet);
    router.unadvertise(robot, &name);
    assert_eq!(watch.take(), vec![name.clone()]);
    assert!(
        router.snapshot(&name).is_none(),
        "gone with its last endpoint"
    );
}

/// A sink that hands over what was fed to it as one batch per flush: what the writer
/// would put on the socket in one go.
struct FlushBatches {
    fed: Vec<WsMessage>,
    tx: tokio::sync::mpsc::UnboundedSender<Vec<WsMessage>>,
}

impl futures_util::Sink<WsMessage> for FlushBatches {
    type Error = WsError;
    fn poll_ready(
        self: std::pin::Pin<&mut Self>,
        _: &mut std::task::Context<'_>,
    ) -> std::task::Poll<Result<(), WsError>> {
        std::task::Poll::Ready(Ok(()))
    }
    fn start_send(mut self: std::pin::Pin<&mut Self>, m: WsMessage) -> Result<(), WsError> {
        self.fed.push(m);
        Ok(())
    }
    fn poll_flush(
        mut self: std::pin::Pin<&mut Self>,
        _: &mut std::task::Context<'_>,
    ) -> std::task::Poll<Result<(), WsError>> {
        if !self.fed.is_empty() {
            let batch = std::mem::take(&mut self.fed);
            if self.tx.send(batch).is_err() {
                return std::task::Poll::Ready(Err(WsError::ConnectionClosed));
            }
        }
        std::task::Poll::Ready(Ok(()))
    }
    fn poll_close(
        self: std::pin::Pin<&mut Self>,
        cx: &mut std::task::Context<'_>,
    ) -> std::task::Poll<Result<(), WsError>> {
        self.poll_flush(cx)
    }
}

/// Issues 10 and 11: on the agent's uplink a large message goes out as many chunks as the
/// link's window allows in one flush (one system call), not one flush per chunk, and the
/// next window's worth only after the hub acknowledges.
#[tokio::test]
async fn the_uplink_writes_a_window_of_chunks_in_one_flush() {
    use fleetlink_relay::link_control::FIRST_CHUNK;
    use std::time::Instant;

    let router = Arc::new(Router::default());
    let (outbox, publisher) = uplink_and_publisher(&router);
    let cloud = router
        .advertise(
            publisher,
            &TopicName::parse("/cloud").unwrap(),
            Schema::named("t/Blob"),
            false,
        )
        .unwrap();
    let (tx, mut batches) = tokio::sync::mpsc::unbounded_channel();
    let sink = FlushBatches {
        fed: Vec::new(),
        tx,
    };
    let (_ctrl_tx, ctrl_rx) = tokio::sync::mpsc::channel::<Box<Control>>(8);
    let writer = tokio::spawn(write_link(
        sink,
        outbox.clone(),
        ctrl_rx,
        Arc::new(|m| Some(m.name.to_string())),
        Vec::new(),
        None,
        None,
    ));
    let size = 8 * FIRST_CHUNK;
    cloud.publish(publisher, 1, 0, Payload::json(Bytes::from(vec![7u8; size])));
    let chunks_in = |batch: &[WsMessage]| -> Vec<(u64, usize)> {
        let mut out = Vec::new();
        for m in batch {
            let WsMessage::Binary(b) = m else { continue };
            for f in frame::frames(b) {
                if let Frame::Chunk { offset, data, .. } = f.expect("valid frames") {
                    out.push((offset, data.len()));
                }
            }
        }
        out
    };
    let next_batch_with_chunks =
        async |batches: &mut tokio::sync::mpsc::UnboundedReceiver<Vec<WsMessage>>| loop {
            let b = tokio::time::timeout(Duration::from_secs(10), batches.recv())
                .await
                .expect("the writer flushes")
                .expect("open");
            let c = chunks_in(&b);
            if !c.is_empty() {
                return c;
            }
        };
    // Before any rate is measured the window is two first-size chunks: both go out in the
    // first flush, and nothing more until the hub acknowledges them.
    let first = next_batch_with_chunks(&mut batches).await;
    assert_eq!(
        first,
        vec![(0, FIRST_CHUNK), (FIRST_CHUNK as u64, FIRST_CHUNK)],
        "one flush carries the window's chunks"
    );
    // Whatever the writer flushes meanwhile (its idle ticks, probes) carries no chunk;
    // looked at for 200 ms.
    let quiet = tokio::time::Instant::now() + Duration::from_millis(200);
    while let Ok(Some(b)) = tokio::time::timeout_at(quiet, batches.recv()).await {
        assert!(
            chunks_in(&b).is_empty(),
            "nothing beyond the window before an acknowledgement"
        );
    }
    let mut received: usize = first.iter().map(|c| c.1).sum();
    let mut offsets: Vec<u64> = first.iter().map(|c| c.0).collect();
    let mut acked = 0;
    while received < size {
        // The hub acknowledges what arrived.
        outbox.on_acked(0, (received - acked) as u64, Instant::now());
        acked = received;
        let more = next_batch_with_chunks(&mut batches).await;
        received += more.iter().map(|c| c.1).sum::<usize>();
        assert!(
            more.len() >= 2 || received == size,
            "a window's worth per flush: {more:?}"
        );
        offsets.extend(more.iter().map(|c| c.0));
    }
    assert_eq!(received, size);
    assert!(offsets.windows(2).all(|w| w[0] < w[1]), "{offsets:?}");
    writer.abort();
}

/// Every frame the writer sends within `wait` but the link estimator's probes (`PING`).
async fn frames_within(
    rx: &mut futures_channel::mpsc::Receiver<WsMessage>,
    wait: Duration,
) -> Vec<Frame> {
    let mut out = Vec::new();
    while let Ok(Some(WsMessage::Binary(b))) = tokio::time::timeout(wait, rx.next()).await {
        out.extend(
            frame::frames(&b)
                .map(|f| f.expect("valid frames"))
                .filter(|f| !matches!(f, Frame::Ping { .. })),
        );
    }
    out
}

/// The payloads of the `MESSAGE` frames among `frames`, in order.
fn message_payloads(frames: &[Frame]) -> Vec<Vec<u8>> {
    frames
        .iter()
        .filter_map(|f| match f {
            Frame::Message { payload, .. } => Some(payload.to_vec()),
            _ => None,
        })
        .collect()
}

/// A demand-driven uplink: a topic nobody wants is announced but its messages are held
/// back; when interest comes its latest message goes at once (no new publish needed),
/// then every message while it is wanted, and nothing once interest is gone. An uplink
/// whose peer never spoke of interest sends everything.
#[tokio::test]
async fn a_demand_driven_uplink_sends_a_topic_only_while_it_is_wanted() {
    let router = Arc::new(Router::default());
    let (outbox, publisher) = uplink_and_publisher(&router);
    let map = router
        .advertise(
            publisher,
            &TopicName::parse("/map").unwrap(),
            Schema::named("t/Map"),
            false,
        )
        .unwrap();
    outbox.set_demand_driven(true);
    let (_ctrl_tx, mut rx, writer) = spawn_writer(outbox.clone(), 16);
    for i in 0..5u8 {
        map.publish(publisher, u64::from(i), 0, Payload::json(vec![b'0' + i]));
    }
    let frames = frames_within(&mut rx, Duration::from_millis(200)).await;
    let alias = match frames.as_slice() {
        [Frame::Advertise { alias, topic, .. }] if topic == "/map" => *alias,
        other => panic!("expected the topic announced and nothing else, got {other:?}"),
    };
    assert!(outbox.is_held_back(alias));
    assert_eq!(
        map.stats
            .held_back
            .load(std::sync::atomic::Ordering::Relaxed),
        5
    );

    // Interest: the latest message at once, then what is published.
    outbox.set_wanted(alias, true, std::time::Instant::now());
    let got = frames_within(&mut rx, Duration::from_millis(200)).await;
    assert_eq!(message_payloads(&got), vec![b"4".to_vec()]);
    map.publish(publisher, 5, 0, Payload::json(&b"5"[..]));
    let got = frames_within(&mut rx, Duration::from_millis(200)).await;
    assert_eq!(message_payloads(&got), vec![b"5".to_vec()]);

    // No interest: nothing more goes.
    outbox.set_wanted(alias, false, std::time::Instant::now());
    map.publish(publisher, 6, 0, Payload::json(&b"6"[..]));
    let got = frames_within(&mut rx, Duration::from_millis(200)).await;
    assert!(message_payloads(&got).is_empty(), "{got:?}");

    // A peer that does not speak of interest gets everything.
    outbox.set_demand_driven(false);
    map.publish(publisher, 7, 0, Payload::json(&b"7"[..]));
    let got = frames_within(&mut rx, Duration::from_millis(200)).await;
    assert_eq!(message_payloads(&got), vec![b"7".to_vec()]);
    writer.abort();
}

/// The router tells a publisher that watches demand when its topic gains or loses the
/// subscribers that count (not the publisher's own subscriptions), coalesced.
#[tokio::test]
async fn a_publisher_hears_when_demand_for_its_topic_changes() {
    let router = Arc::new(Router::default());
    let (robot, _) = router.connect(ClientKind::Agent { robot: "r".into() }, None);
    let watch = router.watch_demand(robot);
    let topic = router
        .advertise(
            robot,
            &TopicName::parse("/r/scan").unwrap(),
            Schema::named("t/Scan"),
            false,
        )
        .unwrap();
    // The robot's own pattern subscription to its namespace is no demand.
    router
        .subscribe(
            robot,
            Target::Pattern(Router::compile_pattern("/r/.*").unwrap()),
            SubOptions::default(),
        )
        .unwrap();
    assert_eq!(watch.take(), vec![topic.id()]);
    assert!(!topic.wanted_by_others(robot));

    let (viewer, _) = router.connect(ClientKind::Rosbridge, None);
    let sid = router
        .subscribe(
            viewer,
            Target::Exact(TopicName::parse("/r/scan").unwrap()),
            SubOptions::default(),
        )
        .unwrap();
    tokio::time::timeout(Duration::from_secs(5), watch.changed())
        .await
        .expect("woken");
    assert_eq!(watch.take(), vec![topic.id()]);
    assert!(topic.wanted_by_others(robot));

    // Churn between two looks is one entry.
    router.unsubscribe(viewer, sid);
    router
        .subscribe(
            viewer,
            Target::Exact(TopicName::parse("/r/scan").unwrap()),
            SubOptions::default(),
        )
        .unwrap();
    router.disconnect(viewer);
    assert_eq!(watch.take(), vec![topic.id()]);
    assert!(!topic.wanted_by_others(robot));
    assert!(watch.take().is_empty());
}

/// An age limit: a message older than its topic's `max_age` when its turn comes is not
/// sent (counted `too_old`), and a held-back topic's latest message that has grown too old
/// is not sent when interest comes.
#[tokio::test]
async fn messages_past_their_topics_age_limit_are_not_sent() {
    use fleetlink_relay::queue::DropReason;
    let router = Arc::new(Router::default());
    let qos = fleetlink_qos::TopicQos {
        max_age_ms: Some(100),
        ..Default::default()
    };
    let (outbox, publisher) = uplink_with_qos(&router, qos);
    let scan = router
        .advertise(
            publisher,
            &TopicName::parse("/scan").unwrap(),
            Schema::named("t/Scan"),
            false,
        )
        .unwrap();
    // Queued while no writer runs (the link is down), then aged past the limit.
    scan.publish(publisher, 1, 0, Payload::json(&b"1"[..]));
    tokio::time::sleep(Duration::from_millis(250)).await;
    scan.publish(publisher, 2, 0, Payload::json(&b"2"[..]));
    let (_ctrl_tx, mut rx, writer) = spawn_writer(outbox.clone(), 16);
    let sent = message_payloads(&frames_within(&mut rx, Duration::from_millis(200)).await);
    assert_eq!(sent, vec![b"2".to_vec()], "the stale message went out");
    assert_eq!(scan.stats.drops(DropReason::TooOld), 1);

    // Held back until its latest message is too old: interest sends nothing stale.
    outbox.set_demand_driven(true);
    scan.publish(publisher, 3, 0, Payload::json(&b"3"[..]));
    tokio::time::sleep(Duration::from_millis(250)).await;
    let alias = scan.id().0;
    outbox.set_wanted(alias, true, std::time::Instant::now());
    let got = frames_within(&mut rx, Duration::from_millis(200)).await;
    assert!(
        !got.iter().any(|f| matches!(f, Frame::Message { .. })),
        "{got:?}"
    );
    writer.abort();
}

/// A pull topic: announced flagged `ADVERTISE_PULL`, never sent by itself (even when
/// wanted); each pull sends its latest message once.
#[tokio::test]
async fn a_pull_topic_goes_out_only_when_pulled() {
    let router = Arc::new(Router::default());
    let qos = fleetlink_qos::TopicQos {
        mode: fleetlink_qos::Mode::Pull,
        ..Default::default()
    };
    let (outbox, publisher) = uplink_with_qos(&router, qos);
    let map = router
        .advertise(
            publisher,
            &TopicName::parse("/map").unwrap(),
            Schema::named("t/Map"),
            false,
        )
        .unwrap();
    outbox.set_demand_driven(true);
    let (_ctrl_tx, mut rx, writer) = spawn_writer(outbox.clone(), 16);
    map.publish(publisher, 1, 0, Payload::json(&b"1"[..]));
    map.publish(publisher, 2, 0, Payload::json(&b"2"[..]));
    let frames = frames_within(&mut rx, Duration::from_millis(200)).await;
    let alias = match frames.as_slice() {
        [Frame::Advertise { alias, flags, .. }] if flags & frame::ADVERTISE_PULL != 0 => *alias,
        other => panic!("expected the topic announced as pull, got {other:?}"),
    };
    outbox.set_wanted(alias, true, std::time::Instant::now());
    map.publish(publisher, 3, 0, Payload::json(&b"3"[..]));
    let got = frames_within(&mut rx, Duration::from_millis(200)).await;
    assert!(got.is_empty(), "sent without a pull: {got:?}");
    for _ in 0..2 {
        outbox.pull(alias, std::time::Instant::now());
        let got = frames_within(&mut rx, Duration::from_millis(200)).await;
        assert_eq!(message_payloads(&got), vec![b"3".to_vec()]);
    }
    writer.abort();
}

/// The latest-message cache is bounded for all topics together: a topic whose newest
/// message does not fit has none kept, so interest then waits for its next publish.
#[tokio::test]
async fn the_latest_message_cache_keeps_within_its_bound() {
    let router = Arc::new(Router::default());
    let (outbox, publisher) = uplink_and_publisher(&router);
    outbox.set_latest_limit(1000);
    let small = router
        .advertise(
            publisher,
            &TopicName::parse("/small").unwrap(),
            Schema::named("t/S"),
            false,
        )
        .unwrap();
    let big = router
        .advertise(
            publisher,
            &TopicName::parse("/big").unwrap(),
            Schema::named("t/B"),
            false,
        )
        .unwrap();
    outbox.set_demand_driven(true);
    let (_ctrl_tx, mut rx, writer) = spawn_writer(outbox.clone(), 16);
    small.publish(publisher, 1, 0, Payload::json(vec![b's'; 600]));
    big.publish(publisher, 1, 0, Payload::json(vec![b'b'; 600]));
    let announced = frames_within(&mut rx, Duration::from_millis(200)).await;
    let alias = |name: &str| {
        announced
            .iter()
            .find_map(|f| match f {
                Frame::Advertise { alias, topic, .. } if topic == name => Some(*alias),
                _ => None,
            })
            .unwrap_or_else(|| panic!("{name} not announced: {announced:?}"))
    };
    let (s, b) = (alias("/small"), alias("/big"));
    // 600 + 600 bytes do not fit 1000: the second topic has nothing kept.
    outbox.set_wanted(s, true, std::time::Instant::now());
    outbox.set_wanted(b, true, std::time::Instant::now());
    let got = frames_within(&mut rx, Duration::from_millis(200)).await;
    let sizes: Vec<usize> = message_payloads(&got).iter().map(Vec::len).collect();
    assert_eq!(sizes, vec![600], "{got:?}");
    writer.abort();
}

/// A held-back topic withdrawn (`UNADVERTISE`, its publisher gone) and published again is
/// announced again, so the peer can still ask for it.
#[tokio::test]
async fn a_held_back_topic_published_again_after_its_unadvertise_is_announced_again() {
    let router = Arc::new(Router::default());
    let (outbox, publisher) = uplink_and_publisher(&router);
    let odom = router
        .advertise(
            publisher,
            &TopicName::parse("/odom").unwrap(),
            Schema::named("t/O"),
            false,
        )
        .unwrap();
    outbox.set_demand_driven(true);
    let (ctrl_tx, mut rx, writer) = spawn_writer(outbox.clone(), 16);
    odom.publish(publisher, 1, 0, Payload::json(&b"1"[..]));
    let advertises = |fs: &[Frame]| {
        fs.iter()
            .filter(|f| matches!(f, Frame::Advertise { .. }))
            .count()
    };
    assert_eq!(
        advertises(&frames_within(&mut rx, Duration::from_millis(200)).await),
        1
    );
    ctrl_tx
        .send(Box::new(Control::Unadvertise {
            topic: odom.id(),
            since: std::time::Instant::now(),
        }))
        .await
        .unwrap();
    let got = frames_within(&mut rx, Duration::from_millis(200)).await;
    assert!(
        got.iter().any(|f| matches!(f, Frame::Unadvertise { .. })),
        "{got:?}"
    );
    odom.publish(publisher, 2, 0, Payload::json(&b"2"[..]));
    let got = frames_within(&mut rx, Duration::from_millis(200)).await;
    assert_eq!(advertises(&got), 1, "not announced again: {got:?}");
    assert!(
        !got.iter().any(|f| matches!(f, Frame::Message { .. })),
        "{got:?}"
    );
    writer.abort();
}

/// xorshift noise: bytes no compressor can shrink.
fn noise(n: usize, seed: u64) -> Vec<u8> {
    let mut x = seed | 1;
    (0..n)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x as u8
        })
        .collect()
}

/// Per-topic compression on the uplink (`compression: auto`, the default): a message
/// that shrinks goes out compressed (`ZMESSAGE`, or `ZCHUNK`s when still large), one that
/// does not goes out as it is, and the receiving side gets every payload back exactly. A
/// peer that did not offer compression gets nothing compressed.
#[tokio::test]
async fn the_uplink_compresses_what_pays_and_the_link_opens_it() {
    use fleetlink_relay::link::{LinkEvent, LinkIn};
    let router = Arc::new(Router::default());
    let (outbox, publisher) = uplink_and_publisher(&router);
    let cloud = router
        .advertise(
            publisher,
            &TopicName::parse("/cloud").unwrap(),
            Schema::named("sensor_msgs/PointCloud2"),
            false,
        )
        .unwrap();
    let jpeg = router
        .advertise(
            publisher,
            &TopicName::parse("/jpeg").unwrap(),
            Schema::named("sensor_msgs/CompressedImage"),
            false,
        )
        .unwrap();
    outbox.set_compression_allowed(true);
    let (_ctrl_tx, mut rx, writer) = spawn_writer(outbox.clone(), 64);
    // A repetitive cloud (shrinks to a small ZMESSAGE), a large one with a noisy part
    // (still larger than a chunk once compressed: ZCHUNKs), and noise (sent as it is).
    let small_cloud: Vec<u8> = (0..200_000u32).map(|i| (i % 251) as u8).collect();
    let mut big_cloud = noise(40_000, 7);
    big_cloud.extend(std::iter::repeat_n(0u8, 400_000));
    let picture = noise(20_000, 3);
    cloud.publish(
        publisher,
        1,
        0,
        Payload::new(fleetlink_proto::Encoding::Cdr, small_cloud.clone()),
    );
    cloud.publish(
        publisher,
        2,
        0,
        Payload::new(fleetlink_proto::Encoding::Cdr, big_cloud.clone()),
    );
    jpeg.publish(
        publisher,
        1,
        0,
        Payload::new(fleetlink_proto::Encoding::Cdr, picture.clone()),
    );

    let mut link = LinkIn::default();
    let mut got: Vec<(u32, Vec<u8>, usize)> = Vec::new();
    let (mut z, mut plain) = (0, 0);
    let deadline = tokio::time::Instant::now() + Duration::from_secs(10);
    while got.len() < 3 && tokio::time::Instant::now() < deadline {
        for f in frames_within(&mut rx, Duration::from_millis(200)).await {
            match &f {
                Frame::ZMessage { .. } | Frame::ZChunk { .. } => z += 1,
                Frame::Message { .. } | Frame::Chunk { .. } => plain += 1,
                _ => {}
            }
            if let LinkEvent::Message {
                alias,
                payload,
                wire_len,
                ..
            } = link.on_frame(f).expect("frames the link takes")
            {
                got.push((alias, payload.bytes.to_vec(), wire_len));
            }
        }
        // Acknowledge what arrived, so the uplink's window lets the chunks go.
        if let Some(Frame::Ack { frames, bytes }) = link.take_ack() {
            outbox.on_acked(frames as usize, bytes, std::time::Instant::now());
        }
    }
    writer.abort();
    assert_eq!(
        got.len(),
        3,
        "three messages arrive ({z} compressed frames, {plain} plain)"
    );
    let by = |want: &[u8]| {
        got.iter()
            .find(|(_, p, _)| p == want)
            .map(|(_, p, wire)| (p.len(), *wire))
            .expect("payload arrives intact")
    };
    let (raw, wire) = by(&small_cloud);
    assert!(
        wire * 20 < raw,
        "repetitive cloud: {wire} of {raw} bytes on the link"
    );
    let (raw, wire) = by(&big_cloud);
    assert!(
        wire < raw / 5 && wire > 16 * 1024,
        "big cloud: {wire} of {raw}"
    );
    let (raw, wire) = by(&picture);
    assert_eq!(wire, raw, "noise goes as it is");
    assert!(z >= 3, "a ZMESSAGE and several ZCHUNKs, got {z}");
    assert!(plain >= 1, "the picture in plain frames");
}

/// An uplink whose peer did not offer compression (an older hub) sends every message as
/// it is.
#[tokio::test]
async fn nothing_is_compressed_for_a_peer_that_did_not_offer_it() {
    let router = Arc::new(Router::default());
    let (outbox, publisher) = uplink_and_publisher(&router);
    let t = router
        .advertise(
            publisher,
            &TopicName::parse("/cloud").unwrap(),
            Schema::named("sensor_msgs/PointCloud2"),
            false,
        )
        .unwrap();
    let (_ctrl_tx, mut rx, writer) = spawn_writer(outbox.clone(), 16);
    t.publish(
        publisher,
        1,
        0,
        Payload::new(fleetlink_proto::Encoding::Cdr, vec![0u8; 8_000]),
    );
    // Until the message (estimator probes follow while it is unacknowledged).
    let mut got = Vec::new();
    while !got
        .iter()
        .any(|f| matches!(f, Frame::Message { .. } | Frame::ZMessage { .. }))
    {
        got.extend(next_frames(&mut rx).await);
    }
    writer.abort();
    assert_eq!(message_payloads(&got), vec![vec![0u8; 8_000]], "{got:?}");
}

/// A compressed message that lies (claims more than the message limit, or is not what its
/// codec says) is an error naming the topic; the link's next message is taken as usual.
#[test]
fn a_bad_compressed_message_is_refused_and_the_link_goes_on() {
    use fleetlink_relay::link::{LinkError, LinkEvent, LinkIn, MAX_LINK_MESSAGE};
    let mut link = LinkIn::default();
    link.on_frame(Frame::Advertise {
        alias: 1,
        topic: "/cloud".into(),
        schema: Schema::named("sensor_msgs/PointCloud2"),
        encoding: fleetlink_proto::Encoding::Cdr,
        flags: 0,
    })
    .unwrap();
    let mut bomb = bytes::BytesMut::new();
    bomb.extend_from_slice(&[2]);
    fleetlink_proto::wire::put_varint(&mut bomb, MAX_LINK_MESSAGE as u64 + 1);
    bomb.extend_from_slice(&[0; 16]);
    for payload in [bomb.freeze(), Bytes::from_static(b"\x01\x40garbage")] {
        let e = link
            .on_frame(Frame::ZMessage {
                alias: 1,
                seq: 1,
                stamp_ns: 0,
                payload,
            })
            .unwrap_err();
        assert!(matches!(e, LinkError::Compression { .. }), "{e}");
        assert!(e.to_string().contains("/cloud"), "{e}");
    }
    let ok = link
        .on_frame(Frame::Message {
            alias: 1,
            seq: 2,
            stamp_ns: 0,
            payload: Bytes::from_static(b"fine"),
        })
        .unwrap();
    assert!(
        matches!(
            ok,
            LinkEvent::Message {
                seq: 2,
                wire_len: 4,
                ..
            }
        ),
        "{ok:?}"
    );
}

/// Between hubs (issue 40): the writer marks each message with the hubs it passed, this
/// hub last, writing `VIA` only when the way changes, and sends nothing that has passed
/// the peer hub.
#[tokio::test]
async fn a_link_between_hubs_marks_messages_with_the_hubs_they_passed() {
    use fleetlink_relay::link::ViaOut;
    use fleetlink_relay::message::Via;
    use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
    let router = Arc::new(Router::default());
    let (outbox, publisher) = link_and_publisher(&router, ".*");
    let topic = router
        .advertise(
            publisher,
            &TopicName::parse("/chat").unwrap(),
            Schema::named("std_msgs/msg/String"),
            false,
        )
        .unwrap();
    let (tx, mut rx) = futures_channel::mpsc::channel::<WsMessage>(64);
    let sink = tx.sink_map_err(|_| WsError::ConnectionClosed);
    let (_ctrl_tx, ctrl_rx) = tokio::sync::mpsc::channel::<Box<Control>>(8);
    let peer = Arc::new(AtomicU64::new(0));
    let via = ViaOut {
        me: 10,
        peer: peer.clone(),
        always: false,
    };
    let _writer = tokio::spawn(write_link(
        sink,
        outbox,
        ctrl_rx,
        Arc::new(|m| Some(m.name.to_string())),
        Vec::new(),
        None,
        Some(via),
    ));
    let send = |data: &str, via: Option<Vec<u64>>| {
        let msg = fleetlink_relay::Message::new(
            topic.meta(),
            1,
            0,
            publisher,
            Payload::json(Bytes::from(format!("{{\"data\":\"{data}\"}}"))),
        )
        .with_via(via.map(|v| Arc::new(Via::new(v))));
        topic.deliver(&Arc::new(msg));
    };
    // The peer is not known to be a hub yet: no VIA at all.
    send("plain", None);
    let frames = next_frames(&mut rx).await;
    assert!(
        !frames.iter().any(|f| matches!(f, Frame::Via { .. })),
        "{frames:?}"
    );
    // Once it is (its own VIA said so), every message is marked, the way written once.
    peer.store(20, Relaxed);
    send("here-1", None);
    send("here-2", None);
    send("from-30", Some(vec![30]));
    send("back-to-20", Some(vec![30, 20]));
    send("from-30-again", Some(vec![30]));
    let mut seen = Vec::new();
    while seen
        .iter()
        .filter(|s: &&String| !s.starts_with("via"))
        .count()
        < 4
    {
        for f in next_frames(&mut rx).await {
            match f {
                Frame::Via { hubs } => seen.push(format!("via {hubs:?}")),
                Frame::Message { payload, .. } => {
                    let v: serde_json::Value = serde_json::from_slice(&payload).unwrap();
                    seen.push(v["data"].as_str().unwrap().to_owned());
                }
                _ => {}
            }
        }
    }
    assert_eq!(
        seen,
        [
            "via [10]",
            "here-1",
            "here-2",
            "via [30, 10]",
            "from-30",
            "from-30-again",
        ],
        "the message that passed the peer (20) is not sent"
    );
}
