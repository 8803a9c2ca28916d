//! Timed runs of the scenes and their observables: the block's steady drift by every
//! method, the stick's mean speed (chapter 7's work-precision charts, the benchmarks).
//!
//! The drift is the mean horizontal velocity `(x(t_b) - x(t_a)) / (t_b - t_a)` over
//! whole drive periods after a transient. Every run is the workbook's block model
//! ([`crate::physics::block`]): event-driven runs take `x` at whole periods from
//! [`crate::physics::block::BlockRun`]; Moreau-Jean runs (its contact form) use a step
//! that divides the period, so `t_a` and `t_b` are step boundaries.

use super::block::BlockScene;
use crate::numerics::hybrid::{Options, Outcome};
use crate::numerics::timestepping::{self as mj, MjOptions};
use crate::physics::block::contact_form::BlockContact;
use crate::physics::block::{simulate_block, BlockOptions};
use crate::physics::stick::run::{initial_state, simulate_stick, Recording, StickOutcome};
use crate::physics::stick::StickModel;

/// One run of a method: the observable, its cost and whether it completed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measured {
    /// The observable (m/s).
    pub value: f64,
    /// Right-hand-side evaluations (flow evaluations; one per Moreau-Jean step).
    pub rhs_evals: u64,
    /// Accepted steps (integrator steps; Moreau-Jean steps).
    pub steps: u64,
    /// Events handled (impacts, takeoffs, stick-slip switches), or contact steps for
    /// Moreau-Jean.
    pub events: u64,
    /// Did the run reach its end time with a finite result?
    pub completed: bool,
    /// How the run ended (`completed`, `zeno`, `invalid`, `failed`, ...).
    pub note: &'static str,
}

/// The drift window: `(t_a, t_b)` after `transient` periods, `cycles` periods long (s).
pub fn window(scene: &BlockScene, transient: u32, cycles: u32) -> (f64, f64) {
    let t = scene.period_s();
    (f64::from(transient) * t, f64::from(transient + cycles) * t)
}

fn outcome_label<X>(o: &Outcome<X>) -> &'static str {
    match o {
        Outcome::Completed => "completed",
        Outcome::Stopped(_) => "stopped",
        Outcome::Zeno { .. } => "zeno",
        Outcome::Failed(_) => "failed",
    }
}

/// The block's drift with Moreau-Jean, `steps_per_period` steps per drive period.
pub fn drift_mj(scene: &BlockScene, steps_per_period: u32, (t_a, t_b): (f64, f64)) -> Measured {
    let h = scene.period_s() / f64::from(steps_per_period);
    let Some(contact) = BlockContact::new(scene.params, &scene.plate) else {
        return Measured {
            value: f64::NAN,
            rhs_evals: 0,
            steps: 0,
            events: 0,
            completed: false,
            note: "invalid",
        };
    };
    let (q0, v0) = contact.on_plate(0.0, 0.0, 0.0);
    let n_a = (t_a / h).round() as u64;
    let mut k = 0u64;
    let mut xa = f64::NAN;
    let run = mj::simulate(&contact, 0.0, q0, v0, t_b, &MjOptions::midpoint(h), |s| {
        k += 1;
        if k == n_a {
            xa = s.q1[0];
        }
    });
    match run {
        Ok(r) => {
            let value = if n_a == 0 {
                (r.q[0] - q0[0]) / (t_b - t_a)
            } else {
                (r.q[0] - xa) / (t_b - t_a)
            };
            Measured {
                value,
                rhs_evals: r.stats.rhs_evals,
                steps: r.stats.steps,
                events: r.stats.contact_steps,
                completed: value.is_finite(),
                note: "completed",
            }
        }
        Err(_) => Measured {
            value: f64::NAN,
            rhs_evals: k,
            steps: k,
            events: 0,
            completed: false,
            note: "failed",
        },
    }
}

/// Runs `f` `repeats` times (at least once); returns its (last) result and the minimum
/// wall time (s), the same measure as the ladder's `Timing::MinOf`.
pub fn timed<R>(repeats: u32, mut f: impl FnMut() -> R) -> (R, f64) {
    let mut best_s = f64::INFINITY;
    let mut out = None;
    for _ in 0..repeats.max(1) {
        let start = std::time::Instant::now();
        out = Some(f());
        best_s = best_s.min(start.elapsed().as_secs_f64());
    }
    (out.expect("at least one run"), best_s)
}

/// The block's drift by the workbook's block model ([`crate::physics::block`]) with the
/// driver options `opts`, closed forms on or off, and guards sampled (and integrated
/// steps bounded) at `samples_per_period` per period; same scene and window.
pub fn drift_block_model(
    scene: &BlockScene,
    opts: &Options,
    closed_forms: bool,
    samples_per_period: usize,
    transient: u32,
    cycles: u32,
) -> Measured {
    let bo = BlockOptions {
        hybrid: Options {
            record_events: false,
            ..*opts
        },
        closed_forms,
        samples_per_period,
        transient_periods: transient as usize,
        record_events: false,
        start: (0.0, [0.0; 4]),
    };
    let run = simulate_block(
        &scene.params,
        &scene.plate,
        f64::from(transient + cycles) * scene.period_s(),
        &bo,
    );
    let c = run.total_counts;
    let events =
        (c.takeoffs + c.landings + c.stick_to_slip + c.slip_to_stick + c.reversals + c.breakpoints)
            as u64;
    Measured {
        value: run.mean_velocity_mps,
        rhs_evals: run.stats.rhs_evals,
        steps: run.stats.accepted,
        events,
        completed: run.outcome == Outcome::Completed && run.mean_velocity_mps.is_finite(),
        note: outcome_label(&run.outcome),
    }
}

/// The stick's mean horizontal speed of C (m/s) over `cycles` drive periods from rest at
/// its static angle (the workbook's stick model, [`crate::physics::stick`]), with the
/// driver options `opts`; the outcome's reason if it did not complete.
pub fn stick_speed(model: &StickModel, cycles: f64, opts: &Options) -> (Measured, Option<String>) {
    let p = &model.p;
    let y0 = initial_state(model, 0.0, p.static_angle().unwrap_or(p.theta0_rad));
    let r = simulate_stick(
        model,
        0.0,
        y0,
        cycles * model.period_s,
        opts,
        Recording::default(),
    );
    let completed = r.outcome == StickOutcome::Completed && r.mean_velocity_mps.is_finite();
    let reason = match &r.outcome {
        StickOutcome::Completed => None,
        StickOutcome::Invalid(why) => {
            let why = why.to_string();
            Some(why.split(" at t =").next().unwrap_or(&why).to_string())
        }
        other => Some(other.label().to_string()),
    };
    let m = Measured {
        value: r.mean_velocity_mps,
        rhs_evals: r.stats.rhs_evals,
        steps: r.stats.accepted,
        events: r.event_count as u64,
        completed,
        note: r.outcome.label(),
    };
    (m, reason)
}
