//! `fleetlink agent`.

#[derive(clap::Args)]
pub struct Args {}

pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`fleetlink agent` is not implemented yet")
}
