//! What a reader must know about one run beyond its numbers: the starting angle when no
//! static angle exists, and how far the mean speed moves when the tolerance is
//! tightened (on chaotic scenes the hop sequence, and the speed with it, depends on
//! rounding-level differences; a single run cannot show it).

use super::{round, run_scene_from, Start};
use crate::numerics::hybrid::Options;
use crate::numerics::ode::StepControl;
use crate::physics::stick::run::{Recording, RunSummary, StickOutcome};
use crate::physics::stick::StickParams;
use crate::report::ChapterReport;
use serde_json::json;

/// Largest run (drive cycles) for which the second tolerance is run: twice the work of
/// a default run at most a few seconds in release.
pub const SENSITIVITY_MAX_CYCLES: f64 = 1e5;

/// Relative difference of the mean speeds above which the scene is flagged: the
/// workbook quotes mean speeds to three digits (`round(v, 6)` in m/s and the figures'
/// axes), so a difference beyond 1e-3 of the speed (or 1e-6 m/s) is one a reader sees.
pub const SENSITIVITY_REL: f64 = 1e-3;

/// Records `start_angle_rad` and, when the scene has no static angle under `--start
/// static`, a `start_note` saying that the run starts at theta_0 instead.
pub fn start_note(r: &mut ChapterReport, p: &StickParams, start: Start) {
    if start != Start::Static {
        return;
    }
    match p.static_angle() {
        Some(th) => r.result("start_angle_rad", round(th, 10)),
        None => {
            r.result("start_angle_rad", round(p.theta0_rad, 10));
            let note = format!(
                "no static angle: the spring (k = {} N m/rad) cannot hold the weight's moment m g L sin(θ) at any angle near θ₀, so --start static starts at rest at θ₀ = {} rad instead",
                p.stiffness_nm_per_rad, p.theta0_rad
            );
            r.note(note.clone());
            r.result("start_note", note);
        }
    }
}

/// Re-runs the main run at rtol / 100 (when it is short enough) and records the mean
/// speeds at both tolerances, their relative difference and whether it exceeds
/// [`SENSITIVITY_REL`] (`sensitive`: the speed is not converged at this rtol, typically a
/// chaotic hop sequence).
#[allow(clippy::too_many_arguments)]
pub fn tolerance_sensitivity(
    r: &mut ChapterReport,
    p: &StickParams,
    start: Start,
    duration_s: f64,
    opts: &Options,
    rtol: f64,
    main: &RunSummary,
) {
    let cycles = duration_s * p.frequency_hz();
    let completed = main.outcome == StickOutcome::Completed;
    if cycles > SENSITIVITY_MAX_CYCLES || !completed || !main.mean_velocity_mps.is_finite() {
        r.result(
            "mean_velocity_sensitivity",
            json!({"measured": false, "why": if completed { "run longer than 1e5 drive cycles: the second tolerance is not run" } else { "the run did not complete" }}),
        );
        return;
    }
    let rtol2 = (rtol / 100.0).max(1e-14);
    let tight = Options {
        control: StepControl::tol(rtol2, rtol2),
        ..*opts
    };
    let rec = Recording {
        sequence_cap: 0,
        trace_dt_s: 0.0,
        check_invariants: false,
        grid_only: false,
        list_cap: None,
    };
    let second = run_scene_from(p, start, duration_s, &tight, rec);
    let (v1, v2) = (main.mean_velocity_mps, second.mean_velocity_mps);
    let diff = (v1 - v2).abs();
    let rel = diff / v2.abs().max(1e-300);
    // formula: flagged when |v(rtol) - v(rtol/100)| > 1e-3 |v| + 1e-6 m/s
    let sensitive = second.outcome != StickOutcome::Completed
        || !v2.is_finite()
        || diff > SENSITIVITY_REL * v2.abs() + 1e-6;
    r.result(
        "mean_velocity_sensitivity",
        json!({
            "measured": true,
            "rtol": rtol,
            "rtol_second": rtol2,
            "mean_velocity_mps": round(v1, 6),
            "mean_velocity_second_mps": if v2.is_finite() { json!(round(v2, 6)) } else { json!(crate::report::NON_FINITE) },
            "relative_difference": if rel.is_finite() { json!(round(rel, 2)) } else { json!(crate::report::NON_FINITE) },
            "sensitive": sensitive,
        }),
    );
}
