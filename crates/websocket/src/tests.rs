//! The halves against tungstenite's client, over an in-memory pipe: what one side writes
//! the other reads, message for message.

use std::time::Duration;

use futures_util::{SinkExt, StreamExt};
use tokio::io::{AsyncWriteExt, DuplexStream};
use tokio_tungstenite::WebSocketStream;
use tokio_tungstenite::tungstenite::error::CapacityError;
use tokio_tungstenite::tungstenite::protocol::frame::coding::{CloseCode, Data, OpCode};
use tokio_tungstenite::tungstenite::protocol::frame::{Frame, FrameHeader};
use tokio_tungstenite::tungstenite::protocol::{CloseFrame, Role};

use super::*;

type Server = (
    Writer<tokio::io::WriteHalf<DuplexStream>>,
    Reader<tokio::io::ReadHalf<DuplexStream>>,
);

async fn pair(max: usize) -> (WebSocketStream<DuplexStream>, Server) {
    let (c, s) = tokio::io::duplex(1 << 20);
    let client = WebSocketStream::from_raw_socket(c, Role::Client, None).await;
    (client, server(s, max))
}

async fn next<S: Stream + Unpin>(s: &mut S) -> S::Item {
    tokio::time::timeout(Duration::from_secs(5), s.next())
        .await
        .expect("no timeout")
        .expect("not ended")
}

#[tokio::test]
async fn client_messages_of_every_kind_are_read_in_order() {
    let (mut client, (_w, mut reader)) = pair(4 << 20).await;
    let big: Vec<u8> = (0..1_000_000u32).map(|i| (i % 253) as u8).collect();
    client
        .send(WsMessage::text("{\"op\":\"publish\"}"))
        .await
        .unwrap();
    client
        .send(WsMessage::Binary(big.clone().into()))
        .await
        .unwrap();
    client.send(WsMessage::Ping("p".into())).await.unwrap();
    // A text message in three fragments, as a client may cut it.
    let frag = |data: &str, op, fin| WsMessage::Frame(Frame::message(data.to_owned(), op, fin));
    client
        .feed(frag("hel", OpCode::Data(Data::Text), false))
        .await
        .unwrap();
    client
        .feed(frag("lo ", OpCode::Data(Data::Continue), false))
        .await
        .unwrap();
    client
        .send(frag("wörld", OpCode::Data(Data::Continue), true))
        .await
        .unwrap();
    let text = |t: &str| ClientMessage::Text(Bytes::copy_from_slice(t.as_bytes()));
    let next_is = async |reader: &mut Reader<_>, want: ClientMessage| {
        assert_eq!(next(reader).await.unwrap(), want);
    };
    next_is(&mut reader, text("{\"op\":\"publish\"}")).await;
    next_is(&mut reader, ClientMessage::Binary(big.into())).await;
    next_is(&mut reader, ClientMessage::Ping("p".into())).await;
    next_is(&mut reader, text("hello wörld")).await;
    client
        .close(Some(CloseFrame {
            code: CloseCode::Away,
            reason: "leaving".into(),
        }))
        .await
        .unwrap();
    match next(&mut reader).await.unwrap() {
        ClientMessage::Close(Some(f)) => {
            assert_eq!((f.code, f.reason.as_str()), (CloseCode::Away, "leaving"))
        }
        other => panic!("expected the close, got {other:?}"),
    }
    assert!(reader.next().await.is_none(), "nothing after a close");
}

#[tokio::test]
async fn a_burst_in_one_write_comes_out_whole() {
    let (c, s) = tokio::io::duplex(4 << 20);
    let (_w, mut reader) = server(s, 1 << 20);
    // 5,000 masked frames written at once, as one socket read may hold them.
    let mut bytes = Vec::new();
    for i in 0..5_000u32 {
        let text = format!("{{\"n\":{i}}}");
        let header = FrameHeader {
            opcode: OpCode::Data(Data::Text),
            mask: Some([1, 2, 3, 4]),
            ..FrameHeader::default()
        };
        header.format(text.len() as u64, &mut bytes).unwrap();
        bytes.extend(
            text.bytes()
                .enumerate()
                .map(|(k, b)| b ^ [1, 2, 3, 4][k % 4]),
        );
    }
    let mut c = c;
    c.write_all(&bytes).await.unwrap();
    for i in 0..5_000u32 {
        assert_eq!(
            next(&mut reader).await.unwrap(),
            ClientMessage::Text(format!("{{\"n\":{i}}}").into())
        );
    }
}

#[tokio::test]
async fn server_messages_reach_the_client_as_sent() {
    let (mut client, (mut writer, _r)) = pair(1 << 20).await;
    let big: Vec<u8> = (0..3_000_000u32).map(|i| (i % 251) as u8).collect();
    let sent = vec![
        WsMessage::text("small"),
        WsMessage::Binary(big.into()),
        WsMessage::text("x".repeat(70_000)),
        WsMessage::Pong("p".into()),
        WsMessage::text("after"),
    ];
    let reading = tokio::spawn(async move {
        let mut got = Vec::new();
        while let Some(m) = client.next().await {
            match m {
                Ok(WsMessage::Close(c)) => {
                    got.push(WsMessage::Close(c));
                    break;
                }
                Ok(m) => got.push(m),
                Err(e) => panic!("client read failed: {e}"),
            }
        }
        got
    });
    for m in &sent {
        writer.feed(m.clone()).await.unwrap();
    }
    writer.flush().await.unwrap();
    let long_reason = "é".repeat(100); // 200 bytes: cut to fit a control frame
    writer
        .send(WsMessage::Close(Some(CloseFrame {
            code: CloseCode::Size,
            reason: long_reason.as_str().into(),
        })))
        .await
        .unwrap();
    let got = tokio::time::timeout(Duration::from_secs(10), reading)
        .await
        .unwrap()
        .unwrap();
    assert_eq!(got[..sent.len()], sent[..]);
    match &got[sent.len()] {
        WsMessage::Close(Some(f)) => {
            assert_eq!(f.code, CloseCode::Size);
            assert!(long_reason.starts_with(f.reason.as_str()) && f.reason.len() <= 123);
        }
        other => panic!("expected a close, got {other:?}"),
    }
    // Nothing may follow a close.
    assert!(matches!(
        writer.send(WsMessage::text("late")).await,
        Err(WsError::Protocol(ProtocolError::SendAfterClosing))
    ));
}

#[tokio::test]
async fn closing_the_writer_sends_a_close_and_ends_the_stream() {
    let (mut client, (mut writer, _r)) = pair(1 << 20).await;
    writer.feed(WsMessage::text("last")).await.unwrap();
    writer.close().await.unwrap();
    assert_eq!(next(&mut client).await.unwrap(), WsMessage::text("last"));
    assert_eq!(next(&mut client).await.unwrap(), WsMessage::Close(None));
}

#[tokio::test]
async fn an_oversized_message_ends_the_reader_with_a_capacity_error() {
    let (mut client, (_w, mut reader)) = pair(1000).await;
    client
        .send(WsMessage::Binary(vec![0; 1001].into()))
        .await
        .unwrap();
    match next(&mut reader).await {
        Err(WsError::Capacity(CapacityError::MessageTooLong { size, max_size })) => {
            assert_eq!((size, max_size), (1001, 1000));
        }
        other => panic!("expected too long, got {other:?}"),
    }
    assert!(reader.next().await.is_none());
}

#[tokio::test]
async fn a_connection_cut_mid_frame_is_an_error_and_a_clean_end_is_not() {
    let (c, s) = tokio::io::duplex(1024);
    let (_w, mut reader) = server(s, 1024);
    let mut c = c;
    c.write_all(&[0x81, 0x85, 1, 2]).await.unwrap(); // half a header
    drop(c);
    assert!(matches!(
        next(&mut reader).await,
        Err(WsError::Protocol(
            ProtocolError::ResetWithoutClosingHandshake
        ))
    ));
    let (c, s) = tokio::io::duplex(1024);
    let (_w, mut reader) = server(s, 1024);
    drop(c);
    assert!(reader.next().await.is_none());
}

#[tokio::test]
async fn a_binary_message_in_two_parts_arrives_as_one_whether_its_body_is_copied_or_not() {
    let (mut client, (mut writer, _r)) = pair(4 << 20).await;
    let small = Bytes::from_static(b"payload");
    let large = Bytes::from(
        (0..(COPY_UP_TO as u32 + 100))
            .map(|i| i as u8)
            .collect::<Vec<_>>(),
    );
    for body in [&small, &large] {
        feed_binary_parts(&mut writer, &[1, 2, 3], body)
            .await
            .unwrap();
    }
    writer.flush().await.unwrap();
    for body in [small, large] {
        let mut want = vec![1, 2, 3];
        want.extend_from_slice(&body);
        assert_eq!(
            next(&mut client).await.unwrap(),
            WsMessage::Binary(want.into())
        );
    }
}

#[tokio::test]
async fn an_idle_reader_holds_little_and_a_busy_one_reads_large() {
    let (mut client, (_w, mut reader)) = pair(4 << 20).await;
    client.send(WsMessage::binary(vec![1u8; 20])).await.unwrap();
    assert!(matches!(
        next(&mut reader).await,
        Ok(ClientMessage::Binary(_))
    ));
    assert!(
        reader.buf.capacity() <= 2 * FIRST_READ,
        "a heartbeat-sized read holds {} bytes",
        reader.buf.capacity()
    );
    // A burst (inside the pipe's 1 MB): reads grow while they fill the room given.
    for _ in 0..20 {
        client
            .feed(WsMessage::binary(vec![2u8; 30_000]))
            .await
            .unwrap();
    }
    client.flush().await.unwrap();
    for _ in 0..20 {
        assert!(
            matches!(next(&mut reader).await, Ok(ClientMessage::Binary(b)) if b.len() == 30_000)
        );
    }
    assert!(reader.chunk > FIRST_READ, "reads grew in a burst");
    // Small messages again: the reads shrink back and the burst's buffer is let go.
    for _ in 0..8 {
        client.send(WsMessage::binary(vec![3u8; 20])).await.unwrap();
        assert!(matches!(
            next(&mut reader).await,
            Ok(ClientMessage::Binary(_))
        ));
    }
    assert_eq!(reader.chunk, FIRST_READ);
    assert!(
        reader.buf.capacity() <= 2 * FIRST_READ,
        "after the burst the reader holds {} bytes",
        reader.buf.capacity()
    );
}
