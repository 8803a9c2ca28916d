//! Figures of the horizontal-shaking chapter (only drawn when figures are on) and the
//! lesson's generated error table.

use super::drift::{steady_drift, Scene};
use super::evidence::{booktop, Evidence};
use crate::error::Result;
use crate::ladder::{self as work, WorkPoint};
use crate::numerics::hybrid::Segment;
use crate::physics::block::{BlockMode, BlockOptions, Observer};
use crate::physics::plate::PlateMotion;
use crate::plot::{save_chart, Chart};
use crate::sweep::{linspace, par_map};
use std::path::Path;

/// Collects `(t, absolute block velocity)` samples of every segment.
struct Trace<'a, P: PlateMotion> {
    plate: &'a P,
    pts: Vec<(f64, f64)>,
}

impl<P: PlateMotion> Observer<BlockMode, 4> for Trace<'_, P> {
    fn segment(&mut self, _m: BlockMode, seg: &Segment<'_, 4>) {
        for k in 0..=8 {
            let t = seg.t0 + (seg.t1 - seg.t0) * k as f64 / 8.0;
            self.pts.push((t, seg.eval(t)[1] + self.plate.vx_mps(t)));
        }
    }
}

/// Draws every figure; returns the written paths.
pub fn draw(dir: &Path, ev: &Evidence, wp: &[WorkPoint], quick: bool) -> Result<Vec<String>> {
    let mut paths = Vec::new();
    paths.extend(save_chart(&error_chart(ev), dir, "averaged-law-error")?);
    paths.extend(save_chart(
        &drift_chart(&ev.scene, quick),
        dir,
        "drift-vs-bias",
    )?);
    let steady = steady_chart(&ev.scene, ev.exact.v0_mps);
    paths.extend(save_chart(&steady, dir, "steady-period")?);
    paths.extend(save_chart(
        &booktop_chart(&ev.scene, quick),
        dir,
        "booktop",
    )?);
    // Work against accuracy.
    let [a, b] = work::charts(wp, "horizontal shaking");
    paths.extend(save_chart(&a, dir, "work-precision")?);
    // wall time: machine-dependent, written outside the committed set
    let wall = dir.join(crate::chapters::WALL_TIME_DIR);
    paths.extend(save_chart(&b, wall, "work-precision")?);
    Ok(paths)
}

/// Averaged-law error against Gamma_x.
fn error_chart(ev: &Evidence) -> Chart {
    let sweep = &ev.sweep;
    let g1 = ev.g1.0;
    let (g_hi, e_hi, _) = sweep[sweep.len() - 1];
    let c = e_hi * g_hi * g_hi;
    let fit: Vec<(f64, f64)> = sweep.iter().map(|&(g, _, _)| (g, c / (g * g))).collect();
    Chart::new(
        &format!(
            "Averaged law vs exact drift (bias {:.2})",
            ev.err_scene.bias
        ),
        "Γₓ = δₓω² / (μg)",
        "relative error of V sin(πb/2)",
    )
    .log_x()
    .log_y()
    .points(
        "exact periodic drift (shooting)",
        sweep.iter().map(|&(g, e, _)| (g, e)).collect(),
    )
    .dashed(&format!("{c:.2} / Γₓ²"), fit)
    .hline(0.01, "1 %")
    .vline(g1, &format!("Γₓ = {g1:.2}"))
}

/// Drift against bias at several Gamma_x, with the averaged and the linear laws.
fn drift_chart(scene: &Scene, quick: bool) -> Chart {
    let biases = linspace(0.0, 0.95, if quick { 6 } else { 20 });
    let mut chart = Chart::new(
        "Drift speed against bias",
        "bias b = F / (μmg)",
        "drift / V",
    );
    for gx in [1.5, 3.0, 10.0] {
        let s = scene.at_gamma_x(gx);
        let pts = par_map(&biases, "drift vs bias", |&b| {
            let sc = Scene { bias: b, ..s };
            (b, steady_drift(&sc).drift_mps / sc.velocity_amplitude_mps())
        });
        chart = chart.points(&format!("exact, Γₓ = {gx}"), pts);
    }
    let fine = linspace(0.0, 0.95, 60);
    chart
        .line(
            "averaged law sin(πb/2)",
            fine.iter()
                .map(|&b| (b, (std::f64::consts::PI * b / 2.0).sin()))
                .collect(),
        )
        .dashed(
            "linear (viscous) law πb/2",
            fine.iter()
                .map(|&b| (b, std::f64::consts::PI * b / 2.0))
                .filter(|p| p.1 <= 1.1)
                .collect(),
        )
}

/// One steady period: plate and block velocities, from the block velocity `v0` (m/s)
/// at phase 0 on the periodic orbit.
fn steady_chart(scene: &Scene, v0: f64) -> Chart {
    let plate = scene.plate();
    let mut tr = Trace {
        plate: &plate,
        pts: Vec::new(),
    };
    let o = BlockOptions {
        start: (0.0, [0.0, v0 - plate.vx_mps(0.0), 0.0, 0.0]),
        transient_periods: 0,
        ..BlockOptions::default()
    };
    crate::physics::block::simulate_block_observed(
        &scene.params(),
        &plate,
        plate.period_s(),
        &o,
        &mut tr,
    );
    let period = plate.period_s();
    let plate_pts: Vec<(f64, f64)> = linspace(0.0, 1.0, 200)
        .iter()
        .map(|&p| (p, plate.vx_mps(p * period)))
        .collect();
    Chart::new("One period of the steady state", "t / T", "velocity (m/s)")
        .line("plate", plate_pts)
        .line(
            "block (exact)",
            tr.pts.iter().map(|&(t, v)| (t / period, v)).collect(),
        )
        .hline(steady_drift(scene).drift_mps, "mean drift")
}

/// Booktop: drift against tilt.
fn booktop_chart(scene: &Scene, quick: bool) -> Chart {
    let atan = scene.mu.atan().to_degrees();
    let tilts = linspace(0.0, 0.95 * atan, if quick { 6 } else { 24 });
    let rows = par_map(&tilts, "booktop", |&a| {
        let b = booktop(scene, a);
        (a, steady_drift(&b).drift_mps, b.averaged_drift_mps())
    });
    Chart::new(
        &format!(
            "Booktop: coin on a book shaken at {} Hz, {} m",
            scene.frequency_hz, scene.amplitude_m
        ),
        "tilt (deg)",
        "downhill drift speed (m/s)",
    )
    .points(
        "exact simulation",
        rows.iter().map(|r| (r.0, r.1)).collect(),
    )
    .line("averaged law", rows.iter().map(|r| (r.0, r.2)).collect())
    .vline(atan, "arctan μ: slides unshaken")
}

/// The lesson's table of the averaged law's error against Gamma_x (block
/// `error-vs-gamma`).
pub fn error_table(ev: &Evidence) -> String {
    let rows: Vec<String> = ev
        .sweep
        .iter()
        .map(|&(gx, e, ex)| {
            let s = ev.err_scene.at_gamma_x(gx);
            let v = s.velocity_amplitude_mps();
            format!(
                "| {:.3} | {:.5} | {:.5} | {:.2e} |",
                gx,
                ex / v,
                s.averaged_drift_mps() / v,
                e
            )
        })
        .collect();
    format!(
        "| Γₓ | exact drift / V | averaged law / V | relative error |\n|---|---|---|---|\n{}\n",
        rows.join("\n")
    )
}
