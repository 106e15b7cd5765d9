//! A hub session and an agent session joined by a simulated link, on virtual time.
//!
//! The link carries each side's writes to the other after a latency; "loss" is what it is
//! on TCP, a retransmission that holds up the message and everything behind it; a cut
//! drops everything from then on. Around the link each side has a call table with
//! participants that call, provide, and send feedback, driven the way the hub's and the
//! agent's tasks drive their sessions.
//!
//! The property under test (issue 36): a link that goes silent is declared dead within
//! 2 × heartbeat (+ one heartbeat of slack) of the last byte received, whatever else the
//! two sides keep doing — service calls and action feedback both ways, topic publishes
//! both ways, subscription churn, parameter calls — at rates from 0.1 to 1,000 events/s;
//! the calls pending on the dead link end at once, saying the link was lost; and a link
//! that only loses and delays is never declared dead.

use std::sync::Arc;
use std::time::{Duration, Instant};

use bytes::{Bytes, BytesMut};
use fleetlink_proto::frame::{CallStatus, Frame, Level, SUBSCRIBE_REGEX, VERSION, status_code};
use fleetlink_proto::{Encoding, Payload, Schema};

use super::*;
use crate::calls::{CallEvent, CallId, CallOptions, Calls, ChannelPeer, PeerReceiver};
use crate::link_calls::SameNames;
use crate::names::{ClientId, TopicName};
use crate::router::Router;

const HB: Duration = Duration::from_millis(1000);
const STEP: Duration = Duration::from_millis(1);

fn name(s: &str) -> TopicName {
    TopicName::parse(s).unwrap()
}

fn wall(base: Instant) -> WallClock {
    Box::new(move |now: Instant| 1_700_000_000_000_000_000 + (now - base).as_nanos() as u64)
}

fn config(role: Role, base: Instant) -> SessionConfig {
    SessionConfig {
        role,
        heartbeat: HB,
        handshake_timeout: Duration::from_secs(10),
        report_every: (role == Role::Agent).then_some(Duration::from_secs(1)),
        wall: wall(base),
    }
}

/// A participant of one side's call table: calls, provides, or both.
struct Local {
    id: ClientId,
    rx: PeerReceiver,
    /// Goals this participant provides that are still running (for feedback).
    goals: Vec<CallId>,
    /// Its own calls: id → when made.
    pending: std::collections::HashMap<CallId, Instant>,
    /// How its calls ended: (status, text, when made, when ended).
    ended: Vec<(CallId, CallStatus, String, Instant, Instant)>,
}

impl Local {
    fn new(calls: &Calls, id: u64) -> Local {
        let (peer, rx) = ChannelPeer::new();
        calls.attach(ClientId(id), peer);
        Local {
            id: ClientId(id),
            rx,
            goals: Vec::new(),
            pending: Default::default(),
            ended: Vec::new(),
        }
    }

    /// Answers what it was handed: service calls at once, goals later (they stay running).
    fn serve(&mut self, calls: &Calls, now: Instant) {
        while let Ok(Some(m)) = self.rx.try_recv() {
            match m {
                PeerMsg::Call(req) if req.goal_id.is_some() => self.goals.push(req.id),
                PeerMsg::Call(req) => {
                    calls.respond(
                        self.id,
                        req.id,
                        CallStatus::Ok,
                        Some(json("{}")),
                        String::new(),
                    );
                }
                PeerMsg::Cancel(id) => self.goals.retain(|g| *g != id),
                PeerMsg::Event(CallEvent::Done {
                    id, status, text, ..
                }) => {
                    if let Some(made) = self.pending.remove(&id) {
                        self.ended.push((id, status, text, made, now));
                    }
                }
                PeerMsg::Event(CallEvent::Feedback { .. }) | PeerMsg::Changed(_) => {}
            }
        }
    }

    fn call(&mut self, calls: &Calls, service: &str, goal: bool, now: Instant) {
        let opts = CallOptions {
            timeout: Some(Duration::from_secs(600)),
            goal,
            goal_id: None,
            on_behalf_of: None,
        };
        match calls.call(self.id, &name(service), json("{}"), opts) {
            Ok(id) => {
                self.pending.insert(id, now);
            }
            Err(e) => self.ended.push((0, e.status, e.text, now, now)),
        }
    }
}

fn json(s: &str) -> Payload {
    Payload::new(Encoding::Json, Bytes::copy_from_slice(s.as_bytes()))
}

/// One side: its session, its call table, its link end's queue and its participants.
struct Side {
    session: LinkSession,
    calls: Arc<Calls>,
    link_end: ClientId,
    link_rx: PeerReceiver,
    /// Calls (and a provider of an action, for feedback the other way).
    caller: Local,
    /// Provides a service, a "parameter" service and an action.
    provider: Local,
    closed: Option<(CloseReason, Instant)>,
    opened: bool,
    /// When bytes from the other side last arrived here.
    last_rx: Option<Instant>,
    /// Hub-side accounting of statuses received from the peer, etc.
    statuses_in: Vec<String>,
    messages_in: u64,
    /// Times the session's timer came due and ran.
    timer_runs: u64,
}

impl Side {
    fn new(session: LinkSession, calls: Arc<Calls>, link_end: u64, base_id: u64) -> Side {
        let (peer, link_rx) = ChannelPeer::new();
        calls.attach(ClientId(link_end), peer);
        let caller = Local::new(&calls, base_id);
        let provider = Local::new(&calls, base_id + 1);
        Side {
            session,
            calls,
            link_end: ClientId(link_end),
            link_rx,
            caller,
            provider,
            closed: None,
            opened: false,
            last_rx: None,
            statuses_in: Vec::new(),
            messages_in: 0,
            timer_runs: 0,
        }
    }

    /// What the task around a session does each turn: feed it the table's news while it
    /// has room, act on its events, and hand its frames to the writer.
    fn drive(&mut self, now: Instant, out: &mut Vec<Bytes>) {
        self.caller.serve(&self.calls, now);
        self.provider.serve(&self.calls, now);
        while self.session.wants_peer_events() {
            match self.link_rx.try_recv() {
                Ok(Some(m)) => self.session.handle_peer_event(m),
                _ => break,
            }
        }
        if self.session.poll_timeout().is_some_and(|t| now >= t) {
            self.timer_runs += 1;
            self.session.handle_timeout(now);
        }
        while let Some(ev) = self.session.poll_event() {
            match ev {
                Event::Hello { .. } => {
                    let (calls, me) = (self.calls.clone(), self.link_end);
                    self.session.accept(
                        Accept {
                            session: "1".into(),
                            namespace: "/r1".into(),
                            heartbeat: HB,
                            gate: Box::new(AllowAll),
                            calls: Box::new(move |_| {
                                LinkCalls::new(calls, me, Box::new(SameNames))
                            }),
                            features: 0,
                        },
                        now,
                    );
                }
                Event::Opened { .. } => {
                    self.opened = true;
                    // What the robot may call (hub) / every local service (agent).
                    let pattern = match self.session.role() {
                        Role::Hub => "/cloud/.*",
                        Role::Agent => "/r1/.*",
                    };
                    self.calls
                        .watch(self.link_end, Router::compile_pattern(pattern).unwrap());
                }
                Event::Link(LinkEvent::Message { .. }) => self.messages_in += 1,
                Event::Link(LinkEvent::Control(Frame::Status { text, .. })) => {
                    self.statuses_in.push(text)
                }
                Event::Closed(r) => {
                    // The driver: drain what the table queued, then leave the table.
                    while let Ok(Some(m)) = self.link_rx.try_recv() {
                        self.session.handle_peer_event(m);
                    }
                    self.calls.detach(self.link_end);
                    self.closed = Some((r, now));
                }
                _ => {}
            }
        }
        while let Some(c) = self.session.poll_transmit() {
            match c {
                Control::Frame(f) => out.push(f.to_bytes()),
                Control::Sequence(fs) => out.extend(fs.iter().map(Frame::to_bytes)),
                other => panic!("a session only sends frames: {other:?}"),
            }
        }
        // A closed session's driver stops reading and writing.
        if self.closed.is_some() {
            out.clear();
        }
        self.caller.serve(&self.calls, now);
        self.provider.serve(&self.calls, now);
    }
}

/// In flight on the simulated link, one direction.
#[derive(Default)]
struct Wire {
    q: std::collections::VecDeque<(Instant, Bytes)>,
}

/// Traffic the two sides keep generating.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// An operator calls the robot's service; a node on the robot calls a fleet service.
    Calls,
    /// Feedback of a running goal, both ways.
    Feedback,
    /// Topic messages, both ways (written by each side's outbox writer).
    Publishes,
    /// The agent's subscriptions change; the hub reports statuses and confirms deliveries.
    Churn,
    /// The hub's parameter services call the robot's nodes.
    Params,
}

const KINDS: [Kind; 5] = [
    Kind::Calls,
    Kind::Feedback,
    Kind::Publishes,
    Kind::Churn,
    Kind::Params,
];

struct Pair {
    base: Instant,
    now: Instant,
    hub: Side,
    agent: Side,
    to_hub: Wire,
    to_agent: Wire,
    latency: Duration,
    /// Each message is held up by this much with probability `loss` (a TCP retransmission).
    loss: f64,
    rto: Duration,
    /// Each message takes up to this much longer than `latency` (uniform), in order.
    jitter: Duration,
    /// The agent's `PING`s never reach the hub (a peer that stopped pinging).
    agent_stops_pinging: bool,
    cut: bool,
    rng: fastrand::Rng,
    /// Goals running for feedback: (provider side is agent?, id).
    feedback_goals: bool,
}

impl Pair {
    fn new(latency: Duration) -> Pair {
        let base = Instant::now();
        let (hub_calls, agent_calls) = (Arc::new(Calls::default()), Arc::new(Calls::default()));
        let hub = Side::new(
            LinkSession::hub(config(Role::Hub, base), base),
            hub_calls,
            1,
            10,
        );
        let me = ClientId(2);
        let c = agent_calls.clone();
        let agent_session = LinkSession::agent(
            config(Role::Agent, base),
            AgentHello {
                robot: "r1".into(),
                token: String::new(),
                outbox_epoch: 0,
                mirror: String::new(),
            },
            Box::new(move |_| LinkCalls::new(c, me, Box::new(SameNames))),
            base,
        );
        let agent = Side::new(agent_session, agent_calls, 2, 20);
        // The robot's services, and the fleet's.
        let schema = Schema::named("std_srvs/srv/Trigger");
        let act = Schema::named("x/action/Nav");
        let (a, h) = (&agent.calls, &hub.calls);
        a.advertise(agent.provider.id, name("/r1/svc"), schema.clone(), false);
        a.advertise(agent.provider.id, name("/r1/params"), schema.clone(), false);
        a.advertise(agent.provider.id, name("/r1/act"), act.clone(), true);
        h.advertise(hub.provider.id, name("/cloud/svc"), schema, false);
        h.advertise(hub.provider.id, name("/cloud/act"), act, true);
        Pair {
            base,
            now: base,
            hub,
            agent,
            to_hub: Wire::default(),
            to_agent: Wire::default(),
            latency,
            loss: 0.0,
            rto: Duration::from_millis(200),
            jitter: Duration::ZERO,
            agent_stops_pinging: false,
            cut: false,
            rng: fastrand::Rng::with_seed(36),
            feedback_goals: false,
        }
    }

    fn put(&mut self, to_hub: bool, msgs: Vec<Bytes>) {
        if self.cut {
            return;
        }
        for m in msgs {
            if to_hub
                && self.agent_stops_pinging
                && m.first() == Some(&(fleetlink_proto::frame::FrameKind::Ping as u8))
            {
                continue;
            }
            let mut at = self.now + self.latency;
            if !self.jitter.is_zero() {
                let ns = u64::try_from(self.jitter.as_nanos()).unwrap_or(u64::MAX);
                at += Duration::from_nanos(self.rng.u64(0..=ns));
            }
            if self.loss > 0.0 && self.rng.f64() < self.loss {
                at += self.rto;
            }
            let wire = if to_hub {
                &mut self.to_hub
            } else {
                &mut self.to_agent
            };
            // In order, as on a TCP connection: nothing overtakes a held-up message.
            if let Some((last, _)) = wire.q.back() {
                at = at.max(*last);
            }
            wire.q.push_back((at, m));
        }
    }

    /// One step of virtual time: deliver what is due, drive both sides.
    fn step(&mut self) {
        self.now += STEP;
        let now = self.now;
        for to_hub in [true, false] {
            loop {
                let wire = if to_hub {
                    &mut self.to_hub
                } else {
                    &mut self.to_agent
                };
                let Some((at, _)) = wire.q.front() else { break };
                if *at > now {
                    break;
                }
                let (_, m) = wire.q.pop_front().unwrap();
                let side = if to_hub {
                    &mut self.hub
                } else {
                    &mut self.agent
                };
                if side.closed.is_none() {
                    side.session.handle_binary(&m, now);
                    side.last_rx = Some(now);
                }
            }
        }
        let mut out = Vec::new();
        self.hub.drive(now, &mut out);
        self.put(false, std::mem::take(&mut out));
        self.agent.drive(now, &mut out);
        self.put(true, out);
    }

    fn run_until(&mut self, t: Instant, mut each: impl FnMut(&mut Pair)) {
        while self.now < t {
            each(self);
            self.step();
        }
    }

    fn open(&mut self) {
        let until = self.now + Duration::from_secs(1);
        self.run_until(until, |_| {});
        assert!(self.hub.opened && self.agent.opened, "handshake done");
        // Each side sees the other's services.
        assert!(self.hub.calls.service(&name("/r1/svc")).is_some());
        assert!(self.agent.calls.service(&name("/cloud/svc")).is_some());
    }

    /// One event of `kind` on both sides.
    fn event(&mut self, kind: Kind, n: u64) {
        let now = self.now;
        match kind {
            Kind::Calls => {
                self.hub.caller.call(&self.hub.calls, "/r1/svc", false, now);
                self.agent
                    .caller
                    .call(&self.agent.calls, "/cloud/svc", false, now);
            }
            Kind::Params => self
                .hub
                .caller
                .call(&self.hub.calls, "/r1/params", false, now),
            Kind::Feedback => {
                if !self.feedback_goals {
                    self.feedback_goals = true;
                    self.hub.caller.call(&self.hub.calls, "/r1/act", true, now);
                    self.agent
                        .caller
                        .call(&self.agent.calls, "/cloud/act", true, now);
                    return;
                }
                for side in [&mut self.hub, &mut self.agent] {
                    for g in side.provider.goals.clone() {
                        side.calls
                            .feedback(side.provider.id, g, json(&format!("{{\"n\":{n}}}")));
                    }
                }
            }
            Kind::Publishes => {
                let mut to_hub = Vec::new();
                let mut to_agent = Vec::new();
                for (out, alias) in [(&mut to_hub, 7u32), (&mut to_agent, 9u32)] {
                    let mut b = BytesMut::new();
                    if n == 0 {
                        Frame::Advertise {
                            alias,
                            topic: "/r1/scan".into(),
                            schema: Schema::named("std_msgs/msg/String"),
                            encoding: Encoding::Json,
                            flags: 0,
                        }
                        .encode(&mut b);
                    }
                    Frame::Message {
                        alias,
                        seq: n,
                        stamp_ns: 0,
                        payload: Bytes::from_static(b"{\"data\":\"x\"}"),
                    }
                    .encode(&mut b);
                    out.push(b.freeze());
                }
                // Written by each side's outbox writer, beside the session.
                if self.hub.closed.is_none() {
                    self.put(false, to_agent);
                }
                if self.agent.closed.is_none() {
                    self.put(true, to_hub);
                }
            }
            Kind::Churn => {
                let id = (n % 16) as u32 + 100;
                if n.is_multiple_of(2) {
                    self.agent.session.send(Frame::Subscribe {
                        id,
                        pattern: "/fleet/.*".into(),
                        flags: SUBSCRIBE_REGEX,
                        throttle_ms: 0,
                        queue_length: 0,
                    });
                } else {
                    self.agent.session.send(Frame::Unsubscribe { id });
                }
                self.hub.session.delivered(7, n);
                self.hub
                    .session
                    .status(Level::Warning, 9, format!("status {n}"));
            }
        }
    }
}

/// Runs `kinds` at `rate` events/s from well before a cut until both ends are closed.
/// Returns the pair after the run.
fn cut_under_traffic(kinds: &[Kind], rate: f64) -> Pair {
    let mut p = Pair::new(Duration::from_millis(20));
    p.open();
    let period = Duration::from_secs_f64(1.0 / rate);
    let mut next = p.now;
    let mut n = 0u64;
    let cut_at = p.now + Duration::from_secs(3);
    let end = cut_at + Duration::from_secs(8);
    let kinds = kinds.to_vec();
    p.run_until(end, |p| {
        if !p.cut && p.now >= cut_at {
            p.cut = true;
            p.to_hub.q.clear();
            p.to_agent.q.clear();
        }
        // Events are generated before and after the cut alike, at the rate asked (with
        // events due in the same millisecond done together).
        while p.now >= next {
            for k in &kinds {
                p.event(*k, n);
            }
            n += 1;
            next += period;
        }
    });
    p
}

/// Checks one side of a cut: dead within [2 hb, 3 hb] of the last byte received, for
/// being silent; the calls pending on the link ended at once, saying so.
fn check_side(side: &Side, what: &str, lost: &str) {
    let (reason, at) = side
        .closed
        .clone()
        .unwrap_or_else(|| panic!("{what}: the link was never declared dead"));
    assert!(
        matches!(reason, CloseReason::Silent { .. }),
        "{what}: closed for {reason}"
    );
    let last = side.last_rx.expect("bytes arrived before the cut");
    let silent = at - last;
    assert!(
        silent >= 2 * HB && silent <= 3 * HB,
        "{what}: declared dead {silent:?} after the last byte received (must be 2 to 3 \
         heartbeats)"
    );
    // Every call of this side still waiting when the link died ended then, with the reason;
    // none is left pending.
    let c = &side.caller;
    assert!(
        c.pending.is_empty(),
        "{what}: {} calls still pending",
        c.pending.len()
    );
    for (_, status, text, made, ended) in &c.ended {
        if *ended < at {
            continue;
        }
        if *made < at {
            // Pending when the link died: ended then, saying why.
            assert_eq!(*ended, at, "{what}: {text}");
            assert_eq!(*status, CallStatus::Aborted, "{what}: {text}");
            assert!(text.contains(lost), "{what}: {text}");
        } else {
            // Made after the link was gone: the service is not there, refused at once.
            assert_eq!(*ended, *made, "{what}: {text}");
            assert_eq!(*status, CallStatus::NoProvider, "{what}: {text}");
        }
    }
}

fn rates() -> [f64; 5] {
    [0.1, 1.0, 10.0, 100.0, 1000.0]
}

#[test]
fn a_cut_link_is_declared_dead_on_time_under_every_kind_of_traffic() {
    for kind in KINDS {
        for rate in rates() {
            let p = cut_under_traffic(&[kind], rate);
            let what = format!("{kind:?} at {rate}/s");
            check_side(&p.hub, &format!("hub, {what}"), "robot link lost");
            check_side(&p.agent, &format!("agent, {what}"), "hub link lost");
        }
    }
}

#[test]
fn a_cut_link_is_declared_dead_on_time_under_all_traffic_at_once() {
    for rate in rates() {
        let p = cut_under_traffic(&KINDS, rate);
        check_side(&p.hub, &format!("hub, all at {rate}/s"), "robot link lost");
        check_side(
            &p.agent,
            &format!("agent, all at {rate}/s"),
            "hub link lost",
        );
    }
}

#[test]
fn calls_pending_on_a_dead_link_end_at_once_with_the_reason() {
    let mut p = Pair::new(Duration::from_millis(20));
    p.open();
    // The robot's provider holds the goal; the operator's service calls are answered only
    // after the cut (never), so they are pending when the link dies.
    p.cut = true;
    let now = p.now;
    for _ in 0..5 {
        p.hub.caller.call(&p.hub.calls, "/r1/svc", false, now);
    }
    p.hub.caller.call(&p.hub.calls, "/r1/act", true, now);
    let until = p.now + 4 * HB;
    p.run_until(until, |_| {});
    let (_, at) = p.hub.closed.clone().expect("declared dead");
    let lost: Vec<_> = p.hub.caller.ended.iter().filter(|e| e.4 == at).collect();
    assert_eq!(lost.len(), 6, "{:?}", p.hub.caller.ended);
    for (_, status, text, ..) in lost {
        assert_eq!(*status, CallStatus::Aborted);
        assert!(
            text.starts_with("robot link lost: no bytes received for 2"),
            "{text}"
        );
    }
    assert_eq!(
        p.hub.calls.pending(),
        0,
        "nothing is left in the hub's table"
    );
    assert_eq!(p.hub.calls.bookkeeping(), 0);
}

#[test]
fn a_slow_lossy_link_under_load_is_never_declared_dead() {
    let mut p = Pair::new(Duration::from_millis(150));
    p.loss = 0.02;
    p.rto = Duration::from_millis(300);
    p.open();
    let mut n = 0u64;
    let end = p.now + Duration::from_secs(30);
    p.run_until(end, |p| {
        if (p.now - p.base).as_millis().is_multiple_of(2) {
            for k in KINDS {
                p.event(k, n);
            }
            n += 1;
        }
    });
    assert!(p.hub.closed.is_none(), "{:?}", p.hub.closed);
    assert!(p.agent.closed.is_none(), "{:?}", p.agent.closed);
    // The calls went through, but for those over the table's bound on calls pending per
    // caller (500 calls a second over a 300 ms round trip, more while a loss holds
    // everything up).
    for s in [&p.hub, &p.agent] {
        let ok = s
            .caller
            .ended
            .iter()
            .filter(|e| e.1 == CallStatus::Ok)
            .count();
        assert!(ok > 5_000, "{ok}");
        for (_, status, text, ..) in &s.caller.ended {
            assert!(
                matches!(status, CallStatus::Ok | CallStatus::Busy),
                "{status:?}: {text}"
            );
        }
    }
    assert!(p.hub.messages_in > 10_000 && p.agent.messages_in > 10_000);
}

#[test]
fn an_idle_link_stays_up_on_heartbeats_alone() {
    let mut p = Pair::new(Duration::from_millis(300));
    p.open();
    let hub_timer_before = p.hub.timer_runs;
    let end = p.now + Duration::from_secs(60);
    p.run_until(end, |_| {});
    assert!(p.hub.closed.is_none() && p.agent.closed.is_none());
    // The agent pings every heartbeat; the hub, hearing those, only every fifth.
    let (hub_pings, agent_pings) = (
        p.hub.session.stats().pings_sent,
        p.agent.session.stats().pings_sent,
    );
    assert!(
        (59..=61).contains(&agent_pings),
        "agent pinged {agent_pings} times in 60 s"
    );
    let every = u64::from(HUB_PING_EVERY);
    assert!(
        (60 / every - 1..=60 / every + 1).contains(&hub_pings),
        "hub pinged {hub_pings} times in 60 s"
    );
    // The hub's timer runs for its own pings only, not at every heartbeat it leaves out
    // (the agent's pings wake it to answer them anyway).
    let hub_timer = p.hub.timer_runs - hub_timer_before;
    assert!(
        hub_timer <= 60 / every + 2,
        "the hub's timer ran {hub_timer} times in 60 s"
    );
    // And a cut of an idle link is found the same way.
    p.cut = true;
    let end = p.now + 4 * HB;
    p.run_until(end, |_| {});
    check_side(&p.hub, "hub, idle", "robot link lost");
    check_side(&p.agent, "agent, idle", "hub link lost");
}

#[test]
fn the_hub_leaves_its_pings_out_when_the_agents_come_a_little_late() {
    // A real agent's pings come a heartbeat apart plus its timer's lateness and the
    // network's jitter: the hub must not take each late one for a quiet peer.
    let mut p = Pair::new(Duration::from_millis(300));
    p.open();
    p.jitter = Duration::from_millis(40);
    let before = p.hub.session.stats().pings_sent;
    let end = p.now + Duration::from_secs(60);
    p.run_until(end, |_| {});
    assert!(p.hub.closed.is_none() && p.agent.closed.is_none());
    let hub_pings = p.hub.session.stats().pings_sent - before;
    let every = u64::from(HUB_PING_EVERY);
    assert!(
        (60 / every - 1..=60 / every + 1).contains(&hub_pings),
        "hub pinged {hub_pings} times in 60 s"
    );
    // A peer that stops pinging gets the hub's pings in time to keep its link up.
    p.agent_stops_pinging = true;
    let end = p.now + Duration::from_secs(10);
    p.run_until(end, |_| {});
    assert!(p.hub.closed.is_none() && p.agent.closed.is_none());
}

// --- handshake and malformed input

fn hub_session() -> (LinkSession, Instant) {
    let base = Instant::now();
    (LinkSession::hub(config(Role::Hub, base), base), base)
}

fn statuses(s: &mut LinkSession) -> Vec<(u32, String)> {
    let mut v = Vec::new();
    while let Some(c) = s.poll_transmit() {
        if let Control::Frame(Frame::Status { code, text, .. }) = c {
            v.push((code, text));
        }
    }
    v
}

fn closed(s: &mut LinkSession) -> Option<CloseReason> {
    let mut r = None;
    while let Some(e) = s.poll_event() {
        if let Event::Closed(c) = e {
            r = Some(c);
        }
    }
    r
}

#[test]
fn the_hub_refuses_a_connection_that_does_not_start_with_hello() {
    for first in [
        Frame::Ping { id: 1, sent_ns: 0 }.to_bytes(),
        Bytes::from_static(&[0xff, 0xff, 0xff, 0xff, 0xff]),
        Bytes::new(),
    ] {
        let (mut s, t) = hub_session();
        s.handle_binary(&first, t);
        let st = statuses(&mut s);
        assert_eq!(st.len(), 1, "{st:?}");
        assert_eq!(st[0].0, 401);
        assert!(matches!(closed(&mut s), Some(CloseReason::Refused(_))));
    }
    let (mut s, t) = hub_session();
    s.handle_text(t);
    assert!(statuses(&mut s)[0].1.contains("binary HELLO"));
}

#[test]
fn the_hub_refuses_another_protocol_version_and_waits_ten_seconds_for_hello() {
    let (mut s, t) = hub_session();
    let hello = Frame::Hello {
        version: VERSION + 1,
        robot: "r1".into(),
        token: String::new(),
        heartbeat_ms: 0,
        outbox_epoch: 0,
        mirror: String::new(),
    };
    s.handle_binary(&hello.to_bytes(), t);
    assert!(
        statuses(&mut s)[0]
            .1
            .contains("unsupported protocol version")
    );

    let (mut s, t) = hub_session();
    assert_eq!(s.poll_timeout(), Some(t + Duration::from_secs(10)));
    s.handle_timeout(t + Duration::from_millis(9_999));
    assert!(!s.is_closed());
    s.handle_timeout(t + Duration::from_secs(10));
    assert_eq!(
        closed(&mut s).map(|r| r.to_string()),
        Some("no HELLO within 10 s".to_owned())
    );
}

#[test]
fn the_agent_reads_a_refusal_and_times_out_without_welcome() {
    let base = Instant::now();
    let calls = Arc::new(Calls::default());
    let make = |calls: Arc<Calls>| -> CallsFactory {
        Box::new(move |_| LinkCalls::new(calls, ClientId(1), Box::new(SameNames)))
    };
    let hello = || AgentHello {
        robot: "r1".into(),
        token: "t".into(),
        outbox_epoch: 3,
        mirror: String::new(),
    };
    let mut s = LinkSession::agent(
        config(Role::Agent, base),
        hello(),
        make(calls.clone()),
        base,
    );
    match s.poll_transmit() {
        Some(Control::Frame(Frame::Hello {
            robot,
            heartbeat_ms,
            outbox_epoch,
            ..
        })) => assert_eq!(
            (robot.as_str(), heartbeat_ms, outbox_epoch),
            ("r1", 1000, 3)
        ),
        other => panic!("{other:?}"),
    }
    let refusal = Frame::Status {
        level: Level::Error,
        code: 401,
        alias: 0,
        text: "authentication failed".into(),
    };
    s.handle_binary(&refusal.to_bytes(), base);
    assert_eq!(
        closed(&mut s),
        Some(CloseReason::Refused("authentication failed".into()))
    );

    let mut s = LinkSession::agent(config(Role::Agent, base), hello(), make(calls), base);
    s.handle_timeout(base + Duration::from_secs(10));
    assert!(matches!(
        closed(&mut s),
        Some(CloseReason::HandshakeTimeout {
            waiting_for: "WELCOME",
            ..
        })
    ));
}

/// Both ends meet bad input the same way: a `STATUS` naming the problem, and the link
/// goes on.
#[test]
fn both_ends_report_malformed_input_and_keep_serving() {
    let mut p = Pair::new(Duration::from_millis(5));
    p.open();
    let mut garbage = BytesMut::new();
    Frame::Ping { id: 5, sent_ns: 1 }.encode(&mut garbage);
    garbage.extend_from_slice(&[0x07, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff]);
    let unknown_alias = Frame::Message {
        alias: 4242,
        seq: 1,
        stamp_ns: 0,
        payload: Bytes::from_static(b"{}"),
    }
    .to_bytes();
    for at_hub in [true, false] {
        let now = p.now;
        let side = if at_hub { &mut p.hub } else { &mut p.agent };
        side.session.handle_binary(&garbage.clone().freeze(), now);
        side.session.handle_binary(&unknown_alias, now);
        let mut sent = Vec::new();
        let mut st = Vec::new();
        while let Some(c) = side.session.poll_transmit() {
            let Control::Frame(f) = c else { continue };
            if let Frame::Status { code, text, .. } = &f {
                st.push((*code, text.clone()));
            }
            sent.push(f.to_bytes());
        }
        assert_eq!(st.len(), 2, "{st:?}");
        assert_eq!(st[0].0, status_code::MALFORMED);
        assert!(st[0].1.starts_with("malformed frame"), "{}", st[0].1);
        assert_eq!(st[1].0, status_code::UNKNOWN_ALIAS);
        assert!(st[1].1.contains("4242"), "{}", st[1].1);
        assert_eq!(side.session.stats().malformed, 1);
        assert!(side.session.is_open());
        // The frame before the bad one was read: its ping is answered.
        assert!(sent.iter().any(|b| {
            b[0] == Frame::Pong {
                id: 0,
                echo_ns: 0,
                responder_ns: 0,
            }
            .kind_byte()
        }));
        p.put(!at_hub, sent);
    }
    // The statuses reach the other side, which keeps going too.
    let until = p.now + Duration::from_millis(50);
    p.run_until(until, |_| {});
    assert!(p.hub.statuses_in.iter().any(|s| s.starts_with("malformed")));
    assert!(
        p.agent
            .statuses_in
            .iter()
            .any(|s| s.starts_with("malformed"))
    );
    let now = p.now;
    p.hub.caller.call(&p.hub.calls, "/r1/svc", false, now);
    let until = p.now + Duration::from_millis(100);
    p.run_until(until, |_| {});
    assert!(p.hub.caller.ended.iter().any(|e| e.1 == CallStatus::Ok));
}

#[test]
fn error_reports_to_the_peer_are_capped_and_counted() {
    let mut p = Pair::new(Duration::from_millis(5));
    p.open();
    for i in 0..1000 {
        p.hub.session.status(Level::Error, 9, format!("{i}"));
    }
    let sent = statuses(&mut p.hub.session);
    assert_eq!(sent.len(), MAX_STATUSES);
    assert_eq!(
        p.hub.session.stats().statuses_dropped,
        1000 - MAX_STATUSES as u64
    );
}

#[test]
fn only_bytes_from_the_peer_move_the_deadline() {
    let mut p = Pair::new(Duration::from_millis(5));
    p.open();
    let s = &mut p.hub.session;
    let before = s.poll_timeout().unwrap();
    let t = p.now + Duration::from_millis(500);
    // Everything this side can do, except reading the socket.
    s.handle_timeout(t);
    s.send(Frame::Share { bytes_per_sec: 1 });
    s.status(Level::Info, 0, "x".into());
    s.delivered(1, 1);
    while s.poll_transmit().is_some() {}
    while s.poll_event().is_some() {}
    let dead = t - Duration::from_millis(500) + s.dead_after();
    assert!(s.poll_timeout().unwrap() <= dead, "{before:?}");
    s.handle_timeout(dead);
    assert!(s.is_closed());
}

// --- acknowledgements (issue 38: one ACK per small message was a system call each)

/// An open hub session with alias 7 bound to a topic, everything it had to send taken.
fn hub_with_topic() -> (LinkSession, Instant) {
    let mut p = Pair::new(Duration::from_millis(5));
    p.open();
    let now = p.now;
    let mut s = p.hub.session;
    let advertise = Frame::Advertise {
        alias: 7,
        topic: "/r1/pose".into(),
        schema: Schema::named("std_msgs/msg/String"),
        encoding: Encoding::Json,
        flags: 0,
    };
    s.handle_binary(&advertise.to_bytes(), now);
    while s.poll_transmit().is_some() {}
    while s.poll_event().is_some() {}
    (s, now)
}

fn small_messages(n: u64, size: usize) -> Bytes {
    let mut b = BytesMut::new();
    for seq in 0..n {
        Frame::Message {
            alias: 7,
            seq,
            stamp_ns: 0,
            payload: Bytes::from(vec![b'x'; size]),
        }
        .encode(&mut b);
    }
    b.freeze()
}

/// The ACKs the session sends now, and whether anything else went with them.
fn acks_now(s: &mut LinkSession) -> (Vec<(u32, u64)>, usize) {
    let (mut acks, mut others) = (Vec::new(), 0);
    while s.has_transmit() {
        match s.poll_transmit() {
            Some(Control::Frame(Frame::Ack { frames, bytes })) => acks.push((frames, bytes)),
            Some(_) => others += 1,
            None => break,
        }
    }
    (acks, others)
}

#[test]
fn a_few_small_messages_are_acknowledged_with_the_next_frame_written() {
    let (mut s, t) = hub_with_topic();
    s.handle_binary(&small_messages(1, 64), t);
    assert_eq!(acks_now(&mut s), (vec![], 0), "one small message waits");
    s.handle_binary(&small_messages(2, 64), t + Duration::from_millis(10));
    assert_eq!(acks_now(&mut s), (vec![], 0), "so do three");
    // Any frame written anyway takes the acknowledgement along, ahead of it.
    s.send(Frame::Interest {
        alias: 7,
        wanted: true,
    });
    assert_eq!(
        s.poll_transmit()
            .map(|c| matches!(c, Control::Frame(Frame::Ack { .. }))),
        Some(true)
    );
    let (acks, others) = acks_now(&mut s);
    assert_eq!((acks.len(), others), (0, 1), "then the frame it rode with");
    // A pong to the agent's ping likewise.
    s.handle_binary(&small_messages(1, 64), t + Duration::from_millis(20));
    s.handle_binary(
        &Frame::Ping { id: 3, sent_ns: 1 }.to_bytes(),
        t + Duration::from_millis(21),
    );
    assert_eq!(acks_now(&mut s), (vec![(1, 64)], 1));
}

#[test]
fn a_window_share_of_messages_a_kilobyte_or_a_piece_of_bulk_are_acknowledged_at_once() {
    let (mut s, t) = hub_with_topic();
    s.handle_binary(&small_messages(ACK_EVERY_MESSAGES as u64, 64), t);
    assert_eq!(
        acks_now(&mut s),
        (
            vec![(ACK_EVERY_MESSAGES, 64 * u64::from(ACK_EVERY_MESSAGES))],
            0
        )
    );
    s.handle_binary(&small_messages(1, ACK_EVERY_BYTES as usize), t);
    assert_eq!(acks_now(&mut s), (vec![(1, ACK_EVERY_BYTES)], 0));
    // One short of the count, then the last in another WebSocket message: all at once.
    let short = u64::from(ACK_EVERY_MESSAGES) - 1;
    s.handle_binary(&small_messages(short, 10), t);
    assert_eq!(acks_now(&mut s), (vec![], 0));
    s.handle_binary(&small_messages(1, 10), t);
    assert_eq!(
        acks_now(&mut s),
        (vec![(ACK_EVERY_MESSAGES, 10 * (short + 1))], 0)
    );
    // A chunk of a large message, however small: the agent paces bulk by its ACKs.
    let chunk = Frame::Chunk {
        alias: 7,
        seq: 9,
        stamp_ns: 0,
        total_len: 4096,
        offset: 0,
        data: Bytes::from(vec![0u8; 100]),
    };
    s.handle_binary(&chunk.to_bytes(), t);
    assert_eq!(acks_now(&mut s), (vec![(0, 100)], 0));
}

#[test]
fn a_waiting_acknowledgement_goes_with_a_later_read_or_the_heartbeat() {
    let (mut s, t) = hub_with_topic();
    s.handle_binary(&small_messages(1, 64), t);
    s.handle_binary(&small_messages(1, 64), t + ACK_DELAY / 2);
    assert_eq!(acks_now(&mut s), (vec![], 0));
    // A read once the first has waited ACK_DELAY sends all of them.
    s.handle_binary(&small_messages(1, 64), t + ACK_DELAY);
    assert_eq!(acks_now(&mut s), (vec![(3, 192)], 0));
    // With no read after it, the heartbeat takes it: no timer of its own moves the
    // session's deadline.
    let t2 = t + ACK_DELAY + Duration::from_millis(1);
    let before = s.poll_timeout().unwrap();
    s.handle_binary(&small_messages(1, 64), t2);
    assert_eq!(acks_now(&mut s), (vec![], 0));
    let deadline = s.poll_timeout().unwrap();
    assert!(deadline >= before, "{deadline:?} {before:?}");
    s.handle_timeout(deadline);
    let (acks, _) = acks_now(&mut s);
    assert_eq!(acks, vec![(1, 64)]);
    assert!(s.is_open());
}

// --- between hubs (issue 40: a message never comes back to a hub it has passed)

fn with_via(hubs: &[u64], then: Bytes) -> Bytes {
    let mut b = BytesMut::new();
    Frame::Via {
        hubs: hubs.to_vec(),
    }
    .encode(&mut b);
    b.extend_from_slice(&then);
    b.freeze()
}

fn messages(s: &mut LinkSession) -> Vec<Option<Vec<u64>>> {
    let mut out = Vec::new();
    while let Some(e) = s.poll_event() {
        if let Event::Link(LinkEvent::Message { via, .. }) = e {
            out.push(via.map(|v| v.hubs().to_vec()));
        }
    }
    out
}

#[test]
fn a_message_or_topic_that_passed_this_hub_is_dropped_as_it_arrives() {
    let (mut s, t) = hub_with_topic();
    s.set_local_hub(5);
    // From an agent: no VIA, nothing to check.
    s.handle_binary(&small_messages(1, 8), t);
    assert_eq!(messages(&mut s), vec![None]);
    // From a site hub (7) whose message passed hub 3 first: kept, with its way.
    s.handle_binary(&with_via(&[3, 7], small_messages(1, 8)), t);
    assert_eq!(messages(&mut s), vec![Some(vec![3, 7])]);
    assert_eq!(
        s.link_in()
            .peer_hub
            .load(std::sync::atomic::Ordering::Relaxed),
        7
    );
    // One that passed this hub (5) before: dropped, counted; the VIA holds for what follows
    // in later WebSocket messages too.
    s.handle_binary(&with_via(&[5, 7], small_messages(2, 8)), t);
    s.handle_binary(&small_messages(1, 8), t);
    assert_eq!(messages(&mut s), vec![]);
    assert_eq!(s.link_in().looped, 3);
    // A topic whose publisher is behind this hub is refused the same way.
    let advertise = Frame::Advertise {
        alias: 9,
        topic: "/site5/r/scan".into(),
        schema: Schema::named("std_msgs/msg/String"),
        encoding: Encoding::Json,
        flags: 0,
    };
    s.handle_binary(&advertise.to_bytes(), t);
    assert!(s.link_in().topic(9).is_none());
    assert_eq!(s.link_in().looped_topics, 1);
    // A new way without this hub: messages flow again.
    s.handle_binary(&with_via(&[7], small_messages(1, 8)), t);
    assert_eq!(messages(&mut s), vec![Some(vec![7])]);
    assert!(s.is_open());
}

#[test]
fn a_refusal_from_the_call_table_counts_like_any_other_status() {
    let mut p = Pair::new(Duration::from_millis(5));
    p.open();
    // The call table refuses a service it cannot name; its STATUS goes out with the rest.
    let bad = Frame::ServiceAdvertise {
        alias: 7,
        name: "not a name".into(),
        schema: Schema::named("std_srvs/srv/Trigger"),
        flags: 0,
    };
    p.hub.session.handle_binary(&bad.to_bytes(), p.now);
    let sent = statuses(&mut p.hub.session);
    assert!(
        sent.iter()
            .any(|(code, text)| *code == 400 && text.contains("invalid name")),
        "{sent:?}"
    );
    // Taking it off the queue left the count where it was: the cap still lets a full
    // quota of reports through.
    for i in 0..MAX_STATUSES {
        p.hub.session.status(Level::Error, 9, format!("{i}"));
    }
    assert_eq!(statuses(&mut p.hub.session).len(), MAX_STATUSES);
    assert_eq!(p.hub.session.stats().statuses_dropped, 0);
}
