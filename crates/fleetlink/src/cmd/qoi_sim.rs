//! `fleetlink qoi-sim`: the AFR paper's Figure 5 — Quantity of Information kept by Oracle,
//! AFR, Drop-Oldest and Random after an outage of T messages — written as `qoi.csv` and
//! `qoi.png`. The computation lives in `fleetlink_qos::qoi`; this is argument glue.

use std::io::Write;
use std::path::PathBuf;

use anyhow::Context;
use fleetlink_qos::qoi::{self, QoiParams, ValueFn};

#[derive(clap::Args)]
pub struct Args {
    /// Directory for qoi.csv and qoi.png (created if missing).
    #[arg(long, default_value = ".")]
    out: PathBuf,
    /// Queue length L.
    #[arg(long, default_value_t = 8)]
    l: usize,
    /// Smallest outage length T.
    #[arg(long, default_value_t = 1)]
    t_min: u64,
    /// Largest outage length T.
    #[arg(long, default_value_t = 200)]
    t_max: u64,
    /// Value function V(d): exp:<base> (1 - base^d), log (ln(1+d)) or sqrt.
    #[arg(long, default_value = "exp:0.618", value_parser = ValueFn::parse)]
    v: ValueFn,
    /// Seeded runs of the random policy per T.
    #[arg(long, default_value_t = 10_000)]
    runs: u32,
    /// Seed of the first random run (run r uses seed + r).
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// TrueType font for the chart's labels (default: DejaVu Sans from the system).
    #[arg(long)]
    font: Option<PathBuf>,
}

pub fn run(args: Args) -> anyhow::Result<()> {
    anyhow::ensure!(args.l >= 1, "--l must be at least 1");
    anyhow::ensure!(
        args.t_min >= 1 && args.t_min <= args.t_max,
        "need 1 <= --t-min <= --t-max"
    );
    let params = QoiParams {
        l: args.l,
        t_min: args.t_min,
        t_max: args.t_max,
        v: args.v,
        runs: args.runs.max(1),
        seed: args.seed,
    };
    let rows = qoi::simulate(&params);
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;

    let csv_path = args.out.join("qoi.csv");
    let mut csv = std::io::BufWriter::new(
        std::fs::File::create(&csv_path)
            .with_context(|| format!("creating {}", csv_path.display()))?,
    );
    writeln!(csv, "{}", qoi::QoiRow::CSV_HEADER)?;
    for row in &rows {
        writeln!(csv, "{}", row.to_csv())?;
    }
    csv.flush()
        .with_context(|| format!("writing {}", csv_path.display()))?;

    let png_path = args.out.join("qoi.png");
    let labelled = fleetlink_qos::plot::write_png(&rows, args.l, &png_path, args.font.as_deref())?;
    if !labelled {
        eprintln!(
            "warning: no TrueType font found (use --font); {} has no labels",
            png_path.display()
        );
    }

    let ratio = rows
        .iter()
        .map(|r| (r.afr / r.oracle, r.t))
        .fold((f64::INFINITY, 0), |a, b| if b.0 < a.0 { b } else { a });
    println!("wrote {} and {}", csv_path.display(), png_path.display());
    println!(
        "AFR = Oracle at T = {:?} (T > L)",
        qoi::special_t_values(&rows, args.l)
    );
    println!(
        "min AFR/Oracle = {:.4} at T = {} (Theorem 2 bound {:.4})",
        ratio.0,
        ratio.1,
        qoi::theorem2_bound(args.l)
    );
    let below = rows
        .iter()
        .filter(|r| r.afr + 1e-12 < r.drop_oldest)
        .count();
    println!("T where AFR < Drop-Oldest: {below}");
    Ok(())
}
