//! `fleetlink demo`: a hub and three simulated robots in one process. Each robot is a
//! real agent connected to the hub over `fleetlink.v1` on the hub's port, so the demo
//! runs the same path as a deployment.

use std::net::SocketAddr;
use std::path::PathBuf;

use anyhow::Context;
use fleetlink_agent::config::AgentConfig;
use fleetlink_agent::{Agent, AgentOptions};
use fleetlink_hub::Hub;
use tokio_util::sync::CancellationToken;

#[derive(clap::Args)]
pub struct Args {
    /// Address and port of the demo hub.
    #[arg(long, default_value = "127.0.0.1:8080")]
    pub listen: SocketAddr,
    /// Where the demo hub keeps its database.
    #[arg(long, default_value = "./fleetlink-data")]
    pub data_dir: PathBuf,
    /// How many simulated robots to start.
    #[arg(long, default_value_t = 3)]
    pub robots: u32,
}

/// The configuration of demo robot `i` (1-based).
pub fn robot_config(hub_url: &str, i: u32) -> anyhow::Result<AgentConfig> {
    let yaml = format!(
        "hub: {hub_url}\nname: robot{i}\nheartbeat_ms: 500\nlocal_rosbridge: null\n\
         sim:\n  seed: {i}\n  laser_scan: {{ rate_hz: 10 }}\n  odometry: {{ rate_hz: 20 }}\n  pose: {{ rate_hz: 10 }}\n  \
         point_cloud: {{ rate_hz: 5, points: 5000 }}\n  image: {{ rate_hz: 5, bytes: 30000 }}\n  \
         markers: {{ rate_hz: 1 }}\n"
    );
    Ok(AgentConfig::from_str(&yaml, "<demo>")?)
}

pub fn run(args: Args) -> anyhow::Result<()> {
    super::init_logging("warn");
    let rt = tokio::runtime::Runtime::new().context("starting the async runtime")?;
    rt.block_on(async {
        let cfg = fleetlink_hub::HubConfig {
            listen: args.listen,
            data_dir: args.data_dir.clone(),
            // Anonymous clients may look (loopback only); tasking needs the operator token.
            auth: fleetlink_auth::AuthPolicy::demo(),
            acl: fleetlink_auth::AclDefaults::demo(),
            ..fleetlink_hub::HubConfig::default()
        };
        let hub = Hub::bind(cfg, crate::transcoder(&[])?).await?;
        let security = hub.state().security.clone();
        let now = fleetlink_auth::UnixTime::now();
        let addr = hub.local_addr();
        let stop = CancellationToken::new();
        let hub_stop = stop.clone();
        let hub_task = tokio::spawn(hub.run(async move { hub_stop.cancelled().await }));
        let url = format!("ws://{addr}");
        let mut robots = Vec::new();
        for i in 1..=args.robots {
            let mut cfg = robot_config(&url, i)?;
            let robot = fleetlink_auth::RobotName::new(&cfg.name)?;
            cfg.token = security
                .store
                .add_robot_token(&robot, None, now)?
                .expose()
                .to_owned();
            let agent =
                Agent::bind(AgentOptions::from_config(&cfg)?, crate::transcoder(&[])?).await?;
            robots.push(tokio::spawn(agent.run(stop.clone())));
        }
        println!("fleetlink demo: hub with {} simulated robots", args.robots);
        println!("  open http://{addr}/ in a browser");
        println!(
            "  rosbridge clients (roslibjs, roslibpy): ws://{addr}/  e.g. subscribe to /robot1/scan"
        );
        let operator = security.store.mint_operator_token(
            &fleetlink_auth::UserName::new("operator")?,
            &[fleetlink_auth::GroupName::new("admin")?],
            None,
            now,
        )?;
        println!(
            "  anonymous local clients may subscribe and list topics; to publish, authenticate with"
        );
        println!("  the operator token (full rights): {}", operator.expose());
        println!("    e.g. ws://{addr}/?token={}", operator.expose());
        println!("  press Ctrl-C to stop");
        super::shutdown_signal().await;
        stop.cancel();
        for r in robots {
            let _ = r.await;
        }
        let _ = hub_task.await;
        println!("fleetlink demo stopped");
        Ok::<_, anyhow::Error>(())
    })
}
