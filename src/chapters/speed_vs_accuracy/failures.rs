//! The failure scenes of the chapter: each runs the failing method and the good one.

use super::block_scene::BlockScene;
use super::measure::{drift_block_model, drift_mj, window, Measured};
use crate::numerics::hybrid::{Options, Outcome};
use crate::numerics::ode::{Integrator, Method, OdeError, StepControl};
use crate::numerics::timestepping::{self as mj, ContactStatus, MjOptions};
use crate::physics::block::contact_form::BlockContact;
use crate::physics::block::{simulate_block, BlockOptions, BlockParams};
use crate::physics::plate::{Axis, Harmonic};
use super::zeno_bound::{event_driven_bound_s, mj_rest_bound_s, ZenoStop};
use crate::numerics::rounding::{gamma, OWN};
use serde_json::{json, Value};

/// One observed failure: `{method, scene, symptom}`.
#[derive(Debug, Clone, PartialEq)]
pub struct Failure {
    /// The failing method.
    pub method: String,
    /// The scene.
    pub scene: String,
    /// What went wrong, with the number that shows it.
    pub symptom: String,
}

impl Failure {
    /// The JSON row of `failures`.
    pub fn json(&self) -> Value {
        json!({"method": self.method, "scene": self.scene, "symptom": self.symptom})
    }
}

/// The stick's flight relaxation `theta' = -(k/gamma)(theta - theta_0(t))` with a
/// target moving at the drive frequency: tau = gamma/k (s), forcing amplitude 0.1 rad.
pub struct Relaxation {
    /// Time constant gamma/k (s).
    pub tau_s: f64,
    /// Drive angular frequency (rad/s).
    pub omega_rad_s: f64,
}

impl Relaxation {
    const A: f64 = 0.1;

    fn rhs(&self, t: f64, y: &[f64; 1]) -> [f64; 1] {
        [-(y[0] - Self::A * (self.omega_rad_s * t).cos()) / self.tau_s] // formula: theta' = -(theta - a cos wt)/tau
    }

    /// Closed form from theta(0) = 0.
    pub fn exact(&self, t: f64) -> f64 {
        let wt = self.omega_rad_s * self.tau_s;
        let d = 1.0 + wt * wt;
        // formula: theta = a (cos wt + w tau sin wt)/(1 + w^2 tau^2) - a e^(-t/tau)/(1 + w^2 tau^2)
        Self::A * ((self.omega_rad_s * t).cos() + wt * (self.omega_rad_s * t).sin()) / d
            - Self::A / d * (-t / self.tau_s).exp()
    }

    /// The error at `t_end` of `method` with `control`, or the integrator's error.
    pub fn error(&self, method: Method, control: StepControl, t_end: f64) -> Result<f64, OdeError> {
        self.error_and_budget(method, control, t_end).map(|(e, _)| e)
    }

    /// The error at `t_end` of `method` with `control` and its error budget (rad), or
    /// the integrator's error. The budget, for an adaptive `control` (rtol, atol): every
    /// accepted step k, ending at t_k, leaves a local error below its error scale
    /// `sc_k = atol + rtol max(|θ_k-1|, |θ_k|)` (its error norm is at most 1;
    /// *assumed*: the embedded estimate bounds the local error of the propagated
    /// solution, as local extrapolation makes it smaller), plus its rounding, γ_16 times
    /// the step's magnitudes |θ_k| + |θ_k - θ_k-1|; the flow is linear with rate -1/τ,
    /// so a deviation at t_k reaches t_end multiplied by exactly e^(-(t_end - t_k)/τ);
    /// the closed form's own rounding adds γ_16 2a. For a fixed step the budget is NaN.
    pub fn error_and_budget(
        &self,
        method: Method,
        control: StepControl,
        t_end: f64,
    ) -> Result<(f64, f64), OdeError> {
        let mut integ = Integrator::new(method, control);
        let (rtol, atol) = match control {
            StepControl::Adaptive { rtol, atol, .. } => (rtol, atol),
            _ => (f64::NAN, f64::NAN),
        };
        let mut steps: Vec<(f64, f64)> = Vec::new();
        let y = integ.integrate(
            &|t: f64, y: &[f64; 1]| self.rhs(t, y),
            0.0,
            [0.0],
            t_end,
            |s| {
                let (a, b) = (s.y0[0], s.y1[0]);
                let sc = atol + rtol * a.abs().max(b.abs()); // formula: sc_k = atol + rtol max(|θ_k-1|, |θ_k|)
                let round = gamma(16) * (b.abs() + (b - a).abs()); // formula: γ_16 (|θ_k| + |θ_k - θ_k-1|)
                steps.push((s.t1, sc + round));
            },
        )?;
        let damped: f64 = steps
            .iter()
            .map(|&(t1, local)| local * (-(t_end - t1) / self.tau_s).exp()) // formula: sum_k (sc_k + rounding_k) e^(-(t_end - t_k)/τ)
            .sum();
        let budget = (damped + gamma(16) * 2.0 * Self::A) * OWN; // formula: + γ_16 2a (closed form)
        let e = (y[0] - self.exact(t_end)).abs();
        if e.is_finite() {
            Ok((e, budget))
        } else {
            Err(OdeError::NonFinite { t_s: t_end })
        }
    }
}

/// Result of the stiff-relaxation scene.
#[derive(Debug, Clone, PartialEq)]
pub struct StiffOutcome {
    /// Per fixed-step method: the error at the end, or `None` if the state overflowed.
    pub fixed: Vec<(Method, Option<f64>)>,
    /// Adaptive DP5's error at the end (rad).
    pub dopri5_error: f64,
    /// Adaptive DP5's error budget at the end (rad), [`Relaxation::error_and_budget`].
    pub dopri5_budget: f64,
    /// The fixed step over tau.
    pub h_over_tau: f64,
}

/// Fixed steps of a tenth of the drive period on the relaxation with `tau_s`, for
/// `duration_s`; DP5 at 1e-8.
pub fn stiff(tau_s: f64, frequency_hz: f64, duration_s: f64) -> StiffOutcome {
    let r = Relaxation {
        tau_s,
        omega_rad_s: std::f64::consts::TAU * frequency_hz,
    };
    let h = 1.0 / (10.0 * frequency_hz);
    let fixed = [Method::Euler, Method::Rk4]
        .into_iter()
        .map(|m| {
            (
                m,
                r.error(m, StepControl::Fixed { h_s: h }, duration_s).ok(),
            )
        })
        .collect();
    let (dopri5_error, dopri5_budget) = r
        .error_and_budget(Method::Dopri5, StepControl::tol(1e-8, 1e-8), duration_s)
        .unwrap_or((f64::NAN, f64::NAN));
    StiffOutcome {
        fixed,
        dopri5_error,
        dopri5_budget,
        h_over_tau: h / tau_s,
    }
}

/// Does `method` blow up at the fixed step `h = h_over_tau tau` on the relaxation with
/// `tau_s` (error above 1e3 rad, or overflow, within 400 steps)? On the linear decay
/// the amplification per step, |R(-h/tau)|, exceeds 1 exactly beyond the method's
/// stability limit (Euler: |1 - z| < 1, z < 2; RK4: z < 2.785): 5 % beyond it the
/// transient grows by 1.1 (Euler) or 1.23 (RK4) per step, 10^16 and more in 400 steps;
/// 5 % inside it decays.
pub fn blows_up(method: Method, tau_s: f64, frequency_hz: f64, h_over_tau: f64) -> bool {
    let r = Relaxation {
        tau_s,
        omega_rad_s: std::f64::consts::TAU * frequency_hz,
    };
    let h = h_over_tau * tau_s;
    r.error(method, StepControl::Fixed { h_s: h }, 400.0 * h)
        .ok()
        .is_none_or(|e| e > 1e3)
}

/// Result of the Zeno scenes.
#[derive(Debug, Clone, PartialEq)]
pub struct ZenoOutcome {
    /// Ball on a fixed floor: time the event-driven run stopped with `Outcome::Zeno` (s).
    pub ball_zeno_at_s: Option<f64>,
    /// Ball: the bound (s) on |t_stop - t_inf| of that run (`zeno_bound.rs`,
    /// [`event_driven_bound_s`]): the event times' rounding and the stop criterion.
    pub ball_zeno_bound_s: f64,
    /// Ball: the accumulation time `t1 (1 + e)/(1 - e)` (s), closed form.
    pub ball_t_inf_s: f64,
    /// Ball: time from which Moreau-Jean (h = 1 ms) keeps it at rest (s), NaN if never.
    pub ball_mj_rest_s: f64,
    /// Ball: the derived bound on |t_rest - t_inf| for that run (s), `zeno_bound.rs`.
    pub ball_mj_rest_bound_s: f64,
    /// Block on the plate without a rest threshold: events over the run.
    pub events_chattering: u64,
    /// Block with the sticking transition: events over the run.
    pub events_sticking: u64,
    /// Drift with the sticking transition (event-driven, m/s), NaN if it did not complete.
    pub drift_sticking_mps: f64,
    /// Drift with Moreau-Jean (m/s), NaN if it did not complete.
    pub drift_mj_mps: f64,
    /// Drift with Moreau-Jean at half and a quarter of the step (m/s, NaN if a run did not
    /// complete): with `drift_mj_mps` the estimate of Moreau-Jean's error.
    pub drift_mj_half_quarter_mps: (f64, f64),
    /// Drift with the sticking transition at a tenth of its threshold, 0.01 mm/s (m/s,
    /// NaN if it did not complete): the threshold's effect on the drift.
    pub drift_sticking_tenth_mps: f64,
}

/// The Zeno scenes with restitution `e`: (1) a ball (the point-mass block, no bias)
/// dropped from 1 m on a fixed floor (a plate at rest), event-driven (stops with
/// `Outcome::Zeno`) and Moreau-Jean at h = 1 ms (comes to rest); (2) the block on the
/// plate with peak acceleration `gamma_zeno` g, by the workbook's block model without a
/// rest threshold (each chattering sequence is ended only by round-off) and with the
/// sticking transition (rebounds below 0.1 mm/s end in contact), and by Moreau-Jean,
/// over `cycles` periods after `transient`.
pub fn zeno(
    scene: &BlockScene,
    e: f64,
    transient: u32,
    cycles: u32,
    mj_steps_per_period: u32,
) -> ZenoOutcome {
    let g = scene.g();
    let t1 = (2.0 / g).sqrt(); // formula: first impact from 1 m at sqrt(2 h/g)
    let ball_t_inf_s = t1 * (1.0 + e) / (1.0 - e); // formula: t_inf = t1 (1 + e)/(1 - e)
    let t_run = ball_t_inf_s + 1.0;
    let floor = Harmonic::sine(Axis::Z, 0.0, 1.0); // a plate at rest
    let mut ball = scene.params;
    ball.bias_mps2 = 0.0;
    ball.restitution = e;
    ball.rest_velocity_mps = 0.0;
    let (ball_zeno_at_s, ball_zeno_bound_s) = event_driven_ball(ball, &floor, ball_t_inf_s);
    let rest = mj_ball_rest_s(ball, &floor, t_run);
    let s = scene.with_restitution(e, 0.0);
    let chattering = drift_block_model(&s, &Options::default(), true, 64, transient, cycles);
    let s = scene.with_restitution(e, 1e-4);
    let sticking = drift_block_model(&s, &Options::default(), true, 64, transient, cycles);
    let tenth = scene.with_restitution(e, 1e-5);
    let sticking_tenth =
        drift_block_model(&tenth, &Options::default(), true, 64, transient, cycles);
    let win = window(&s, transient, cycles);
    let mj = drift_mj(&s, mj_steps_per_period, win);
    let mj_half = drift_mj(&s, 2 * mj_steps_per_period, win);
    let mj_quarter = drift_mj(&s, 4 * mj_steps_per_period, win);
    let value = |m: &Measured| if m.completed { m.value } else { f64::NAN };
    ZenoOutcome {
        ball_zeno_at_s,
        ball_zeno_bound_s,
        ball_t_inf_s,
        ball_mj_rest_s: rest,
        ball_mj_rest_bound_s: mj_rest_bound_s(e, g, MJ_BALL_STEP_S, 1.0),
        events_chattering: chattering.events,
        events_sticking: sticking.events,
        drift_sticking_mps: value(&sticking),
        drift_mj_mps: value(&mj),
        drift_mj_half_quarter_mps: (value(&mj_half), value(&mj_quarter)),
        drift_sticking_tenth_mps: value(&sticking_tenth),
    }
}

/// The event-driven `ball` (its params: no bias, restitution e, no rest threshold)
/// dropped from 1 m on the `floor`, run to `t_inf_s` + 1 s: the time of its Zeno stop
/// (None if it did not stop so) and the bound on |t_stop - t_inf| of that run
/// ([`event_driven_bound_s`]; NaN without a stop).
pub(super) fn event_driven_ball(ball: BlockParams, floor: &Harmonic, t_inf_s: f64) -> (Option<f64>, f64) {
    let opts = BlockOptions {
        hybrid: Options {
            record_events: false,
            ..Options::default()
        },
        record_events: false,
        start: (0.0, [0.0, 0.0, 1.0, 0.0]),
        ..BlockOptions::default()
    };
    let run = simulate_block(&ball, floor, t_inf_s + 1.0, &opts);
    match run.outcome {
        Outcome::Zeno {
            t_s,
            events,
            window_s,
        } => {
            let stop = ZenoStop {
                t_s,
                landings: run.total_counts.landings as u64,
                in_window: events,
                guard: (opts.hybrid.zeno.max_events, window_s),
            };
            let bound = event_driven_bound_s(ball.restitution, ball.g_mps2, 1.0, t_inf_s, &stop);
            (Some(t_s), bound)
        }
        _ => (None, f64::NAN),
    }
}

/// Moreau-Jean's step on the Zeno ball (s).
pub(super) const MJ_BALL_STEP_S: f64 = 1e-3;

/// The time (s) from which Moreau-Jean (h = 1 ms, theta = 1/2) keeps the `ball` (its
/// params, dropped from 1 m) at rest on the `floor` over `[0, t_run]`: the end of the
/// first step of the final run of sticking steps ending with |v| < 1e-12 m/s; NaN if
/// it never rests.
pub(super) fn mj_ball_rest_s(ball: BlockParams, floor: &Harmonic, t_run: f64) -> f64 {
    let mut rest = f64::NAN;
    if let Some(contact) = BlockContact::new(ball, floor) {
        let _ = mj::simulate(
            &contact,
            0.0,
            [0.0, 1.0],
            [0.0, 0.0],
            t_run,
            &MjOptions::midpoint(MJ_BALL_STEP_S),
            |s| {
                let resting = s.impulse.status == ContactStatus::Stick && s.v1[1].abs() < 1e-12;
                if !resting {
                    rest = f64::NAN;
                } else if rest.is_nan() {
                    rest = s.t1;
                }
            },
        );
    }
    rest
}
