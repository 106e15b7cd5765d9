//! The agent's rosbridge client adapter: for robots that offer only a rosbridge v2
//! server (many vendor robots do), the agent connects to that server as a client and
//! bridges it with its local [`Router`](fleetlink_relay::Router), like the ROS 1 and ROS 2
//! adapters bridge a ROS graph.
//!
//! Up (robot → fleet), it lists the server's topics, services and action servers through
//! the server's rosapi every discovery period, subscribes to the topics that match (JSON)
//! and publishes what arrives into the router under the same name, with the definition
//! from the registry or from rosapi's `message_details`; matching services and actions
//! are advertised in the router's call table, and calls from the fleet are forwarded as
//! `call_service` / `send_action_goal`. Down (fleet → robot), router topics it is told
//! to subscribe are advertised and published on the server, and fleet services it is told
//! to offer are advertised there with `advertise_service`, so programs on the robot can
//! call them. When the link drops it connects again with capped exponential backoff and
//! subscribes and advertises everything again.
//!
//! # Layout
//!
//! - [`options`]: what to bridge ([`RosbridgeClientOptions`]).
//! - [`ops`]: the operations exchanged with the server (JSON text, no I/O).
//! - [`typedefs`]: rosapi typedefs into definition text.
//! - [`bridge`]: the connection loop and the router side ([`run`]).
//! - `discovery`: what the server has, through its rosapi, once per period.
//! - `shared`: what the connection loop and discovery share: counters, the state that
//!   outlives a connection, rosapi requests to the server.

pub mod bridge;
mod discovery;
pub mod ops;
pub mod options;
mod shared;
pub mod typedefs;

pub use bridge::{RosbridgeClientStats, run};
pub use options::{NameFilter, RosbridgeClientOptions};

/// Why the bridge cannot run at all (a problem with the configuration, not with the
/// server, which is retried).
#[derive(Debug, thiserror::Error)]
pub enum RosbridgeClientError {
    #[error("rosbridge: url {url:?} {why}")]
    Url { url: String, why: String },
}
