//! The parts of a `fleetlink.v1` link that hub and agent share: the link session
//! ([`session::LinkSession`], the protocol as one state machine for both ends), turning
//! received frames into topic events ([`LinkIn`]), what goes out on the link next without
//! I/O ([`Outbound`]: an outbox's messages, chunks, announcements, the session's frames)
//! and the task that writes it ([`write_link`]).
//!
//! On every link a topic's alias is its id in the *sending* router, so a message's frames
//! ([`Message::link_frames`](crate::Message::link_frames)) are the same bytes for every
//! link it goes out on. Large messages go out as `CHUNK`s, one chunk per topic per round,
//! so a small message on another topic overtakes a large one that is half sent.

mod compress;
pub mod drive;
pub mod outbound;
pub mod session;
mod writer;

pub use outbound::{Outbound, Round, Transmit, ViaOut};
pub use writer::write_link;

use std::collections::VecDeque;
use std::sync::Arc;
use std::sync::atomic::AtomicU64;
use std::sync::atomic::Ordering::Relaxed;
use std::time::Instant;

use bytes::Bytes;
use fleetlink_proto::frame::{ADVERTISE_LATCHED, ADVERTISE_PULL, ADVERTISE_RELIABLE, Frame};
use fleetlink_proto::reassembly::{Reassembler, ReassemblyError};
use fleetlink_proto::{Encoding, Payload, Schema};
use tokio_tungstenite::tungstenite::protocol::CloseFrame;

use crate::message::{TopicMeta, Via};
use crate::names::TopicId;

/// Ids of heartbeat `PING`s start here; lower ids are link-estimator probes.
pub const HEARTBEAT_ID_BASE: u64 = 1 << 62;

/// Largest message reassembled from chunks.
pub const MAX_LINK_MESSAGE: usize = 64 << 20;
/// Largest total of partially received chunked messages on one link.
pub const MAX_LINK_REASSEMBLY: usize = 128 << 20;

/// A topic the peer announced on this link.
#[derive(Debug, Clone)]
pub struct InTopic {
    pub name: String,
    pub schema: Schema,
    pub encoding: Encoding,
    pub latched: bool,
    /// No-drop: sequence numbers are the sender's stream numbering; confirm with
    /// `DELIVERED`.
    pub reliable: bool,
    /// A pull topic: sent only when asked (`PULL`).
    pub pull: bool,
}

/// What a received frame means for the router.
#[derive(Debug)]
pub enum LinkEvent {
    Advertise {
        alias: u32,
        topic: InTopic,
        /// The hubs its publisher is behind, from a peer hub's `VIA`.
        via: Option<Arc<Via>>,
    },
    Unadvertise {
        alias: u32,
        topic: InTopic,
    },
    Message {
        alias: u32,
        seq: u64,
        stamp_ns: u64,
        payload: Payload,
        /// Its topic was advertised reliable (no-drop): `seq` is the sender's stream
        /// number, to be confirmed with `DELIVERED`.
        reliable: bool,
        /// Bytes the message took on the link (compressed, if it came so).
        wire_len: usize,
        /// The hubs it has passed, from a peer hub's `VIA`.
        via: Option<Arc<Via>>,
    },
    /// Every other frame (HELLO, SUBSCRIBE, PING, ACK, SHARE, ...), as decoded: there is
    /// nothing to resolve on the link for them.
    Control(Frame),
    /// Nothing for the router (an unknown frame, a chunk that is not complete).
    None,
}

#[derive(Debug, thiserror::Error)]
pub enum LinkError {
    #[error("message on alias {0} that was never advertised")]
    UnknownAlias(u32),
    #[error(transparent)]
    Reassembly(#[from] ReassemblyError),
    #[error("topic {topic}: {error}")]
    Compression {
        topic: String,
        error: fleetlink_proto::DecodeError,
    },
}

/// Per-link receive state: the peer's aliases and partially received chunked messages.
pub struct LinkIn {
    // Looked up for every message: small integer keys the peer chose, hashed with Fx
    // (no collision attack pays: a link may bind at most as many aliases as it sends
    // ADVERTISEs, each counted against its own messages).
    aliases: rustc_hash::FxHashMap<u32, InTopic>,
    reassembly: Reassembler,
    /// Whole messages received since the last `ACK` we sent.
    pub unacked: u32,
    /// Payload bytes (message payloads, chunk data) received since the last `ACK`.
    pub unacked_bytes: u64,
    /// A piece of a chunked message came since the last `ACK` (its sender paces bulk
    /// data by the acknowledgements: they go at once).
    pub unacked_chunk: bool,
    /// The hubs the messages arriving now have passed: the peer hub's last `VIA` (none
    /// from an agent, which sends no `VIA`).
    via: Option<Arc<Via>>,
    /// This end's hub, if it is one: a message whose `VIA` lists it has come back and is
    /// dropped ([`LinkIn::looped`]).
    pub local_hub: Option<u64>,
    /// The peer hub's id, the last of its `VIA`s (0 until one came): the link's writer
    /// sends it nothing that has passed it, and marks what it sends with `VIA`.
    pub peer_hub: Arc<AtomicU64>,
    /// Messages dropped because they had passed this hub before.
    pub looped: u64,
    /// Topics refused because their publisher is behind this hub (a cycle of hub links).
    pub looped_topics: u64,
}

impl Default for LinkIn {
    fn default() -> Self {
        LinkIn {
            aliases: rustc_hash::FxHashMap::default(),
            reassembly: Reassembler::new(MAX_LINK_MESSAGE, MAX_LINK_REASSEMBLY),
            unacked: 0,
            unacked_bytes: 0,
            unacked_chunk: false,
            via: None,
            local_hub: None,
            peer_hub: Arc::default(),
            looped: 0,
            looped_topics: 0,
        }
    }
}

impl LinkIn {
    pub fn topic(&self, alias: u32) -> Option<&InTopic> {
        self.aliases.get(&alias)
    }

    pub fn on_frame(&mut self, frame: Frame) -> Result<LinkEvent, LinkError> {
        Ok(match frame {
            Frame::Advertise {
                alias,
                topic,
                schema,
                encoding,
                flags,
            } => {
                let t = InTopic {
                    name: topic,
                    schema,
                    encoding,
                    latched: flags & ADVERTISE_LATCHED != 0,
                    reliable: flags & ADVERTISE_RELIABLE != 0,
                    pull: flags & ADVERTISE_PULL != 0,
                };
                if self.came_back() {
                    // A cycle of hub links: the topic's publisher is behind this hub.
                    self.looped_topics += 1;
                    return Ok(LinkEvent::None);
                }
                self.aliases.insert(alias, t.clone());
                LinkEvent::Advertise {
                    alias,
                    topic: t,
                    via: self.via.clone(),
                }
            }
            Frame::Unadvertise { alias } => {
                self.reassembly.forget(alias);
                match self.aliases.remove(&alias) {
                    Some(topic) => LinkEvent::Unadvertise { alias, topic },
                    None => LinkEvent::None,
                }
            }
            Frame::Message {
                alias,
                seq,
                stamp_ns,
                payload,
            } => self.on_message(alias, seq, stamp_ns, payload, false)?,
            Frame::ZMessage {
                alias,
                seq,
                stamp_ns,
                payload,
            } => self.on_message(alias, seq, stamp_ns, payload, true)?,
            Frame::Chunk {
                alias,
                seq,
                stamp_ns,
                total_len,
                offset,
                data,
            } => self.on_chunk(alias, seq, stamp_ns, total_len, offset, data, false)?,
            Frame::ZChunk {
                alias,
                seq,
                stamp_ns,
                total_len,
                offset,
                data,
            } => self.on_chunk(alias, seq, stamp_ns, total_len, offset, data, true)?,
            Frame::Via { hubs } => {
                if let Some(peer) = hubs.last() {
                    self.peer_hub.store(*peer, Relaxed);
                }
                self.via = (!hubs.is_empty()).then(|| Arc::new(Via::new(hubs)));
                LinkEvent::None
            }
            Frame::Unknown { .. } => LinkEvent::None,
            other => LinkEvent::Control(other),
        })
    }

    /// A whole message; `compressed`: its payload is a compression envelope, opened here,
    /// once, before the router sees it.
    fn on_message(
        &mut self,
        alias: u32,
        seq: u64,
        stamp_ns: u64,
        payload: Bytes,
        compressed: bool,
    ) -> Result<LinkEvent, LinkError> {
        {
            self.unacked += 1;
            self.unacked_bytes += payload.len() as u64;
            if !self.aliases.contains_key(&alias) {
                return Err(LinkError::UnknownAlias(alias));
            }
            if self.came_back() {
                self.looped += 1;
                return Ok(LinkEvent::None);
            }
            let t = self
                .aliases
                .get(&alias)
                .ok_or(LinkError::UnknownAlias(alias))?;
            let wire_len = payload.len();
            Ok(LinkEvent::Message {
                alias,
                seq,
                stamp_ns,
                payload: Payload::new(t.encoding, open(t, payload, compressed)?),
                reliable: t.reliable,
                wire_len,
                via: self.via.clone(),
            })
        }
    }

    /// A piece of a large message (of a compressed one, when `compressed`).
    #[allow(clippy::too_many_arguments)]
    fn on_chunk(
        &mut self,
        alias: u32,
        seq: u64,
        stamp_ns: u64,
        total_len: u64,
        offset: u64,
        data: Bytes,
        compressed: bool,
    ) -> Result<LinkEvent, LinkError> {
        Ok({
            self.unacked_bytes += data.len() as u64;
            self.unacked_chunk = true;
            let t = self
                .aliases
                .get(&alias)
                .ok_or(LinkError::UnknownAlias(alias))?;
            let (encoding, reliable) = (t.encoding, t.reliable);
            match self
                .reassembly
                .push(alias, seq, stamp_ns, total_len, offset, &data)?
            {
                Some(done) => {
                    self.unacked += 1;
                    let t = self
                        .aliases
                        .get(&alias)
                        .ok_or(LinkError::UnknownAlias(alias))?;
                    let wire_len = done.payload.len();
                    // The last piece's kind says what the whole is, and the VIA before
                    // it which hubs the message passed (a sender marks every piece).
                    let payload = open(t, done.payload, compressed)?;
                    if self.came_back() {
                        self.looped += 1;
                        return Ok(LinkEvent::None);
                    }
                    LinkEvent::Message {
                        alias,
                        seq: done.seq,
                        stamp_ns: done.stamp_ns,
                        payload: Payload::new(encoding, payload),
                        reliable,
                        wire_len,
                        via: self.via.clone(),
                    }
                }
                None => LinkEvent::None,
            }
        })
    }
}

impl LinkIn {
    /// Whether what arrives now has passed this hub before.
    fn came_back(&self) -> bool {
        matches!((self.local_hub, &self.via), (Some(me), Some(v)) if v.contains(me))
    }
}

/// A message's payload as it came on the link, opened from its envelope when it came
/// compressed (never larger than [`MAX_LINK_MESSAGE`]).
fn open(topic: &InTopic, bytes: Bytes, compressed: bool) -> Result<Bytes, LinkError> {
    if !compressed {
        return Ok(bytes);
    }
    fleetlink_proto::compress::open(&bytes, MAX_LINK_MESSAGE).map_err(|error| {
        LinkError::Compression {
            topic: topic.name.clone(),
            error,
        }
    })
}

/// Maps a router topic to the name it has on this link; `None` keeps it off the link.
pub type LinkNamer = Arc<dyn Fn(&TopicMeta) -> Option<String> + Send + Sync>;

/// The way to a link's writer: its [`Control`]s in a bounded queue, each boxed. tokio's
/// channel allocates room for 32 entries at a time and a `Control` is over 100 bytes, so
/// boxed an idle link's queue holds a few hundred bytes instead of several kilobytes
/// (10,000 idle robots, docs/benchmarks/log.md); a box per control frame is nothing beside
/// what the frame is for.
pub type ControlSender = tokio::sync::mpsc::Sender<Box<Control>>;
/// The writer's end of [`ControlSender`].
pub type ControlReceiver = tokio::sync::mpsc::Receiver<Box<Control>>;

/// Frames written on a link besides messages (replies, subscriptions, status).
#[derive(Debug)]
pub enum Control {
    Frame(Frame),
    /// Frames of one large call body (its `CALL_CHUNK`s, then the frame they belong to):
    /// sent one per writer round, between other traffic, in order.
    Sequence(VecDeque<Frame>),
    /// The topic has had no publisher since `since`: tell the peer (`UNADVERTISE`) once
    /// what was queued for it has been sent. Ignored for a topic never advertised on this
    /// link and for no-drop (reliable) topics, whose streams outlive their publishers;
    /// dropped when a message of the topic received after `since` comes (published
    /// again). A later message of the topic advertises it again.
    Unadvertise {
        topic: TopicId,
        since: Instant,
    },
    /// Announce the topic (`ADVERTISE`) if it is not announced on this link yet, in
    /// `encoding`: a topic nobody on the far side wants has no message to announce it by.
    Announce {
        meta: Arc<TopicMeta>,
        encoding: fleetlink_proto::Encoding,
    },
    /// A WebSocket pong answering the peer's ping (RFC 6455 5.5.3), after what is queued.
    Pong(Bytes),
    /// Close the link after flushing what is queued, with this close frame (code and
    /// reason) if any.
    Close(Option<CloseFrame>),
}

impl LinkIn {
    /// An `ACK` for what arrived since the last one, if anything did.
    pub fn take_ack(&mut self) -> Option<Frame> {
        let n = std::mem::take(&mut self.unacked);
        let bytes = std::mem::take(&mut self.unacked_bytes);
        self.unacked_chunk = false;
        (n > 0 || bytes > 0).then_some(Frame::Ack { frames: n, bytes })
    }
}

/// Parses every frame of one received WebSocket message.
pub fn decode_all(data: &Bytes) -> Result<Vec<Frame>, fleetlink_proto::DecodeError> {
    fleetlink_proto::frame::frames(data).collect()
}
