//! The linearly implicit Rosenbrock 2(3) pair of Shampine & Reichelt (1997, MATLAB's
//! `ode23s`; its order-2 formula is Wolfbrandt's modified Rosenbrock method), for stiff
//! systems such as soft (penalty) contact.
//!
//! With `J = df/dy` and `T = df/dt` at the step's start, `d = 1/(2 + sqrt 2)`,
//! `e32 = 6 + sqrt 2` and `W = I - h d J`:
//!
//! ```text
//! F0 = f(t, y)
//! k1 = W^-1 (F0 + h d T)
//! F1 = f(t + h/2, y + h/2 k1)
//! k2 = W^-1 (F1 - k1) + k1
//! y1 = y + h k2                                        (order 2, L-stable)
//! F2 = f(t + h, y1)
//! k3 = W^-1 (F2 - e32 (k2 - F1) - 2 (k1 - F0) + h d T)
//! err = h/6 (k1 - 2 k2 + k3)                           (its local error, order 3)
//! ```
//!
//! Only linear systems with the one matrix `W` are solved (nalgebra's LU, once per
//! step size): no Newton iteration, which is what makes the method *linearly*
//! implicit. The formula is a W-method: it keeps order 2 with an approximate `J`, so a
//! finite-difference Jacobian is enough. `F2` is the next step's `F0`
//! (first-same-as-last) and the dense output is the cubic Hermite of `(y, F0, y1, F2)`.
//! Work per step: 2 evaluations, plus `N + 1` for a finite-difference `J` and `T`.

// Index loops run over several arrays of the same length at once.
#![allow(clippy::needless_range_loop)]

use super::common::{finite, initial_step, place_step, Tol};
use super::dopri5::error_norm;
use super::step::Interp;
use super::stepper::{At, Memory, Stepper};
use super::{OdeError, OdeSystem, Stats, StepControl};
use nalgebra::{DMatrix, DVector};
use std::f64::consts::SQRT_2;

/// `d = 1 / (2 + sqrt 2)`: the diagonal of the method (L-stability).
const D: f64 = 1.0 / (2.0 + SQRT_2);
/// `e32 = 6 + sqrt 2`.
const E32: f64 = 6.0 + SQRT_2;

/// The Jacobian `J = df/dy` (supplied by the system, or forward differences with
/// increments `sqrt(eps) max(|y_j|, 1e-3)`, the floor for components near zero) and
/// `T = df/dt` (forward difference in `t`), with the evaluations spent.
#[allow(clippy::type_complexity)]
fn jacobian<S: OdeSystem<N> + ?Sized, const N: usize>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    f0: &[f64; N],
) -> (DMatrix<f64>, DVector<f64>, u64) {
    let sq = f64::EPSILON.sqrt();
    let mut evals = 0;
    let j = match sys.jacobian(t, y) {
        Some(j) => DMatrix::<f64>::from_fn(N, N, |r, c| j[r][c]),
        None => {
            let mut m = DMatrix::<f64>::zeros(N, N);
            for c in 0..N {
                let dy = sq * y[c].abs().max(1e-3);
                let mut yp = *y;
                yp[c] += dy;
                let fp = sys.rhs(t, &yp);
                for r in 0..N {
                    m[(r, c)] = (fp[r] - f0[r]) / dy; // formula: J_rc = (f_r(y + dy e_c) - f_r(y)) / dy
                }
            }
            evals += N as u64;
            m
        }
    };
    let dt = sq * t.abs().max(1e-3);
    let ft = sys.rhs(t + dt, y);
    evals += 1;
    let tv = DVector::<f64>::from_fn(N, |r, _| (ft[r] - f0[r]) / dt); // formula: T = (f(t + dt, y) - f(t, y)) / dt
    (j, tv, evals)
}

/// One attempt of size `h`: `(y1, F2, err)`, or `None` when `W` is singular or a stage
/// is not finite.
#[allow(clippy::type_complexity)]
fn attempt<S: OdeSystem<N> + ?Sized, const N: usize>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    f0: &[f64; N],
    (j, tv): (&DMatrix<f64>, &DVector<f64>),
    h: f64,
) -> Option<([f64; N], [f64; N], [f64; N])> {
    let w = DMatrix::<f64>::identity(N, N) - j * (h * D); // formula: W = I - h d J
    let lu = w.lu();
    let f0v = DVector::<f64>::from_column_slice(f0);
    let k1 = lu.solve(&(&f0v + tv * (h * D)))?; // formula: k1 = W^-1 (F0 + h d T)
    let mut ys = *y;
    for i in 0..N {
        ys[i] += 0.5 * h * k1[i]; // formula: y + h/2 k1
    }
    let f1 = DVector::<f64>::from_column_slice(&sys.rhs(t + 0.5 * h, &ys));
    let k2 = lu.solve(&(&f1 - &k1))? + &k1; // formula: k2 = W^-1 (F1 - k1) + k1
    let mut y1 = *y;
    for i in 0..N {
        y1[i] += h * k2[i]; // formula: y1 = y + h k2
    }
    let f2a = sys.rhs(t + h, &y1);
    let f2 = DVector::<f64>::from_column_slice(&f2a);
    // formula: k3 = W^-1 (F2 - e32 (k2 - F1) - 2 (k1 - F0) + h d T)
    let k3 = lu.solve(&(f2 - (&k2 - &f1) * E32 - (&k1 - &f0v) * 2.0 + tv * (h * D)))?;
    let mut err = [0.0; N];
    for i in 0..N {
        err[i] = h / 6.0 * (k1[i] - 2.0 * k2[i] + k3[i]); // formula: err = h/6 (k1 - 2 k2 + k3)
    }
    (finite(&y1) && finite(&f2a) && finite(&err)).then_some((y1, f2a, err))
}

/// Short name for tables and JSON.
pub(super) const NAME: &str = "rosenbrock23";
/// Order of the solution.
pub(super) const ORDER: u32 = 2;

/// Rosenbrock 2(3), fixed or error-controlled.
#[derive(Debug, Clone, Default)]
pub(super) struct Rosenbrock23<const N: usize>;

impl<const N: usize> Stepper<N> for Rosenbrock23<N> {
    fn step<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        at: At<'_, N>,
        control: StepControl,
        mem: &mut Memory<N>,
        stats: &mut Stats,
    ) -> Result<(), OdeError> {
        let (tol, h_fixed_or_max) = match control {
            StepControl::Adaptive {
                rtol,
                atol,
                h_max_s,
            } => (Some(Tol { rtol, atol }), h_max_s),
            StepControl::Fixed { h_s } => (None, h_s.min(at.span())),
        };
        rosenbrock(sys, &at, tol, h_fixed_or_max, (mem, stats))
    }
}

/// One accepted Rosenbrock step from `at`: a fixed step of `h_fixed` (when `tol` is
/// `None`) or an error-controlled one (error per step below `tol` in the RMS norm,
/// steps at most `h_max`), never beyond `at.t_max`.
fn rosenbrock<S: OdeSystem<N> + ?Sized, const N: usize>(
    sys: &S,
    at: &At<'_, N>,
    tol: Option<Tol>,
    h_fixed_or_max: f64,
    (mem, stats): (&mut Memory<N>, &mut Stats),
) -> Result<(), OdeError> {
    let (t, y, f0, span) = (at.t, at.y, at.f0, at.span());
    let (j, tv, evals) = jacobian(sys, t, y, &f0);
    stats.rhs_evals += evals;
    let mut h = match (tol, mem.h_next) {
        (None, _) => h_fixed_or_max,
        (Some(_), Some(h)) => h.min(h_fixed_or_max),
        (Some(tol), None) => initial_step(sys, t, y, &f0, tol, ORDER, stats).min(h_fixed_or_max),
    };
    loop {
        let (h_placed, t1, last) = place_step(t, span, h)?;
        h = h_placed;
        let trial = attempt(sys, t, y, &f0, (&j, &tv), h);
        stats.rhs_evals += 2;
        let e = match (&trial, tol) {
            (Some((y1, _, err)), Some(tol)) => error_norm(y, y1, err, tol),
            (Some(_), None) => 0.0,
            (None, _) => f64::INFINITY,
        };
        if let (Some((y1, f2, _)), true) = (trial, e <= 1.0) {
            if tol.is_some() && !last {
                // formula: h_new = h min(5, max(0.2, 0.8 e^(-1/3))) (local error O(h^3))
                let fac = if e == 0.0 {
                    5.0
                } else {
                    (0.8 * e.powf(-1.0 / 3.0)).clamp(0.2, 5.0)
                };
                mem.h_next = Some((h * fac).min(h_fixed_or_max));
            }
            stats.accepted += 1;
            mem.finish((t, y), (t1, y1), f2, Some(Interp::Hermite { f0, f1: f2 }));
            return Ok(());
        }
        if tol.is_none() {
            return Err(OdeError::NonFinite { t_s: t });
        }
        stats.rejected += 1;
        let fac = if e.is_finite() {
            (0.8 * e.powf(-1.0 / 3.0)).clamp(0.1, 0.9)
        } else {
            0.1
        };
        h *= fac;
        mem.h_next = Some(h);
    }
}

#[cfg(test)]
mod tests {
    use crate::numerics::ode::{Integrator, Method, OdeError, StepControl};

    /// Van der Pol (mu = 1, not stiff) with a time-dependent forcing: smooth.
    fn forced_vdp(t: f64, y: &[f64; 2]) -> [f64; 2] {
        [y[1], (1.0 - y[0] * y[0]) * y[1] - y[0] + 0.5 * t.cos()]
    }

    fn run(method: Method, control: StepControl, t1: f64) -> [f64; 2] {
        run_counted(method, control, t1).0
    }

    fn run_counted(method: Method, control: StepControl, t1: f64) -> ([f64; 2], u64) {
        let mut integ = Integrator::new(method, control);
        let y = integ.integrate(&forced_vdp, 0.0, [2.0, 0.0], t1, |_| {});
        (y.unwrap(), integ.stats.accepted)
    }

    #[test]
    fn step_halving_shows_order_two() {
        // Reference: DOP853 at 1e-13 (its error ~1e-12, far below the errors compared).
        let want = run(Method::Dop853, StepControl::tol(1e-13, 1e-13), 2.0);
        let err = |h: f64| {
            let y = run(Method::Rosenbrock23, StepControl::Fixed { h_s: h }, 2.0);
            (y[0] - want[0]).hypot(y[1] - want[1])
        };
        let e: Vec<f64> = [0.02, 0.01, 0.005].iter().map(|&h| err(h)).collect();
        // Order 2: each halving divides the error by 4 (observed order log2 of the
        // ratio); +-0.15 allows the O(h) change of the next error term at these steps.
        for w in e.windows(2) {
            let order = (w[0] / w[1]).log2();
            assert!((order - 2.0).abs() < 0.15, "order {order}, errors {e:?}");
        }
    }

    #[test]
    fn adaptive_steps_meet_the_tolerance_on_a_smooth_problem() {
        let want = run(Method::Dop853, StepControl::tol(1e-13, 1e-13), 5.0);
        let (got, steps) = run_counted(Method::Rosenbrock23, StepControl::tol(1e-8, 1e-8), 5.0);
        // Error per step controlled to 1e-8 (RMS, scaled by 1 + |y| <= 3): the global
        // error is at most the sum of the local ones carried by the flow, which on this
        // attracting limit cycle does not amplify them: steps x 3e-8. The estimate is
        // of order 3 for an order-2 solution, so it is an honest bound of the local error.
        let e = (got[0] - want[0]).hypot(got[1] - want[1]);
        assert!(e < steps as f64 * 3e-8, "{e} after {steps} steps");
        assert!(
            e > 1e-9,
            "an order-2 method cannot be this accurate at 1e-8: {e}"
        );
    }

    #[test]
    fn a_stiff_linear_problem_is_stable_where_the_explicit_pair_explodes() {
        // y' = -lambda (y - cos t) - sin t, exact y = cos t, lambda = 1e6: h lambda = 1e5.
        // Rosenbrock 2(3) is L-stable: the stiff part is damped at any step; DP5's
        // stability interval ends near h lambda = 3.3, so it blows up.
        let lambda = 1e6;
        let f = move |t: f64, y: &[f64; 1]| [-lambda * (y[0] - t.cos()) - t.sin()];
        let h = 0.1;
        let mut ros = Integrator::new(Method::Rosenbrock23, StepControl::Fixed { h_s: h });
        let y = ros.integrate(&f, 0.0, [1.0], 5.0, |_| {}).unwrap();
        // In the stiff limit h lambda -> infinity the step from y = cos t gives
        // k1 = -sin t, k2 = k1 - h cos t / (8 d) (the half-step stage lands h^2/8 cos t
        // off the slow manifold and W^-1 ~ -1/(h d J) maps it back), so
        // y1 - cos(t + h) = (1/2 - 1/(8 d)) h^2 cos t = 0.0732 h^2 cos t: order 2 locally
        // and no accumulation (the stiff error is damped at once, R(inf) = 0). At
        // t = 5, h = 0.1: 2.08e-4. The bound 20 % covers the O(h^3) and O(1/(h lambda))
        // terms left out.
        let want = (0.5 - 1.0 / (8.0 * super::D)) * h * h * 5f64.cos();
        let err = y[0] - 5f64.cos();
        assert!((err - want).abs() < 0.2 * want.abs(), "{err} vs {want}");
        let mut dp = Integrator::new(Method::Dopri5, StepControl::Fixed { h_s: 0.1 });
        let r = dp.integrate(&f, 0.0, [1.0], 5.0, |_| {});
        assert!(matches!(r, Err(OdeError::NonFinite { .. })), "{r:?}");
        // Adaptive: the step is set by accuracy alone. With the stiff-limit local error
        // c h^2 (c <= 0.0732 |cos t| from above, the estimate of the same order) held
        // below ~1e-6, h ~ 4e-3 and ~1300 steps (measured 2218); any explicit method
        // needs h lambda below its stability bound (~3.3 for DP5): 1.5e6 steps. The
        // bound 1e4 separates the two by two orders of magnitude.
        let mut ros = Integrator::new(Method::Rosenbrock23, StepControl::tol(1e-6, 1e-6));
        let y = ros.integrate(&f, 0.0, [1.0], 5.0, |_| {}).unwrap();
        assert!((y[0] - 5f64.cos()).abs() < 1e-5, "{}", y[0]);
        assert!(ros.stats.accepted < 10_000, "{:?}", ros.stats);
    }
}
