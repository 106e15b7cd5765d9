//! The agent's native ROS 2 adapter: a DDS participant in the robot's ROS 2 graph that
//! bridges its topics, services and actions with the agent's local
//! [`Router`](fleetlink_relay::Router), like the simulator and the ROS 1 bridge do.
//!
//! Up (robot → hub), it follows DDS discovery and reads the graph's writers of bridged
//! topics as the CDR bytes that arrived (encapsulation header included), typed by their
//! ROS 2 name; the definition comes from the agent's registry. Down (hub → robot), it
//! writes router topics into the graph, converting once when a message is not CDR.
//! Services use ROS 2's request/reply topics in the mapping of the other side's
//! middleware (Cyclone DDS's or Fast DDS's); actions are their three services and two
//! topics; nodes' parameters answer rosapi's parameter services.
//! docs/ros2.md has the design, the QoS table and the limits.
//!
//! # Layout
//!
//! - [`options`]: what to bridge ([`Ros2Options`]).
//! - [`raw`]: the raw-CDR sample type and its rustdds adapters.
//! - [`names`]: ROS 2 names ⇄ DDS topic and type names.
//! - [`qos`]: DDS QoS for the readers and writers the bridge creates.
//! - [`bridge`]: the participant, discovery, topics both ways ([`run`]).
//! - [`services`]: services both ways, local action servers exposed to the fleet.
//! - [`offered_actions`]: fleet actions served to local action clients.
//! - [`params`]: nodes' parameters behind rosapi's parameter services.
//! - [`node_info`]: the agent as a node in `ros_discovery_info` (`ros2 node list`).

pub mod bridge;
mod lost_peers;
pub mod names;
pub mod node_info;
pub mod offered_actions;
pub mod options;
pub mod params;
pub mod qos;
pub mod raw;
pub mod services;

pub use bridge::{Ros2Error, Stats as Ros2Stats, run};
pub use options::Ros2Options;
