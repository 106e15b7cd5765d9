//! Local servers exposed to the fleet ([`Remote`]): found in discovery, advertised in
//! the call table, and fleet calls and goals carried to them as requests.
//!
//! A service is one [`Endpoint`]; an action is its `send_goal`, `get_result` and
//! `cancel_goal` endpoints and a reader of its feedback topic.

use std::collections::{HashMap, HashSet};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::TopicName;
use fleetlink_relay::calls::{CallRequest, CallStatus};
use futures::StreamExt;
use tokio::task::AbortHandle;

use super::endpoint::{Endpoint, Mapping, client_id};
use crate::bridge::{Bridge, RawReader};
use crate::names::{self, DdsName};
use crate::qos;
use crate::raw::CDR_LE_HEADER;

pub(crate) enum RemoteKind {
    Service {
        srv_type: String,
        call: Arc<Endpoint>,
    },
    Action {
        action_type: String,
        send_goal: Arc<Endpoint>,
        get_result: Arc<Endpoint>,
        cancel_goal: Arc<Endpoint>,
        /// Goals in flight: UUID → call id (for their feedback).
        goals: Mutex<HashMap<[u8; 16], u64>>,
    },
}

/// A local service or action server offered to the fleet.
pub struct Remote {
    name: String,
    kind: RemoteKind,
    tasks: Vec<AbortHandle>,
}

impl Remote {
    pub(crate) fn abort(&self) {
        for t in &self.tasks {
            t.abort();
        }
    }
}

/// Follows the graph's servers: exposes new ones, withdraws vanished ones.
pub(crate) fn discover(bridge: &Arc<Bridge>) {
    let mut services: HashMap<String, (String, Mapping)> = HashMap::new();
    let mut actions: HashMap<String, (String, Mapping)> = HashMap::new();
    let opts = bridge.live();
    for r in bridge.dp.discovered_readers() {
        let s = &r.subscription_topic_data;
        if bridge.is_own(s.key()) {
            continue;
        }
        let Some(DdsName::Request(service)) = DdsName::parse(s.topic_name()) else {
            continue;
        };
        let mapping = Mapping::of(r.reader_proxy.remote_reader_guid);
        if let Some(action) = names::action_of_send_goal(&service) {
            if opts.expose_actions.matches(action)
                && let Some(t) = names::action_type(s.type_name())
            {
                actions.insert(action.to_owned(), (t, mapping));
            }
        } else if !names::is_hidden(&service)
            && opts.expose.matches(&service)
            && let Some(t) = names::service_type(s.type_name())
        {
            services.insert(service, (t, mapping));
        }
    }
    let known: HashSet<String> = bridge.lock().remotes.keys().cloned().collect();
    for name in known
        .iter()
        .filter(|n| !services.contains_key(*n) && !actions.contains_key(*n))
    {
        if let Some(r) = bridge.lock().remotes.remove(name) {
            r.abort();
            if let Ok(n) = TopicName::parse(name) {
                bridge.router.calls.unadvertise(bridge.client, &n);
            }
            tracing::info!("ros2: local server of {name} went away");
        }
    }
    for (name, (t, mapping)) in services {
        if !known.contains(&name) {
            expose(bridge, &name, &t, false, mapping);
        }
    }
    for (name, (t, mapping)) in actions {
        if !known.contains(&name) {
            expose(bridge, &name, &t, true, mapping);
        }
    }
}

fn expose(bridge: &Arc<Bridge>, name: &str, type_name: &str, action: bool, mapping: Mapping) {
    // A service or action is known when its request (goal) part is; the registry may
    // or may not have a full text for the whole interface.
    let part = format!("{type_name}{}", if action { "_Goal" } else { "_Request" });
    let Some(schema) = bridge.schema(&part).map(|_| {
        bridge
            .schema(type_name)
            .unwrap_or_else(|| Schema::named(type_name))
    }) else {
        bridge.report_once(name, &bridge.stats.unknown_types, || {
            format!(
                "ros2: not exposing {name}: type {type_name} is unknown to the agent's registry; \
                 give the agent its package with --msg-path DIR"
            )
        });
        return;
    };
    let Ok(topic_name) = TopicName::parse(name) else {
        return;
    };
    let made = if action {
        make_action(bridge, name, type_name, client_id(bridge), mapping)
    } else {
        Endpoint::start(bridge, name, type_name, mapping).map(|(call, task)| {
            (
                RemoteKind::Service {
                    srv_type: type_name.to_owned(),
                    call,
                },
                vec![task],
            )
        })
    };
    let (kind, tasks) = match made {
        Ok(k) => k,
        Err(e) => {
            tracing::warn!("ros2: cannot expose {name}: {e}");
            return;
        }
    };
    tracing::info!(
        "ros2: exposing local {} {name} ({type_name}) to the fleet",
        if action { "action" } else { "service" }
    );
    bridge.lock().remotes.insert(
        name.to_owned(),
        Arc::new(Remote {
            name: name.to_owned(),
            kind,
            tasks,
        }),
    );
    bridge
        .router
        .calls
        .advertise(bridge.client, topic_name, schema, action);
}

fn make_action(
    bridge: &Arc<Bridge>,
    name: &str,
    action_type: &str,
    client: u64,
    mapping: Mapping,
) -> Result<(RemoteKind, Vec<AbortHandle>), String> {
    let part = |p: &str| format!("{name}/_action/{p}");
    let (send_goal, r1) = Endpoint::new(
        bridge,
        &part("send_goal"),
        &format!("{action_type}_SendGoal"),
        client,
        true,
        mapping,
    )?;
    let (get_result, r2) = Endpoint::new(
        bridge,
        &part("get_result"),
        &format!("{action_type}_GetResult"),
        client,
        false,
        mapping,
    )?;
    let (cancel_goal, r3) = Endpoint::new(
        bridge,
        &part("cancel_goal"),
        "action_msgs/srv/CancelGoal",
        client,
        true,
        mapping,
    )?;
    let feedback_type = names::dds_type(&format!("{action_type}_FeedbackMessage"))
        .ok_or_else(|| format!("{action_type} is not a ROS type name"))?;
    let feedback = bridge.reader(
        &names::topic(&part("feedback")),
        &feedback_type,
        qos::reader_for(None, None, qos::DEPTH),
    )?;
    let tasks = vec![
        tokio::spawn(send_goal.clone().pump(r1)).abort_handle(),
        tokio::spawn(get_result.clone().pump(r2)).abort_handle(),
        tokio::spawn(cancel_goal.clone().pump(r3)).abort_handle(),
        tokio::spawn(pump_feedback(bridge.clone(), name.to_owned(), feedback)).abort_handle(),
    ];
    Ok((
        RemoteKind::Action {
            action_type: action_type.to_owned(),
            send_goal,
            get_result,
            cancel_goal,
            goals: Mutex::new(HashMap::new()),
        },
        tasks,
    ))
}

/// Feedback samples of `action`'s goals → the goals' callers. A feedback message is the
/// goal's UUID (16 bytes, so the feedback after it keeps its alignment) then the feedback.
async fn pump_feedback(bridge: Arc<Bridge>, action: String, reader: RawReader) {
    let mut samples = reader.async_sample_stream();
    while let Some(r) = samples.next().await {
        let Ok(sample) = r else { continue };
        let raw = sample.into_value().0;
        let Some(uuid) = raw.get(4..20).and_then(|u| <[u8; 16]>::try_from(u).ok()) else {
            continue;
        };
        let Some(remote) = bridge.lock().remotes.get(&action).cloned() else {
            return;
        };
        let RemoteKind::Action { goals, .. } = &remote.kind else {
            return;
        };
        let id = goals
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .get(&uuid)
            .copied();
        if let Some(id) = id {
            let mut fb = Vec::with_capacity(raw.len() - 16);
            fb.extend_from_slice(&raw[..4]);
            fb.extend_from_slice(&raw[20..]);
            bridge
                .router
                .calls
                .feedback(bridge.client, id, Payload::new(Encoding::Cdr, fb));
        }
    }
}

/// A fleet call or goal for a local server, answered in the call table.
pub(super) async fn serve(bridge: &Bridge, remote: &Arc<Remote>, req: CallRequest) {
    let limit = req.deadline.map_or(bridge.opts.call_timeout, |d| {
        d.saturating_duration_since(Instant::now())
    });
    let outcome = tokio::time::timeout(limit, async {
        match &remote.kind {
            RemoteKind::Service { srv_type, call } => {
                let body = bridge.to_cdr(&format!("{srv_type}_Request"), &req.payload)?;
                let reply = call.request(body).await?;
                Ok((
                    CallStatus::Ok,
                    Some(Payload::new(Encoding::Cdr, reply)),
                    String::new(),
                ))
            }
            RemoteKind::Action { .. } => goal(bridge, remote, &req).await,
        }
    })
    .await;
    let (status, payload, text) = match outcome {
        Ok(Ok(answer)) => answer,
        Ok(Err(text)) => (CallStatus::Failed, None, text),
        Err(_) => (
            CallStatus::Timeout,
            None,
            format!("{} did not answer within {limit:?}", remote.name),
        ),
    };
    bridge.lock().goals.remove(&req.id);
    if let RemoteKind::Action { goals, .. } = &remote.kind {
        goals
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .retain(|_, id| *id != req.id);
    }
    bridge
        .router
        .calls
        .respond(bridge.client, req.id, status, payload, text);
}

type Answer = (CallStatus, Option<Payload>, String);

/// A goal: `send_goal`, then `get_result` (feedback flows meanwhile).
async fn goal(bridge: &Bridge, remote: &Arc<Remote>, req: &CallRequest) -> Result<Answer, String> {
    let RemoteKind::Action {
        action_type,
        send_goal,
        get_result,
        goals,
        ..
    } = &remote.kind
    else {
        return Err("not an action".into());
    };
    let uuid = req.goal_id.unwrap_or_default();
    let goal = bridge.to_cdr(&format!("{action_type}_Goal"), &req.payload)?;
    let mut msg = Vec::with_capacity(goal.len() + 16);
    msg.extend_from_slice(&CDR_LE_HEADER);
    msg.extend_from_slice(&uuid);
    msg.extend_from_slice(goal.get(4..).unwrap_or_default());
    goals
        .lock()
        .unwrap_or_else(|p| p.into_inner())
        .insert(uuid, req.id);
    bridge.lock().goals.insert(req.id, (remote.clone(), uuid));
    let accepted = send_goal.request(msg.into()).await?;
    if accepted.get(4).copied().unwrap_or(0) == 0 {
        return Ok((
            CallStatus::Failed,
            None,
            format!("{} rejected the goal", remote.name),
        ));
    }
    let mut ask = Vec::with_capacity(20);
    ask.extend_from_slice(&CDR_LE_HEADER);
    ask.extend_from_slice(&uuid);
    let reply = get_result.request(ask.into()).await?;
    // `{int8 status, T_Result result}`: the result is not aligned as a message of its
    // own, so the registry reads the whole answer once.
    let v = bridge.json_of(
        &format!("{action_type}_GetResult_Response"),
        &Payload::new(Encoding::Cdr, reply),
    )?;
    let status = match v.get("status").and_then(|s| s.as_i64()) {
        Some(4) => CallStatus::Ok,
        Some(5) => CallStatus::Cancelled,
        _ => CallStatus::Aborted,
    };
    let result = serde_json::to_vec(v.get("result").unwrap_or(&serde_json::Value::Null))
        .map_err(|e| e.to_string())?;
    let text = match status {
        CallStatus::Ok => String::new(),
        CallStatus::Cancelled => format!("{} cancelled the goal", remote.name),
        _ => format!("{} aborted the goal", remote.name),
    };
    Ok((status, Some(Payload::new(Encoding::Json, result)), text))
}

/// Asks a local action server to cancel a goal (`cancel_goal` with the goal's UUID and a
/// zero stamp); the goal's `get_result` then ends it.
pub(super) async fn cancel(remote: &Remote, uuid: [u8; 16]) {
    let RemoteKind::Action { cancel_goal, .. } = &remote.kind else {
        return;
    };
    let mut msg = Vec::with_capacity(28);
    msg.extend_from_slice(&CDR_LE_HEADER);
    msg.extend_from_slice(&uuid);
    msg.extend_from_slice(&[0u8; 8]);
    if let Err(e) = cancel_goal.request(msg.into()).await {
        tracing::debug!("ros2: cancelling a goal of {}: {e}", remote.name);
    }
}
