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
//!   per connection, shuts everything down on request; [`Hub`] and [`HubConfig`].
//! - [`state`]: [`state::HubState`], what the HTTP handlers, the upgrade and the
//!   background tasks share, and the [`state::SiteConfig`] it carries.
//! - [`connection`]: one accepted socket: front-door limits, TLS, hyper, the hand-over
//!   to a WebSocket session.
//! - [`limits`]: the front door's timeouts and connection limits, as permits.
//! - [`http_guards`]: idle and request-body bounds hyper does not enforce itself.
//! - [`upgraded`]: the socket under an upgraded connection as two halves (a plain TCP
//!   connection's own, taken back from hyper).
//! - [`http`]: the HTTP surface: `/api/v1/*` JSON (`api`, and `admin_api` for login,
//!   rules, tokens, users and the audit log, every change through the security core),
//!   Prometheus `/metrics` (`metrics`, read from the router's counters at scrape time),
//!   the embedded fleet dashboard (`dashboard`) and the authentication every API route
//!   sits behind (`caller`).
//! - [`agents`]: one agent's `fleetlink.v1` session on the hub.
//! - [`registry`]: the robots online now and each link's figures.
//! - [`delivery`]: each message of a robot's no-drop topics delivered once, across
//!   reconnects and hub restarts (delivery marks, `DELIVERED` confirmations).
//! - [`capacity`]: shares of a site's access link for its robots, sent once a second.
//! - [`jwks`]: the OIDC signing keys, from a file or the provider's URL.
//! - [`federated`]: the seam to other hubs (remote robots and federation status for the
//!   API), implemented by the `fleetlink-federation` crate.
//! - [`params`]: the parameter store behind `/rosapi/get_param` ..., kept in the store
//!   (and reloaded when another hub sharing the database changes it).
//! - [`rosout`]: `/rosout` as `rcl_interfaces/msg/Log`: the hub's events (robots coming,
//!   going, refused; links degrading; drops) and the robots' own logs.
//! - [`security`]: credentials from each transport, and the `fleetlink-auth` core behind
//!   the relay's `Gate` (checks at request time and on every delivery, audit log).
//! - [`store`]: the SQLite database in the data directory, or the PostgreSQL database
//!   several hubs share (robots seen so far, delivery marks, parameters).
//!
//! Imports run one way, from the top of this list of layers to the bottom; no module
//! imports one above it (check with `grep -rn "crate::" crates/hub/src`, which also finds
//! paths written inline):
//!
//! 1. `server` — builds the state and wires everything below together.
//! 2. `http` (→ `state`, `capacity`, `security`, `connection` for `ConnMeta`, `limits` for
//!    its counters). Inside it, `mod.rs` → the handlers' modules → `caller`; `api` and
//!    `metrics` → `admin_api` for its refusals.
//! 3. `capacity` (→ `state`, `registry`); `connection` (→ `limits`, `http_guards`);
//!    `upgraded` (→ `http_guards`).
//! 4. `state` (→ `agents`, `registry`, `store`, `jwks`, `limits`).
//! 5. `agents` (→ `security`, `rosout`, `delivery`, `registry`, `store`).
//! 6. `security`, `rosout` (→ `registry`); `delivery`, `params` (→ `store`).
//! 7. Leaves, importing nothing from the crate: `registry`, `store`, `limits`,
//!    `http_guards`, `jwks`, `federated`.

pub mod agents;
pub mod capacity;
pub mod connection;
pub mod delivery;
pub mod federated;
pub mod http;
pub mod http_guards;
pub mod jwks;
pub mod limits;
pub mod params;
pub mod rates;
pub mod registry;
pub mod rosout;
pub mod security;
pub mod server;
pub mod state;
pub mod store;
pub mod upgraded;

pub use server::{Hub, HubConfig};
