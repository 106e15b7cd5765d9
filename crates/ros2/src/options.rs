//! What the bridge is told to do (the agent builds this from its `ros2:` YAML section).

use std::time::Duration;

use fleetlink_relay::TopicName;
pub use fleetlink_relay::names::NameFilter;

#[derive(Debug, Clone)]
pub struct Ros2Options {
    /// The DDS domain (`ROS_DOMAIN_ID`).
    pub domain_id: u16,
    /// Local topics sent up: the graph's writers whose ROS topic name matches.
    pub publish: NameFilter,
    /// Local router topics (hub topics brought down) written into the graph.
    pub subscribe: Vec<TopicName>,
    /// Local router topics written into the graph while one of its nodes reads them (a
    /// mirror's robot topics): subscribed only while such a reader is discovered, so a
    /// topic no node reads is not brought down at all.
    pub read: NameFilter,
    /// Local ROS 2 services offered to the fleet.
    pub expose: NameFilter,
    /// Fleet services (as named in the agent's call table) offered to local nodes.
    pub offer: NameFilter,
    /// Local ROS 2 action servers offered to the fleet.
    pub expose_actions: NameFilter,
    /// Fleet actions served to local ROS 2 action clients.
    pub offer_actions: NameFilter,
    /// How often the discovered endpoints are looked at.
    pub discovery_period: Duration,
    /// How long a local caller's fleet call may take.
    pub call_timeout: Duration,
    /// Answer rosapi's parameter services from the graph's nodes ([`crate::params`]).
    pub parameters: bool,
    /// The agent's node in the graph (`ros2 node list`): a full ROS name.
    pub node_name: String,
    /// The robot's ROS 2 distribution (`ros2.distro`, else `ROS_DISTRO`), for the layout
    /// of `ros_discovery_info` ([`crate::node_info`]); `None`: learned from the graph.
    pub distro: Option<String>,
    /// Options that replace these while the bridge runs (a runtime configuration change):
    /// what crosses (`publish`, `subscribe`, `read`, services and actions) changes at
    /// once, without disturbing the rest; the other fields stay as the bridge started.
    pub changes: Option<tokio::sync::watch::Receiver<Ros2Options>>,
}

impl Ros2Options {
    /// The domain from `ROS_DOMAIN_ID`, else 0. An unreadable value is an error naming
    /// it (a robot silently on domain 0 would see nothing).
    pub fn default_domain_id() -> Result<u16, String> {
        match std::env::var("ROS_DOMAIN_ID") {
            Ok(v) if !v.trim().is_empty() => v.trim().parse::<u16>().ok().filter(|d| *d <= 232).ok_or_else(|| {
                format!("ROS_DOMAIN_ID={v:?} is not a domain id (an integer 0..=232); fix the variable or set ros2.domain_id")
            }),
            _ => Ok(0),
        }
    }
}
