//! The fleet bench's options (`fleetlink bench fleet --help`) and their checks.

use anyhow::bail;

/// Most topics a simulated robot announces (its interest is one 64-bit mask).
const MAX_TOPICS: usize = 64;

#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Hub URL (ws://host:port or host:port). Give it several times to spread the robots
    /// over federated hubs: robot i connects to hub i mod H.
    #[arg(long = "hub", required = true)]
    pub hubs: Vec<String>,
    /// Token sent in every robot's HELLO and by the subscribers (empty: the hub trusts
    /// robots from this address, `--robot-network`). Also read from FLEETLINK_TOKEN.
    #[arg(long, env = "FLEETLINK_TOKEN", default_value = "")]
    pub token: String,
    /// Token of the subscribers (operators: they may read every robot's topics); default
    /// the `--token`. Also read from FLEETLINK_SUBSCRIBER_TOKEN.
    #[arg(long, env = "FLEETLINK_SUBSCRIBER_TOKEN")]
    pub subscriber_token: Option<String>,
    /// Number of robots.
    #[arg(long, default_value_t = 100)]
    pub robots: usize,
    /// Topics per robot (at most 64).
    #[arg(long, default_value_t = 10)]
    pub topics: usize,
    /// Messages per second per topic; 0 connects the fleet and measures it idle only.
    #[arg(long, default_value_t = 10.0)]
    pub rate: f64,
    /// Payload bytes per message.
    #[arg(long, default_value_t = 64)]
    pub size: usize,
    /// Subscriber connections, subscriber j on robot (j mod robots)'s pose topic.
    #[arg(long, default_value_t = 0)]
    pub subscribers: usize,
    /// One more subscriber, to every topic of the fleet.
    #[arg(long)]
    pub wildcard: bool,
    /// Measured seconds of publishing (after the warm-up).
    #[arg(long, default_value_t = 10.0)]
    pub duration: f64,
    /// Seconds of publishing before the measurement starts.
    #[arg(long, default_value_t = 2.0)]
    pub warmup: f64,
    /// Seconds the connected fleet is measured idle before publishing starts.
    #[arg(long, default_value_t = 5.0)]
    pub idle: f64,
    /// Longest time, in seconds, for the whole fleet to connect.
    #[arg(long, default_value_t = 300.0)]
    pub connect_timeout: f64,
    /// Handshakes this bench has in progress at once (the hub admits what it can and
    /// answers the rest 503; those retry with backoff).
    #[arg(long, default_value_t = 1024)]
    pub connect_concurrency: usize,
    /// Milliseconds between a robot's pings while it publishes: the agent's link
    /// estimator sends an echo probe every 200 ms besides its heartbeat ping while data
    /// waits or is unacknowledged, and so do these robots while their schedule runs. An
    /// idle agent pings at its heartbeat only, and so do these robots before and after
    /// their schedule (and throughout with `--rate 0`). 0: heartbeat pings only.
    #[arg(long, default_value_t = 200)]
    pub probe_ms: u64,
    /// Queue length the subscribers ask the hub for (0: the hub's default).
    #[arg(long, default_value_t = 4096)]
    pub queue_length: u32,
    /// Process id of a hub to measure (repeat per hub); hubs on loopback URLs are found
    /// by their listening port without it.
    #[arg(long = "hub-pid")]
    pub hub_pids: Vec<u32>,
    /// Print the final summary as one JSON object on stdout.
    #[arg(long)]
    pub json: bool,
    /// Worker threads of the bench's runtime (default: one per core).
    #[arg(long)]
    pub threads: Option<usize>,
}

pub fn check(args: &Args) -> anyhow::Result<()> {
    if args.robots == 0 {
        bail!("--robots must be at least 1");
    }
    if args.topics == 0 || args.topics > MAX_TOPICS {
        bail!("--topics must be 1 to {MAX_TOPICS}, got {}", args.topics);
    }
    if !(args.rate >= 0.0 && args.rate.is_finite()) {
        bail!("--rate must be a number of messages per second (0 for an idle fleet)");
    }
    if !(args.duration > 0.0 && args.duration.is_finite()) {
        bail!("--duration must be a positive number of seconds");
    }
    for (name, v) in [
        ("--warmup", args.warmup),
        ("--idle", args.idle),
        ("--connect-timeout", args.connect_timeout),
    ] {
        if !(v >= 0.0 && v.is_finite()) {
            bail!("{name} must be a non-negative number of seconds");
        }
    }
    if args.connect_concurrency == 0 {
        bail!("--connect-concurrency must be at least 1");
    }
    Ok(())
}
