//! What the bridge is told to do (the agent builds this from its `ros1:` YAML section).

use std::time::Duration;

use fleetlink_relay::TopicName;
pub use fleetlink_relay::names::NameFilter;

#[derive(Debug, Clone)]
pub struct Ros1Options {
    /// `http://host:port` of the ROS master.
    pub master_uri: String,
    /// This node's name in the graph (`/fleetlink_robot1`).
    pub node_name: String,
    /// The host name or IP other nodes use to reach this one.
    pub host: String,
    /// Local topics sent up: the graph's publishers whose topic matches.
    pub publish: NameFilter,
    /// Local router topics (hub topics brought down) published into the graph.
    pub subscribe: Vec<TopicName>,
    /// Local ROS services offered to the fleet.
    pub expose: NameFilter,
    /// Fleet services (as named in the agent's call table) offered to local nodes.
    pub offer: NameFilter,
    /// How often the master is asked for new publishers and services (and whether it
    /// restarted).
    pub discovery_period: Duration,
    /// How long a local caller waits for a fleet service.
    pub call_timeout: Duration,
    /// Provide rosapi's parameter services from the master's parameters (`crate::params`).
    pub parameters: bool,
    /// Options that replace these while the bridge runs (a runtime configuration change):
    /// what crosses (`publish`, `subscribe`, `expose`, `offer`) changes at once, without
    /// disturbing the rest; the other fields stay as the bridge started.
    pub changes: Option<tokio::sync::watch::Receiver<Ros1Options>>,
}

impl Ros1Options {
    /// The master URI from `ROS_MASTER_URI`, else `http://localhost:11311`.
    pub fn default_master_uri() -> String {
        std::env::var("ROS_MASTER_URI")
            .ok()
            .filter(|s| !s.is_empty())
            .unwrap_or_else(|| "http://localhost:11311".to_owned())
    }

    /// The advertised host as ROS nodes choose it: `ROS_HOSTNAME`, else `ROS_IP`, else
    /// the machine's host name.
    pub fn default_host() -> String {
        ["ROS_HOSTNAME", "ROS_IP"]
            .iter()
            .find_map(|k| std::env::var(k).ok().filter(|s| !s.is_empty()))
            .or_else(|| {
                std::fs::read_to_string("/proc/sys/kernel/hostname")
                    .ok()
                    .map(|s| s.trim().to_owned())
                    .filter(|s| !s.is_empty())
            })
            .unwrap_or_else(|| "localhost".to_owned())
    }
}
