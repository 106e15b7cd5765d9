//! A robot's configuration, read and changed while it runs (docs/runtime-config.md):
//!
//! - `GET /api/v1/robots/{name}/config`: the configuration in force on the robot (asked of
//!   its agent over the link), and what the hub keeps for it. For callers who may see the
//!   robot.
//! - `PUT /api/v1/robots/{name}/config` with a change (YAML or JSON text, the agent's YAML
//!   shape, only the fields to change): checked and applied by the agent, which answers
//!   with the configuration in force or the error its YAML would give. For callers who may
//!   administer `/robots/<name>/config` (the admin group, or a rule with `admin` on that
//!   name). Audited (`config_change`) either way.
//!
//! The hub keeps the changes in force (the record the agent answers with: each entry with
//! what the robot's file said when it was made) per robot, and applies them again whenever
//! the robot's configuration service appears — the robot reconnected, restarted without
//! its kept changes, or moved here from another hub sharing the database
//! ([`keep_applied`]); the agent merges them with its file as it does its own.
//!
//! Both go through the robot's configuration services, which only the hub may call (the
//! gate refuses every client: `crate::security::is_config_service`).

use std::sync::Arc;
use std::time::Duration;

use axum::extract::{Path, State};
use axum::http::StatusCode;
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::{Extension, Json};
use bytes::Bytes;
use fleetlink_auth::audit::AuditAction;
use fleetlink_auth::{AuditRecord, Identity, Operation, UnixTime};
use fleetlink_proto::Payload;
use fleetlink_relay::calls::{
    CallEvent, CallOptions, CallStatus, ChannelPeer, PeerMsg, ServiceChange,
};
use fleetlink_relay::names::{CONFIG_GET_SERVICE, CONFIG_SET_SERVICE};
use fleetlink_relay::{ClientKind, Router, TopicName};
use serde_json::{Value, json};
use tokio_util::sync::CancellationToken;

use super::caller::Caller;
use crate::state::HubState;

/// How long the hub waits for a robot's answer.
const CALL_TIMEOUT: Duration = Duration::from_secs(10);

pub fn routes() -> axum::Router<Arc<HubState>> {
    axum::Router::new()
        .route("/api/v1/robots/{name}/config", get(read).put(change))
        // A robot of a site hub chained to this one (docs/site-hubs.md), `/site7/robot1`.
        .route(
            "/api/v1/robots/{site}/robots/{name}/config",
            get(read_site).put(change_site),
        )
}

fn error(status: StatusCode, text: String) -> Response {
    (status, Json(json!({ "error": text }))).into_response()
}

/// The admin resource whose right lets a caller change `robot`'s configuration.
fn resource(robot: &str) -> String {
    format!("/robots/{robot}/config")
}

fn audit(st: &HubState, caller: &Identity, robot: &str, allowed: bool, detail: String) {
    st.security.audit.record(
        AuditRecord::operation(
            caller,
            AuditAction::ConfigChange,
            &resource(robot),
            None,
            allowed,
            UnixTime::now(),
        )
        .with_detail(detail),
    );
}

/// A robot's path: its name, or `site/name` for a site hub's robot; each part a valid
/// robot name.
fn robot_path(parts: &[&str]) -> Result<String, Box<Response>> {
    for p in parts {
        fleetlink_auth::RobotName::new(p)
            .map_err(|e| Box::new(error(StatusCode::BAD_REQUEST, format!("robot {p:?}: {e}"))))?;
    }
    Ok(parts.join("/"))
}

async fn read(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path(name): Path<String>,
) -> Response {
    match robot_path(&[&name]) {
        Ok(robot) => read_robot(st, me, robot).await,
        Err(r) => *r,
    }
}

async fn read_site(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path((site, name)): Path<(String, String)>,
) -> Response {
    match robot_path(&[&site, &name]) {
        Ok(robot) => read_robot(st, me, robot).await,
        Err(r) => *r,
    }
}

async fn change_site(
    State(st): State<Arc<HubState>>,
    Extension(caller): Extension<Caller>,
    Path((site, name)): Path<(String, String)>,
    body: Bytes,
) -> Response {
    match robot_path(&[&site, &name]) {
        Ok(robot) => change_robot(st, caller.0, robot, body).await,
        Err(r) => *r,
    }
}

async fn read_robot(st: Arc<HubState>, me: Identity, robot: String) -> Response {
    let may_change = st
        .security
        .authz
        .decide(&me, &resource(&robot), Operation::Admin)
        .allowed;
    let mut access = st.security.access(me);
    let visible = may_change
        || access.allows(&format!("/{robot}"), Operation::Subscribe)
        || access.allows(&format!("/{robot}/"), Operation::Subscribe);
    if !visible {
        return error(
            StatusCode::FORBIDDEN,
            format!(
                "{} may not see robot {robot}",
                access.identity().principal()
            ),
        );
    }
    let kept = kept(&st, robot.as_str()).await;
    match call(&st.router, robot.as_str(), CONFIG_GET_SERVICE, json!({})).await {
        Ok(mut view) => {
            view["robot"] = json!(robot.as_str());
            view["online"] = json!(true);
            view["may_change"] = json!(may_change);
            view["kept"] = json!(kept);
            Json(view).into_response()
        }
        Err(Failure::NoService) => Json(json!({
            "robot": robot.as_str(),
            "online": st.registry.is_online(robot.as_str()),
            "may_change": may_change,
            "kept": kept,
            "error": format!("{robot} does not answer for its configuration now (offline, or its agent cannot change it while it runs)"),
        }))
        .into_response(),
        Err(Failure::Other(text)) => error(StatusCode::BAD_GATEWAY, text),
    }
}

async fn change(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path(name): Path<String>,
    body: Bytes,
) -> Response {
    match robot_path(&[&name]) {
        Ok(robot) => change_robot(st, me, robot, body).await,
        Err(r) => *r,
    }
}

async fn change_robot(st: Arc<HubState>, me: Identity, robot: String, body: Bytes) -> Response {
    if let Err(e) = super::admin_api::require_admin_as(
        &st,
        &me,
        &resource(robot.as_str()),
        AuditAction::ConfigChange,
    ) {
        return e.into_response();
    }
    let Ok(text) = std::str::from_utf8(&body) else {
        return error(
            StatusCode::BAD_REQUEST,
            "a change is YAML or JSON text, in UTF-8".into(),
        );
    };
    let by = me.principal();
    let request = json!({ "change": text, "by": format!("{by} (hub API)") });
    let answer = match call(&st.router, robot.as_str(), CONFIG_SET_SERVICE, request).await {
        Ok(a) => a,
        Err(Failure::NoService) => {
            audit(&st, &me, robot.as_str(), false, "robot offline".into());
            return error(
                StatusCode::SERVICE_UNAVAILABLE,
                format!(
                    "{robot} does not answer for its configuration now (offline, or its agent \
                     cannot change it while it runs); try again when it is connected"
                ),
            );
        }
        Err(Failure::Other(text)) => {
            audit(&st, &me, robot.as_str(), false, text.clone());
            return error(StatusCode::BAD_GATEWAY, text);
        }
    };
    if answer["ok"] != json!(true) {
        let refusal = answer.get("error").cloned().unwrap_or(Value::Null);
        let text = refusal["error"].as_str().unwrap_or("refused").to_owned();
        audit(&st, &me, robot.as_str(), false, format!("refused: {text}"));
        return (StatusCode::BAD_REQUEST, Json(refusal)).into_response();
    }
    let fields = answer["changed"].clone();
    if answer["unchanged"] != json!(true) {
        // The agent's record of the changes in force (each entry with what the robot's file
        // said then, when and by whom), so that they merge with its file when applied again;
        // an agent without one answers with the changes only.
        let overlay = match answer.get("record") {
            Some(record) if record.is_object() => record.to_string(),
            _ => answer["overlay"].to_string(),
        };
        let store = st.store.clone();
        let (robot_s, by_s) = (robot.to_string(), by.clone());
        let kept =
            tokio::task::spawn_blocking(move || store.set_robot_config(&robot_s, &overlay, &by_s))
                .await;
        if !matches!(kept, Ok(Ok(()))) {
            tracing::error!(%robot, "the hub could not keep the configuration change: {kept:?}");
        }
        audit(
            &st,
            &me,
            robot.as_str(),
            true,
            format!("changed {fields}: {text}"),
        );
    }
    let mut view = answer;
    view["robot"] = json!(robot.as_str());
    Json(view).into_response()
}

/// What the hub keeps for `robot`, if anything.
async fn kept(st: &HubState, robot: &str) -> Option<Value> {
    let store = st.store.clone();
    let robot = robot.to_owned();
    let kept = tokio::task::spawn_blocking(move || store.robot_config(&robot))
        .await
        .ok()?
        .ok()??;
    let kept_value = serde_json::from_str::<Value>(&kept.overlay).unwrap_or(Value::Null);
    // An agent's record (`change` with `entries`), or the change alone (kept before records).
    let (overlay, record) = match kept_value.get("change") {
        Some(change) => (change.clone(), kept_value.clone()),
        None => (kept_value.clone(), Value::Null),
    };
    Some(json!({
        "overlay": overlay,
        "record": record,
        "by": kept.by,
        "at_ms": kept.at_ms,
    }))
}

enum Failure {
    /// Nobody offers the service: the robot is offline (or cannot change its
    /// configuration).
    NoService,
    Other(String),
}

/// Calls `robot`'s configuration service `service` (a local name) with the JSON
/// `request`, as an internal client of the hub's call table.
async fn call(
    router: &Arc<Router>,
    robot: &str,
    service: &str,
    request: Value,
) -> Result<Value, Failure> {
    let name = TopicName::parse(&format!("/{robot}{service}"))
        .map_err(|e| Failure::Other(format!("robot {robot}: {e}")))?;
    let (client, _outbox) = router.connect(
        ClientKind::Internal {
            role: "robot config".into(),
        },
        None,
    );
    let (peer, events) = ChannelPeer::new();
    router.calls.attach(client, peer);
    let opts = CallOptions {
        timeout: Some(CALL_TIMEOUT),
        ..CallOptions::default()
    };
    let body = serde_json::to_vec(&request).unwrap_or_default();
    let outcome = match router.calls.call(client, &name, Payload::json(body), opts) {
        Err(refused) if refused.status == CallStatus::NoProvider => Err(Failure::NoService),
        Err(refused) => Err(Failure::Other(refused.text)),
        Ok(id) => loop {
            match events.recv().await {
                Some(PeerMsg::Event(CallEvent::Done {
                    id: done,
                    status,
                    payload,
                    text,
                })) if done == id => {
                    break match status {
                        CallStatus::Ok => payload
                            .and_then(|p| serde_json::from_slice::<Value>(&p.bytes).ok())
                            .ok_or_else(|| {
                                Failure::Other(format!(
                                    "{robot} answered with something that is not JSON"
                                ))
                            }),
                        CallStatus::NoProvider => Err(Failure::NoService),
                        _ => Err(Failure::Other(format!("{robot}: {text}"))),
                    };
                }
                Some(_) => continue,
                None => break Err(Failure::Other("the call table closed".into())),
            }
        },
    };
    router.disconnect(client);
    outcome
}

/// Applies the changes the hub keeps for a robot whenever its configuration service
/// appears (it connected, or its agent restarted), until `shutdown`.
pub async fn keep_applied(st: Arc<HubState>, shutdown: CancellationToken) {
    let router = st.router.clone();
    let (client, _outbox) = router.connect(
        ClientKind::Internal {
            role: "robot config keeper".into(),
        },
        None,
    );
    let (peer, events) = ChannelPeer::new();
    router.calls.attach(client, peer);
    // A robot here, or a site hub's robot (`/site7/robot1/…`).
    let pattern = format!("(/[^/]+)+{}", regex::escape(CONFIG_SET_SERVICE));
    match Router::compile_pattern(&pattern) {
        Ok(re) => router.calls.watch(client, re),
        Err(e) => {
            tracing::error!("robot configuration: cannot watch {pattern}: {e}");
            return;
        }
    }
    loop {
        let m = tokio::select! {
            m = events.recv() => m,
            _ = shutdown.cancelled() => break,
        };
        match m {
            Some(PeerMsg::Changed(ServiceChange::Added(info))) => {
                let Some(robot) = info
                    .name
                    .as_str()
                    .strip_suffix(CONFIG_SET_SERVICE)
                    .and_then(|r| r.strip_prefix('/'))
                    .map(str::to_owned)
                else {
                    continue;
                };
                // Off this loop: the call waits for the robot's answer.
                tokio::spawn(reapply(st.clone(), robot));
            }
            Some(_) => {}
            None => break,
        }
    }
    router.disconnect(client);
}

/// Applies the kept changes of `robot` (if the hub keeps any).
async fn reapply(st: Arc<HubState>, robot: String) {
    let Some(kept) = kept(&st, &robot).await else {
        return;
    };
    let by = "the hub (changes it keeps, applied again)";
    // A record merges with the robot's file as the agent's own kept changes do (what the
    // file has changed since is set aside, not forced back).
    let request = if kept["record"].is_object() {
        json!({ "kept": kept["record"], "by": by })
    } else {
        json!({ "change": kept["overlay"].to_string(), "by": by })
    };
    match call(&st.router, &robot, CONFIG_SET_SERVICE, request).await {
        Ok(a) if a["ok"] == json!(true) => {
            if let Some(aside) = a["set_aside_now"].as_array().filter(|s| !s.is_empty()) {
                tracing::warn!(
                    %robot,
                    "some configuration changes the hub keeps for it were set aside by the robot: {}",
                    serde_json::Value::Array(aside.clone())
                );
            }
            if a["unchanged"] != json!(true) {
                tracing::info!(%robot, "applied the configuration changes the hub keeps for it again");
                st.security.audit.record(AuditRecord {
                    at: UnixTime::now(),
                    principal: "hub".into(),
                    client_ip: std::net::IpAddr::from([127, 0, 0, 1]),
                    action: AuditAction::ConfigChange,
                    name: resource(&robot),
                    size: None,
                    allowed: true,
                    detail: Some(format!("applied again on reconnect: {}", a["changed"])),
                });
            }
        }
        Ok(a) => tracing::warn!(
            %robot,
            "the configuration changes the hub keeps no longer apply to it: {}",
            a["error"]["error"].as_str().unwrap_or("refused")
        ),
        Err(Failure::NoService) => {}
        Err(Failure::Other(text)) => {
            tracing::warn!(%robot, "applying the kept configuration changes: {text}")
        }
    }
}
