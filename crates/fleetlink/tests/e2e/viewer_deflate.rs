//! Issue 56, item 2: permessage-deflate through the hub's own upgrade, on a raw socket so
//! every byte is seen. The offers a client may make (and those the hub declines), a
//! large publish arriving compressed to a viewer that negotiated it, and a compressed
//! message inflating past the size limit closing that viewer with 1009.

use fleetlink_relay::websocket::deflate::{self, Inflater};
use serde_json::{Value, json};
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::TcpStream;

use crate::util::*;

/// Upgrades a raw connection offering `extensions`; the socket and the answer's
/// `Sec-WebSocket-Extensions`, if any.
async fn upgrade(hub: &TestHub, extensions: Option<&str>) -> (TcpStream, Option<String>) {
    let mut tcp = TcpStream::connect(hub.addr).await.unwrap();
    let offer = extensions.map_or(String::new(), |e| {
        format!("Sec-WebSocket-Extensions: {e}\r\n")
    });
    let req = format!(
        "GET /?token={} HTTP/1.1\r\nHost: {}\r\nConnection: Upgrade\r\nUpgrade: websocket\r\n\
         Sec-WebSocket-Version: 13\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n{offer}\r\n",
        hub.operator_token, hub.addr
    );
    tcp.write_all(req.as_bytes()).await.unwrap();
    let mut head = Vec::new();
    while !head.ends_with(b"\r\n\r\n") {
        head.push(tcp.read_u8().await.unwrap());
    }
    let head = String::from_utf8(head).unwrap();
    assert!(head.starts_with("HTTP/1.1 101"), "{head}");
    let answer = head.lines().find_map(|l| {
        let (k, v) = l.split_once(':')?;
        k.eq_ignore_ascii_case("sec-websocket-extensions")
            .then(|| v.trim().to_owned())
    });
    (tcp, answer)
}

/// A masked client frame, RSV1 set when `compressed`.
fn client_frame(opcode: u8, compressed: bool, payload: &[u8]) -> Vec<u8> {
    let key = [1, 2, 3, 4];
    let mut out = vec![0x80 | if compressed { 0x40 } else { 0 } | opcode];
    match payload.len() {
        n if n <= 125 => out.push(0x80 | n as u8),
        n if n <= 0xFFFF => {
            out.push(0x80 | 126);
            out.extend_from_slice(&(n as u16).to_be_bytes());
        }
        n => {
            out.push(0x80 | 127);
            out.extend_from_slice(&(n as u64).to_be_bytes());
        }
    }
    out.extend_from_slice(&key);
    out.extend(payload.iter().enumerate().map(|(i, b)| b ^ key[i % 4]));
    out
}

/// The next server frame: its first byte and payload.
async fn server_frame(tcp: &mut TcpStream) -> (u8, Vec<u8>) {
    let read = async {
        let b0 = tcp.read_u8().await.unwrap();
        let len = match tcp.read_u8().await.unwrap() {
            126 => usize::from(tcp.read_u16().await.unwrap()),
            127 => tcp.read_u64().await.unwrap() as usize,
            n => usize::from(n),
        };
        let mut payload = vec![0; len];
        tcp.read_exact(&mut payload).await.unwrap();
        (b0, payload)
    };
    within("a server frame", read).await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue_56_the_hub_answers_offers_it_can_honour_and_declines_the_rest() {
    let hub = start_hub().await;
    let answer = "permessage-deflate; server_no_context_takeover; client_no_context_takeover";
    for (offer, want) in [
        // Chromium, Python websockets and node ws offer this.
        (
            "permessage-deflate; client_max_window_bits",
            Some(answer.to_owned()),
        ),
        // A smaller server window cannot be honoured; the next offer is taken.
        (
            "permessage-deflate; server_max_window_bits=10, permessage-deflate",
            Some(answer.to_owned()),
        ),
        (
            "permessage-deflate; server_max_window_bits=15",
            Some(format!("{answer}; server_max_window_bits=15")),
        ),
        ("permessage-deflate; server_max_window_bits=9", None),
        ("permessage-deflate; no_such_param", None),
        ("x-webkit-deflate-frame", None),
    ] {
        let (_tcp, got) = upgrade(&hub, Some(offer)).await;
        assert_eq!(got, want, "{offer}");
    }
    let (_tcp, got) = upgrade(&hub, None).await;
    assert_eq!(got, None);
    // Turned off: never negotiated.
    let off = start_hub_with(|c| c.viewer_deflate = None).await;
    let (_tcp, got) = upgrade(&off, Some("permessage-deflate")).await;
    assert_eq!(got, None);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue_56_a_large_publish_arrives_compressed_and_a_zip_bomb_gets_1009() {
    let hub = start_hub_with(|c| c.max_message_size = 1 << 20).await;
    let (mut viewer, answer) = upgrade(&hub, Some("permessage-deflate")).await;
    assert!(answer.is_some());
    // The viewer's subscribe, itself compressed.
    let sub = json!({"op": "subscribe", "topic": "/deflate/text", "type": "std_msgs/msg/String"});
    let z = deflate::compress(&[sub.to_string().as_bytes()]);
    // Too small to pay: sent as it is then, RSV1 clear.
    let frame = match &z {
        Some(z) => client_frame(0x1, true, z),
        None => client_frame(0x1, false, sub.to_string().as_bytes()),
    };
    viewer.write_all(&frame).await.unwrap();
    let router = hub.state.router.clone();
    let topic = fleetlink_relay::TopicName::parse("/deflate/text").unwrap();
    eventually("the viewer's subscription", || {
        router
            .topic(&topic)
            .is_some_and(|t| t.subscriber_count() == 1)
    })
    .await;
    let text = "a line of a long report; ".repeat(4000);
    let mut publisher = Rosbridge::connect(&hub.ws_url()).await;
    publisher
        .send_all([
            json!({"op": "advertise", "topic": "/deflate/text", "type": "std_msgs/msg/String"}),
            json!({"op": "publish", "topic": "/deflate/text", "msg": {"data": text}}),
        ])
        .await;
    let (b0, payload) = server_frame(&mut viewer).await;
    assert_eq!(b0, 0xC1, "a compressed text frame");
    assert!(payload.len() * 10 < text.len(), "{} bytes", payload.len());
    let m: Value =
        serde_json::from_slice(&Inflater::new(1 << 24).inflate(&payload).unwrap()).unwrap();
    assert_eq!(m["op"], "publish");
    assert_eq!(m["msg"]["data"], text.as_str());
    // A few KB that inflate past the 1 MiB limit: 1009, and the hub serves the others.
    let bomb = deflate::compress(&[&vec![b' '; 4 << 20]]).unwrap();
    assert!(bomb.len() < 64 << 10);
    viewer
        .write_all(&client_frame(0x1, true, &bomb))
        .await
        .unwrap();
    let (b0, payload) = server_frame(&mut viewer).await;
    assert_eq!(b0, 0x88, "a close frame");
    assert_eq!(u16::from_be_bytes([payload[0], payload[1]]), 1009);
    let mut other = Rosbridge::connect(&hub.ws_url()).await;
    let reply = other.call("/rosapi/get_time", json!({}), "t").await;
    assert_eq!(reply["result"], true, "{reply}");
}
