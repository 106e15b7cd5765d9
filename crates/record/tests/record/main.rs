//! The record crate's integration tests, one binary (each test binary links the whole
//! dependency tree): recordings read back, the robot's black box, and the hub fetching
//! a slice of it.

mod blackbox;
mod fetch;
mod recording;
