//! `fleetlink agent`: run the robot side.

use std::net::SocketAddr;
use std::path::PathBuf;

use anyhow::Context;
use fleetlink_agent::config::origin::annotated_yaml;
use fleetlink_agent::config::runtime::kept::{self, Level};
use fleetlink_agent::config::{AgentConfig, ConfigSource, Overrides};
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
    /// Run as a mirror of ROBOT (overrides `mirror:`), beside offloaded ROS nodes in the
    /// cloud: they see ROBOT's topics, services and actions under its own local names,
    /// and what they publish goes to ROBOT (docs/mirror.md). --name is then the mirror's
    /// own name (default ROBOT_mirror), its credential one with rights under /ROBOT.
    #[arg(long, value_name = "ROBOT")]
    pub mirror: Option<RobotName>,
    /// Configuration file: the agent's YAML (docs/config.md) or a ROS Gateway JSON file
    /// (docs/rosgw.md). Without it, defaults apply.
    #[arg(long)]
    pub config: Option<PathBuf>,
    /// A file holding the credential presented to the hub (overrides `token:`), so the
    /// secret stays out of the configuration and the command line; surrounding whitespace
    /// is ignored. A ROS Gateway file has no place for one: give it here.
    #[arg(long, value_name = "FILE")]
    pub token_file: Option<PathBuf>,
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
    /// Check the configuration and what it names (message definitions, TLS files, the
    /// outbox directory), print the configuration that will run (the file with the changes
    /// kept from earlier runs), each field with where it comes from, and exit 0 if all is
    /// well, 1 if not — without connecting to the hub or the robot's ROS graph.
    #[arg(long)]
    pub check: bool,
}

/// Loads the file (if any) and applies the command-line overrides; with where the
/// configuration came from.
pub fn load(args: &Args) -> anyhow::Result<(AgentConfig, ConfigSource)> {
    let overrides = Overrides {
        hub: (!args.hub.is_empty()).then(|| args.hub.clone()),
        name: args.name.clone(),
        mirror: args.mirror.clone(),
    };
    let (mut cfg, mut source) = AgentConfig::load_source(args.config.as_deref(), &overrides)?;
    if let Some(path) = &args.token_file {
        let text = std::fs::read_to_string(path)
            .map_err(|e| anyhow::anyhow!("--token-file {}: cannot read it: {e}", path.display()))?;
        let token = text.trim();
        if token.is_empty() {
            anyhow::bail!(
                "--token-file {}: the file is empty; put the robot's token in it (`fleetlink \
                 admin … token robot NAME` prints one)",
                path.display()
            );
        }
        cfg.token = token.to_owned();
        source = source.with_flag("token", "--token-file");
    }
    if let Some(addr) = args.local_listen {
        let l = cfg.local_rosbridge.get_or_insert_with(Default::default);
        l.enabled = true;
        l.listen = addr;
        source = source.with_flag("local_rosbridge", "--local-listen");
    }
    if args.no_local {
        cfg.local_rosbridge = None;
        source = source.with_flag("local_rosbridge", "--no-local");
    }
    Ok((cfg, source))
}

/// `fleetlink agent --check`: see [`Args::check`].
pub fn check(
    args: &Args,
    command: &clap::Command,
    matches: &clap::ArgMatches,
) -> anyhow::Result<()> {
    let mut r = super::check::Report::default();
    let what = match &args.config {
        Some(p) => format!("configuration file {}", p.display()),
        None => "configuration: the defaults (no --config)".to_owned(),
    };
    let Some((file_cfg, source)) = r.step(what, load(args)) else {
        return r.finish("fleetlink agent", "");
    };
    // The changes made while it ran before, merged with the file as at start.
    let runtime_file = file_cfg.runtime_file_path();
    let opened = runtime_file
        .as_deref()
        .map(|path| kept::open(&file_cfg, &source, path));
    let (cfg, in_force) = match &opened {
        Some(o) => (o.settled.config.clone(), o.settled.in_force.clone()),
        None => (file_cfg.clone(), Vec::new()),
    };
    r.step(
        "options the agent runs with",
        AgentOptions::from_config(&cfg),
    );
    if let (Some(o), Some(path)) = (&opened, &runtime_file) {
        if !o.found && o.notes.is_empty() {
            r.ok(format!("no changes kept in {} yet", path.display()));
        }
        for n in &o.notes {
            match n.level {
                Level::Info => r.ok(&n.text),
                Level::Warn | Level::Error => r.note(&n.text),
            }
        }
    }
    r.definitions(&args.msg_path);
    if let Some(tls) = &cfg.tls {
        if let Some(ca) = &tls.ca {
            r.step(
                format!("TLS CA {}", ca.display()),
                fleetlink_auth::tls::load_certs(ca),
            );
        }
        if let Some(cert) = &tls.cert {
            r.step(
                format!("TLS client certificate {}", cert.display()),
                fleetlink_auth::tls::load_certs(cert),
            );
        }
        if let Some(key) = &tls.key {
            r.step(
                format!("TLS client key {}", key.display()),
                fleetlink_auth::tls::load_key(key),
            );
        }
    }
    if let Some(outbox) = &cfg.outbox {
        let dir = &outbox.dir;
        match std::fs::metadata(dir) {
            Ok(m) if m.is_dir() && !m.permissions().readonly() => {
                r.ok(format!("outbox directory {}", dir.display()))
            }
            Ok(_) => r.problem(format!(
                "outbox.dir {}: not a writable directory",
                dir.display()
            )),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => r.ok(format!(
                "outbox directory {} (made at start)",
                dir.display()
            )),
            Err(e) => r.problem(format!("outbox.dir {}: {e}", dir.display())),
        }
    }
    if cfg.hub.is_empty() {
        r.note("no hub: the agent serves its local rosbridge only");
    }
    let mut effective = super::check::options(command, matches);
    effective.push_str(&format!(
        "  # the configuration that will run: {}{}, each field with where it comes from\n",
        source.name(),
        match (&opened, &runtime_file) {
            (Some(o), Some(path)) if !o.settled.in_force.is_empty() => {
                format!(" with the changes kept in {}", path.display())
            }
            _ => String::new(),
        }
    ));
    for line in annotated_yaml(&cfg, &source, &in_force).lines() {
        effective.push_str("  ");
        effective.push_str(line);
        effective.push('\n');
    }
    r.finish("fleetlink agent", &effective)
}

pub fn run(args: Args) -> anyhow::Result<()> {
    super::init_logging("info");
    let (cfg, source) = load(&args)?;
    // Changes made while it ran before are merged in first (docs/runtime-config.md).
    let opts = AgentOptions::changeable(&cfg, &source).context("configuration")?;
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
        if let Some(r) = &cfg.rosbridge {
            println!("  rosbridge client of: {}", r.url);
        }
        if let Some(f) = cfg.runtime_file_path() {
            println!("  changes made at run time kept in: {}", f.display());
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
