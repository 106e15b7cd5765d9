//! The entries a configuration's changeable part is made of, and kept changes merge at:
//! one field of one topic's QoS (`topics["/pose"].rate_limit_hz`), one `remap` entry, one
//! `subscribe` entry, one name of a bridge's list (`/scan` in `ros2.publish.include`), one
//! field of one camera's video stream (`video["/camera/image_raw"].bitrate_kbps`).
//!
//! A configuration is read and written entry by entry, so a change to `/pose` touches
//! `/pose` alone, and the changes in force are exactly the entries where the running
//! configuration differs from its file ([`diff`]). An entry's value is JSON: a QoS field's,
//! a video field's or a remap's value (`null`: not set), or whether a list holds a name
//! (`true`/`false`). A camera has a video stream while its `topic` is set.

use std::collections::BTreeSet;
use std::fmt;

use fleetlink_qos::TopicQosSpec;
use serde_json::{Map, Value};

use crate::config::{AgentConfig, Subscription, VideoStreamConfig};

/// The bridges' lists a running agent changes, by the path a change writes them at.
pub const LISTS: &[&str] = &[
    "ros1.publish.include",
    "ros1.publish.exclude",
    "ros1.subscribe",
    "ros1.services.expose",
    "ros1.services.exclude",
    "ros1.services.offer",
    "ros2.publish.include",
    "ros2.publish.exclude",
    "ros2.subscribe",
    "ros2.read",
    "ros2.services.expose",
    "ros2.services.exclude",
    "ros2.services.offer",
    "ros2.actions.expose",
    "ros2.actions.exclude",
    "ros2.actions.offer",
];

/// A field of a camera's video stream (`VideoStreamConfig`'s), each an entry. `Topic`
/// comes first, as entries sort and apply: setting it makes the stream (its other fields
/// then take their defaults), unsetting it removes the stream.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum VideoField {
    Topic,
    Fps,
    BitrateKbps,
    MinBitrateKbps,
    KeyframeS,
}

impl VideoField {
    pub const ALL: [VideoField; 5] = [
        VideoField::Topic,
        VideoField::Fps,
        VideoField::BitrateKbps,
        VideoField::MinBitrateKbps,
        VideoField::KeyframeS,
    ];

    /// Its key in the YAML.
    pub fn as_str(self) -> &'static str {
        match self {
            VideoField::Topic => "topic",
            VideoField::Fps => "fps",
            VideoField::BitrateKbps => "bitrate_kbps",
            VideoField::MinBitrateKbps => "min_bitrate_kbps",
            VideoField::KeyframeS => "keyframe_s",
        }
    }

    pub fn of(key: &str) -> Option<VideoField> {
        VideoField::ALL.into_iter().find(|f| f.as_str() == key)
    }
}

/// One entry of the changeable part of a configuration.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Entry {
    /// One field of one topic's QoS.
    Qos { topic: String, field: String },
    /// The hub name of one local topic.
    Remap { local: String },
    /// One hub topic brought down under a local name.
    Subscribe { hub: String, local: String },
    /// One name (or pattern) of a bridge's list ([`LISTS`]).
    Name { list: &'static str, name: String },
    /// One field of one camera topic's video stream.
    Video { camera: String, field: VideoField },
}

impl fmt::Display for Entry {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Entry::Qos { topic, field } => write!(f, "topics[{topic:?}].{field}"),
            Entry::Remap { local } => write!(f, "remap[{local:?}]"),
            Entry::Subscribe { hub, local } => {
                write!(f, "subscribe {{ hub: {hub}, local: {local} }}")
            }
            Entry::Name { list, name } => write!(f, "{list} {name}"),
            Entry::Video { camera, field } => {
                write!(f, "video[{camera:?}].{}", field.as_str())
            }
        }
    }
}

impl Entry {
    /// The changeable field ([`super::CHANGEABLE`]) the entry belongs to.
    pub fn field(&self) -> &'static str {
        match self {
            Entry::Qos { .. } => "topics",
            Entry::Remap { .. } => "remap",
            Entry::Subscribe { .. } => "subscribe",
            Entry::Video { .. } => "video",
            Entry::Name { list, .. } => super::CHANGEABLE
                .iter()
                .copied()
                .filter(|f| list.starts_with(f))
                .max_by_key(|f| f.len())
                .unwrap_or("topics"),
        }
    }

    /// The bridge section (`ros1`, `ros2`) the entry needs, if any.
    pub fn section(&self) -> Option<&'static str> {
        match self {
            Entry::Name { list, .. } => Some(if list.starts_with("ros1.") {
                "ros1"
            } else {
                "ros2"
            }),
            _ => None,
        }
    }

    /// The entry's value in `cfg`; `None` when `cfg` has no section for it (no `ros2:`).
    pub fn get(&self, cfg: &AgentConfig) -> Option<Value> {
        Some(match self {
            Entry::Qos { topic, field } => cfg
                .topics
                .get(topic)
                .and_then(|spec| qos_fields(spec).remove(field))
                .unwrap_or(Value::Null),
            Entry::Remap { local } => cfg
                .remap
                .get(local)
                .map_or(Value::Null, |h| Value::String(h.clone())),
            Entry::Subscribe { hub, local } => Value::Bool(
                cfg.subscribe
                    .iter()
                    .any(|s| s.hub == *hub && s.local == *local),
            ),
            Entry::Name { list, name } => {
                let (_, names) = lists(cfg).into_iter().find(|(l, _)| l == list)?;
                Value::Bool(names.contains(name))
            }
            Entry::Video { camera, field } => cfg
                .video
                .get(camera)
                .and_then(|stream| video_fields(stream).remove(field.as_str()))
                .unwrap_or(Value::Null),
        })
    }

    /// Gives the entry `value` in `cfg`. Refused, saying why, when `cfg` has no section
    /// for it or the value does not fit.
    pub fn set(&self, cfg: &mut AgentConfig, value: &Value) -> Result<(), String> {
        match self {
            Entry::Qos { topic, field } => {
                let spec = cfg.topics.entry(topic.clone()).or_default();
                let mut fields = qos_fields(spec);
                fields.insert(field.clone(), value.clone());
                // Unset is left out (`max_age` reads no `null`).
                fields.retain(|_, v| !v.is_null());
                *spec = serde_json::from_value(Value::Object(fields))
                    .map_err(|e| format!("{self}: {e}"))?;
                if *spec == TopicQosSpec::default() {
                    cfg.topics.remove(topic);
                }
            }
            Entry::Remap { local } => match value {
                Value::Null => {
                    cfg.remap.remove(local);
                }
                Value::String(hub) => {
                    cfg.remap.insert(local.clone(), hub.clone());
                }
                other => return Err(format!("{self}: expected a topic name, got {other}")),
            },
            Entry::Subscribe { hub, local } => {
                let present = flag(self, value)?;
                let same = |s: &Subscription| s.hub == *hub && s.local == *local;
                if !present {
                    cfg.subscribe.retain(|s| !same(s));
                } else if !cfg.subscribe.iter().any(same) {
                    cfg.subscribe.push(Subscription {
                        hub: hub.clone(),
                        local: local.clone(),
                    });
                }
            }
            Entry::Name { list, name } => {
                let present = flag(self, value)?;
                let section = self.section().unwrap_or("ros2");
                let Some((_, names)) = lists_mut(cfg).into_iter().find(|(l, _)| l == list) else {
                    return Err(format!(
                        "the configuration has no {section}: section (the {} bridge), so \
                         there is no {list} to change",
                        if section == "ros1" { "ROS 1" } else { "ROS 2" }
                    ));
                };
                if !present {
                    names.retain(|n| n != name);
                } else if !names.contains(name) {
                    names.push(name.clone());
                }
            }
            Entry::Video { camera, field } => {
                // A camera has a stream while its video topic is set.
                if *field == VideoField::Topic && value.is_null() {
                    cfg.video.remove(camera);
                    return Ok(());
                }
                if value.is_null() && !cfg.video.contains_key(camera) {
                    return Ok(());
                }
                let mut fields = cfg.video.get(camera).map(video_fields).unwrap_or_default();
                fields.insert(field.as_str().to_owned(), value.clone());
                fields.retain(|_, v| !v.is_null());
                if !fields.contains_key("topic") {
                    return Err(format!(
                        "video[{camera:?}]: {camera} has no video stream to change; a new \
                         stream names its video topic, for example `video: {{ {camera}: {{ \
                         topic: {camera}/video }} }}`"
                    ));
                }
                let stream = serde_json::from_value(Value::Object(fields))
                    .map_err(|e| format!("{self}: {e}"))?;
                cfg.video.insert(camera.clone(), stream);
            }
        }
        Ok(())
    }
}

fn flag(entry: &Entry, value: &Value) -> Result<bool, String> {
    value
        .as_bool()
        .ok_or_else(|| format!("{entry}: expected true or false, got {value}"))
}

/// A video stream's fields as JSON (the defaults written out; `min_bitrate_kbps` only
/// when set).
pub fn video_fields(stream: &VideoStreamConfig) -> Map<String, Value> {
    match serde_json::to_value(stream) {
        Ok(Value::Object(map)) => map,
        _ => Map::new(),
    }
}

/// A topic's QoS fields as JSON, unset ones `null`.
pub fn qos_fields(spec: &TopicQosSpec) -> Map<String, Value> {
    match serde_json::to_value(spec) {
        Ok(Value::Object(map)) => map,
        _ => Map::new(),
    }
}

/// The bridges' lists of `cfg`, by their path (those of a bridge it runs).
pub fn lists(cfg: &AgentConfig) -> Vec<(&'static str, &Vec<String>)> {
    let mut out = Vec::new();
    if let Some(r) = &cfg.ros1 {
        out.extend([
            ("ros1.publish.include", &r.publish.include),
            ("ros1.publish.exclude", &r.publish.exclude),
            ("ros1.subscribe", &r.subscribe),
            ("ros1.services.expose", &r.services.expose),
            ("ros1.services.exclude", &r.services.exclude),
            ("ros1.services.offer", &r.services.offer),
        ]);
    }
    if let Some(r) = &cfg.ros2 {
        out.extend([
            ("ros2.publish.include", &r.publish.include),
            ("ros2.publish.exclude", &r.publish.exclude),
            ("ros2.subscribe", &r.subscribe),
            ("ros2.read", &r.read),
            ("ros2.services.expose", &r.services.expose),
            ("ros2.services.exclude", &r.services.exclude),
            ("ros2.services.offer", &r.services.offer),
            ("ros2.actions.expose", &r.actions.expose),
            ("ros2.actions.exclude", &r.actions.exclude),
            ("ros2.actions.offer", &r.actions.offer),
        ]);
    }
    out
}

/// [`lists`], to change them.
fn lists_mut(cfg: &mut AgentConfig) -> Vec<(&'static str, &mut Vec<String>)> {
    let mut out = Vec::new();
    if let Some(r) = &mut cfg.ros1 {
        out.extend([
            ("ros1.publish.include", &mut r.publish.include),
            ("ros1.publish.exclude", &mut r.publish.exclude),
            ("ros1.subscribe", &mut r.subscribe),
            ("ros1.services.expose", &mut r.services.expose),
            ("ros1.services.exclude", &mut r.services.exclude),
            ("ros1.services.offer", &mut r.services.offer),
        ]);
    }
    if let Some(r) = &mut cfg.ros2 {
        out.extend([
            ("ros2.publish.include", &mut r.publish.include),
            ("ros2.publish.exclude", &mut r.publish.exclude),
            ("ros2.subscribe", &mut r.subscribe),
            ("ros2.read", &mut r.read),
            ("ros2.services.expose", &mut r.services.expose),
            ("ros2.services.exclude", &mut r.services.exclude),
            ("ros2.services.offer", &mut r.services.offer),
            ("ros2.actions.expose", &mut r.actions.expose),
            ("ros2.actions.exclude", &mut r.actions.exclude),
            ("ros2.actions.offer", &mut r.actions.offer),
        ]);
    }
    out
}

/// The entries `cfg` holds (set QoS fields, remaps, subscriptions, listed names).
fn entries(cfg: &AgentConfig) -> BTreeSet<Entry> {
    let mut out = BTreeSet::new();
    for (topic, spec) in &cfg.topics {
        for (field, value) in qos_fields(spec) {
            if !value.is_null() {
                out.insert(Entry::Qos {
                    topic: topic.clone(),
                    field,
                });
            }
        }
    }
    out.extend(cfg.remap.keys().map(|local| Entry::Remap {
        local: local.clone(),
    }));
    out.extend(cfg.subscribe.iter().map(|s| Entry::Subscribe {
        hub: s.hub.clone(),
        local: s.local.clone(),
    }));
    for (list, names) in lists(cfg) {
        out.extend(names.iter().map(|name| Entry::Name {
            list,
            name: name.clone(),
        }));
    }
    for (camera, stream) in &cfg.video {
        out.extend(
            video_fields(stream)
                .keys()
                .filter_map(|k| VideoField::of(k))
                .map(|field| Entry::Video {
                    camera: camera.clone(),
                    field,
                }),
        );
    }
    out
}

/// The entries where `to` differs from `from`, with `to`'s values, in a stable order.
pub fn diff(from: &AgentConfig, to: &AgentConfig) -> Vec<(Entry, Value)> {
    let mut all = entries(from);
    all.extend(entries(to));
    all.into_iter()
        .filter_map(|e| {
            let now = e.get(to)?;
            (e.get(from).as_ref() != Some(&now)).then_some((e, now))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cfg(text: &str) -> AgentConfig {
        AgentConfig::from_str(text, "robot.yaml").expect("a valid file")
    }

    #[test]
    fn every_list_is_named_once_and_in_order() {
        let both = cfg("ros1: {}\nros2: {}\n");
        let names: Vec<&str> = lists(&both).into_iter().map(|(l, _)| l).collect();
        assert_eq!(names, LISTS);
    }

    #[test]
    fn an_entry_set_is_read_back_and_the_diff_names_only_it() {
        let file = cfg(
            "ros2: { publish: [/a, /b] }\ntopics:\n  /a: { priority: 3 }\n  /b: { no_drop: true }\n",
        );
        let mut to = file.clone();
        let rate = Entry::Qos {
            topic: "/a".into(),
            field: "rate_limit_hz".into(),
        };
        rate.set(&mut to, &serde_json::json!(0.5)).unwrap();
        let gone = Entry::Name {
            list: "ros2.publish.include",
            name: "/b".into(),
        };
        gone.set(&mut to, &Value::Bool(false)).unwrap();
        assert_eq!(rate.get(&to), Some(serde_json::json!(0.5)));
        assert_eq!(
            to.topics["/a"].priority,
            Some(3.0),
            "the topic's other fields stay"
        );
        assert_eq!(to.topics["/b"].no_drop, Some(true), "the other topics stay");
        assert_eq!(
            diff(&file, &to),
            vec![(rate, serde_json::json!(0.5)), (gone, Value::Bool(false))]
        );
        let mut none = cfg("");
        let e = Entry::Name {
            list: "ros1.subscribe",
            name: "/cmd".into(),
        };
        assert_eq!(e.get(&none), None);
        assert!(
            e.set(&mut none, &Value::Bool(true))
                .unwrap_err()
                .contains("ros1:")
        );
    }
}
