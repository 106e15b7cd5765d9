//! `fleetlink agent`: run the robot side.

use std::net::SocketAddr;
use std::path::PathBuf;

use anyhow::Context;
use fleetlink_agent::config::{AgentConfig, Overrides};
use fleetlink_agent::{Agent, AgentOptions};
use fleetlink_auth::RobotName;
use tokio_util::sync::CancellationToken;

#[derive(clap::Args)]
pub struct Args {
    /// Hub URL, e.g. ws://hub.example:8080; give it once per hub to list several (tried
    /// in the order given, see docs/config.md). Replaces the config's whole `hub:` list.
    #[arg(long, value_name = "URL")]
    pub hub: Vec<String>,
    /// Robot name (overrides `name:`); its topics appear on the hub under /NAME. The rule:
    /// docs/config.md, "Robot names".
    #[arg(long)]
    pub name: Option<RobotName>,
    /// YAML configuration file (see docs/config.md). Without it, defaults apply.
    #[arg(long)]
    pub config: Option<PathBuf>,
    /// Address of the local rosbridge listener (overrides `local_rosbridge.listen`).
    #[arg(long)]
    pub local_listen: Option<SocketAddr>,
    /// Run without the local rosbridge listener.
    #[arg(long, conflicts_with = "local_listen")]
    pub no_local: bool,
    /// A directory of ROS message packages (DIR/<package>/msg/<Type>.msg, srv/, action/)
    /// whose types the agent should know besides the bundled ones; repeatable.
    #[arg(long = "msg-path", value_name = "DIR")]
    pub msg_path: Vec<PathBuf>,
}

/// Loads the file (if any) and applies the command-line overrides.
pub fn load(args: &Args) -> anyhow::Result<AgentConfig> {
    let overrides = Overrides {
        hub: (!args.hub.is_empty()).then(|| args.hub.clone()),
        name: args.name.clone(),
    };
    let mut cfg = AgentConfig::load_with(args.config.as_deref(), &overrides)?;
    if let Some(addr) = args.local_listen {
        let l = cfg.local_rosbridge.get_or_insert_with(Default::default);
        l.enabled = true;
        l.listen = addr;
    }
    if args.no_local {
        cfg.local_rosbridge = None;
    }
    Ok(cfg)
}

pub fn run(args: Args) -> anyhow::Result<()> {
    super::init_logging("info");
    let cfg = load(&args)?;
    let opts = AgentOptions::from_config(&cfg).context("configuration")?;
    let transcoder = crate::transcoder(&args.msg_path)?;
    // One thread. The agent's work is moving bytes between sockets; on a multi-threaded
    // runtime most of its CPU went to waking threads (an ACK read on one, the writer it
    // frees on another), which a robot pays for in every message it bridges. The durable
    // outbox's disk syncs and the ROS 2 adapter run on threads of their own (see
    // `Agent::run`).
    let rt = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .context("starting the async runtime")?;
    rt.block_on(async {
        let agent = Agent::bind(opts, transcoder).await?;
        println!("fleetlink agent {} → {}", cfg.name, cfg.hub.join(", "));
        if let Some(a) = agent.local_addr() {
            println!("  local rosbridge: ws://{a}/");
        }
        let stop = CancellationToken::new();
        let s = stop.clone();
        tokio::spawn(async move {
            super::shutdown_signal().await;
            s.cancel();
        });
        agent.run(stop).await;
        println!("fleetlink agent stopped");
        Ok::<_, anyhow::Error>(())
    })
}
