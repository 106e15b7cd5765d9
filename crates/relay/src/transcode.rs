//! Converting a message body between encodings.
//!
//! The router never converts eagerly: a [`Message`](crate::Message) asks its transcoder
//! the first time a subscriber needs another encoding and caches the result. The
//! [`GenericTranscoder`] handles JSON ↔ CBOR without knowing the type; converting the raw
//! ROS serializations (CDR, ROS 1) needs a type registry and is supplied by the message
//! layer through this same trait.

use bytes::Bytes;
use fleetlink_proto::rosbridge::convert;
use fleetlink_proto::{Encoding, Payload, Schema};

#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TranscodeError {
    #[error("cannot convert {type_name} from {from} to {to}: {reason}")]
    Unsupported {
        type_name: String,
        from: Encoding,
        to: Encoding,
        reason: String,
    },
    #[error("cannot convert {type_name} from {from} to {to}: {cause}")]
    Invalid {
        type_name: String,
        from: Encoding,
        to: Encoding,
        cause: String,
    },
}

impl TranscodeError {
    /// Why, without the conversion's endpoints (for messages about one message).
    pub fn cause_text(&self) -> String {
        match self {
            TranscodeError::Unsupported { reason, .. } => reason.clone(),
            TranscodeError::Invalid { cause, .. } => cause.clone(),
        }
    }
}

pub trait Transcoder: Send + Sync + 'static {
    /// The message object of `payload` in encoding `to`. Called at most once per message
    /// and target encoding.
    fn convert(
        &self,
        schema: &Schema,
        payload: &Payload,
        to: Encoding,
    ) -> Result<Bytes, TranscodeError>;

    /// A topic was advertised with this schema: remember its definition so messages of a
    /// type nobody compiled in can be converted.
    fn learn(&self, _schema: &Schema) {}

    /// The full definition of a known type, to send along with a topic.
    fn schema_for(&self, _type_name: &str) -> Option<Schema> {
        None
    }

    /// The ROS 1 identity of a known message or service type (a native ROS 1 peer needs
    /// the md5sum and, for topics, the full `message_definition`).
    fn ros1_identity(&self, _type_name: &str) -> Option<Ros1Identity> {
        None
    }

    /// A rosbridge publish checked and completed against its type, once at the hub:
    /// missing fields filled with their defaults, integers in float fields made floats,
    /// a wrong type refused naming the field. `Ok(None)` when the type is not known here
    /// (the message goes on as sent).
    fn normalize(
        &self,
        _schema: &Schema,
        _payload: &Payload,
    ) -> Result<Option<Payload>, TranscodeError> {
        Ok(None)
    }

    /// [`Transcoder::normalize`] for a publisher that sends many messages on one topic:
    /// `cache` keeps whatever the transcoder resolved for the type between calls.
    /// Unlike `normalize`, takes the message and gives it back (unchanged, moved, when
    /// it already is in normal form or the type is not known here).
    fn normalize_cached(
        &self,
        schema: &Schema,
        payload: Payload,
        _cache: &mut NormalizeCache,
    ) -> Result<Payload, TranscodeError> {
        Ok(self.normalize(schema, &payload)?.unwrap_or(payload))
    }

    /// [`Transcoder::normalize_cached`] of JSON text that nothing has checked yet, not even
    /// as UTF-8 (the message of a publish read by its envelope's shape), left where it
    /// is: `Ok(None)` when `text` is the message as it goes out, `Ok(Some(..))` with the
    /// message to send instead (defaults filled, numbers converted). The text is checked
    /// as it is read — by the check against the type where the type is known, for its
    /// syntax and UTF-8 where not. The error does not say which check failed; the caller
    /// reads such a message again the full way for that.
    fn normalize_json_unchecked(
        &self,
        schema: &Schema,
        text: &[u8],
        _cache: &mut NormalizeCache,
    ) -> Result<Option<Bytes>, TranscodeError> {
        check_syntax(schema, text)?;
        let payload = Payload::json(Bytes::copy_from_slice(text));
        Ok(self.normalize(schema, &payload)?.map(|p| p.bytes))
    }

    /// Every message type this side knows (rosapi `interfaces`).
    fn type_names(&self) -> Vec<String> {
        Vec::new()
    }

    /// rosapi's `typedefs` for a message type (the type and every type it uses): per
    /// type its field names, types, array lengths (-1 single, 0 unbounded, N fixed),
    /// example values, constant names and values. `None` for an unknown type.
    fn typedefs(&self, _type_name: &str) -> Option<Vec<serde_json::Value>> {
        None
    }
}

/// JSON text that is not exactly one JSON value (in UTF-8) is refused.
fn check_syntax(schema: &Schema, text: &[u8]) -> Result<(), TranscodeError> {
    if fleetlink_proto::rosbridge::is_json_value(text) {
        return Ok(());
    }
    Err(invalid(
        schema,
        Encoding::Json,
        "not one well-formed JSON value".into(),
    ))
}

/// A message refused by its check against `schema`'s type.
fn invalid(schema: &Schema, enc: Encoding, cause: String) -> TranscodeError {
    TranscodeError::Invalid {
        type_name: schema.type_name.clone(),
        from: enc,
        to: enc,
        cause,
    }
}

/// State a transcoder keeps for one publisher's topic between
/// [`Transcoder::normalize_cached`] calls; opaque to the caller.
#[derive(Default)]
pub struct NormalizeCache(Option<Box<dyn std::any::Any + Send + Sync>>);

/// What a ROS 1 connection header says about a type.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Ros1Identity {
    /// `pkg/T` (ROS 1 spelling, no `msg/` or `srv/`).
    pub type_name: String,
    pub md5sum: String,
    /// The concatenated definition (`MSG: pkg/T` sections); empty for services.
    pub definition: String,
}

/// Type-aware conversion through the message registry (`crates/msg`): CDR and ROS 1 to
/// and from rosbridge JSON and CBOR (typed arrays, byte strings), following the rosbridge
/// conventions. Types the registry does not know fall back to [`GenericTranscoder`].
#[derive(Clone)]
pub struct RegistryTranscoder {
    registry: fleetlink_msg::Registry,
}

impl RegistryTranscoder {
    pub fn new(registry: fleetlink_msg::Registry) -> RegistryTranscoder {
        RegistryTranscoder { registry }
    }

    pub fn bundled() -> RegistryTranscoder {
        Self::new(fleetlink_msg::Registry::bundled())
    }

    pub fn registry(&self) -> &fleetlink_msg::Registry {
        &self.registry
    }
}

impl RegistryTranscoder {
    /// The type of `schema` as resolved for checking messages in `enc`, kept in `cache`
    /// between calls; `None` when the registry does not know the type.
    fn resolved<'c>(
        &self,
        schema: &Schema,
        enc: Encoding,
        cache: &'c mut NormalizeCache,
    ) -> Result<Option<&'c fleetlink_msg::registry::Resolved>, TranscodeError> {
        let reg = &self.registry;
        let ty = schema.type_name.as_str();
        let dialect = dialect_of(schema, enc);
        let current = cache
            .0
            .as_ref()
            .and_then(|c| c.downcast_ref::<ResolvedTopic>())
            .is_some_and(|c| {
                c.type_name == ty && c.dialect == dialect && reg.is_current(&c.resolved)
            });
        if !current {
            if !reg.contains(ty) {
                return Ok(None);
            }
            let resolved = reg
                .resolve(ty, dialect)
                .map_err(|e| invalid(schema, enc, e.to_string()))?;
            cache.0 = Some(Box::new(ResolvedTopic {
                type_name: ty.to_owned(),
                dialect,
                resolved,
            }));
        }
        Ok(cache
            .0
            .as_ref()
            .and_then(|c| c.downcast_ref::<ResolvedTopic>())
            .map(|c| &c.resolved))
    }
}

/// What [`RegistryTranscoder::normalize_cached`] keeps per topic.
struct ResolvedTopic {
    type_name: String,
    dialect: fleetlink_msg::Dialect,
    resolved: fleetlink_msg::Resolved,
}

/// The dialect a topic's messages are read in, and so the names their times and headers
/// take: ROS 1's for a ROS 1 robot's topic (its definition came as `ros1msg`, or its
/// payload is ROS 1 serialization), and for a type only ROS 1 has
/// (`TypeName::is_ros1_only`: actionlib's) when no robot said otherwise — rosbridge
/// clients of such a type are ROS 1 programs (docs/msg.md, "ROS 1 names").
fn dialect_of(schema: &Schema, payload: Encoding) -> fleetlink_msg::Dialect {
    let ros1_type = || {
        schema.encoding != "ros2msg"
            && fleetlink_msg::TypeName::parse(&schema.type_name).is_ok_and(|t| t.is_ros1_only())
    };
    if payload == Encoding::Ros1 || schema.encoding == "ros1msg" || ros1_type() {
        fleetlink_msg::Dialect::Ros1
    } else {
        fleetlink_msg::Dialect::Ros2
    }
}

impl Transcoder for RegistryTranscoder {
    fn convert(
        &self,
        schema: &Schema,
        payload: &Payload,
        to: Encoding,
    ) -> Result<Bytes, TranscodeError> {
        use fleetlink_msg::{
            Wire, decode, encode, from_cbor, from_json_bytes, to_cbor_bytes, to_json_bytes,
        };
        let from = payload.encoding;
        if from == to {
            return Ok(payload.bytes.clone());
        }
        let ty = schema.type_name.as_str();
        if !self.registry.contains(ty) {
            return GenericTranscoder.convert(schema, payload, to);
        }
        let reg = &self.registry;
        let dialect = dialect_of(schema, from);
        let invalid = |e: fleetlink_msg::CodecError| TranscodeError::Invalid {
            type_name: ty.to_owned(),
            from,
            to,
            cause: e.to_string(),
        };
        let value = match from {
            Encoding::Json => from_json_bytes(reg, ty, dialect, &payload.bytes),
            Encoding::Cbor => from_cbor(reg, ty, dialect, &payload.bytes),
            Encoding::Cdr => decode(reg, ty, Wire::Cdr, &payload.bytes),
            Encoding::Ros1 => decode(reg, ty, Wire::Ros1, &payload.bytes),
        }
        .map_err(invalid)?;
        let out = match to {
            Encoding::Json => to_json_bytes(&value),
            Encoding::Cbor => to_cbor_bytes(&value),
            Encoding::Cdr => encode(reg, ty, Wire::Cdr, &value).map_err(invalid)?,
            Encoding::Ros1 => encode(reg, ty, Wire::Ros1, &value).map_err(invalid)?,
        };
        Ok(Bytes::from(out))
    }

    fn learn(&self, schema: &Schema) {
        if schema.text.is_empty()
            || schema.type_name.is_empty()
            || self.registry.contains(&schema.type_name)
        {
            return;
        }
        let dialect = if schema.encoding == "ros1msg" {
            fleetlink_msg::Dialect::Ros1
        } else {
            fleetlink_msg::Dialect::Ros2
        };
        if let Err(e) = self
            .registry
            .add_full_text(&schema.type_name, &schema.text, dialect)
        {
            tracing::warn!(
                "cannot use the definition sent for {}: {e}",
                schema.type_name
            );
        }
    }

    fn ros1_identity(&self, type_name: &str) -> Option<Ros1Identity> {
        let name = fleetlink_msg::TypeName::parse(type_name).ok()?;
        let md5sum = fleetlink_msg::md5sum(&self.registry, type_name).ok()?;
        let definition = match name.kind() {
            fleetlink_msg::InterfaceKind::Msg => self
                .registry
                .full_text(type_name, fleetlink_msg::Dialect::Ros1)
                .ok()?,
            _ => String::new(),
        };
        Some(Ros1Identity {
            type_name: format!("{}/{}", name.package(), name.name()),
            md5sum,
            definition,
        })
    }

    fn normalize(
        &self,
        schema: &Schema,
        payload: &Payload,
    ) -> Result<Option<Payload>, TranscodeError> {
        let ty = schema.type_name.as_str();
        let from = payload.encoding;
        if !matches!(from, Encoding::Json | Encoding::Cbor) || !self.registry.contains(ty) {
            return Ok(None);
        }
        let reg = &self.registry;
        let dialect = dialect_of(schema, from);
        let invalid = |e: fleetlink_msg::CodecError| TranscodeError::Invalid {
            type_name: ty.to_owned(),
            from,
            to: from,
            cause: e.to_string(),
        };
        if from == Encoding::Json {
            // One path for JSON: the cached one, with a cache that lives for this call.
            let cache = &mut NormalizeCache::default();
            return self
                .normalize_cached(schema, payload.clone(), cache)
                .map(Some);
        }
        let v = fleetlink_msg::from_cbor(reg, ty, dialect, &payload.bytes).map_err(invalid)?;
        Ok(Some(Payload::new(
            Encoding::Cbor,
            fleetlink_msg::to_cbor_bytes(&v),
        )))
    }

    fn normalize_cached(
        &self,
        schema: &Schema,
        payload: Payload,
        cache: &mut NormalizeCache,
    ) -> Result<Payload, TranscodeError> {
        let enc = payload.encoding;
        if !matches!(enc, Encoding::Json | Encoding::Cbor) {
            return Ok(self.normalize(schema, &payload)?.unwrap_or(payload));
        }
        let Some(resolved) = self.resolved(schema, enc, cache)? else {
            return Ok(payload);
        };
        let refused = |e: fleetlink_msg::CodecError| invalid(schema, enc, e.to_string());
        if enc == Encoding::Cbor {
            return match fleetlink_msg::normalize_cbor_resolved(resolved, &payload.bytes) {
                Ok(Some(normal)) => Ok(Payload::new(Encoding::Cbor, normal)),
                // Already in normal form: the bytes as they came (no copy).
                Ok(None) => Ok(payload),
                Err(e) => Err(refused(e)),
            };
        }
        match fleetlink_msg::normalize_json_resolved(resolved, &payload.bytes) {
            Ok(Some(normal)) => Ok(Payload::json(normal)),
            // Already in normal form: the bytes as they came (no copy).
            Ok(None) => Ok(payload),
            Err(e) => Err(refused(e)),
        }
    }

    fn normalize_json_unchecked(
        &self,
        schema: &Schema,
        text: &[u8],
        cache: &mut NormalizeCache,
    ) -> Result<Option<Bytes>, TranscodeError> {
        let Some(resolved) = self.resolved(schema, Encoding::Json, cache)? else {
            // Not checked against a type: its syntax (and UTF-8), on its own.
            check_syntax(schema, text)?;
            return Ok(None);
        };
        // The check against the type accepts only UTF-8, and the full path's parse
        // checks it first.
        fleetlink_msg::normalize_json_resolved(resolved, text)
            .map(|normal| normal.map(Bytes::from))
            .map_err(|e| invalid(schema, Encoding::Json, e.to_string()))
    }

    fn type_names(&self) -> Vec<String> {
        self.registry
            .message_names()
            .iter()
            .map(|n| n.to_string())
            .collect()
    }

    fn typedefs(&self, type_name: &str) -> Option<Vec<serde_json::Value>> {
        use fleetlink_msg::spec::{ArrayKind, Element};
        let reg = &self.registry;
        let dialect = fleetlink_msg::Dialect::Ros2;
        let first = reg.resolve_name(type_name, dialect).ok()?;
        let mut out = Vec::new();
        let mut todo = vec![first.to_string()];
        let mut seen = std::collections::HashSet::new();
        while let Some(name) = todo.pop() {
            if !seen.insert(name.clone()) {
                continue;
            }
            let Ok(spec) = reg.message(&name, dialect) else {
                continue;
            };
            let (mut names, mut types, mut lens, mut examples) =
                (Vec::new(), Vec::new(), Vec::new(), Vec::new());
            for f in &spec.fields {
                let (ty, example) = match &f.ty.element {
                    Element::Primitive(p) => {
                        let k = p.keyword();
                        let ex = match k {
                            "string" | "wstring" => "",
                            "bool" => "False",
                            "time" | "duration" => "{}",
                            _ => "0",
                        };
                        (k.to_owned(), ex)
                    }
                    Element::Named { package, name: n } => {
                        let pkg = package.clone().unwrap_or_else(|| {
                            if n == "Header" {
                                "std_msgs".to_owned()
                            } else {
                                spec.name.package().to_owned()
                            }
                        });
                        let full = reg
                            .resolve_name(&format!("{pkg}/{n}"), dialect)
                            .map(|t| t.to_string())
                            .unwrap_or_else(|_| format!("{pkg}/msg/{n}"));
                        todo.push(full.clone());
                        (full, "{}")
                    }
                };
                let len = match f.ty.array {
                    ArrayKind::Single => -1,
                    ArrayKind::Fixed(n) => i64::from(n),
                    ArrayKind::Bounded(_) | ArrayKind::Unbounded => 0,
                };
                names.push(f.name.clone());
                types.push(ty);
                lens.push(len);
                examples.push(if len >= 0 { "[]" } else { example }.to_owned());
            }
            out.push(serde_json::json!({
                "type": spec.name.to_string(),
                "fieldnames": names,
                "fieldtypes": types,
                "fieldarraylen": lens,
                "examples": examples,
                "constnames": spec.constants.iter().map(|c| c.name.clone()).collect::<Vec<_>>(),
                "constvalues": spec.constants.iter().map(|c| c.value_text.clone()).collect::<Vec<_>>(),
            }));
        }
        Some(out)
    }

    fn schema_for(&self, type_name: &str) -> Option<Schema> {
        // A type only ROS 1 has is given as ROS 1's, so that its topic is read in the ROS 1
        // dialect (`dialect_of`) and its channel is a ROS 1 one.
        let ros1 = fleetlink_msg::TypeName::parse(type_name).is_ok_and(|t| t.is_ros1_only());
        let (dialect, encoding) = if ros1 {
            (fleetlink_msg::Dialect::Ros1, "ros1msg")
        } else {
            (fleetlink_msg::Dialect::Ros2, "ros2msg")
        };
        let text = self.registry.full_text(type_name, dialect).ok()?;
        Some(Schema {
            type_name: type_name.to_owned(),
            encoding: encoding.into(),
            text,
        })
    }
}

/// Schema-less JSON ↔ CBOR conversion (see [`fleetlink_proto::rosbridge::convert`]).
#[derive(Debug, Default, Clone, Copy)]
pub struct GenericTranscoder;

impl Transcoder for GenericTranscoder {
    fn convert(
        &self,
        schema: &Schema,
        payload: &Payload,
        to: Encoding,
    ) -> Result<Bytes, TranscodeError> {
        let from = payload.encoding;
        if from == to {
            return Ok(payload.bytes.clone());
        }
        let invalid = |cause: convert::ConvertError| TranscodeError::Invalid {
            type_name: schema.type_name.clone(),
            from,
            to,
            cause: cause.to_string(),
        };
        match (from, to) {
            (Encoding::Json, Encoding::Cbor) => convert::json_to_cbor(&payload.bytes)
                .map(Bytes::from)
                .map_err(invalid),
            (Encoding::Cbor, Encoding::Json) => convert::cbor_to_json(&payload.bytes)
                .map(Bytes::from)
                .map_err(invalid),
            _ => Err(TranscodeError::Unsupported {
                type_name: schema.type_name.clone(),
                from,
                to,
                reason: "no message definition is loaded for this conversion".into(),
            }),
        }
    }
}
