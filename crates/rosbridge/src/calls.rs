//! Services and actions on a rosbridge session: the client as caller (`call_service`,
//! `send_action_goal`, `cancel_action_goal`) and as provider (`advertise_service`,
//! `advertise_action`, answering with `service_response`, `action_feedback`,
//! `action_result`), both through the router's call table.
//!
//! Ids: a caller's own `id` is echoed in its answers; calls this client serves carry ids
//! the session makes (`call:<n>` / `goal:<n>`, unique on the session), so two callers
//! using the same id never collide at the provider.
//!
//! Layout: this file holds the session's call tables and the helpers both sides use;
//! `shared` the session's methods both sides use (bodies completed against their types,
//! answers framed and sent, the call table's messages dispatched); `caller` the calls
//! and goals this client makes,
//! `provider` the services and actions it offers and the answers it gives, and
//! `robot_params` the parameter calls the hub forwards to robots' agents.

mod caller;
mod provider;
mod robot_params;
mod shared;

use std::collections::{HashMap, HashSet};
use std::time::Duration;

use bytes::Bytes;
use fleetlink_proto::{Encoding, Payload};
use fleetlink_relay::calls::{CallId, CallStatus};
use fleetlink_relay::names::TopicName;
use serde_json::Value;

/// How a caller wants its answers.
#[derive(Debug, Clone, Copy, Default)]
pub struct Answering {
    /// Split a JSON answer into rosbridge fragments of at most this many characters.
    pub fragment_size: Option<u32>,
    /// Answer in a CBOR binary frame (the caller asked for `cbor` or spoke CBOR).
    pub cbor: bool,
}

struct Made {
    id: Option<Value>,
    /// The name as the client wrote it, echoed in answers.
    name: String,
    type_name: String,
    goal: bool,
    feedback: bool,
    how: Answering,
    size: usize,
    /// A parameter call forwarded to this robot's agent: its answer names the robot.
    robot: Option<String>,
    /// Part of a `get_param_names` listing (the key of its [`Gathering`]).
    gather: Option<u64>,
}

impl Made {
    /// A `call_service` of `name` (as the client wrote it).
    fn service_call(name: &str, id: Option<&Value>, how: Answering, size: usize) -> Made {
        Made {
            id: id.cloned(),
            name: name.to_owned(),
            type_name: String::new(),
            goal: false,
            feedback: false,
            how,
            size,
            robot: None,
            gather: None,
        }
    }
}

/// A `get_param_names` waiting for the lists of the robots that provide parameters.
struct Gathering {
    id: Option<Value>,
    how: Answering,
    /// Names so far: the hub's own, then each robot's as it answers.
    names: Vec<String>,
    /// Robots that have not answered yet.
    pending: usize,
}

struct Serving {
    call: CallId,
    name: TopicName,
    goal: bool,
}

/// One session's calls.
#[derive(Default)]
pub struct SessionCalls {
    /// The client speaks CBOR binary frames: calls it serves are sent as CBOR.
    pub binary: bool,
    made: HashMap<CallId, Made>,
    /// Pending goals by the id their caller gave them.
    goals: HashMap<String, CallId>,
    serving: HashMap<String, Serving>,
    serving_by_call: HashMap<CallId, String>,
    provided: HashSet<(TopicName, bool)>,
    gathering: HashMap<u64, Gathering>,
    next_gathering: u64,
}

/// `action_msgs/GoalStatus` codes.
const GOAL_SUCCEEDED: u32 = 4;
const GOAL_CANCELED: u32 = 5;
const GOAL_ABORTED: u32 = 6;

fn goal_status(status: CallStatus) -> u32 {
    match status {
        CallStatus::Ok => GOAL_SUCCEEDED,
        CallStatus::Cancelled => GOAL_CANCELED,
        _ => GOAL_ABORTED,
    }
}

fn id_key(id: &Value) -> String {
    match id {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// Seconds from a client into a duration (0 = no deadline of its own).
fn timeout_of(secs: Option<f64>) -> Option<Duration> {
    secs.filter(|s| *s > 0.0)
        .map(|s| Duration::from_secs_f64(s.min(1e9)))
}

/// The part of a service or action type a payload is: `pkg/srv/T` + `_Request`.
fn part(type_name: &str, suffix: &str) -> String {
    format!("{type_name}{suffix}")
}

fn empty_map(cbor: bool) -> Bytes {
    if cbor {
        Bytes::from_static(&[0xa0])
    } else {
        Bytes::from_static(b"{}")
    }
}

/// An object (JSON object or CBOR map), as `args` and `values` must be.
fn is_map(p: &Payload) -> bool {
    match p.encoding {
        Encoding::Json => p.bytes.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'{'),
        Encoding::Cbor => p.bytes.first().is_some_and(|b| b >> 5 == 5),
        _ => true,
    }
}
