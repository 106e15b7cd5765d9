//! Calls across a `fleetlink.v1` link, the same code on both ends.
//!
//! A link end is one participant of its side's [`Calls`] table. Toward the table it
//! provides the services the remote side advertised (and forwards their calls over the
//! link) and calls, on the remote's behalf, the services this side advertised to it.
//! Toward the link it speaks the call frames (`SERVICE_ADVERTISE` ... `CALL_CHUNK`,
//! docs/protocol.md). Call ids on the link are chosen by the side that sends the call:
//! a forwarded call goes out under its id in this side's table, which is unique here.
//!
//! What is offered to the remote follows a watch on the table (the agent's uplink offers
//! every local service; the hub offers what the robot asked for with
//! `SUBSCRIBE_SERVICES` and may call), filtered by a [`LinkPolicy`].

use std::collections::{HashMap, VecDeque};
use std::sync::Arc;
use std::time::{Duration, Instant};

use bytes::Bytes;
use fleetlink_proto::frame::{
    CallStatus, DEFAULT_CHUNK_SIZE, Frame, FrameKind, Level, SERVICE_ACTION, split_call_body,
};
use fleetlink_proto::reassembly::CallReassembler;
use fleetlink_proto::{Encoding, Payload};

use crate::calls::{CallEvent, CallId, CallOptions, CallRequest, Calls, PeerMsg, ServiceChange};
use crate::gate::{Gate, Op};
use crate::link::Control;
use crate::names::{ClientId, TopicName};

/// Largest request or response reassembled from `CALL_CHUNK`s.
pub const MAX_CALL_BODY: usize = 64 << 20;
/// Largest total of partially received call bodies on one link.
pub const MAX_CALL_REASSEMBLY: usize = 128 << 20;

/// How names map between this side and the remote.
pub trait LinkNames: Send + Sync {
    /// The name a service of this side has on the link; `None` keeps it off the link.
    fn remote_name(&self, local: &TopicName) -> Option<String>;
    /// The name on this side of a service the remote advertised.
    fn local_name(&self, remote: &str) -> Option<TopicName>;
}

/// The same names on both sides (the hub's end of an agent link).
pub struct SameNames;

impl LinkNames for SameNames {
    fn remote_name(&self, local: &TopicName) -> Option<String> {
        Some(local.to_string())
    }
    fn local_name(&self, remote: &str) -> Option<TopicName> {
        TopicName::parse(remote).ok()
    }
}

/// Whether `f` is one of the call frames this module handles.
pub fn is_call_frame(f: &Frame) -> bool {
    matches!(
        f,
        Frame::ServiceAdvertise { .. }
            | Frame::ServiceUnadvertise { .. }
            | Frame::Call { .. }
            | Frame::Goal { .. }
            | Frame::Reply { .. }
            | Frame::Feedback { .. }
            | Frame::Cancel { .. }
            | Frame::CallChunk { .. }
    )
}

/// One link end's call state.
pub struct LinkCalls {
    calls: Arc<Calls>,
    me: ClientId,
    names: Box<dyn LinkNames>,
    /// Services the remote advertised: its alias → our name.
    remote: HashMap<u32, TopicName>,
    remote_by_name: HashMap<TopicName, u32>,
    /// Services we advertised to the remote: alias by name, and the provider behind each.
    ours_by_name: HashMap<TopicName, u32>,
    ours: HashMap<u32, (TopicName, ClientId, bool)>,
    next_alias: u32,
    /// Calls the remote made here: our table's id → (its call id, service, goal, size).
    served: HashMap<CallId, (u64, TopicName, bool, usize)>,
    served_by_remote: HashMap<u64, CallId>,
    /// Calls forwarded to the remote, by their id (ours, and theirs on the link).
    forwarded: HashMap<CallId, bool>,
    reassembly: CallReassembler,
    /// Why the link was lost, once it was ([`LinkCalls::close`]).
    lost: Option<String>,
}

fn status(code: u32, text: String) -> Control {
    Control::Frame(Frame::Status {
        level: Level::Error,
        code,
        alias: 0,
        text,
    })
}

/// Frames for a call body: small ones whole, large ones as `CALL_CHUNK`s first, sent
/// by the link writer one per round between other traffic.
fn body_frames(
    call_id: u64,
    kind: FrameKind,
    payload: &Bytes,
    head: impl FnOnce(Bytes) -> Frame,
) -> Control {
    if payload.len() <= DEFAULT_CHUNK_SIZE {
        return Control::Frame(head(payload.clone()));
    }
    let (chunks, last) = split_call_body(call_id, kind, payload, DEFAULT_CHUNK_SIZE);
    let mut frames: VecDeque<Frame> = chunks.into_iter().collect();
    frames.push_back(head(last));
    Control::Sequence(frames)
}

fn remaining_ms(deadline: Option<Instant>) -> u64 {
    match deadline {
        None => 0,
        Some(d) => (d.saturating_duration_since(Instant::now()).as_millis() as u64).max(1),
    }
}

/// What a REPLY's body is: the response for outcomes that carry one, else error text.
fn carries_result(status: CallStatus) -> bool {
    matches!(
        status,
        CallStatus::Ok | CallStatus::Cancelled | CallStatus::Aborted
    )
}

impl LinkCalls {
    pub fn new(calls: Arc<Calls>, me: ClientId, names: Box<dyn LinkNames>) -> LinkCalls {
        LinkCalls {
            calls,
            me,
            names,
            remote: HashMap::new(),
            remote_by_name: HashMap::new(),
            ours_by_name: HashMap::new(),
            ours: HashMap::new(),
            next_alias: 1,
            served: HashMap::new(),
            served_by_remote: HashMap::new(),
            forwarded: HashMap::new(),
            reassembly: CallReassembler::new(MAX_CALL_BODY, MAX_CALL_REASSEMBLY),
            lost: None,
        }
    }

    /// Something the table queued for this link end; frames to send go to `out`.
    /// `gate` decides which services the remote may see (those it may call) and records
    /// how the remote's own calls ended.
    pub fn on_peer(&mut self, msg: PeerMsg, gate: &mut dyn Gate, out: &mut Vec<Control>) {
        match msg {
            PeerMsg::Changed(ServiceChange::Added(info)) => {
                let op = if info.action {
                    Op::SendActionGoal
                } else {
                    Op::CallService
                };
                let Some(remote_name) = self.names.remote_name(&info.name) else {
                    return;
                };
                if !gate.allows(info.name.as_str(), op) {
                    return;
                }
                let alias = match self.ours_by_name.get(&info.name) {
                    Some(a) => *a,
                    None => {
                        let a = self.next_alias;
                        self.next_alias += 1;
                        a
                    }
                };
                self.ours_by_name.insert(info.name.clone(), alias);
                self.ours
                    .insert(alias, (info.name.clone(), info.provider, info.action));
                out.push(Control::Frame(Frame::ServiceAdvertise {
                    alias,
                    name: remote_name,
                    schema: info.schema.clone(),
                    flags: if info.action { SERVICE_ACTION } else { 0 },
                }));
            }
            PeerMsg::Changed(ServiceChange::Removed(info)) => {
                let Some(alias) = self.ours_by_name.get(&info.name).copied() else {
                    return;
                };
                // A newer provider may have taken the name over already.
                if self.ours.get(&alias).is_some_and(|o| o.1 == info.provider) {
                    self.ours_by_name.remove(&info.name);
                    self.ours.remove(&alias);
                    out.push(Control::Frame(Frame::ServiceUnadvertise { alias }));
                }
            }
            PeerMsg::Call(req) => self.forward(req, out),
            PeerMsg::Cancel(id) => {
                // A service call ends here and now; a goal ends when the remote answers.
                if let Some(goal) = self.forwarded.get(&id).copied() {
                    if !goal {
                        self.forwarded.remove(&id);
                    }
                    out.push(Control::Frame(Frame::Cancel { call_id: id }));
                }
            }
            PeerMsg::Event(ev) => self.answer_remote(ev, gate, out),
        }
    }

    /// Sends a call of the table to the remote provider of its service.
    fn forward(&mut self, req: CallRequest, out: &mut Vec<Control>) {
        if let Some(why) = &self.lost {
            self.calls
                .respond(self.me, req.id, CallStatus::Aborted, None, why.clone());
            return;
        }
        let Some(alias) = self.remote_by_name.get(&req.service.name).copied() else {
            let text = format!("{} is no longer offered on this link", req.service.name);
            self.calls
                .respond(self.me, req.id, CallStatus::NoProvider, None, text);
            return;
        };
        let deadline_ms = remaining_ms(req.deadline);
        let (id, encoding) = (req.id, req.payload.encoding);
        self.forwarded.insert(id, req.goal_id.is_some());
        let frame = match req.goal_id {
            Some(goal_id) => body_frames(id, FrameKind::Goal, &req.payload.bytes, |payload| {
                Frame::Goal {
                    call_id: id,
                    alias,
                    deadline_ms,
                    goal_id,
                    encoding,
                    payload,
                }
            }),
            None => body_frames(id, FrameKind::Call, &req.payload.bytes, |payload| {
                Frame::Call {
                    call_id: id,
                    alias,
                    deadline_ms,
                    encoding,
                    payload,
                }
            }),
        };
        out.push(frame);
    }

    /// Progress or the end of a call the remote made through this link end.
    fn answer_remote(&mut self, ev: CallEvent, gate: &mut dyn Gate, out: &mut Vec<Control>) {
        match ev {
            CallEvent::Feedback { id, payload } => {
                if let Some((r, ..)) = self.served.get(&id) {
                    let r = *r;
                    let enc = payload.encoding;
                    out.push(body_frames(r, FrameKind::Feedback, &payload.bytes, |p| {
                        Frame::Feedback {
                            call_id: r,
                            encoding: enc,
                            payload: p,
                        }
                    }));
                }
            }
            CallEvent::Done {
                id,
                status,
                payload,
                text,
            } => {
                let Some((r, name, goal, size)) = self.served.remove(&id) else {
                    return;
                };
                self.served_by_remote.remove(&r);
                let op = if goal {
                    Op::SendActionGoal
                } else {
                    Op::CallService
                };
                gate.finished(name.as_str(), op, size, &outcome_text(status, &text));
                let (encoding, body) = match (carries_result(status), payload) {
                    (true, Some(p)) => (p.encoding, p.bytes),
                    (true, None) => (Encoding::Json, Bytes::new()),
                    (false, _) => (Encoding::Json, Bytes::from(text.into_bytes())),
                };
                out.push(body_frames(r, FrameKind::Reply, &body, |payload| {
                    Frame::Reply {
                        call_id: r,
                        status,
                        encoding,
                        payload,
                    }
                }));
            }
        }
    }

    /// A frame from the remote. Returns false for frames that are not about calls.
    pub fn on_frame(&mut self, frame: Frame, gate: &mut dyn Gate, out: &mut Vec<Control>) -> bool {
        match frame {
            Frame::ServiceAdvertise {
                alias,
                name,
                schema,
                flags,
            } => {
                let action = flags & SERVICE_ACTION != 0;
                let Some(local) = self.names.local_name(&name) else {
                    out.push(status(
                        400,
                        format!("advertise service: invalid name {name:?}"),
                    ));
                    return true;
                };
                let op = if action {
                    Op::AdvertiseAction
                } else {
                    Op::AdvertiseService
                };
                if !gate.allows(local.as_str(), op) {
                    let what = if action { "action" } else { "service" };
                    out.push(status(
                        403,
                        format!(
                            "advertise {what} {local}: not allowed for {}",
                            gate.principal()
                        ),
                    ));
                    return true;
                }
                gate.done(local.as_str(), op, 0);
                if let Some(old) = self.remote.insert(alias, local.clone())
                    && old != local
                {
                    self.remote_by_name.remove(&old);
                    self.calls.withdraw(self.me, &old);
                }
                self.remote_by_name.insert(local.clone(), alias);
                if let Some(prev) = self.calls.advertise(self.me, local.clone(), schema, action) {
                    tracing::info!("{local} is now provided over this link (was client {prev})");
                }
            }
            Frame::ServiceUnadvertise { alias } => {
                if let Some(name) = self.remote.remove(&alias) {
                    self.remote_by_name.remove(&name);
                    self.calls.withdraw(self.me, &name);
                }
            }
            Frame::Call {
                call_id,
                alias,
                deadline_ms,
                encoding,
                payload,
            } => self.incoming_call(
                call_id,
                alias,
                deadline_ms,
                None,
                encoding,
                payload,
                gate,
                out,
            ),
            Frame::Goal {
                call_id,
                alias,
                deadline_ms,
                goal_id,
                encoding,
                payload,
            } => self.incoming_call(
                call_id,
                alias,
                deadline_ms,
                Some(goal_id),
                encoding,
                payload,
                gate,
                out,
            ),
            Frame::Reply {
                call_id,
                status: st,
                encoding,
                payload,
            } => {
                let Some(body) = self.finish(call_id, FrameKind::Reply, payload, out) else {
                    return true;
                };
                if self.forwarded.remove(&call_id).is_none() {
                    // Answered after its deadline or its caller left: nothing waits for it.
                    return true;
                }
                let (p, text) = if carries_result(st) {
                    let p = (!body.is_empty()).then(|| Payload::new(encoding, body));
                    (p, String::new())
                } else {
                    (None, String::from_utf8_lossy(&body).into_owned())
                };
                self.calls.respond(self.me, call_id, st, p, text);
            }
            Frame::Feedback {
                call_id,
                encoding,
                payload,
            } => {
                let Some(body) = self.finish(call_id, FrameKind::Feedback, payload, out) else {
                    return true;
                };
                if self.forwarded.contains_key(&call_id) {
                    self.calls
                        .feedback(self.me, call_id, Payload::new(encoding, body));
                }
            }
            Frame::Cancel { call_id } => {
                if let Some(id) = self.served_by_remote.get(&call_id) {
                    self.calls.cancel(self.me, *id);
                }
            }
            Frame::CallChunk {
                call_id,
                kind,
                total_len,
                offset,
                data,
            } => {
                if let Err(e) = self
                    .reassembly
                    .push(call_id, kind, total_len, offset, &data)
                {
                    out.push(status(413, format!("call {call_id}: {e}")));
                }
            }
            _ => return false,
        }
        true
    }

    /// The whole body of a call frame whose earlier pieces came as `CALL_CHUNK`s.
    fn finish(
        &mut self,
        call_id: u64,
        kind: FrameKind,
        last: Bytes,
        out: &mut Vec<Control>,
    ) -> Option<Bytes> {
        match self.reassembly.finish(call_id, kind as u8, last) {
            Ok(b) => Some(b),
            Err(e) => {
                out.push(status(413, format!("call {call_id}: {e}")));
                None
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn incoming_call(
        &mut self,
        r: u64,
        alias: u32,
        deadline_ms: u64,
        goal_id: Option<[u8; 16]>,
        encoding: Encoding,
        payload: Bytes,
        gate: &mut dyn Gate,
        out: &mut Vec<Control>,
    ) {
        let goal = goal_id.is_some();
        let kind = if goal {
            FrameKind::Goal
        } else {
            FrameKind::Call
        };
        let Some(body) = self.finish(r, kind, payload, out) else {
            return;
        };
        let refuse = |status: CallStatus, text: String| {
            Control::Frame(Frame::Reply {
                call_id: r,
                status,
                encoding: Encoding::Json,
                payload: Bytes::from(text.into_bytes()),
            })
        };
        if self.served_by_remote.contains_key(&r) {
            out.push(refuse(
                CallStatus::Failed,
                format!("call id {r} is already in use on this link"),
            ));
            return;
        }
        let Some((name, _, action)) = self.ours.get(&alias).cloned() else {
            out.push(refuse(
                CallStatus::NoProvider,
                format!("no service is advertised under alias {alias} on this link"),
            ));
            return;
        };
        let op = if goal {
            Op::SendActionGoal
        } else {
            Op::CallService
        };
        if !gate.allows(name.as_str(), op) {
            let text = format!("{name}: not allowed for {}", gate.principal());
            out.push(refuse(CallStatus::Forbidden, text));
            return;
        }
        if action != goal {
            let text = format!("{name}: a goal must go to an action and a call to a service");
            out.push(refuse(CallStatus::Failed, text));
            return;
        }
        let size = body.len();
        let opts = CallOptions {
            timeout: (deadline_ms > 0).then(|| Duration::from_millis(deadline_ms)),
            goal,
            goal_id,
            on_behalf_of: gate.caller().map(std::sync::Arc::new),
        };
        match self
            .calls
            .call(self.me, &name, Payload::new(encoding, body), opts)
        {
            Ok(id) => {
                self.served.insert(id, (r, name, goal, size));
                self.served_by_remote.insert(r, id);
            }
            Err(e) => {
                gate.finished(name.as_str(), op, size, &outcome_text(e.status, &e.text));
                out.push(refuse(e.status, e.text));
            }
        }
    }

    /// The link is gone, for the reason `why` ("robot link lost: ..."): the calls
    /// forwarded to the remote end at once with that text (`aborted`: they may or may not
    /// have run there), the remote's services are withdrawn here, and the calls the
    /// remote made are cancelled. A call the table hands this link end afterwards (it was
    /// queued before the withdrawal) fails the same way.
    pub fn close(&mut self, why: &str) {
        for (id, _) in self.forwarded.drain() {
            self.calls
                .respond(self.me, id, CallStatus::Aborted, None, why.to_owned());
        }
        for (_, name) in self.remote.drain() {
            self.calls.unadvertise(self.me, &name);
        }
        self.remote_by_name.clear();
        for (id, _) in self.served.drain() {
            self.calls.cancel(self.me, id);
        }
        self.served_by_remote.clear();
        self.lost = Some(why.to_owned());
    }

    /// Calls and services in flight on this link end (for tests: all zero when idle).
    pub fn in_flight(&self) -> (usize, usize) {
        (self.served.len(), self.forwarded.len())
    }
}

/// How a call ended, for the audit log.
pub fn outcome_text(status: CallStatus, text: &str) -> String {
    if text.is_empty() {
        status.as_str().to_owned()
    } else {
        format!("{}: {text}", status.as_str())
    }
}
