//! The operations a client sends, as values: [`Request`] (an operation and its `id`),
//! [`Op`] with one variant per rosbridge operation we read, the delivery [`Compression`] a
//! subscriber asks for, and the [`ParseError`] a frame that is not a valid operation
//! gives.

use bytes::Bytes;
use serde_json::{Map, Value};

use crate::payload::Payload;

/// A parsed client operation with the `id` it carried (echoed verbatim in replies).
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    pub id: Option<Value>,
    pub op: Op,
}

/// How a subscriber wants messages delivered.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Compression {
    #[default]
    None,
    /// The message as CBOR (typed arrays, byte strings) in a binary frame.
    Cbor,
    /// The raw ROS serialization in a CBOR envelope (`secs`, `nsecs`, `bytes`).
    CborRaw,
    /// rosbridge's PNG packing; not supported, served as `none` with a warning.
    Png,
}

impl Compression {
    pub(super) fn parse(s: &str) -> Option<Compression> {
        Some(match s {
            "none" | "" => Compression::None,
            "cbor" => Compression::Cbor,
            "cbor-raw" => Compression::CborRaw,
            "png" => Compression::Png,
            _ => return None,
        })
    }
}

#[derive(Debug, Clone, PartialEq)]
pub enum Op {
    Advertise {
        topic: String,
        type_name: String,
        latch: bool,
        queue_size: u32,
    },
    Unadvertise {
        topic: String,
    },
    Publish {
        topic: String,
        msg: Payload,
    },
    Subscribe {
        topic: String,
        type_name: Option<String>,
        throttle_rate: u32,
        queue_length: u32,
        fragment_size: Option<u32>,
        compression: Compression,
        /// fleetlink extension: `topic` is a regular expression matched against whole
        /// topic names (field `"regex": true`).
        regex: bool,
        /// fleetlink extension: the subscription's QoS (`priority`, `rate_limit_hz`,
        /// `policy`, `queue`, `no_drop`), an object checked by the server.
        qos: Option<Value>,
    },
    Unsubscribe {
        topic: String,
    },
    /// fleetlink extension: one message of a pull topic, delivered through the caller's
    /// subscription to it.
    Pull {
        topic: String,
    },
    CallService {
        service: String,
        type_name: Option<String>,
        args: Payload,
        /// Seconds the caller waits for the answer (`None`: the server's default).
        timeout: Option<f64>,
        /// Answer in fragments of at most this many characters.
        fragment_size: Option<u32>,
        /// `cbor` answers in a binary frame; anything else as JSON text.
        compression: Compression,
    },
    /// The client provides `service`: calls to it come to this client as `call_service`
    /// operations, answered with `service_response`.
    AdvertiseService {
        service: String,
        type_name: String,
    },
    UnadvertiseService {
        service: String,
    },
    /// A provider's answer to a `call_service` the server sent it (the request's `id`).
    ServiceResponse {
        service: Option<String>,
        /// The response object, or on failure usually a text saying why.
        values: Option<Payload>,
        /// `None` when the field is missing or `null` (roslibjs leaves it out, roslibpy
        /// sends `null`, when the provider's callback returns nothing).
        result: Option<bool>,
    },
    AdvertiseAction {
        action: String,
        type_name: String,
    },
    UnadvertiseAction {
        action: String,
    },
    SendActionGoal {
        action: String,
        action_type: Option<String>,
        args: Payload,
        /// Whether the caller wants `action_feedback` operations.
        feedback: bool,
        timeout: Option<f64>,
        compression: Compression,
    },
    /// Cancels the goal the request's `id` names.
    CancelActionGoal {
        action: Option<String>,
    },
    /// An action provider's progress report for the goal the request's `id` names.
    ActionFeedback {
        action: Option<String>,
        values: Payload,
    },
    /// An action provider's final answer for the goal the request's `id` names.
    ActionResult {
        action: Option<String>,
        values: Option<Payload>,
        /// `action_msgs/GoalStatus` code (4 succeeded, 5 canceled, 6 aborted).
        status: Option<u32>,
        result: bool,
    },
    /// rosbridge's authentication operation; fields kept for the auth layer.
    Auth {
        fields: Map<String, Value>,
    },
    /// One piece of a larger operation the client cut with rosbridge's fragmentation;
    /// the request's `id` names the operation the pieces make up.
    Fragment {
        data: String,
        num: u32,
        total: u32,
    },
    /// Which `status` messages the client wants: `none`, `error` (the default),
    /// `warning` or `info`.
    SetLevel {
        level: String,
    },
    /// Valid envelope, operation name we do not serve.
    Unknown {
        op: String,
    },
}

impl Op {
    pub fn name(&self) -> &str {
        match self {
            Op::Advertise { .. } => "advertise",
            Op::Unadvertise { .. } => "unadvertise",
            Op::Publish { .. } => "publish",
            Op::Subscribe { .. } => "subscribe",
            Op::Unsubscribe { .. } => "unsubscribe",
            Op::Pull { .. } => "pull",
            Op::CallService { .. } => "call_service",
            Op::AdvertiseService { .. } => "advertise_service",
            Op::UnadvertiseService { .. } => "unadvertise_service",
            Op::ServiceResponse { .. } => "service_response",
            Op::AdvertiseAction { .. } => "advertise_action",
            Op::UnadvertiseAction { .. } => "unadvertise_action",
            Op::SendActionGoal { .. } => "send_action_goal",
            Op::CancelActionGoal { .. } => "cancel_action_goal",
            Op::ActionFeedback { .. } => "action_feedback",
            Op::ActionResult { .. } => "action_result",
            Op::Fragment { .. } => "fragment",
            Op::SetLevel { .. } => "set_level",
            Op::Auth { .. } => "auth",
            Op::Unknown { op } => op,
        }
    }
}

/// Why a frame could not be turned into a [`Request`]. Carries the `id` and `op` when the
/// envelope got far enough to have them, so the error reply can reference the request.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct ParseError {
    pub id: Option<Value>,
    pub op: Option<String>,
    pub message: String,
}

impl ParseError {
    pub(super) fn new(message: impl Into<String>) -> Self {
        ParseError {
            id: None,
            op: None,
            message: message.into(),
        }
    }
}

/// The `msg` of a publish as a shared slice, for tests and tools.
pub fn payload_bytes(op: &Op) -> Option<&Bytes> {
    match op {
        Op::Publish { msg, .. } => Some(&msg.bytes),
        Op::CallService { args, .. } | Op::SendActionGoal { args, .. } => Some(&args.bytes),
        _ => None,
    }
}
