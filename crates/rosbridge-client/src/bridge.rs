//! The bridge's tasks: the connection loop with its reconnect backoff and the router
//! side (messages both ways, calls both ways); discovery is in `crate::discovery`.
//!
//! One task ([`run`]) owns the WebSocket, the router client's outbox and its call-table
//! channel; it writes everything the server gets. Discovery runs beside it per
//! connection and asks the server's rosapi through [`Shared::request`], whose answers the
//! connection loop hands back by id. State that outlives a connection (what is bridged,
//! which calls are in flight) lives in [`Shared`] (`crate::shared`) behind a std mutex
//! that is never held across an await.

use std::sync::Arc;
use std::sync::atomic::Ordering::Relaxed;
use std::time::{Duration, Instant};

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::{
    CallEvent, CallOptions, CallRequest, CallStatus, ChannelPeer, PeerMsg, PeerReceiver,
    ServiceChange,
};
use fleetlink_relay::outbox::Outbox;
use fleetlink_relay::router::{SubOptions, Target};
use fleetlink_relay::{ClientKind, Message, Router, TopicName};
use futures_util::{SinkExt, StreamExt};
use serde_json::Value;
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_util::sync::CancellationToken;

use crate::RosbridgeClientError;
use crate::ops::{self, ServerOp, text_of};
use crate::options::RosbridgeClientOptions;
use crate::shared::{Forwarded, Serving, Shared};

pub use crate::shared::RosbridgeClientStats;

/// Frames waiting for the connection task (from discovery and call handling). Bounded:
/// when the server reads too slowly to take 1024 control frames, further ones are
/// dropped and counted as refusals, and the requests behind them time out.
const OUT_QUEUE: usize = 1024;

/// Bridges the rosbridge server at `opts.url` with `router` until `shutdown`. A URL that
/// cannot work is an error at once; a server that is down or drops the link is retried
/// with backoff for as long as the bridge runs.
pub async fn run(
    opts: RosbridgeClientOptions,
    router: Arc<Router>,
    stats: Arc<RosbridgeClientStats>,
    shutdown: CancellationToken,
) -> Result<(), RosbridgeClientError> {
    let url = opts.connect_url()?;
    let (client, outbox) = router.connect(
        ClientKind::Internal {
            role: "rosbridge-client".into(),
        },
        None,
    );
    let (peer, peer_rx) = ChannelPeer::new();
    router.calls.attach(client, peer);
    let shared = Arc::new(Shared::new(opts, router.clone(), client, stats));
    for name in &shared.opts.subscribe {
        if let Err(e) = router.subscribe(client, Target::Exact(name.clone()), SubOptions::default())
        {
            tracing::warn!("rosbridge: cannot subscribe to {name}: {e}");
        }
    }
    for re in &shared.opts.offer.include {
        router.calls.watch(client, re.clone());
    }
    let shown = shared.opts.url.clone();
    let mut backoff = shared.opts.reconnect_initial;
    let mut failures = 0u32;
    loop {
        let connect = tokio_tungstenite::connect_async_tls_with_config(
            url.as_str(),
            None,
            true,
            shared
                .opts
                .tls
                .clone()
                .map(tokio_tungstenite::Connector::Rustls),
        );
        let attempt = tokio::select! {
            r = tokio::time::timeout(CONNECT_TIMEOUT, connect) => r,
            _ = shutdown.cancelled() => break,
        };
        match attempt {
            Ok(Ok((ws, _))) => {
                let n = shared.stats.connects.fetch_add(1, Relaxed);
                if n == 0 {
                    tracing::info!("rosbridge: connected to {shown}");
                } else {
                    tracing::info!(
                        "rosbridge: connected to {shown} again; subscribing and advertising again"
                    );
                }
                failures = 0;
                backoff = shared.opts.reconnect_initial;
                let end = connection(&shared, ws, &outbox, &peer_rx, &shutdown).await;
                shared.connection_ended();
                match end {
                    End::Shutdown => break,
                    End::Lost(why) => {
                        tracing::warn!("rosbridge: link to {shown} lost ({why}); connecting again")
                    }
                }
            }
            Ok(Err(e)) => {
                if failures == 0 {
                    tracing::warn!(
                        "rosbridge: cannot connect to {shown}: {e}; retrying with backoff up to {:?}",
                        shared.opts.reconnect_max
                    );
                }
                failures += 1;
            }
            Err(_) => {
                if failures == 0 {
                    tracing::warn!(
                        "rosbridge: {shown} did not answer within {CONNECT_TIMEOUT:?}; retrying"
                    );
                }
                failures += 1;
            }
        }
        // While not connected: what the fleet sends is dropped and calls fail at once.
        let wait = tokio::time::sleep(backoff);
        tokio::pin!(wait);
        loop {
            tokio::select! {
                _ = &mut wait => break,
                _ = shutdown.cancelled() => {
                    router.disconnect(client);
                    return Ok(());
                }
                _ = outbox.ready() => {
                    let n = outbox.take(256, 8 << 20, Instant::now()).items.len();
                    shared.stats.dropped_down.fetch_add(n as u64, Relaxed);
                }
                Some(m) = peer_rx.recv() => shared.on_peer(m, None),
            }
        }
        backoff = (backoff * 2).min(shared.opts.reconnect_max);
    }
    router.disconnect(client);
    Ok(())
}

/// Longest wait for the server to accept a connection.
const CONNECT_TIMEOUT: Duration = Duration::from_secs(5);

enum End {
    Shutdown,
    Lost(String),
}

type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

/// One connection, until it drops or the bridge stops.
async fn connection(
    shared: &Arc<Shared>,
    ws: Ws,
    outbox: &Arc<Outbox>,
    peer_rx: &PeerReceiver,
    shutdown: &CancellationToken,
) -> End {
    let (mut sink, mut stream) = ws.split();
    let (tx, mut rx) = mpsc::channel::<WsMessage>(OUT_QUEUE);
    shared.connected(tx.clone());
    let discovery = tokio::spawn(crate::discovery::discovery(shared.clone()));
    let end = loop {
        tokio::select! {
            _ = shutdown.cancelled() => {
                let _ = sink.send(WsMessage::Close(None)).await;
                break End::Shutdown;
            }
            frame = stream.next() => match frame {
                Some(Ok(WsMessage::Text(text))) => shared.on_frame(text.as_str()),
                Some(Ok(WsMessage::Close(c))) => {
                    break End::Lost(c.map_or("closed by the server".into(), |c| {
                        format!("closed by the server: {} {}", c.code, c.reason.as_str())
                    }));
                }
                // Pings are answered by tungstenite; nothing asked for binary frames.
                Some(Ok(_)) => {}
                Some(Err(e)) => break End::Lost(e.to_string()),
                None => break End::Lost("closed".into()),
            },
            Some(frame) = rx.recv() => {
                if let Err(e) = sink.send(frame).await {
                    break End::Lost(e.to_string());
                }
            }
            _ = outbox.ready() => {
                let batch = outbox.take(64, 8 << 20, Instant::now());
                let mut lost = None;
                for (_, _, msg) in batch.items {
                    for frame in shared.down(&msg) {
                        if let Err(e) = sink.feed(frame).await {
                            lost = Some(e.to_string());
                            break;
                        }
                    }
                }
                if lost.is_none()
                    && let Err(e) = sink.flush().await
                {
                    lost = Some(e.to_string());
                }
                if let Some(why) = lost {
                    break End::Lost(why);
                }
            }
            Some(m) = peer_rx.recv() => shared.on_peer(m, Some(&tx)),
        }
    };
    discovery.abort();
    end
}

impl Shared {
    /// One text frame from the server.
    fn on_frame(&self, text: &str) {
        let op = match ServerOp::parse(text) {
            Ok(op) => op,
            Err(e) => {
                tracing::debug!("rosbridge: unreadable frame from the server ({e})");
                return;
            }
        };
        match op.op.as_str() {
            "publish" => self.on_publish(&op),
            "service_response" => self.on_service_response(&op),
            "call_service" => self.on_server_call(&op),
            "action_feedback" => self.on_action_feedback(&op),
            "action_result" => self.on_action_result(&op),
            "status" => self.on_status(&op),
            _ => {}
        }
    }

    fn on_publish(&self, op: &ServerOp<'_>) {
        let (Some(topic), Some(msg)) = (&op.topic, op.msg) else {
            return;
        };
        let (t, seq) = {
            let mut st = self.lock();
            let Some(up) = st.up.get_mut(topic) else {
                return;
            };
            up.seq += 1;
            (up.topic.clone(), up.seq)
        };
        let payload = Payload::json(Bytes::copy_from_slice(msg.get().as_bytes()));
        t.publish(self.client, seq, fleetlink_relay::unix_nanos(), payload);
        self.stats.messages_up.fetch_add(1, Relaxed);
    }

    fn on_service_response(&self, op: &ServerOp<'_>) {
        let Some(id) = op.id_str() else {
            return;
        };
        let ok = op.result.unwrap_or(true);
        let mut st = self.lock();
        if let Some(tx) = st.waiting.remove(id) {
            drop(st);
            let reply = match (ok, op.values) {
                (true, Some(v)) => Ok(v.to_owned()),
                (true, None) => Ok(empty_object()),
                (false, v) => Err(text_of(v)),
            };
            let _ = tx.send(reply);
            return;
        }
        let Some(f) = st.forwarded.remove(id) else {
            return;
        };
        st.forwarded_ids.remove(&f.call);
        drop(st);
        let (status, payload, text) = if ok {
            let body = op.values.map_or("{}", |v| v.get());
            let payload = Payload::json(Bytes::copy_from_slice(body.as_bytes()));
            (CallStatus::Ok, Some(payload), String::new())
        } else {
            (CallStatus::Failed, None, text_of(op.values))
        };
        self.router
            .calls
            .respond(self.client, f.call, status, payload, text);
    }

    fn on_action_feedback(&self, op: &ServerOp<'_>) {
        let (Some(id), Some(values)) = (op.id_str(), op.values) else {
            return;
        };
        let call = match self.lock().forwarded.get(id) {
            Some(f) if f.action => f.call,
            _ => return,
        };
        let payload = Payload::json(Bytes::copy_from_slice(values.get().as_bytes()));
        self.router.calls.feedback(self.client, call, payload);
    }

    fn on_action_result(&self, op: &ServerOp<'_>) {
        let Some(id) = op.id_str() else {
            return;
        };
        let f = {
            let mut st = self.lock();
            let Some(f) = st.forwarded.remove(id) else {
                return;
            };
            st.forwarded_ids.remove(&f.call);
            f
        };
        // action_msgs/GoalStatus numbers (`send_action_goal` is ROS 2's).
        let status = match (op.status, op.result) {
            (Some(4), _) => CallStatus::Ok,
            (Some(5), _) => CallStatus::Cancelled,
            (Some(6), _) => CallStatus::Aborted,
            (Some(_), _) | (None, Some(false)) => CallStatus::Failed,
            (None, _) => CallStatus::Ok,
        };
        let values = op.values.map(|v| v.get()).filter(|v| v.starts_with('{'));
        let payload = values.map(|v| Payload::json(Bytes::copy_from_slice(v.as_bytes())));
        let text = if payload.is_none() {
            text_of(op.values)
        } else {
            String::new()
        };
        self.router
            .calls
            .respond(self.client, f.call, status, payload, text);
    }

    /// A program on the robot calls a fleet service this client advertised there.
    fn on_server_call(&self, op: &ServerOp<'_>) {
        let Some(service) = &op.service else {
            return;
        };
        let refuse = |text: String| {
            let st = self.lock();
            let body = Value::from(text).to_string();
            let frame = ops::service_response(op.id.as_ref(), service, body.as_bytes(), false);
            self.send(&st, WsMessage::binary_text(frame));
        };
        let Ok(name) = TopicName::parse(service) else {
            return refuse(format!("{service} is not a valid service name"));
        };
        if !self.lock().offered.contains_key(service) {
            return refuse(format!("{service} is not offered by fleetlink"));
        }
        let args = op.args.map_or("{}", |a| a.get());
        let payload = Payload::json(Bytes::copy_from_slice(args.as_bytes()));
        let opts = CallOptions {
            timeout: Some(self.opts.call_timeout),
            ..CallOptions::default()
        };
        match self.router.calls.call(self.client, &name, payload, opts) {
            Ok(call) => {
                self.stats.calls_served.fetch_add(1, Relaxed);
                let type_name = self
                    .router
                    .calls
                    .service(&name)
                    .map(|s| s.schema.type_name.clone())
                    .unwrap_or_default();
                let serving = Serving {
                    id: op.id.clone(),
                    service: service.clone(),
                    type_name,
                };
                self.lock().serving.insert(call, serving);
            }
            Err(e) => refuse(format!("{service}: {}", e.text)),
        }
    }

    fn on_status(&self, op: &ServerOp<'_>) {
        let level = op.level.as_deref().unwrap_or("error");
        if !matches!(level, "error" | "warning") {
            return;
        }
        self.stats.refusals.fetch_add(1, Relaxed);
        let text = text_of(op.msg);
        match op.id_str() {
            Some(id) if id.starts_with("sub:") => tracing::warn!(
                "rosbridge: the server refused to subscribe {} ({level}): {text}; other topics go on",
                &id[4..]
            ),
            Some(id) if id.starts_with("adv:") => tracing::warn!(
                "rosbridge: the server refused to advertise {} ({level}): {text}",
                &id[4..]
            ),
            Some(id) => {
                // A request that failed with a status instead of an answer.
                let waiting = self.lock().waiting.remove(id);
                match waiting {
                    Some(tx) => {
                        let _ = tx.send(Err(text));
                    }
                    None => tracing::warn!("rosbridge: the server says ({level}, {id}): {text}"),
                }
            }
            None => tracing::warn!("rosbridge: the server says ({level}): {text}"),
        }
    }

    /// A router message for the server: its `advertise` first if it is the topic's first
    /// on this connection, then the `publish`.
    fn down(&self, msg: &Message) -> Vec<WsMessage> {
        let name = msg.topic.name.as_str();
        let mut frames = Vec::new();
        {
            let mut st = self.lock();
            if !st.advertised.contains(name) {
                let ty = msg.topic.schema.type_name.as_str();
                if ty.is_empty() {
                    if st.unadvertisable.insert(name.to_owned()) {
                        tracing::warn!(
                            "rosbridge: cannot advertise {name} on the server: its type is unknown"
                        );
                    }
                    self.stats.dropped_down.fetch_add(1, Relaxed);
                    return frames;
                }
                let ty = type_for_server(ty, st.ros_version);
                frames.push(WsMessage::text(ops::advertise(name, &ty)));
                st.advertised.insert(name.to_owned());
                tracing::info!("rosbridge: publishing {name} ({ty}) on the server");
            }
        }
        match msg.payload_in(Encoding::Json, self.router.transcoder()) {
            Ok(json) => {
                let frame = fleetlink_proto::rosbridge::outbound::publish_json(name, &json);
                frames.push(WsMessage::binary_text(frame.to_vec()));
                self.stats.messages_down.fetch_add(1, Relaxed);
            }
            Err(e) => {
                self.stats.dropped_down.fetch_add(1, Relaxed);
                tracing::debug!("rosbridge: dropping a message of {name}: {e}");
            }
        }
        frames
    }

    /// The call table's news: calls to the server's services, cancels, answers to the
    /// server programs' calls, offered services coming and going.
    fn on_peer(&self, m: PeerMsg, out: Option<&mpsc::Sender<WsMessage>>) {
        match m {
            PeerMsg::Call(req) => self.forward_call(req, out.is_some()),
            PeerMsg::Cancel(call) => {
                // A goal stays forwarded: the server's `action_result` (cancelled) ends
                // it. A service call's caller gave up: its answer is not wanted.
                let mut st = self.lock();
                let Some(id) = st.forwarded_ids.get(&call).cloned() else {
                    return;
                };
                if st.forwarded.get(&id).is_some_and(|f| f.action) {
                    let action = st.forwarded[&id].name.clone();
                    self.send(&st, WsMessage::text(ops::cancel_action_goal(&id, &action)));
                } else {
                    st.forwarded_ids.remove(&call);
                    st.forwarded.remove(&id);
                }
            }
            PeerMsg::Event(CallEvent::Done {
                id,
                status,
                payload,
                text,
            }) => {
                let Some(Serving {
                    id: rid,
                    service,
                    type_name,
                }) = self.lock().serving.remove(&id)
                else {
                    return;
                };
                let body = match payload.filter(|_| status == CallStatus::Ok) {
                    Some(p) => {
                        let schema = Schema::named(format!("{type_name}_Response"));
                        self.router
                            .transcoder()
                            .convert(&schema, &p, Encoding::Json)
                            .map_err(|e| e.to_string())
                    }
                    None if status == CallStatus::Ok => Ok(Bytes::from_static(b"{}")),
                    None => Err(format!("{service} {}: {text}", status.as_str())),
                };
                let frame = match body {
                    Ok(b) => ops::service_response(rid.as_ref(), &service, &b, true),
                    Err(why) => {
                        let t = Value::from(why).to_string();
                        ops::service_response(rid.as_ref(), &service, t.as_bytes(), false)
                    }
                };
                let st = self.lock();
                self.send(&st, WsMessage::binary_text(frame));
            }
            PeerMsg::Event(CallEvent::Feedback { .. }) => {}
            PeerMsg::Changed(ServiceChange::Added(info)) => {
                let name = info.name.as_str();
                if info.action || info.provider == self.client || !self.opts.offer.matches(name) {
                    return;
                }
                let mut st = self.lock();
                let ty = type_for_server(&info.schema.type_name, st.ros_version);
                tracing::info!("rosbridge: offering fleet service {name} ({ty}) on the server");
                st.offered.insert(name.to_owned(), ty.clone());
                self.send(&st, WsMessage::text(ops::advertise_service(name, &ty)));
            }
            PeerMsg::Changed(ServiceChange::Removed(info)) => {
                let name = info.name.as_str();
                let mut st = self.lock();
                if st.offered.remove(name).is_some() {
                    self.send(&st, WsMessage::text(ops::unadvertise_service(name)));
                }
            }
        }
    }

    /// A fleet call of one of the server's services (or a goal for one of its actions),
    /// sent on as `call_service` / `send_action_goal`.
    fn forward_call(&self, req: CallRequest, connected: bool) {
        let name = req.service.name.as_str().to_owned();
        let refuse = |status, text: String| {
            self.router
                .calls
                .respond(self.client, req.id, status, None, text);
        };
        if !connected {
            return refuse(
                CallStatus::NoProvider,
                format!("{name}: the robot's rosbridge server is not connected"),
            );
        }
        let (type_name, action) = match self.lock().exposed.get(&name) {
            Some(e) => (e.type_name.clone(), e.action),
            None => {
                return refuse(
                    CallStatus::NoProvider,
                    format!("{name} is not exposed by the rosbridge client"),
                );
            }
        };
        let part = if action { "_Goal" } else { "_Request" };
        let schema = Schema::named(format!("{}{part}", req.service.schema.type_name));
        let args = match self
            .router
            .transcoder()
            .convert(&schema, &req.payload, Encoding::Json)
        {
            Ok(b) => b,
            Err(e) => return refuse(CallStatus::Failed, e.to_string()),
        };
        let mut st = self.lock();
        let id = self.next_id(&mut st, if action { "goal" } else { "call" });
        let frame = if action {
            ops::send_action_goal(&id, &name, &type_name, &args)
        } else {
            ops::call_service(&id, &name, Some(&type_name), &args)
        };
        if !self.send(&st, WsMessage::binary_text(frame)) {
            drop(st);
            return refuse(
                CallStatus::Busy,
                format!("{name}: the robot's rosbridge server is not taking requests"),
            );
        }
        st.forwarded.insert(
            id.clone(),
            Forwarded {
                call: req.id,
                name,
                action,
            },
        );
        st.forwarded_ids.insert(req.id, id);
        self.stats.calls_forwarded.fetch_add(1, Relaxed);
    }
}

fn empty_object() -> Box<serde_json::value::RawValue> {
    serde_json::value::RawValue::from_string("{}".into()).expect("{} is JSON")
}

/// A type as the server names it: `pkg/T` for a ROS 1 server, as known otherwise.
fn type_for_server(type_name: &str, ros_version: Option<u64>) -> String {
    if ros_version == Some(1) {
        let parts: Vec<&str> = type_name.split('/').collect();
        if let [pkg, _, t] = parts[..] {
            return format!("{pkg}/{t}");
        }
    }
    type_name.to_owned()
}

/// Text frames built as bytes (JSON is UTF-8 by construction).
trait BinaryText {
    fn binary_text(bytes: Vec<u8>) -> WsMessage;
}

impl BinaryText for WsMessage {
    fn binary_text(bytes: Vec<u8>) -> WsMessage {
        match String::from_utf8(bytes) {
            Ok(s) => WsMessage::text(s),
            Err(e) => WsMessage::text(String::from_utf8_lossy(e.as_bytes()).into_owned()),
        }
    }
}

#[cfg(test)]
mod tests {
    use tokio::sync::oneshot;

    use super::*;

    fn shared() -> Shared {
        let router = Arc::new(Router::new(Arc::new(
            fleetlink_relay::transcode::GenericTranscoder,
        )));
        let (client, _) = router.connect(ClientKind::Internal { role: "t".into() }, None);
        Shared::new(
            RosbridgeClientOptions::new("ws://robot:9090"),
            router,
            client,
            Arc::new(RosbridgeClientStats::default()),
        )
    }

    /// A server that refuses one topic's subscribe (an unknown type, say): counted and
    /// logged, and the bridge reads the server's next operations as before.
    #[test]
    fn a_refused_subscribe_is_counted_and_the_bridge_goes_on() {
        let s = shared();
        let (tx, _rx) = oneshot::channel();
        s.lock().waiting.insert("rosapi:1".into(), tx);
        s.on_frame(r#"{"op":"status","level":"error","id":"sub:/odd","msg":"unknown type x/Y"}"#);
        assert_eq!(s.stats.refusals.load(Relaxed), 1);
        // Info-level status ops are not refusals; other requests are untouched.
        s.on_frame(r#"{"op":"status","level":"info","msg":"hello"}"#);
        assert_eq!(s.stats.refusals.load(Relaxed), 1);
        assert!(s.lock().waiting.contains_key("rosapi:1"));
        // A request refused with a status ends with the server's text.
        let (tx, mut rx) = oneshot::channel();
        s.lock().waiting.insert("rosapi:2".into(), tx);
        s.on_frame(r#"{"op":"status","level":"error","id":"rosapi:2","msg":"no such service"}"#);
        assert_eq!(rx.try_recv().unwrap().unwrap_err(), "no such service");
    }

    #[test]
    fn types_are_written_as_a_ros_1_server_names_them() {
        assert_eq!(
            type_for_server("std_msgs/msg/String", Some(1)),
            "std_msgs/String"
        );
        assert_eq!(
            type_for_server("std_msgs/msg/String", Some(2)),
            "std_msgs/msg/String"
        );
        assert_eq!(
            type_for_server("std_msgs/String", Some(1)),
            "std_msgs/String"
        );
    }
}
