//! What a link session and its driver hand each other: the session's settings and
//! handshake inputs ([`SessionConfig`], [`AgentHello`], [`Accept`]), what it tells the
//! driver ([`Event`], [`CloseReason`]), its limits and its counters.

use std::fmt;
use std::time::{Duration, Instant};

use super::super::LinkEvent;
use crate::gate::Gate;
use crate::link_calls::LinkCalls;

/// Which end of the link this is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// Accepts `HELLO`, answers `WELCOME`, acknowledges what it receives.
    Hub,
    /// Sends `HELLO`, waits for `WELCOME`.
    Agent,
}

impl Role {
    /// What the other end is called in messages.
    pub(super) fn peer(self) -> &'static str {
        match self {
            Role::Hub => "robot",
            Role::Agent => "hub",
        }
    }
}

/// Reads the wall clock (nanoseconds since the Unix epoch) at a monotonic instant, for
/// the stamps of `PING`/`PONG`. The system clock in production; tests extrapolate from a
/// fixed base so that a run is repeatable.
pub type WallClock = Box<dyn Fn(Instant) -> u64 + Send>;

/// The system's wall clock, read when asked (the instant is not used).
pub fn system_wall_clock() -> WallClock {
    Box::new(|_| crate::unix_nanos())
}

/// Builds the session's call state once it is open, from the namespace the hub gave the
/// robot (the agent's names depend on it).
pub type CallsFactory = Box<dyn FnOnce(&str) -> LinkCalls + Send>;

/// Most pong answers kept while the writer is backed up (the oldest go first).
pub(super) const MAX_PONGS: usize = 8;
/// While the peer pings every heartbeat itself, the hub pings only every this many
/// heartbeats (see `LinkSession::skip_ping`).
pub const HUB_PING_EVERY: u32 = 5;
/// Most error reports to the peer waiting to be sent; more are counted and not sent.
pub(super) const MAX_STATUSES: usize = 64;
/// The driver feeds call-table news in only while fewer frames than this wait.
pub const PEER_EVENT_ROOM: usize = 64;
/// A read finds the hub's `ACK` of a few small messages due once it has waited this long
/// (see `Transmit::ack_since`).
pub const ACK_DELAY: Duration = Duration::from_millis(100);
/// An `ACK` goes at once when it covers this many messages (the agent allows this many
/// in flight beyond Robofleet's 32, `UPLINK_IN_FLIGHT`) ...
pub const ACK_EVERY_MESSAGES: u32 = 16;
/// ... or this many payload bytes, or any piece of a chunked message.
pub const ACK_EVERY_BYTES: u64 = 1024;

/// Why a session ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CloseReason {
    /// Nothing arrived from the peer for `after`: the link is taken to be dead.
    Silent { after: Duration },
    /// The handshake did not complete in time; `waiting_for` names the frame.
    HandshakeTimeout {
        waiting_for: &'static str,
        after: Duration,
    },
    /// The peer closed the WebSocket (or the stream ended); the detail, if any.
    PeerClosed(String),
    /// Reading the socket failed.
    ReadError(String),
    /// The peer broke the WebSocket protocol (RFC 6455); `code` is the close code it gets
    /// (1002 protocol error, 1007 not UTF-8, 1009 too large).
    Invalid { code: u16, text: String },
    /// Refused during the handshake: by the hub (this text was sent to the agent), or,
    /// on the agent, the hub's refusal as it came.
    Refused(String),
    /// The peer broke the protocol in a way the session cannot go on from.
    Protocol(String),
    /// Ended from this side (shutdown, a newer connection of the same robot).
    Local(String),
}

impl CloseReason {
    /// Whether the hub refused the connection during the handshake.
    pub fn is_refusal(&self) -> bool {
        matches!(self, CloseReason::Refused(_))
    }
}

impl fmt::Display for CloseReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CloseReason::Silent { after } => write!(
                f,
                "no bytes received for {} ms: link declared dead",
                after.as_millis()
            ),
            CloseReason::HandshakeTimeout { waiting_for, after } => {
                write!(f, "no {waiting_for} within {} s", after.as_secs())
            }
            CloseReason::PeerClosed(d) if d.is_empty() => write!(f, "the connection was closed"),
            CloseReason::PeerClosed(d) => write!(f, "the connection was closed: {d}"),
            CloseReason::ReadError(e) => write!(f, "link error: {e}"),
            CloseReason::Invalid { code, text } => {
                write!(f, "WebSocket protocol error ({code}): {text}")
            }
            CloseReason::Refused(t) | CloseReason::Protocol(t) | CloseReason::Local(t) => {
                f.write_str(t)
            }
        }
    }
}

/// What the session tells its driver.
#[derive(Debug)]
pub enum Event {
    /// Hub: the agent's `HELLO`, checked for the protocol version. Authenticate it, then
    /// [`LinkSession::accept`] or [`LinkSession::refuse`].
    Hello {
        robot: String,
        token: String,
        /// The heartbeat the agent asks for (0 = the hub's default).
        heartbeat_ms: u32,
        outbox_epoch: u64,
        /// The robot this link mirrors, if it is a mirror (empty: it is the robot).
        mirror: String,
    },
    /// The session is open: the agent got `WELCOME`, or the hub accepted.
    Opened {
        session: String,
        namespace: String,
        heartbeat: Duration,
        /// The `WELCOME` features (the hub's offer, on both ends).
        features: u64,
    },
    /// A topic event or a control frame for the driver to act on (`SUBSCRIBE`, `ACK`,
    /// `DELIVERED`, `SHARE`, `LINK_REPORT`, a peer's `STATUS`, ...).
    Link(LinkEvent),
    /// The answer to one of our pings: `id`, the peer's clock when it answered, and the
    /// round trip.
    Pong {
        id: u64,
        responder_ns: u64,
        rtt: Duration,
        /// Our clock minus the peer's, estimated from this exchange.
        offset_ns: i64,
    },
    /// Time for the driver's periodic report (the agent's `LINK_REPORT`).
    ReportDue,
    /// The session ended; nothing more comes from it.
    Closed(CloseReason),
}

/// Settings of a session.
pub struct SessionConfig {
    pub role: Role,
    /// The agent: the heartbeat it asks for. The hub: the heartbeat until it accepts.
    pub heartbeat: Duration,
    /// How long the handshake may take from the session's start.
    pub handshake_timeout: Duration,
    /// How often [`Event::ReportDue`] comes once open; `None` for never.
    pub report_every: Option<Duration>,
    pub wall: WallClock,
}

/// What the agent says in `HELLO`.
pub struct AgentHello {
    pub robot: String,
    pub token: String,
    pub outbox_epoch: u64,
    /// The robot this agent mirrors (`HELLO.mirror`); empty for a robot's own agent.
    pub mirror: String,
}

/// The hub's answer to a `HELLO` it accepts.
pub struct Accept {
    pub session: String,
    pub namespace: String,
    pub heartbeat: Duration,
    /// What the robot may do, for its calls and services.
    pub gate: Box<dyn Gate>,
    pub calls: CallsFactory,
    /// `WELCOME` features the hub offers ([`fleetlink_proto::frame::WELCOME_INTEREST`]).
    pub features: u64,
}

/// Counters of one session.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct SessionStats {
    /// WebSocket messages with a frame that did not decode.
    pub malformed: u64,
    /// Error reports to the peer not sent because too many were waiting.
    pub statuses_dropped: u64,
    /// Pong answers dropped because the writer was backed up.
    pub pongs_dropped: u64,
    /// Heartbeat pings sent.
    pub pings_sent: u64,
}
