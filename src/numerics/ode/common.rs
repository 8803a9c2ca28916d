//! What the methods share: stage arithmetic, the error scale, and the starting step.

// Index loops run over several arrays of the same length at once.
#![allow(clippy::needless_range_loop)]

use super::{OdeError, OdeSystem, Stats};

/// `y + h * sum(c_j k_j)` for up to six stages.
#[inline]
pub(super) fn comb<const N: usize>(y: &[f64; N], h: f64, terms: &[(f64, &[f64; N])]) -> [f64; N] {
    stage_arg(y, h, terms, N)
}

/// A stage argument: `y + h * sum(c_j k_j)` in the first `args` components (those the
/// right-hand side reads, [`OdeSystem::ARGS`]); the rest keep `y`'s values.
#[inline]
pub(super) fn stage_arg<const N: usize>(
    y: &[f64; N],
    h: f64,
    terms: &[(f64, &[f64; N])],
    args: usize,
) -> [f64; N] {
    let mut out = *y;
    for (c, k) in terms {
        for i in 0..args.min(N) {
            out[i] += h * c * k[i];
        }
    }
    out
}

pub(super) fn finite<const N: usize>(y: &[f64; N]) -> bool {
    y.iter().all(|v| v.is_finite())
}

/// Tolerances of the error control.
#[derive(Debug, Clone, Copy)]
pub(super) struct Tol {
    pub(super) rtol: f64,
    pub(super) atol: f64,
}

impl Tol {
    /// For fixed steps, whose error estimate is not used.
    pub(super) const UNUSED: Tol = Tol {
        rtol: 1.0,
        atol: 1.0,
    };

    /// The error scale of a component that goes from `a` to `b` in a step.
    #[inline]
    pub(super) fn scale(self, a: f64, b: f64) -> f64 {
        self.atol + self.rtol * a.abs().max(b.abs()) // formula: sc = atol + rtol max(|y0|, |y1|)
    }
}

/// Where a trial step of length `h` from `t` towards `t + span` ends: `(h, t1, last)`.
/// A step within 1e-12 of the span goes onto its end exactly (`last`). A final step may
/// be as short as it needs to be (a few ulps before a breakpoint); any other step this
/// short means the error control has collapsed.
pub(super) fn place_step(t: f64, span: f64, h: f64) -> Result<(f64, f64, bool), OdeError> {
    let last = h >= span * (1.0 - 1e-12);
    if last {
        return Ok((span, t + span, true));
    }
    if h <= 16.0 * f64::EPSILON * t.abs().max(1e-300) {
        return Err(OdeError::StepTooSmall { t_s: t });
    }
    Ok((h, t + h, false))
}

/// Hairer's starting-step heuristic (`hinit`) for a method of order `order`.
pub(super) fn initial_step<S: OdeSystem<N> + ?Sized, const N: usize>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    f0: &[f64; N],
    tol: Tol,
    order: u32,
    stats: &mut Stats,
) -> f64 {
    let norm = |v: &[f64; N]| {
        let mut s = 0.0;
        for i in 0..N {
            let sc = tol.scale(y[i], 0.0);
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
        (0.01 / d1.max(d2)).powf(1.0 / f64::from(order)) // formula: (0.01 / max(d1, d2))^(1/p)
    };
    (100.0 * h0).min(h1)
}
