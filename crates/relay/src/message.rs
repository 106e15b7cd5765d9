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
        Message {
            topic,
            seq,
            stamp_ns,
            received,
            origin,
            payload,
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

    /// The rosbridge `publish` frame of this message in the given form, built once. JSON
    /// frames are text messages (validated as UTF-8 once, here), CBOR ones binary.
    pub fn rosbridge_frame(
        &self,
        kind: FrameKind,
        tc: &dyn Transcoder,
    ) -> Result<WsMessage, TranscodeError> {
        let topic = self.topic.name.as_str();
        let cell = match kind {
            FrameKind::RosbridgeJson => &self.json,
            FrameKind::RosbridgeCbor => &self.cbor,
            FrameKind::RosbridgeCborRaw => &self.cbor_raw,
            FrameKind::RosbridgePng => &self.png,
        };
        cell.get_or_init(|| match kind {
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
