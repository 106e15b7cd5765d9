//! Type identities: ROS 1 md5sums, full definition texts and the ROS 2 type hash.
//!
//! Design choice: identities are computed from the parsed definitions (not the
//! layouts) because they depend on details the codecs do not care about, such as
//! `byte` vs `uint8`, constants and how a type was spelled in the file. ROS 1 identities
//! read the registry in the ROS 1 dialect, the type hash in the ROS 2 dialect.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::sync::Arc;

use md5::{Digest as _, Md5};
use sha2::Sha256;

use crate::error::RegistryError;
use crate::layout::named_key;
use crate::registry::Registry;
use crate::spec::{
    ArrayKind, Definition, Dialect, Element, FieldSpec, MsgSpec, Primitive, array_suffix,
};

/// ROS 1 md5sum of a message or service (`pkg/T`, `pkg/msg/T`, `pkg/srv/T`).
pub fn md5sum(registry: &Registry, type_name: &str) -> Result<String, RegistryError> {
    let def = registry.interface(type_name, Dialect::Ros1)?;
    let text = match &*def {
        Definition::Msg(m) => md5_text(registry, m)?,
        Definition::Srv {
            request, response, ..
        } => {
            format!(
                "{}{}",
                md5_text(registry, request)?,
                md5_text(registry, response)?
            )
        }
        Definition::Action { name, .. } => {
            return Err(RegistryError::NotAMessage(name.to_string()));
        }
    };
    Ok(hex(&Md5::digest(text.as_bytes())))
}

fn hex(bytes: &[u8]) -> String {
    bytes
        .iter()
        .fold(String::with_capacity(bytes.len() * 2), |mut s, b| {
            let _ = write!(s, "{b:02x}");
            s
        })
}

/// The ROS 1 key of a builtin_interfaces time type, if `key` is one.
fn ros1_time(key: &(String, String)) -> Option<&'static str> {
    match (key.0.as_str(), key.1.as_str()) {
        ("builtin_interfaces", "Time") => Some("time"),
        ("builtin_interfaces", "Duration") => Some("duration"),
        _ => None,
    }
}

/// The text ROS 1 hashes for one message: constants, then one line per field with
/// built-in types as written and message types replaced by their own md5sum.
fn md5_text(registry: &Registry, spec: &MsgSpec) -> Result<String, RegistryError> {
    // Resolving first rejects unknown and recursive types before we recurse ourselves.
    registry.layout(&spec.name.to_string(), Dialect::Ros1)?;
    let mut lines = Vec::new();
    for c in &spec.constants {
        lines.push(format!("{} {}={}", c.ty.keyword(), c.name, c.value_text));
    }
    for f in &spec.fields {
        match ros1_type_text(registry, spec, f) {
            Some(t) => lines.push(format!("{t} {}", f.name)),
            None => {
                let Element::Named { package, name } = &f.ty.element else {
                    continue;
                };
                let dep = registry.message(
                    &named_key_string(registry, spec, package, name),
                    Dialect::Ros1,
                )?;
                let sub = hex(&Md5::digest(md5_text(registry, &dep)?.as_bytes()));
                lines.push(format!("{sub} {}", f.name));
            }
        }
    }
    Ok(lines.join("\n"))
}

fn named_key_string(
    registry: &Registry,
    spec: &MsgSpec,
    package: &Option<String>,
    name: &str,
) -> String {
    let (p, n) = registry.with_source(|src| named_key(src, Dialect::Ros1, spec, package, name));
    format!("{p}/{n}")
}

/// A field's type as ROS 1 writes a built-in type (`float64[36]`, `time`), or `None`
/// for message types.
fn ros1_type_text(registry: &Registry, spec: &MsgSpec, f: &FieldSpec) -> Option<String> {
    match &f.ty.element {
        Element::Primitive(_) => f.ty.builtin_text(),
        Element::Named { package, name } => {
            let key =
                registry.with_source(|src| named_key(src, Dialect::Ros1, spec, package, name));
            ros1_time(&key).map(|t| format!("{t}{}", array_suffix(f.ty.array)))
        }
    }
}

/// The definition of `type_name` with all its dependencies, in the concatenated form
/// peers exchange (ROS 1 `message_definition`, rosbridge's `typedefs_full_text`, MCAP
/// `ros1msg`/`ros2msg` schemas). Dependency sections are headed `MSG: pkg/T` in both
/// dialects: that is how the definitions' own fields name them (`std_msgs/Header`), and
/// parsers such as `@foxglove/rosmsg` (Foxglove, Lichtblick) match the two spellings
/// exactly. Parts of services and actions keep `pkg/srv/…` / `pkg/action/…`, the only
/// name that says what they are.
pub fn full_text(
    registry: &Registry,
    type_name: &str,
    dialect: Dialect,
) -> Result<String, RegistryError> {
    let main = registry.message(type_name, dialect)?;
    registry.layout(&main.name.to_string(), dialect)?;
    let mut order: Vec<Arc<MsgSpec>> = Vec::new();
    collect_deps(registry, &main, dialect, &mut order);
    let mut out = own_text(registry, &main, dialect);
    out.push('\n');
    for dep in &order {
        out.push_str(&"=".repeat(80));
        out.push('\n');
        // Service and action parts keep their kind: `pkg/T_Feedback` would name a message.
        let shown = match dep.name.kind() {
            crate::InterfaceKind::Msg => dep.name.short(),
            _ => dep.name.to_string(),
        };
        let _ = writeln!(out, "MSG: {shown}");
        out.push_str(&own_text(registry, dep, dialect));
        out.push('\n');
    }
    out.pop();
    Ok(out)
}

// The method lives here, beside what it calls, so the registry does not depend on the
// identities computed from it.
impl Registry {
    /// The concatenated definition to send along with a topic (see [`crate::full_text`]).
    pub fn full_text(&self, type_name: &str, dialect: Dialect) -> Result<String, RegistryError> {
        full_text(self, type_name, dialect)
    }
}

fn collect_deps(
    registry: &Registry,
    spec: &MsgSpec,
    dialect: Dialect,
    order: &mut Vec<Arc<MsgSpec>>,
) {
    for dep in registry.direct_deps(spec, dialect) {
        if order.iter().any(|o| o.name == dep.name) {
            continue;
        }
        order.push(dep.clone());
        collect_deps(registry, &dep, dialect, order);
    }
}

/// A spec's own text. In the ROS 1 dialect, ROS 2-form definitions are re-rendered so a
/// ROS 1 peer can read them (`builtin_interfaces/Time` becomes `time`, no defaults).
fn own_text(registry: &Registry, spec: &MsgSpec, dialect: Dialect) -> String {
    if dialect == Dialect::Ros2 || registry.has_ros1_override(&spec.name) {
        return spec.text.clone();
    }
    let mut lines = Vec::new();
    for c in &spec.constants {
        lines.push(format!("{} {}={}", c.ty.keyword(), c.name, c.value_text));
    }
    for f in &spec.fields {
        let t = match (&f.ty.element, ros1_type_text(registry, spec, f)) {
            (_, Some(t)) => t,
            (
                Element::Named {
                    package: Some(p),
                    name,
                },
                None,
            ) => format!("{p}/{name}{}", array_suffix(f.ty.array)),
            (
                Element::Named {
                    package: None,
                    name,
                },
                None,
            ) => format!("{name}{}", array_suffix(f.ty.array)),
            (Element::Primitive(_), None) => continue,
        };
        lines.push(format!("{t} {}", f.name));
    }
    lines.join("\n")
}

/// REP-2016 type hash (`RIHS01_<sha256>`) of a message type, computed from the same
/// type description JSON rosidl hashes (field names, type ids, capacities, nested type
/// names; no default values; referenced types sorted by name).
///
/// `char` fields hash as `uint8`, because rosidl converts `.msg` `char` to IDL `uint8`
/// before hashing. (rosbags hashes them as IDL `char`; see [`type_hash_char_as_idl_char`].)
pub fn type_hash(registry: &Registry, type_name: &str) -> Result<String, RegistryError> {
    hash_with(registry, type_name, 3)
}

/// The type hash with `char` fields counted as IDL `char` (type id 13), which is what
/// rosbags computes. Only for cross-checking the rest of the algorithm against rosbags.
#[doc(hidden)]
pub fn type_hash_char_as_idl_char(
    registry: &Registry,
    type_name: &str,
) -> Result<String, RegistryError> {
    hash_with(registry, type_name, 13)
}

fn hash_with(registry: &Registry, type_name: &str, char_id: u32) -> Result<String, RegistryError> {
    let main = registry.message(type_name, Dialect::Ros2)?;
    registry.layout(&main.name.to_string(), Dialect::Ros2)?;
    let mut refs: BTreeMap<String, String> = BTreeMap::new();
    let top = describe(registry, &main, &mut refs, char_id)?;
    let mut json = String::from("{\"type_description\": ");
    json.push_str(&top);
    json.push_str(", \"referenced_type_descriptions\": [");
    json.push_str(&refs.values().cloned().collect::<Vec<_>>().join(", "));
    json.push_str("]}");
    Ok(format!("RIHS01_{}", hex(&Sha256::digest(json.as_bytes()))))
}

fn describe(
    registry: &Registry,
    spec: &MsgSpec,
    refs: &mut BTreeMap<String, String>,
    char_id: u32,
) -> Result<String, RegistryError> {
    let mut fields = Vec::new();
    for f in &spec.fields {
        let (base, nested) = match &f.ty.element {
            Element::Primitive(p) => match p {
                Primitive::Time | Primitive::Duration => {
                    let n = if *p == Primitive::Time {
                        "Time"
                    } else {
                        "Duration"
                    };
                    (1, Some(format!("builtin_interfaces/{n}")))
                }
                Primitive::Char => (char_id, None),
                _ => (primitive_type_id(*p, f.ty.string_bound), None),
            },
            Element::Named { package, name } => {
                let (p, n) =
                    registry.with_source(|src| named_key(src, Dialect::Ros2, spec, package, name));
                (1, Some(format!("{p}/{n}")))
            }
        };
        let mut nested_name = String::new();
        if let Some(n) = nested {
            let dep = registry.message(&n, Dialect::Ros2)?;
            nested_name = dep.name.to_string();
            if !refs.contains_key(&nested_name) {
                let d = describe(registry, &dep, refs, char_id)?;
                refs.insert(nested_name.clone(), d);
            }
        }
        let (offset, capacity) = match f.ty.array {
            ArrayKind::Single => (0, 0),
            ArrayKind::Fixed(n) => (48, n),
            ArrayKind::Bounded(n) => (96, n),
            ArrayKind::Unbounded => (144, 0),
        };
        fields.push(format!(
            "{{\"name\": {}, \"type\": {{\"type_id\": {}, \"capacity\": {capacity}, \"string_capacity\": {}, \"nested_type_name\": {}}}}}",
            json_str(&f.name),
            base + offset,
            f.ty.string_bound.unwrap_or(0),
            json_str(&nested_name)
        ));
    }
    if fields.is_empty() {
        fields.push("{\"name\": \"structure_needs_at_least_one_member\", \"type\": {\"type_id\": 3, \"capacity\": 0, \"string_capacity\": 0, \"nested_type_name\": \"\"}}".to_owned());
    }
    Ok(format!(
        "{{\"type_name\": {}, \"fields\": [{}]}}",
        json_str(&spec.name.to_string()),
        fields.join(", ")
    ))
}

fn json_str(s: &str) -> String {
    serde_json::Value::String(s.to_owned()).to_string()
}

/// rosidl's field type ids (`type_description_interfaces/FieldType`).
fn primitive_type_id(p: Primitive, bound: Option<u32>) -> u32 {
    match p {
        Primitive::Int8 => 2,
        Primitive::UInt8 | Primitive::Char => 3,
        Primitive::Int16 => 4,
        Primitive::UInt16 => 5,
        Primitive::Int32 => 6,
        Primitive::UInt32 => 7,
        Primitive::Int64 => 8,
        Primitive::UInt64 => 9,
        Primitive::Float32 => 10,
        Primitive::Float64 => 11,
        Primitive::Bool => 15,
        Primitive::Byte => 16,
        Primitive::String if bound.is_some() => 21,
        Primitive::String => 17,
        Primitive::WString if bound.is_some() => 22,
        Primitive::WString => 18,
        Primitive::Time | Primitive::Duration => 1,
    }
}
