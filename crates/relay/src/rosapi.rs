//! The answers to the `/rosapi` services (which clients and viewers call to discover the
//! graph) from the router's own tables, shared by the rosbridge and Foxglove servers.
//!
//! rosbridge deployments run a separate `rosapi` node; fleetlink answers from the router
//! directly, so listings are exactly what can be subscribed to here. Service names match
//! with or without the leading slash; replies use ROS 2 field names and, for time, the
//! ROS 1 names as well so clients of either generation read them.

use serde_json::{Value, json};

use crate::gate::Op;
use crate::names::TopicName;
use crate::router::{ClientKind, Router, TopicSnapshot};
use crate::unix_nanos;

/// What the session should answer for a `call_service`.
pub enum Answer {
    /// A rosapi service: these values, `result: true`.
    Values(Value),
    /// A rosapi service that failed: `result: false` with this text.
    Failed(String),
    /// Not a rosapi service.
    NotRosapi,
}

/// Services this module answers, without the `/rosapi/` prefix.
pub const SERVICES: &[&str] = &[
    "topics",
    "topics_and_raw_types",
    "topic_type",
    "topics_for_type",
    "publishers",
    "subscribers",
    "get_time",
    "get_ros_version",
    "nodes",
    "services",
    "service_type",
    "service_providers",
    "service_node",
    "action_servers",
    "service_request_details",
    "service_response_details",
    "message_details",
    "node_details",
    "interfaces",
    "get_param",
    "set_param",
    "has_param",
    "delete_param",
    "get_param_names",
    "search_param",
];

/// Answers a `call_service` of a `/rosapi/` service: `visible` says whether the caller
/// may see a name for an operation (the ACL), `changed` hears of each parameter change.
pub fn answer(
    router: &Router,
    node_name: &str,
    service: &str,
    args: &Value,
    visible: &mut dyn FnMut(&str, Op) -> bool,
    changed: &mut dyn FnMut(&str, &str, usize),
) -> Answer {
    let name = service.trim_start_matches('/');
    let Some(call) = name.strip_prefix("rosapi/") else {
        return Answer::NotRosapi;
    };
    // Listings show only what the caller may subscribe to, and only topics that still
    // have an endpoint (`TopicSnapshot::listed`).
    let topics: Vec<_> = router
        .topics()
        .into_iter()
        .filter(|t| t.listed() && visible(t.meta.name.as_str(), Op::Subscribe))
        .collect();
    let values = match call {
        "topics"
        | "topics_and_raw_types"
        | "topic_type"
        | "topics_for_type"
        | "publishers"
        | "subscribers" => topic_info(router, call, args, &topics),
        "get_time" | "get_ros_version" | "nodes" | "services" | "action_servers" | "interfaces"
        | "node_details" => graph(router, node_name, call, args, &topics, visible),
        "get_param" | "set_param" | "has_param" | "delete_param" | "get_param_names"
        | "search_param" => params(router, call, args, visible, changed),
        "service_request_details" | "service_response_details" | "message_details" => {
            type_details(router, call, args)
        }
        "service_type" | "service_providers" | "service_node" => {
            service_info(router, node_name, call, args, visible)
        }
        other => return Answer::Failed(format!("unknown rosapi service '{other}'")),
    };
    values.map_or_else(
        |e| Answer::Failed(format!("{service}: {e}")),
        Answer::Values,
    )
}

/// The topic services: listings, a topic's type, its publishers and subscribers.
/// `topics` are those the caller may see.
fn topic_info(
    router: &Router,
    call: &str,
    args: &Value,
    topics: &[TopicSnapshot],
) -> Result<Value, String> {
    let arg_topic = || -> Result<TopicName, String> {
        let raw = args
            .get("topic")
            .and_then(Value::as_str)
            .ok_or("missing string argument 'topic'")?;
        TopicName::parse(raw).map_err(|e| e.to_string())
    };
    Ok(match call {
        "topics" => json!({
            "topics": topics.iter().map(|t| t.meta.name.as_str()).collect::<Vec<_>>(),
            "types": topics.iter().map(|t| t.meta.schema.type_name.as_str()).collect::<Vec<_>>(),
        }),
        "topics_and_raw_types" => json!({
            "topics": topics.iter().map(|t| t.meta.name.as_str()).collect::<Vec<_>>(),
            "types": topics.iter().map(|t| t.meta.schema.type_name.as_str()).collect::<Vec<_>>(),
            // In the ROS 2 grammar the hub announces (`get_ros_version`), from the registry
            // where it knows the type (a ROS 1 robot's definitions included), else as sent.
            "typedefs_full_text": topics.iter().map(|t| {
                let s = &t.meta.schema;
                if (s.encoding != "ros2msg" || s.text.is_empty())
                    && let Some(full) = router.transcoder().schema_for(&s.type_name)
                {
                    return full.text;
                }
                s.text.clone()
            }).collect::<Vec<_>>(),
        }),
        "topic_type" => {
            let n = arg_topic()?;
            json!({"type": topics.iter().find(|t| t.meta.name == n).map_or("", |t| t.meta.schema.type_name.as_str())})
        }
        "topics_for_type" => {
            let Some(ty) = args.get("type").and_then(Value::as_str) else {
                return Err("missing string argument 'type'".into());
            };
            json!({"topics": topics.iter().filter(|t| crate::router::same_type(&t.meta.schema.type_name, ty)).map(|t| t.meta.name.as_str()).collect::<Vec<_>>()})
        }
        "publishers" | "subscribers" => {
            let n = arg_topic()?;
            let ids = topics
                .iter()
                .find(|t| t.meta.name == n)
                .map(|t| {
                    if call == "publishers" {
                        t.publishers.clone()
                    } else {
                        t.subscribers.clone()
                    }
                })
                .unwrap_or_default();
            let names: Vec<String> = ids.iter().map(|id| client_node_name(router, *id)).collect();
            json!({call: names})
        }
        _ => unreachable!("listed in the caller"),
    })
}

/// The graph beyond topics: time, version, nodes, services, action servers, the types
/// known here, and what one node publishes, subscribes to and provides.
fn graph(
    router: &Router,
    node_name: &str,
    call: &str,
    args: &Value,
    topics: &[TopicSnapshot],
    visible: &mut dyn FnMut(&str, Op) -> bool,
) -> Result<Value, String> {
    Ok(match call {
        "get_time" => {
            let ns = unix_nanos();
            let (s, n) = (ns / 1_000_000_000, ns % 1_000_000_000);
            json!({"time": {"sec": s, "nanosec": n, "secs": s, "nsecs": n}})
        }
        "get_ros_version" => json!({"version": 2, "distro": "fleetlink"}),
        "nodes" => {
            let mut nodes = vec![node_name.to_owned()];
            nodes.extend(
                router
                    .clients()
                    .iter()
                    .map(|(info, _, _)| client_node_name(router, info.id)),
            );
            nodes.sort();
            nodes.dedup();
            json!({"nodes": nodes})
        }
        "services" => {
            let mut names: Vec<String> = SERVICES.iter().map(|s| format!("/rosapi/{s}")).collect();
            names.extend(
                router
                    .calls
                    .services()
                    .iter()
                    .filter(|s| !s.action && visible(s.name.as_str(), Op::CallService))
                    .map(|s| s.name.to_string()),
            );
            json!({ "services": names })
        }
        "action_servers" => json!({
            "action_servers": router
                .calls
                .services()
                .iter()
                .filter(|s| s.action && visible(s.name.as_str(), Op::SendActionGoal))
                .map(|s| s.name.to_string())
                .collect::<Vec<_>>(),
        }),
        "interfaces" => json!({ "interfaces": router.transcoder().type_names() }),
        "node_details" => {
            let Some(node) = args.get("node").and_then(Value::as_str) else {
                return Err("missing string argument 'node'".into());
            };
            let node = format!("/{}", node.trim_start_matches('/'));
            let is = |id: &crate::ClientId| client_node_name(router, *id) == node;
            let (mut publishing, mut subscribing) = (Vec::new(), Vec::new());
            for t in topics {
                if t.publishers.iter().any(is) {
                    publishing.push(t.meta.name.to_string());
                }
                if t.subscribers.iter().any(is) {
                    subscribing.push(t.meta.name.to_string());
                }
            }
            let services: Vec<String> = router
                .calls
                .services()
                .iter()
                .filter(|s| is(&s.provider) && visible(s.name.as_str(), Op::CallService))
                .map(|s| s.name.to_string())
                .collect();
            json!({"publishing": publishing, "subscribing": subscribing, "services": services})
        }
        _ => unreachable!("listed in the caller"),
    })
}

/// The definitions of a message type, or of a service's request or response.
fn type_details(router: &Router, call: &str, args: &Value) -> Result<Value, String> {
    let Some(ty) = args.get("type").and_then(Value::as_str) else {
        return Err("missing string argument 'type'".into());
    };
    let part = match call {
        "service_request_details" => format!("{}_Request", srv_name(ty)),
        "service_response_details" => format!("{}_Response", srv_name(ty)),
        _ => ty.to_owned(),
    };
    match router.transcoder().typedefs(&part) {
        Some(defs) => Ok(json!({ "typedefs": defs })),
        None => Err(format!(
            "type {ty} is not known to this server (it learns types from advertisements \
             and from --msg-path packages)"
        )),
    }
}

/// A service's type, provider and node; the server's own `/rosapi/` services are
/// provided by `node_name`.
fn service_info(
    router: &Router,
    node_name: &str,
    call: &str,
    args: &Value,
    visible: &mut dyn FnMut(&str, Op) -> bool,
) -> Result<Value, String> {
    let raw = args.get("service").and_then(Value::as_str);
    let Some(name) = raw.and_then(|r| TopicName::parse(r).ok()) else {
        return Err("missing string argument 'service'".into());
    };
    let own = name
        .as_str()
        .strip_prefix("/rosapi/")
        .is_some_and(|s| SERVICES.contains(&s));
    let found = router.calls.service(&name).filter(|s| {
        visible(
            s.name.as_str(),
            if s.action {
                Op::SendActionGoal
            } else {
                Op::CallService
            },
        )
    });
    let provider = match (&found, own) {
        (Some(s), _) => Some(client_node_name(router, s.provider)),
        (None, true) => Some(node_name.to_owned()),
        (None, false) => None,
    };
    Ok(match call {
        "service_type" => json!({"type": found.as_ref().map_or(
                if own { "rosapi/srv/Service" } else { "" },
                |s| s.schema.type_name.as_str())}),
        "service_node" => json!({"node": provider.unwrap_or_default()}),
        _ => json!({"providers": provider.into_iter().collect::<Vec<_>>()}),
    })
}

/// The parameter services. Reading a parameter needs `subscribe` on its name, changing it
/// `publish` (the ACL's operations, so one rule grants a robot's topics and parameters).
fn params(
    router: &Router,
    call: &str,
    args: &Value,
    visible: &mut dyn FnMut(&str, Op) -> bool,
    changed: &mut dyn FnMut(&str, &str, usize),
) -> Result<Value, String> {
    use crate::params::{lookup, param_name};
    let store = &router.params;
    let name = || -> Result<String, String> {
        param_name(args.get("name").and_then(Value::as_str).unwrap_or_default())
    };
    let may = |n: &str, op: Op, visible: &mut dyn FnMut(&str, Op) -> bool| {
        if visible(n, op) {
            Ok(())
        } else {
            let verb = if op == Op::Publish { "change" } else { "read" };
            Err(format!("not allowed to {verb} parameter {n}"))
        }
    };
    Ok(match call {
        "get_param" => {
            let n = name()?;
            may(&n, Op::Subscribe, visible)?;
            match lookup(&store.snapshot(), &n) {
                Some(v) => json!({"value": v.to_string()}),
                None => json!({"value": crate::params::default_text(args)}),
            }
        }
        "has_param" => {
            let n = name()?;
            may(&n, Op::Subscribe, visible)?;
            json!({"exists": lookup(&store.snapshot(), &n).is_some()})
        }
        "search_param" => {
            let n = name()?;
            may(&n, Op::Subscribe, visible)?;
            let found = lookup(&store.snapshot(), &n).is_some();
            json!({"global_name": if found { n } else { String::new() }})
        }
        "get_param_names" => json!({
            "names": store
                .snapshot()
                .into_keys()
                .filter(|k| visible(k, Op::Subscribe))
                .collect::<Vec<_>>(),
        }),
        "set_param" => {
            let n = name()?;
            may(&n, Op::Publish, visible)?;
            let (text, v) = crate::params::value_to_set(args, &n)?;
            // An object sets the tree under the name, as rosparam does.
            let mut flat = Vec::new();
            flatten(&n, &v, &mut flat);
            store.delete(&n);
            for (k, val) in flat {
                store.set(&k, val);
            }
            changed(&n, "set_param", text.len());
            json!({})
        }
        "delete_param" => {
            let n = name()?;
            may(&n, Op::Publish, visible)?;
            if !store.delete(&n) {
                return Err(format!("parameter {n} is not set"));
            }
            changed(&n, "delete_param", 0);
            json!({})
        }
        _ => unreachable!("listed in the caller"),
    })
}

/// `name` = `value`, with objects spread into one parameter per leaf.
fn flatten(name: &str, value: &Value, out: &mut Vec<(String, String)>) {
    match value {
        Value::Object(m) if !m.is_empty() => {
            for (k, v) in m {
                flatten(&format!("{name}/{k}"), v, out);
            }
        }
        other => out.push((name.to_owned(), other.to_string())),
    }
}

/// `pkg/T` or `pkg/srv/T` as the service's `pkg/srv/T`.
fn srv_name(ty: &str) -> String {
    match ty.split('/').collect::<Vec<_>>()[..] {
        [pkg, name] => format!("{pkg}/srv/{name}"),
        _ => ty.to_owned(),
    }
}

/// How a client appears as a node in `nodes`, `publishers` and `subscribers`.
pub fn client_node_name(router: &Router, id: crate::ClientId) -> String {
    match router.client_info(id).map(|c| c.kind) {
        Some(ClientKind::Agent { robot }) => format!("/{robot}"),
        Some(ClientKind::Internal { role }) => format!("/fleetlink/{role}"),
        Some(ClientKind::Rosbridge) => format!("/rosbridge_client_{}", id.0),
        Some(ClientKind::Foxglove) => format!("/foxglove_client_{}", id.0),
        None => format!("/gone_{}", id.0),
    }
}
