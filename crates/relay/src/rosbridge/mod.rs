//! A rosbridge v2 server session, used by the hub for operators and by the agent for
//! local programs.
//!
//! - [`session`]: one connection: reads operations, answers errors with `status`, writes
//!   the client's outbox to the socket. Generic over any WebSocket `Stream`/`Sink` pair
//!   (the hub's and the agent's are [`crate::websocket`]'s halves), so it is tested over
//!   channels as well as real sockets.
//! - [`calls`]: services and actions: the client as caller and as provider.
//! - [`rosapi`]: the `/rosapi` services answered from the router's own tables.

pub mod calls;
pub mod rosapi;
pub mod session;

pub use session::{SessionConfig, serve};
