//! `ros1:` — the native ROS 1 bridge (crates/ros1): which master, which node, and what
//! crosses between the robot's ROS graph and the fleet. Reference in docs/config.md.

use std::time::Duration;

use serde::Deserialize;

/// The agent as a node of the robot's ROS 1 graph.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Ros1Config {
    /// `http://host:port` of the master. Default: `ROS_MASTER_URI`, else
    /// `http://localhost:11311`.
    pub master_uri: Option<String>,
    /// The node's name in the graph. Default `/fleetlink_<robot name>`.
    pub node_name: Option<String>,
    /// Host name or IP other nodes reach this one at. Default: `ROS_HOSTNAME`, else
    /// `ROS_IP`, else the machine's host name.
    pub host: Option<String>,
    /// Local topics sent up to the hub.
    pub publish: Ros1Publish,
    /// Topics of the agent's router (hub topics brought down, e.g. `/cmd_vel` for the
    /// hub's `/<robot>/cmd_vel`) published into the graph.
    pub subscribe: Vec<String>,
    /// Services both ways.
    pub services: Ros1Services,
    /// Master polling period for new publishers/services and master restarts. Default
    /// 1000.
    pub discovery_ms: u64,
    /// How long a local caller of a fleet service waits. Default 10000.
    pub call_timeout_ms: u64,
    /// Offer the master's parameters to the fleet (rosapi's parameter services under
    /// `/<robot>/rosapi/`, which the hub's `/rosapi/get_param` of `/<robot>/...` reaches).
    /// Default true.
    pub parameters: bool,
}

impl Default for Ros1Config {
    fn default() -> Self {
        Self {
            master_uri: None,
            node_name: None,
            host: None,
            publish: Ros1Publish::default(),
            subscribe: Vec::new(),
            services: Ros1Services::default(),
            discovery_ms: 1000,
            call_timeout_ms: 10_000,
            parameters: true,
        }
    }
}

/// Whole-name regular expressions; a plain topic name matches itself.
#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Ros1Publish {
    /// Topics (names or patterns) bridged when a local node publishes them.
    pub include: Vec<String>,
    /// Topics never bridged, even when `include` matches.
    pub exclude: Vec<String>,
}

#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Ros1Services {
    /// Local ROS services (names or patterns) offered to the fleet, under the robot's
    /// namespace on the hub.
    pub expose: Vec<String>,
    /// Local services never exposed.
    pub exclude: Vec<String>,
    /// Fleet services (as the agent names them: `/cloud/plan`, `/robot2/set_mode`)
    /// offered to local nodes as ROS services.
    pub offer: Vec<String>,
}

impl Ros1Config {
    pub fn discovery(&self) -> Duration {
        Duration::from_millis(self.discovery_ms)
    }

    pub fn call_timeout(&self) -> Duration {
        Duration::from_millis(self.call_timeout_ms)
    }
}
