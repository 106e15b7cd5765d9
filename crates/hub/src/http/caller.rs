//! Who is calling the HTTP API: [`require_identity`], the middleware in front of every
//! `/api/v1/*` route and `/metrics`, authenticates the request and puts the [`Caller`] in
//! it for the handlers.
//!
//! Design choice: its own module so the handlers' modules (`api`, `admin_api`,
//! `metrics`) import it and `http`'s `mod.rs` only assembles routes: imports inside the
//! folder run one way. The credentials are read by [`crate::security`], the same code the
//! WebSocket upgrade uses, so HTTP and WebSocket clients authenticate alike.

use std::sync::Arc;

use axum::Json;
use axum::extract::State;
use serde_json::json;

use crate::connection::ConnMeta;
use crate::state::HubState;

/// The identity behind an API request, put in the request by [`require_identity`].
#[derive(Clone)]
pub struct Caller(pub fleetlink_auth::Identity);

/// Every `/api` route and `/metrics` need an authenticated caller (or anonymous read where
/// the hub allows it): a bearer token in `Authorization` or a `token` query parameter.
pub async fn require_identity(
    State(st): State<Arc<HubState>>,
    axum::extract::ConnectInfo(peer): axum::extract::ConnectInfo<std::net::SocketAddr>,
    mut req: axum::extract::Request,
    next: axum::middleware::Next,
) -> axum::response::Response {
    use axum::response::IntoResponse;
    let tls_name = req
        .extensions()
        .get::<ConnMeta>()
        .and_then(|m| m.tls_name.clone());
    let conn = crate::security::conn_info(peer, req.headers(), tls_name);
    let credential = crate::security::request_credential(req.headers(), req.uri().query());
    match crate::security::authenticate(&st.security, credential, conn).await {
        Ok(identity) => {
            req.extensions_mut().insert(Caller(identity));
            next.run(req).await
        }
        Err(e) => (
            axum::http::StatusCode::UNAUTHORIZED,
            Json(json!({"error": format!("authentication required: {}", e.public_message())})),
        )
            .into_response(),
    }
}
