//! One rosbridge v2 connection.
//!
//! Two halves: the reader (this task) parses operations and applies them to the router;
//! the writer (a spawned task) sends the client's outbox plus direct replies (`status`,
//! `service_response`). A bad operation gets a `status` error carrying the request's `id`
//! and the connection stays open; only a transport failure (or a frame over the size
//! limit, answered with close code 1009) ends the session.

mod fragments;
mod publish;
mod read;
mod write;

use std::collections::HashMap;
use std::sync::Arc;
use std::time::Instant;

use bytes::{Buf, Bytes};
use fleetlink_proto::rosbridge::shape::Matched;
use fleetlink_proto::rosbridge::{
    Compression, Op, ParseError, Publish, PublishId, Request, outbound,
};
use fleetlink_proto::{Encoding, Payload, Schema};
use futures_util::{FutureExt, SinkExt, Stream, StreamExt};
use serde_json::Value;
use std::sync::Mutex;

use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::protocol::CloseFrame;
use tokio_tungstenite::tungstenite::protocol::frame::coding::CloseCode;
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};
use tokio_util::sync::CancellationToken;

use fleetlink_relay::calls::ChannelPeer;
use fleetlink_relay::gate::{Gate, Guard, Op as GateOp, SessionAuth};
use fleetlink_relay::message::{FrameKind, Message};
use fleetlink_relay::names::{ClientId, TopicName};
use fleetlink_relay::outbox::{Delivery, Outbox};
use fleetlink_relay::queue::DropReason;
use fleetlink_relay::rosapi::{self, Answer};
use fleetlink_relay::router::{
    ClientKind, Router, SubOptions, SubscriptionId, Target, Topic, TopicView, same_type,
};
use fleetlink_relay::stats::StatsBatch;
use fleetlink_relay::transcode::NormalizeCache;
use fleetlink_relay::websocket::deflate::DeflateConfig;
use fleetlink_relay::websocket::liveness::{LivenessConfig, Peer, Watch};
use fleetlink_relay::websocket::replies::{Reply, close_with, wait_for_work};
use fleetlink_relay::websocket::{ClientMessage, PartsSink};

use fragments::Fragments;
use publish::Published;
pub use read::serve;
use write::write_loop;

/// Settings shared by all rosbridge sessions of one server.
#[derive(Debug, Clone)]
pub struct SessionConfig {
    /// How this server appears in `/rosapi/nodes`.
    pub node_name: String,
    /// Largest frame accepted from a client (also set on the WebSocket itself).
    pub max_message_size: usize,
    /// Messages the writer sends per socket flush.
    pub batch: usize,
    /// How often the client is pinged, and how long it may show no progress before it
    /// is closed and what it held released ([`fleetlink_relay::websocket::liveness`]).
    pub liveness: LivenessConfig,
    /// permessage-deflate for clients that offer it (`None`: never negotiated). The
    /// server answering the handshake reads it
    /// ([`fleetlink_relay::websocket::deflate::negotiate`]).
    pub deflate: Option<DeflateConfig>,
}

impl Default for SessionConfig {
    fn default() -> Self {
        SessionConfig {
            node_name: "/fleetlink".into(),
            max_message_size: 16 << 20,
            batch: 256,
            liveness: LivenessConfig::default(),
            deflate: Some(DeflateConfig::default()),
        }
    }
}

/// Replies the reader hands to the writer. Bounded: a client that floods bad requests
/// without reading the answers is slowed down, nobody else is.
const REPLY_QUEUE: usize = 256;

/// Frames a session takes from its client between looks at its call replies, its
/// shutdown and its counters ([`Session::flush_counts`]).
const LOOK_AROUND: u32 = 64;

/// An operation as read from a frame, when it needs more than the short path of a
/// publish (`Session::publish_now`): something to wait for or to answer.
enum Incoming<'a> {
    /// A `publish` read on the short path (JSON text or CBOR) that must wait: the client
    /// has not authenticated yet, or the topic is a no-drop one with a full queue
    /// ([`Session::handle_publish`] answers the one and waits for room for the other).
    Publish(Publish<'a>),
    /// A publish refused, with the `status` text to answer it with.
    Refused(PublishId<'a>, String),
    Other(Request),
}

pub(super) struct Session {
    pub(super) router: Arc<Router>,
    pub(super) client: ClientId,
    pub(super) cfg: Arc<SessionConfig>,
    /// Keyed by names the client chose: a seeded fast hash (foldhash), looked up on every
    /// publish.
    published: HashMap<TopicName, Published, foldhash::fast::RandomState>,
    /// Subscriptions by the `topic` string the client used, with the `id` each came with.
    subs: HashMap<String, Vec<(Option<Value>, SubscriptionId)>>,
    /// What this client may do; `None` until it authenticates.
    pub(super) gate: Option<Box<dyn Gate>>,
    guard: Option<Arc<dyn Guard>>,
    /// The writer's copy, checked for every message it delivers. std Mutex: taken once per
    /// batch by the writer and on `auth` by the reader, never across an await.
    writer_gate: Arc<Mutex<Option<Box<dyn Gate>>>>,
    replies: mpsc::Sender<Reply>,
    /// Services, actions and calls of this client.
    pub(super) calls: super::calls::SessionCalls,
    /// The least severe `status` the client wants (`set_level`; shared with the writer).
    level: Arc<std::sync::atomic::AtomicU8>,
    /// Operations the client sent in `fragment`s, being put back together.
    fragments: Fragments,
    /// Stamps the messages this client publishes.
    clock: fleetlink_relay::StampClock,
    /// Published topics whose `counts` hold messages ([`Session::flush_counts`]).
    unflushed: Vec<TopicName>,
}

/// Severity of `status` levels, as `set_level` names them.
fn severity(level: &str) -> Option<u8> {
    Some(match level {
        "info" => 0,
        "warning" => 1,
        "error" => 2,
        "none" => 3,
        _ => return None,
    })
}

/// rosbridge's default: errors only, until the client asks for more.
const DEFAULT_LEVEL: u8 = 2;

impl Session {
    pub(super) async fn send(&self, m: WsMessage) {
        let _ = self.replies.send(Reply::Frame(m)).await;
    }

    pub(super) async fn status(&self, level: &str, msg: String, id: Option<&Value>) {
        let wanted = self.level.load(std::sync::atomic::Ordering::Relaxed);
        if severity(level).unwrap_or(2) < wanted {
            return;
        }
        self.send(WsMessage::text(outbound::status(level, &msg, id)))
            .await;
    }

    fn set_level(&mut self, level: &str) -> Result<(), String> {
        let Some(v) = severity(level) else {
            return Err(format!(
                "set_level: unknown level '{}' (use none, error, warning or info)",
                level.chars().take(32).collect::<String>()
            ));
        };
        self.level.store(v, std::sync::atomic::Ordering::Relaxed);
        Ok(())
    }

    async fn parse_error(&self, e: ParseError) {
        let msg = match &e.op {
            Some(op) => format!("{op}: {}", e.message.trim_start_matches(&format!("{op}: "))),
            None => e.message.clone(),
        };
        self.status("error", msg, e.id.as_ref()).await;
    }

    async fn handle(&mut self, req: Request) {
        let id = req.id.clone();
        if let Op::Auth { fields } = &req.op {
            return self.authenticate(fields, id.as_ref()).await;
        }
        if self.gate.is_none() {
            let msg = format!(
                "{}: authentication required: send an 'auth' operation with a token first",
                req.op.name()
            );
            return self.status("error", msg, id.as_ref()).await;
        }
        let result = match req.op {
            Op::Advertise {
                topic,
                type_name,
                latch,
                ..
            } => self.advertise(&topic, &type_name, latch),
            Op::Unadvertise { topic } => self.unadvertise(&topic),
            Op::Publish { topic, msg } => self.publish(&topic, msg).await,
            Op::Subscribe {
                topic,
                type_name,
                throttle_rate,
                queue_length,
                fragment_size,
                compression,
                regex,
                qos,
            } => {
                match subscription_qos(qos, queue_length, throttle_rate, self.router.default_queue)
                {
                    Ok(qos) => {
                        let opts = SubOptions {
                            queue_length,
                            throttle_ms: throttle_rate,
                            qos,
                            delivery: Delivery {
                                compression,
                                fragment_size,
                            },
                            unlisted: false,
                            passive: false,
                        };
                        self.subscribe(&topic, type_name.as_deref(), regex, opts, id.clone())
                    }
                    Err(e) => Err(format!("subscribe {topic}: {e}")),
                }
            }
            Op::Unsubscribe { topic } => {
                self.unsubscribe(&topic, id.as_ref());
                Ok(())
            }
            Op::Pull { topic } => self.pull(&topic),
            Op::CallService {
                service,
                args,
                timeout,
                fragment_size,
                compression,
                ..
            } => {
                let how = super::calls::Answering {
                    fragment_size,
                    cbor: compression == Compression::Cbor || args.encoding == Encoding::Cbor,
                };
                self.call_service(&service, args, id.as_ref(), timeout, how)
                    .await;
                Ok(())
            }
            Op::AdvertiseService { service, type_name } => {
                self.advertise_service(&service, &type_name, false)
            }
            Op::UnadvertiseService { service } => self.unadvertise_service(&service, false),
            Op::AdvertiseAction { action, type_name } => {
                self.advertise_service(&action, &type_name, true)
            }
            Op::UnadvertiseAction { action } => self.unadvertise_service(&action, true),
            Op::ServiceResponse { values, result, .. } => {
                self.service_response(id.as_ref(), values, result)
            }
            Op::SendActionGoal {
                action,
                args,
                feedback,
                timeout,
                compression,
                ..
            } => {
                let how = super::calls::Answering {
                    fragment_size: None,
                    cbor: compression == Compression::Cbor || args.encoding == Encoding::Cbor,
                };
                self.send_action_goal(&action, args, id.as_ref(), feedback, timeout, how)
                    .await;
                Ok(())
            }
            Op::CancelActionGoal { .. } => self.cancel_action_goal(id.as_ref()),
            Op::ActionFeedback { values, .. } => self.action_feedback(id.as_ref(), values),
            Op::ActionResult {
                values,
                status,
                result,
                ..
            } => self.action_result(id.as_ref(), values, status, result),
            Op::Auth { .. } => Ok(()), // handled above
            // Reassembled before `handle` (see `serve`); a stray one is an error.
            Op::Fragment { .. } => Err("fragment: handled before this point".into()),
            Op::SetLevel { level } => self.set_level(&level),
            Op::Unknown { op } => Err(format!("unknown operation '{op}'")),
        };
        if let Err(msg) = result {
            self.status("error", msg, id.as_ref()).await;
        }
    }

    async fn authenticate(&mut self, fields: &serde_json::Map<String, Value>, id: Option<&Value>) {
        let Some(guard) = self.guard.clone() else {
            // Nothing to authenticate against (a robot's local listener): accept quietly,
            // as rosbridge does when authentication is off.
            return;
        };
        match guard.authenticate(fields) {
            Ok(gate) => {
                *self.writer_gate.lock().unwrap_or_else(|p| p.into_inner()) = Some(gate.fork());
                self.gate = Some(gate);
            }
            Err(msg) => self.status("error", format!("auth: {msg}"), id).await,
        }
    }

    /// Whether the client may do `op` on `name`; the refusal text names both.
    pub(super) fn check(&mut self, verb: &str, name: &str, op: GateOp) -> Result<(), String> {
        check(&mut self.gate, verb, name, op).map(|_| ())
    }

    fn subscribe(
        &mut self,
        topic: &str,
        type_name: Option<&str>,
        regex: bool,
        opts: SubOptions,
        id: Option<Value>,
    ) -> Result<(), String> {
        let target = if regex {
            Target::Pattern(Router::compile_pattern(topic).map_err(|e| format!("subscribe: {e}"))?)
        } else {
            let name = TopicName::parse(topic).map_err(|e| format!("subscribe: {e}"))?;
            if let (Some(want), Some(t)) = (
                type_name.filter(|t| !t.is_empty()),
                self.router.topic(&name),
            ) {
                let have = t.meta().schema.type_name.clone();
                if !have.is_empty() && !same_type(&have, want) {
                    return Err(format!(
                        "subscribe {name}: requested type {want} but the topic carries {have}"
                    ));
                }
            }
            self.check("subscribe", name.as_str(), GateOp::Subscribe)?;
            Target::Exact(name)
        };
        let entry = self.subs.entry(topic.to_owned()).or_default();
        if let Some(pos) = entry.iter().position(|(i, _)| *i == id) {
            // Same topic and id again: replace (options may have changed), never duplicate.
            let (_, old) = entry.remove(pos);
            self.router.unsubscribe(self.client, old);
        }
        let sid = self
            .router
            .subscribe(self.client, target, opts)
            .map_err(|e| format!("subscribe: {e}"))?;
        self.subs
            .entry(topic.to_owned())
            .or_default()
            .push((id, sid));
        Ok(())
    }

    /// fleetlink's `pull`: one message of a pull topic, which comes through this client's
    /// subscription to it (so it must have one).
    fn pull(&mut self, topic: &str) -> Result<(), String> {
        if !self.subs.contains_key(topic) {
            return Err(format!(
                "pull {topic}: subscribe to it first (the pulled message comes through the \
                 subscription)"
            ));
        }
        let name = TopicName::parse(topic).map_err(|e| format!("pull {topic}: {e}"))?;
        if self.router.request_pull(&name) {
            Ok(())
        } else {
            Err(format!(
                "pull {topic}: not a pull topic of a connected robot (see its `mode: pull`)"
            ))
        }
    }

    fn unsubscribe(&mut self, topic: &str, id: Option<&Value>) {
        let Some(list) = self.subs.get_mut(topic) else {
            return;
        };
        let (gone, keep): (Vec<_>, Vec<_>) = list
            .drain(..)
            .partition(|(i, _)| id.is_none() || i.as_ref() == id);
        *list = keep;
        if list.is_empty() {
            self.subs.remove(topic);
        }
        for (_, sid) in gone {
            self.router.unsubscribe(self.client, sid);
        }
    }

    /// The hub's own `/rosapi` services, answered from the router's tables.
    pub(super) async fn call_rosapi(
        &mut self,
        service: &str,
        args: &Payload,
        id: Option<&Value>,
        how: super::calls::Answering,
    ) {
        let args_json = fleetlink_relay::params::call_args(args).unwrap_or(Value::Null);
        if let Some(forwarded) = self.forward_param(service, &args_json, id, how) {
            if let Err(e) = forwarded {
                let reply = outbound::service_response(service, id, Value::String(e), false);
                self.send_value(&reply, how.cbor).await;
            }
            return;
        }
        let gate = self.gate.as_mut().expect("checked by the caller");
        let mut changes = Vec::new();
        let answer = {
            let mut visible = |name: &str, op: GateOp| gate.allows(name, op);
            let mut changed = |name: &str, what: &str, size: usize| {
                changes.push((name.to_owned(), what.to_owned(), size))
            };
            rosapi::answer(
                &self.router,
                &self.cfg.node_name,
                service,
                &args_json,
                &mut visible,
                &mut changed,
            )
        };
        // Parameter changes are audited like publishes, with what was done.
        for (name, what, size) in changes {
            gate.finished(&name, GateOp::Publish, size, &what);
        }
        let reply = match answer {
            Answer::Values(v) if service == "/rosapi/get_param_names" => {
                // Robots that provide parameters add theirs; answered when they have.
                let own = match v.get("names") {
                    Some(Value::Array(a)) => a
                        .iter()
                        .filter_map(|n| n.as_str().map(str::to_owned))
                        .collect(),
                    _ => Vec::new(),
                };
                if self.gather_param_names(own, id, how) {
                    return;
                }
                outbound::service_response(service, id, v, true)
            }
            Answer::Values(v) => outbound::service_response(service, id, v, true),
            Answer::Failed(e) => outbound::service_response(service, id, Value::String(e), false),
            Answer::NotRosapi => outbound::service_response(
                service,
                id,
                Value::String(format!("service {service} does not exist")),
                false,
            ),
        };
        self.send_value(&reply, how.cbor).await;
    }
}

/// The QoS of a rosbridge subscription: the fleetlink `qos` extension resolved over what
/// `queue_length` and `throttle_rate` say.
fn subscription_qos(
    qos: Option<Value>,
    queue_length: u32,
    throttle_ms: u32,
    default_queue: usize,
) -> Result<Option<fleetlink_qos::TopicQos>, String> {
    let Some(v) = qos else { return Ok(None) };
    let spec: fleetlink_qos::TopicQosSpec =
        serde_json::from_value(v).map_err(|e| format!("field 'qos': {e}"))?;
    let base = fleetlink_relay::queue::qos_for_options(queue_length, throttle_ms, default_queue);
    spec.resolve(&base)
        .map(Some)
        .map_err(|e| format!("field 'qos': {e}"))
}

/// Whether the session's client may do `op` on `name` (the gate, when it has
/// authenticated); the refusal text names both.
fn check<'g>(
    gate: &'g mut Option<Box<dyn Gate>>,
    verb: &str,
    name: &str,
    op: GateOp,
) -> Result<&'g mut Box<dyn Gate>, String> {
    let gate = gate
        .as_mut()
        .ok_or_else(|| format!("{verb} {name}: authentication required"))?;
    if gate.allows(name, op) {
        Ok(gate)
    } else {
        Err(format!(
            "{verb} {name}: not allowed for {}",
            gate.principal()
        ))
    }
}
