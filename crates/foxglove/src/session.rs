//! One Foxglove WebSocket connection.
//!
//! Two halves, as a rosbridge session: the reader (this task) reads the client's
//! operations and applies them to the router, follows the router's topics
//! ([`Router::watch_topics`]) to advertise and unadvertise channels as topics come and
//! go, and follows the call table's services; the writer ([`crate::writer`]) sends the
//! client's outbox as `MessageData` plus the reader's replies. An operation that cannot
//! be done is answered with a `status` error naming the problem and the session goes
//! on; only a transport failure (or a message over the size limit, which the socket
//! layer cannot skip) ends it.
//!
//! Channels are this session's numbering of the topics the client may see; a
//! subscription is a router subscription of the topic, so it has the router's bounded
//! queue (drops counted on the topic) and counts as interest toward the robot that
//! publishes it, like any subscriber.

use std::collections::{HashMap, HashSet};
use std::sync::Arc;

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::{ChannelPeer, PeerMsg};
use fleetlink_relay::gate::{Op as GateOp, SessionAuth};
use fleetlink_relay::router::{SubOptions, SubscriptionId, Target};
use fleetlink_relay::transcode::NormalizeCache;
use fleetlink_relay::websocket::deflate::DeflateConfig;
use fleetlink_relay::websocket::liveness::{LivenessConfig, Peer, Watch};
use fleetlink_relay::websocket::{ClientMessage, PartsSink};
use fleetlink_relay::{ClientKind, Router, Topic, TopicId, TopicName};
use futures_util::{Stream, StreamExt};
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::protocol::CloseFrame;
use tokio_tungstenite::tungstenite::protocol::frame::coding::CloseCode;
use tokio_tungstenite::tungstenite::{Error as WsError, Message as WsMessage};
use tokio_util::sync::CancellationToken;

use crate::channels::{self, CLIENT_ENCODINGS, ChannelForm};
use crate::client::Client;
use crate::protocol::{self, ClientBinary, ClientChannel, ClientOp, Subscription};
use crate::services::{self, SessionServices};
use crate::writer::{self, Deliveries, Delivering, Reply};

/// Settings shared by all Foxglove sessions of one server.
#[derive(Debug, Clone)]
pub struct SessionConfig {
    /// The server's name in `serverInfo`.
    pub name: String,
    /// Changes whenever the server restarts (`serverInfo`'s `sessionId`), so a client
    /// can tell a reconnection to the same server from a new one.
    pub session_id: String,
    /// Messages the writer sends per socket flush.
    pub batch: usize,
    /// How often the client is pinged, and how long it may show no progress before it
    /// is closed and what it held released (`fleetlink_relay::websocket::liveness`).
    pub liveness: LivenessConfig,
    /// permessage-deflate for clients that offer it (`None`: never negotiated), read by
    /// the server answering the handshake.
    pub deflate: Option<DeflateConfig>,
}

impl Default for SessionConfig {
    fn default() -> Self {
        SessionConfig {
            name: "fleetlink".into(),
            session_id: fleetlink_relay::unix_nanos().to_string(),
            batch: 256,
            liveness: LivenessConfig::default(),
            deflate: Some(DeflateConfig::default()),
        }
    }
}

/// The next change of the rules, if they can change; a closed watch (the hub going
/// away) is never ready again.
async fn rules_changed(rules: &mut Option<tokio::sync::watch::Receiver<u64>>) -> Option<()> {
    if let Some(r) = rules
        && r.changed().await.is_ok()
    {
        return Some(());
    }
    std::future::pending().await
}

/// Replies the reader hands to the writer. Bounded: a client that floods bad requests
/// without reading the answers is slowed down (its reader waits), nobody else is.
const REPLY_QUEUE: usize = 256;

/// Runs a session until the client leaves, shows no progress for the silence limit
/// (`cfg.liveness`; `conn` says how to sample its connection), or `shutdown` is cancelled. `sink` and
/// `stream` are an accepted WebSocket's halves ([`fleetlink_relay::websocket`]), or
/// channels in tests. `auth.gate` is what the client may do (`None`: it presented no
/// credential where anonymous access is off, and sees and may do nothing; the protocol
/// has no operation to authenticate later, so `auth.guard` is not used).
pub async fn serve<K, S>(
    sink: K,
    mut stream: S,
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
    let (client, outbox) = router.connect(ClientKind::Foxglove, addr);
    if sink.deflate().is_some() {
        router.note_deflate(client);
    }
    let (peer, peer_rx) = ChannelPeer::new();
    router.calls.attach(client, peer);
    let watch = router.watch_topics();
    let (reply_tx, reply_rx) = mpsc::channel(REPLY_QUEUE);
    let mut live = Watch::new(cfg.liveness, conn.progress, reply_tx.clone());
    let deliveries: Deliveries = Arc::default();
    let writer = tokio::spawn(writer::write_loop(
        sink,
        outbox.clone(),
        reply_rx,
        router.clone(),
        cfg.batch,
        auth.gate.as_ref().map(|g| g.fork()),
        deliveries.clone(),
    ));
    let mut s = Session {
        client: Client {
            router: router.clone(),
            id: client,
            gate: auth.gate,
            replies: reply_tx,
        },
        deliveries,
        listed: HashSet::new(),
        channels: HashMap::new(),
        channel_topics: HashMap::new(),
        next_channel: 1,
        subs: HashMap::new(),
        published: HashMap::new(),
        services: SessionServices::default(),
        clock: fleetlink_relay::StampClock::default(),
    };
    s.start(&cfg).await;
    let cancelled = shutdown.cancelled();
    tokio::pin!(cancelled);
    let mut calls_open = true;
    // A change of the access rules shows in the channels as soon as it is made (a topic
    // newly allowed appears, one no longer allowed goes); deliveries follow it anyway, as
    // the writer asks for every message.
    let mut rules = s.client.gate.as_ref().and_then(|g| g.rules_changed());
    // Set when the client showed no progress for the silence limit: how long. Every step
    // that may wait on the client (a full reply queue) is raced against that.
    let mut gone = None;
    loop {
        let step = tokio::select! {
            biased;
            _ = &mut cancelled => break,
            silent = live.gone() => Err(silent),
            m = peer_rx.recv(), if calls_open => match m {
                Some(m) => live.race(s.on_peer(m)).await.map(|()| true),
                None => {
                    calls_open = false;
                    Ok(true)
                }
            },
            _ = watch.changed() => {
                let changed = watch.take();
                live.race(s.sync_channels(changed)).await.map(|()| true)
            }
            Some(()) = rules_changed(&mut rules) => live.race(s.recheck_rules()).await.map(|()| true),
            f = stream.next() => {
                let Some(f) = f else { break };
                live.read();
                live.race(s.on_frame(f)).await
            }
        };
        match step {
            Ok(true) => {}
            Ok(false) => break,
            Err(silent) => {
                gone = Some(silent);
                break;
            }
        }
    }
    if shutdown.is_cancelled() {
        let away = CloseFrame {
            code: CloseCode::Away,
            reason: "the server is shutting down".into(),
        };
        let _ = s.client.replies.try_send(Reply::Close(Some(away)));
    }
    if let Some(silent) = gone {
        tracing::info!(
            "Foxglove client {}: no progress for {} ms (no bytes read, its connection not \
             draining); closing it and releasing what it held",
            addr.map_or_else(|| "?".into(), |a| a.to_string()),
            silent.as_millis()
        );
    }
    router.disconnect(client);
    drop(s);
    drop(live);
    if gone.is_some() {
        // Its socket may never drain: the writer is not waited for.
        writer.abort();
    }
    let _ = writer.await;
}

/// A channel advertised to the client.
struct Advertised {
    id: u32,
    topic: TopicId,
    form: ChannelForm,
}

/// A subscription of the client.
struct Sub {
    channel: u32,
    topic: TopicId,
    router_sub: SubscriptionId,
}

/// A channel the client advertised to publish on.
struct Publishing {
    name: TopicName,
    topic: Arc<Topic>,
    encoding: Encoding,
    seq: u64,
    normalize: NormalizeCache,
}

pub(crate) struct Session {
    /// The router, the client's id and gate, and where its replies go.
    client: Client,
    /// The writer's view of the subscriptions (std Mutex: taken by the reader when a
    /// subscription changes and by the writer once per batch, never across an await).
    deliveries: Deliveries,
    /// Every listed topic, whether the client may see it or not (kept from the topics
    /// watch, so that a rule change can be looked for without asking the router).
    listed: HashSet<TopicName>,
    /// Channels by topic, and the topic of each channel id.
    channels: HashMap<TopicName, Advertised>,
    channel_topics: HashMap<u32, TopicName>,
    next_channel: u32,
    /// By the client's subscription id.
    subs: HashMap<u32, Sub>,
    /// By the client's channel id.
    published: HashMap<u32, Publishing>,
    services: SessionServices,
    clock: fleetlink_relay::StampClock,
}

impl Session {
    /// `serverInfo`, then the services (the channels follow from the topics watch).
    async fn start(&mut self, cfg: &SessionConfig) {
        let caps = [
            protocol::CAP_CLIENT_PUBLISH,
            protocol::CAP_SERVICES,
            protocol::CAP_PARAMETERS,
        ];
        let info = protocol::server_info(&cfg.name, &caps, &CLIENT_ENCODINGS, &cfg.session_id);
        self.client.send_text(info).await;
        match &self.client.gate {
            Some(_) => services::watch_services(&self.client),
            None => {
                self.client
                    .error(
                        "not authenticated: this hub allows no anonymous access; connect with \
                     ?token=<token> in the URL (or an Authorization: Bearer header)",
                    )
                    .await
            }
        }
    }

    /// One message from the client; `false` ends the session.
    async fn on_frame(&mut self, f: Result<ClientMessage, WsError>) -> bool {
        match f {
            Ok(ClientMessage::Text(t)) => match protocol::parse_client_text(&t) {
                Ok(op) => self.on_op(op).await,
                Err(e) => self.client.error(&e.to_string()).await,
            },
            Ok(ClientMessage::Binary(b)) => match protocol::parse_client_binary(&b) {
                Ok(ClientBinary::MessageData { channel, payload }) => {
                    if let Err(e) = self.publish(channel, payload).await {
                        self.client.error(&e).await;
                    }
                }
                Ok(ClientBinary::ServiceCallRequest(call)) => {
                    self.services.call_service(&mut self.client, call).await
                }
                Err(e) => self.client.error(&e.to_string()).await,
            },
            Ok(ClientMessage::Ping(p)) => {
                let _ = self
                    .client
                    .replies
                    .send(Reply::Frame(WsMessage::Pong(p)))
                    .await;
            }
            Ok(ClientMessage::Pong(_)) => {}
            Ok(ClientMessage::Close(c)) => {
                let echo = c.map(|c| CloseFrame {
                    code: c.code,
                    reason: "".into(),
                });
                let _ = self.client.replies.send(Reply::Close(echo)).await;
                return false;
            }
            Err(e) => {
                let (code, reason) = match &e {
                    // The socket layer cannot skip the rest of a message over the limit:
                    // the client hears why before the connection closes.
                    WsError::Capacity(e) => (CloseCode::Size, format!("message too large: {e}")),
                    WsError::Protocol(e) => (CloseCode::Protocol, e.to_string()),
                    WsError::Utf8(e) => (CloseCode::Invalid, e.clone()),
                    // A compressed message that does not inflate.
                    WsError::Io(e) if e.kind() == std::io::ErrorKind::InvalidData => {
                        (CloseCode::Protocol, e.to_string())
                    }
                    _ => return false,
                };
                self.client.error(&reason).await;
                let close = CloseFrame {
                    code,
                    reason: reason.into(),
                };
                let _ = self.client.replies.send(Reply::Close(Some(close))).await;
                return false;
            }
        }
        true
    }

    async fn on_op(&mut self, op: ClientOp) {
        match op {
            ClientOp::Subscribe { subscriptions } => {
                for s in subscriptions {
                    if let Err(e) = self.subscribe(s) {
                        self.client.error(&e).await;
                    }
                }
            }
            ClientOp::Unsubscribe { subscription_ids } => {
                for id in subscription_ids {
                    if !self.unsubscribe(id) {
                        self.client
                            .error(&format!("unsubscribe: no subscription {id}"))
                            .await;
                    }
                }
            }
            ClientOp::Advertise { channels } => {
                for c in channels {
                    if let Err(e) = self.advertise(c) {
                        self.client.error(&e).await;
                    }
                }
            }
            ClientOp::Unadvertise { channel_ids } => {
                for id in channel_ids {
                    if let Err(e) = self.unadvertise(id) {
                        self.client.error(&e).await;
                    }
                }
            }
            ClientOp::GetParameters {
                parameter_names,
                id,
            } => {
                self.services
                    .get_parameters(&mut self.client, parameter_names, id)
                    .await
            }
        }
    }

    /// Brings the channels up to date with the topics `names` (those that changed, or all
    /// of them when the rules are looked at again): a topic the client
    /// may see and that is listed gets a channel, one that went (or that it may no
    /// longer see) loses it along with its subscriptions, and one whose form changed (a
    /// schema arrived) is advertised anew under a new id.
    async fn sync_channels(&mut self, names: Vec<TopicName>) {
        let mut added = Vec::new();
        let mut removed = Vec::new();
        for name in names {
            let listed = self.client.router.snapshot(&name).filter(|s| s.listed());
            if listed.is_some() {
                self.listed.insert(name.clone());
            } else {
                self.listed.remove(&name);
            }
            let now = listed
                .filter(|_| {
                    self.client
                        .gate
                        .as_mut()
                        .is_some_and(|g| g.allows(name.as_str(), GateOp::Subscribe))
                })
                .map(|s| {
                    (
                        s.meta.id,
                        ChannelForm::of(&s.meta.schema, self.client.router.transcoder()),
                    )
                });
            if let Some(old) = self.channels.get(&name) {
                if now
                    .as_ref()
                    .is_some_and(|(id, form)| *id == old.topic && *form == old.form)
                {
                    continue;
                }
                let old = self.channels.remove(&name).expect("present");
                self.channel_topics.remove(&old.id);
                self.drop_channel_subs(old.id);
                removed.push(old.id);
            }
            if let Some((topic, form)) = now {
                let id = self.next_channel;
                self.next_channel += 1;
                added.push(channels::advertised(&form, id, name.as_str()));
                self.channel_topics.insert(id, name.clone());
                self.channels.insert(name, Advertised { id, topic, form });
            }
        }
        if !removed.is_empty() {
            self.client.send_text(protocol::unadvertise(&removed)).await;
        }
        if !added.is_empty() {
            self.client.send_text(protocol::advertise(&added)).await;
        }
    }

    /// The listed topics whose visibility under the gate no longer matches the channels
    /// (a rule changed), brought up to date. Each question is the gate's cached decision.
    async fn recheck_rules(&mut self) {
        let Some(gate) = self.client.gate.as_mut() else {
            return;
        };
        let stale: Vec<TopicName> = self
            .listed
            .iter()
            .filter(|n| {
                gate.allows(n.as_str(), GateOp::Subscribe) != self.channels.contains_key(*n)
            })
            .cloned()
            .collect();
        if !stale.is_empty() {
            self.sync_channels(stale).await;
        }
    }

    fn drop_channel_subs(&mut self, channel: u32) {
        let ids: Vec<u32> = self
            .subs
            .iter()
            .filter(|(_, s)| s.channel == channel)
            .map(|(id, _)| *id)
            .collect();
        for id in ids {
            self.unsubscribe(id);
        }
    }

    fn subscribe(&mut self, s: Subscription) -> Result<(), String> {
        if self.subs.contains_key(&s.id) {
            return Err(format!(
                "subscribe: subscription id {} is already in use",
                s.id
            ));
        }
        let Some(name) = self.channel_topics.get(&s.channel_id).cloned() else {
            return Err(format!(
                "subscribe: unknown channel {} (not advertised, or gone)",
                s.channel_id
            ));
        };
        // The protocol allows one subscription per channel: a second would deliver every
        // message twice.
        if let Some((id, _)) = self.subs.iter().find(|(_, x)| x.channel == s.channel_id) {
            return Err(format!(
                "subscribe: channel {} ({name}) is already subscribed as {id}",
                s.channel_id
            ));
        }
        self.client
            .check("subscribe", name.as_str(), GateOp::Subscribe)?;
        let ch = &self.channels[&name];
        let (topic, encoding) = (ch.topic, ch.form.encoding);
        let router_sub = self
            .client
            .router
            .subscribe(
                self.client.id,
                Target::Exact(name.clone()),
                SubOptions::default(),
            )
            .map_err(|e| format!("subscribe {name}: {e}"))?;
        self.subs.insert(
            s.id,
            Sub {
                channel: s.channel_id,
                topic,
                router_sub,
            },
        );
        self.update_delivery(topic, Some(encoding));
        Ok(())
    }

    /// Removes subscription `id`; `false` when there is none.
    fn unsubscribe(&mut self, id: u32) -> bool {
        let Some(sub) = self.subs.remove(&id) else {
            return false;
        };
        self.client
            .router
            .unsubscribe(self.client.id, sub.router_sub);
        self.update_delivery(sub.topic, None);
        true
    }

    /// Tells the writer the subscriptions of `topic` as they now are.
    fn update_delivery(&self, topic: TopicId, encoding: Option<Encoding>) {
        let ids: Vec<u32> = self
            .subs
            .iter()
            .filter(|(_, s)| s.topic == topic)
            .map(|(id, _)| *id)
            .collect();
        let mut d = self.deliveries.lock().unwrap_or_else(|p| p.into_inner());
        if ids.is_empty() {
            d.remove(&topic);
            return;
        }
        let encoding = encoding
            .or_else(|| d.get(&topic).map(|x| x.encoding))
            .unwrap_or(Encoding::Json);
        d.insert(
            topic,
            Delivering {
                encoding,
                subs: ids.into(),
            },
        );
    }

    /// A client channel: publishing on `topic` with the same rules as a rosbridge
    /// `advertise` (the gate's publish right; the type is the client's `schemaName`, or
    /// the topic's when the client leaves it empty).
    fn advertise(&mut self, c: ClientChannel) -> Result<(), String> {
        let name = TopicName::parse(&c.topic).map_err(|e| format!("advertise: {e}"))?;
        let Some(encoding) = channels::from_wire_name(&c.encoding) else {
            return Err(format!(
                "advertise {name}: encoding '{}' is not supported (use one of {})",
                c.encoding.chars().take(32).collect::<String>(),
                CLIENT_ENCODINGS.join(", ")
            ));
        };
        if self.published.contains_key(&c.id) {
            return Err(format!(
                "advertise {name}: client channel id {} is already in use",
                c.id
            ));
        }
        self.client
            .check("advertise", name.as_str(), GateOp::Publish)?;
        let schema = if c.schema_name.trim().is_empty() {
            match self.client.router.topic(&name) {
                Some(t) if !t.meta().schema.type_name.is_empty() => t.meta().schema.clone(),
                _ => {
                    return Err(format!(
                        "advertise {name}: 'schemaName' is empty and the topic's type is not known"
                    ));
                }
            }
        } else {
            let text = c.schema.unwrap_or_default();
            let encoding = match c.schema_encoding.as_deref() {
                Some(e @ ("ros1msg" | "ros2msg")) if !text.is_empty() => e.to_owned(),
                _ => String::new(),
            };
            Schema {
                type_name: c.schema_name.clone(),
                text: if encoding.is_empty() {
                    String::new()
                } else {
                    text
                },
                encoding,
            }
        };
        let topic = self
            .client
            .router
            .advertise(self.client.id, &name, schema, false)
            .map_err(|e| format!("advertise {name}: {e}"))?;
        self.published.insert(
            c.id,
            Publishing {
                name,
                topic,
                encoding,
                seq: 0,
                normalize: NormalizeCache::default(),
            },
        );
        Ok(())
    }

    fn unadvertise(&mut self, id: u32) -> Result<(), String> {
        let Some(p) = self.published.remove(&id) else {
            return Err(format!("unadvertise: no client channel {id}"));
        };
        // The router counts one advertisement per client and topic: it goes with the
        // last of this client's channels on the topic.
        if !self.published.values().any(|o| o.name == p.name) {
            self.client.router.unadvertise(self.client.id, &p.name);
        }
        Ok(())
    }

    /// A message on client channel `id`: checked as a rosbridge publish is (the gate,
    /// asked for every message; JSON checked against the type and completed), then
    /// fanned out. A no-drop topic whose queue is full makes this wait, which slows the
    /// client's own socket, as for rosbridge.
    async fn publish(&mut self, id: u32, bytes: Bytes) -> Result<(), String> {
        let Some(p) = self.published.get_mut(&id) else {
            return Err(format!(
                "message data: client channel {id} is not advertised"
            ));
        };
        let gate = self
            .client
            .gate
            .as_mut()
            .ok_or_else(|| format!("publish {}: not authenticated", p.name))?;
        if !gate.allows_topic(p.topic.id().0, p.name.as_str(), GateOp::Publish) {
            return Err(format!(
                "publish {}: not allowed for {}",
                p.name,
                gate.principal()
            ));
        }
        let mut msg = Payload::new(p.encoding, bytes);
        if p.encoding == Encoding::Json {
            let meta = p.topic.meta();
            msg = self
                .client
                .router
                .transcoder()
                .normalize_cached(&meta.schema, msg, &mut p.normalize)
                .map_err(|e| {
                    format!(
                        "publish {}: the message does not fit its type: {}",
                        p.name,
                        e.cause_text()
                    )
                })?;
        }
        while p.topic.stats.no_drop_flow.is_full() {
            p.topic.stats.no_drop_flow.wait_room().await;
        }
        p.seq += 1;
        let size = msg.len();
        let (_, stamp) = self.clock.now();
        p.topic.publish(self.client.id, p.seq, stamp, msg);
        gate.done(p.name.as_str(), GateOp::Publish, size);
        Ok(())
    }

    async fn on_peer(&mut self, m: PeerMsg) {
        match m {
            PeerMsg::Changed(change) => {
                self.services
                    .service_changed(&mut self.client, change)
                    .await
            }
            PeerMsg::Event(ev) => self.services.call_event(&mut self.client, ev).await,
            // This client provides no services: nothing is called on it.
            PeerMsg::Call(_) | PeerMsg::Cancel(_) => {}
        }
    }
}
