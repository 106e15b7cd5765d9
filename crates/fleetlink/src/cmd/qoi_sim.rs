//! `fleetlink qoi-sim`: the AFR paper's Figure 5 (issue 3).

#[derive(clap::Args)]
pub struct Args {}

pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("`fleetlink qoi-sim` is not implemented yet")
}
