//! The changes in force, as kept: on the robot in `runtime_file`, and by the hub for each
//! robot it changed.
//!
//! What is kept is entries ([`super::entry`]), each with its value, what the file said
//! there when the change was made (`was`), and when and by whom; with them the file they
//! were made against (its path and SHA-256). At the next start they merge with the file
//! the way a three-way merge does ([`settle`]): an entry the file has changed since is set
//! aside (listed, not applied); so is one that would turn a topic's `no_drop` on or off,
//! one whose bridge section the file no longer has, and one that no longer checks out with
//! the file. The others apply, whatever else changed in the file.
//!
//! On disk (JSON):
//!
//! ```json
//! {
//!   "made_against": { "file": "/etc/fleetlink/robot.yaml", "sha256": "9f2c…" },
//!   "change": { "topics": { "/pose": { "rate_limit_hz": 0.5 } },
//!               "remove": { "ros2": { "publish": { "include": ["/scan"] } } } },
//!   "entries": {
//!     "topics[\"/pose\"].rate_limit_hz": { "was": null, "at_ms": 1718000000000, "by": "user:ana (hub API)" },
//!     "ros2.publish.include /scan": { "was": true, "at_ms": 1718000000000, "by": "the local API" }
//!   }
//! }
//! ```
//!
//! `change` is the changes in force written as a change (what `GET …/config` shows as
//! `overlay`); `entries` says where each of its entries comes from. A file holding a plain
//! change (as agents before kept them) is read as a change made against an unknown file.

use std::path::Path;
use std::time::{Duration, UNIX_EPOCH};

use serde_json::{Map, Value, json};

use super::entry::{Entry, diff};
use super::{NoDropFlip, no_drop_flips, path_is_in};
use crate::config::{AgentConfig, ConfigError, ConfigSource, validate};

/// One entry of the changes in force, and where it comes from.
#[derive(Debug, Clone, PartialEq)]
pub struct KeptEntry {
    pub entry: Entry,
    pub value: Value,
    /// The file's value of the entry when the change was made; `None`: not known (kept by
    /// an agent that did not record it).
    pub was: Option<Value>,
    /// When the entry was changed (Unix ms); 0: not known.
    pub at_ms: u64,
    /// Who changed it.
    pub by: String,
}

impl KeptEntry {
    /// `2024-06-10T08:00:00Z by user:ana (hub API)`, as far as it is known.
    pub fn when_and_who(&self) -> String {
        let when = (self.at_ms > 0).then(|| {
            humantime::format_rfc3339_seconds(UNIX_EPOCH + Duration::from_millis(self.at_ms))
                .to_string()
        });
        match (when, self.by.is_empty()) {
            (Some(w), false) => format!("{w} by {}", self.by),
            (Some(w), true) => w,
            (None, false) => format!("by {}", self.by),
            (None, true) => "when and by whom not recorded".to_owned(),
        }
    }
}

/// The configuration file changes were made against.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct MadeAgainst {
    /// Its path; `None`: no file (the defaults, or a configuration built in code).
    pub file: Option<String>,
    /// SHA-256 of its text, in hex.
    pub sha256: String,
}

/// Kept changes: what the runtime file holds, and what the hub keeps for a robot.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Record {
    /// `None`: not recorded (a plain change, as agents before kept them).
    pub made_against: Option<MadeAgainst>,
    pub entries: Vec<KeptEntry>,
}

impl Record {
    /// The record as it is kept (see the module's documentation).
    pub fn to_json(&self) -> Value {
        let entries: Map<String, Value> = self
            .entries
            .iter()
            .map(|k| {
                (
                    k.entry.to_string(),
                    json!({"was": k.was, "at_ms": k.at_ms, "by": k.by}),
                )
            })
            .collect();
        json!({
            "made_against": self.made_against,
            "change": change_doc(&self.entries),
            "entries": entries,
        })
    }

    /// Reads a kept record, or a plain change (then made against an unknown file). Its
    /// change is read like any change; `source` names it in errors.
    pub fn read(value: &Value, source: &str) -> Result<Record, ConfigError> {
        let is_record = value.get("change").is_some()
            && (value.get("entries").is_some() || value.get("made_against").is_some());
        let (change, meta, made_against) = if is_record {
            let made_against = value
                .get("made_against")
                .filter(|m| !m.is_null())
                .map(|m| serde_json::from_value::<MadeAgainst>(m.clone()))
                .transpose()
                .map_err(|e| ConfigError::Invalid {
                    field: "made_against".into(),
                    message: format!("{e} (in {source})"),
                })?;
            (&value["change"], value.get("entries"), made_against)
        } else {
            (value, None, None)
        };
        let text = serde_json::to_string_pretty(change).unwrap_or_else(|_| "{}".into());
        let written = super::read(&text, source, None)?;
        let mut entries: Vec<KeptEntry> = Vec::new();
        for (entry, value) in written.sets {
            let m = meta.and_then(|m| m.get(entry.to_string()));
            let kept = KeptEntry {
                was: m.and_then(|m| m.get("was")).cloned(),
                at_ms: m.and_then(|m| m["at_ms"].as_u64()).unwrap_or(0),
                by: m
                    .and_then(|m| m["by"].as_str())
                    .unwrap_or_default()
                    .to_owned(),
                entry,
                value,
            };
            match entries.iter_mut().find(|k| k.entry == kept.entry) {
                Some(earlier) => *earlier = kept,
                None => entries.push(kept),
            }
        }
        entries.sort_by(|a, b| a.entry.cmp(&b.entry));
        Ok(Record {
            made_against,
            entries,
        })
    }
}

/// The entries as a change that makes them (removals under `remove:`). Applied to the file
/// they were made against, it gives the configuration they are in force in.
pub fn change_doc(entries: &[KeptEntry]) -> Map<String, Value> {
    let mut doc = Map::new();
    let mut remove = Map::new();
    for k in entries {
        let present = k.value.as_bool() == Some(true);
        match &k.entry {
            Entry::Qos { topic, field } => {
                let spec = object_at(&mut doc, &["topics", topic]);
                spec.insert(field.clone(), k.value.clone());
            }
            Entry::Video { camera, field } => {
                let stream = object_at(&mut doc, &["video", camera]);
                stream.insert(field.as_str().to_owned(), k.value.clone());
            }
            Entry::Remap { local } if k.value.is_null() => {
                push_at(&mut remove, &["remap"], Value::String(local.clone()));
            }
            Entry::Remap { local } => {
                object_at(&mut doc, &["remap"]).insert(local.clone(), k.value.clone());
            }
            Entry::Subscribe { hub, local } => {
                let to = if present { &mut doc } else { &mut remove };
                push_at(to, &["subscribe"], json!({"hub": hub, "local": local}));
            }
            Entry::Name { list, name } => {
                let to = if present { &mut doc } else { &mut remove };
                let path: Vec<&str> = list.split('.').collect();
                push_at(to, &path, Value::String(name.clone()));
            }
        }
    }
    if !remove.is_empty() {
        doc.insert("remove".into(), Value::Object(remove));
    }
    doc
}

/// The mapping at `path` in `doc`, made if missing.
fn object_at<'a>(doc: &'a mut Map<String, Value>, path: &[&str]) -> &'a mut Map<String, Value> {
    let mut map = doc;
    for key in path {
        let slot = map
            .entry((*key).to_owned())
            .or_insert_with(|| Value::Object(Map::new()));
        if !slot.is_object() {
            *slot = Value::Object(Map::new());
        }
        map = match slot {
            Value::Object(m) => m,
            _ => unreachable!("made a mapping above"),
        };
    }
    map
}

/// Appends `item` to the list at `path` in `doc`, made if missing.
fn push_at(doc: &mut Map<String, Value>, path: &[&str], item: Value) {
    let Some((last, parent)) = path.split_last() else {
        return;
    };
    let slot = object_at(doc, parent)
        .entry((*last).to_owned())
        .or_insert_with(|| Value::Array(Vec::new()));
    if let Value::Array(items) = slot {
        items.push(item);
    }
}

/// The changes in force in `to` (running) over `file`: every entry where they differ. An
/// entry kept already with the same value keeps when and by whom it was made; a new one is
/// `by` at `at_ms`. Each records the file's value now.
pub fn carry(
    file: &AgentConfig,
    to: &AgentConfig,
    kept: &[KeptEntry],
    by: &str,
    at_ms: u64,
) -> Vec<KeptEntry> {
    diff(file, to)
        .into_iter()
        .map(|(entry, value)| {
            let was = entry.get(file);
            match kept.iter().find(|k| k.entry == entry && k.value == value) {
                Some(k) => KeptEntry { was, ..k.clone() },
                None => KeptEntry {
                    entry,
                    value,
                    was,
                    at_ms,
                    by: by.to_owned(),
                },
            }
        })
        .collect()
}

/// A kept entry that was not applied, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct SetAside {
    pub kept: KeptEntry,
    pub why: String,
    /// It would have turned a topic's `no_drop` on or off.
    pub no_drop: bool,
}

/// Kept entries merged with a file.
#[derive(Debug, Clone)]
pub struct Settled {
    /// The file's configuration with the entries that apply.
    pub config: AgentConfig,
    /// The changes in force (the entries that apply and change something).
    pub in_force: Vec<KeptEntry>,
    pub set_aside: Vec<SetAside>,
}

/// Merges the kept entries `candidates` with `file` (see the module's documentation).
pub fn settle(file: &AgentConfig, candidates: Vec<KeptEntry>) -> Settled {
    let mut set_aside = Vec::new();
    let aside = |kept: KeptEntry, why: String| SetAside {
        kept,
        why,
        no_drop: false,
    };
    let mut todo = Vec::new();
    for k in candidates {
        let Some(now) = k.entry.get(file) else {
            let section = k.entry.section().unwrap_or("its");
            let why = format!("the configuration has no {section}: section now");
            set_aside.push(aside(k, why));
            continue;
        };
        match &k.was {
            Some(was) if *was != now && now != k.value => {
                let why = format!(
                    "the file has changed it since the change was made: it says {} there now, \
                     {} then",
                    show(&k.entry, &now),
                    show(&k.entry, was)
                );
                set_aside.push(aside(k, why));
            }
            _ => todo.push(k),
        }
    }
    loop {
        let mut config = file.clone();
        let unplaced = todo
            .iter()
            .enumerate()
            .find_map(|(i, k)| k.entry.set(&mut config, &k.value).err().map(|e| (i, e)));
        if let Some((i, why)) = unplaced {
            set_aside.push(aside(todo.remove(i), why));
            continue;
        }
        let flips = no_drop_flips(file, &config);
        if !flips.is_empty() {
            let before = todo.len();
            for flip in &flips {
                let (out, keep): (Vec<_>, Vec<_>) = std::mem::take(&mut todo)
                    .into_iter()
                    .partition(|k| on_topic(k, flip));
                todo = keep;
                set_aside.extend(out.into_iter().map(|kept| SetAside {
                    kept,
                    why: flip.refusal(),
                    no_drop: true,
                }));
            }
            if todo.len() == before {
                // Never reached (the file alone flips nothing); it ends the loop all the same.
                set_aside.extend(todo.drain(..).map(|k| aside(k, flips[0].refusal())));
            }
            continue;
        }
        match validate::validate(&config) {
            Ok(()) => {
                return Settled {
                    in_force: carry(file, &config, &todo, "", 0),
                    config,
                    set_aside,
                };
            }
            Err(problem) => {
                let why = format!(
                    "with the file it does not check out: {}: {}",
                    problem.path, problem.message
                );
                let blamed: Vec<bool> = todo
                    .iter()
                    .map(|k| path_is_in(&problem.path, &k.entry, &config))
                    .collect();
                let any = blamed.contains(&true);
                let (out, keep): (Vec<_>, Vec<_>) = todo
                    .into_iter()
                    .zip(blamed)
                    .partition(|(_, blamed)| *blamed || !any);
                todo = keep.into_iter().map(|(k, _)| k).collect();
                set_aside.extend(out.into_iter().map(|(k, _)| aside(k, why.clone())));
            }
        }
    }
}

fn on_topic(k: &KeptEntry, flip: &NoDropFlip) -> bool {
    matches!(&k.entry, Entry::Qos { topic, .. } if *topic == flip.topic)
}

/// The value of `entry` as a person reads it.
pub fn show(entry: &Entry, value: &Value) -> String {
    match (entry, value) {
        (_, Value::Null) => "nothing".into(),
        (Entry::Name { .. } | Entry::Subscribe { .. }, Value::Bool(true)) => "listed".into(),
        (Entry::Name { .. } | Entry::Subscribe { .. }, Value::Bool(false)) => "not listed".into(),
        (_, Value::String(s)) => s.clone(),
        (_, other) => other.to_string(),
    }
}

/// How much a note on opening the kept changes matters.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Level {
    Info,
    Warn,
    Error,
}

/// Something to say about the kept changes when the agent starts.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Note {
    pub level: Level,
    pub text: String,
}

/// The configuration an agent starts with: its file's and the changes kept in `path`.
#[derive(Debug, Clone)]
pub struct Opened {
    pub settled: Settled,
    /// Whether `path` held kept changes.
    pub found: bool,
    pub notes: Vec<Note>,
}

/// Reads the changes kept in `path` and merges them with `file` (read from `source`):
/// what the agent runs at start, and what it says about it.
pub fn open(file: &AgentConfig, source: &ConfigSource, path: &Path) -> Opened {
    let shown = path.display();
    let mut notes = Vec::new();
    let mut note = |level, text: String| notes.push(Note { level, text });
    let nothing = |notes, found| Opened {
        settled: Settled {
            config: file.clone(),
            in_force: Vec::new(),
            set_aside: Vec::new(),
        },
        found,
        notes,
    };
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return nothing(notes, false),
        Err(e) => {
            note(
                Level::Error,
                format!("cannot read {shown}: {e}; running without the changes kept there"),
            );
            return nothing(notes, false);
        }
    };
    let record = serde_json::from_str::<Value>(&text)
        .map_err(|e| e.to_string())
        .and_then(|v| Record::read(&v, &shown.to_string()).map_err(|e| e.to_string()));
    let record = match record {
        Ok(r) => r,
        Err(e) => {
            note(
                Level::Error,
                format!(
                    "the changes kept in {shown} cannot be read ({e}); running without them \
                     (fix the file, or delete it to drop them)"
                ),
            );
            return nothing(notes, true);
        }
    };
    let now = source.made_against();
    let file_changed = match &record.made_against {
        None => Some(format!(
            "the changes kept in {shown} do not record which configuration they were made \
             against (an older agent kept them): each applies where it still merges with {}",
            source.name()
        )),
        Some(then) if *then != now => Some(format!(
            "{} has changed since the changes kept in {shown} were made (against {}, \
             SHA-256 {}; now {}): each applies where it still merges with it",
            source.name(),
            then.file.as_deref().unwrap_or("no file"),
            short(&then.sha256),
            short(&now.sha256),
        )),
        Some(_) => None,
    };
    let settled = settle(file, record.entries);
    if let Some(text) = file_changed {
        let level = if settled.set_aside.is_empty() {
            Level::Info
        } else {
            Level::Warn
        };
        note(level, text);
    }
    if !settled.in_force.is_empty() {
        let mut fields: Vec<&str> = settled.in_force.iter().map(|k| k.entry.field()).collect();
        fields.dedup();
        note(
            Level::Info,
            format!(
                "the changes kept in {shown} are in force ({} {}: {})",
                settled.in_force.len(),
                if settled.in_force.len() == 1 {
                    "entry"
                } else {
                    "entries"
                },
                fields.join(", ")
            ),
        );
    }
    for a in &settled.set_aside {
        let level = if a.no_drop { Level::Error } else { Level::Warn };
        note(
            level,
            format!(
                "the kept change {} = {} ({}) is set aside, {}'s value runs: {}",
                a.kept.entry,
                show(&a.kept.entry, &a.kept.value),
                a.kept.when_and_who(),
                source.name(),
                a.why
            ),
        );
    }
    match settled.set_aside.len() {
        0 => {}
        1 => note(
            Level::Warn,
            format!(
                "1 kept change is set aside; it stays in {shown} until the next change made \
                 while the agent runs, which drops it (make it again to keep it, or delete \
                 {shown} to drop it now)"
            ),
        ),
        n => note(
            Level::Warn,
            format!(
                "{n} kept changes are set aside; they stay in {shown} until the next change \
                 made while the agent runs, which drops them (make one again to keep it, or \
                 delete {shown} to drop them now)"
            ),
        ),
    }
    Opened {
        settled,
        found: true,
        notes,
    }
}

/// The first 12 hex digits of a hash.
fn short(hash: &str) -> &str {
    hash.get(..12).unwrap_or(hash)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(text: &str) -> AgentConfig {
        AgentConfig::from_str(text, "robot.yaml").expect("a valid file")
    }

    fn kept_of(file_cfg: &AgentConfig, change: &str) -> Vec<KeptEntry> {
        super::super::change(
            file_cfg,
            file_cfg,
            &[],
            change,
            "change",
            "user:ana",
            1_718_000_000_000,
        )
        .expect("a valid change")
        .kept
    }

    #[test]
    fn a_record_reads_back_as_it_was_written() {
        let f = file("ros2: { publish: [/a, /b] }\nremap: { /a: /x/a }\n");
        let entries = kept_of(
            &f,
            "topics: { /a: { rate_limit_hz: 2, priority: null } }\n\
             ros2: { subscribe: [/cmd] }\nsubscribe: [{ hub: /h, local: /l }]\n\
             remove: { remap: [/a], ros2: { publish: [/b] } }\n",
        );
        let record = Record {
            made_against: Some(MadeAgainst {
                file: Some("robot.yaml".into()),
                sha256: "00".into(),
            }),
            entries,
        };
        let back = Record::read(&record.to_json(), "runtime.json").unwrap();
        assert_eq!(back, record);
        assert!(
            record.to_json()["change"]["remove"]["ros2"]["publish"]["include"]
                .to_string()
                .contains("/b")
        );
    }

    #[test]
    fn a_plain_change_reads_as_made_against_an_unknown_file() {
        let plain = json!({"topics": {"/pose": {"rate_limit_hz": 0.5}}});
        let r = Record::read(&plain, "runtime.json").unwrap();
        assert_eq!(r.made_against, None);
        assert_eq!(r.entries.len(), 1);
        assert_eq!(r.entries[0].was, None);
    }

    #[test]
    fn settling_applies_what_merges_and_sets_aside_what_the_file_changed() {
        let old = file("topics:\n  /a: { priority: 3 }\n  /b: { priority: 4 }\n");
        let entries = kept_of(
            &old,
            "topics: { /a: { rate_limit_hz: 2 }, /b: { priority: 7 } }",
        );
        // Unchanged file: both apply.
        let s = settle(&old, entries.clone());
        assert!(s.set_aside.is_empty());
        assert_eq!(s.in_force, entries);
        // The file changed /b's priority since: that entry is set aside, /a's applies.
        let new = file("topics:\n  /a: { priority: 3 }\n  /b: { priority: 5 }\n  /c: {}\n");
        let s = settle(&new, entries);
        assert_eq!(s.config.topics["/a"].rate_limit_hz, Some(2.0));
        assert_eq!(s.config.topics["/b"].priority, Some(5.0));
        assert_eq!(s.set_aside.len(), 1);
        assert!(
            s.set_aside[0].why.contains("says 5"),
            "{}",
            s.set_aside[0].why
        );
    }
}
