//! Assembling an agent: local router, hub link, local listener, simulator, the ROS 1
//! and ROS 2 bridges, the rosbridge client and the black box.

use std::net::SocketAddr;
use std::sync::Arc;
use std::time::Duration;

use fleetlink_relay::Router;
use fleetlink_relay::transcode::Transcoder;
use fleetlink_rosbridge::SessionConfig;
use tokio::net::TcpListener;
use tokio::sync::watch;
use tokio_util::sync::CancellationToken;
use tokio_util::task::TaskTracker;

use crate::config::{AgentConfig, SimConfig};
use crate::options::PartOptions;
use crate::uplink::{LinkState, Uplink, UplinkConfig, UplinkStats};

pub use crate::options::{OptionsError, UPLINK_IN_FLIGHT};

/// How long a stopping agent waits for its parts (after its link and durable outbox,
/// which the uplink closes itself).
pub const SHUTDOWN_GRACE: Duration = Duration::from_secs(5);

/// Everything an agent needs to run (the CLI builds it from flags and the YAML file).
#[derive(Debug, Clone)]
pub struct AgentOptions {
    pub uplink: UplinkConfig,
    /// Where local rosbridge clients connect; `None` disables the listener.
    pub local_listen: Option<SocketAddr>,
    /// The simulated robot to run, if any.
    pub sim: Option<SimConfig>,
    /// The native ROS 1 bridge, if any.
    pub ros1: Option<fleetlink_ros1::Ros1Options>,
    /// The native ROS 2 bridge, if any.
    pub ros2: Option<fleetlink_ros2::Ros2Options>,
    /// The rosbridge client of the robot's rosbridge server, if any.
    pub rosbridge: Option<fleetlink_rosbridge_client::RosbridgeClientOptions>,
    /// The black box, if any.
    pub blackbox: Option<fleetlink_record::blackbox::ring::RingOptions>,
    /// Camera topics offered as video.
    pub video: Vec<crate::video::VideoOptions>,
    /// The configuration, changeable while the agent runs ([`crate::runtime`]); `None`:
    /// fixed as built.
    pub runtime: Option<Arc<crate::runtime::RuntimeConfig>>,
}

impl AgentOptions {
    /// Options from a loaded configuration (read from `source`) that may change while the
    /// agent runs: the changes kept in `cfg.runtime_file_path()` are merged in first
    /// (docs/runtime-config.md).
    pub fn changeable(
        cfg: &AgentConfig,
        source: &crate::config::ConfigSource,
    ) -> Result<AgentOptions, OptionsError> {
        let runtime = Arc::new(crate::runtime::RuntimeConfig::open(
            cfg.clone(),
            source.clone(),
            cfg.runtime_file_path(),
        ));
        let mut opts = Self::from_config(&runtime.current())?;
        opts.runtime = Some(runtime);
        Ok(opts)
    }

    /// Options from a loaded configuration file.
    pub fn from_config(cfg: &AgentConfig) -> Result<AgentOptions, OptionsError> {
        let PartOptions {
            uplink,
            local_listen,
            sim,
            ros1,
            ros2,
            rosbridge,
            blackbox,
            video,
        } = PartOptions::from_config(cfg)?;
        Ok(AgentOptions {
            uplink,
            local_listen,
            sim,
            ros1,
            ros2,
            rosbridge,
            blackbox,
            video,
            runtime: None,
        })
    }
}
/// A bound agent, ready to run.
pub struct Agent {
    router: Arc<Router>,
    uplink: Uplink,
    local: Option<TcpListener>,
    sim: Option<SimConfig>,
    ros1: Option<fleetlink_ros1::Ros1Options>,
    ros2: Option<fleetlink_ros2::Ros2Options>,
    rosbridge: Option<fleetlink_rosbridge_client::RosbridgeClientOptions>,
    blackbox: Option<fleetlink_record::blackbox::ring::RingOptions>,
    video: Vec<crate::video::VideoOptions>,
    runtime: Option<Arc<crate::runtime::RuntimeConfig>>,
    /// A mirror offers no configuration services to the fleet (their names would be its
    /// robot's).
    mirror: bool,
    robot: fleetlink_auth::RobotName,
}

#[derive(Debug, thiserror::Error)]
pub enum AgentError {
    #[error("cannot listen for local rosbridge clients on {addr}: {source}")]
    Bind {
        addr: SocketAddr,
        source: std::io::Error,
    },
    #[error(transparent)]
    Outbox(#[from] crate::outbox_store::StoreError),
    /// The rosbridge client's URL cannot work (not retried).
    #[error(transparent)]
    Rosbridge(#[from] fleetlink_rosbridge_client::RosbridgeClientError),
}

impl Agent {
    pub async fn bind(
        opts: AgentOptions,
        transcoder: Arc<dyn Transcoder>,
    ) -> Result<Agent, AgentError> {
        let local = match opts.local_listen {
            Some(addr) => Some(
                crate::local::bind(addr)
                    .await
                    .map_err(|source| AgentError::Bind { addr, source })?,
            ),
            None => None,
        };
        if let Some(r) = &opts.rosbridge {
            r.connect_url()?;
        }
        let router = Arc::new(Router::new(transcoder));
        let robot = opts.uplink.robot.clone();
        let mirror = opts.uplink.mirror.is_some();
        let uplink = Uplink::new(opts.uplink, router.clone())?;
        Ok(Agent {
            router,
            uplink,
            local,
            sim: opts.sim,
            ros1: opts.ros1,
            ros2: opts.ros2,
            rosbridge: opts.rosbridge,
            blackbox: opts.blackbox,
            video: opts.video,
            runtime: opts.runtime,
            mirror,
            robot,
        })
    }

    /// The local router (the simulator and tests publish into it).
    pub fn router(&self) -> Arc<Router> {
        self.router.clone()
    }

    pub fn local_addr(&self) -> Option<SocketAddr> {
        self.local.as_ref().and_then(|l| l.local_addr().ok())
    }

    pub fn link_state(&self) -> watch::Receiver<LinkState> {
        self.uplink.watch()
    }

    pub fn uplink_stats(&self) -> Arc<UplinkStats> {
        self.uplink.stats.clone()
    }

    /// The changeable configuration, if the agent was built with one.
    pub fn runtime(&self) -> Option<Arc<crate::runtime::RuntimeConfig>> {
        self.runtime.clone()
    }

    /// Runs until `shutdown` is cancelled, then stops: the link closes with 1001, local
    /// clients get 1001, the durable outbox writes and syncs what it holds, and the tasks
    /// are waited for (at most [`SHUTDOWN_GRACE`]).
    pub async fn run(mut self, shutdown: CancellationToken) {
        let sessions = TaskTracker::new();
        // The running parts take a runtime change through these.
        let mut ros1_changes = None;
        let mut ros2_changes = None;
        if let Some(o) = self.ros1.as_mut().filter(|_| self.runtime.is_some()) {
            let (tx, rx) = watch::channel(o.clone());
            o.changes = Some(rx);
            ros1_changes = Some(tx);
        }
        if let Some(o) = self.ros2.as_mut().filter(|_| self.runtime.is_some()) {
            let (tx, rx) = watch::channel(o.clone());
            o.changes = Some(rx);
            ros2_changes = Some(tx);
        }
        let (video_changes, videos) = watch::channel(std::mem::take(&mut self.video));
        if let Some(rt) = &self.runtime {
            rt.attach(crate::runtime::Parts {
                uplink: self.uplink.control(),
                ros1: ros1_changes,
                ros2: ros2_changes,
                video: Some(video_changes),
            });
        }
        // A mirror offers no configuration services (their names would be its robot's).
        let runtime_task = self.runtime.clone().filter(|_| !self.mirror).map(|rt| {
            tokio::spawn(crate::runtime::serve(
                rt,
                self.router.clone(),
                shutdown.clone(),
            ))
        });
        let deadlines = tokio::spawn(self.router.calls.clone().run_deadlines(shutdown.clone()));
        let local = self.local.map(|l| {
            let cfg = Arc::new(SessionConfig {
                node_name: "/fleetlink_agent".into(),
                ..SessionConfig::default()
            });
            tokio::spawn(crate::local::serve(
                l,
                self.router.clone(),
                cfg,
                self.runtime.clone(),
                shutdown.clone(),
                sessions.clone(),
            ))
        });
        let sim = self.sim.map(|cfg| {
            tokio::spawn(crate::sim::drive(
                cfg,
                self.robot.to_string(),
                self.router.clone(),
                shutdown.clone(),
            ))
        });
        // What the ROS adapters report goes on the status topic (crate::status).
        let mut parts = Vec::new();
        let ros1 = self.ros1.map(|opts| {
            let (router, shutdown) = (self.router.clone(), shutdown.clone());
            let interest = Some(self.uplink.read_interest());
            let stats = Arc::new(fleetlink_ros1::Ros1Stats::default());
            parts.push(crate::status::Part {
                name: "ros1",
                report: stats.clone(),
            });
            tokio::spawn(async move {
                if let Err(e) = fleetlink_ros1::run(opts, router, stats, interest, shutdown).await {
                    tracing::error!("{e}");
                }
            })
        });
        // The ROS 2 adapter runs on a two-worker runtime of its own, whatever runtime the
        // rest of the agent runs on. Its downlink writes into rustdds may block the calling
        // thread (up to the writer's 100 ms reliable blocking time), which on the agent's
        // one thread would hold everything else up. (The suite failures once blamed on
        // the runtime were a deadlock in the Cyclone test peers: docs/ros2.md, "Tests".)
        let ros2 = self.ros2.map(|opts| {
            let (router, shutdown) = (self.router.clone(), shutdown.clone());
            let interest = Some(self.uplink.read_interest());
            let stats = Arc::new(fleetlink_ros2::Ros2Stats::default());
            parts.push(crate::status::Part {
                name: "ros2",
                report: stats.clone(),
            });
            spawn_ros2(opts, router, stats, interest, shutdown)
        });
        let rosbridge = self.rosbridge.map(|opts| {
            let (router, shutdown) = (self.router.clone(), shutdown.clone());
            let stats = Arc::new(fleetlink_rosbridge_client::RosbridgeClientStats::default());
            tokio::spawn(async move {
                if let Err(e) = fleetlink_rosbridge_client::run(opts, router, stats, shutdown).await
                {
                    tracing::error!("{e}");
                }
            })
        });
        let blackbox = self.blackbox.map(|opts| {
            tokio::spawn(crate::blackbox::serve(
                opts,
                self.router.clone(),
                shutdown.clone(),
            ))
        });
        let video = tokio::spawn(crate::video::supervise(
            videos,
            self.router.clone(),
            Some(self.uplink.read_interest()),
            shutdown.clone(),
        ));
        let status = (!parts.is_empty()).then(|| {
            tokio::spawn(crate::status::publish(
                self.router.clone(),
                self.robot.to_string(),
                parts,
                self.uplink.stats.clone(),
                self.uplink.watch(),
                shutdown.clone(),
            ))
        });
        self.uplink.run(shutdown.clone()).await;
        sessions.close();
        let rest = async {
            for t in [local, sim, ros1, rosbridge, blackbox, status, runtime_task]
                .into_iter()
                .flatten()
                .chain([video])
            {
                let _ = t.await;
            }
            sessions.wait().await;
            if let Some(t) = ros2.flatten() {
                let _ = tokio::task::spawn_blocking(move || t.join()).await;
            }
            let _ = deadlines.await;
        };
        if tokio::time::timeout(SHUTDOWN_GRACE, rest).await.is_err() {
            tracing::warn!(
                "parts of the agent did not stop within {SHUTDOWN_GRACE:?}; stopping anyway"
            );
        }
    }
}

/// The ROS 2 adapter's thread: it runs on a two-worker runtime of its own, whatever
/// runtime the rest of the agent runs on (see [`Agent::run`]).
fn spawn_ros2(
    opts: fleetlink_ros2::Ros2Options,
    router: Arc<Router>,
    stats: Arc<fleetlink_ros2::Ros2Stats>,
    interest: Option<Arc<fleetlink_relay::read_interest::ReadInterest>>,
    shutdown: CancellationToken,
) -> Option<std::thread::JoinHandle<()>> {
    std::thread::Builder::new()
        .name("ros2".into())
        .spawn(move || {
            let rt = match tokio::runtime::Builder::new_multi_thread()
                .worker_threads(2)
                .thread_name("ros2-rt")
                .enable_all()
                .build()
            {
                Ok(rt) => rt,
                Err(e) => {
                    tracing::error!("ros2: cannot start its runtime: {e}");
                    return;
                }
            };
            rt.block_on(async move {
                if let Err(e) = fleetlink_ros2::run(opts, router, stats, interest, shutdown).await {
                    tracing::error!("{e}");
                }
            })
        })
        .map_err(|e| tracing::error!("ros2: cannot start its thread: {e}"))
        .ok()
}
