//! Prometheus `/metrics`.
//!
//! The relay keeps its counters as plain atomics on the hot path; this module reads them
//! only when scraped, through a prometheus-client collector, so metrics cost the fan-out
//! nothing.

use std::sync::Arc;
use std::time::Instant;

use axum::Extension;
use axum::extract::State;
use axum::http::{StatusCode, header};
use axum::response::{IntoResponse, Response};
use fleetlink_relay::queue::DropReason;
use prometheus_client::collector::Collector;
use prometheus_client::encoding::{DescriptorEncoder, EncodeMetric};
use prometheus_client::metrics::MetricType;
use prometheus_client::metrics::counter::ConstCounter;
use prometheus_client::metrics::gauge::ConstGauge;
use prometheus_client::registry::Registry;

use super::caller::Caller;
use crate::state::HubState;

struct HubCollector(Arc<HubState>);

impl std::fmt::Debug for HubCollector {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("HubCollector")
    }
}

impl Collector for HubCollector {
    fn encode(&self, mut enc: DescriptorEncoder) -> Result<(), std::fmt::Error> {
        let st = &self.0;
        encode_topics(st, &mut enc)?;
        encode_clients(st, &mut enc)?;
        let m = enc.encode_descriptor(
            "fleetlink_robots_online",
            "Robots connected now",
            None,
            MetricType::Gauge,
        )?;
        ConstGauge::new(st.registry.list().len() as i64).encode(m)?;
        let m = enc.encode_descriptor(
            "fleetlink_video_kept_bytes",
            "Bytes of video frames kept since each video topic's last keyframe, for new \
             viewers, all topics together (bounded; docs/video.md)",
            None,
            MetricType::Gauge,
        )?;
        ConstGauge::new(st.router.video_pool.used() as i64).encode(m)?;
        encode_budgets(&st.registry.list(), &mut enc)?;
        encode_audit(&st.security.audit, &mut enc)?;
        if let Some(f) = st.federation.get() {
            encode_federation(f.as_ref(), &mut enc)?;
        }
        encode_shared_changes(&st.security, &mut enc)?;
        encode_front_door(&st.limits, &mut enc)
    }
}

/// Each topic's counters: messages, bytes, deliveries, drops and subscribers.
fn encode_topics(st: &HubState, enc: &mut DescriptorEncoder) -> Result<(), std::fmt::Error> {
    let topics = st.router.topics();
    let relaxed = std::sync::atomic::Ordering::Relaxed;

    let mut m = enc.encode_descriptor(
        "fleetlink_topic_messages",
        "Messages published on a topic",
        None,
        MetricType::Counter,
    )?;
    for t in &topics {
        ConstCounter::new(t.stats.messages.load(relaxed))
            .encode(m.encode_family(&[("topic", t.meta.name.as_str())])?)?;
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_topic_bytes",
        "Payload bytes published on a topic",
        None,
        MetricType::Counter,
    )?;
    for t in &topics {
        ConstCounter::new(t.stats.bytes.load(relaxed))
            .encode(m.encode_family(&[("topic", t.meta.name.as_str())])?)?;
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_topic_link_bytes",
        "Bytes a robot topic's messages took on the robot's link (compressed where they \
         came so); their payload bytes are fleetlink_topic_link_payload_bytes",
        None,
        MetricType::Counter,
    )?;
    for t in &topics {
        if let Some((wire, _)) = t.stats.link_figures() {
            ConstCounter::new(wire).encode(m.encode_family(&[("topic", t.meta.name.as_str())])?)?;
        }
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_topic_link_payload_bytes",
        "Payload bytes of the messages that came over a robot's link, before compression",
        None,
        MetricType::Counter,
    )?;
    for t in &topics {
        if let Some((_, raw)) = t.stats.link_figures() {
            ConstCounter::new(raw).encode(m.encode_family(&[("topic", t.meta.name.as_str())])?)?;
        }
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_topic_deliveries",
        "Messages queued to subscribers of a topic",
        None,
        MetricType::Counter,
    )?;
    for t in &topics {
        ConstCounter::new(t.stats.deliveries.load(relaxed))
            .encode(m.encode_family(&[("topic", t.meta.name.as_str())])?)?;
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_topic_drops",
        "Messages a subscriber of a topic lost, by reason",
        None,
        MetricType::Counter,
    )?;
    for t in &topics {
        for r in DropReason::ALL {
            let labels = [("topic", t.meta.name.as_str()), ("reason", r.as_str())];
            ConstCounter::new(t.stats.drops(r)).encode(m.encode_family(&labels)?)?;
        }
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_topic_robot_drops",
        "Messages of a robot's topic its agent lost before the link, by reason (as the \
         agent last reported)",
        None,
        MetricType::Counter,
    )?;
    for t in &topics {
        for r in DropReason::ALL {
            let n = t.stats.robot_drops(r);
            if n > 0 {
                let labels = [("topic", t.meta.name.as_str()), ("reason", r.as_str())];
                ConstCounter::new(n).encode(m.encode_family(&labels)?)?;
            }
        }
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_topic_subscribers",
        "Subscribers of a topic",
        None,
        MetricType::Gauge,
    )?;
    for t in &topics {
        ConstGauge::new(t.subscribers.len() as i64)
            .encode(m.encode_family(&[("topic", t.meta.name.as_str())])?)?;
    }
    Ok(())
}

/// Each client's outbound queues: depth, lag and losses.
fn encode_clients(st: &HubState, enc: &mut DescriptorEncoder) -> Result<(), std::fmt::Error> {
    let relaxed = std::sync::atomic::Ordering::Relaxed;
    let now = Instant::now();
    let clients = st.router.clients();
    let label = |id| fleetlink_relay::rosapi::client_node_name(&st.router, id);
    let mut m = enc.encode_descriptor(
        "fleetlink_client_queue_depth",
        "Messages waiting in a client's outbound queues",
        None,
        MetricType::Gauge,
    )?;
    for (info, outbox, _) in &clients {
        let l = [("client", label(info.id))];
        ConstGauge::new(outbox.depth() as i64).encode(m.encode_family(&l)?)?;
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_client_lag_seconds",
        "Age of the oldest message waiting for a client",
        None,
        MetricType::Gauge,
    )?;
    for (info, outbox, _) in &clients {
        let l = [("client", label(info.id))];
        ConstGauge::new(outbox.lag(now).as_secs_f64()).encode(m.encode_family(&l)?)?;
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_client_dropped",
        "Messages a client lost",
        None,
        MetricType::Counter,
    )?;
    for (info, outbox, _) in &clients {
        let l = [("client", label(info.id))];
        ConstCounter::new(outbox.dropped.load(relaxed)).encode(m.encode_family(&l)?)?;
    }
    Ok(())
}

/// Robots' data budgets: what each allows, what it counted, which topics it holds back.
fn encode_budgets(
    robots: &[Arc<crate::registry::LiveRobot>],
    enc: &mut DescriptorEncoder,
) -> Result<(), std::fmt::Error> {
    let budgets: Vec<(String, crate::registry::RobotBudget)> = robots
        .iter()
        .filter_map(|r| {
            let b = r.budget.lock().unwrap_or_else(|p| p.into_inner()).clone()?;
            Some((r.name.clone(), b))
        })
        .collect();
    let mut m = enc.encode_descriptor(
        "fleetlink_robot_budget_used_bytes",
        "Bytes a robot's link counted against its data budget since the agent set it",
        None,
        MetricType::Counter,
    )?;
    for (name, b) in &budgets {
        ConstCounter::new(b.used_bytes).encode(m.encode_family(&[("robot", name.as_str())])?)?;
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_robot_budget_allowed_bps",
        "Bytes per second a robot's data budget allows over the long run (the lower of its \
         rate limit and its daily pace)",
        None,
        MetricType::Gauge,
    )?;
    for (name, b) in &budgets {
        let day = b.day_bytes.map(|d| d as f64 / 86_400.0);
        let allowed = [b.max_bps.map(|r| r as f64), day]
            .into_iter()
            .flatten()
            .fold(f64::INFINITY, f64::min);
        ConstGauge::new(allowed).encode(m.encode_family(&[("robot", name.as_str())])?)?;
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_topic_thinned",
        "1 while a robot's data budget holds the topic back (thinned or paused)",
        None,
        MetricType::Gauge,
    )?;
    for (_, b) in &budgets {
        for t in &b.thinned {
            ConstGauge::new(1).encode(m.encode_family(&[("topic", t.as_str())])?)?;
        }
    }
    Ok(())
}

/// The audit log's writer: what it stored and what it lost. A lost record is an
/// event nobody can look up later, so it is counted where an alert can see it.
fn encode_audit(
    audit: &fleetlink_auth::AuditLog,
    enc: &mut DescriptorEncoder,
) -> Result<(), std::fmt::Error> {
    let m = enc.encode_descriptor(
        "fleetlink_audit_records_written",
        "Audit log records written to the database",
        None,
        MetricType::Counter,
    )?;
    ConstCounter::new(audit.written()).encode(m)?;
    let mut m = enc.encode_descriptor(
        "fleetlink_audit_records_lost",
        "Audit log records lost: queue_full (the writer fell behind) or database_error",
        None,
        MetricType::Counter,
    )?;
    ConstCounter::new(audit.overflowed()).encode(m.encode_family(&[("reason", "queue_full")])?)?;
    ConstCounter::new(audit.failed()).encode(m.encode_family(&[("reason", "database_error")])?)?;
    Ok(())
}

/// What crossed to and from the other hubs of a federation.
fn encode_federation(
    federation: &dyn crate::federated::Federated,
    enc: &mut DescriptorEncoder,
) -> Result<(), std::fmt::Error> {
    for (name, help, value) in federation.counters() {
        let m = enc.encode_descriptor(name, help, None, MetricType::Counter)?;
        ConstCounter::new(value).encode(m)?;
    }
    Ok(())
}

/// Change notifications from hubs sharing the database (all zero with SQLite): a rise of
/// `everything` means the listener lost its connection and reloaded on its return.
fn encode_shared_changes(
    security: &fleetlink_auth::Security,
    enc: &mut DescriptorEncoder,
) -> Result<(), std::fmt::Error> {
    let mut m = enc.encode_descriptor(
        "fleetlink_database_changes",
        "Change notifications received from the shared database, by kind",
        None,
        MetricType::Counter,
    )?;
    for (kind, n) in security.changes_received() {
        ConstCounter::new(n).encode(m.encode_family(&[("kind", kind)])?)?;
    }
    Ok(())
}

/// The front door's counts: open connections, handshakes, and what the limits refused.
fn encode_front_door(
    limits: &crate::limits::Limits,
    enc: &mut DescriptorEncoder,
) -> Result<(), std::fmt::Error> {
    let m = enc.encode_descriptor(
        "fleetlink_connections_open",
        "Client connections open now (HTTP and WebSocket)",
        None,
        MetricType::Gauge,
    )?;
    ConstGauge::new(limits.open() as i64).encode(m)?;
    let m = enc.encode_descriptor(
        "fleetlink_handshakes_in_progress",
        "TLS handshakes and WebSocket upgrades not yet completed",
        None,
        MetricType::Gauge,
    )?;
    ConstGauge::new(limits.handshaking() as i64).encode(m)?;
    let mut m = enc.encode_descriptor(
        "fleetlink_connections_refused",
        "Connections refused by a front-door limit (total, per_ip, handshakes)",
        None,
        MetricType::Counter,
    )?;
    for r in crate::limits::Refusal::ALL {
        ConstCounter::new(limits.refused(r)).encode(m.encode_family(&[("limit", r.as_str())])?)?;
    }
    let mut m = enc.encode_descriptor(
        "fleetlink_request_bodies_refused",
        "Request bodies refused: over --max-body-bytes, or not complete within --body-timeout-secs",
        None,
        MetricType::Counter,
    )?;
    let (large, slow) = limits.bodies_refused();
    ConstCounter::new(large).encode(m.encode_family(&[("reason", "too_large")])?)?;
    ConstCounter::new(slow).encode(m.encode_family(&[("reason", "too_slow")])?)?;
    Ok(())
}

/// `/metrics` for callers that may read [`fleetlink_auth::acl::METRICS`]: the admin
/// group, the `metrics` group, a rule granting `admin` on `/metrics`, or anonymous
/// clients where anonymous read is on.
pub async fn handler(
    State(st): State<Arc<HubState>>,
    Extension(Caller(me)): Extension<Caller>,
) -> Response {
    if let Err(e) = super::admin_api::require_read(&st, &me, fleetlink_auth::acl::METRICS) {
        return e.into_response();
    }
    let mut reg = Registry::default();
    reg.register_collector(Box::new(HubCollector(st)));
    let mut out = String::new();
    match prometheus_client::encoding::text::encode(&mut out, &reg) {
        Ok(()) => (
            [(
                header::CONTENT_TYPE,
                "text/plain; version=0.0.4; charset=utf-8",
            )],
            out,
        )
            .into_response(),
        Err(e) => (
            StatusCode::INTERNAL_SERVER_ERROR,
            format!("cannot encode metrics: {e}\n"),
        )
            .into_response(),
    }
}
