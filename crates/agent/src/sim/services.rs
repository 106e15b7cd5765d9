//! The simulated robot's services and action, so the demo exercises calls end to end:
//!
//! - `/set_mode` (`std_srvs/srv/SetBool`): `true` = patrol (the figure-eight), `false` =
//!   idle (stop where it is);
//! - `/get_status` (`std_srvs/srv/Trigger`): `message` is a JSON text with the mode and
//!   the pose;
//! - `/navigate_to_pose` (action `fleetlink_sim/action/NavigateTo`): goal `{x, y}` (or a
//!   `nav2_msgs` style `{pose: {pose: {position: {x, y}}}}`), drives there in a straight
//!   line at 0.5 m/s with feedback `{distance_remaining}` five times a second, result
//!   `{x, y, reached}`; cancel stops the robot where it is. A new goal replaces the
//!   running one, which ends cancelled.
//!
//! Requests arrive in whatever encoding their caller used and are read as JSON.

use std::time::Duration;

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::{CallId, CallRequest, CallStatus};
use serde_json::{Value, json};

use super::{Motion, ROOM_HALF, Sim};

/// Speed of a navigation goal, m/s.
pub const NAV_SPEED: f64 = 0.5;
/// Feedback period of a navigation goal.
pub const FEEDBACK_EVERY: Duration = Duration::from_millis(200);
/// Closer than this to the goal counts as there.
const ARRIVED: f64 = 0.02;

/// The services and action the simulator offers, relative to the robot: name, type,
/// definition, whether it is an action.
pub fn offered() -> [(&'static str, Schema, bool); 3] {
    [
        ("/set_mode", Schema::named("std_srvs/srv/SetBool"), false),
        ("/get_status", Schema::named("std_srvs/srv/Trigger"), false),
        (
            "/navigate_to_pose",
            Schema {
                type_name: "fleetlink_sim/action/NavigateTo".into(),
                encoding: "ros2msg".into(),
                text: NAVIGATE_TO.into(),
            },
            true,
        ),
    ]
}

const NAVIGATE_TO: &str = "\
# Drive the simulated robot in a straight line to (x, y) in the odom frame.
float64 x
float64 y
---
float64 x
float64 y
bool reached
---
float64 distance_remaining
";

/// What the driver should do after a request.
#[derive(Debug, PartialEq)]
pub enum Answer {
    /// Answer the call now.
    Reply {
        status: CallStatus,
        values: Option<Value>,
        text: String,
    },
    /// A goal was accepted; it is answered when it ends.
    Accepted,
}

/// The one goal being driven to.
#[derive(Debug)]
pub struct ActiveGoal {
    pub id: CallId,
    pub to: (f64, f64),
}

/// The simulator's call state: the running goal, and the mode set by `/set_mode`.
#[derive(Debug, Default)]
pub struct SimCalls {
    pub goal: Option<ActiveGoal>,
    pub idle: bool,
}

fn as_json(p: &Payload) -> Option<Value> {
    match p.encoding {
        Encoding::Json => serde_json::from_slice(&p.bytes).ok(),
        Encoding::Cbor => {
            let j = fleetlink_proto::rosbridge::convert::cbor_to_json(&p.bytes).ok()?;
            serde_json::from_slice(&j).ok()
        }
        _ => None,
    }
}

fn mode(sim: &Sim, calls: &SimCalls) -> &'static str {
    match sim.motion() {
        Motion::Drive { .. } => "navigating",
        Motion::Patrol => "active",
        Motion::Hold { .. } if calls.idle => "idle",
        Motion::Hold { .. } => "holding",
    }
}

fn failed(text: String) -> Answer {
    Answer::Reply {
        status: CallStatus::Failed,
        values: None,
        text,
    }
}

impl SimCalls {
    /// A call to one of the offered services. `cancelled` collects a goal that a new one
    /// replaced (to be answered `cancelled`).
    pub fn on_call(
        &mut self,
        sim: &mut Sim,
        now: Duration,
        local_name: &str,
        req: &CallRequest,
        replaced: &mut Option<(CallId, Value)>,
    ) -> Answer {
        let Some(args) = as_json(&req.payload) else {
            return failed(format!(
                "{local_name}: the simulator reads requests as JSON or CBOR, not {}",
                req.payload.encoding
            ));
        };
        match local_name {
            "/set_mode" => {
                let Some(on) = args.get("data").and_then(Value::as_bool) else {
                    return failed("/set_mode: request field 'data' (bool) is missing".into());
                };
                self.end_goal(sim, now, replaced);
                if on {
                    sim.patrol();
                } else {
                    sim.hold(now);
                }
                self.idle = !on;
                Answer::Reply {
                    status: CallStatus::Ok,
                    values: Some(json!({
                        "success": true,
                        "message": format!("mode: {}", mode(sim, self)),
                    })),
                    text: String::new(),
                }
            }
            "/get_status" => {
                let (x, y, yaw) = sim.pose_at(now);
                let mut status = json!({
                    "mode": mode(sim, self),
                    "x": round(x), "y": round(y), "yaw": round(yaw),
                });
                if let Some(g) = &self.goal {
                    status["goal"] = json!({"x": g.to.0, "y": g.to.1,
                        "distance_remaining": sim.distance_remaining(now).map(round)});
                }
                Answer::Reply {
                    status: CallStatus::Ok,
                    values: Some(json!({"success": true, "message": status.to_string()})),
                    text: String::new(),
                }
            }
            "/navigate_to_pose" => {
                let pick = |v: &Value, k: &str| {
                    v.get(k)
                        .or_else(|| v.pointer(&format!("/pose/pose/position/{k}")))
                        .and_then(Value::as_f64)
                };
                let (Some(x), Some(y)) = (pick(&args, "x"), pick(&args, "y")) else {
                    return failed(
                        "/navigate_to_pose: the goal needs numbers 'x' and 'y' (or \
                         pose.pose.position.x/y)"
                            .into(),
                    );
                };
                if !(x.abs() <= ROOM_HALF && y.abs() <= ROOM_HALF) {
                    return Answer::Reply {
                        status: CallStatus::Aborted,
                        values: Some(json!({"x": x, "y": y, "reached": false})),
                        text: format!(
                            "goal ({x}, {y}) is outside the room (|x|, |y| <= {ROOM_HALF} m)"
                        ),
                    };
                }
                self.end_goal(sim, now, replaced);
                sim.navigate(now, x, y, NAV_SPEED);
                self.goal = Some(ActiveGoal {
                    id: req.id,
                    to: (x, y),
                });
                self.idle = false;
                Answer::Accepted
            }
            other => failed(format!("the simulator offers no service {other}")),
        }
    }

    /// A running goal, ended because something else took over: stop and report it.
    fn end_goal(&mut self, sim: &mut Sim, now: Duration, replaced: &mut Option<(CallId, Value)>) {
        if let Some(g) = self.goal.take() {
            sim.hold(now);
            let (x, y, _) = sim.pose_at(now);
            *replaced = Some((
                g.id,
                json!({"x": round(x), "y": round(y), "reached": false}),
            ));
        }
    }

    /// The caller of `id` cancelled (or its deadline passed): stop where the robot is.
    /// Returns the result to answer with, if `id` is the running goal.
    pub fn on_cancel(&mut self, sim: &mut Sim, now: Duration, id: CallId) -> Option<Value> {
        if self.goal.as_ref().is_none_or(|g| g.id != id) {
            return None;
        }
        self.goal = None;
        sim.hold(now);
        let (x, y, _) = sim.pose_at(now);
        Some(json!({"x": round(x), "y": round(y), "reached": false}))
    }

    /// Progress of the running goal at `now`: `Ok(feedback)` while driving, `Err(result)`
    /// once arrived (the goal is then over and the robot holds at the goal).
    pub fn progress(
        &mut self,
        sim: &mut Sim,
        now: Duration,
    ) -> Option<(CallId, Result<Value, Value>)> {
        let g = self.goal.as_ref()?;
        let id = g.id;
        let left = sim.distance_remaining(now).unwrap_or(0.0);
        if left > ARRIVED {
            return Some((id, Ok(json!({"distance_remaining": round(left)}))));
        }
        let to = g.to;
        self.goal = None;
        sim.hold(now);
        Some((id, Err(json!({"x": to.0, "y": to.1, "reached": true}))))
    }
}

fn round(v: f64) -> f64 {
    (v * 1000.0).round() / 1000.0
}
