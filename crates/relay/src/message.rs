//! One published message, shared by every subscriber that receives it.
//!
//! The body stays in the encoding it arrived in. Each kind of outgoing frame (rosbridge
//! JSON, rosbridge CBOR, `cbor-raw`, `fleetlink.v1`) is built the first time a subscriber
//! needs it and kept in a [`OnceLock`], so a message fanned out to a hundred subscribers
//! is converted and framed at most once per kind, and every subscriber sends the same
//! [`Bytes`].

use std::sync::{Arc, OnceLock};
use std::time::Instant;

use bytes::{Bytes, BytesMut};
use fleetlink_proto::frame::{self, DEFAULT_CHUNK_SIZE};
use fleetlink_proto::rosbridge::outbound;
use fleetlink_proto::{Encoding, Payload, Schema};
use tokio_tungstenite::tungstenite::{Message as WsMessage, Utf8Bytes};

use crate::names::{ClientId, TopicId, TopicName};
use crate::transcode::{TranscodeError, Transcoder};

/// What a topic is, as of the moment a message was published on it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TopicMeta {
    pub id: TopicId,
    pub name: TopicName,
    pub schema: Schema,
    /// A publisher advertised the topic latched: links announce it so (`ADVERTISE_LATCHED`),
    /// and the far side latches it too.
    pub latched: bool,
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
    /// When this router received it; queue lag is measured from here.
    pub received: Instant,
    /// Who published it; it is never delivered back to its origin.
    pub origin: ClientId,
    pub payload: Payload,
    /// The JSON frame when the publisher built it ([`Message::framed`]); not a `OnceLock`
    /// set at once, which costs the lock's whole initialization per message.
    json_built: Option<WsMessage>,
    json: OnceLock<Result<WsMessage, TranscodeError>>,
    cbor: OnceLock<Result<WsMessage, TranscodeError>>,
    cbor_raw: OnceLock<Result<WsMessage, TranscodeError>>,
    png: OnceLock<Result<WsMessage, TranscodeError>>,
    link: OnceLock<Arc<[Bytes]>>,
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
        Self::framed(topic, seq, stamp_ns, origin, payload, received, None)
    }

    /// [`Message::received_at`] with its rosbridge JSON frame already built, if `json`
    /// is that frame's text (see [`outbound::publish_json_text`]): a publisher that sent
    /// the message as JSON text has it at hand, and the writers then need neither a
    /// conversion nor a second UTF-8 check.
    pub fn framed(
        topic: Arc<TopicMeta>,
        seq: u64,
        stamp_ns: u64,
        origin: ClientId,
        payload: Payload,
        received: Instant,
        json: Option<String>,
    ) -> Message {
        Message {
            topic,
            seq,
            stamp_ns,
            received,
            origin,
            payload,
            json_built: json.map(|f| WsMessage::Text(Utf8Bytes::from(f))),
            json: OnceLock::new(),
            cbor: OnceLock::new(),
            cbor_raw: OnceLock::new(),
            png: OnceLock::new(),
            link: OnceLock::new(),
        }
    }

    /// The same message numbered `seq` (a no-drop stream's own numbering, see
    /// [`crate::reliable`]); shares the payload, starts with an empty frame cache.
    pub fn resequenced(&self, seq: u64) -> Message {
        Message {
            seq,
            received: self.received,
            ..Message::new(
                self.topic.clone(),
                seq,
                self.stamp_ns,
                self.origin,
                self.payload.clone(),
            )
        }
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
        if kind == FrameKind::RosbridgeJson && this.json_built.is_some() {
            return Ok(match Arc::get_mut(&mut this) {
                Some(m) => m.json_built.take(),
                None => this.json_built.clone(),
            }
            .expect("checked above"));
        }
        if !matches!(this.cell(kind).get(), Some(Ok(_))) {
            return Err(this);
        }
        if let Some(m) = Arc::get_mut(&mut this)
            && let Some(Ok(frame)) = m.cell_mut(kind).take()
        {
            return Ok(frame);
        }
        match this.cell(kind).get() {
            Some(Ok(frame)) => Ok(frame.clone()),
            _ => Err(this),
        }
    }

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

    /// The rosbridge `publish` frame of this message in the given form, built once. JSON
    /// frames are text messages (validated as UTF-8 once, here), CBOR ones binary.
    pub fn rosbridge_frame(
        &self,
        kind: FrameKind,
        tc: &dyn Transcoder,
    ) -> Result<WsMessage, TranscodeError> {
        if let (FrameKind::RosbridgeJson, Some(built)) = (kind, &self.json_built) {
            return Ok(built.clone());
        }
        let topic = self.topic.name.as_str();
        self.cell(kind)
            .get_or_init(|| match kind {
                FrameKind::RosbridgeJson => {
                    let body = tc.convert(&self.topic.schema, &self.payload, Encoding::Json)?;
                    let text =
                        Utf8Bytes::try_from(outbound::publish_json(topic, &body)).map_err(|e| {
                            TranscodeError::Invalid {
                                type_name: self.topic.schema.type_name.clone(),
                                from: self.payload.encoding,
                                to: Encoding::Json,
                                cause: format!("JSON is not UTF-8: {e}"),
                            }
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

    /// The `fleetlink.v1` frames of this message with the topic's router-wide id as alias:
    /// one `MESSAGE`, or `CHUNK`s when the payload is larger than the chunk size. Built
    /// once; the same bytes go to every downstream link.
    pub fn link_frames(&self) -> Arc<[Bytes]> {
        self.link
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
        Arc::new(TopicMeta {
            id: TopicId(3),
            name: TopicName::parse("/chatter").expect("valid name"),
            schema: Schema::named("std_msgs/msg/String"),
            latched: false,
        })
    }

    fn message(json: Option<String>) -> Message {
        let body = r#"{"data":"hi"}"#;
        Message::framed(
            meta(),
            1,
            7,
            ClientId(1),
            Payload::json(body),
            Instant::now(),
            json,
        )
    }

    #[test]
    fn a_frame_built_by_the_publisher_is_the_frame_the_writers_would_build() {
        let built = outbound::publish_json_text("/chatter", r#"{"data":"hi"}"#);
        let lazy = message(None)
            .rosbridge_frame(FrameKind::RosbridgeJson, &GenericTranscoder)
            .expect("converts");
        let eager = message(Some(built))
            .rosbridge_frame(FrameKind::RosbridgeJson, &GenericTranscoder)
            .expect("built");
        assert_eq!(eager, lazy);
        // PNG is made from the JSON frame, whichever way that was built.
        let png = |m: Message| m.rosbridge_frame(FrameKind::RosbridgePng, &GenericTranscoder);
        let built = outbound::publish_json_text("/chatter", r#"{"data":"hi"}"#);
        assert_eq!(
            png(message(Some(built))).expect("png"),
            png(message(None)).expect("png")
        );
    }

    #[test]
    fn the_last_holder_takes_the_built_frame_and_others_share_it() {
        let frame = || Some(outbound::publish_json_text("/chatter", r#"{"data":"hi"}"#));
        let kind = FrameKind::RosbridgeJson;
        // Shared: a clone of the frame, the message keeps its own.
        let m = Arc::new(message(frame()));
        let other = m.clone();
        let shared = Message::take_built_frame(m, kind).expect("built");
        assert_eq!(Some(&shared), other.json_built.as_ref());
        // Last holder: the frame is moved out.
        let mut last = other;
        let taken = Message::take_built_frame(last.clone(), kind).expect("built");
        assert_eq!(taken, shared);
        assert!(Arc::get_mut(&mut last).is_some(), "the clone was dropped");
        let moved = Message::take_built_frame(last, kind).expect("built");
        assert_eq!(moved, shared);
        // Not built: the message comes back, for the writer to build the frame.
        let m = Arc::new(message(None));
        let back = Message::take_built_frame(m, kind).expect_err("nothing built");
        let made = back
            .rosbridge_frame(kind, &GenericTranscoder)
            .expect("converts");
        assert_eq!(made, shared);
        // Once made, it is built.
        assert_eq!(
            Message::take_built_frame(back, kind).expect("built"),
            shared
        );
    }
}
