//! `fleetlink hub`: run the relay.

use std::net::SocketAddr;
use std::path::PathBuf;
use std::time::Duration;

use anyhow::Context;
use fleetlink_hub::{Hub, HubConfig};

#[derive(clap::Args)]
pub struct Args {
    /// A directory of ROS message packages (DIR/<package>/msg/<Type>.msg, srv/, action/)
    /// whose types the hub should know besides the bundled ones and those robots
    /// advertise; repeatable.
    #[arg(long = "msg-path", value_name = "DIR")]
    pub msg_path: Vec<std::path::PathBuf>,
    /// Address and port for agents, rosbridge clients and HTTP.
    #[arg(long, default_value = "127.0.0.1:8080")]
    pub listen: SocketAddr,
    /// Where the hub keeps its SQLite database and files.
    #[arg(long, default_value = "./fleetlink-data")]
    pub data_dir: PathBuf,
    /// Where MCAP recordings (`fleetlink record`, /api/v1/recordings) are written
    /// [default: DATA_DIR/recordings].
    #[arg(long, value_name = "DIR")]
    pub recordings_dir: Option<PathBuf>,
    /// Keep credentials, rules, the audit log, robots, delivery marks and parameters in
    /// this PostgreSQL database (postgres://USER[:PASSWORD]@HOST[:PORT]/DB), shared with
    /// the other hubs using it, instead of SQLite in --data-dir (docs/scaling.md).
    #[arg(
        long,
        env = "FLEETLINK_DATABASE",
        value_name = "URL",
        hide_env_values = true
    )]
    pub database: Option<String>,
    /// Heartbeat interval for agents that do not ask for one (milliseconds).
    #[arg(long, default_value_t = 1000)]
    pub heartbeat_ms: u64,
    /// Largest WebSocket message accepted from a client (bytes).
    #[arg(long, default_value_t = 16 << 20)]
    pub max_message_size: usize,
    /// Queue length (messages) of subscriptions that do not ask for one.
    #[arg(long, default_value_t = 1000)]
    pub queue_length: usize,
    /// Payload bytes such a queue holds at most (its oldest messages go first).
    #[arg(long, default_value_t = 2 << 20)]
    pub queue_bytes: usize,
    /// TLS certificate chain (PEM): serve wss:// and https://. Reloaded when it changes.
    #[arg(long, requires = "tls_key")]
    pub tls_cert: Option<PathBuf>,
    /// TLS private key (PEM).
    #[arg(long, requires = "tls_cert")]
    pub tls_key: Option<PathBuf>,
    /// CA (PEM) that signs robots' client certificates; enables mutual TLS.
    #[arg(long, requires = "tls_cert")]
    pub tls_client_ca: Option<PathBuf>,
    /// Refuse TLS clients without a certificate signed by --tls-client-ca.
    #[arg(long, requires = "tls_client_ca")]
    pub require_client_cert: bool,
    /// A reverse proxy (CIDR) whose X-Forwarded-For header is believed; repeatable.
    #[arg(long = "trusted-proxy", value_name = "CIDR")]
    pub trusted_proxies: Vec<ipnet::IpNet>,
    /// Robots on this network (a VPN) may connect without a token: CIDR, or CIDR=ROBOT to
    /// allow only that robot from it. Repeatable.
    #[arg(long = "robot-network", value_name = "CIDR[=ROBOT]", value_parser = parse_robot_network)]
    pub robot_networks: Vec<fleetlink_auth::authn::RobotNetwork>,
    /// Robots sharing one access link: NAME=MBIT:ROBOT_REGEX (e.g. warehouse=20:wh_[0-9]+);
    /// the hub divides the capacity among them by demand and latency. Repeatable.
    #[arg(long = "site", value_name = "NAME=MBIT:REGEX")]
    pub sites: Vec<fleetlink_hub::state::SiteConfig>,
    /// Accept OIDC/JWT bearer tokens signed by keys from this JWKS: a file, or the
    /// provider's https:// URL (re-read hourly, and sooner for an unknown key id).
    #[arg(long, value_name = "FILE|URL", requires_all = ["jwt_issuer", "jwt_audience"])]
    pub jwks: Option<fleetlink_hub::jwks::JwksSource>,
    /// Accepted `iss` of OIDC tokens (e.g. https://accounts.google.com); repeatable.
    #[arg(long = "jwt-issuer", value_name = "ISS")]
    pub jwt_issuer: Vec<String>,
    /// Accepted `aud` of OIDC tokens (the client id registered with the provider); repeatable.
    #[arg(long = "jwt-audience", value_name = "AUD")]
    pub jwt_audience: Vec<String>,
    /// Claim naming the user (`sub`, `email`, `preferred_username`).
    #[arg(long, default_value = "sub")]
    pub jwt_user_claim: String,
    /// Claim listing the user's groups (Keycloak: `groups`).
    #[arg(long)]
    pub jwt_groups_claim: Option<String>,
    /// Seconds a client has to send a whole request head; also how long an idle
    /// keep-alive connection waits for its next request.
    #[arg(long, default_value_t = 10.0, value_parser = positive_secs)]
    pub header_timeout_secs: f64,
    /// Seconds an HTTP exchange may sit with nothing read or written before it is closed.
    #[arg(long, default_value_t = 60.0, value_parser = positive_secs)]
    pub idle_timeout_secs: f64,
    /// Seconds a client has to send a whole request body.
    #[arg(long, default_value_t = 30.0, value_parser = positive_secs)]
    pub body_timeout_secs: f64,
    /// Largest request body (bytes); larger ones get 413.
    #[arg(long, default_value_t = 1 << 20)]
    pub max_body_bytes: u64,
    /// Seconds for a TLS handshake, including the wait for a handshake slot.
    #[arg(long, default_value_t = 10.0, value_parser = positive_secs)]
    pub tls_handshake_timeout_secs: f64,
    /// Connections open at once, all clients together (each needs a file descriptor:
    /// raise `ulimit -n` to match).
    #[arg(long, default_value_t = 20_000, value_parser = clap::value_parser!(u32).range(1..))]
    pub max_connections: u32,
    /// Connections open at once from one client address (a NAT or a proxy is one address).
    #[arg(long, default_value_t = 2_000, value_parser = clap::value_parser!(u32).range(1..))]
    pub max_connections_per_ip: u32,
    /// TLS handshakes and WebSocket upgrades in progress at once; above it upgrades get
    /// 503 with a Retry-After of a few seconds.
    #[arg(long, default_value_t = 256, value_parser = clap::value_parser!(u32).range(1..))]
    pub max_handshakes: u32,
    /// Seconds between the WebSocket pings the hub sends every rosbridge and Foxglove
    /// client.
    #[arg(long, default_value_t = 10.0, value_parser = positive_secs)]
    pub viewer_ping_secs: f64,
    /// Seconds a rosbridge or Foxglove client may show no progress (nothing read from
    /// it, its connection not draining) before it is closed and its subscriptions,
    /// advertisements, calls and goals released. Must exceed --viewer-ping-secs.
    #[arg(long, default_value_t = 30.0, value_parser = positive_secs)]
    pub viewer_silence_secs: f64,
    /// Messages at least this large (as framed for the client) go compressed to rosbridge
    /// and Foxglove clients that negotiated permessage-deflate; smaller ones go as they
    /// are.
    #[arg(long, default_value_t = 1024)]
    pub viewer_deflate_min_bytes: usize,
    /// Never negotiate permessage-deflate with rosbridge and Foxglove clients.
    #[arg(long)]
    pub no_viewer_deflate: bool,
    /// Seconds a service call waits for its answer when the caller gives no `timeout`.
    #[arg(long, default_value_t = 30.0, value_parser = positive_secs)]
    pub call_timeout_secs: f64,
    /// Service calls and action goals one client may have waiting at once; more are
    /// answered "busy" at once.
    #[arg(long, default_value_t = 256, value_parser = clap::value_parser!(u32).range(1..))]
    pub max_pending_calls_per_caller: u32,
    /// Calls and goals waiting on one provider (a robot, a client offering services) at
    /// once; more are answered "busy" at once.
    #[arg(long, default_value_t = 1024, value_parser = clap::value_parser!(u32).range(1..))]
    pub max_pending_calls_per_provider: u32,
    #[command(flatten)]
    pub federation: super::federation::FederationArgs,
    #[command(flatten)]
    pub upstream: super::upstream::UpstreamArgs,
    /// Check the options and the files they name (TLS certificate and key, message
    /// definitions, JWKS file, data directory or database URL, Zenoh configuration), print
    /// the effective options with their defaults, and exit 0 if all is well, 1 if not —
    /// without binding a port or connecting anywhere.
    #[arg(long)]
    pub check: bool,
}

impl Args {
    pub fn config(&self) -> HubConfig {
        HubConfig {
            listen: self.listen,
            data_dir: self.data_dir.clone(),
            database: self.database.clone(),
            recordings_dir: self.recordings_dir.clone(),
            heartbeat: Duration::from_millis(self.heartbeat_ms.max(10)),
            max_message_size: self.max_message_size,
            default_queue: self.queue_length.max(1),
            default_queue_bytes: self.queue_bytes.max(1),
            auth: fleetlink_auth::AuthPolicy {
                trusted_proxies: fleetlink_auth::TrustedProxies::new(self.trusted_proxies.clone()),
                robot_networks: self.robot_networks.clone(),
                jwt: self.jwks.as_ref().map(|_| {
                    let mut c = fleetlink_auth::jwt::JwtConfig::new(String::new(), String::new());
                    c.issuers = self.jwt_issuer.clone();
                    c.audiences = self.jwt_audience.clone();
                    c.user_claim = self.jwt_user_claim.clone();
                    c.groups_claim = self.jwt_groups_claim.clone();
                    c
                }),
                ..fleetlink_auth::AuthPolicy::default()
            },
            jwks: self.jwks.clone(),
            acl: fleetlink_auth::AclDefaults::default(),
            sites: self.sites.clone(),
            door: fleetlink_hub::limits::FrontDoor {
                header_timeout: Duration::from_secs_f64(self.header_timeout_secs),
                idle_timeout: Duration::from_secs_f64(self.idle_timeout_secs),
                body_timeout: Duration::from_secs_f64(self.body_timeout_secs),
                max_body: self.max_body_bytes,
                tls_handshake_timeout: Duration::from_secs_f64(self.tls_handshake_timeout_secs),
                max_connections: self.max_connections as usize,
                max_connections_per_ip: self.max_connections_per_ip as usize,
                max_handshakes: self.max_handshakes as usize,
            },
            viewer_liveness: fleetlink_relay::websocket::liveness::LivenessConfig {
                ping_every: Duration::from_secs_f64(self.viewer_ping_secs),
                silence: Duration::from_secs_f64(self.viewer_silence_secs),
            },
            viewer_deflate: (!self.no_viewer_deflate).then_some(
                fleetlink_relay::websocket::deflate::DeflateConfig {
                    min_bytes: self.viewer_deflate_min_bytes,
                },
            ),
            calls: fleetlink_relay::calls::CallLimits {
                default_timeout: Duration::from_secs_f64(self.call_timeout_secs),
                max_pending_per_caller: self.max_pending_calls_per_caller as usize,
                max_pending_per_provider: self.max_pending_calls_per_provider as usize,
                ..fleetlink_relay::calls::CallLimits::default()
            },
            tls: self
                .tls_cert
                .clone()
                .zip(self.tls_key.clone())
                .map(|(cert, key)| {
                    use fleetlink_auth::tls::{ClientAuth, ServerTlsFiles};
                    let client_auth = match (&self.tls_client_ca, self.require_client_cert) {
                        (None, _) => ClientAuth::None,
                        (Some(_), false) => ClientAuth::Optional,
                        (Some(_), true) => ClientAuth::Required,
                    };
                    ServerTlsFiles {
                        cert,
                        key,
                        client_ca: self.tls_client_ca.clone(),
                        client_auth,
                    }
                }),
        }
    }
}

impl Args {
    /// A silence limit that does not leave a client time to answer a ping.
    fn liveness_problem(&self) -> Option<String> {
        (self.viewer_silence_secs <= self.viewer_ping_secs).then(|| {
            format!(
                "--viewer-silence-secs {} must exceed --viewer-ping-secs {}: a client answers \
                 a ping only after it was sent",
                self.viewer_silence_secs, self.viewer_ping_secs
            )
        })
    }
}

/// `fleetlink hub --check`: see [`Args::check`].
pub fn check(
    args: &Args,
    command: &clap::Command,
    matches: &clap::ArgMatches,
) -> anyhow::Result<()> {
    let mut r = super::check::Report::default();
    r.definitions(&args.msg_path);
    if let Some(files) = args.config().tls {
        let what = format!(
            "TLS certificate {} and key {}",
            files.cert.display(),
            files.key.display()
        );
        r.step(what, fleetlink_auth::tls::server_config(&files));
    }
    match &args.database {
        Some(url) => {
            let shown = fleetlink_postgres::redact(url);
            r.step(
                format!("database URL {shown} reads (not connected to)"),
                fleetlink_postgres::parse_url(url),
            );
        }
        None => check_data_dir(&mut r, &args.data_dir),
    }
    match &args.jwks {
        Some(fleetlink_hub::jwks::JwksSource::File(path)) => {
            let keys = fleetlink_auth::jwt::read_jwks_file(path)
                .map_err(|e| e.to_string())
                .and_then(|doc| {
                    fleetlink_auth::jwt::JwksCache::new()
                        .install(&doc, fleetlink_auth::UnixTime::now())
                        .map_err(|e| e.to_string())
                });
            match keys {
                Ok(0) => r.problem(format!(
                    "JWKS file {}: no usable signing key in it (keys need a kid and an \
                     asymmetric algorithm)",
                    path.display()
                )),
                Ok(n) => r.ok(format!("JWKS file {}: {n} signing key(s)", path.display())),
                Err(e) => r.problem(format!("JWKS file {}: {e}", path.display())),
            }
        }
        Some(fleetlink_hub::jwks::JwksSource::Url(url)) => {
            r.note(format!(
                "JWKS {url} is fetched when the hub starts (not now)"
            ));
        }
        None => {}
    }
    if args.federation.federate.is_some() {
        r.step(
            "federation: Zenoh configuration",
            super::federation::check(&args.federation),
        );
    }
    if args.upstream.wanted() {
        r.step(
            "upstream link (site hub): configuration",
            super::upstream::config(&args.upstream, &args.data_dir),
        );
    }
    if let Some(problem) = args.liveness_problem() {
        r.problem(problem);
    }
    let files = u64::from(args.max_connections) + 256;
    match super::open_files_limit() {
        Some(hard) if hard < files => r.note(format!(
            "--max-connections {} needs {files} open files but the hard limit is {hard}: \
             the hub will hold fewer connections (raise it with ulimit -Hn or LimitNOFILE=)",
            args.max_connections
        )),
        _ => {}
    }
    r.finish("fleetlink hub", &super::check::options(command, matches))
}

/// The data directory exists and can be written, or can be created.
fn check_data_dir(r: &mut super::check::Report, dir: &std::path::Path) {
    match std::fs::metadata(dir) {
        Ok(m) if !m.is_dir() => r.problem(format!(
            "--data-dir {}: not a directory; give a directory (it holds hub.sqlite3)",
            dir.display()
        )),
        Ok(m) if m.permissions().readonly() => {
            r.problem(format!("--data-dir {}: not writable", dir.display()))
        }
        Ok(_) => {
            let db = dir.join("hub.sqlite3");
            if db.exists() {
                r.ok(format!(
                    "data directory {} (its database exists)",
                    dir.display()
                ));
            } else {
                r.ok(format!(
                    "data directory {} (a new database is made at start)",
                    dir.display()
                ));
            }
        }
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            let parent = dir.parent().filter(|p| !p.as_os_str().is_empty());
            match parent.map(std::fs::metadata) {
                Some(Ok(p)) if p.is_dir() => {
                    r.ok(format!("data directory {} (made at start)", dir.display()))
                }
                None => r.ok(format!("data directory {} (made at start)", dir.display())),
                Some(_) => r.problem(format!(
                    "--data-dir {}: neither it nor its parent directory exists",
                    dir.display()
                )),
            }
        }
        Err(e) => r.problem(format!("--data-dir {}: {e}", dir.display())),
    }
}

pub fn run(args: Args) -> anyhow::Result<()> {
    super::init_logging("info");
    if let Some(problem) = args.liveness_problem() {
        anyhow::bail!(problem);
    }
    // Every connection is a file: room for the front door's whole admission plus the
    // store, logs and listeners; a hard limit below that is reported, not fatal.
    let files = u64::from(args.max_connections) + 256;
    if let Err(e) = super::raise_open_files(files) {
        tracing::warn!("{e:#}: the hub can hold fewer connections than --max-connections");
    }
    let upstream_cfg = super::upstream::config(&args.upstream, &args.data_dir)?;
    let rt = tokio::runtime::Runtime::new().context("starting the async runtime")?;
    let transcoder = crate::transcoder(&args.msg_path)?;
    rt.block_on(async {
        let hub = Hub::bind(args.config(), transcoder).await?;
        super::federation::join(&args.federation, &hub).await?;
        let upstream = match &upstream_cfg {
            Some(cfg) => Some(super::upstream::start(
                cfg,
                &args.upstream.upstream_group,
                &hub,
            )?),
            None => None,
        };
        let addr = hub.local_addr();
        let (ws, http) = if args.tls_cert.is_some() {
            ("wss", "https")
        } else {
            ("ws", "http")
        };
        println!("fleetlink hub listening on {addr}");
        println!("  dashboard:  {http}://{addr}/?token=TOKEN");
        println!(
            "  rosbridge:  {ws}://{addr}/   agents: {ws}://{addr}/ (subprotocol fleetlink.v1)"
        );
        println!("  foxglove:   {ws}://{addr}/?token=TOKEN (Foxglove, Lichtblick)");
        match &args.database {
            Some(url) => println!(
                "  credentials: fleetlink admin --database {} --help",
                fleetlink_postgres::redact(url)
            ),
            None => println!(
                "  credentials: fleetlink admin --data-dir {} --help",
                args.data_dir.display()
            ),
        }
        if let Some(cfg) = &upstream_cfg {
            println!(
                "  upstream:   {} as site {} (its robots there: /{}/<robot>/…)",
                cfg.hub.join(", "),
                cfg.name,
                cfg.name
            );
        }
        let result = hub.run(super::shutdown_signal()).await;
        if let Some(u) = upstream {
            u.stop().await;
        }
        result?;
        println!("fleetlink hub stopped");
        Ok::<_, anyhow::Error>(())
    })?;
    Ok(())
}

/// A timeout in seconds: finite, above zero, at most a day.
fn positive_secs(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .parse()
        .map_err(|e| format!("{s:?} is not a number of seconds: {e}"))?;
    if v > 0.0 && v <= 86_400.0 {
        Ok(v)
    } else {
        Err(format!("{v} s: expected more than 0 and at most 86400"))
    }
}

/// `CIDR` or `CIDR=ROBOT`.
fn parse_robot_network(s: &str) -> Result<fleetlink_auth::authn::RobotNetwork, String> {
    let (net, robot) = match s.split_once('=') {
        Some((n, r)) => (n, Some(r)),
        None => (s, None),
    };
    let net: ipnet::IpNet = net
        .parse()
        .map_err(|e| format!("{net:?} is not a CIDR network: {e}"))?;
    let robot = robot
        .map(|r| fleetlink_auth::RobotName::new(r).map_err(|e| e.to_string()))
        .transpose()?;
    Ok(fleetlink_auth::authn::RobotNetwork { net, robot })
}
