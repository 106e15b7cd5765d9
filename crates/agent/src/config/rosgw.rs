//! ROS Gateway (rosgw) configuration files, taken as they are: `fleetlink agent --config
//! rosgw.json` runs the agent a rosgw JSON file describes (side by side in
//! docs/rosgw.md).
//!
//! A rosgw file is a JSON list of entries (or one entry): each names a peer gateway
//! (`address`) and what to exchange with it — `publish` (local topics sent to the peer),
//! `trans-publish` (the same under another name there), `subscribe` (the peer's topics
//! brought into the local graph), `expose-service`/`expose-action` (local servers the peer
//! may call) and `reserve-service`/`reserve-action` (the peer's servers made callable
//! locally). rosgw is a ROS 2 program, so the entries become the agent's `ros2:` section,
//! and the address becomes the hub the agent connects to.
//!
//! Design choices:
//! - Recognised by shape, not by file name: a top-level list, or a mapping with rosgw's
//!   `address`/`service_uri`, is never an agent YAML (whose top level is a mapping of its
//!   own keys), so one `--config` takes either.
//! - Strict like the YAML: an unknown key, a value of the wrong kind or something that has
//!   no meaning in fleetlink is an error naming the entry's field (`[0].publish[1].name`)
//!   and why, never silently dropped. What carries over without effect is documented:
//!   message types (the agent learns them from the graph), `israw` (fleetlink always
//!   carries the raw serialization) and the CBOR compressions (the link is binary).
//! - Names are ROS 2's: a relative name (`add_two_ints`, as rosgw's own examples write
//!   services) resolves in the root namespace, as rclpy resolves it for a node in `/`.

use serde_json::{Map, Value};

use super::locate::FieldPath;
use super::validate::{Problem, check_hub_url, check_topic};
use super::{AgentConfig, Ros2Config};
use fleetlink_qos::{Compression, TopicQosSpec};

/// Keys of a rosgw gateway entry.
const ENTRY_KEYS: &[&str] = &[
    "title",
    "active",
    "address",
    "compression",
    "publish",
    "trans-publish",
    "subscribe",
    "expose-service",
    "reserve-service",
    "expose-action",
    "reserve-action",
];

/// rosgw's ROS-to-REST binding entries carry these instead of `address`.
const REST_KEYS: &[&str] = &[
    "service_name",
    "service_uri",
    "service_method",
    "request_rule",
    "response_rule",
];

/// The config a rosgw file describes, or `None` when `text` is not a rosgw file (then it
/// is read as the agent's YAML).
pub(super) fn parse(text: &str) -> Option<Result<AgentConfig, Problem>> {
    let doc: Value = serde_json::from_str(text).ok()?;
    let rosgw = match &doc {
        Value::Array(_) => true,
        Value::Object(m) => m.contains_key("address") || m.contains_key("service_uri"),
        _ => false,
    };
    rosgw.then(|| convert(&doc))
}

fn problem(path: FieldPath, message: impl Into<String>) -> Problem {
    Problem {
        path,
        at_key: false,
        message: message.into(),
    }
}

fn key_problem(path: FieldPath, message: impl Into<String>) -> Problem {
    Problem {
        path,
        at_key: true,
        message: message.into(),
    }
}

/// What one list item of an entry (`publish[0]`, `expose-service[1]`, …) is.
#[derive(Clone, Copy)]
enum Kind {
    Publish,
    TransPublish,
    Subscribe,
    ExposeService,
    ReserveService,
    ExposeAction,
    ReserveAction,
}

impl Kind {
    fn of(key: &str) -> Option<Kind> {
        Some(match key {
            "publish" => Kind::Publish,
            "trans-publish" => Kind::TransPublish,
            "subscribe" => Kind::Subscribe,
            "expose-service" => Kind::ExposeService,
            "reserve-service" => Kind::ReserveService,
            "expose-action" => Kind::ExposeAction,
            "reserve-action" => Kind::ReserveAction,
            _ => return None,
        })
    }

    /// The item's name key, its type key (rosgw's examples also write `type` for topics),
    /// and the other keys it may have.
    fn keys(
        self,
    ) -> (
        &'static str,
        &'static [&'static str],
        &'static [&'static str],
    ) {
        const TOPIC_EXTRA: &[&str] = &["israw", "compression"];
        match self {
            Kind::Publish | Kind::Subscribe => ("name", &["messageType", "type"], TOPIC_EXTRA),
            Kind::TransPublish => (
                "name",
                &["messageType", "type"],
                &["remote_name", "israw", "compression"],
            ),
            Kind::ExposeService | Kind::ReserveService => {
                ("service", &["serviceType", "type"], TOPIC_EXTRA)
            }
            Kind::ExposeAction | Kind::ReserveAction => {
                ("action", &["actionType", "type"], TOPIC_EXTRA)
            }
        }
    }
}

fn convert(doc: &Value) -> Result<AgentConfig, Problem> {
    let root = FieldPath::default();
    let entries: Vec<(FieldPath, &Map<String, Value>)> = match doc {
        Value::Array(items) => items
            .iter()
            .enumerate()
            .map(|(i, v)| {
                let path = root.index(i);
                match v {
                    Value::Object(m) => Ok((path, m)),
                    _ => Err(problem(
                        path,
                        "a rosgw entry is an object with `address` and what to exchange \
                         (`publish`, `subscribe`, ...)",
                    )),
                }
            })
            .collect::<Result<_, _>>()?,
        Value::Object(m) => vec![(root, m)],
        _ => unreachable!("parse() only converts lists and objects"),
    };
    let mut cfg = AgentConfig::default();
    let mut ros2 = Ros2Config::default();
    // The first active entry's address and where it was.
    let mut address: Option<(FieldPath, String)> = None;
    let mut title: Option<(FieldPath, String)> = None;
    for (path, entry) in entries {
        if let Some(key) = REST_KEYS.iter().find(|k| entry.contains_key(**k)) {
            return Err(key_problem(
                path.key(*key),
                "a rosgw ROS-to-REST binding (topics posted to an HTTP service, its answer \
                 published back) has no counterpart in the fleetlink agent; remove the entry \
                 and call the HTTP service from a program that subscribes through the hub \
                 (rosbridge, REST API)",
            ));
        }
        for key in entry.keys() {
            if !ENTRY_KEYS.contains(&key.as_str()) {
                return Err(key_problem(
                    path.key(key.as_str()),
                    format!(
                        "`{key}` is not a field of a rosgw entry; the fields are {}",
                        ENTRY_KEYS.join(", ")
                    ),
                ));
            }
        }
        match entry.get("active") {
            None | Some(Value::Bool(true)) => {}
            // rosgw skips an inactive entry altogether; so does the agent.
            Some(Value::Bool(false)) => continue,
            Some(_) => {
                return Err(problem(path.key("active"), "`active` is true or false"));
            }
        }
        let here = path.key("address");
        let url = match entry.get("address") {
            Some(Value::String(s)) => s.clone(),
            Some(_) => return Err(problem(here, "`address` is the hub's ws:// or wss:// URL")),
            None => {
                return Err(key_problem(
                    path,
                    "this entry has no `address`: the hub's ws:// or wss:// URL the agent \
                     connects to",
                ));
            }
        };
        check_hub_url(&url).map_err(|why| problem(here.clone(), why))?;
        match &address {
            None => address = Some((here, url)),
            Some((first, a)) if *a != url => {
                return Err(problem(
                    here,
                    format!(
                        "{first} is {a:?}: a fleetlink agent keeps one link to one hub, which \
                         carries every exchange; give every entry the same address, or run \
                         one agent per hub"
                    ),
                ));
            }
            Some(_) => {}
        }
        if let Some(t) = entry.get("title") {
            let Value::String(t) = t else {
                return Err(problem(path.key("title"), "`title` is a string"));
            };
            match &title {
                None => title = Some((path.key("title"), t.clone())),
                Some((first, t0)) if t0 != t => {
                    return Err(problem(
                        path.key("title"),
                        format!(
                            "{first} is {t0:?}: the agent takes the title as the robot's \
                             name, and a robot has one"
                        ),
                    ));
                }
                Some(_) => {}
            }
        }
        let default_compression = match entry.get("compression") {
            None => None,
            Some(v) => compression(path.key("compression"), v)?,
        };
        for (key, value) in entry {
            let Some(kind) = Kind::of(key) else { continue };
            let list_path = path.key(key.as_str());
            let Value::Array(items) = value else {
                return Err(problem(
                    list_path,
                    format!("`{key}` is a list of objects, e.g. [{}]", example(kind)),
                ));
            };
            for (i, item) in items.iter().enumerate() {
                apply(
                    kind,
                    &list_path.index(i),
                    item,
                    default_compression,
                    &mut cfg,
                    &mut ros2,
                )?;
            }
        }
    }
    let Some((_, url)) = address else {
        return Err(problem(
            FieldPath::default(),
            "no active rosgw entry: nothing to run (every entry has `active: false`, or the \
             list is empty)",
        ));
    };
    cfg.hub = vec![url];
    if let Some((path, t)) = title {
        cfg.name = t.parse().map_err(|e| {
            problem(
                path,
                format!("the agent takes the title as the robot's name: {e}"),
            )
        })?;
    }
    cfg.ros2 = Some(ros2);
    Ok(cfg)
}

/// One item of a list: checks its keys and adds it to the configuration.
fn apply(
    kind: Kind,
    path: &FieldPath,
    item: &Value,
    default_compression: Option<Compression>,
    cfg: &mut AgentConfig,
    ros2: &mut Ros2Config,
) -> Result<(), Problem> {
    let Value::Object(item) = item else {
        return Err(problem(
            path.clone(),
            format!("an item is an object, e.g. {}", example(kind)),
        ));
    };
    let (name_key, type_keys, extra) = kind.keys();
    for key in item.keys() {
        let k = key.as_str();
        if k != name_key && !type_keys.contains(&k) && !extra.contains(&k) {
            let mut known = vec![name_key];
            known.extend_from_slice(type_keys);
            known.extend_from_slice(extra);
            return Err(key_problem(
                path.key(k),
                format!(
                    "`{k}` is not a field here; the fields are {}",
                    known.join(", ")
                ),
            ));
        }
    }
    for key in type_keys {
        if let Some(v) = item.get(*key)
            && !v.is_string()
        {
            return Err(problem(path.key(*key), format!("`{key}` is a type name")));
        }
    }
    let name = ros_name(&path.key(name_key), item.get(name_key), name_key, kind)?;
    let compression = match item.get("compression") {
        Some(v) => compression(path.key("compression"), v)?,
        None => default_compression,
    };
    let exact = regex::escape(&name);
    match kind {
        Kind::Publish | Kind::TransPublish => {
            ros2.publish.include.push(exact);
            if let Kind::TransPublish = kind {
                let remote = ros_name(
                    &path.key("remote_name"),
                    item.get("remote_name"),
                    "remote_name",
                    kind,
                )?;
                cfg.remap.insert(name.clone(), remote);
            }
            if let Some(c) = compression {
                cfg.topics.insert(
                    name,
                    TopicQosSpec {
                        compression: Some(c),
                        ..TopicQosSpec::default()
                    },
                );
            }
        }
        Kind::Subscribe => ros2.subscribe.push(name),
        Kind::ExposeService => ros2.services.expose.push(exact),
        Kind::ReserveService => ros2.services.offer.push(exact),
        Kind::ExposeAction => ros2.actions.expose.push(exact),
        Kind::ReserveAction => ros2.actions.offer.push(exact),
    }
    Ok(())
}

/// A topic, service or action name: required, a string, a valid ROS name once a relative
/// name is resolved in the root namespace.
fn ros_name(path: &FieldPath, v: Option<&Value>, key: &str, kind: Kind) -> Result<String, Problem> {
    let Some(v) = v else {
        return Err(key_problem(
            path.clone(),
            format!("`{key}` is missing, e.g. {}", example(kind)),
        ));
    };
    let Value::String(s) = v else {
        return Err(problem(path.clone(), format!("`{key}` is a ROS name")));
    };
    let name = if s.starts_with('/') {
        s.clone()
    } else {
        format!("/{s}")
    };
    check_topic(&name).map_err(|why| problem(path.clone(), why))?;
    Ok(name)
}

/// rosgw's compression names: the zip ones compress on the link; the CBOR ones, `none` and
/// an empty value change nothing (the link is binary and carries the raw serialization).
fn compression(path: FieldPath, v: &Value) -> Result<Option<Compression>, Problem> {
    match v {
        Value::Null => Ok(None),
        Value::String(s) => match s.as_str() {
            "" | "none" | "cbor" | "cbor-raw" => Ok(None),
            "zip" | "rawzip" => Ok(Some(Compression::Zstd)),
            other => Err(problem(
                path,
                format!(
                    "compression {other:?} is not one of rosgw's: none, cbor, cbor-raw, zip, \
                     rawzip"
                ),
            )),
        },
        _ => Err(problem(
            path,
            "`compression` is a name: none, cbor, cbor-raw, zip or rawzip",
        )),
    }
}

fn example(kind: Kind) -> &'static str {
    match kind {
        Kind::Publish | Kind::Subscribe => {
            r#"{"name": "/scan", "messageType": "sensor_msgs/msg/LaserScan"}"#
        }
        Kind::TransPublish => {
            r#"{"name": "/scan", "messageType": "sensor_msgs/msg/LaserScan", "remote_name": "/robot7/scan"}"#
        }
        Kind::ExposeService | Kind::ReserveService => {
            r#"{"service": "/add_two_ints", "serviceType": "example_interfaces/srv/AddTwoInts"}"#
        }
        Kind::ExposeAction | Kind::ReserveAction => {
            r#"{"action": "/fibonacci", "actionType": "example_interfaces/action/Fibonacci"}"#
        }
    }
}
