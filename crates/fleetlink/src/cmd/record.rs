//! `fleetlink record`: MCAP recordings on a hub, through its API.
//!
//! `fleetlink record --hub URL --topics PATTERN…` starts a recording on the hub and
//! prints it. With `--out DIR` it stays: until the recording's `--duration` is over, or
//! until Ctrl-C (which stops it), then downloads its files into DIR. `list`, `stop`,
//! `download` and `remove` act on the hub's recordings; `blackbox` asks a robot for a
//! slice of its black box, which becomes one of them.

use std::path::PathBuf;

use anyhow::Context;
use fleetlink_record::spec::{parse_duration_s, parse_size};
use fleetlink_record::{Compression, RecordSpec};
use hyper::Method;
use serde_json::Value;

use super::remote::Remote;

#[derive(clap::Args, Debug)]
#[command(args_conflicts_with_subcommands = true)]
pub struct Args {
    #[command(subcommand)]
    action: Option<Action>,
    #[command(flatten)]
    start: Start,
}

#[derive(clap::Subcommand, Debug)]
enum Action {
    /// The hub's recordings, newest first.
    List {
        #[command(flatten)]
        remote: Remote,
        /// Print the API's JSON instead of a table.
        #[arg(long)]
        json: bool,
    },
    /// Stop a recording; its files are finished when this returns.
    Stop {
        /// The recording's id (`rec-…`, from `list`).
        id: String,
        #[command(flatten)]
        remote: Remote,
    },
    /// Download a recording's files into a directory.
    Download {
        /// The recording's id (`rec-…`, from `list`).
        id: String,
        #[command(flatten)]
        remote: Remote,
        /// Where the files go (created if missing).
        #[arg(long, default_value = ".")]
        out: PathBuf,
    },
    /// Stop a recording and delete its files on the hub.
    Remove {
        /// The recording's id (`rec-…`, from `list`).
        id: String,
        #[command(flatten)]
        remote: Remote,
    },
    /// Ask a robot for a slice of its black box (its agent's `blackbox:` ring); the hub
    /// keeps it as a recording.
    Blackbox(Blackbox),
}

#[derive(clap::Args, Debug)]
struct Blackbox {
    /// The robot's name.
    #[arg(long)]
    robot: String,
    #[command(flatten)]
    remote: Remote,
    /// The last this long before now, by the robot's clock (`60s`, `5m`).
    #[arg(long, value_name = "DURATION", value_parser = parse_duration_s, conflicts_with = "from")]
    last: Option<u64>,
    /// From this time (RFC 3339, `2026-11-28T23:00:00Z`).
    #[arg(long, value_name = "TIME", value_parser = parse_time_ns)]
    from: Option<u64>,
    /// Until this time (RFC 3339); default now.
    #[arg(long, value_name = "TIME", value_parser = parse_time_ns, requires = "from")]
    to: Option<u64>,
    /// The robot's local topic names (whole-name regular expressions); default every
    /// topic its black box keeps.
    #[arg(long, num_args = 1.., value_name = "PATTERN")]
    topics: Vec<String>,
    /// A label; the file is named after it.
    #[arg(long)]
    name: Option<String>,
    /// Wait until the slice is at the hub, then download it into this directory.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
}

/// An RFC 3339 time as Unix nanoseconds.
fn parse_time_ns(text: &str) -> Result<u64, String> {
    let t =
        time::OffsetDateTime::parse(text.trim(), &time::format_description::well_known::Rfc3339)
            .map_err(|e| {
                format!("{text:?} is not an RFC 3339 time like 2026-11-28T23:00:00Z: {e}")
            })?;
    u64::try_from(t.unix_timestamp_nanos()).map_err(|_| format!("{text:?} is before 1970"))
}

// The start's flags are declared here rather than as a flattened `Remote`: clap takes an
// optional flattened group only when one of its own flags is given, and --hub would be
// required even for `fleetlink record list`.
#[derive(clap::Args, Debug)]
struct Start {
    /// The hub: ws://HOST:PORT, wss://…, http(s)://…, or HOST:PORT.
    #[arg(long, value_name = "URL")]
    hub: Option<String>,
    /// The caller's token (a user's, from `fleetlink admin token` or the login API). Also
    /// read from FLEETLINK_TOKEN.
    #[arg(
        long,
        env = "FLEETLINK_TOKEN",
        hide_env_values = true,
        default_value = ""
    )]
    token: String,
    /// Check a wss:// or https:// hub's certificate against this CA file instead of the
    /// system's roots.
    #[arg(long, value_name = "FILE")]
    ca: Option<PathBuf>,
    /// Topics to record: whole-name regular expressions (`/robot1/.*`, `/robot2/scan`).
    #[arg(long, num_args = 1.., value_name = "PATTERN")]
    topics: Vec<String>,
    /// A label; the files are named after it.
    #[arg(long)]
    name: Option<String>,
    /// Start a new file after this size (`500MB`, `2GiB`).
    #[arg(long, value_name = "SIZE", value_parser = parse_size)]
    split_size: Option<u64>,
    /// Start a new file after this long (`10m`, `1h`).
    #[arg(long, value_name = "DURATION", value_parser = parse_duration_s)]
    split_duration: Option<u64>,
    /// Stop after this long (`30s`, `2h`); otherwise it records until stopped.
    #[arg(long, value_name = "DURATION", value_parser = parse_duration_s)]
    duration: Option<u64>,
    /// Chunk compression.
    #[arg(long, value_enum, default_value = "zstd")]
    compression: CompressionArg,
    /// Messages kept per topic while the hub's disk is behind (more drop the oldest).
    #[arg(long, default_value_t = fleetlink_record::spec::DEFAULT_QUEUE)]
    queue: usize,
    /// Stay until the recording ends (its --duration, or Ctrl-C, which stops it), then
    /// download its files into this directory.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
}

#[derive(clap::ValueEnum, Clone, Copy, Debug)]
enum CompressionArg {
    Zstd,
    Lz4,
    None,
}

pub fn run(args: Args) -> anyhow::Result<()> {
    super::init_logging("warn");
    let rt = tokio::runtime::Runtime::new().context("starting the async runtime")?;
    rt.block_on(async move {
        match (args.action, args.start) {
            (Some(Action::List { remote, json }), _) => list(&remote, json).await,
            (Some(Action::Stop { id, remote }), _) => {
                let v = remote
                    .request(Method::POST, &format!("/api/v1/recordings/{id}/stop"), None)
                    .await?
                    .json(&format!("stopping {id}"))?;
                println!("{}", summary(&v));
                Ok(())
            }
            (Some(Action::Download { id, remote, out }), _) => download(&remote, &id, &out).await,
            (Some(Action::Remove { id, remote }), _) => {
                remote
                    .request(Method::DELETE, &format!("/api/v1/recordings/{id}"), None)
                    .await?
                    .json(&format!("removing {id}"))?;
                println!("removed {id}");
                Ok(())
            }
            (Some(Action::Blackbox(b)), _) => blackbox(b).await,
            (None, s) if s.hub.is_some() && !s.topics.is_empty() => start(s).await,
            (None, _) => anyhow::bail!(
                "give --hub URL --topics PATTERN… to start a recording, or one of list, stop, \
                 download, remove, blackbox (see fleetlink record --help)"
            ),
        }
    })
}

async fn start(s: Start) -> anyhow::Result<()> {
    let remote = Remote {
        hub: s.hub.unwrap_or_default(),
        token: s.token,
        ca: s.ca,
    };
    let spec = RecordSpec {
        topics: s.topics,
        name: s.name,
        split_size_bytes: s.split_size,
        split_duration_s: s.split_duration,
        duration_s: s.duration,
        compression: match s.compression {
            CompressionArg::Zstd => Compression::Zstd,
            CompressionArg::Lz4 => Compression::Lz4,
            CompressionArg::None => Compression::None,
        },
        queue: s.queue,
    };
    // The hub checks it too; checking here says what is wrong before connecting.
    spec.check().map_err(|e| anyhow::anyhow!("{e}"))?;
    let v = remote
        .request(
            Method::POST,
            "/api/v1/recordings",
            Some(serde_json::to_value(&spec)?),
        )
        .await?
        .json("starting the recording")?;
    let id = v["id"].as_str().unwrap_or_default().to_owned();
    println!("{}", summary(&v));
    let Some(out) = s.out else {
        println!(
            "stop it with: fleetlink record stop {id} --hub {}",
            remote.hub
        );
        return Ok(());
    };
    eprintln!("recording; Ctrl-C stops it");
    let path = format!("/api/v1/recordings/{id}");
    loop {
        tokio::select! {
            _ = super::shutdown_signal() => break,
            _ = tokio::time::sleep(std::time::Duration::from_secs(1)) => {
                let v = remote.request(Method::GET, &path, None).await?.json(&id)?;
                if v["state"] != "recording" {
                    break;
                }
            }
        }
    }
    let v = remote
        .request(Method::POST, &format!("{path}/stop"), None)
        .await?
        .json(&format!("stopping {id}"))?;
    println!("{}", summary(&v));
    download(&remote, &id, &out).await
}

async fn blackbox(b: Blackbox) -> anyhow::Result<()> {
    let spec = fleetlink_record::blackbox::fetch::FetchSpec {
        robot: b.robot,
        last_s: match (b.last, b.from) {
            (None, None) => {
                anyhow::bail!("give the time range: --last 60s, or --from TIME [--to TIME]")
            }
            (l, _) => l.map(|s| s as f64),
        },
        from_ns: b.from,
        to_ns: b.to,
        topics: b.topics,
        name: b.name,
    };
    spec.check().map_err(|e| anyhow::anyhow!("{e}"))?;
    let remote = b.remote;
    let v = remote
        .request(
            Method::POST,
            "/api/v1/recordings/blackbox",
            Some(serde_json::to_value(&spec)?),
        )
        .await?
        .json("asking for the black box")?;
    let id = v["id"].as_str().unwrap_or_default().to_owned();
    println!("{}", summary(&v));
    let Some(out) = b.out else {
        println!(
            "follow it with: fleetlink record list --hub {}; download it with: fleetlink record \
             download {id} --hub {}",
            remote.hub, remote.hub
        );
        return Ok(());
    };
    let path = format!("/api/v1/recordings/{id}");
    let mut said = String::new();
    let v = loop {
        tokio::select! {
            _ = super::shutdown_signal() => {
                remote.request(Method::POST, &format!("{path}/stop"), None).await?.json(&id)?;
                anyhow::bail!("interrupted; the fetch {id} was stopped");
            }
            _ = tokio::time::sleep(std::time::Duration::from_millis(500)) => {
                let v = remote.request(Method::GET, &path, None).await?.json(&id)?;
                if v["state"] != "fetching" {
                    break v;
                }
                let bb = &v["blackbox"];
                let now = match (bb["waiting"].as_str(), bb["size"].as_u64()) {
                    (Some(w), _) => w.to_owned(),
                    (None, Some(size)) => format!("{} of {size} bytes", bb["received"]),
                    (None, None) => "the robot is cutting the slice".to_owned(),
                };
                if now != said {
                    eprintln!("{now}");
                    said = now;
                }
            }
        }
    };
    println!("{}", summary(&v));
    if v["state"] != "stopped" {
        anyhow::bail!(
            "the fetch {id} failed: {}",
            v["error"].as_str().unwrap_or("no reason given")
        );
    }
    download(&remote, &id, &out).await
}

async fn list(remote: &Remote, json: bool) -> anyhow::Result<()> {
    let v = remote
        .request(Method::GET, "/api/v1/recordings", None)
        .await?
        .json("listing recordings")?;
    if json {
        println!("{}", serde_json::to_string_pretty(&v)?);
        return Ok(());
    }
    let all = v["recordings"].as_array().cloned().unwrap_or_default();
    if all.is_empty() {
        println!("no recordings");
    }
    for r in all {
        println!("{}", summary(&r));
    }
    Ok(())
}

async fn download(remote: &Remote, id: &str, out: &std::path::Path) -> anyhow::Result<()> {
    let v = remote
        .request(Method::GET, &format!("/api/v1/recordings/{id}"), None)
        .await?
        .json(id)?;
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    for f in v["files"].as_array().cloned().unwrap_or_default() {
        let name = f["name"].as_str().unwrap_or_default();
        // Names come from the hub: never let one climb out of the directory.
        if name.is_empty() || name.contains('/') || name.contains("..") {
            anyhow::bail!("the hub named a file {name:?}; refusing to write it");
        }
        let to = out.join(name);
        let n = remote
            .download(&format!("/api/v1/recordings/{id}/files/{name}"), &to)
            .await?;
        println!("{} ({n} bytes)", to.display());
    }
    Ok(())
}

/// One line about a recording.
fn summary(r: &Value) -> String {
    let files = r["files"].as_array().map_or(0, |f| f.len());
    format!(
        "{} {} topics={} messages={} bytes={} dropped={} files={files}{}",
        r["id"].as_str().unwrap_or("?"),
        r["state"].as_str().unwrap_or("?"),
        r["spec"]["topics"]
            .as_array()
            .map(|t| t
                .iter()
                .filter_map(|x| x.as_str())
                .collect::<Vec<_>>()
                .join(","))
            .unwrap_or_default(),
        r["messages"],
        r["bytes"],
        r["dropped"],
        r["error"]
            .as_str()
            .map(|e| format!(" error={e}"))
            .unwrap_or_default()
    )
}
