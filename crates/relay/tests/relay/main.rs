//! The relay crate's integration tests, one binary (each test binary links the whole
//! dependency tree): the link writer over an in-memory sink, and ROS 1 field names.

mod link_writer;
mod ros1_names;
