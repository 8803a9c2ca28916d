//! The integrator: a method's stepper (chosen once, from the user's [`Method`]), the
//! step-size control, the work counters and the memory between steps.

use super::common::finite;
use super::{At, Chosen, Memory, Method, OdeError, OdeSystem, Stats, Step, StepControl, Stepper};

/// A stepping integrator with memory (step-size suggestion, first-same-as-last value).
#[derive(Debug, Clone)]
pub struct Integrator<const N: usize> {
    /// The method.
    pub method: Method,
    /// The step-size control.
    pub control: StepControl,
    /// Work done so far.
    pub stats: Stats,
    /// The method's stepper, made once from `method`.
    stepper: Chosen<N>,
    /// The step-size suggestion, the first-same-as-last derivative and the last
    /// accepted step, lent to the caller by [`Integrator::step`].
    mem: Memory<N>,
    /// The control it was checked for, and the verdict ([`StepControl::check`]):
    /// checked again only when `control` has been changed since.
    checked: (StepControl, Result<(), OdeError>),
}

impl<const N: usize> Integrator<N> {
    /// A new integrator. Adaptive control is only meaningful for the Dormand-Prince
    /// pairs and Rosenbrock 2(3); Euler and RK4 with `Adaptive` use `h_max_s` (or
    /// 1e-3 s) as a fixed step.
    pub fn new(method: Method, control: StepControl) -> Self {
        Integrator {
            method,
            control,
            stats: Stats::default(),
            stepper: Chosen::new(method),
            mem: Memory::default(),
            checked: (control, control.check()),
        }
    }

    /// Forgets the step history: call after a discontinuity (an event or a reset),
    /// so that no derivative from before it is reused. Keeps the step suggestion.
    pub(crate) fn restart(&mut self) {
        self.mem.fsal = None;
    }

    /// Takes one accepted step from `(t, y)` towards `t_max` (never beyond it). The
    /// step is kept inside the integrator until the next call (no copy of its stages).
    /// A control outside its range ([`StepControl::check`]) is an error, not a panic.
    pub fn step<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        y: &[f64; N],
        t_max: f64,
    ) -> Result<&Step<N>, OdeError> {
        if self.control != self.checked.0 {
            self.checked = (self.control, self.control.check());
        }
        self.checked.1?;
        let f0 = self.mem.deriv(&mut self.stats, sys, t, y);
        self.mem.last.f0 = f0;
        if !finite(&f0) || !finite(y) {
            return Err(OdeError::NonFinite { t_s: t });
        }
        let at = At { t, y, f0, t_max };
        self.stepper
            .step(sys, at, self.control, &mut self.mem, &mut self.stats)?;
        Ok(&self.mem.last)
    }

    /// Integrates from `(t0, y0)` to `t1`, calling `on_step` for every accepted step.
    pub fn integrate<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        t0: f64,
        y0: [f64; N],
        t1: f64,
        mut on_step: impl FnMut(&Step<N>),
    ) -> Result<[f64; N], OdeError> {
        let (mut t, mut y) = (t0, y0);
        while t < t1 {
            let s = self.step(sys, t, &y, t1)?;
            on_step(s);
            t = s.t1;
            y = s.y1;
        }
        Ok(y)
    }
}
