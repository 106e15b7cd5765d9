//! Schedulers, drop policies, link estimation and capacity sharing for fleetlink's links:
//! the decisions of *what to send next and what to drop*, on the robot (agent uplink) and
//! on the hub (per-subscriber queues).
//!
//! Every type here is sans-IO: plain deterministic state machines that take `now`
//! ([`Nanos`]) as an argument, `handle_*` what happened and answer `poll_*` questions. No
//! tokio, no threads, no clocks; the agent and hub drive them, tests run them on virtual
//! time.
//!
//! # Layout
//!
//! - [`config`] — per-topic settings ([`TopicQos`], [`Policy`]), defaults by ROS type,
//!   validation.
//! - [`queue`] — one bounded per-topic queue with its drop policy and rate limit
//!   ([`TopicQueue`], [`Push`], [`DropReason`]).
//! - [`afr`] — the AFR buffering algorithm, O(1) per message.
//! - [`rate_limit`] — per-topic message rate limit.
//! - [`scheduler`] — the Robofleet uplink scheduler ([`Scheduler`]): no-drop FIFO first,
//!   then priority × wait, paused by frames in flight and the byte budget.
//! - [`budget`] — a robot's data budget ([`DataBudget`]): a rate and/or a daily
//!   allowance on its link, which holds back all but protected topics while spent.
//! - [`link`] — link estimation from echo probes and acknowledged frames
//!   ([`LinkEstimator`]): rate, latency, clock offset, pacing rate.
//! - [`capacity`] — capacity shares for robots on one access link and the offload signal
//!   ([`CapacityAllocator`]).
//! - [`predict`] — receive-rate prediction for a robot's topics on its measured link
//!   ([`predict::receive_rates`]).
//! - [`qoi`] — Quantity-of-Information evaluation and the offline Oracle (Figure 5 of
//!   the AFR paper).
//! - [`time`], [`rng`] — virtual time and a seeded generator.
//!
//! The configuration reference and the algorithms' conventions are in `docs/qos.md`.

pub mod afr;
pub mod bucket;
pub mod budget;
pub mod capacity;
pub mod config;
mod error;
pub mod link;
#[cfg(feature = "plot")]
pub mod plot;
pub mod predict;
pub mod qoi;
pub mod queue;
pub mod rate_limit;
mod ring;
pub mod rng;
pub mod scheduler;
pub mod time;
mod topic;

pub use bucket::TokenBucket;
pub use budget::{BudgetConfig, DataBudget};
pub use capacity::{CapacityAllocator, CapacityConfig, OffloadParams, RobotLinkReport, Share};
pub use config::{Compression, Mode, Policy, TopicQos, TopicQosSpec};
pub use error::QosError;
pub use link::{LinkConfig, LinkEstimator, Probe};
pub use queue::{DropReason, Push, TopicQueue};
pub use scheduler::{Offer, Scheduler, SchedulerConfig, TopicId, WireLen};
pub use time::Nanos;
