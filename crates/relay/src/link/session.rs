//! The `fleetlink.v1` link session: one deterministic state machine for both ends of an
//! agent ↔ hub link, with a [`Role`].
//!
//! It owns everything about the link that is protocol rather than I/O: the handshake
//! (`HELLO` → `WELCOME`, or a refusal), the peer's topic aliases and chunk reassembly
//! ([`LinkIn`]), acknowledgements, calls across the link ([`LinkCalls`]), heartbeats and
//! liveness. It reads no clock and touches no socket: every input carries `now`, and its
//! driver (the hub's `agents::serve_agent`, the agent's uplink) feeds it what the socket
//! read, takes what it has to send ([`LinkSession::poll_transmit`]) and what happened
//! ([`LinkSession::poll_event`]), and sleeps until [`LinkSession::poll_timeout`].
//!
//! **Liveness** is a deadline, `last byte received + 2 × heartbeat`, and only bytes from
//! the peer move it ([`LinkSession::handle_binary`] and the other `handle_*` of things
//! read from the socket). Nothing this side does — calls and feedback from the call
//! table, frames the driver queues, its own timers — can, so a link that went silent is
//! declared dead on time however busy this side is. Each end sends a `PING` every
//! heartbeat, so a live peer is never silent for longer than one heartbeat plus the
//! link's delay.
//!
//! **Malformed input** is treated the same on both ends: a frame that does not decode
//! ends the processing of its WebSocket message (its length can no longer be trusted), a
//! frame that decodes but means nothing here (an unknown alias, a chunk out of place) is
//! skipped, and either way the peer gets a `STATUS` saying what was wrong while the link
//! keeps serving. During the handshake, anything but the expected frame ends the session
//! with a refusal.
//!
//! **What it sends** is bounded: answers to pings keep the newest few, acknowledgements
//! and delivery confirmations are summed into one pending frame each, error reports to
//! the peer are capped (the excess is counted), and the driver feeds call-table news in
//! only while fewer than [`PEER_EVENT_ROOM`] frames wait ([`LinkSession::wants_peer_events`]),
//! so a stalled writer backs up into the call table's coalescing queue, not here.

use std::collections::{BTreeMap, VecDeque};
use std::time::{Duration, Instant};

use bytes::Bytes;
use fleetlink_proto::frame::{Frame, Level, VERSION, status_code};
use fleetlink_proto::reassembly::ReassemblyError;

use super::{Control, HEARTBEAT_ID_BASE, LinkError, LinkEvent, LinkIn};
use crate::calls::PeerMsg;
use crate::gate::{AllowAll, Gate};
use crate::link_calls::{LinkCalls, is_call_frame};

mod types;
pub use types::*;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Phase {
    /// Hub: waiting for `HELLO` until the deadline.
    AwaitHello(Instant),
    /// Hub: `HELLO` came; the driver is authenticating it.
    Authenticating(Instant),
    /// Agent: `HELLO` sent, waiting for `WELCOME`.
    AwaitWelcome(Instant),
    Open,
    Closed,
}

/// Frames waiting to be sent, with the kinds that only ever matter in sum or as the
/// newest kept apart (see the module docs).
#[derive(Default)]
struct Transmit {
    pongs: VecDeque<Frame>,
    ack: Option<(u32, u64)>,
    /// Since when the pending `ack` has waited; `None` once it must go now.
    ///
    /// Design choice: the hub acknowledges at once what the agent's window waits on — a
    /// piece of bulk data, a kilobyte, [`ACK_EVERY_MESSAGES`] messages (the room its
    /// window keeps for them) — and lets an acknowledgement of fewer small messages wait
    /// for a frame that is written anyway:
    /// the next `PONG` (the agent probes every 200 ms and pings every heartbeat), the
    /// hub's own heartbeat `PING`, any other frame, or the next read once it has waited
    /// [`ACK_DELAY`]. It never gets a timer of its own: a robot publishing small topics
    /// unsynchronised sends each message as its own WebSocket message, and one `ACK`
    /// each (or one timer wake-up each) was a system call and a writer wake-up per
    /// message, the largest share of what a hub of a thousand such robots spent beyond
    /// the fan-out. The agent loses nothing by it: its round trips and base delay come
    /// from its probes and from promptly acknowledged bulk, and a small message is never
    /// held back by the byte window, nor by its window of messages, which has room for
    /// those the hub has not acknowledged yet.
    ack_since: Option<Instant>,
    delivered: BTreeMap<u32, u64>,
    frames: VecDeque<Control>,
    statuses: usize,
}

/// One end of a `fleetlink.v1` link (see the module docs).
pub struct LinkSession {
    role: Role,
    phase: Phase,
    heartbeat: Duration,
    handshake_timeout: Duration,
    /// When the last bytes from the peer arrived: the only input of liveness.
    last_rx: Instant,
    next_ping: Instant,
    ping_id: u64,
    /// When the peer last sent a `PING` (the hub skips most of its own while the peer
    /// keeps the link alive itself: see [`HUB_PING_EVERY`]).
    peer_pinged: Option<Instant>,
    /// Heartbeat pings skipped in a row.
    pings_skipped: u32,
    report_every: Option<Duration>,
    next_report: Option<Instant>,
    link: LinkIn,
    gate: Box<dyn Gate>,
    calls: Option<LinkCalls>,
    calls_factory: Option<CallsFactory>,
    tx: Transmit,
    events: VecDeque<Event>,
    wall: WallClock,
    stats: SessionStats,
}

impl LinkSession {
    fn new(cfg: SessionConfig, phase: Phase, now: Instant) -> LinkSession {
        LinkSession {
            role: cfg.role,
            phase,
            heartbeat: cfg.heartbeat,
            handshake_timeout: cfg.handshake_timeout,
            last_rx: now,
            next_ping: now + cfg.heartbeat,
            ping_id: HEARTBEAT_ID_BASE,
            peer_pinged: None,
            pings_skipped: 0,
            report_every: cfg.report_every,
            next_report: None,
            link: LinkIn::default(),
            gate: Box::new(AllowAll),
            calls: None,
            calls_factory: None,
            tx: Transmit::default(),
            events: VecDeque::new(),
            wall: cfg.wall,
            stats: SessionStats::default(),
        }
    }

    /// The hub's end of a new connection: waits for `HELLO`.
    pub fn hub(cfg: SessionConfig, now: Instant) -> LinkSession {
        let deadline = now + cfg.handshake_timeout;
        LinkSession::new(
            SessionConfig {
                role: Role::Hub,
                ..cfg
            },
            Phase::AwaitHello(deadline),
            now,
        )
    }

    /// The agent's end of a new connection: `HELLO` is the first thing to send.
    pub fn agent(
        cfg: SessionConfig,
        hello: AgentHello,
        calls: CallsFactory,
        now: Instant,
    ) -> LinkSession {
        let deadline = now + cfg.handshake_timeout;
        let heartbeat_ms = cfg.heartbeat.as_millis().min(u32::MAX as u128) as u32;
        let mut s = LinkSession::new(
            SessionConfig {
                role: Role::Agent,
                ..cfg
            },
            Phase::AwaitWelcome(deadline),
            now,
        );
        s.calls_factory = Some(calls);
        s.push(Control::Frame(Frame::Hello {
            version: VERSION,
            robot: hello.robot,
            token: hello.token,
            heartbeat_ms,
            outbox_epoch: hello.outbox_epoch,
            mirror: hello.mirror,
        }));
        s
    }

    pub fn role(&self) -> Role {
        self.role
    }

    pub fn is_open(&self) -> bool {
        self.phase == Phase::Open
    }

    pub fn is_closed(&self) -> bool {
        self.phase == Phase::Closed
    }

    pub fn heartbeat(&self) -> Duration {
        self.heartbeat
    }

    /// How long the peer may be silent before the link is declared dead.
    pub fn dead_after(&self) -> Duration {
        self.heartbeat * 2
    }

    pub fn stats(&self) -> SessionStats {
        self.stats
    }

    /// The gate the session checks calls with (the driver checks topics with it too).
    pub fn gate(&mut self) -> &mut dyn Gate {
        &mut *self.gate
    }

    /// The peer's topic aliases.
    pub fn link_in(&self) -> &LinkIn {
        &self.link
    }

    /// What the peer may do on this side (its calls to this side's services, the services
    /// it may see): the hub's end gets it with [`LinkSession::accept`]; a site hub's link
    /// upstream sets the rules its hub has for the hub upstream.
    pub fn set_gate(&mut self, gate: Box<dyn Gate>) {
        self.gate = gate;
    }

    /// This end is hub `id`: messages whose `VIA` lists it are dropped as they arrive
    /// (they came back), and its writer marks what it sends to a peer hub
    /// ([`super::ViaOut`], with [`LinkIn::peer_hub`]).
    pub fn set_local_hub(&mut self, id: u64) {
        self.link.local_hub = Some(id);
    }

    /// Calls in flight across this link: (served for the peer, forwarded to it).
    pub fn calls_in_flight(&self) -> (usize, usize) {
        self.calls.as_ref().map_or((0, 0), LinkCalls::in_flight)
    }

    // --- input: what the socket read

    /// One binary WebSocket message from the peer.
    pub fn handle_binary(&mut self, data: &Bytes, now: Instant) {
        self.received(now);
        match self.phase {
            Phase::Closed | Phase::Authenticating(_) => {}
            Phase::AwaitHello(_) => self.on_hello_message(data, now),
            Phase::AwaitWelcome(_) | Phase::Open => {
                for f in fleetlink_proto::frame::frames(data) {
                    match f {
                        Ok(f) => self.on_frame(f, now),
                        Err(e) => {
                            self.stats.malformed += 1;
                            let text = format!(
                                "malformed frame: {e}; the rest of this WebSocket message is \
                                 dropped"
                            );
                            tracing::warn!("from the {}: {text}", self.role.peer());
                            self.status(Level::Error, status_code::MALFORMED, text);
                            break;
                        }
                    }
                    if self.phase == Phase::Closed {
                        return;
                    }
                }
                if self.role == Role::Hub {
                    self.queue_ack(now);
                }
            }
        }
    }

    /// A text WebSocket message: `fleetlink.v1` has none.
    pub fn handle_text(&mut self, now: Instant) {
        self.received(now);
        match self.phase {
            Phase::AwaitHello(_) => self.refuse("expected a binary HELLO frame".into()),
            Phase::Open | Phase::AwaitWelcome(_) => self.status(
                Level::Error,
                status_code::MALFORMED,
                "fleetlink.v1 carries binary frames only; a text message was dropped".into(),
            ),
            Phase::Authenticating(_) | Phase::Closed => {}
        }
    }

    /// A WebSocket ping or pong from the peer: bytes, so the peer is alive.
    pub fn handle_activity(&mut self, now: Instant) {
        self.received(now);
    }

    /// The peer closed the WebSocket (`detail`: its close frame, if any).
    pub fn handle_close(&mut self, detail: String) {
        self.close(CloseReason::PeerClosed(detail));
    }

    /// Reading the socket failed.
    pub fn handle_read_error(&mut self, error: String) {
        self.close(CloseReason::ReadError(error));
    }

    /// The peer broke the WebSocket protocol; it is answered with close `code`.
    pub fn handle_invalid(&mut self, code: u16, text: String) {
        self.close(CloseReason::Invalid { code, text });
    }

    fn received(&mut self, now: Instant) {
        if now > self.last_rx {
            self.last_rx = now;
        }
    }

    // --- input: from this side

    /// News from the call table for this link end: calls to forward, answers to send,
    /// services coming and going. Does not move liveness. After the session closed, a
    /// call still handed in fails at once with the reason the link was lost (the driver
    /// drains the table's queue this way).
    pub fn handle_peer_event(&mut self, msg: PeerMsg) {
        let Some(calls) = self.calls.as_mut() else {
            return;
        };
        let mut out = Vec::new();
        calls.on_peer(msg, &mut *self.gate, &mut out);
        for c in out {
            self.push(c);
        }
    }

    /// Whether the driver should feed in call-table news now (see the module docs).
    pub fn wants_peer_events(&self) -> bool {
        self.phase == Phase::Open && self.tx.frames.len() < PEER_EVENT_ROOM
    }

    /// Queues a frame the driver originates (subscriptions, reports, shares). Ignored
    /// unless the session is open.
    pub fn send(&mut self, frame: Frame) {
        if self.phase == Phase::Open {
            self.push(Control::Frame(frame));
        }
    }

    /// Queues an instruction for the link's writer, in order with the frames (a topic to
    /// announce). Ignored unless the session is open.
    pub fn send_control(&mut self, c: Control) {
        if self.phase == Phase::Open {
            self.push(c);
        }
    }

    /// Queues an error report for the peer (capped; see the module docs).
    pub fn status(&mut self, level: Level, code: u32, text: String) {
        if self.phase == Phase::Closed {
            return;
        }
        if self.tx.statuses >= MAX_STATUSES {
            self.stats.statuses_dropped += 1;
            return;
        }
        self.tx.statuses += 1;
        self.tx.frames.push_back(Control::Frame(Frame::Status {
            level,
            code,
            alias: 0,
            text,
        }));
    }

    /// Confirms to the agent that `alias` is delivered (and recorded) up to `seq`.
    pub fn delivered(&mut self, alias: u32, seq: u64) {
        if self.phase != Phase::Open {
            return;
        }
        let s = self.tx.delivered.entry(alias).or_default();
        *s = (*s).max(seq);
    }

    /// Hub: accepts the `HELLO` it reported; `WELCOME` goes out and the session is open.
    pub fn accept(&mut self, accept: Accept, now: Instant) {
        if !matches!(self.phase, Phase::Authenticating(_)) {
            return;
        }
        self.gate = accept.gate;
        self.push(Control::Frame(Frame::Welcome {
            session: accept.session.clone(),
            namespace: accept.namespace.clone(),
            hub_time_ns: (self.wall)(now),
            heartbeat_ms: accept.heartbeat.as_millis().min(u32::MAX as u128) as u32,
            features: accept.features,
        }));
        self.open(
            accept.session,
            accept.namespace,
            accept.heartbeat,
            accept.calls,
            accept.features,
            now,
        );
    }

    /// Hub: refuses the connection; the reason goes to the agent in a `STATUS`, then the
    /// session ends.
    pub fn refuse(&mut self, reason: String) {
        if self.phase == Phase::Closed {
            return;
        }
        self.tx.frames.clear();
        self.tx.statuses = 0;
        self.push(Control::Frame(Frame::Status {
            level: Level::Error,
            code: status_code::UNAUTHORIZED,
            alias: 0,
            text: reason.clone(),
        }));
        self.close(CloseReason::Refused(reason));
    }

    /// Ends the session. Calls forwarded over the link fail at once, saying the link was
    /// lost and why; the peer's services are withdrawn here. Idempotent.
    pub fn close(&mut self, reason: CloseReason) {
        if self.phase == Phase::Closed {
            return;
        }
        self.phase = Phase::Closed;
        if let Some(calls) = self.calls.as_mut() {
            let text = format!("{} link lost: {reason}", self.role.peer());
            calls.close(&text);
        }
        self.events.push_back(Event::Closed(reason));
    }

    // --- time

    /// When [`LinkSession::handle_timeout`] must be called next; `None` once closed.
    pub fn poll_timeout(&self) -> Option<Instant> {
        match self.phase {
            Phase::AwaitHello(d) | Phase::Authenticating(d) | Phase::AwaitWelcome(d) => Some(d),
            Phase::Open => {
                let mut t = (self.last_rx + self.dead_after()).min(self.heartbeat_due());
                if let Some(r) = self.next_report {
                    t = t.min(r);
                }
                Some(t)
            }
            Phase::Closed => None,
        }
    }

    /// Acts on every timer due at `now`: the handshake deadline, liveness, the heartbeat
    /// ping, the periodic report.
    pub fn handle_timeout(&mut self, now: Instant) {
        match self.phase {
            Phase::AwaitHello(d) | Phase::Authenticating(d) if now >= d => {
                self.close(CloseReason::HandshakeTimeout {
                    waiting_for: "HELLO",
                    after: self.handshake_timeout,
                });
            }
            Phase::AwaitWelcome(d) if now >= d => {
                self.close(CloseReason::HandshakeTimeout {
                    waiting_for: "WELCOME",
                    after: self.handshake_timeout,
                });
            }
            Phase::Open => {
                let silent = now.saturating_duration_since(self.last_rx);
                if silent >= self.dead_after() {
                    tracing::warn!(
                        "no bytes from the {} for {} ms; declaring the link dead",
                        self.role.peer(),
                        silent.as_millis()
                    );
                    self.close(CloseReason::Silent { after: silent });
                    return;
                }
                if now >= self.next_ping {
                    // An acknowledgement still waiting goes with the heartbeat at the
                    // latest (or on its own, when the hub leaves out its ping).
                    self.tx.ack_since = None;
                    // Heartbeats that passed while the hub slept through them
                    // (`heartbeat_due`) were each one it could leave out.
                    let hb = self.heartbeat.as_nanos().max(1);
                    let slept = (now - self.next_ping).as_nanos() / hb;
                    self.pings_skipped = self
                        .pings_skipped
                        .saturating_add(u32::try_from(slept).unwrap_or(u32::MAX));
                    if self.skip_ping(now) {
                        self.pings_skipped += 1;
                    } else {
                        self.pings_skipped = 0;
                        self.stats.pings_sent += 1;
                        self.ping_id += 1;
                        let ping = Frame::Ping {
                            id: self.ping_id,
                            sent_ns: (self.wall)(now),
                        };
                        self.push(Control::Frame(ping));
                    }
                    self.next_ping = now + self.heartbeat;
                }
                if let (Some(at), Some(every)) = (self.next_report, self.report_every)
                    && now >= at
                {
                    self.events.push_back(Event::ReportDue);
                    self.next_report = Some(now + every);
                }
            }
            _ => {}
        }
    }

    // --- output

    /// The next frame to send, if any: pongs and acknowledgements first (a peer measures
    /// its link with them), then delivery confirmations, then everything else in order.
    /// An acknowledgement that may still wait (`Transmit::ack_since`) goes only with other
    /// frames.
    pub fn poll_transmit(&mut self) -> Option<Control> {
        // The acknowledgement before the frame it rides with.
        if self.ack_ready()
            && let Some((frames, bytes)) = self.tx.ack.take()
        {
            self.tx.ack_since = None;
            return Some(Control::Frame(Frame::Ack { frames, bytes }));
        }
        if let Some(p) = self.tx.pongs.pop_front() {
            return Some(Control::Frame(p));
        }
        if let Some((alias, seq)) = self.tx.delivered.pop_first() {
            return Some(Control::Frame(Frame::Delivered { alias, seq }));
        }
        let c = self.tx.frames.pop_front()?;
        release_if_drained(&mut self.tx.frames);
        if let Control::Frame(Frame::Status { .. }) = c {
            self.tx.statuses -= 1;
        }
        Some(c)
    }

    /// Whether anything waits to be sent now.
    pub fn has_transmit(&self) -> bool {
        self.ack_ready() || self.has_other_transmit()
    }

    /// Whether a pending acknowledgement goes now: it must, or other frames go anyway.
    fn ack_ready(&self) -> bool {
        self.tx.ack.is_some() && (self.tx.ack_since.is_none() || self.has_other_transmit())
    }

    fn has_other_transmit(&self) -> bool {
        !self.tx.pongs.is_empty() || !self.tx.delivered.is_empty() || !self.tx.frames.is_empty()
    }

    pub fn poll_event(&mut self) -> Option<Event> {
        let e = self.events.pop_front();
        if e.is_none() {
            // A handshake's burst (a robot's every ADVERTISE at once) leaves no room
            // behind on an idle link; a few events come back without reallocating.
            release_if_drained(&mut self.events);
        }
        e
    }

    // --- inside

    /// Queues `c`; a `STATUS` counts towards the cap wherever it comes from (the call
    /// table's refusals too), so that taking it off the queue balances the count.
    fn push(&mut self, c: Control) {
        if let Control::Frame(Frame::Status { .. }) = c {
            self.tx.statuses += 1;
        }
        self.tx.frames.push_back(c);
    }

    /// Adds what the last WebSocket message brought to the pending `ACK`, and decides
    /// whether it goes now or may wait (see `Transmit::ack_since`).
    fn queue_ack(&mut self, now: Instant) {
        let chunked = self.link.unacked_chunk;
        let Some(Frame::Ack { frames, bytes }) = self.link.take_ack() else {
            return;
        };
        let (f, b) = self.tx.ack.get_or_insert((0, 0));
        *f = f.saturating_add(frames);
        *b = b.saturating_add(bytes);
        let urgent = chunked || *f >= ACK_EVERY_MESSAGES || *b >= ACK_EVERY_BYTES;
        self.tx.ack_since = match self.tx.ack_since {
            _ if urgent => None,
            Some(since) if now.saturating_duration_since(since) >= ACK_DELAY => None,
            Some(since) => Some(since),
            None => Some(now),
        };
    }

    /// Whether the hub may leave out this heartbeat's `PING`: the peer pinged within the
    /// last heartbeat and a quarter ([`LinkSession::peer_pings_within`]), so it hears the
    /// hub's `PONG` and the hub hears the peer, each well inside two heartbeats, without a
    /// second exchange. Every [`HUB_PING_EVERY`]th
    /// heartbeat still pings, for the round trip and clock offset it measures. Only the
    /// hub skips: a peer that stops pinging gets the hub's pings again from the next
    /// heartbeat on. An idle fleet's links carry half the frames, which is most of what
    /// an idle hub spends per robot.
    fn skip_ping(&self, now: Instant) -> bool {
        self.role == Role::Hub
            && self.pings_skipped + 1 < HUB_PING_EVERY
            && self
                .peer_pinged
                .is_some_and(|at| now.saturating_duration_since(at) < self.peer_pings_within())
    }

    /// How long after the peer's last `PING` the hub still counts it as pinging: a
    /// heartbeat, and a quarter for the peer's timer running late and the network's
    /// jitter. Without the quarter, a peer whose pings come a heartbeat apart plus a
    /// millisecond had the hub's own timer win the race every other heartbeat, and the
    /// hub pinged about half the heartbeats instead of one in [`HUB_PING_EVERY`]. A peer
    /// that stops pinging hears the hub's pings a quarter of a heartbeat later than
    /// without it, still inside the two heartbeats its link may stay silent.
    fn peer_pings_within(&self) -> Duration {
        self.heartbeat + self.heartbeat / 4
    }

    /// When the heartbeat timer must next run. The agent pings every heartbeat. The hub,
    /// while the peer pings ([`LinkSession::skip_ping`]) and no acknowledgement waits to go
    /// with a heartbeat, would only leave its pings out: it sleeps through them until its
    /// every-[`HUB_PING_EVERY`]th ping or until the peer has been quiet a heartbeat and a
    /// quarter, whichever comes first. Each ping the peer sends wakes the hub anyway (it
    /// answers it), and this is asked again then; so an idle robot's link wakes the hub
    /// once a heartbeat, not twice.
    fn heartbeat_due(&self) -> Instant {
        let Some(pinged) = self.peer_pinged else {
            return self.next_ping;
        };
        if self.role != Role::Hub || self.tx.ack_since.is_some() {
            return self.next_ping;
        }
        let skips_left = HUB_PING_EVERY.saturating_sub(self.pings_skipped + 1);
        let own_ping = self.next_ping + self.heartbeat * skips_left;
        let peer_quiet = pinged + self.peer_pings_within();
        self.next_ping.max(own_ping.min(peer_quiet))
    }

    fn open(
        &mut self,
        session: String,
        namespace: String,
        heartbeat: Duration,
        calls: CallsFactory,
        features: u64,
        now: Instant,
    ) {
        self.phase = Phase::Open;
        self.heartbeat = heartbeat;
        // The peer cannot have been silent before there was a session to be silent in.
        self.last_rx = self.last_rx.max(now);
        self.next_ping = now + heartbeat;
        self.next_report = self.report_every.map(|e| now + e);
        self.calls = Some(calls(&namespace));
        self.events.push_back(Event::Opened {
            session,
            namespace,
            heartbeat,
            features,
        });
    }

    /// Hub, waiting for `HELLO`: it must be the message's first frame.
    fn on_hello_message(&mut self, data: &Bytes, now: Instant) {
        let first = fleetlink_proto::frame::frames(data).next();
        match first {
            Some(Ok(Frame::Hello {
                version,
                robot,
                token,
                heartbeat_ms,
                outbox_epoch,
                mirror,
            })) => {
                if version != VERSION {
                    return self.refuse(format!(
                        "unsupported protocol version {version}; this hub speaks {VERSION}"
                    ));
                }
                let Phase::AwaitHello(deadline) = self.phase else {
                    return;
                };
                self.phase = Phase::Authenticating(deadline);
                self.last_rx = now;
                self.events.push_back(Event::Hello {
                    robot,
                    token,
                    heartbeat_ms,
                    outbox_epoch,
                    mirror,
                });
            }
            Some(Err(e)) => self.refuse(format!("malformed HELLO: {e}")),
            Some(Ok(_)) | None => self.refuse("the first frame must be HELLO".into()),
        }
    }

    fn on_frame(&mut self, f: Frame, now: Instant) {
        if self.phase != Phase::Open {
            // Agent, before WELCOME: the answer to HELLO or a refusal; nothing else counts.
            match f {
                Frame::Welcome {
                    session,
                    namespace,
                    heartbeat_ms,
                    features,
                    ..
                } => {
                    let heartbeat = Duration::from_millis(u64::from(heartbeat_ms.max(10)));
                    let calls = self.calls_factory.take().unwrap_or_else(|| {
                        unreachable!("an agent session is made with its calls factory")
                    });
                    self.open(session, namespace, heartbeat, calls, features, now);
                }
                Frame::Status { text, .. } => self.close(CloseReason::Refused(text)),
                _ => {}
            }
            return;
        }
        if is_call_frame(&f) {
            if let Some(calls) = self.calls.as_mut() {
                let mut out = Vec::new();
                calls.on_frame(f, &mut *self.gate, &mut out);
                for c in out {
                    self.push(c);
                }
            }
            return;
        }
        match f {
            Frame::Ping { id, sent_ns } => {
                self.peer_pinged = Some(now);
                if self.tx.pongs.len() == MAX_PONGS {
                    self.tx.pongs.pop_front();
                    self.stats.pongs_dropped += 1;
                }
                self.tx.pongs.push_back(Frame::Pong {
                    id,
                    echo_ns: sent_ns,
                    responder_ns: (self.wall)(now),
                });
            }
            Frame::Pong {
                id,
                echo_ns,
                responder_ns,
            } => {
                let at = (self.wall)(now);
                let rtt = at.saturating_sub(echo_ns);
                // The peer read its clock about half a round trip after we sent.
                let offset = (echo_ns as i128 + rtt as i128 / 2 - responder_ns as i128)
                    .clamp(i64::MIN as i128, i64::MAX as i128) as i64;
                self.events.push_back(Event::Pong {
                    id,
                    responder_ns,
                    rtt: Duration::from_nanos(rtt),
                    offset_ns: offset,
                });
            }
            // A second handshake frame means nothing on an open link.
            Frame::Hello { .. } | Frame::Welcome { .. } => {}
            other => match self.link.on_frame(other) {
                Ok(LinkEvent::None) => {}
                Ok(ev) => self.events.push_back(Event::Link(ev)),
                Err(e) => {
                    // The frame is lost, not the link.
                    let code = match &e {
                        LinkError::UnknownAlias(_) => status_code::UNKNOWN_ALIAS,
                        LinkError::Reassembly(ReassemblyError::OutOfOrder { .. }) => {
                            status_code::CHUNK_ORDER
                        }
                        LinkError::Reassembly(_) => status_code::TOO_LARGE,
                        LinkError::Compression { .. } => status_code::MALFORMED,
                    };
                    let text = e.to_string();
                    tracing::debug!("from the {}: {text}", self.role.peer());
                    self.status(Level::Warning, code, text);
                }
            },
        }
    }
}

/// Lets a drained queue's large buffer go (one a burst grew), so an idle link holds
/// little; a queue of a few entries keeps its room.
fn release_if_drained<T>(q: &mut VecDeque<T>) {
    if q.is_empty() && q.capacity() > 8 {
        *q = VecDeque::new();
    }
}

#[cfg(test)]
#[path = "session_tests.rs"]
mod tests;
