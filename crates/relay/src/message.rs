//! One published message, shared by every subscriber that receives it.
//!
//! The body stays in the encoding it arrived in. Each kind of outgoing frame (rosbridge
//! JSON, rosbridge CBOR, `cbor-raw`, `fleetlink.v1`) is built the first time a subscriber
//! needs it and kept in a [`OnceLock`], so a message fanned out to a hundred subscribers
//! is converted and framed at most once per kind, and every subscriber sends the same
//! [`Bytes`].
//!
//! The same holds for the compressed forms sent to clients that negotiated
//! permessage-deflate ([`Message::deflated_frame`], [`Message::deflated_payload`]): made
//! by the first such subscriber, kept beside the frame they compress, shared by the rest.
//! A message no such client receives never makes or holds one.

use std::sync::{Arc, OnceLock};
use std::time::Instant;

use bytes::{Bytes, BytesMut};
use fleetlink_proto::frame::{self, DEFAULT_CHUNK_SIZE};
use fleetlink_proto::rosbridge::outbound;
use fleetlink_proto::{Encoding, Payload, Schema};
use tokio_tungstenite::tungstenite::{Message as WsMessage, Utf8Bytes};

use crate::names::{ClientId, TopicId, TopicName};
use crate::transcode::{TranscodeError, Transcoder};
use crate::websocket::deflate::{self, DeflateConfig};

/// What a topic is, as of the moment a message was published on it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TopicMeta {
    pub id: TopicId,
    pub name: TopicName,
    pub schema: Schema,
    /// A publisher advertised the topic latched: links announce it so (`ADVERTISE_LATCHED`),
    /// and the far side latches it too.
    pub latched: bool,
    /// A robot publishes it as a no-drop stream (`ADVERTISE_RELIABLE`): a hub's own
    /// uplink carries it upstream as no-drop too.
    pub no_drop: bool,
    /// Its publisher is behind these hubs (it came from another hub); `None` when it is
    /// published here. A link announces it with them, and a hub among them refuses it.
    pub via: Option<Arc<Via>>,
    /// What a rosbridge JSON `publish` of this topic starts with (see
    /// [`outbound::publish_json_head`]): made once per topic, not per message.
    json_head: Box<str>,
    /// Its type's content may shrink under compression (not JPEG, video...; see
    /// [`deflate::type_pays`]): judged once per topic.
    deflate_pays: bool,
}

impl TopicMeta {
    pub fn new(id: TopicId, name: TopicName, schema: Schema, latched: bool) -> TopicMeta {
        let json_head = outbound::publish_json_head(name.as_str()).into();
        let deflate_pays = deflate::type_pays(&schema.type_name);
        TopicMeta {
            deflate_pays,
            id,
            name,
            schema,
            latched,
            no_drop: false,
            via: None,
            json_head,
        }
    }

    /// The same topic, published behind the hubs `via`.
    pub fn with_topic_via(mut self, via: Option<Arc<Via>>) -> TopicMeta {
        self.via = via;
        self
    }

    /// The same topic, published as a no-drop stream or not.
    pub fn with_no_drop(mut self, no_drop: bool) -> TopicMeta {
        self.no_drop = no_drop;
        self
    }

    /// `{"op":"publish","topic":<name>,"msg":`.
    pub fn json_head(&self) -> &str {
        &self.json_head
    }
}

/// The frame kinds a message can be delivered as.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrameKind {
    RosbridgeJson,
    RosbridgeCbor,
    RosbridgeCborRaw,
    /// rosbridge's `png` compression: the JSON publish as the pixels of a PNG image,
    /// sent as `{"op": "png", "data": <base64>}` (roslibjs asks for it for big messages).
    RosbridgePng,
}

#[derive(Debug)]
pub struct Message {
    pub topic: Arc<TopicMeta>,
    /// Per-topic sequence number assigned by the publisher.
    pub seq: u64,
    /// When the message was created at its origin (Unix nanoseconds).
    pub stamp_ns: u64,
    /// When this router received it ([`Message::received`]), as Unix nanoseconds on the
    /// router's monotonic clock ([`crate::instant_to_unix_nanos`]): half the size of an
    /// `Instant`, which keeps a message within the allocator's small sizes.
    received_ns: u64,
    /// Who published it; it is never delivered back to its origin.
    pub origin: ClientId,
    pub payload: Payload,
    /// The payload is the JSON text of the message as a rosbridge client sent it, checked
    /// as UTF-8 and against its type ([`Message::framed`]): its `publish` frame is the
    /// topic's head, the payload and a brace ([`Message::json_parts`]), written by each
    /// subscriber's writer straight into its socket buffer.
    json_text: bool,
    /// Frames built for subscribers, made when the first one is needed: a message whose
    /// subscribers all take it as JSON text never allocates them, and stays small (it is
    /// allocated once per message and held in every subscriber's queue).
    frames: OnceLock<Box<Frames>>,
    /// The hubs it was published on before this one, when it came from another hub.
    via: Option<Arc<Via>>,
}

/// The hubs a message has been published on, in the order it passed them (the `VIA` of
/// docs/protocol.md §1.8d): one value shared by every message that came the same way.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Via(Box<[u64]>);

impl Via {
    pub fn new(hubs: Vec<u64>) -> Via {
        Via(hubs.into_boxed_slice())
    }

    pub fn hubs(&self) -> &[u64] {
        &self.0
    }

    pub fn contains(&self, hub: u64) -> bool {
        self.0.contains(&hub)
    }
}

/// The frames of one message, each built the first time a subscriber needs it.
#[derive(Debug, Default)]
struct Frames {
    json: OnceLock<Result<WsMessage, TranscodeError>>,
    cbor: OnceLock<Result<WsMessage, TranscodeError>>,
    cbor_raw: OnceLock<Result<WsMessage, TranscodeError>>,
    png: OnceLock<Result<WsMessage, TranscodeError>>,
    link: OnceLock<Arc<[Bytes]>>,
    /// The message object in another encoding, by `Encoding as usize` (a Foxglove
    /// channel's encoding, when the message arrived in a different one).
    converted: [OnceLock<Result<Bytes, TranscodeError>>; 4],
    /// Compressed forms, made for the first subscriber that negotiated permessage-deflate;
    /// boxed apart so that messages no such subscriber receives stay as small as before.
    deflated: OnceLock<Box<Deflated>>,
}

/// A message's compressed forms: `None` where compression does not pay (it is sent as it
/// is then, the judgement kept like the bytes).
#[derive(Debug, Default)]
struct Deflated {
    /// rosbridge frames, by [`FrameKind`] (as [`Frames::cell`] orders them).
    frames: [OnceLock<Option<Bytes>>; 4],
    /// The message object in each encoding, by `Encoding as usize` (Foxglove).
    payloads: [OnceLock<Option<Bytes>>; 4],
}

impl FrameKind {
    fn index(self) -> usize {
        match self {
            FrameKind::RosbridgeJson => 0,
            FrameKind::RosbridgeCbor => 1,
            FrameKind::RosbridgeCborRaw => 2,
            FrameKind::RosbridgePng => 3,
        }
    }
}

impl Frames {
    fn cell(&self, kind: FrameKind) -> &OnceLock<Result<WsMessage, TranscodeError>> {
        match kind {
            FrameKind::RosbridgeJson => &self.json,
            FrameKind::RosbridgeCbor => &self.cbor,
            FrameKind::RosbridgeCborRaw => &self.cbor_raw,
            FrameKind::RosbridgePng => &self.png,
        }
    }

    fn cell_mut(&mut self, kind: FrameKind) -> &mut OnceLock<Result<WsMessage, TranscodeError>> {
        match kind {
            FrameKind::RosbridgeJson => &mut self.json,
            FrameKind::RosbridgeCbor => &mut self.cbor,
            FrameKind::RosbridgeCborRaw => &mut self.cbor_raw,
            FrameKind::RosbridgePng => &mut self.png,
        }
    }
}

impl Message {
    pub fn new(
        topic: Arc<TopicMeta>,
        seq: u64,
        stamp_ns: u64,
        origin: ClientId,
        payload: Payload,
    ) -> Message {
        Self::received_at(topic, seq, stamp_ns, origin, payload, Instant::now())
    }

    /// [`Message::new`] for a message received at `received`.
    pub fn received_at(
        topic: Arc<TopicMeta>,
        seq: u64,
        stamp_ns: u64,
        origin: ClientId,
        payload: Payload,
        received: Instant,
    ) -> Message {
        Self::framed(topic, seq, stamp_ns, origin, payload, received, false)
    }

    /// [`Message::received_at`] of a message whose payload is the JSON text a rosbridge
    /// client sent (`json_text`: valid UTF-8, and the object as it goes out): a writer
    /// then needs neither a conversion nor a frame built for it.
    pub fn framed(
        topic: Arc<TopicMeta>,
        seq: u64,
        stamp_ns: u64,
        origin: ClientId,
        payload: Payload,
        received: Instant,
        json_text: bool,
    ) -> Message {
        Message {
            topic,
            seq,
            stamp_ns,
            received_ns: crate::instant_to_unix_nanos(received),
            origin,
            json_text: json_text && payload.encoding == Encoding::Json,
            payload,
            frames: OnceLock::new(),
            via: None,
        }
    }

    /// The same message, come from another hub by way of `via`.
    pub fn with_via(mut self, via: Option<Arc<Via>>) -> Message {
        self.via = via;
        self
    }

    /// The hubs it was published on before this one (none when it was published here
    /// first).
    pub fn via(&self) -> Option<&Arc<Via>> {
        self.via.as_ref()
    }

    /// The rosbridge JSON `publish` frame of a message published as JSON text, in the
    /// three pieces it is made of: the topic's head, the message object and `}`. Together
    /// they are UTF-8.
    pub fn json_parts(&self) -> Option<[&[u8]; 3]> {
        self.json_text.then(|| {
            [
                self.topic.json_head.as_bytes(),
                &self.payload.bytes[..],
                b"}".as_slice(),
            ]
        })
    }

    /// The same message numbered `seq` (a no-drop stream's own numbering, see
    /// [`crate::reliable`]); shares the payload, starts with an empty frame cache.
    pub fn resequenced(&self, seq: u64) -> Message {
        Message {
            seq,
            received_ns: self.received_ns,
            ..Message::new(
                self.topic.clone(),
                seq,
                self.stamp_ns,
                self.origin,
                self.payload.clone(),
            )
        }
    }

    /// The same message carrying `bytes` instead (its payload as one link carries it:
    /// compressed); keeps number, stamp, origin and receive time.
    pub fn with_link_bytes(&self, bytes: Bytes) -> Message {
        Message {
            received_ns: self.received_ns,
            ..Message::new(
                self.topic.clone(),
                self.seq,
                self.stamp_ns,
                self.origin,
                Payload::new(self.payload.encoding, bytes),
            )
        }
    }

    /// When this router received it; queue lag is measured from here.
    pub fn received(&self) -> Instant {
        crate::unix_nanos_to_instant(self.received_ns)
    }

    /// [`Message::received`] as Unix nanoseconds (see [`crate::instant_to_unix_nanos`]).
    pub fn received_unix_ns(&self) -> u64 {
        self.received_ns
    }

    pub fn wire_len(&self) -> usize {
        self.payload.len()
    }

    /// The frame of `kind` if it is already built: moved out when `this` is the message's
    /// last holder, cloned otherwise. The message comes back when its frame of `kind` is
    /// not built (or could not be). Moving spares what sharing costs: a reference count
    /// for bytes built in one piece is allocated on their first clone.
    pub fn take_built_frame(
        mut this: Arc<Message>,
        kind: FrameKind,
    ) -> Result<WsMessage, Arc<Message>> {
        let built = |m: &Message| {
            m.frames
                .get()
                .is_some_and(|f| matches!(f.cell(kind).get(), Some(Ok(_))))
        };
        if !built(&this) {
            return Err(this);
        }
        if let Some(m) = Arc::get_mut(&mut this)
            && let Some(f) = m.frames.get_mut()
            && let Some(Ok(frame)) = f.cell_mut(kind).take()
        {
            return Ok(frame);
        }
        match this.frames.get().and_then(|f| f.cell(kind).get()) {
            Some(Ok(frame)) => Ok(frame.clone()),
            _ => Err(this),
        }
    }

    /// The frame cache, made on first use.
    fn frames(&self) -> &Frames {
        self.frames.get_or_init(Box::default)
    }

    /// The rosbridge `publish` frame of this message in the given form, built once. JSON
    /// frames are text messages (validated as UTF-8 once, here), CBOR ones binary.
    pub fn rosbridge_frame(
        &self,
        kind: FrameKind,
        tc: &dyn Transcoder,
    ) -> Result<WsMessage, TranscodeError> {
        let topic = self.topic.name.as_str();
        self.frames()
            .cell(kind)
            .get_or_init(|| match kind {
                FrameKind::RosbridgeJson => {
                    let frame = match self.json_parts() {
                        Some(parts) => Bytes::from(parts.concat()),
                        None => {
                            let body =
                                tc.convert(&self.topic.schema, &self.payload, Encoding::Json)?;
                            outbound::publish_json(topic, &body)
                        }
                    };
                    let text = Utf8Bytes::try_from(frame).map_err(|e| TranscodeError::Invalid {
                        type_name: self.topic.schema.type_name.clone(),
                        from: self.payload.encoding,
                        to: Encoding::Json,
                        cause: format!("JSON is not UTF-8: {e}"),
                    })?;
                    Ok(WsMessage::Text(text))
                }
                FrameKind::RosbridgeCbor => {
                    let body = tc.convert(&self.topic.schema, &self.payload, Encoding::Cbor)?;
                    Ok(WsMessage::Binary(outbound::publish_cbor(topic, &body)))
                }
                FrameKind::RosbridgeCborRaw => {
                    // The raw ROS serialization: as it arrived, or CDR made from the message
                    // object when the type is known.
                    let raw = if self.payload.encoding.is_raw() {
                        self.payload.bytes.clone()
                    } else {
                        tc.convert(&self.topic.schema, &self.payload, Encoding::Cdr)?
                    };
                    Ok(WsMessage::Binary(outbound::publish_cbor_raw(
                        topic,
                        self.stamp_ns,
                        &raw,
                    )))
                }
                FrameKind::RosbridgePng => {
                    let json = self.rosbridge_frame(FrameKind::RosbridgeJson, tc)?;
                    let png = crate::png::op(&json.into_data());
                    Ok(WsMessage::Text(Utf8Bytes::from(png)))
                }
            })
            .clone()
    }

    /// The compressed form of the rosbridge `publish` frame of `kind` for a client that
    /// negotiated permessage-deflate, with whether it is text; `None` when the frame goes
    /// as it is: under `cfg.min_bytes`, a PNG frame or a type whose content is compressed
    /// already, or one that does not shrink. Compressed once, for every subscriber.
    pub fn deflated_frame(
        &self,
        kind: FrameKind,
        tc: &dyn Transcoder,
        cfg: DeflateConfig,
    ) -> Result<Option<(bool, Bytes)>, TranscodeError> {
        if kind == FrameKind::RosbridgePng || !self.topic.deflate_pays {
            return Ok(None);
        }
        let text = kind == FrameKind::RosbridgeJson;
        // A JSON text message is judged and compressed from its pieces: its whole frame
        // is never needed.
        if text && let Some(parts) = self.json_parts() {
            if parts.iter().map(|p| p.len()).sum::<usize>() < cfg.min_bytes {
                return Ok(None);
            }
            let z = self.deflated().frames[kind.index()].get_or_init(|| deflate::compress(&parts));
            return Ok(z.clone().map(|z| (text, z)));
        }
        let frame = self.rosbridge_frame(kind, tc)?;
        let bytes: &[u8] = match &frame {
            WsMessage::Text(t) => t.as_bytes(),
            WsMessage::Binary(b) => b,
            _ => return Ok(None),
        };
        if bytes.len() < cfg.min_bytes {
            return Ok(None);
        }
        let z = self.deflated().frames[kind.index()].get_or_init(|| deflate::compress(&[bytes]));
        Ok(z.clone().map(|z| (text, z)))
    }

    /// The compressed form of the message object in encoding `to` ([`Message::payload_in`])
    /// for a Foxglove client that negotiated permessage-deflate; `None` as for
    /// [`Message::deflated_frame`]. Compressed once, for every subscriber.
    pub fn deflated_payload(
        &self,
        to: Encoding,
        tc: &dyn Transcoder,
        cfg: DeflateConfig,
    ) -> Result<Option<Bytes>, TranscodeError> {
        if !self.topic.deflate_pays {
            return Ok(None);
        }
        let payload = self.payload_in(to, tc)?;
        if payload.len() < cfg.min_bytes {
            return Ok(None);
        }
        Ok(self.deflated().payloads[to as usize]
            .get_or_init(|| deflate::compress(&[&payload]))
            .clone())
    }

    fn deflated(&self) -> &Deflated {
        self.frames().deflated.get_or_init(Box::default)
    }

    /// The message object in encoding `to`: the bytes as they arrived when that is their
    /// encoding (shared, not copied), otherwise converted once for every subscriber that
    /// wants `to` (a Foxglove channel carries one encoding per topic; its `MessageData`
    /// is this payload behind a per-subscriber header).
    pub fn payload_in(&self, to: Encoding, tc: &dyn Transcoder) -> Result<Bytes, TranscodeError> {
        if self.payload.encoding == to {
            return Ok(self.payload.bytes.clone());
        }
        self.frames().converted[to as usize]
            .get_or_init(|| tc.convert(&self.topic.schema, &self.payload, to))
            .clone()
    }

    /// The `fleetlink.v1` frames of this message with the topic's router-wide id as alias:
    /// one `MESSAGE`, or `CHUNK`s when the payload is larger than the chunk size. Built
    /// once; the same bytes go to every downstream link.
    pub fn link_frames(&self) -> Arc<[Bytes]> {
        self.frames()
            .link
            .get_or_init(|| {
                let alias = self.topic.id.0;
                let p = &self.payload.bytes;
                if p.len() <= DEFAULT_CHUNK_SIZE {
                    let mut b = BytesMut::with_capacity(p.len() + 24);
                    frame::encode_message(&mut b, alias, self.seq, self.stamp_ns, p);
                    Arc::from([b.freeze()])
                } else {
                    let total = p.len() as u64;
                    p.chunks(DEFAULT_CHUNK_SIZE)
                        .enumerate()
                        .map(|(i, data)| {
                            let mut b = BytesMut::with_capacity(data.len() + 32);
                            let offset = (i * DEFAULT_CHUNK_SIZE) as u64;
                            frame::encode_chunk(
                                &mut b,
                                false,
                                alias,
                                self.seq,
                                self.stamp_ns,
                                total,
                                offset,
                                data,
                            );
                            b.freeze()
                        })
                        .collect::<Vec<_>>()
                        .into()
                }
            })
            .clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::GenericTranscoder;

    fn meta() -> Arc<TopicMeta> {
        Arc::new(TopicMeta::new(
            TopicId(3),
            TopicName::parse("/chatter").expect("valid name"),
            Schema::named("std_msgs/msg/String"),
            false,
        ))
    }

    fn message(json_text: bool) -> Message {
        let body = r#"{"data":"hi"}"#;
        Message::framed(
            meta(),
            1,
            7,
            ClientId(1),
            Payload::json(body),
            Instant::now(),
            json_text,
        )
    }

    #[test]
    fn the_pieces_of_a_json_text_message_make_the_frame_a_conversion_builds() {
        let converted = message(false)
            .rosbridge_frame(FrameKind::RosbridgeJson, &GenericTranscoder)
            .expect("converts");
        assert!(message(false).json_parts().is_none());
        let text = message(true);
        let parts = text.json_parts().expect("published as text").concat();
        assert_eq!(
            WsMessage::text(String::from_utf8(parts).unwrap()),
            converted
        );
        assert_eq!(
            text.rosbridge_frame(FrameKind::RosbridgeJson, &GenericTranscoder)
                .expect("framed"),
            converted
        );
        // PNG is made from the JSON frame, whichever way that was built.
        let png = |m: Message| m.rosbridge_frame(FrameKind::RosbridgePng, &GenericTranscoder);
        assert_eq!(
            png(message(true)).expect("png"),
            png(message(false)).expect("png")
        );
        // Only JSON payloads are JSON text.
        let cbor = Message::framed(
            meta(),
            1,
            7,
            ClientId(1),
            Payload::new(fleetlink_proto::Encoding::Cbor, Bytes::from_static(&[0xa0])),
            Instant::now(),
            true,
        );
        assert!(cbor.json_parts().is_none());
    }

    #[test]
    fn a_payload_in_another_encoding_is_converted_once_and_shared() {
        let tc = crate::transcode::RegistryTranscoder::bundled();
        let m = message(false);
        // In its own encoding: the bytes as they arrived.
        let same = m.payload_in(Encoding::Json, &tc).expect("as is");
        assert_eq!(same.as_ptr(), m.payload.bytes.as_ptr());
        // Converted once: every later caller gets the same bytes.
        let a = m.payload_in(Encoding::Cdr, &tc).expect("converts");
        let b = m.payload_in(Encoding::Cdr, &tc).expect("cached");
        assert_eq!(a.as_ptr(), b.as_ptr());
        assert_eq!(
            a,
            tc.convert(&m.topic.schema, &m.payload, Encoding::Cdr)
                .expect("converts")
        );
    }

    fn big(type_name: &str, json_text: bool) -> Message {
        let topic = Arc::new(TopicMeta::new(
            TopicId(4),
            TopicName::parse("/big").expect("valid name"),
            Schema::named(type_name),
            false,
        ));
        let body = format!(r#"{{"data":"{}"}}"#, "ros ".repeat(2000));
        let payload = Payload::json(body);
        Message::framed(topic, 1, 7, ClientId(1), payload, Instant::now(), json_text)
    }

    #[test]
    fn a_large_frame_is_compressed_once_and_shared() {
        let cfg = DeflateConfig::default();
        let inflate = |z: &Bytes| {
            crate::websocket::deflate::Inflater::new(1 << 20)
                .inflate(z)
                .expect("inflates")
        };
        for json_text in [true, false] {
            let m = big("std_msgs/msg/String", json_text);
            let (text, a) = m
                .deflated_frame(FrameKind::RosbridgeJson, &GenericTranscoder, cfg)
                .expect("converts")
                .expect("compressed");
            assert!(text);
            let (_, b) = m
                .deflated_frame(FrameKind::RosbridgeJson, &GenericTranscoder, cfg)
                .expect("converts")
                .expect("compressed");
            assert_eq!(a.as_ptr(), b.as_ptr(), "made once");
            let plain = m
                .rosbridge_frame(FrameKind::RosbridgeJson, &GenericTranscoder)
                .expect("converts");
            assert_eq!(inflate(&a), plain.into_data());
            assert!(a.len() * 10 < m.payload.len());
            // CBOR is compressed apart, and binary.
            let (text, _) = m
                .deflated_frame(FrameKind::RosbridgeCbor, &GenericTranscoder, cfg)
                .expect("converts")
                .expect("compressed");
            assert!(!text);
        }
        // The object for Foxglove, in its own encoding: compressed once too.
        let m = big("std_msgs/msg/String", false);
        let z = m
            .deflated_payload(Encoding::Json, &GenericTranscoder, cfg)
            .expect("as is")
            .expect("compressed");
        assert_eq!(inflate(&z), m.payload.bytes);
    }

    #[test]
    fn small_frames_and_compressed_content_go_as_they_are() {
        let cfg = DeflateConfig::default();
        let tc = &GenericTranscoder;
        // Under the threshold: nothing is built for it.
        let small = message(true);
        assert_eq!(
            small.deflated_frame(FrameKind::RosbridgeJson, tc, cfg),
            Ok(None)
        );
        assert!(small.frames.get().is_none());
        let large = big("std_msgs/msg/String", true);
        let high = DeflateConfig {
            min_bytes: large.payload.len() + 100,
        };
        assert_eq!(
            large.deflated_frame(FrameKind::RosbridgeJson, tc, high),
            Ok(None)
        );
        // JPEG, PNG, video: not worth the hub's time.
        let jpeg = big("sensor_msgs/msg/CompressedImage", true);
        assert_eq!(
            jpeg.deflated_frame(FrameKind::RosbridgeJson, tc, cfg),
            Ok(None)
        );
        assert_eq!(jpeg.deflated_payload(Encoding::Json, tc, cfg), Ok(None));
        assert_eq!(
            large.deflated_frame(FrameKind::RosbridgePng, tc, cfg),
            Ok(None)
        );
    }

    #[test]
    fn a_message_stays_small_until_a_frame_is_built_for_it() {
        // Allocated once per message and held in every subscriber's queue: kept within
        // the allocator's small sizes (glibc's fast bins take chunks of up to 128 bytes:
        // the message, the `Arc`'s two counts and malloc's own word).
        assert!(
            std::mem::size_of::<Message>() <= 120,
            "{}",
            std::mem::size_of::<Message>()
        );
    }

    #[test]
    fn the_last_holder_takes_the_built_frame_and_others_share_it() {
        let kind = FrameKind::RosbridgeJson;
        // Not built: the message comes back, for the writer to build the frame.
        let m = Arc::new(message(false));
        let back = Message::take_built_frame(m, kind).expect_err("nothing built");
        let made = back
            .rosbridge_frame(kind, &GenericTranscoder)
            .expect("converts");
        // Shared: a clone of the frame, the message keeps its own.
        let other = back.clone();
        let shared = Message::take_built_frame(back, kind).expect("built");
        assert_eq!(shared, made);
        // Last holder: the frame is moved out.
        let mut last = other;
        let taken = Message::take_built_frame(last.clone(), kind).expect("built");
        assert_eq!(taken, made);
        assert!(Arc::get_mut(&mut last).is_some(), "the clone was dropped");
        let moved = Message::take_built_frame(last, kind).expect("built");
        assert_eq!(moved, made);
    }
}
