//! The record crate's integration tests, one binary (each test binary links the whole
//! dependency tree): recordings read back, and the robot's black box.

mod blackbox;
mod recording;
