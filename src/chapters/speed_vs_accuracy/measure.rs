//! Observables and timed runs: the block's steady drift by every method.
//!
//! The drift is the mean horizontal velocity `(x(t_b) - x(t_a)) / (t_b - t_a)` over
//! whole drive periods after a transient. The event-driven runs read `x(t_a)` from the
//! dense output of the segment that contains `t_a`; Moreau-Jean runs use a step that
//! divides the period, so `t_a` and `t_b` are step boundaries.

use super::block_scene::{BlockMode, BlockScene};
use crate::numerics::hybrid::{simulate, Observer, Options, Outcome, Segment};
use crate::numerics::timestepping::{self as mj, MjOptions};
use crate::physics::plate::PlateMotion;
use crate::physics::stick::run::{initial_state, simulate_stick, Recording, StickOutcome};
use crate::physics::stick::StickModel;
use std::time::Instant;

/// One run of a method: the observable, its cost and whether it completed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measured {
    /// The observable (m/s).
    pub value: f64,
    /// Right-hand-side evaluations (flow evaluations; one per Moreau-Jean step).
    pub rhs_evals: u64,
    /// Events handled (impacts, takeoffs, stick-slip switches), or contact steps for
    /// Moreau-Jean.
    pub events: u64,
    /// Did the run reach its end time with a finite result?
    pub completed: bool,
    /// How the run ended (`completed`, `zeno`, `invalid`, `failed`, ...).
    pub note: &'static str,
}

/// Records `x(t)` from the segment containing `t`.
struct XAt {
    t: f64,
    x: Option<f64>,
}

impl Observer<BlockMode, 4> for XAt {
    fn segment(&mut self, _m: BlockMode, s: &Segment<'_, 4>) {
        if self.x.is_none() && s.t0 <= self.t && self.t <= s.t1 {
            self.x = Some(s.eval(self.t)[0]);
        }
    }
}

/// The drift window: `(t_a, t_b)` after `transient` periods, `cycles` periods long (s).
pub fn window(scene: &BlockScene, transient: u32, cycles: u32) -> (f64, f64) {
    let t = scene.period_s();
    (f64::from(transient) * t, f64::from(transient + cycles) * t)
}

/// The block's drift with the event-driven driver and `opts`.
pub fn drift_hybrid(scene: &BlockScene, opts: &Options, (t_a, t_b): (f64, f64)) -> Measured {
    let mut obs = XAt { t: t_a, x: None };
    let y0 = [0.0, 0.0, scene.plate.z_m(0.0), scene.plate.vz_mps(0.0)];
    let run = simulate(
        scene,
        BlockMode::Stick,
        0.0,
        y0,
        t_b,
        &Options {
            record_events: false,
            ..*opts
        },
        &mut obs,
    );
    let value = match obs.x {
        Some(xa) => (run.y_end[0] - xa) / (t_b - t_a), // formula: v_drift = (x(t_b) - x(t_a)) / (t_b - t_a)
        None => f64::NAN,
    };
    Measured {
        value,
        rhs_evals: run.stats.rhs_evals,
        events: run.event_count as u64,
        completed: run.outcome == Outcome::Completed && value.is_finite(),
        note: outcome_label(&run.outcome),
    }
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
    let q0 = [0.0, scene.plate.z_m(0.0)];
    let v0 = [0.0, scene.plate.vz_mps(0.0)];
    let n_a = (t_a / h).round() as u64;
    let mut k = 0u64;
    let mut xa = f64::NAN;
    let run = mj::simulate(scene, 0.0, q0, v0, t_b, &MjOptions::midpoint(h), |s| {
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
                events: r.stats.contact_steps,
                completed: value.is_finite(),
                note: "completed",
            }
        }
        Err(_) => Measured {
            value: f64::NAN,
            rhs_evals: k,
            events: 0,
            completed: false,
            note: "failed",
        },
    }
}

/// Runs `f` `repeats` times; returns its (last) result and the minimum wall time (s).
pub fn timed<R>(repeats: u32, mut f: impl FnMut() -> R) -> (R, f64) {
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..repeats.max(1) {
        let start = Instant::now();
        let r = f();
        best = best.min(start.elapsed().as_secs_f64());
        out = Some(r);
    }
    (out.expect("at least one repeat"), best)
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
    use crate::physics::block::{simulate_block, BlockOptions, BlockParams};
    let mut params = BlockParams::coulomb(scene.g, scene.mu, scene.bias * scene.g); // b = F/m = bias g
    params.restitution = scene.e;
    params.rest_velocity_mps = scene.stick_below_mps;
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
        &params,
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
        StickOutcome::Invalid(why) => Some(why.split(" at t =").next().unwrap_or(why).to_string()),
        other => Some(other.label().to_string()),
    };
    let m = Measured {
        value: r.mean_velocity_mps,
        rhs_evals: r.stats.rhs_evals,
        events: r.hops as u64,
        completed,
        note: r.outcome.label(),
    };
    (m, reason)
}
