//! Integration tests of `fleetlink-qos`, compiled into one binary (one module per concern).

mod data_budget;
mod no_allocation;
mod policy_properties;
mod qoi_claims;
mod scheduler_order;
mod simulated_link;
mod util;
