//! Resolved message layouts: the tree the codecs walk.
//!
//! Design choice: a definition is resolved once per dialect into an `Arc` tree where
//! every nested type is a direct pointer (no name look-ups while decoding), ROS 1
//! `time`/`duration` and ROS 2 `builtin_interfaces` are mapped to the dialect's own
//! form, defaults are parsed into [`Value`]s, and recursion is rejected. The registry
//! caches layouts and drops the cache whenever a definition changes.

use std::collections::HashMap;
use std::sync::Arc;

use crate::error::RegistryError;
use crate::name::TypeName;
use crate::parse::parse_scalar;
use crate::spec::{ArrayKind, Dialect, Element, FieldSpec, MsgSpec, Primitive};
use crate::value::{Array, Struct, Value};

/// Wire-level element kinds after dialect mapping.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scalar {
    Bool,
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    I64,
    U64,
    F32,
    F64,
    String,
    WString,
    /// ROS 1 `time`: `uint32 sec, uint32 nanosec`.
    Time,
    /// ROS 1 `duration`: `int32 sec, int32 nanosec`.
    Duration,
}

impl Scalar {
    /// Size on the wire for fixed-size scalars (ROS 1 time counts as 8).
    pub fn fixed_size(self) -> Option<usize> {
        Some(match self {
            Scalar::Bool | Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::I64 | Scalar::U64 | Scalar::F64 | Scalar::Time | Scalar::Duration => 8,
            Scalar::String | Scalar::WString => return None,
        })
    }
}

/// The element type of a resolved field.
#[derive(Debug, Clone)]
pub enum Elem {
    Scalar(Scalar),
    Msg(Arc<MsgLayout>),
}

/// One resolved field.
#[derive(Debug, Clone)]
pub struct FieldLayout {
    pub name: Arc<str>,
    pub elem: Elem,
    pub array: ArrayKind,
    pub string_bound: Option<u32>,
    pub default: Option<Value>,
}

/// A resolved message type.
#[derive(Debug)]
pub struct MsgLayout {
    pub name: TypeName,
    pub fields: Vec<FieldLayout>,
}

/// Where resolution looks definitions up: `(dialect, key) -> spec`.
pub(crate) trait SpecSource {
    fn spec(&self, dialect: Dialect, key: &(String, String)) -> Option<Arc<MsgSpec>>;
}

pub(crate) type LayoutCache = HashMap<(Dialect, (String, String)), Arc<MsgLayout>>;

/// Resolves `key` (and everything it uses) into a layout, filling `cache`.
pub(crate) fn compile(
    src: &dyn SpecSource,
    cache: &mut LayoutCache,
    dialect: Dialect,
    key: &(String, String),
    stack: &mut Vec<(String, String)>,
    from: &str,
) -> Result<Arc<MsgLayout>, RegistryError> {
    if let Some(l) = cache.get(&(dialect, key.clone())) {
        return Ok(l.clone());
    }
    if stack.contains(key) {
        let mut chain: Vec<String> = stack.iter().map(|(p, n)| format!("{p}/{n}")).collect();
        chain.push(format!("{}/{}", key.0, key.1));
        return Err(RegistryError::Recursive {
            chain: chain.join(" -> "),
        });
    }
    let spec = src
        .spec(dialect, key)
        .ok_or_else(|| RegistryError::UnknownType {
            name: format!("{}/{}", key.0, key.1),
            from: from.to_owned(),
        })?;
    stack.push(key.clone());
    let mut fields = Vec::with_capacity(spec.fields.len());
    for f in &spec.fields {
        let elem = resolve_elem(src, cache, dialect, &spec, f, stack)?;
        let default =
            match &f.default {
                Some(text) => Some(parse_default(&elem, f, text).map_err(|reason| {
                    RegistryError::BadDefault {
                        type_name: spec.name.to_string(),
                        field: f.name.clone(),
                        reason,
                    }
                })?),
                None => None,
            };
        fields.push(FieldLayout {
            name: Arc::from(f.name.as_str()),
            elem,
            array: f.ty.array,
            string_bound: f.ty.string_bound,
            default,
        });
    }
    stack.pop();
    let layout = Arc::new(MsgLayout {
        name: spec.name.clone(),
        fields,
    });
    cache.insert((dialect, key.clone()), layout.clone());
    Ok(layout)
}

/// The registry key a named element refers to, from inside `spec`.
pub(crate) fn named_key(
    src: &dyn SpecSource,
    dialect: Dialect,
    spec: &MsgSpec,
    package: &Option<String>,
    name: &str,
) -> (String, String) {
    match package {
        Some(p) => (p.clone(), name.to_owned()),
        None => {
            let local = (spec.name.package().to_owned(), name.to_owned());
            if name == "Header" && src.spec(dialect, &local).is_none() {
                ("std_msgs".to_owned(), "Header".to_owned())
            } else {
                local
            }
        }
    }
}

fn resolve_elem(
    src: &dyn SpecSource,
    cache: &mut LayoutCache,
    dialect: Dialect,
    spec: &MsgSpec,
    f: &FieldSpec,
    stack: &mut Vec<(String, String)>,
) -> Result<Elem, RegistryError> {
    let builtin = |name: &str| ("builtin_interfaces".to_owned(), name.to_owned());
    let key = match (&f.ty.element, dialect) {
        (Element::Primitive(p), _) => match (p, dialect) {
            (Primitive::Time, Dialect::Ros2) => builtin("Time"),
            (Primitive::Duration, Dialect::Ros2) => builtin("Duration"),
            _ => return Ok(Elem::Scalar(scalar_of(*p, dialect))),
        },
        (Element::Named { package, name }, _) => named_key(src, dialect, spec, package, name),
    };
    if dialect == Dialect::Ros1 && key.0 == "builtin_interfaces" {
        match key.1.as_str() {
            "Time" => return Ok(Elem::Scalar(Scalar::Time)),
            "Duration" => return Ok(Elem::Scalar(Scalar::Duration)),
            _ => {}
        }
    }
    let from = format!("{}.{}", spec.name, f.name);
    Ok(Elem::Msg(compile(src, cache, dialect, &key, stack, &from)?))
}

/// The wire scalar for a primitive in a dialect (`byte` is signed only in ROS 1).
pub(crate) fn scalar_of(p: Primitive, dialect: Dialect) -> Scalar {
    match p {
        Primitive::Bool => Scalar::Bool,
        Primitive::Byte if dialect == Dialect::Ros1 => Scalar::I8,
        Primitive::Byte | Primitive::Char | Primitive::UInt8 => Scalar::U8,
        Primitive::Int8 => Scalar::I8,
        Primitive::Int16 => Scalar::I16,
        Primitive::UInt16 => Scalar::U16,
        Primitive::Int32 => Scalar::I32,
        Primitive::UInt32 => Scalar::U32,
        Primitive::Int64 => Scalar::I64,
        Primitive::UInt64 => Scalar::U64,
        Primitive::Float32 => Scalar::F32,
        Primitive::Float64 => Scalar::F64,
        Primitive::String => Scalar::String,
        Primitive::WString => Scalar::WString,
        Primitive::Time => Scalar::Time,
        Primitive::Duration => Scalar::Duration,
    }
}

fn primitive_of(s: Scalar) -> Primitive {
    match s {
        Scalar::Bool => Primitive::Bool,
        Scalar::I8 => Primitive::Int8,
        Scalar::U8 => Primitive::UInt8,
        Scalar::I16 => Primitive::Int16,
        Scalar::U16 => Primitive::UInt16,
        Scalar::I32 => Primitive::Int32,
        Scalar::U32 => Primitive::UInt32,
        Scalar::I64 => Primitive::Int64,
        Scalar::U64 => Primitive::UInt64,
        Scalar::F32 => Primitive::Float32,
        Scalar::F64 => Primitive::Float64,
        Scalar::String => Primitive::String,
        Scalar::WString => Primitive::WString,
        Scalar::Time => Primitive::Time,
        Scalar::Duration => Primitive::Duration,
    }
}

fn parse_default(elem: &Elem, f: &FieldSpec, text: &str) -> Result<Value, String> {
    let Elem::Scalar(s) = elem else {
        return Err("only primitive fields can have defaults".into());
    };
    let prim = primitive_of(*s);
    if f.ty.array == ArrayKind::Single {
        return parse_scalar(prim, text);
    }
    let inner = text
        .trim()
        .strip_prefix('[')
        .and_then(|t| t.strip_suffix(']'))
        .ok_or_else(|| format!("array default `{text}` must be in [brackets]"))?;
    let items: Vec<Value> = split_items(inner)
        .into_iter()
        .filter(|t| !t.is_empty())
        .map(|t| parse_scalar(prim, t))
        .collect::<Result<_, _>>()?;
    let n = items.len();
    match f.ty.array {
        ArrayKind::Fixed(len) if n != len as usize => {
            return Err(format!("{n} values for an array of {len}"));
        }
        ArrayKind::Bounded(max) if n > max as usize => {
            return Err(format!("{n} values for an array of at most {max}"));
        }
        _ => {}
    }
    Ok(Value::Array(pack(*s, items)))
}

/// Splits `a, "b,c", d` on commas outside quotes, trimming each item.
fn split_items(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut quote = None;
    let mut start = 0;
    for (i, c) in text.char_indices() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if c == '"' || c == '\'' => quote = Some(c),
            None if c == ',' => {
                out.push(text[start..i].trim());
                start = i + 1;
            }
            None => {}
        }
    }
    out.push(text[start..].trim());
    out
}

/// Packs scalar values of one kind into the typed array variant.
pub(crate) fn pack(s: Scalar, items: Vec<Value>) -> Array {
    macro_rules! typed {
        ($variant:ident) => {
            Array::$variant(
                items
                    .into_iter()
                    .filter_map(|v| match v {
                        Value::$variant(x) => Some(x),
                        _ => None,
                    })
                    .collect(),
            )
        };
    }
    match s {
        Scalar::Bool => typed!(Bool),
        Scalar::I8 => typed!(I8),
        Scalar::U8 => typed!(U8),
        Scalar::I16 => typed!(I16),
        Scalar::U16 => typed!(U16),
        Scalar::I32 => typed!(I32),
        Scalar::U32 => typed!(U32),
        Scalar::I64 => typed!(I64),
        Scalar::U64 => typed!(U64),
        Scalar::F32 => typed!(F32),
        Scalar::F64 => typed!(F64),
        _ => Array::Values(items),
    }
}

static SECS: std::sync::LazyLock<Arc<str>> = std::sync::LazyLock::new(|| Arc::from("secs"));
static NSECS: std::sync::LazyLock<Arc<str>> = std::sync::LazyLock::new(|| Arc::from("nsecs"));

/// A ROS 1 time or duration as the codecs hold it: `{secs, nsecs}`, ROS 1's names, which
/// rosbridge on ROS 1 writes and ROS 1 clients read (roslibpy's actionlib reads
/// `stamp.secs`). Only the ROS 1 dialect has these primitives; a ROS 2 time is the
/// message `builtin_interfaces/Time`, `{sec, nanosec}`.
pub(crate) fn time_value(secs: Value, nsecs: Value) -> Value {
    Value::Struct(Struct {
        fields: vec![(SECS.clone(), secs), (NSECS.clone(), nsecs)],
    })
}

/// The value a field takes when a message omits it: its default, else zero/empty.
pub(crate) fn default_field(f: &FieldLayout) -> Value {
    if let Some(d) = &f.default {
        return d.clone();
    }
    match f.array {
        ArrayKind::Single => zero(&f.elem),
        ArrayKind::Fixed(n) => {
            let n = n as usize;
            match &f.elem {
                Elem::Scalar(s)
                    if !matches!(
                        s,
                        Scalar::String | Scalar::WString | Scalar::Time | Scalar::Duration
                    ) =>
                {
                    pack(*s, vec![zero(&f.elem); n])
                }
                _ => Array::Values(vec![zero(&f.elem); n]),
            }
            .into()
        }
        ArrayKind::Bounded(_) | ArrayKind::Unbounded => match &f.elem {
            Elem::Scalar(s) => pack(*s, Vec::new()).into(),
            Elem::Msg(_) => Value::Array(Array::Values(Vec::new())),
        },
    }
}

/// The zero value of one element.
pub(crate) fn zero(elem: &Elem) -> Value {
    match elem {
        Elem::Scalar(s) => match s {
            Scalar::Bool => Value::Bool(false),
            Scalar::I8 => Value::I8(0),
            Scalar::U8 => Value::U8(0),
            Scalar::I16 => Value::I16(0),
            Scalar::U16 => Value::U16(0),
            Scalar::I32 => Value::I32(0),
            Scalar::U32 => Value::U32(0),
            Scalar::I64 => Value::I64(0),
            Scalar::U64 => Value::U64(0),
            Scalar::F32 => Value::F32(0.0),
            Scalar::F64 => Value::F64(0.0),
            Scalar::String | Scalar::WString => Value::String(String::new()),
            Scalar::Time => time_value(Value::U32(0), Value::U32(0)),
            Scalar::Duration => time_value(Value::I32(0), Value::I32(0)),
        },
        Elem::Msg(m) => Value::Struct(Struct {
            fields: m
                .fields
                .iter()
                .map(|f| (f.name.clone(), default_field(f)))
                .collect(),
        }),
    }
}
