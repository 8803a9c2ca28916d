//! Figures of the vertical-shaking chapter (only drawn when figures are on).

use super::claims::gamma_n;
use super::regimes::{Boundary, SweepPoint};
use super::scene::Scene;
use crate::chapters::horizontal_shaking::work;
use crate::error::Result;
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
        "Gamma = delta_z omega^2 / g",
        "flight time / drive period",
    )
    .points("flights", fl)
    .legend(Legend::UpperLeft);
    for n in 1..=3 {
        chart = chart.vline(gamma_n(n as f64), &format!("Gamma_{n}"));
    }
    paths.extend(save_chart(&chart, dir, "bifurcation")?);

    // Regime boundaries over the contact fraction.
    let mut chart = Chart::new(
        "Contact fraction and located regime boundaries",
        "Gamma",
        "fraction of time in contact",
    )
    .line(
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
        "Bias law v_ave = (F / m g) delta omega vs exact drift",
        "Gamma",
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
