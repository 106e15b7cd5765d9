//! fleetlink's whole-system benchmarks: the load generators behind `fleetlink bench
//! <subcommand>`, run against a running hub (or hubs, agents and other servers they start
//! themselves), each reporting one summary. Component benchmarks are criterion benches
//! beside their crates (`cargo bench`); results and the commands that produced them are in
//! `docs/benchmarks.md` (the latest figure per target) and `docs/benchmarks/log.md` (every
//! dated run). The `fleetlink` binary parses the command line with [`Args`] and calls
//! [`run`], handing in what it owns for the whole process ([`Host`]).
//!
//! Layout. Each subcommand is a module with its `Args` and `run`; the shared pieces below
//! them import nothing from the subcommands that use them.
//!
//! - [`relay`]: the `relay` subcommand: the run's order of events and what is counted.
//! - [`relay_args`]: the `relay` subcommand's options and measurement window, shared by
//!   its publishers, subscribers and report.
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
//! - [`measure`]: a summary's two forms and the runtime a measurement runs on.
//! - [`host`]: what a bench borrows from the binary that runs it.

mod calls;
mod conn;
mod copy_floor;
mod delivery;
mod fleet;
mod fleet_floor;
mod host;
mod journal;
mod measure;
mod publisher;
mod reconnect;
mod record;
mod relay;
mod relay_args;
mod report;
mod subscriber;
mod video;
mod viewer;
mod ws_floor;

pub use host::Host;

#[derive(clap::Args)]
pub struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(clap::Subcommand)]
enum Command {
    /// Publishers and subscribers on fleetlink.v1 links through a running hub: delivered
    /// msg/s, MB/s, latency percentiles and drops.
    Relay(relay_args::Args),
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

/// Runs the subcommand `args` names.
pub fn run(args: Args, host: &Host) -> anyhow::Result<()> {
    match args.command {
        Command::Relay(a) => relay::run(a),
        Command::Fleet(a) => fleet::run(a, host),
        Command::Reconnect(a) => reconnect::run(a, host),
        Command::Calls(a) => calls::run(a, host),
        Command::Delivery(a) => delivery::run(a, host),
        Command::CopyFloor(a) => copy_floor::run(a),
        Command::WsFloor(a) => ws_floor::run(a),
        Command::FleetFloor(a) => fleet_floor::run(a),
        Command::Viewer(a) => viewer::run(a, host),
        Command::Record(a) => record::run(a),
        Command::Journal(a) => journal::run(a),
        Command::Video(a) => video::run(a),
    }
}
