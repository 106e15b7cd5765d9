//! The fleetlink hub: the relay every robot connects out to.
//!
//! One TCP port serves WebSocket agents (`fleetlink.v1`), rosbridge v2 clients (any
//! other WebSocket), and HTTP (health, metrics, JSON API, the dashboard). Routing is the
//! shared [`fleetlink_relay::Router`]; this crate adds the listener, the agent side of
//! the link, durable state and the HTTP surface.
//!
//! # Layout
//!
//! - [`server`]: binds the port, tells WebSocket upgrades from plain HTTP, spawns one task
//!   per connection, shuts everything down on request.
//! - [`connection`]: one accepted socket: front-door limits, TLS, hyper, the hand-over
//!   to a WebSocket session.
//! - [`limits`]: the front door's timeouts and connection limits, as permits.
//! - [`http_guards`]: idle and request-body bounds hyper does not enforce itself.
//! - [`agents`]: one agent's `fleetlink.v1` session on the hub, and the registry of live
//!   robots.
//! - [`api`]: `/api/v1/*` JSON.
//! - [`dashboard`]: the fleet dashboard (`web/`) at `/`, embedded in the binary.
//! - [`admin_api`]: `/api/v1/` login/logout, rules, tokens, users and the audit log,
//!   every change through the security core.
//! - [`delivery`]: each message of a robot's no-drop topics delivered once, across
//!   reconnects and hub restarts (delivery marks, `DELIVERED` confirmations).
//! - [`capacity`]: shares of a site's access link for its robots, sent once a second.
//! - [`jwks`]: the OIDC signing keys, from a file or the provider's URL.
//! - [`metrics`]: Prometheus `/metrics`, read from the router's counters at scrape time.
//! - [`params`]: the parameter store behind `/rosapi/get_param` ..., kept in SQLite.
//! - [`rosout`]: `/rosout` as `rcl_interfaces/msg/Log`: the hub's events (robots coming,
//!   going, refused; links degrading; drops) and the robots' own logs.
//! - [`security`]: credentials from each transport, and the `fleetlink-auth` core behind
//!   the relay's `Gate` (checks at request time and on every delivery, audit log).
//! - [`store`]: the SQLite database in the data directory (robots seen so far, delivery
//!   marks).

pub mod admin_api;
pub mod agents;
pub mod api;
pub mod capacity;
pub mod connection;
pub mod dashboard;
pub mod delivery;
pub mod http_guards;
pub mod jwks;
pub mod limits;
pub mod metrics;
pub mod params;
pub mod rosout;
pub mod security;
pub mod server;
pub mod store;

pub use server::{Hub, HubConfig};
