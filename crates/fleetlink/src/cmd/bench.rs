//! `fleetlink bench`: the load generators live in the `fleetlink-bench` crate; this module
//! hands them the process setup they borrow from the binary.

pub use fleetlink_bench::Args;

pub fn run(args: Args) -> anyhow::Result<()> {
    let host = fleetlink_bench::Host {
        init_logging: super::init_logging,
        raise_open_files: super::raise_open_files,
    };
    fleetlink_bench::run(args, &host)
}
