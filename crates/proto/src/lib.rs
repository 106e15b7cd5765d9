//! fleetlink wire types and codecs. No sockets, no tokio: bytes in, values out.
//!
//! # Layout
//!
//! - [`wire`]: the primitives every frame is built from (LEB128 varints, length-prefixed
//!   strings and byte runs) and a bounds-checked reader over a received buffer.
//! - [`frame`]: the `fleetlink.v1` frames agents and the hub exchange (topics, and service
//!   and action calls), their encoder and decoder (one codec, used by both sides). Byte
//!   layouts are in `docs/protocol.md`.
//! - [`payload`]: a message body as it arrived ([`Payload`]: encoding tag plus shared bytes)
//!   and the schema that travels with a topic ([`Schema`]).
//! - [`compress`]: the envelope of a message on a compressed topic (LZ4, zstd or stored).
//! - [`reassembly`]: turns `CHUNK` frames back into whole messages and `CALL_CHUNK` pieces
//!   back into whole service/action bodies, with size limits.
//! - [`rosbridge`]: rosbridge v2 operations, parsed from JSON text or CBOR binary frames,
//!   and builders for the frames the server sends back.
//! - [`error`]: decode errors that tell *incomplete* input from *invalid* input.

pub mod compress;
pub mod error;
pub mod frame;
pub mod payload;
pub mod reassembly;
pub mod rosbridge;
pub mod wire;

pub use error::{DecodeError, ErrorKind};
pub use frame::{Frame, FrameKind, SUBPROTOCOL};
pub use payload::{Encoding, Payload, Schema};
