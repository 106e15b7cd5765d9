//! The type registry: every definition the process knows, from three sources.
//!
//! Sources: the bundled standard definitions, user directories laid out as ROS packages,
//! and full texts received at run time (a TCPROS `message_definition`, a rosbag2/MCAP
//! schema). Design choice: a [`Registry`] is a cheap handle (`Arc` + `RwLock`); clones
//! share one table, so the hub can learn a robot's custom type on one connection and
//! convert it on all others. ROS 1 definitions live in their own table that overrides the
//! shared (ROS 2 form) table only when a message is read in the ROS 1 dialect, because
//! the two generations disagree on types like `std_msgs/Header`.

use std::collections::HashMap;
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, OnceLock, RwLock, RwLockReadGuard};

use crate::bundled;
use crate::error::RegistryError;
use crate::layout::{self, LayoutCache, MsgLayout, SpecSource};
use crate::name::{InterfaceKind, TypeName};
use crate::parse::{parse_definition, parse_message};
use crate::spec::{Definition, Dialect, Element, MsgSpec};

type Key = (String, String);

#[derive(Default, Clone)]
struct Tables {
    /// Message definitions in ROS 2 form, used by both dialects.
    shared: HashMap<Key, Arc<MsgSpec>>,
    /// ROS 1 definitions; in the ROS 1 dialect they win over `shared`.
    ros1: HashMap<Key, Arc<MsgSpec>>,
    /// Whole interfaces (msg, srv, action) by name, for `show` and service md5sums.
    interfaces: HashMap<(Dialect, Key), Arc<Definition>>,
    layouts: LayoutCache,
    /// Counts changes to the definitions; a [`Resolved`] type is current while it holds.
    generation: u64,
}

/// A message type resolved once, for converting many messages of one topic without
/// looking the type up each time. [`Registry::is_current`] tells whether a definition
/// changed since (then resolve again).
#[derive(Clone, Debug)]
pub struct Resolved {
    pub(crate) layout: Arc<MsgLayout>,
    generation: u64,
}

impl SpecSource for Tables {
    fn spec(&self, dialect: Dialect, key: &Key) -> Option<Arc<MsgSpec>> {
        if dialect == Dialect::Ros1
            && let Some(s) = self.ros1.get(key)
        {
            return Some(s.clone());
        }
        self.shared.get(key).cloned()
    }
}

impl Tables {
    fn insert_msg(&mut self, dialect: Dialect, spec: MsgSpec) {
        let key = spec.name.key();
        let table = match dialect {
            Dialect::Ros1 => &mut self.ros1,
            Dialect::Ros2 => &mut self.shared,
        };
        if table.get(&key).is_some_and(|old| **old == spec) {
            return;
        }
        table.insert(key, Arc::new(spec));
        self.layouts.clear();
        self.generation += 1;
    }

    fn insert_definition(&mut self, dialect: Dialect, def: Definition) {
        let key = def.name().key();
        match &def {
            Definition::Msg(m) => self.insert_msg(dialect, m.clone()),
            Definition::Srv {
                request, response, ..
            } => {
                self.insert_msg(dialect, request.clone());
                self.insert_msg(dialect, response.clone());
            }
            Definition::Action {
                name,
                goal,
                result,
                feedback,
            } => {
                self.insert_msg(dialect, goal.clone());
                self.insert_msg(dialect, result.clone());
                self.insert_msg(dialect, feedback.clone());
                for part in action_wrappers(name) {
                    self.insert_msg(dialect, part);
                }
            }
        }
        self.interfaces.insert((dialect, key), Arc::new(def));
    }

    /// Finds the key for a user-supplied name, accepting ROS 1 service part names
    /// (`pkg/AddTwoIntsRequest` for `pkg/srv/AddTwoInts_Request`).
    fn find(&self, dialect: Dialect, name: &TypeName) -> Option<Key> {
        let key = name.key();
        if self.spec(dialect, &key).is_some() {
            return Some(key);
        }
        for suffix in ["Request", "Response"] {
            if let Some(base) = name.name().strip_suffix(suffix)
                && !base.ends_with('_')
            {
                let alt = (key.0.clone(), format!("{base}_{suffix}"));
                if self.spec(dialect, &alt).is_some() {
                    return Some(alt);
                }
            }
        }
        None
    }
}

/// The message types ROS 2 derives from an action (goal service, result service and
/// feedback topic), as definition texts parsed like any other message.
fn action_wrappers(name: &TypeName) -> Vec<MsgSpec> {
    let n = name.name();
    let parts = [
        (
            "_SendGoal_Request",
            format!("unique_identifier_msgs/UUID goal_id\n{n}_Goal goal\n"),
        ),
        (
            "_SendGoal_Response",
            "bool accepted\nbuiltin_interfaces/Time stamp\n".to_owned(),
        ),
        (
            "_GetResult_Request",
            "unique_identifier_msgs/UUID goal_id\n".to_owned(),
        ),
        (
            "_GetResult_Response",
            format!("int8 status\n{n}_Result result\n"),
        ),
        (
            "_FeedbackMessage",
            format!("unique_identifier_msgs/UUID goal_id\n{n}_Feedback feedback\n"),
        ),
    ];
    parts
        .into_iter()
        .filter_map(|(suffix, text)| {
            let part = name.sibling(format!("{n}{suffix}"));
            // The texts above are fixed and valid; a failure would be a bug caught by tests.
            parse_message(&part, &text, Dialect::Ros2).ok()
        })
        .collect()
}

/// Shared, thread-safe table of interface definitions. Clones share the same table.
#[derive(Clone, Default)]
pub struct Registry {
    tables: Arc<RwLock<Tables>>,
    /// The tables' generation, readable without the lock: [`Registry::is_current`] runs
    /// once per converted message.
    generation: Arc<AtomicU64>,
}

/// The tables, written; the generation is published when the writing ends.
struct Writing<'a> {
    guard: std::sync::RwLockWriteGuard<'a, Tables>,
    generation: &'a AtomicU64,
}

impl std::ops::Deref for Writing<'_> {
    type Target = Tables;
    fn deref(&self) -> &Tables {
        &self.guard
    }
}

impl std::ops::DerefMut for Writing<'_> {
    fn deref_mut(&mut self) -> &mut Tables {
        &mut self.guard
    }
}

impl Drop for Writing<'_> {
    fn drop(&mut self) {
        // Still under the lock: generations are published in order.
        self.generation
            .store(self.guard.generation, Ordering::Release);
    }
}

impl std::fmt::Debug for Registry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let t = self.read();
        f.debug_struct("Registry")
            .field("shared", &t.shared.len())
            .field("ros1", &t.ros1.len())
            .finish()
    }
}

impl Registry {
    /// An empty registry (no standard types).
    pub fn empty() -> Self {
        Registry::default()
    }

    /// A registry holding the bundled standard definitions. Parsed once per process;
    /// each call returns an independent table.
    pub fn bundled() -> Self {
        static BUNDLED: OnceLock<Tables> = OnceLock::new();
        let tables = BUNDLED.get_or_init(|| {
            let mut t = Tables::default();
            for (dir, pkg, kind, name, text) in bundled::FILES {
                let dialect = if *dir == "ros1" {
                    Dialect::Ros1
                } else {
                    Dialect::Ros2
                };
                let kind = match *kind {
                    "srv" => InterfaceKind::Srv,
                    "action" => InterfaceKind::Action,
                    _ => InterfaceKind::Msg,
                };
                // Bundled files are checked by the `every_bundled_type_resolves` test.
                if let Ok(n) = TypeName::new(pkg, kind, name)
                    && let Ok(def) = parse_definition(&n, text, dialect)
                {
                    t.insert_definition(dialect, def);
                }
            }
            t
        });
        Registry {
            tables: Arc::new(RwLock::new(tables.clone())),
            generation: Arc::new(AtomicU64::new(tables.generation)),
        }
    }

    fn read(&self) -> RwLockReadGuard<'_, Tables> {
        // A panic while holding the lock cannot leave the tables half-written (inserts
        // are single HashMap operations), so a poisoned lock is still usable.
        self.tables.read().unwrap_or_else(|e| e.into_inner())
    }

    fn write(&self) -> Writing<'_> {
        Writing {
            guard: self.tables.write().unwrap_or_else(|e| e.into_inner()),
            generation: &self.generation,
        }
    }

    /// Registers one interface file's text (`name` says msg, srv or action).
    pub fn add_definition(
        &self,
        name: &str,
        text: &str,
        dialect: Dialect,
    ) -> Result<TypeName, RegistryError> {
        let name = TypeName::parse(name)?;
        let def = parse_definition(&name, text, dialect)?;
        self.write().insert_definition(dialect, def);
        Ok(name)
    }

    /// Adds every `.msg`, `.srv` and `.action` file found under `path`: either one ROS
    /// package (a directory with `msg/`, `srv/` or `action/`) or a tree of packages.
    /// Returns how many interfaces were added.
    pub fn add_package_dir(&self, path: impl AsRef<Path>) -> Result<usize, RegistryError> {
        let mut defs = Vec::new();
        collect_packages(path.as_ref(), 0, &mut defs)?;
        let n = defs.len();
        let mut t = self.write();
        for d in defs {
            t.insert_definition(Dialect::Ros2, d);
        }
        Ok(n)
    }

    /// Registers a concatenated definition as peers send it: the main type's text, then
    /// for each dependency a line of `=`, a `MSG: pkg/Type` line and its text. This is
    /// ROS 1's `message_definition` and rosbag2/MCAP's `ros2msg` schema.
    pub fn add_full_text(
        &self,
        type_name: &str,
        text: &str,
        dialect: Dialect,
    ) -> Result<TypeName, RegistryError> {
        let main = TypeName::parse(type_name)?;
        let mut specs = Vec::new();
        let mut current = main.clone();
        let mut body = String::new();
        let mut pending_header = false;
        for line in text.lines() {
            let t = line.trim();
            if t.len() >= 3 && t.chars().all(|c| c == '=') {
                specs.push((current.clone(), std::mem::take(&mut body)));
                pending_header = true;
                continue;
            }
            if pending_header {
                if t.is_empty() {
                    continue;
                }
                let dep = t
                    .strip_prefix("MSG:")
                    .ok_or_else(|| RegistryError::BadName {
                        name: t.to_owned(),
                        reason: "expected `MSG: pkg/Type` after a separator line",
                    })?;
                current = TypeName::parse(dep.trim())?;
                pending_header = false;
                continue;
            }
            body.push_str(line);
            body.push('\n');
        }
        specs.push((current, body));
        let mut parsed = Vec::with_capacity(specs.len());
        for (name, body) in specs {
            parsed.push(parse_message(&name, &body, dialect)?);
        }
        let mut t = self.write();
        for spec in parsed {
            t.insert_msg(dialect, spec);
        }
        Ok(main)
    }

    /// True if `type_name` (any accepted spelling) names a known message or interface.
    pub fn contains(&self, type_name: &str) -> bool {
        let Ok(name) = TypeName::parse(type_name) else {
            return false;
        };
        let t = self.read();
        [Dialect::Ros2, Dialect::Ros1]
            .into_iter()
            .any(|d| t.find(d, &name).is_some() || t.interfaces.contains_key(&(d, name.key())))
    }

    /// Normalises a name to the registered `pkg/kind/T` form.
    pub fn resolve_name(
        &self,
        type_name: &str,
        dialect: Dialect,
    ) -> Result<TypeName, RegistryError> {
        let name = TypeName::parse(type_name)?;
        let t = self.read();
        if let Some(s) = t.find(dialect, &name).and_then(|key| t.spec(dialect, &key)) {
            return Ok(s.name.clone());
        }
        if let Some(d) = t
            .interfaces
            .get(&(dialect, name.key()))
            .or_else(|| t.interfaces.get(&(Dialect::Ros2, name.key())))
        {
            return Ok(d.name().clone());
        }
        Err(RegistryError::UnknownType {
            name: type_name.to_owned(),
            from: "the caller".into(),
        })
    }

    /// The parsed definition of a message type.
    pub fn message(
        &self,
        type_name: &str,
        dialect: Dialect,
    ) -> Result<Arc<MsgSpec>, RegistryError> {
        let name = TypeName::parse(type_name)?;
        let t = self.read();
        let key = t
            .find(dialect, &name)
            .ok_or_else(|| self.unknown(&t, dialect, &name))?;
        t.spec(dialect, &key)
            .ok_or_else(|| self.unknown(&t, dialect, &name))
    }

    fn unknown(&self, t: &Tables, dialect: Dialect, name: &TypeName) -> RegistryError {
        if t.interfaces.contains_key(&(dialect, name.key()))
            || t.interfaces.contains_key(&(Dialect::Ros2, name.key()))
        {
            RegistryError::NotAMessage(name.to_string())
        } else {
            RegistryError::UnknownType {
                name: name.to_string(),
                from: "the caller".into(),
            }
        }
    }

    /// The whole interface (msg, srv or action) named `type_name`.
    pub fn interface(
        &self,
        type_name: &str,
        dialect: Dialect,
    ) -> Result<Arc<Definition>, RegistryError> {
        let name = TypeName::parse(type_name)?;
        let t = self.read();
        for d in [dialect, Dialect::Ros2] {
            if let Some(def) = t.interfaces.get(&(d, name.key())) {
                return Ok(def.clone());
            }
        }
        let key = t
            .find(dialect, &name)
            .ok_or_else(|| self.unknown(&t, dialect, &name))?;
        let spec = t
            .spec(dialect, &key)
            .ok_or_else(|| self.unknown(&t, dialect, &name))?;
        Ok(Arc::new(Definition::Msg((*spec).clone())))
    }

    /// The resolved layout the codecs walk (cached until a definition changes).
    pub fn layout(
        &self,
        type_name: &str,
        dialect: Dialect,
    ) -> Result<Arc<MsgLayout>, RegistryError> {
        let name = TypeName::parse(type_name)?;
        {
            let t = self.read();
            let key = t
                .find(dialect, &name)
                .ok_or_else(|| self.unknown(&t, dialect, &name))?;
            if let Some(l) = t.layouts.get(&(dialect, key)) {
                return Ok(l.clone());
            }
        }
        let mut guard = self.write();
        let t = &mut *guard;
        let key = t
            .find(dialect, &name)
            .ok_or_else(|| self.unknown(t, dialect, &name))?;
        let mut cache = std::mem::take(&mut t.layouts);
        let result = layout::compile(
            &*t,
            &mut cache,
            dialect,
            &key,
            &mut Vec::new(),
            "the caller",
        );
        t.layouts = cache;
        result
    }

    /// `type_name` resolved for repeated conversions (see [`Resolved`]).
    pub fn resolve(&self, type_name: &str, dialect: Dialect) -> Result<Resolved, RegistryError> {
        // Read first: a change between the two steps makes the result look stale, never
        // the other way round.
        let generation = self.generation.load(Ordering::Acquire);
        let layout = self.layout(type_name, dialect)?;
        Ok(Resolved { layout, generation })
    }

    /// False once a definition has changed since `r` was resolved.
    pub fn is_current(&self, r: &Resolved) -> bool {
        self.generation.load(Ordering::Acquire) == r.generation
    }

    /// Every registered message type (both tables), sorted, in `pkg/kind/T` form.
    pub fn message_names(&self) -> Vec<TypeName> {
        let t = self.read();
        let mut v: Vec<TypeName> = t
            .shared
            .values()
            .chain(t.ros1.values())
            .map(|s| s.name.clone())
            .collect();
        v.sort();
        v.dedup();
        v
    }

    /// Message types `spec` uses directly, in first-use order, as registry keys.
    pub(crate) fn direct_deps(&self, spec: &MsgSpec, dialect: Dialect) -> Vec<Arc<MsgSpec>> {
        let t = self.read();
        let mut out: Vec<Arc<MsgSpec>> = Vec::new();
        for f in &spec.fields {
            let key = match &f.ty.element {
                Element::Named { package, name } => {
                    layout::named_key(&*t, dialect, spec, package, name)
                }
                Element::Primitive(crate::spec::Primitive::Time) if dialect == Dialect::Ros2 => {
                    ("builtin_interfaces".into(), "Time".into())
                }
                Element::Primitive(crate::spec::Primitive::Duration)
                    if dialect == Dialect::Ros2 =>
                {
                    ("builtin_interfaces".into(), "Duration".into())
                }
                Element::Primitive(_) => continue,
            };
            if dialect == Dialect::Ros1
                && key.0 == "builtin_interfaces"
                && (key.1 == "Time" || key.1 == "Duration")
            {
                continue;
            }
            if let Some(s) = t.spec(dialect, &key)
                && !out.iter().any(|o| o.name == s.name)
            {
                out.push(s);
            }
        }
        out
    }

    /// Runs `f` with the tables as a definition source (for name resolution).
    pub(crate) fn with_source<R>(&self, f: impl FnOnce(&dyn SpecSource) -> R) -> R {
        let t = self.read();
        f(&*t)
    }

    /// True if the ROS 1 table has its own definition of this message.
    pub(crate) fn has_ros1_override(&self, name: &TypeName) -> bool {
        self.read().ros1.contains_key(&name.key())
    }
}

fn collect_packages(
    dir: &Path,
    depth: usize,
    out: &mut Vec<Definition>,
) -> Result<(), RegistryError> {
    let io = |cause| RegistryError::Io {
        path: dir.to_owned(),
        cause,
    };
    let is_package = ["msg", "srv", "action"]
        .iter()
        .any(|k| dir.join(k).is_dir());
    if is_package {
        let pkg =
            dir.file_name()
                .and_then(|n| n.to_str())
                .ok_or_else(|| RegistryError::BadName {
                    name: dir.display().to_string(),
                    reason: "package directory name is not UTF-8",
                })?;
        for (sub, kind) in [
            ("msg", InterfaceKind::Msg),
            ("srv", InterfaceKind::Srv),
            ("action", InterfaceKind::Action),
        ] {
            let subdir = dir.join(sub);
            if !subdir.is_dir() {
                continue;
            }
            let mut files: Vec<_> = std::fs::read_dir(&subdir)
                .map_err(io)?
                .filter_map(|e| e.ok())
                .map(|e| e.path())
                .collect();
            files.sort();
            for file in files {
                if file.extension().and_then(|e| e.to_str()) != Some(sub) {
                    continue;
                }
                let Some(stem) = file.file_stem().and_then(|s| s.to_str()) else {
                    continue;
                };
                let text = std::fs::read_to_string(&file).map_err(|cause| RegistryError::Io {
                    path: file.clone(),
                    cause,
                })?;
                let name = TypeName::new(pkg, kind, stem)?;
                // Name the file in parse errors: that is what the user has to open.
                let def = parse_definition(&name, &text, Dialect::Ros2).map_err(|mut e| {
                    e.source_name = file.display().to_string();
                    e
                })?;
                out.push(def);
            }
        }
        return Ok(());
    }
    if depth >= 4 {
        return Ok(());
    }
    let mut dirs: Vec<_> = std::fs::read_dir(dir)
        .map_err(io)?
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.is_dir())
        .collect();
    dirs.sort();
    for d in dirs {
        collect_packages(&d, depth + 1, out)?;
    }
    Ok(())
}
