//! `fleetlink hub --upstream URL --name SITE`: a site hub, itself an agent of an upstream
//! hub (docs/site-hubs.md).
//!
//! Design choice: the site hub's link upstream is the agent's own uplink
//! (`fleetlink_agent::Uplink`) attached to the hub's router, configured by the agent's own
//! YAML (`--upstream-config`, the same fields as an agent's file) or by flags. Everything
//! the agent's link does — handshake, failover between several URLs, backoff, interest,
//! QoS, no-drop streams with a durable outbox, calls both ways — the site's link does the
//! same way, and its robots appear upstream under `/SITE/<robot>/…` by the same namespace
//! rule that puts a robot's `/scan` at `/robot1/scan`.

use std::path::{Path, PathBuf};

use anyhow::Context;
use fleetlink_agent::config::{AgentConfig, OutboxConfig, Overrides};
use fleetlink_agent::uplink::Uplink;
use fleetlink_auth::RobotName;
use tokio_util::sync::CancellationToken;

#[derive(clap::Args, Debug, Clone)]
pub struct UpstreamArgs {
    /// Serve as a site hub: connect out to this upstream hub (ws:// or wss://) as an
    /// agent named --name; give it once per hub to list several (failover, tried in
    /// order). Replaces the `hub:` list of --upstream-config.
    #[arg(long = "upstream", value_name = "URL")]
    pub upstream: Vec<String>,
    /// This site's name upstream: its robots' topics appear there as /NAME/<robot>/…
    /// (the robot name rule applies). Overrides `name:` of --upstream-config.
    #[arg(long, value_name = "NAME")]
    pub name: Option<RobotName>,
    /// The credential the site presents upstream: a robot token the upstream hub minted
    /// for --name (`fleetlink admin token robot NAME` there).
    #[arg(
        long,
        env = "FLEETLINK_UPSTREAM_TOKEN",
        value_name = "TOKEN",
        hide_env_values = true,
        conflicts_with = "upstream_token_file"
    )]
    pub upstream_token: Option<String>,
    /// A file holding that credential, so it stays off the command line.
    #[arg(long, value_name = "FILE")]
    pub upstream_token_file: Option<PathBuf>,
    /// The upstream link's settings in the agent's YAML (docs/config.md): `hub`, `name`,
    /// `token`, `tls`, `heartbeat_ms`, `reconnect`, `remap`, `subscribe`, `topics`,
    /// `outbox`, `latest_cache_mb`, `link`. The robot-side sections (`sim`, `ros1`, `ros2`,
    /// `rosbridge`, `blackbox`) have no place here.
    #[arg(long, value_name = "FILE")]
    pub upstream_config: Option<PathBuf>,
    /// What the hub upstream may do here — see and call this hub's services and actions,
    /// publish to its topics (commands down to its robots), receive its topics — is what
    /// this hub's rules let the user `upstream` in this group do (docs/site-hubs.md). The
    /// default, `admin`, trusts the hub upstream with everything.
    #[arg(long, value_name = "GROUP", default_value = "admin")]
    pub upstream_group: fleetlink_auth::GroupName,
}

impl UpstreamArgs {
    /// Whether the hub is to have an upstream link at all.
    pub fn wanted(&self) -> bool {
        !self.upstream.is_empty() || self.upstream_config.is_some()
    }
}

/// The upstream link's configuration, checked; `None` without --upstream or
/// --upstream-config. Without an `outbox:`, no-drop streams wait in `DATA_DIR/upstream-outbox`
/// while the upstream hub is out of reach, so a WAN outage (or a restart of this hub) loses
/// nothing of them.
pub fn config(args: &UpstreamArgs, data_dir: &Path) -> anyhow::Result<Option<AgentConfig>> {
    if !args.wanted() {
        return Ok(None);
    }
    if args.name.is_none() && args.upstream_config.is_none() {
        anyhow::bail!(
            "--upstream needs --name: the site's name upstream, under which its robots \
             appear there (/NAME/<robot>/…)"
        );
    }
    let overrides = Overrides {
        hub: (!args.upstream.is_empty()).then(|| args.upstream.clone()),
        name: args.name.clone(),
        mirror: None,
    };
    let mut cfg = AgentConfig::load_with(args.upstream_config.as_deref(), &overrides)
        .map_err(|e| anyhow::anyhow!("the upstream link's configuration: {e}"))?;
    let robot_side = [
        ("sim", cfg.sim.is_some()),
        ("ros1", cfg.ros1.is_some()),
        ("ros2", cfg.ros2.is_some()),
        ("rosbridge", cfg.rosbridge.is_some()),
        ("blackbox", cfg.blackbox.is_some()),
        ("mirror", cfg.mirror.is_some()),
    ];
    if let Some((section, _)) = robot_side.iter().find(|(_, set)| *set) {
        anyhow::bail!(
            "--upstream-config: `{section}:` belongs in a robot's agent configuration; a site \
             hub's upstream link carries the hub's own topics (remove the section, or run an \
             agent for it that connects to this hub)"
        );
    }
    if let Some(token) = &args.upstream_token {
        cfg.token = token.trim().to_owned();
    }
    if let Some(path) = &args.upstream_token_file {
        let text = std::fs::read_to_string(path).map_err(|e| {
            anyhow::anyhow!(
                "--upstream-token-file {}: cannot read it: {e}",
                path.display()
            )
        })?;
        cfg.token = text.trim().to_owned();
        if cfg.token.is_empty() {
            anyhow::bail!(
                "--upstream-token-file {}: the file is empty; put the site's robot token from \
                 the upstream hub in it (`fleetlink admin … token robot {}` there prints one)",
                path.display(),
                cfg.name
            );
        }
    }
    if cfg.outbox.is_none() {
        cfg.outbox = Some(OutboxConfig {
            dir: data_dir.join("upstream-outbox"),
            max_mb: 1024,
            fsync: Default::default(),
        });
    }
    cfg.validate()
        .map_err(|e| anyhow::anyhow!("the upstream link's configuration: {e}"))?;
    Ok(Some(cfg))
}

/// The running upstream link: stop it with [`Running::stop`].
pub struct Running {
    stop: CancellationToken,
    task: tokio::task::JoinHandle<()>,
}

impl Running {
    /// Closes the link (after what it holds is journaled) and waits for it.
    pub async fn stop(self) {
        self.stop.cancel();
        let _ = self.task.await;
    }
}

/// The identity the hub upstream acts as here: the user `upstream` in `group`.
fn upstream_identity(group: &fleetlink_auth::GroupName) -> fleetlink_auth::Identity {
    let local = std::net::IpAddr::from([127, 0, 0, 1]);
    fleetlink_auth::Identity {
        kind: fleetlink_auth::IdentityKind::User {
            name: fleetlink_auth::UserName::new("upstream").expect("a valid user name"),
            groups: vec![group.clone()],
        },
        source: fleetlink_auth::ConnInfo::new(local),
        client_ip: local,
    }
}

/// Starts the site's link upstream on the hub's router; the hub upstream acts here as the
/// user `upstream` of `group`.
pub fn start(
    cfg: &AgentConfig,
    group: &fleetlink_auth::GroupName,
    hub: &fleetlink_hub::Hub,
) -> anyhow::Result<Running> {
    let options =
        fleetlink_agent::AgentOptions::from_config(cfg).context("the upstream link's options")?;
    let mut up = options.uplink;
    let state = hub.state();
    // Marks what goes up with this hub, and drops what comes back having passed it.
    up.hub_id = Some(state.agents.hub_id);
    let identity = upstream_identity(group);
    up.upstream_gate = Some(fleetlink_agent::uplink::GateFactory(std::sync::Arc::new(
        move || {
            Box::new(fleetlink_hub::security::HubGate::for_upstream(
                state.security.clone(),
                state.registry.clone(),
                identity.clone(),
            ))
        },
    )));
    let uplink = Uplink::new(up, hub.router().clone()).context("the upstream link")?;
    let stop = CancellationToken::new();
    let task = tokio::spawn(uplink.run(stop.clone()));
    Ok(Running { stop, task })
}
