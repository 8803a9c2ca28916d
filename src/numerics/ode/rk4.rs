//! Classical Runge-Kutta: order 4, four evaluations per step, the cubic Hermite of the
//! end values and end derivatives as its interpolant.

use super::common::{comb, stage_arg};
use super::step::Interp;
use super::stepper::{accept_fixed, fixed_step, At, Memory, Stepper};
use super::{OdeError, OdeSystem, Stats, StepControl};

/// Short name for tables and JSON.
pub(super) const NAME: &str = "rk4";
/// Order of the solution.
pub(super) const ORDER: u32 = 4;

/// Classical Runge-Kutta 4 (fixed steps only: adaptive control gives its `h_max_s`).
#[derive(Debug, Clone, Default)]
pub(super) struct Rk4<const N: usize>;

impl<const N: usize> Stepper<N> for Rk4<N> {
    fn step<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        at: At<'_, N>,
        control: StepControl,
        mem: &mut Memory<N>,
        stats: &mut Stats,
    ) -> Result<(), OdeError> {
        let (h, t1) = fixed_step(&at, control);
        let (t, y, f0, m) = (at.t, at.y, at.f0, S::ARGS);
        let k2 = sys.rhs(t + 0.5 * h, &stage_arg(y, h, &[(0.5, &f0)], m));
        let k3 = sys.rhs(t + 0.5 * h, &stage_arg(y, h, &[(0.5, &k2)], m));
        let k4 = sys.rhs(t + h, &stage_arg(y, h, &[(1.0, &k3)], m));
        stats.rhs_evals += 3;
        // formula: y1 = y0 + h/6 (k1 + 2 k2 + 2 k3 + k4)
        let y1 = comb(
            y,
            h,
            &[
                (1.0 / 6.0, &f0),
                (1.0 / 3.0, &k2),
                (1.0 / 3.0, &k3),
                (1.0 / 6.0, &k4),
            ],
        );
        // End derivative for the Hermite interpolant; it is the next step's first
        // stage, so it is cached, not wasted.
        let f1 = mem.deriv(stats, sys, t1, &y1);
        mem.finish((t, y), (t1, y1), f1, Some(Interp::Hermite { f0, f1 }));
        accept_fixed(mem, stats, t1)
    }
}
