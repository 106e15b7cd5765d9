//! fleetlink's rosbridge v2 server: one session per WebSocket connection, used by the hub
//! for operators and by the agent for local programs. The routing it drives (the router,
//! the call table, the outboxes, the `/rosapi` answers) is `fleetlink-relay`'s; this crate
//! owns only the rosbridge protocol on top of it.
//!
//! - [`session`]: one connection: reads operations, answers errors with `status`, writes
//!   the client's outbox to the socket. Generic over any WebSocket `Stream`/`Sink` pair
//!   (the hub's and the agent's are [`fleetlink_relay::websocket`]'s halves), so it is
//!   tested over channels as well as real sockets.
//! - [`calls`]: services and actions: the client as caller and as provider.
//!
//! The `/rosapi` services a session answers itself come from
//! [`fleetlink_relay::rosapi`], which the Foxglove server shares.

pub mod calls;
pub mod session;

pub use session::{SessionConfig, serve};
