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

pub trait Transcoder: Send + Sync + 'static {
    /// The message object of `payload` in encoding `to`. Called at most once per message
    /// and target encoding.
    fn convert(
        &self,
        schema: &Schema,
        payload: &Payload,
        to: Encoding,
    ) -> Result<Bytes, TranscodeError>;
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
