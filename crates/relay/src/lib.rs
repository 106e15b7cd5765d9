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
//! - [`channel_form`]: a topic as a typed channel (encoding and schema) for Foxglove
//!   clients and MCAP files.
//! - [`stats`]: per-topic counters and rates read by metrics and the API.
//! - [`router`]: the topic table, subscribe/advertise/publish and the fan-out.
//! - [`rosapi`]: the answers to the `/rosapi` services from the router's own tables,
//!   shared by the rosbridge server (the `fleetlink-rosbridge` crate) and the Foxglove one.
//! - [`websocket`]: the server side of a WebSocket connection as a reader and a writer
//!   that share only the socket, which rosbridge sessions run on (the `fleetlink-websocket`
//!   crate, with the writers' wait for work that needs an outbox).

pub mod calls;
pub mod channel_form;
pub mod gate;
pub mod gop;
pub mod link;
pub mod link_calls;
pub mod link_control;
pub mod live;
pub mod message;
pub mod names;
pub mod outbox;
pub mod params;
pub mod png;
pub mod queue;
pub mod read_interest;
pub mod reliable;
pub mod rosapi;
pub mod router;
pub mod stats;
pub mod transcode;
pub mod websocket;

pub use message::Message;
pub use names::{ClientId, NameError, TopicId, TopicName};
pub use outbox::Outbox;
pub use queue::{DropReason, OutboundQueue, QosQueue};
pub use router::{ClientInfo, ClientKind, Router, Topic};
pub use transcode::{GenericTranscoder, TranscodeError, Transcoder};

/// One reading of both clocks, taken at first use: the pair that converts between them.
fn clock_base() -> (std::time::Instant, u64) {
    static BASE: std::sync::OnceLock<(std::time::Instant, u64)> = std::sync::OnceLock::new();
    *BASE.get_or_init(|| (std::time::Instant::now(), unix_nanos()))
}

/// The Unix time of an `Instant`, from one reading of both clocks taken at first use:
/// cheaper than reading the system clock for every message, and monotonic.
pub fn instant_to_unix_nanos(at: std::time::Instant) -> u64 {
    let (i0, u0) = clock_base();
    match at.checked_duration_since(i0) {
        Some(d) => u0 + d.as_nanos() as u64,
        None => u0.saturating_sub(i0.duration_since(at).as_nanos() as u64),
    }
}

/// The `Instant` of a Unix time made by [`instant_to_unix_nanos`]: the same instant,
/// to the nanosecond.
pub fn unix_nanos_to_instant(ns: u64) -> std::time::Instant {
    let (i0, u0) = clock_base();
    match ns.checked_sub(u0) {
        Some(after) => i0 + std::time::Duration::from_nanos(after),
        None => i0 - std::time::Duration::from_nanos(u0 - ns),
    }
}

/// Stamps for a stream of messages: the monotonic clock, with the wall clock read again
/// whenever 100 ms have passed (so a stamp is never more than 100 ms worth of clock slew
/// away from the wall clock). A publisher's hot path reads the clock at most once per
/// message instead of twice, and [`StampClock::arrival`] shares one reading between the
/// messages of one socket read.
#[derive(Debug)]
pub struct StampClock {
    base: std::time::Instant,
    base_unix: u64,
    /// The reading [`StampClock::arrival`] hands out, and how many more times it may.
    last: Option<(std::time::Instant, u64)>,
    reuses: u32,
}

impl Default for StampClock {
    fn default() -> Self {
        StampClock {
            base: std::time::Instant::now(),
            base_unix: unix_nanos(),
            last: None,
            reuses: 0,
        }
    }
}

impl StampClock {
    const REFRESH: std::time::Duration = std::time::Duration::from_millis(100);
    /// Messages that may share one reading. Between two readings the reader does no more
    /// than handle that many operations already received (microseconds).
    const SHARED: u32 = 32;

    /// Now, as an `Instant` and as Unix nanoseconds.
    pub fn now(&mut self) -> (std::time::Instant, u64) {
        let now = std::time::Instant::now();
        let since = now.saturating_duration_since(self.base);
        if since >= Self::REFRESH {
            self.base = now;
            self.base_unix = unix_nanos();
            return (now, self.base_unix);
        }
        (now, self.base_unix + since.as_nanos() as u64)
    }

    /// When the message being handled arrived: the reading taken for the operations
    /// before it, unless the reader has waited since ([`StampClock::waited`]) or that
    /// reading has served [`Self::SHARED`] messages. Operations that came in one socket
    /// read arrived together; one clock read per message cost ~2 % of the hub's CPU for
    /// a stream of small messages.
    pub fn arrival(&mut self) -> (std::time::Instant, u64) {
        match self.last {
            Some(at) if self.reuses > 0 => {
                self.reuses -= 1;
                at
            }
            _ => {
                let at = self.now();
                self.last = Some(at);
                self.reuses = Self::SHARED - 1;
                at
            }
        }
    }

    /// Time has passed (the reader waited for the socket, or for room in a queue): the
    /// next [`StampClock::arrival`] reads the clock.
    pub fn waited(&mut self) {
        self.last = None;
    }
}

/// Nanoseconds since the Unix epoch, the unit of message stamps.
pub fn unix_nanos() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_nanos() as u64)
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_instant_survives_the_trip_through_unix_nanoseconds() {
        let now = std::time::Instant::now();
        for at in [
            now,
            now + std::time::Duration::from_nanos(123_456_789),
            now - std::time::Duration::from_millis(1500),
        ] {
            assert_eq!(unix_nanos_to_instant(instant_to_unix_nanos(at)), at);
        }
    }

    #[test]
    fn stamp_clock_stays_within_a_refresh_period_of_the_wall_clock() {
        let mut clock = StampClock::default();
        let deadline = std::time::Instant::now() + std::time::Duration::from_millis(250);
        // Across at least two wall-clock refreshes.
        while std::time::Instant::now() < deadline {
            let before = unix_nanos();
            let (_, stamp) = clock.now();
            let after = unix_nanos();
            // Within a refresh period of the wall clock (slew between refreshes).
            assert!(stamp + 100_000_000 >= before && stamp <= after + 100_000_000);
        }
    }

    #[test]
    fn arrivals_share_a_reading_until_the_reader_waits() {
        let mut clock = StampClock::default();
        let first = clock.arrival();
        std::thread::sleep(std::time::Duration::from_millis(2));
        // Same read: the same stamp, up to the bound.
        for _ in 1..StampClock::SHARED {
            assert_eq!(clock.arrival(), first);
        }
        let next = clock.arrival();
        assert!(next.0 > first.0 && next.1 > first.1);
        std::thread::sleep(std::time::Duration::from_millis(2));
        clock.waited();
        let after_wait = clock.arrival();
        assert!(after_wait.0 >= next.0 + std::time::Duration::from_millis(2));
    }
}
