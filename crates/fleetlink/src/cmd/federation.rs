//! `fleetlink hub --federate zenoh`: the hub's options for joining other hubs, and the
//! glue that starts the federation beside the hub (crates/federation).

use std::path::PathBuf;

#[derive(clap::Args, Debug, Clone, Default)]
pub struct FederationArgs {
    /// Join the other hubs of the fleet through this engine (only `zenoh`): topics cross
    /// to hubs where someone subscribes, calls go to the robot's hub, listings show the
    /// whole fleet (docs/scaling.md). Hubs authenticate each other with certificates of
    /// the fleet's CA (--zenoh-ca, --zenoh-cert, --zenoh-key).
    #[arg(long, value_name = "ENGINE", value_parser = ["zenoh"])]
    pub federate: Option<String>,
    /// A Zenoh configuration file (JSON5) for everything the flags below do not cover.
    #[arg(long, value_name = "FILE", requires = "federate")]
    pub zenoh_config: Option<PathBuf>,
    /// Zenoh mode: peer (default: hubs connect to each other), router, or client (through
    /// a zenohd router).
    #[arg(long, value_name = "MODE", requires = "federate")]
    pub zenoh_mode: Option<String>,
    /// A Zenoh endpoint to connect to, e.g. tls/10.0.0.2:7447; repeatable.
    #[arg(long = "zenoh-connect", value_name = "ENDPOINT", requires = "federate")]
    pub zenoh_connect: Vec<String>,
    /// A Zenoh endpoint to listen on, e.g. tls/0.0.0.0:7447; repeatable. Without one the
    /// hub listens nowhere and only connects out.
    #[arg(long = "zenoh-listen", value_name = "ENDPOINT", requires = "federate")]
    pub zenoh_listen: Vec<String>,
    /// The fleet's federation CA (PEM): every other hub's certificate must come from it.
    #[arg(long = "zenoh-ca", value_name = "FILE", requires = "federate")]
    pub zenoh_ca: Option<PathBuf>,
    /// This hub's federation certificate (PEM, chain leaf first), named HUB@FLEET; made
    /// by `fleetlink admin cert federation`.
    #[arg(long = "zenoh-cert", value_name = "FILE", requires = "federate")]
    pub zenoh_cert: Option<PathBuf>,
    /// The key of --zenoh-cert (PEM).
    #[arg(long = "zenoh-key", value_name = "FILE", requires = "federate")]
    pub zenoh_key: Option<PathBuf>,
    /// Federate over plain TCP, without certificates: any process that reaches a Zenoh
    /// endpoint can read and drive the fleet. For a private network only.
    #[arg(long = "zenoh-insecure-tcp", requires = "federate")]
    pub zenoh_insecure_tcp: bool,
    /// Hubs federate with the hubs of the same fleet name.
    #[arg(long, default_value = "fleet", requires = "federate")]
    pub fleet: String,
    /// This hub's name in the other hubs' listings (default: its certificate's, else the
    /// host name).
    #[arg(long, value_name = "NAME", requires = "federate")]
    pub hub_name: Option<String>,
}

/// Checks the federation options as `start` would read them, without joining.
pub fn check(args: &FederationArgs) -> anyhow::Result<()> {
    check_engine(args)
}

#[cfg(feature = "federation")]
fn trust_args(args: &FederationArgs) -> fleetlink_federation::TrustArgs {
    fleetlink_federation::TrustArgs {
        ca: args.zenoh_ca.clone(),
        cert: args.zenoh_cert.clone(),
        key: args.zenoh_key.clone(),
        insecure_tcp: args.zenoh_insecure_tcp,
    }
}

/// The Zenoh configuration and trust the flags describe, and the hub's name.
#[cfg(feature = "federation")]
fn settings(args: &FederationArgs) -> anyhow::Result<fleetlink_federation::Settings> {
    if args.federate.is_none() {
        anyhow::bail!("--federate is not given");
    }
    let (zenoh, trust) = fleetlink_federation::zenoh_config(
        args.zenoh_config.as_deref(),
        args.zenoh_mode.as_deref(),
        &args.zenoh_connect,
        &args.zenoh_listen,
        &fleetlink_federation::keys::chunk(&args.fleet),
        &trust_args(args),
    )?;
    let hub_name = match (&trust, &args.hub_name) {
        (fleetlink_federation::Trust::Tls { me, .. }, Some(n)) if *n != me.hub => {
            anyhow::bail!(
                "--hub-name {n:?}, but this hub's certificate names it {:?}: over TLS a hub \
                 is known by its certificate (leave --hub-name out, or use a certificate \
                 made for {n:?})",
                me.hub
            )
        }
        (fleetlink_federation::Trust::Tls { me, .. }, _) => me.hub.clone(),
        (_, Some(n)) => n.clone(),
        (_, None) => rustix::system::uname()
            .nodename()
            .to_string_lossy()
            .into_owned(),
    };
    Ok(fleetlink_federation::Settings {
        fleet: args.fleet.clone(),
        hub_name,
        zenoh,
        trust,
    })
}

#[cfg(feature = "federation")]
fn check_engine(args: &FederationArgs) -> anyhow::Result<()> {
    if args.federate.is_some() {
        settings(args)?;
    }
    Ok(())
}

#[cfg(not(feature = "federation"))]
fn check_engine(_args: &FederationArgs) -> anyhow::Result<()> {
    anyhow::bail!("this fleetlink was built without the federation feature")
}

/// Starts the federation when asked for, and tells the hub about it.
pub async fn join(args: &FederationArgs, hub: &fleetlink_hub::Hub) -> anyhow::Result<()> {
    let Some(engine) = &args.federate else {
        return Ok(());
    };
    start(engine, args, hub).await
}

#[cfg(feature = "federation")]
async fn start(
    _engine: &str,
    args: &FederationArgs,
    hub: &fleetlink_hub::Hub,
) -> anyhow::Result<()> {
    use anyhow::Context;
    let settings = settings(args)?;
    let fed = fleetlink_federation::Federation::start(
        settings,
        hub.router().clone(),
        hub.registry().clone(),
        hub.state().security.clone(),
        hub.shutdown_token(),
    )
    .await
    .context("joining the federation")?;
    hub.federate(std::sync::Arc::new(fed));
    Ok(())
}

#[cfg(not(feature = "federation"))]
async fn start(
    engine: &str,
    _args: &FederationArgs,
    _hub: &fleetlink_hub::Hub,
) -> anyhow::Result<()> {
    anyhow::bail!(
        "--federate {engine}: this fleetlink was built without federation; \
         build it with `cargo build --release --features federation` (the default)"
    )
}
