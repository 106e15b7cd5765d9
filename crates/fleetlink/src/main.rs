//! The `fleetlink` binary: command-line glue only.
//!
//! Every subcommand lives in its own module under `cmd/` with an `Args` struct and a
//! `run(args)` function; the work itself is done by the library crates.

mod cmd;

use std::sync::Arc;

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

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
    /// Record topics to MCAP on a hub; list, stop, download and remove recordings.
    Record(cmd::record::Args),
    /// Publish an MCAP file's messages to a hub with their original timing.
    Play(cmd::play::Args),
    /// Reproduce the AFR paper's quality-of-information comparison (Figure 5).
    QoiSim(cmd::qoi_sim::Args),
}

fn main() -> std::process::ExitCode {
    // A user's error is one line saying what is wrong and what to do: never a backtrace
    // (even with RUST_BACKTRACE set), never the `Debug` form of the error chain.
    // Parsed through `ArgMatches` so `--check` can tell given values from defaults.
    let matches = Cli::command().get_matches();
    let cli = Cli::from_arg_matches(&matches).unwrap_or_else(|e| e.exit());
    match run(cli, &matches) {
        Ok(()) => std::process::ExitCode::SUCCESS,
        // Output piped into `head` and closed early: the reader has what it wanted.
        Err(e) if is_broken_pipe(&e) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", error_text(&e));
            std::process::ExitCode::FAILURE
        }
    }
}

fn is_broken_pipe(e: &anyhow::Error) -> bool {
    use std::io::ErrorKind::BrokenPipe;
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == BrokenPipe)
            || c.downcast_ref::<serde_json::Error>()
                .is_some_and(|j| j.io_error_kind() == Some(BrokenPipe))
    })
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

fn run(cli: Cli, matches: &clap::ArgMatches) -> anyhow::Result<()> {
    // The subcommand's own definition and values, for `--check`'s listing.
    let sub = |name: &str| {
        let command = Cli::command().find_subcommand(name).cloned();
        let m = matches.subcommand_matches(name).cloned();
        command.zip(m).expect("the subcommand that was parsed")
    };
    match cli.command {
        Command::Hub(args) if args.check => {
            let (command, m) = sub("hub");
            cmd::hub::check(&args, &command, &m)
        }
        Command::Hub(args) => cmd::hub::run(args),
        Command::Agent(args) if args.check => {
            let (command, m) = sub("agent");
            cmd::agent::check(&args, &command, &m)
        }
        Command::Agent(args) => cmd::agent::run(args),
        Command::Demo(args) => cmd::demo::run(args),
        Command::Bench(args) => cmd::bench::run(args),
        Command::Admin(args) => cmd::admin::run(args),
        Command::Msg(args) => cmd::msg::run(args),
        Command::Record(args) => cmd::record::run(args),
        Command::Play(args) => cmd::play::run(args),
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
    use super::{Cli, error_text};

    #[test]
    fn a_closed_pipe_is_not_an_error() {
        let pipe = std::io::Error::new(std::io::ErrorKind::BrokenPipe, "broken pipe");
        assert!(super::is_broken_pipe(
            &anyhow::Error::new(pipe).context("writing the list")
        ));
        let other = std::io::Error::new(std::io::ErrorKind::NotFound, "no such file");
        assert!(!super::is_broken_pipe(&anyhow::Error::new(other)));
    }

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

    /// Issue 14: `--help` showed empty descriptions. Every subcommand and argument a user
    /// can see must say what it is.
    #[test]
    fn issue14_every_subcommand_and_argument_has_help_text() {
        fn walk(cmd: &clap::Command, path: &str, missing: &mut Vec<String>) {
            for arg in cmd.get_arguments() {
                let id = arg.get_id().as_str();
                if arg.is_hide_set() || id == "help" || id == "version" {
                    continue;
                }
                if arg.get_help().is_none() && arg.get_long_help().is_none() {
                    missing.push(format!("{path} <{id}>"));
                }
            }
            for sub in cmd.get_subcommands() {
                let here = format!("{path} {}", sub.get_name());
                if sub.get_about().is_none() && sub.get_long_about().is_none() {
                    missing.push(here.clone());
                }
                walk(sub, &here, missing);
            }
        }
        let mut missing = Vec::new();
        walk(
            &<Cli as clap::CommandFactory>::command(),
            "fleetlink",
            &mut missing,
        );
        assert!(
            missing.is_empty(),
            "without help text (add a /// doc comment):\n  {}",
            missing.join("\n  ")
        );
    }
}
