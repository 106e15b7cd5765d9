//! `POST /api/v1/robots/{robot}/topics/{topic}/pull`: one message of a robot's pull topic
//! (`mode: pull` on the agent), asked of the robot and answered as rosbridge JSON.
//!
//! The hub subscribes for the request's length, asks the robot's link for one message
//! ([`Router::request_pull`]) and waits for it, at most [`PULL_WAIT`]. The caller needs
//! the right to subscribe to the topic, as for every other way of reading it.

use std::sync::Arc;
use std::time::{Duration, Instant};

use axum::Json;
use axum::extract::{Extension, Path, State};
use axum::http::StatusCode;
use fleetlink_auth::Operation;
use fleetlink_proto::Encoding;
use fleetlink_relay::router::{ClientKind, SubOptions, Target};
use fleetlink_relay::{ClientId, Router, TopicName};
use serde_json::{Value, json};

use super::caller::Caller;
use crate::state::HubState;

/// How long a pull waits for the robot's answer.
pub const PULL_WAIT: Duration = Duration::from_secs(5);

type Answer = Result<Json<Value>, (StatusCode, Json<Value>)>;

fn error(status: StatusCode, text: String) -> (StatusCode, Json<Value>) {
    (status, Json(json!({ "error": text })))
}

/// The request's own subscriber, gone with the request.
struct Puller {
    router: Arc<Router>,
    client: ClientId,
}

impl Drop for Puller {
    fn drop(&mut self) {
        self.router.disconnect(self.client);
    }
}

pub async fn pull(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    Path((robot, rest)): Path<(String, String)>,
) -> Answer {
    let Some(local) = rest.strip_suffix("/pull") else {
        return Err(error(
            StatusCode::NOT_FOUND,
            "expected POST /api/v1/robots/{robot}/topics/{topic}/pull".into(),
        ));
    };
    let name = TopicName::parse(&format!("/{robot}/{}", local.trim_start_matches('/')))
        .map_err(|e| error(StatusCode::BAD_REQUEST, e.to_string()))?;
    let mut access = st.security.access(me.clone());
    if !access.allows(name.as_str(), Operation::Subscribe) {
        return Err(error(
            StatusCode::FORBIDDEN,
            format!("{} may not subscribe to {name}", me.principal()),
        ));
    }
    let Some(topic) = st.router.topic(&name) else {
        return Err(error(
            StatusCode::NOT_FOUND,
            format!("no topic {name} (is robot {robot} connected?)"),
        ));
    };
    if !topic.is_pull() {
        return Err(error(
            StatusCode::CONFLICT,
            format!("{name} is not a pull topic: it streams while subscribed; subscribe to it"),
        ));
    }
    let (client, outbox) = st.router.connect(
        ClientKind::Internal {
            role: "pull".into(),
        },
        None,
    );
    let _puller = Puller {
        router: st.router.clone(),
        client,
    };
    st.router
        .subscribe(client, Target::Exact(name.clone()), SubOptions::default())
        .map_err(|e| error(StatusCode::INTERNAL_SERVER_ERROR, e.to_string()))?;
    if !st.router.request_pull(&name) {
        return Err(error(
            StatusCode::CONFLICT,
            format!("{name}: its robot is no longer connected"),
        ));
    }
    let deadline = tokio::time::Instant::now() + PULL_WAIT;
    loop {
        let batch = outbox.take(1, usize::MAX, Instant::now());
        if let Some((_, _, m)) = batch.items.into_iter().next() {
            let text = st
                .router
                .transcoder()
                .convert(&m.topic.schema, &m.payload, Encoding::Json)
                .map_err(|e| error(StatusCode::BAD_GATEWAY, format!("{name}: {e}")))?;
            let msg: Value = serde_json::from_slice(&text)
                .map_err(|e| error(StatusCode::BAD_GATEWAY, format!("{name}: not JSON: {e}")))?;
            return Ok(Json(json!({
                "topic": name.as_str(),
                "type": m.topic.schema.type_name,
                "stamp_ns": m.stamp_ns,
                "msg": msg,
            })));
        }
        if tokio::time::timeout_at(deadline, outbox.ready())
            .await
            .is_err()
        {
            return Err(error(
                StatusCode::GATEWAY_TIMEOUT,
                format!(
                    "{name}: the robot sent nothing within {} s (no message yet, or none \
                     younger than its max_age)",
                    PULL_WAIT.as_secs()
                ),
            ));
        }
    }
}
