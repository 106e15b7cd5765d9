//! One rosbridge v2 connection.
//!
//! Two halves: the reader (this task) parses operations and applies them to the router;
//! the writer (a spawned task) sends the client's outbox plus direct replies (`status`,
//! `service_response`). A bad operation gets a `status` error carrying the request's `id`
//! and the connection stays open; only a transport failure (or a frame over the size
//! limit, answered with close code 1009) ends the session.

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

use crate::calls::ChannelPeer;
use crate::gate::{Gate, Guard, Op as GateOp, SessionAuth};
use crate::message::{FrameKind, Message};
use crate::names::{ClientId, TopicName};
use crate::outbox::{Delivery, Outbox};
use crate::queue::DropReason;
use crate::rosbridge::rosapi::{self, Answer};
use crate::router::{
    ClientKind, Router, SubOptions, SubscriptionId, Target, Topic, TopicView, same_type,
};
use crate::stats::StatsBatch;
use crate::transcode::NormalizeCache;
use crate::websocket::deflate::DeflateConfig;
use crate::websocket::liveness::{LivenessConfig, Peer, Watch};
use crate::websocket::replies::{Reply, close_with, wait_for_work};
use crate::websocket::{ClientMessage, PartsSink};

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
    /// is closed and what it held released ([`crate::websocket::liveness`]).
    pub liveness: LivenessConfig,
    /// permessage-deflate for clients that offer it (`None`: never negotiated). The
    /// server answering the handshake reads it ([`crate::websocket::deflate::negotiate`]).
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

/// Runs a session until the client leaves: `stream` gives the client's messages, `sink`
/// takes what is sent to it (an accepted WebSocket's halves, see [`crate::websocket`]).
/// Ends when the client leaves, when it shows no progress for the silence limit
/// (`cfg.liveness`; `conn` says how to sample its connection), or when `shutdown` is
/// cancelled.
///
/// Control frames are answered here: a `Ping` with a `Pong`, a `Close` with a `Close`
/// echoing its code; a frame that breaks the protocol closes the connection with the
/// code that says why (1002, 1007 for text that is not UTF-8, 1009 when too large).
pub async fn serve<K, S>(
    sink: K,
    stream: S,
    router: Arc<Router>,
    conn: impl Into<Peer>,
    cfg: Arc<SessionConfig>,
    shutdown: CancellationToken,
    auth: SessionAuth,
) where
    K: PartsSink + Send + 'static,
    S: Stream<Item = Result<ClientMessage, WsError>> + Unpin + Send,
{
    let conn: Peer = conn.into();
    let addr = conn.addr;
    let (client, outbox) = router.connect(ClientKind::Rosbridge, addr);
    if sink.deflate().is_some() {
        router.note_deflate(client);
    }
    let (peer, peer_rx) = ChannelPeer::new();
    router.calls.attach(client, peer);
    let mut stream = stream;
    // The client's recent publish envelopes (kept here, beside the session, because the
    // frame that is read with them borrows them while the session publishes).
    let mut shapes = fleetlink_proto::rosbridge::EnvelopeShapes::default();
    let (reply_tx, reply_rx) = mpsc::channel(REPLY_QUEUE);
    let mut watch = Watch::new(cfg.liveness, conn.progress, reply_tx.clone());
    let writer_gate = Arc::new(Mutex::new(auth.gate.as_ref().map(|g| g.fork())));
    let level = Arc::new(std::sync::atomic::AtomicU8::new(DEFAULT_LEVEL));
    let writer = tokio::spawn(write_loop(
        sink,
        outbox.clone(),
        reply_rx,
        router.clone(),
        cfg.batch,
        writer_gate.clone(),
        level.clone(),
    ));
    let mut session = Session {
        router: router.clone(),
        client,
        cfg,
        published: HashMap::default(),
        subs: HashMap::new(),
        replies: reply_tx,
        gate: auth.gate,
        guard: auth.guard,
        writer_gate,
        calls: super::calls::SessionCalls::default(),
        level,
        fragments: Fragments::default(),
        clock: crate::StampClock::default(),
        unflushed: Vec::new(),
    };
    // One wait for the shutdown, registered once: a fresh `cancelled()` per frame costs a
    // lock and a waker registration on every operation.
    let cancelled = shutdown.cancelled();
    tokio::pin!(cancelled);
    // Frames are taken first while the client has some queued: a frame already read is
    // taken without a select, since polling every branch for each of thousands of small
    // operations in a read costs more than handling them. So that a flooding client still
    // sees its call replies and a shutdown, both are looked at every `LOOK_AROUND` frames
    // without waiting.
    let mut frames = 0u32;
    // Set when the client showed no progress for the silence limit: how long.
    let mut gone = None;
    loop {
        frames += 1;
        if frames.is_multiple_of(LOOK_AROUND) {
            if shutdown.is_cancelled() {
                break;
            }
            session.flush_counts();
            // A client sending without pause is read without waiting: it is alive, and
            // its pings fall due here.
            watch.read();
            if let Some(silent) = watch.check() {
                gone = Some(silent);
                break;
            }
            while let Ok(Some(m)) = peer_rx.try_recv() {
                if let Err(silent) = watch.race(session.on_peer(m)).await {
                    gone = Some(silent);
                    break;
                }
            }
            if gone.is_some() {
                break;
            }
        }
        let frame = match stream.next().now_or_never() {
            Some(f) => f,
            None => {
                // Nothing more has come: the counters catch up before the wait, and the
                // next message's arrival is a new clock reading.
                session.flush_counts();
                let f = tokio::select! {
                    biased;
                    f = stream.next() => f,
                    m = peer_rx.recv() => {
                        if let Some(m) = m
                            && let Err(silent) = watch.race(session.on_peer(m)).await
                        {
                            gone = Some(silent);
                            break;
                        }
                        continue;
                    }
                    _ = &mut cancelled => break,
                    silent = watch.gone() => {
                        gone = Some(silent);
                        break;
                    }
                };
                session.clock.waited();
                watch.read();
                f
            }
        };
        let Some(frame) = frame else {
            break;
        };
        if matches!(frame, Ok(ClientMessage::Binary(_))) {
            session.calls.binary = true;
        }
        let (text, binary);
        let req = match frame {
            Ok(ClientMessage::Text(t)) => {
                // Nearly all traffic: a publish in one of the client's recent envelopes
                // (`EnvelopeShapes`), read by comparing text, its UTF-8 and syntax
                // checked by its check against the type.
                let (t, fitted) = match shapes.fit(&t) {
                    Some(m) => match session.publish_shaped(t, m) {
                        Ok(()) => {
                            tokio::task::consume_budget().await;
                            continue;
                        }
                        // Not published at once (refused, or to wait): read again in
                        // full, so that what follows is what the full read gives, the
                        // precise error included.
                        Err(back) => (back, true),
                    },
                    None => (t, false),
                };
                text = t;
                let Ok(utf8) = std::str::from_utf8(&text) else {
                    let close = CloseFrame {
                        code: CloseCode::Invalid,
                        reason: "a text message is not UTF-8".into(),
                    };
                    let _ = session.replies.send(Reply::Close(Some(close))).await;
                    break;
                };
                let publish = if fitted {
                    Publish::from_json_text(utf8, &text)
                } else {
                    Publish::from_json_text_shaped(utf8, &text, &mut shapes)
                };
                match publish {
                    Some(p) => match session.publish_now(p, Some(&text)) {
                        Some(rest) => Ok(rest),
                        None => {
                            tokio::task::consume_budget().await;
                            continue;
                        }
                    },
                    None => match Request::from_json(&text) {
                        Ok(r) if matches!(r.op, Op::Fragment { .. }) => match session.fragment(r) {
                            Some(whole) => whole.map(Incoming::Other),
                            None => continue,
                        },
                        other => other.map(Incoming::Other),
                    },
                }
            }
            Ok(ClientMessage::Binary(b)) => {
                binary = b;
                match Publish::from_cbor_frame(&binary) {
                    Some(p) => match session.publish_now(p, None) {
                        Some(rest) => Ok(rest),
                        None => {
                            tokio::task::consume_budget().await;
                            continue;
                        }
                    },
                    None => Request::from_cbor(&binary).map(Incoming::Other),
                }
            }
            Ok(ClientMessage::Ping(p)) => {
                session.send(WsMessage::Pong(p)).await;
                continue;
            }
            Ok(ClientMessage::Close(c)) => {
                // The close handshake: the client's code echoed back.
                let echo = c.map(|c| CloseFrame {
                    code: c.code,
                    reason: "".into(),
                });
                let _ = session.replies.send(Reply::Close(echo)).await;
                break;
            }
            Ok(_) => continue,
            Err(e) => {
                let (code, reason) = match &e {
                    WsError::Capacity(e) => (CloseCode::Size, format!("frame too large: {e}")),
                    WsError::Protocol(e) => (CloseCode::Protocol, e.to_string()),
                    WsError::Utf8(e) => (CloseCode::Invalid, e.clone()),
                    // A compressed message that does not inflate.
                    WsError::Io(e) if e.kind() == std::io::ErrorKind::InvalidData => {
                        (CloseCode::Protocol, e.to_string())
                    }
                    _ => break,
                };
                let close = CloseFrame {
                    code,
                    reason: reason.into(),
                };
                let _ = session.replies.send(Reply::Close(Some(close))).await;
                break;
            }
        };
        // A publish may wait for room on a no-drop topic (`Session::wait_for_room`); a
        // shutdown must not wait for it. `biased`: the step nearly always finishes at once.
        let step = async {
            match req {
                Ok(Incoming::Publish(p)) => session.handle_publish(p).await,
                Ok(Incoming::Refused(id, msg)) => {
                    session.status("error", msg, id.value().as_ref()).await;
                    session.clock.waited();
                }
                // Other operations are rare and may wait (a reply queue, a call): the next
                // message's arrival is read from the clock again.
                Ok(Incoming::Other(req)) => {
                    session.handle(req).await;
                    session.clock.waited();
                }
                Err(e) => {
                    session.parse_error(e).await;
                    session.clock.waited();
                }
            }
        };
        tokio::select! {
            biased;
            _ = step => {}
            _ = &mut cancelled => break,
            silent = watch.gone() => {
                gone = Some(silent);
                break;
            }
        }
        // One socket read can hold thousands of small operations; counting each against
        // the task's budget makes a flooding client give way to the writers that deliver
        // its messages (without it, a woken writer waits behind the whole read and the
        // subscribers' queues overflow).
        tokio::task::consume_budget().await;
    }
    session.flush_counts();
    if shutdown.is_cancelled() {
        // Going away (RFC 6455, 7.4.1), after what is queued; a writer too backed up to
        // take it is closed by the end of the reply channel anyway.
        let away = CloseFrame {
            code: CloseCode::Away,
            reason: "the server is shutting down".into(),
        };
        let _ = session.replies.try_send(Reply::Close(Some(away)));
    }
    if let Some(silent) = gone {
        tracing::info!(
            "rosbridge client {}: no progress for {} ms (no bytes read, its connection not \
             draining); closing it and releasing what it held",
            addr.map_or_else(|| "?".into(), |a| a.to_string()),
            silent.as_millis()
        );
    }
    // What the client held goes now: its subscriptions (and the demand they made), its
    // advertisements, its calls and goals, their callers and providers told.
    router.disconnect(client);
    drop(session);
    drop(watch);
    if gone.is_some() {
        // Its socket may never drain: the writer is not waited for.
        writer.abort();
    }
    let _ = writer.await;
}

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

/// What [`Session::publish_on_known`] did.
enum Known {
    /// The topic is one this client publishes: the publish's outcome.
    Done(Result<Option<(Payload, Arc<Topic>)>, String>),
    /// It is not (under that spelling): the message, untouched.
    Not(Payload),
}

struct Published {
    /// The name it is published under (this entry's key).
    name: TopicName,
    topic: Arc<Topic>,
    seq: u64,
    /// What the transcoder resolved for checking this topic's messages.
    normalize: NormalizeCache,
    /// This client's messages not yet added to the topic's counters
    /// ([`Session::flush_counts`]).
    counts: StatsBatch,
    /// The topic as of this client's last publish, held until the session waits.
    view: TopicView,
    /// In the session's `unflushed` list.
    listed: bool,
}

impl Published {
    fn new(name: TopicName, topic: Arc<Topic>) -> Published {
        Published {
            name,
            topic,
            seq: 0,
            normalize: NormalizeCache::default(),
            counts: StatsBatch::default(),
            view: TopicView::default(),
            listed: false,
        }
    }
}

impl Published {
    /// Lists the entry in `unflushed` (once), for the session to let go of its `view` and
    /// flush its counters when it next waits: done before a publish takes the view.
    fn list(&mut self, unflushed: &mut Vec<TopicName>) {
        if !self.listed {
            self.listed = true;
            unflushed.push(self.name.clone());
        }
    }

    /// Fans out `msg`, checked against the topic's type (its `view` read for that), as
    /// this client's next message on the topic; gives its size.
    fn publish(
        &mut self,
        client: ClientId,
        clock: &mut crate::StampClock,
        msg: Payload,
        json_text: bool,
    ) -> usize {
        self.seq += 1;
        let size = msg.len();
        let (received, stamp) = clock.arrival();
        self.topic.publish_framed(
            &self.view,
            client,
            self.seq,
            stamp,
            msg,
            received,
            json_text,
            &mut self.counts,
        );
        size
    }
}

impl Drop for Published {
    fn drop(&mut self) {
        self.topic.stats.flush(&mut self.counts);
    }
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
    clock: crate::StampClock,
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

/// Fragmented operations in progress, bounded: a client cannot make the session hold more
/// than a few partial operations, nor more bytes than one whole message may have.
#[derive(Default)]
struct Fragments {
    parts: HashMap<String, (Vec<Option<String>>, usize)>,
}

/// Partial operations one session may have at once.
const MAX_FRAGMENTED: usize = 16;
/// Pieces one operation may be cut into.
const MAX_PIECES: u32 = 100_000;

impl Fragments {
    /// Adds a piece; returns the whole operation's text once every piece arrived.
    fn add(
        &mut self,
        id: String,
        data: String,
        num: u32,
        total: u32,
        max_bytes: usize,
    ) -> Result<Option<String>, String> {
        if total == 0 || total > MAX_PIECES {
            self.parts.remove(&id);
            return Err(format!(
                "fragment: 'total' must be 1 to {MAX_PIECES}, got {total}"
            ));
        }
        if num >= total {
            return Err(format!(
                "fragment: 'num' {num} is not below 'total' {total}"
            ));
        }
        if !self.parts.contains_key(&id) && self.parts.len() >= MAX_FRAGMENTED {
            return Err(format!(
                "fragment: {MAX_FRAGMENTED} fragmented operations are already in progress; \
                 finish one first"
            ));
        }
        let entry = self
            .parts
            .entry(id.clone())
            .or_insert_with(|| (vec![None; total as usize], 0));
        if entry.0.len() != total as usize {
            self.parts.remove(&id);
            return Err(format!(
                "fragment {id}: 'total' changed between pieces; the operation is dropped"
            ));
        }
        let slot = &mut entry.0[num as usize];
        let old = slot.as_ref().map_or(0, String::len);
        entry.1 = entry.1 - old + data.len();
        *slot = Some(data);
        if entry.1 > max_bytes {
            self.parts.remove(&id);
            return Err(format!(
                "fragment {id}: the operation is larger than {max_bytes} bytes; it is dropped"
            ));
        }
        if entry.0.iter().all(Option::is_some) {
            let (pieces, _) = self.parts.remove(&id).expect("present above");
            return Ok(Some(pieces.into_iter().flatten().collect()));
        }
        Ok(None)
    }
}

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

    /// Adds what this client published since the last call to its topics' counters, and
    /// lets go of the topics' snapshots (a subscriber that left is not kept alive by an
    /// idle publisher): done before the session waits for the client and every
    /// [`LOOK_AROUND`] frames, so the counters are never behind by more than a moment or
    /// a few dozen messages.
    fn flush_counts(&mut self) {
        for name in self.unflushed.drain(..) {
            if let Some(p) = self.published.get_mut(&name) {
                p.topic.stats.flush(&mut p.counts);
                p.view.clear();
                p.listed = false;
            }
        }
    }

    /// A `fragment` op: kept until its operation is whole, which is then parsed.
    fn fragment(&mut self, req: Request) -> Option<Result<Request, ParseError>> {
        let id = req.id.clone();
        let Op::Fragment { data, num, total } = req.op else {
            return Some(Ok(req));
        };
        let fid = match &id {
            Some(Value::String(s)) => s.clone(),
            Some(other) => other.to_string(),
            None => {
                return Some(Err(ParseError {
                    id: None,
                    op: Some("fragment".into()),
                    message: "fragment: missing field 'id' (it names the operation the pieces \
                              make up)"
                        .into(),
                }));
            }
        };
        let err = |message: String| ParseError {
            id: id.clone(),
            op: Some("fragment".into()),
            message,
        };
        match self
            .fragments
            .add(fid, data, num, total, self.cfg.max_message_size)
        {
            Ok(None) => None,
            Ok(Some(text)) => Some(Request::from_json(text.as_bytes())),
            Err(e) => Some(Err(err(e))),
        }
    }

    async fn parse_error(&self, e: ParseError) {
        let msg = match &e.op {
            Some(op) => format!("{op}: {}", e.message.trim_start_matches(&format!("{op}: "))),
            None => e.message.clone(),
        };
        self.status("error", msg, e.id.as_ref()).await;
    }

    /// The short path of nearly every frame: a publish the topic takes at once is done
    /// here, without the future and the select of the waiting path (whose state is
    /// hundreds of bytes moved for each message). What it cannot finish comes back.
    /// `frame` is the frame's bytes when it is a JSON text frame.
    fn publish_now<'a>(&mut self, p: Publish<'a>, frame: Option<&[u8]>) -> Option<Incoming<'a>> {
        if self.gate.is_none() {
            return Some(Incoming::Publish(p));
        }
        let Publish { id, topic, msg } = p;
        match self.try_publish(&topic, msg, frame) {
            Ok(None) => None,
            Ok(Some((msg, _full))) => Some(Incoming::Publish(Publish { id, topic, msg })),
            Err(text) => Some(Incoming::Refused(id, text)),
        }
    }

    /// A `publish` from the short path: what [`Session::handle`] does for one.
    async fn handle_publish(&mut self, p: Publish<'_>) {
        if self.gate.is_none() {
            let msg =
                "publish: authentication required: send an 'auth' operation with a token first";
            return self
                .status("error", msg.into(), p.id.value().as_ref())
                .await;
        }
        if let Err(msg) = self.publish(&p.topic, p.msg).await {
            self.status("error", msg, p.id.value().as_ref()).await;
            self.clock.waited();
        }
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

    fn advertise(&mut self, topic: &str, type_name: &str, latch: bool) -> Result<(), String> {
        let name = TopicName::parse(topic).map_err(|e| format!("advertise: {e}"))?;
        if type_name.trim().is_empty() {
            return Err(format!("advertise {name}: field 'type' is empty"));
        }
        self.check("advertise", name.as_str(), GateOp::Publish)?;
        let t = self
            .router
            .advertise(self.client, &name, Schema::named(type_name), latch)
            .map_err(|e| format!("advertise: {e}"))?;
        self.published
            .entry(name.clone())
            .or_insert_with(|| Published::new(name, t));
        Ok(())
    }

    fn unadvertise(&mut self, topic: &str) -> Result<(), String> {
        let name = TopicName::parse(topic).map_err(|e| format!("unadvertise: {e}"))?;
        if self.published.remove(&name).is_none() {
            return Err(format!(
                "unadvertise {name}: this client has not advertised it"
            ));
        }
        self.router.unadvertise(self.client, &name);
        Ok(())
    }

    /// Publishes `msg` on `topic`. Backpressure for no-drop topics: while a subscriber's
    /// no-drop queue of this topic is full (the robot's link is down and nothing spills to
    /// disk), the message waits here for room — and, because this loop is what reads the
    /// socket, the client's own sends slow down with it — instead of being refused.
    async fn publish(&mut self, topic: &str, mut msg: Payload) -> Result<(), String> {
        loop {
            match self.try_publish(topic, msg, None)? {
                None => return Ok(()),
                Some((back, full)) => {
                    msg = back;
                    tracing::debug!("publish {topic}: no-drop queue full, waiting for room");
                    full.stats.no_drop_flow.wait_room().await;
                    self.clock.waited();
                }
            }
        }
    }

    /// Publishes `msg` on `topic` unless it is a no-drop topic whose queue is full; then
    /// hands the message back, with the topic to wait on. `frame` is the text frame
    /// `msg` came in, if it came in one (see [`Session::publish_on_known`]).
    fn try_publish(
        &mut self,
        topic: &str,
        msg: Payload,
        frame: Option<&[u8]>,
    ) -> Result<Option<(Payload, Arc<Topic>)>, String> {
        // Most publishes name a topic this client already publishes, spelled the same way:
        // one lookup by the client's spelling, no parse, no copy of the name.
        let msg = match self.publish_on_known(topic, msg, frame) {
            Known::Done(r) => return r,
            Known::Not(msg) => msg,
        };
        let name = TopicName::parse(topic).map_err(|e| format!("publish: {e}"))?;
        if !is_object(&msg) {
            return Err(format!("publish {name}: field 'msg' must be an object"));
        }
        self.check("publish", name.as_str(), GateOp::Publish)?;
        if !self.published.contains_key(name.as_str()) {
            self.start_publishing(name.as_str())?;
        }
        match self.publish_on_known(name.as_str(), msg, frame) {
            Known::Done(r) => r,
            Known::Not(_) => unreachable!("{name} was added to the published topics above"),
        }
    }

    /// [`Session::try_publish`] on a topic this client publishes under exactly this
    /// spelling; the message comes back untouched when it does not. When `msg` is still
    /// the JSON text it came in (a slice of `frame`, which the type check left as it
    /// was), the message is marked so: writers frame it as it is.
    fn publish_on_known(&mut self, name: &str, msg: Payload, frame: Option<&[u8]>) -> Known {
        let Session {
            published,
            gate,
            router,
            clock,
            client,
            unflushed,
            ..
        } = self;
        let Some(p) = published.get_mut(name) else {
            return Known::Not(msg);
        };
        Known::Done((|| {
            if !is_object(&msg) {
                return Err(format!("publish {name}: field 'msg' must be an object"));
            }
            // Asked for every message: rules can change while a client publishes, and the
            // gate's cache makes the repeat question cheap.
            let gate = check(gate, "publish", name, GateOp::Publish)?;
            if p.topic.stats.no_drop_flow.is_full() {
                return Ok(Some((msg, p.topic.clone())));
            }
            // Checked and completed once here, for every subscriber.
            p.list(unflushed);
            let meta = p.topic.view(&mut p.view).meta();
            let msg = router
                .transcoder()
                .normalize_cached(&meta.schema, msg, &mut p.normalize)
                .map_err(|e| {
                    format!(
                        "publish {name}: the message does not fit its type: {}",
                        e.cause_text()
                    )
                })?;
            // Still the text it came in: writers frame it as it is.
            let json_text = frame.is_some_and(|f| lies_within(f, &msg));
            let size = p.publish(*client, clock, msg, json_text);
            gate.done(name, GateOp::Publish, size);
            Ok(None)
        })())
    }

    /// A publish read by its envelope's shape (`m`, parts of `frame`), done at once when
    /// nothing stands in its way: the client publishes the topic under this spelling and
    /// may, the topic has room, and the message passes its check against the type —
    /// which is also what checks its syntax and UTF-8. The message is `frame` itself, cut
    /// down to the message, so it costs no new reference to the read buffer. Anything
    /// else hands the frame back, for the full read ([`Publish::from_json_text`]) to do
    /// and answer as for any publish.
    fn publish_shaped(&mut self, frame: Bytes, m: Matched) -> Result<(), Bytes> {
        let Some(gate) = self.gate.as_mut() else {
            return Err(frame);
        };
        let Some(p) = std::str::from_utf8(&frame[m.topic])
            .ok()
            .and_then(|topic| self.published.get_mut(topic))
        else {
            return Err(frame);
        };
        // Asked for every message: rules can change while a client publishes.
        if !gate.allows_topic(p.topic.id().0, p.name.as_str(), GateOp::Publish)
            || p.topic.stats.no_drop_flow.is_full()
        {
            return Err(frame);
        }
        p.list(&mut self.unflushed);
        let meta = p.topic.view(&mut p.view).meta();
        let checked = self.router.transcoder().normalize_json_unchecked(
            &meta.schema,
            &frame[m.msg.clone()],
            &mut p.normalize,
        );
        let (msg, json_text) = match checked {
            Ok(None) => {
                let mut msg = frame;
                msg.truncate(m.msg.end);
                msg.advance(m.msg.start);
                (Payload::json(msg), true)
            }
            Ok(Some(normal)) => (Payload::json(normal), false),
            Err(_) => return Err(frame),
        };
        let size = p.publish(self.client, &mut self.clock, msg, json_text);
        gate.done(p.name.as_str(), GateOp::Publish, size);
        Ok(())
    }

    /// The first publish on `name` without an `advertise`: rosbridge allows it on a topic
    /// whose type is already known.
    fn start_publishing(&mut self, name: &str) -> Result<(), String> {
        let name = TopicName::parse(name).map_err(|e| format!("publish: {e}"))?;
        let Some(existing) = self
            .router
            .topic(&name)
            .filter(|t| !t.meta().schema.type_name.is_empty())
        else {
            return Err(format!(
                "publish {name}: topic is not advertised; send 'advertise' with its type first"
            ));
        };
        let schema = existing.meta().schema.clone();
        let t = self
            .router
            .advertise(self.client, &name, schema, false)
            .map_err(|e| format!("publish: {e}"))?;
        self.published.insert(name.clone(), Published::new(name, t));
        Ok(())
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
        let args_json = crate::params::call_args(args).unwrap_or(Value::Null);
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
    let base = crate::queue::qos_for_options(queue_length, throttle_ms, default_queue);
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

/// A message object is a JSON object or a CBOR map.
fn is_object(p: &Payload) -> bool {
    match p.encoding {
        Encoding::Json => p.bytes.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'{'),
        Encoding::Cbor => p.bytes.first().is_some_and(|b| b >> 5 == 5),
        _ => true,
    }
}

/// Whether `p` is JSON lying within `frame` (a slice of the text frame it came in).
fn lies_within(frame: &[u8], p: &Payload) -> bool {
    if p.encoding != Encoding::Json {
        return false;
    }
    // Live buffers do not overlap: bytes inside the frame's are a slice of that frame.
    let start = p.bytes.as_ptr() as usize;
    let begin = frame.as_ptr() as usize;
    start >= begin && start + p.len() <= begin + frame.len()
}

/// Messages taken in one go that mean a burst is being read (`write_loop`).
const BURST: usize = 32;

/// Turns a writer gives the reader of a burst before it flushes (`write_loop`): each is
/// at most one tokio budget (128 operations) read, so a burst of up to about 500 small
/// messages goes out in one write, and nothing waits longer than four budgets' work.
const BURST_TURNS: u32 = 4;

async fn write_loop<K: PartsSink>(
    mut sink: K,
    outbox: Arc<Outbox>,
    mut replies: mpsc::Receiver<Reply>,
    router: Arc<Router>,
    batch: usize,
    gate: Arc<Mutex<Option<Box<dyn Gate>>>>,
    level: Arc<std::sync::atomic::AtomicU8>,
) {
    let mut warned: HashMap<TopicName, ()> = HashMap::new();
    // Negotiated at the handshake; a client without it costs this one check per message.
    let deflate = sink.deflate();
    // Frames written since the last flush, and the turns this task has given the others
    // since (see below).
    let (mut unflushed, mut turns) = (false, 0u32);
    // The batch, kept across rounds so a busy writer does not allocate one per round.
    let mut items: Vec<crate::outbox::Taken> = Vec::new();
    loop {
        let mut wrote = false;
        while let Ok(r) = replies.try_recv() {
            match r {
                Reply::Frame(m) => {
                    if sink.feed(m).await.is_err() {
                        return;
                    }
                    wrote = true;
                }
                Reply::Close(c) => return close_with(&mut sink, c).await,
            }
        }
        let now = Instant::now();
        let wake_at = outbox.take_into(&mut items, batch, 8 << 20, now);
        let took = items.len();
        // Checked on delivery, so a rule change reaches live subscriptions.
        {
            let mut g = gate.lock().unwrap_or_else(|p| p.into_inner());
            match g.as_mut() {
                Some(g) => {
                    // A batch mostly holds runs of one topic: ask once per run.
                    let mut last = None;
                    items.retain(|(_, _, m)| match last {
                        Some((id, ok)) if id == m.topic.id => ok,
                        _ => {
                            let ok = g.allows_topic(
                                m.topic.id.0,
                                m.topic.name.as_str(),
                                GateOp::Subscribe,
                            );
                            last = Some((m.topic.id, ok));
                            ok
                        }
                    })
                }
                None => items.clear(),
            }
        }
        for (slot, delivery, msg) in items.drain(..) {
            let kind = match delivery.compression {
                Compression::Cbor => FrameKind::RosbridgeCbor,
                Compression::CborRaw => FrameKind::RosbridgeCborRaw,
                Compression::Png => FrameKind::RosbridgePng,
                Compression::None => FrameKind::RosbridgeJson,
            };
            let fragment = delivery
                .fragment_size
                .map(|s| s as usize)
                .filter(|s| *s > 0);
            // A client that negotiated permessage-deflate gets a large message compressed:
            // once per message and kind, the same bytes for every such subscriber. The
            // rest (small, not worth it, or cut in rosbridge fragments) goes as below.
            if let Some(cfg) = deflate
                && fragment.is_none()
                && let Ok(Some((text, z))) = msg.deflated_frame(kind, router.transcoder(), cfg)
            {
                if crate::websocket::feed_deflated(&mut sink, text, &[], &z)
                    .await
                    .is_err()
                {
                    return;
                }
                wrote = true;
                continue;
            }
            // Most messages: JSON text as its publisher sent it, framed into the socket
            // buffer; or a frame already built, sent whole. A large message is framed
            // once for all its subscribers instead (below), and each writes that frame
            // from where it lies.
            if fragment.is_none()
                && kind == FrameKind::RosbridgeJson
                && let Some(parts) = msg.json_parts()
                && msg.payload.len() <= crate::websocket::COPY_UP_TO
            {
                if crate::websocket::feed_parts(&mut sink, &parts)
                    .await
                    .is_err()
                {
                    return;
                }
                wrote = true;
                continue;
            }
            let msg = match fragment {
                None => match Message::take_built_frame(msg, kind) {
                    Ok(frame) => {
                        if sink.feed(frame).await.is_err() {
                            return;
                        }
                        wrote = true;
                        continue;
                    }
                    Err(msg) => msg,
                },
                Some(_) => msg,
            };
            let mut frame = msg.rosbridge_frame(kind, router.transcoder());
            if frame.is_err() && kind == FrameKind::RosbridgeCborRaw {
                // No raw serialization for this message: the CBOR form is the closest.
                frame = msg.rosbridge_frame(FrameKind::RosbridgeCbor, router.transcoder());
            }
            let frame = match frame {
                Ok(f) => f,
                Err(e) => {
                    outbox.record_drop(slot, DropReason::Encode);
                    let wants = level.load(std::sync::atomic::Ordering::Relaxed) <= 1;
                    if wants && warned.insert(msg.topic.name.clone(), ()).is_none() {
                        let text = outbound::status("warning", &e.to_string(), None);
                        if sink.feed(WsMessage::text(text)).await.is_err() {
                            return;
                        }
                    }
                    continue;
                }
            };
            match (fragment, &frame) {
                (Some(size), WsMessage::Text(t)) if t.len() > size => {
                    let fid = format!("{}_{}", msg.topic.name, msg.seq);
                    for piece in outbound::fragments(&fid, t.as_str(), size) {
                        if sink.feed(WsMessage::text(piece)).await.is_err() {
                            return;
                        }
                    }
                }
                _ => {
                    if sink.feed(frame).await.is_err() {
                        return;
                    }
                }
            }
            wrote = true;
        }
        unflushed |= wrote;
        // While a burst is being read (a full run of a publisher's operations came in),
        // a turn for the other tasks before the flush lets the next run join this system
        // call: each flush wakes the client, and on a busy hub those wake-ups cost more
        // than the writes. A publisher's read yields after tokio's budget of operations,
        // so a burst of a few hundred comes as several runs; turns continue while runs
        // keep coming, up to `BURST_TURNS` (a bound on what waits unflushed). A trickle
        // (a few messages per wake-up, as each of many subscribers of a topic sees) is
        // flushed at once; a turn would only add work.
        if took >= BURST && unflushed && turns < BURST_TURNS {
            turns += 1;
            tokio::task::yield_now().await;
            continue;
        }
        if unflushed {
            if sink.flush().await.is_err() {
                return;
            }
            (unflushed, turns) = (false, 0);
        }
        if took > 0 {
            continue;
        }
        if !wait_for_work(&mut sink, &mut replies, &outbox, wake_at).await {
            return;
        }
    }
}
