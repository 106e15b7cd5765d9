//! Integration tests of the ROS 1 adapter: one test binary (ripgrep style).
//!
//! - `bridge`: the whole bridge against an in-process fake master and publisher.
//! - `malformed_inputs`: one attack per test on the XML-RPC and TCPROS decoders.
//! - `round_trips`: property tests of the codecs.

mod it {
    mod bridge;
    mod malformed_inputs;
    mod round_trips;
}
