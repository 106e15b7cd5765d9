//! Whole Foxglove sessions over in-memory sockets against a router: what a client sees
//! and what reaches the router, message for message. (The real Foxglove client is run
//! against a hub by tests/interop/foxglove.)

use std::sync::Arc;
use std::time::Duration;

use bytes::Bytes;
use fleetlink_foxglove::{SessionConfig, serve};
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::gate::SessionAuth;
use fleetlink_relay::router::{SubOptions, Target};
use fleetlink_relay::transcode::RegistryTranscoder;
use fleetlink_relay::{ClientKind, Router, TopicName, websocket};
use futures_util::{SinkExt, StreamExt};
use serde_json::{Value, json};
use tokio::io::DuplexStream;
use tokio_tungstenite::WebSocketStream;
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_tungstenite::tungstenite::protocol::Role;
use tokio_util::sync::CancellationToken;

type Client = WebSocketStream<DuplexStream>;

async fn connect(router: &Arc<Router>, shutdown: &CancellationToken) -> Client {
    let (c, s) = tokio::io::duplex(1 << 20);
    let (sink, stream) = websocket::server(s, 1 << 20);
    tokio::spawn(serve(
        sink,
        stream,
        router.clone(),
        None,
        Arc::new(SessionConfig::default()),
        shutdown.clone(),
        SessionAuth::open(),
    ));
    WebSocketStream::from_raw_socket(c, Role::Client, None).await
}

/// The next message; the bound is past the session's 5 s look at the rules, which the
/// tests on paused time wait for.
async fn next(c: &mut Client) -> WsMessage {
    tokio::time::timeout(Duration::from_secs(20), c.next())
        .await
        .expect("no timeout")
        .expect("not ended")
        .expect("no error")
}

/// The next text message, as JSON, whose `op` is `op`.
async fn next_op(c: &mut Client, op: &str) -> Value {
    loop {
        if let WsMessage::Text(t) = next(c).await {
            let v: Value = serde_json::from_str(&t).expect("JSON");
            if v["op"] == op {
                return v;
            }
        }
    }
}

async fn next_binary(c: &mut Client) -> Bytes {
    loop {
        if let WsMessage::Binary(b) = next(c).await {
            return b;
        }
    }
}

async fn send(c: &mut Client, v: Value) {
    c.send(WsMessage::text(v.to_string())).await.unwrap();
}

fn router() -> Arc<Router> {
    Arc::new(Router::new(Arc::new(RegistryTranscoder::bundled())))
}

#[tokio::test]
async fn two_subscribers_get_the_same_cdr_payload_under_their_own_subscription_ids() {
    let router = router();
    let shutdown = CancellationToken::new();
    let (robot, _) = router.connect(ClientKind::Internal { role: "sim".into() }, None);
    let name = TopicName::parse("/r1/chatter").unwrap();
    let topic = router
        .advertise(robot, &name, Schema::named("std_msgs/msg/String"), false)
        .unwrap();
    let mut clients = [
        connect(&router, &shutdown).await,
        connect(&router, &shutdown).await,
    ];
    for (c, sub) in clients.iter_mut().zip([1u32, 70]) {
        let info = next_op(c, "serverInfo").await;
        assert!(
            info["capabilities"]
                .as_array()
                .unwrap()
                .contains(&json!("clientPublish"))
        );
        let adv = next_op(c, "advertise").await;
        let ch = &adv["channels"][0];
        assert_eq!(ch["topic"], "/r1/chatter");
        assert_eq!(
            (ch["encoding"].as_str(), ch["schemaEncoding"].as_str()),
            (Some("cdr"), Some("ros2msg"))
        );
        assert_eq!(ch["schema"].as_str().map(str::trim), Some("string data"));
        let channel = ch["id"].as_u64().unwrap();
        send(
            c,
            json!({"op": "subscribe", "subscriptions": [{"id": sub, "channelId": channel}]}),
        )
        .await;
    }
    // The subscriptions are router subscriptions.
    tokio::time::timeout(Duration::from_secs(5), async {
        while topic.subscriber_count() < 2 {
            tokio::time::sleep(Duration::from_millis(5)).await;
        }
    })
    .await
    .expect("both subscribed");
    // One subscription per channel: a second is refused by name.
    let c = &mut clients[0];
    send(
        c,
        json!({"op": "subscribe", "subscriptions": [{"id": 2, "channelId": 1}]}),
    )
    .await;
    let st = next_op(c, "status").await;
    assert!(
        st["message"]
            .as_str()
            .unwrap()
            .contains("already subscribed as 1"),
        "{st}"
    );
    topic.publish(robot, 1, 5, Payload::json(r#"{"data":"hello"}"#));
    let want = router
        .transcoder()
        .convert(
            &topic.meta().schema,
            &Payload::json(r#"{"data":"hello"}"#),
            Encoding::Cdr,
        )
        .unwrap();
    for (c, sub) in clients.iter_mut().zip([1u32, 70]) {
        let b = next_binary(c).await;
        assert_eq!(b[0], 0x01, "MessageData");
        assert_eq!(&b[1..5], &sub.to_le_bytes());
        let received = u64::from_le_bytes(b[5..13].try_into().unwrap());
        assert!(
            received > 1_600_000_000_000_000_000,
            "a Unix time in ns: {received}"
        );
        assert_eq!(&b[13..], &want[..]);
    }
    shutdown.cancel();
}

#[tokio::test]
async fn bad_operations_get_a_status_error_and_the_session_goes_on() {
    let router = router();
    let shutdown = CancellationToken::new();
    let mut c = connect(&router, &shutdown).await;
    next_op(&mut c, "serverInfo").await;
    let cases: [(WsMessage, &str); 6] = [
        (WsMessage::text("{"), "malformed JSON"),
        (
            WsMessage::text(r#"{"op":"dance"}"#),
            "unknown operation 'dance'",
        ),
        (
            WsMessage::text(r#"{"op":"unsubscribe","subscriptionIds":[99]}"#),
            "no subscription 99",
        ),
        (
            WsMessage::text(r#"{"op":"subscribe","subscriptions":[{"id":1,"channelId":42}]}"#),
            "unknown channel 42",
        ),
        (
            WsMessage::Binary(Bytes::from_static(&[0x09])),
            "unknown binary opcode 0x09",
        ),
        (
            WsMessage::Binary(Bytes::from_static(&[0x01, 3, 0, 0, 0, 1])),
            "client channel 3 is not advertised",
        ),
    ];
    for (m, says) in cases {
        c.send(m).await.unwrap();
        let st = next_op(&mut c, "status").await;
        assert_eq!(st["level"], 2);
        let text = st["message"].as_str().unwrap();
        assert!(text.contains(says), "{text:?} should say {says:?}");
    }
    // Still serving: a client channel is taken.
    send(&mut c, json!({"op": "advertise", "channels": [{"id": 3, "topic": "/cmd", "encoding": "protobuf", "schemaName": "x/msg/Y"}]})).await;
    let st = next_op(&mut c, "status").await;
    assert!(
        st["message"]
            .as_str()
            .unwrap()
            .contains("'protobuf' is not supported"),
        "{st}"
    );
    shutdown.cancel();
}

#[tokio::test]
async fn a_client_publishes_json_checked_against_its_type() {
    let router = router();
    let shutdown = CancellationToken::new();
    let (viewer, outbox) = router.connect(
        ClientKind::Internal {
            role: "viewer".into(),
        },
        None,
    );
    let name = TopicName::parse("/r1/cmd_vel").unwrap();
    router
        .subscribe(viewer, Target::Exact(name.clone()), SubOptions::default())
        .unwrap();
    let mut c = connect(&router, &shutdown).await;
    next_op(&mut c, "serverInfo").await;
    send(&mut c, json!({"op": "advertise", "channels": [{"id": 5, "topic": "/r1/cmd_vel", "encoding": "json", "schemaName": "geometry_msgs/msg/Twist"}]})).await;
    let mut frame = vec![0x01, 5, 0, 0, 0];
    frame.extend_from_slice(br#"{"linear":{"x":1.5}}"#);
    c.send(WsMessage::Binary(frame.into())).await.unwrap();
    let mut items = Vec::new();
    tokio::time::timeout(Duration::from_secs(5), async {
        while items.is_empty() {
            outbox.take_into(&mut items, 10, 1 << 20, std::time::Instant::now());
            tokio::time::sleep(Duration::from_millis(5)).await;
        }
    })
    .await
    .expect("the publish reached the router");
    let msg = &items[0].2;
    let v: Value = serde_json::from_slice(&msg.payload.bytes).unwrap();
    // Completed against the type, as a rosbridge publish is.
    assert_eq!(v["linear"]["x"], 1.5);
    assert_eq!(v["angular"]["z"], 0.0);
    // A message that does not fit the type is refused by name.
    let mut bad = vec![0x01, 5, 0, 0, 0];
    bad.extend_from_slice(br#"{"linear":{"x":"fast"}}"#);
    c.send(WsMessage::Binary(bad.into())).await.unwrap();
    let st = next_op(&mut c, "status").await;
    assert!(
        st["message"]
            .as_str()
            .unwrap()
            .contains("does not fit its type"),
        "{st}"
    );
    shutdown.cancel();
}

#[tokio::test]
async fn a_robot_s_parameter_is_read_from_the_robot_and_a_hub_parameter_from_the_hub() {
    use fleetlink_relay::calls::{CallStatus, ChannelPeer, PeerMsg};
    let router = router();
    let shutdown = CancellationToken::new();
    // A robot whose agent answers parameter reads (as a ROS 1 or ROS 2 robot's does).
    let (robot, _) = router.connect(ClientKind::Agent { robot: "r1".into() }, None);
    let (peer, calls) = ChannelPeer::new();
    router.calls.attach(robot, peer);
    router.calls.advertise(
        robot,
        TopicName::parse("/r1/rosapi/get_param").unwrap(),
        Schema::named("rosapi/srv/GetParam"),
        false,
    );
    let table = router.calls.clone();
    tokio::spawn(async move {
        while let Some(m) = calls.recv().await {
            if let PeerMsg::Call(c) = m {
                let args: Value = serde_json::from_slice(&c.payload.bytes).unwrap();
                // The name as the robot sees it, relative to its namespace.
                assert_eq!(args["name"], "/max_speed");
                let answer = Payload::json(json!({"value": "2.5"}).to_string());
                table.respond(robot, c.id, CallStatus::Ok, Some(answer), String::new());
            }
        }
    });
    router.params.set("/hub_mode", json!("night").to_string());
    let mut c = connect(&router, &shutdown).await;
    next_op(&mut c, "serverInfo").await;
    send(
        &mut c,
        json!({"op": "getParameters", "parameterNames": ["/r1/max_speed", "/hub_mode", "/unset"], "id": "q1"}),
    )
    .await;
    let pv = next_op(&mut c, "parameterValues").await;
    assert_eq!(pv["id"], "q1");
    let mut got: Vec<(String, Value)> = pv["parameters"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (p["name"].as_str().unwrap().to_owned(), p["value"].clone()))
        .collect();
    got.sort_by(|a, b| a.0.cmp(&b.0));
    assert_eq!(
        got,
        vec![
            ("/hub_mode".to_owned(), json!("night")),
            ("/r1/max_speed".to_owned(), json!(2.5)),
        ]
    );
    shutdown.cancel();
}

/// A gate whose one rule (may the client see `/r1/secret`?) a test flips, telling its
/// sessions as the hub's rules do.
#[derive(Clone)]
struct Switch {
    allowed: Arc<std::sync::atomic::AtomicBool>,
    changed: Arc<tokio::sync::watch::Sender<u64>>,
}

impl Switch {
    fn set(&self, allowed: bool) {
        self.allowed
            .store(allowed, std::sync::atomic::Ordering::Relaxed);
        self.changed.send_modify(|g| *g += 1);
    }
}

impl fleetlink_relay::gate::Gate for Switch {
    fn allows(&mut self, name: &str, _op: fleetlink_relay::gate::Op) -> bool {
        name != "/r1/secret" || self.allowed.load(std::sync::atomic::Ordering::Relaxed)
    }
    fn fork(&self) -> Box<dyn fleetlink_relay::gate::Gate> {
        Box::new(self.clone())
    }
    fn rules_changed(&self) -> Option<tokio::sync::watch::Receiver<u64>> {
        Some(self.changed.subscribe())
    }
    fn principal(&self) -> String {
        "user:test".into()
    }
}

#[tokio::test(start_paused = true)]
async fn a_rule_change_shows_in_the_channels() {
    let router = router();
    let shutdown = CancellationToken::new();
    let (robot, _) = router.connect(ClientKind::Internal { role: "sim".into() }, None);
    for t in ["/r1/open", "/r1/secret"] {
        let name = TopicName::parse(t).unwrap();
        router
            .advertise(robot, &name, Schema::named("std_msgs/msg/String"), false)
            .unwrap();
    }
    let switch = Switch {
        allowed: Arc::default(),
        changed: Arc::new(tokio::sync::watch::Sender::new(0)),
    };
    let (cs, ss) = tokio::io::duplex(1 << 20);
    let (sink, stream) = websocket::server(ss, 1 << 20);
    let auth = SessionAuth {
        gate: Some(Box::new(switch.clone())),
        guard: None,
    };
    tokio::spawn(serve(
        sink,
        stream,
        router.clone(),
        None,
        Arc::new(SessionConfig::default()),
        shutdown.clone(),
        auth,
    ));
    let mut c = WebSocketStream::from_raw_socket(cs, Role::Client, None).await;
    let topics = |v: &Value| -> Vec<String> {
        v["channels"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c["topic"].as_str().unwrap().to_owned())
            .collect()
    };
    let first = next_op(&mut c, "advertise").await;
    assert_eq!(topics(&first), vec!["/r1/open"]);
    // Allowed now: the channel appears as the rules change, without a timer.
    switch.set(true);
    let more = tokio::time::timeout(Duration::from_millis(100), next_op(&mut c, "advertise"))
        .await
        .expect("the channel appears at once");
    assert_eq!(topics(&more), vec!["/r1/secret"]);
    let id = more["channels"][0]["id"].clone();
    // Refused again: it goes.
    switch.set(false);
    let gone = tokio::time::timeout(Duration::from_millis(100), next_op(&mut c, "unadvertise"))
        .await
        .expect("the channel goes at once");
    assert_eq!(gone["channelIds"], json!([id]));
    shutdown.cancel();
}
