//! `fleetlink msg`: show definitions, decode and encode messages (issue 4).

#[derive(clap::Args)]
pub struct Args {}

pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`fleetlink msg` is not implemented yet")
}
