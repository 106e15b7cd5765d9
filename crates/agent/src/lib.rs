//! The robot side of fleetlink.
//!
//! # Layout
//!
//! - [`config`]: the agent's YAML configuration, with errors that name file, line and field.
//! - [`sim`]: a simulated robot producing plausible sensor data at configured rates.

pub mod config;
pub mod sim;
