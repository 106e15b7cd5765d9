//! Parameters: the `/rosapi` parameter services (`get_param`, `set_param`, `has_param`,
//! `delete_param`, `get_param_names`, `search_param`) answered from a store the hub
//! keeps.
//!
//! Values are JSON texts, as rosapi exchanges them (`set_param` sends
//! `value: "<json>"`). Names are ROS names; a parameter whose name is a prefix (`/robot1`)
//! stands for the tree under it, as on a ROS 1 parameter server: `get_param /robot1`
//! answers an object of everything below.
//!
//! The relay knows the [`ParamStore`] seam only; the hub supplies a durable one.

use std::collections::BTreeMap;
use std::sync::Mutex;

use serde_json::{Map, Value};

/// Where parameters live. Reads and writes are quick (in memory); a durable store writes
/// through to disk without blocking the caller for long.
pub trait ParamStore: Send + Sync {
    /// Every parameter with its JSON text, by name.
    fn snapshot(&self) -> BTreeMap<String, String>;
    fn get(&self, name: &str) -> Option<String>;
    fn set(&self, name: &str, value_json: String);
    /// Deletes `name` and everything under it; false if nothing was there.
    fn delete(&self, name: &str) -> bool;
    /// Blocks until every change made before this call is durable. For shutdown only —
    /// never on an async worker thread.
    fn flush(&self) {}
}

/// Parameters in memory only (an agent, tests).
#[derive(Default)]
pub struct MemoryParams(Mutex<BTreeMap<String, String>>);

impl MemoryParams {
    pub fn with(values: BTreeMap<String, String>) -> MemoryParams {
        MemoryParams(Mutex::new(values))
    }
}

impl ParamStore for MemoryParams {
    fn snapshot(&self) -> BTreeMap<String, String> {
        self.0.lock().unwrap_or_else(|p| p.into_inner()).clone()
    }
    fn get(&self, name: &str) -> Option<String> {
        self.0
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .get(name)
            .cloned()
    }
    fn set(&self, name: &str, value_json: String) {
        self.0
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .insert(name.to_owned(), value_json);
    }
    fn delete(&self, name: &str) -> bool {
        !self.remove_under(name).is_empty()
    }
}

impl MemoryParams {
    /// Deletes `name` and everything under it; returns the names deleted.
    pub fn remove_under(&self, name: &str) -> Vec<String> {
        let mut m = self.0.lock().unwrap_or_else(|p| p.into_inner());
        let prefix = format!("{name}/");
        let mut gone = Vec::new();
        m.retain(|k, _| {
            let hit = k == name || k.starts_with(&prefix);
            if hit {
                gone.push(k.clone());
            }
            !hit
        });
        gone
    }
}

/// The rosapi parameter services an agent's ROS adapter may answer for its robot: name
/// in the agent's call table, rosapi's type, its definition.
pub const SERVICES: [(&str, &str, &str); 6] = [
    (
        "/rosapi/get_param",
        "rosapi/srv/GetParam",
        "string name\nstring default\n---\nstring value\n",
    ),
    (
        "/rosapi/set_param",
        "rosapi/srv/SetParam",
        "string name\nstring value\n---\n",
    ),
    (
        "/rosapi/has_param",
        "rosapi/srv/HasParam",
        "string name\n---\nbool exists\n",
    ),
    (
        "/rosapi/delete_param",
        "rosapi/srv/DeleteParam",
        "string name\n---\n",
    ),
    (
        "/rosapi/get_param_names",
        "rosapi/srv/GetParamNames",
        "---\nstring[] names\n",
    ),
    (
        "/rosapi/search_param",
        "rosapi/srv/SearchParam",
        "string name\n---\nstring global_name\n",
    ),
];

/// Advertises every parameter service in the call table as `client`'s (an agent's ROS
/// adapter that answers them for its robot).
pub fn advertise_services(calls: &crate::calls::Calls, client: crate::ClientId) {
    for (name, type_name, definition) in SERVICES {
        let name = crate::TopicName::parse(name).expect("a valid service name");
        let schema = fleetlink_proto::Schema {
            type_name: type_name.to_owned(),
            encoding: "ros1msg".into(),
            text: definition.to_owned(),
        };
        calls.advertise(client, name, schema, false);
    }
}

/// Whether `name` is one of the parameter services.
pub fn is_param_service(name: &str) -> bool {
    SERVICES.iter().any(|(n, _, _)| *n == name)
}

/// A parameter name as rosapi clients send it, by the one name rule
/// ([`crate::names::normalize`]: leading `/` added, trailing `/` dropped) after the
/// spaces around it are trimmed.
pub fn param_name(raw: &str) -> Result<String, String> {
    let t = raw.trim();
    if t.is_empty() || t == "/" {
        return Err("missing parameter name".into());
    }
    crate::names::normalize(t)
        .map(|n| n.into_owned())
        .map_err(|e| {
            format!(
                "invalid parameter name {:?}: {}",
                t.chars().take(64).collect::<String>(),
                e.reason
            )
        })
}

/// [`param_name`], also taking `/` alone: the whole tree (a robot's namespace as its
/// agent sees it).
pub fn param_name_or_root(raw: &str) -> Result<String, String> {
    match raw.trim() {
        "/" => Ok("/".into()),
        other => param_name(other),
    }
}

/// The arguments of a parameter call (JSON text or CBOR) as JSON.
pub fn call_args(p: &fleetlink_proto::Payload) -> Option<Value> {
    use fleetlink_proto::Encoding;
    match p.encoding {
        Encoding::Json => serde_json::from_slice(&p.bytes).ok(),
        Encoding::Cbor => fleetlink_proto::rosbridge::convert::cbor_to_json(&p.bytes)
            .ok()
            .and_then(|j| serde_json::from_slice(&j).ok()),
        _ => None,
    }
}

/// `get_param`'s answer for a parameter that is not set: the caller's default (a JSON
/// text; rosapi names it `default` for ROS 1 and `default_value` for ROS 2), `null`
/// without one.
pub fn default_text(args: &Value) -> &str {
    ["default", "default_value"]
        .iter()
        .find_map(|k| {
            args.get(*k)
                .and_then(Value::as_str)
                .filter(|d| !d.is_empty())
        })
        .unwrap_or("null")
}

/// `set_param`'s `value` for parameter `name`: its JSON text and what it says. Refused
/// when missing, not JSON, or larger than 1 MiB.
pub fn value_to_set(args: &Value, name: &str) -> Result<(String, Value), String> {
    let text = match args.get("value") {
        Some(Value::String(s)) => s.clone(),
        Some(other) => other.to_string(),
        None => return Err("missing argument 'value' (a JSON text)".into()),
    };
    if text.len() > 1 << 20 {
        return Err(format!("value of {name} is larger than 1 MiB"));
    }
    let v = serde_json::from_str(&text)
        .map_err(|e| format!("value of {name} is not a JSON text: {e}"))?;
    Ok((text, v))
}

/// The value of `name`: the parameter itself, or the tree of parameters under it as an
/// object (`/a/b/c` = 1 gives `get /a` = `{"b": {"c": 1}}`).
pub fn lookup(all: &BTreeMap<String, String>, name: &str) -> Option<Value> {
    if let Some(v) = all.get(name) {
        return serde_json::from_str(v).ok();
    }
    let prefix = format!("{name}/");
    let mut tree = Map::new();
    let mut any = false;
    for (k, v) in all.range(prefix.clone()..) {
        let Some(rest) = k.strip_prefix(&prefix) else {
            break;
        };
        any = true;
        let value: Value = serde_json::from_str(v).unwrap_or(Value::Null);
        let mut node = &mut tree;
        let parts: Vec<&str> = rest.split('/').collect();
        for (i, p) in parts.iter().enumerate() {
            if i + 1 == parts.len() {
                node.insert((*p).to_owned(), value.clone());
            } else {
                let next = node
                    .entry((*p).to_owned())
                    .or_insert_with(|| Value::Object(Map::new()));
                if !next.is_object() {
                    *next = Value::Object(Map::new());
                }
                node = next.as_object_mut().expect("made an object above");
            }
        }
    }
    any.then_some(Value::Object(tree))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_prefix_reads_the_tree_below_it_and_delete_takes_the_tree() {
        let p = MemoryParams::default();
        p.set("/r1/max_speed", "1.5".into());
        p.set("/r1/nav/planner", "\"dwa\"".into());
        p.set("/r10/x", "1".into());
        let all = p.snapshot();
        assert_eq!(
            lookup(&all, "/r1"),
            Some(serde_json::json!({"max_speed": 1.5, "nav": {"planner": "dwa"}}))
        );
        assert_eq!(lookup(&all, "/r1/max_speed"), Some(serde_json::json!(1.5)));
        assert_eq!(lookup(&all, "/nope"), None);
        assert!(p.delete("/r1"));
        assert_eq!(p.snapshot().len(), 1, "/r10 is not under /r1");
    }

    #[test]
    fn names_are_normalised_and_bad_ones_refused() {
        assert_eq!(param_name("r1/speed/").unwrap(), "/r1/speed");
        assert!(param_name("a b").is_err());
        assert!(param_name("").is_err());
    }
}
