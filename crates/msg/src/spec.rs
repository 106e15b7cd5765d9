//! The parsed form of interface definitions, before dependencies are resolved.
//!
//! Design choice: a [`MsgSpec`] keeps field types as written (`Header`, `Point`,
//! `geometry_msgs/Point`) and its source text; resolution against a registry happens
//! later in `layout`, so definitions can arrive in any order (a package directory, a
//! concatenated full text) and unknown dependencies are reported where they are used.

use crate::name::TypeName;

/// Built-in field types of the ROS 1 and ROS 2 interface languages.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Primitive {
    Bool,
    /// ROS 1: signed 8-bit (deprecated alias of `int8`); ROS 2: `octet`, unsigned.
    Byte,
    /// ROS 1: unsigned 8-bit (alias of `uint8`); ROS 2: unsigned 8-bit.
    Char,
    Int8,
    UInt8,
    Int16,
    UInt16,
    Int32,
    UInt32,
    Int64,
    UInt64,
    Float32,
    Float64,
    String,
    WString,
    /// ROS 1 `time`: `uint32 secs, uint32 nsecs`; in ROS 2 read as `builtin_interfaces/Time`.
    Time,
    /// ROS 1 `duration`: `int32 secs, int32 nsecs`; in ROS 2 `builtin_interfaces/Duration`.
    Duration,
}

impl Primitive {
    /// The keyword for this type in `.msg` files.
    pub fn keyword(self) -> &'static str {
        match self {
            Primitive::Bool => "bool",
            Primitive::Byte => "byte",
            Primitive::Char => "char",
            Primitive::Int8 => "int8",
            Primitive::UInt8 => "uint8",
            Primitive::Int16 => "int16",
            Primitive::UInt16 => "uint16",
            Primitive::Int32 => "int32",
            Primitive::UInt32 => "uint32",
            Primitive::Int64 => "int64",
            Primitive::UInt64 => "uint64",
            Primitive::Float32 => "float32",
            Primitive::Float64 => "float64",
            Primitive::String => "string",
            Primitive::WString => "wstring",
            Primitive::Time => "time",
            Primitive::Duration => "duration",
        }
    }

    /// Parses a keyword; `None` for message type names.
    pub fn from_keyword(word: &str) -> Option<Self> {
        Some(match word {
            "bool" => Primitive::Bool,
            "byte" => Primitive::Byte,
            "char" => Primitive::Char,
            "int8" => Primitive::Int8,
            "uint8" => Primitive::UInt8,
            "int16" => Primitive::Int16,
            "uint16" => Primitive::UInt16,
            "int32" => Primitive::Int32,
            "uint32" => Primitive::UInt32,
            "int64" => Primitive::Int64,
            "uint64" => Primitive::UInt64,
            "float32" => Primitive::Float32,
            "float64" => Primitive::Float64,
            "string" => Primitive::String,
            "wstring" => Primitive::WString,
            "time" => Primitive::Time,
            "duration" => Primitive::Duration,
            _ => return None,
        })
    }
}

/// How many elements a field holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ArrayKind {
    /// A single value.
    Single,
    /// `T[N]`: exactly N, no length on the wire.
    Fixed(u32),
    /// `T[<=N]` (ROS 2): a sequence of at most N.
    Bounded(u32),
    /// `T[]`: a sequence.
    Unbounded,
}

/// The element type of a field, as written.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Element {
    Primitive(Primitive),
    /// A message type: `Point` (package-relative), `geometry_msgs/Point`, or ROS 1 `Header`.
    Named {
        package: Option<String>,
        name: String,
    },
}

/// A field's full type.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct FieldType {
    pub element: Element,
    /// `string<=N`: the maximum length in bytes.
    pub string_bound: Option<u32>,
    pub array: ArrayKind,
}

impl FieldType {
    /// The type as ROS 1's md5 text writes built-in types, e.g. `float64[36]`.
    pub fn builtin_text(&self) -> Option<String> {
        let Element::Primitive(p) = &self.element else {
            return None;
        };
        let mut s = p.keyword().to_owned();
        if let Some(b) = self.string_bound {
            s.push_str(&format!("<={b}"));
        }
        s.push_str(&array_suffix(self.array));
        Some(s)
    }
}

/// `[]`, `[N]`, `[<=N]` or nothing.
pub fn array_suffix(array: ArrayKind) -> String {
    match array {
        ArrayKind::Single => String::new(),
        ArrayKind::Fixed(n) => format!("[{n}]"),
        ArrayKind::Bounded(n) => format!("[<={n}]"),
        ArrayKind::Unbounded => "[]".to_owned(),
    }
}

/// One field declaration.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldSpec {
    pub name: String,
    pub ty: FieldType,
    /// ROS 2 default value text, as written after the name.
    pub default: Option<String>,
    /// 1-based line of the declaration (for error messages).
    pub line: usize,
}

/// One constant declaration (`uint8 FOO = 1`).
#[derive(Debug, Clone, PartialEq)]
pub struct ConstantSpec {
    pub name: String,
    pub ty: Primitive,
    /// The value text, trimmed (ROS 1's md5 uses this text).
    pub value_text: String,
}

/// A message, or one part of a service or action.
#[derive(Debug, Clone, PartialEq)]
pub struct MsgSpec {
    pub name: TypeName,
    pub fields: Vec<FieldSpec>,
    pub constants: Vec<ConstantSpec>,
    /// The definition text this spec was parsed from (one section for srv/action parts).
    pub text: String,
}

/// What one interface file defines.
#[derive(Debug, Clone, PartialEq)]
pub enum Definition {
    Msg(MsgSpec),
    Srv {
        name: TypeName,
        request: MsgSpec,
        response: MsgSpec,
    },
    Action {
        name: TypeName,
        goal: MsgSpec,
        result: MsgSpec,
        feedback: MsgSpec,
    },
}

impl Definition {
    /// The interface's own name.
    pub fn name(&self) -> &TypeName {
        match self {
            Definition::Msg(m) => &m.name,
            Definition::Srv { name, .. } | Definition::Action { name, .. } => name,
        }
    }
}

/// Which ROS generation a definition or message belongs to.
///
/// It decides how `time`, `duration`, `Header` and `byte` are read and which standard
/// definitions apply (ROS 1 `std_msgs/Header` carries a `seq` field, ROS 2's does not).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Dialect {
    Ros1,
    Ros2,
}
