//! The hub's shared state: [`HubState`], what the HTTP handlers, the WebSocket upgrade and
//! the hub's background tasks (capacity sharing, housekeeping) read, and the
//! [`SiteConfig`] it carries.
//!
//! Design choice: a module of its own so imports run one way. It holds the parts
//! (router, registry of online robots, the agents' context, security core, front-door
//! limits) and imports only their modules, never the ones that read it (`http`,
//! `capacity`, `server`). Built once by `Hub::bind` (crate::server), shared as
//! `Arc<HubState>`.

use std::sync::Arc;

use fleetlink_relay::Router;
use fleetlink_rosbridge::SessionConfig;
use tokio_util::sync::CancellationToken;

use crate::agents::AgentContext;
use crate::registry::Registry;
use crate::store::Store;

/// Everything the HTTP handlers and sessions share.
pub struct HubState {
    pub router: Arc<Router>,
    /// MCAP recordings of the fleet's topics (`/api/v1/recordings`).
    pub recordings: Arc<fleetlink_record::Recordings>,
    pub registry: Arc<Registry>,
    pub store: Store,
    pub agents: Arc<AgentContext>,
    pub rosbridge: Arc<SessionConfig>,
    /// Settings of Foxglove WebSocket sessions (the server's name and this run's id).
    pub foxglove: Arc<fleetlink_foxglove::SessionConfig>,
    pub shutdown: CancellationToken,
    /// Every connection's task (HTTP, rosbridge and agent sessions): a stopping hub waits
    /// for them, within [`crate::server::SHUTDOWN_GRACE`].
    pub tasks: tokio_util::task::TaskTracker,
    pub security: Arc<fleetlink_auth::Security>,
    pub tls: Option<Arc<fleetlink_auth::tls::ReloadingServerConfig>>,
    pub sites: Vec<SiteConfig>,
    pub jwks: Option<crate::jwks::JwksSource>,
    pub started: std::time::SystemTime,
    pub limits: Arc<crate::limits::Limits>,
    /// The other hubs, once this hub joined a federation ([`Hub::federate`]).
    ///
    /// [`Hub::federate`]: crate::server::Hub::federate
    pub federation: std::sync::OnceLock<Arc<dyn crate::federated::Federated>>,
}

/// Robots behind one access link (a site uplink, a cell) and its capacity.
#[derive(Debug, Clone)]
pub struct SiteConfig {
    pub name: String,
    /// Capacity of the shared link, bytes/s.
    pub capacity_bps: f64,
    /// Robots (whole-name regex) at this site.
    pub robots: regex::Regex,
}

impl std::str::FromStr for SiteConfig {
    type Err = String;

    /// `NAME=MBIT:ROBOT_REGEX`, e.g. `warehouse=20:robot[0-9]+`.
    fn from_str(s: &str) -> Result<SiteConfig, String> {
        let (name, rest) = s.split_once('=').ok_or("expected NAME=MBIT:ROBOT_REGEX")?;
        let (mbit, re) = rest
            .split_once(':')
            .ok_or("expected NAME=MBIT:ROBOT_REGEX")?;
        let mbit: f64 = mbit
            .parse()
            .map_err(|e| format!("capacity {mbit:?} is not a number of Mbit/s: {e}"))?;
        if !(mbit > 0.0 && mbit.is_finite()) {
            return Err(format!("capacity must be > 0 Mbit/s, got {mbit}"));
        }
        let robots = regex::RegexBuilder::new(&format!("^(?:{re})$"))
            .size_limit(256 * 1024)
            .build()
            .map_err(|e| format!("robot pattern {re:?}: {e}"))?;
        Ok(SiteConfig {
            name: name.to_owned(),
            capacity_bps: mbit * 1e6 / 8.0,
            robots,
        })
    }
}
