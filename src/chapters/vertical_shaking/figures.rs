//! Figures of the vertical-shaking chapter (only drawn when figures are on).

use super::claims::gamma_n;
use super::regimes::{Boundary, SweepPoint};
use super::scene::Scene;
use crate::error::Result;
use crate::ladder as work;
use crate::plot::{save_chart, Chart, Legend};
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
