//! The stick's share of the chapter: work-precision of its mean speed, its failures,
//! and the simulator's speed in drive cycles per second.

use super::failures::Failure;
use super::measure::{stick_speed, timed};
use super::report_parts::{fmt_err, observed_order};
use super::work_precision::{
    cheapest_json, dopri5_errors_at, error_at, ladder, measure, rhs_evals_at, Solver, WpPoint,
    EVENT_DRIVEN_LABELS,
};
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::stick::{authors_scene, StickModel};
use crate::report::{ChapterReport, Claim};
use serde_json::json;

/// Runs the stick ladder on the authors' scene (section 4; g = `g_mps2`) over `cycles`
/// drive periods; adds claims and results to `r`, failures to `fails`; returns the points.
pub fn build(
    r: &mut ChapterReport,
    fails: &mut Vec<Failure>,
    g_mps2: f64,
    quick: bool,
) -> Vec<WpPoint> {
    let model = StickModel::new(authors_scene(g_mps2));
    let period = model.period_s;
    let cycles = if quick { 10.0 } else { 50.0 };
    let repeats = if quick { 1 } else { 3 };
    let speed = |opts: &Options| stick_speed(&model, cycles, opts);
    let dp = |tol: f64| {
        speed(&Options {
            control: StepControl::tol(tol, tol),
            ..Options::default()
        })
        .0
    };
    // Reference: DP5 at 1e-13 with located events (flight in closed form).
    let reference = dp(1e-13);
    let rel = |v: f64| ((v - reference.value) / reference.value).abs();
    let (d11, d12) = (dp(1e-11), dp(1e-12));
    r.result("stick_mean_speed_mps", reference.value);
    r.result(
        "stick_reference_check",
        json!({"dopri5_1e-11": rel(d11.value), "dopri5_1e-12": rel(d12.value)}),
    );
    // The stick's flows are smooth between events located to ulps: DP5's global error
    // scales with the tolerance (measured ~1e-11 relative at 1e-11 and 1e-12), so the
    // two tightest runs agree with the reference to well under 1e-8.
    r.claim(Claim::close(
        "stick-reference-converged",
        "4, 5",
        "The stick's mean speed at rtol = atol = 1e-13 (the reference) agrees with the runs at 1e-11 and 1e-12 (largest relative difference)",
        0.0,
        rel(d11.value).max(rel(d12.value)),
        1e-8,
    ));
    let (steps, tols): (Vec<u32>, Vec<f64>) = if quick {
        (vec![32, 128, 512], vec![1e-4, 1e-7, 1e-10])
    } else {
        (
            vec![32, 64, 128, 256, 512, 1024, 2048],
            (3..=12).map(|k| 10f64.powi(-k)).collect(),
        )
    };
    let solvers = ladder(period, &steps, &tols, &[]);
    let points = measure("stick-speed", &solvers, reference.value, repeats, |s| {
        speed(&s.options(0).expect("hybrid")).0
    });
    let o = observed_order(&points, "rk4-located", 1e-10);
    // RK4 with located events: order 4; +-1 as for the block (event phases vary with h).
    r.claim(Claim::close(
        "stick-rk4-located-order",
        "4, 5",
        "RK4 with located events converges at order 4 on the stick's mean speed (least-squares slope of log error against log step, errors above 1e-10)",
        4.0,
        o,
        1.0,
    ));
    let err_of = |label: &str, knob: f64| error_at(&points, label, knob);
    let tight = *tols.last().expect("tolerances");
    let (loc, unloc) = dopri5_errors_at(&points, tight);
    r.claim(Claim::exact(
        "stick-unlocated-events-stall",
        "4, 5",
        "Without event location Dormand-Prince's error on the stick's mean speed stalls: at the tightest tolerance it is over 100 times the located error, or the run breaks down",
        true,
        unloc.is_nan() || unloc > 100.0 * loc.max(1e-15),
    ));
    // Failures seen on the ladder: runs that broke down, and unlocated runs far off.
    for p in &points {
        if !p.completed {
            let why = speed(&p.solver.options(0).expect("hybrid"))
                .1
                .unwrap_or_else(|| "did not complete".into());
            fails.push(Failure {
                method: p.solver.label(),
                scene: format!("stick mean speed, {}", knob_text(&p.solver, period)),
                symptom: format!("run broke down: {why}"),
            });
        }
    }
    for m in ["euler", "rk4"] {
        let h = period / f64::from(steps[0]);
        let (l, u) = (
            err_of(&format!("{m}-located"), h),
            err_of(&format!("{m}-unlocated"), h),
        );
        if u.is_finite() && u > 10.0 * l {
            fails.push(Failure {
                method: format!("{m}-unlocated"),
                scene: format!("stick mean speed, h = T/{}", steps[0]),
                symptom: format!(
                    "events late by up to a step: speed error {} (located: {})",
                    fmt_err(u),
                    fmt_err(l)
                ),
            });
        }
    }
    // The stick chapter's choice of DOP853: at rtol 1e-10 both pairs must land within
    // 1e-9 of the DP5 reference at 1e-13 (an independent method: DOP853 shares no
    // stage with it), and DOP853 must do so with fewer right-hand sides.
    let (e5, e8) = (
        err_of("dopri5-located", 1e-10),
        err_of("dop853-located", 1e-10),
    );
    let (n5, n8) = (
        rhs_evals_at(&points, "dopri5-located", 1e-10),
        rhs_evals_at(&points, "dop853-located", 1e-10),
    );
    r.claim(Claim::exact(
        "stick-dop853-cheaper-at-1e-10",
        "4, 5",
        "At rtol = atol = 1e-10 Dormand-Prince 8(5,3) reaches the stick's mean speed within 1e-9 of the reference with fewer right-hand-side evaluations than Dormand-Prince 5(4) (the stick chapter's default integrator rests on this)",
        true,
        e5 <= 1e-9 && e8 <= 1e-9 && n8 < n5,
    ));
    r.result(
        "stick_rhs_evals_at_1e-10",
        json!({"dopri5": n5, "dop853": n8, "dopri5_error": e5, "dop853_error": e8}),
    );
    // Simulator speed at rtol 1e-10 with each pair, minimum of repeats.
    for (key, method) in [
        ("stick_cycles_per_second", Method::Dop853),
        ("stick_cycles_per_second_dopri5", Method::Dopri5),
    ] {
        let opts = Options {
            method,
            ..Options::default()
        };
        let (run, wall) = timed(if quick { 1 } else { 5 }, || speed(&opts).0);
        r.result(
            key,
            if run.completed {
                cycles / wall
            } else {
                f64::NAN
            },
        );
    }
    r.result(
        "stick_rhs_evals_to_reach_1e-6",
        cheapest_json(&points, &EVENT_DRIVEN_LABELS, 1e-6),
    );
    points
}

fn knob_text(s: &Solver, period: f64) -> String {
    match s {
        Solver::Adaptive { tol, .. } => format!("tol = {tol:e}"),
        other => format!("h = T/{}", (period / other.knob()).round()),
    }
}
