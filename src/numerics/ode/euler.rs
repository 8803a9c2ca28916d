//! Explicit Euler: order 1, one evaluation per step, a straight line as its interpolant.

use super::common::comb;
use super::step::Interp;
use super::stepper::{accept_fixed, fixed_step, At, Memory, Stepper};
use super::{OdeError, OdeSystem, Stats, StepControl};

/// Short name for tables and JSON.
pub(super) const NAME: &str = "euler";
/// Order of the solution.
pub(super) const ORDER: u32 = 1;

/// Explicit Euler (fixed steps only: adaptive control gives its `h_max_s` as the step).
#[derive(Debug, Clone, Default)]
pub(super) struct Euler<const N: usize>;

impl<const N: usize> Stepper<N> for Euler<N> {
    fn step<S: OdeSystem<N> + ?Sized>(
        &mut self,
        _sys: &S,
        at: At<'_, N>,
        control: StepControl,
        mem: &mut Memory<N>,
        stats: &mut Stats,
    ) -> Result<(), OdeError> {
        let (h, t1) = fixed_step(&at, control);
        let y1 = comb(at.y, h, &[(1.0, &at.f0)]); // formula: y1 = y0 + h f(t0, y0)
        mem.keep((at.t, at.y), (t1, y1), Some(Interp::Linear));
        mem.last.f1 = None;
        accept_fixed(mem, stats, t1)
    }
}
