//! `fleetlink play FILE.mcap --hub URL`: a recording published again with its original
//! timing, so an incident can be watched on the dashboard, in Foxglove, or by any
//! rosbridge client.
//!
//! The player is a Foxglove WebSocket client of the hub (`clientPublish`): each channel
//! of the file is advertised with its encoding and schema and its messages are sent as
//! the bytes in the file — CDR, ROS 1 or JSON, never converted on the way. Message `i`
//! goes out at `start + (log_time_i − log_time_0) / rate`; with `--loop` the file starts
//! again after its last message. The caller needs the right to publish the topics (under
//! `--prefix` if given, e.g. to keep a replay apart from a live robot's names).

use std::collections::HashMap;
use std::path::PathBuf;
use std::time::Duration;

use anyhow::{Context, bail};
use bytes::{BufMut, BytesMut};
use fleetlink_record::read::{Channel, Item, McapReader};
use futures_util::{SinkExt, StreamExt};
use serde_json::{Value, json};
use tokio::time::Instant;
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_tungstenite::tungstenite::client::IntoClientRequest;
use tokio_tungstenite::tungstenite::http::HeaderValue;

use super::remote::Remote;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The MCAP file.
    file: PathBuf,
    #[command(flatten)]
    remote: Remote,
    /// Speed: 2 plays twice as fast, 0.5 at half speed.
    #[arg(long, default_value_t = 1.0)]
    rate: f64,
    /// Start again after the last message, until interrupted.
    #[arg(long = "loop")]
    repeat: bool,
    /// Only these topics (whole-name regular expressions, as recorded).
    #[arg(long, num_args = 1.., value_name = "PATTERN")]
    topics: Vec<String>,
    /// Publish under this namespace (`/replay` turns `/robot1/scan` into
    /// `/replay/robot1/scan`).
    #[arg(long, value_name = "NAMESPACE")]
    prefix: Option<String>,
}

/// Attempts to connect while the hub's handshake admission is full (HTTP 503).
const CONNECT_ATTEMPTS: u32 = 8;

pub fn run(args: Args) -> anyhow::Result<()> {
    super::init_logging("warn");
    if !(args.rate.is_finite() && args.rate > 0.0 && args.rate <= 1000.0) {
        bail!(
            "--rate {}: give a speed factor above 0 and at most 1000",
            args.rate
        );
    }
    let filter = if args.topics.is_empty() {
        None
    } else {
        let joined = args
            .topics
            .iter()
            .map(|t| format!("(?:{t})"))
            .collect::<Vec<_>>()
            .join("|");
        Some(
            fleetlink_relay::Router::compile_pattern(&joined)
                .map_err(|e| anyhow::anyhow!("--topics: {e}"))?,
        )
    };
    let prefix = match &args.prefix {
        Some(p) => {
            let p = p.trim_end_matches('/');
            fleetlink_relay::TopicName::parse(p)
                .map_err(|e| anyhow::anyhow!("--prefix {p}: {e}"))?;
            p.to_owned()
        }
        None => String::new(),
    };
    // The file is read before connecting: a wrong path or a file that is not MCAP is
    // said at once.
    McapReader::open(&args.file).with_context(|| format!("opening {}", args.file.display()))?;
    let rt = tokio::runtime::Runtime::new().context("starting the async runtime")?;
    rt.block_on(async move {
        tokio::select! {
            r = play(&args, filter.as_ref(), &prefix) => r,
            _ = super::shutdown_signal() => Ok(()),
        }
    })
}

type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

async fn connect(remote: &Remote) -> anyhow::Result<Ws> {
    let url = remote.ws_url()?;
    let connector = if url.starts_with("wss://") {
        Some(tokio_tungstenite::Connector::Rustls(remote.tls()?))
    } else {
        None
    };
    let mut wait = Duration::from_millis(200);
    for attempt in 1..=CONNECT_ATTEMPTS {
        let mut req = url.as_str().into_client_request()?;
        req.headers_mut().insert(
            "Sec-WebSocket-Protocol",
            HeaderValue::from_static("foxglove.websocket.v1"),
        );
        match tokio_tungstenite::connect_async_tls_with_config(req, None, true, connector.clone())
            .await
        {
            Ok((ws, _)) => return Ok(ws),
            Err(tokio_tungstenite::tungstenite::Error::Http(r))
                if r.status() == 503 && attempt < CONNECT_ATTEMPTS =>
            {
                tokio::time::sleep(wait).await;
                wait = (wait * 2).min(Duration::from_secs(5));
            }
            Err(e) => return Err(e).with_context(|| format!("connecting to {}", remote.hub)),
        }
    }
    unreachable!("the last attempt returns")
}

/// A channel of the file as the hub knows it.
struct Advertised {
    id: u32,
}

async fn play(args: &Args, filter: Option<&regex::Regex>, prefix: &str) -> anyhow::Result<()> {
    let ws = connect(&args.remote).await?;
    let (mut tx, mut rx) = ws.split();
    // The hub's status messages are what it says about our publishing (a refused topic,
    // a type conflict): shown as they come. The reader also answers pings.
    let (fatal_tx, mut fatal_rx) = tokio::sync::mpsc::channel::<String>(1);
    let reader = tokio::spawn(async move {
        while let Some(m) = rx.next().await {
            match m {
                Ok(WsMessage::Text(t)) => {
                    let v: Value = serde_json::from_str(&t).unwrap_or_default();
                    if v["op"] == "status" {
                        let level = match v["level"].as_u64() {
                            Some(2) => "error",
                            Some(1) => "warning",
                            _ => "info",
                        };
                        let text = v["message"].as_str().unwrap_or_default();
                        eprintln!("hub {level}: {text}");
                        if text.contains("not authenticated") {
                            let _ = fatal_tx.send(text.to_owned()).await;
                        }
                    }
                }
                Ok(WsMessage::Close(c)) => {
                    let why = c.map(|c| c.reason.to_string()).unwrap_or_default();
                    let _ = fatal_tx
                        .send(format!("the hub closed the connection {why}"))
                        .await;
                    return;
                }
                Err(e) => {
                    let _ = fatal_tx.send(format!("connection lost: {e}")).await;
                    return;
                }
                _ => {}
            }
        }
    });
    let mut channels: HashMap<u16, Channel> = HashMap::new();
    let mut advertised: HashMap<u16, Option<Advertised>> = HashMap::new();
    let mut next_id = 1u32;
    let mut sent = 0u64;
    let started = Instant::now();
    // Where the file's time stands against the wall clock: (log time, instant) of the
    // first message of the current pass.
    let mut pass_origin: Option<(u64, Instant)> = None;
    let mut last_at = started;
    loop {
        let mut reader_file = McapReader::open(&args.file)?;
        let mut pass_messages = 0u64;
        while let Some(item) = reader_file.next_item() {
            if let Ok(why) = fatal_rx.try_recv() {
                bail!("{why}");
            }
            match item.map_err(|e| anyhow::anyhow!("{}: {e}", args.file.display()))? {
                Item::Channel(c) => {
                    channels.insert(c.id, c);
                }
                Item::Message {
                    channel,
                    log_time,
                    data,
                    ..
                } => {
                    let Some(c) = channels.get(&channel) else {
                        bail!(
                            "{}: a message on channel {channel}, which the file never declared",
                            args.file.display()
                        );
                    };
                    if let std::collections::hash_map::Entry::Vacant(slot) =
                        advertised.entry(channel)
                    {
                        let entry = if filter.is_none_or(|f| f.is_match(&c.topic)) {
                            let id = next_id;
                            next_id += 1;
                            tx.send(WsMessage::text(advertise(id, c, prefix)?.to_string()))
                                .await?;
                            Some(Advertised { id })
                        } else {
                            None
                        };
                        slot.insert(entry);
                    }
                    let Some(Some(a)) = advertised.get(&channel) else {
                        continue;
                    };
                    let (t0, w0) = *pass_origin.get_or_insert((log_time, last_at));
                    let offset = log_time.saturating_sub(t0) as f64 / args.rate;
                    let at = w0 + Duration::from_nanos(offset as u64);
                    if at > Instant::now() {
                        tx.flush().await?;
                        tokio::select! {
                            _ = tokio::time::sleep_until(at) => {}
                            why = fatal_rx.recv() => bail!("{}", why.unwrap_or_default()),
                        }
                    }
                    last_at = at.max(last_at);
                    let mut b = BytesMut::with_capacity(5 + data.len());
                    b.put_u8(0x01);
                    b.put_u32_le(a.id);
                    b.put_slice(&data);
                    tx.feed(WsMessage::Binary(b.freeze())).await?;
                    sent += 1;
                    pass_messages += 1;
                }
            }
        }
        tx.flush().await?;
        if !args.repeat || pass_messages == 0 {
            break;
        }
        pass_origin = None;
    }
    // Give the hub the last messages before leaving.
    tokio::time::sleep(Duration::from_millis(300)).await;
    let _ = tx.send(WsMessage::Close(None)).await;
    reader.abort();
    eprintln!(
        "played {sent} messages of {} channels in {:.1} s",
        advertised.values().filter(|a| a.is_some()).count(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// The `advertise` of a file's channel as client channel `id`.
fn advertise(id: u32, c: &Channel, prefix: &str) -> anyhow::Result<Value> {
    let encoding = match c.message_encoding.as_str() {
        e @ ("cdr" | "ros1" | "json") => e,
        other => bail!(
            "{}: message encoding {other:?} cannot be published to a hub (cdr, ros1 or json)",
            c.topic
        ),
    };
    let topic = format!("{prefix}{}", c.topic);
    let mut ch = json!({
        "id": id,
        "topic": topic,
        "encoding": encoding,
        "schemaName": c.schema_name,
    });
    if matches!(c.schema_encoding.as_str(), "ros1msg" | "ros2msg") {
        ch["schema"] = Value::String(String::from_utf8_lossy(&c.schema).into_owned());
        ch["schemaEncoding"] = Value::String(c.schema_encoding.clone());
    }
    Ok(json!({ "op": "advertise", "channels": [ch] }))
}
