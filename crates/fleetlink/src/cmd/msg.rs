//! `fleetlink msg`: show definitions, decode and encode messages (issue 4).
//!
//! A debugging aid in the spirit of `ros2 interface show`, working from the bundled
//! definitions plus any `--msg-path` package directories, without a ROS installation.
//! All the work is done by `fleetlink-msg`; this module only moves bytes between
//! stdin/stdout and the library.

use std::io::{Read, Write};
use std::path::PathBuf;

use anyhow::Context;
use fleetlink_msg::spec::Definition;
use fleetlink_msg::{Dialect, Registry, Wire};

#[derive(clap::Args)]
pub struct Args {
    /// Directory of ROS packages (or one package) with extra .msg/.srv/.action files.
    #[arg(long = "msg-path", value_name = "DIR", global = true)]
    msg_path: Vec<PathBuf>,
    #[command(subcommand)]
    command: Command,
}

#[derive(clap::Subcommand)]
enum Command {
    /// Print a type's full definition with its dependencies.
    Show {
        /// `pkg/Type`, `pkg/msg/Type`, `pkg/srv/Type` or `pkg/action/Type`.
        type_name: String,
        /// Which generation's definitions to show.
        #[arg(long, value_enum, default_value_t = DialectArg::Ros2)]
        dialect: DialectArg,
    },
    /// Read a serialized message on stdin and print it as rosbridge JSON.
    Decode {
        /// The message type, e.g. `sensor_msgs/msg/LaserScan` or `std_msgs/String`.
        type_name: String,
        /// How the bytes on stdin are serialized.
        #[arg(long, value_enum)]
        format: Format,
    },
    /// Read rosbridge JSON on stdin and write the serialized message to stdout.
    Encode {
        /// The message type, e.g. `sensor_msgs/msg/LaserScan` or `std_msgs/String`.
        type_name: String,
        /// How to serialize the message written to stdout.
        #[arg(long, value_enum)]
        format: Format,
    },
    /// Print a type's identities: ROS 1 md5sum, DDS name, REP-2016 type hash.
    Ids {
        /// The message type, e.g. `sensor_msgs/msg/LaserScan` or `std_msgs/String`.
        type_name: String,
    },
    /// List every known message type (bundled and `--msg-path`), one per line; with
    /// `--full-texts`, a JSON object of each type's full definition in `--dialect`.
    List {
        /// Print every type's full definition (with its dependencies) as JSON.
        #[arg(long)]
        full_texts: bool,
        /// Which generation's definitions to print with `--full-texts`.
        #[arg(long, value_enum, default_value_t = DialectArg::Ros2)]
        dialect: DialectArg,
    },
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum Format {
    /// ROS 2 CDR, as DDS carries it (with its 4-byte encapsulation header).
    Cdr,
    /// ROS 1 serialization, as TCPROS and rosbag carry it.
    Ros1,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum DialectArg {
    /// ROS 1 `.msg` syntax.
    Ros1,
    /// ROS 2 `.msg` syntax.
    Ros2,
}

impl From<DialectArg> for Dialect {
    fn from(d: DialectArg) -> Self {
        match d {
            DialectArg::Ros1 => Dialect::Ros1,
            DialectArg::Ros2 => Dialect::Ros2,
        }
    }
}

impl From<Format> for Wire {
    fn from(f: Format) -> Self {
        match f {
            Format::Cdr => Wire::Cdr,
            Format::Ros1 => Wire::Ros1,
        }
    }
}

pub fn run(args: Args) -> anyhow::Result<()> {
    let registry = Registry::bundled();
    for dir in &args.msg_path {
        registry
            .add_package_dir(dir)
            .with_context(|| format!("loading --msg-path {}", dir.display()))?;
    }
    let mut stdout = std::io::stdout().lock();
    match args.command {
        Command::Show { type_name, dialect } => {
            writeln!(stdout, "{}", show(&registry, &type_name, dialect.into())?)?;
        }
        Command::List {
            full_texts,
            dialect,
        } => {
            let mut names: Vec<String> = registry
                .message_names()
                .iter()
                .map(|n| n.to_string())
                .collect();
            names.sort();
            if full_texts {
                let mut map = serde_json::Map::new();
                for n in names {
                    // Parts only some dialect has (ROS 2's action wrappers) are skipped.
                    if let Ok(t) = fleetlink_msg::full_text(&registry, &n, dialect.into()) {
                        map.insert(n, serde_json::Value::String(t));
                    }
                }
                serde_json::to_writer_pretty(&mut stdout, &map)?;
                writeln!(stdout)?;
            } else {
                for n in names {
                    writeln!(stdout, "{n}")?;
                }
            }
        }
        Command::Decode { type_name, format } => {
            let input = read_stdin()?;
            let json = match Wire::from(format) {
                Wire::Cdr => fleetlink_msg::cdr_to_json_bytes(&registry, &type_name, &input)?,
                wire => fleetlink_msg::to_json_bytes(&fleetlink_msg::decode(
                    &registry, &type_name, wire, &input,
                )?),
            };
            stdout.write_all(&json)?;
            stdout.write_all(b"\n")?;
        }
        Command::Encode { type_name, format } => {
            let input = read_stdin()?;
            let wire = Wire::from(format);
            let dialect = fleetlink_msg::dialect_of(wire);
            let value = fleetlink_msg::from_json_bytes(&registry, &type_name, dialect, &input)?;
            stdout.write_all(&fleetlink_msg::encode(&registry, &type_name, wire, &value)?)?;
        }
        Command::Ids { type_name } => {
            let name = registry.resolve_name(&type_name, Dialect::Ros2)?;
            writeln!(stdout, "type:     {name}")?;
            writeln!(stdout, "dds:      {}", name.dds_name())?;
            match fleetlink_msg::md5sum(&registry, &type_name) {
                Ok(m) => writeln!(stdout, "md5sum:   {m}")?,
                Err(e) => writeln!(stdout, "md5sum:   n/a ({e})")?,
            }
            match fleetlink_msg::type_hash(&registry, &type_name) {
                Ok(h) => writeln!(stdout, "rihs01:   {h}")?,
                Err(e) => writeln!(stdout, "rihs01:   n/a ({e})")?,
            }
        }
    }
    stdout.flush()?;
    Ok(())
}

fn read_stdin() -> anyhow::Result<Vec<u8>> {
    let mut buf = Vec::new();
    std::io::stdin()
        .read_to_end(&mut buf)
        .context("reading stdin")?;
    Ok(buf)
}

/// A message's full text, or for a service/action each part's full text in turn.
fn show(registry: &Registry, type_name: &str, dialect: Dialect) -> anyhow::Result<String> {
    let def = registry.interface(type_name, dialect)?;
    let parts: Vec<String> = match &*def {
        Definition::Msg(m) => vec![m.name.to_string()],
        Definition::Srv {
            request, response, ..
        } => vec![request.name.to_string(), response.name.to_string()],
        Definition::Action {
            goal,
            result,
            feedback,
            ..
        } => {
            vec![
                goal.name.to_string(),
                result.name.to_string(),
                feedback.name.to_string(),
            ]
        }
    };
    let texts = parts
        .iter()
        .map(|p| fleetlink_msg::full_text(registry, p, dialect))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(texts.join("\n---\n"))
}
