//! The hub's HTTP surface, everything on the port that is not a WebSocket upgrade: the
//! JSON API, Prometheus metrics and the embedded dashboard.
//!
//! - [`caller`]: the authentication middleware every API route and `/metrics` sit
//!   behind, and the [`caller::Caller`] it hands the handlers.
//! - [`api`]: `/api/v1/*` read-only listings (robots, topics, clients, offload).
//! - [`admin_api`]: `/api/v1/` login/logout, rules, tokens, users and the audit log,
//!   every change through the security core; its `ApiError` and `require_read` are
//!   the API's refusals.
//! - [`recordings`]: `/api/v1/recordings`: MCAP recordings started, stopped, listed,
//!   removed and downloaded.
//! - [`metrics`]: Prometheus `/metrics`, read from the router's counters at scrape time.
//! - [`dashboard`]: the fleet dashboard (`web/`) files, embedded in the binary.
//!
//! Design choice: handlers read [`HubState`] (crate::state) and the parts below it and
//! never the listener: `server` imports this module, not the other way round. `/` is
//! routed by `server` itself, since it is both the WebSocket endpoint and the
//! dashboard's page.

pub mod admin_api;
pub mod api;
pub mod caller;
pub mod dashboard;
pub mod metrics;
pub mod pull;
pub mod recordings;
pub mod robot_config;

use std::sync::Arc;

use axum::routing::get;

use crate::state::HubState;

/// Every HTTP route but `/`: `/healthz`; the API and `/metrics` behind
/// [`caller::require_identity`]; and the one public route, login.
pub fn routes(state: Arc<HubState>) -> axum::Router<Arc<HubState>> {
    let api = api::routes()
        .merge(admin_api::routes())
        .merge(recordings::routes())
        .merge(robot_config::routes())
        .route("/metrics", get(metrics::handler))
        .route_layer(axum::middleware::from_fn_with_state(
            state,
            caller::require_identity,
        ));
    axum::Router::new()
        .route("/healthz", get(|| async { "ok\n" }))
        .merge(api)
        .merge(admin_api::public_routes())
}
