//! `fleetlink bench ws-floor`: the least a rosbridge-style WebSocket server does to pass
//! each message on — the floor under the hub's figure in `fleetlink bench delivery`.
//!
//! It serves WebSocket connections on `--listen` until it is killed. A text frame that
//! contains `"subscribe"` makes its connection a subscriber, one that contains
//! `"advertise"` is ignored, and every other text frame is sent on, as the same bytes, to
//! every subscriber. It does not parse JSON, check types, authenticate, keep topics or
//! queue with a policy. What it keeps is the shape the hub has, so the two figures
//! compare: tokio, a reader task and a writer task per connection, the reader giving way
//! after each tokio budget of operations, and the writer flushing when it has nothing
//! more to write. `--websocket` picks the WebSocket layer: `fleetlink`, the one the hub's
//! rosbridge sessions run on (`fleetlink_relay::websocket`), or `tungstenite`
//! (tokio-tungstenite's stream, split, with the 64 KiB read buffer the hub used), to
//! measure what each costs. Run it where `fleetlink bench delivery --protocol
//! rosbridge-json --server-pid <pid>` can measure it: the hub's figure minus this one is
//! what the hub's own work costs per message.

use std::net::SocketAddr;
use std::sync::{Arc, Mutex};

use anyhow::Context;
use fleetlink_relay::websocket::ClientMessage;
use futures_util::{Sink, SinkExt, Stream, StreamExt};
use tokio::sync::mpsc;
use tokio_tungstenite::tungstenite::protocol::WebSocketConfig;
use tokio_tungstenite::tungstenite::{Error as WsError, Message, Utf8Bytes};

#[derive(clap::Args)]
pub struct Args {
    /// Address to serve on; port 0 picks a free one. The address taken is printed on
    /// stdout.
    #[arg(long, default_value = "127.0.0.1:0")]
    listen: SocketAddr,
    /// The WebSocket layer under the relay.
    #[arg(long, value_enum, default_value_t = Layer::Fleetlink)]
    websocket: Layer,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum Layer {
    /// The hub's own reader and writer halves (`fleetlink_relay::websocket`).
    Fleetlink,
    /// tokio-tungstenite's `WebSocketStream`, split into its two halves.
    Tungstenite,
}

type Subscribers = Arc<Mutex<Vec<mpsc::UnboundedSender<Message>>>>;

/// Largest message the relay takes, as the hub's default.
const MAX_MESSAGE: usize = 16 << 20;

pub fn run(args: Args) -> anyhow::Result<()> {
    let rt = tokio::runtime::Runtime::new().context("starting the async runtime")?;
    rt.block_on(async {
        let listener = tokio::net::TcpListener::bind(args.listen)
            .await
            .with_context(|| format!("binding {}", args.listen))?;
        println!("listening on {}", listener.local_addr()?);
        let subscribers = Subscribers::default();
        loop {
            let (tcp, _) = listener.accept().await.context("accepting")?;
            // As the hub does; a connection where it fails is still served.
            let _ = tcp.set_nodelay(true);
            tokio::spawn(accept(tcp, args.websocket, subscribers.clone()));
        }
    })
}

async fn accept(tcp: tokio::net::TcpStream, layer: Layer, subscribers: Subscribers) {
    let cfg = WebSocketConfig::default().read_buffer_size(64 * 1024);
    let Ok(ws) = tokio_tungstenite::accept_async_with_config(tcp, Some(cfg)).await else {
        return;
    };
    match layer {
        Layer::Fleetlink => {
            let (sink, stream) = fleetlink_relay::websocket::server(ws.into_inner(), MAX_MESSAGE);
            relay(sink, stream, subscribers).await
        }
        Layer::Tungstenite => {
            let (sink, stream) = ws.split();
            relay(sink, stream, subscribers).await
        }
    }
}

/// A received message as the relay needs it: its text, checked as UTF-8, if it is text.
trait Received {
    fn into_text(self) -> Result<Option<Utf8Bytes>, WsError>;
}

/// tungstenite checked the text as it read it.
impl Received for Message {
    fn into_text(self) -> Result<Option<Utf8Bytes>, WsError> {
        Ok(match self {
            Message::Text(t) => Some(t),
            _ => None,
        })
    }
}

/// The hub's reader leaves the check to the reader of the text: here, one pass.
impl Received for ClientMessage {
    fn into_text(self) -> Result<Option<Utf8Bytes>, WsError> {
        match self {
            ClientMessage::Text(b) => Utf8Bytes::try_from(b)
                .map(Some)
                .map_err(|e| WsError::Utf8(e.to_string())),
            _ => Ok(None),
        }
    }
}

/// A connection's writer task, as the hub has one: writes what is queued, flushing when
/// nothing more is; the returned sender queues for it. Shared by the floors.
pub(super) fn spawn_writer<K>(mut sink: K) -> mpsc::UnboundedSender<Message>
where
    K: Sink<Message, Error = WsError> + Unpin + Send + 'static,
{
    let (tx, mut rx) = mpsc::unbounded_channel::<Message>();
    tokio::spawn(async move {
        while let Some(m) = rx.recv().await {
            if sink.feed(m).await.is_err() {
                return;
            }
            while let Ok(m) = rx.try_recv() {
                if sink.feed(m).await.is_err() {
                    return;
                }
            }
            if sink.flush().await.is_err() {
                return;
            }
        }
    });
    tx
}

async fn relay<K, S, M>(sink: K, mut stream: S, subscribers: Subscribers)
where
    K: Sink<Message, Error = WsError> + Unpin + Send + 'static,
    S: Stream<Item = Result<M, WsError>> + Unpin,
    M: Received,
{
    let tx = spawn_writer(sink);
    // The subscribers as of this connection's last publish; taken again after a new
    // subscription anywhere would need a shared generation, which a floor can do without:
    // the bench subscribes before it publishes.
    let mut targets = Vec::new();
    while let Some(Ok(m)) = stream.next().await {
        let Ok(text) = m.into_text() else {
            return;
        };
        if let Some(text) = text {
            if text.as_str().contains("\"subscribe\"") {
                subscribers.lock().expect("not poisoned").push(tx.clone());
            } else if !text.as_str().contains("\"advertise\"") {
                if targets.is_empty() {
                    targets = subscribers.lock().expect("not poisoned").clone();
                }
                let m = Message::Text(text);
                for t in &targets {
                    let _ = t.send(m.clone());
                }
            }
        }
        tokio::task::consume_budget().await;
    }
}
