//! The failure scenes of the chapter: each runs the failing method and the good one.

use super::block_scene::{BlockMode, BlockScene};
use super::measure::{drift_hybrid, drift_mj, window};
use crate::numerics::hybrid::{simulate, Options, Outcome};
use crate::numerics::ode::{Integrator, Method, OdeError, StepControl};
use crate::physics::plate::PlateMotion;
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
        let mut integ = Integrator::new(method, control);
        let y = integ.integrate(
            &|t: f64, y: &[f64; 1]| self.rhs(t, y),
            0.0,
            [0.0],
            t_end,
            |_| {},
        )?;
        let e = (y[0] - self.exact(t_end)).abs();
        if e.is_finite() {
            Ok(e)
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
    /// Adaptive DP5's error at the end.
    pub dopri5_error: f64,
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
    let dopri5_error = r
        .error(Method::Dopri5, StepControl::tol(1e-8, 1e-8), duration_s)
        .unwrap_or(f64::NAN);
    StiffOutcome {
        fixed,
        dopri5_error,
        h_over_tau: h / tau_s,
    }
}

/// Result of the Zeno scene.
#[derive(Debug, Clone, PartialEq)]
pub struct ZenoOutcome {
    /// Time the event-driven run stopped with `Outcome::Zeno` (s), if it did.
    pub zeno_at_s: Option<f64>,
    /// Events before it stopped.
    pub events: usize,
    /// Drift with the sticking transition (event-driven, m/s), NaN if it did not complete.
    pub drift_sticking_mps: f64,
    /// Drift with Moreau-Jean (m/s), NaN if it did not complete.
    pub drift_mj_mps: f64,
    /// Moreau-Jean steps per period.
    pub mj_steps_per_period: u32,
}

/// The bouncing block with restitution `e` on the plate: event-driven without and
/// with the sticking transition (rebounds slower than 0.1 mm/s end in contact), and
/// Moreau-Jean, over `cycles` periods after `transient`.
pub fn zeno(
    scene: &BlockScene,
    e: f64,
    transient: u32,
    cycles: u32,
    mj_steps_per_period: u32,
) -> ZenoOutcome {
    let mut s = BlockScene {
        e,
        closed_form: true,
        stick_below_mps: 0.0,
        ..*scene
    };
    let w = window(&s, transient, cycles);
    let y0 = [0.0, 0.0, s.plate.z_m(0.0), s.plate.vz_mps(0.0)];
    let run = simulate(
        &s,
        BlockMode::Stick,
        0.0,
        y0,
        w.1,
        &Options {
            record_events: false,
            ..Options::default()
        },
        &mut (),
    );
    let zeno_at_s = match run.outcome {
        Outcome::Zeno { t_s, .. } => Some(t_s),
        _ => None,
    };
    s.stick_below_mps = 1e-4;
    let sticking = drift_hybrid(&s, &Options::default(), w);
    let mj = drift_mj(&s, mj_steps_per_period, w);
    ZenoOutcome {
        zeno_at_s,
        events: run.event_count,
        drift_sticking_mps: if sticking.completed {
            sticking.value
        } else {
            f64::NAN
        },
        drift_mj_mps: if mj.completed { mj.value } else { f64::NAN },
        mj_steps_per_period,
    }
}
