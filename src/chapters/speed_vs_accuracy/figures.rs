//! The chapter's figures: work-precision diagrams (error against cost, [`crate::ladder`]),
//! the economy charts and the stick by three methods.

use super::economy::SweepRow;
use super::evidence::Evidence;
use super::stick_methods::SceneMethods;
use super::work_precision::WpPoint;
use crate::error::Result;
use crate::ladder::{self, CostAxis, Curve, Draw};
use crate::plot::{save_chart, save_panels, Chart, Legend, Series};
use crate::report::ChapterReport;
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

fn wp_chart(points: &[WpPoint], title: &str, x_label: &str, axis: CostAxis) -> Chart {
    let curves = METHODS
        .into_iter()
        .map(|(label, col, dashed)| {
            let rungs = points.iter().filter(|p| p.setting.label() == label);
            let mut pts = ladder::points(rungs, axis, FLOOR);
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            let draw = if dashed {
                Draw::DashedAndMarkers
            } else {
                Draw::LineAndMarkers
            };
            Curve::new(label, draw, pts).color(col)
        })
        .collect();
    ladder::chart(title, x_label, "relative error of the mean velocity", curves)
}

/// Every figure of the chapter, added to the report in order: the work-precision charts
/// of the block and the stick, the economy charts, the stick by three methods.
pub fn draw(dir: &Path, ev: &Evidence, r: &mut ChapterReport) -> Result<()> {
    let block = work_precision(dir, &ev.block.points, "block-drift", "Block drift")?;
    r.figures.extend(block);
    let stick = work_precision(dir, &ev.stick.points, "stick-speed", "Stick mean speed")?;
    r.figures.extend(stick);
    r.figures
        .extend(economy(dir, &ev.economy.sweep, &ev.horizontal.rows)?);
    r.figures.extend(stick_methods(
        dir,
        &ev.methods_default,
        "Stick by three methods: self-locking scene",
        "stick-methods-default",
    )?);
    r.figures.extend(stick_methods(
        dir,
        &ev.methods_authors,
        "Stick by three methods: authors' scene",
        "stick-methods-authors",
    )?);
    Ok(())
}

/// Work-precision charts of `problem` (its `points`): error against rhs evaluations
/// (committed, deterministic) and against wall time (under `wall-time/`, not committed).
fn work_precision(
    dir: &Path,
    points: &[WpPoint],
    problem: &str,
    what: &str,
) -> Result<Vec<String>> {
    let a = wp_chart(
        points,
        &format!("{what}: error vs work"),
        "right-hand-side evaluations",
        CostAxis::RhsEvals,
    );
    let b = wp_chart(
        points,
        &format!("{what}: error vs time"),
        "wall time (s, minimum of repeats)",
        CostAxis::Wall,
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

/// Labels and colours of the stick's three methods in their charts.
const STICK_METHODS: [(&str, &str, usize); 4] = [
    ("event_dop853", "event-driven DOP853 (rtol)", 4),
    ("event_dopri5", "event-driven DP5 (rtol)", 2),
    ("moreau_jean", "Moreau-Jean (step h)", 3),
    ("soft_contact", "soft contact + Rosenbrock (ε)", 0),
];

/// The stick by three methods on one scene: error against force evaluations.
fn stick_methods(dir: &Path, s: &SceneMethods, title: &str, name: &str) -> Result<Vec<String>> {
    let curves = STICK_METHODS
        .into_iter()
        .map(|(key, label, col)| {
            let pts = ladder::points(&s.ladder(key).rungs, CostAxis::RhsEvals, FLOOR);
            Curve::new(label, Draw::LineAndMarkers, pts).color(col)
        })
        .collect();
    let c = ladder::chart(
        title,
        "force evaluations",
        "relative difference of the mean speed",
        curves,
    )
    .legend(Legend::LowerRight);
    save_panels(&[c], 1, dir, name)
}

/// The economy charts: relative error of the averaged laws against Gamma (vertical
/// shaking) and against Γₓ = δₓω²/(μg) (horizontal shaking).
fn economy(
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
