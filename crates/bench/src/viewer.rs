//! `fleetlink bench viewer`: a robot's large point cloud watched by viewers, over the
//! Foxglove WebSocket protocol or rosbridge CBOR (issue 39's comparison).
//!
//! One simulated robot (a `fleetlink.v1` link, as an agent on a ROS 2 robot) publishes a
//! `sensor_msgs/msg/PointCloud2` in CDR of `--size` bytes at `--rate` Hz, cut into `CHUNK`s
//! like the agent's link writer does. Its header stamp is the send time. `--viewers`
//! clients watch it: with `--protocol foxglove` each subscribes to the topic's channel and
//! reads the CDR out of `MessageData`; with `rosbridge-cbor` each subscribes with
//! `compression: cbor` and decodes the CBOR message. Per viewer and message the latency is
//! arrival minus the header stamp (one machine, one clock), so the two protocols are
//! measured the same way. The hub's CPU comes from `/proc/<pid>` over the measured window.
//!
//! Reported: messages sent and delivered in the window (the delivery ratio), latency
//! percentiles, the hub's CPU. Run it once per protocol against the same hub, back to back
//! (scripts/bench-viewer.sh does, alternating).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering::Relaxed};
use std::time::{Duration, Instant};

use anyhow::{Context, bail};
use bytes::{Bytes, BytesMut};
use fleetlink_msg::{Registry, Wire};
use fleetlink_proto::frame::{self, DEFAULT_CHUNK_SIZE, Frame};
use fleetlink_proto::{Encoding, Schema};
use futures_util::{SinkExt, StreamExt};
use hdrhistogram::Histogram;
use serde_json::{Value, json};
use std::sync::Mutex;
use tokio_tungstenite::tungstenite::Message as WsMessage;
use tokio_tungstenite::tungstenite::client::IntoClientRequest;
use tokio_tungstenite::tungstenite::http::HeaderValue;

use super::calls::{proc_figures, with_token};
use super::conn::{self, pong};
use crate::host::Host;

#[derive(Clone, Copy, Debug, clap::ValueEnum, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Protocol {
    /// Foxglove WebSocket (`foxglove.websocket.v1`): binary `MessageData`, CDR as published.
    Foxglove,
    /// rosbridge v2 with `compression: cbor`: the hub converts CDR to CBOR once per message.
    RosbridgeCbor,
}

#[derive(clap::Args)]
pub struct Args {
    /// How the viewers connect.
    #[arg(long, value_enum)]
    protocol: Protocol,
    /// The hub's URL (`ws://127.0.0.1:8080`).
    #[arg(long)]
    hub: String,
    /// An operator token the viewers present (the robot connects as `bench_cloud` and
    /// needs the hub to trust it: a robot token's name, or `--robot-network`). Also read
    /// from FLEETLINK_TOKEN.
    #[arg(
        long,
        env = "FLEETLINK_TOKEN",
        default_value = "",
        hide_env_values = true
    )]
    token: String,
    /// The robot's token, if the hub does not trust its address.
    #[arg(long, default_value = "")]
    robot_token: String,
    /// The hub's process id: its CPU is read from /proc over the measured window.
    #[arg(long)]
    hub_pid: Option<u32>,
    /// Bytes of point data per cloud (16-byte points: x, y, z, intensity).
    #[arg(long, default_value_t = 1 << 20)]
    size: usize,
    /// Clouds per second.
    #[arg(long, default_value_t = 30.0)]
    rate: f64,
    /// Viewers, each receiving every cloud.
    #[arg(long, default_value_t = 1)]
    viewers: usize,
    /// Measured seconds, after the warm-up.
    #[arg(long, default_value_t = 10.0)]
    duration: f64,
    /// Seconds of sending before the measurement starts.
    #[arg(long, default_value_t = 2.0)]
    warmup: f64,
    /// Print the summary as one JSON object.
    #[arg(long)]
    json: bool,
}

const ROBOT: &str = "bench_cloud";
const TOPIC: &str = "/bench_cloud/points";
const TYPE: &str = "sensor_msgs/msg/PointCloud2";
const ALIAS: u32 = 1;
const SETUP: Duration = Duration::from_secs(15);

#[derive(serde::Serialize)]
struct Summary {
    protocol: Protocol,
    size: usize,
    rate: f64,
    viewers: usize,
    seconds: f64,
    sent: u64,
    delivered: u64,
    delivery_ratio: f64,
    latency_ms: Option<Latency>,
    hub_cpu_percent: Option<f64>,
    hub_cpu_ms_per_cloud: Option<f64>,
}

#[derive(serde::Serialize)]
struct Latency {
    p50: f64,
    p99: f64,
    max: f64,
}

impl crate::measure::Report for Summary {
    fn text(&self) -> String {
        let lat = self
            .latency_ms
            .as_ref()
            .map_or("no latency".to_owned(), |l| {
                format!(
                    "latency p50 {:.1} ms, p99 {:.1} ms, max {:.1} ms",
                    l.p50, l.p99, l.max
                )
            });
        let cpu = match (self.hub_cpu_percent, self.hub_cpu_ms_per_cloud) {
            (Some(p), Some(ms)) => format!("hub {p:.1} % of a core, {ms:.2} ms CPU per cloud sent"),
            _ => "hub CPU not measured (give --hub-pid)".to_owned(),
        };
        format!(
            "{:?}: {} viewer(s), {} B at {} Hz: sent {}, delivered {} ({:.1} %); {lat}; {cpu}\n",
            self.protocol,
            self.viewers,
            self.size,
            self.rate,
            self.sent,
            self.delivered,
            self.delivery_ratio * 100.0
        )
    }
}

pub fn run(args: Args, host: &Host) -> anyhow::Result<()> {
    if args.rate <= 0.0 || args.viewers == 0 || args.duration <= 0.0 || args.size < 16 {
        bail!("--rate, --viewers and --duration must be positive and --size at least 16");
    }
    (host.init_logging)("error");
    let json = args.json;
    crate::measure::run_measurement(None, json, bench(args))
}

/// The window's counters, shared by the viewers.
struct Window {
    /// Only clouds stamped at or after this (Unix ns) are counted; 0 = not started.
    from_ns: AtomicU64,
    /// … and before this.
    to_ns: AtomicU64,
    delivered: AtomicU64,
    latency_us: Mutex<Histogram<u64>>,
    failed: AtomicBool,
}

impl Window {
    fn arrived(&self, stamp_ns: u64) {
        let now = fleetlink_relay::unix_nanos();
        let (from, to) = (self.from_ns.load(Relaxed), self.to_ns.load(Relaxed));
        if from == 0 || stamp_ns < from || stamp_ns >= to {
            return;
        }
        self.delivered.fetch_add(1, Relaxed);
        let us = now.saturating_sub(stamp_ns) / 1000;
        if let Ok(mut h) = self.latency_us.lock() {
            let _ = h.record(us.max(1));
        }
    }
}

async fn bench(args: Args) -> anyhow::Result<Summary> {
    let (cloud, schema) = point_cloud(args.size)?;
    let mut robot = conn::connect(&conn::hub_url(&args.hub), ROBOT, &args.robot_token)
        .await
        .context("the robot's link")?;
    robot
        .send_and_sync(
            &[Frame::Advertise {
                alias: ALIAS,
                topic: TOPIC.into(),
                schema,
                encoding: Encoding::Cdr,
                flags: 0,
            }],
            "robot",
        )
        .await?;
    let window = Arc::new(Window {
        from_ns: AtomicU64::new(0),
        to_ns: AtomicU64::new(u64::MAX),
        delivered: AtomicU64::new(0),
        latency_us: Mutex::new(Histogram::new_with_bounds(1, 600_000_000, 3)?),
        failed: AtomicBool::new(false),
    });
    let mut viewers = Vec::new();
    for i in 0..args.viewers {
        let url = with_token(&args.hub, &args.token);
        let w = window.clone();
        let task = match args.protocol {
            Protocol::Foxglove => {
                let ws = foxglove_subscribe(&url)
                    .await
                    .with_context(|| format!("viewer {i}"))?;
                tokio::spawn(foxglove_read(ws, w))
            }
            Protocol::RosbridgeCbor => {
                let ws = rosbridge_subscribe(&url)
                    .await
                    .with_context(|| format!("viewer {i}"))?;
                tokio::spawn(rosbridge_read(ws, w))
            }
        };
        viewers.push(task);
    }
    let stop = Arc::new(AtomicBool::new(false));
    let sent_stamps = Arc::new(Mutex::new(Vec::<u64>::new()));
    let publisher = tokio::spawn(publish(
        robot,
        cloud,
        args.rate,
        stop.clone(),
        sent_stamps.clone(),
    ));
    tokio::time::sleep(Duration::from_secs_f64(args.warmup)).await;
    let from = fleetlink_relay::unix_nanos();
    window.from_ns.store(from, Relaxed);
    let cpu0 = args.hub_pid.and_then(proc_figures);
    let t0 = Instant::now();
    tokio::time::sleep(Duration::from_secs_f64(args.duration)).await;
    let to = fleetlink_relay::unix_nanos();
    window.to_ns.store(to, Relaxed);
    let cpu1 = args.hub_pid.and_then(proc_figures);
    let secs = t0.elapsed().as_secs_f64();
    // What was sent in the window may still be on its way: wait for it (bounded).
    tokio::time::sleep(Duration::from_secs(2)).await;
    stop.store(true, Relaxed);
    publisher.await.context("publisher task")??;
    for v in &viewers {
        v.abort();
    }
    if window.failed.load(Relaxed) {
        bail!("a viewer lost its connection or got something it could not read (see above)");
    }
    let sent = sent_stamps
        .lock()
        .map_err(|_| anyhow::anyhow!("publisher poisoned its counter"))?
        .iter()
        .filter(|s| **s >= from && **s < to)
        .count() as u64;
    let expected = sent * args.viewers as u64;
    let delivered = window.delivered.load(Relaxed);
    let latency_ms = window.latency_us.lock().ok().and_then(|h| {
        (!h.is_empty()).then(|| Latency {
            p50: h.value_at_quantile(0.5) as f64 / 1000.0,
            p99: h.value_at_quantile(0.99) as f64 / 1000.0,
            max: h.max() as f64 / 1000.0,
        })
    });
    let cpu = match (cpu0, cpu1) {
        (Some((c0, _)), Some((c1, _))) => Some(c1 - c0),
        _ => None,
    };
    Ok(Summary {
        protocol: args.protocol,
        size: args.size,
        rate: args.rate,
        viewers: args.viewers,
        seconds: secs,
        sent,
        delivered,
        delivery_ratio: delivered as f64 / expected.max(1) as f64,
        latency_ms,
        hub_cpu_percent: cpu.map(|c| c * 100.0 / secs),
        hub_cpu_ms_per_cloud: cpu.map(|c| c * 1000.0 / sent.max(1) as f64),
    })
}

/// A PointCloud2 in CDR with `size` bytes of points, and its schema. The header stamp
/// (bytes 4..12: sec, nanosec) is rewritten per message.
fn point_cloud(size: usize) -> anyhow::Result<(Vec<u8>, Schema)> {
    let registry = Registry::bundled();
    let points = size / 16;
    let data: Vec<u8> = (0..points * 16).map(|i| (i % 251) as u8).collect();
    let field = |name: &str, offset: u32| json!({"name": name, "offset": offset, "datatype": 7, "count": 1});
    let value = json!({
        "header": {"stamp": {"sec": 0, "nanosec": 0}, "frame_id": "bench"},
        "height": 1,
        "width": points,
        "fields": [field("x", 0), field("y", 4), field("z", 8), field("intensity", 12)],
        "is_bigendian": false,
        "point_step": 16,
        "row_step": points * 16,
        "data": data,
        "is_dense": true,
    });
    let msg = fleetlink_msg::from_json(&registry, TYPE, fleetlink_msg::Dialect::Ros2, &value)
        .context("building the point cloud")?;
    let cdr = fleetlink_msg::encode(&registry, TYPE, Wire::Cdr, &msg)?;
    let text = registry.full_text(TYPE, fleetlink_msg::Dialect::Ros2)?;
    Ok((
        cdr,
        Schema {
            type_name: TYPE.into(),
            encoding: "ros2msg".into(),
            text,
        },
    ))
}

/// The header stamp of a CDR message of a type that starts with `std_msgs/Header`.
fn cdr_stamp(cdr: &[u8]) -> Option<u64> {
    let sec = u32::from_le_bytes(cdr.get(4..8)?.try_into().ok()?);
    let nsec = u32::from_le_bytes(cdr.get(8..12)?.try_into().ok()?);
    Some(u64::from(sec) * 1_000_000_000 + u64::from(nsec))
}

/// Sends the cloud at `rate` Hz, stamped, in chunks; answers the hub's pings.
async fn publish(
    robot: conn::Conn,
    mut cloud: Vec<u8>,
    rate: f64,
    stop: Arc<AtomicBool>,
    stamps: Arc<Mutex<Vec<u64>>>,
) -> anyhow::Result<()> {
    let (mut sink, mut stream) = robot.ws.split();
    let period = Duration::from_secs_f64(1.0 / rate);
    let mut tick = tokio::time::interval(period);
    tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    let mut seq = 0u64;
    let mut buf = BytesMut::new();
    while !stop.load(Relaxed) {
        tokio::select! {
            _ = tick.tick() => {
                let now = fleetlink_relay::unix_nanos();
                cloud[4..8].copy_from_slice(&((now / 1_000_000_000) as u32).to_le_bytes());
                cloud[8..12].copy_from_slice(&((now % 1_000_000_000) as u32).to_le_bytes());
                let total = cloud.len() as u64;
                for (i, data) in cloud.chunks(DEFAULT_CHUNK_SIZE).enumerate() {
                    let offset = (i * DEFAULT_CHUNK_SIZE) as u64;
                    frame::encode_chunk(&mut buf, false, ALIAS, seq, now, total, offset, data);
                    sink.feed(WsMessage::Binary(buf.split().freeze())).await?;
                }
                sink.flush().await?;
                seq += 1;
                if let Ok(mut s) = stamps.lock() {
                    s.push(now);
                }
            }
            m = stream.next() => match m {
                Some(Ok(WsMessage::Binary(b))) => {
                    for f in frame::frames(&b) {
                        if let Ok(Frame::Ping { id, sent_ns }) = f {
                            sink.send(WsMessage::Binary(pong(id, sent_ns))).await?;
                        }
                    }
                }
                Some(Ok(_)) => {}
                Some(Err(e)) => return Err(e).context("the robot's link"),
                None => bail!("the hub closed the robot's link"),
            },
        }
    }
    Ok(())
}

type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

async fn text_op(ws: &mut Ws) -> anyhow::Result<Value> {
    loop {
        match ws.next().await.context("the hub closed the connection")?? {
            WsMessage::Text(t) => return Ok(serde_json::from_str(&t)?),
            WsMessage::Close(c) => bail!("the hub closed the connection: {c:?}"),
            _ => {}
        }
    }
}

/// Connects as a Foxglove client and subscribes to the cloud's channel.
async fn foxglove_subscribe(url: &str) -> anyhow::Result<Ws> {
    let mut req = url.into_client_request()?;
    req.headers_mut().insert(
        "Sec-WebSocket-Protocol",
        HeaderValue::from_static("foxglove.websocket.v1"),
    );
    let (mut ws, _) = tokio_tungstenite::connect_async(req).await?;
    let channel = tokio::time::timeout(SETUP, async {
        loop {
            let op = text_op(&mut ws).await?;
            if op["op"] == "advertise"
                && let Some(c) = op["channels"]
                    .as_array()
                    .and_then(|cs| cs.iter().find(|c| c["topic"] == TOPIC))
            {
                return anyhow::Ok(c["id"].as_u64().context("channel id")?);
            }
        }
    })
    .await
    .context("no channel for the cloud's topic")??;
    let sub = json!({"op": "subscribe", "subscriptions": [{"id": 1, "channelId": channel}]});
    ws.send(WsMessage::Text(sub.to_string().into())).await?;
    Ok(ws)
}

/// Reads `MessageData` (opcode 1: subscription id, receive time, payload) and counts it.
async fn foxglove_read(mut ws: Ws, w: Arc<Window>) {
    while let Some(m) = ws.next().await {
        match m {
            Ok(WsMessage::Binary(b)) if b.first() == Some(&1) => {
                match b.get(13..).and_then(cdr_stamp) {
                    Some(stamp) => w.arrived(stamp),
                    None => return fail(&w, "a MessageData too short for a PointCloud2"),
                }
            }
            Ok(WsMessage::Text(t)) if t.contains("\"op\":\"status\"") => {
                if t.contains("\"level\":2") {
                    return fail(&w, &format!("the hub said: {t}"));
                }
            }
            Ok(WsMessage::Close(_)) | Err(_) => return fail(&w, "the connection ended"),
            Ok(_) => {}
        }
    }
}

/// Connects as a rosbridge client and subscribes with `compression: cbor`.
async fn rosbridge_subscribe(url: &str) -> anyhow::Result<Ws> {
    let (mut ws, _) = tokio_tungstenite::connect_async(url).await?;
    let sub = json!({"op": "subscribe", "id": "viewer", "topic": TOPIC, "type": TYPE,
                     "compression": "cbor"});
    ws.send(WsMessage::Text(sub.to_string().into())).await?;
    Ok(ws)
}

/// Reads CBOR `publish` messages and counts them by their header stamp.
async fn rosbridge_read(mut ws: Ws, w: Arc<Window>) {
    while let Some(m) = ws.next().await {
        match m {
            Ok(WsMessage::Binary(b)) => match cbor_stamp(&b) {
                Some(stamp) => w.arrived(stamp),
                None => return fail(&w, "a CBOR message without msg.header.stamp"),
            },
            Ok(WsMessage::Text(t)) if t.contains("\"level\":\"error\"") => {
                return fail(&w, &format!("the hub said: {t}"));
            }
            Ok(WsMessage::Close(_)) | Err(_) => return fail(&w, "the connection ended"),
            Ok(_) => {}
        }
    }
}

fn cbor_stamp(b: &Bytes) -> Option<u64> {
    use ciborium::Value as C;
    fn get<'a>(v: &'a C, key: &str) -> Option<&'a C> {
        v.as_map()?
            .iter()
            .find(|(k, _)| k.as_text() == Some(key))
            .map(|(_, v)| v)
    }
    let v: C = ciborium::from_reader(&b[..]).ok()?;
    let stamp = get(get(get(&v, "msg")?, "header")?, "stamp")?;
    let sec: u64 = get(stamp, "sec")?.as_integer()?.try_into().ok()?;
    let nsec: u64 = get(stamp, "nanosec")?.as_integer()?.try_into().ok()?;
    Some(sec * 1_000_000_000 + nsec)
}

fn fail(w: &Window, why: &str) {
    eprintln!("viewer: {why}");
    w.failed.store(true, Relaxed);
}
