//! The graph's node parameters, offered to the fleet.
//!
//! ROS 2 has no parameter server: each node keeps its own parameters and serves them with
//! `rcl_interfaces` services under its name (`/<node>/get_parameters`, `set_parameters`,
//! `list_parameters`). With `ros2: parameters: true` (the default) the bridge provides
//! rosapi's parameter services in the agent's call table — the same six as the ROS 1
//! bridge ([`params::SERVICES`]) — and answers them by calling those node services, so
//! the hub's `/rosapi/get_param` of `/<robot>/<node>:<parameter>` reads a robot's node
//! parameter (docs/ros2.md, "Parameters").
//!
//! Names are rosapi's for ROS 2: `<node>:<parameter>` (`/camera:fps`,
//! `/nav/planner:tolerance`). Values travel as JSON texts. A value set is sent with the
//! parameter's current type where it fits (`2` to a double parameter is `2.0`; a node
//! refuses to change a parameter's type), else with the type the JSON says.
//!
//! The nodes are found in DDS discovery: every node whose `list_parameters` service has
//! a reader. Each of a node's services gets an endpoint of the bridge when first called,
//! kept while the node is there.

use std::collections::BTreeMap;
use std::sync::Arc;
use std::time::{Duration, Instant};

use base64::Engine as _;
use fleetlink_proto::{Encoding, Payload};
use fleetlink_relay::calls::{CallRequest, CallStatus};
use fleetlink_relay::params;
use serde_json::{Value as Json, json};
use tokio::task::AbortHandle;

use crate::bridge::Bridge;
use crate::names::DdsName;
use crate::services::{Endpoint, Mapping};

/// How long `get_param_names` waits for one node's list (a node that does not answer in
/// time is left out; the hub waits 5 s for a robot's whole list).
const LIST_WAIT: Duration = Duration::from_secs(3);

/// `rcl_interfaces/msg/ParameterType`: the field of `ParameterValue` each type uses.
const VALUE_FIELDS: [&str; 10] = [
    "",
    "bool_value",
    "integer_value",
    "double_value",
    "string_value",
    "byte_array_value",
    "bool_array_value",
    "integer_array_value",
    "double_array_value",
    "string_array_value",
];
const NOT_SET: u8 = 0;
const BOOL: u8 = 1;
const INTEGER: u8 = 2;
const DOUBLE: u8 = 3;
const STRING: u8 = 4;
const BYTE_ARRAY: u8 = 5;
const BOOL_ARRAY: u8 = 6;
const INTEGER_ARRAY: u8 = 7;
const DOUBLE_ARRAY: u8 = 8;
const STRING_ARRAY: u8 = 9;

/// A node's `rcl_interfaces` parameter services the bridge calls.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(crate) enum Srv {
    Get,
    Set,
    List,
}

impl Srv {
    fn type_name(self) -> &'static str {
        match self {
            Srv::Get => "GetParameters",
            Srv::Set => "SetParameters",
            Srv::List => "ListParameters",
        }
    }

    fn service(self) -> &'static str {
        match self {
            Srv::Get => "get_parameters",
            Srv::Set => "set_parameters",
            Srv::List => "list_parameters",
        }
    }
}

/// The bridge's endpoint for one parameter service of one node; its reply reader stops
/// when it is dropped.
pub(crate) struct ParamEndpoint {
    ep: Arc<Endpoint>,
    task: AbortHandle,
}

impl Drop for ParamEndpoint {
    fn drop(&mut self) {
        self.task.abort();
    }
}

/// A node of the graph that serves parameters, as the bridge calls it.
struct Node<'a> {
    bridge: &'a Bridge,
    name: &'a str,
    mapping: Mapping,
}

/// Answers one call of a rosapi parameter service.
pub(crate) async fn serve(bridge: &Arc<Bridge>, req: &CallRequest) {
    let limit = req.deadline.map_or(bridge.opts.call_timeout, |d| {
        d.saturating_duration_since(Instant::now())
    });
    let (status, payload, text) = match tokio::time::timeout(limit, answer(bridge, req)).await {
        Ok(Ok(values)) => (
            CallStatus::Ok,
            Some(Payload::json(serde_json::to_vec(&values).expect("JSON"))),
            String::new(),
        ),
        Ok(Err(text)) => (CallStatus::Failed, None, text),
        Err(_) => (
            CallStatus::Timeout,
            None,
            format!("the robot's ROS 2 nodes did not answer within {limit:?}"),
        ),
    };
    bridge
        .router
        .calls
        .respond(bridge.client, req.id, status, payload, text);
}

async fn answer(bridge: &Arc<Bridge>, req: &CallRequest) -> Result<Json, String> {
    let args = params::call_args(&req.payload)
        .filter(Json::is_object)
        .ok_or("the arguments must be an object (JSON or CBOR)")?;
    let service = req.service.name.as_str();
    let call = service.strip_prefix("/rosapi/").unwrap_or(service);
    let raw_name = args.get("name").and_then(Json::as_str).unwrap_or_default();
    let nodes = nodes(bridge);
    if call == "get_param_names" {
        return Ok(json!({"names": all_names(bridge, &nodes).await}));
    }
    if call == "search_param" && !raw_name.contains(':') {
        // A bare parameter name: the first node (by name) that has it.
        let wanted = raw_name.trim().trim_start_matches('/');
        let found = all_names(bridge, &nodes)
            .await
            .into_iter()
            .find(|n| n.split_once(':').is_some_and(|(_, p)| p == wanted));
        return Ok(json!({"global_name": found.unwrap_or_default()}));
    }
    let (node, param) = split_name(raw_name)?;
    let Some(&mapping) = nodes.get(&node) else {
        return match call {
            "has_param" => Ok(json!({"exists": false})),
            "search_param" => Ok(json!({"global_name": ""})),
            "get_param" if has_default(&args) => Ok(json!({"value": params::default_text(&args)})),
            _ => Err(format!(
                "no node {node} serves parameters in the robot's ROS 2 graph (DDS domain {}); \
                 `get_param_names` lists the nodes' parameters",
                bridge.opts.domain_id
            )),
        };
    };
    let full = format!("{node}:{param}");
    let node = Node {
        bridge,
        name: &node,
        mapping,
    };
    Ok(match call {
        "get_param" => match value_json(&node.get(&param).await?) {
            Some(v) => json!({"value": v.to_string()}),
            None => json!({"value": params::default_text(&args)}),
        },
        "has_param" => json!({"exists": type_of(&node.get(&param).await?) != NOT_SET}),
        "search_param" => {
            let found = type_of(&node.get(&param).await?) != NOT_SET;
            json!({"global_name": if found { full.as_str() } else { "" }})
        }
        "set_param" => {
            let (_, value) = params::value_to_set(&args, &full)?;
            let current = type_of(&node.get(&param).await?);
            let pv =
                parameter_value(&value, current).map_err(|e| format!("value of {full}: {e}"))?;
            node.set(&param, pv).await?;
            json!({})
        }
        "delete_param" => {
            if type_of(&node.get(&param).await?) == NOT_SET {
                return Err(format!("parameter {full} is not set"));
            }
            node.set(&param, typed(NOT_SET, None)).await?;
            json!({})
        }
        other => return Err(format!("{other} is not a parameter service")),
    })
}

/// `<node>:<parameter>` → the node's full name and the parameter's (the whole name
/// checked and given its leading `/` as any parameter name).
fn split_name(raw: &str) -> Result<(String, String), String> {
    let full = params::param_name(raw)?;
    let shown = || full.chars().take(64).collect::<String>();
    let Some((node, param)) = full.split_once(':') else {
        return Err(format!(
            "{:?} names no ROS 2 node: name a parameter as <node>:<parameter>, e.g. \
             /camera:fps, as rosapi does (get_param_names lists them)",
            shown()
        ));
    };
    let node = node.trim_end_matches('/');
    if node.is_empty() || param.is_empty() {
        return Err(format!(
            "{:?}: both the node and the parameter must be named (<node>:<parameter>)",
            shown()
        ));
    }
    Ok((node.to_owned(), param.to_owned()))
}

/// Whether the caller gave a default for a parameter that is not set.
fn has_default(args: &Json) -> bool {
    params::default_text(args) != "null"
}

/// The graph's nodes that serve parameters, by full name, with their request mapping.
fn nodes(bridge: &Bridge) -> BTreeMap<String, Mapping> {
    let mut nodes = BTreeMap::new();
    for r in bridge.dp.discovered_readers() {
        let s = &r.subscription_topic_data;
        if bridge.is_own(s.key()) {
            continue;
        }
        if let Some(DdsName::Request(service)) = DdsName::parse(s.topic_name())
            && let Some(node) = service.strip_suffix("/list_parameters")
            && !node.is_empty()
        {
            nodes.insert(
                node.to_owned(),
                Mapping::of(r.reader_proxy.remote_reader_guid),
            );
        }
    }
    // Endpoints of nodes that have gone are dropped here.
    bridge
        .lock()
        .params
        .retain(|(node, _), _| nodes.contains_key(node));
    nodes
}

impl Node<'_> {
    /// The bridge's endpoint for this node's `srv`, made on first use (only what is
    /// called: listing a graph's names makes one endpoint per node, not three).
    fn endpoint(&self, srv: Srv) -> Result<Arc<Endpoint>, String> {
        let key = (self.name.to_owned(), srv);
        if let Some(p) = self.bridge.lock().params.get(&key) {
            return Ok(p.ep.clone());
        }
        let (ep, task) = Endpoint::start(
            self.bridge,
            &format!("{}/{}", self.name, srv.service()),
            &format!("rcl_interfaces/srv/{}", srv.type_name()),
            self.mapping,
        )
        .map_err(|e| format!("cannot reach the parameters of {}: {e}", self.name))?;
        // Made twice at once: the first one stays, the second is dropped (and stops).
        let mut st = self.bridge.lock();
        let kept = st.params.entry(key).or_insert(ParamEndpoint { ep, task });
        Ok(kept.ep.clone())
    }

    /// One call of `srv`, JSON both ways.
    async fn call(&self, srv: Srv, request: Json) -> Result<Json, String> {
        let ty = format!("rcl_interfaces/srv/{}", srv.type_name());
        let body = self.bridge.cdr_of(&format!("{ty}_Request"), &request)?;
        let reply = self.endpoint(srv)?.request(body).await?;
        self.bridge
            .json_of(
                &format!("{ty}_Response"),
                &Payload::new(Encoding::Cdr, reply),
            )
            .map_err(|e| format!("the answer of {} cannot be read: {e}", srv.service()))
    }

    /// The `ParameterValue` of `param` (type NOT_SET when the node has no such
    /// parameter).
    async fn get(&self, param: &str) -> Result<Json, String> {
        let reply = self.call(Srv::Get, json!({"names": [param]})).await?;
        reply
            .get("values")
            .and_then(|v| v.get(0))
            .cloned()
            .ok_or_else(|| format!("get_parameters answered no value for {param}"))
    }

    /// Sets `param` to `value` (a `ParameterValue`); the node's refusal is the error.
    async fn set(&self, param: &str, value: Json) -> Result<(), String> {
        let request = json!({"parameters": [{"name": param, "value": value}]});
        let reply = self.call(Srv::Set, request).await?;
        let node = self.name;
        match reply.get("results").and_then(|r| r.get(0)) {
            Some(r) if r.get("successful").and_then(Json::as_bool) == Some(true) => Ok(()),
            Some(r) => Err(format!(
                "{node} refused to change {param}: {}",
                r.get("reason")
                    .and_then(Json::as_str)
                    .filter(|s| !s.is_empty())
                    .unwrap_or("no reason given")
            )),
            None => Err(format!("set_parameters of {node} answered no result")),
        }
    }

    /// The node's parameters as `<node>:<parameter>`.
    async fn names(&self) -> Result<Vec<String>, String> {
        let reply = self
            .call(Srv::List, json!({"prefixes": [], "depth": 0}))
            .await?;
        Ok(reply
            .pointer("/result/names")
            .and_then(Json::as_array)
            .map(|names| {
                names
                    .iter()
                    .filter_map(Json::as_str)
                    .map(|p| format!("{}:{p}", self.name))
                    .collect()
            })
            .unwrap_or_default())
    }
}

/// Every node's parameters as `<node>:<parameter>`, sorted; a node that does not answer
/// within [`LIST_WAIT`] is left out.
async fn all_names(bridge: &Bridge, nodes: &BTreeMap<String, Mapping>) -> Vec<String> {
    let lists = nodes.iter().map(|(name, &mapping)| async move {
        let node = Node {
            bridge,
            name,
            mapping,
        };
        match tokio::time::timeout(LIST_WAIT, node.names()).await {
            Ok(Ok(names)) => names,
            Ok(Err(e)) => {
                tracing::debug!("ros2: listing the parameters of {name}: {e}");
                Vec::new()
            }
            Err(_) => {
                tracing::debug!("ros2: {name} did not list its parameters within {LIST_WAIT:?}");
                Vec::new()
            }
        }
    });
    let mut names: Vec<String> = futures::future::join_all(lists)
        .await
        .into_iter()
        .flatten()
        .collect();
    names.sort();
    names
}

fn type_of(value: &Json) -> u8 {
    value
        .get("type")
        .and_then(Json::as_u64)
        .and_then(|t| u8::try_from(t).ok())
        .unwrap_or(NOT_SET)
}

/// A `ParameterValue` (as JSON) as the plain JSON value rosapi gives; `None` when not set.
fn value_json(pv: &Json) -> Option<Json> {
    let t = type_of(pv);
    let field = VALUE_FIELDS.get(usize::from(t)).filter(|f| !f.is_empty())?;
    let v = pv.get(*field)?.clone();
    if t == BYTE_ARRAY
        && let Some(text) = v.as_str()
    {
        // Bytes are base64 in the registry's JSON; rosapi gives them as numbers.
        let bytes = base64::engine::general_purpose::STANDARD
            .decode(text)
            .ok()?;
        return Some(Json::Array(bytes.into_iter().map(Json::from).collect()));
    }
    Some(v)
}

/// A `ParameterValue` of type `t` holding `value` in its field (the others at their
/// defaults, as a node's own client sends them).
fn typed(t: u8, value: Option<Json>) -> Json {
    let mut pv = json!({
        "type": t,
        "bool_value": false,
        "integer_value": 0,
        "double_value": 0.0,
        "string_value": "",
        "byte_array_value": "",
        "bool_array_value": [],
        "integer_array_value": [],
        "double_array_value": [],
        "string_array_value": [],
    });
    if let (Some(field), Some(v)) = (VALUE_FIELDS.get(usize::from(t)), value)
        && !field.is_empty()
    {
        pv[*field] = v;
    }
    pv
}

/// The `ParameterValue` for JSON `value`, given the parameter's `current` type: kept
/// where the value fits it (a node refuses a change of type), else what the JSON is.
fn parameter_value(value: &Json, current: u8) -> Result<Json, String> {
    let as_doubles = |items: &[Json]| -> Json {
        items
            .iter()
            .map(|x| x.as_f64().map_or(Json::Null, Json::from))
            .collect()
    };
    Ok(match value {
        Json::Bool(b) => typed(BOOL, Some(json!(b))),
        Json::String(s) => typed(STRING, Some(json!(s))),
        Json::Number(n) => match n.as_i64() {
            Some(i) if current != DOUBLE => typed(INTEGER, Some(json!(i))),
            _ => typed(
                DOUBLE,
                Some(json!(n.as_f64().ok_or("number out of range")?)),
            ),
        },
        Json::Array(items) if items.is_empty() => {
            if !(BYTE_ARRAY..=STRING_ARRAY).contains(&current) {
                return Err(
                    "an empty array's element type is unknown for a parameter that is not \
                     an array yet; set it with at least one element"
                        .into(),
                );
            }
            typed(current, None)
        }
        Json::Array(items) if items.iter().all(Json::is_boolean) => {
            typed(BOOL_ARRAY, Some(Json::Array(items.clone())))
        }
        Json::Array(items) if items.iter().all(Json::is_string) => {
            typed(STRING_ARRAY, Some(Json::Array(items.clone())))
        }
        Json::Array(items) if items.iter().all(Json::is_number) => {
            let ints = items.iter().all(|x| x.as_i64().is_some());
            let bytes = items
                .iter()
                .filter_map(|x| x.as_u64().and_then(|b| u8::try_from(b).ok()))
                .collect::<Vec<u8>>();
            if current == BYTE_ARRAY && bytes.len() == items.len() {
                let text = base64::engine::general_purpose::STANDARD.encode(bytes);
                typed(BYTE_ARRAY, Some(json!(text)))
            } else if ints && current != DOUBLE_ARRAY {
                typed(INTEGER_ARRAY, Some(Json::Array(items.clone())))
            } else {
                typed(DOUBLE_ARRAY, Some(as_doubles(items)))
            }
        }
        Json::Array(_) => {
            return Err(
                "the elements of an array parameter must all be booleans, all numbers or \
                 all strings"
                    .into(),
            );
        }
        Json::Null | Json::Object(_) => {
            return Err(
                "a ROS 2 parameter is a boolean, an integer, a double, a string or an array \
                 of one of them"
                    .into(),
            );
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_node_colon_parameter_as_rosapi_has_them() {
        assert_eq!(
            split_name("/camera:fps").unwrap(),
            ("/camera".into(), "fps".into())
        );
        assert_eq!(
            split_name("nav/planner:qos_overrides./tf.depth").unwrap(),
            ("/nav/planner".into(), "qos_overrides./tf.depth".into())
        );
        let e = split_name("/max_speed").unwrap_err();
        assert!(e.contains("<node>:<parameter>"), "{e}");
        assert!(split_name("/camera:").is_err());
        assert!(split_name(":fps").is_err());
    }

    #[test]
    fn a_value_keeps_the_parameters_type_where_it_fits() {
        // An integer written to a double parameter stays a double (a node refuses a
        // change of type); to a new or integer one it is an integer.
        let v = parameter_value(&json!(2), DOUBLE).unwrap();
        assert_eq!((type_of(&v), &v["double_value"]), (DOUBLE, &json!(2.0)));
        let v = parameter_value(&json!(2), NOT_SET).unwrap();
        assert_eq!((type_of(&v), &v["integer_value"]), (INTEGER, &json!(2)));
        let v = parameter_value(&json!([1, 2.5]), NOT_SET).unwrap();
        assert_eq!(type_of(&v), DOUBLE_ARRAY);
        assert_eq!(v["double_array_value"], json!([1.0, 2.5]));
        let v = parameter_value(&json!([1, 2]), DOUBLE_ARRAY).unwrap();
        assert_eq!(v["double_array_value"], json!([1.0, 2.0]));
        let v = parameter_value(&json!([1, 255]), BYTE_ARRAY).unwrap();
        assert_eq!(value_json(&v), Some(json!([1, 255])));
        let v = parameter_value(&json!([]), STRING_ARRAY).unwrap();
        assert_eq!(type_of(&v), STRING_ARRAY);
        assert!(parameter_value(&json!([]), NOT_SET).is_err());
        assert!(parameter_value(&json!([1, "a"]), NOT_SET).is_err());
        assert!(parameter_value(&json!({"a": 1}), NOT_SET).is_err());
        assert!(parameter_value(&Json::Null, NOT_SET).is_err());
        let v = parameter_value(&json!(["a", "b"]), NOT_SET).unwrap();
        assert_eq!(value_json(&v), Some(json!(["a", "b"])));
    }

    #[test]
    fn an_unset_value_reads_as_none_and_a_set_one_as_its_field() {
        assert_eq!(value_json(&typed(NOT_SET, None)), None);
        assert_eq!(
            value_json(&typed(BOOL, Some(json!(true)))),
            Some(json!(true))
        );
        assert_eq!(value_json(&json!({"type": 42})), None);
    }

    #[test]
    fn a_default_is_taken_from_either_dialects_argument() {
        assert_eq!(params::default_text(&json!({"default_value": "3"})), "3");
        assert_eq!(params::default_text(&json!({"default": "4"})), "4");
        assert!(has_default(&json!({"default_value": "3"})));
        assert!(!has_default(&json!({"default": ""})));
    }
}
