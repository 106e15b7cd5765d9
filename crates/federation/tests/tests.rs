//! The federation crate's integration tests, one binary: hubs federated in-process over
//! Zenoh on loopback (plain TCP), each with its own router.

mod keyframes;
mod util;
