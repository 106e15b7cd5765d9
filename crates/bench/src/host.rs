//! What a bench borrows from the program that runs it: the process-wide setup the
//! `fleetlink` binary owns (its log subscriber, its limit on open files), handed in so
//! this crate does not depend on the binary's package.

/// The binary's process setup, as plain functions.
#[derive(Clone, Copy)]
pub struct Host {
    /// Installs the process's log subscriber; the argument is the default level
    /// (`RUST_LOG` overrides it).
    pub init_logging: fn(&str),
    /// Raises the soft limit on open files to at least the given number, or says why it
    /// cannot.
    pub raise_open_files: fn(u64) -> anyhow::Result<()>,
}
