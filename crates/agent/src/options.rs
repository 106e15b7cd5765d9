//! Turning the agent's configuration into the options of each part it runs: the hub
//! link, the local listener, the simulator, the ROS 1, ROS 2 and rosbridge bridges, the
//! black box and the video streams.
//!
//! The agent builds them here when it starts (`AgentOptions::from_config`), and a
//! runtime change ([`crate::runtime`]) builds them here again from the changed
//! configuration, so a change is turned into options exactly as the file was.

use std::net::SocketAddr;
use std::sync::Arc;

use fleetlink_relay::TopicName;

use crate::config::{AgentConfig, SimConfig};
use crate::uplink::{NameMap, UplinkConfig};
use crate::video::VideoOptions;

/// Messages the uplink sends before it waits for the hub's `ACK`: Robofleet's 32 in
/// flight, plus the small messages a hub may gather before it acknowledges them
/// (`ACK_EVERY_MESSAGES`), so that a link full of small messages carries as many per round
/// trip as with an acknowledgement of each.
pub const UPLINK_IN_FLIGHT: usize =
    32 + fleetlink_relay::link::session::ACK_EVERY_MESSAGES as usize;

/// The options of each part a configuration sets: everything `AgentOptions` holds but
/// the changeable configuration itself (the fields are documented there).
pub(crate) struct PartOptions {
    pub uplink: UplinkConfig,
    pub local_listen: Option<SocketAddr>,
    pub sim: Option<SimConfig>,
    pub ros1: Option<fleetlink_ros1::Ros1Options>,
    pub ros2: Option<fleetlink_ros2::Ros2Options>,
    pub rosbridge: Option<fleetlink_rosbridge_client::RosbridgeClientOptions>,
    pub blackbox: Option<fleetlink_record::blackbox::ring::RingOptions>,
    pub video: Vec<VideoOptions>,
}

impl PartOptions {
    /// The options a loaded configuration sets.
    pub(crate) fn from_config(cfg: &AgentConfig) -> Result<PartOptions, OptionsError> {
        let parse = TopicName::parse;
        let remap = cfg
            .remap
            .iter()
            .map(|(l, h)| Ok((parse(l)?, parse(h)?)))
            .collect::<Result<_, fleetlink_relay::NameError>>()?;
        let subscribe = cfg
            .subscribe
            .iter()
            .map(|s| Ok((parse(&s.hub)?, parse(&s.local)?)))
            .collect::<Result<_, fleetlink_relay::NameError>>()?;
        Ok(PartOptions {
            uplink: UplinkConfig {
                hub_urls: cfg.hub.clone(),
                robot: cfg.name.clone(),
                token: cfg.token.clone(),
                heartbeat: cfg.heartbeat(),
                reconnect_initial: cfg.reconnect.initial(),
                reconnect_max: cfg.reconnect.max(),
                names: NameMap { remap, subscribe },
                topic_qos: cfg
                    .topics
                    .iter()
                    .map(|(n, spec)| Ok((parse(n)?, spec.clone())))
                    .collect::<Result<_, fleetlink_relay::NameError>>()?,
                max_in_flight: UPLINK_IN_FLIGHT,
                tls: tls_client(cfg)?,
                outbox: cfg.outbox.as_ref().map(|o| o.store()),
                latest_cache_bytes: cfg.latest_cache_mb.saturating_mul(1 << 20) as usize,
                budget: cfg.link.budget.as_ref().map(|b| b.to_config()),
                hub_id: None,
                upstream_gate: None,
                mirror: cfg.mirror.clone(),
            },
            local_listen: cfg.local_rosbridge_listen(),
            sim: cfg.sim.clone(),
            ros1: cfg
                .ros1
                .as_ref()
                .map(|r| ros1_options(r, cfg.name.as_str()))
                .transpose()?,
            ros2: cfg
                .ros2
                .as_ref()
                .map(|r| ros2_options(r, cfg.name.as_str()))
                .transpose()?,
            rosbridge: cfg.rosbridge.as_ref().map(rosbridge_options).transpose()?,
            blackbox: cfg.blackbox.as_ref().map(|b| {
                fleetlink_record::blackbox::ring::RingOptions {
                    dir: b.dir.clone().into(),
                    max_bytes: b.max_mb.saturating_mul(1 << 20),
                    topics: b.topics.clone(),
                    compression: b.compression,
                }
            }),
            video: cfg
                .video
                .iter()
                .map(|(camera, v)| {
                    Ok(VideoOptions {
                        camera: parse(camera)?,
                        topic: parse(&v.topic)?,
                        settings: v.settings(),
                        min_bitrate_bps: v.min_bitrate_bps(),
                        library: cfg.openh264_library.clone(),
                    })
                })
                .collect::<Result<_, fleetlink_relay::NameError>>()?,
        })
    }
}

/// The ROS 1 bridge's options from the `ros1:` section (patterns were checked already).
fn ros1_options(
    r: &crate::config::Ros1Config,
    robot: &str,
) -> Result<fleetlink_ros1::Ros1Options, OptionsError> {
    use fleetlink_ros1::{NameFilter, Ros1Options};
    let node_name = r
        .node_name
        .clone()
        .unwrap_or_else(|| format!("/fleetlink_{robot}"));
    Ok(Ros1Options {
        master_uri: r
            .master_uri
            .clone()
            .unwrap_or_else(Ros1Options::default_master_uri),
        node_name: if node_name.starts_with('/') {
            node_name
        } else {
            format!("/{node_name}")
        },
        host: r.host.clone().unwrap_or_else(Ros1Options::default_host),
        publish: NameFilter::new(&r.publish.include, &r.publish.exclude)?,
        subscribe: r
            .subscribe
            .iter()
            .map(|t| TopicName::parse(t))
            .collect::<Result<_, _>>()?,
        expose: NameFilter::new(&r.services.expose, &r.services.exclude)?,
        offer: NameFilter::new(&r.services.offer, &[])?,
        discovery_period: r.discovery(),
        call_timeout: r.call_timeout(),
        parameters: r.parameters,
        changes: None,
    })
}

/// The ROS 2 bridge's options from the `ros2:` section (patterns were checked already).
fn ros2_options(
    r: &crate::config::Ros2Config,
    robot: &str,
) -> Result<fleetlink_ros2::Ros2Options, OptionsError> {
    use fleetlink_relay::names::NameFilter;
    use fleetlink_ros2::Ros2Options;
    let domain_id = match r.domain_id {
        Some(d) => d,
        None => Ros2Options::default_domain_id().map_err(OptionsError::Env)?,
    };
    Ok(Ros2Options {
        domain_id,
        publish: NameFilter::new(&r.publish.include, &r.publish.exclude)?,
        subscribe: r
            .subscribe
            .iter()
            .map(|t| TopicName::parse(t))
            .collect::<Result<_, _>>()?,
        read: NameFilter::new(&r.read, &[])?,
        expose: NameFilter::new(&r.services.expose, &r.services.exclude)?,
        offer: NameFilter::new(&r.services.offer, &[])?,
        expose_actions: NameFilter::new(&r.actions.expose, &r.actions.exclude)?,
        offer_actions: NameFilter::new(&r.actions.offer, &[])?,
        discovery_period: r.discovery(),
        call_timeout: r.call_timeout(),
        parameters: r.parameters,
        node_name: r
            .node_name
            .clone()
            .unwrap_or_else(|| format!("/fleetlink_{robot}")),
        changes: None,
        distro: r.distro.clone().or_else(|| {
            std::env::var("ROS_DISTRO")
                .ok()
                .filter(|d| !d.trim().is_empty())
        }),
    })
}

/// The rosbridge client's options from the `rosbridge:` section (checked already).
fn rosbridge_options(
    r: &crate::config::RosbridgeConfig,
) -> Result<fleetlink_rosbridge_client::RosbridgeClientOptions, OptionsError> {
    use fleetlink_auth::tls::{ClientTlsFiles, HubRoots, client_config};
    use fleetlink_relay::names::NameFilter;
    let tls = if r.url.starts_with("wss://") {
        let files = ClientTlsFiles {
            roots: HubRoots::System,
            client_cert: None,
        };
        Some(client_config(&files)?)
    } else {
        None
    };
    Ok(fleetlink_rosbridge_client::RosbridgeClientOptions {
        url: r.url.clone(),
        token: r.token.clone(),
        publish: NameFilter::new(&r.publish.include, &r.publish.exclude)?,
        subscribe: r
            .subscribe
            .iter()
            .map(|t| TopicName::parse(t))
            .collect::<Result<_, _>>()?,
        expose: NameFilter::new(&r.services.expose, &r.services.exclude)?,
        offer: NameFilter::new(&r.services.offer, &[])?,
        expose_actions: NameFilter::new(&r.actions.expose, &r.actions.exclude)?,
        discovery_period: r.discovery(),
        call_timeout: r.call_timeout(),
        reconnect_initial: r.reconnect.initial(),
        reconnect_max: r.reconnect.max(),
        tls,
    })
}

/// A configuration that checks out field by field but cannot be turned into options.
#[derive(Debug, thiserror::Error)]
pub enum OptionsError {
    #[error(transparent)]
    Name(#[from] fleetlink_relay::NameError),
    #[error("tls: {0}")]
    Tls(#[from] fleetlink_auth::tls::TlsError),
    #[error("invalid pattern: {0}")]
    Pattern(#[from] regex::Error),
    #[error("ros2: {0}")]
    Env(String),
}

/// The TLS client config for the `wss://` hubs: the `tls:` files, else the system's roots.
/// One for all of them (`tls:` applies to every hub); a `ws://` hub does not use it.
fn tls_client(cfg: &AgentConfig) -> Result<Option<Arc<rustls::ClientConfig>>, OptionsError> {
    use fleetlink_auth::tls::{ClientTlsFiles, HubRoots, client_config};
    if !cfg.hub.iter().any(|url| url.starts_with("wss://")) {
        return Ok(None);
    }
    let tls = cfg.tls.clone().unwrap_or_default();
    let files = ClientTlsFiles {
        roots: tls.ca.map_or(HubRoots::System, HubRoots::CaFile),
        client_cert: tls.cert.zip(tls.key),
    };
    Ok(Some(client_config(&files)?))
}
