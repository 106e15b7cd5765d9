//! The `fleetlink` binary: command-line glue only.
//!
//! Every subcommand lives in its own module under `cmd/` with an `Args` struct and a
//! `run(args)` function; the work itself is done by the library crates.

mod cmd;

use std::sync::Arc;

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
// Parsed once at start-up; boxing the larger variants would buy nothing.
#[allow(clippy::large_enum_variant)]
enum Command {
    /// Run a hub: the relay robots connect to and operators use.
    Hub(cmd::hub::Args),
    /// Run an agent on a robot: connects out to a hub.
    Agent(cmd::agent::Args),
    /// Run a hub with three simulated robots, on one command.
    Demo(cmd::demo::Args),
    /// Load generators and measurements against a running hub.
    Bench(cmd::bench::Args),
    /// Manage a hub's tokens, users, access rules and audit log (on its data directory).
    Admin(cmd::admin::Args),
    /// Inspect ROS interface definitions and convert serialized messages.
    Msg(cmd::msg::Args),
    /// Reproduce the AFR paper's quality-of-information comparison (Figure 5).
    QoiSim(cmd::qoi_sim::Args),
}

fn main() -> std::process::ExitCode {
    // A user's error is one line saying what is wrong and what to do: never a backtrace
    // (even with RUST_BACKTRACE set), never the `Debug` form of the error chain.
    match run(Cli::parse()) {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", error_text(&e));
            std::process::ExitCode::FAILURE
        }
    }
}

/// An error and its causes on one line, each cause once: errors that already quote their
/// source in their own text are not followed by it again ("X: X").
fn error_text(e: &anyhow::Error) -> String {
    let mut text = e.to_string();
    for cause in e.chain().skip(1) {
        let c = cause.to_string();
        if !text.contains(&c) {
            text.push_str(": ");
            text.push_str(&c);
        }
    }
    text
}

fn run(cli: Cli) -> anyhow::Result<()> {
    match cli.command {
        Command::Hub(args) => cmd::hub::run(args),
        Command::Agent(args) => cmd::agent::run(args),
        Command::Demo(args) => cmd::demo::run(args),
        Command::Bench(args) => cmd::bench::run(args),
        Command::Admin(args) => cmd::admin::run(args),
        Command::Msg(args) => cmd::msg::run(args),
        Command::QoiSim(args) => cmd::qoi_sim::run(args),
    }
}

/// How messages are converted between encodings in this binary: the bundled
/// definitions plus the packages under each `--msg-path` directory.
pub fn transcoder(
    msg_path: &[std::path::PathBuf],
) -> anyhow::Result<Arc<dyn fleetlink_relay::Transcoder>> {
    use anyhow::Context;
    let registry = fleetlink_msg::Registry::bundled();
    for dir in msg_path {
        registry.add_package_dir(dir).with_context(|| {
            format!(
                "loading --msg-path {} (a directory of ROS packages: DIR/<package>/msg/<Type>.msg)",
                dir.display()
            )
        })?;
    }
    Ok(Arc::new(
        fleetlink_relay::transcode::RegistryTranscoder::new(registry),
    ))
}

#[cfg(test)]
mod tests {
    use super::error_text;

    #[test]
    fn causes_are_shown_once() {
        let io = std::io::Error::new(std::io::ErrorKind::NotFound, "no such file");
        let quoted = anyhow::Error::new(io).context("robot.yaml: cannot read config: no such file");
        assert_eq!(
            error_text(&quoted),
            "robot.yaml: cannot read config: no such file"
        );
        let io = std::io::Error::new(std::io::ErrorKind::NotFound, "no such file");
        let plain = anyhow::Error::new(io).context("loading --msg-path msgs");
        assert_eq!(error_text(&plain), "loading --msg-path msgs: no such file");
    }
}
