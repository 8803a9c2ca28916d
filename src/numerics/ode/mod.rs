//! Explicit Runge-Kutta methods for `y' = f(t, y)`: Euler, classical Runge-Kutta 4,
//! Dormand-Prince 5(4) (`ode/dopri5.rs`) and Dormand-Prince 8(5,3) (`ode/dop853.rs`).
//!
//! One [`Integrator`] serves all four methods. Every accepted step comes back as a
//! [`Step`] carrying an interpolant over the step (linear for Euler, cubic Hermite for
//! RK4, the continuous extensions of Hairer, Norsett & Wanner for the two
//! Dormand-Prince pairs: order 4 for DP5, order 7 for DOP853), which is what event
//! location searches.
//!
//! State vectors are fixed-size arrays `[f64; N]`: no allocation in the stepping loop.

// Index loops run over several arrays of the same length at once (y, k1..k7, r); they read
// like the formulas they implement.
#![allow(clippy::needless_range_loop)]

mod common;
mod dop853;
mod dopri5;
mod rosenbrock;
mod step;

use common::{comb, finite, initial_step, place_step, stage_arg, Tol};
use step::Interp;
pub use step::Step;

/// A first-order system `y' = f(t, y)` of dimension `N`.
pub trait OdeSystem<const N: usize> {
    /// How many leading components of `y` the right-hand side reads (default: all).
    /// The others are outputs only, integrals such as an energy account that nothing
    /// feeds back from (SUNDIALS calls them quadrature variables): they are integrated
    /// with the same stages and error control, but the stage arguments are formed for
    /// the first `ARGS` components only, which changes no result as long as `rhs`
    /// really does not read the rest.
    const ARGS: usize = N;

    /// The right-hand side `f(t, y)`.
    fn rhs(&self, t: f64, y: &[f64; N]) -> [f64; N];

    /// The Jacobian `df/dy` at `(t, y)`, row-major, for the implicit method; `None`
    /// (the default): the method forms it by finite differences.
    fn jacobian(&self, _t: f64, _y: &[f64; N]) -> Option<[[f64; N]; N]> {
        None
    }
}

impl<F, const N: usize> OdeSystem<N> for F
where
    F: Fn(f64, &[f64; N]) -> [f64; N],
{
    fn rhs(&self, t: f64, y: &[f64; N]) -> [f64; N] {
        self(t, y)
    }
}

/// The integration method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Method {
    /// Explicit Euler, order 1, one evaluation per step.
    Euler,
    /// Classical Runge-Kutta, order 4, four evaluations per step.
    Rk4,
    /// Dormand-Prince 5(4), order 5 with an embedded order-4 error estimate, six new
    /// evaluations per step (first-same-as-last).
    Dopri5,
    /// Dormand-Prince 8(5,3), order 8 with a blended fifth/third-order error estimate,
    /// eleven new evaluations per step (first-same-as-last), three more for a step whose
    /// interior is evaluated (the order-7 interpolant).
    Dop853,
    /// The linearly implicit Rosenbrock 2(3) pair of Shampine & Reichelt (MATLAB's
    /// `ode23s`), order 2, L-stable, for stiff systems: two evaluations and one LU of
    /// `I - h d J` per step, plus `N + 1` evaluations for a finite-difference Jacobian.
    Rosenbrock23,
}

impl Method {
    /// Short lower-case name for tables and JSON.
    pub fn name(self) -> &'static str {
        match self {
            Method::Euler => "euler",
            Method::Rk4 => "rk4",
            Method::Dopri5 => "dopri5",
            Method::Dop853 => "dop853",
            Method::Rosenbrock23 => "rosenbrock23",
        }
    }

    /// Order of the method's solution.
    pub fn order(self) -> u32 {
        match self {
            Method::Euler => 1,
            Method::Rk4 => 4,
            Method::Dopri5 => 5,
            Method::Dop853 => 8,
            Method::Rosenbrock23 => 2,
        }
    }
}

/// How the step size is chosen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepControl {
    /// Constant step `h_s` (the last step of an interval is shortened to land on its end).
    Fixed {
        /// Step size (s).
        h_s: f64,
    },
    /// Error-controlled steps (the Dormand-Prince pairs and Rosenbrock 2(3)): per component the local error estimate is
    /// kept below `atol + rtol * |y|` in the RMS norm; steps never exceed `h_max_s`.
    Adaptive {
        /// Relative tolerance.
        rtol: f64,
        /// Absolute tolerance (units of the state).
        atol: f64,
        /// Largest step (s).
        h_max_s: f64,
    },
}

impl StepControl {
    /// Adaptive control with `rtol`, `atol` and no step limit.
    pub fn tol(rtol: f64, atol: f64) -> Self {
        StepControl::Adaptive {
            rtol,
            atol,
            h_max_s: f64::INFINITY,
        }
    }
}

/// Work counters.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Right-hand-side evaluations.
    pub rhs_evals: u64,
    /// Accepted steps.
    pub accepted: u64,
    /// Rejected steps (adaptive control only).
    pub rejected: u64,
}

impl std::ops::AddAssign for Stats {
    fn add_assign(&mut self, o: Stats) {
        self.rhs_evals += o.rhs_evals;
        self.accepted += o.accepted;
        self.rejected += o.rejected;
    }
}

/// Why integration stopped early.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OdeError {
    /// The adaptive step fell below the round-off limit at time `t_s`.
    StepTooSmall {
        /// Time (s).
        t_s: f64,
    },
    /// The state or its derivative became NaN or infinite at time `t_s`.
    NonFinite {
        /// Time (s).
        t_s: f64,
    },
}

impl std::fmt::Display for OdeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OdeError::StepTooSmall { t_s } => write!(f, "step size underflow at t = {t_s} s"),
            OdeError::NonFinite { t_s } => write!(f, "non-finite state at t = {t_s} s"),
        }
    }
}

/// A stepping integrator with memory (step-size suggestion, first-same-as-last value).
#[derive(Debug, Clone)]
pub struct Integrator<const N: usize> {
    /// The method.
    pub method: Method,
    /// The step-size control.
    pub control: StepControl,
    /// Work done so far.
    pub stats: Stats,
    h_next: Option<f64>,
    fsal: Option<(f64, [f64; N], [f64; N])>,
    /// DP5's last trial step, before acceptance: its seventh stage and its continuous
    /// extension's coefficients (DOP853's stages are written straight into `last`, and a
    /// trial returns only its end state, so nothing large is moved per trial).
    dopri_trial: ([f64; N], [[f64; N]; 4]),
    /// The last accepted step, lent to the caller by [`Integrator::step`].
    last: Step<N>,
}

impl<const N: usize> Integrator<N> {
    /// A new integrator. Adaptive control is only meaningful for the Dormand-Prince
    /// pairs; Euler and RK4 with `Adaptive` use `h_max_s` (or 1e-3 s) as a fixed step.
    pub fn new(method: Method, control: StepControl) -> Self {
        Integrator {
            method,
            control,
            stats: Stats::default(),
            h_next: None,
            fsal: None,
            dopri_trial: ([0.0; N], [[0.0; N]; 4]),
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

    /// Forgets the step history: call after a discontinuity (an event or a reset),
    /// so that no derivative from before it is reused. Keeps the step suggestion.
    pub fn restart(&mut self) {
        self.fsal = None;
    }

    fn deriv<S: OdeSystem<N> + ?Sized>(&mut self, sys: &S, t: f64, y: &[f64; N]) -> [f64; N] {
        if let Some((tf, yf, f)) = &self.fsal {
            if *tf == t && yf == y {
                return *f;
            }
        }
        self.stats.rhs_evals += 1;
        sys.rhs(t, y)
    }

    /// Takes one accepted step from `(t, y)` towards `t_max` (never beyond it). The
    /// step is kept inside the integrator until the next call (no copy of its stages).
    pub fn step<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        y: &[f64; N],
        t_max: f64,
    ) -> Result<&Step<N>, OdeError> {
        let f0 = self.deriv(sys, t, y);
        self.last.f0 = f0;
        if !finite(&f0) || !finite(y) {
            return Err(OdeError::NonFinite { t_s: t });
        }
        let span = t_max - t;
        match (self.method, self.control) {
            (
                Method::Dopri5 | Method::Dop853,
                StepControl::Adaptive {
                    rtol,
                    atol,
                    h_max_s,
                },
            ) => {
                self.adaptive(sys, t, y, f0, span, Tol { rtol, atol }, h_max_s)?;
                Ok(&self.last)
            }
            (
                Method::Rosenbrock23,
                StepControl::Adaptive {
                    rtol,
                    atol,
                    h_max_s,
                },
            ) => {
                self.rosenbrock(sys, (t, y, f0), span, Some(Tol { rtol, atol }), h_max_s)?;
                Ok(&self.last)
            }
            (Method::Rosenbrock23, StepControl::Fixed { h_s }) => {
                self.rosenbrock(sys, (t, y, f0), span, None, h_s.min(span))?;
                Ok(&self.last)
            }
            (method, control) => {
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
                let t1 = if h == span { t_max } else { t + h };
                match method {
                    Method::Euler => {
                        let y1 = comb(y, h, &[(1.0, &f0)]); // formula: y1 = y0 + h f(t0, y0)
                        self.keep(t, y, t1, y1, Some(Interp::Linear));
                        self.last.f1 = None;
                    }
                    Method::Rk4 => {
                        let m = S::ARGS;
                        let k2 = sys.rhs(t + 0.5 * h, &stage_arg(y, h, &[(0.5, &f0)], m));
                        let k3 = sys.rhs(t + 0.5 * h, &stage_arg(y, h, &[(0.5, &k2)], m));
                        let k4 = sys.rhs(t + h, &stage_arg(y, h, &[(1.0, &k3)], m));
                        self.stats.rhs_evals += 3;
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
                        // End derivative for the Hermite interpolant; it is the next
                        // step's first stage, so it is cached, not wasted.
                        let f1 = self.deriv(sys, t1, &y1);
                        self.finish(t, y, t1, y1, f1, Some(Interp::Hermite { f0, f1 }))
                    }
                    Method::Dopri5 | Method::Dop853 => {
                        let (trial, _) = self.trial(sys, t, y, &f0, h, Tol::UNUSED);
                        self.accept(sys, t, y, t1, trial)
                    }
                    Method::Rosenbrock23 => unreachable!("matched above"),
                };
                if !finite(&self.last.y1) {
                    return Err(OdeError::NonFinite { t_s: t1 });
                }
                self.stats.accepted += 1;
                Ok(&self.last)
            }
        }
    }

    /// One trial step of size `h` of a Dormand-Prince pair and its error norm (1 = at
    /// the tolerance).
    fn trial<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        y: &[f64; N],
        f0: &[f64; N],
        h: f64,
        tol: Tol,
    ) -> ([f64; N], f64) {
        if self.method == Method::Dop853 {
            let (y1, e) = dop853::attempt(sys, t, y, f0, h, tol, self.dop853_stages());
            self.stats.rhs_evals += 11;
            (y1, e)
        } else {
            let (y1, k7, r, err) = dopri5::stages(sys, t, y, f0, h);
            self.stats.rhs_evals += 6;
            self.dopri_trial = (k7, r);
            (y1, dopri5::error_norm(y, &y1, &err, tol))
        }
    }

    /// DOP853's stage buffer inside the kept step (made a DOP853 step, its continuous
    /// extension forgotten): the trial writes its stages there.
    fn dop853_stages(&mut self) -> &mut dop853::Stages<N> {
        if !matches!(self.last.interp, Interp::Dop853(_)) {
            self.last.interp = Interp::Dop853(dop853::Lazy::default());
        }
        match &mut self.last.interp {
            Interp::Dop853(lazy) => lazy.stages_for_new_step(),
            _ => unreachable!("made a DOP853 step just above"),
        }
    }

    /// Finishes an accepted trial step `t -> t1`: its end derivative (DOP853 evaluates
    /// it now, DP5 has it as its seventh stage) becomes the next step's first stage.
    fn accept<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        y: &[f64; N],
        t1: f64,
        y1: [f64; N],
    ) {
        match self.method {
            Method::Dop853 => {
                let f1 = sys.rhs(t1, &y1); // formula: f(t + h, y1), first stage of the next step
                self.stats.rhs_evals += 1;
                self.dop853_stages()[12] = f1;
                self.finish(t, y, t1, y1, f1, None)
            }
            _ => {
                let (k7, r) = self.dopri_trial;
                self.finish(t, y, t1, y1, k7, Some(Interp::Dopri { r }))
            }
        }
    }

    /// The step `(t, y) -> (t1, y1)` with its interpolant (`None`: DOP853's, already
    /// in place); its end derivative `f1` is kept as the next step's first stage.
    fn finish(
        &mut self,
        t: f64,
        y: &[f64; N],
        t1: f64,
        y1: [f64; N],
        f1: [f64; N],
        interp: Option<Interp<N>>,
    ) {
        self.fsal = Some((t1, y1, f1));
        self.keep(t, y, t1, y1, interp);
        self.last.f1 = Some(f1);
    }

    /// Makes `(t, y) -> (t1, y1)` the kept step, with its interpolant (`None`: the one
    /// already in place).
    fn keep(&mut self, t: f64, y: &[f64; N], t1: f64, y1: [f64; N], interp: Option<Interp<N>>) {
        self.last.t0 = t;
        self.last.t1 = t1;
        self.last.y0 = *y;
        self.last.y1 = y1;
        if let Some(interp) = interp {
            self.last.interp = interp;
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn adaptive<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        y: &[f64; N],
        f0: [f64; N],
        span: f64,
        tol: Tol,
        h_max: f64,
    ) -> Result<(), OdeError> {
        // Step-size controller of each pair (Hairer's codes): the error estimate is of
        // order q + 1 in h (q = 4 for DP5, 7 for DOP853), so h_new = h (0.9 / e)^(1/(q+1)),
        // limited to [fac_min, fac_max] after an accepted step. DOP853's e^(-1/8) is three
        // square roots (a fifth of the cost of powf).
        let (root, fac_min, fac_max): (fn(f64) -> f64, f64, f64) = match self.method {
            Method::Dop853 => (|e| 1.0 / e.sqrt().sqrt().sqrt(), 1.0 / 3.0, 6.0), // formula: e^(-1/8)
            _ => (|e| e.powf(-0.2), 0.2, 5.0), // formula: e^(-1/5)
        };
        let mut h = match self.h_next {
            Some(h) => h,
            None => initial_step(sys, t, y, &f0, tol, self.method.order(), &mut self.stats),
        }
        .min(h_max);
        loop {
            let (h_placed, t1, last) = place_step(t, span, h)?;
            h = h_placed;
            let (y1, e) = self.trial(sys, t, y, &f0, h, tol);
            if e.is_finite() && e <= 1.0 {
                // formula: h_new = h min(fac_max, max(fac_min, 0.9 e^(-1/(q+1))))
                let fac = if e == 0.0 {
                    fac_max
                } else {
                    (0.9 * root(e)).clamp(fac_min, fac_max)
                };
                if !last {
                    self.h_next = Some((h * fac).min(h_max));
                } else if self.h_next.is_none() {
                    self.h_next = Some(h);
                }
                self.stats.accepted += 1;
                self.accept(sys, t, y, t1, y1);
                return Ok(());
            }
            self.stats.rejected += 1;
            let fac = if e.is_finite() {
                (0.9 * root(e)).clamp(0.1, 0.9)
            } else {
                0.1
            };
            h *= fac;
            self.h_next = Some(h);
        }
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

#[cfg(test)]
mod tests;
