//! Services and parameters on a Foxglove session, through the same paths as rosbridge
//! clients: calls go through the router's call table to whoever provides the service (a
//! robot, over its link), parameters are read as `/rosapi/get_param` reads them.
//!
//! A parameter in a robot's namespace (`/robot1/max_speed`) is read from that robot when
//! its agent provides parameters (`/robot1/rosapi/get_param` is in the call table, as a
//! ROS 1 or ROS 2 robot's does): the same forwarding a rosbridge client's
//! `/rosapi/get_param` gets, answered once every robot asked has answered.
//!
//! The client hears of every service it may call (the gate's `call_service` right) as
//! the call table's watch reports them; actions are not offered (the protocol has no
//! goals). A call's request may come as `json`, `cdr` or `ros1`; it goes to the provider
//! as JSON, the form every provider takes, and the answer comes back in the request's
//! encoding.

use std::collections::HashMap;
use std::sync::Arc;

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::calls::{
    CallEvent, CallId, CallOptions, CallStatus, ServiceChange, ServiceInfo,
};
use fleetlink_relay::gate::Op as GateOp;
use fleetlink_relay::link_calls::outcome_text;
use fleetlink_relay::rosapi::{self, Answer};
use fleetlink_relay::{Router, TopicName};
use serde_json::{Value, json};

use crate::channels::{self, CLIENT_ENCODINGS};
use crate::client::Client;
use crate::protocol::{self, ServiceCall, ServicePart};

/// The services advertised to the client and the calls it has in flight.
#[derive(Default)]
pub(crate) struct SessionServices {
    by_name: HashMap<TopicName, u32>,
    by_id: HashMap<u32, Arc<ServiceInfo>>,
    next_id: u32,
    calls: HashMap<CallId, Made>,
    /// `getParameters` waiting for robots, by a key of this session's.
    gatherings: HashMap<u64, Gathering>,
    next_gathering: u64,
    /// Robot parameter reads in flight: their gathering and the parameter's full name.
    param_calls: HashMap<CallId, (u64, String)>,
}

/// A `getParameters` answered once the robots asked have answered.
struct Gathering {
    id: Option<String>,
    values: Vec<(String, Value)>,
    /// Reads that failed, for the `status` that goes with the answer.
    failed: Vec<String>,
    waiting: usize,
}

/// A call this client made.
struct Made {
    service: u32,
    /// The client's own call id, echoed in the answer.
    call: u32,
    encoding: Encoding,
    name: TopicName,
    type_name: String,
    size: usize,
}

/// The definition of one part (`_Request`, `_Response`) of a service type, for the
/// client to encode requests and decode answers with.
fn part(router: &fleetlink_relay::Router, type_name: &str, suffix: &str) -> ServicePart {
    let name = format!("{type_name}{suffix}");
    // A known part may have an empty definition (`std_srvs/srv/Trigger_Request` has no
    // fields): it is still CDR the client can write.
    match router.transcoder().schema_for(&name) {
        Some(s) => ServicePart {
            encoding: "cdr",
            schema_name: name,
            schema_encoding: "ros2msg",
            schema: s.text,
        },
        _ => ServicePart {
            encoding: "json",
            schema_name: name,
            schema_encoding: "jsonschema",
            schema: String::new(),
        },
    }
}

fn schema_of(router: &fleetlink_relay::Router, name: &str) -> Schema {
    router
        .transcoder()
        .schema_for(name)
        .unwrap_or_else(|| Schema::named(name))
}

/// From now on the call table tells the session of services coming and going (the
/// ones there are come at once).
pub(crate) fn watch_services(client: &Client) {
    let all = regex::Regex::new(".*").expect("a valid pattern");
    client.router.calls.watch(client.id, all);
}

impl SessionServices {
    pub(crate) async fn service_changed(&mut self, client: &mut Client, change: ServiceChange) {
        match change {
            ServiceChange::Added(info) => {
                if info.action {
                    return;
                }
                let visible = client
                    .gate
                    .as_mut()
                    .is_some_and(|g| g.allows(info.name.as_str(), GateOp::CallService));
                // A provider that comes again replaces the advertisement.
                let old = self.by_name.remove(&info.name);
                if let Some(id) = old {
                    self.by_id.remove(&id);
                    client
                        .send_text(protocol::unadvertise_services(&[id]))
                        .await;
                }
                if !visible {
                    return;
                }
                self.next_id += 1;
                let id = self.next_id;
                let ty = info.schema.type_name.clone();
                let request = part(&client.router, &ty, "_Request");
                let response = part(&client.router, &ty, "_Response");
                let service = protocol::Service {
                    id,
                    name: info.name.to_string(),
                    type_name: ty,
                    request_schema: request.schema.clone(),
                    response_schema: response.schema.clone(),
                    request,
                    response,
                };
                self.by_name.insert(info.name.clone(), id);
                self.by_id.insert(id, info);
                client
                    .send_text(protocol::advertise_services(&[service]))
                    .await;
            }
            ServiceChange::Removed(info) => {
                if let Some(id) = self.by_name.remove(&info.name) {
                    self.by_id.remove(&id);
                    client
                        .send_text(protocol::unadvertise_services(&[id]))
                        .await;
                }
            }
        }
    }

    /// A `ServiceCallRequest`: checked as a rosbridge `call_service` is (the gate's call
    /// right), its request made JSON and completed against the type, then started in
    /// the call table. Whatever stops it is a `serviceCallFailure`.
    pub(crate) async fn call_service(&mut self, client: &mut Client, c: ServiceCall) {
        if let Err(e) = self.start_call(client, &c) {
            let text = protocol::service_call_failure(c.service, c.call, &e);
            client.send_text(text).await;
        }
    }

    fn start_call(&mut self, client: &mut Client, c: &ServiceCall) -> Result<(), String> {
        let Some(info) = self.by_id.get(&c.service).cloned() else {
            return Err(format!("unknown service id {}", c.service));
        };
        let name = info.name.clone();
        let Some(encoding) = channels::from_wire_name(&c.encoding) else {
            return Err(format!(
                "call {name}: encoding '{}' is not supported (use one of {})",
                c.encoding.chars().take(32).collect::<String>(),
                CLIENT_ENCODINGS.join(", ")
            ));
        };
        client.check("call", name.as_str(), GateOp::CallService)?;
        let type_name = info.schema.type_name.clone();
        let tc = client.router.transcoder();
        let req_schema = schema_of(&client.router, &format!("{type_name}_Request"));
        let request = Payload::new(encoding, c.payload.clone());
        let json = if encoding == Encoding::Json {
            request
        } else {
            let b = tc
                .convert(&req_schema, &request, Encoding::Json)
                .map_err(|e| format!("call {name}: the request cannot be read: {e}"))?;
            Payload::json(b)
        };
        let json = match tc.normalize(&req_schema, &json) {
            Ok(Some(done)) => done,
            Ok(None) => json,
            Err(e) => {
                return Err(format!(
                    "call {name}: the request does not fit {}: {}",
                    req_schema.type_name,
                    e.cause_text()
                ));
            }
        };
        let size = json.len();
        let opts = CallOptions {
            on_behalf_of: client
                .gate
                .as_ref()
                .and_then(|g| g.caller())
                .map(std::sync::Arc::new),
            ..CallOptions::default()
        };
        match client.router.calls.call(client.id, &name, json, opts) {
            Ok(id) => {
                self.calls.insert(
                    id,
                    Made {
                        service: c.service,
                        call: c.call,
                        encoding,
                        name,
                        type_name,
                        size,
                    },
                );
                Ok(())
            }
            Err(e) => {
                if let Some(g) = client.gate.as_mut() {
                    g.finished(
                        name.as_str(),
                        GateOp::CallService,
                        size,
                        &outcome_text(e.status, &e.text),
                    );
                }
                Err(format!("call {name}: {}", e.text))
            }
        }
    }

    /// The end of a call this client made: the response in the request's encoding, or
    /// a failure saying why.
    pub(crate) async fn call_event(&mut self, client: &mut Client, ev: CallEvent) {
        let CallEvent::Done {
            id,
            status,
            payload,
            text,
        } = ev
        else {
            return;
        };
        if let Some((key, name)) = self.param_calls.remove(&id) {
            let read = match (status, payload) {
                (CallStatus::Ok, Some(p)) => robot_param_value(&p)
                    .ok_or_else(|| format!("{name}: the robot's answer has no value")),
                (status, _) => Err(format!("{name}: {}", outcome_text(status, &text))),
            };
            return self.param_read(client, key, name, read).await;
        }
        let Some(m) = self.calls.remove(&id) else {
            return;
        };
        if let Some(g) = client.gate.as_mut() {
            g.finished(
                m.name.as_str(),
                GateOp::CallService,
                m.size,
                &outcome_text(status, &text),
            );
        }
        let answer = match (status, payload) {
            (CallStatus::Ok, Some(p)) => {
                let schema = schema_of(&client.router, &format!("{}_Response", m.type_name));
                client
                    .router
                    .transcoder()
                    .convert(&schema, &p, m.encoding)
                    .map_err(|e| {
                        format!(
                            "the response cannot be given as {}: {e}",
                            channels::wire_name(m.encoding)
                        )
                    })
            }
            (CallStatus::Ok, None) => Err("the provider answered without a response".into()),
            (status, Some(p)) if text.is_empty() => Err(format!(
                "{}: {}",
                status.as_str(),
                String::from_utf8_lossy(&p.bytes)
            )),
            (status, _) => Err(outcome_text(status, &text)),
        };
        match answer {
            Ok(bytes) => {
                let wire = channels::wire_name(m.encoding);
                let frame = protocol::service_call_response(m.service, m.call, wire, &bytes);
                client.send_binary(frame).await;
            }
            Err(e) => {
                let text = format!("call {}: {e}", m.name);
                client
                    .send_text(protocol::service_call_failure(m.service, m.call, &text))
                    .await;
            }
        }
    }

    /// `getParameters`: each name read as `/rosapi/get_param` reads it — from the robot
    /// whose namespace it is in when that robot provides parameters, otherwise from the
    /// hub's parameter store — under the gate's read right per name; no names: every hub
    /// parameter the client may read. Names the client may not read, or that are not set,
    /// are left out, as the protocol has no per-parameter error; a `status` names the
    /// refused and failed ones.
    pub(crate) async fn get_parameters(
        &mut self,
        client: &mut Client,
        names: Vec<String>,
        id: Option<String>,
    ) {
        if client.gate.is_none() {
            return client.error("getParameters: not authenticated").await;
        }
        let names = if names.is_empty() {
            match hub_rosapi(client, "/rosapi/get_param_names", json!({})) {
                Answer::Values(v) => v["names"]
                    .as_array()
                    .map(|a| {
                        a.iter()
                            .filter_map(|n| n.as_str().map(str::to_owned))
                            .collect()
                    })
                    .unwrap_or_default(),
                _ => Vec::new(),
            }
        } else {
            names
        };
        let mut g = Gathering {
            id,
            values: Vec::new(),
            failed: Vec::new(),
            waiting: 0,
        };
        let mut at_robots = Vec::new();
        for raw in names {
            // Decided, read and answered under one spelling: the normalized name.
            let name = match fleetlink_relay::params::param_name(&raw) {
                Ok(n) => n,
                Err(e) => {
                    g.failed.push(e);
                    continue;
                }
            };
            if let Some((provider, rest)) = robot_param(&client.router, &name) {
                at_robots.push((name, provider, rest));
                continue;
            }
            match hub_rosapi(client, "/rosapi/has_param", json!({ "name": name })) {
                Answer::Values(v) if v["exists"] == json!(true) => {}
                Answer::Failed(e) => {
                    g.failed.push(e);
                    continue;
                }
                _ => continue,
            }
            if let Answer::Values(v) =
                hub_rosapi(client, "/rosapi/get_param", json!({ "name": name }))
                && let Some(value) = param_value(&v)
            {
                g.values.push((name, value));
            }
        }
        let key = self.next_gathering;
        self.next_gathering += 1;
        for (name, provider, rest) in at_robots {
            let gate = client.gate.as_mut().expect("checked above");
            if !gate.allows(&name, GateOp::Subscribe) {
                g.failed
                    .push(format!("not allowed to read parameter {name}"));
                continue;
            }
            let body = json!({ "name": rest }).to_string();
            let opts = CallOptions {
                on_behalf_of: gate.caller().map(std::sync::Arc::new),
                ..CallOptions::default()
            };
            match client
                .router
                .calls
                .call(client.id, &provider, Payload::json(body), opts)
            {
                Ok(call) => {
                    self.param_calls.insert(call, (key, name));
                    g.waiting += 1;
                }
                Err(e) => g.failed.push(format!("{name}: {}", e.text)),
            }
        }
        if g.waiting == 0 {
            return answer_parameters(client, g).await;
        }
        self.gatherings.insert(key, g);
    }

    /// One robot's answer to a parameter read of gathering `key`.
    async fn param_read(
        &mut self,
        client: &Client,
        key: u64,
        name: String,
        read: Result<Value, String>,
    ) {
        let Some(g) = self.gatherings.get_mut(&key) else {
            return;
        };
        match read {
            Ok(v) => g.values.push((name, v)),
            Err(e) => g.failed.push(e),
        }
        g.waiting -= 1;
        if g.waiting == 0 {
            let g = self.gatherings.remove(&key).expect("present");
            answer_parameters(client, g).await;
        }
    }
}

/// One of the hub's own `/rosapi` services, under this client's gate (reads only:
/// nothing is changed, so nothing is audited).
fn hub_rosapi(client: &mut Client, service: &str, args: Value) -> Answer {
    let Some(gate) = client.gate.as_mut() else {
        return Answer::Failed("not authenticated".into());
    };
    let mut visible = |n: &str, op| gate.allows(n, op);
    let mut changed = |_: &str, _: &str, _: usize| {};
    rosapi::answer(
        &client.router,
        "/fleetlink",
        service,
        &args,
        &mut visible,
        &mut changed,
    )
}

/// The robot that answers for parameter `name` (normalized: [`param_name`]) — its
/// `rosapi/get_param` service and the name as the robot sees it — when there is one.
///
/// [`param_name`]: fleetlink_relay::params::param_name
fn robot_param(router: &Router, name: &str) -> Option<(TopicName, String)> {
    let (robot, rest) = match name[1..].find('/') {
        Some(i) => (&name[1..=i], &name[i + 1..]),
        None => return None,
    };
    let provider = TopicName::parse(&format!("/{robot}/rosapi/get_param")).ok()?;
    router.calls.service(&provider)?;
    Some((provider, rest.to_owned()))
}

async fn answer_parameters(client: &Client, g: Gathering) {
    if !g.failed.is_empty() {
        client
            .error(&format!("getParameters: {}", g.failed.join("; ")))
            .await;
    }
    client
        .send_text(protocol::parameter_values(&g.values, g.id.as_deref()))
        .await;
}

/// A rosapi `get_param` answer's value: JSON text, as rosapi gives it.
fn param_value(answer: &Value) -> Option<Value> {
    let text = answer["value"].as_str()?;
    Some(serde_json::from_str(text).unwrap_or_else(|_| json!(text)))
}

/// The value in a robot's answer to `rosapi/get_param` (JSON or CBOR).
fn robot_param_value(p: &Payload) -> Option<Value> {
    let v = fleetlink_relay::params::call_args(p)?;
    param_value(&v)
}
