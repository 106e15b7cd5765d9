//! `fleetlink demo`: a hub and three simulated robots in one process. Each robot is a
//! real agent connected to the hub over `fleetlink.v1` on the hub's port, so the demo
//! runs the same path as a deployment.
//!
//! The demo's tokens (the operator's and each robot's) are kept in
//! `DATA_DIR/demo-tokens` and reused by the next run while they are valid, so repeated
//! runs do not pile up credentials; each expires [`TOKEN_DAYS`] after it was minted.

use std::net::SocketAddr;
use std::path::PathBuf;

use anyhow::Context;
use fleetlink_agent::config::{AgentConfig, ConfigSource};
use fleetlink_agent::{Agent, AgentOptions};
use fleetlink_hub::Hub;
use tokio_util::sync::CancellationToken;

/// Days a demo token stays valid.
const TOKEN_DAYS: i64 = 7;

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

/// The configuration of demo robot `i` (1-based), and where it comes from: its text but
/// the hub (made from `--listen`), so that changes kept for it are made against the same
/// text whatever port the demo listens on.
pub fn robot_config(hub_url: &str, i: u32) -> anyhow::Result<(AgentConfig, ConfigSource)> {
    let yaml = format!(
        "name: robot{i}\nheartbeat_ms: 500\nlocal_rosbridge: null\n\
         sim:\n  seed: {i}\n  laser_scan: {{ rate_hz: 10 }}\n  odometry: {{ rate_hz: 20 }}\n  pose: {{ rate_hz: 10 }}\n  \
         point_cloud: {{ rate_hz: 5, points: 5000 }}\n  \
         image: {{ rate_hz: 15, width: 640, height: 480 }}\n  markers: {{ rate_hz: 1 }}\n\
         video:\n  /camera/image/compressed: {{ topic: /camera/video, fps: 15, bitrate_kbps: 800 }}\n"
    );
    let mut cfg = AgentConfig::from_str(&yaml, "<demo>")?;
    cfg.hub = vec![hub_url.to_owned()];
    cfg.validate()?;
    Ok((cfg, ConfigSource::text(yaml).with_flag("hub", "--listen")))
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
        let mut tokens = DemoTokens::load(&args.data_dir, now)?;
        let addr = hub.local_addr();
        let stop = CancellationToken::new();
        let hub_stop = stop.clone();
        let hub_task = tokio::spawn(hub.run(async move { hub_stop.cancelled().await }));
        let url = format!("ws://{addr}");
        let mut robots = Vec::new();
        for i in 1..=args.robots {
            let (mut cfg, source) = robot_config(&url, i)?;
            let robot = cfg.name.clone();
            cfg.token = tokens.get_or_mint(&security, &format!("robot:{robot}"), |exp| {
                Ok(security.store.add_robot_token(&robot, exp, now)?)
            })?;
            // Changes made through the dashboard are kept with the demo's data.
            cfg.runtime_file = Some(
                args.data_dir
                    .join("robots")
                    .join(robot.as_str())
                    .join("runtime.json"),
            );
            let agent =
                Agent::bind(AgentOptions::changeable(&cfg, &source)?, crate::transcoder(&[])?).await?;
            robots.push(tokio::spawn(agent.run(stop.clone())));
        }
        println!("fleetlink demo: hub with {} simulated robots", args.robots);
        println!("  open http://{addr}/ in a browser");
        println!(
            "  rosbridge clients (roslibjs, roslibpy): ws://{addr}/  e.g. subscribe to /robot1/scan"
        );
        let operator = tokens.get_or_mint(&security, "operator", |exp| {
            Ok(security.store.mint_operator_token(
                &fleetlink_auth::UserName::new("operator")?,
                &[fleetlink_auth::GroupName::new("admin")?],
                exp,
                now,
            )?)
        })?;
        println!(
            "  anonymous local clients may subscribe and list topics; to publish, authenticate with"
        );
        println!(
            "  the operator token (full rights; reused by later demo runs, valid {TOKEN_DAYS} days): {operator}"
        );
        println!("    e.g. ws://{addr}/?token={operator}");
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

/// The demo's tokens by role (`operator`, `robot:<name>`), in `DATA_DIR/demo-tokens`
/// (one `role token` per line, readable by its owner only).
struct DemoTokens {
    path: PathBuf,
    now: fleetlink_auth::UnixTime,
    known: Vec<(String, String)>,
}

impl DemoTokens {
    fn load(data_dir: &std::path::Path, now: fleetlink_auth::UnixTime) -> anyhow::Result<Self> {
        let path = data_dir.join("demo-tokens");
        let known = match std::fs::read_to_string(&path) {
            Ok(text) => text
                .lines()
                .filter_map(|l| l.split_once(' '))
                .map(|(role, token)| (role.to_owned(), token.to_owned()))
                .collect(),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Vec::new(),
            Err(e) => return Err(e).with_context(|| format!("reading {}", path.display())),
        };
        Ok(DemoTokens { path, now, known })
    }

    /// The saved token for `role` if the hub still accepts it for at least another day;
    /// otherwise a new one from `mint` (given its expiry), saved.
    fn get_or_mint(
        &mut self,
        security: &fleetlink_auth::Security,
        role: &str,
        mint: impl FnOnce(Option<fleetlink_auth::UnixTime>) -> anyhow::Result<fleetlink_auth::Token>,
    ) -> anyhow::Result<String> {
        let soon = self.now.plus_secs(86_400);
        let valid = |text: &str| -> bool {
            let Ok(token) = fleetlink_auth::Token::parse(text) else {
                return false;
            };
            matches!(
                security.store.lookup_token(&token.hash()),
                Ok(Some(r)) if r.revoked_at.is_none() && r.expires_at.is_some_and(|e| e > soon)
            )
        };
        if let Some((_, t)) = self.known.iter().find(|(r, t)| r == role && valid(t)) {
            return Ok(t.clone());
        }
        let token = mint(Some(self.now.plus_secs(TOKEN_DAYS * 86_400)))?
            .expose()
            .to_owned();
        self.known.retain(|(r, _)| r != role);
        self.known.push((role.to_owned(), token.clone()));
        self.save()?;
        Ok(token)
    }

    fn save(&self) -> anyhow::Result<()> {
        use std::io::Write;
        let mut options = std::fs::OpenOptions::new();
        options.write(true).create(true).truncate(true);
        #[cfg(unix)]
        std::os::unix::fs::OpenOptionsExt::mode(&mut options, 0o600);
        let mut f = options
            .open(&self.path)
            .with_context(|| format!("writing {}", self.path.display()))?;
        for (role, token) in &self.known {
            writeln!(f, "{role} {token}")?;
        }
        Ok(())
    }
}
