//! rosbridge v2 operations: what clients send ([`inbound`]), what the server sends back
//! ([`outbound`]), and schema-less conversion between the JSON and CBOR forms of a
//! message object ([`convert`]).
//!
//! A client may send JSON text frames or CBOR binary frames (rosbridge itself accepts only
//! text from clients; fleetlink accepts both). Either way the message object inside a
//! `publish` (or the `args` of a `call_service`) is kept as encoded bytes in a
//! [`Payload`](crate::Payload) rather than as a parsed tree, so it can be forwarded
//! without being rebuilt.

pub mod convert;
pub mod inbound;
pub mod outbound;
mod scan;
pub mod shape;

pub use inbound::{Compression, Op, ParseError, Publish, PublishId, Request};
pub use scan::is_json_value;
pub use shape::EnvelopeShapes;
