//! The main run of a stick scene (the reader's own scene, set by the flags of
//! `workbook stick-state-machine` or by the lab's sliders) and its named parameters and
//! results: one piece of code for the CLI and for `workbook lab`, so that the lab shows
//! the CLI's numbers (tests/lab.rs compares them).

use super::{event_counts, phase_fractions, run_printed_from, run_scene_from};
use super::{Choice as _, ContactMethod, Rules, Scene, Start, SECONDS_PER_CYCLE};
use crate::error::Result;
use crate::numerics::hybrid::Options;
use crate::numerics::ode::Method;
use crate::physics::stick::printed::Printed;
use crate::physics::stick::run::{Recording, RunSummary, StickOutcome};
use crate::physics::stick::{InvalidReason, StickParams};
use crate::scenes::round;
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// The recording of the main run: the phase sequence and the switches (4000 at most;
/// the CLI raises the cap to `EVENTS_CAP` with `--events`), Table 1 checked at every step; `trace_dt_s` samples the trajectory
/// (0 for the CLI, which draws no animation; the lab's frames).
pub fn recording(trace_dt_s: f64) -> Recording {
    Recording {
        sequence_cap: 4000,
        trace_dt_s,
        check_invariants: true,
        grid_only: false,
        list_cap: None,
    }
}

/// The estimated work of a run of `duration_s` (s), checked against the CLI's budget
/// of 10 minutes (unless `allow_long_runs`); the estimate (s).
pub fn check_work(p: &StickParams, duration_s: f64, allow_long_runs: bool) -> Result<f64> {
    let cycles = duration_s * p.frequency_hz(); // formula: work = drive cycles f t
    crate::sweep::check_budget(
        "--duration-s",
        cycles,
        "drive cycles",
        SECONDS_PER_CYCLE,
        allow_long_runs,
    )
}

/// How the main run is run: the choices of `workbook stick-state-machine` besides the
/// stick's parameters (which are in its [`StickParams`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// The scene whose values the flags overrode.
    pub scene: Scene,
    /// The starting state.
    pub start: Start,
    /// The transition rules.
    pub rules: Rules,
    /// The integrator of the contact modes.
    pub method: ContactMethod,
    /// Its relative (and absolute) tolerance.
    pub rtol: f64,
}

/// The report's `params` of the main run, in the CLI's order.
pub fn params(s: &Settings, p: &StickParams, duration_s: f64) -> Vec<(&'static str, Value)> {
    vec![
        ("scene", json!(s.scene.name())),
        ("length_m", json!(p.length_m)),
        ("mass_kg", json!(p.mass_kg)),
        ("stiffness_nm_per_rad", json!(p.stiffness_nm_per_rad)),
        ("damping_nms_per_rad", json!(p.damping_nms_per_rad)),
        ("mu", json!(p.mu)),
        ("theta0_rad", json!(round(p.theta0_rad, 10))),
        ("gamma", json!(p.gamma_accel())),
        ("frequency_hz", json!(p.frequency_hz())),
        ("g_mps2", json!(p.g_mps2)),
        ("duration_s", json!(duration_s)),
        (
            "collision_angle",
            json!(format!("{:?}", p.collision_angle).to_lowercase()),
        ),
        ("rtol", json!(s.rtol)),
        ("method", json!(s.method.method().name())),
        ("rules", json!(s.rules.name())),
        ("start", json!(s.start.name())),
    ]
}

/// The main run: the physical run (the claims are judged on it) and the reported one
/// (the physical run, or with `--rules printed` the printed rules' run and the counts of
/// the printed lines that fired).
pub type MainRuns = (RunSummary, RunSummary, BTreeMap<&'static str, u64>);

/// Runs the main run of the settings `s` with the validated `p`, `duration_s`, `opts`.
pub fn run_main(
    s: &Settings,
    p: &StickParams,
    duration_s: f64,
    opts: &Options,
    rec: Recording,
) -> MainRuns {
    let physical = run_scene_from(p, s.start, duration_s, opts, rec);
    let (main, fired) = match s.rules {
        Rules::Physical => (physical.clone(), Default::default()),
        Rules::Printed => run_printed_from(p, Printed::AS_PRINTED, s.start, duration_s, opts, rec),
    };
    (physical, main, fired)
}

/// The options to run the main run again with when DOP853 produced a non-finite state
/// (`None` otherwise): DOPRI5 with the same tolerances. Near the vertical the slides'
/// C.14 divides by sin(theta), their theta'' is of order 1/theta, and the order-8
/// pair's stages overflow where DOPRI5's smaller steps do not (measured on the jamming
/// scene with theta_0 from 1e-9 to 1e-3 rad: DOP853 NaN, DOPRI5 completes; at
/// theta_0 = 1e-6 DOPRI5 agrees with an independent time-stepping run).
pub fn dopri5_fallback(first: &RunSummary, opts: &Options) -> Option<Options> {
    let nan = matches!(
        &first.outcome,
        StickOutcome::Invalid(InvalidReason::NonFinite { .. })
    );
    (nan && opts.method == Method::Dop853).then_some(Options {
        method: Method::Dopri5,
        ..*opts
    })
}

/// The report's `results` of the main run, in the CLI's order. A run whose numbers are
/// not all finite is marked `invalid` here (its non-finite numbers are left out).
pub fn results(
    main: &mut RunSummary,
    p: &StickParams,
    fired: &BTreeMap<&'static str, u64>,
) -> Vec<(&'static str, Value)> {
    let b = main.budget;
    let finite = [
        main.mean_velocity_mps,
        main.end_time_s,
        b.plate_work_j,
        b.delta_mechanical_j,
        b.friction_j,
        b.damper_j,
        b.impact_j,
    ]
    .iter()
    .all(|x| x.is_finite());
    if !finite {
        // A NaN escaped the model (seen with the rod leaning less than ~1e-3 rad, where
        // the slide equations divide by sin(theta)): the run ends `invalid`, and its
        // non-finite numbers are left out of the results, never printed.
        main.outcome = StickOutcome::Invalid(InvalidReason::NonFinite {
            t_s: round(main.end_time_s, 6),
            near_vertical: false,
        });
    }
    if let StickOutcome::Invalid(InvalidReason::NonFinite { near_vertical, .. }) = &mut main.outcome
    {
        // the slides' C.14 divides by sin(theta): near the vertical their theta'' is
        // of order 1/theta and the order-8 pair's stages overflow where DOPRI5's
        // smaller steps do not (measured at theta_0 = 1e-6: DOP853 NaN at 0.029 s,
        // DOPRI5 completes and agrees with a time-stepping run); the message says so
        *near_vertical = p.theta0_rad.abs() < 1e-3;
    }
    let reason = match &main.outcome {
        StickOutcome::Invalid(why) => why.to_string(),
        StickOutcome::Aborted(why) => why.clone(),
        _ => String::new(),
    };
    let mut out = vec![
        ("outcome", json!(main.outcome.label())),
        ("outcome_reason", json!(reason)),
    ];
    if finite {
        out.push(("end_time_s", json!(round(main.end_time_s, 9))));
        // a run stopped within its first drive cycle has no mean speed: 0 (see outcome)
        let v = if main.end_time_s - main.start_time_s >= p.period_s() {
            main.mean_velocity_mps
        } else {
            0.0
        };
        out.push(("mean_velocity_mps", json!(round(v, 6))));
    }
    out.push(("phase_fractions", phase_fractions(main)));
    out.push(("event_counts", event_counts(main)));
    out.push(("hops", json!(main.hops as u64)));
    out.push(("printed_rules_fired", json!(fired)));
    if finite {
        out.push((
            "energy_budget_j",
            json!({
                "plate_work": round(b.plate_work_j, 6),
                "delta_mechanical": round(b.delta_mechanical_j, 6),
                "friction": round(b.friction_j, 6),
                "damper": round(b.damper_j, 6),
                "impact": round(b.impact_j, 6),
                "relative_residual_below_1e-5": b.relative_residual() < 1e-5,
            }),
        ));
    }
    out
}

/// The late mean speed of C (m/s) of a short run (the cells of chapter 6's speed maps in
/// quick mode), NaN unless the run completed: what the lab's map shows.
pub fn map_cell_speed(p: &StickParams, opts: &Options) -> f64 {
    super::late_speed(p, opts, true)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::ode::StepControl;

    fn short_run(p: &StickParams, method: Method) -> (RunSummary, Options) {
        let opts = Options {
            method,
            control: StepControl::tol(1e-10, 1e-10),
            ..Options::default()
        };
        (
            run_scene_from(p, Start::Static, 0.05, &opts, recording(0.0)),
            opts,
        )
    }

    #[test]
    fn a_nan_in_the_results_ends_the_run_invalid_and_is_never_printed() {
        // the guard of `results` (the CLI's `--theta0-rad 1e-6` no longer reaches it:
        // DOP853's NaN there is repeated with DOPRI5, see `dopri5_fallback`)
        let p = Scene::Jamming.params(None);
        let (mut s, _) = short_run(&p, Method::Dop853);
        s.mean_velocity_mps = f64::NAN;
        let out = results(&mut s, &p, &BTreeMap::new());
        let text =
            serde_json::to_string(&out.iter().map(|(k, v)| (*k, v.clone())).collect::<Vec<_>>())
                .unwrap();
        assert_eq!(out[0].1, json!("invalid"));
        assert!(out[1].1.as_str().unwrap().contains("non-finite"));
        // a NaN number would serialise as null: none is left in the results
        assert!(
            !text.contains("null") && !text.contains("mean_velocity"),
            "{text}"
        );
    }

    #[test]
    fn only_a_non_finite_dop853_run_is_repeated_with_dopri5() {
        let p = Scene::Jamming.params(None);
        let (mut s, opts) = short_run(&p, Method::Dop853);
        assert!(dopri5_fallback(&s, &opts).is_none(), "a completed run");
        s.outcome = StickOutcome::Invalid(InvalidReason::NonFinite {
            t_s: 0.0,
            near_vertical: false,
        });
        let o = dopri5_fallback(&s, &opts).expect("repeated");
        assert_eq!(o.method, Method::Dopri5);
        assert_eq!(o.control, opts.control);
        let dp5 = Options {
            method: Method::Dopri5,
            ..opts
        };
        assert!(dopri5_fallback(&s, &dp5).is_none(), "DOPRI5 itself failed");
        s.outcome = StickOutcome::Invalid("no consistent contact mode".into());
        assert!(dopri5_fallback(&s, &opts).is_none(), "not a NaN");
    }
}
