//! The short path for `publish`, the operation that carries nearly all traffic: its
//! envelope is walked in one pass, JSON or CBOR, without building a tree, the topic is
//! borrowed and the message is a slice of the frame. Anything unusual falls back to the
//! full parse ([`Request::from_json`](super::Request::from_json),
//! [`Request::from_cbor`](super::Request::from_cbor)), which gives the precise error.

use bytes::Bytes;
use serde_json::Value;

use super::fields::valid_topic;
use crate::payload::{Encoding, Payload};
use crate::rosbridge::shape::EnvelopeShapes;
use crate::rosbridge::{convert, scan};

/// A `publish` read on the short path, its topic borrowed from the frame: the operation
/// that carries nearly all traffic costs no allocation before it reaches the router.
#[derive(Debug)]
pub struct Publish<'a> {
    pub id: PublishId<'a>,
    pub topic: std::borrow::Cow<'a, str>,
    pub msg: Payload,
}

/// A publish's `id`. From JSON it stays text until asked for: roslibpy and roslibjs
/// number every publish, and the id is only wanted when something goes wrong.
#[derive(Debug)]
pub struct PublishId<'a>(IdRepr<'a>);

#[derive(Debug)]
enum IdRepr<'a> {
    None,
    Value(Value),
    /// Checked by the scan, so it parses.
    Json(&'a str),
}

impl PublishId<'_> {
    /// The `id` as the client sent it, for a `status` that echoes it.
    pub fn value(&self) -> Option<Value> {
        match &self.0 {
            IdRepr::None => None,
            IdRepr::Value(v) => Some(v.clone()),
            IdRepr::Json(text) => serde_json::from_str(text).ok(),
        }
    }
}

impl<'a> Publish<'a> {
    /// A well-formed JSON `publish` (object `msg`, valid topic name) from a frame whose
    /// text is known to be UTF-8 (a WebSocket text frame, validated on arrival, so it is
    /// not checked again): its envelope read in one pass, the topic borrowed, the message
    /// a slice of `frame`. `text` must be a view of `frame`'s own bytes. `None` for
    /// anything else, which [`Request::from_json`](super::Request::from_json) then parses
    /// with the precise error.
    pub fn from_json_text(text: &'a str, frame: &Bytes) -> Option<Publish<'a>> {
        Self::read_json_text(text, frame, None)
    }

    /// [`Publish::from_json_text`], keeping the envelope's shape in `shapes` for the
    /// client's next publishes ([`EnvelopeShapes::fit`]).
    pub fn from_json_text_shaped(
        text: &'a str,
        frame: &Bytes,
        shapes: &mut EnvelopeShapes,
    ) -> Option<Publish<'a>> {
        Self::read_json_text(text, frame, Some(shapes))
    }

    fn read_json_text(
        text: &'a str,
        frame: &Bytes,
        shapes: Option<&mut EnvelopeShapes>,
    ) -> Option<Publish<'a>> {
        if !std::ptr::eq(text.as_ptr(), frame.as_ptr()) || text.len() != frame.len() {
            return None;
        }
        let e = scan::envelope(text)?;
        if e.op? != "publish" {
            return None;
        }
        let topic = e.topic?;
        let msg = e.msg.clone()?;
        if text.as_bytes()[msg.start] != b'{' || !valid_topic(topic) {
            return None;
        }
        if let Some(shapes) = shapes {
            shapes.learn(text, &e, &msg);
        }
        let id = match e.id {
            Some(r) => PublishId(IdRepr::Json(&text[r])),
            None => PublishId(IdRepr::None),
        };
        Some(Publish {
            id,
            topic: topic.into(),
            msg: Payload::json(frame.slice(msg)),
        })
    }

    /// A CBOR `publish` (a definite-length map with text `op`, `topic`, a map `msg`,
    /// maybe `id`), its envelope walked head by head without decoding
    /// the message: `msg` is a slice of `frame`. `None` for anything else (indefinite
    /// lengths, duplicate keys, trailing bytes...), which
    /// [`Request::from_cbor`](super::Request::from_cbor) then parses with the precise error.
    pub fn from_cbor_frame(frame: &'a Bytes) -> Option<Publish<'a>> {
        let mut c = CborCursor {
            data: frame,
            pos: 0,
        };
        let (5, Some(entries)) = c.header()? else {
            return None;
        };
        let (mut op, mut topic, mut msg, mut id) = (None, None, None, None);
        for _ in 0..entries {
            let slot = match c.text()? {
                "op" => &mut op,
                "topic" => &mut topic,
                "msg" => &mut msg,
                "id" => &mut id,
                _ => {
                    c.skip(0)?;
                    continue;
                }
            };
            if slot.is_some() {
                return None;
            }
            let start = c.pos;
            c.skip(0)?;
            *slot = Some(start..c.pos);
        }
        if c.pos != frame.len() {
            return None;
        }
        let text = |r: std::ops::Range<usize>| {
            let mut t = CborCursor {
                data: &frame[..r.end],
                pos: r.start,
            };
            t.text()
        };
        if text(op?)? != "publish" {
            return None;
        }
        let topic = text(topic?)?;
        let msg = msg?;
        // Major type 5: a map.
        if frame[msg.start] >> 5 != 5 || !valid_topic(topic) {
            return None;
        }
        let id = match id {
            Some(r) => PublishId(IdRepr::Value(
                convert::parse_cbor(&frame[r])
                    .ok()
                    .and_then(|v| convert::cbor_value_to_json(v).ok())?,
            )),
            None => PublishId(IdRepr::None),
        };
        Some(Publish {
            id,
            topic: topic.into(),
            msg: Payload::new(Encoding::Cbor, frame.slice(msg)),
        })
    }
}

/// Walks CBOR items by their headers, keeping the position in the input.
struct CborCursor<'a> {
    data: &'a [u8],
    pos: usize,
}

impl<'a> CborCursor<'a> {
    /// Deepest nesting walked (as for JSON).
    const MAX_DEPTH: usize = 128;

    /// One item's head: its major type and argument (`None` for an indefinite length or
    /// a break).
    fn header(&mut self) -> Option<(u8, Option<u64>)> {
        let h = fleetlink_msg::cbor::read_head(self.data, &mut self.pos)?;
        Some((h.major, h.arg))
    }

    fn take(&mut self, len: usize) -> Option<&'a [u8]> {
        let s = self.data.get(self.pos..self.pos.checked_add(len)?)?;
        self.pos += len;
        Some(s)
    }

    /// A definite-length text item.
    fn text(&mut self) -> Option<&'a str> {
        match self.header()? {
            (3, Some(n)) => std::str::from_utf8(self.take(usize::try_from(n).ok()?)?).ok(),
            _ => None,
        }
    }

    /// Steps over one item; `None` for what only the full parse handles (indefinite
    /// lengths, a stray break, truncation, nesting deeper than `MAX_DEPTH`).
    fn skip(&mut self, depth: usize) -> Option<()> {
        if depth > Self::MAX_DEPTH {
            return None;
        }
        let (major, arg) = self.header()?;
        // Indefinite lengths and breaks are left to the full parse.
        let n = arg?;
        match major {
            0 | 1 | 7 => {}
            2 | 3 => {
                self.take(usize::try_from(n).ok()?)?;
            }
            4 => {
                for _ in 0..n {
                    self.skip(depth + 1)?;
                }
            }
            5 => {
                for _ in 0..n.checked_mul(2)? {
                    self.skip(depth + 1)?;
                }
            }
            _ => self.skip(depth + 1)?, // 6: a tag and its item
        }
        Some(())
    }
}
