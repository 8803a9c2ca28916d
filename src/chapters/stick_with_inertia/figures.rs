//! The chapter's figures: the Painleve boundary (closed form and bisected points).

use super::evidence::Evidence;
use crate::error::Result;
use crate::physics::stick_inertia::painleve::mu_painleve;
use crate::plot::{save_chart, Chart, Legend};
use std::path::Path;

/// `painleve-boundary`: mu_P(theta) for the three rods, with the bisected points.
pub fn painleve_boundary(ev: &Evidence, dir: &Path) -> Result<Vec<String>> {
    let mut chart = Chart::new(
        "Painleve boundary of the sliding rod",
        "lean angle theta (rad)",
        "mu_P (1)",
    )
    .y_range(0.0, 4.0)
    .legend(Legend::UpperRight);
    let mut alphas: Vec<f64> = ev.boundaries.iter().map(|b| b.1).collect();
    alphas.dedup();
    for a in alphas {
        let curve = (1..150)
            .map(|i| {
                let th = 1.5 * i as f64 / 150.0;
                (th, mu_painleve(th, a))
            })
            .filter(|p| p.1 < 4.0)
            .collect();
        chart = chart.line(&format!("alpha = {a:.3}"), curve);
    }
    let tan = (1..150)
        .map(|i| 1.3 * i as f64 / 150.0)
        .map(|th: f64| (th, th.tan()))
        .filter(|p| p.1 < 4.0)
        .collect();
    chart = chart.dashed("tan(theta): alpha -> infinity (chapter 6's edge)", tan);
    let pts = ev.boundaries.iter().map(|b| (b.0, b.2)).collect();
    chart = chart.points("bisection on the simulated slide", pts);
    save_chart(&chart, dir, "painleve-boundary")
}

/// `validity-map`: the massless model's relative speed error against `I_P k / gamma^2`.
pub fn validity_map(ev: &Evidence, dir: &Path) -> Result<Vec<String>> {
    let mut chart = Chart::new(
        "Error of the massless model (chapter 6) against the rod's inertia",
        "I_P k / gamma^2 (1)",
        "|mean-speed error| (1)",
    )
    .log_x()
    .log_y()
    .hline(0.01, "1 %")
    .hline(0.1, "10 %")
    .legend(Legend::UpperLeft);
    for (name, l) in ["self-locking scene", "authors' scene"]
        .iter()
        .zip(&ev.ladders)
    {
        let pts = l
            .iter()
            .map(|r| (r.inertia_ratio, r.error().abs()))
            .collect();
        chart = chart.line_points(name, pts);
    }
    save_chart(&chart, dir, "validity-map")
}

/// `painleve-map`: the cells of the (theta_0, mu) map whose gait met a Painleve case.
pub fn painleve_map(map: &[Vec<super::answers::MapCell>], dir: &Path) -> Result<Vec<String>> {
    let mut chart = Chart::new(
        "Where the gait meets Painleve cases (the authors' plate)",
        "spring rest angle theta_0 (rad)",
        "friction mu (1)",
    )
    .x_range(0.0, 1.05)
    .y_range(0.0, 2.1)
    .legend(Legend::LowerRight);
    for (i, ((label, ..), cells)) in super::answers::MAP_RODS.iter().zip(map).enumerate() {
        let pts: Vec<(f64, f64)> = cells
            .iter()
            .filter(|c| c.events > 0)
            // offset each distribution a little so that shared cells stay visible
            .map(|c| (c.theta0_rad + 0.012 * (i as f64 - 1.0), c.mu))
            .collect();
        chart = chart.series(crate::plot::Series::points(label, pts).color(i));
    }
    for (i, a) in [3.0, 5.4].iter().enumerate() {
        let curve = (1..100)
            .map(|k| 1.05 * k as f64 / 100.0)
            .map(|th: f64| (th, mu_painleve(th, *a)))
            .filter(|p| p.1 < 2.1)
            .collect();
        chart = chart.series(
            crate::plot::Series::dashed(&format!("mu_P at the rest angle, alpha = {a}"), curve)
                .color(i),
        );
    }
    let tan = (1..100)
        .map(|k| 1.05 * k as f64 / 100.0)
        .map(|th: f64| (th, th.tan()))
        .filter(|p| p.1 < 2.1)
        .collect();
    chart = chart.series(crate::plot::Series::dashed("tan(theta_0)", tan).color(2));
    save_chart(&chart, dir, "painleve-map")
}
