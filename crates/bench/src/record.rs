//! `fleetlink bench record`: the hub recording a robot's mixed topics to MCAP at a given
//! data rate (issue 39: 50 MB/s, no recorder drops, recorder CPU ≤ 25 % of a core).
//!
//! One simulated robot (a `fleetlink.v1` link, as an agent on a ROS 2 robot) publishes in
//! CDR: a `sensor_msgs/msg/PointCloud2` at 30 Hz sized so the whole makes `--rate-mb`, a
//! 640×480 `rgb8` `sensor_msgs/msg/Image` at 15 Hz (13.8 MB/s), a 1,080-beam `LaserScan`
//! at 40 Hz, an `Imu` at 200 Hz and an `Odometry` at 50 Hz. The cloud's and the image's
//! bytes are smooth values with noise, so zstd has real work (neither all zeros nor
//! random). After a warm-up the bench starts a recording of the robot's topics through
//! the API, lets it run `--duration` seconds, reads the recorder thread's CPU from
//! `/proc/<hub>/task/*` (the thread is named `recorder …`), stops it and reports what the
//! hub says it wrote and dropped.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering::Relaxed};
use std::time::{Duration, Instant};

use anyhow::{Context, bail};
use bytes::BytesMut;
use fleetlink_msg::{Registry, Wire};
use fleetlink_proto::frame::{self, DEFAULT_CHUNK_SIZE, Frame};
use fleetlink_proto::{Encoding, Schema};
use fleetlink_remote::Remote;
use futures_util::{SinkExt, StreamExt};
use hyper::Method;
use serde_json::{Value, json};
use tokio_tungstenite::tungstenite::Message as WsMessage;

use super::calls::{proc_figures, stat_cpu_seconds};
use super::conn::{self, pong};

#[derive(clap::Args)]
pub struct Args {
    /// The hub (`ws://127.0.0.1:8080`).
    #[arg(long)]
    hub: String,
    /// A token with the right to record (`/recordings`, the admin group has it). Also
    /// read from FLEETLINK_TOKEN.
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
    /// The hub's process id: the recorder thread's CPU is read from /proc.
    #[arg(long)]
    hub_pid: u32,
    /// Megabytes (10^6 bytes) per second the robot publishes in all.
    #[arg(long, default_value_t = 50.0)]
    rate_mb: f64,
    /// Measured seconds of recording.
    #[arg(long, default_value_t = 20.0)]
    duration: f64,
    /// Seconds of publishing before the recording starts.
    #[arg(long, default_value_t = 2.0)]
    warmup: f64,
    /// Chunk compression of the recording.
    #[arg(long, default_value = "zstd")]
    compression: String,
    /// Print the summary as one JSON object.
    #[arg(long)]
    json: bool,
}

const ROBOT: &str = "bench_rec";

#[derive(serde::Serialize)]
struct Summary {
    offered_mb_per_s: f64,
    seconds: f64,
    sent: u64,
    recorded: u64,
    dropped: u64,
    file_bytes: u64,
    /// Message bytes over file bytes.
    compression_ratio: f64,
    recorder_cpu_percent: f64,
    hub_cpu_percent: f64,
}

impl crate::measure::Report for Summary {
    fn text(&self) -> String {
        format!(
            "offered {:.1} MB/s for {:.1} s: {} messages sent, {} recorded, {} dropped; \
             {:.1} MB of files (x{:.2}); recorder thread {:.1} % of a core, hub {:.1} %\n",
            self.offered_mb_per_s,
            self.seconds,
            self.sent,
            self.recorded,
            self.dropped,
            self.file_bytes as f64 / 1e6,
            self.compression_ratio,
            self.recorder_cpu_percent,
            self.hub_cpu_percent
        )
    }
}

/// One of the robot's topics.
struct Stream {
    alias: u32,
    topic: String,
    type_name: &'static str,
    rate: f64,
    cdr: Vec<u8>,
}

pub fn run(args: Args) -> anyhow::Result<()> {
    let json = args.json;
    crate::measure::run_measurement(None, json, bench(args))
}

/// A smooth value with noise, as bytes of a sensor's data look.
fn sensor_bytes(n: usize, seed: u64) -> Vec<u8> {
    let mut x = seed | 1;
    (0..n)
        .map(|i| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let smooth = ((i as f64 / 97.0).sin() * 100.0 + 120.0) as u8;
            smooth.wrapping_add((x % 7) as u8)
        })
        .collect()
}

fn cdr(registry: &Registry, type_name: &str, value: Value) -> anyhow::Result<Vec<u8>> {
    let msg = fleetlink_msg::from_json(registry, type_name, fleetlink_msg::Dialect::Ros2, &value)
        .with_context(|| format!("building a {type_name}"))?;
    Ok(fleetlink_msg::encode(registry, type_name, Wire::Cdr, &msg)?)
}

fn streams(rate_mb: f64) -> anyhow::Result<Vec<Stream>> {
    let registry = Registry::bundled();
    let header = json!({"stamp": {"sec": 0, "nanosec": 0}, "frame_id": "bench"});
    let image_bytes = 640 * 480 * 3;
    let image = cdr(
        &registry,
        "sensor_msgs/msg/Image",
        json!({"header": header, "height": 480, "width": 640, "encoding": "rgb8",
               "is_bigendian": 0, "step": 640 * 3, "data": sensor_bytes(image_bytes, 7)}),
    )?;
    let scan = cdr(
        &registry,
        "sensor_msgs/msg/LaserScan",
        json!({"header": header, "angle_min": -std::f64::consts::PI, "angle_max": std::f64::consts::PI, "angle_increment": 0.0058,
               "time_increment": 0.0, "scan_time": 0.025, "range_min": 0.1, "range_max": 30.0,
               "ranges": (0..1080).map(|i| 2.0 + (i as f64 / 50.0).sin()).collect::<Vec<_>>(),
               "intensities": (0..1080).map(|i| (i % 100) as f64).collect::<Vec<_>>()}),
    )?;
    let imu = cdr(
        &registry,
        "sensor_msgs/msg/Imu",
        json!({"header": header, "orientation": {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0},
               "linear_acceleration": {"x": 0.1, "y": 0.0, "z": 9.81}}),
    )?;
    let odom = cdr(
        &registry,
        "nav_msgs/msg/Odometry",
        json!({"header": header, "child_frame_id": "base_link",
               "pose": {"pose": {"position": {"x": 1.0, "y": 2.0, "z": 0.0},
                                 "orientation": {"w": 1.0}}}}),
    )?;
    let rest = image.len() as f64 * 15.0
        + scan.len() as f64 * 40.0
        + imu.len() as f64 * 200.0
        + odom.len() as f64 * 50.0;
    let cloud_rate = 30.0;
    let cloud_bytes = ((rate_mb * 1e6 - rest) / cloud_rate).max(16.0) as usize / 16 * 16;
    let points = cloud_bytes / 16;
    let field = |name: &str, offset: u32| json!({"name": name, "offset": offset, "datatype": 7, "count": 1});
    let cloud = cdr(
        &registry,
        "sensor_msgs/msg/PointCloud2",
        json!({"header": header, "height": 1, "width": points,
               "fields": [field("x", 0), field("y", 4), field("z", 8), field("intensity", 12)],
               "is_bigendian": false, "point_step": 16, "row_step": points * 16,
               "data": sensor_bytes(points * 16, 11), "is_dense": true}),
    )?;
    let s = |alias, name: &str, type_name, rate, cdr| Stream {
        alias,
        topic: format!("/{ROBOT}/{name}"),
        type_name,
        rate,
        cdr,
    };
    Ok(vec![
        s(
            1,
            "points",
            "sensor_msgs/msg/PointCloud2",
            cloud_rate,
            cloud,
        ),
        s(2, "image", "sensor_msgs/msg/Image", 15.0, image),
        s(3, "scan", "sensor_msgs/msg/LaserScan", 40.0, scan),
        s(4, "imu", "sensor_msgs/msg/Imu", 200.0, imu),
        s(5, "odom", "nav_msgs/msg/Odometry", 50.0, odom),
    ])
}

/// CPU seconds of the hub's threads whose name starts with `recorder`.
fn recorder_cpu(pid: u32) -> f64 {
    let Ok(tasks) = std::fs::read_dir(format!("/proc/{pid}/task")) else {
        return 0.0;
    };
    tasks
        .flatten()
        .filter(|t| {
            std::fs::read_to_string(t.path().join("comm")).is_ok_and(|c| c.starts_with("recorder"))
        })
        .filter_map(|t| stat_cpu_seconds(&t.path().join("stat").to_string_lossy()))
        .sum()
}

async fn bench(args: Args) -> anyhow::Result<Summary> {
    let streams = streams(args.rate_mb)?;
    let registry = Registry::bundled();
    let mut robot = conn::connect(&conn::hub_url(&args.hub), ROBOT, &args.robot_token)
        .await
        .context("the robot's link")?;
    let mut ads = Vec::new();
    for s in &streams {
        ads.push(Frame::Advertise {
            alias: s.alias,
            topic: s.topic.clone(),
            schema: Schema {
                type_name: s.type_name.into(),
                encoding: "ros2msg".into(),
                text: registry.full_text(s.type_name, fleetlink_msg::Dialect::Ros2)?,
            },
            encoding: Encoding::Cdr,
            flags: 0,
        });
    }
    robot.send_and_sync(&ads, "robot").await?;
    let offered: f64 = streams.iter().map(|s| s.cdr.len() as f64 * s.rate).sum();
    let stop = Arc::new(AtomicBool::new(false));
    let sent = Arc::new(AtomicU64::new(0));
    let publisher = tokio::spawn(publish(robot, streams, stop.clone(), sent.clone()));
    tokio::time::sleep(Duration::from_secs_f64(args.warmup)).await;

    let remote = Remote {
        hub: args.hub.clone(),
        token: args.token.clone(),
        ca: None,
    };
    let rec = remote
        .request(
            Method::POST,
            "/api/v1/recordings",
            Some(json!({"topics": [format!("/{ROBOT}/.*")], "name": "bench",
                        "compression": args.compression})),
        )
        .await?
        .json("starting the recording")?;
    let id = rec["id"].as_str().unwrap_or_default().to_owned();
    let sent0 = sent.load(Relaxed);
    let hub0 = proc_figures(args.hub_pid).map(|p| p.0);
    let rec0 = recorder_cpu(args.hub_pid);
    let t0 = Instant::now();
    tokio::time::sleep(Duration::from_secs_f64(args.duration)).await;
    let secs = t0.elapsed().as_secs_f64();
    let rec1 = recorder_cpu(args.hub_pid);
    let hub1 = proc_figures(args.hub_pid).map(|p| p.0);
    let sent1 = sent.load(Relaxed);
    let done = remote
        .request(Method::POST, &format!("/api/v1/recordings/{id}/stop"), None)
        .await?
        .json("stopping the recording")?;
    stop.store(true, Relaxed);
    publisher.await.context("publisher task")??;
    // The recording is the bench's alone: it goes with the bench.
    let _ = remote
        .request(Method::DELETE, &format!("/api/v1/recordings/{id}"), None)
        .await;
    if done["state"] != "stopped" {
        bail!("the recording ended {}: {}", done["state"], done["error"]);
    }
    let recorded = done["messages"].as_u64().unwrap_or(0);
    let file_bytes = done["bytes"].as_u64().unwrap_or(0);
    let message_bytes: f64 = offered * secs;
    Ok(Summary {
        offered_mb_per_s: offered / 1e6,
        seconds: secs,
        sent: sent1 - sent0,
        recorded,
        dropped: done["dropped"].as_u64().unwrap_or(0),
        file_bytes,
        compression_ratio: message_bytes / file_bytes.max(1) as f64,
        recorder_cpu_percent: (rec1 - rec0) * 100.0 / secs,
        hub_cpu_percent: hub0.zip(hub1).map_or(0.0, |(a, b)| (b - a) * 100.0 / secs),
    })
}

/// Sends every stream at its rate, in chunks; answers the hub's pings.
async fn publish(
    robot: conn::Conn,
    streams: Vec<Stream>,
    stop: Arc<AtomicBool>,
    sent: Arc<AtomicU64>,
) -> anyhow::Result<()> {
    let (mut sink, mut stream) = robot.ws.split();
    let start = tokio::time::Instant::now();
    let mut next: Vec<tokio::time::Instant> = streams.iter().map(|_| start).collect();
    let mut seq = vec![0u64; streams.len()];
    let mut buf = BytesMut::new();
    while !stop.load(Relaxed) {
        let (i, at) = next
            .iter()
            .copied()
            .enumerate()
            .min_by_key(|(_, t)| *t)
            .expect("streams");
        tokio::select! {
            _ = tokio::time::sleep_until(at) => {
                let s = &streams[i];
                let now = fleetlink_relay::unix_nanos();
                let total = s.cdr.len() as u64;
                for (k, data) in s.cdr.chunks(DEFAULT_CHUNK_SIZE).enumerate() {
                    let offset = (k * DEFAULT_CHUNK_SIZE) as u64;
                    frame::encode_chunk(&mut buf, false, s.alias, seq[i], now, total, offset, data);
                    sink.feed(WsMessage::Binary(buf.split().freeze())).await?;
                }
                sink.flush().await?;
                seq[i] += 1;
                sent.fetch_add(1, Relaxed);
                next[i] = at + Duration::from_secs_f64(1.0 / s.rate);
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
