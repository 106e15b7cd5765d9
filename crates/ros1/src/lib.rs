//! The agent's native ROS 1 adapter: a node of the robot's ROS graph that bridges its
//! topics and services with the agent's local [`Router`](fleetlink_relay::Router), like
//! the simulator and the local rosbridge listener do.
//!
//! Up (robot → hub), it subscribes to the graph's publishers with type `*` and forwards
//! each message as the ROS 1 bytes that arrived, with the publisher's definition learned
//! into the registry. Down (hub → robot), it publishes router topics into the graph with
//! the md5sum and full definition from the registry. Services go both ways through the
//! router's call table. The protocol (master/slave XML-RPC and TCPROS) is implemented
//! here on tokio; docs/ros1.md says why no ROS 1 client crate is used.
//!
//! # Layout
//!
//! - [`options`]: what to bridge ([`Ros1Options`]).
//! - [`xmlrpc`]: XML-RPC values, calls and responses (codec, no I/O).
//! - [`http`]: the little HTTP/1.1 that carries XML-RPC.
//! - [`tcpros`]: TCPROS connection headers and message framing.
//! - [`master`]: calls to the master and to other nodes' slave APIs.
//! - [`node`]: the node's shared state and its slave API server.
//! - [`inbound`]: the TCPROS listener (local subscribers, local service callers).
//! - [`outbound`]: connections to local publishers and local service providers.
//! - [`bridge`]: the router side, discovery and master-restart handling ([`run`]).

pub mod bridge;
pub mod http;
pub mod inbound;
pub mod master;
pub mod node;
pub mod options;
pub mod outbound;
pub mod params;
pub mod tcpros;
pub mod xmlrpc;

pub use bridge::{Ros1Error, run};
pub use node::Ros1Stats;
pub use options::{NameFilter, Ros1Options};
