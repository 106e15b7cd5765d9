//! What the bridge is told to do (the agent builds this from its `ros1:` YAML section).

use std::time::Duration;

use fleetlink_relay::TopicName;
use regex::Regex;

/// Whole-name include/exclude patterns (a plain name is a pattern matching itself).
#[derive(Debug, Clone, Default)]
pub struct NameFilter {
    pub include: Vec<Regex>,
    pub exclude: Vec<Regex>,
}

impl NameFilter {
    /// Compiles patterns as whole-name regexes (`^(?:p)$`).
    pub fn new(include: &[String], exclude: &[String]) -> Result<NameFilter, regex::Error> {
        let compile = |ps: &[String]| {
            ps.iter()
                .map(|p| Regex::new(&format!("^(?:{p})$")))
                .collect::<Result<Vec<_>, _>>()
        };
        Ok(NameFilter {
            include: compile(include)?,
            exclude: compile(exclude)?,
        })
    }

    pub fn matches(&self, name: &str) -> bool {
        self.include.iter().any(|r| r.is_match(name))
            && !self.exclude.iter().any(|r| r.is_match(name))
    }

    pub fn is_empty(&self) -> bool {
        self.include.is_empty()
    }
}

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn filter_includes_then_excludes_whole_names() {
        let f = NameFilter::new(&[".*".into()], &["/camera/raw".into()]).unwrap();
        assert!(f.matches("/scan"));
        assert!(!f.matches("/camera/raw"));
        assert!(f.matches("/camera/raw/compressed"));
        let f = NameFilter::new(&["/scan".into()], &[]).unwrap();
        assert!(!f.matches("/scan2"));
        assert!(NameFilter::default().is_empty());
        assert!(!NameFilter::default().matches("/x"));
    }
}
