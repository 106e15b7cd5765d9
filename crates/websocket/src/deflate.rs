//! permessage-deflate (RFC 7692) as this server speaks it: negotiation, the compressed
//! form of a message, and reading a client's compressed messages. No I/O.
//!
//! Design choice: the server never keeps a compression context between messages
//! (`server_no_context_takeover`, always in its answer). A message's compressed bytes then
//! depend on the message alone, so they are made once per message and encoding and the
//! same bytes go to every subscriber that negotiated the extension, beside the frame cache
//! ([`crate::Message::deflated_frame`]). The answer also carries
//! `client_no_context_takeover` (a server may add it, RFC 7692 7.1.1.1): each message a
//! client sends is inflated on its own, so what a reader keeps between messages is only a
//! reusable buffer, never history that must stay consistent.
//!
//! ```text
//!  a compressed message's payload (RSV1 on its first frame):
//!    deflate blocks of the message, flushed to a byte boundary (sync flush),
//!    without the 4 bytes 00 00 FF FF the flush ends with (RFC 7692 7.2.1)
//!  a Foxglove MessageData, shared body behind a per-subscriber head:
//!    [stored block: 00 | LEN LE | !LEN LE | head] [the body's blocks, as above]
//! ```
//!
//! A server compresses only with a full 32 KiB window: an offer whose
//! `server_max_window_bits` is below 15 is declined (the next offer, if any, is taken),
//! as is an offer with a parameter that is unknown, repeated or out of range — the
//! connection then simply goes without compression.

use std::cell::RefCell;

use bytes::{BufMut, Bytes, BytesMut};
use flate2::{Compress, Compression, Decompress, FlushCompress, FlushDecompress, Status};

/// The extension's name in `Sec-WebSocket-Extensions`.
pub const EXTENSION: &str = "permessage-deflate";

/// What ends a sync-flushed deflate stream, cut from a message and put back to read it.
const TAIL: [u8; 4] = [0x00, 0x00, 0xFF, 0xFF];

/// zlib level: the work is done once per message for every subscriber, and at the first
/// levels most of a ROS message's redundancy (repeated field names, zeros, float
/// exponents) is already found.
const LEVEL: u32 = 3;

/// A compressed message must be at most this share of the original (in 1/16ths) to be
/// sent compressed: below that saving, compression costs the receiver more than the
/// bytes saved are worth.
const PAYS_SIXTEENTHS: usize = 15;

/// Settings of a server that offers compression to its viewers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DeflateConfig {
    /// Messages smaller than this (as framed for the client) go uncompressed.
    pub min_bytes: usize,
}

impl Default for DeflateConfig {
    fn default() -> Self {
        DeflateConfig { min_bytes: 1024 }
    }
}

/// The answer to a client's accepted offer, for `Sec-WebSocket-Extensions`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Agreed {
    /// The client offered `server_max_window_bits=15`: the answer repeats it.
    window_bits_echo: bool,
}

impl Agreed {
    /// The response header's value.
    pub fn response(&self) -> String {
        let mut r = format!("{EXTENSION}; server_no_context_takeover; client_no_context_takeover");
        if self.window_bits_echo {
            r.push_str("; server_max_window_bits=15");
        }
        r
    }
}

/// Why one offer was declined (for tests and logs; the handshake goes on without it).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Declined {
    UnknownParam(String),
    RepeatedParam(String),
    BadValue {
        param: String,
        value: String,
    },
    /// `server_max_window_bits` below 15: compressed bytes are shared by every client, all
    /// made with the full window.
    SmallWindow(u8),
}

/// The first `permessage-deflate` offer among the `Sec-WebSocket-Extensions` header
/// values `headers` that this server can honour, or `None` (then no extension is
/// negotiated). Other extensions are ignored.
pub fn negotiate<'a>(headers: impl IntoIterator<Item = &'a str>) -> Option<Agreed> {
    headers
        .into_iter()
        .flat_map(|h| h.split(','))
        .filter_map(|offer| {
            let mut parts = offer.split(';').map(str::trim);
            let name = parts.next()?;
            name.eq_ignore_ascii_case(EXTENSION).then(|| accept(parts))
        })
        .find_map(Result::ok)
}

/// Checks one offer's parameters.
fn accept<'a>(params: impl Iterator<Item = &'a str>) -> Result<Agreed, Declined> {
    let mut seen: Vec<String> = Vec::new();
    let mut agreed = Agreed {
        window_bits_echo: false,
    };
    for p in params.filter(|p| !p.is_empty()) {
        let (name, value) = match p.split_once('=') {
            Some((n, v)) => (n.trim(), Some(v.trim().trim_matches('"'))),
            None => (p, None),
        };
        let name = name.to_ascii_lowercase();
        if seen.contains(&name) {
            return Err(Declined::RepeatedParam(name));
        }
        let bad = |value: &str| Declined::BadValue {
            param: name.clone(),
            value: value.to_owned(),
        };
        match (name.as_str(), value) {
            ("server_no_context_takeover" | "client_no_context_takeover", None) => {}
            ("server_no_context_takeover" | "client_no_context_takeover", Some(v)) => {
                return Err(bad(v));
            }
            // The client says it can take a smaller window for its own messages; the
            // answer does not ask for one, so it compresses with whatever it likes up to
            // 15 bits, which the reader's inflater takes.
            ("client_max_window_bits", None) => {}
            ("client_max_window_bits" | "server_max_window_bits", Some(v)) => {
                let bits = window_bits(v).ok_or_else(|| bad(v))?;
                if name == "server_max_window_bits" {
                    if bits < 15 {
                        return Err(Declined::SmallWindow(bits));
                    }
                    agreed.window_bits_echo = true;
                }
            }
            ("server_max_window_bits", None) => return Err(bad("")),
            _ => return Err(Declined::UnknownParam(name)),
        }
        seen.push(name);
    }
    Ok(agreed)
}

/// A window size parameter: 8 to 15, digits only (RFC 7692 7.1.2).
fn window_bits(v: &str) -> Option<u8> {
    if v.is_empty() || v.len() > 2 || !v.bytes().all(|b| b.is_ascii_digit()) || v.starts_with('0') {
        return None;
    }
    v.parse().ok().filter(|b| (8..=15).contains(b))
}

/// Whether messages of type `type_name` are worth compressing: not those whose content is
/// compressed already (JPEG or PNG images, video, compressed point clouds), which
/// deflate cannot shrink and would only spend the hub's time on.
pub fn type_pays(type_name: &str) -> bool {
    let short = type_name.rsplit('/').next().unwrap_or(type_name);
    !(short.starts_with("Compressed") || short == "FFMPEGPacket" || short == "Packet")
}

/// The compressed form of the message made of `parts`, as a frame with RSV1 carries it,
/// or `None` when compression does not pay for it.
pub fn compress(parts: &[&[u8]]) -> Option<Bytes> {
    thread_local! {
        // One compressor per thread, reset for each message: its state (hundreds of KB
        // with the window and hash tables) is made once, not per message.
        static COMPRESSOR: RefCell<Option<Compress>> = const { RefCell::new(None) };
    }
    let len: usize = parts.iter().map(|p| p.len()).sum();
    COMPRESSOR.with(|cell| {
        let mut slot = cell.borrow_mut();
        let c = slot.get_or_insert_with(|| Compress::new(Compression::new(LEVEL), false));
        c.reset();
        let mut out = Vec::with_capacity(len / 2 + 64);
        for p in parts {
            feed(c, p, &mut out);
        }
        // A message that cannot be closed with the flush marker goes uncompressed.
        if !flush(c, &mut out) {
            return None;
        }
        out.truncate(out.len() - TAIL.len());
        (out.len() * 16 <= len * PAYS_SIXTEENTHS).then(|| Bytes::from(out))
    })
}

/// Room kept free in the output before each call: zlib asks for more than six bytes
/// during a flush, or it may write its flush marker twice.
const SPARE: usize = 64;

/// Feeds all of `input` to `c`, growing `out` as needed.
fn feed(c: &mut Compress, mut input: &[u8], out: &mut Vec<u8>) {
    while !input.is_empty() {
        grow(out);
        let before = c.total_in();
        // Compressing from memory to memory fails only on a misuse of the stream, and
        // then the data is taken as it is, never lost: the caller's flush fails too.
        if c.compress_vec(input, out, FlushCompress::None).is_err() {
            return;
        }
        input = &input[(c.total_in() - before) as usize..];
    }
}

/// Sync-flushes `c` into `out`: calls again until a call writes nothing and leaves room,
/// so the flush is whole whatever steps the backend takes. True when `out` then ends with
/// the flush marker (00 00 FF FF).
fn flush(c: &mut Compress, out: &mut Vec<u8>) -> bool {
    loop {
        grow(out);
        let before = c.total_out();
        if c.compress_vec(&[], out, FlushCompress::Sync).is_err() {
            return false;
        }
        if c.total_out() == before && out.len() < out.capacity() {
            return out.ends_with(&TAIL);
        }
    }
}

fn grow(out: &mut Vec<u8>) {
    if out.capacity() - out.len() < SPARE {
        out.reserve(out.capacity().max(4096));
    }
}

/// Appends `head` to `out` as a stored (uncompressed) deflate block, not the last one:
/// a per-subscriber head in front of a body compressed once for all. Stored blocks end on
/// a byte boundary, and the body was compressed from a fresh context, so the two
/// together are one valid deflate stream. `head` must be under 64 KiB.
pub fn stored_block(out: &mut BytesMut, head: &[u8]) {
    let len = u16::try_from(head.len()).expect("a head under 64 KiB");
    out.put_u8(0x00);
    out.put_u16_le(len);
    out.put_u16_le(!len);
    out.put_slice(head);
}

/// Why a client's compressed message could not be read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum InflateError {
    /// It inflates to more than the message size limit.
    TooLong { limit: usize },
    /// It is not a deflate stream.
    Invalid(String),
}

/// Reads a client's compressed messages, each on its own (`client_no_context_takeover`).
pub struct Inflater {
    limit: usize,
    /// Made at the first compressed message: most clients never send one.
    d: Option<Box<Decompress>>,
}

impl std::fmt::Debug for Inflater {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Inflater")
            .field("limit", &self.limit)
            .finish()
    }
}

impl Inflater {
    /// Refuses messages that inflate to more than `limit` bytes.
    pub fn new(limit: usize) -> Inflater {
        Inflater { limit, d: None }
    }

    /// The message compressed as `data`. Never holds more than `limit` + a little
    /// output: a small message inflating to gigabytes is refused as soon as it passes
    /// the limit.
    pub fn inflate(&mut self, data: &[u8]) -> Result<Bytes, InflateError> {
        let d = self
            .d
            .get_or_insert_with(|| Box::new(Decompress::new(false)));
        d.reset(false);
        let limit = self.limit;
        let mut out: Vec<u8> = Vec::with_capacity((data.len() * 4).clamp(256, limit.max(256)));
        let mut ended = false;
        for mut input in [data, &TAIL[..]] {
            while !ended {
                if out.len() > limit {
                    return Err(InflateError::TooLong { limit });
                }
                if out.capacity() == out.len() {
                    // Room for at most one byte past the limit: enough to know it passed.
                    let room = limit.saturating_add(1) - out.len().min(limit);
                    let grow = out.capacity().min(room).max(1);
                    out.reserve_exact(grow);
                }
                let (before_in, before_out) = (d.total_in(), d.total_out());
                let status = d
                    .decompress_vec(input, &mut out, FlushDecompress::Sync)
                    .map_err(|e| InflateError::Invalid(e.to_string()))?;
                input = &input[(d.total_in() - before_in) as usize..];
                let progress = d.total_in() != before_in || d.total_out() != before_out;
                match status {
                    Status::StreamEnd => ended = true,
                    // Input taken and output not full: this piece is done.
                    _ if input.is_empty() && out.len() < out.capacity() => break,
                    Status::BufError if !progress && out.len() < out.capacity() => {
                        if input.is_empty() {
                            break;
                        }
                        return Err(InflateError::Invalid(
                            "a deflate stream stopped early".into(),
                        ));
                    }
                    _ => {}
                }
            }
        }
        if out.len() > limit {
            return Err(InflateError::TooLong { limit });
        }
        Ok(Bytes::from(out))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn inflate_all(data: &[u8]) -> Vec<u8> {
        Inflater::new(64 << 20)
            .inflate(data)
            .expect("inflates")
            .to_vec()
    }

    #[test]
    fn the_usual_offers_are_accepted_with_both_no_context_takeovers() {
        let answer = "permessage-deflate; server_no_context_takeover; client_no_context_takeover";
        // Chromium, Python websockets, node ws.
        for offer in [
            "permessage-deflate; client_max_window_bits",
            "permessage-deflate",
            "permessage-deflate; server_no_context_takeover; client_no_context_takeover",
            "Permessage-Deflate;client_max_window_bits=12",
        ] {
            let a = negotiate([offer]).unwrap_or_else(|| panic!("{offer} accepted"));
            assert_eq!(a.response(), answer, "{offer}");
        }
        let a = negotiate(["permessage-deflate; server_max_window_bits=\"15\""]).expect("15");
        assert_eq!(a.response(), format!("{answer}; server_max_window_bits=15"));
    }

    #[test]
    fn an_offer_that_cannot_be_honoured_is_passed_over_for_the_next() {
        // A smaller server window first, then a plain offer (RFC 7692 5: in preference
        // order, in one header or several).
        let a = negotiate([
            "x-webkit-deflate-frame, permessage-deflate; server_max_window_bits=10",
            "permessage-deflate; client_max_window_bits",
        ])
        .expect("second offer");
        assert!(!a.window_bits_echo);
        assert_eq!(
            negotiate(["permessage-deflate; server_max_window_bits=10"]),
            None
        );
        assert_eq!(negotiate(["x-webkit-deflate-frame"]), None);
        assert_eq!(negotiate(std::iter::empty()), None);
    }

    #[test]
    fn bad_parameters_decline_the_offer() {
        let one = |p: &str| accept(p.split(';').map(str::trim));
        assert_eq!(one("foo"), Err(Declined::UnknownParam("foo".into())));
        assert_eq!(
            one("server_no_context_takeover; server_no_context_takeover"),
            Err(Declined::RepeatedParam("server_no_context_takeover".into()))
        );
        assert_eq!(
            one("server_no_context_takeover=1"),
            Err(Declined::BadValue {
                param: "server_no_context_takeover".into(),
                value: "1".into()
            })
        );
        for v in ["7", "16", "08", "abc", "", "1.5", "-9"] {
            assert!(
                matches!(
                    one(&format!("client_max_window_bits={v}")),
                    Err(Declined::BadValue { .. })
                ),
                "{v}"
            );
        }
        assert_eq!(
            one("server_max_window_bits=9"),
            Err(Declined::SmallWindow(9))
        );
        assert!(matches!(
            one("server_max_window_bits"),
            Err(Declined::BadValue { .. })
        ));
        // Declined offers leave the connection uncompressed, never failed.
        assert_eq!(negotiate(["permessage-deflate; foo=1"]), None);
    }

    #[test]
    fn compressed_messages_inflate_to_what_was_compressed() {
        let json: Vec<u8> = (0..2000)
            .flat_map(|i| format!("{{\"x\":{i},\"y\":0.0,\"z\":1.5}},").into_bytes())
            .collect();
        let z = compress(&[b"{\"points\":[", &json, b"]}"]).expect("pays");
        assert!(!z.ends_with(&TAIL));
        assert!(z.len() * 4 < json.len(), "{} of {}", z.len(), json.len());
        let mut whole = b"{\"points\":[".to_vec();
        whole.extend_from_slice(&json);
        whole.extend_from_slice(b"]}");
        assert_eq!(inflate_all(&z), whole);
        // Made again, the same bytes: no state carried from one message to the next.
        assert_eq!(compress(&[&whole]).expect("pays"), z);
    }

    #[test]
    fn every_size_ends_with_the_flush_marker_and_inflates_back() {
        // Sizes around the output buffer's growth steps, of data that compresses a
        // little (as CBOR of floats does) and a lot.
        let mut rng = fastrand::Rng::with_seed(3);
        let floaty: Vec<u8> = (0..200_000)
            .map(|i| if i % 4 == 3 { 0x3f } else { rng.u8(..) })
            .collect();
        for n in (1..70_000)
            .step_by(997)
            .chain([4096, 8192, 32_000, 32_768, 65_536, 200_000])
        {
            for data in [&floaty[..n], &vec![7u8; n][..]] {
                if let Some(z) = compress(&[data]) {
                    assert_eq!(inflate_all(&z), data, "size {n}");
                }
            }
        }
    }

    #[test]
    fn a_stored_head_before_a_shared_body_reads_as_one_message() {
        let body: Vec<u8> = b"abcabcabc".repeat(500);
        let z = compress(&[&body]).expect("pays");
        for head in [&b""[..], &[4, 1, 0, 0, 0, 9, 9, 9, 9, 9, 9, 9, 9][..]] {
            let mut m = BytesMut::new();
            stored_block(&mut m, head);
            m.extend_from_slice(&z);
            let mut want = head.to_vec();
            want.extend_from_slice(&body);
            assert_eq!(inflate_all(&m), want);
        }
    }

    #[test]
    fn what_does_not_shrink_is_sent_as_it_is() {
        let mut rng = fastrand::Rng::with_seed(7);
        let noise: Vec<u8> = (0..4096).map(|_| rng.u8(..)).collect();
        assert_eq!(compress(&[&noise]), None);
        assert!(!type_pays("sensor_msgs/msg/CompressedImage"));
        assert!(!type_pays("sensor_msgs/CompressedImage"));
        assert!(!type_pays("foxglove_msgs/msg/CompressedVideo"));
        assert!(!type_pays(
            "point_cloud_interfaces/msg/CompressedPointCloud2"
        ));
        assert!(type_pays("sensor_msgs/msg/PointCloud2"));
        assert!(type_pays("sensor_msgs/msg/Image"));
    }

    #[test]
    fn a_message_inflating_past_the_limit_is_refused_early() {
        // 64 MB of zeros: a few tens of KB compressed.
        let zeros = vec![0u8; 64 << 20];
        let z = compress(&[&zeros]).expect("pays");
        assert!(z.len() < 100_000, "{}", z.len());
        let mut i = Inflater::new(1 << 20);
        assert_eq!(i.inflate(&z), Err(InflateError::TooLong { limit: 1 << 20 }));
        // Exactly at the limit is fine, and the inflater serves the next message.
        let z = compress(&[&zeros[..1 << 20]]).expect("pays");
        assert_eq!(i.inflate(&z).expect("at the limit").len(), 1 << 20);
        let z = compress(&[&zeros[..(1 << 20) + 1]]).expect("pays");
        assert!(matches!(i.inflate(&z), Err(InflateError::TooLong { .. })));
    }

    #[test]
    fn garbage_is_refused_not_panicked_on() {
        let mut i = Inflater::new(1 << 16);
        assert!(matches!(
            i.inflate(&[0xFF, 0xFF, 0xFF, 0x01]),
            Err(InflateError::Invalid(_))
        ));
        // An empty message inflates to nothing.
        assert_eq!(i.inflate(&[0x00]).map(|b| b.len()), Ok(0));
    }

    mod round_trip {
        use proptest::prelude::*;

        use super::*;

        proptest! {
            #[test]
            fn anything_compressed_inflates_back(
                body in proptest::collection::vec(0u8..4, 0..5000),
                head in proptest::collection::vec(any::<u8>(), 0..20),
            ) {
                if let Some(z) = compress(&[&body]) {
                    let mut m = BytesMut::new();
                    stored_block(&mut m, &head);
                    m.extend_from_slice(&z);
                    let mut want = head.clone();
                    want.extend_from_slice(&body);
                    prop_assert_eq!(inflate_all(&m), want);
                }
            }

            #[test]
            fn any_bytes_inflate_or_are_refused(bytes in proptest::collection::vec(any::<u8>(), 0..300)) {
                let mut i = Inflater::new(4096);
                if let Ok(out) = i.inflate(&bytes) {
                    prop_assert!(out.len() <= 4096);
                }
            }
        }
    }
}
