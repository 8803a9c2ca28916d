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
    let mut alphas: Vec<f64> = ev.boundaries.iter().map(|b| b.alpha).collect();
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
    let pts = ev.boundaries.iter().map(|b| (b.theta_rad, b.mu)).collect();
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

/// A curve: (x, y) points.
type Curve = Vec<(f64, f64)>;

/// Chapter 6's massless rod on the self-locking scene from rest to `t_end` (s), sampled
/// every `dt` (s): label, foot x (mm) and foot height above the plate (mm) against drive cycles.
fn massless_gait(
    t_end: f64,
    dt: f64,
    opts: &crate::numerics::hybrid::Options,
) -> (String, Curve, Curve) {
    use crate::physics::stick::jamming_scene;
    use crate::physics::stick::run::{initial_state, simulate_stick, Recording};
    use crate::physics::stick::StickModel;
    let b6 = jamming_scene(9.81);
    let m6 = StickModel::new(b6);
    let y6 = initial_state(&m6, 0.0, b6.static_angle().unwrap_or(b6.theta0_rad));
    let rec = Recording {
        trace_dt_s: dt,
        ..Recording::default()
    };
    let s6 = simulate_stick(&m6, 0.0, y6, t_end, opts, rec);
    let pick6 = |k: usize| -> Vec<(f64, f64)> {
        s6.trace
            .iter()
            .map(|s| {
                (
                    s.t_s * 30.0,
                    1e3 * (s.y[k]
                        - if k == crate::physics::stick::ZC {
                            m6.plate(s.t_s).0
                        } else {
                            0.0
                        }),
                )
            })
            .collect()
    };
    (
        "massless rod, 1 kg at P (chapter 6)".into(),
        pick6(crate::physics::stick::XC),
        pick6(crate::physics::stick::ZC),
    )
}

/// `gaits`: the foot's position and height over four drive cycles of the self-locking
/// scene, for the massless model (chapter 6), a 1 kg tip on a 10 g rod, and a uniform
/// 1 kg stick (with chapter 6's spring and damper).
pub fn gaits(dir: &Path) -> Result<Vec<String>> {
    use crate::numerics::hybrid::Options;
    use crate::physics::stick::jamming_scene;
    use crate::physics::stick_inertia::{InertiaParams, XC, ZC};
    let t_end = 4.0 / 30.0;
    let dt = t_end / 800.0;
    let opts = Options {
        record_events: false,
        ..super::evidence::options(1e-10)
    };
    let b6 = jamming_scene(9.81);
    let mut series: Vec<(String, Curve, Curve)> = vec![massless_gait(t_end, dt, &opts)];
    for (label, m, m_r) in [
        ("1 kg at P on a 10 g rod", 1.0, 0.01),
        ("uniform 1 kg stick", 0.0, 1.0),
    ] {
        let mut b = b6;
        b.mass_kg = m;
        let p = InertiaParams {
            base: b,
            rod_mass_kg: m_r,
            restitution: 0.0,
        };
        let md = crate::physics::stick_inertia::InertiaModel::new(p);
        let r = super::evidence::scene_run(&p, t_end, 1e-10, dt);
        let xs = r
            .trace
            .iter()
            .map(|s| (s.t_s * 30.0, 1e3 * s.y[XC]))
            .collect();
        let hs = r
            .trace
            .iter()
            .map(|s| (s.t_s * 30.0, 1e3 * (s.y[ZC] - md.plate(s.t_s).0)))
            .collect();
        series.push((label.into(), xs, hs));
    }
    let mut cx = Chart::new(
        "The foot's walk (self-locking scene's plate)",
        "time (drive cycles)",
        "x of the foot C (mm)",
    )
    .legend(Legend::UpperLeft);
    let mut ch = Chart::new(
        "The foot's height above the plate",
        "time (drive cycles)",
        "h_C (mm)",
    )
    .legend(Legend::UpperLeft);
    for (i, (label, xs, hs)) in series.into_iter().enumerate() {
        cx = cx.series(crate::plot::Series::line(&label, xs).color(i));
        ch = ch.series(crate::plot::Series::line(&label, hs).color(i));
    }
    let mut out = save_chart(&cx, dir, "gait-position")?;
    out.extend(save_chart(&ch, dir, "gait-height")?);
    Ok(out)
}
