//! The [`Stepper`] trait: one accepted step of one method, and what every method shares
//! (the kept step, the step-size suggestion, the first-same-as-last derivative, the
//! placement of a fixed step). Each method is one file implementing it
//! (`euler.rs`, `rk4.rs`, `dopri5.rs`, `dop853.rs`, `rosenbrock.rs`); the list that
//! maps a user's [`Method`](super::Method) to its stepper is one line per method in
//! `ode/mod.rs`.

use super::common::finite;
use super::step::{Interp, Step};
use super::{OdeError, OdeSystem, Stats, StepControl};

/// Where a step starts: `(t, y)`, the derivative `f0 = f(t, y)`, and the end of the
/// interval it may not pass, `t_max` (all times in s).
#[derive(Debug, Clone, Copy)]
pub(super) struct At<'a, const N: usize> {
    pub(super) t: f64,
    pub(super) y: &'a [f64; N],
    pub(super) f0: [f64; N],
    pub(super) t_max: f64,
}

impl<const N: usize> At<'_, N> {
    /// The length of the interval left (s).
    pub(super) fn span(&self) -> f64 {
        self.t_max - self.t
    }
}

/// One integration method: takes one accepted step from `at` under `control`, leaves
/// it in `mem.last` (with its interpolant) and counts its work in `stats`.
pub(super) trait Stepper<const N: usize>: Default {
    fn step<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        at: At<'_, N>,
        control: StepControl,
        mem: &mut Memory<N>,
        stats: &mut Stats,
    ) -> Result<(), OdeError>;
}

/// What an integrator remembers between steps, whatever its method.
#[derive(Debug, Clone)]
pub(super) struct Memory<const N: usize> {
    /// The suggested size of the next step (adaptive control), s.
    pub(super) h_next: Option<f64>,
    /// `(t1, y1, f(t1, y1))` of the last step, the next step's first stage.
    pub(super) fsal: Option<(f64, [f64; N], [f64; N])>,
    /// The last accepted step, lent to the caller.
    pub(super) last: Step<N>,
}

impl<const N: usize> Default for Memory<N> {
    fn default() -> Self {
        Memory {
            h_next: None,
            fsal: None,
            last: Step {
                t0: 0.0,
                t1: 0.0,
                y0: [0.0; N],
                y1: [0.0; N],
                f0: [0.0; N],
                f1: None,
                interp: Interp::Linear,
            },
        }
    }
}

impl<const N: usize> Memory<N> {
    /// `f(t, y)`, reusing the last step's end derivative when `(t, y)` is its end.
    pub(super) fn deriv<S: OdeSystem<N> + ?Sized>(
        &self,
        stats: &mut Stats,
        sys: &S,
        t: f64,
        y: &[f64; N],
    ) -> [f64; N] {
        if let Some((tf, yf, f)) = &self.fsal {
            if *tf == t && yf == y {
                return *f;
            }
        }
        stats.rhs_evals += 1;
        sys.rhs(t, y)
    }

    /// The step `(t, y) -> (t1, y1)` with its interpolant (`None`: the one already in
    /// place); its end derivative `f1` is kept as the next step's first stage.
    pub(super) fn finish(
        &mut self,
        (t, y): (f64, &[f64; N]),
        (t1, y1): (f64, [f64; N]),
        f1: [f64; N],
        interp: Option<Interp<N>>,
    ) {
        self.fsal = Some((t1, y1, f1));
        self.keep((t, y), (t1, y1), interp);
        self.last.f1 = Some(f1);
    }

    /// Makes `(t, y) -> (t1, y1)` the kept step, with its interpolant (`None`: the one
    /// already in place).
    pub(super) fn keep(
        &mut self,
        (t, y): (f64, &[f64; N]),
        (t1, y1): (f64, [f64; N]),
        interp: Option<Interp<N>>,
    ) {
        self.last.t0 = t;
        self.last.t1 = t1;
        self.last.y0 = *y;
        self.last.y1 = y1;
        if let Some(interp) = interp {
            self.last.interp = interp;
        }
    }
}

/// The size and end of a fixed step from `at`: `h_s` of [`StepControl::Fixed`], or
/// `h_max_s` (1e-3 s when unlimited) for a fixed-step method given adaptive control;
/// within a hair (1e-12 relative) of `t_max` the step lands on it, instead of leaving
/// a sliver. Returns `(h, t1)`.
pub(super) fn fixed_step<const N: usize>(at: &At<'_, N>, control: StepControl) -> (f64, f64) {
    let span = at.span();
    let h_fixed = match control {
        StepControl::Fixed { h_s } => h_s,
        StepControl::Adaptive { h_max_s, .. } => {
            if h_max_s.is_finite() {
                h_max_s
            } else {
                1e-3
            }
        }
    };
    // Land on t_max when within a hair of it, instead of a sliver step.
    let h = if h_fixed >= span * (1.0 - 1e-12) {
        span
    } else {
        h_fixed
    };
    let t1 = if h == span { at.t_max } else { at.t + h };
    (h, t1)
}

/// Closes a fixed step: its end state must be finite; it counts as accepted.
pub(super) fn accept_fixed<const N: usize>(
    mem: &Memory<N>,
    stats: &mut Stats,
    t1: f64,
) -> Result<(), OdeError> {
    if !finite(&mem.last.y1) {
        return Err(OdeError::NonFinite { t_s: t1 });
    }
    stats.accepted += 1;
    Ok(())
}
