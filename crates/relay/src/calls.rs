//! Services and actions: who provides what, and every call in flight.
//!
//! [`Calls`] is to calls what the [`Router`](crate::Router) is to topics, shared by every
//! connection of a hub or an agent. A provider (a rosbridge client after
//! `advertise_service`, an agent link on behalf of its robot, the simulator) registers a
//! name; a caller asks the table, which routes the call to the one provider, never
//! broadcasts it, and keeps a pending entry until the call ends.
//!
//! Design choice: participants are [`CallPeer`]s, and the table talks to them by calling
//! their non-blocking `deliver_*` methods after releasing its lock; each peer queues what
//! it gets for its own task (a session's loop, a link's writer). So the table never waits
//! on a socket, and a peer that answers from inside a delivery cannot deadlock it.
//!
//! Every pending entry ends exactly once — answered, timed out, cancelled, or failed
//! because its provider or caller went away — and is removed when it does: nothing
//! outlives a call. Pending calls are bounded per caller and per provider.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

pub use fleetlink_proto::frame::CallStatus;
use fleetlink_proto::{Payload, Schema};
use regex::Regex;
use tokio::sync::Notify;

use crate::names::{ClientId, TopicName};

mod queue;
pub use queue::{ChannelPeer, Closed, PeerReceiver};

/// A call's id in one table (hub- or agent-wide, never reused).
pub type CallId = u64;

/// A service or action someone provides.
#[derive(Debug, Clone, PartialEq)]
pub struct ServiceInfo {
    pub name: TopicName,
    /// `pkg/srv/T` (or `pkg/action/T`) with its definition text when known.
    pub schema: Schema,
    pub action: bool,
    pub provider: ClientId,
}

/// A call as its provider gets it.
#[derive(Debug, Clone)]
pub struct CallRequest {
    pub id: CallId,
    pub service: Arc<ServiceInfo>,
    pub caller: ClientId,
    pub payload: Payload,
    /// When the caller stops waiting; the provider may give up then too.
    pub deadline: Option<Instant>,
    /// For an action goal: the goal's UUID.
    pub goal_id: Option<[u8; 16]>,
    /// Who made the call, when the caller's gate could say ([`CallOptions::on_behalf_of`]).
    pub on_behalf_of: Option<Arc<crate::gate::Caller>>,
}

/// What comes back to a caller.
#[derive(Debug, Clone)]
pub enum CallEvent {
    /// Progress of an action goal.
    Feedback { id: CallId, payload: Payload },
    /// The end of a call: its outcome, and the response (or result) when there is one;
    /// `text` says why when the status is not `Ok`.
    Done {
        id: CallId,
        status: CallStatus,
        payload: Option<Payload>,
        text: String,
    },
}

impl CallEvent {
    pub fn id(&self) -> CallId {
        match self {
            CallEvent::Feedback { id, .. } | CallEvent::Done { id, .. } => *id,
        }
    }
}

/// A service appeared or went away (for peers that watch services).
#[derive(Debug, Clone)]
pub enum ServiceChange {
    Added(Arc<ServiceInfo>),
    Removed(Arc<ServiceInfo>),
}

/// A participant of the call table. Every method must return at once (queue, do not
/// wait): the table calls them from whichever task caused the event.
pub trait CallPeer: Send + Sync {
    /// A call to a service this peer provides.
    fn deliver_call(&self, call: CallRequest);
    /// The caller of `id` gave up (cancel, deadline, or it left): stop working on it.
    fn deliver_cancel(&self, id: CallId);
    /// Progress or the end of a call this peer made.
    fn deliver_event(&self, event: CallEvent);
    /// A service matching one of this peer's watches changed.
    fn service_changed(&self, _change: ServiceChange) {}
}

/// What a [`ChannelPeer`] queues for its task.
#[derive(Debug)]
pub enum PeerMsg {
    Call(CallRequest),
    Cancel(CallId),
    Event(CallEvent),
    Changed(ServiceChange),
}

/// Bounds and defaults of a table.
#[derive(Debug, Clone)]
pub struct CallLimits {
    /// Deadline of a service call whose caller gives none.
    pub default_timeout: Duration,
    /// Deadline of an action goal whose caller gives none (`None`: goals may run as long
    /// as their provider is there).
    pub goal_timeout: Option<Duration>,
    /// Calls one caller may have pending at once.
    pub max_pending_per_caller: usize,
    /// Calls one provider may have pending at once.
    pub max_pending_per_provider: usize,
    /// How long a cancelled goal's provider has to confirm before the caller is told the
    /// goal is cancelled anyway.
    pub cancel_grace: Duration,
}

impl Default for CallLimits {
    fn default() -> Self {
        CallLimits {
            default_timeout: Duration::from_secs(30),
            goal_timeout: None,
            max_pending_per_caller: 256,
            max_pending_per_provider: 1024,
            cancel_grace: Duration::from_secs(5),
        }
    }
}

/// Why a call could not even start.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{text}")]
pub struct CallRefused {
    pub status: CallStatus,
    pub text: String,
}

impl CallRefused {
    fn new(status: CallStatus, text: String) -> CallRefused {
        CallRefused { status, text }
    }
}

/// A call's options.
#[derive(Debug, Clone, Default)]
pub struct CallOptions {
    /// The caller's deadline from now; `None` takes the table's default.
    pub timeout: Option<Duration>,
    /// A goal of an action rather than a service call.
    pub goal: bool,
    /// The goal's UUID when it already has one (a goal arriving over a link keeps the id
    /// its first table gave it); `None` makes a new one.
    pub goal_id: Option<[u8; 16]>,
    /// Who the call is made for ([`crate::gate::Gate::caller`]): a provider that forwards
    /// calls to another hub (the federation) tells it, so it decides on the same identity.
    pub on_behalf_of: Option<Arc<crate::gate::Caller>>,
}

struct Pending {
    caller: ClientId,
    provider: ClientId,
    service: TopicName,
    deadline: Option<Instant>,
    goal: bool,
    /// The caller asked to cancel (a goal waits for its provider's confirmation).
    cancelled: bool,
}

#[derive(Default)]
struct State {
    peers: HashMap<ClientId, Arc<dyn CallPeer>>,
    services: HashMap<TopicName, Arc<ServiceInfo>>,
    pending: HashMap<CallId, Pending>,
    per_caller: HashMap<ClientId, usize>,
    per_provider: HashMap<ClientId, usize>,
    watches: HashMap<ClientId, Vec<Regex>>,
    /// Deadlines of pending calls; stale entries (calls already ended) are skipped.
    deadlines: BinaryHeap<Reverse<(Instant, CallId)>>,
    next_id: CallId,
}

impl State {
    fn remove(&mut self, id: CallId) -> Option<Pending> {
        let p = self.pending.remove(&id)?;
        for (map, who) in [
            (&mut self.per_caller, p.caller),
            (&mut self.per_provider, p.provider),
        ] {
            if let Some(n) = map.get_mut(&who) {
                *n -= 1;
                if *n == 0 {
                    map.remove(&who);
                }
            }
        }
        // Deadlines of ended calls stay in the heap until they come due; rebuild it when
        // they outnumber the live ones, so a burst of fast calls cannot grow it.
        if self.deadlines.len() > 1024 && self.deadlines.len() > 4 * self.pending.len() {
            self.deadlines = self
                .pending
                .iter()
                .filter_map(|(id, p)| p.deadline.map(|d| Reverse((d, *id))))
                .collect();
        }
        Some(p)
    }

    fn peer(&self, id: ClientId) -> Option<Arc<dyn CallPeer>> {
        self.peers.get(&id).cloned()
    }

    /// The peers whose watches match `name`, except `provider` itself.
    fn watchers(&self, name: &TopicName, provider: ClientId) -> Vec<Arc<dyn CallPeer>> {
        self.watches
            .iter()
            .filter(|(c, res)| **c != provider && res.iter().any(|r| r.is_match(name.as_str())))
            .filter_map(|(c, _)| self.peer(*c))
            .collect()
    }
}

/// What to tell peers once the lock is released.
enum Out {
    Cancel(Arc<dyn CallPeer>, CallId),
    Event(Arc<dyn CallPeer>, CallEvent),
    Change(Arc<dyn CallPeer>, ServiceChange),
}

fn send(out: Vec<Out>) {
    for o in out {
        match o {
            Out::Cancel(p, id) => p.deliver_cancel(id),
            Out::Event(p, e) => p.deliver_event(e),
            Out::Change(p, c) => p.service_changed(c),
        }
    }
}

fn done(id: CallId, status: CallStatus, text: String) -> CallEvent {
    CallEvent::Done {
        id,
        status,
        payload: None,
        text,
    }
}

/// The service table and the calls in flight. Shared as `Arc<Calls>`.
pub struct Calls {
    // std Mutex: short critical sections, never held across an await or a delivery.
    state: Mutex<State>,
    limits: CallLimits,
    /// Woken when a call with an earlier deadline than any before is added.
    timer: Notify,
}

impl Default for Calls {
    fn default() -> Self {
        Calls::new(CallLimits::default())
    }
}

impl Calls {
    pub fn new(limits: CallLimits) -> Calls {
        Calls {
            state: Mutex::new(State {
                next_id: 1,
                ..State::default()
            }),
            limits,
            timer: Notify::new(),
        }
    }

    pub fn limits(&self) -> &CallLimits {
        &self.limits
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Registers a participant (before it advertises, calls or watches).
    pub fn attach(&self, client: ClientId, peer: Arc<dyn CallPeer>) {
        self.lock().peers.insert(client, peer);
    }

    /// Removes a participant: its services go away and their pending calls fail at once
    /// (`no provider`); its own pending calls are cancelled at their providers.
    pub fn detach(&self, client: ClientId) {
        let mut out = Vec::new();
        {
            let mut st = self.lock();
            st.peers.remove(&client);
            st.watches.remove(&client);
            let gone: Vec<Arc<ServiceInfo>> = st
                .services
                .values()
                .filter(|s| s.provider == client)
                .cloned()
                .collect();
            for s in gone {
                st.services.remove(&s.name);
                for w in st.watchers(&s.name, client) {
                    out.push(Out::Change(w, ServiceChange::Removed(s.clone())));
                }
            }
            let ids: Vec<CallId> = st
                .pending
                .iter()
                .filter(|(_, p)| p.provider == client || p.caller == client)
                .map(|(id, _)| *id)
                .collect();
            for id in ids {
                let p = st.remove(id).expect("listed above");
                if p.provider == client {
                    if let Some(c) = st.peer(p.caller) {
                        let text =
                            format!("the provider of {} went away before answering", p.service);
                        out.push(Out::Event(c, done(id, CallStatus::NoProvider, text)));
                    }
                } else if let Some(prov) = st.peer(p.provider) {
                    out.push(Out::Cancel(prov, id));
                }
            }
        }
        send(out);
    }

    /// `client` provides `name`. A name already provided by someone else is taken over
    /// (the previous provider's pending calls still end normally): a client that
    /// reconnects before its old connection is noticed dead must not be locked out.
    /// Returns the previous provider, if another client had it.
    pub fn advertise(
        &self,
        client: ClientId,
        name: TopicName,
        schema: Schema,
        action: bool,
    ) -> Option<ClientId> {
        let info = Arc::new(ServiceInfo {
            name: name.clone(),
            schema,
            action,
            provider: client,
        });
        let mut out = Vec::new();
        let previous = {
            let mut st = self.lock();
            let old = st.services.insert(name.clone(), info.clone());
            if let Some(old) = &old {
                if **old == *info {
                    return None;
                }
                for w in st.watchers(&name, old.provider) {
                    out.push(Out::Change(w, ServiceChange::Removed(old.clone())));
                }
            }
            for w in st.watchers(&name, client) {
                out.push(Out::Change(w, ServiceChange::Added(info.clone())));
            }
            old.map(|o| o.provider).filter(|p| *p != client)
        };
        send(out);
        previous
    }

    /// `client` stops providing `name`; calls waiting on it fail with `no provider`.
    /// False if `client` did not provide it.
    pub fn unadvertise(&self, client: ClientId, name: &TopicName) -> bool {
        self.remove_service(client, name, true)
    }

    /// Like [`Calls::unadvertise`], but the calls already sent to `client` stay pending:
    /// a link end withdraws a service this way, because the remote side answers each of
    /// those calls itself (an answer may still be on its way behind the withdrawal).
    pub fn withdraw(&self, client: ClientId, name: &TopicName) -> bool {
        self.remove_service(client, name, false)
    }

    fn remove_service(&self, client: ClientId, name: &TopicName, fail_pending: bool) -> bool {
        let mut out = Vec::new();
        {
            let mut st = self.lock();
            if st.services.get(name).is_none_or(|s| s.provider != client) {
                return false;
            }
            let info = st.services.remove(name).expect("checked above");
            for w in st.watchers(name, client) {
                out.push(Out::Change(w, ServiceChange::Removed(info.clone())));
            }
            let ids: Vec<CallId> = st
                .pending
                .iter()
                .filter(|(_, p)| fail_pending && p.provider == client && p.service == *name)
                .map(|(id, _)| *id)
                .collect();
            for id in ids {
                let p = st.remove(id).expect("listed above");
                if let Some(c) = st.peer(p.caller) {
                    let text = format!("{name} was withdrawn by its provider before answering");
                    out.push(Out::Event(c, done(id, CallStatus::NoProvider, text)));
                }
            }
        }
        send(out);
        true
    }

    /// Starts a call of `name` by `caller`; the outcome comes back to the caller's peer as
    /// a [`CallEvent`] with the returned id.
    pub fn call(
        &self,
        caller: ClientId,
        name: &TopicName,
        payload: Payload,
        opts: CallOptions,
    ) -> Result<CallId, CallRefused> {
        let now = Instant::now();
        let (provider, request) = {
            let mut st = self.lock();
            let Some(info) = st.services.get(name).cloned() else {
                let what = if opts.goal { "action" } else { "service" };
                return Err(CallRefused::new(
                    CallStatus::NoProvider,
                    format!("{what} {name} is not advertised by anyone"),
                ));
            };
            if info.action != opts.goal {
                let text = if info.action {
                    format!("{name} is an action: send it a goal (send_action_goal)")
                } else {
                    format!("{name} is a service, not an action: call it with call_service")
                };
                return Err(CallRefused::new(CallStatus::Failed, text));
            }
            let mine = st.per_caller.get(&caller).copied().unwrap_or(0);
            if mine >= self.limits.max_pending_per_caller {
                return Err(CallRefused::new(
                    CallStatus::Busy,
                    format!(
                        "this client already has {mine} calls pending (the limit per caller); \
                         wait for some to finish"
                    ),
                ));
            }
            let theirs = st.per_provider.get(&info.provider).copied().unwrap_or(0);
            if theirs >= self.limits.max_pending_per_provider {
                return Err(CallRefused::new(
                    CallStatus::Busy,
                    format!(
                        "the provider of {name} already has {theirs} calls pending (the limit \
                         per provider); try again later"
                    ),
                ));
            }
            let Some(provider) = st.peer(info.provider) else {
                return Err(CallRefused::new(
                    CallStatus::NoProvider,
                    format!("the provider of {name} is gone"),
                ));
            };
            let timeout = match (opts.timeout, opts.goal) {
                (Some(t), _) if !t.is_zero() => Some(t),
                (_, false) => Some(self.limits.default_timeout),
                (_, true) => self.limits.goal_timeout,
            };
            let deadline = timeout.and_then(|t| now.checked_add(t));
            let id = st.next_id;
            st.next_id += 1;
            st.pending.insert(
                id,
                Pending {
                    caller,
                    provider: info.provider,
                    service: name.clone(),
                    deadline,
                    goal: opts.goal,
                    cancelled: false,
                },
            );
            *st.per_caller.entry(caller).or_default() += 1;
            *st.per_provider.entry(info.provider).or_default() += 1;
            if let Some(d) = deadline {
                let earliest = st.deadlines.peek().is_none_or(|Reverse((e, _))| d < *e);
                st.deadlines.push(Reverse((d, id)));
                if earliest {
                    self.timer.notify_one();
                }
            }
            let request = CallRequest {
                id,
                service: info,
                caller,
                payload,
                deadline,
                goal_id: opts.goal.then(|| opts.goal_id.unwrap_or_else(new_goal_id)),
                on_behalf_of: opts.on_behalf_of,
            };
            (provider, request)
        };
        let id = request.id;
        provider.deliver_call(request);
        Ok(id)
    }

    /// The provider's answer to `id`. False if `id` is not a call pending at `provider`
    /// (answered already, timed out, or never made).
    pub fn respond(
        &self,
        provider: ClientId,
        id: CallId,
        status: CallStatus,
        payload: Option<Payload>,
        text: String,
    ) -> bool {
        let caller = {
            let mut st = self.lock();
            if st.pending.get(&id).is_none_or(|p| p.provider != provider) {
                return false;
            }
            let p = st.remove(id).expect("checked above");
            st.peer(p.caller)
        };
        if let Some(c) = caller {
            c.deliver_event(CallEvent::Done {
                id,
                status,
                payload,
                text,
            });
        }
        true
    }

    /// Progress of goal `id` from its provider. False if it is not a goal pending there.
    pub fn feedback(&self, provider: ClientId, id: CallId, payload: Payload) -> bool {
        let caller = {
            let st = self.lock();
            match st.pending.get(&id) {
                Some(p) if p.provider == provider && p.goal => st.peer(p.caller),
                _ => return false,
            }
        };
        if let Some(c) = caller {
            c.deliver_event(CallEvent::Feedback { id, payload });
        }
        true
    }

    /// The caller cancels `id`. A service call ends at once (`cancelled`); a goal's
    /// provider is asked to stop and answers with the goal's final status, or the caller
    /// hears `cancelled` after the grace period. False if `id` is not the caller's.
    pub fn cancel(&self, caller: ClientId, id: CallId) -> bool {
        let mut out = Vec::new();
        {
            let mut st = self.lock();
            let grace = Instant::now() + self.limits.cancel_grace;
            let Some(p) = st.pending.get_mut(&id).filter(|p| p.caller == caller) else {
                return false;
            };
            if p.cancelled {
                return true;
            }
            p.cancelled = true;
            let (goal, provider) = (p.goal, p.provider);
            if goal {
                if p.deadline.is_none_or(|d| grace < d) {
                    p.deadline = Some(grace);
                    st.deadlines.push(Reverse((grace, id)));
                    self.timer.notify_one();
                }
            } else {
                st.remove(id);
                if let Some(c) = st.peer(caller) {
                    let text = "cancelled by the caller".to_owned();
                    out.push(Out::Event(c, done(id, CallStatus::Cancelled, text)));
                }
            }
            if let Some(prov) = st.peer(provider) {
                out.push(Out::Cancel(prov, id));
            }
        }
        send(out);
        true
    }

    /// Ends every call whose deadline has passed: the caller hears `timeout` (or
    /// `cancelled` for a cancelled goal whose provider did not confirm in time), the
    /// provider is told to stop. Returns when the next deadline falls.
    pub fn expire(&self, now: Instant) -> Option<Instant> {
        let mut out = Vec::new();
        let next = {
            let mut st = self.lock();
            while let Some(Reverse((at, id))) = st.deadlines.peek().copied() {
                if at > now {
                    break;
                }
                st.deadlines.pop();
                // Skip stale entries: the call ended, or its deadline moved.
                if st.pending.get(&id).is_none_or(|p| p.deadline != Some(at)) {
                    continue;
                }
                let p = st.remove(id).expect("checked above");
                let (status, text) = if p.cancelled {
                    (
                        CallStatus::Cancelled,
                        format!(
                            "cancelled; the provider of {} did not confirm within {:?}",
                            p.service, self.limits.cancel_grace
                        ),
                    )
                } else {
                    (
                        CallStatus::Timeout,
                        format!("{} did not answer before the call's deadline", p.service),
                    )
                };
                if let Some(c) = st.peer(p.caller) {
                    out.push(Out::Event(c, done(id, status, text)));
                }
                if let Some(prov) = st.peer(p.provider) {
                    out.push(Out::Cancel(prov, id));
                }
            }
            st.deadlines.peek().map(|Reverse((at, _))| *at)
        };
        send(out);
        next
    }

    /// Runs the deadlines until `shutdown`. One task per table.
    pub async fn run_deadlines(self: Arc<Self>, shutdown: tokio_util::sync::CancellationToken) {
        loop {
            let next = self.expire(Instant::now());
            let sleep = async {
                match next {
                    Some(at) => tokio::time::sleep_until(tokio::time::Instant::from_std(at)).await,
                    None => std::future::pending().await,
                }
            };
            tokio::select! {
                _ = sleep => {}
                _ = self.timer.notified() => {}
                _ = shutdown.cancelled() => return,
            }
        }
    }

    /// `client` hears about services whose names match `pattern` (not its own): at once
    /// for those that exist, then as they come and go.
    pub fn watch(&self, client: ClientId, pattern: Regex) {
        let out: Vec<Out> = {
            let mut st = self.lock();
            let Some(peer) = st.peer(client) else {
                return;
            };
            let mut list: Vec<&Arc<ServiceInfo>> = st
                .services
                .values()
                .filter(|s| s.provider != client && pattern.is_match(s.name.as_str()))
                .collect();
            list.sort_by(|a, b| a.name.cmp(&b.name));
            let out = list
                .into_iter()
                .map(|s| Out::Change(peer.clone(), ServiceChange::Added(s.clone())))
                .collect();
            st.watches.entry(client).or_default().push(pattern);
            out
        };
        send(out);
    }

    /// `client` no longer hears about services (until it watches again).
    pub fn unwatch(&self, client: ClientId) {
        self.lock().watches.remove(&client);
    }

    /// Every service, sorted by name.
    pub fn services(&self) -> Vec<Arc<ServiceInfo>> {
        let mut v: Vec<_> = self.lock().services.values().cloned().collect();
        v.sort_by(|a, b| a.name.cmp(&b.name));
        v
    }

    pub fn service(&self, name: &TopicName) -> Option<Arc<ServiceInfo>> {
        self.lock().services.get(name).cloned()
    }

    /// Calls in flight now (for metrics, and to prove nothing is left behind).
    pub fn pending(&self) -> usize {
        self.lock().pending.len()
    }

    /// Size of the bookkeeping that must return to zero when no call is in flight:
    /// pending entries and per-client counters.
    pub fn bookkeeping(&self) -> usize {
        let st = self.lock();
        st.pending.len() + st.per_caller.len() + st.per_provider.len()
    }

    /// Deadlines queued, ended calls' included until they come due or are compacted away.
    pub fn deadline_entries(&self) -> usize {
        self.lock().deadlines.len()
    }
}

/// A random UUID (version 4) for an action goal.
fn new_goal_id() -> [u8; 16] {
    let mut b = [0u8; 16];
    if getrandom::fill(&mut b).is_err() {
        // No entropy source: fall back to a per-process counter mixed with the clock,
        // still unique within this process.
        use std::sync::atomic::{AtomicU64, Ordering};
        static N: AtomicU64 = AtomicU64::new(0);
        let n = N.fetch_add(1, Ordering::Relaxed);
        b[..8].copy_from_slice(&crate::unix_nanos().to_le_bytes());
        b[8..].copy_from_slice(&n.to_le_bytes());
    }
    b[6] = (b[6] & 0x0f) | 0x40;
    b[8] = (b[8] & 0x3f) | 0x80;
    b
}

/// A goal id in the usual UUID text form.
pub fn goal_id_text(id: &[u8; 16]) -> String {
    let h: String = id.iter().map(|b| format!("{b:02x}")).collect();
    format!(
        "{}-{}-{}-{}-{}",
        &h[0..8],
        &h[8..12],
        &h[12..16],
        &h[16..20],
        &h[20..32]
    )
}

#[cfg(test)]
#[path = "calls_tests.rs"]
mod tests;
