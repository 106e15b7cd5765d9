//! `fleetlink bench delivery`: what a message server spends per delivered message.
//!
//! One publisher and one or more subscribers, all in this process, exchange small messages
//! at a fixed rate through a server speaking one of several protocols: the hub's rosbridge
//! JSON and CBOR, its native `fleetlink.v1` links, NATS, or MQTT 3.1.1. The figure that
//! matters is the server's CPU time (user + system, read from `/proc/<pid>/stat` over the
//! measured window) divided by the messages the subscribers received in that window. The
//! generator paces every protocol the same way (one write per millisecond carrying the
//! messages then due), so the servers see the same load shape, and because the server's
//! CPU is read from `/proc`, a generator that saturates first does not distort the figure.
//!
//! NATS and MQTT are spoken with a few lines of framing each rather than their client
//! libraries: the client libraries decide for themselves when to flush and how to batch,
//! which would give each server a different load shape, and the bench needs only
//! `PUB`/`SUB` and QoS 0 `PUBLISH`/`SUBSCRIBE`.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering::Relaxed};
use std::time::{Duration, Instant};

use anyhow::{Context, bail};
use bytes::{Buf, BufMut, Bytes, BytesMut};
use fleetlink_proto::frame::{self, Frame};
use futures_util::{SinkExt, StreamExt};
use serde_json::json;
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::TcpStream;
use tokio_tungstenite::tungstenite::Message as WsMessage;

use super::calls::{proc_figures, with_token};
use super::conn;
use crate::host::Host;

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Protocol {
    /// rosbridge v2 JSON text frames through a fleetlink hub (`std_msgs/String`).
    RosbridgeJson,
    /// rosbridge v2 CBOR binary frames, subscribed with `compression: cbor`.
    RosbridgeCbor,
    /// The hub's native `fleetlink.v1` link frames.
    Native,
    /// NATS core `PUB`/`SUB` (e.g. nats-server).
    Nats,
    /// MQTT 3.1.1, QoS 0 (e.g. mosquitto).
    Mqtt,
}

#[derive(clap::Args)]
pub struct Args {
    /// Protocol, and so which kind of server `--server` is.
    #[arg(long, value_enum)]
    protocol: Protocol,
    /// The server's address: a hub URL (`ws://127.0.0.1:8080`) for the fleetlink
    /// protocols, `host:port` for NATS and MQTT.
    #[arg(long)]
    server: String,
    /// An operator token of the hub's admin group (fleetlink protocols). Also read from
    /// FLEETLINK_TOKEN.
    #[arg(
        long,
        env = "FLEETLINK_TOKEN",
        default_value = "",
        hide_env_values = true
    )]
    token: String,
    /// The server's process id: its CPU time is read from /proc over the measured window.
    #[arg(long)]
    server_pid: Option<u32>,
    /// Messages per second the publisher sends.
    #[arg(long, default_value_t = 20_000)]
    rate: u64,
    /// Payload bytes per message (the `data` string's length is chosen so the message
    /// object has this size).
    #[arg(long, default_value_t = 64)]
    size: usize,
    /// Subscribers, each receiving every message.
    #[arg(long, default_value_t = 1)]
    subscribers: usize,
    /// Measured seconds, after the warm-up.
    #[arg(long, default_value_t = 10.0)]
    duration: f64,
    /// Seconds of sending before the measurement starts.
    #[arg(long, default_value_t = 2.0)]
    warmup: f64,
    /// Print the summary as one JSON object.
    #[arg(long)]
    json: bool,
    /// rosbridge runs: every publish carries an `id`, as roslibpy and roslibjs send one
    /// (`"publish:<topic>:<n>"`).
    #[arg(long)]
    with_id: bool,
}

/// Topic of the rosbridge and MQTT runs (the native run uses the relay bench's topic).
const TOPIC: &str = "/bench_delivery/data";
const NATS_SUBJECT: &str = "bench.data";
/// Longest wait for a connection and its setup exchange.
const SETUP: Duration = Duration::from_secs(10);

pub fn run(args: Args, host: &Host) -> anyhow::Result<()> {
    if args.rate == 0 || args.subscribers == 0 || args.duration <= 0.0 {
        bail!("--rate, --subscribers and --duration must be positive");
    }
    if args.size < 16 {
        bail!("--size must be at least 16 bytes");
    }
    (host.init_logging)("error");
    let rt = tokio::runtime::Runtime::new().context("starting the async runtime")?;
    rt.block_on(bench(args))
}

async fn bench(args: Args) -> anyhow::Result<()> {
    let counts: Vec<Arc<AtomicU64>> = (0..args.subscribers)
        .map(|_| Arc::new(AtomicU64::new(0)))
        .collect();
    let failed = Arc::new(AtomicBool::new(false));
    let mut subs = Vec::new();
    for (i, count) in counts.iter().enumerate() {
        let rx = open_subscriber(&args, i)
            .await
            .with_context(|| format!("subscriber {i}"))?;
        subs.push(tokio::spawn(rx.run(count.clone(), failed.clone())));
    }
    let mut tx = open_publisher(&args).await.context("publisher")?;
    let stop = Arc::new(AtomicBool::new(false));
    let sent = Arc::new(AtomicU64::new(0));
    let publisher = {
        let (stop, sent, rate) = (stop.clone(), sent.clone(), args.rate);
        tokio::spawn(async move { tx.run(rate, &stop, &sent).await })
    };
    tokio::time::sleep(Duration::from_secs_f64(args.warmup)).await;
    let total = |c: &[Arc<AtomicU64>]| c.iter().map(|c| c.load(Relaxed)).sum::<u64>();
    let (t0, got0, sent0) = (Instant::now(), total(&counts), sent.load(Relaxed));
    let cpu0 = args.server_pid.and_then(proc_figures);
    tokio::time::sleep(Duration::from_secs_f64(args.duration)).await;
    let cpu1 = args.server_pid.and_then(proc_figures);
    let (secs, got1, sent1) = (
        t0.elapsed().as_secs_f64(),
        total(&counts),
        sent.load(Relaxed),
    );
    stop.store(true, Relaxed);
    let published = publisher.await.context("publisher task")?;
    for s in subs {
        s.abort();
    }
    published.context("publisher")?;
    if failed.load(Relaxed) {
        bail!("a subscriber lost its connection (see above)");
    }
    let delivered = got1 - got0;
    let offered = (sent1 - sent0) as f64 / secs;
    let cpu = match (cpu0, cpu1) {
        (Some((c0, _)), Some((c1, rss))) => Some((c1 - c0, rss)),
        _ => None,
    };
    let per_delivery_us = cpu.map(|(c, _)| c * 1e6 / delivered.max(1) as f64);
    if args.json {
        println!(
            "{}",
            json!({
                "protocol": format!("{:?}", args.protocol),
                "rate": args.rate,
                "size": args.size,
                "subscribers": args.subscribers,
                "seconds": secs,
                "sent_per_sec": offered,
                "delivered_per_sec": delivered as f64 / secs,
                "server_cpu_percent": cpu.map(|(c, _)| c * 100.0 / secs),
                "server_cpu_us_per_delivery": per_delivery_us,
                "server_rss_kb": cpu.map(|(_, r)| r),
            })
        );
    } else {
        println!(
            "{:?}: sent {offered:.0} msg/s, delivered {:.0} msg/s ({} subscriber(s), {} B)",
            args.protocol,
            delivered as f64 / secs,
            args.subscribers,
            args.size
        );
        match (cpu, per_delivery_us) {
            (Some((c, rss)), Some(us)) => println!(
                "server: {:.1} % of a core, {us:.2} µs CPU per delivered message, RSS {:.1} MB",
                c * 100.0 / secs,
                rss as f64 / 1024.0
            ),
            _ => println!("server: no CPU figures (give --server-pid)"),
        }
    }
    Ok(())
}

/// A `std_msgs/String` whose JSON object (`{"data":"…"}`) is `size` bytes.
fn string_data(size: usize) -> String {
    "x".repeat(size.saturating_sub(11))
}

type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

async fn ws_connect(url: &str) -> anyhow::Result<Ws> {
    let (ws, _) = tokio::time::timeout(SETUP, tokio_tungstenite::connect_async(url))
        .await
        .with_context(|| format!("connecting to {url} timed out"))?
        .with_context(|| format!("connecting to {url}"))?;
    Ok(ws)
}

async fn tcp_connect(addr: &str) -> anyhow::Result<TcpStream> {
    let s = tokio::time::timeout(SETUP, TcpStream::connect(addr))
        .await
        .with_context(|| format!("connecting to {addr} timed out"))?
        .with_context(|| format!("connecting to {addr}"))?;
    s.set_nodelay(true)?;
    Ok(s)
}

enum Publisher {
    /// rosbridge: every message its own WebSocket message.
    Ws { ws: Box<Ws>, frame: WsMessage },
    /// Native link frames packed into one WebSocket message per write.
    Native {
        conn: Box<conn::Conn>,
        payload: Bytes,
    },
    /// A byte protocol: the same encoded message repeated.
    Tcp { stream: TcpStream, one: Bytes },
}

async fn open_publisher(args: &Args) -> anyhow::Result<Publisher> {
    let data = string_data(args.size);
    Ok(match args.protocol {
        Protocol::RosbridgeJson | Protocol::RosbridgeCbor => {
            let mut ws = ws_connect(&with_token(&args.server, &args.token)).await?;
            let adv = json!({"op": "advertise", "topic": TOPIC, "type": "std_msgs/String"});
            ws.send(WsMessage::text(adv.to_string())).await?;
            let mut publish = json!({"op": "publish", "topic": TOPIC, "msg": {"data": data}});
            if args.with_id {
                publish["id"] = json!(format!("publish:{TOPIC}:1"));
            }
            let frame = if args.protocol == Protocol::RosbridgeJson {
                WsMessage::text(publish.to_string())
            } else {
                let mut out = Vec::new();
                ciborium::into_writer(&publish, &mut out)?;
                WsMessage::Binary(out.into())
            };
            Publisher::Ws {
                ws: Box::new(ws),
                frame,
            }
        }
        Protocol::Native => {
            let mut c =
                conn::connect(&conn::hub_url(&args.server), "bench_pub_0", &args.token).await?;
            c.send_and_sync(&[conn::advertise(0)], "publisher").await?;
            Publisher::Native {
                conn: Box::new(c),
                payload: vec![0x5a; args.size].into(),
            }
        }
        Protocol::Nats => {
            let mut stream = tcp_connect(&args.server).await?;
            nats_handshake(&mut stream).await?;
            let mut one = BytesMut::new();
            one.put_slice(format!("PUB {NATS_SUBJECT} {}\r\n", args.size).as_bytes());
            one.put_bytes(b'x', args.size);
            one.put_slice(b"\r\n");
            Publisher::Tcp {
                stream,
                one: one.freeze(),
            }
        }
        Protocol::Mqtt => {
            let mut stream = tcp_connect(&args.server).await?;
            mqtt_connect(&mut stream, "bench-pub").await?;
            let mut body = BytesMut::new();
            put_mqtt_str(&mut body, TOPIC);
            body.put_bytes(b'x', args.size);
            let mut one = BytesMut::new();
            one.put_u8(0x30); // PUBLISH, QoS 0
            put_mqtt_len(&mut one, body.len());
            one.put_slice(&body);
            Publisher::Tcp {
                stream,
                one: one.freeze(),
            }
        }
    })
}

impl Publisher {
    /// Sends at `rate` until `stop`: once a millisecond, every message then due, in one
    /// write.
    async fn run(&mut self, rate: u64, stop: &AtomicBool, sent: &AtomicU64) -> anyhow::Result<()> {
        let start = Instant::now();
        let mut tick = tokio::time::interval(Duration::from_millis(1));
        tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Skip);
        let mut seq = 0u64;
        let mut buf = BytesMut::new();
        while !stop.load(Relaxed) {
            tick.tick().await;
            let due = (start.elapsed().as_secs_f64() * rate as f64) as u64;
            let n = due.saturating_sub(seq);
            if n == 0 {
                continue;
            }
            match self {
                Publisher::Ws { ws, frame } => {
                    for _ in 0..n {
                        ws.feed(frame.clone()).await?;
                    }
                    ws.flush().await?;
                }
                Publisher::Native { conn, payload } => {
                    let now = fleetlink_relay::unix_nanos();
                    for s in seq..seq + n {
                        frame::encode_message(&mut buf, 1, s, now, payload);
                    }
                    conn.ws
                        .send(WsMessage::Binary(buf.split().freeze()))
                        .await?;
                    // The hub's pings need answers; nothing else comes to a publisher.
                    while let Some(Some(m)) = futures_util::FutureExt::now_or_never(conn.ws.next())
                    {
                        answer_pings(&mut conn.ws, &m?).await?;
                    }
                }
                Publisher::Tcp { stream, one } => {
                    for _ in 0..n {
                        buf.put_slice(one);
                    }
                    stream.write_all(&buf).await?;
                    buf.clear();
                }
            }
            seq += n;
            sent.store(seq, Relaxed);
        }
        Ok(())
    }
}

async fn answer_pings(ws: &mut conn::Ws, m: &WsMessage) -> anyhow::Result<()> {
    let WsMessage::Binary(b) = m else {
        return Ok(());
    };
    for f in frame::frames(b) {
        if let Frame::Ping { id, sent_ns } = f? {
            ws.send(WsMessage::Binary(conn::pong(id, sent_ns))).await?;
        }
    }
    Ok(())
}

enum Subscriber {
    Ws(Box<Ws>),
    Native(Box<conn::Conn>),
    Nats(TcpStream),
    Mqtt(TcpStream),
}

async fn open_subscriber(args: &Args, i: usize) -> anyhow::Result<Subscriber> {
    Ok(match args.protocol {
        Protocol::RosbridgeJson | Protocol::RosbridgeCbor => {
            let mut ws = ws_connect(&with_token(&args.server, &args.token)).await?;
            let compression = match args.protocol {
                Protocol::RosbridgeCbor => "cbor",
                _ => "none",
            };
            let sub = json!({"op": "subscribe", "topic": TOPIC, "type": "std_msgs/String",
                             "compression": compression});
            ws.send(WsMessage::text(sub.to_string())).await?;
            Subscriber::Ws(Box::new(ws))
        }
        Protocol::Native => {
            let robot = format!("bench_sub_{i}");
            let mut c = conn::connect(&conn::hub_url(&args.server), &robot, &args.token).await?;
            c.send_and_sync(&[super::subscriber::subscribe(0)], &robot)
                .await?;
            Subscriber::Native(Box::new(c))
        }
        Protocol::Nats => {
            let mut s = tcp_connect(&args.server).await?;
            nats_handshake(&mut s).await?;
            s.write_all(format!("SUB {NATS_SUBJECT} 1\r\nPING\r\n").as_bytes())
                .await?;
            // The PONG to that PING says the subscription is in place.
            let mut line = Vec::new();
            read_line(&mut s, &mut line).await?;
            if line != b"PONG" {
                bail!(
                    "NATS: expected PONG, got {:?}",
                    String::from_utf8_lossy(&line)
                );
            }
            Subscriber::Nats(s)
        }
        Protocol::Mqtt => {
            let mut s = tcp_connect(&args.server).await?;
            mqtt_connect(&mut s, &format!("bench-sub-{i}")).await?;
            let mut body = BytesMut::new();
            body.put_u16(1); // packet id
            put_mqtt_str(&mut body, TOPIC);
            body.put_u8(0); // QoS 0
            let mut pkt = BytesMut::new();
            pkt.put_u8(0x82);
            put_mqtt_len(&mut pkt, body.len());
            pkt.put_slice(&body);
            s.write_all(&pkt).await?;
            let mut ack = [0u8; 5];
            tokio::time::timeout(SETUP, s.read_exact(&mut ack))
                .await
                .context("MQTT: no SUBACK")??;
            if ack[0] != 0x90 || ack[4] == 0x80 {
                bail!("MQTT: subscription refused ({ack:02x?})");
            }
            Subscriber::Mqtt(s)
        }
    })
}

impl Subscriber {
    /// Counts messages into `count` until the task is aborted; sets `failed` if the
    /// connection fails.
    async fn run(self, count: Arc<AtomicU64>, failed: Arc<AtomicBool>) {
        let r = match self {
            Subscriber::Ws(mut ws) => {
                async {
                    while let Some(m) = ws.next().await {
                        if matches!(m?, WsMessage::Text(_) | WsMessage::Binary(_)) {
                            count.fetch_add(1, Relaxed);
                        }
                    }
                    anyhow::Ok(())
                }
                .await
            }
            Subscriber::Native(mut c) => {
                async {
                    while let Some(m) = c.ws.next().await {
                        let WsMessage::Binary(b) = m? else { continue };
                        let mut n = 0;
                        for f in frame::frames(&b) {
                            match f? {
                                Frame::Message { .. } => n += 1,
                                Frame::Ping { id, sent_ns } => {
                                    c.ws.send(WsMessage::Binary(conn::pong(id, sent_ns)))
                                        .await?
                                }
                                _ => {}
                            }
                        }
                        count.fetch_add(n, Relaxed);
                    }
                    anyhow::Ok(())
                }
                .await
            }
            Subscriber::Nats(s) => nats_count(s, &count).await,
            Subscriber::Mqtt(s) => mqtt_count(s, &count).await,
        };
        if let Err(e) = r {
            eprintln!("bench: subscriber: {e:#}");
        }
        failed.store(true, Relaxed);
    }
}

async fn read_line(s: &mut TcpStream, line: &mut Vec<u8>) -> anyhow::Result<()> {
    line.clear();
    let read = async {
        loop {
            let b = s.read_u8().await?;
            if b == b'\n' {
                if line.last() == Some(&b'\r') {
                    line.pop();
                }
                return anyhow::Ok(());
            }
            line.push(b);
        }
    };
    tokio::time::timeout(SETUP, read)
        .await
        .context("no answer")?
}

async fn nats_handshake(s: &mut TcpStream) -> anyhow::Result<()> {
    let mut line = Vec::new();
    read_line(s, &mut line).await?;
    if !line.starts_with(b"INFO ") {
        bail!(
            "not a NATS server (first line {:?})",
            String::from_utf8_lossy(&line)
        );
    }
    s.write_all(b"CONNECT {\"verbose\":false,\"pedantic\":false}\r\n")
        .await?;
    Ok(())
}

/// Reads `MSG <subject> <sid> <size>\r\n<payload>\r\n` operations, answering `PING`s.
async fn nats_count(mut s: TcpStream, count: &AtomicU64) -> anyhow::Result<()> {
    let mut buf = BytesMut::with_capacity(1 << 16);
    loop {
        if s.read_buf(&mut buf).await? == 0 {
            bail!("NATS server closed the connection");
        }
        let mut n = 0;
        while let Some(eol) = buf.windows(2).position(|w| w == b"\r\n") {
            let line = &buf[..eol];
            if line.starts_with(b"MSG ") {
                let size: usize = std::str::from_utf8(line)?
                    .rsplit(' ')
                    .next()
                    .and_then(|v| v.parse().ok())
                    .context("NATS: bad MSG line")?;
                if buf.len() < eol + 2 + size + 2 {
                    break;
                }
                buf.advance(eol + 2 + size + 2);
                n += 1;
            } else {
                if line == b"PING" {
                    s.write_all(b"PONG\r\n").await?;
                } else if line.starts_with(b"-ERR") {
                    bail!("NATS: {}", String::from_utf8_lossy(line));
                }
                buf.advance(eol + 2);
            }
        }
        count.fetch_add(n, Relaxed);
    }
}

fn put_mqtt_len(buf: &mut BytesMut, mut len: usize) {
    loop {
        let mut b = (len % 128) as u8;
        len /= 128;
        if len > 0 {
            b |= 0x80;
        }
        buf.put_u8(b);
        if len == 0 {
            return;
        }
    }
}

fn put_mqtt_str(buf: &mut BytesMut, s: &str) {
    buf.put_u16(s.len() as u16);
    buf.put_slice(s.as_bytes());
}

/// CONNECT (MQTT 3.1.1, clean session, no keep-alive) and its CONNACK.
async fn mqtt_connect(s: &mut TcpStream, client_id: &str) -> anyhow::Result<()> {
    let mut body = BytesMut::new();
    put_mqtt_str(&mut body, "MQTT");
    body.put_u8(4); // protocol level 3.1.1
    body.put_u8(0x02); // clean session
    body.put_u16(0); // keep-alive off
    put_mqtt_str(&mut body, client_id);
    let mut pkt = BytesMut::new();
    pkt.put_u8(0x10);
    put_mqtt_len(&mut pkt, body.len());
    pkt.put_slice(&body);
    s.write_all(&pkt).await?;
    let mut ack = [0u8; 4];
    tokio::time::timeout(SETUP, s.read_exact(&mut ack))
        .await
        .context("MQTT: no CONNACK")??;
    if ack[0] != 0x20 || ack[3] != 0 {
        bail!("MQTT: connection refused ({ack:02x?})");
    }
    Ok(())
}

/// Reads MQTT packets, counting `PUBLISH`es.
async fn mqtt_count(mut s: TcpStream, count: &AtomicU64) -> anyhow::Result<()> {
    let mut buf = BytesMut::with_capacity(1 << 16);
    loop {
        if s.read_buf(&mut buf).await? == 0 {
            bail!("MQTT broker closed the connection");
        }
        let mut n = 0;
        loop {
            // Fixed header: type byte, then the remaining length in 1–4 bytes.
            let (mut len, mut at, mut shift) = (0usize, 1usize, 0);
            let complete = loop {
                let Some(&b) = buf.get(at) else { break false };
                len |= ((b & 0x7f) as usize) << shift;
                at += 1;
                shift += 7;
                if b & 0x80 == 0 {
                    break true;
                }
                if at > 4 {
                    bail!("MQTT: malformed remaining length");
                }
            };
            if !complete || buf.len() < at + len {
                break;
            }
            if buf[0] >> 4 == 3 {
                n += 1;
            }
            buf.advance(at + len);
        }
        count.fetch_add(n, Relaxed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mqtt_remaining_length_uses_seven_bits_per_byte() {
        let enc = |n| {
            let mut b = BytesMut::new();
            put_mqtt_len(&mut b, n);
            b.to_vec()
        };
        assert_eq!(enc(0), [0x00]);
        assert_eq!(enc(127), [0x7f]);
        assert_eq!(enc(128), [0x80, 0x01]);
        assert_eq!(enc(16_383), [0xff, 0x7f]);
        assert_eq!(enc(2_097_152), [0x80, 0x80, 0x80, 0x01]);
    }

    #[test]
    fn string_message_has_the_asked_size() {
        let msg = json!({"data": string_data(64)}).to_string();
        assert_eq!(msg.len(), 64);
    }
}
