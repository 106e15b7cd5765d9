//! `fleetlink bench calls`: service round trips through a running hub and agent, the way
//! an operator calls a robot's service: rosbridge client → hub → agent link → a program
//! on the robot's local listener → back.
//!
//! The bench is both ends: a provider on the agent's local rosbridge listener advertises
//! `/bench/echo` (it answers every call at once with its request), and `--callers`
//! rosbridge clients on the hub call `/<robot>/bench/echo`, each with one call in flight at
//! a time. Per phase (one per `--callers` value) it reports round-trip percentiles and
//! calls per second; with `--hub-pid`/`--agent-pid` also the servers' CPU per call and
//! resident memory from `/proc`, and after the last phase a soak of `--soak` more calls
//! that shows whether memory stays flat.

use std::time::{Duration, Instant};

use anyhow::{Context, bail};
use futures_util::{SinkExt, StreamExt};
use serde_json::{Value, json};
use tokio::task::JoinSet;
use tokio_tungstenite::tungstenite::Message as WsMessage;

use super::conn::hub_url;
use crate::host::Host;

#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Hub rosbridge URL, e.g. ws://127.0.0.1:8080 (a bare host:port works too).
    #[arg(long)]
    pub hub: String,
    /// An operator token allowed to call the robot's services. Also read from
    /// FLEETLINK_TOKEN.
    #[arg(long, env = "FLEETLINK_TOKEN", default_value = "")]
    pub token: String,
    /// The agent's local rosbridge listener, where the bench's provider runs.
    #[arg(long)]
    pub local: String,
    /// The robot the agent speaks for (its services are `/<robot>/...` on the hub).
    #[arg(long)]
    pub robot: fleetlink_auth::RobotName,
    /// Concurrent callers of each phase, comma separated.
    #[arg(long, value_delimiter = ',', default_value = "1,50")]
    pub callers: Vec<usize>,
    /// Calls per phase (all callers together).
    #[arg(long, default_value_t = 20_000)]
    pub calls: usize,
    /// Calls of the memory soak after the phases (0 = none), at the last phase's
    /// concurrency.
    #[arg(long, default_value_t = 0)]
    pub soak: usize,
    /// Bytes of payload in each request (a string field).
    #[arg(long, default_value_t = 16)]
    pub size: usize,
    /// The hub's process id, for its CPU time and resident memory.
    #[arg(long)]
    pub hub_pid: Option<u32>,
    /// The agent's process id, likewise.
    #[arg(long)]
    pub agent_pid: Option<u32>,
}

const SERVICE: &str = "/bench/echo";

pub fn run(args: Args, host: &Host) -> anyhow::Result<()> {
    if args.callers.is_empty() || args.callers.contains(&0) {
        bail!("--callers needs at least one concurrency, each at least 1");
    }
    if args.calls == 0 {
        bail!("--calls must be at least 1");
    }
    (host.init_logging)("error");
    let rt = tokio::runtime::Runtime::new().context("starting the async runtime")?;
    rt.block_on(bench(args))
}

pub(super) fn with_token(url: &str, token: &str) -> String {
    let url = hub_url(url);
    if token.is_empty() {
        return url;
    }
    let sep = if url.contains('?') { '&' } else { '?' };
    let base = if url.ends_with('/') || url.contains('?') {
        url
    } else {
        format!("{url}/")
    };
    format!("{base}{sep}token={token}")
}

type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

async fn connect(url: &str) -> anyhow::Result<Ws> {
    let (ws, _) = tokio::time::timeout(
        Duration::from_secs(10),
        tokio_tungstenite::connect_async(url),
    )
    .await
    .with_context(|| format!("connecting to {url} timed out"))?
    .with_context(|| format!("connecting to {url}"))?;
    Ok(ws)
}

async fn next_json(ws: &mut Ws) -> anyhow::Result<Value> {
    loop {
        let m = tokio::time::timeout(Duration::from_secs(10), ws.next())
            .await
            .context("no answer within 10 s")?
            .context("the connection closed")??;
        if let WsMessage::Text(t) = m {
            return Ok(serde_json::from_str(t.as_str())?);
        }
    }
}

/// The provider: answers every call with its arguments.
async fn provide(mut ws: Ws) -> anyhow::Result<()> {
    ws.send(WsMessage::text(
        json!({"op": "advertise_service", "service": SERVICE, "type": "fleetlink_bench/srv/Echo"})
            .to_string(),
    ))
    .await?;
    while let Some(m) = ws.next().await {
        let WsMessage::Text(t) = m? else { continue };
        let v: Value = serde_json::from_str(t.as_str())?;
        if v["op"] == "call_service" {
            let reply = json!({"op": "service_response", "id": v["id"], "service": v["service"],
                               "values": v["args"], "result": true});
            ws.send(WsMessage::text(reply.to_string())).await?;
        }
    }
    Ok(())
}

/// One caller: `n` calls one after another; returns each round trip.
async fn caller(
    mut ws: Ws,
    service: String,
    n: usize,
    blob: String,
) -> anyhow::Result<Vec<Duration>> {
    let mut rtts = Vec::with_capacity(n);
    for i in 0..n {
        let id = format!("c{i}");
        let call = json!({"op": "call_service", "id": id, "service": service,
                          "args": {"data": blob}});
        let t0 = Instant::now();
        ws.send(WsMessage::text(call.to_string())).await?;
        loop {
            let v = next_json(&mut ws).await?;
            if v["op"] == "service_response" && v["id"] == id.as_str() {
                if v["result"] != true {
                    bail!("call {id} failed: {}", v["values"]);
                }
                break;
            }
        }
        rtts.push(t0.elapsed());
    }
    Ok(rtts)
}

/// CPU seconds (user + system) from a `/proc/.../stat` file: a process's, or one
/// thread's (`/proc/self/task/<tid>/stat`).
pub(super) fn stat_cpu_seconds(path: &str) -> Option<f64> {
    let stat = std::fs::read_to_string(path).ok()?;
    // Fields after the command name (which may contain spaces) start after ") ".
    let rest = &stat[stat.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / rustix::param::clock_ticks_per_second() as f64)
}

/// CPU seconds (user + system) and resident kB of a process, from /proc.
pub(super) fn proc_figures(pid: u32) -> Option<(f64, u64)> {
    let cpu = stat_cpu_seconds(&format!("/proc/{pid}/stat"))?;
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let rss = status
        .lines()
        .find_map(|l| l.strip_prefix("VmRSS:"))?
        .split_whitespace()
        .next()?
        .parse()
        .ok()?;
    Some((cpu, rss))
}

struct Phase {
    callers: usize,
    calls: usize,
    elapsed: Duration,
    rtts: Vec<Duration>,
}

async fn phase(args: &Args, hub: &str, callers: usize, calls: usize) -> anyhow::Result<Phase> {
    let service = format!("/{}{SERVICE}", args.robot);
    let blob = "x".repeat(args.size);
    let mut conns = Vec::with_capacity(callers);
    for _ in 0..callers {
        conns.push(connect(hub).await?);
    }
    let per = calls.div_ceil(callers);
    let start = Instant::now();
    let mut set = JoinSet::new();
    for ws in conns {
        set.spawn(caller(ws, service.clone(), per, blob.clone()));
    }
    let mut rtts = Vec::with_capacity(per * callers);
    while let Some(r) = set.join_next().await {
        rtts.extend(r??);
    }
    let elapsed = start.elapsed();
    rtts.sort();
    Ok(Phase {
        callers,
        calls: rtts.len(),
        elapsed,
        rtts,
    })
}

fn pct(sorted: &[Duration], p: f64) -> f64 {
    let i = ((sorted.len() as f64 - 1.0) * p).round() as usize;
    sorted[i.min(sorted.len() - 1)].as_secs_f64() * 1e3
}

fn servers(args: &Args) -> Vec<(&'static str, u32)> {
    let mut v = Vec::new();
    if let Some(p) = args.hub_pid {
        v.push(("hub", p));
    }
    if let Some(p) = args.agent_pid {
        v.push(("agent", p));
    }
    v
}

async fn bench(args: Args) -> anyhow::Result<()> {
    let hub = with_token(&args.hub, &args.token);
    let local = hub_url(&args.local);
    let provider = tokio::spawn(provide(connect(&local).await?));
    // Wait until the service is reachable through the hub.
    let mut probe = connect(&hub).await?;
    let service = format!("/{}{SERVICE}", args.robot);
    let ready = Instant::now();
    loop {
        probe
            .send(WsMessage::text(
                json!({"op": "call_service", "id": "probe", "service": service, "args": {"data": ""}})
                    .to_string(),
            ))
            .await?;
        let v = loop {
            let v = next_json(&mut probe).await?;
            if v["op"] == "service_response" {
                break v;
            }
        };
        if v["result"] == true {
            break;
        }
        if ready.elapsed() > Duration::from_secs(15) {
            bail!(
                "{service} not reachable through the hub within 15 s: {}",
                v["values"]
            );
        }
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
    println!(
        "service round trip: client -> hub -> agent {} -> local provider -> back; {} B requests",
        args.robot, args.size
    );
    println!(
        "{:>8} {:>8} {:>10} {:>9} {:>9} {:>9} {:>9}{}",
        "callers",
        "calls",
        "calls/s",
        "p50 ms",
        "p90 ms",
        "p99 ms",
        "max ms",
        if servers(&args).is_empty() {
            ""
        } else {
            "  server CPU us/call, RSS MB"
        }
    );
    for &c in &args.callers {
        // A short warm-up at this concurrency (connections, caches), not measured.
        phase(&args, &hub, c, (c * 20).min(args.calls)).await?;
        let before: Vec<_> = servers(&args)
            .into_iter()
            .map(|(n, p)| (n, proc_figures(p)))
            .collect();
        let ph = phase(&args, &hub, c, args.calls).await?;
        let mut cpu = String::new();
        for (name, b) in before {
            let pid = if name == "hub" {
                args.hub_pid
            } else {
                args.agent_pid
            };
            if let (Some((c0, _)), Some((c1, rss))) = (b, pid.and_then(proc_figures)) {
                cpu.push_str(&format!(
                    "  {name} {:.1} us, {:.1} MB",
                    (c1 - c0) * 1e6 / ph.calls as f64,
                    rss as f64 / 1024.0
                ));
            }
        }
        println!(
            "{:>8} {:>8} {:>10.0} {:>9.3} {:>9.3} {:>9.3} {:>9.3}{cpu}",
            ph.callers,
            ph.calls,
            ph.calls as f64 / ph.elapsed.as_secs_f64(),
            pct(&ph.rtts, 0.5),
            pct(&ph.rtts, 0.9),
            pct(&ph.rtts, 0.99),
            pct(&ph.rtts, 1.0),
        );
    }
    if args.soak > 0 {
        // In four parts, so a leak shows as growth from part to part, not as the
        // one-time growth of buffers and caches to their working size.
        let c = *args.callers.last().expect("checked non-empty");
        let rss = |pid: Option<u32>| pid.and_then(proc_figures).map(|f| f.1 as f64 / 1024.0);
        let show = |label: &str| {
            let mut line = format!("  {label}:");
            for (name, pid) in [("hub", args.hub_pid), ("agent", args.agent_pid)] {
                if let Some(mb) = rss(pid) {
                    line.push_str(&format!(" {name} RSS {mb:.1} MB"));
                }
            }
            println!("{line}");
        };
        println!("soak: {} calls at {c} callers, in four parts", args.soak);
        show("before");
        let t0 = Instant::now();
        for part in 1..=4 {
            phase(&args, &hub, c, args.soak.div_ceil(4)).await?;
            show(&format!(
                "after part {part} ({:.1} s)",
                t0.elapsed().as_secs_f64()
            ));
        }
    }
    provider.abort();
    Ok(())
}
