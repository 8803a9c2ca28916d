//! Explicit Euler, classical Runge-Kutta 4 and Dormand-Prince 5(4) for `y' = f(t, y)`.
//!
//! One [`Integrator`] serves all three methods. Every accepted step comes back as a
//! [`Step`] carrying an interpolant over the step (linear for Euler, cubic Hermite for
//! RK4, the fourth-order continuous extension of Hairer, Norsett & Wanner for DP5),
//! which is what event location searches.
//!
//! State vectors are fixed-size arrays `[f64; N]`: no allocation in the stepping loop.

// Index loops run over several arrays of the same length at once (y, k1..k7, r); they read
// like the formulas they implement.
#![allow(clippy::needless_range_loop)]

/// A first-order system `y' = f(t, y)` of dimension `N`.
pub trait OdeSystem<const N: usize> {
    /// The right-hand side `f(t, y)`.
    fn rhs(&self, t: f64, y: &[f64; N]) -> [f64; N];
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
}

impl Method {
    /// Short lower-case name for tables and JSON.
    pub fn name(self) -> &'static str {
        match self {
            Method::Euler => "euler",
            Method::Rk4 => "rk4",
            Method::Dopri5 => "dopri5",
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
    /// Error-controlled steps (Dopri5 only): per component the local error estimate is
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

/// The interpolant of one step.
#[derive(Debug, Clone, Copy)]
enum Interp<const N: usize> {
    /// Straight line between the ends.
    Linear,
    /// Cubic Hermite from the end values and end derivatives (`f0`, `f1`).
    Hermite { f0: [f64; N], f1: [f64; N] },
    /// Dormand-Prince continuous extension: `r[0..4]` of Hairer's `contd5`.
    Dopri { r: [[f64; N]; 4] },
}

/// One accepted step `t0 -> t1` with its dense output.
#[derive(Debug, Clone, Copy)]
pub struct Step<const N: usize> {
    /// Start time (s).
    pub t0: f64,
    /// End time (s).
    pub t1: f64,
    /// State at `t0`.
    pub y0: [f64; N],
    /// State at `t1`.
    pub y1: [f64; N],
    interp: Interp<N>,
}

impl<const N: usize> Step<N> {
    /// The interpolated state at `t` in `[t0, t1]` (exact at the ends).
    pub fn eval(&self, t: f64) -> [f64; N] {
        let h = self.t1 - self.t0;
        if h == 0.0 || t == self.t0 {
            return self.y0;
        }
        if t == self.t1 {
            return self.y1;
        }
        let s = (t - self.t0) / h; // formula: theta = (t - t0)/h
        let mut out = [0.0; N];
        match &self.interp {
            Interp::Linear => {
                for i in 0..N {
                    out[i] = self.y0[i] + s * (self.y1[i] - self.y0[i]); // formula: linear
                }
            }
            Interp::Hermite { f0, f1 } => {
                // formula: cubic Hermite basis h00, h10, h01, h11
                let (s2, s3) = (s * s, s * s * s);
                let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
                let h10 = s3 - 2.0 * s2 + s;
                let h01 = -2.0 * s3 + 3.0 * s2;
                let h11 = s3 - s2;
                for i in 0..N {
                    out[i] =
                        h00 * self.y0[i] + h10 * h * f0[i] + h01 * self.y1[i] + h11 * h * f1[i];
                }
            }
            Interp::Dopri { r } => {
                let s1 = 1.0 - s;
                for i in 0..N {
                    // formula: y0 + th (r1 + th1 (r2 + th (r3 + th1 r4)))   (Hairer contd5)
                    out[i] =
                        self.y0[i] + s * (r[0][i] + s1 * (r[1][i] + s * (r[2][i] + s1 * r[3][i])));
                }
            }
        }
        out
    }
}

// Dormand-Prince 5(4) tableau.
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
// Error coefficients: fifth-order minus embedded fourth-order weights.
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// Dense-output coefficients (Hairer's contd5).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// `y + h * sum(c_j k_j)` for up to six stages.
#[inline]
fn comb<const N: usize>(y: &[f64; N], h: f64, terms: &[(f64, &[f64; N])]) -> [f64; N] {
    let mut out = *y;
    for (c, k) in terms {
        for i in 0..N {
            out[i] += h * c * k[i];
        }
    }
    out
}

fn finite<const N: usize>(y: &[f64; N]) -> bool {
    y.iter().all(|v| v.is_finite())
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
}

impl<const N: usize> Integrator<N> {
    /// A new integrator. Adaptive control is only meaningful for [`Method::Dopri5`];
    /// Euler and RK4 with `Adaptive` use `h_max_s` (or 1e-3 s) as a fixed step.
    pub fn new(method: Method, control: StepControl) -> Self {
        Integrator {
            method,
            control,
            stats: Stats::default(),
            h_next: None,
            fsal: None,
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

    /// Takes one accepted step from `(t, y)` towards `t_max` (never beyond it).
    pub fn step<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        y: &[f64; N],
        t_max: f64,
    ) -> Result<Step<N>, OdeError> {
        let f0 = self.deriv(sys, t, y);
        if !finite(&f0) || !finite(y) {
            return Err(OdeError::NonFinite { t_s: t });
        }
        let span = t_max - t;
        match (self.method, self.control) {
            (
                Method::Dopri5,
                StepControl::Adaptive {
                    rtol,
                    atol,
                    h_max_s,
                },
            ) => self.dopri_adaptive(sys, t, y, f0, span, rtol, atol, h_max_s),
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
                let step = match method {
                    Method::Euler => {
                        let y1 = comb(y, h, &[(1.0, &f0)]); // formula: y1 = y0 + h f(t0, y0)
                        Step {
                            t0: t,
                            t1,
                            y0: *y,
                            y1,
                            interp: Interp::Linear,
                        }
                    }
                    Method::Rk4 => {
                        let k2 = sys.rhs(t + 0.5 * h, &comb(y, h, &[(0.5, &f0)]));
                        let k3 = sys.rhs(t + 0.5 * h, &comb(y, h, &[(0.5, &k2)]));
                        let k4 = sys.rhs(t + h, &comb(y, h, &[(1.0, &k3)]));
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
                        self.fsal = Some((t1, y1, f1));
                        Step {
                            t0: t,
                            t1,
                            y0: *y,
                            y1,
                            interp: Interp::Hermite { f0, f1 },
                        }
                    }
                    Method::Dopri5 => {
                        let (y1, k7, r, _) = dopri_stages(sys, t, y, &f0, h);
                        self.stats.rhs_evals += 6;
                        self.fsal = Some((t1, y1, k7));
                        Step {
                            t0: t,
                            t1,
                            y0: *y,
                            y1,
                            interp: Interp::Dopri { r },
                        }
                    }
                };
                if !finite(&step.y1) {
                    return Err(OdeError::NonFinite { t_s: t1 });
                }
                self.stats.accepted += 1;
                Ok(step)
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn dopri_adaptive<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        t: f64,
        y: &[f64; N],
        f0: [f64; N],
        span: f64,
        rtol: f64,
        atol: f64,
        h_max: f64,
    ) -> Result<Step<N>, OdeError> {
        let mut h = match self.h_next {
            Some(h) => h,
            None => initial_step(sys, t, y, &f0, rtol, atol, &mut self.stats),
        }
        .min(h_max);
        loop {
            let last = h >= span * (1.0 - 1e-12);
            if last {
                h = span;
            }
            let t1 = if last { t + span } else { t + h };
            // A final step onto t_max may be as short as it needs to be (a few ulps
            // before a breakpoint); any other step this short means the error control
            // has collapsed.
            if !last && h <= 16.0 * f64::EPSILON * t.abs().max(1e-300) {
                return Err(OdeError::StepTooSmall { t_s: t });
            }
            let (y1, k7, r, err) = dopri_stages(sys, t, y, &f0, h);
            self.stats.rhs_evals += 6;
            // formula: err = sqrt(mean((e_i / (atol + rtol max(|y0_i|, |y1_i|)))^2))
            let mut sum = 0.0;
            for i in 0..N {
                let sc = atol + rtol * y[i].abs().max(y1[i].abs());
                sum += (err[i] / sc) * (err[i] / sc);
            }
            let e = (sum / N as f64).sqrt();
            if e.is_finite() && e <= 1.0 {
                // formula: h_new = h min(5, max(0.2, 0.9 e^(-1/5)))
                let fac = if e == 0.0 {
                    5.0
                } else {
                    (0.9 * e.powf(-0.2)).clamp(0.2, 5.0)
                };
                if !last {
                    self.h_next = Some((h * fac).min(h_max));
                } else if self.h_next.is_none() {
                    self.h_next = Some(h);
                }
                self.stats.accepted += 1;
                self.fsal = Some((t1, y1, k7));
                return Ok(Step {
                    t0: t,
                    t1,
                    y0: *y,
                    y1,
                    interp: Interp::Dopri { r },
                });
            }
            self.stats.rejected += 1;
            let fac = if e.is_finite() {
                (0.9 * e.powf(-0.2)).clamp(0.1, 0.9)
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
            on_step(&s);
            t = s.t1;
            y = s.y1;
        }
        Ok(y)
    }
}

/// The seven Dormand-Prince stages: returns `(y1, k7, dense coefficients, error)`.
#[allow(clippy::type_complexity)]
fn dopri_stages<S: OdeSystem<N> + ?Sized, const N: usize>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    k1: &[f64; N],
    h: f64,
) -> ([f64; N], [f64; N], [[f64; N]; 4], [f64; N]) {
    let k2 = sys.rhs(t + C2 * h, &comb(y, h, &[(A21, k1)]));
    let k3 = sys.rhs(t + C3 * h, &comb(y, h, &[(A31, k1), (A32, &k2)]));
    let k4 = sys.rhs(
        t + C4 * h,
        &comb(y, h, &[(A41, k1), (A42, &k2), (A43, &k3)]),
    );
    let k5 = sys.rhs(
        t + C5 * h,
        &comb(y, h, &[(A51, k1), (A52, &k2), (A53, &k3), (A54, &k4)]),
    );
    let k6 = sys.rhs(
        t + h,
        &comb(
            y,
            h,
            &[(A61, k1), (A62, &k2), (A63, &k3), (A64, &k4), (A65, &k5)],
        ),
    );
    // formula: y1 = y0 + h (35/384 k1 + 500/1113 k3 + 125/192 k4 - 2187/6784 k5 + 11/84 k6)
    let y1 = comb(
        y,
        h,
        &[(A71, k1), (A73, &k3), (A74, &k4), (A75, &k5), (A76, &k6)],
    );
    let k7 = sys.rhs(t + h, &y1);
    let mut err = [0.0; N];
    let mut r = [[0.0; N]; 4];
    for i in 0..N {
        // formula: e = h (e1 k1 + e3 k3 + e4 k4 + e5 k5 + e6 k6 + e7 k7)
        err[i] = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
        let dy = y1[i] - y[i];
        let bspl = h * k1[i] - dy;
        r[0][i] = dy;
        r[1][i] = bspl;
        r[2][i] = dy - h * k7[i] - bspl;
        r[3][i] = h * (D1 * k1[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] + D6 * k6[i] + D7 * k7[i]);
    }
    (y1, k7, r, err)
}

/// Hairer's starting-step heuristic (`hinit`, order 5).
fn initial_step<S: OdeSystem<N> + ?Sized, const N: usize>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    f0: &[f64; N],
    rtol: f64,
    atol: f64,
    stats: &mut Stats,
) -> f64 {
    let norm = |v: &[f64; N]| {
        let mut s = 0.0;
        for i in 0..N {
            let sc = atol + rtol * y[i].abs();
            s += (v[i] / sc) * (v[i] / sc);
        }
        (s / N as f64).sqrt()
    };
    let (d0, d1) = (norm(y), norm(f0));
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    let y1 = comb(y, h0, &[(1.0, f0)]);
    let f1 = sys.rhs(t + h0, &y1);
    stats.rhs_evals += 1;
    let mut diff = [0.0; N];
    for i in 0..N {
        diff[i] = f1[i] - f0[i];
    }
    let d2 = norm(&diff) / h0;
    let h1 = if d1.max(d2) <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / d1.max(d2)).powf(0.2)
    };
    (100.0 * h0).min(h1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decay(_t: f64, y: &[f64; 1]) -> [f64; 1] {
        [-y[0]]
    }

    fn oscillator(_t: f64, y: &[f64; 2]) -> [f64; 2] {
        [y[1], -y[0]]
    }

    /// Global error at t = 1 of y' = -y, y(0) = 1 with fixed step h.
    fn decay_error(method: Method, h: f64) -> f64 {
        let mut integ = Integrator::new(method, StepControl::Fixed { h_s: h });
        let y = integ.integrate(&decay, 0.0, [1.0], 1.0, |_| {}).unwrap();
        (y[0] - (-1.0f64).exp()).abs()
    }

    /// Observed order from a step-halving study: log2(e(h)/e(h/2)).
    fn observed_order(method: Method, h: f64) -> f64 {
        (decay_error(method, h) / decay_error(method, h / 2.0)).log2()
    }

    #[test]
    fn convergence_orders_from_step_halving() {
        // Step sizes are in the asymptotic range (error well above round-off), so the
        // observed order is within 0.1 of the theoretical one.
        let euler = observed_order(Method::Euler, 1.0 / 64.0);
        let rk4 = observed_order(Method::Rk4, 1.0 / 16.0);
        let dp5 = observed_order(Method::Dopri5, 1.0 / 8.0);
        assert!((euler - 1.0).abs() < 0.1, "Euler order {euler}");
        assert!((rk4 - 4.0).abs() < 0.1, "RK4 order {rk4}");
        assert!((dp5 - 5.0).abs() < 0.15, "DP5 order {dp5}");
    }

    #[test]
    fn adaptive_dopri_meets_tolerance_on_decay_and_oscillator() {
        // Global error of a stable problem stays within a small multiple of the tolerance.
        for &tol in &[1e-6, 1e-9, 1e-12] {
            let mut integ = Integrator::new(Method::Dopri5, StepControl::tol(tol, tol));
            let y = integ.integrate(&decay, 0.0, [1.0], 5.0, |_| {}).unwrap();
            assert!(
                (y[0] - (-5.0f64).exp()).abs() < 10.0 * tol,
                "decay tol {tol}"
            );
            let mut integ = Integrator::new(Method::Dopri5, StepControl::tol(tol, tol));
            let t_end = 2.0 * std::f64::consts::PI * 3.0;
            let y = integ
                .integrate(&oscillator, 0.0, [1.0, 0.0], t_end, |_| {})
                .unwrap();
            // three periods: error grows linearly with time, hence 100 x tol
            assert!(
                (y[0] - 1.0).abs() < 100.0 * tol && y[1].abs() < 100.0 * tol,
                "osc tol {tol}: {y:?}"
            );
        }
    }

    #[test]
    fn dense_output_is_fourth_order_accurate_inside_steps() {
        let mut integ = Integrator::new(Method::Dopri5, StepControl::tol(1e-10, 1e-10));
        let mut worst: f64 = 0.0;
        integ
            .integrate(&oscillator, 0.0, [1.0, 0.0], 10.0, |s| {
                for k in 1..10 {
                    let t = s.t0 + (s.t1 - s.t0) * k as f64 / 10.0;
                    let y = s.eval(t);
                    worst = worst
                        .max((y[0] - t.cos()).abs())
                        .max((y[1] + t.sin()).abs());
                }
            })
            .unwrap();
        // The interpolant's error is of the order of the local tolerance.
        assert!(worst < 1e-8, "dense output error {worst}");
    }

    #[test]
    fn hermite_and_linear_interpolants_match_ends() {
        for m in [Method::Euler, Method::Rk4, Method::Dopri5] {
            let mut integ = Integrator::new(m, StepControl::Fixed { h_s: 0.1 });
            let s = integ.step(&oscillator, 0.0, &[1.0, 0.0], 1.0).unwrap();
            assert_eq!(s.eval(s.t0), s.y0);
            assert_eq!(s.eval(s.t1), s.y1);
        }
    }

    #[test]
    fn rhs_evaluations_are_counted_per_method() {
        for (m, per_step) in [(Method::Euler, 1u64), (Method::Rk4, 4), (Method::Dopri5, 6)] {
            let mut integ = Integrator::new(m, StepControl::Fixed { h_s: 0.1 });
            integ.integrate(&decay, 0.0, [1.0], 1.0, |_| {}).unwrap();
            assert_eq!(integ.stats.accepted, 10, "{m:?}");
            // first step evaluates f0 once more for methods that reuse the end value
            let expected = match m {
                Method::Euler => 10,
                _ => 10 * per_step + 1,
            };
            assert_eq!(integ.stats.rhs_evals, expected, "{m:?}");
        }
    }

    #[test]
    fn non_finite_state_is_an_error_not_a_panic() {
        let blow = |_t: f64, y: &[f64; 1]| [y[0] * y[0]];
        let mut integ = Integrator::new(Method::Euler, StepControl::Fixed { h_s: 0.5 });
        let r = integ.integrate(&blow, 0.0, [1e200], 10.0, |_| {});
        assert!(matches!(r, Err(OdeError::NonFinite { .. })));
    }
}
