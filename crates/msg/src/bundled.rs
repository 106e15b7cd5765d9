//! The standard interface definitions shipped inside the crate.
//!
//! Design choice: the `.msg`/`.srv`/`.action` files under `crates/msg/defs/` are written
//! by us from the public interface specifications and embedded at build time, so a hub
//! needs no ROS installation. `defs/ros2` holds the ROS 2 (Humble) forms; `defs/ros1`
//! holds only the few types whose ROS 1 layout differs (e.g. `std_msgs/Header` with
//! `seq`), which override the ROS 2 form in the ROS 1 dialect.

/// `(dialect dir, package, kind, type, text)` for every bundled file.
pub(crate) const FILES: &[(&str, &str, &str, &str, &str)] =
    include!(concat!(env!("OUT_DIR"), "/bundled_list.rs"));
