//! permessage-deflate through the halves: compressed messages a client sends are read
//! inflated (and refused past the size limit or when not negotiated), and compressed
//! messages the writer is given go out with RSV1, readable by a client.

use std::time::Duration;

use bytes::{Bytes, BytesMut};
use futures_util::{SinkExt, StreamExt};
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio_tungstenite::tungstenite::error::{CapacityError, ProtocolError};
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};

use super::deflate::{self, DeflateConfig, Inflater};
use super::*;

const KEY: [u8; 4] = [9, 8, 7, 6];

/// A masked client frame; `rsv1` marks a compressed message's first frame.
fn frame(fin: bool, rsv1: bool, opcode: u8, payload: &[u8]) -> Vec<u8> {
    let mut out = vec![if fin { 0x80 } else { 0 } | if rsv1 { 0x40 } else { 0 } | opcode];
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
    out.extend_from_slice(&KEY);
    out.extend(payload.iter().enumerate().map(|(i, b)| b ^ KEY[i % 4]));
    out
}

async fn read_from(
    bytes: Vec<u8>,
    max: usize,
    inflating: bool,
) -> Vec<Result<ClientMessage, WsError>> {
    let (mut c, s) = tokio::io::duplex(1 << 20);
    let (_w, reader) = server(s, max);
    let mut reader = if inflating {
        reader.inflating()
    } else {
        reader
    };
    let writing = tokio::spawn(async move {
        c.write_all(&bytes).await.unwrap();
        c
    });
    let mut got = Vec::new();
    while let Ok(Some(m)) = tokio::time::timeout(Duration::from_secs(5), reader.next()).await {
        let end = m.is_err();
        got.push(m);
        if end {
            break;
        }
    }
    drop(writing);
    got
}

fn json(n: usize) -> Vec<u8> {
    let mut rng = fastrand::Rng::with_seed(n as u64);
    let mut s = String::from("{\"op\":\"publish\",\"topic\":\"/cloud\",\"msg\":{\"data\":[");
    for _ in 0..n {
        s.push_str(&format!("{},", rng.u32(..1000)));
    }
    s.push_str("0]}}");
    s.into_bytes()
}

#[tokio::test]
async fn compressed_client_messages_are_read_inflated_whole_or_fragmented() {
    let text = json(5000);
    let z = deflate::compress(&[&text]).expect("pays");
    let mut wire = frame(true, true, 0x1, &z);
    // Fragmented: RSV1 on the first frame only, a ping between the fragments.
    let (a, b) = z.split_at(z.len() / 2);
    wire.extend(frame(false, true, 0x2, a));
    wire.extend(frame(true, false, 0x9, b"hi"));
    wire.extend(frame(true, false, 0x0, b));
    // An uncompressed message on the same connection.
    wire.extend(frame(true, false, 0x1, b"plain"));
    let got: Vec<ClientMessage> = read_from(wire, 1 << 20, true)
        .await
        .into_iter()
        .map(|m| m.expect("valid"))
        .collect();
    assert_eq!(
        got,
        vec![
            ClientMessage::Text(text.clone().into()),
            ClientMessage::Ping("hi".into()),
            ClientMessage::Binary(text.into()),
            ClientMessage::Text("plain".into()),
        ]
    );
}

#[tokio::test]
async fn a_compressed_message_inflating_past_the_limit_is_a_capacity_error() {
    // 8 MB of zeros in a few KB: a small frame, refused once it inflates past 64 KB.
    let z = deflate::compress(&[&vec![0u8; 8 << 20]]).expect("pays");
    let got = read_from(frame(true, true, 0x2, &z), 64 << 10, true).await;
    match got.last() {
        Some(Err(WsError::Capacity(CapacityError::MessageTooLong { max_size, .. }))) => {
            assert_eq!(*max_size, 64 << 10)
        }
        other => panic!("expected too long, got {other:?}"),
    }
}

#[tokio::test]
async fn rsv1_is_refused_where_it_may_not_be() {
    let z = deflate::compress(&[&json(100)]).expect("pays");
    let refused = |got: Vec<Result<ClientMessage, WsError>>| match got.last() {
        Some(Err(WsError::Protocol(ProtocolError::NonZeroReservedBits))) => {}
        other => panic!("expected refused, got {other:?}"),
    };
    // Not negotiated.
    refused(read_from(frame(true, true, 0x1, &z), 1 << 20, false).await);
    // On a control frame, on a continuation, with RSV2.
    refused(read_from(frame(true, true, 0x9, b"x"), 1 << 20, true).await);
    let mut wire = frame(false, false, 0x1, b"a");
    wire.extend(frame(true, true, 0x0, b"b"));
    refused(read_from(wire, 1 << 20, true).await);
    let mut f = frame(true, false, 0x1, b"x");
    f[0] |= 0x20;
    refused(read_from(f, 1 << 20, true).await);
    // Bytes that do not inflate.
    let got = read_from(frame(true, true, 0x1, &[0xFF, 0xFF, 0xFF]), 1 << 20, true).await;
    assert!(
        matches!(got.last(), Some(Err(WsError::Io(e))) if e.kind() == std::io::ErrorKind::InvalidData),
        "{got:?}"
    );
}

/// The server frames in `wire`: (first byte, payload).
fn server_frames(mut wire: &[u8]) -> Vec<(u8, Vec<u8>)> {
    let mut out = Vec::new();
    while !wire.is_empty() {
        let (b0, n) = (wire[0], wire[1] & 0x7F);
        let (len, at) = match n {
            126 => (u16::from_be_bytes([wire[2], wire[3]]) as usize, 4),
            127 => (
                u64::from_be_bytes(wire[2..10].try_into().unwrap()) as usize,
                10,
            ),
            n => (n as usize, 2),
        };
        out.push((b0, wire[at..at + len].to_vec()));
        wire = &wire[at + len..];
    }
    out
}

#[tokio::test]
async fn compressed_messages_are_written_with_rsv1_and_a_shared_body() {
    let (mut c, s) = tokio::io::duplex(1 << 22);
    let (w, _r) = server(s, 1 << 20);
    assert_eq!(w.deflate(), None);
    let mut w = w.deflating(DeflateConfig::default());
    assert_eq!(w.deflate(), Some(DeflateConfig::default()));
    let text = json(20_000);
    let z = deflate::compress(&[&text]).expect("pays");
    assert!(z.len() > COPY_UP_TO, "the body is queued, not copied");
    let small = deflate::compress(&[&json(200)]).expect("pays");
    let mut head = BytesMut::new();
    deflate::stored_block(&mut head, &[1, 0, 0, 0, 7]);
    feed_deflated(&mut w, true, &[], &z).await.unwrap();
    feed_deflated(&mut w, false, &head, &small).await.unwrap();
    w.feed(WsMessage::text("plain")).await.unwrap();
    w.close().await.unwrap();
    let mut wire = Vec::new();
    c.read_to_end(&mut wire).await.unwrap();
    let frames = server_frames(&wire);
    let inflate = |p: &[u8]| Inflater::new(1 << 24).inflate(p).expect("inflates");
    assert_eq!(frames[0].0, 0xC1);
    assert_eq!(inflate(&frames[0].1), Bytes::from(text));
    assert_eq!(frames[1].0, 0xC2);
    let mut want = vec![1, 0, 0, 0, 7];
    want.extend_from_slice(&json(200));
    assert_eq!(inflate(&frames[1].1), Bytes::from(want));
    assert_eq!(frames[2], (0x81, b"plain".to_vec()));
    assert_eq!(frames[3].0, 0x88);
}
