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
//! a reader. Its three services get endpoints of the bridge on first use, kept while the
//! node is there.

use std::collections::BTreeMap;
use std::sync::Arc;
use std::time::{Duration, Instant};

use base64::Engine as _;
use fleetlink_proto::{Encoding, Payload, Schema};
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

/// The bridge's endpoints for one node's parameter services.
pub(crate) struct NodeParams {
    get: Arc<Endpoint>,
    set: Arc<Endpoint>,
    list: Arc<Endpoint>,
    tasks: Vec<AbortHandle>,
}

impl NodeParams {
    pub(crate) fn abort(&self) {
        for t in &self.tasks {
            t.abort();
        }
    }
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
    let ep = endpoints(bridge, &node, mapping)?;
    let full = format!("{node}:{param}");
    Ok(match call {
        "get_param" => match value_json(&get_value(bridge, &ep, &param).await?) {
            Some(v) => json!({"value": v.to_string()}),
            None => json!({"value": params::default_text(&args)}),
        },
        "has_param" => {
            let v = get_value(bridge, &ep, &param).await?;
            json!({"exists": type_of(&v) != NOT_SET})
        }
        "search_param" => {
            let v = get_value(bridge, &ep, &param).await?;
            let found = type_of(&v) != NOT_SET;
            json!({"global_name": if found { full.as_str() } else { "" }})
        }
        "set_param" => {
            let (_, value) = params::value_to_set(&args, &full)?;
            let current = type_of(&get_value(bridge, &ep, &param).await?);
            let pv =
                parameter_value(&value, current).map_err(|e| format!("value of {full}: {e}"))?;
            set_value(bridge, &ep, &node, &param, pv).await?;
            json!({})
        }
        "delete_param" => {
            if type_of(&get_value(bridge, &ep, &param).await?) == NOT_SET {
                return Err(format!("parameter {full} is not set"));
            }
            set_value(bridge, &ep, &node, &param, typed(NOT_SET, None)).await?;
            json!({})
        }
        other => return Err(format!("{other} is not a parameter service")),
    })
}

/// `<node>:<parameter>` → the node's full name and the parameter's.
fn split_name(raw: &str) -> Result<(String, String), String> {
    let raw = raw.trim();
    let Some((node, param)) = raw.split_once(':') else {
        return Err(format!(
            "{:?} names no ROS 2 node: name a parameter as <node>:<parameter>, e.g. \
             /camera:fps, as rosapi does (get_param_names lists them)",
            raw.chars().take(64).collect::<String>()
        ));
    };
    let node = node.trim_end_matches('/');
    if node.is_empty() || node == "/" || param.is_empty() {
        return Err(format!(
            "{:?}: both the node and the parameter must be named (<node>:<parameter>)",
            raw.chars().take(64).collect::<String>()
        ));
    }
    let node = if node.starts_with('/') {
        node.to_owned()
    } else {
        format!("/{node}")
    };
    Ok((node, param.to_owned()))
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
    bridge.lock().params.retain(|node, ep| {
        let live = nodes.contains_key(node);
        if !live {
            ep.abort();
        }
        live
    });
    nodes
}

/// The bridge's endpoints for `node`'s parameter services, made on first use.
fn endpoints(bridge: &Bridge, node: &str, mapping: Mapping) -> Result<Arc<NodeParams>, String> {
    if let Some(ep) = bridge.lock().params.get(node) {
        return Ok(ep.clone());
    }
    let mut tasks = Vec::new();
    let mut start = |srv: &str| {
        Endpoint::start(
            bridge,
            &format!("{node}/{}", srv_service(srv)),
            &format!("rcl_interfaces/srv/{srv}"),
            mapping,
        )
        .map(|(ep, task)| {
            tasks.push(task);
            ep
        })
    };
    let made = (|| {
        Ok::<_, String>((
            start("GetParameters")?,
            start("SetParameters")?,
            start("ListParameters")?,
        ))
    })();
    let (get, set, list) = match made {
        Ok(m) => m,
        Err(e) => {
            for t in &tasks {
                t.abort();
            }
            return Err(format!("cannot reach the parameters of {node}: {e}"));
        }
    };
    let ep = Arc::new(NodeParams {
        get,
        set,
        list,
        tasks,
    });
    let mut st = bridge.lock();
    // Made twice at once: the first one stays.
    let kept = st
        .params
        .entry(node.to_owned())
        .or_insert_with(|| ep.clone());
    if !Arc::ptr_eq(kept, &ep) {
        ep.abort();
    }
    Ok(kept.clone())
}

/// `GetParameters` → `get_parameters`.
fn srv_service(srv: &str) -> &'static str {
    match srv {
        "GetParameters" => "get_parameters",
        "SetParameters" => "set_parameters",
        _ => "list_parameters",
    }
}

/// One call of an `rcl_interfaces` service (`srv`) through `ep`, JSON both ways.
async fn call(bridge: &Bridge, ep: &Endpoint, srv: &str, request: Json) -> Result<Json, String> {
    let ty = format!("rcl_interfaces/srv/{srv}");
    let body = bridge.to_cdr(
        &format!("{ty}_Request"),
        &Payload::json(serde_json::to_vec(&request).expect("JSON")),
    )?;
    let reply = ep.request(&body).await?;
    let schema = Schema {
        type_name: format!("{ty}_Response"),
        encoding: "ros2msg".into(),
        text: String::new(),
    };
    let json = bridge
        .router
        .transcoder()
        .convert(&schema, &Payload::new(Encoding::Cdr, reply), Encoding::Json)
        .map_err(|e| format!("the answer of {srv} cannot be read: {e}"))?;
    serde_json::from_slice(&json).map_err(|e| e.to_string())
}

/// The `ParameterValue` of `param` (type NOT_SET when the node has no such parameter).
async fn get_value(bridge: &Bridge, ep: &NodeParams, param: &str) -> Result<Json, String> {
    let reply = call(bridge, &ep.get, "GetParameters", json!({"names": [param]})).await?;
    reply
        .get("values")
        .and_then(|v| v.get(0))
        .cloned()
        .ok_or_else(|| format!("get_parameters answered no value for {param}"))
}

/// Sets `param` to `value` (a `ParameterValue`); the node's refusal is the error.
async fn set_value(
    bridge: &Bridge,
    ep: &NodeParams,
    node: &str,
    param: &str,
    value: Json,
) -> Result<(), String> {
    let request = json!({"parameters": [{"name": param, "value": value}]});
    let reply = call(bridge, &ep.set, "SetParameters", request).await?;
    let result = reply.get("results").and_then(|r| r.get(0));
    match result {
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

/// Every node's parameters as `<node>:<parameter>`, sorted; a node that does not answer
/// within [`LIST_WAIT`] is left out.
async fn all_names(bridge: &Bridge, nodes: &BTreeMap<String, Mapping>) -> Vec<String> {
    let lists = nodes.iter().map(|(node, &mapping)| async move {
        let listed = async {
            let ep = endpoints(bridge, node, mapping)?;
            let reply = call(
                bridge,
                &ep.list,
                "ListParameters",
                json!({"prefixes": [], "depth": 0}),
            )
            .await?;
            Ok::<_, String>(
                reply
                    .pointer("/result/names")
                    .and_then(Json::as_array)
                    .map(|names| {
                        names
                            .iter()
                            .filter_map(Json::as_str)
                            .map(|p| format!("{node}:{p}"))
                            .collect::<Vec<_>>()
                    })
                    .unwrap_or_default(),
            )
        };
        match tokio::time::timeout(LIST_WAIT, listed).await {
            Ok(Ok(names)) => names,
            Ok(Err(e)) => {
                tracing::debug!("ros2: listing the parameters of {node}: {e}");
                Vec::new()
            }
            Err(_) => {
                tracing::debug!("ros2: {node} did not list its parameters within {LIST_WAIT:?}");
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
