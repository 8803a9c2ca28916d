//! Figures of the vertical-shaking chapter (only drawn when figures are on).

use super::chladni::{gamma_at, Chladni, BIAS, PLATE_SIDE_M};
use super::regimes::{gamma_n, Boundary, SweepPoint};
use super::scene::Scene;
use crate::error::Result;
use crate::ladder as work;
use crate::plot::{
    save_chart, save_drawing, save_heatmap, Chart, HeatMap, Legend, Series, WithInset, CHART_SIZE,
};
use std::path::Path;

/// Draws every figure; returns the written paths.
pub fn draw(
    dir: &Path,
    scene: &Scene,
    pts: &[SweepPoint],
    bounds: &[Boundary],
    wp: &[work::WorkPoint],
    _quick: bool,
) -> Result<Vec<String>> {
    let mut paths = Vec::new();

    // Bifurcation diagram: flight durations against Gamma.
    let mut fl = Vec::new();
    for p in pts {
        for &f in &p.flights {
            fl.push((p.gamma, f));
        }
    }
    let mut chart = Chart::new(
        "Completely inelastic block: flight times (last 32 flights)",
        "Γ = δ_z ω² / g",
        "flight time / drive period",
    )
    .points("flights", fl)
    .legend(Legend::Hidden);
    for n in 1..=3 {
        chart = chart.vline(gamma_n(n as f64), &format!("Γ{}", ["₁", "₂", "₃"][n - 1]));
    }
    paths.extend(save_chart(&chart, dir, "bifurcation")?);

    // Regime boundaries over the contact fraction.
    let chart = Chart::new(
        "Contact fraction and located regime boundaries",
        "Γ = δ_z ω² / g",
        "fraction of time in contact",
    );
    let mut chart = regime_bands(chart, pts).line(
        "exact simulation",
        pts.iter().map(|p| (p.gamma, p.contact_fraction)).collect(),
    );
    for b in bounds.iter().filter(|b| b.accuracy() < 1e-3) {
        chart = chart.vline(b.gamma, "");
    }
    paths.extend(save_chart(&chart, dir, "contact-fraction")?);

    // The bias law's error against Gamma.
    let err: Vec<(f64, f64)> = pts
        .iter()
        .filter(|p| p.v_mps > 0.0)
        .map(|p| {
            (
                p.gamma,
                (scene.at_gamma(p.gamma).law_velocity_mps() / p.v_mps - 1.0).abs(),
            )
        })
        .filter(|p| p.1 > 0.0)
        .collect();
    let chart = Chart::new(
        "Bias law v_ave = (F / mg) δω vs exact drift",
        "Γ = δ_z ω² / g",
        "|law / exact - 1|",
    )
    .log_y()
    .points("exact model (Coulomb contact and impacts)", err)
    .hline(0.01, "1 %");
    paths.extend(save_chart(&chart, dir, "bias-law-error")?);

    let [a, b] = work::charts(wp, "vertical shaking");
    paths.extend(save_chart(&a, dir, "work-precision")?);
    // wall time: machine-dependent, written outside the committed set
    let wall = dir.join(crate::chapters::WALL_TIME_DIR);
    paths.extend(save_chart(&b, wall, "work-precision")?);
    Ok(paths)
}

/// Shades the sweep's regimes on `c`, one colour per class of regime ([`regime_class`]; bands reach halfway to the neighbouring points). Band colours cycle
/// with the band index, so empty bands pad each regime to its colour.
fn regime_bands(mut c: Chart, pts: &[SweepPoint]) -> Chart {
    let labels: Vec<String> = pts.iter().map(|p| regime_class(&p.regime).into()).collect();
    let mut order: Vec<&str> = Vec::new();
    let mut i = 0;
    while i < pts.len() {
        let mut j = i;
        while j + 1 < pts.len() && labels[j + 1] == labels[i] {
            j += 1;
        }
        let edge = |k: usize, up: bool| match (up, k) {
            (false, 0) => pts[0].gamma,
            (false, k) => 0.5 * (pts[k - 1].gamma + pts[k].gamma),
            (true, k) if k + 1 == pts.len() => pts[k].gamma,
            (true, k) => 0.5 * (pts[k].gamma + pts[k + 1].gamma),
        };
        let (new, idx) = match order.iter().position(|l| *l == labels[i]) {
            Some(k) => (false, k),
            None => {
                order.push(&labels[i]);
                (true, order.len() - 1)
            }
        };
        while c.bands.len() % 5 != idx % 5 {
            c = c.band(-1e9, -1e9, "");
        }
        let label = if new { labels[i].as_str() } else { "" };
        c = c.band(edge(i, false), edge(j, true), label);
        i = j + 1;
    }
    c
}

/// The class of a regime for the shading: five classes, one per band colour.
fn regime_class(r: &super::regimes::Regime) -> &'static str {
    match (r.flights_per_cycle, r.periods_per_cycle, r.rests) {
        (0, 0, _) => "no flight",
        (0, _, _) => "aperiodic (no period up to 16 flights)",
        (1, _, true) => "rests, one flight per cycle",
        (_, _, true) => "rests, two or more flights per cycle",
        (_, _, false) => "never rests",
    }
}

/// The Chladni demonstration: draws the plate with its grains at the start and at the end, and the drift table.
pub fn chladni(dir: &Path, c: &Chladni) -> Result<Vec<String>> {
    let n = 200;
    let xs = crate::sweep::linspace(0.0, 100.0 * PLATE_SIDE_M, n);
    let values: Vec<Vec<f64>> = xs
        .iter()
        .map(|&y| xs.iter().map(|&x| gamma_at(x / 100.0, y / 100.0)).collect())
        .collect();
    let cm = |ps: &[[f64; 2]]| ps.iter().map(|p| (100.0 * p[0], 100.0 * p[1])).collect();
    let mut paths = Vec::new();
    for (name, when, grains) in [
        ("chladni-start", "at the start", &c.grains.0),
        (
            "chladni",
            &*format!("after {:.0} s", c.t_end_s),
            &c.grains.1,
        ),
    ] {
        let map = HeatMap::new(
            &format!("Grains on a plate in a mode, bias b = {BIAS}: {when}"),
            "x (cm)",
            "y (cm)",
            xs.clone(),
            xs.clone(),
            values.clone(),
            "local peak acceleration Γ (1)",
        )
        .overlay(Series::points("grains", cm(grains)).color(7))
        .legend(Legend::Hidden);
        paths.extend(save_heatmap(&map, dir, name)?);
    }
    let table: Vec<(f64, f64)> = c
        .table
        .gammas
        .iter()
        .copied()
        .zip(c.table.speeds_mps.iter().copied())
        .collect();
    let mm = |v: &[(f64, f64)]| v.iter().map(|p| (p.0, p.1 * 1e3)).collect::<Vec<_>>();
    let main = Chart::new(
        &format!("Drift of the block with bias b = {BIAS} (block model)"),
        "Γ = δ_z ω² / g",
        "mean velocity (mm/s)",
    )
    .line("", mm(&table))
    .legend(Legend::Hidden);
    // the inset: the table's points around the threshold, which joins the grid
    let near: Vec<(f64, f64)> = table
        .iter()
        .copied()
        .filter(|p| (0.8..=1.2).contains(&p.0))
        .collect();
    let inset = Chart::new("near the threshold", "Γ", "mm/s")
        .line_points("", mm(&near))
        .vline(c.threshold.1, "1 − b")
        .vline(c.threshold.0, "located")
        .vline(1.0, "Γ = 1: flights")
        .legend(Legend::Hidden);
    let fig = WithInset {
        main,
        inset,
        frac: (0.11, 0.09, 0.37, 0.45),
    };
    paths.extend(save_drawing(&fig, dir, "chladni-drift", CHART_SIZE)?);
    Ok(paths)
}
