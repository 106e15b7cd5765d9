//! Changes to a running agent's configuration (docs/runtime-config.md): a document in the
//! YAML file's own shape (JSON is YAML too) naming only what changes.
//!
//! A change merges with the configuration entry by entry ([`entry`]): a topic's QoS field,
//! a `remap` entry, a `subscribe` entry, a name of a bridge's list, a field of a camera's
//! video stream. Writing `/pose` under
//! `topics` changes the fields of `/pose` it writes and nothing else; a name written in a
//! list is added to it. Removing is an operation of its own, written under `remove:` in the
//! same shape (`remove: { topics: [/pose], video: [/camera/image_raw], ros2: { publish:
//! [/scan] } }`), applied before what the change sets; a QoS or video field written `null`
//! is unset (a video field then takes its default).
//!
//! A change is read like the file: the same typed parse, the same checks on what it writes
//! and on the configuration it makes, so its errors have the same texts, with the line and
//! column in the change. Only what the agent can change while it runs may be written
//! ([`CHANGEABLE`]); anything else is refused naming the field. No change turns a topic's
//! `no_drop` on or off: that is the file's alone ([`no_drop_flips`]).
//!
//! The changes in force are the entries where the running configuration differs from the
//! file's ([`kept`]): what is kept on the robot and by the hub, with when and by whom each
//! entry was changed and what the file said then, so that they merge again with the file
//! at the next start, also with a file that changed meanwhile.

pub mod entry;
pub mod kept;

use std::collections::BTreeMap;

use fleetlink_qos::TopicQosSpec;
use serde::Deserialize;
use serde_json::Value;

use super::locate::{FieldPath, LocationTree, Segment};
use super::{
    AgentConfig, ConfigError, Ros1Config, Ros2Config, SourcePos, Subscription, field_error,
    parse_error, validate,
};
use entry::{Entry, VideoField, lists, qos_fields};
use kept::KeptEntry;

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
    "video",
];

/// A change that checked out.
#[derive(Debug, Clone)]
pub struct Changed {
    /// The configuration with the change.
    pub config: AgentConfig,
    /// The changes in force with this one.
    pub kept: Vec<KeptEntry>,
    /// The fields the change wrote (from [`CHANGEABLE`]).
    pub fields: Vec<&'static str>,
}

/// Reads the change `text` (named `source` in errors) and applies it to `current`, the
/// configuration running with the changes `kept` on top of `file` (the configuration the
/// agent started with). `by` and `at_ms` are recorded with the entries it changes.
pub fn change(
    file: &AgentConfig,
    current: &AgentConfig,
    kept: &[KeptEntry],
    text: &str,
    source: &str,
    by: &str,
    at_ms: u64,
) -> Result<Changed, ConfigError> {
    let written = read(text, source, Some(current))?;
    let text = written.text.as_str();
    let mut config = current.clone();
    for (entry, value) in &written.sets {
        entry
            .set(&mut config, value)
            .map_err(|message| ConfigError::Invalid {
                field: entry.to_string(),
                message,
            })?;
    }
    if let Some(flip) = no_drop_flips(file, &config).into_iter().next() {
        let topic = FieldPath::default().key("topics").key(flip.topic.clone());
        let at = if written.tree.keys_at(&["topics", &flip.topic]).is_some() {
            topic.clone()
        } else {
            FieldPath::from("remove.topics")
        };
        let (line, column) = written.tree.position_of(&at, true);
        return Err(ConfigError::Field {
            at: SourcePos {
                file: source.to_owned(),
                line,
                column,
            },
            field: topic.key("no_drop").to_string(),
            message: flip.refusal(),
        });
    }
    validate::validate(&config).map_err(|problem| {
        let path = problem.path.to_string();
        if written.fields.iter().any(|f| path.starts_with(f)) {
            field_error(problem, text, source)
        } else {
            ConfigError::Invalid {
                field: path,
                message: problem.message,
            }
        }
    })?;
    Ok(Changed {
        kept: kept::carry(file, &config, kept, by, at_ms),
        config,
        fields: written.fields,
    })
}

/// What a change writes.
pub(crate) struct Written {
    /// The entries it sets, with their values: its removals first, then what it writes.
    pub(crate) sets: Vec<(Entry, Value)>,
    /// The changeable fields it writes, in [`CHANGEABLE`]'s order.
    pub(crate) fields: Vec<&'static str>,
    pub(crate) text: String,
    tree: LocationTree,
}

/// A change as written: the changeable fields of the file, and `remove:`.
#[derive(Debug, Default, Deserialize)]
#[serde(default, deny_unknown_fields)]
struct ChangeDoc {
    remap: BTreeMap<String, String>,
    subscribe: Vec<Subscription>,
    topics: BTreeMap<String, TopicQosSpec>,
    ros1: Option<Ros1Config>,
    ros2: Option<Ros2Config>,
    video: BTreeMap<String, VideoChange>,
    remove: Removal,
}

/// A camera's video stream as a change writes it: only the fields it changes
/// (`VideoStreamConfig`'s, which the whole configuration's checks then read).
#[derive(Debug, Default, Deserialize, serde::Serialize)]
#[serde(default, deny_unknown_fields)]
struct VideoChange {
    #[serde(skip_serializing_if = "Option::is_none")]
    topic: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    fps: Option<f32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    bitrate_kbps: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    min_bitrate_kbps: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    keyframe_s: Option<f32>,
}

/// `remove:` — entries to remove, written as they are written to add them; `topics` and
/// `remap` by their topic names.
#[derive(Debug, Default, Deserialize)]
#[serde(default, deny_unknown_fields)]
struct Removal {
    remap: Vec<String>,
    subscribe: Vec<Subscription>,
    topics: Vec<String>,
    ros1: Option<Ros1Config>,
    ros2: Option<Ros2Config>,
    /// Camera topics whose video stream goes.
    video: Vec<String>,
}

/// Reads a change: its shape (only changeable fields; with `running`, only bridges it
/// runs), its typed values, and the checks the file's lines would get.
pub(crate) fn read(
    text: &str,
    source: &str,
    running: Option<&AgentConfig>,
) -> Result<Written, ConfigError> {
    let text = if text.trim().is_empty() { "{}" } else { text };
    let tree = LocationTree::parse(text).map_err(|e| parse_error(&e, text, source))?;
    let mut fields = written_fields(&tree, &[], running, source)?;
    if tree.keys_at(&["remove"]).is_some() {
        fields.extend(written_fields(&tree, &["remove"], running, source)?);
    }
    let doc: ChangeDoc = serde_saphyr::from_str(text).map_err(|e| parse_error(&e, text, source))?;
    // What the change writes, checked as the same lines of a file would be.
    let alone = AgentConfig {
        remap: doc.remap.clone(),
        subscribe: doc.subscribe.clone(),
        topics: doc.topics.clone(),
        ros1: doc.ros1.clone(),
        ros2: doc.ros2.clone(),
        ..AgentConfig::default()
    };
    validate::validate(&alone).map_err(|problem| field_error(problem, text, source))?;

    let mut sets = Vec::new();
    let unset = qos_fields(&TopicQosSpec::default());
    for topic in &doc.remove.topics {
        for field in unset.keys() {
            let entry = Entry::Qos {
                topic: topic.clone(),
                field: field.clone(),
            };
            sets.push((entry, Value::Null));
        }
    }
    for camera in &doc.remove.video {
        let entry = Entry::Video {
            camera: camera.clone(),
            field: VideoField::Topic,
        };
        sets.push((entry, Value::Null));
    }
    for local in &doc.remove.remap {
        sets.push((
            Entry::Remap {
                local: local.clone(),
            },
            Value::Null,
        ));
    }
    let removed = AgentConfig {
        ros1: doc.remove.ros1.clone(),
        ros2: doc.remove.ros2.clone(),
        subscribe: doc.remove.subscribe.clone(),
        ..AgentConfig::default()
    };
    push_memberships(&mut sets, &removed, false);
    for (topic, spec) in &doc.topics {
        let values = qos_fields(spec);
        for (field, _) in tree.keys_at(&["topics", topic]).unwrap_or_default() {
            let value = values.get(&field).cloned().unwrap_or(Value::Null);
            sets.push((
                Entry::Qos {
                    topic: topic.clone(),
                    field,
                },
                value,
            ));
        }
    }
    for (camera, change) in &doc.video {
        let values = match serde_json::to_value(change) {
            Ok(Value::Object(map)) => map,
            _ => serde_json::Map::new(),
        };
        // The typed parse took only known keys; the topic first ([`VideoField`]).
        let mut written: Vec<VideoField> = tree
            .keys_at(&["video", camera])
            .unwrap_or_default()
            .iter()
            .filter_map(|(key, _)| VideoField::of(key))
            .collect();
        written.sort();
        for field in written {
            let value = values.get(field.as_str()).cloned().unwrap_or(Value::Null);
            let entry = Entry::Video {
                camera: camera.clone(),
                field,
            };
            sets.push((entry, value));
        }
    }
    for (local, hub) in &doc.remap {
        sets.push((
            Entry::Remap {
                local: local.clone(),
            },
            Value::String(hub.clone()),
        ));
    }
    push_memberships(&mut sets, &alone, true);
    let fields = CHANGEABLE
        .iter()
        .copied()
        .filter(|f| fields.iter().any(|w| w == f))
        .collect();
    Ok(Written {
        sets,
        fields,
        text: text.to_owned(),
        tree,
    })
}

/// Every `subscribe` entry and bridge list name of `cfg`, as present (`true`) or not.
fn push_memberships(sets: &mut Vec<(Entry, Value)>, cfg: &AgentConfig, present: bool) {
    for s in &cfg.subscribe {
        let entry = Entry::Subscribe {
            hub: s.hub.clone(),
            local: s.local.clone(),
        };
        sets.push((entry, Value::Bool(present)));
    }
    for (list, names) in lists(cfg) {
        for name in names {
            let entry = Entry::Name {
                list,
                name: name.clone(),
            };
            sets.push((entry, Value::Bool(present)));
        }
    }
}

/// The changeable fields the mapping at `under` (the document, or `remove:`) writes; a
/// field that cannot change while the agent runs is an error at its key. Keys that are
/// no field at all are left to the typed parse, which names the ones a change may write.
fn written_fields(
    tree: &LocationTree,
    under: &[&str],
    running: Option<&AgentConfig>,
    source: &str,
) -> Result<Vec<String>, ConfigError> {
    let at = |(line, column): (u64, u64), field: String, message: String| ConfigError::Field {
        at: SourcePos {
            file: source.to_owned(),
            line,
            column,
        },
        field,
        message,
    };
    let prefix = |key: &str| {
        under
            .iter()
            .chain(std::iter::once(&key))
            .copied()
            .collect::<Vec<_>>()
            .join(".")
    };
    let Some(top) = tree.keys_at(under) else {
        let path = under.iter().fold(FieldPath::default(), |p, k| p.key(*k));
        return Err(at(
            tree.position_of(&path, false),
            if under.is_empty() {
                "(document)".into()
            } else {
                under.join(".")
            },
            "a change is a mapping of the fields to change, for example \
             `topics: { /scan: { rate_limit_hz: 2 } }`, or to remove, for example \
             `remove: { ros2: { publish: [/scan] } }`"
                .into(),
        ));
    };
    let config_fields = field_names(&AgentConfig::default());
    let mut written = Vec::new();
    for (key, pos) in top {
        match key.as_str() {
            "remap" | "subscribe" | "topics" | "video" => written.push(key),
            "remove" if under.is_empty() => {}
            "ros1" | "ros2" => {
                if let Some(cfg) = running {
                    let runs = if key == "ros1" {
                        cfg.ros1.is_some()
                    } else {
                        cfg.ros2.is_some()
                    };
                    if !runs {
                        let bridge = if key == "ros1" { "ROS 1" } else { "ROS 2" };
                        return Err(at(
                            pos,
                            prefix(&key),
                            format!(
                                "this agent runs no {bridge} bridge, so there is nothing of it \
                                 to change; add a {key}: section to its YAML and restart it"
                            ),
                        ));
                    }
                }
                let mut path = under.to_vec();
                path.push(&key);
                let Some(inner) = tree.keys_at(&path) else {
                    return Err(at(
                        pos,
                        prefix(&key),
                        format!(
                            "write the fields to change under it, for example \
                             `{key}: {{ publish: [/scan] }}`"
                        ),
                    ));
                };
                let section_fields = if key == "ros1" {
                    field_names(&Ros1Config::default())
                } else {
                    field_names(&Ros2Config::default())
                };
                for (sub, sub_pos) in inner {
                    let field = format!("{key}.{sub}");
                    if CHANGEABLE.contains(&field.as_str()) {
                        written.push(field);
                    } else if section_fields.contains(&sub) {
                        return Err(at(sub_pos, prefix(&field), not_changeable()));
                    }
                }
            }
            other if config_fields.iter().any(|f| f == other) => {
                return Err(at(pos, prefix(&key), not_changeable()));
            }
            _ => {}
        }
    }
    Ok(written)
}

/// The field names of a configuration section, as the file writes them.
fn field_names<T: serde::Serialize>(section: &T) -> Vec<String> {
    match serde_json::to_value(section) {
        Ok(Value::Object(map)) => map.keys().cloned().collect(),
        _ => Vec::new(),
    }
}

fn not_changeable() -> String {
    format!(
        "cannot change while the agent runs (what can: {}); change it in the agent's YAML \
         and restart it",
        CHANGEABLE.join(", ")
    )
}

/// A topic whose `no_drop` one configuration decides otherwise than another.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NoDropFlip {
    pub topic: String,
    /// Whether the topic would be no_drop with the change (where it differs).
    pub on: bool,
    /// Only for topics no_drop by default (by their name or type: `/map`, `/tf_static`,
    /// `nav_msgs/OccupancyGrid`): the change ends that default.
    pub default_only: bool,
}

impl NoDropFlip {
    /// What is wrong, and what to do instead.
    pub fn refusal(&self) -> String {
        let what = if self.default_only {
            format!(
                "this would end the no_drop that {} has by default (topics named map or \
                 tf_static, and map types, are no_drop unless the file says otherwise; a \
                 dropping policy, mode: pull or max_age ends it)",
                self.topic
            )
        } else {
            format!(
                "this would turn no_drop {} for {}",
                if self.on { "on" } else { "off" },
                self.topic
            )
        };
        format!(
            "{what}, and no_drop is the agent's YAML file's alone: a no_drop topic's messages \
             are numbered and kept until the hub confirms them, from the agent's start. Set \
             it for {} in the YAML file and restart the agent",
            self.topic
        )
    }
}

/// The topics whose `no_drop` `to` decides otherwise than `file`, for a topic of any type
/// (a topic's type, which may make it no_drop by default, is known only when it flows).
pub fn no_drop_flips(file: &AgentConfig, to: &AgentConfig) -> Vec<NoDropFlip> {
    let mut topics: Vec<&String> = file.topics.keys().chain(to.topics.keys()).collect();
    topics.sort();
    topics.dedup();
    let outcome = |cfg: &AgentConfig, topic: &str, base: bool| {
        cfg.topics
            .get(topic)
            .map_or(base, |spec| spec.no_drop_with(base))
    };
    topics
        .into_iter()
        .filter_map(|topic| {
            let differs = |base| outcome(file, topic, base) != outcome(to, topic, base);
            let (plain, by_default) = (differs(false), differs(true));
            (plain || by_default).then(|| NoDropFlip {
                topic: topic.clone(),
                on: outcome(to, topic, !plain),
                default_only: !plain,
            })
        })
        .collect()
}

/// Whether `path` is at or inside the entry `entry` of `cfg` (to tell which entry a
/// problem found in `cfg` is about).
pub(crate) fn path_is_in(path: &FieldPath, entry: &Entry, cfg: &AgentConfig) -> bool {
    let keys: Vec<Option<&str>> = path
        .0
        .iter()
        .map(|s| match s {
            Segment::Key(k) => Some(k.as_str()),
            Segment::Index(_) => None,
        })
        .collect();
    let index = path.0.iter().find_map(|s| match s {
        Segment::Index(i) => Some(*i),
        Segment::Key(_) => None,
    });
    match entry {
        Entry::Qos { topic, .. } => keys.get(..2) == Some(&[Some("topics"), Some(topic)]),
        Entry::Remap { local } => keys.get(..2) == Some(&[Some("remap"), Some(local)]),
        Entry::Video { camera, .. } => keys.get(..2) == Some(&[Some("video"), Some(camera)]),
        Entry::Subscribe { hub, local } => {
            keys.first() == Some(&Some("subscribe"))
                && index
                    .and_then(|i| cfg.subscribe.get(i))
                    .is_some_and(|s| s.hub == *hub && s.local == *local)
        }
        Entry::Name { list, name } => {
            let at: Vec<&str> = keys.iter().map_while(|k| *k).collect();
            at.join(".") == *list
                && index
                    .and_then(|i| {
                        lists(cfg)
                            .into_iter()
                            .find(|(l, _)| l == list)
                            .and_then(|(_, names)| names.get(i))
                    })
                    .is_some_and(|n| n == name)
        }
    }
}

#[cfg(test)]
mod tests;
