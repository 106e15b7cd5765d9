//! The seam to other hubs: what a federation (crates/federation, over Zenoh) tells this
//! hub's HTTP surface about the rest of the fleet.
//!
//! Design choice: a trait here and the implementation in its own crate, so the hub builds
//! without the federation's dependencies and the federation reaches the hub only through
//! the router (topics, calls) and this one seam (listings).

/// A robot connected to another hub of the federation.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RemoteRobot {
    pub name: String,
    /// The name of the hub it is connected to.
    pub hub: String,
}

/// What the HTTP API asks of the federation this hub belongs to.
pub trait Federated: Send + Sync {
    /// Robots connected to the other hubs now.
    fn remote_robots(&self) -> Vec<RemoteRobot>;
    /// The federation's state for `/api/v1/federation`: this hub's id, its peers, the
    /// topics crossing in each direction with their counters.
    fn status(&self) -> serde_json::Value;
    /// Counters for `/metrics`: (name, help, value).
    fn counters(&self) -> Vec<(&'static str, &'static str, u64)>;
}
