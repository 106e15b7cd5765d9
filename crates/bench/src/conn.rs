//! One bench client's `fleetlink.v1` connection: connect with the subprotocol, `HELLO` →
//! `WELCOME`, and a barrier (`PING` answered by `PONG`) that tells the client the hub has
//! processed everything sent before it.
//!
//! The hub handles one connection's frames in order, so once the `PONG` for a barrier
//! `PING` arrives, an `ADVERTISE` or `SUBSCRIBE` sent before it is in the router.

use std::time::Duration;

use anyhow::{Context, bail};
use bytes::{Bytes, BytesMut};
use fleetlink_proto::frame::{Frame, Level, VERSION};
use fleetlink_proto::{Encoding, SUBPROTOCOL, Schema};
use fleetlink_relay::link::{LinkEvent, LinkIn};
use futures_util::{SinkExt, StreamExt};
use tokio::net::TcpStream;
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_tungstenite::tungstenite::client::IntoClientRequest;
use tokio_tungstenite::tungstenite::http::HeaderValue;
use tokio_tungstenite::tungstenite::protocol::WebSocketConfig;
use tokio_tungstenite::{MaybeTlsStream, WebSocketStream};

pub type Ws = WebSocketStream<MaybeTlsStream<TcpStream>>;

/// Connecting plus every setup exchange must finish within this.
const SETUP_TIMEOUT: Duration = Duration::from_secs(10);
/// Heartbeat the bench clients propose; the hub may change it in `WELCOME`.
const HEARTBEAT_MS: u32 = 1000;
/// Ping id of the setup barrier; keepalive pings count up from 1.
pub const BARRIER_PING: u64 = u64::MAX;

/// Bytes a bench client reads at most at a time.
const READ_BUFFER: usize = 4096;

/// Largest message the bench accepts from the hub (a whole chunk-packed write).
const MAX_MESSAGE: usize = 64 << 20;

/// Type name the bench topics are advertised with; the hub never looks inside.
pub const BENCH_TYPE: &str = "fleetlink_bench/msg/Blob";

/// A connected, welcomed client.
pub struct Conn {
    pub ws: Ws,
    pub link: LinkIn,
    /// Period of our keepalive pings: half the agreed heartbeat, so the hub, which closes a
    /// link silent for two heartbeats, always hears from us in time.
    pub keepalive: Duration,
}

/// Accepts `ws://host:port[/path]` or a bare `host:port`.
pub fn hub_url(hub: &str) -> String {
    if hub.contains("://") {
        hub.to_owned()
    } else {
        format!("ws://{hub}")
    }
}

pub async fn connect(url: &str, robot: &str, token: &str) -> anyhow::Result<Conn> {
    connect_from(url, robot, token, None).await
}

/// The hub refused a connection for now (HTTP 503: its handshake admission is full);
/// `retry_after` is what it asked for. Agents back off and retry; so do the benches.
#[derive(Debug)]
pub struct Busy {
    pub retry_after: Option<Duration>,
}

impl std::fmt::Display for Busy {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "the hub is busy (HTTP 503)")?;
        if let Some(d) = self.retry_after {
            write!(f, ", retry after {} s", d.as_secs())?;
        }
        Ok(())
    }
}

impl std::error::Error for Busy {}

/// As [`connect`], from the local address `source` when given (a plain `ws://` URL only):
/// a fleet on one machine spreads its connections over loopback addresses as a real fleet
/// comes from many, so per-address limits and ephemeral ports are not what a bench hits.
pub async fn connect_from(
    url: &str,
    robot: &str,
    token: &str,
    source: Option<std::net::IpAddr>,
) -> anyhow::Result<Conn> {
    tokio::time::timeout(SETUP_TIMEOUT, connect_inner(url, robot, token, source))
        .await
        .with_context(|| format!("{robot}: connecting to {url} timed out"))?
}

/// Opens the WebSocket, from `source` if given.
async fn open_ws(
    url: &str,
    source: Option<std::net::IpAddr>,
    config: WebSocketConfig,
) -> Result<Ws, tokio_tungstenite::tungstenite::Error> {
    let mut req = url.into_client_request()?;
    req.headers_mut().insert(
        "Sec-WebSocket-Protocol",
        HeaderValue::from_static(SUBPROTOCOL),
    );
    let Some(source) = source.filter(|_| url.starts_with("ws://")) else {
        return Ok(
            tokio_tungstenite::connect_async_with_config(req, Some(config), true)
                .await?
                .0,
        );
    };
    let host = req
        .uri()
        .host()
        .unwrap_or_default()
        .trim_matches(['[', ']']);
    let port = req.uri().port_u16().unwrap_or(80);
    let dest = tokio::net::lookup_host((host, port))
        .await?
        .find(|a| a.is_ipv4() == source.is_ipv4())
        .ok_or_else(|| std::io::Error::other(format!("{host} has no address like {source}")))?;
    let socket = if source.is_ipv4() {
        tokio::net::TcpSocket::new_v4()?
    } else {
        tokio::net::TcpSocket::new_v6()?
    };
    socket.bind(std::net::SocketAddr::new(source, 0))?;
    let tcp = socket.connect(dest).await?;
    tcp.set_nodelay(true)?;
    Ok(
        tokio_tungstenite::client_async_with_config(req, MaybeTlsStream::Plain(tcp), Some(config))
            .await?
            .0,
    )
}

async fn connect_inner(
    url: &str,
    robot: &str,
    token: &str,
    source: Option<std::net::IpAddr>,
) -> anyhow::Result<Conn> {
    // tungstenite zeroes the free part of its read buffer before every read: at its
    // 128 KiB default, a thousand simulated robots reading their acknowledgements spent
    // half the bench's CPU in memset. A frame's whole length is reserved once its header
    // is read, so small reads cost nothing on large messages.
    let config = WebSocketConfig::default()
        .read_buffer_size(READ_BUFFER)
        .max_message_size(Some(MAX_MESSAGE))
        .max_frame_size(Some(MAX_MESSAGE));
    let mut ws = match open_ws(url, source, config).await {
        Ok(ws) => ws,
        Err(tokio_tungstenite::tungstenite::Error::Http(resp)) if resp.status() == 503 => {
            let retry_after = fleetlink_agent::uplink::retry_after(resp.headers());
            return Err(Busy { retry_after }.into());
        }
        Err(e) => return Err(e).with_context(|| format!("{robot}: cannot connect to {url}")),
    };
    let hello = Frame::Hello {
        version: VERSION,
        robot: robot.to_owned(),
        token: token.to_owned(),
        heartbeat_ms: HEARTBEAT_MS,
        outbox_epoch: 0,
        mirror: String::new(),
    };
    ws.send(WsMessage::Binary(hello.to_bytes()))
        .await
        .with_context(|| format!("{robot}: sending HELLO"))?;
    let mut link = LinkIn::default();
    let heartbeat_ms = loop {
        let Some(m) = ws.next().await else {
            bail!("{robot}: hub closed the connection before WELCOME");
        };
        let WsMessage::Binary(b) = m.with_context(|| format!("{robot}: reading WELCOME"))? else {
            continue;
        };
        let mut welcome = None;
        for f in fleetlink_proto::frame::frames(&b) {
            match link.on_frame(f.with_context(|| format!("{robot}: malformed frame"))?) {
                Ok(LinkEvent::Control(Frame::Welcome { heartbeat_ms, .. })) => {
                    welcome = Some(heartbeat_ms)
                }
                Ok(LinkEvent::Control(Frame::Status { text, .. })) => {
                    bail!("{robot}: hub refused: {text}")
                }
                _ => {}
            }
        }
        if let Some(hb) = welcome {
            break hb;
        }
    };
    Ok(Conn {
        ws,
        link,
        keepalive: Duration::from_millis(u64::from(heartbeat_ms.max(20) / 2)),
    })
}

impl Conn {
    /// Sends `frames` followed by a barrier `PING` and waits for its `PONG`, answering the
    /// hub's own pings meanwhile. Everything else received is fed to the link state.
    pub async fn send_and_sync(&mut self, frames: &[Frame], who: &str) -> anyhow::Result<()> {
        let mut buf = BytesMut::new();
        for f in frames {
            f.encode(&mut buf);
        }
        Frame::Ping {
            id: BARRIER_PING,
            sent_ns: fleetlink_relay::unix_nanos(),
        }
        .encode(&mut buf);
        let sync = async {
            self.ws.send(WsMessage::Binary(buf.freeze())).await?;
            loop {
                let Some(m) = self.ws.next().await else {
                    bail!("hub closed the connection");
                };
                let WsMessage::Binary(b) = m? else {
                    continue;
                };
                for f in fleetlink_proto::frame::frames(&b) {
                    match self.link.on_frame(f?) {
                        Ok(LinkEvent::Control(Frame::Pong { id, .. })) if id == BARRIER_PING => {
                            return Ok(());
                        }
                        Ok(LinkEvent::Control(Frame::Ping { id, sent_ns })) => {
                            self.ws.send(WsMessage::Binary(pong(id, sent_ns))).await?;
                        }
                        Ok(LinkEvent::Control(Frame::Status {
                            level: Level::Error,
                            text,
                            ..
                        })) => bail!("hub: {text}"),
                        _ => {}
                    }
                }
            }
        };
        tokio::time::timeout(SETUP_TIMEOUT, sync)
            .await
            .with_context(|| format!("{who}: no answer from the hub during setup"))?
            .with_context(|| format!("{who}: setup"))
    }
}

/// The `PONG` answering a hub `PING`, as one WebSocket message.
pub fn pong(id: u64, sent_ns: u64) -> Bytes {
    Frame::Pong {
        id,
        echo_ns: sent_ns,
        responder_ns: fleetlink_relay::unix_nanos(),
    }
    .to_bytes()
}

/// A keepalive `PING` appended to `buf`.
pub fn put_ping(buf: &mut BytesMut, id: u64) {
    Frame::Ping {
        id,
        sent_ns: fleetlink_relay::unix_nanos(),
    }
    .encode(buf);
}

/// The topic publisher `i` sends on.
pub fn topic_of(i: usize) -> String {
    format!("/bench_pub_{i}/data")
}

/// The publisher index of a bench topic name, if it is one.
pub fn publisher_of(topic: &str) -> Option<usize> {
    topic
        .strip_prefix("/bench_pub_")?
        .strip_suffix("/data")?
        .parse()
        .ok()
}

/// `ADVERTISE` of publisher `i`'s topic under alias 1 (its only topic).
pub fn advertise(i: usize) -> Frame {
    Frame::Advertise {
        alias: 1,
        topic: topic_of(i),
        schema: Schema {
            type_name: BENCH_TYPE.into(),
            encoding: "ros2msg".into(),
            text: "uint8[] data\n".into(),
        },
        encoding: Encoding::Cdr,
        flags: 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bench_topic_names_round_trip_and_others_are_ignored() {
        for i in [0, 7, 99] {
            assert_eq!(publisher_of(&topic_of(i)), Some(i));
        }
        assert_eq!(publisher_of("/bench_pub_x/data"), None);
        assert_eq!(publisher_of("/robot1/scan"), None);
        assert_eq!(publisher_of("/bench_pub_1/data/extra"), None);
    }

    #[test]
    fn hub_url_accepts_a_bare_address() {
        assert_eq!(hub_url("127.0.0.1:8080"), "ws://127.0.0.1:8080");
        assert_eq!(hub_url("wss://hub.example/"), "wss://hub.example/");
    }
}
