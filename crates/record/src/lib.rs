//! MCAP on the hub: recordings of the fleet's topics, and reading files back for replay.
//!
//! - [`spec`]: what a recording is asked to do (`POST /api/v1/recordings`, `fleetlink
//!   record`), checked with errors that name the field.
//! - [`recordings`]: a hub's recordings, each in its own directory with a
//!   `recording.json`, started, stopped, listed and removed.
//! - [`recorder`]: one running recording: a subscriber with its own bounded queue and a
//!   thread that writes.
//! - [`file`]: one MCAP file: typed channels, chunks of at most [`file::CHUNK_MAX`],
//!   zstd, indexes and summary, the recording's figures as metadata.
//! - [`read`]: an MCAP file front to back (`fleetlink play`).
//! - [`blackbox`]: the robot's ring buffer, slices cut from it, and the hub fetching a
//!   slice over the link.

pub mod blackbox;
pub mod file;
pub mod read;
pub mod recorder;
pub mod recordings;
pub mod spec;

pub use recorder::{RecordingInfo, State};
pub use recordings::{RecordError, Recordings};
pub use spec::{Compression, RecordSpec};
