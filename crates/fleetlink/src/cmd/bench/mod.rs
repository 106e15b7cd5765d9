//! `fleetlink bench`: whole-system load generators against a running hub. Component
//! benchmarks are criterion benches beside their crates (`cargo bench`); results and the
//! commands that produced them are in `docs/benchmarks.md`.
//!
//! - [`relay`]: the `relay` subcommand: options, the run's order of events and what is
//!   counted.
//! - [`conn`]: a bench client's `fleetlink.v1` connection and setup handshake.
//! - [`publisher`], [`subscriber`]: the two kinds of client and their hot loops.
//! - [`report`]: the progress line and the final summary.

mod conn;
mod publisher;
mod relay;
mod report;
mod subscriber;

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
}

pub fn run(args: Args) -> anyhow::Result<()> {
    match args.command {
        Command::Relay(a) => relay::run(a),
    }
}
