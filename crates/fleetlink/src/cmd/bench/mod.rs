//! `fleetlink bench`: whole-system load generators against a running hub. Component
//! benchmarks are criterion benches beside their crates (`cargo bench`); results and the
//! commands that produced them are in `docs/benchmarks.md` (the latest figure per target)
//! and `docs/benchmarks/log.md` (every dated run).
//!
//! - [`relay`]: the `relay` subcommand: options, the run's order of events and what is
//!   counted.
//! - [`calls`]: the `calls` subcommand: service round trips through a hub and an agent.
//! - [`delivery`]: the `delivery` subcommand: a server's CPU per delivered message, for
//!   the hub's protocols and for NATS and MQTT servers.
//! - [`conn`]: a bench client's `fleetlink.v1` connection and setup handshake.
//! - [`publisher`], [`subscriber`]: the two kinds of client and their hot loops.
//! - [`report`]: the progress line and the final summary.
//! - [`copy_floor`]: the `copy-floor` subcommand: the CPU of a plain loopback TCP relay,
//!   the floor under a bridge's figure.
//! - [`ws_floor`]: the `ws-floor` subcommand: a bare WebSocket relay, the floor under the
//!   hub's figure in `delivery`.
//! - [`fleet`]: the `fleet` subcommand: N simulated robots with T topics each from one
//!   process against one or several hubs: throughput, latency, connect time, hub CPU and
//!   memory per robot.
//! - [`fleet_floor`]: the `fleet-floor` subcommand: the least a hub does for the fleet
//!   bench's traffic, the floor under the hub's figure in `fleet`.
//! - [`reconnect`]: the `reconnect` subcommand: a fleet of in-process agents against a
//!   hub that restarts, measuring how the fleet comes back.
//! - [`viewer`]: the `viewer` subcommand: a large point cloud watched over Foxglove
//!   WebSocket or rosbridge CBOR, side by side.
//! - [`record`]: the `record` subcommand: the hub recording a robot's mixed topics to
//!   MCAP at a given rate; the recorder thread's CPU and its drops.
//! - [`video`]: the `video` subcommand: camera video against JPEG on the same frames
//!   (bytes at equal luma PSNR, encode time).
//! - [`journal`]: the `journal` subcommand: the agent thread's heartbeat and an adapter
//!   while the durable outbox compacts on a slow disk (test builds).

mod calls;
mod conn;
mod copy_floor;
mod delivery;
mod fleet;
mod fleet_floor;
mod journal;
mod publisher;
mod reconnect;
mod record;
mod relay;
mod report;
mod subscriber;
mod video;
mod viewer;
mod ws_floor;

#[derive(clap::Args)]
pub struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(clap::Subcommand)]
enum Command {
    /// Publishers and subscribers on fleetlink.v1 links through a running hub: delivered
    /// msg/s, MB/s, latency percentiles and drops.
    Relay(relay::Args),
    /// N simulated robots (T topics at a rate each) and their subscribers against one hub
    /// or several federated hubs: connect time, delivered msg/s, latency percentiles, and
    /// the hubs' CPU and memory per robot, idle and loaded.
    Fleet(fleet::Args),
    /// A fleet of agents against a hub that is stopped and restarted: how fast and how
    /// spread out the robots come back (backoff, jitter, handshake admission).
    Reconnect(reconnect::Args),
    /// Service calls from rosbridge clients on the hub to a provider on an agent's local
    /// listener: round-trip percentiles, calls/s, servers' CPU per call and memory.
    Calls(calls::Args),
    /// One publisher and its subscribers at a fixed rate through a server speaking
    /// rosbridge JSON or CBOR, fleetlink.v1, NATS or MQTT: the server's CPU per delivered
    /// message, from /proc.
    Delivery(delivery::Args),
    /// A plain loopback TCP relay (blocking reads and writes, nothing else) carrying
    /// messages of a given size and rate: its CPU, the floor under any bridge's figure.
    CopyFloor(copy_floor::Args),
    /// A bare WebSocket relay (each text frame passed to every subscriber as it is, no
    /// parsing, checks or routing) serving until killed: measured with `delivery
    /// --protocol rosbridge-json`, the floor under the hub's figure.
    WsFloor(ws_floor::Args),
    /// The least a hub does to carry `bench fleet`'s traffic (`fleetlink.v1` handshake,
    /// pongs, interest, messages passed to the matching subscribers; no auth, QoS, acks
    /// or statistics): the floor under the hub's figure in the fleet bench.
    FleetFloor(fleet_floor::Args),
    /// A robot's large point cloud watched by viewers over the Foxglove WebSocket protocol
    /// or rosbridge CBOR: delivery ratio, latency from the cloud's stamp, the hub's CPU.
    Viewer(viewer::Args),
    /// The hub recording a robot's mixed topics (point cloud, image, scan, IMU, odometry)
    /// to MCAP at a given data rate: messages recorded and dropped, the recorder thread's
    /// CPU.
    Record(record::Args),
    /// Camera video against JPEG on the same frames: for each clip, the H.264 bitrate that
    /// matches JPEG's luma PSNR, the bytes of each, and the encoder's time per frame.
    Video(video::Args),
    /// The agent thread's heartbeat lateness and an adapter's latency while the durable
    /// outbox compacts a large journal on a simulated slow disk (test builds only).
    Journal(journal::Args),
}

pub fn run(args: Args) -> anyhow::Result<()> {
    match args.command {
        Command::Relay(a) => relay::run(a),
        Command::Fleet(a) => fleet::run(a),
        Command::Reconnect(a) => reconnect::run(a),
        Command::Calls(a) => calls::run(a),
        Command::Delivery(a) => delivery::run(a),
        Command::CopyFloor(a) => copy_floor::run(a),
        Command::WsFloor(a) => ws_floor::run(a),
        Command::FleetFloor(a) => fleet_floor::run(a),
        Command::Viewer(a) => viewer::run(a),
        Command::Record(a) => record::run(a),
        Command::Journal(a) => journal::run(a),
        Command::Video(a) => video::run(a),
    }
}

/// A bench's final summary: one JSON object with `--json`, else text.
trait Report: serde::Serialize {
    fn text(&self) -> String;
}

/// Runs `measure` on a multi-thread runtime (`threads` workers, default one per core) and
/// prints its summary. Connections still open are dropped with the runtime; nothing
/// waits for the hub to close them.
fn run_measurement<R: Report>(
    threads: Option<usize>,
    json: bool,
    measure: impl Future<Output = anyhow::Result<R>>,
) -> anyhow::Result<()> {
    use anyhow::Context;
    let mut rt = tokio::runtime::Builder::new_multi_thread();
    if let Some(n) = threads {
        rt.worker_threads(n.max(1));
    }
    let rt = rt
        .enable_all()
        .build()
        .context("starting the async runtime")?;
    let summary = rt.block_on(measure)?;
    if json {
        println!("{}", serde_json::to_string(&summary)?);
    } else {
        print!("{}", summary.text());
    }
    rt.shutdown_timeout(std::time::Duration::from_millis(200));
    Ok(())
}
