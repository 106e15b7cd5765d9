//! The frames as values: the [`Frame`] enum, with each body's layout drawn on its
//! variant, the kind bytes, and the flags, codes and outcomes its fields carry. Writing
//! and reading them is left to the codec files beside this one.

use bytes::Bytes;

use crate::payload::{Encoding, Schema};

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
    pub(super) fn from_u8(v: u8) -> Level {
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
    /// [`split_call_body`](super::split_call_body)).
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
}

/// Outcome of a call (`REPLY.status`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum CallStatus {
    /// The payload is the response (the action's result, for a goal).
    Ok = 0,
    /// The provider answered false or raised; the payload says why.
    Failed = 1,
    /// The deadline passed before an answer came.
    Timeout = 2,
    /// Nobody provides the service (any more): not advertised, or its provider went away.
    NoProvider = 3,
    /// The ACL forbids this call for this caller.
    Forbidden = 4,
    /// The caller cancelled the call or goal.
    Cancelled = 5,
    /// The action's server aborted the goal, or the link to it was lost.
    Aborted = 6,
    /// A bound on pending calls was hit; the payload names the bound.
    Busy = 7,
}

impl CallStatus {
    /// Reads a status byte. A value from a later version is read as `Failed`: the call did
    /// not succeed in any way this side understands, and the payload still says why.
    pub fn from_u8(v: u8) -> CallStatus {
        match v {
            0 => CallStatus::Ok,
            2 => CallStatus::Timeout,
            3 => CallStatus::NoProvider,
            4 => CallStatus::Forbidden,
            5 => CallStatus::Cancelled,
            6 => CallStatus::Aborted,
            7 => CallStatus::Busy,
            _ => CallStatus::Failed,
        }
    }

    pub fn as_str(self) -> &'static str {
        match self {
            CallStatus::Ok => "ok",
            CallStatus::Failed => "failed",
            CallStatus::Timeout => "timeout",
            CallStatus::NoProvider => "no_provider",
            CallStatus::Forbidden => "forbidden",
            CallStatus::Cancelled => "cancelled",
            CallStatus::Aborted => "aborted",
            CallStatus::Busy => "busy",
        }
    }
}
