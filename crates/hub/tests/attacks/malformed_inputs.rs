//! Hostile and broken rosbridge input, one test per attack. Each must get a `status`
//! error (or, for an oversized frame, a clean close) and the hub must keep serving the
//! attacker's other requests and every other client.

use std::sync::Arc;
use std::time::Duration;

use fleetlink_hub::{Hub, HubConfig};
use fleetlink_relay::GenericTranscoder;
use futures_util::{SinkExt, StreamExt};
use serde_json::{Value, json};
use tokio::net::TcpStream;
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::{MaybeTlsStream, WebSocketStream};
use tokio_util::sync::CancellationToken;

type Ws = WebSocketStream<MaybeTlsStream<TcpStream>>;
const WAIT: Duration = Duration::from_secs(20);

struct Fixture {
    url: String,
    stop: CancellationToken,
}

async fn hub() -> Fixture {
    let dir = std::env::temp_dir().join(format!(
        "fleetlink-malformed-{}-{:?}",
        std::process::id(),
        std::thread::current().id()
    ));
    let cfg = HubConfig {
        listen: "127.0.0.1:0".parse().unwrap(),
        data_dir: dir,
        max_message_size: 1 << 20,
        ..HubConfig::default()
    };
    let hub = Hub::bind(cfg, Arc::new(GenericTranscoder)).await.unwrap();
    // Attackers here are authenticated operators: what is tested is input handling.
    let token = hub
        .state()
        .security
        .store
        .mint_operator_token(
            &fleetlink_auth::UserName::new("attacker").unwrap(),
            &[fleetlink_auth::GroupName::new("admin").unwrap()],
            None,
            fleetlink_auth::UnixTime::now(),
        )
        .unwrap();
    let url = format!("ws://{}/?token={}", hub.local_addr(), token.expose());
    let stop = CancellationToken::new();
    let s = stop.clone();
    tokio::spawn(hub.run(async move { s.cancelled().await }));
    Fixture { url, stop }
}

async fn connect(url: &str) -> Ws {
    tokio::time::timeout(WAIT, tokio_tungstenite::connect_async(url))
        .await
        .unwrap()
        .unwrap()
        .0
}

/// The next text or binary frame as JSON; `None` when the connection closed.
async fn next(ws: &mut Ws) -> Option<Value> {
    loop {
        match tokio::time::timeout(WAIT, ws.next())
            .await
            .expect("hub answers in time")?
        {
            Ok(Message::Text(t)) => return Some(serde_json::from_str(t.as_str()).unwrap()),
            Ok(Message::Binary(b)) => {
                let j = fleetlink_proto::rosbridge::convert::cbor_to_json(&b).unwrap();
                return Some(serde_json::from_slice(&j).unwrap());
            }
            Ok(Message::Close(_)) | Err(_) => return None,
            Ok(_) => {}
        }
    }
}

async fn expect_status_error(ws: &mut Ws, needle: &str) -> Value {
    let v = next(ws).await.expect("connection stays open and answers");
    assert_eq!(v["op"], "status", "{v}");
    assert_eq!(v["level"], "error", "{v}");
    let msg = v["msg"].as_str().unwrap();
    assert!(
        msg.contains(needle),
        "status {msg:?} should mention {needle:?}"
    );
    v
}

/// The connection still works after the attack: a rosapi call is answered.
async fn still_serving(ws: &mut Ws) {
    ws.send(Message::text(
        json!({"op": "call_service", "service": "/rosapi/get_time", "id": "alive"}).to_string(),
    ))
    .await
    .unwrap();
    loop {
        let v = next(ws).await.expect("connection open");
        if v["op"] == "service_response" {
            assert_eq!(v["id"], "alive");
            assert_eq!(v["result"], true);
            return;
        }
    }
}

/// Another client can still subscribe and receive while the attacker is around.
async fn others_still_served(url: &str) {
    let mut a = connect(url).await;
    let mut b = connect(url).await;
    b.send(Message::text(
        json!({"op": "subscribe", "topic": "/probe"}).to_string(),
    ))
    .await
    .unwrap();
    a.send(Message::text(
        json!({"op": "advertise", "topic": "/probe", "type": "std_msgs/msg/String"}).to_string(),
    ))
    .await
    .unwrap();
    for _ in 0..200 {
        a.send(Message::text(
            json!({"op": "publish", "topic": "/probe", "msg": {"data": "x"}}).to_string(),
        ))
        .await
        .unwrap();
        if let Ok(Some(Ok(Message::Text(t)))) =
            tokio::time::timeout(Duration::from_millis(50), b.next()).await
        {
            let v: Value = serde_json::from_str(t.as_str()).unwrap();
            assert_eq!(v["topic"], "/probe");
            return;
        }
    }
    panic!("another client was not served after the attack");
}

async fn attack_text(text: String, needle: &str) {
    let f = hub().await;
    let mut ws = connect(&f.url).await;
    ws.send(Message::text(text)).await.unwrap();
    expect_status_error(&mut ws, needle).await;
    still_serving(&mut ws).await;
    others_still_served(&f.url).await;
    f.stop.cancel();
}

#[tokio::test]
async fn invalid_json_gets_a_status_error() {
    attack_text("{\"op\": \"publish\", ".into(), "invalid JSON").await;
}

#[tokio::test]
async fn invalid_cbor_gets_a_status_error() {
    let f = hub().await;
    let mut ws = connect(&f.url).await;
    ws.send(Message::binary(vec![0xbf, 0x61, 0x6f, 0xff, 0x00, 0x1c]))
        .await
        .unwrap();
    expect_status_error(&mut ws, "CBOR").await;
    still_serving(&mut ws).await;
    others_still_served(&f.url).await;
    f.stop.cancel();
}

#[tokio::test]
async fn unknown_op_is_named_in_the_error_and_id_echoed() {
    let f = hub().await;
    let mut ws = connect(&f.url).await;
    ws.send(Message::text(
        json!({"op": "launch_rockets", "id": "x1"}).to_string(),
    ))
    .await
    .unwrap();
    let v = expect_status_error(&mut ws, "launch_rockets").await;
    assert_eq!(v["id"], "x1");
    still_serving(&mut ws).await;
    f.stop.cancel();
}

#[tokio::test]
async fn missing_field_is_named() {
    attack_text(
        json!({"op": "advertise", "topic": "/a", "id": 3}).to_string(),
        "type",
    )
    .await;
}

#[tokio::test]
async fn wrongly_typed_field_is_named() {
    attack_text(
        json!({"op": "subscribe", "topic": "/a", "throttle_rate": "fast"}).to_string(),
        "throttle_rate",
    )
    .await;
}

#[tokio::test]
async fn publish_with_non_object_msg_is_refused() {
    let f = hub().await;
    let mut ws = connect(&f.url).await;
    ws.send(Message::text(
        json!({"op": "advertise", "topic": "/a", "type": "std_msgs/msg/String"}).to_string(),
    ))
    .await
    .unwrap();
    ws.send(Message::text(
        json!({"op": "publish", "topic": "/a", "msg": [1, 2]}).to_string(),
    ))
    .await
    .unwrap();
    expect_status_error(&mut ws, "must be an object").await;
    still_serving(&mut ws).await;
    f.stop.cancel();
}

#[tokio::test]
async fn publish_to_unadvertised_topic_is_refused() {
    attack_text(
        json!({"op": "publish", "topic": "/nobody", "msg": {}}).to_string(),
        "not advertised",
    )
    .await;
}

#[tokio::test]
async fn deeply_nested_json_is_refused() {
    let depth = 10_000;
    let text = format!(
        "{{\"op\":\"publish\",\"topic\":\"/a\",\"msg\":{}{}}}",
        "[".repeat(depth),
        "]".repeat(depth)
    );
    attack_text(text, "recursion").await;
}

#[tokio::test]
async fn deeply_nested_cbor_is_refused() {
    let f = hub().await;
    let mut ws = connect(&f.url).await;
    // {"op": "publish", "topic": "/a", "msg": [[[[ ... 10,000 levels ... ]]]]}
    let mut frame = vec![0xa3, 0x62, b'o', b'p', 0x67];
    frame.extend_from_slice(b"publish");
    frame.extend_from_slice(&[
        0x65, b't', b'o', b'p', b'i', b'c', 0x62, b'/', b'a', 0x63, b'm', b's', b'g',
    ]);
    frame.extend(std::iter::repeat_n(0x81u8, 10_000));
    frame.push(0x00);
    ws.send(Message::binary(frame)).await.unwrap();
    expect_status_error(&mut ws, "CBOR").await;
    still_serving(&mut ws).await;
    f.stop.cancel();
}

#[tokio::test]
async fn oversized_frame_gets_a_clean_close_and_others_are_served() {
    let f = hub().await;
    let mut ws = connect(&f.url).await;
    // 64 MiB, far over the 1 MiB limit this hub is configured with.
    let big = format!(
        "{{\"op\":\"publish\",\"topic\":\"/a\",\"msg\":{{\"data\":\"{}\"}}}}",
        "x".repeat(64 << 20)
    );
    let _ = ws.send(Message::text(big)).await;
    let mut closed_with = None;
    loop {
        match tokio::time::timeout(WAIT, ws.next())
            .await
            .expect("hub reacts in time")
        {
            Some(Ok(Message::Close(c))) => {
                closed_with = c;
                break;
            }
            Some(Ok(_)) => continue,
            Some(Err(_)) | None => break,
        }
    }
    if let Some(c) = closed_with {
        assert_eq!(u16::from(c.code), 1009, "close code for a too-big message");
    }
    others_still_served(&f.url).await;
    f.stop.cancel();
}

#[tokio::test]
async fn invalid_regex_subscription_is_refused() {
    attack_text(
        json!({"op": "subscribe", "topic": "/robot[0-9", "regex": true}).to_string(),
        "invalid subscription pattern",
    )
    .await;
}

#[tokio::test]
async fn catastrophic_regex_is_cheap_or_refused() {
    // Exponential for a backtracking engine; the regex crate matches in linear time, so
    // the subscription is accepted and topic creation stays fast.
    let f = hub().await;
    let mut ws = connect(&f.url).await;
    ws.send(Message::text(
        json!({"op": "subscribe", "topic": "(a+)+$", "regex": true, "id": "evil"}).to_string(),
    ))
    .await
    .unwrap();
    let mut p = connect(&f.url).await;
    let long = format!("/{}b", "a".repeat(900));
    p.send(Message::text(
        json!({"op": "advertise", "topic": long, "type": "std_msgs/msg/String"}).to_string(),
    ))
    .await
    .unwrap();
    still_serving(&mut ws).await;
    still_serving(&mut p).await;
    f.stop.cancel();
}

#[tokio::test]
async fn gigantic_regex_is_refused() {
    let pattern = format!(
        "({})",
        (0..5000)
            .map(|i| format!("/robot{i}/scan"))
            .collect::<Vec<_>>()
            .join("|")
    );
    attack_text(
        json!({"op": "subscribe", "topic": pattern, "regex": true}).to_string(),
        "invalid subscription pattern",
    )
    .await;
}

#[tokio::test]
async fn invalid_topic_name_is_refused() {
    attack_text(
        json!({"op": "subscribe", "topic": "/a b"}).to_string(),
        "topic",
    )
    .await;
}
