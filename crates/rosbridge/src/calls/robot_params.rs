//! Parameters of robots, reached through the hub: a rosapi parameter call for a name in
//! a robot's namespace is forwarded to that robot's agent, a `get_param_names` listing
//! gathers every robot's names, and a robot's parameter service called directly is held
//! to the same ACL.

use std::time::Duration;

use fleetlink_proto::rosbridge::outbound;
use fleetlink_proto::{Encoding, Payload};
use fleetlink_relay::calls::{CallOptions, CallStatus};
use fleetlink_relay::gate::Op as GateOp;
use fleetlink_relay::names::TopicName;
use serde_json::{Value, json};

use super::{Answering, Gathering, Made, timeout_of};
use crate::session::Session;

/// How long a listing of parameter names waits for a robot's own list.
const ROBOT_NAMES_WAIT: Duration = Duration::from_secs(5);

/// The parameter services a robot's agent may answer for names in its namespace.
/// (`get_param_names` has no name to route by: the hub asks every robot that provides
/// parameters, see [`Session::gather_param_names`].)
const FORWARDED_PARAMS: [&str; 5] = [
    "get_param",
    "set_param",
    "has_param",
    "delete_param",
    "search_param",
];

impl Session {
    /// A rosapi parameter call for a name in a robot's namespace (`/robot1/max_speed`),
    /// when that robot's agent provides parameters (`/robot1/rosapi/get_param` is in the
    /// call table): forwarded there with the name relative to the robot (`/max_speed`),
    /// answered when the robot answers. The ACL applies to the full name as for the hub's
    /// own parameters (reading needs `subscribe`, changing `publish`). `None`: not such a
    /// call, the hub answers it from its own store.
    pub(crate) fn forward_param(
        &mut self,
        service: &str,
        args: &Value,
        id: Option<&Value>,
        how: Answering,
    ) -> Option<Result<(), String>> {
        let call = service.strip_prefix("/rosapi/")?;
        if !FORWARDED_PARAMS.contains(&call) {
            return None;
        }
        let name = fleetlink_relay::params::param_name(args.get("name")?.as_str()?).ok()?;
        let (robot, rest) = match name[1..].find('/') {
            Some(i) => (&name[1..=i], &name[i + 1..]),
            None => (&name[1..], "/"),
        };
        let provider = TopicName::parse(&format!("/{robot}/rosapi/{call}")).ok()?;
        self.router.calls.service(&provider)?;
        let op = if matches!(call, "set_param" | "delete_param") {
            GateOp::Publish
        } else {
            GateOp::Subscribe
        };
        let gate = self.gate.as_mut()?;
        if !gate.allows(&name, op) {
            let verb = if op == GateOp::Publish {
                "change"
            } else {
                "read"
            };
            return Some(Err(format!("not allowed to {verb} parameter {name}")));
        }
        let mut forwarded = args.clone();
        forwarded["name"] = json!(rest);
        let body = serde_json::to_vec(&forwarded).expect("JSON");
        let size = body.len();
        if op == GateOp::Publish {
            // Audited like a change of the hub's own parameters.
            gate.finished(
                &name,
                GateOp::Publish,
                size,
                &format!("{call} on robot {robot}"),
            );
        }
        let made = Made {
            robot: Some(robot.to_owned()),
            ..Made::service_call(service, id, how, size)
        };
        let opts = CallOptions {
            timeout: timeout_of(None),
            goal: false,
            goal_id: None,
            on_behalf_of: None, // filled by `start`
        };
        Some(
            self.start(&provider, Payload::json(body), opts, made)
                .map(|_| ())
                .map_err(|e| format!("{service} of {name}: robot {robot}: {}", e.text)),
        )
    }

    /// `get_param_names` when robots provide parameters: `own` (the hub's names, already
    /// held to the ACL) and, as each robot answers, the robot's names in its namespace
    /// (`/robot1/max_speed`) under the same ACL. Answered once every robot has answered or
    /// [`ROBOT_NAMES_WAIT`] has passed; a robot that fails is left out of the list.
    /// `false`: no robot provides parameters (the caller answers with `own`).
    pub(crate) fn gather_param_names(
        &mut self,
        own: Vec<String>,
        id: Option<&Value>,
        how: Answering,
    ) -> bool {
        let providers: Vec<(String, TopicName)> = self
            .router
            .calls
            .services()
            .iter()
            .filter_map(|s| {
                let robot = s
                    .name
                    .as_str()
                    .strip_prefix('/')?
                    .strip_suffix("/rosapi/get_param_names")?;
                (!robot.contains('/')).then(|| (robot.to_owned(), s.name.clone()))
            })
            .collect();
        if providers.is_empty() {
            return false;
        }
        let key = self.calls.next_gathering;
        self.calls.next_gathering += 1;
        let mut pending = 0;
        for (robot, provider) in providers {
            let made = Made {
                robot: Some(robot.clone()),
                gather: Some(key),
                ..Made::service_call("/rosapi/get_param_names", id, how, 2)
            };
            let opts = CallOptions {
                timeout: Some(ROBOT_NAMES_WAIT),
                goal: false,
                goal_id: None,
                on_behalf_of: None, // filled by `start`
            };
            match self.start(&provider, Payload::json(&b"{}"[..]), opts, made) {
                Ok(_) => pending += 1,
                Err(e) => tracing::debug!("parameter names of robot {robot}: {}", e.text),
            }
        }
        if pending == 0 {
            return false;
        }
        let gathering = Gathering {
            id: id.cloned(),
            how,
            names: own,
            pending,
        };
        self.calls.gathering.insert(key, gathering);
        true
    }

    /// One robot's answer to a `get_param_names` listing; the last one sends the list.
    pub(super) async fn gathered(
        &mut self,
        key: u64,
        m: Made,
        status: CallStatus,
        payload: Option<Payload>,
        text: String,
    ) {
        let robot = m.robot.unwrap_or_default();
        let names = payload
            .filter(|_| status == CallStatus::Ok)
            .and_then(|p| serde_json::from_slice::<Value>(&p.bytes).ok())
            .and_then(|v| match v.get("names") {
                Some(Value::Array(a)) => Some(a.clone()),
                _ => None,
            });
        let Some(g) = self.calls.gathering.get_mut(&key) else {
            return;
        };
        g.pending -= 1;
        match names {
            Some(names) => {
                for n in names.iter().filter_map(Value::as_str) {
                    let full = match n {
                        "/" => format!("/{robot}"),
                        n if n.starts_with('/') => format!("/{robot}{n}"),
                        n => format!("/{robot}/{n}"),
                    };
                    g.names.push(full);
                }
            }
            None => tracing::info!(
                "parameter names of robot {robot} left out of a listing: {}",
                if text.is_empty() {
                    status.as_str().replace('_', " ")
                } else {
                    text
                }
            ),
        }
        if g.pending > 0 {
            return;
        }
        let g = self.calls.gathering.remove(&key).expect("present");
        let mut names = g.names;
        if let Some(gate) = self.gate.as_mut() {
            names.retain(|n| gate.allows(n, GateOp::Subscribe));
        }
        names.sort_unstable();
        names.dedup();
        let reply = outbound::service_response(
            "/rosapi/get_param_names",
            g.id.as_ref(),
            json!({ "names": names }),
            true,
        );
        self.send_value(&reply, g.how.cbor).await;
    }

    /// A robot's parameter service called by its own name (`/robot1/rosapi/set_param`
    /// with `/max_speed`) is held to the ACL the hub's forwarding applies: the parameter's
    /// full name (`/robot1/max_speed`), `subscribe` to read, `publish` to change. The
    /// refusal text, or `None` when the call may go on (or is not such a call).
    pub(super) fn direct_param_refusal(&mut self, service: &str, args: &Payload) -> Option<String> {
        let (robot, call) = service.strip_prefix('/')?.split_once("/rosapi/")?;
        if robot.contains('/') || !FORWARDED_PARAMS.contains(&call) {
            return None;
        }
        let args = fleetlink_relay::params::call_args(args)?;
        let raw = args.get("name").and_then(Value::as_str).unwrap_or_default();
        // An invalid name is the provider's to refuse.
        let full = match fleetlink_relay::params::param_name_or_root(raw)
            .ok()?
            .as_str()
        {
            "/" => format!("/{robot}"),
            rel => format!("/{robot}{rel}"),
        };
        let op = if matches!(call, "set_param" | "delete_param") {
            GateOp::Publish
        } else {
            GateOp::Subscribe
        };
        let gate = self.gate.as_mut()?;
        if gate.allows(&full, op) {
            return None;
        }
        let verb = if op == GateOp::Publish {
            "change"
        } else {
            "read"
        };
        Some(format!("not allowed to {verb} parameter {full}"))
    }
}

/// A robot's answer to a forwarded parameter call, in the hub's names: a found name
/// (`search_param`) gets the robot's namespace back, an error says which robot.
pub(super) fn from_robot(
    robot: &str,
    payload: Option<Payload>,
    text: String,
) -> (Option<Payload>, String) {
    let text = if text.is_empty() {
        text
    } else {
        format!("robot {robot}: {text}")
    };
    let payload = payload.map(|p| {
        let json = match p.encoding {
            Encoding::Json => serde_json::from_slice::<Value>(&p.bytes).ok(),
            _ => None,
        };
        match json {
            Some(mut v) => {
                if let Some(found) = v.get("global_name").and_then(Value::as_str)
                    && !found.is_empty()
                {
                    let full = if found == "/" {
                        format!("/{robot}")
                    } else {
                        format!("/{robot}{found}")
                    };
                    v["global_name"] = json!(full);
                    return Payload::json(serde_json::to_vec(&v).expect("JSON"));
                }
                p
            }
            None => p,
        }
    });
    (payload, text)
}
