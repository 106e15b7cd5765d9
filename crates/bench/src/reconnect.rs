//! `fleetlink bench reconnect`: a fleet of real agents against a hub that is stopped and
//! started again on the same address, measuring how the fleet comes back.
//!
//! Everything runs in this process: a hub (trusting robots from loopback, so no tokens
//! are needed) and `--robots` agents, each a full `Agent` with its own router and uplink.
//! Once every robot is connected the hub stops; `--down` seconds later a new hub starts on
//! the same port and data directory. Each agent is watched for the moment its link is up
//! again. What the numbers show: whether robots back off with jitter (arrivals spread
//! out, no burst above the hub's handshake admission) and how often the hub had to
//! refuse with `Retry-After` — the stampede a restarted hub must survive.

use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::{Duration, Instant};

use anyhow::{Context, bail};
use fleetlink_agent::uplink::{LinkState, NameMap, UplinkConfig};
use fleetlink_agent::{Agent, AgentOptions};
use fleetlink_hub::{Hub, HubConfig};
use tokio_util::sync::CancellationToken;

use crate::host::Host;

#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Number of robots (agents) in the fleet.
    #[arg(long, default_value_t = 1000)]
    pub robots: usize,
    /// Seconds the hub stays down.
    #[arg(long, default_value_t = 5.0)]
    pub down: f64,
    /// Longest wait, in seconds, for the fleet to connect (at start and after the restart).
    #[arg(long, default_value_t = 120.0)]
    pub timeout: f64,
}

/// Times at which the robots' links came up after the restart, and the hub's refusals.
struct Outcome {
    back: Vec<Duration>,
    refused_busy: u64,
}

pub fn run(args: Args, host: &Host) -> anyhow::Result<()> {
    if args.robots == 0 {
        bail!("--robots must be at least 1");
    }
    (host.raise_open_files)(args.robots as u64 * 2 + 256)?;
    (host.init_logging)("error");
    let rt = tokio::runtime::Runtime::new().context("starting the async runtime")?;
    rt.block_on(bench(args))
}

/// Messages converted with the bundled definitions only, as `fleetlink hub` and
/// `fleetlink agent` do without `--msg-path`.
fn transcoder() -> Arc<dyn fleetlink_relay::Transcoder> {
    Arc::new(fleetlink_relay::transcode::RegistryTranscoder::new(
        fleetlink_msg::Registry::bundled(),
    ))
}

fn hub_config(listen: SocketAddr, data_dir: PathBuf) -> anyhow::Result<HubConfig> {
    let mut auth = fleetlink_auth::AuthPolicy::default();
    auth.robot_networks
        .push(fleetlink_auth::authn::RobotNetwork {
            net: "127.0.0.0/8".parse().context("a constant network")?,
            robot: None,
        });
    Ok(HubConfig {
        listen,
        data_dir,
        auth,
        ..HubConfig::default()
    })
}

struct RunningHub {
    addr: SocketAddr,
    stop: CancellationToken,
    limits: Arc<fleetlink_hub::limits::Limits>,
}

async fn start_hub(cfg: HubConfig) -> anyhow::Result<RunningHub> {
    let hub = Hub::bind(cfg, transcoder()).await?;
    let addr = hub.local_addr();
    let limits = hub.state().limits.clone();
    let stop = CancellationToken::new();
    let s = stop.clone();
    tokio::spawn(hub.run(async move { s.cancelled().await }));
    Ok(RunningHub { addr, stop, limits })
}

async fn bench(args: Args) -> anyhow::Result<()> {
    let data_dir =
        std::env::temp_dir().join(format!("fleetlink-bench-reconnect-{}", std::process::id()));
    let first = start_hub(hub_config("127.0.0.1:0".parse()?, data_dir.clone())?).await?;
    let addr = first.addr;
    let stop = CancellationToken::new();
    let mut states = Vec::with_capacity(args.robots);
    let started = Instant::now();
    for i in 0..args.robots {
        let uplink = UplinkConfig {
            hub_urls: vec![format!("ws://{addr}")],
            robot: fleetlink_auth::RobotName::new(&format!("r{i}"))?,
            token: String::new(),
            heartbeat: Duration::from_secs(1),
            reconnect_initial: Duration::from_millis(250),
            reconnect_max: Duration::from_secs(10),
            names: NameMap::default(),
            topic_qos: Vec::new(),
            max_in_flight: 32,
            tls: None,
            outbox: None,
            latest_cache_bytes: 64 << 20,
            budget: None,
            hub_id: None,
            upstream_gate: None,
            mirror: None,
        };
        let opts = AgentOptions {
            uplink,
            local_listen: None,
            sim: None,
            ros1: None,
            ros2: None,
            rosbridge: None,
            blackbox: None,
            video: Vec::new(),
            runtime: None,
        };
        let agent = Agent::bind(opts, transcoder()).await?;
        states.push(agent.link_state());
        tokio::spawn(agent.run(stop.clone()));
    }
    let limit = Duration::from_secs_f64(args.timeout);
    wait_all_connected(&mut states, limit)
        .await
        .context("the fleet did not connect at start")?;
    println!(
        "fleetlink bench reconnect: {} robots connected in {:.2} s (all started at once; \
         the hub refused {} handshakes with 503 + Retry-After)",
        args.robots,
        started.elapsed().as_secs_f64(),
        first
            .limits
            .refused(fleetlink_hub::limits::Refusal::Handshakes)
    );

    first.stop.cancel();
    let down_at = Instant::now();
    // Every robot notices (its hub closed the connection).
    for s in &mut states {
        let _ = tokio::time::timeout(
            limit,
            s.wait_for(|s| !matches!(s, LinkState::Connected { .. })),
        )
        .await;
    }
    tokio::time::sleep(Duration::from_secs_f64(args.down).saturating_sub(down_at.elapsed())).await;
    let second = start_hub(hub_config(addr, data_dir.clone())?).await?;
    let restarted = Instant::now();
    let back = watch_return(states, restarted, limit).await;
    let outcome = Outcome {
        back,
        refused_busy: second
            .limits
            .refused(fleetlink_hub::limits::Refusal::Handshakes),
    };
    report(&args, &outcome);
    stop.cancel();
    second.stop.cancel();
    let _ = std::fs::remove_dir_all(&data_dir);
    if outcome.back.len() < args.robots {
        bail!(
            "only {} of {} robots came back within {:.0} s",
            outcome.back.len(),
            args.robots,
            args.timeout
        );
    }
    Ok(())
}

async fn wait_all_connected(
    states: &mut [tokio::sync::watch::Receiver<LinkState>],
    limit: Duration,
) -> anyhow::Result<()> {
    let deadline = tokio::time::Instant::now() + limit;
    for s in states {
        tokio::time::timeout_at(
            deadline,
            s.wait_for(|s| matches!(s, LinkState::Connected { .. })),
        )
        .await
        .context("timed out")?
        .context("agent stopped")?;
    }
    Ok(())
}

/// Watches every robot until its link is up again: when each came back, sorted.
async fn watch_return(
    states: Vec<tokio::sync::watch::Receiver<LinkState>>,
    since: Instant,
    limit: Duration,
) -> Vec<Duration> {
    let tasks: Vec<_> = states
        .into_iter()
        .map(|mut rx| {
            tokio::spawn(async move {
                let up = rx.wait_for(|s| matches!(s, LinkState::Connected { .. }));
                match tokio::time::timeout(limit, up).await {
                    Ok(Ok(_)) => Some(since.elapsed()),
                    _ => None,
                }
            })
        })
        .collect();
    let mut back = Vec::new();
    for t in tasks {
        if let Ok(Some(at)) = t.await {
            back.push(at);
        }
    }
    back.sort();
    back
}

fn report(args: &Args, o: &Outcome) {
    let n = o.back.len();
    if n == 0 {
        println!("  after the restart: no robot came back");
        return;
    }
    let pct = |p: f64| o.back[((n - 1) as f64 * p).round() as usize].as_secs_f64();
    // Arrivals per 100 ms window: how bursty the return was.
    let mut windows = std::collections::BTreeMap::<u64, usize>::new();
    for d in &o.back {
        *windows.entry(d.as_millis() as u64 / 100).or_default() += 1;
    }
    let busiest = windows.values().copied().max().unwrap_or(0);
    println!(
        "  hub down {:.1} s, then restarted on the same port: {n} of {} robots back",
        args.down, args.robots
    );
    println!(
        "  back after: first {:.2} s, median {:.2} s, p90 {:.2} s, last {:.2} s",
        pct(0.0),
        pct(0.5),
        pct(0.9),
        pct(1.0)
    );
    println!(
        "  busiest 100 ms: {busiest} robots connected; over {} windows with arrivals",
        windows.len()
    );
    println!(
        "  handshakes refused by admission (503 + Retry-After): {}",
        o.refused_busy
    );
}
