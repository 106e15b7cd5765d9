//! `fleetlink.v1` frames: the binary protocol between agents and the hub.
//!
//! A WebSocket binary message carries one or more frames back to back, so a sender can
//! pack many small messages into one write. Every frame is
//!
//! ```text
//! +---------+----------------+--------------------+
//! | kind u8 | body_len varint| body (body_len)    |
//! +---------+----------------+--------------------+
//! ```
//!
//! and a decoder skips frames of unknown kind and ignores bytes after the fields it knows,
//! so later versions can add frames and append fields. Body layouts are drawn per variant
//! below and in `docs/protocol.md`.
//!
//! The service and action frames (`0x10`–`0x17`) share the enum and the codec with the
//! topic frames, but what only they need — call outcomes, their decoder, cutting a large
//! call body into `CALL_CHUNK`s — lives in the `calls` submodule, re-exported here.

mod calls;

use bytes::{BufMut, Bytes, BytesMut};

use crate::error::{DecodeError, ErrorKind};
use crate::payload::{Encoding, Schema};
use crate::wire::{Reader, put_bytes, put_str, put_varint, varint_len};

pub use calls::{CallStatus, split_call_body};

/// The WebSocket subprotocol name agents ask for.
pub const SUBPROTOCOL: &str = "fleetlink.v1";
/// Protocol version carried in `HELLO`.
pub const VERSION: u32 = 1;
/// Payloads larger than this are sent as `CHUNK` frames by default. Small enough that a
/// priority message waiting behind one chunk on a 4 Mbit/s link waits ~33 ms, large enough
/// that the ~25 bytes of chunk header stay under 0.2 % of the data.
pub const DEFAULT_CHUNK_SIZE: usize = 16 * 1024;

/// Frame kind bytes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum FrameKind {
    Hello = 0x01,
    Welcome = 0x02,
    Advertise = 0x03,
    Unadvertise = 0x04,
    Subscribe = 0x05,
    Unsubscribe = 0x06,
    Message = 0x07,
    Chunk = 0x08,
    Ping = 0x09,
    Pong = 0x0a,
    Ack = 0x0b,
    Status = 0x0c,
    Share = 0x0d,
    LinkReport = 0x0e,
    Delivered = 0x0f,
    ServiceAdvertise = 0x10,
    ServiceUnadvertise = 0x11,
    Call = 0x12,
    Goal = 0x13,
    Reply = 0x14,
    Feedback = 0x15,
    Cancel = 0x16,
    CallChunk = 0x17,
    Interest = 0x18,
    Pull = 0x19,
    ZMessage = 0x1a,
    ZChunk = 0x1b,
    Budget = 0x1c,
    TopicDrops = 0x1d,
    TopicLoad = 0x1e,
    Via = 0x1f,
}

/// Most hubs a `VIA` lists: a chain of site hubs deeper than this is refused.
pub const MAX_VIA: usize = 64;

/// Severity of a `STATUS` frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum Level {
    Info = 0,
    Warning = 1,
    Error = 2,
}

impl Level {
    fn from_u8(v: u8) -> Level {
        match v {
            0 => Level::Info,
            1 => Level::Warning,
            _ => Level::Error,
        }
    }

    pub fn as_str(self) -> &'static str {
        match self {
            Level::Info => "info",
            Level::Warning => "warning",
            Level::Error => "error",
        }
    }
}

/// `STATUS` codes. The numbers borrow HTTP's meanings so they read at a glance in logs;
/// receivers treat a code they do not know by its level alone.
pub mod status_code {
    /// Nothing more specific to say (informational text).
    pub const NONE: u32 = 0;
    /// A frame could not be decoded; the rest of that WebSocket message was dropped.
    pub const MALFORMED: u32 = 400;
    /// `HELLO` credentials were refused; the hub closes the connection.
    pub const UNAUTHORIZED: u32 = 401;
    /// The ACL forbids this topic for this peer (advertise, subscribe or publish).
    pub const FORBIDDEN: u32 = 403;
    /// `MESSAGE`, `CHUNK` or `UNADVERTISE` named an alias that is not bound.
    pub const UNKNOWN_ALIAS: u32 = 404;
    /// A chunked message broke the chunk rules (out of order, wrong seq) and was dropped.
    pub const CHUNK_ORDER: u32 = 409;
    /// A chunked message exceeded the receiver's size or buffer limits and was dropped.
    pub const TOO_LARGE: u32 = 413;
    /// The peer sends faster than the receiver's limits allow; messages are being dropped.
    pub const RATE_LIMITED: u32 = 429;
    /// The receiver failed for its own reasons.
    pub const INTERNAL: u32 = 500;
}

/// `ADVERTISE` flag: the publisher wants late subscribers to get its last message.
pub const ADVERTISE_LATCHED: u8 = 0x01;
/// `ADVERTISE` flag: the topic is no-drop. Its `seq` numbers are the sender's stream
/// sequence for this topic (strictly increasing for the life of the sender's outbox, see
/// `HELLO.outbox_epoch`); the receiver delivers each sequence number at most once and
/// confirms delivery with `DELIVERED`, and the sender keeps every message until then,
/// resending it on the next connection if this one dies first.
pub const ADVERTISE_RELIABLE: u8 = 0x02;
/// `TOPIC_LOAD` flag: the topic is no-drop (its messages go before every other topic's).
pub const TOPIC_LOAD_NO_DROP: u8 = 0x01;

/// One topic of a `TOPIC_LOAD` report.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TopicLoadEntry {
    pub alias: u32,
    /// Messages per second the robot's publishers offer, in thousandths (after the topic's
    /// rate limit).
    pub rate_mhz: u64,
    /// Payload bytes per second they offer, before compression.
    pub bytes_per_sec: u64,
    /// The topic's scheduler priority, in thousandths.
    pub priority_milli: u32,
    /// Messages its uplink queue holds.
    pub queue: u32,
    /// [`TOPIC_LOAD_NO_DROP`].
    pub flags: u8,
}

/// `SUBSCRIBE` flag: `pattern` is a regular expression matched against whole topic names.
pub const SUBSCRIBE_REGEX: u8 = 0x01;
/// `SERVICE_ADVERTISE` flag: the service is an action (goals, feedback, cancel).
pub const SERVICE_ACTION: u8 = 0x01;
/// `SUBSCRIBE` flag: `pattern` names services and actions, not topics: the peer answers
/// with `SERVICE_ADVERTISE` for every matching service it offers, now and as they appear,
/// and `SERVICE_UNADVERTISE` as they go.
pub const SUBSCRIBE_SERVICES: u8 = 0x02;
/// `ADVERTISE` flag: a pull topic, sent only when the receiver asks (`PULL`), one message
/// per request.
pub const ADVERTISE_PULL: u8 = 0x04;
/// `WELCOME` feature: the hub takes compressed messages (`ZMESSAGE`, `ZCHUNK`).
pub const WELCOME_COMPRESSION: u64 = 0x02;
/// `WELCOME` feature: the hub tells the agent which of its topics are wanted (`INTEREST`),
/// and the agent sends a topic only while it is (demand-driven uplink).
pub const WELCOME_INTEREST: u64 = 0x01;

#[derive(Debug, Clone, PartialEq)]
pub enum Frame {
    /// Agent → hub, first frame on a connection.
    /// `version varint | robot str | token str | heartbeat_ms varint | outbox_epoch u64le`
    ///
    /// `outbox_epoch` names the agent's no-drop sequence space: it changes only when the
    /// agent's outbox starts afresh (a new durable outbox, or no durable outbox and a
    /// restart), telling the receiver that sequence numbers begin again. 0 = none (no
    /// reliable topics); absent in older senders, read as 0.
    ///
    /// `mirror str`, written only when not empty: this link is a *mirror* of the robot it
    /// names (docs/mirror.md): its topics live in that robot's namespace, and it does not
    /// replace the robot's own link; `robot` is then the mirror's own name.
    Hello {
        version: u32,
        robot: String,
        token: String,
        heartbeat_ms: u32,
        outbox_epoch: u64,
        mirror: String,
    },
    /// Hub → agent, answers `HELLO`.
    /// `session str | namespace str | hub_time_ns u64le | heartbeat_ms varint |
    ///  features varint`
    ///
    /// `features` are [`WELCOME_INTEREST`] and later bits; absent in older senders, read
    /// as 0 (an agent then sends every topic, as it always did).
    Welcome {
        session: String,
        namespace: String,
        hub_time_ns: u64,
        heartbeat_ms: u32,
        features: u64,
    },
    /// Either direction: binds `alias` to a topic for the rest of the connection.
    /// `alias varint | topic str | type str | schema_encoding str | schema_text bytes |
    ///  encoding u8 | flags u8`
    Advertise {
        alias: u32,
        topic: String,
        schema: Schema,
        encoding: Encoding,
        flags: u8,
    },
    /// `alias varint`
    Unadvertise { alias: u32 },
    /// Either direction: ask the peer for topics matching `pattern`.
    /// `id varint | pattern str | flags u8 | throttle_ms varint | queue_length varint`
    Subscribe {
        id: u32,
        pattern: String,
        flags: u8,
        throttle_ms: u32,
        queue_length: u32,
    },
    /// `id varint`
    Unsubscribe { id: u32 },
    /// One whole message. `alias varint | seq varint | stamp_ns u64le | payload (rest)`
    Message {
        alias: u32,
        seq: u64,
        stamp_ns: u64,
        payload: Bytes,
    },
    /// A piece of a large message; pieces of one message arrive in order, pieces of
    /// different topics may interleave.
    /// `alias varint | seq varint | stamp_ns u64le | total_len varint | offset varint |
    ///  data (rest)`
    Chunk {
        alias: u32,
        seq: u64,
        stamp_ns: u64,
        total_len: u64,
        offset: u64,
        data: Bytes,
    },
    /// A compressed message: `MESSAGE`'s layout, the payload a compression envelope
    /// ([`crate::compress`]). Sent only to a hub that offers [`WELCOME_COMPRESSION`].
    ZMessage {
        alias: u32,
        seq: u64,
        stamp_ns: u64,
        payload: Bytes,
    },
    /// A piece of a compressed message: `CHUNK`'s layout; the pieces reassemble to a
    /// compression envelope. Every piece of one message has the same kind.
    ZChunk {
        alias: u32,
        seq: u64,
        stamp_ns: u64,
        total_len: u64,
        offset: u64,
        data: Bytes,
    },
    /// Agent → hub, about once a second while the robot has a data budget: what it allows
    /// (0 = no such limit), the bytes counted against it, and the topics it held back
    /// lately. `max_bps varint | day_bytes varint | used_bytes varint | count varint |
    /// alias varint × count`
    Budget {
        max_bps: u64,
        day_bytes: u64,
        used_bytes: u64,
        thinned: Vec<u32>,
    },
    /// Agent → hub, with the once-a-second report, for topics whose counts changed: the
    /// messages the robot lost of each topic, by reason (the relay's `DropReason` index:
    /// 0 rate_limit, 1 policy, 2 backpressure, 3 encode_error, 4 too_old), counted since
    /// the agent started. `count varint | (alias varint | n varint | (reason u8 |
    /// dropped varint) × n) × count`
    TopicDrops { topics: Vec<(u32, Vec<(u8, u64)>)> },
    /// Agent → hub, with the once-a-second report: what the robot offers of each topic it
    /// carries up, and how its uplink queues it (for the hub's receive-rate prediction).
    /// `count varint | (alias varint | rate_mhz varint | bytes_per_sec varint |
    ///  priority_milli varint | queue varint | flags u8) × count`
    TopicLoad { topics: Vec<TopicLoadEntry> },
    /// `id u64le | sent_ns u64le`
    Ping { id: u64, sent_ns: u64 },
    /// `id u64le | echo_ns u64le | responder_ns u64le`
    Pong {
        id: u64,
        echo_ns: u64,
        responder_ns: u64,
    },
    /// Receiver → sender, since the last `ACK`: `frames` whole messages arrived (a chunked
    /// message counts when its last chunk does) and `bytes` bytes of message payload
    /// (`MESSAGE` payloads and `CHUNK` data), in arrival order. `bytes` lets a sender account
    /// for every chunk it wrote, not only for whole messages.
    /// `frames varint | bytes varint` (`bytes` absent in older senders: read as 0)
    Ack { frames: u32, bytes: u64 },
    /// `level u8 | code varint | alias varint (0 = none) | text str`
    Status {
        level: Level,
        code: u32,
        alias: u32,
        text: String,
    },
    /// Hub → agent: the robot's share of its site's access link, bytes per second
    /// (0 = no cap). `bytes_per_sec u64le`
    Share { bytes_per_sec: u64 },
    /// Agent → hub, when its figures moved (looked at once a second): what the robot
    /// would send if it could, what its link delivered, its measured one-way latency, what
    /// it may send now (the smallest of its capacity share, its data budget's rate and the
    /// link's best measured rate; 0 = not known), and when the link's rate was last
    /// measured with data on it, Unix ms on the hub's clock (0 = never: an idle link is
    /// not probed, so its figure is as old as its last traffic).
    /// `demand_bps u64le | rate_bps u64le | latency_ns u64le | capacity_bps u64le |
    /// measured_at_ms u64le` (the last two absent in older senders: read as 0)
    LinkReport {
        demand_bps: u64,
        rate_bps: u64,
        latency_ns: u64,
        capacity_bps: u64,
        measured_at_ms: u64,
    },
    /// Receiver → sender of a reliable topic (`ADVERTISE_RELIABLE`): every message of
    /// `alias` up to and including `seq` has been delivered (and recorded, so it is never
    /// delivered again); the sender may forget them. `alias varint | seq varint`
    Delivered { alias: u32, seq: u64 },
    /// Either direction: binds `alias` to a service (or, with [`SERVICE_ACTION`], an
    /// action) this side provides, for the rest of the connection. Service aliases are a
    /// space of their own, apart from topic aliases. `schema` carries the `.srv` or
    /// `.action` definition so the receiver can convert bodies between encodings.
    /// `alias varint | name str | type str | schema_encoding str | schema_text str |
    ///  flags u8`
    ServiceAdvertise {
        alias: u32,
        name: String,
        schema: Schema,
        flags: u8,
    },
    /// The service bound to `alias` is no longer offered; no new call may name the alias
    /// until it is bound again. `alias varint`
    ServiceUnadvertise { alias: u32 },
    /// Caller side → provider side: a request to the service bound to `alias`. `call_id`
    /// is chosen by the sender, unique among its calls in flight on this connection.
    /// `deadline_ms` is what is left of the caller's deadline (0 = none).
    /// `call_id varint | alias varint | deadline_ms varint | encoding u8 | payload (rest)`
    Call {
        call_id: u64,
        alias: u32,
        deadline_ms: u64,
        encoding: Encoding,
        payload: Bytes,
    },
    /// Caller side → provider side: a goal for the action bound to `alias`; a call that
    /// may get `FEEDBACK` before its `REPLY` and may be cancelled. `goal_id` is the UUID
    /// ROS 2 needs in `action_msgs/GoalInfo`.
    /// `call_id varint | alias varint | deadline_ms varint | goal_id 16 bytes |
    ///  encoding u8 | payload (rest)`
    Goal {
        call_id: u64,
        alias: u32,
        deadline_ms: u64,
        goal_id: [u8; 16],
        encoding: Encoding,
        payload: Bytes,
    },
    /// Provider side → caller side: the end of call (or goal) `call_id`. The payload is the
    /// response (the action's result for a goal) when `status` is `Ok`, otherwise UTF-8
    /// text saying what went wrong.
    /// `call_id varint | status u8 | encoding u8 | payload (rest)`
    Reply {
        call_id: u64,
        status: CallStatus,
        encoding: Encoding,
        payload: Bytes,
    },
    /// Provider side → caller side: progress of goal `call_id`.
    /// `call_id varint | encoding u8 | payload (rest)`
    Feedback {
        call_id: u64,
        encoding: Encoding,
        payload: Bytes,
    },
    /// Caller side → provider side: the caller gives up on call or goal `call_id`.
    /// `call_id varint`
    Cancel { call_id: u64 },
    /// A piece of a large `CALL`/`GOAL`/`REPLY`/`FEEDBACK` body (`kind` names which). The
    /// pieces go first, in order, and the frame they belong to follows with the last piece
    /// as its payload, so a body is complete when its frame arrives (see
    /// [`split_call_body`]).
    /// `call_id varint | kind u8 | total_len varint | offset varint | data (rest)`
    CallChunk {
        call_id: u64,
        kind: u8,
        total_len: u64,
        offset: u64,
        data: Bytes,
    },
    /// Hub → agent: whether anyone beyond the robot wants the topic the agent announced
    /// as `alias` (`wanted` 1) or nobody does (0). Sent for every `ADVERTISE` the hub
    /// accepts and again whenever the answer changes, so after a reconnect the agent has
    /// the whole picture once it has announced its topics. Older agents skip it (an
    /// unknown kind) and send everything.
    /// `alias varint | wanted u8`
    Interest { alias: u32, wanted: bool },
    /// Hub → agent: send the latest message of the pull topic the agent announced as
    /// `alias` (one message; nothing if it has none, or none younger than its age limit).
    /// `alias varint`
    Pull { alias: u32 },
    /// Between hubs (a site hub and its upstream, either way): the hubs each message that
    /// follows on this link (`MESSAGE`, `ZMESSAGE`, each `CHUNK`) has been published on, in
    /// the order it passed them, the sender last; until the next `VIA`. A hub finding
    /// itself in the list drops the message, and a sender does not send a message
    /// listing its peer: a message never comes back to a hub it has passed. Agents never
    /// send it and skip it as an unknown kind.
    /// `count varint | hub u64 LE × count` (count ≤ [`MAX_VIA`])
    Via { hubs: Vec<u64> },
    /// A kind this decoder does not know; skipped.
    Unknown { kind: u8 },
}

impl Frame {
    pub fn kind_byte(&self) -> u8 {
        match self {
            Frame::Hello { .. } => FrameKind::Hello as u8,
            Frame::Welcome { .. } => FrameKind::Welcome as u8,
            Frame::Advertise { .. } => FrameKind::Advertise as u8,
            Frame::Unadvertise { .. } => FrameKind::Unadvertise as u8,
            Frame::Subscribe { .. } => FrameKind::Subscribe as u8,
            Frame::Unsubscribe { .. } => FrameKind::Unsubscribe as u8,
            Frame::Message { .. } => FrameKind::Message as u8,
            Frame::Chunk { .. } => FrameKind::Chunk as u8,
            Frame::Ping { .. } => FrameKind::Ping as u8,
            Frame::Pong { .. } => FrameKind::Pong as u8,
            Frame::Ack { .. } => FrameKind::Ack as u8,
            Frame::Status { .. } => FrameKind::Status as u8,
            Frame::Share { .. } => FrameKind::Share as u8,
            Frame::LinkReport { .. } => FrameKind::LinkReport as u8,
            Frame::Delivered { .. } => FrameKind::Delivered as u8,
            Frame::ServiceAdvertise { .. } => FrameKind::ServiceAdvertise as u8,
            Frame::ServiceUnadvertise { .. } => FrameKind::ServiceUnadvertise as u8,
            Frame::Call { .. } => FrameKind::Call as u8,
            Frame::Goal { .. } => FrameKind::Goal as u8,
            Frame::Reply { .. } => FrameKind::Reply as u8,
            Frame::Feedback { .. } => FrameKind::Feedback as u8,
            Frame::Cancel { .. } => FrameKind::Cancel as u8,
            Frame::CallChunk { .. } => FrameKind::CallChunk as u8,
            Frame::Interest { .. } => FrameKind::Interest as u8,
            Frame::Pull { .. } => FrameKind::Pull as u8,
            Frame::ZMessage { .. } => FrameKind::ZMessage as u8,
            Frame::ZChunk { .. } => FrameKind::ZChunk as u8,
            Frame::Budget { .. } => FrameKind::Budget as u8,
            Frame::TopicDrops { .. } => FrameKind::TopicDrops as u8,
            Frame::TopicLoad { .. } => FrameKind::TopicLoad as u8,
            Frame::Via { .. } => FrameKind::Via as u8,
            Frame::Unknown { kind } => *kind,
        }
    }

    /// Appends this frame to `buf`.
    pub fn encode(&self, buf: &mut BytesMut) {
        let mut body = BytesMut::new();
        self.encode_body(&mut body);
        buf.reserve(1 + varint_len(body.len() as u64) + body.len());
        buf.put_u8(self.kind_byte());
        put_varint(buf, body.len() as u64);
        buf.put_slice(&body);
    }

    /// This frame alone, as the bytes of one WebSocket message.
    pub fn to_bytes(&self) -> Bytes {
        let mut b = BytesMut::new();
        self.encode(&mut b);
        b.freeze()
    }

    fn encode_body(&self, b: &mut BytesMut) {
        match self {
            Frame::Hello {
                version,
                robot,
                token,
                heartbeat_ms,
                outbox_epoch,
                mirror,
            } => {
                put_varint(b, u64::from(*version));
                put_str(b, robot);
                put_str(b, token);
                put_varint(b, u64::from(*heartbeat_ms));
                b.put_u64_le(*outbox_epoch);
                if !mirror.is_empty() {
                    put_str(b, mirror);
                }
            }
            Frame::Welcome {
                session,
                namespace,
                hub_time_ns,
                heartbeat_ms,
                features,
            } => {
                put_str(b, session);
                put_str(b, namespace);
                b.put_u64_le(*hub_time_ns);
                put_varint(b, u64::from(*heartbeat_ms));
                put_varint(b, *features);
            }
            Frame::Interest { alias, wanted } => {
                put_varint(b, u64::from(*alias));
                b.put_u8(u8::from(*wanted));
            }
            Frame::Pull { alias } => put_varint(b, u64::from(*alias)),
            Frame::Via { hubs } => {
                put_varint(b, hubs.len() as u64);
                for h in hubs {
                    b.put_u64_le(*h);
                }
            }
            Frame::TopicDrops { topics } => {
                put_varint(b, topics.len() as u64);
                for (alias, drops) in topics {
                    put_varint(b, u64::from(*alias));
                    put_varint(b, drops.len() as u64);
                    for (reason, n) in drops {
                        b.put_u8(*reason);
                        put_varint(b, *n);
                    }
                }
            }
            Frame::TopicLoad { topics } => {
                put_varint(b, topics.len() as u64);
                for t in topics {
                    put_varint(b, u64::from(t.alias));
                    put_varint(b, t.rate_mhz);
                    put_varint(b, t.bytes_per_sec);
                    put_varint(b, u64::from(t.priority_milli));
                    put_varint(b, u64::from(t.queue));
                    b.put_u8(t.flags);
                }
            }
            Frame::Budget {
                max_bps,
                day_bytes,
                used_bytes,
                thinned,
            } => {
                put_varint(b, *max_bps);
                put_varint(b, *day_bytes);
                put_varint(b, *used_bytes);
                put_varint(b, thinned.len() as u64);
                for a in thinned {
                    put_varint(b, u64::from(*a));
                }
            }
            Frame::Advertise {
                alias,
                topic,
                schema,
                encoding,
                flags,
            } => {
                put_varint(b, u64::from(*alias));
                put_str(b, topic);
                put_str(b, &schema.type_name);
                put_str(b, &schema.encoding);
                put_bytes(b, schema.text.as_bytes());
                b.put_u8(*encoding as u8);
                b.put_u8(*flags);
            }
            Frame::Unadvertise { alias } => put_varint(b, u64::from(*alias)),
            Frame::Subscribe {
                id,
                pattern,
                flags,
                throttle_ms,
                queue_length,
            } => {
                put_varint(b, u64::from(*id));
                put_str(b, pattern);
                b.put_u8(*flags);
                put_varint(b, u64::from(*throttle_ms));
                put_varint(b, u64::from(*queue_length));
            }
            Frame::Unsubscribe { id } => put_varint(b, u64::from(*id)),
            Frame::Message {
                alias,
                seq,
                stamp_ns,
                payload,
            }
            | Frame::ZMessage {
                alias,
                seq,
                stamp_ns,
                payload,
            } => {
                put_message_header(b, *alias, *seq, *stamp_ns);
                b.put_slice(payload);
            }
            Frame::Chunk {
                alias,
                seq,
                stamp_ns,
                total_len,
                offset,
                data,
            }
            | Frame::ZChunk {
                alias,
                seq,
                stamp_ns,
                total_len,
                offset,
                data,
            } => {
                put_message_header(b, *alias, *seq, *stamp_ns);
                put_varint(b, *total_len);
                put_varint(b, *offset);
                b.put_slice(data);
            }
            Frame::Ping { id, sent_ns } => {
                b.put_u64_le(*id);
                b.put_u64_le(*sent_ns);
            }
            Frame::Pong {
                id,
                echo_ns,
                responder_ns,
            } => {
                b.put_u64_le(*id);
                b.put_u64_le(*echo_ns);
                b.put_u64_le(*responder_ns);
            }
            Frame::Ack { frames, bytes } => {
                put_varint(b, u64::from(*frames));
                put_varint(b, *bytes);
            }
            Frame::Status {
                level,
                code,
                alias,
                text,
            } => {
                b.put_u8(*level as u8);
                put_varint(b, u64::from(*code));
                put_varint(b, u64::from(*alias));
                put_str(b, text);
            }
            Frame::Share { bytes_per_sec } => b.put_u64_le(*bytes_per_sec),
            Frame::LinkReport {
                demand_bps,
                rate_bps,
                latency_ns,
                capacity_bps,
                measured_at_ms,
            } => {
                b.put_u64_le(*demand_bps);
                b.put_u64_le(*rate_bps);
                b.put_u64_le(*latency_ns);
                b.put_u64_le(*capacity_bps);
                b.put_u64_le(*measured_at_ms);
            }
            Frame::Delivered { alias, seq } => {
                put_varint(b, u64::from(*alias));
                put_varint(b, *seq);
            }
            Frame::ServiceAdvertise {
                alias,
                name,
                schema,
                flags,
            } => {
                put_varint(b, u64::from(*alias));
                put_str(b, name);
                put_str(b, &schema.type_name);
                put_str(b, &schema.encoding);
                put_str(b, &schema.text);
                b.put_u8(*flags);
            }
            Frame::ServiceUnadvertise { alias } => put_varint(b, u64::from(*alias)),
            Frame::Call {
                call_id,
                alias,
                deadline_ms,
                encoding,
                payload,
            } => {
                put_varint(b, *call_id);
                put_varint(b, u64::from(*alias));
                put_varint(b, *deadline_ms);
                b.put_u8(*encoding as u8);
                b.put_slice(payload);
            }
            Frame::Goal {
                call_id,
                alias,
                deadline_ms,
                goal_id,
                encoding,
                payload,
            } => {
                put_varint(b, *call_id);
                put_varint(b, u64::from(*alias));
                put_varint(b, *deadline_ms);
                b.put_slice(goal_id);
                b.put_u8(*encoding as u8);
                b.put_slice(payload);
            }
            Frame::Reply {
                call_id,
                status,
                encoding,
                payload,
            } => {
                put_varint(b, *call_id);
                b.put_u8(*status as u8);
                b.put_u8(*encoding as u8);
                b.put_slice(payload);
            }
            Frame::Feedback {
                call_id,
                encoding,
                payload,
            } => {
                put_varint(b, *call_id);
                b.put_u8(*encoding as u8);
                b.put_slice(payload);
            }
            Frame::Cancel { call_id } => put_varint(b, *call_id),
            Frame::CallChunk {
                call_id,
                kind,
                total_len,
                offset,
                data,
            } => {
                put_varint(b, *call_id);
                b.put_u8(*kind);
                put_varint(b, *total_len);
                put_varint(b, *offset);
                b.put_slice(data);
            }
            Frame::Unknown { .. } => {}
        }
    }

    /// Decodes the frame starting at `pos` in `buf`; returns it and where the next frame
    /// starts. Payload bytes are shared slices of `buf`.
    pub fn decode(buf: &Bytes, pos: usize) -> Result<(Frame, usize), DecodeError> {
        if pos > buf.len() {
            return Err(DecodeError::incomplete(
                "frame.kind",
                pos - buf.len() + 1,
                0,
            ));
        }
        let mut head = Reader::sub(buf, pos, buf.len() - pos);
        let kind = head.u8("frame.kind")?;
        let len = head.len_prefix("frame.body_len")?;
        let start = head.position();
        let mut r = Reader::sub(buf, start, len);
        // The body is complete (its length was checked above), so a field running past
        // its end can never be fixed by more bytes: that is invalid, not incomplete.
        let frame = decode_body(kind, &mut r).map_err(|e| match e.kind {
            ErrorKind::Incomplete => DecodeError::invalid(
                e.context,
                format!(
                    "field runs past the end of a {len}-byte body ({})",
                    e.reason
                ),
            ),
            ErrorKind::Invalid => e,
        })?;
        Ok((frame, start + len))
    }
}

/// Writes the fields `MESSAGE` and `CHUNK` start with.
fn put_message_header(b: &mut impl BufMut, alias: u32, seq: u64, stamp_ns: u64) {
    put_varint(b, u64::from(alias));
    put_varint(b, seq);
    b.put_u64_le(stamp_ns);
}

/// Appends a `MESSAGE` frame whose payload is `payload`, copying it once into `buf`.
/// Same bytes as `Frame::Message{..}.encode` without building the frame first.
pub fn encode_message(buf: &mut BytesMut, alias: u32, seq: u64, stamp_ns: u64, payload: &[u8]) {
    encode_message_kind(buf, false, alias, seq, stamp_ns, payload);
}

/// [`encode_message`], or `ZMESSAGE` when `compressed` (`payload` is then an envelope).
pub fn encode_message_kind(
    buf: &mut BytesMut,
    compressed: bool,
    alias: u32,
    seq: u64,
    stamp_ns: u64,
    payload: &[u8],
) {
    let body_len = varint_len(u64::from(alias)) + varint_len(seq) + 8 + payload.len();
    buf.reserve(1 + varint_len(body_len as u64) + body_len);
    buf.put_u8(if compressed {
        FrameKind::ZMessage
    } else {
        FrameKind::Message
    } as u8);
    put_varint(buf, body_len as u64);
    put_message_header(buf, alias, seq, stamp_ns);
    buf.put_slice(payload);
}

/// Appends a `CHUNK` frame carrying `data`, which starts at `offset` of a message of
/// `total_len` bytes (`ZCHUNK` when `compressed`: the message is an envelope).
#[allow(clippy::too_many_arguments)]
pub fn encode_chunk(
    buf: &mut BytesMut,
    compressed: bool,
    alias: u32,
    seq: u64,
    stamp_ns: u64,
    total_len: u64,
    offset: u64,
    data: &[u8],
) {
    let body_len = varint_len(u64::from(alias))
        + varint_len(seq)
        + 8
        + varint_len(total_len)
        + varint_len(offset)
        + data.len();
    buf.reserve(1 + varint_len(body_len as u64) + body_len);
    buf.put_u8(if compressed {
        FrameKind::ZChunk
    } else {
        FrameKind::Chunk
    } as u8);
    put_varint(buf, body_len as u64);
    put_message_header(buf, alias, seq, stamp_ns);
    put_varint(buf, total_len);
    put_varint(buf, offset);
    buf.put_slice(data);
}

fn decode_body(kind: u8, r: &mut Reader<'_>) -> Result<Frame, DecodeError> {
    let frame = match kind {
        0x01 => Frame::Hello {
            version: r.varint_u32("HELLO.version")?,
            robot: r.string("HELLO.robot")?,
            token: r.string("HELLO.token")?,
            heartbeat_ms: r.varint_u32("HELLO.heartbeat_ms")?,
            outbox_epoch: if r.is_empty() {
                0
            } else {
                r.u64_le("HELLO.outbox_epoch")?
            },
            mirror: if r.is_empty() {
                String::new()
            } else {
                r.string("HELLO.mirror")?
            },
        },
        0x02 => Frame::Welcome {
            session: r.string("WELCOME.session")?,
            namespace: r.string("WELCOME.namespace")?,
            hub_time_ns: r.u64_le("WELCOME.hub_time_ns")?,
            heartbeat_ms: r.varint_u32("WELCOME.heartbeat_ms")?,
            features: if r.is_empty() {
                0
            } else {
                r.varint("WELCOME.features")?
            },
        },
        0x03 => {
            let alias = r.varint_u32("ADVERTISE.alias")?;
            let topic = r.string("ADVERTISE.topic")?;
            let type_name = r.string("ADVERTISE.type")?;
            let schema_encoding = r.string("ADVERTISE.schema_encoding")?;
            let text = r.string("ADVERTISE.schema_text")?;
            let encoding = read_encoding(r, "ADVERTISE.encoding")?;
            let flags = r.u8("ADVERTISE.flags")?;
            Frame::Advertise {
                alias,
                topic,
                schema: Schema {
                    type_name,
                    encoding: schema_encoding,
                    text,
                },
                encoding,
                flags,
            }
        }
        0x04 => Frame::Unadvertise {
            alias: r.varint_u32("UNADVERTISE.alias")?,
        },
        0x05 => Frame::Subscribe {
            id: r.varint_u32("SUBSCRIBE.id")?,
            pattern: r.string("SUBSCRIBE.pattern")?,
            flags: r.u8("SUBSCRIBE.flags")?,
            throttle_ms: r.varint_u32("SUBSCRIBE.throttle_ms")?,
            queue_length: r.varint_u32("SUBSCRIBE.queue_length")?,
        },
        0x06 => Frame::Unsubscribe {
            id: r.varint_u32("UNSUBSCRIBE.id")?,
        },
        0x07 => {
            let (alias, seq, stamp_ns, payload) = read_message(r, &MESSAGE_FIELDS)?;
            Frame::Message {
                alias,
                seq,
                stamp_ns,
                payload,
            }
        }
        0x08 => read_chunk(r, &CHUNK_FIELDS)?.into_frame(false),
        0x09 => Frame::Ping {
            id: r.u64_le("PING.id")?,
            sent_ns: r.u64_le("PING.sent_ns")?,
        },
        0x0a => Frame::Pong {
            id: r.u64_le("PONG.id")?,
            echo_ns: r.u64_le("PONG.echo_ns")?,
            responder_ns: r.u64_le("PONG.responder_ns")?,
        },
        0x0b => Frame::Ack {
            frames: r.varint_u32("ACK.frames")?,
            bytes: if r.is_empty() {
                0
            } else {
                r.varint("ACK.bytes")?
            },
        },
        0x0c => Frame::Status {
            level: Level::from_u8(r.u8("STATUS.level")?),
            code: r.varint_u32("STATUS.code")?,
            alias: r.varint_u32("STATUS.alias")?,
            text: r.string("STATUS.text")?,
        },
        0x0d => Frame::Share {
            bytes_per_sec: r.u64_le("SHARE.bytes_per_sec")?,
        },
        0x0e => Frame::LinkReport {
            demand_bps: r.u64_le("LINK_REPORT.demand_bps")?,
            rate_bps: r.u64_le("LINK_REPORT.rate_bps")?,
            latency_ns: r.u64_le("LINK_REPORT.latency_ns")?,
            capacity_bps: if r.remaining() >= 8 {
                r.u64_le("LINK_REPORT.capacity_bps")?
            } else {
                0
            },
            measured_at_ms: if r.remaining() >= 8 {
                r.u64_le("LINK_REPORT.measured_at_ms")?
            } else {
                0
            },
        },
        0x0f => Frame::Delivered {
            alias: r.varint_u32("DELIVERED.alias")?,
            seq: r.varint("DELIVERED.seq")?,
        },
        0x10..=0x17 => calls::decode_body(kind, r)?,
        0x18 => Frame::Interest {
            alias: r.varint_u32("INTEREST.alias")?,
            wanted: match r.u8("INTEREST.wanted")? {
                0 => false,
                1 => true,
                v => {
                    return Err(DecodeError::invalid(
                        "INTEREST.wanted",
                        format!("{v} is not 0 or 1"),
                    ));
                }
            },
        },
        0x19 => Frame::Pull {
            alias: r.varint_u32("PULL.alias")?,
        },
        0x1f => {
            let count = r.varint("VIA.count")?;
            if count > MAX_VIA as u64 {
                return Err(DecodeError::invalid(
                    "VIA.count",
                    format!("{count} hubs: a chain of more than {MAX_VIA} hubs"),
                ));
            }
            let hubs = (0..count)
                .map(|_| r.u64_le("VIA.hub"))
                .collect::<Result<_, _>>()?;
            Frame::Via { hubs }
        }
        0x1c => {
            let max_bps = r.varint("BUDGET.max_bps")?;
            let day_bytes = r.varint("BUDGET.day_bytes")?;
            let used_bytes = r.varint("BUDGET.used_bytes")?;
            let count = r.varint("BUDGET.count")?;
            // Every alias takes at least a byte: a count past the body is a lie.
            if count > r.remaining() as u64 {
                return Err(DecodeError::invalid(
                    "BUDGET.count",
                    format!("{count} aliases in {} bytes", r.remaining()),
                ));
            }
            let thinned = (0..count)
                .map(|_| r.varint_u32("BUDGET.alias"))
                .collect::<Result<_, _>>()?;
            Frame::Budget {
                max_bps,
                day_bytes,
                used_bytes,
                thinned,
            }
        }
        0x1d => {
            // Every entry takes at least two bytes, every pair two: a count past the
            // body is a lie.
            let count = r.varint("TOPIC_DROPS.count")?;
            if count > r.remaining() as u64 / 2 {
                return Err(DecodeError::invalid(
                    "TOPIC_DROPS.count",
                    format!("{count} topics in {} bytes", r.remaining()),
                ));
            }
            let mut topics = Vec::with_capacity(count as usize);
            for _ in 0..count {
                let alias = r.varint_u32("TOPIC_DROPS.alias")?;
                let n = r.varint("TOPIC_DROPS.n")?;
                if n > r.remaining() as u64 / 2 {
                    return Err(DecodeError::invalid(
                        "TOPIC_DROPS.n",
                        format!("{n} reasons in {} bytes", r.remaining()),
                    ));
                }
                let mut drops = Vec::with_capacity(n as usize);
                for _ in 0..n {
                    drops.push((
                        r.u8("TOPIC_DROPS.reason")?,
                        r.varint("TOPIC_DROPS.dropped")?,
                    ));
                }
                topics.push((alias, drops));
            }
            Frame::TopicDrops { topics }
        }
        0x1e => {
            let count = r.varint("TOPIC_LOAD.count")?;
            // Each entry takes at least six bytes.
            if count > r.remaining() as u64 / 6 {
                return Err(DecodeError::invalid(
                    "TOPIC_LOAD.count",
                    format!("{count} topics in {} bytes", r.remaining()),
                ));
            }
            let mut topics = Vec::with_capacity(count as usize);
            for _ in 0..count {
                topics.push(TopicLoadEntry {
                    alias: r.varint_u32("TOPIC_LOAD.alias")?,
                    rate_mhz: r.varint("TOPIC_LOAD.rate_mhz")?,
                    bytes_per_sec: r.varint("TOPIC_LOAD.bytes_per_sec")?,
                    priority_milli: r.varint_u32("TOPIC_LOAD.priority_milli")?,
                    queue: r.varint_u32("TOPIC_LOAD.queue")?,
                    flags: r.u8("TOPIC_LOAD.flags")?,
                });
            }
            Frame::TopicLoad { topics }
        }
        0x1a => {
            let (alias, seq, stamp_ns, payload) = read_message(r, &ZMESSAGE_FIELDS)?;
            Frame::ZMessage {
                alias,
                seq,
                stamp_ns,
                payload,
            }
        }
        0x1b => read_chunk(r, &ZCHUNK_FIELDS)?.into_frame(true),
        other => Frame::Unknown { kind: other },
    };
    Ok(frame)
}

/// Reads a payload encoding byte. An unknown value is invalid rather than skipped: the
/// receiver could not interpret the payloads it describes.
fn read_encoding(r: &mut Reader<'_>, ctx: &'static str) -> Result<Encoding, DecodeError> {
    let enc = r.u8(ctx)?;
    Encoding::from_u8(enc)
        .ok_or_else(|| DecodeError::invalid(ctx, format!("unknown encoding {enc}")))
}

/// The names a decoding error gives a message's fields: `MESSAGE` and `ZMESSAGE` share
/// one layout, as do `CHUNK` and `ZCHUNK` (a message's head, then the piece's place),
/// read by one function each ([`read_message`], [`read_chunk`]).
struct MessageFields {
    alias: &'static str,
    seq: &'static str,
    stamp_ns: &'static str,
}

struct ChunkFields {
    head: MessageFields,
    total_len: &'static str,
    offset: &'static str,
}

const MESSAGE_FIELDS: MessageFields = MessageFields {
    alias: "MESSAGE.alias",
    seq: "MESSAGE.seq",
    stamp_ns: "MESSAGE.stamp_ns",
};
const ZMESSAGE_FIELDS: MessageFields = MessageFields {
    alias: "ZMESSAGE.alias",
    seq: "ZMESSAGE.seq",
    stamp_ns: "ZMESSAGE.stamp_ns",
};
const CHUNK_FIELDS: ChunkFields = ChunkFields {
    head: MessageFields {
        alias: "CHUNK.alias",
        seq: "CHUNK.seq",
        stamp_ns: "CHUNK.stamp_ns",
    },
    total_len: "CHUNK.total_len",
    offset: "CHUNK.offset",
};
const ZCHUNK_FIELDS: ChunkFields = ChunkFields {
    head: MessageFields {
        alias: "ZCHUNK.alias",
        seq: "ZCHUNK.seq",
        stamp_ns: "ZCHUNK.stamp_ns",
    },
    total_len: "ZCHUNK.total_len",
    offset: "ZCHUNK.offset",
};

/// A `MESSAGE`'s (or `ZMESSAGE`'s) alias, seq, stamp and payload.
fn read_message(
    r: &mut Reader<'_>,
    f: &MessageFields,
) -> Result<(u32, u64, u64, Bytes), DecodeError> {
    Ok((
        r.varint_u32(f.alias)?,
        r.varint(f.seq)?,
        r.u64_le(f.stamp_ns)?,
        r.rest(),
    ))
}

/// A `CHUNK`'s (or `ZCHUNK`'s) fields.
struct Piece {
    alias: u32,
    seq: u64,
    stamp_ns: u64,
    total_len: u64,
    offset: u64,
    data: Bytes,
}

impl Piece {
    /// The frame it came in: `ZCHUNK` when `compressed`, else `CHUNK`.
    fn into_frame(self, compressed: bool) -> Frame {
        let Piece {
            alias,
            seq,
            stamp_ns,
            total_len,
            offset,
            data,
        } = self;
        if compressed {
            Frame::ZChunk {
                alias,
                seq,
                stamp_ns,
                total_len,
                offset,
                data,
            }
        } else {
            Frame::Chunk {
                alias,
                seq,
                stamp_ns,
                total_len,
                offset,
                data,
            }
        }
    }
}

/// A `CHUNK` (or `ZCHUNK`), its piece checked to lie inside the whole.
fn read_chunk(r: &mut Reader<'_>, f: &ChunkFields) -> Result<Piece, DecodeError> {
    let alias = r.varint_u32(f.head.alias)?;
    let seq = r.varint(f.head.seq)?;
    let stamp_ns = r.u64_le(f.head.stamp_ns)?;
    let total_len = r.varint(f.total_len)?;
    let offset = r.varint(f.offset)?;
    let data = r.rest();
    check_piece_fits(total_len, offset, &data, f.offset)?;
    Ok(Piece {
        alias,
        seq,
        stamp_ns,
        total_len,
        offset,
        data,
    })
}

/// Checks that a piece of `data` at `offset` lies inside a body of `total_len` bytes,
/// without overflowing: a reassembler can then trust the numbers it is given.
fn check_piece_fits(
    total_len: u64,
    offset: u64,
    data: &[u8],
    ctx: &'static str,
) -> Result<(), DecodeError> {
    if offset
        .checked_add(data.len() as u64)
        .is_none_or(|end| end > total_len)
    {
        return Err(DecodeError::invalid(
            ctx,
            format!(
                "{} bytes at offset {offset} overrun total length {total_len}",
                data.len()
            ),
        ));
    }
    Ok(())
}

/// Iterates over the frames packed in one WebSocket message. Stops at the first error.
pub fn frames(buf: &Bytes) -> Frames<'_> {
    Frames {
        buf,
        pos: 0,
        failed: false,
    }
}

pub struct Frames<'a> {
    buf: &'a Bytes,
    pos: usize,
    failed: bool,
}

impl Iterator for Frames<'_> {
    type Item = Result<Frame, DecodeError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.failed || self.pos >= self.buf.len() {
            return None;
        }
        match Frame::decode(self.buf, self.pos) {
            Ok((frame, next)) => {
                self.pos = next;
                Some(Ok(frame))
            }
            Err(e) => {
                self.failed = true;
                Some(Err(e))
            }
        }
    }
}

/// Splits `payload` into `CHUNK` frames of at most `chunk_size` data bytes each. The
/// pieces share `payload`'s storage.
pub fn chunk_frames(
    alias: u32,
    seq: u64,
    stamp_ns: u64,
    payload: &Bytes,
    chunk_size: usize,
) -> impl Iterator<Item = Frame> + '_ {
    let total = payload.len();
    let step = chunk_size.max(1);
    (0..total.div_ceil(step)).map(move |i| {
        let start = i * step;
        let end = (start + step).min(total);
        Frame::Chunk {
            alias,
            seq,
            stamp_ns,
            total_len: total as u64,
            offset: start as u64,
            data: payload.slice(start..end),
        }
    })
}
