//! The figures of the effective-mass chapter (the impulse ratio against the lean
//! angle, the sketch at the chosen angle) and the lesson's jamming table.

use super::evidence::{
    matrices, point_mass_ratio, rod_lock_angles_closed_form, rod_ratio, Evidence,
};
use super::sketch::Sketch;
use crate::error::Result;
use crate::physics::rigid::jam_ratio;
use crate::plot::{save_chart, save_drawing, Chart, Legend, Series};
use crate::report::fmt_num;
use std::path::Path;

/// Draws both figures at friction `mu`; returns the written paths.
pub fn draw(dir: &Path, ev: &Evidence, mu: f64, quick: bool) -> Result<Vec<String>> {
    let mut paths = save_chart(&ratio_chart(ev, mu, quick), dir, "impulse-ratio")?;
    let sketch = Sketch {
        theta_rad: ev.at.theta,
        mu,
        ratio_point_mass: ev.at.point_mass,
        ratio_rod: ev.at.rod,
    };
    paths.extend(save_drawing(&sketch, dir, "impulse-sketch", (900, 700))?);
    Ok(paths)
}

/// The impulse ratio of both models against the lean angle, with the self-locking
/// band, the 45 degree example, the rod's maximum and the rod's own jamming angles.
fn ratio_chart(ev: &Evidence, mu: f64, quick: bool) -> Chart {
    let n = if quick { 90 } else { 891 };
    let angles: Vec<f64> = (0..n).map(|i| 89.0 * i as f64 / (n - 1) as f64).collect();
    let pm: Vec<(f64, f64)> = angles
        .iter()
        .map(|&a| (a, point_mass_ratio(a.to_radians())))
        .collect();
    let rd: Vec<(f64, f64)> = angles
        .iter()
        .map(|&a| (a, rod_ratio(a.to_radians())))
        .collect();
    let lock = mu.atan().to_degrees();
    let best = ev.best.theta_rad;
    Chart::new(
        "Sideways impulse of a vertical collision at C",
        "lean angle θ from the vertical (degrees)",
        "J_ℓ / J_v (1)",
    )
    .band(
        0.0,
        lock,
        &format!("self-locking: tan θ < μ = {}", fmt_num(mu)),
    )
    .series(Series::line("point mass: q", pm).color(0))
    .series(Series::line("uniform rod: 3q/(4+q²)", rd).color(1))
    .series(Series::points("45°: 1 and 0.6", vec![(45.0, 1.0), (45.0, 0.6)]).color(6))
    .series(
        Series::points(
            "rod maximum: 0.75 at 63.43°",
            vec![(best.to_degrees(), 0.75)],
        )
        .color(2),
    )
    .series(
        Series::points(
            "rod jams up to / beyond: 3q/(4+q²) = μ",
            rod_lock_angles_closed_form(mu)
                .map(|(a, b)| vec![(a.to_degrees(), mu), (b.to_degrees(), mu)])
                .unwrap_or_default(),
        )
        .color(4),
    )
    .hline(mu, &format!("μ = {}", fmt_num(mu)))
    .vline(lock, "")
    .x_range(0.0, 90.0)
    .y_range(0.0, 2.0)
    .legend(Legend::UpperLeft)
}

/// Markdown table of the impulse ratios and jamming at a few angles.
pub fn jamming_table(mu: f64, angle_deg: f64) -> String {
    let mut angles = vec![10.0, 20.0, 30.0, 45.0, 2f64.atan().to_degrees(), 75.0, 85.0];
    if !angles
        .iter()
        .any(|a: &f64| (a - angle_deg.abs()).abs() < 1e-9)
    {
        angles.push(angle_deg.abs());
        angles.sort_by(|a, b| a.total_cmp(b));
    }
    let mut t = format!(
        "| θ (deg) | q = tan θ | J_ℓ/J_v point mass | J_ℓ/J_v uniform rod | point mass jams (q <= {mu}) | rod jams (3q/(4+q²) <= {mu}) |\n|---|---|---|---|---|---|\n",
        mu = fmt_num(mu)
    );
    for a in angles {
        let th = f64::to_radians(a);
        let (m_rod, m_pm) = matrices(th);
        let (pm, rd) = (jam_ratio(&m_pm), jam_ratio(&m_rod));
        t.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} |\n",
            fmt_num(a),
            fmt_num(th.tan()),
            fmt_num(pm),
            fmt_num(rd),
            pm <= mu,
            rd <= mu
        ));
    }
    t
}
