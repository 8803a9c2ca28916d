//! One run of the soft-contact stick with a chosen integrator and a step budget.

use super::{SoftParams, SoftStick, SD};
use crate::numerics::ode::{Integrator, Method, OdeError, Stats, StepControl};
use crate::physics::stick::StickModel;
use crate::physics::stick::StickParams;

/// How a soft-contact run ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SoftOutcome {
    /// Reached the end time.
    Completed,
    /// The integrator failed (step too small, non-finite state).
    Failed(OdeError),
    /// The step budget ran out at `t_s` (s).
    Budget {
        /// Time reached (s).
        t_s: f64,
    },
}

/// Summary of a soft-contact run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoftSummary {
    /// Mean horizontal velocity of C (m/s); NaN unless completed.
    pub mean_velocity_mps: f64,
    /// Integration work.
    pub stats: Stats,
    /// How it ended.
    pub outcome: SoftOutcome,
    /// Deepest penetration of C into the plate at a step's end (m).
    pub max_penetration_m: f64,
    /// Smallest accepted step (s).
    pub min_step_s: f64,
}

/// Runs the soft stick of `p` (regularisation `eps`) from rest at its static angle for
/// `cycles` drive periods with `method` and `control`, at most `max_steps` accepted steps.
pub fn simulate_soft(
    p: &StickParams,
    eps: f64,
    cycles: f64,
    method: Method,
    control: StepControl,
    max_steps: u64,
) -> SoftSummary {
    let soft = SoftParams::regularised(p, eps);
    simulate_soft_with(p, soft, cycles, method, control, max_steps)
}

/// As [`simulate_soft`] with the contact constants `soft` given one by one (to vary one
/// constant at a time).
pub(crate) fn simulate_soft_with(
    p: &StickParams,
    soft: SoftParams,
    cycles: f64,
    method: Method,
    control: StepControl,
    max_steps: u64,
) -> SoftSummary {
    let sys = SoftStick {
        model: StickModel::new(*p),
        soft,
    };
    let theta = p.static_angle().unwrap_or(p.theta0_rad);
    let y0 = sys.at_rest(0.0, theta);
    let t_end = cycles * p.period_s();
    let mut integ = Integrator::new(method, control);
    let (mut t, mut y) = (0.0, y0);
    let mut out = SoftSummary {
        mean_velocity_mps: f64::NAN,
        stats: Stats::default(),
        outcome: SoftOutcome::Completed,
        max_penetration_m: 0.0,
        min_step_s: f64::INFINITY,
    };
    while t < t_end {
        if integ.stats.accepted >= max_steps {
            out.outcome = SoftOutcome::Budget { t_s: t };
            break;
        }
        match integ.step(&sys, t, &y, t_end) {
            Ok(s) => {
                if s.t1 < t_end {
                    out.min_step_s = out.min_step_s.min(s.t1 - s.t0);
                }
                t = s.t1;
                y = s.y1;
                out.max_penetration_m = out.max_penetration_m.max(-y[SD]);
            }
            Err(e) => {
                out.outcome = SoftOutcome::Failed(e);
                break;
            }
        }
    }
    out.stats = integ.stats;
    if out.outcome == SoftOutcome::Completed {
        out.mean_velocity_mps = (sys.x_c(&y) - sys.x_c(&y0)) / t_end;
    }
    out
}
