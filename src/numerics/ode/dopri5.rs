//! Dormand-Prince 5(4) (Dormand & Prince 1980; Hairer, Norsett & Wanner, `DOPRI5`):
//! seven stages, the last one first-same-as-last, an embedded fourth-order error
//! estimate and Hairer's fourth-order continuous extension (`contd5`).

// Index loops run over several arrays of the same length at once (y, k1..k7, r).
#![allow(clippy::needless_range_loop)]

use super::common::{comb, stage_arg, Tol};
use super::pair::Pair;
use super::step::Interp;
use super::stepper::{At, Memory};
use super::{OdeSystem, Stats};

/// Short name for tables and JSON.
pub(super) const NAME: &str = "dopri5";
/// Order of the solution.
pub(super) const ORDER: u32 = 5;

/// Dormand-Prince 5(4) with its memory: the last trial step, before acceptance (its
/// seventh stage and its continuous extension's coefficients).
#[derive(Debug, Clone)]
pub(super) struct Dopri5<const N: usize> {
    trial: ([f64; N], [[f64; N]; 4]),
}

impl<const N: usize> Default for Dopri5<N> {
    fn default() -> Self {
        Dopri5 {
            trial: ([0.0; N], [[0.0; N]; 4]),
        }
    }
}

impl<const N: usize> Pair<N> for Dopri5<N> {
    const ORDER: u32 = ORDER;
    const FAC_MIN: f64 = 0.2;
    const FAC_MAX: f64 = 5.0;

    fn root(e: f64) -> f64 {
        e.powf(-0.2) // formula: e^(-1/5)
    }

    fn trial<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        at: &At<'_, N>,
        h: f64,
        tol: Tol,
        _mem: &mut Memory<N>,
        stats: &mut Stats,
    ) -> ([f64; N], f64) {
        let (y1, k7, r, err) = stages(sys, at.t, at.y, &at.f0, h);
        stats.rhs_evals += 6;
        self.trial = (k7, r);
        (y1, error_norm(at.y, &y1, &err, tol))
    }

    /// The end derivative is the seventh stage: it becomes the next step's first.
    fn accept<S: OdeSystem<N> + ?Sized>(
        &mut self,
        _sys: &S,
        at: &At<'_, N>,
        end: (f64, [f64; N]),
        mem: &mut Memory<N>,
        _stats: &mut Stats,
    ) {
        let (k7, r) = self.trial;
        mem.finish((at.t, at.y), end, k7, Some(Interp::Dopri { r }));
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

/// The seven stages of one step of size `h` from `(t, y)` with `k1 = f(t, y)`: returns `(y1, k7, dense coefficients, error)`.
#[allow(clippy::type_complexity)]
pub(super) fn stages<S: OdeSystem<N> + ?Sized, const N: usize>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    k1: &[f64; N],
    h: f64,
) -> ([f64; N], [f64; N], [[f64; N]; 4], [f64; N]) {
    let k2 = sys.rhs(t + C2 * h, &stage_arg(y, h, &[(A21, k1)], S::ARGS));
    let k3 = sys.rhs(
        t + C3 * h,
        &stage_arg(y, h, &[(A31, k1), (A32, &k2)], S::ARGS),
    );
    let k4 = sys.rhs(
        t + C4 * h,
        &stage_arg(y, h, &[(A41, k1), (A42, &k2), (A43, &k3)], S::ARGS),
    );
    let k5 = sys.rhs(
        t + C5 * h,
        &stage_arg(
            y,
            h,
            &[(A51, k1), (A52, &k2), (A53, &k3), (A54, &k4)],
            S::ARGS,
        ),
    );
    let k6 = sys.rhs(
        t + h,
        &stage_arg(
            y,
            h,
            &[(A61, k1), (A62, &k2), (A63, &k3), (A64, &k4), (A65, &k5)],
            S::ARGS,
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

/// The error norm of DOPRI5: the RMS over components of `err_i / (atol + rtol max(|y0_i|, |y1_i|))`.
pub(super) fn error_norm<const N: usize>(
    y0: &[f64; N],
    y1: &[f64; N],
    err: &[f64; N],
    tol: Tol,
) -> f64 {
    // formula: err = sqrt(mean((e_i / (atol + rtol max(|y0_i|, |y1_i|)))^2))
    let mut sum = 0.0;
    for i in 0..N {
        let sc = tol.scale(y0[i], y1[i]);
        sum += (err[i] / sc) * (err[i] / sc);
    }
    (sum / N as f64).sqrt()
}
