//! Dormand-Prince 8(5,3) (Dormand & Prince 1980; Hairer, Norsett & Wanner, `DOP853`):
//! twelve stages of order 8, an error estimate that blends an embedded fifth-order and
//! a third-order formula, and a seventh-order continuous extension (`contd8`) that
//! needs three more stages. Those three are evaluated only when the step's interior is
//! asked for (an event bracketed inside it, a trace sample), so a step without an event
//! costs twelve evaluations (eleven with first-same-as-last).
//!
//! Coefficients: Hairer's `dop853.f`, as tabulated in SciPy's
//! `scipy/integrate/_ivp/dop853_coefficients.py` (same values, shortest round-trip
//! decimal form here). The tests check the order (8 from step halving), the
//! interpolant's order (7) and the row sums `sum_j a_ij = c_i`.

// Index loops run over several arrays of the same length at once (y, k_j, out).
#![allow(clippy::needless_range_loop)]

use super::common::Tol;
use super::pair::Pair;
use super::step::{Interp, Step};
use super::stepper::{At, Memory};
use super::{OdeSystem, Stats};
use std::cell::OnceCell;

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

/// Nodes `c_i` of the twelve stages and the three dense-output stages (index 0 is `c_1 = 0`).
const C: [f64; 16] = [
    0.0,
    0.05260015195876773,
    0.0789002279381516,
    0.1183503419072274,
    0.2816496580927726,
    0.3333333333333333,
    0.25,
    0.3076923076923077,
    0.6512820512820513,
    0.6,
    0.8571428571428571,
    1.0,
    1.0,
    0.1,
    0.2,
    0.7777777777777778,
];

/// Rows of the Runge-Kutta matrix `a_ij`, nonzero entries only, as `(j, a_ij)` with
/// 0-based stage indices: row `i` builds the argument of stage `i` (rows 12 to 15: the
/// solution weights `b_j` and the three extra stages of the dense output).
const A: [&[(usize, f64)]; 16] = [
    &[],
    &[(0, 0.05260015195876773)],
    &[(0, 0.0197250569845379), (1, 0.0591751709536137)],
    &[(0, 0.02958758547680685), (2, 0.08876275643042054)],
    &[
        (0, 0.2413651341592667),
        (2, -0.8845494793282861),
        (3, 0.924834003261792),
    ],
    &[
        (0, 0.037037037037037035),
        (3, 0.17082860872947386),
        (4, 0.12546768756682242),
    ],
    &[
        (0, 0.037109375),
        (3, 0.17025221101954405),
        (4, 0.06021653898045596),
        (5, -0.017578125),
    ],
    &[
        (0, 0.03709200011850479),
        (3, 0.17038392571223998),
        (4, 0.10726203044637328),
        (5, -0.015319437748624402),
        (6, 0.008273789163814023),
    ],
    &[
        (0, 0.6241109587160757),
        (3, -3.3608926294469414),
        (4, -0.868219346841726),
        (5, 27.59209969944671),
        (6, 20.154067550477894),
        (7, -43.48988418106996),
    ],
    &[
        (0, 0.47766253643826434),
        (3, -2.4881146199716677),
        (4, -0.590290826836843),
        (5, 21.230051448181193),
        (6, 15.279233632882423),
        (7, -33.28821096898486),
        (8, -0.020331201708508627),
    ],
    &[
        (0, -0.9371424300859873),
        (3, 5.186372428844064),
        (4, 1.0914373489967295),
        (5, -8.149787010746927),
        (6, -18.52006565999696),
        (7, 22.739487099350505),
        (8, 2.4936055526796523),
        (9, -3.0467644718982196),
    ],
    &[
        (0, 2.273310147516538),
        (3, -10.53449546673725),
        (4, -2.0008720582248625),
        (5, -17.9589318631188),
        (6, 27.94888452941996),
        (7, -2.8589982771350235),
        (8, -8.87285693353063),
        (9, 12.360567175794303),
        (10, 0.6433927460157636),
    ],
    &[
        (0, 0.054293734116568765),
        (5, 4.450312892752409),
        (6, 1.8915178993145003),
        (7, -5.801203960010585),
        (8, 0.3111643669578199),
        (9, -0.1521609496625161),
        (10, 0.20136540080403034),
        (11, 0.04471061572777259),
    ],
    &[
        (0, 0.056167502283047954),
        (6, 0.25350021021662483),
        (7, -0.2462390374708025),
        (8, -0.12419142326381637),
        (9, 0.15329179827876568),
        (10, 0.00820105229563469),
        (11, 0.007567897660545699),
        (12, -0.008298),
    ],
    &[
        (0, 0.03183464816350214),
        (5, 0.028300909672366776),
        (6, 0.053541988307438566),
        (7, -0.05492374857139099),
        (10, -0.00010834732869724932),
        (11, 0.0003825710908356584),
        (12, -0.00034046500868740456),
        (13, 0.1413124436746325),
    ],
    &[
        (0, -0.42889630158379194),
        (5, -4.697621415361164),
        (6, 7.683421196062599),
        (7, 4.06898981839711),
        (8, 0.3567271874552811),
        (12, -0.0013990241651590145),
        (13, 2.9475147891527724),
        (14, -9.15095847217987),
    ],
];

/// Error weights of the fifth-order estimate (`e5_j`, nonzero only).
const E5: [(usize, f64); 8] = [
    (0, 0.01312004499419488),
    (5, -1.2251564463762044),
    (6, -0.4957589496572502),
    (7, 1.6643771824549864),
    (8, -0.35032884874997366),
    (9, 0.3341791187130175),
    (10, 0.08192320648511571),
    (11, -0.022355307863886294),
];
/// Error weights of the third-order estimate (`e3_j = b_j - bhh_j`, nonzero only).
const E3: [(usize, f64); 8] = [
    (0, -0.18980075407240762),
    (5, 4.450312892752409),
    (6, 1.8915178993145003),
    (7, -5.801203960010585),
    (8, -0.4226823213237919),
    (9, -0.1521609496625161),
    (10, 0.20136540080403034),
    (11, 0.02265179219836082),
];

/// Dense-output weights (rows 4 to 7 of Hairer's `contd8`), nonzero only.
const D: [[(usize, f64); 12]; 4] = [
    [
        (0, -8.428938276109013),
        (5, 0.5667149535193777),
        (6, -3.0689499459498917),
        (7, 2.38466765651207),
        (8, 2.117034582445028),
        (9, -0.871391583777973),
        (10, 2.2404374302607883),
        (11, 0.6315787787694688),
        (12, -0.08899033645133331),
        (13, 18.148505520854727),
        (14, -9.194632392478356),
        (15, -4.436036387594894),
    ],
    [
        (0, 10.427508642579134),
        (5, 242.28349177525817),
        (6, 165.20045171727028),
        (7, -374.5467547226902),
        (8, -22.113666853125306),
        (9, 7.733432668472264),
        (10, -30.674084731089398),
        (11, -9.332130526430229),
        (12, 15.697238121770845),
        (13, -31.139403219565178),
        (14, -9.35292435884448),
        (15, 35.81684148639408),
    ],
    [
        (0, 19.985053242002433),
        (5, -387.0373087493518),
        (6, -189.17813819516758),
        (7, 527.8081592054236),
        (8, -11.57390253995963),
        (9, 6.8812326946963),
        (10, -1.0006050966910838),
        (11, 0.7777137798053443),
        (12, -2.778205752353508),
        (13, -60.19669523126412),
        (14, 84.32040550667716),
        (15, 11.99229113618279),
    ],
    [
        (0, -25.69393346270375),
        (5, -154.18974869023643),
        (6, -231.5293791760455),
        (7, 357.6391179106141),
        (8, 93.40532418362432),
        (9, -37.45832313645163),
        (10, 104.0996495089623),
        (11, 29.8402934266605),
        (12, -43.53345659001114),
        (13, 96.32455395918828),
        (14, -39.17726167561544),
        (15, -149.72683625798564),
    ],
];

/// Row `i` of the tableau applied: `y + h sum_j a_ij k_j` over the nonzero `a_ij`, in
/// the first `args` components (a stage argument needs only those the right-hand side
/// reads, [`OdeSystem::ARGS`]; the solution row needs all `N`).
#[inline(always)]
fn row<const N: usize>(
    y: &[f64; N],
    h: f64,
    k: &[[f64; N]],
    a: &[(usize, f64)],
    args: usize,
) -> [f64; N] {
    let mut out = *y;
    for &(j, aij) in a {
        let c = h * aij;
        for i in 0..args.min(N) {
            out[i] += c * k[j][i]; // formula: y + h sum_j a_ij k_j
        }
    }
    out
}

/// The stages of one step: `k[0..12]` are `k_1 .. k_12`; `k[12]` is reserved for
/// `f(t + h, y1)` (filled in when the step is accepted).
pub(super) type Stages<const N: usize> = [[f64; N]; 13];

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

    /// The state at fraction `s = (t - t0)/h` of `step`, whose stages these are.
    /// Only the first `args` components are interpolated; the rest are `y0`'s.
    #[inline(always)]
    pub(super) fn eval<S: OdeSystem<N> + ?Sized>(
        &self,
        sys: &S,
        step: &Step<N>,
        s: f64,
        args: usize,
    ) -> [f64; N] {
        let args = args.min(N);
        let r = self.dense.get_or_init(|| self.build(sys, step));
        let y0 = &step.y0;
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
    fn build<S: OdeSystem<N> + ?Sized>(&self, sys: &S, step: &Step<N>) -> [[f64; N]; 7] {
        let (t0, h, y0, y1) = (step.t0, step.t1 - step.t0, &step.y0, &step.y1);
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn row_sums_equal_the_nodes() {
        // Consistency of the tableau: sum_j a_ij = c_i for every stage (1e-14: the
        // coefficients are 30-digit decimals rounded to doubles; rows 8 to 12 carry
        // terms of size 40, so cancellation leaves a few 1e-15).
        for s in 1..16 {
            if s == 12 {
                continue; // the weights b_j sum to 1, checked below
            }
            let sum: f64 = A[s].iter().map(|&(_, a)| a).sum();
            assert!((sum - C[s]).abs() < 1e-14, "row {s}: {sum} vs {}", C[s]);
        }
        let b: f64 = A[12].iter().map(|&(_, a)| a).sum();
        assert!((b - 1.0).abs() < 1e-14, "{b}");
        // both error formulas are differences of consistent weights: they sum to 0
        let e5: f64 = E5.iter().map(|&(_, a)| a).sum();
        let e3: f64 = E3.iter().map(|&(_, a)| a).sum();
        assert!(e5.abs() < 1e-14 && e3.abs() < 1e-14, "{e5} {e3}");
    }
}
