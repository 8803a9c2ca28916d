//! Dormand-Prince 8(5,3) (Dormand & Prince 1980; Hairer, Norsett & Wanner, `DOP853`):
//! twelve stages of order 8, an error estimate that blends an embedded fifth-order and
//! a third-order formula, and a seventh-order continuous extension (`contd8`) that
//! needs three more stages. Those three are evaluated only when the step's interior is
//! asked for (an event bracketed inside it, a trace sample), so a step without an event
//! costs twelve evaluations (eleven with first-same-as-last).
//!
//! The tableau is in `dop853_tableau.rs`, the continuous extension in `dop853_dense.rs`
//! (so that `step.rs`, which holds the extension, imports no stepper).

// Index loops run over several arrays of the same length at once (y, k_j, out).
#![allow(clippy::needless_range_loop)]

use super::common::Tol;
use super::dop853_dense::Lazy;
use super::dop853_tableau::{row, Stages, A, C, E3, E5};
use super::pair::Pair;
use super::step::{Interp, Step};
use super::stepper::{At, Memory};
use super::{OdeSystem, Stats};

/// Short name for tables and JSON.
pub(super) const NAME: &str = "dop853";
/// Order of the solution.
pub(super) const ORDER: u32 = 8;

/// Dormand-Prince 8(5,3). Its stages are written straight into the kept step's
/// interpolant (a trial returns only its end state, so nothing large is moved per trial).
#[derive(Debug, Clone, Default)]
pub(super) struct Dop853<const N: usize>;

impl<const N: usize> Pair<N> for Dop853<N> {
    const ORDER: u32 = ORDER;
    const FAC_MIN: f64 = 1.0 / 3.0;
    const FAC_MAX: f64 = 6.0;

    /// `e^(-1/8)` as three square roots (a fifth of the cost of powf).
    fn root(e: f64) -> f64 {
        1.0 / e.sqrt().sqrt().sqrt() // formula: e^(-1/8)
    }

    fn trial<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        at: &At<'_, N>,
        h: f64,
        tol: Tol,
        mem: &mut Memory<N>,
        stats: &mut Stats,
    ) -> ([f64; N], f64) {
        let (y1, e) = attempt(sys, at.t, at.y, &at.f0, h, tol, stages(&mut mem.last));
        stats.rhs_evals += 11;
        (y1, e)
    }

    /// Evaluates the end derivative now: the next step's first stage.
    fn accept<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        at: &At<'_, N>,
        (t1, y1): (f64, [f64; N]),
        mem: &mut Memory<N>,
        stats: &mut Stats,
    ) {
        let f1 = sys.rhs(t1, &y1); // formula: f(t + h, y1), first stage of the next step
        stats.rhs_evals += 1;
        stages(&mut mem.last)[12] = f1;
        mem.finish((at.t, at.y), (t1, y1), f1, None)
    }
}

/// The stage buffer inside the kept step (made a DOP853 step, its continuous extension
/// forgotten): the trial writes its stages there.
fn stages<const N: usize>(last: &mut Step<N>) -> &mut Stages<N> {
    if !matches!(last.interp, Interp::Dop853(_)) {
        last.interp = Interp::Dop853(Lazy::default());
    }
    match &mut last.interp {
        Interp::Dop853(lazy) => lazy.stages_for_new_step(),
        _ => unreachable!("made a DOP853 step just above"),
    }
}
/// One trial step of size `h` from `(t, y)` with `k1 = f(t, y)`: fills the stages
/// `k[0..12]`, returns the eighth-order `y1` and the error norm (1 = at the tolerance).
fn attempt<S: OdeSystem<N> + ?Sized, const N: usize>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    k1: &[f64; N],
    h: f64,
    tol: Tol,
    k: &mut Stages<N>,
) -> ([f64; N], f64) {
    k[0] = *k1;
    // One line per stage (not a loop over s): with the row a constant, its terms and
    // the component loop unroll into one pass that keeps the sum in registers.
    macro_rules! stage {
        ($($s:literal)*) => {$(
            k[$s] = sys.rhs(t + C[$s] * h, &row(y, h, k, A[$s], S::ARGS)); // formula: k_s = f(t + c_s h, y + h sum a_sj k_j)
        )*};
    }
    stage!(1 2 3 4 5 6 7 8 9 10 11);
    let y1 = row(y, h, k, A[12], N); // formula: y1 = y + h sum_j b_j k_j
                                     // formula: Hairer's DOP853 norm: err = |h| E5 / sqrt(N (E5 + 0.01 E3)), E_p = sum_i (sum_j e_pj k_ji / sc_i)^2
                                     // The differences summed stage by stage over all components at once (the inner loop
                                     // runs along a stage vector, so it vectorises), each component's sum in the same order.
    let (mut d5, mut d3) = ([0.0; N], [0.0; N]);
    for (&(j5, w5), &(j3, w3)) in E5.iter().zip(E3.iter()) {
        for i in 0..N {
            d5[i] += w5 * k[j5][i]; // formula: sum_j e5_j k_ji
            d3[i] += w3 * k[j3][i]; // formula: sum_j e3_j k_ji
        }
    }
    let (mut e5, mut e3) = (0.0, 0.0);
    for i in 0..N {
        let inv_sc = 1.0 / tol.scale(y[i], y1[i]); // one division, two uses
        let (r5, r3) = (d5[i] * inv_sc, d3[i] * inv_sc);
        e5 += r5 * r5;
        e3 += r3 * r3;
    }
    let deno = e5 + 0.01 * e3;
    let err = if deno > 0.0 {
        h.abs() * e5 / (N as f64 * deno).sqrt()
    } else {
        0.0
    };
    (y1, err)
}
