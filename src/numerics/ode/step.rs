//! One accepted step and its interpolant (dense output), which event location searches.

// Index loops run over several arrays of the same length at once (y0, y1, f0, f1, r).
#![allow(clippy::needless_range_loop)]

use super::{dop853_dense, OdeSystem};

/// The interpolant of one step.
#[derive(Debug, Clone)]
pub(super) enum Interp<const N: usize> {
    /// Straight line between the ends.
    Linear,
    /// Cubic Hermite from the end values and end derivatives (`f0`, `f1`).
    Hermite { f0: [f64; N], f1: [f64; N] },
    /// Dormand-Prince continuous extension: `r[0..4]` of Hairer's `contd5`.
    Dopri { r: [[f64; N]; 4] },
    /// DOP853's stages; its continuous extension is built on first use.
    Dop853(dop853_dense::Lazy<N>),
}

/// One accepted step `t0 -> t1` with its dense output.
#[derive(Debug, Clone)]
pub struct Step<const N: usize> {
    /// Start time (s).
    pub t0: f64,
    /// End time (s).
    pub t1: f64,
    /// State at `t0`.
    pub y0: [f64; N],
    /// State at `t1`.
    pub y1: [f64; N],
    /// The derivative `f(t0, y0)`.
    pub f0: [f64; N],
    /// The derivative `f(t1, y1)` when the method computed it (every method but Euler:
    /// it is the next step's first stage).
    pub f1: Option<[f64; N]>,
    pub(super) interp: Interp<N>,
}

impl<const N: usize> Step<N> {
    /// The interpolated state at `t` in `[t0, t1]` (exact at the ends). `sys` is the
    /// system the step was taken on: DOP853 evaluates it three more times, once per
    /// step, the first time the step's interior is asked for.
    pub(crate) fn eval<S: OdeSystem<N> + ?Sized>(&self, sys: &S, t: f64) -> [f64; N] {
        self.eval_first(sys, t, N)
    }

    /// [`Step::eval`] for a reader of the first `args` components only (a model's
    /// guards, say): DOP853's interpolant skips the others, which keep `y0`'s values
    /// inside the step; the other interpolants, cheap already, give all.
    #[inline(always)]
    pub(crate) fn eval_first<S: OdeSystem<N> + ?Sized>(
        &self,
        sys: &S,
        t: f64,
        args: usize,
    ) -> [f64; N] {
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
            Interp::Dop853(lazy) => {
                return lazy.eval(sys, (self.t0, self.t1, &self.y0, &self.y1), s, args)
            }
        }
        out
    }

    /// Right-hand-side evaluations spent on this step's interpolant after it was
    /// accepted (3 once DOP853's continuous extension is built, else 0).
    pub(crate) fn dense_evals(&self) -> u64 {
        match &self.interp {
            Interp::Dop853(lazy) if lazy.built() => 3,
            _ => 0,
        }
    }
}
