//! Arbitrary bytes as what a WebSocket client sends the hub: read whole and read in
//! pieces (the first byte sets their size), the decoder must give the same messages and
//! the same verdict, never panic, and never hand on a data message over its limit.

#![no_main]

use bytes::{BufMut, BytesMut};
use fleetlink_relay::websocket::ClientMessage;
use fleetlink_relay::websocket::frames::Decoder;
use libfuzzer_sys::fuzz_target;

const MAX_MESSAGE: usize = 4096;

/// Every message `data` decodes to, fed `piece` bytes at a time, and whether it ended in
/// an error.
fn read(data: &[u8], piece: usize) -> (Vec<ClientMessage>, bool) {
    let mut d = Decoder::new(MAX_MESSAGE);
    let mut buf = BytesMut::new();
    let mut out = Vec::new();
    for chunk in data.chunks(piece) {
        buf.put_slice(chunk);
        loop {
            match d.decode(&mut buf) {
                Ok(Some(m)) => {
                    if let ClientMessage::Text(b) | ClientMessage::Binary(b) = &m {
                        assert!(b.len() <= MAX_MESSAGE);
                    }
                    out.push(m);
                }
                Ok(None) => break,
                Err(_) => return (out, true),
            }
        }
    }
    (out, false)
}

fuzz_target!(|data: &[u8]| {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let whole = read(rest, rest.len().max(1));
    let pieces = read(rest, usize::from(first % 32) + 1);
    assert_eq!(whole, pieces);
});
