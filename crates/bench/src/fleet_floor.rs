//! `fleetlink bench fleet-floor`: the least a hub does to carry `fleetlink bench fleet`'s
//! traffic — the floor under the hub's figure in the fleet bench, measured the same way.
//!
//! It speaks just enough `fleetlink.v1` for the bench's robots and subscribers: `HELLO` is
//! answered with `WELCOME`, `PING` with `PONG`, every `ADVERTISE` with `INTEREST` (every
//! topic is wanted), and each `MESSAGE` is passed to the subscribers whose `SUBSCRIBE`
//! (a name, or a regular expression with the regex flag) matched the topic when it was
//! advertised, under the alias that subscriber's link gave it. It does not authenticate,
//! keep QoS queues, acknowledge, check access rules, keep statistics or serve rosbridge;
//! subscriptions made after a topic was advertised do not see it (the bench subscribes
//! first). What it keeps is the shape the hub has, so the figures compare: tokio on every
//! core, the hub's WebSocket reader and writer (`fleetlink_relay::websocket`), a reader
//! task and a writer task per connection, one write per subscriber per read.

use std::collections::HashMap;
use std::net::SocketAddr;
use std::sync::{Arc, Mutex};

use anyhow::Context;
use bytes::BytesMut;
use fleetlink_proto::SUBPROTOCOL;
use fleetlink_proto::frame::{Frame, SUBSCRIBE_REGEX};
use fleetlink_relay::websocket::ClientMessage;
use futures_util::StreamExt;
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::Message;
use tokio_tungstenite::tungstenite::handshake::server::{ErrorResponse, Request, Response};
use tokio_tungstenite::tungstenite::http::HeaderValue;
use tokio_tungstenite::tungstenite::protocol::WebSocketConfig;

#[derive(clap::Args)]
pub struct Args {
    /// Address to serve on; port 0 picks a free one. The address taken is printed on
    /// stdout.
    #[arg(long, default_value = "127.0.0.1:0")]
    listen: SocketAddr,
}

/// Largest message the floor takes, as the hub's default.
const MAX_MESSAGE: usize = 16 << 20;

/// A subscriber's link: where its writes go, and the aliases it has been given.
struct SubLink {
    out: mpsc::UnboundedSender<Message>,
    next_alias: Mutex<u32>,
}

/// One subscription: what it matches (a name, or the hub's whole-name pattern), on which
/// link.
struct Subscription {
    matches: Box<dyn Fn(&str) -> bool + Send + Sync>,
    link: Arc<SubLink>,
}

/// A topic's subscribers as a publisher's link holds them: (link, alias on that link).
type Targets = Vec<(Arc<SubLink>, u32)>;

#[derive(Default)]
struct Shared {
    subscriptions: Mutex<Vec<Subscription>>,
}

/// Answers the upgrade with the subprotocol the bench's clients ask for. (The error type
/// is tungstenite's, an HTTP response, hence the lint.)
#[allow(clippy::result_large_err)]
fn with_subprotocol(_: &Request, mut resp: Response) -> Result<Response, ErrorResponse> {
    resp.headers_mut().insert(
        "Sec-WebSocket-Protocol",
        HeaderValue::from_static(SUBPROTOCOL),
    );
    Ok(resp)
}

pub fn run(args: Args) -> anyhow::Result<()> {
    let rt = tokio::runtime::Runtime::new().context("starting the async runtime")?;
    rt.block_on(async {
        let listener = tokio::net::TcpListener::bind(args.listen)
            .await
            .with_context(|| format!("binding {}", args.listen))?;
        println!("listening on {}", listener.local_addr()?);
        let shared = Arc::new(Shared::default());
        loop {
            let (tcp, _) = listener.accept().await.context("accepting")?;
            let _ = tcp.set_nodelay(true);
            tokio::spawn(serve(tcp, shared.clone()));
        }
    })
}

async fn serve(tcp: tokio::net::TcpStream, shared: Arc<Shared>) {
    let cfg = WebSocketConfig::default().read_buffer_size(64 * 1024);
    let Ok(ws) =
        tokio_tungstenite::accept_hdr_async_with_config(tcp, with_subprotocol, Some(cfg)).await
    else {
        return;
    };
    let (sink, mut stream) = fleetlink_relay::websocket::server(ws.into_inner(), MAX_MESSAGE);
    let tx = super::ws_floor::spawn_writer(sink);
    let me = Arc::new(SubLink {
        out: tx,
        next_alias: Mutex::new(0),
    });
    // This link's topics as a publisher: its alias → the subscribers' links and aliases.
    let mut published: HashMap<u32, Targets> = HashMap::new();
    // Per subscriber link (by address), what one read of ours sends it.
    let mut batches: HashMap<usize, (Arc<SubLink>, BytesMut)> = HashMap::new();
    let mut reply = BytesMut::new();
    while let Some(Ok(m)) = stream.next().await {
        let ClientMessage::Binary(b) = m else {
            continue;
        };
        for f in fleetlink_proto::frame::frames(&b) {
            let Ok(f) = f else { return };
            match f {
                Frame::Hello { heartbeat_ms, .. } => Frame::Welcome {
                    session: "floor".into(),
                    namespace: String::new(),
                    hub_time_ns: fleetlink_relay::unix_nanos(),
                    heartbeat_ms,
                    features: 0,
                }
                .encode(&mut reply),
                Frame::Ping { id, sent_ns } => {
                    reply.extend_from_slice(&super::conn::pong(id, sent_ns))
                }
                Frame::Subscribe { pattern, flags, .. } => {
                    let matches: Box<dyn Fn(&str) -> bool + Send + Sync> =
                        if flags & SUBSCRIBE_REGEX != 0 {
                            let Ok(re) = fleetlink_relay::Router::compile_pattern(&pattern) else {
                                continue;
                            };
                            Box::new(move |t| re.is_match(t))
                        } else {
                            Box::new(move |t| t == pattern)
                        };
                    let s = Subscription {
                        matches,
                        link: me.clone(),
                    };
                    shared.subscriptions.lock().expect("not poisoned").push(s);
                }
                Frame::Advertise {
                    alias,
                    topic,
                    schema,
                    encoding,
                    flags,
                } => {
                    let mut targets = Targets::new();
                    for s in shared.subscriptions.lock().expect("not poisoned").iter() {
                        if !(s.matches)(&topic) {
                            continue;
                        }
                        let sub_alias = {
                            let mut n = s.link.next_alias.lock().expect("not poisoned");
                            *n += 1;
                            *n
                        };
                        let advertise = Frame::Advertise {
                            alias: sub_alias,
                            topic: topic.clone(),
                            schema: schema.clone(),
                            encoding,
                            flags,
                        };
                        let _ = s.link.out.send(Message::Binary(advertise.to_bytes()));
                        targets.push((s.link.clone(), sub_alias));
                    }
                    published.insert(alias, targets);
                    Frame::Interest {
                        alias,
                        wanted: true,
                    }
                    .encode(&mut reply);
                }
                Frame::Message {
                    alias,
                    seq,
                    stamp_ns,
                    payload,
                } => {
                    for (link, sub_alias) in published.get(&alias).into_iter().flatten() {
                        let batch = &mut batches
                            .entry(Arc::as_ptr(link) as usize)
                            .or_insert_with(|| (link.clone(), BytesMut::new()))
                            .1;
                        fleetlink_proto::frame::encode_message(
                            batch, *sub_alias, seq, stamp_ns, &payload,
                        );
                    }
                }
                _ => {}
            }
        }
        for (link, batch) in batches.values_mut() {
            if !batch.is_empty() {
                let _ = link.out.send(Message::Binary(batch.split().freeze()));
            }
        }
        if !reply.is_empty() {
            let _ = me.out.send(Message::Binary(reply.split().freeze()));
        }
        tokio::task::consume_budget().await;
    }
}
