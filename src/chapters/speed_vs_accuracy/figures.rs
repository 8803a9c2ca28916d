//! The chapter's figures: work-precision diagrams and the economy chart.

use super::economy::SweepRow;
use super::work_precision::WpPoint;
use crate::error::Result;
use crate::plot::{save_chart, save_panels, Chart, Series};
use std::path::Path;

/// Method labels in drawing order with (palette colour, dashed).
const METHODS: [(&str, usize, bool); 8] = [
    ("euler-located", 0, false),
    ("euler-unlocated", 0, true),
    ("rk4-located", 1, false),
    ("rk4-unlocated", 1, true),
    ("dopri5-located", 2, false),
    ("dopri5-unlocated", 2, true),
    ("dop853-located", 4, false),
    ("moreau-jean", 3, false),
];

/// Errors below this are drawn at it (the log axis needs positive values).
const FLOOR: f64 = 1e-15;

fn wp_chart(
    points: &[WpPoint],
    problem: &str,
    title: &str,
    x_label: &str,
    x: impl Fn(&WpPoint) -> f64,
) -> Chart {
    let mut c = Chart::new(title, x_label, "relative error of the mean velocity")
        .log_x()
        .log_y();
    for (label, col, dashed) in METHODS {
        let mut pts: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| {
                p.problem == problem && p.solver.label() == label && p.completed && x(p) > 0.0
            })
            .map(|p| (x(p), p.error.max(FLOOR)))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        if pts.is_empty() {
            continue;
        }
        let s = if dashed {
            Series::dashed(label, pts.clone())
        } else {
            Series::line(label, pts.clone())
        };
        c = c
            .series(s.color(col))
            .series(Series::points("", pts).color(col));
    }
    c
}

/// Work-precision charts of `problem`: error against rhs evaluations (committed,
/// deterministic) and against wall time (under `wall-time/`, not committed).
pub fn work_precision(
    dir: &Path,
    points: &[WpPoint],
    problem: &str,
    what: &str,
) -> Result<Vec<String>> {
    let a = wp_chart(
        points,
        problem,
        &format!("{what}: error vs work"),
        "right-hand-side evaluations",
        |p| p.rhs_evals as f64,
    );
    let b = wp_chart(
        points,
        problem,
        &format!("{what}: error vs time"),
        "wall time (s, minimum of repeats)",
        |p| p.wall_s,
    );
    let name = format!("work-precision-{problem}");
    let mut paths = save_chart(&a, dir, &name)?;
    // wall time: machine-dependent, written outside the committed set
    paths.extend(save_chart(
        &b,
        dir.join(crate::chapters::WALL_TIME_DIR),
        &name,
    )?);
    Ok(paths)
}

/// The economy charts: relative error of the averaged laws against Gamma (vertical
/// shaking) and against Γₓ = δₓω²/(μg) (horizontal shaking).
pub fn economy(
    dir: &Path,
    sweep: &[SweepRow],
    horizontal: &[super::economy::HorizontalRow],
) -> Result<Vec<String>> {
    let rel = |m: f64, ex: f64| ((m - ex) / ex).abs().max(1e-6);
    let map: Vec<(f64, f64)> = sweep
        .iter()
        .filter_map(|r| r.2.map(|m| (r.0, rel(m, r.1))))
        .collect();
    let law: Vec<(f64, f64)> = sweep.iter().map(|r| (r.0, rel(r.3, r.1))).collect();
    let c = Chart::new(
        "Vertical shaking: averaged laws",
        "Γ = δ_z ω² / g",
        "relative error of the drift",
    )
    .log_y()
    .series(Series::points("flight map bμg t_f² / (2nT)", map).color(0))
    .series(Series::points("μ_eff law bμ δ_z ω", law).color(1))
    .hline(0.01, "1 %");
    let arcsin: Vec<(f64, f64)> = horizontal.iter().map(|r| (r.0, rel(r.2, r.1))).collect();
    let viscous: Vec<(f64, f64)> = horizontal.iter().map(|r| (r.0, rel(r.3, r.1))).collect();
    let h = Chart::new(
        "Horizontal dither: averaged laws",
        "Γₓ = δₓ ω² / (μg)",
        "relative error of the drift",
    )
    .log_x()
    .log_y()
    .series(Series::line("arcsin law V sin(πb/2)", arcsin).color(0))
    .series(Series::dashed("viscous law F/c, c = 2μg / (πV)", viscous).color(1))
    .hline(0.01, "1 %");
    // One column of two panels, 800 px wide: shown at the book's column width (~750 px)
    // at ~94 %, its smallest text (ticks, ~12.9 px) stays above 11 px (issue 24).
    save_panels(&[c, h], 1, dir, "economy")
}
