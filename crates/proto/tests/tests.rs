//! The integration tests of `fleetlink-proto`, compiled into one binary.
//!
//! - `round_trip`: property tests that whatever is encoded decodes to the same value.
//! - `malformed_inputs`: one test per attack on the decoders, each asserting a clean error.
//! - `util`: strategies and byte builders the two share.

mod malformed_inputs;
mod round_trip;
mod util;
