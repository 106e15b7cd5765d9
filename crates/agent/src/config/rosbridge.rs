//! `rosbridge:` — the rosbridge client adapter (crates/rosbridge-client): the agent as a
//! client of a robot's own rosbridge server, and what crosses between that server and
//! the fleet. Reference in docs/config.md and docs/rosbridge-client.md.

use std::time::Duration;

use serde::Deserialize;

use super::ReconnectConfig;
use super::ros1::list_or_mapping;
use super::{Ros1Publish, Ros1Services, Ros2Actions};

#[derive(Debug, Clone, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct RosbridgeConfig {
    /// `ws://HOST:PORT` (or `wss://`) of the robot's rosbridge server. Required.
    pub url: String,
    /// Sent as `?token=` in the URL when set. Default empty (none).
    pub token: String,
    /// The server's topics sent up to the hub (same shape as `ros1.publish`).
    #[serde(deserialize_with = "list_or_mapping")]
    pub publish: Ros1Publish,
    /// Topics of the agent's router advertised and published on the server.
    pub subscribe: Vec<String>,
    /// Services both ways (same shape as `ros1.services`): `expose` the server's
    /// services to the fleet, `offer` fleet services on the server.
    #[serde(deserialize_with = "list_or_mapping")]
    pub services: Ros1Services,
    /// The server's action servers exposed to the fleet (same shape as `ros2.actions`;
    /// `offer` is not supported here).
    #[serde(deserialize_with = "list_or_mapping")]
    pub actions: Ros2Actions,
    /// How often the server's rosapi is asked for new topics, services and actions.
    /// Default 5000.
    pub discovery_ms: u64,
    /// How long a call through the server may take. Default 10000.
    pub call_timeout_ms: u64,
    /// Backoff between connection attempts. Default 250 doubling to 10000
    /// (the same as the hub link's).
    pub reconnect: ReconnectConfig,
}

impl Default for RosbridgeConfig {
    fn default() -> Self {
        Self {
            url: String::new(),
            token: String::new(),
            publish: Ros1Publish::default(),
            subscribe: Vec::new(),
            services: Ros1Services::default(),
            actions: Ros2Actions::default(),
            discovery_ms: 5000,
            call_timeout_ms: 10_000,
            reconnect: ReconnectConfig::default(),
        }
    }
}

impl RosbridgeConfig {
    pub fn discovery(&self) -> Duration {
        Duration::from_millis(self.discovery_ms)
    }

    pub fn call_timeout(&self) -> Duration {
        Duration::from_millis(self.call_timeout_ms)
    }
}
