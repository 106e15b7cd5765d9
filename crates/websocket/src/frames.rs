//! RFC 6455 frames as a server reads and writes them, without I/O.
//!
//! [`Decoder::decode`] takes whole messages off the front of a read buffer: it checks
//! each frame header, unmasks the payload in place and hands the payload on as a slice
//! of that buffer (no copy), putting fragmented messages together up to the size limit.
//! [`encode_header`] writes a server frame's header (servers never mask).
//!
//! ```text
//!  byte 0: FIN | RSV1 RSV2 RSV3 | opcode (4 bits)     0x0 continue, 0x1 text, 0x2 binary,
//!                                                     0x8 close, 0x9 ping, 0xA pong
//!  byte 1: MASK | length (7 bits)                     126: u16 follows, 127: u64 follows
//!  [2 or 8 bytes of length, big-endian] [4 bytes of mask key when MASK] payload
//! ```
//!
//! When permessage-deflate was negotiated ([`Decoder::inflating`]), RSV1 on the first
//! frame of a data message marks it compressed: its frames are put together as they are
//! and inflated once whole, the result held to the same size limit ([`super::deflate`]).
//!
//! A frame is refused when it breaks the protocol (reserved bits or opcodes, a client
//! frame without a mask, a control frame that is fragmented or over 125 bytes, a
//! continuation without a start), when its message would exceed the limit — before any
//! of its payload is buffered — and when a close reason is not UTF-8. A text message's
//! UTF-8 is left to its reader ([`ClientMessage::Text`]).

use bytes::{Buf, BufMut, BytesMut};
use tokio_tungstenite::tungstenite::error::{CapacityError, ProtocolError};
use tokio_tungstenite::tungstenite::protocol::CloseFrame;
use tokio_tungstenite::tungstenite::protocol::frame::coding::{CloseCode, Data};
use tokio_tungstenite::tungstenite::{Error as WsError, Utf8Bytes};

use super::ClientMessage;
use super::deflate::{InflateError, Inflater};

/// Longest control frame payload (RFC 6455, 5.5).
const MAX_CONTROL: usize = 125;

/// Reads client frames into messages.
#[derive(Debug)]
pub struct Decoder {
    max_message: usize,
    /// A fragmented message being put together: whether it is text, and its bytes so far.
    partial: Option<(bool, BytesMut)>,
    /// The fragmented message being put together is compressed.
    partial_compressed: bool,
    /// permessage-deflate was negotiated: RSV1 marks a compressed message.
    inflater: Option<Inflater>,
}

/// What a frame header says, once checked.
struct Header {
    fin: bool,
    /// RSV1: the message this frame starts is compressed.
    compressed: bool,
    opcode: u8,
    /// Bytes the header takes, mask key included.
    len: usize,
    payload: usize,
    mask: [u8; 4],
}

impl Decoder {
    /// A decoder that refuses messages (whole, after reassembly) over `max_message` bytes.
    pub fn new(max_message: usize) -> Decoder {
        Decoder {
            max_message,
            partial: None,
            partial_compressed: false,
            inflater: None,
        }
    }

    /// The same decoder for a connection that negotiated permessage-deflate: compressed
    /// messages are inflated, and refused when they inflate past the size limit.
    pub fn inflating(mut self) -> Decoder {
        self.inflater = Some(Inflater::new(self.max_message));
        self
    }

    /// Bytes the next frame needs in all (header and payload) when `buf` holds less, so
    /// the reader can make room for it in one go.
    pub fn wanted(&self, buf: &[u8]) -> Option<usize> {
        match parse_header(buf, self.inflater.is_some()) {
            Ok(Some(h)) => Some(h.len.saturating_add(h.payload)),
            _ => None,
        }
    }

    /// Whether a fragmented message is waiting for more frames.
    pub fn in_message(&self) -> bool {
        self.partial.is_some()
    }

    /// Takes the next whole message off the front of `buf`, or `None` when `buf` does not
    /// hold one yet (nothing is consumed then, except completed fragments of a message).
    /// Control frames come out as they arrive, also between the fragments of a message.
    pub fn decode(&mut self, buf: &mut BytesMut) -> Result<Option<ClientMessage>, WsError> {
        loop {
            let Some(h) = parse_header(buf, self.inflater.is_some())? else {
                return Ok(None);
            };
            let so_far = match (&self.partial, h.opcode) {
                (Some((_, b)), 0x0) => b.len(),
                _ => 0,
            };
            if h.opcode < 8 && so_far.saturating_add(h.payload) > self.max_message {
                return Err(WsError::Capacity(CapacityError::MessageTooLong {
                    size: so_far.saturating_add(h.payload),
                    max_size: self.max_message,
                }));
            }
            if buf.len() - h.len < h.payload {
                return Ok(None);
            }
            buf.advance(h.len);
            let mut payload = buf.split_to(h.payload);
            unmask(&mut payload, h.mask);
            let text = match h.opcode {
                0x1 => true,
                0x2 => false,
                0x0 => {
                    let Some((text, mut whole)) = self.partial.take() else {
                        return Err(WsError::Protocol(ProtocolError::UnexpectedContinueFrame));
                    };
                    whole.extend_from_slice(&payload);
                    if !h.fin {
                        self.partial = Some((text, whole));
                        continue;
                    }
                    let compressed = std::mem::take(&mut self.partial_compressed);
                    return self.data(text, compressed, whole).map(Some);
                }
                0x8 => return close(payload).map(|c| Some(ClientMessage::Close(c))),
                0x9 => return Ok(Some(ClientMessage::Ping(payload.freeze()))),
                0xA => return Ok(Some(ClientMessage::Pong(payload.freeze()))),
                _ => unreachable!("parse_header refuses other opcodes"),
            };
            if let Some((was_text, _)) = self.partial {
                let kind = if was_text { Data::Text } else { Data::Binary };
                return Err(WsError::Protocol(ProtocolError::ExpectedFragment(kind)));
            }
            if !h.fin {
                self.partial = Some((text, payload));
                self.partial_compressed = h.compressed;
                continue;
            }
            return self.data(text, h.compressed, payload).map(Some);
        }
    }

    /// A whole data message, inflated when it came compressed.
    fn data(
        &mut self,
        text: bool,
        compressed: bool,
        payload: BytesMut,
    ) -> Result<ClientMessage, WsError> {
        let payload = match (compressed, &mut self.inflater) {
            (true, Some(inflater)) => inflater.inflate(&payload).map_err(|e| match e {
                InflateError::TooLong { limit } => {
                    WsError::Capacity(CapacityError::MessageTooLong {
                        size: limit.saturating_add(1),
                        max_size: limit,
                    })
                }
                InflateError::Invalid(cause) => WsError::Io(std::io::Error::new(
                    std::io::ErrorKind::InvalidData,
                    format!("a compressed message does not inflate: {cause}"),
                )),
            })?,
            _ => payload.freeze(),
        };
        Ok(if text {
            ClientMessage::Text(payload)
        } else {
            ClientMessage::Binary(payload)
        })
    }
}

/// A close frame's code and reason (RFC 6455, 5.5.1 and 7.4).
fn close(payload: BytesMut) -> Result<Option<CloseFrame>, WsError> {
    match payload.len() {
        0 => Ok(None),
        1 => Err(WsError::Protocol(ProtocolError::InvalidCloseSequence)),
        _ => {
            let raw = u16::from_be_bytes([payload[0], payload[1]]);
            let code = CloseCode::from(raw);
            // 1012-1014 are registered with IANA (RFC 6455, 11.7) after tungstenite's list
            // was written (1014 reads as `Bad`): a peer may send them.
            if !code.is_allowed() && !(1012..=1014).contains(&raw) {
                return Err(WsError::Protocol(ProtocolError::InvalidCloseSequence));
            }
            let reason = Utf8Bytes::try_from(payload.freeze().slice(2..))
                .map_err(|e| WsError::Utf8(format!("a close reason is not UTF-8: {e}")))?;
            Ok(Some(CloseFrame { code, reason }))
        }
    }
}

/// The header at the front of `buf`, checked; `None` while it is incomplete. `deflate`:
/// RSV1 may mark the first frame of a data message as compressed.
#[inline]
fn parse_header(buf: &[u8], deflate: bool) -> Result<Option<Header>, WsError> {
    let [b0, b1, ..] = *buf else {
        return Ok(None);
    };
    let (fin, opcode) = (b0 & 0x80 != 0, b0 & 0x0F);
    let compressed = b0 & 0x70 != 0;
    if compressed && !(deflate && b0 & 0x70 == 0x40 && matches!(opcode, 0x1 | 0x2)) {
        return Err(WsError::Protocol(ProtocolError::NonZeroReservedBits));
    }
    match opcode {
        0x0..=0x2 => {}
        0x3..=0x7 => {
            return Err(WsError::Protocol(ProtocolError::UnknownDataFrameType(
                opcode,
            )));
        }
        0x8..=0xA => {
            if !fin {
                return Err(WsError::Protocol(ProtocolError::FragmentedControlFrame));
            }
            if usize::from(b1 & 0x7F) > MAX_CONTROL {
                return Err(WsError::Protocol(ProtocolError::ControlFrameTooBig));
            }
        }
        _ => {
            return Err(WsError::Protocol(ProtocolError::UnknownControlFrameType(
                opcode,
            )));
        }
    }
    if b1 & 0x80 == 0 {
        return Err(WsError::Protocol(ProtocolError::UnmaskedFrameFromClient));
    }
    let (extra, payload) = match b1 & 0x7F {
        126 => match buf.get(2..4) {
            Some(b) => (2, usize::from(u16::from_be_bytes([b[0], b[1]]))),
            None => return Ok(None),
        },
        127 => match buf.get(2..10) {
            Some(b) => {
                // A length beyond memory (or with the top bit set, which RFC 6455 5.2
                // forbids) is over any limit: the caller refuses it as too long.
                let n = u64::from_be_bytes(b.try_into().expect("eight bytes"));
                (8, usize::try_from(n).unwrap_or(usize::MAX))
            }
            None => return Ok(None),
        },
        n => (0, usize::from(n)),
    };
    let Some(key) = buf.get(2 + extra..6 + extra) else {
        return Ok(None);
    };
    Ok(Some(Header {
        fin,
        compressed,
        opcode,
        len: 6 + extra,
        payload,
        mask: key.try_into().expect("four bytes"),
    }))
}

/// Unmasks a client payload in place, eight bytes at a time.
#[inline]
fn unmask(payload: &mut [u8], key: [u8; 4]) {
    let [a, b, c, d] = key;
    let word = u64::from_ne_bytes([a, b, c, d, a, b, c, d]);
    let mut words = payload.chunks_exact_mut(8);
    for w in &mut words {
        let v = u64::from_ne_bytes((&*w).try_into().expect("eight bytes")) ^ word;
        w.copy_from_slice(&v.to_ne_bytes());
    }
    for (i, x) in words.into_remainder().iter_mut().enumerate() {
        *x ^= key[i & 3];
    }
}

/// Writes the header of an unmasked (server) frame: `opcode` with FIN set.
#[inline]
pub fn encode_header(out: &mut BytesMut, opcode: u8, len: usize) {
    encode_first(out, 0x80 | opcode, len);
}

/// Writes the header of a server frame holding a compressed message: RSV1 and FIN set.
pub fn encode_compressed_header(out: &mut BytesMut, opcode: u8, len: usize) {
    encode_first(out, 0x80 | 0x40 | opcode, len);
}

#[inline]
fn encode_first(out: &mut BytesMut, b0: u8, len: usize) {
    if len <= 125 {
        out.put_slice(&[b0, len as u8]);
    } else if let Ok(n) = u16::try_from(len) {
        out.put_slice(&[b0, 126]);
        out.put_u16(n);
    } else {
        out.put_slice(&[b0, 127]);
        out.put_u64(len as u64);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A client frame: masked with `key`.
    fn frame(fin: bool, opcode: u8, payload: &[u8], key: [u8; 4]) -> Vec<u8> {
        let mut out = vec![if fin { 0x80 } else { 0 } | opcode];
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

    const KEY: [u8; 4] = [0x37, 0xfa, 0x21, 0x3d];

    fn decode_all(bytes: &[u8], max: usize) -> Result<Vec<ClientMessage>, WsError> {
        let mut d = Decoder::new(max);
        let mut buf = BytesMut::from(bytes);
        let mut out = Vec::new();
        while let Some(m) = d.decode(&mut buf)? {
            out.push(m);
        }
        assert!(buf.is_empty(), "all bytes taken");
        Ok(out)
    }

    #[test]
    fn messages_of_every_length_format_come_out_unmasked() {
        for len in [0, 1, 7, 8, 9, 125, 126, 127, 65_535, 65_536, 200_000] {
            let body: Vec<u8> = (0..len).map(|i| (i * 7 % 251) as u8).collect();
            let got = decode_all(&frame(true, 0x2, &body, KEY), 1 << 20).expect("valid");
            assert_eq!(
                got,
                vec![ClientMessage::Binary(body.into())],
                "length {len}"
            );
        }
    }

    #[test]
    fn a_message_arriving_byte_by_byte_comes_out_once_whole() {
        let bytes = frame(true, 0x1, br#"{"op":"publish"}"#, KEY);
        let mut d = Decoder::new(1024);
        let mut buf = BytesMut::new();
        for (i, b) in bytes.iter().enumerate() {
            assert_eq!(d.decode(&mut buf).expect("valid so far"), None, "byte {i}");
            buf.put_u8(*b);
        }
        assert_eq!(
            d.decode(&mut buf).expect("valid"),
            Some(ClientMessage::Text(r#"{"op":"publish"}"#.into()))
        );
    }

    #[test]
    fn fragments_are_joined_and_control_frames_between_them_pass() {
        let mut bytes = frame(false, 0x1, "héllo ".as_bytes(), KEY);
        bytes.extend(frame(true, 0x9, b"are you there", KEY));
        // A code point split across fragments is whole once joined.
        let e = "é".as_bytes();
        bytes.extend(frame(false, 0x0, &[b'w', e[0]], KEY));
        bytes.extend(frame(true, 0x0, &[e[1], b'!'], KEY));
        let got = decode_all(&bytes, 1024).expect("valid");
        assert_eq!(
            got,
            vec![
                ClientMessage::Ping("are you there".into()),
                ClientMessage::Text("héllo wé!".into()),
            ]
        );
    }

    #[test]
    fn close_frames_carry_their_code_and_reason() {
        let mut body = 1000u16.to_be_bytes().to_vec();
        body.extend_from_slice(b"bye");
        let got = decode_all(&frame(true, 0x8, &body, KEY), 1024).expect("valid");
        assert_eq!(
            got,
            vec![ClientMessage::Close(Some(CloseFrame {
                code: CloseCode::Normal,
                reason: "bye".into()
            }))]
        );
        let got = decode_all(&frame(true, 0x8, b"", KEY), 1024).expect("valid");
        assert_eq!(got, vec![ClientMessage::Close(None)]);
    }

    fn refused(bytes: &[u8], max: usize) -> WsError {
        decode_all(bytes, max).expect_err("refused")
    }

    #[test]
    fn malformed_frames_are_refused_with_the_rule_they_break() {
        use ProtocolError as P;
        let proto = |e: WsError| match e {
            WsError::Protocol(p) => p,
            other => panic!("not a protocol error: {other:?}"),
        };
        // Reserved bits: no extension is negotiated.
        let mut f = frame(true, 0x1, b"x", KEY);
        f[0] |= 0x40;
        assert_eq!(proto(refused(&f, 64)), P::NonZeroReservedBits);
        // Reserved opcodes.
        assert_eq!(
            proto(refused(&frame(true, 0x3, b"", KEY), 64)),
            P::UnknownDataFrameType(3)
        );
        assert_eq!(
            proto(refused(&frame(true, 0xB, b"", KEY), 64)),
            P::UnknownControlFrameType(0xB)
        );
        // A client must mask.
        let mut f = frame(true, 0x1, b"x", KEY);
        f[1] &= 0x7F;
        assert_eq!(proto(refused(&f, 64)), P::UnmaskedFrameFromClient);
        // Control frames: whole and short.
        assert_eq!(
            proto(refused(&frame(false, 0x9, b"", KEY), 64)),
            P::FragmentedControlFrame
        );
        assert_eq!(
            proto(refused(&frame(true, 0x9, &[0; 126], KEY), 1024)),
            P::ControlFrameTooBig
        );
        // Continuation without a start; a new message before the last one ended.
        assert_eq!(
            proto(refused(&frame(true, 0x0, b"x", KEY), 64)),
            P::UnexpectedContinueFrame
        );
        let mut f = frame(false, 0x1, b"x", KEY);
        f.extend(frame(true, 0x2, b"y", KEY));
        assert_eq!(proto(refused(&f, 64)), P::ExpectedFragment(Data::Text));
        // A one-byte close body, a close code no endpoint may send.
        assert_eq!(
            proto(refused(&frame(true, 0x8, &[3], KEY), 64)),
            P::InvalidCloseSequence
        );
        assert_eq!(
            proto(refused(&frame(true, 0x8, &1005u16.to_be_bytes(), KEY), 64)),
            P::InvalidCloseSequence
        );
        // A 64-bit length with its top bit set is over any limit.
        let mut f = vec![0x82, 0x80 | 127];
        f.extend_from_slice(&(1u64 << 63).to_be_bytes());
        f.extend_from_slice(&KEY);
        assert!(matches!(refused(&f, 64), WsError::Capacity(_)));
    }

    #[test]
    fn text_is_handed_on_unchecked_and_a_close_reason_that_is_not_utf8_is_refused() {
        // Text as it came, joined from its fragments: its reader checks it.
        let mut f = frame(false, 0x1, b"ok", KEY);
        f.extend(frame(true, 0x0, &[0xFF], KEY));
        assert_eq!(
            decode_all(&f, 64).expect("framed well"),
            vec![ClientMessage::Text(vec![b'o', b'k', 0xFF].into())]
        );
        let mut close = 1000u16.to_be_bytes().to_vec();
        close.push(0xFF);
        assert!(matches!(
            refused(&frame(true, 0x8, &close, KEY), 64),
            WsError::Utf8(_)
        ));
    }

    #[test]
    fn an_oversized_message_is_refused_from_its_header_alone() {
        // Only the header of a 1 MB frame: refused before its payload is waited for.
        let f = frame(true, 0x2, &vec![0; 1 << 20], KEY);
        let mut d = Decoder::new(1000);
        let mut buf = BytesMut::from(&f[..14]);
        match d.decode(&mut buf) {
            Err(WsError::Capacity(CapacityError::MessageTooLong { size, max_size })) => {
                assert_eq!((size, max_size), (1 << 20, 1000));
            }
            other => panic!("expected too long, got {other:?}"),
        }
        // Fragments count together.
        let mut f = frame(false, 0x2, &[0; 600], KEY);
        f.extend(frame(true, 0x0, &[0; 600], KEY));
        assert!(matches!(refused(&f, 1000), WsError::Capacity(_)));
        // Exactly at the limit is fine.
        assert_eq!(
            decode_all(&frame(true, 0x2, &[0; 1000], KEY), 1000)
                .unwrap()
                .len(),
            1
        );
    }

    #[test]
    fn headers_written_are_headers_read() {
        for len in [0usize, 5, 125, 126, 65_535, 65_536, 1 << 20] {
            let mut out = BytesMut::new();
            encode_header(&mut out, 0x2, len);
            // Read back as a client frame would be: add a zero mask key.
            let mut masked = out.to_vec();
            masked[1] |= 0x80;
            masked.extend_from_slice(&[0; 4]);
            let h = parse_header(&masked, false).expect("valid").expect("whole");
            assert_eq!((h.payload, h.len), (len, out.len() + 4), "length {len}");
            assert!(h.fin);
            assert_eq!(h.opcode, 0x2);
        }
    }

    mod round_trip {
        use proptest::prelude::*;

        use super::*;

        /// A client message and how it is sent: its kind (text, binary or ping), its
        /// payload, the fragments a data message is cut into, the mask key.
        fn message() -> impl Strategy<Value = (u8, Vec<u8>, usize, [u8; 4])> {
            (
                0u8..3,
                proptest::collection::vec(any::<u8>(), 0..300),
                1usize..4,
                any::<[u8; 4]>(),
            )
                .prop_map(|(kind, mut body, pieces, key)| {
                    if kind == 2 {
                        body.truncate(MAX_CONTROL);
                    }
                    (kind, body, pieces, key)
                })
        }

        proptest! {
            /// Whatever a client sends, cut into fragments and arriving in any pieces, is
            /// read back message for message.
            #[test]
            fn messages_come_out_as_sent_however_they_arrive(
                messages in proptest::collection::vec(message(), 0..12),
                cuts in proptest::collection::vec(1usize..200, 1..20),
            ) {
                let mut wire = Vec::new();
                let mut want = Vec::new();
                for (kind, body, pieces, key) in &messages {
                    match kind {
                        2 => {
                            wire.extend(frame(true, 0x9, body, *key));
                            want.push(ClientMessage::Ping(body.clone().into()));
                        }
                        _ => {
                            let opcode = if *kind == 0 { 0x1 } else { 0x2 };
                            let step = body.len().div_ceil(*pieces).max(1);
                            let parts: Vec<&[u8]> = if body.is_empty() {
                                vec![&body[..]]
                            } else {
                                body.chunks(step).collect()
                            };
                            for (i, part) in parts.iter().enumerate() {
                                let op = if i == 0 { opcode } else { 0x0 };
                                wire.extend(frame(i + 1 == parts.len(), op, part, *key));
                            }
                            let b = bytes::Bytes::from(body.clone());
                            want.push(if *kind == 0 {
                                ClientMessage::Text(b)
                            } else {
                                ClientMessage::Binary(b)
                            });
                        }
                    }
                }
                let mut d = Decoder::new(1 << 20);
                let mut buf = BytesMut::new();
                let mut got = Vec::new();
                let (mut at, mut k) = (0, 0);
                while at < wire.len() {
                    let n = cuts[k % cuts.len()].min(wire.len() - at);
                    buf.put_slice(&wire[at..at + n]);
                    (at, k) = (at + n, k + 1);
                    while let Some(m) = d.decode(&mut buf).expect("valid frames") {
                        got.push(m);
                    }
                }
                prop_assert!(buf.is_empty());
                prop_assert_eq!(got, want);
            }

            /// Any bytes at all: an error or messages, never a panic, and never a data
            /// message over the limit.
            #[test]
            fn any_bytes_give_messages_or_an_error(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
                let mut d = Decoder::new(64);
                let mut buf = BytesMut::from(&bytes[..]);
                while let Ok(Some(m)) = d.decode(&mut buf) {
                    if let ClientMessage::Text(b) | ClientMessage::Binary(b) = m {
                        prop_assert!(b.len() <= 64);
                    }
                }
            }
        }
    }
}
