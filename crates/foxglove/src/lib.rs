//! The hub's Foxglove WebSocket server: Foxglove and Lichtblick connect to the hub's one
//! port (subprotocol `foxglove.sdk.v1` or `foxglove.websocket.v1`) and see the whole
//! fleet's topics as channels, with the same tokens, access rules and audit as rosbridge
//! clients.
//!
//! # Layout
//!
//! - [`protocol`]: the protocol's JSON operations and binary messages, no I/O (our own
//!   serde types; why not the `foxglove` crate's is written there).
//! - [`channels`]: a topic as a channel: which encoding its messages go in, and the
//!   schema text (the full definition with its dependencies) the client decodes them
//!   with.
//! - [`session`]: one connection's reader: channels following the router's topics,
//!   subscriptions as router subscriptions, client publishing.
//! - `client`: the client as the reader acts toward it (router id, gate, the replies
//!   queue), shared by the session and its services.
//! - `services`: service calls through the call table and parameters through rosapi's
//!   path, for a session.
//! - `writer`: one connection's writer: the outbox as `MessageData`, a shared payload
//!   behind a per-subscription header.

pub mod channels;
mod client;
pub mod protocol;
mod services;
pub mod session;
mod writer;

pub use protocol::{SUBPROTOCOLS, choose_subprotocol};
pub use session::{SessionConfig, serve};
