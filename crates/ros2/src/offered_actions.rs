//! Fleet actions offered to local ROS 2 action clients: this bridge serves the action's
//! three services and writes its feedback and status topics, as a ROS 2 action server
//! does, and each goal becomes a goal in the call table.
//!
//! - `send_goal` → a fleet goal with the client's UUID; the reply says accepted (or not,
//!   when the call table refuses it at once).
//! - `get_result` → answered when the goal ends (at once when it has ended); the last
//!   [`KEEP_ENDED`] ended goals are kept for late askers.
//! - `cancel_goal` → the goal's cancel in the call table (a zero UUID cancels all goals).
//! - feedback from the fleet → `<action>/_action/feedback` with the goal's UUID; status
//!   changes → `<action>/_action/status` (transient local, so a late client sees them).
//!
//! Small messages this side builds (replies, status) go through the registry from JSON;
//! goal and feedback bodies are carried as CDR without decoding.

use std::collections::{HashMap, VecDeque};
use std::sync::{Arc, Mutex};
use std::time::SystemTime;

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload};
use fleetlink_relay::TopicName;
use fleetlink_relay::calls::{CallEvent, CallOptions, CallStatus};
use futures::StreamExt;
use serde_json::{Value, json};
use tokio::task::AbortHandle;

use crate::bridge::{Bridge, RawReader, RawWriter};
use crate::names;
use crate::qos;
use crate::raw::{CDR_LE_HEADER, RawCdr};
use crate::services::ReplyTo;

/// Ended goals remembered for `get_result` requests that come after the end.
const KEEP_ENDED: usize = 64;

const STATUS_EXECUTING: i64 = 2;
const STATUS_CANCELING: i64 = 3;
const STATUS_SUCCEEDED: i64 = 4;
const STATUS_CANCELED: i64 = 5;
const STATUS_ABORTED: i64 = 6;

/// One goal of a local client.
struct Goal {
    uuid: [u8; 16],
    call: u64,
    stamp: (i32, u32),
    status: i64,
    /// The `get_result` reply once the goal ended.
    result: Option<Bytes>,
    /// `get_result` requests waiting for the end.
    waiting: Vec<ReplyTo>,
}

struct Writers {
    send_goal: RawWriter,
    get_result: RawWriter,
    cancel_goal: RawWriter,
    feedback: RawWriter,
    status: RawWriter,
}

/// A fleet action served to local clients.
pub struct OfferedAction {
    name: String,
    action_type: String,
    writers: Writers,
    goals: Mutex<Goals>,
    tasks: Mutex<Vec<AbortHandle>>,
}

#[derive(Default)]
struct Goals {
    live: HashMap<[u8; 16], Goal>,
    ended: VecDeque<Goal>,
}

impl OfferedAction {
    fn goals(&self) -> std::sync::MutexGuard<'_, Goals> {
        self.goals.lock().unwrap_or_else(|p| p.into_inner())
    }
}

fn now_stamp() -> (i32, u32) {
    let d = SystemTime::now()
        .duration_since(SystemTime::UNIX_EPOCH)
        .unwrap_or_default();
    (
        i32::try_from(d.as_secs()).unwrap_or(i32::MAX),
        d.subsec_nanos(),
    )
}

fn goal_info(uuid: &[u8; 16], stamp: (i32, u32)) -> Value {
    json!({"goal_id": {"uuid": uuid.to_vec()}, "stamp": {"sec": stamp.0, "nanosec": stamp.1}})
}

fn uuid_at(msg: &[u8]) -> Option<[u8; 16]> {
    msg.get(4..20).and_then(|u| <[u8; 16]>::try_from(u).ok())
}

/// Serves fleet action `name` (type `pkg/action/T`) to local clients.
pub(crate) fn offer(
    bridge: &Arc<Bridge>,
    name: &str,
    action_type: &str,
) -> Result<Arc<OfferedAction>, String> {
    let part = |p: &str| format!("{name}/_action/{p}");
    let dds = |suffix: &str| {
        names::dds_type(&format!("{action_type}{suffix}"))
            .ok_or_else(|| format!("{action_type:?} is not a ROS action type name"))
    };
    let service_pair = |service: &str, base: &str| -> Result<(RawReader, RawWriter), String> {
        let ty = |s: &str| {
            names::dds_type(&format!("{base}{s}"))
                .ok_or_else(|| format!("{base:?} is not a ROS type name"))
        };
        Ok((
            bridge.reader(
                &names::request_topic(&part(service)),
                &ty("_Request")?,
                qos::service(),
            )?,
            bridge.writer(
                &names::reply_topic(&part(service)),
                &ty("_Response")?,
                qos::service(),
            )?,
        ))
    };
    let (send_goal_rx, send_goal) = service_pair("send_goal", &format!("{action_type}_SendGoal"))?;
    let (get_result_rx, get_result) =
        service_pair("get_result", &format!("{action_type}_GetResult"))?;
    let (cancel_rx, cancel_goal) = service_pair("cancel_goal", "action_msgs/srv/CancelGoal")?;
    let feedback = bridge.writer(
        &names::topic(&part("feedback")),
        &dds("_FeedbackMessage")?,
        qos::writer(false),
    )?;
    let status = bridge.writer(
        &names::topic(&part("status")),
        "action_msgs::msg::dds_::GoalStatusArray_",
        qos::action_status(),
    )?;
    let action = Arc::new(OfferedAction {
        name: name.to_owned(),
        action_type: action_type.to_owned(),
        writers: Writers {
            send_goal,
            get_result,
            cancel_goal,
            feedback,
            status,
        },
        goals: Mutex::new(Goals::default()),
        tasks: Mutex::new(Vec::new()),
    });
    let spawn = |reader: RawReader, kind: Request| {
        tokio::spawn(serve_requests(bridge.clone(), action.clone(), kind, reader)).abort_handle()
    };
    let tasks = vec![
        spawn(send_goal_rx, Request::SendGoal),
        spawn(get_result_rx, Request::GetResult),
        spawn(cancel_rx, Request::Cancel),
    ];
    *action.tasks.lock().unwrap_or_else(|p| p.into_inner()) = tasks;
    Ok(action)
}

impl OfferedAction {
    /// Stops serving the action's requests.
    pub(crate) fn abort(&self) {
        for t in self.tasks.lock().unwrap_or_else(|p| p.into_inner()).iter() {
            t.abort();
        }
    }
}

#[derive(Clone, Copy)]
enum Request {
    SendGoal,
    GetResult,
    Cancel,
}

async fn serve_requests(
    bridge: Arc<Bridge>,
    action: Arc<OfferedAction>,
    kind: Request,
    reader: RawReader,
) {
    let mut samples = reader.async_sample_stream();
    while let Some(r) = samples.next().await {
        let Ok(sample) = r else { continue };
        if bridge.is_own(sample.sample_info().writer_guid()) {
            continue;
        }
        let info = sample.sample_info().clone();
        let Some((header, msg)) = ReplyTo::of_request(&info, sample.into_value().0) else {
            continue;
        };
        let outcome = match kind {
            Request::SendGoal => send_goal(&bridge, &action, header, &msg),
            Request::GetResult => get_result(&action, header, &msg),
            Request::Cancel => cancel_goal(&bridge, &action, header, &msg),
        };
        if let Err(e) = outcome {
            tracing::warn!(
                "ros2: a local client's request to {} failed: {e}",
                action.name
            );
        }
    }
}

fn send_goal(
    bridge: &Arc<Bridge>,
    action: &Arc<OfferedAction>,
    header: ReplyTo,
    msg: &Bytes,
) -> Result<(), String> {
    let uuid = uuid_at(msg).ok_or("a send_goal request without a goal id")?;
    // The goal follows the 16-byte UUID, so it keeps its alignment as a message of its own.
    let mut goal = Vec::with_capacity(msg.len() - 16);
    goal.extend_from_slice(&CDR_LE_HEADER);
    goal.extend_from_slice(&msg[20..]);
    let stamp = now_stamp();
    let opts = CallOptions {
        timeout: None,
        goal: true,
        goal_id: Some(uuid),
        on_behalf_of: None,
    };
    let name = TopicName::parse(&action.name).map_err(|e| e.to_string())?;
    let accepted = match bridge.router.calls.call(
        bridge.client,
        &name,
        Payload::new(Encoding::Cdr, goal),
        opts,
    ) {
        Ok(call) => {
            action.goals().live.insert(
                uuid,
                Goal {
                    uuid,
                    call,
                    stamp,
                    status: STATUS_EXECUTING,
                    result: None,
                    waiting: Vec::new(),
                },
            );
            bridge.lock().offered_goals.insert(call, action.clone());
            true
        }
        Err(e) => {
            tracing::warn!(
                "ros2: a local goal for {} was refused: {}",
                action.name,
                e.text
            );
            false
        }
    };
    let answer = bridge.cdr_of(
        &format!("{}_SendGoal_Response", action.action_type),
        &json!({"accepted": accepted, "stamp": {"sec": stamp.0, "nanosec": stamp.1}}),
    )?;
    header.reply(&action.writers.send_goal, answer)?;
    publish_status(bridge, action);
    Ok(())
}

fn get_result(action: &OfferedAction, header: ReplyTo, msg: &Bytes) -> Result<(), String> {
    let uuid = uuid_at(msg).ok_or("a get_result request without a goal id")?;
    let ready = {
        let mut g = action.goals();
        if let Some(goal) = g.live.get_mut(&uuid) {
            goal.waiting.push(header);
            return Ok(());
        }
        g.ended
            .iter()
            .find(|e| e.uuid == uuid)
            .and_then(|e| e.result.clone())
    };
    match ready {
        Some(result) => header.reply(&action.writers.get_result, result),
        None => Err(format!(
            "get_result for a goal {} does not know",
            action.name
        )),
    }
}

fn cancel_goal(
    bridge: &Bridge,
    action: &OfferedAction,
    header: ReplyTo,
    msg: &Bytes,
) -> Result<(), String> {
    let uuid = uuid_at(msg).ok_or("a cancel_goal request without a goal id")?;
    let all = uuid == [0u8; 16];
    let cancelling: Vec<([u8; 16], u64, (i32, u32))> = {
        let mut g = action.goals();
        g.live
            .values_mut()
            .filter(|goal| all || goal.uuid == uuid)
            .map(|goal| {
                goal.status = STATUS_CANCELING;
                (goal.uuid, goal.call, goal.stamp)
            })
            .collect()
    };
    for (_, call, _) in &cancelling {
        bridge.router.calls.cancel(bridge.client, *call);
    }
    let return_code = if cancelling.is_empty() { 2 } else { 0 };
    let infos: Vec<Value> = cancelling
        .iter()
        .map(|(u, _, s)| goal_info(u, *s))
        .collect();
    let answer = bridge.cdr_of(
        "action_msgs/srv/CancelGoal_Response",
        &json!({"return_code": return_code, "goals_canceling": infos}),
    )?;
    header.reply(&action.writers.cancel_goal, answer)
}

/// The status of every live and recently ended goal, as `GoalStatusArray`.
fn publish_status(bridge: &Bridge, action: &OfferedAction) {
    let list: Vec<Value> = {
        let g = action.goals();
        g.live
            .values()
            .chain(g.ended.iter())
            .map(|goal| json!({"goal_info": goal_info(&goal.uuid, goal.stamp), "status": goal.status}))
            .collect()
    };
    match bridge.cdr_of(
        "action_msgs/msg/GoalStatusArray",
        &json!({"status_list": list}),
    ) {
        Ok(body) => {
            if let Err(e) = action.writers.status.write(RawCdr(body), None) {
                tracing::debug!("ros2: status of {}: {e:?}", action.name);
            }
        }
        Err(e) => tracing::debug!("ros2: status of {}: {e}", action.name),
    }
}

/// Feedback or the end of a local client's goal, from the call table.
pub(crate) fn on_event(bridge: &Bridge, action: &OfferedAction, ev: CallEvent) {
    match ev {
        CallEvent::Feedback { id, payload } => {
            let uuid = action
                .goals()
                .live
                .values()
                .find(|g| g.call == id)
                .map(|g| g.uuid);
            let Some(uuid) = uuid else { return };
            let body = match bridge.to_cdr(&format!("{}_Feedback", action.action_type), &payload) {
                Ok(b) => b,
                Err(e) => {
                    tracing::debug!("ros2: feedback of {}: {e}", action.name);
                    return;
                }
            };
            let mut fb = Vec::with_capacity(body.len() + 16);
            fb.extend_from_slice(&CDR_LE_HEADER);
            fb.extend_from_slice(&uuid);
            fb.extend_from_slice(body.get(4..).unwrap_or_default());
            if let Err(e) = action.writers.feedback.write(RawCdr(Bytes::from(fb)), None) {
                tracing::debug!("ros2: feedback of {}: {e:?}", action.name);
            }
        }
        CallEvent::Done {
            id,
            status,
            payload,
            text,
        } => {
            bridge.lock().offered_goals.remove(&id);
            let code = match status {
                CallStatus::Ok => STATUS_SUCCEEDED,
                CallStatus::Cancelled => STATUS_CANCELED,
                _ => STATUS_ABORTED,
            };
            if code == STATUS_ABORTED {
                tracing::info!(
                    "ros2: a local client's goal for {} ended {status:?}: {text}",
                    action.name
                );
            }
            let result_type = format!("{}_Result", action.action_type);
            let result = payload
                .and_then(|p| bridge.json_of(&result_type, &p).ok())
                .unwrap_or_else(|| json!({}));
            let answer = bridge
                .cdr_of(
                    &format!("{}_GetResult_Response", action.action_type),
                    &json!({"status": code, "result": result}),
                )
                .or_else(|_| {
                    // A result the registry cannot write (missing fields): the status alone.
                    let empty = bridge
                        .cdr_of(&result_type, &json!({}))
                        .ok()
                        .and_then(|b| {
                            bridge
                                .json_of(&result_type, &Payload::new(Encoding::Cdr, b))
                                .ok()
                        })
                        .unwrap_or_else(|| json!({}));
                    bridge.cdr_of(
                        &format!("{}_GetResult_Response", action.action_type),
                        &json!({"status": code, "result": empty}),
                    )
                });
            let waiting = {
                let mut g = action.goals();
                let Some(uuid) = g
                    .live
                    .values()
                    .find(|goal| goal.call == id)
                    .map(|goal| goal.uuid)
                else {
                    return;
                };
                let mut goal = g.live.remove(&uuid).expect("found above");
                goal.status = code;
                goal.result = answer.as_ref().ok().cloned();
                let waiting = std::mem::take(&mut goal.waiting);
                g.ended.push_back(goal);
                while g.ended.len() > KEEP_ENDED {
                    g.ended.pop_front();
                }
                waiting
            };
            match answer {
                Ok(result) => {
                    for h in waiting {
                        if let Err(e) = h.reply(&action.writers.get_result, result.clone()) {
                            tracing::debug!("ros2: result of {}: {e}", action.name);
                        }
                    }
                }
                Err(e) => tracing::warn!(
                    "ros2: the result of a goal for {} cannot be written: {e}",
                    action.name
                ),
            }
            publish_status(bridge, action);
        }
    }
}
