//! Services and actions both ways, over ROS 2's request/reply topics (`rq/<name>Request`,
//! `rr/<name>Reply`) in the two mappings ROS 2's middlewares use ([`Mapping`]): Cyclone
//! DDS's (a 16-byte request header in each sample: the client's id and a sequence number,
//! copied into the reply) and Fast DDS's (the request's own sample identity, echoed as the
//! reply's related sample identity in the RTPS inline QoS).
//!
//! - **Exposed** ([`Remote`]): a local server (a foreign reader on `rq/…Request`) matching
//!   `services.expose` is advertised in the call table; a fleet call becomes a request
//!   with this bridge's client id and the answer is matched by sequence number. An action
//!   server (its `send_goal` service) matching `actions.expose` is advertised as an
//!   action: a goal is a `send_goal` request, then `get_result`; feedback samples with the
//!   goal's UUID become the goal's feedback; a cancel is a `cancel_goal` request.
//! - **Offered** ([`Offered`]): a fleet service matching `services.offer` gets a reader on
//!   its request topic and a writer on its reply topic, so local clients call it like any
//!   ROS 2 service.
//!
//! Bodies are never decoded except an action's result (its `get_result` answer puts the
//! result after a status byte, so its alignment differs from a result of its own; the
//! registry converts that one message).

use std::collections::{HashMap, HashSet};
use std::sync::atomic::{AtomicI32, AtomicI64, Ordering::Relaxed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::{
    CallEvent, CallOptions, CallRequest, CallStatus, PeerMsg, ServiceChange,
};
use fleetlink_relay::{TopicName, params};
use futures::StreamExt;
use rustdds::{
    DataReaderStatus, DataWriterStatus, GUID, RTPSEntity, SampleIdentity, SequenceNumber,
    StatusEvented, WriteOptionsBuilder,
};
use tokio::sync::{Semaphore, oneshot};
use tokio::task::AbortHandle;

use crate::bridge::{Bridge, RawReader, RawWriter};
use crate::names::{self, DdsName};
use crate::qos;
use crate::raw::{CDR_LE_HEADER, RawCdr, RequestHeader};

/// How long a request waits for its server's request reader and reply writer to be
/// matched before it is sent (a volatile request, or its reply, written before matching
/// would be lost).
const MATCH_WAIT: Duration = Duration::from_secs(3);

/// How many requests one service of a local server has unanswered at once. A ROS 2
/// server's request reader keeps the last 10 requests (rmw's default service QoS): a
/// burst of more than that, arriving before the server takes them, would push the
/// oldest out unanswered. Further calls wait here, in order, for a reply to free a slot.
/// `get_result` is not limited: its requests wait for goals to end and are taken at once.
pub(crate) const IN_FLIGHT: usize = 10;

/// How a request and its reply are tied together, by the middleware of the other side.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Mapping {
    /// rmw_cyclonedds: a 16-byte header (client id, sequence number) before the fields.
    Cyclone,
    /// rmw_fastrtps (Fast DDS, ROS 2's default): no header; a request carries the GUID of
    /// the client's reply reader as its related sample identity, and the reply carries
    /// that GUID with the request's sequence number.
    FastDds,
}

impl Mapping {
    /// The mapping of the participant that owns `guid`, from its vendor id: RTPS
    /// implementations start their GUID prefixes with it, eProsima's being 01.0f.
    pub(crate) fn of(guid: GUID) -> Mapping {
        if guid.prefix.as_ref().starts_with(&[0x01, 0x0f]) {
            Mapping::FastDds
        } else {
            Mapping::Cyclone
        }
    }
}

/// One service of a local server, as this bridge calls it.
pub(crate) struct Endpoint {
    service: String,
    writer: RawWriter,
    mapping: Mapping,
    /// The reply reader's GUID (a Fast DDS server answers to it).
    reply_reader: GUID,
    client: u64,
    seq: AtomicI64,
    /// Readers matched to `writer` (the server's), from the writer's status events.
    matched: AtomicI32,
    /// Writers matched to the reply reader (the server's), from the reader's events: a
    /// reply written before its writer is matched with this reader would be lost.
    reply_matched: AtomicI32,
    waiting: Mutex<HashMap<i64, oneshot::Sender<Bytes>>>,
    /// Unanswered requests allowed at once ([`IN_FLIGHT`]); `None`: no limit.
    slots: Option<Semaphore>,
}

impl Endpoint {
    fn new(
        bridge: &Bridge,
        service: &str,
        type_base: &str,
        client: u64,
        limited: bool,
        mapping: Mapping,
    ) -> Result<(Arc<Endpoint>, RawReader), String> {
        let dds = |suffix: &str| {
            names::dds_type(&format!("{type_base}{suffix}"))
                .ok_or_else(|| format!("{type_base} is not a ROS type name"))
        };
        let writer = bridge.writer(
            &names::request_topic(service),
            &dds("_Request")?,
            qos::service(),
        )?;
        let reader = bridge.reader(
            &names::reply_topic(service),
            &dds("_Response")?,
            qos::service(),
        )?;
        Ok((
            Arc::new(Endpoint {
                service: service.to_owned(),
                writer,
                mapping,
                reply_reader: reader.guid(),
                client,
                seq: AtomicI64::new(0),
                matched: AtomicI32::new(0),
                reply_matched: AtomicI32::new(0),
                waiting: Mutex::new(HashMap::new()),
                slots: limited.then(|| Semaphore::new(IN_FLIGHT)),
            }),
            reader,
        ))
    }

    /// An endpoint of this bridge for `service` of a local server (type `type_base`,
    /// in `mapping`), at most [`IN_FLIGHT`] requests unanswered, its replies read by a
    /// task of its own.
    pub(crate) fn start(
        bridge: &Bridge,
        service: &str,
        type_base: &str,
        mapping: Mapping,
    ) -> Result<(Arc<Endpoint>, AbortHandle), String> {
        let (call, reader) =
            Endpoint::new(bridge, service, type_base, client_id(bridge), true, mapping)?;
        let task = tokio::spawn(call.clone().pump(reader)).abort_handle();
        Ok((call, task))
    }

    /// Sends `msg` (a CDR request message) and waits for the reply message.
    pub(crate) async fn request(&self, msg: Bytes) -> Result<Bytes, String> {
        // Held until the reply came or the call ended (timeout, cancel: dropped).
        let _slot = match &self.slots {
            Some(s) => Some(
                s.acquire()
                    .await
                    .map_err(|_| "the bridge is closing".to_owned())?,
            ),
            None => None,
        };
        let started = Instant::now();
        while !(self.server_matched() && self.reply_matched.load(Relaxed) > 0) {
            if started.elapsed() > MATCH_WAIT {
                return Err(format!(
                    "the server of {} is not reachable over DDS",
                    self.service
                ));
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
        let (tx, rx) = oneshot::channel();
        let seq = match self.mapping {
            Mapping::Cyclone => {
                let seq = self.seq.fetch_add(1, Relaxed) + 1;
                self.lock().insert(seq, tx);
                let header = RequestHeader {
                    client: self.client,
                    seq,
                };
                if let Err(e) = self.writer.write(RawCdr(header.prepend(&msg)), None) {
                    self.lock().remove(&seq);
                    return Err(format!("sending a request to {}: {e:?}", self.service));
                }
                seq
            }
            Mapping::FastDds => {
                // The request's sequence number is known once it is written, and its
                // reply could be read before that: the table stays locked meanwhile.
                let mut waiting = self.lock();
                let to = SampleIdentity {
                    writer_guid: self.reply_reader,
                    sequence_number: SequenceNumber::default(),
                };
                let options = WriteOptionsBuilder::new()
                    .related_sample_identity(to)
                    .build();
                match self.writer.write_with_options(RawCdr(msg), options) {
                    Ok(id) => {
                        let seq = i64::from(id.sequence_number);
                        waiting.insert(seq, tx);
                        seq
                    }
                    Err(e) => {
                        return Err(format!("sending a request to {}: {e:?}", self.service));
                    }
                }
            }
        };
        let forget = Forget(self, seq);
        let reply = rx.await.map_err(|_| format!("{} went away", self.service));
        drop(forget);
        reply
    }

    /// True once the server's request reader is matched with this endpoint's writer.
    fn server_matched(&self) -> bool {
        while let Some(ev) = self.writer.try_recv_status() {
            if let DataWriterStatus::PublicationMatched { current, .. } = ev {
                self.matched.store(current.count(), Relaxed);
            }
        }
        self.matched.load(Relaxed) > 0
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, HashMap<i64, oneshot::Sender<Bytes>>> {
        self.waiting.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Hands replies meant for this bridge to their waiting requests, and follows which
    /// writers the reply reader is matched with.
    async fn pump(self: Arc<Self>, reader: RawReader) {
        let mut samples = reader.async_sample_stream();
        let mut events = samples.async_event_stream();
        let own = [self.reply_reader, self.writer.guid()];
        loop {
            let r = tokio::select! {
                r = samples.next() => match r {
                    Some(r) => r,
                    None => return,
                },
                Some(ev) = events.next() => {
                    if let DataReaderStatus::SubscriptionMatched { current, .. } = ev {
                        self.reply_matched.store(current.count(), Relaxed);
                    }
                    continue;
                }
            };
            let Ok(sample) = r else { continue };
            if self.mapping == Mapping::FastDds {
                // Ours when the reply names this endpoint's reader (or writer).
                let Some(to) = sample.sample_info().related_sample_identity() else {
                    continue;
                };
                if !own.contains(&to.writer_guid) {
                    continue;
                }
                let seq = i64::from(to.sequence_number);
                if let Some(tx) = self.lock().remove(&seq) {
                    let _ = tx.send(sample.into_value().0);
                }
                continue;
            }
            let raw = sample.into_value().0;
            let Some(h) = RequestHeader::read(&raw) else {
                continue;
            };
            if h.client != self.client {
                continue; // another client's reply
            }
            if let (Some(tx), Some(msg)) = (self.lock().remove(&h.seq), RequestHeader::strip(&raw))
            {
                let _ = tx.send(msg);
            }
        }
    }
}

/// Removes a request's waiter when the request is dropped (timeout, cancel).
struct Forget<'a>(&'a Endpoint, i64);

impl Drop for Forget<'_> {
    fn drop(&mut self) {
        self.0.lock().remove(&self.1);
    }
}

pub(crate) enum RemoteKind {
    Service {
        srv_type: String,
        call: Arc<Endpoint>,
    },
    Action {
        action_type: String,
        send_goal: Arc<Endpoint>,
        get_result: Arc<Endpoint>,
        cancel_goal: Arc<Endpoint>,
        /// Goals in flight: UUID → call id (for their feedback).
        goals: Mutex<HashMap<[u8; 16], u64>>,
    },
}

/// A local service or action server offered to the fleet.
pub struct Remote {
    name: String,
    kind: RemoteKind,
    tasks: Vec<AbortHandle>,
}

impl Remote {
    pub(crate) fn abort(&self) {
        for t in &self.tasks {
            t.abort();
        }
    }
}

/// A fleet service offered to local clients.
pub struct Offered {
    srv_type: String,
    replies: RawWriter,
    pub(crate) task: AbortHandle,
}

/// Where a local caller's answer goes.
pub(crate) struct LocalCall {
    service: String,
    reply: ReplyTo,
}

/// What ties a local caller's reply to its request, in the caller's mapping.
#[derive(Debug, Clone, Copy)]
pub(crate) enum ReplyTo {
    Cyclone(RequestHeader),
    FastDds(SampleIdentity),
}

impl ReplyTo {
    /// A local client's request sample (`raw`, described by `info`): where its reply
    /// goes, and the request message as a CDR sample of its own. `None`: a Cyclone-style
    /// sample too short for its header.
    pub(crate) fn of_request(info: &rustdds::SampleInfo, raw: Bytes) -> Option<(ReplyTo, Bytes)> {
        let (related, id) = (info.related_sample_identity(), info.sample_identity());
        if related.is_some() || Mapping::of(id.writer_guid) == Mapping::FastDds {
            // A Fast DDS client names its reply reader; else its writer gets the reply.
            let writer_guid = related
                .map(|r| r.writer_guid)
                .filter(|g| *g != GUID::GUID_UNKNOWN)
                .unwrap_or(id.writer_guid);
            let to = SampleIdentity {
                writer_guid,
                sequence_number: id.sequence_number,
            };
            return Some((ReplyTo::FastDds(to), raw));
        }
        let header = RequestHeader::read(&raw)?;
        Some((ReplyTo::Cyclone(header), RequestHeader::strip(&raw)?))
    }

    /// Writes `body` (a CDR message with its encapsulation header) as the reply.
    pub(crate) fn reply(&self, writer: &RawWriter, body: Bytes) -> Result<(), String> {
        match self {
            ReplyTo::Cyclone(header) => writer
                .write(RawCdr(header.prepend(&body)), None)
                .map_err(|e| format!("writing a reply: {e:?}")),
            ReplyTo::FastDds(to) => {
                let options = WriteOptionsBuilder::new()
                    .related_sample_identity(*to)
                    .build();
                writer
                    .write_with_options(RawCdr(body), options)
                    .map(|_| ())
                    .map_err(|e| format!("writing a reply: {e:?}"))
            }
        }
    }
}

/// Follows the graph's servers: exposes new ones, withdraws vanished ones.
pub(crate) fn discover(bridge: &Arc<Bridge>) {
    let mut services: HashMap<String, (String, Mapping)> = HashMap::new();
    let mut actions: HashMap<String, (String, Mapping)> = HashMap::new();
    let opts = bridge.live();
    for r in bridge.dp.discovered_readers() {
        let s = &r.subscription_topic_data;
        if bridge.is_own(s.key()) {
            continue;
        }
        let Some(DdsName::Request(service)) = DdsName::parse(s.topic_name()) else {
            continue;
        };
        let mapping = Mapping::of(r.reader_proxy.remote_reader_guid);
        if let Some(action) = names::action_of_send_goal(&service) {
            if opts.expose_actions.matches(action)
                && let Some(t) = names::action_type(s.type_name())
            {
                actions.insert(action.to_owned(), (t, mapping));
            }
        } else if !names::is_hidden(&service)
            && opts.expose.matches(&service)
            && let Some(t) = names::service_type(s.type_name())
        {
            services.insert(service, (t, mapping));
        }
    }
    let known: HashSet<String> = bridge.lock().remotes.keys().cloned().collect();
    for name in known
        .iter()
        .filter(|n| !services.contains_key(*n) && !actions.contains_key(*n))
    {
        if let Some(r) = bridge.lock().remotes.remove(name) {
            r.abort();
            if let Ok(n) = TopicName::parse(name) {
                bridge.router.calls.unadvertise(bridge.client, &n);
            }
            tracing::info!("ros2: local server of {name} went away");
        }
    }
    for (name, (t, mapping)) in services {
        if !known.contains(&name) {
            expose(bridge, &name, &t, false, mapping);
        }
    }
    for (name, (t, mapping)) in actions {
        if !known.contains(&name) {
            expose(bridge, &name, &t, true, mapping);
        }
    }
}

/// This bridge's client id in request headers: from its participant's GUID, so two agents
/// on one graph never read each other's replies.
fn client_id(bridge: &Bridge) -> u64 {
    let p = bridge.own.prefix.as_ref();
    let mut b = [0u8; 8];
    b.copy_from_slice(&p[4..12]);
    u64::from_le_bytes(b)
}

fn expose(bridge: &Arc<Bridge>, name: &str, type_name: &str, action: bool, mapping: Mapping) {
    // A service or action is known when its request (goal) part is; the registry may
    // or may not have a full text for the whole interface.
    let part = format!("{type_name}{}", if action { "_Goal" } else { "_Request" });
    let Some(schema) = bridge.schema(&part).map(|_| {
        bridge
            .schema(type_name)
            .unwrap_or_else(|| Schema::named(type_name))
    }) else {
        bridge.report_once(name, &bridge.stats.unknown_types, || {
            format!(
                "ros2: not exposing {name}: type {type_name} is unknown to the agent's registry; \
                 give the agent its package with --msg-path DIR"
            )
        });
        return;
    };
    let Ok(topic_name) = TopicName::parse(name) else {
        return;
    };
    let made = if action {
        make_action(bridge, name, type_name, client_id(bridge), mapping)
    } else {
        Endpoint::start(bridge, name, type_name, mapping).map(|(call, task)| {
            (
                RemoteKind::Service {
                    srv_type: type_name.to_owned(),
                    call,
                },
                vec![task],
            )
        })
    };
    let (kind, tasks) = match made {
        Ok(k) => k,
        Err(e) => {
            tracing::warn!("ros2: cannot expose {name}: {e}");
            return;
        }
    };
    tracing::info!(
        "ros2: exposing local {} {name} ({type_name}) to the fleet",
        if action { "action" } else { "service" }
    );
    bridge.lock().remotes.insert(
        name.to_owned(),
        Arc::new(Remote {
            name: name.to_owned(),
            kind,
            tasks,
        }),
    );
    bridge
        .router
        .calls
        .advertise(bridge.client, topic_name, schema, action);
}

fn make_action(
    bridge: &Arc<Bridge>,
    name: &str,
    action_type: &str,
    client: u64,
    mapping: Mapping,
) -> Result<(RemoteKind, Vec<AbortHandle>), String> {
    let part = |p: &str| format!("{name}/_action/{p}");
    let (send_goal, r1) = Endpoint::new(
        bridge,
        &part("send_goal"),
        &format!("{action_type}_SendGoal"),
        client,
        true,
        mapping,
    )?;
    let (get_result, r2) = Endpoint::new(
        bridge,
        &part("get_result"),
        &format!("{action_type}_GetResult"),
        client,
        false,
        mapping,
    )?;
    let (cancel_goal, r3) = Endpoint::new(
        bridge,
        &part("cancel_goal"),
        "action_msgs/srv/CancelGoal",
        client,
        true,
        mapping,
    )?;
    let feedback_type = names::dds_type(&format!("{action_type}_FeedbackMessage"))
        .ok_or_else(|| format!("{action_type} is not a ROS type name"))?;
    let feedback = bridge.reader(
        &names::topic(&part("feedback")),
        &feedback_type,
        qos::reader_for(None, None, qos::DEPTH),
    )?;
    let tasks = vec![
        tokio::spawn(send_goal.clone().pump(r1)).abort_handle(),
        tokio::spawn(get_result.clone().pump(r2)).abort_handle(),
        tokio::spawn(cancel_goal.clone().pump(r3)).abort_handle(),
        tokio::spawn(pump_feedback(bridge.clone(), name.to_owned(), feedback)).abort_handle(),
    ];
    Ok((
        RemoteKind::Action {
            action_type: action_type.to_owned(),
            send_goal,
            get_result,
            cancel_goal,
            goals: Mutex::new(HashMap::new()),
        },
        tasks,
    ))
}

/// Feedback samples of `action`'s goals → the goals' callers. A feedback message is the
/// goal's UUID (16 bytes, so the feedback after it keeps its alignment) then the feedback.
async fn pump_feedback(bridge: Arc<Bridge>, action: String, reader: RawReader) {
    let mut samples = reader.async_sample_stream();
    while let Some(r) = samples.next().await {
        let Ok(sample) = r else { continue };
        let raw = sample.into_value().0;
        let Some(uuid) = raw.get(4..20).and_then(|u| <[u8; 16]>::try_from(u).ok()) else {
            continue;
        };
        let Some(remote) = bridge.lock().remotes.get(&action).cloned() else {
            return;
        };
        let RemoteKind::Action { goals, .. } = &remote.kind else {
            return;
        };
        let id = goals
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .get(&uuid)
            .copied();
        if let Some(id) = id {
            let mut fb = Vec::with_capacity(raw.len() - 16);
            fb.extend_from_slice(&raw[..4]);
            fb.extend_from_slice(&raw[20..]);
            bridge
                .router
                .calls
                .feedback(bridge.client, id, Payload::new(Encoding::Cdr, fb));
        }
    }
}

/// The call table's messages for this bridge.
pub(crate) fn on_peer(bridge: &Arc<Bridge>, m: PeerMsg) {
    match m {
        PeerMsg::Call(req)
            if bridge.opts.parameters && params::is_param_service(req.service.name.as_str()) =>
        {
            let bridge = bridge.clone();
            tokio::spawn(async move { crate::params::serve(&bridge, &req).await });
        }
        PeerMsg::Call(req) => {
            let remote = bridge
                .lock()
                .remotes
                .get(req.service.name.as_str())
                .cloned();
            let bridge = bridge.clone();
            tokio::spawn(async move {
                match remote {
                    Some(r) => serve(&bridge, &r, req).await,
                    None => {
                        let text =
                            format!("{} is not exposed by the ROS 2 bridge", req.service.name);
                        bridge.router.calls.respond(
                            bridge.client,
                            req.id,
                            CallStatus::NoProvider,
                            None,
                            text,
                        );
                    }
                }
            });
        }
        PeerMsg::Cancel(id) => {
            let goal = bridge.lock().goals.get(&id).cloned();
            if let Some((remote, uuid)) = goal {
                tokio::spawn(async move { cancel(&remote, uuid).await });
            }
        }
        PeerMsg::Event(ev) => {
            let action = bridge.lock().offered_goals.get(&ev.id()).cloned();
            match action {
                Some(a) => crate::offered_actions::on_event(bridge, &a, ev),
                None => answer_local(bridge, ev),
            }
        }
        PeerMsg::Changed(ServiceChange::Added(info)) => {
            let name = info.name.as_str();
            if info.provider == bridge.client {
                return;
            }
            let opts = bridge.live();
            if info.action && opts.offer_actions.matches(name) {
                offer_action(bridge, name, &info.schema.type_name);
            } else if !info.action && opts.offer.matches(name) {
                offer(bridge, name, &info.schema.type_name);
            }
        }
        PeerMsg::Changed(ServiceChange::Removed(info)) => {
            let name = info.name.as_str();
            let (service, action) = {
                let mut st = bridge.lock();
                (st.offered.remove(name), st.offered_actions.remove(name))
            };
            if let Some(o) = &service {
                o.task.abort();
            }
            if let Some(a) = &action {
                a.abort();
            }
            if service.is_some() || action.is_some() {
                tracing::info!("ros2: fleet {name} is gone: no longer offered to local nodes");
            }
        }
    }
}

/// Serves fleet action `name` to local action clients.
fn offer_action(bridge: &Arc<Bridge>, name: &str, type_name: &str) {
    if bridge.lock().offered_actions.contains_key(name) {
        return;
    }
    match crate::offered_actions::offer(bridge, name, type_name) {
        Ok(a) => {
            tracing::info!("ros2: offering fleet action {name} ({type_name}) to local nodes");
            bridge.lock().offered_actions.insert(name.to_owned(), a);
        }
        Err(e) => tracing::warn!("ros2: cannot offer fleet action {name} to local nodes: {e}"),
    }
}

/// A fleet call or goal for a local server, answered in the call table.
async fn serve(bridge: &Bridge, remote: &Arc<Remote>, req: CallRequest) {
    let limit = req.deadline.map_or(bridge.opts.call_timeout, |d| {
        d.saturating_duration_since(Instant::now())
    });
    let outcome = tokio::time::timeout(limit, async {
        match &remote.kind {
            RemoteKind::Service { srv_type, call } => {
                let body = bridge.to_cdr(&format!("{srv_type}_Request"), &req.payload)?;
                let reply = call.request(body).await?;
                Ok((
                    CallStatus::Ok,
                    Some(Payload::new(Encoding::Cdr, reply)),
                    String::new(),
                ))
            }
            RemoteKind::Action { .. } => goal(bridge, remote, &req).await,
        }
    })
    .await;
    let (status, payload, text) = match outcome {
        Ok(Ok(answer)) => answer,
        Ok(Err(text)) => (CallStatus::Failed, None, text),
        Err(_) => (
            CallStatus::Timeout,
            None,
            format!("{} did not answer within {limit:?}", remote.name),
        ),
    };
    bridge.lock().goals.remove(&req.id);
    if let RemoteKind::Action { goals, .. } = &remote.kind {
        goals
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .retain(|_, id| *id != req.id);
    }
    bridge
        .router
        .calls
        .respond(bridge.client, req.id, status, payload, text);
}

type Answer = (CallStatus, Option<Payload>, String);

/// A goal: `send_goal`, then `get_result` (feedback flows meanwhile).
async fn goal(bridge: &Bridge, remote: &Arc<Remote>, req: &CallRequest) -> Result<Answer, String> {
    let RemoteKind::Action {
        action_type,
        send_goal,
        get_result,
        goals,
        ..
    } = &remote.kind
    else {
        return Err("not an action".into());
    };
    let uuid = req.goal_id.unwrap_or_default();
    let goal = bridge.to_cdr(&format!("{action_type}_Goal"), &req.payload)?;
    let mut msg = Vec::with_capacity(goal.len() + 16);
    msg.extend_from_slice(&CDR_LE_HEADER);
    msg.extend_from_slice(&uuid);
    msg.extend_from_slice(goal.get(4..).unwrap_or_default());
    goals
        .lock()
        .unwrap_or_else(|p| p.into_inner())
        .insert(uuid, req.id);
    bridge.lock().goals.insert(req.id, (remote.clone(), uuid));
    let accepted = send_goal.request(msg.into()).await?;
    if accepted.get(4).copied().unwrap_or(0) == 0 {
        return Ok((
            CallStatus::Failed,
            None,
            format!("{} rejected the goal", remote.name),
        ));
    }
    let mut ask = Vec::with_capacity(20);
    ask.extend_from_slice(&CDR_LE_HEADER);
    ask.extend_from_slice(&uuid);
    let reply = get_result.request(ask.into()).await?;
    // `{int8 status, T_Result result}`: the result is not aligned as a message of its
    // own, so the registry reads the whole answer once.
    let v = bridge.json_of(
        &format!("{action_type}_GetResult_Response"),
        &Payload::new(Encoding::Cdr, reply),
    )?;
    let status = match v.get("status").and_then(|s| s.as_i64()) {
        Some(4) => CallStatus::Ok,
        Some(5) => CallStatus::Cancelled,
        _ => CallStatus::Aborted,
    };
    let result = serde_json::to_vec(v.get("result").unwrap_or(&serde_json::Value::Null))
        .map_err(|e| e.to_string())?;
    let text = match status {
        CallStatus::Ok => String::new(),
        CallStatus::Cancelled => format!("{} cancelled the goal", remote.name),
        _ => format!("{} aborted the goal", remote.name),
    };
    Ok((status, Some(Payload::new(Encoding::Json, result)), text))
}

/// Asks a local action server to cancel a goal (`cancel_goal` with the goal's UUID and a
/// zero stamp); the goal's `get_result` then ends it.
async fn cancel(remote: &Remote, uuid: [u8; 16]) {
    let RemoteKind::Action { cancel_goal, .. } = &remote.kind else {
        return;
    };
    let mut msg = Vec::with_capacity(28);
    msg.extend_from_slice(&CDR_LE_HEADER);
    msg.extend_from_slice(&uuid);
    msg.extend_from_slice(&[0u8; 8]);
    if let Err(e) = cancel_goal.request(msg.into()).await {
        tracing::debug!("ros2: cancelling a goal of {}: {e}", remote.name);
    }
}

/// Offers fleet service `name` to local clients.
fn offer(bridge: &Arc<Bridge>, name: &str, type_name: &str) {
    if bridge.lock().offered.contains_key(name) {
        return;
    }
    let srv_type = type_name.trim_end_matches("_Request").to_owned();
    let made = (|| {
        let dds = |suffix: &str| {
            names::dds_type(&format!("{srv_type}{suffix}"))
                .ok_or_else(|| format!("{srv_type:?} is not a ROS service type name"))
        };
        let requests = bridge.reader(
            &names::request_topic(name),
            &dds("_Request")?,
            qos::service(),
        )?;
        let replies = bridge.writer(
            &names::reply_topic(name),
            &dds("_Response")?,
            qos::service(),
        )?;
        Ok::<_, String>((requests, replies))
    })();
    let (requests, replies) = match made {
        Ok(m) => m,
        Err(e) => {
            tracing::warn!("ros2: cannot offer fleet service {name} to local nodes: {e}");
            return;
        }
    };
    let task =
        tokio::spawn(pump_requests(bridge.clone(), name.to_owned(), requests)).abort_handle();
    tracing::info!("ros2: offering fleet service {name} ({srv_type}) to local nodes");
    bridge.lock().offered.insert(
        name.to_owned(),
        Arc::new(Offered {
            srv_type,
            replies,
            task,
        }),
    );
}

/// Local clients' requests of an offered fleet service → fleet calls.
async fn pump_requests(bridge: Arc<Bridge>, service: String, reader: RawReader) {
    let Ok(name) = TopicName::parse(&service) else {
        return;
    };
    let mut samples = reader.async_sample_stream();
    while let Some(r) = samples.next().await {
        let Ok(sample) = r else { continue };
        if bridge.is_own(sample.sample_info().writer_guid()) {
            continue;
        }
        let info = sample.sample_info().clone();
        let Some((reply, msg)) = ReplyTo::of_request(&info, sample.into_value().0) else {
            continue;
        };
        let opts = CallOptions {
            timeout: Some(bridge.opts.call_timeout),
            goal: false,
            goal_id: None,
            on_behalf_of: None,
        };
        match bridge
            .router
            .calls
            .call(bridge.client, &name, Payload::new(Encoding::Cdr, msg), opts)
        {
            Ok(id) => {
                bridge.lock().local_calls.insert(
                    id,
                    LocalCall {
                        service: service.clone(),
                        reply,
                    },
                );
            }
            Err(e) => tracing::warn!("ros2: a local call of {service} was refused: {}", e.text),
        }
    }
}

/// The end of a local caller's fleet call: the reply, written with the caller's header.
fn answer_local(bridge: &Bridge, ev: CallEvent) {
    let CallEvent::Done {
        id,
        status,
        payload,
        text,
    } = ev
    else {
        return;
    };
    let (call, offered) = {
        let mut st = bridge.lock();
        let Some(call) = st.local_calls.remove(&id) else {
            return;
        };
        let offered = st.offered.get(&call.service).cloned();
        (call, offered)
    };
    let Some(offered) = offered else {
        return;
    };
    let Some(payload) = payload.filter(|_| status == CallStatus::Ok) else {
        // ROS 2 services have no error reply: the local client times out.
        tracing::warn!(
            "ros2: a local call of {} failed ({status:?}): {text}",
            call.service
        );
        return;
    };
    match bridge.to_cdr(&format!("{}_Response", offered.srv_type), &payload) {
        Ok(body) => {
            if let Err(e) = call.reply.reply(&offered.replies, body) {
                tracing::debug!("ros2: replying to a local call of {}: {e}", call.service);
            }
        }
        Err(e) => tracing::warn!(
            "ros2: the answer of {} cannot be sent to the local caller: {e}",
            call.service
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn guid(prefix: [u8; 2]) -> GUID {
        let mut b = [0x5a; 16];
        b[..2].copy_from_slice(&prefix);
        GUID::from_bytes(b)
    }

    #[test]
    fn the_request_mapping_follows_the_vendor_in_the_guid() {
        assert_eq!(Mapping::of(guid([0x01, 0x0f])), Mapping::FastDds); // eProsima
        assert_eq!(Mapping::of(guid([0x01, 0x10])), Mapping::Cyclone); // Eclipse Cyclone
        assert_eq!(Mapping::of(guid([0x01, 0x12])), Mapping::Cyclone); // rustdds
        assert_eq!(Mapping::of(GUID::GUID_UNKNOWN), Mapping::Cyclone);
    }
}
