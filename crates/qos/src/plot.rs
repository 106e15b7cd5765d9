//! PNG rendering of the QoI comparison (`fleetlink qoi-sim`), behind the `plot` feature.
//!
//! Design choice: `plotters` with only its bitmap backend and the pure-Rust `ab_glyph`
//! text renderer, so it builds on a bare machine (no fontconfig, no freetype). A TrueType
//! font is loaded at run time from the given path or the usual system locations; without
//! one the chart is drawn without text (the CSV carries the numbers).

use std::path::{Path, PathBuf};

use plotters::prelude::*;

use crate::qoi::QoiRow;

/// Error while drawing or writing the PNG, with the plotting library's message.
#[derive(Debug, thiserror::Error)]
#[error("cannot draw {path}: {reason}")]
pub struct PlotError {
    pub path: PathBuf,
    pub reason: String,
}

const FONT_CANDIDATES: &[&str] = &[
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
    "/System/Library/Fonts/Supplemental/Arial.ttf",
];

/// Registers a font for labels; returns false if none could be loaded.
fn register_font(explicit: Option<&Path>) -> bool {
    let candidates = explicit
        .map(|p| vec![p.to_path_buf()])
        .unwrap_or_else(|| FONT_CANDIDATES.iter().map(PathBuf::from).collect());
    for path in candidates {
        if let Ok(bytes) = std::fs::read(&path) {
            // plotters keeps fonts for the life of the process; one leak per run.
            let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
            if plotters::style::register_font("sans-serif", FontStyle::Normal, bytes).is_ok() {
                return true;
            }
        }
    }
    false
}

/// Draws Oracle, AFR, Drop-Oldest and Random (mean, ±1 sd band) against T.
/// Returns whether labels could be drawn (a font was found).
pub fn write_png(
    rows: &[QoiRow],
    l: usize,
    path: &Path,
    font: Option<&Path>,
) -> Result<bool, PlotError> {
    let labelled = register_font(font);
    draw(rows, l, path, labelled)
        .map(|()| labelled)
        .map_err(|e| PlotError {
            path: path.to_path_buf(),
            reason: e.to_string(),
        })
}

fn draw(
    rows: &[QoiRow],
    l: usize,
    path: &Path,
    labelled: bool,
) -> Result<(), Box<dyn std::error::Error>> {
    let root = BitMapBackend::new(path, (1000, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let t_min = rows.first().map_or(1, |r| r.t);
    let t_max = rows.last().map_or(2, |r| r.t).max(t_min + 1);
    let y_max = rows
        .iter()
        .map(|r| r.oracle.max(r.random_mean + r.random_sd))
        .fold(0.0, f64::max)
        * 1.05;
    let mut builder = ChartBuilder::on(&root);
    builder.margin(20);
    if labelled {
        builder
            .caption(
                format!("Quantity of Information after an outage (L = {l})"),
                ("sans-serif", 24),
            )
            .x_label_area_size(45)
            .y_label_area_size(60);
    } else {
        builder.x_label_area_size(10).y_label_area_size(10);
    }
    let mut chart = builder.build_cartesian_2d(t_min as f64..t_max as f64, 0.0..y_max.max(1.0))?;
    let mut mesh = chart.configure_mesh();
    if labelled {
        mesh.x_desc("T (messages during the outage)").y_desc("QoI");
    } else {
        mesh.disable_x_axis().disable_y_axis();
    }
    mesh.draw()?;

    let band_color = RGBColor(255, 160, 60);
    let band: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| (r.t as f64, r.random_mean + r.random_sd))
        .chain(
            rows.iter()
                .rev()
                .map(|r| (r.t as f64, (r.random_mean - r.random_sd).max(0.0))),
        )
        .collect();
    chart.draw_series(std::iter::once(Polygon::new(band, band_color.mix(0.25))))?;
    type Series = (&'static str, RGBColor, fn(&QoiRow) -> f64);
    let series: [Series; 4] = [
        ("Oracle", BLACK, |r| r.oracle),
        ("AFR", RGBColor(200, 30, 30), |r| r.afr),
        ("Drop-Oldest", RGBColor(30, 90, 200), |r| r.drop_oldest),
        ("Random (mean, ±1 sd)", band_color, |r| r.random_mean),
    ];
    for (name, color, value) in series {
        let drawn = chart.draw_series(LineSeries::new(
            rows.iter().map(|r| (r.t as f64, value(r))),
            color.stroke_width(2),
        ))?;
        if labelled {
            drawn.label(name).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
        }
    }
    if labelled {
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .draw()?;
    }
    root.present()?;
    Ok(())
}
