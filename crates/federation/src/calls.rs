//! Service calls and action goals between hubs, as Zenoh queries.
//!
//! The federation is a peer of this hub's call table ([`ChannelPeer`]):
//!
//! - as a **provider** of every remote service (advertised by [`crate::topics`]), it
//!   gets calls made here and sends each as a query to `call/<hub>/<service>` of the hub
//!   providing it (payload: the request; attachment: [`CallHeader`]), with the call's
//!   deadline as the query's timeout. The other hub's replies are the goal's feedback and,
//!   last, the outcome ([`ReplyHeader`]). When the caller here gives up, a cancel goes to
//!   that hub (`cancel/<hub>`).
//! - as a **caller**, it makes the calls other hubs send here on this table, answering
//!   each query as the provider's feedback and answer come back, and it offers this
//!   hub's own services and actions (those it hears of through a watch on the table) as
//!   liveliness tokens.
//!
//! Also here, because it is a queryable of the same kind: `schema/<hub>/<topic>`, the
//! full definition of a topic this hub offers, for hubs that do not know the type.

use std::collections::HashMap;
use std::sync::atomic::Ordering::Relaxed;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use fleetlink_hub::security::HubGate;
use fleetlink_proto::frame::CallStatus;
use fleetlink_proto::{Encoding, Payload};
use fleetlink_relay::calls::{
    CallEvent, CallId, CallOptions, CallRequest, ChannelPeer, PeerMsg, PeerReceiver, ServiceChange,
};
use fleetlink_relay::gate::{Caller, Gate, Op};
use fleetlink_relay::{Router, TopicName};
use serde_json::{Value, json};
use tokio::sync::mpsc;
use tokio_util::sync::CancellationToken;
use zenoh::Session;
use zenoh::liveliness::LivelinessToken;
use zenoh::query::{ConsolidationMode, Query, Queryable};

use crate::keys::{self, Offer};
use crate::topics::Providers;
use crate::{FederationError, Shared, zerr};

/// How long a goal without a deadline may run across hubs (Zenoh queries need one).
const GOAL_QUERY_LIMIT: Duration = Duration::from_secs(24 * 3600);
/// Beyond the caller's deadline, how long the query waits for the far hub's own timeout
/// answer (which says why better than silence).
const DEADLINE_SLACK: Duration = Duration::from_secs(2);
/// Calls and cancels from other hubs waiting for the bridge's loop. Zenoh's callbacks
/// cannot wait for room: a call that finds the queue full is answered `Busy` at once (its
/// caller may try again), a cancel is dropped (the call's own deadline still ends it).
const INPUT_QUEUE: usize = 4096;

/// A call's attachment: who calls and how.
#[derive(Debug, Clone, PartialEq)]
pub struct CallHeader {
    /// The calling hub and its call id, for a later cancel.
    pub from: String,
    pub id: CallId,
    pub encoding: Encoding,
    pub goal: bool,
    pub goal_id: Option<[u8; 16]>,
    pub timeout_ms: Option<u64>,
    /// Who made the call at the calling hub, as that hub's gate knew them; `None`: the
    /// hub itself. The robot's hub decides the call on it.
    pub caller: Option<Caller>,
}

fn caller_json(c: &Caller) -> Value {
    match c {
        Caller::Robot { name } => json!({ "robot": name }),
        Caller::User { name, groups } => json!({ "user": name, "groups": groups }),
        Caller::Anonymous => json!({ "anonymous": true }),
    }
}

fn caller_of(v: &Value) -> Result<Caller, String> {
    let text = |k: &str| v.get(k).and_then(Value::as_str).map(str::to_owned);
    if let Some(name) = text("robot") {
        return Ok(Caller::Robot { name });
    }
    if let Some(name) = text("user") {
        let groups = match v.get("groups") {
            None => Vec::new(),
            Some(Value::Array(a)) => a
                .iter()
                .map(|g| g.as_str().map(str::to_owned))
                .collect::<Option<Vec<_>>>()
                .ok_or("call header: caller groups must be strings")?,
            Some(_) => return Err("call header: caller groups must be a list".into()),
        };
        return Ok(Caller::User { name, groups });
    }
    if v.get("anonymous").and_then(Value::as_bool) == Some(true) {
        return Ok(Caller::Anonymous);
    }
    Err("call header: caller is not a robot, user or anonymous".into())
}

impl CallHeader {
    pub fn encode(&self) -> Vec<u8> {
        json!({
            "from": self.from,
            "id": self.id,
            "enc": self.encoding as u8,
            "goal": self.goal,
            "goal_id": self.goal_id.map(|g| g.iter().map(|b| format!("{b:02x}")).collect::<String>()),
            "timeout_ms": self.timeout_ms,
            "caller": self.caller.as_ref().map(caller_json),
        })
        .to_string()
        .into_bytes()
    }

    pub fn decode(b: &[u8]) -> Result<CallHeader, String> {
        let v: Value = serde_json::from_slice(b).map_err(|e| format!("call header: {e}"))?;
        let goal_id = match v.get("goal_id").and_then(Value::as_str) {
            Some(h) if h.len() == 32 => {
                let mut id = [0u8; 16];
                for (i, byte) in id.iter_mut().enumerate() {
                    *byte = u8::from_str_radix(&h[2 * i..2 * i + 2], 16)
                        .map_err(|_| "call header: goal_id is not hex")?;
                }
                Some(id)
            }
            Some(_) => return Err("call header: goal_id must be 32 hex digits".into()),
            None => None,
        };
        Ok(CallHeader {
            from: v
                .get("from")
                .and_then(Value::as_str)
                .ok_or("call header: no from")?
                .to_owned(),
            id: v
                .get("id")
                .and_then(Value::as_u64)
                .ok_or("call header: no id")?,
            encoding: v
                .get("enc")
                .and_then(Value::as_u64)
                .and_then(|e| Encoding::from_u8(e as u8))
                .ok_or("call header: no known encoding")?,
            goal: v.get("goal").and_then(Value::as_bool).unwrap_or(false),
            goal_id,
            timeout_ms: v.get("timeout_ms").and_then(Value::as_u64),
            caller: match v.get("caller") {
                None | Some(Value::Null) => None,
                Some(c) => Some(caller_of(c)?),
            },
        })
    }
}

/// A reply's attachment: feedback, or the outcome.
#[derive(Debug, Clone, PartialEq)]
pub enum ReplyHeader {
    Feedback {
        encoding: Encoding,
    },
    Done {
        status: CallStatus,
        text: String,
        /// The encoding of the response, when there is one.
        encoding: Option<Encoding>,
    },
}

impl ReplyHeader {
    pub fn encode(&self) -> Vec<u8> {
        match self {
            ReplyHeader::Feedback { encoding } => {
                json!({ "kind": "feedback", "enc": *encoding as u8 })
            }
            ReplyHeader::Done {
                status,
                text,
                encoding,
            } => json!({
                "kind": "done",
                "status": *status as u8,
                "text": text,
                "enc": encoding.map(|e| e as u8),
            }),
        }
        .to_string()
        .into_bytes()
    }

    pub fn decode(b: &[u8]) -> Result<ReplyHeader, String> {
        let v: Value = serde_json::from_slice(b).map_err(|e| format!("reply header: {e}"))?;
        let enc = v
            .get("enc")
            .and_then(Value::as_u64)
            .and_then(|e| Encoding::from_u8(e as u8));
        match v.get("kind").and_then(Value::as_str) {
            Some("feedback") => Ok(ReplyHeader::Feedback {
                encoding: enc.ok_or("reply header: feedback without a known encoding")?,
            }),
            Some("done") => Ok(ReplyHeader::Done {
                status: CallStatus::from_u8(
                    v.get("status").and_then(Value::as_u64).unwrap_or(1) as u8
                ),
                text: v
                    .get("text")
                    .and_then(Value::as_str)
                    .unwrap_or("")
                    .to_owned(),
                encoding: enc,
            }),
            other => Err(format!("reply header: unknown kind {other:?}")),
        }
    }
}

/// A call another hub made here, waiting for this hub's provider.
struct Incoming {
    query: Query,
    from: (String, CallId),
    /// The gate that let it through, for its audit record when it ends.
    gate: HubGate,
    name: TopicName,
    op: Op,
    size: usize,
}

enum Input {
    Query(Query),
    Cancel { from: String, id: CallId },
}

pub struct CallBridge {
    session: Session,
    router: Arc<Router>,
    shared: Arc<Shared>,
    providers: Providers,
    receiver: PeerReceiver,
    /// Kept so the table can reach the federation (it holds the peer too).
    _peer: Arc<ChannelPeer>,
    /// Calls and cancels from other hubs, bounded ([`INPUT_QUEUE`]): a call that finds
    /// it full is answered `Busy`, a cancel is dropped.
    inputs: mpsc::Receiver<Input>,
    _queryables: Vec<Queryable<()>>,
    _cancels: zenoh::pubsub::Subscriber<()>,
    /// Calls made here by other hubs, by this table's id: one per call pending on the
    /// table with the federation as its caller, so bounded by the table's limit of
    /// pending calls per caller (past it a call is answered `Busy`). Each goes when the
    /// table ends its call, which it does for every call (answer, deadline, cancel).
    incoming: HashMap<CallId, Incoming>,
    /// The same calls by the calling hub's id, for its cancels (never more than above).
    incoming_ids: HashMap<(String, CallId), CallId>,
    /// Calls this hub sent elsewhere: the hub each went to, kept while its Zenoh query
    /// is open. The table's limit of pending calls per provider bounds the calls in
    /// flight; a query outlives its call here by at most [`DEADLINE_SLACK`], except for a
    /// goal without a deadline that ended here first (cancelled, its caller gone): its
    /// query waits for the far hub's answer, or for that hub to leave, at most
    /// [`GOAL_QUERY_LIMIT`].
    outgoing: Arc<Mutex<HashMap<CallId, String>>>,
    /// This hub's services and actions, offered as tokens: one per service provided on
    /// this hub.
    offered: HashMap<TopicName, LivelinessToken>,
}

impl CallBridge {
    pub async fn start(
        session: Session,
        router: Arc<Router>,
        shared: Arc<Shared>,
        providers: Providers,
    ) -> Result<CallBridge, FederationError> {
        let root = keys::root(&shared.fleet);
        let (tx, inputs) = mpsc::channel(INPUT_QUEUE);
        let calls_tx = tx.clone();
        let rt = tokio::runtime::Handle::current();
        let busy_rt = rt.clone();
        let calls_q = session
            .declare_queryable(format!("{root}/call/{}/**", shared.me))
            .callback(move |q| {
                if let Err(mpsc::error::TrySendError::Full(Input::Query(q))) =
                    calls_tx.try_send(Input::Query(q))
                {
                    busy_rt.spawn(async move {
                        let text = "the hub is busy: too many calls from other hubs wait; \
                                    try again";
                        reply_done(&q, CallStatus::Busy, text).await;
                    });
                }
            })
            .await
            .map_err(zerr)?;
        let schema_router = router.clone();
        let schema_prefix = format!("{root}/schema/{}/", shared.me);
        let schema_q = session
            .declare_queryable(format!("{root}/schema/{}/**", shared.me))
            .callback(move |q| {
                let Some(rest) = q.key_expr().as_str().strip_prefix(&schema_prefix) else {
                    return;
                };
                let Ok(name) = TopicName::parse(&format!("/{rest}")) else {
                    return;
                };
                let Some(topic) = schema_router.topic(&name) else {
                    return;
                };
                let s = topic.meta().schema.clone();
                let body = json!({ "type": s.type_name, "encoding": s.encoding, "text": s.text });
                rt.spawn(async move {
                    let key = q.key_expr().clone();
                    if let Err(e) = q.reply(key, body.to_string()).await {
                        tracing::debug!("federation: answering a definition: {e}");
                    }
                });
            })
            .await
            .map_err(zerr)?;
        let cancels = session
            .declare_subscriber(format!("{root}/cancel/{}", shared.me))
            .callback(move |sample| {
                let Ok(v) = serde_json::from_slice::<Value>(&sample.payload().to_bytes()) else {
                    return;
                };
                if let (Some(from), Some(id)) = (
                    v.get("from").and_then(Value::as_str),
                    v.get("id").and_then(Value::as_u64),
                ) {
                    let _ = tx.try_send(Input::Cancel {
                        from: from.to_owned(),
                        id,
                    });
                }
            })
            .await
            .map_err(zerr)?;
        let (peer, receiver) = ChannelPeer::new();
        router.calls.attach(shared.client, peer.clone());
        router.calls.watch(
            shared.client,
            regex::Regex::new("^.*$").expect("a valid pattern"),
        );
        Ok(CallBridge {
            session,
            router,
            shared,
            providers,
            receiver,
            _peer: peer,
            inputs,
            _queryables: vec![calls_q, schema_q],
            _cancels: cancels,
            incoming: HashMap::new(),
            incoming_ids: HashMap::new(),
            outgoing: Arc::default(),
            offered: HashMap::new(),
        })
    }

    pub async fn run(mut self, stop: CancellationToken) {
        loop {
            tokio::select! {
                _ = stop.cancelled() => break,
                msg = self.receiver.recv() => match msg {
                    Some(m) => self.on_table(m).await,
                    None => break,
                },
                Some(input) = self.inputs.recv() => match input {
                    Input::Query(q) => self.on_query(q).await,
                    Input::Cancel { from, id } => {
                        if !self.shared.admission.is_admitted(&from) {
                            continue;
                        }
                        if let Some(local) = self.incoming_ids.get(&(from, id)) {
                            self.router.calls.cancel(self.shared.client, *local);
                        }
                    }
                },
            }
        }
    }

    async fn on_table(&mut self, msg: PeerMsg) {
        match msg {
            PeerMsg::Call(req) => self.send_call(req),
            PeerMsg::Cancel(id) => {
                let hub = self
                    .outgoing
                    .lock()
                    .unwrap_or_else(|p| p.into_inner())
                    .get(&id)
                    .cloned();
                if let Some(hub) = hub {
                    let key = format!("{}/cancel/{hub}", keys::root(&self.shared.fleet));
                    let body = json!({ "from": self.shared.me, "id": id }).to_string();
                    if let Err(e) = self.session.put(key, body).await {
                        tracing::debug!("federation: cancel of call {id}: {e}");
                    }
                }
            }
            PeerMsg::Event(ev) => self.answer(ev).await,
            PeerMsg::Changed(change) => self.offer(change).await,
        }
    }

    /// A call here to a service another hub provides: a query to that hub.
    fn send_call(&self, req: CallRequest) {
        let me = self.shared.client;
        let calls = self.router.calls.clone();
        let name = req.service.name.clone();
        let hub = self
            .providers
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .get(&name)
            .cloned();
        let key = hub.as_ref().and_then(|h| {
            keys::name_chunks(name.as_str())
                .map(|c| format!("{}/call/{h}/{c}", keys::root(&self.shared.fleet)))
        });
        let (Some(hub), Some(key)) = (hub, key) else {
            calls.respond(
                me,
                req.id,
                CallStatus::NoProvider,
                None,
                format!("no hub provides {name} any more"),
            );
            return;
        };
        let now = Instant::now();
        let remaining = req.deadline.map(|d| d.saturating_duration_since(now));
        let header = CallHeader {
            from: self.shared.me.clone(),
            id: req.id,
            encoding: req.payload.encoding,
            goal: req.goal_id.is_some(),
            goal_id: req.goal_id,
            timeout_ms: remaining.map(|r| r.as_millis() as u64),
            caller: req.on_behalf_of.as_deref().cloned(),
        };
        let limit = remaining.map_or(GOAL_QUERY_LIMIT, |r| r + DEADLINE_SLACK);
        self.shared.counters.calls_out.fetch_add(1, Relaxed);
        self.outgoing
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .insert(req.id, hub.clone());
        let outgoing = self.outgoing.clone();
        let session = self.session.clone();
        let hub_name = self.shared.peer_name(&hub);
        tokio::spawn(async move {
            let id = req.id;
            let outcome = async {
                let replies = session
                    .get(key)
                    .payload(zenoh::bytes::ZBytes::from(req.payload.bytes.clone()))
                    .attachment(header.encode())
                    .consolidation(ConsolidationMode::None)
                    .timeout(limit)
                    .await
                    .map_err(|e| format!("cannot send the call to hub {hub_name}: {e}"))?;
                while let Ok(reply) = replies.recv_async().await {
                    let sample = match reply.result() {
                        Ok(s) => s,
                        Err(e) => {
                            let text =
                                String::from_utf8_lossy(&e.payload().to_bytes()).into_owned();
                            return Err(format!("hub {hub_name}: {text}"));
                        }
                    };
                    let parsed = sample
                        .attachment()
                        .map(|a| ReplyHeader::decode(&a.to_bytes()))
                        .unwrap_or_else(|| Err("reply without a header".into()));
                    let body = || bytes::Bytes::from(sample.payload().to_bytes().into_owned());
                    match parsed {
                        Ok(ReplyHeader::Feedback { encoding }) => {
                            calls.feedback(me, id, Payload::new(encoding, body()));
                        }
                        Ok(ReplyHeader::Done {
                            status,
                            text,
                            encoding,
                        }) => {
                            let payload = encoding.map(|e| Payload::new(e, body()));
                            calls.respond(me, id, status, payload, text);
                            return Ok(());
                        }
                        Err(e) => tracing::debug!("federation: reply to call {id}: {e}"),
                    }
                }
                Err(format!(
                    "hub {hub_name} did not answer (it left, or the call outlived its deadline)"
                ))
            }
            .await;
            outgoing
                .lock()
                .unwrap_or_else(|p| p.into_inner())
                .remove(&id);
            if let Err(text) = outcome {
                // False if the call already ended here (deadline, cancel): nothing to say.
                calls.respond(me, id, CallStatus::NoProvider, None, text);
            }
        });
    }

    /// A call from another hub: made on this table; answered as it progresses.
    async fn on_query(&mut self, query: Query) {
        let me = self.shared.client;
        let prefix = format!(
            "{}/call/{}/",
            keys::root(&self.shared.fleet),
            self.shared.me
        );
        let name = query
            .key_expr()
            .as_str()
            .strip_prefix(&prefix)
            .and_then(|rest| TopicName::parse(&format!("/{rest}")).ok());
        let header = query
            .attachment()
            .map(|a| CallHeader::decode(&a.to_bytes()))
            .unwrap_or_else(|| Err("call without a header".into()));
        let (name, header) = match (name, header) {
            (Some(n), Ok(h)) => (n, h),
            (None, _) => return reply_done(&query, CallStatus::Failed, "not a service name").await,
            (_, Err(e)) => return reply_done(&query, CallStatus::Failed, &e).await,
        };
        self.shared.counters.calls_in.fetch_add(1, Relaxed);
        // Only a hub whose link showed a certificate of this fleet is answered.
        if !self.shared.admission.is_admitted(&header.from) {
            self.shared.counters.refused.fetch_add(1, Relaxed);
            let why = self
                .shared
                .admission
                .refusal(&header.from)
                .unwrap_or_else(|| "no link from it has shown a certificate of this fleet".into());
            let text = format!("hub {} is not admitted: {why}", header.from);
            return reply_done(&query, CallStatus::Forbidden, &text).await;
        }
        // Decided as a local call would be: the caller's identity, vouched for by the
        // calling hub (named by its certificate), through this hub's gate — hub-only
        // services, rules naming the hub, and the audit log included.
        let hub = self.shared.hub_name_of(&header.from);
        let addr = self.shared.admission.address(&header.from);
        let identity = match &header.caller {
            None => Some(fleetlink_hub::security::hub_identity(&hub, addr)),
            Some(c) => fleetlink_hub::security::vouched_identity(c, &hub, addr),
        };
        let Some(identity) = identity else {
            return reply_done(
                &query,
                CallStatus::Failed,
                "call header: a caller name is not valid",
            )
            .await;
        };
        let mut gate = HubGate::new(
            self.shared.security.clone(),
            self.shared.registry.clone(),
            identity,
        );
        let op = if header.goal {
            Op::SendActionGoal
        } else {
            Op::CallService
        };
        if !gate.allows(name.as_str(), op) {
            self.shared.counters.refused.fetch_add(1, Relaxed);
            let text = format!("{name}: not allowed for {}", gate.principal());
            return reply_done(&query, CallStatus::Forbidden, &text).await;
        }
        // The federation provides remote services here; a call for one of those must not
        // bounce to yet another hub.
        if self
            .router
            .calls
            .service(&name)
            .is_some_and(|s| s.provider == me)
        {
            let text = format!("{name} is not provided on this hub");
            return reply_done(&query, CallStatus::NoProvider, &text).await;
        }
        let payload = query
            .payload()
            .map(|p| bytes::Bytes::from(p.to_bytes().into_owned()))
            .unwrap_or_default();
        let size = payload.len();
        let opts = CallOptions {
            timeout: header.timeout_ms.map(Duration::from_millis),
            goal: header.goal,
            goal_id: header.goal_id,
            on_behalf_of: None,
        };
        match self
            .router
            .calls
            .call(me, &name, Payload::new(header.encoding, payload), opts)
        {
            Ok(id) => {
                let from = (header.from, header.id);
                self.incoming_ids.insert(from.clone(), id);
                self.incoming.insert(
                    id,
                    Incoming {
                        query,
                        from,
                        gate,
                        name,
                        op,
                        size,
                    },
                );
            }
            Err(refused) => {
                gate.finished(
                    name.as_str(),
                    op,
                    size,
                    &format!("{:?}: {}", refused.status, refused.text),
                );
                reply_done(&query, refused.status, &refused.text).await
            }
        }
    }

    /// Progress or the end of a call another hub made here.
    async fn answer(&mut self, ev: CallEvent) {
        match ev {
            CallEvent::Feedback { id, payload } => {
                if let Some(inc) = self.incoming.get(&id) {
                    let header = ReplyHeader::Feedback {
                        encoding: payload.encoding,
                    };
                    let key = inc.query.key_expr().clone();
                    let sent = inc
                        .query
                        .reply(key, zenoh::bytes::ZBytes::from(payload.bytes))
                        .attachment(header.encode())
                        .await;
                    if let Err(e) = sent {
                        tracing::debug!("federation: feedback of call {id}: {e}");
                    }
                }
            }
            CallEvent::Done {
                id,
                status,
                payload,
                text,
            } => {
                let Some(mut inc) = self.incoming.remove(&id) else {
                    return;
                };
                self.incoming_ids.remove(&inc.from);
                let outcome = if status == CallStatus::Ok {
                    "ok".to_owned()
                } else {
                    format!("{status:?}: {text}")
                };
                inc.gate
                    .finished(inc.name.as_str(), inc.op, inc.size, &outcome);
                let header = ReplyHeader::Done {
                    status,
                    text,
                    encoding: payload.as_ref().map(|p| p.encoding),
                };
                let body = payload.map(|p| p.bytes).unwrap_or_default();
                let key = inc.query.key_expr().clone();
                let sent = inc
                    .query
                    .reply(key, zenoh::bytes::ZBytes::from(body))
                    .attachment(header.encode())
                    .await;
                if let Err(e) = sent {
                    tracing::debug!("federation: answer of call {id}: {e}");
                }
                // Dropping the query ends it at the caller's hub.
            }
        }
    }

    /// This hub's services and actions, offered to the fleet as they come and go (a
    /// robot's hub-only services stay here: only its own hub calls them).
    async fn offer(&mut self, change: ServiceChange) {
        match change {
            ServiceChange::Added(info)
                if fleetlink_relay::names::hub_only(info.name.as_str()).is_some() => {}
            ServiceChange::Added(info) => {
                let offer = if info.action {
                    Offer::Action {
                        name: info.name.as_str().to_owned(),
                        type_name: info.schema.type_name.clone(),
                    }
                } else {
                    Offer::Service {
                        name: info.name.as_str().to_owned(),
                        type_name: info.schema.type_name.clone(),
                    }
                };
                let Some(key) = keys::offer_key(&self.shared.fleet, &self.shared.me, &offer) else {
                    tracing::warn!(
                        "federation: service {} cannot be named in Zenoh; it stays on this hub",
                        info.name
                    );
                    return;
                };
                match self.session.liveliness().declare_token(key).await {
                    Ok(t) => {
                        self.offered.insert(info.name.clone(), t);
                    }
                    Err(e) => tracing::warn!("federation: cannot offer {}: {e}", info.name),
                }
            }
            ServiceChange::Removed(info) => {
                self.offered.remove(&info.name);
            }
        }
    }
}

async fn reply_done(query: &Query, status: CallStatus, text: &str) {
    let header = ReplyHeader::Done {
        status,
        text: text.to_owned(),
        encoding: None,
    };
    let key = query.key_expr().clone();
    if let Err(e) = query
        .reply(key, zenoh::bytes::ZBytes::new())
        .attachment(header.encode())
        .await
    {
        tracing::debug!("federation: answering a call: {e}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn call_headers_round_trip() {
        let h = CallHeader {
            from: "abc".into(),
            id: 42,
            encoding: Encoding::Cbor,
            goal: true,
            goal_id: Some([7; 16]),
            timeout_ms: Some(1500),
            caller: Some(Caller::User {
                name: "alice".into(),
                groups: vec!["operators".into()],
            }),
        };
        assert_eq!(CallHeader::decode(&h.encode()), Ok(h.clone()));
        for caller in [
            None,
            Some(Caller::Robot { name: "r2".into() }),
            Some(Caller::Anonymous),
        ] {
            let h = CallHeader {
                caller,
                ..h.clone()
            };
            assert_eq!(CallHeader::decode(&h.encode()), Ok(h));
        }
        assert!(
            CallHeader::decode(br#"{"from":"a","id":1,"enc":0,"caller":{"x":1}}"#)
                .unwrap_err()
                .contains("caller")
        );
        assert!(CallHeader::decode(b"{}").unwrap_err().contains("from"));
        assert!(
            CallHeader::decode(b"nope")
                .unwrap_err()
                .contains("call header")
        );
    }

    #[test]
    fn reply_headers_round_trip() {
        for h in [
            ReplyHeader::Feedback {
                encoding: Encoding::Json,
            },
            ReplyHeader::Done {
                status: CallStatus::Aborted,
                text: "lost".into(),
                encoding: Some(Encoding::Cdr),
            },
            ReplyHeader::Done {
                status: CallStatus::Ok,
                text: String::new(),
                encoding: None,
            },
        ] {
            assert_eq!(ReplyHeader::decode(&h.encode()), Ok(h));
        }
        assert!(
            ReplyHeader::decode(br#"{"kind":"x"}"#)
                .unwrap_err()
                .contains("unknown kind")
        );
    }
}
