//! ROS interface model for fleetlink: parser, type registry and dynamic codecs.
//!
//! fleetlink carries any ROS message type between robots, the hub and browsers without
//! a ROS installation and without recompiling. This crate knows the types (bundled
//! standard definitions, user package directories, definitions received at run time)
//! and converts messages between ROS 2 CDR, ROS 1 serialization, rosbridge JSON and
//! rosbridge CBOR. It does no I/O except reading package directories on request.
//!
//! # Layout
//!
//! - [`name`]: type names in every spelling (`pkg/T`, `pkg/msg/T`, DDS `pkg::msg::dds_::T_`).
//! - [`spec`]: the parsed form of `.msg`/`.srv`/`.action` files.
//! - [`parse`]: the parser (ROS 1 and ROS 2 flavours, errors with line and column).
//! - `bundled`: the standard definitions embedded from `crates/msg/defs/`.
//! - [`registry`]: the shared table of definitions ([`Registry`]).
//! - `layout`: definitions resolved per dialect into the tree the codecs walk.
//! - [`value`]: dynamic message values ([`Value`]).
//! - `binary`: CDR and ROS 1 reader/writer ([`Wire`]).
//! - `loose`: rosbridge JSON/CBOR input rules, shared by both formats.
//! - [`json`], [`cbor`]: rosbridge JSON and CBOR output; `json_text`: the JSON text
//!   parser of the JSON → message hot path.
//! - [`view`]: zero-copy access to header and large arrays of CDR messages ([`CdrView`]).
//! - [`ident`]: ROS 1 md5sums, concatenated full texts, REP-2016 type hashes.
//! - [`error`]: error types.
//!
//! # Entry points
//!
//! ```
//! use fleetlink_msg::{Registry, Wire, decode, encode, from_json, to_json, Dialect};
//! let reg = Registry::bundled();
//! let v = from_json(&reg, "geometry_msgs/Point", Dialect::Ros2, &serde_json::json!({"x": 1})).unwrap();
//! let cdr = encode(&reg, "geometry_msgs/msg/Point", Wire::Cdr, &v).unwrap();
//! assert_eq!(to_json(&decode(&reg, "geometry_msgs/Point", Wire::Cdr, &cdr).unwrap())["x"], 1.0);
//! ```

mod binary;
mod bundled;
pub mod cbor;
mod cbor_check;
pub mod error;
pub mod h264;
pub mod ident;
pub mod json;
pub mod json_scan;
mod json_text;
mod layout;
mod loose;
pub mod name;
pub mod parse;
pub mod registry;
pub mod spec;
pub mod value;
pub mod view;

pub use binary::Wire;
pub use error::{CodecError, ParseError, RegistryError};
pub use ident::{full_text, md5sum, type_hash};
pub use json::{to_json, write_json};
pub use name::{InterfaceKind, TypeName, from_dds_name, ros2_dds_name};
pub use registry::{Registry, Resolved};
pub use spec::Dialect;
pub use value::{Array, Struct, Value};
pub use view::{CdrView, HeaderView, PrimitiveSlice};

/// The dialect whose definitions a wire format uses.
pub fn dialect_of(wire: Wire) -> Dialect {
    match wire {
        Wire::Cdr => Dialect::Ros2,
        Wire::Ros1 => Dialect::Ros1,
    }
}

/// Decodes a serialized message of `type_name`.
pub fn decode(
    registry: &Registry,
    type_name: &str,
    wire: Wire,
    bytes: &[u8],
) -> Result<Value, CodecError> {
    let layout = registry.layout(type_name, dialect_of(wire))?;
    binary::decode_message(&layout, wire, bytes)
        .map_err(|e| binary::in_field(e, &layout.name.short()))
}

/// Serializes a message value of `type_name`. Missing fields take their defaults.
pub fn encode(
    registry: &Registry,
    type_name: &str,
    wire: Wire,
    value: &Value,
) -> Result<Vec<u8>, CodecError> {
    let layout = registry.layout(type_name, dialect_of(wire))?;
    binary::encode_message(&layout, wire, value)
        .map_err(|e| binary::in_field(e, &layout.name.short()))
}

/// Builds a message value from rosbridge JSON (see `docs/msg.md` for the conventions).
pub fn from_json(
    registry: &Registry,
    type_name: &str,
    dialect: Dialect,
    json: &serde_json::Value,
) -> Result<Value, CodecError> {
    let layout = registry.layout(type_name, dialect)?;
    loose::to_struct(&layout, json)
        .map(Value::Struct)
        .map_err(|e| binary::in_field(e, &layout.name.short()))
}

/// Parses rosbridge JSON text and builds a message value.
pub fn from_json_bytes(
    registry: &Registry,
    type_name: &str,
    dialect: Dialect,
    text: &[u8],
) -> Result<Value, CodecError> {
    let layout = registry.layout(type_name, dialect)?;
    let doc = json_text::parse(text)?;
    loose::to_struct(&layout, &doc)
        .map(Value::Struct)
        .map_err(|e| binary::in_field(e, &layout.name.short()))
}

/// Checks rosbridge JSON text against `type_name` and brings it to normal form (missing
/// fields filled with defaults, integers in float fields made floats). `Ok(None)` when the
/// text already is in normal form and can be used as it is, which is the common case and
/// costs one parse without building a message value.
pub fn normalize_json_bytes(
    registry: &Registry,
    type_name: &str,
    dialect: Dialect,
    text: &[u8],
) -> Result<Option<Vec<u8>>, CodecError> {
    normalize_json_resolved(&registry.resolve(type_name, dialect)?, text)
}

/// [`normalize_json_bytes`] for a type resolved beforehand.
pub fn normalize_json_resolved(
    ty: &registry::Resolved,
    text: &[u8],
) -> Result<Option<Vec<u8>>, CodecError> {
    let layout = &ty.layout;
    // One pass without a tree for the common case; the full path decides the rest.
    let quick = json_text::is_normal_text(layout, text);
    if quick && !cfg!(debug_assertions) {
        return Ok(None);
    }
    let doc = json_text::parse(text)?;
    let normal = json_text::is_normal(layout, &doc);
    // Builds with debug assertions (the test suites' `ci` profile) check every message
    // the one-pass check passes against the full one.
    debug_assert!(
        !quick || normal,
        "one-pass normal-form check passed what the full check refuses: {}",
        String::from_utf8_lossy(text)
    );
    if normal {
        return Ok(None);
    }
    let v = loose::to_struct(layout, &doc)
        .map(Value::Struct)
        .map_err(|e| binary::in_field(e, &layout.name.short()))?;
    Ok(Some(to_json_bytes(&v)))
}

/// Rosbridge CBOR checked against a type resolved beforehand and brought to normal form
/// ([`from_cbor`] then [`to_cbor_bytes`], without resolving the type again). `Ok(None)`
/// when the bytes already are in normal form and can be forwarded as they came: one pass
/// without a tree, the common case for clients that write what rosbridge writes.
pub fn normalize_cbor_resolved(
    ty: &registry::Resolved,
    bytes: &[u8],
) -> Result<Option<Vec<u8>>, CodecError> {
    let layout = &ty.layout;
    let quick = cbor_check::is_normal(layout, bytes);
    if quick && !cfg!(debug_assertions) {
        return Ok(None);
    }
    let doc: ciborium::Value =
        ciborium::de::from_reader(bytes).map_err(|e| CodecError::Cbor(e.to_string()))?;
    let v = loose::to_struct(layout, &doc)
        .map(Value::Struct)
        .map_err(|e| binary::in_field(e, &layout.name.short()))?;
    let normal = to_cbor_bytes(&v);
    // Builds with debug assertions (the test suites' `ci` profile) check every message the
    // one-pass check passes against the full path's output.
    debug_assert!(
        !quick || normal == bytes,
        "one-pass CBOR normal-form check passed bytes the full path rewrites: {bytes:02x?}"
    );
    Ok(if quick || normal == bytes {
        None
    } else {
        Some(normal)
    })
}

/// The message as compact rosbridge JSON text.
pub fn to_json_bytes(value: &Value) -> Vec<u8> {
    let mut out = Vec::with_capacity(256);
    write_json(value, &mut out);
    out
}

/// CDR bytes → rosbridge JSON text, without an intermediate `serde_json::Value`.
pub fn cdr_to_json_bytes(
    registry: &Registry,
    type_name: &str,
    cdr: &[u8],
) -> Result<Vec<u8>, CodecError> {
    let v = decode(registry, type_name, Wire::Cdr, cdr)?;
    let mut out = Vec::with_capacity(cdr.len() * 4 / 3 + 256);
    write_json(&v, &mut out);
    Ok(out)
}

/// The message as rosbridge CBOR (the object rosbridge's `cbor` compression embeds).
pub fn to_cbor_bytes(value: &Value) -> Vec<u8> {
    let mut out = Vec::with_capacity(256);
    cbor::write_cbor(value, &mut out);
    out
}

/// CDR bytes → rosbridge CBOR.
pub fn cdr_to_cbor_bytes(
    registry: &Registry,
    type_name: &str,
    cdr: &[u8],
) -> Result<Vec<u8>, CodecError> {
    let v = decode(registry, type_name, Wire::Cdr, cdr)?;
    let mut out = Vec::with_capacity(cdr.len() + 256);
    cbor::write_cbor(&v, &mut out);
    Ok(out)
}

/// Builds a message value from rosbridge CBOR bytes (typed arrays, byte strings).
pub fn from_cbor(
    registry: &Registry,
    type_name: &str,
    dialect: Dialect,
    bytes: &[u8],
) -> Result<Value, CodecError> {
    let layout = registry.layout(type_name, dialect)?;
    let doc: ciborium::Value =
        ciborium::de::from_reader(bytes).map_err(|e| CodecError::Cbor(e.to_string()))?;
    loose::to_struct(&layout, &doc)
        .map(Value::Struct)
        .map_err(|e| binary::in_field(e, &layout.name.short()))
}

/// The value a message of `type_name` has when every field takes its default.
pub fn default_value(
    registry: &Registry,
    type_name: &str,
    dialect: Dialect,
) -> Result<Value, CodecError> {
    let layout = registry.layout(type_name, dialect)?;
    Ok(layout::zero(&layout::Elem::Msg(layout)))
}
