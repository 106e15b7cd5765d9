//! The configuration that will run, as YAML, each field marked with where it came from:
//! the file, a kept change (when and by whom), the environment (`ROS_DOMAIN_ID`, ...), a
//! command-line flag, or a default. `fleetlink agent --check` prints it, the agent logs it
//! at start and its configuration API shows it, so what runs is never a guess.
//!
//! Fields the agent resolves from the environment when the file leaves them out are shown
//! with the value they resolve to. Entries a kept change removed are shown as comments
//! where they were, so a list that lost a name says so.

use std::collections::BTreeMap;
use std::fmt;

use serde_json::{Map, Value, json};

use super::locate::{FieldPath, LocationTree, Segment};
use super::runtime::entry::{Entry, LISTS};
use super::runtime::kept::KeptEntry;
use super::{AgentConfig, ConfigSource};

/// Where a field's value came from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Origin {
    Default,
    File,
    /// Set on the command line by this flag.
    Flag(&'static str),
    /// Resolved from this environment variable.
    Environment(&'static str),
    /// A change made while the agent ran, kept: when and by whom.
    Kept(String),
}

impl fmt::Display for Origin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Origin::Default => f.write_str("default"),
            Origin::File => f.write_str("file"),
            Origin::Flag(flag) => write!(f, "command line: {flag}"),
            Origin::Environment(var) => write!(f, "environment: {var}"),
            Origin::Kept(when) => write!(f, "kept change, {when}"),
        }
    }
}

/// `cfg` (read from `source`, with the changes `kept` in force) as YAML with each field's
/// origin in a comment.
pub fn annotated_yaml(cfg: &AgentConfig, source: &ConfigSource, kept: &[KeptEntry]) -> String {
    let mut value = match cfg.effective_value() {
        Ok(v) => v,
        Err(e) => return format!("# cannot show the configuration: {e}\n"),
    };
    let mut env = BTreeMap::new();
    resolve_environment(cfg, &mut value, &mut env);
    let reference = source.is_rosgw().then(|| {
        // A ROS Gateway file's fields are not the agent's: a field is the file's where it
        // differs from the agent's default for it.
        let d = AgentConfig {
            ros1: cfg.ros1.as_ref().map(|_| Default::default()),
            ros2: cfg.ros2.as_ref().map(|_| Default::default()),
            rosbridge: cfg.rosbridge.as_ref().map(|_| Default::default()),
            ..AgentConfig::default()
        };
        d.effective_value().unwrap_or(Value::Null)
    });
    let view = View {
        tree: source.tree(),
        reference,
        shown: value.clone(),
        source,
        kept,
        env,
    };
    let mut out = String::new();
    if let Value::Object(map) = &value {
        view.map(&mut out, map, &FieldPath::default(), 0, None);
    }
    out
}

struct View<'a> {
    tree: Option<LocationTree>,
    reference: Option<Value>,
    /// The whole configuration shown.
    shown: Value,
    source: &'a ConfigSource,
    kept: &'a [KeptEntry],
    /// Fields resolved from the environment, by path.
    env: BTreeMap<String, Origin>,
}

impl View<'_> {
    fn map(
        &self,
        out: &mut String,
        map: &Map<String, Value>,
        path: &FieldPath,
        indent: usize,
        item: Option<&Value>,
    ) {
        // A topic's unset QoS fields are left out (they take its type's defaults).
        let in_topic =
            matches!(path.0.as_slice(), [Segment::Key(t), Segment::Key(_)] if t == "topics");
        for (key, value) in map {
            if in_topic && value.is_null() {
                continue;
            }
            let here = path.key(key.clone());
            let key = scalar(&Value::String(key.clone()));
            match value {
                Value::Object(inner) if !inner.is_empty() => {
                    line(out, indent, &format!("{key}:"), None);
                    self.map(out, inner, &here, indent + 2, item);
                }
                Value::Array(items) if !items.is_empty() => {
                    line(out, indent, &format!("{key}:"), None);
                    self.seq(out, items, &here, indent + 2);
                }
                _ => {
                    let origin = self.origin(&here, item);
                    line(
                        out,
                        indent,
                        &format!("{key}: {}", scalar(value)),
                        Some(&origin),
                    );
                }
            }
            self.removed(out, &here, value, indent + 2);
        }
    }

    fn seq(&self, out: &mut String, items: &[Value], path: &FieldPath, indent: usize) {
        for (i, it) in items.iter().enumerate() {
            let here = path.index(i);
            match it {
                Value::Object(inner) if !inner.is_empty() => {
                    let mut block = String::new();
                    self.map(&mut block, inner, &here, indent + 2, Some(it));
                    // The first key goes on the dash's line.
                    let pad = " ".repeat(indent + 2);
                    let first = format!("{}- ", " ".repeat(indent));
                    out.push_str(&block.replacen(&pad, &first, 1));
                }
                _ => {
                    let origin = self.origin(&here, Some(it));
                    line(out, indent, &format!("- {}", scalar(it)), Some(&origin));
                }
            }
        }
    }

    /// Comments for what kept changes removed from the list or mapping at `path`.
    fn removed(&self, out: &mut String, path: &FieldPath, shown: &Value, indent: usize) {
        let at = path.to_string();
        for k in self.kept {
            let text = match (&k.entry, &k.value) {
                (Entry::Name { list, name }, Value::Bool(false)) if *list == at => {
                    format!("- {}", scalar(&Value::String(name.clone())))
                }
                (Entry::Subscribe { hub, local }, Value::Bool(false)) if at == "subscribe" => {
                    format!("- {{ hub: {hub}, local: {local} }}")
                }
                (Entry::Remap { local }, Value::Null) if at == "remap" => {
                    format!("{}: …", scalar(&Value::String(local.clone())))
                }
                (Entry::Qos { topic, field }, Value::Null)
                    if at == "topics" && shown.get(topic).is_none() =>
                {
                    format!(
                        "{}: {{ {field}: … }}",
                        scalar(&Value::String(topic.clone()))
                    )
                }
                (Entry::Qos { topic, field }, Value::Null)
                    if at
                        == FieldPath::default()
                            .key("topics")
                            .key(topic.clone())
                            .to_string() =>
                {
                    format!("{field}: …")
                }
                _ => continue,
            };
            let origin = format!("removed by a kept change, {}", k.when_and_who());
            out.push_str(&format!("{}# {text}  ({origin})\n", " ".repeat(indent)));
        }
    }

    fn origin(&self, path: &FieldPath, item: Option<&Value>) -> Origin {
        if let Some(entry) = entry_at(path, item)
            && let Some(k) = self.kept.iter().find(|k| k.entry == entry)
        {
            return Origin::Kept(k.when_and_who());
        }
        if let Some(Segment::Key(top)) = path.0.first()
            && let Some(flag) = self.source.flag_for(top)
        {
            return Origin::Flag(flag);
        }
        if let Some(origin) = self.env.get(&path.to_string()) {
            return origin.clone();
        }
        let written = match (&self.tree, &self.reference) {
            (Some(tree), _) => tree.written(path),
            (None, Some(reference)) => value_at(reference, path) != value_at(&self.shown, path),
            (None, None) => false,
        };
        if written {
            Origin::File
        } else {
            Origin::Default
        }
    }
}

/// The entry a field of the configuration belongs to (`item`: the list item it is in).
fn entry_at(path: &FieldPath, item: Option<&Value>) -> Option<Entry> {
    let keys: Vec<&str> = path
        .0
        .iter()
        .map_while(|s| match s {
            Segment::Key(k) => Some(k.as_str()),
            Segment::Index(_) => None,
        })
        .collect();
    let text = |v: &Value, k: &str| v.get(k).and_then(Value::as_str).map(str::to_owned);
    match keys.as_slice() {
        ["topics", topic, field] => Some(Entry::Qos {
            topic: (*topic).to_owned(),
            field: (*field).to_owned(),
        }),
        ["remap", local] => Some(Entry::Remap {
            local: (*local).to_owned(),
        }),
        ["subscribe"] => {
            let item = item?;
            Some(Entry::Subscribe {
                hub: text(item, "hub")?,
                local: text(item, "local")?,
            })
        }
        _ => {
            let joined = keys.join(".");
            let list = LISTS.iter().copied().find(|l| *l == joined)?;
            Some(Entry::Name {
                list,
                name: item?.as_str()?.to_owned(),
            })
        }
    }
}

fn value_at<'a>(value: &'a Value, path: &FieldPath) -> Option<&'a Value> {
    path.0.iter().try_fold(value, |v, s| match s {
        Segment::Key(k) => v.get(k),
        Segment::Index(i) => v.get(i),
    })
}

/// Fields the agent resolves from the environment when the file leaves them out, with the
/// value they resolve to (the same resolution as the agent's, see `crate::agent`).
fn resolve_environment(cfg: &AgentConfig, value: &mut Value, env: &mut BTreeMap<String, Origin>) {
    let set_by = |vars: &[&'static str]| {
        vars.iter()
            .copied()
            .find(|v| std::env::var(v).is_ok_and(|s| !s.trim().is_empty()))
            .map_or(Origin::Default, Origin::Environment)
    };
    let mut put = |pointer: &str, v: Value, origin: Origin| {
        if let Some(slot) = value.pointer_mut(pointer) {
            *slot = v;
            let path = pointer.trim_start_matches('/').replace('/', ".");
            env.insert(path, origin);
        }
    };
    let node = format!("/fleetlink_{}", cfg.name);
    if let Some(r) = &cfg.ros1 {
        if r.master_uri.is_none() {
            let uri = fleetlink_ros1::Ros1Options::default_master_uri();
            put("/ros1/master_uri", json!(uri), set_by(&["ROS_MASTER_URI"]));
        }
        if r.host.is_none() {
            let host = fleetlink_ros1::Ros1Options::default_host();
            put(
                "/ros1/host",
                json!(host),
                set_by(&["ROS_HOSTNAME", "ROS_IP"]),
            );
        }
        if r.node_name.is_none() {
            put("/ros1/node_name", json!(node), Origin::Default);
        }
    }
    if let Some(r) = &cfg.ros2 {
        if r.domain_id.is_none() {
            let id = fleetlink_ros2::Ros2Options::default_domain_id().ok();
            put("/ros2/domain_id", json!(id), set_by(&["ROS_DOMAIN_ID"]));
        }
        if r.distro.is_none() {
            let distro = std::env::var("ROS_DISTRO")
                .ok()
                .filter(|d| !d.trim().is_empty());
            put("/ros2/distro", json!(distro), set_by(&["ROS_DISTRO"]));
        }
        if r.node_name.is_none() {
            put("/ros2/node_name", json!(node), Origin::Default);
        }
    }
    if cfg.runtime_file.is_none() {
        let (path, var) = cfg.runtime_file_from();
        let origin = var.map_or(Origin::Default, Origin::Environment);
        put("/runtime_file", json!(path), origin);
    }
}

/// A scalar (or an empty list or mapping) as YAML writes it.
fn scalar(value: &Value) -> String {
    match value {
        Value::Array(a) if a.is_empty() => "[]".to_owned(),
        Value::Object(m) if m.is_empty() => "{}".to_owned(),
        // One line, so that its origin can follow it: a string the YAML writer would fold
        // is written double-quoted (JSON's quoting is YAML's).
        _ => match serde_saphyr::to_string(value) {
            Ok(s) if !s.trim_end().contains('\n') => s.trim_end().to_owned(),
            _ => value.to_string(),
        },
    }
}

fn line(out: &mut String, indent: usize, text: &str, origin: Option<&Origin>) {
    out.push_str(&" ".repeat(indent));
    out.push_str(text);
    if let Some(o) = origin {
        out.push_str("  # ");
        out.push_str(&o.to_string());
    }
    out.push('\n');
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::runtime;

    #[test]
    fn each_field_says_where_it_came_from() {
        let text = "name: robot7\nros2:\n  publish: [/a, /b]\ntopics:\n  /a: { priority: 3 }\n";
        let file = AgentConfig::from_str(text, "robot.yaml").unwrap();
        let source = ConfigSource {
            path: Some("robot.yaml".into()),
            text: text.into(),
            flags: vec![("hub", "--hub")],
        };
        let changed = runtime::change(
            &file,
            &file,
            &[],
            "topics: { /a: { rate_limit_hz: 2 } }\nremove: { ros2: { publish: [/b] } }",
            "change",
            "user:ana",
            1_718_000_000_000,
        )
        .unwrap();
        let shown = annotated_yaml(&changed.config, &source, &changed.kept);
        let line_of = |needle: &str| {
            shown
                .lines()
                .find(|l| l.contains(needle))
                .unwrap_or_else(|| panic!("no {needle:?} in\n{shown}"))
                .to_owned()
        };
        assert!(line_of("name: robot7").ends_with("# file"), "{shown}");
        assert!(line_of("heartbeat_ms: 1000").ends_with("# default"));
        assert!(line_of("- ws://").ends_with("# command line: --hub"));
        assert!(line_of("priority: 3").ends_with("# file"));
        assert!(
            line_of("rate_limit_hz: 2").contains("# kept change, 2024-06-10T06:13:20Z by user:ana"),
            "{shown}"
        );
        assert!(line_of("- /a").ends_with("# file"));
        assert!(line_of("# - /b").contains("removed by a kept change"));
        assert!(line_of("runtime_file:").contains("# "));
        // Still YAML: the comments aside, it reads back as the same configuration.
        let back: AgentConfig = serde_saphyr::from_str(&shown).unwrap();
        assert_eq!(back.topics, changed.config.topics);
    }
}
