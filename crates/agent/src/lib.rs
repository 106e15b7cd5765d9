//! The robot side of fleetlink.
//!
//! An agent runs a local [`Router`](fleetlink_relay::Router) with three kinds of
//! participants: local rosbridge clients ([`local`]), the simulator ([`sim`]), and the
//! hub link ([`uplink`]), which carries every local topic up and the robot's inputs down.
//!
//! # Layout
//!
//! - [`agent`]: assembles and runs the pieces from one set of options.
//! - [`blackbox`]: the black box: a ring of local topics on disk, and the service the hub
//!   fetches slices of it through.
//! - [`config`]: the agent's YAML configuration, with errors that name file, line and field.
//! - [`local`]: the local rosbridge-compatible listener.
//! - `options`: the configuration turned into each part's options (at start and for a
//!   runtime change).
//! - [`outbox_store`]: the durable outbox: no-drop messages on disk until the hub has them.
//! - ROS 1 graphs are bridged by the `fleetlink-ros1` crate, started from [`agent`]
//!   when the configuration has a `ros1:` section.
//! - [`sim`]: a simulated robot producing plausible sensor data at configured rates.
//! - [`uplink`]: the `fleetlink.v1` link to the hub: reconnects, heartbeat, name mapping.

pub mod agent;
pub mod blackbox;
pub mod config;
pub mod local;
mod options;
pub mod outbox_store;
pub mod runtime;
pub mod sim;
pub mod status;
pub mod uplink;
pub mod video;

pub use agent::{Agent, AgentOptions};
