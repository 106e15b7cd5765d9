//! The WebSocket layer (the `fleetlink-websocket` crate) under the paths relay's users
//! know it by, and the wait between a writer's batches, which needs an [`crate::Outbox`].

pub use fleetlink_websocket::*;

/// The direct replies a session's reader hands its writer, and the writer's wait.
#[path = "websocket_wait.rs"]
pub mod replies;
