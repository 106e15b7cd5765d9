//! `ros2:` — the native ROS 2 bridge (crates/ros2): which DDS domain, and what crosses
//! between the robot's ROS 2 graph and the fleet. Reference in docs/config.md.

use std::time::Duration;

use serde::Deserialize;

use super::ros1::{Shorthand, list_or_mapping};
use super::{Ros1Publish, Ros1Services};

/// The agent as a DDS participant of the robot's ROS 2 graph.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct Ros2Config {
    /// The DDS domain. Default: `ROS_DOMAIN_ID`, else 0.
    pub domain_id: Option<u16>,
    /// Local topics sent up to the hub (same shape as `ros1.publish`).
    #[serde(deserialize_with = "list_or_mapping")]
    pub publish: Ros1Publish,
    /// Topics of the agent's router written into the graph.
    pub subscribe: Vec<String>,
    /// Topics of the agent's router (names or patterns) written into the graph while one
    /// of its nodes reads them, and not asked for otherwise: a mirror's robot topics.
    pub read: Vec<String>,
    /// Services both ways (same shape as `ros1.services`).
    #[serde(deserialize_with = "list_or_mapping")]
    pub services: Ros1Services,
    /// Actions. A list is short for its `expose`.
    #[serde(deserialize_with = "list_or_mapping")]
    pub actions: Ros2Actions,
    /// How often discovered endpoints are looked at. Default 250.
    pub discovery_ms: u64,
    /// How long a local caller of a fleet service may wait. Default 10000.
    pub call_timeout_ms: u64,
    /// The agent's node name in the graph (`ros2 node list`). Default
    /// `/fleetlink_<name>`.
    pub node_name: Option<String>,
    /// The robot's ROS 2 distribution (`humble`, `jazzy`, ...), for the layout of
    /// `ros_discovery_info`. Default: `ROS_DISTRO`, else learned from the graph.
    pub distro: Option<String>,
    /// Offer the graph's node parameters to the fleet (rosapi's parameter services under
    /// `/<robot>/rosapi/`, names as `<node>:<parameter>`). Default true.
    pub parameters: bool,
}

impl Default for Ros2Config {
    fn default() -> Self {
        Self {
            domain_id: None,
            publish: Ros1Publish::default(),
            subscribe: Vec::new(),
            read: Vec::new(),
            services: Ros1Services::default(),
            actions: Ros2Actions::default(),
            discovery_ms: 250,
            call_timeout_ms: 10_000,
            parameters: true,
            node_name: None,
            distro: None,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct Ros2Actions {
    /// Local action servers (names or patterns) offered to the fleet, under the robot's
    /// namespace on the hub.
    pub expose: Vec<String>,
    /// Local action servers never exposed.
    pub exclude: Vec<String>,
    /// Fleet actions (as the agent names them) served to local ROS 2 action clients.
    pub offer: Vec<String>,
}

impl Shorthand for Ros2Actions {
    const EXPECTING: &'static str = "a list of local action servers to expose (`actions: \
        [/navigate]`) or a mapping (`actions: { expose: [/navigate], offer: [/cloud/dock] }`)";
    fn from_list(expose: Vec<String>) -> Self {
        Self {
            expose,
            ..Self::default()
        }
    }
}

impl Ros2Config {
    pub fn discovery(&self) -> Duration {
        Duration::from_millis(self.discovery_ms)
    }

    pub fn call_timeout(&self) -> Duration {
        Duration::from_millis(self.call_timeout_ms)
    }
}
