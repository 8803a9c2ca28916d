//! DOP853's seventh-order continuous extension (Hairer's `contd8`): the stages of an
//! accepted step are kept, and three more evaluations build the interpolant the first
//! time the step's interior is asked for.

// Index loops run over several arrays of the same length at once (y0, r_d, out).
#![allow(clippy::needless_range_loop)]

use super::dop853_tableau::{row, Stages, A, C, D};
use super::OdeSystem;
use std::cell::OnceCell;

/// The ends of a step: `(t0, t1, y0, y1)`.
pub(super) type Ends<'a, const N: usize> = (f64, f64, &'a [f64; N], &'a [f64; N]);

/// The stages of an accepted step, kept for the continuous extension, which is built
/// on first use.
#[derive(Debug, Clone)]
pub(super) struct Lazy<const N: usize> {
    k: Stages<N>,
    dense: OnceCell<[[f64; N]; 7]>,
}

impl<const N: usize> Default for Lazy<N> {
    fn default() -> Self {
        Lazy {
            k: [[0.0; N]; 13],
            dense: OnceCell::new(),
        }
    }
}

impl<const N: usize> Lazy<N> {
    /// The stage buffer, for a new step to fill (`k[12] = f(t1, y1)` once accepted);
    /// the previous step's continuous extension is dropped.
    pub(super) fn stages_for_new_step(&mut self) -> &mut Stages<N> {
        self.dense.take();
        &mut self.k
    }

    /// Has the continuous extension been built (three more evaluations)?
    pub(super) fn built(&self) -> bool {
        self.dense.get().is_some()
    }

    /// The state at fraction `s = (t - t0)/h` of the step with these `ends`, whose
    /// stages these are.
    /// Only the first `args` components are interpolated; the rest are `y0`'s.
    #[inline(always)]
    pub(super) fn eval<S: OdeSystem<N> + ?Sized>(
        &self,
        sys: &S,
        ends: Ends<'_, N>,
        s: f64,
        args: usize,
    ) -> [f64; N] {
        let args = args.min(N);
        let r = self.dense.get_or_init(|| self.build(sys, ends));
        let y0 = ends.2;
        let s1 = 1.0 - s;
        // formula: y0 + s (r1 + s1 (r2 + s (r3 + s1 (r4 + s (r5 + s1 (r6 + s r7))))))   (Hairer contd8)
        // One Horner level per pass over the components (passes vectorise; a chain of
        // seven dependent operations per component in one loop did not).
        let mut v = r[6];
        for (d, w) in [(5, s), (4, s1), (3, s), (2, s1), (1, s), (0, s1)] {
            for i in 0..args {
                v[i] = r[d][i] + w * v[i];
            }
        }
        let mut out = *y0;
        for i in 0..args {
            out[i] += s * v[i];
        }
        out
    }

    /// Hairer's `contd8` coefficients: three extra stages, then seven vectors.
    fn build<S: OdeSystem<N> + ?Sized>(&self, sys: &S, ends: Ends<'_, N>) -> [[f64; N]; 7] {
        let (t0, t1, y0, y1) = ends;
        let h = t1 - t0;
        let mut k = [[0.0; N]; 16];
        k[..13].copy_from_slice(&self.k);
        for s in 13..16 {
            k[s] = sys.rhs(t0 + C[s] * h, &row(y0, h, &k, A[s], S::ARGS)); // formula: extra stages 14 to 16
        }
        let mut r = [[0.0; N]; 7];
        for i in 0..N {
            let dy = y1[i] - y0[i];
            let bspl = h * k[0][i] - dy;
            r[0][i] = dy; // formula: r1 = y1 - y0
            r[1][i] = bspl; // formula: r2 = h f0 - (y1 - y0)
            r[2][i] = dy - h * k[12][i] - bspl; // formula: r3 = (y1 - y0) - h f1 - r2
        }
        // (a pass over the components per stage: these vectorise)
        for (d, row) in D.iter().enumerate() {
            let out = &mut r[3 + d];
            for &(j, w) in row {
                let c = h * w;
                for i in 0..N {
                    out[i] += c * k[j][i]; // formula: r4..r7 = h sum_j d_j k_j
                }
            }
        }
        r
    }
}
