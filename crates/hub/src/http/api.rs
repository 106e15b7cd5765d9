//! The JSON API (`/api/v1/*`).
//!
//! Everything here is read from live state at request time: the router's tables and
//! counters, the registry of online robots, and the database for robots seen before.
//!
//! Design choice: listings answer the caller with what the caller may see under the same
//! rules as `/rosapi` — a topic appears when the caller may subscribe to it, a robot when
//! the caller may subscribe to its namespace or one of its topics — so the REST API is
//! never a side door around the access rules. Who is connected from where (robot
//! addresses, `/api/v1/clients`) is for those who may administer `/robots` and
//! `/clients`.

use std::sync::Arc;
use std::time::Instant;

use axum::extract::State;
use axum::routing::get;
use axum::{Extension, Json};
use fleetlink_auth::{Access, Operation};
use fleetlink_relay::queue::DropReason;
use fleetlink_relay::router::ClientKind;
use serde_json::{Value, json};

use super::caller::Caller;
use crate::state::HubState;

/// The read-only routes; they need an authenticated caller (see [`super::routes`]).
pub fn routes() -> axum::Router<Arc<HubState>> {
    axum::Router::new()
        .route("/api/v1/robots", get(robots))
        .route("/api/v1/topics", get(topics))
        .route("/api/v1/clients", get(clients))
        .route("/api/v1/federation", get(federation))
        .route("/api/v1/robots/{name}/offload", get(offload))
        .route("/api/v1/robots/{name}/rates", get(rates))
        // One message of a pull topic (reads data; asks the robot for it).
        .route(
            "/api/v1/robots/{name}/topics/{*rest}",
            axum::routing::post(super::pull::pull),
        )
}

fn client_label(st: &HubState, id: fleetlink_relay::ClientId) -> String {
    fleetlink_relay::rosapi::client_node_name(&st.router, id)
}

/// Whether the caller may subscribe to robot `name`'s namespace as a whole (`/<name>`
/// or, for rules written `/<name>/.*`, `/<name>/`).
fn namespace_visible(access: &mut Access, name: &str) -> bool {
    access.allows(&format!("/{name}"), Operation::Subscribe)
        || access.allows(&format!("/{name}/"), Operation::Subscribe)
}

/// Whether a topic appears in listings: listed by its publishers, and not one of the
/// names only the hub reads (a robot's black-box data).
fn shown(t: &fleetlink_relay::router::TopicSnapshot) -> bool {
    t.listed() && fleetlink_relay::names::hub_only(t.meta.name.as_str()).is_none()
}

/// The listed topics in robot `name`'s namespace that the caller may subscribe to.
fn robot_topics<'t>(
    access: &mut Access,
    topics: &'t [fleetlink_relay::router::TopicSnapshot],
    name: &str,
) -> Vec<&'t str> {
    let ns = format!("/{name}/");
    access.visible(
        topics
            .iter()
            .filter(|t| shown(t))
            .map(|t| t.meta.name.as_str())
            .filter(|n| n.starts_with(&ns)),
        Operation::Subscribe,
    )
}

/// Robots online now and robots seen before, online first; only those the caller may
/// see, with addresses only for those who may administer `/robots`.
async fn robots(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
) -> Json<Value> {
    let show_addr = st
        .security
        .authz
        .decide(&me, "/robots", Operation::Admin)
        .allowed;
    let mut access = st.security.access(me);
    let live = st.registry.list();
    let topics = st.router.topics();
    let mut out: Vec<Value> = Vec::new();
    let now_ms = fleetlink_relay::unix_nanos() / 1_000_000;
    for r in &live {
        let own = robot_topics(&mut access, &topics, &r.name);
        if own.is_empty() && !namespace_visible(&mut access, &r.name) {
            continue;
        }
        let measured_at = r.measured_at_ms.load(std::sync::atomic::Ordering::Relaxed);
        out.push(json!({
                "name": r.name,
                "online": true,
                "namespace": format!("/{}", r.name),
                "addr": r.addr.filter(|_| show_addr).map(|a| a.to_string()),
                "connected_at_ms": ms(r.connected_at),
                "heartbeat_ms": r.heartbeat_ms,
                "rtt_ms": r.rtt_ns.load(std::sync::atomic::Ordering::Relaxed) as f64 / 1e6,
                "last_seen_ms": r.last_seen_ns.load(std::sync::atomic::Ordering::Relaxed) / 1_000_000,
                "topics": own,
                "site": st.sites.iter().find(|site| site.robots.is_match(&r.name)).map(|site| site.name.clone()),
                "share_bps": nonzero(r.share_bps.load(std::sync::atomic::Ordering::Relaxed)),
                "demand_bps": r.demand_bps.load(std::sync::atomic::Ordering::Relaxed),
                "link_rate_bps": r.rate_bps.load(std::sync::atomic::Ordering::Relaxed),
                "latency_ms": r.latency_ns.load(std::sync::atomic::Ordering::Relaxed) as f64 / 1e6,
                // What the robot may send now (share, budget and the link's measured rate).
                "capacity_bps": nonzero(r.capacity_bps.load(std::sync::atomic::Ordering::Relaxed)),
                // When the link's rate was last measured with data on it, and how long ago:
                // an idle link is not probed, so its estimate is as old as its traffic.
                "link_measured_at_ms": nonzero(measured_at),
                "link_estimate_age_s": (measured_at > 0)
                    .then(|| now_ms.saturating_sub(measured_at) as f64 / 1e3),
                "clock_offset_ms": r.clock_offset_ns().map(|o| o as f64 / 1e6),
                // The robot's data budget, as its agent last reported it.
                "budget": r.budget.lock().unwrap_or_else(|p| p.into_inner()).as_ref().map(|b| json!({
                    "max_bps": b.max_bps,
                    "day_bytes": b.day_bytes,
                    "used_bytes": b.used_bytes,
                    "use_bps": b.use_bps.round(),
                    "thinned": b.thinned,
                })),
                "mirrors": mirrors_of(&st, r, &topics),
        }));
    }
    // Robots on the other hubs of a federation, where the caller may see them.
    let remote = st
        .federation
        .get()
        .map(|f| f.remote_robots())
        .unwrap_or_default();
    for r in &remote {
        if live.iter().any(|l| l.name == r.name) || !namespace_visible(&mut access, &r.name) {
            continue;
        }
        let own = robot_topics(&mut access, &topics, &r.name);
        out.push(json!({
            "name": r.name,
            "online": true,
            "namespace": format!("/{}", r.name),
            "hub": r.hub,
            "topics": own,
        }));
    }
    let store = st.store.clone();
    let known = tokio::task::spawn_blocking(move || store.robots())
        .await
        .ok()
        .and_then(Result::ok)
        .unwrap_or_default();
    for k in known {
        if !live.iter().any(|r| r.name == k.name)
            && !remote.iter().any(|r| r.name == k.name)
            && namespace_visible(&mut access, &k.name)
        {
            out.push(json!({
                "name": k.name,
                "online": false,
                "namespace": format!("/{}", k.name),
                "addr": if show_addr { json!(k.last_addr) } else { Value::Null },
                "last_seen_ms": k.last_seen_ms,
                "connects": k.connects,
                "topics": [],
            }));
        }
    }
    Json(json!({ "robots": out }))
}

/// Topics the caller may subscribe to.
async fn topics(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
) -> Json<Value> {
    let now = fleetlink_relay::unix_nanos();
    let mut access = st.security.access(me);
    // Topics a robot's data budget holds back now.
    let thinned: std::collections::HashSet<String> = st
        .registry
        .list()
        .iter()
        .filter_map(|r| {
            r.budget
                .lock()
                .unwrap_or_else(|p| p.into_inner())
                .as_ref()
                .map(|b| b.thinned.clone())
        })
        .flatten()
        .collect();
    let snapshot = st.router.topics();
    // Each online robot's topics: what it offers and what its link should deliver.
    let by_publisher = crate::rates::by_publisher(&snapshot);
    let mut predicted: std::collections::HashMap<String, crate::rates::TopicRate> =
        std::collections::HashMap::new();
    for r in st.registry.list() {
        if let Some(own) = by_publisher.get(&r.client) {
            for t in crate::rates::robot_rates(&r, own, now).topics {
                predicted.insert(t.name.clone(), t);
            }
        }
    }
    let list: Vec<Value> = snapshot
        .iter()
        .filter(|t| shown(t) && access.allows(t.meta.name.as_str(), Operation::Subscribe))
        .map(|t| {
            let p = predicted.get(t.meta.name.as_str());
            let (rate, bw) = t.stats.rates(now);
            let last = t.stats.last_message_ns.load(std::sync::atomic::Ordering::Relaxed);
            let drops: serde_json::Map<String, Value> =
                DropReason::ALL.iter().map(|r| (r.as_str().to_owned(), json!(t.stats.drops(*r)))).collect();
            json!({
                "name": t.meta.name.as_str(),
                "type": t.meta.schema.type_name,
                "publishers": t.publishers.iter().map(|c| client_label(&st, *c)).collect::<Vec<_>>(),
                // A robot's topic that nobody wants is held back on the robot (idle).
                // `pull`: sent only when a subscriber asks (POST …/pull, rosbridge `pull`).
                "state": if t.topic.is_pull() { "pull" } else if t.topic.is_idle() { "idle" } else { "flowing" },
                // Held back by its robot's data budget lately (thinned or paused).
                "thinned": thinned.contains(t.meta.name.as_str()),
                "subscribers": t.subscribers.iter().map(|c| client_label(&st, *c)).collect::<Vec<_>>(),
                "rate_hz": (rate * 100.0).round() / 100.0,
                // A robot's topic: what its publishers offer on the robot, and what its
                // link should deliver of that (docs/qos.md, receive-rate prediction).
                "offered_rate_hz": p.map(|p| round2(p.offer.hz)),
                "predicted_rate_hz": p.and_then(|p| p.predicted_hz).map(round2),
                "bandwidth_bps": bw.round(),
                "messages": t.stats.messages.load(std::sync::atomic::Ordering::Relaxed),
                "bytes": t.stats.bytes.load(std::sync::atomic::Ordering::Relaxed),
                // Over a robot's link: bytes as carried (compressed where it paid), the
                // payload bytes over those, and the link bytes per second that implies.
                "link_bytes": t.stats.link_figures().map(|(wire, _)| wire),
                "compression_ratio": t.stats.link_figures().map(|(wire, raw)| (raw as f64 / wire as f64 * 100.0).round() / 100.0),
                "link_bandwidth_bps": t.stats.link_figures().map(|(wire, raw)| (bw * wire as f64 / raw.max(1) as f64).round()),
                "last_message_ms": if last == 0 { Value::Null } else { json!(last / 1_000_000) },
                "drops": drops,
                // What the robot lost of it before its link (agent queues, `max_age`, the
                // data budget), by reason, as its agent last reported.
                "robot_drops": DropReason::ALL.iter().map(|r| (r.as_str().to_owned(), json!(t.stats.robot_drops(*r)))).collect::<serde_json::Map<String, Value>>(),
                "latency_ms": match t.stats.latency_ns.load(std::sync::atomic::Ordering::Relaxed) {
                    0 => Value::Null,
                    ns => json!(ns as f64 / 1e6),
                },
            })
        })
        .collect();
    Json(json!({ "topics": list }))
}

/// Every client connection with its queues: for those who may administer `/clients`.
/// This hub's federation: its id, the other hubs, the topics crossing each way.
async fn federation(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
) -> Result<Json<Value>, super::admin_api::ApiError> {
    super::admin_api::require_read(&st, &me, "/clients")?;
    Ok(Json(match st.federation.get() {
        Some(f) => f.status(),
        None => json!({ "federated": false }),
    }))
}

async fn clients(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
) -> Result<Json<Value>, super::admin_api::ApiError> {
    super::admin_api::require_read(&st, &me, "/clients")?;
    let now = Instant::now();
    let list: Vec<Value> = st
        .router
        .clients()
        .iter()
        .map(|(info, outbox, subs)| {
            let kind = match &info.kind {
                ClientKind::Rosbridge => "rosbridge".to_owned(),
                ClientKind::Foxglove => "foxglove".to_owned(),
                ClientKind::Agent { .. } => "agent".to_owned(),
                ClientKind::Internal { role } => format!("internal:{role}"),
            };
            json!({
                "id": info.id.0,
                "name": client_label(&st, info.id),
                "kind": kind,
                "addr": info.addr.map(|a| a.to_string()),
                "connected_at_ms": ms(info.connected_at),
                "deflate": info.deflate,
                "subscriptions": subs,
                "queue_depth": outbox.depth(),
                "lag_ms": outbox.lag(now).as_secs_f64() * 1e3,
                "sent": outbox.sent.load(std::sync::atomic::Ordering::Relaxed),
                "dropped": outbox.dropped.load(std::sync::atomic::Ordering::Relaxed),
            })
        })
        .collect();
    Ok(Json(json!({ "clients": list })))
}

fn round2(v: f64) -> f64 {
    (v * 100.0).round() / 100.0
}

/// One robot's receive-rate prediction with its inputs, so a reader can redo the sum:
/// the link capacity, and per topic what the robot offers, the message size on the link,
/// the scheduler's priority and queue, the rate the link could carry of the topic alone
/// (capacity / size), the prediction, and the rate measured at the hub.
async fn rates(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    axum::extract::Path(name): axum::extract::Path<String>,
) -> axum::response::Response {
    use axum::response::IntoResponse;
    let mut access = st.security.access(me);
    let snapshot = st.router.topics();
    let Some(robot) = st.registry.list().into_iter().find(|r| r.name == name) else {
        return (
            axum::http::StatusCode::NOT_FOUND,
            Json(json!({"error": format!("robot {name} is not online")})),
        )
            .into_response();
    };
    let own = robot_topics(&mut access, &snapshot, &name);
    if own.is_empty() && !namespace_visible(&mut access, &name) {
        return (
            axum::http::StatusCode::NOT_FOUND,
            Json(json!({"error": format!("robot {name} is not online")})),
        )
            .into_response();
    }
    let now = fleetlink_relay::unix_nanos();
    let by_publisher = crate::rates::by_publisher(&snapshot);
    let mine = by_publisher
        .get(&robot.client)
        .map_or(&[][..], Vec::as_slice);
    let r = crate::rates::robot_rates(&robot, mine, now);
    let topics: Vec<Value> = r
        .topics
        .iter()
        .filter(|t| own.contains(&t.name.as_str()))
        .map(|t| {
            let measured = snapshot
                .iter()
                .find(|s| s.meta.name.as_str() == t.name)
                .map(|s| round2(s.stats.rates(now).0));
            json!({
                "name": t.name,
                "offered_rate_hz": round2(t.offer.hz),
                "offered_bps": t.offer.bytes_per_sec.round(),
                "wire_bytes": t.wire_bytes.round(),
                "priority": t.offer.priority,
                "queue": t.offer.queue,
                "no_drop": t.offer.no_drop,
                "link_limit_hz": t.link_limit_hz.map(round2),
                "predicted_rate_hz": t.predicted_hz.map(round2),
                "rate_hz": measured,
            })
        })
        .collect();
    Json(json!({
        "robot": name,
        "capacity_bps": r.capacity_bps.map(f64::round),
        "topics": topics,
    }))
    .into_response()
}

/// A robot's mirrors (docs/mirror.md) with the topics each reads, and the offload signal:
/// Cloudroid's rule, offload while the link can carry the offloaded nodes' inputs (their
/// topics' bytes per second over the robot's link, against the capacity its agent
/// reports).
fn mirrors_of(
    st: &HubState,
    robot: &crate::registry::LiveRobot,
    topics: &[fleetlink_relay::router::TopicSnapshot],
) -> Value {
    let now = fleetlink_relay::unix_nanos();
    let capacity = robot
        .capacity_bps
        .load(std::sync::atomic::Ordering::Relaxed);
    let list: Vec<Value> = st
        .registry
        .mirrors_of(&robot.name)
        .iter()
        .map(|m| {
            let read: Vec<&fleetlink_relay::router::TopicSnapshot> = topics
                .iter()
                .filter(|t| t.publishers.contains(&robot.client) && t.subscribers.contains(&m.client))
                .collect();
            let inputs_bps: f64 = read
                .iter()
                .map(|t| {
                    let (_, bw) = t.stats.rates(now);
                    match t.stats.link_figures() {
                        Some((wire, raw)) => bw * wire as f64 / raw.max(1) as f64,
                        None => bw,
                    }
                })
                .sum();
            json!({
                "name": m.name,
                "connected_at_ms": ms(m.connected_at),
                "reads": read.iter().map(|t| t.meta.name.as_str()).collect::<Vec<_>>(),
                "inputs_bps": inputs_bps.round(),
                "offload": {
                    "rule": "offload while inputs_bps <= capacity_bps (the link carries the offloaded nodes' inputs)",
                    "fits": (capacity > 0).then_some(inputs_bps <= capacity as f64),
                },
            })
        })
        .collect();
    json!(list)
}

fn nonzero(v: u64) -> Value {
    if v == 0 { Value::Null } else { json!(v) }
}

/// The numbers of inequality (5), set by the operator for the task at hand.
#[derive(serde::Deserialize)]
struct OffloadQuery {
    /// Robots that need each piece of cooperation data.
    h: f64,
    /// The robot's computing speed, operations/s.
    s_m: f64,
    /// The server's computing speed, operations/s.
    s_s: f64,
    /// Data per task, bytes.
    d: f64,
    /// Computation per task, operations.
    x: f64,
}

/// Whether offloading a cooperation task to the cloud beats doing it on the robots,
/// given the robot's measured link (Cloudroid Swarm's inequality (5)).
async fn offload(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
    axum::extract::Path(name): axum::extract::Path<String>,
    q: Result<axum::extract::Query<OffloadQuery>, axum::extract::rejection::QueryRejection>,
) -> axum::response::Response {
    use axum::response::IntoResponse;
    let bad = |code, msg: String| (code, Json(json!({"error": msg}))).into_response();
    let q = match q {
        Ok(q) => q.0,
        Err(e) => {
            return bad(
                axum::http::StatusCode::BAD_REQUEST,
                format!("offload needs h, s_m, s_s, d and x: {e}"),
            );
        }
    };
    let visible = namespace_visible(&mut st.security.access(me), &name);
    let Some(r) = st
        .registry
        .list()
        .into_iter()
        .find(|r| r.name == name && visible)
    else {
        return bad(
            axum::http::StatusCode::NOT_FOUND,
            format!("robot {name} is not online"),
        );
    };
    let report = crate::capacity::report(&r);
    let params = fleetlink_qos::OffloadParams {
        h: q.h,
        s_m: q.s_m,
        s_s: q.s_s,
        d: q.d,
        x: q.x,
    };
    let offload = params.offload(report.rate, report.latency);
    Json(json!({
        "robot": name,
        "offload": offload,
        "link_rate_bps": report.rate,
        "latency_ms": report.latency.as_millis_f64(),
        "params": {"h": q.h, "s_m": q.s_m, "s_s": q.s_s, "d": q.d, "x": q.x},
    }))
    .into_response()
}

fn ms(t: std::time::SystemTime) -> u64 {
    t.duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_millis() as u64)
        .unwrap_or(0)
}
