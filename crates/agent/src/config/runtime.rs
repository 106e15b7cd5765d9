//! Changes to a running agent's configuration (docs/runtime-config.md): a document in the
//! YAML file's own shape (JSON is YAML too) naming only the fields to change, each replaced
//! whole by its new value.
//!
//! A change is read exactly like the file: the same typed parse, the same checks on the
//! configuration it makes, so its errors have the same texts, with the line and column in
//! the change. Only what the agent can change while it runs may be written
//! ([`CHANGEABLE`]); anything else is refused naming the field.
//!
//! The changes in force are kept as an overlay: the same kind of document, holding every
//! field ever changed with the value it has now. The overlay is what is persisted on the
//! robot and kept by the hub; applied to the configuration the agent started with (its file
//! and flags), it gives the configuration the agent runs.

use serde_json::{Map, Value};

use super::locate::{FieldPath, LocationTree};
use super::{AgentConfig, ConfigError, SourcePos, field_error, parse_error, validate};

/// The fields a running agent changes without a restart.
pub const CHANGEABLE: &[&str] = &[
    "remap",
    "subscribe",
    "topics",
    "ros1.publish",
    "ros1.subscribe",
    "ros1.services",
    "ros2.publish",
    "ros2.subscribe",
    "ros2.read",
    "ros2.services",
    "ros2.actions",
];

/// A change that checked out.
#[derive(Debug, Clone)]
pub struct Changed {
    /// The configuration with the change.
    pub config: AgentConfig,
    /// The changes in force with this one (the overlay).
    pub overlay: Map<String, Value>,
    /// The fields the change wrote (from [`CHANGEABLE`]).
    pub fields: Vec<&'static str>,
}

/// Reads the change `text` (named `source` in errors) and applies it to `current`, the
/// configuration running with the changes `overlay`.
pub fn change(
    current: &AgentConfig,
    overlay: &Map<String, Value>,
    text: &str,
    source: &str,
) -> Result<Changed, ConfigError> {
    let text = if text.trim().is_empty() { "{}" } else { text };
    let parsed: AgentConfig =
        serde_saphyr::from_str(text).map_err(|e| parse_error(&e, text, source))?;
    let tree = LocationTree::parse(text).map_err(|e| parse_error(&e, text, source))?;
    let fields = written_fields(current, &tree, source)?;
    let mut config = current.clone();
    let mut overlay = overlay.clone();
    for field in &fields {
        copy_field(&mut config, &parsed, field);
    }
    let whole = serde_json::to_value(&config).unwrap_or(Value::Null);
    for field in &fields {
        put(&mut overlay, field, field_value(&whole, field));
    }
    validate::validate(&config).map_err(|problem| {
        if fields
            .iter()
            .any(|f| starts_with(&problem.path, &FieldPath::from(*f)))
        {
            field_error(problem, text, source)
        } else {
            ConfigError::Invalid {
                field: problem.path.to_string(),
                message: problem.message,
            }
        }
    })?;
    Ok(Changed {
        config,
        overlay,
        fields,
    })
}

/// The overlay as the text a change is written in (JSON, which the change reader takes).
pub fn overlay_text(overlay: &Map<String, Value>) -> String {
    serde_json::to_string_pretty(overlay).unwrap_or_else(|_| "{}".to_owned())
}

/// The changeable fields `tree` writes, in [`CHANGEABLE`]'s order; a field that cannot
/// change while the agent runs is an error at its key.
fn written_fields(
    current: &AgentConfig,
    tree: &LocationTree,
    source: &str,
) -> Result<Vec<&'static str>, ConfigError> {
    let at = |(line, column): (u64, u64), field: String, message: String| ConfigError::Field {
        at: SourcePos {
            file: source.to_owned(),
            line,
            column,
        },
        field,
        message,
    };
    let Some(top) = tree.keys_at(&[]) else {
        return Err(at(
            (1, 1),
            "(document)".into(),
            "a change is a mapping of the fields to change, for example \
             `topics: { /scan: { rate_limit_hz: 2 } }`"
                .into(),
        ));
    };
    let mut written = Vec::new();
    for (key, pos) in top {
        match key.as_str() {
            "remap" | "subscribe" | "topics" => written.push(key),
            "ros1" | "ros2" => {
                let running = match key.as_str() {
                    "ros1" => current.ros1.is_some(),
                    _ => current.ros2.is_some(),
                };
                if !running {
                    let bridge = if key == "ros1" { "ROS 1" } else { "ROS 2" };
                    return Err(at(
                        pos,
                        key.clone(),
                        format!(
                            "this agent runs no {bridge} bridge, so there is nothing of it to \
                             change; add a {key}: section to its YAML and restart it"
                        ),
                    ));
                }
                let Some(inner) = tree.keys_at(&[&key]) else {
                    return Err(at(
                        pos,
                        key.clone(),
                        format!(
                            "write the fields to change under it, for example \
                             `{key}: {{ publish: [/scan] }}`"
                        ),
                    ));
                };
                for (sub, sub_pos) in inner {
                    let path = format!("{key}.{sub}");
                    if !CHANGEABLE.contains(&path.as_str()) {
                        return Err(at(sub_pos, path, not_changeable()));
                    }
                    written.push(path);
                }
            }
            _ => return Err(at(pos, key, not_changeable())),
        }
    }
    Ok(CHANGEABLE
        .iter()
        .copied()
        .filter(|f| written.iter().any(|w| w == f))
        .collect())
}

fn not_changeable() -> String {
    format!(
        "cannot change while the agent runs (what can: {}); change it in the agent's YAML \
         and restart it",
        CHANGEABLE.join(", ")
    )
}

fn starts_with(path: &FieldPath, prefix: &FieldPath) -> bool {
    path.0.len() >= prefix.0.len() && path.0[..prefix.0.len()] == prefix.0[..]
}

/// Copies `field` of `from` into `to` (whose ROS sections exist: [`written_fields`]
/// checked).
fn copy_field(to: &mut AgentConfig, from: &AgentConfig, field: &str) {
    let (to1, from1) = (to.ros1.as_mut(), from.ros1.as_ref());
    let (to2, from2) = (to.ros2.as_mut(), from.ros2.as_ref());
    match (field, to1.zip(from1), to2.zip(from2)) {
        ("remap", ..) => to.remap = from.remap.clone(),
        ("subscribe", ..) => to.subscribe = from.subscribe.clone(),
        ("topics", ..) => to.topics = from.topics.clone(),
        ("ros1.publish", Some((t, f)), _) => t.publish = f.publish.clone(),
        ("ros1.subscribe", Some((t, f)), _) => t.subscribe = f.subscribe.clone(),
        ("ros1.services", Some((t, f)), _) => t.services = f.services.clone(),
        ("ros2.publish", _, Some((t, f))) => t.publish = f.publish.clone(),
        ("ros2.subscribe", _, Some((t, f))) => t.subscribe = f.subscribe.clone(),
        ("ros2.read", _, Some((t, f))) => t.read = f.read.clone(),
        ("ros2.services", _, Some((t, f))) => t.services = f.services.clone(),
        ("ros2.actions", _, Some((t, f))) => t.actions = f.actions.clone(),
        _ => {}
    }
}

/// `field`'s value in `whole` (a configuration as JSON), as the change document writes it.
fn field_value(whole: &Value, field: &str) -> Value {
    let pointer = format!("/{}", field.replace('.', "/"));
    let mut value = whole.pointer(&pointer).cloned().unwrap_or(Value::Null);
    drop_nulls(&mut value);
    value
}

/// Removes the unset optional fields (`null`s inside mappings): written out, the file reader
/// takes them for a value, left out, for what they are — unset.
fn drop_nulls(value: &mut Value) {
    match value {
        Value::Object(map) => {
            map.retain(|_, v| !v.is_null());
            map.values_mut().for_each(drop_nulls);
        }
        Value::Array(items) => items.iter_mut().for_each(drop_nulls),
        _ => {}
    }
}

/// Sets the dotted `field` of `doc` to `value`.
fn put(doc: &mut Map<String, Value>, field: &str, value: Value) {
    let mut keys = field.split('.').peekable();
    let mut map = doc;
    while let Some(k) = keys.next() {
        if keys.peek().is_none() {
            map.insert(k.to_owned(), value);
            return;
        }
        let entry = map
            .entry(k.to_owned())
            .or_insert_with(|| Value::Object(Map::new()));
        if !entry.is_object() {
            *entry = Value::Object(Map::new());
        }
        map = entry.as_object_mut().expect("made an object above");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn running() -> AgentConfig {
        AgentConfig::from_str(
            "ros2:\n  publish: [/a, /b]\ntopics:\n  /a: { priority: 3 }\n",
            "robot.yaml",
        )
        .expect("a valid file")
    }

    #[test]
    fn a_change_replaces_the_fields_it_writes_and_keeps_the_others() {
        let cfg = running();
        let c = change(
            &cfg,
            &Map::new(),
            "ros2: { publish: [/a, /c] }\ntopics: { /c: { rate_limit_hz: 2 } }\n",
            "change",
        )
        .expect("a valid change");
        assert_eq!(c.fields, vec!["topics", "ros2.publish"]);
        let r2 = c.config.ros2.as_ref().expect("ros2 kept");
        assert_eq!(r2.publish.include, vec!["/a", "/c"]);
        assert!(c.config.topics.contains_key("/c") && !c.config.topics.contains_key("/a"));
        assert_eq!(r2.discovery_ms, cfg.ros2.as_ref().unwrap().discovery_ms);
        // The overlay re-applied to the file's configuration gives the same.
        let again = change(&cfg, &Map::new(), &overlay_text(&c.overlay), "overlay").unwrap();
        assert_eq!(again.config, c.config);
        assert_eq!(again.overlay, c.overlay);
    }

    #[test]
    fn a_change_is_refused_with_the_files_error_text() {
        let cfg = running();
        let bad = "topics:\n  /a: { rate_limit_hz: 0 }\n";
        let from_change = change(&cfg, &Map::new(), bad, "change").unwrap_err();
        let from_file = AgentConfig::from_str(bad, "change").unwrap_err();
        assert_eq!(from_change.to_string(), from_file.to_string());
        assert!(
            from_change.to_string().starts_with("change:2:"),
            "{from_change}"
        );
        let typo = "topics:\n  /a: { rate_limit: 1 }\n";
        assert_eq!(
            change(&cfg, &Map::new(), typo, "change")
                .unwrap_err()
                .to_string(),
            AgentConfig::from_str(typo, "change")
                .unwrap_err()
                .to_string()
        );
    }

    #[test]
    fn fields_that_need_a_restart_are_refused_by_name() {
        let cfg = running();
        let e = change(&cfg, &Map::new(), "hub: ws://other:8080\n", "change").unwrap_err();
        assert_eq!(e.field(), Some("hub"));
        assert!(e.to_string().contains("restart"), "{e}");
        let e = change(&cfg, &Map::new(), "ros2: { domain_id: 3 }\n", "change").unwrap_err();
        assert_eq!(e.field(), Some("ros2.domain_id"));
        let e = change(&cfg, &Map::new(), "ros1: { publish: [/x] }\n", "change").unwrap_err();
        assert!(e.to_string().contains("no ROS 1 bridge"), "{e}");
    }

    #[test]
    fn changes_accumulate_in_the_overlay() {
        let cfg = running();
        let one = change(&cfg, &Map::new(), "ros2: { subscribe: [/cmd] }", "c").unwrap();
        let two = change(
            &one.config,
            &one.overlay,
            "{\"remap\": {\"/a\": \"/x/a\"}}",
            "c",
        )
        .unwrap();
        assert_eq!(two.config.ros2.as_ref().unwrap().subscribe, vec!["/cmd"]);
        assert_eq!(two.config.remap.get("/a").map(String::as_str), Some("/x/a"));
        assert!(two.overlay.contains_key("remap") && two.overlay.contains_key("ros2"));
        let restored = change(&cfg, &Map::new(), &overlay_text(&two.overlay), "o").unwrap();
        assert_eq!(restored.config, two.config);
    }

    proptest::proptest! {
        /// Whatever a change says, reading it never panics; a change that is taken gives a
        /// configuration that checks out and that its overlay, applied to the file's
        /// configuration, gives again; one that is refused says why.
        #[test]
        fn any_change_is_taken_whole_or_refused_with_a_reason(
            entries in proptest::collection::vec(
                (
                    proptest::sample::select(vec![
                        "remap", "subscribe", "topics", "ros2", "ros1", "hub", "name", "sim",
                        "ros2.publish", "ros2.subscribe", "ros2.services", "ros2.actions",
                        "ros2.read", "ros2.domain_id", "topics./a", "topics./a.rate_limit_hz",
                        "topics./a.priority", "topics./a.policy", "remap./a",
                    ]),
                    proptest::sample::select(vec![
                        "[/a, /b]", "[]", "{}", "0", "2", "-1", "latest", "/x/a", "null",
                        "{ include: [/a], exclude: [/b] }", "[{ hub: /h, local: /l }]",
                        "{ rate_limit_hz: 2 }", "\"bad name\"", "[1, 2]", "{ x: 1 }",
                    ]),
                ),
                0..5,
            )
        ) {
            let cfg = running();
            // Dotted keys become nested mappings, written in flow style.
            let mut doc = serde_json::Map::new();
            let mut text = String::new();
            for (key, value) in &entries {
                let mut parts: Vec<&str> = key.split('.').collect();
                if key.starts_with("topics./") || key.starts_with("remap./") {
                    let (section, rest) = key.split_once('.').unwrap();
                    let mut p = vec![section];
                    p.extend(rest.splitn(2, '.'));
                    parts = p;
                }
                let mut line = String::new();
                for p in &parts[..parts.len() - 1] {
                    line.push_str(&format!("{p}: {{ "));
                }
                line.push_str(&format!("{}: {value}", parts[parts.len() - 1]));
                for _ in 1..parts.len() {
                    line.push_str(" }");
                }
                // One key once: a second would be a duplicate, which the parser refuses too.
                if doc.insert(parts[0].to_owned(), Value::Null).is_none() {
                    text.push_str(&line);
                    text.push('\n');
                }
            }
            match change(&cfg, &Map::new(), &text, "change") {
                Ok(c) => {
                    proptest::prop_assert!(c.config.validate().is_ok());
                    let again = change(&cfg, &Map::new(), &overlay_text(&c.overlay), "overlay");
                    proptest::prop_assert!(again.is_ok(), "{:?} from {}", again, overlay_text(&c.overlay));
                    proptest::prop_assert_eq!(again.unwrap().config, c.config);
                }
                Err(e) => {
                    let said = e.to_string();
                    proptest::prop_assert!(!said.is_empty() && (e.field().is_some() || e.position().is_some()), "{}", said);
                }
            }
        }
    }
}
