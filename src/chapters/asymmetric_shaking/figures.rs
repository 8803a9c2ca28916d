//! Figures of the chapter (only when figures are on): velocities over a few periods,
//! drift against the asymmetry, drift against the drive number, the regime map, and
//! the work-precision chart. Sweeps here feed figures only.

use super::evidence::Evidence;
use super::sims::{biharmonic, drift_after_lock, run_block, slip_transient, Law, Numerics, Window};
use super::work::{Drive, Method, WorkRow};
use super::Scene;
use crate::error::Result;
use crate::physics::plate::{PlateMotion, Sawtooth};
use crate::physics::sawtooth::biharmonic::{always_slipping_drift, stick_forever_gamma};
use crate::physics::sawtooth::{drift_ratio, drift_velocity_mps, lock_time_s, steady_velocity_mps};
use crate::plot::{save_chart, save_heatmap, save_panels, Chart, HeatMap, Legend, Series};
use crate::sweep::{linspace, logspace, par_map};
use std::path::Path;

/// Draws every figure into `dir`; returns the written paths.
pub fn draw(sc: &Scene, quick: bool, ev: &Evidence, dir: &Path) -> Result<Vec<String>> {
    let mut paths = Vec::new();
    paths.extend(velocities(sc, ev, dir)?);
    paths.extend(drift_vs_asymmetry(sc, quick, dir)?);
    paths.extend(drift_vs_drive(sc, quick, dir)?);
    paths.extend(regime_map(sc, dir)?);
    if let Some((_, rows)) = &ev.work {
        paths.extend(work_precision(rows, ev.tol.v_mps, dir)?);
    }
    Ok(paths)
}

/// Velocities over a few periods, both laws.
fn velocities(sc: &Scene, ev: &Evidence, dir: &Path) -> Result<Vec<String>> {
    let saw = sc.saw;
    let k = sc.k_mps2();
    let (coulomb, linear) = (&ev.main.trace, &ev.linear.trace);
    let ms = |v: &[(f64, f64, f64)], i: usize| -> Vec<(f64, f64)> {
        v.iter()
            .map(|p| (p.0 * 1e3, if i == 1 { p.1 } else { p.2 }))
            .collect()
    };
    let vd = drift_velocity_mps(&saw, k);
    // The closed-form periodic velocity from the first whole period after the lock.
    let t_lock = lock_time_s(&saw, k, 0.0);
    let t_from = (t_lock / saw.period_s()).ceil() * saw.period_s();
    let t_to = coulomb.last().map_or(t_from, |p| p.0);
    let steady: Vec<(f64, f64)> = linspace(t_from, t_to, 800)
        .into_iter()
        .map(|t| (t * 1e3, steady_velocity_mps(&saw, k, t)))
        .collect();
    let c1 = Chart::new(
        "Coulomb friction: the block locks onto the slow stroke",
        "time (ms)",
        "velocity (m/s)",
    )
    .dashed("plate", ms(coulomb, 2))
    .line("block (simulated)", ms(coulomb, 1))
    .points(
        "closed-form periodic velocity",
        steady.into_iter().step_by(10).collect(),
    )
    .hline(vd, "closed-form drift")
    .vline(t_lock * 1e3, "first stick");
    let c2 = Chart::new(
        "Linear friction: the block follows the plate, mean zero",
        "time (ms)",
        "velocity (m/s)",
    )
    .dashed("plate", ms(linear, 2))
    .line("block (simulated)", ms(linear, 1))
    .hline(0.0, "zero");
    save_panels(&[c1, c2], 1, dir, "velocities")
}

/// Drift against the asymmetry: sawtooth speed ratio, bi-harmonic eps.
fn drift_vs_asymmetry(sc: &Scene, quick: bool, dir: &Path) -> Result<Vec<String>> {
    let saw = sc.saw;
    let k = sc.k_mps2();
    let coul = Law::Coulomb { k_mps2: k };
    let num = Numerics::default();
    let measured = if quick { 2 } else { 6 };
    let ratios = linspace(1.25, 6.0, if quick { 4 } else { 12 });
    let a = saw.slow_velocity_mps;
    let sim_r: Vec<(f64, f64)> = par_map(&ratios, "sawtooth ratio sweep", |&r| {
        let s = Sawtooth {
            fast_velocity_mps: r * a,
            ..saw
        };
        let v = drift_after_lock(coul, &s, k, measured, &num);
        (r, v / a)
    });
    let y = k * saw.slow_duration_s / a;
    let theory_r: Vec<(f64, f64)> = linspace(1.01, 6.0, 200)
        .into_iter()
        .map(|r| (r, drift_ratio(r, y)))
        .collect();
    let p1 = Chart::new(
        &format!("Sawtooth, friction number μg T_slow / v_slow = {y:.3}"),
        "speed ratio v_fast / v_slow",
        "drift / v_slow",
    )
    .line("closed form", theory_r)
    .points("simulation", sim_r);
    let vb = 0.5 * (saw.slow_velocity_mps + saw.fast_velocity_mps);
    let epss = linspace(-0.45, 0.45, if quick { 5 } else { 19 });
    let mut p2 = Chart::new(
        "Bi-harmonic drive v_p = V (sin ωt + ε cos 2ωt)",
        "asymmetry ε",
        "drift / V",
    )
    .dashed("limit ε (Γₓ → ∞)", vec![(-0.45, -0.45), (0.45, 0.45)]);
    for gamma in [3.0, 10.0] {
        let pts: Vec<(f64, f64)> = par_map(&epss, "bi-harmonic ε sweep", |&e| {
            let p = biharmonic(vb, gamma, e, k);
            let w = Window {
                transient: slip_transient(gamma),
                measured: 4,
            };
            (
                e,
                run_block(coul, &p, 0.0, w, &num, (0.0, 0.0), 0.0).mean_velocity_mps / vb,
            )
        });
        let theory: Vec<(f64, f64)> = linspace(-0.45, 0.45, 91)
            .into_iter()
            .filter_map(|e| always_slipping_drift(gamma, e).map(|d| (e, d)))
            .collect();
        p2 = p2
            .line(&format!("always slipping, Γₓ = {gamma}"), theory)
            .points(&format!("simulation, Γₓ = {gamma}"), pts);
    }
    // Stacked for the book's column (~750 px): an 800-px panel shows at ~94 %, its
    // 12.9-px ticks and legend at ~12 px (side by side, 1600 px at 47 %: 6 px).
    save_panels(&[p1, p2], 1, dir, "drift-vs-asymmetry")
}

/// Bi-harmonic drift against the drive number.
fn drift_vs_drive(sc: &Scene, quick: bool, dir: &Path) -> Result<Vec<String>> {
    let saw = sc.saw;
    let k = sc.k_mps2();
    let coul = Law::Coulomb { k_mps2: k };
    let num = Numerics::default();
    let vb = 0.5 * (saw.slow_velocity_mps + saw.fast_velocity_mps);
    let gammas = logspace(0.5, 100.0, if quick { 6 } else { 30 });
    let mut c3 = Chart::new(
        "Bi-harmonic drift against the drive number",
        "drive number Γₓ = Vω / (μg)",
        "drift / (εV)",
    )
    .log_x();
    for eps in [0.1, 0.3] {
        let pts: Vec<(f64, f64)> = par_map(&gammas, "bi-harmonic Γₓ sweep", |&g| {
            let p = biharmonic(vb, g, eps, k);
            let w = Window {
                transient: slip_transient(g),
                measured: 4,
            };
            (
                g,
                run_block(coul, &p, 0.0, w, &num, (0.0, 0.0), 0.0).mean_velocity_mps / (eps * vb),
            )
        });
        let theory: Vec<(f64, f64)> = logspace(0.5, 100.0, 300)
            .into_iter()
            .filter_map(|g| always_slipping_drift(g, eps).map(|d| (g, d / eps)))
            .collect();
        c3 = c3
            .points(&format!("simulation, ε = {eps}"), pts)
            .line(&format!("always slipping, ε = {eps}"), theory);
        c3 = c3.vline(
            stick_forever_gamma(eps),
            &format!("sticks for good below: ε = {eps}"),
        );
    }
    c3 = c3.hline(1.0, "limit εV");
    save_chart(&c3, dir, "drift-vs-drive")
}

/// Regime map of the sawtooth (closed form) with the boundary y = r (r + 1).
fn regime_map(sc: &Scene, dir: &Path) -> Result<Vec<String>> {
    let saw = sc.saw;
    let a = saw.slow_velocity_mps;
    let y = sc.k_mps2() * saw.slow_duration_s / a;
    let rs = linspace(1.05, 4.0, 60);
    let ys = linspace(0.05, 20.0, 60);
    let values: Vec<Vec<f64>> = ys
        .iter()
        .map(|&y| rs.iter().map(|&r| drift_ratio(r, y)).collect())
        .collect();
    let boundary: Vec<(f64, f64)> = rs
        .iter()
        .map(|&r| (r, r * (r + 1.0)))
        .filter(|p| p.1 <= 20.0)
        .collect();
    let here = vec![(saw.fast_velocity_mps / a, y)];
    let h = HeatMap::new(
        "Sawtooth regimes: drift / v_slow (closed form)",
        "speed ratio v_fast / v_slow",
        "friction number μg T_slow / v_slow",
        rs,
        ys,
        values,
        "drift / v_slow",
    )
    .overlay(Series::line(
        "stick in both strokes above: μg T_fast = v_slow + v_fast",
        boundary,
    ))
    .overlay(Series::points("this scene", here))
    .legend(Legend::UpperLeft); // over the uniform zero-drift region, off the boundary
    save_heatmap(&h, dir, "regime-map")
}

/// Work-precision: the error of the Coulomb drift against the work, both drives, with
/// the claims' tolerance `tol_mps` (the scene's error budget, m/s).
fn work_precision(rows: &[WorkRow], tol_mps: f64, dir: &Path) -> Result<Vec<String>> {
    let floor = 1e-17; // errors of exactly 0 drawn at the floor
    let mut charts = Vec::new();
    for drive in Drive::ALL {
        let pick = |method: Method| -> Vec<(f64, f64)> {
            rows.iter()
                .filter(|w| w.drive == drive && w.method == method)
                .map(|w| ((w.rhs_evals as f64).max(1.0), w.error_mps.max(floor)))
                .collect()
        };
        charts.push(
            Chart::new(
                &format!("{}: error of the Coulomb drift against work", drive.label()),
                "right-hand-side evaluations",
                &format!("|drift - {}| (m/s)", drive.reference()),
            )
            .log_x()
            .log_y()
            .line_points("DP5, located events (tol 1e-3 … 1e-12)", pick(Method::Dopri5))
            .line_points(
                "RK4 fixed step, no event location (T/15 … T/1023)",
                pick(Method::Rk4Fixed),
            )
            .hline(tol_mps, "claim tolerance (the run's error budget)"),
        );
    }
    // Stacked for the book's column (~750 px): an 800-px panel shows at ~94 %, its
    // 12.9-px ticks and legend at ~12 px (side by side, 1600 px at 47 %: 6 px).
    save_panels(&charts, 1, dir, "work-precision")
}
