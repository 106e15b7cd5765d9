//! `/api/v1/recordings`: MCAP recordings of the fleet's topics on the hub.
//!
//! - `GET /api/v1/recordings`: every recording, newest first;
//! - `POST /api/v1/recordings` with a [`RecordSpec`] body: start one (201 with it);
//! - `GET /api/v1/recordings/{id}`: one, with its files and figures;
//! - `POST /api/v1/recordings/{id}/stop`: stop it, answered once its files are finished;
//! - `DELETE /api/v1/recordings/{id}`: stop it and delete its files;
//! - `GET /api/v1/recordings/{id}/files/{name}`: download one of its files;
//! - `POST /api/v1/recordings/blackbox` with a [`FetchSpec`] body: ask a robot for a
//!   slice of its black box (201 with the new recording, state `fetching`; it becomes
//!   `stopped` when the slice is in, or `failed` with the reason).
//!
//! Recordings are the admin resource `/recordings`: reading the list and the files needs
//! the right to read it, starting, stopping and removing the right to change it (the admin
//! group has both; a rule can grant them to others). A recording records what its starter
//! may subscribe to, asked for every message as for any subscriber. Starts, stops and
//! removals are audited, refused ones too.

use std::sync::Arc;

use axum::Json;
use axum::body::Body;
use axum::extract::{Extension, Path, State};
use axum::http::{StatusCode, header};
use axum::response::{IntoResponse, Response};
use fleetlink_auth::audit::{AuditAction, AuditRecord};
use fleetlink_auth::{Identity, UnixTime};
use fleetlink_record::blackbox::fetch::FetchSpec;
use fleetlink_record::{RecordError, RecordSpec};
use serde_json::{Value, json};

use super::admin_api::{ApiError, require_admin, require_read};
use super::caller::Caller;
use crate::state::HubState;

const RESOURCE: &str = "/recordings";

pub fn routes() -> axum::Router<Arc<HubState>> {
    use axum::routing::{get, post};
    axum::Router::new()
        .route("/api/v1/recordings", get(list).post(start))
        .route("/api/v1/recordings/{id}", get(one).delete(remove))
        .route("/api/v1/recordings/{id}/stop", post(stop))
        .route("/api/v1/recordings/{id}/files/{name}", get(download))
        .route("/api/v1/recordings/blackbox", post(fetch))
}

fn refusal(e: RecordError) -> Response {
    let status = match &e {
        RecordError::Invalid(_) => StatusCode::BAD_REQUEST,
        RecordError::NotFound(_) => StatusCode::NOT_FOUND,
        RecordError::TooMany => StatusCode::TOO_MANY_REQUESTS,
        RecordError::Io(_) => StatusCode::INTERNAL_SERVER_ERROR,
    };
    (status, Json(json!({ "error": e.to_string() }))).into_response()
}

fn audit(st: &HubState, caller: &Identity, name: &str, allowed: bool, detail: String) {
    st.security.audit.record(
        AuditRecord::operation(
            caller,
            AuditAction::Recording,
            name,
            None,
            allowed,
            UnixTime::now(),
        )
        .with_detail(detail),
    );
}

async fn list(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
) -> Result<Json<Value>, ApiError> {
    require_read(&st, &me, RESOURCE)?;
    Ok(Json(json!({ "recordings": st.recordings.list() })))
}

async fn one(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path(id): Path<String>,
) -> Result<Response, ApiError> {
    require_read(&st, &me, RESOURCE)?;
    Ok(match st.recordings.get(&id) {
        Ok(info) => Json(info).into_response(),
        Err(e) => refusal(e),
    })
}

async fn start(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    body: axum::body::Bytes,
) -> Result<Response, ApiError> {
    require_admin(&st, &me, RESOURCE)?;
    let spec: RecordSpec = match serde_json::from_slice(&body) {
        Ok(s) => s,
        Err(e) => {
            let text = format!(
                "the body must be a recording request like {{\"topics\": [\"/robot1/.*\"]}}: {e}"
            );
            audit(&st, &me, RESOURCE, false, text.clone());
            return Ok(refusal(RecordError::Invalid(text)));
        }
    };
    let topics = spec.topics.join(" ");
    let started = st.recordings.start(spec, me.principal(), gate_of(&st, &me));
    Ok(created(&st, &me, started, format!("started: {topics}")))
}

/// The caller's access rules, asked for every message a recording or a slice keeps.
fn gate_of(st: &HubState, me: &Identity) -> Box<crate::security::HubGate> {
    Box::new(crate::security::HubGate::new(
        st.security.clone(),
        st.registry.clone(),
        me.clone(),
    ))
}

/// 201 with a new recording (or fetch), or the refusal; audited either way.
fn created(
    st: &HubState,
    me: &Identity,
    outcome: Result<fleetlink_record::RecordingInfo, RecordError>,
    detail: String,
) -> Response {
    match outcome {
        Ok(info) => {
            audit(st, me, &format!("{RESOURCE}/{}", info.id), true, detail);
            (StatusCode::CREATED, Json(info)).into_response()
        }
        Err(e) => {
            audit(st, me, RESOURCE, false, e.to_string());
            refusal(e)
        }
    }
}

async fn fetch(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    body: axum::body::Bytes,
) -> Result<Response, ApiError> {
    require_admin(&st, &me, RESOURCE)?;
    let spec: FetchSpec = match serde_json::from_slice(&body) {
        Ok(s) => s,
        Err(e) => {
            let text = format!(
                "the body must be a black-box request like {{\"robot\": \"robot1\", \
                 \"last_s\": 60, \"topics\": [\"/scan\"]}}: {e}"
            );
            audit(&st, &me, RESOURCE, false, text.clone());
            return Ok(refusal(RecordError::Invalid(text)));
        }
    };
    // The slice keeps what the requester may read: the rules are asked per topic once it
    // is in.
    let what = format!(
        "fetching the black box of {}: {}",
        spec.robot,
        spec.topics.join(" ")
    );
    let registry = st.registry.clone();
    let online = Box::new(move |robot: &str| registry.is_online(robot));
    let started = st
        .recordings
        .fetch(spec, me.principal(), gate_of(&st, &me), online);
    Ok(created(&st, &me, started, what))
}

async fn stop(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path(id): Path<String>,
) -> Result<Response, ApiError> {
    require_admin(&st, &me, RESOURCE)?;
    Ok(match st.recordings.stop(&id).await {
        Ok(info) => {
            audit(
                &st,
                &me,
                &format!("{RESOURCE}/{id}"),
                true,
                "stopped".into(),
            );
            Json(info).into_response()
        }
        Err(e) => refusal(e),
    })
}

async fn remove(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path(id): Path<String>,
) -> Result<Response, ApiError> {
    require_admin(&st, &me, RESOURCE)?;
    Ok(match st.recordings.remove(&id).await {
        Ok(()) => {
            audit(
                &st,
                &me,
                &format!("{RESOURCE}/{id}"),
                true,
                "removed".into(),
            );
            StatusCode::NO_CONTENT.into_response()
        }
        Err(e) => refusal(e),
    })
}

async fn download(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path((id, name)): Path<(String, String)>,
) -> Result<Response, ApiError> {
    require_read(&st, &me, RESOURCE)?;
    let path = match st.recordings.file(&id, &name) {
        Ok(p) => p,
        Err(e) => return Ok(refusal(e)),
    };
    let file = match tokio::fs::File::open(&path).await {
        Ok(f) => f,
        Err(e) => {
            return Ok(refusal(RecordError::Io(format!(
                "opening {id}/{name}: {e}"
            ))));
        }
    };
    // The size as it is now: a growing file is sent up to here.
    let len = file.metadata().await.map(|m| m.len()).unwrap_or(0);
    let body = Body::from_stream(tokio_util::io::ReaderStream::with_capacity(
        tokio::io::AsyncReadExt::take(file, len),
        256 << 10,
    ));
    Ok((
        [
            (header::CONTENT_TYPE, "application/octet-stream".to_owned()),
            (header::CONTENT_LENGTH, len.to_string()),
            (
                header::CONTENT_DISPOSITION,
                format!("attachment; filename=\"{name}\""),
            ),
        ],
        body,
    )
        .into_response())
}
