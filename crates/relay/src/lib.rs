//! The routing core shared by the hub and the agent.
//!
//! A hub routes between robots and operators; an agent routes between its local programs,
//! its simulator and the hub link. Both are the same problem — topics with publishers and
//! subscribers, fan-out without copies, a bounded queue per subscriber — so both run a
//! [`Router`] from this crate and differ only in the connections they attach to it.
//!
//! # Layout
//!
//! - [`names`]: identifier newtypes ([`TopicName`], [`ClientId`], [`TopicId`]).
//! - [`message`]: [`Message`], one published message shared by every subscriber, with a
//!   cache of its ready-to-send frames (each target encoding built at most once).
//! - [`transcode`]: converting a message between encodings ([`Transcoder`]).
//! - [`params`]: the parameter store behind `/rosapi/get_param` and friends.
//! - [`png`]: rosbridge's `png` compression of outgoing operations.
//! - [`queue`]: the per-subscription outbound queue seam ([`OutboundQueue`]) and the
//!   default drop-oldest queue.
//! - [`outbox`]: one client's outbound side: its subscriptions' queues, served round-robin
//!   to the task that writes the client's socket.
//! - [`reliable`]: no-drop topics on a link, the sender's half: stream numbering, messages
//!   kept until confirmed and resent after a reconnect, the durable [`reliable::Journal`]
//!   seam.
//! - [`calls`]: services and actions: the provider table and every call in flight, with
//!   deadlines, cancel and bounds ([`calls::Calls`]).
//! - [`link_calls`]: calls across a `fleetlink.v1` link: service advertisements and call
//!   frames to and from the table, on both the hub's and the agent's side.
//! - [`gate`]: the authorization seam ([`gate::Gate`]): what a connection may do,
//!   asked at request time and on every delivery.
//! - [`link`]: what hub and agent share on a `fleetlink.v1` link: received frames to
//!   events, and the writer that sends an outbox as (chunked) frames.
//! - [`link_control`]: per-frame link accounting of a scheduled outbox and the window
//!   that keeps bulk data from queueing below the scheduler.
//! - [`stats`]: per-topic counters and rates read by metrics and the API.
//! - [`router`]: the topic table, subscribe/advertise/publish and the fan-out.
//! - [`rosbridge`]: a rosbridge v2 server session over any WebSocket stream, including the
//!   `/rosapi` services the hub answers itself.

pub mod calls;
pub mod gate;
pub mod link;
pub mod link_calls;
pub mod link_control;
pub mod message;
pub mod names;
pub mod outbox;
pub mod params;
pub mod png;
pub mod queue;
pub mod reliable;
pub mod rosbridge;
pub mod router;
pub mod stats;
pub mod transcode;

pub use message::Message;
pub use names::{ClientId, NameError, TopicId, TopicName};
pub use outbox::Outbox;
pub use queue::{DropReason, OutboundQueue, QosQueue};
pub use router::{ClientInfo, ClientKind, Router, Topic};
pub use transcode::{GenericTranscoder, TranscodeError, Transcoder};

/// The Unix time of an `Instant`, from one reading of both clocks taken at first use:
/// cheaper than reading the system clock for every message, and monotonic.
pub fn instant_to_unix_nanos(at: std::time::Instant) -> u64 {
    static BASE: std::sync::OnceLock<(std::time::Instant, u64)> = std::sync::OnceLock::new();
    let (i0, u0) = *BASE.get_or_init(|| (std::time::Instant::now(), unix_nanos()));
    match at.checked_duration_since(i0) {
        Some(d) => u0 + d.as_nanos() as u64,
        None => u0.saturating_sub(i0.duration_since(at).as_nanos() as u64),
    }
}

/// Nanoseconds since the Unix epoch, the unit of message stamps.
pub fn unix_nanos() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_nanos() as u64)
        .unwrap_or(0)
}
