//! The `fleetlink` binary: command-line glue only.
//!
//! Every subcommand lives in its own module under `cmd/` with an `Args` struct and a
//! `run(args)` function; the work itself is done by the library crates.

mod cmd;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(
    name = "fleetlink",
    version,
    about = "Communication for robot fleets: hub, agent, demo and tools"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Inspect ROS interface definitions and convert serialized messages.
    Msg(cmd::msg::Args),
    /// Reproduce the AFR paper's quality-of-information comparison (Figure 5).
    QoiSim(cmd::qoi_sim::Args),
}

fn main() -> anyhow::Result<()> {
    let cli = Cli::parse();
    match cli.command {
        Command::Msg(args) => cmd::msg::run(args),
        Command::QoiSim(args) => cmd::qoi_sim::run(args),
    }
}
