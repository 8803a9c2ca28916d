//! Runge-Kutta methods for `y' = f(t, y)`: Euler (`ode/euler.rs`), classical Runge-Kutta 4
//! (`ode/rk4.rs`), Dormand-Prince 5(4) (`ode/dopri5.rs`), Dormand-Prince 8(5,3)
//! (`ode/dop853.rs`) and the linearly implicit Rosenbrock 2(3) (`ode/rosenbrock.rs`).
//!
//! Each method is one file implementing the `Stepper` trait (`ode/stepper.rs`) and one
//! line of the `methods!` list below, which makes the user-facing [`Method`] enum and
//! maps each of its values to its stepper once, when an [`Integrator`] is made.
//! One [`Integrator`] serves all five methods. Every accepted step comes back as a
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
mod dop853_dense;
mod dop853_tableau;
mod dopri5;
mod euler;
mod integrator;
mod pair;
mod rk4;
mod rosenbrock;
mod step;
mod stepper;

pub use integrator::Integrator;
pub use step::Step;
use stepper::{At, Memory, Stepper};

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

/// The list of methods: its doc, the [`Method`] variant, the file and its stepper type.
/// Makes [`Method`] (with `name` and `order` from each file's `NAME` and `ORDER`) and
/// `Chosen`, the stepper an [`Integrator`] holds, dispatched statically.
macro_rules! methods {
    ($($(#[$doc:meta])* $v:ident => $file:ident :: $ty:ident,)*) => {
        /// The integration method.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum Method {
            $($(#[$doc])* $v,)*
        }

        impl Method {
            /// Short lower-case name for tables and JSON.
            pub fn name(self) -> &'static str {
                match self {
                    $(Method::$v => $file::NAME,)*
                }
            }

            /// Order of the method's solution.
            pub fn order(self) -> u32 {
                match self {
                    $(Method::$v => $file::ORDER,)*
                }
            }
        }

        /// The stepper of the chosen method (made once, by [`Chosen::new`]).
        #[derive(Debug, Clone)]
        enum Chosen<const N: usize> {
            $($v($file::$ty<N>),)*
        }

        impl<const N: usize> Chosen<N> {
            fn new(method: Method) -> Self {
                match method {
                    $(Method::$v => Chosen::$v(Default::default()),)*
                }
            }
        }

        impl<const N: usize> Stepper<N> for Chosen<N> {
            #[inline(always)]
            fn step<S: OdeSystem<N> + ?Sized>(
                &mut self,
                sys: &S,
                at: At<'_, N>,
                control: StepControl,
                mem: &mut Memory<N>,
                stats: &mut Stats,
            ) -> Result<(), OdeError> {
                match self {
                    $(Chosen::$v(s) => s.step(sys, at, control, mem, stats),)*
                }
            }
        }

        impl<const N: usize> Default for Chosen<N> {
            fn default() -> Self {
                Chosen::new(Method::Dopri5)
            }
        }
    };
}

methods! {
    /// Explicit Euler, order 1, one evaluation per step.
    Euler => euler::Euler,
    /// Classical Runge-Kutta, order 4, four evaluations per step.
    Rk4 => rk4::Rk4,
    /// Dormand-Prince 5(4), order 5 with an embedded order-4 error estimate, six new
    /// evaluations per step (first-same-as-last).
    Dopri5 => dopri5::Dopri5,
    /// Dormand-Prince 8(5,3), order 8 with a blended fifth/third-order error estimate,
    /// eleven new evaluations per step (first-same-as-last), three more for a step whose
    /// interior is evaluated (the order-7 interpolant).
    Dop853 => dop853::Dop853,
    /// The linearly implicit Rosenbrock 2(3) pair of Shampine & Reichelt (MATLAB's
    /// `ode23s`), order 2, L-stable, for stiff systems: two evaluations and one LU of
    /// `I - h d J` per step, plus `N + 1` evaluations for a finite-difference Jacobian.
    Rosenbrock23 => rosenbrock::Rosenbrock23,
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

    /// The range of `rtol` the methods accept (0: absolute control only, with
    /// `atol > 0`; above 1 the control would accept any step).
    pub const RTOL_RANGE: (f64, f64) = (0.0, 1.0);

    /// Is every number in range? `rtol` in [0, 1], `atol` finite and >= 0, not both
    /// zero (no scale for the error); a step (`h_s`, `h_max_s`) above zero (either may
    /// be infinite: the step is then bounded by the interval, the caller's `t_max`). NaN is out of every range. The error names the quantity, its
    /// value and its range.
    pub fn check(&self) -> Result<(), OdeError> {
        let bad = |name, value, range| Err(OdeError::InvalidControl { name, value, range });
        match *self {
            StepControl::Fixed { h_s } => {
                if h_s.is_nan() || h_s <= 0.0 {
                    return bad("h_s", h_s, "> 0 s (infinite: the model's longest step)");
                }
            }
            StepControl::Adaptive {
                rtol,
                atol,
                h_max_s,
            } => {
                let (lo, hi) = Self::RTOL_RANGE;
                if !(lo..=hi).contains(&rtol) {
                    return bad("rtol", rtol, "[0, 1]");
                }
                if atol.is_nan() || atol < 0.0 || atol.is_infinite() {
                    return bad("atol", atol, "finite and >= 0");
                }
                if rtol == 0.0 && atol == 0.0 {
                    return bad("atol", atol, "> 0 when rtol = 0");
                }
                if h_max_s.is_nan() || h_max_s <= 0.0 {
                    return bad("h_max_s", h_max_s, "> 0 s (may be infinite)");
                }
            }
        }
        Ok(())
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
    /// A number of the step-size control is NaN or outside its range.
    InvalidControl {
        /// The quantity (`rtol`, `atol`, `h_s`, `h_max_s`).
        name: &'static str,
        /// Its value.
        value: f64,
        /// The accepted range, in words.
        range: &'static str,
    },
}

impl std::fmt::Display for OdeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OdeError::StepTooSmall { t_s } => write!(f, "step size underflow at t = {t_s} s"),
            OdeError::NonFinite { t_s } => write!(f, "non-finite state at t = {t_s} s"),
            OdeError::InvalidControl { name, value, range } => {
                write!(f, "{name} = {value} is outside its range {range}")
            }
        }
    }
}

#[cfg(test)]
mod tests;
