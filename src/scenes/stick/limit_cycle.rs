//! One scene's gait as a limit cycle: settle on the stroboscopic map, the fixed point
//! by Newton, its Floquet multipliers by two methods (central differences of the map on
//! a ladder of steps; the variational flows and saltation matrices), and a displaced
//! start followed by simulation.

use super::poincare::{
    distance, jacobian, moduli, multipliers, newton, scales, settle, static_start, strobe,
    Difference, Gait, Point,
};
use super::saltation::monodromy;
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::stick::{StickModel, StickParams};
use nalgebra::{Complex, DMatrix, DVector};

/// Tolerance of the limit-cycle runs (relative and absolute): every run of the map is
/// this accurate, so a difference quotient with step `h` carries `RTOL / h` of noise.
pub const RTOL: f64 = 1e-12;
/// Steps of the central-difference ladder (units of the scales): `h, h/2, h/4` give the
/// observed order; the smallest step, [`H_FINE`], gives the multipliers compared.
pub const LADDER: [f64; 3] = [2e-4, 1e-4, 5e-5];
/// Step of the finite-difference multipliers that are compared with the saltation ones.
pub const H_FINE: f64 = 1e-5;
/// Drive periods of the transient before the orbit is tested for a period.
pub const TRANSIENT: usize = 400;
/// Largest period tried.
pub const MAX_PERIOD: usize = 8;
/// An orbit closes when its points repeat to this distance (units of the scales). A
/// classification threshold, not a claim's tolerance: it only has to lie between the
/// map's evaluation error and the distance of distinct orbit points. Measured on the two
/// scenes (`Analysis::run_error`, the map at [`RTOL`] against [`RTOL`]/100): 2.0e-13
/// (authors') and 7.2e-15 (self-locking), 50 and 1,400 times below it; the authors'
/// unsettled orbit keeps its points at least 6.7e-3 apart (periods 1 to 8 after
/// [`TRANSIENT`]), 7e5 times above it; the self-locking orbit repeats to 2.5e-15 (it
/// approaches its fixed point by a factor 0.89 per period: 1.1e-6 after 100 periods,
/// 6.8e-12 after 200, so 400 leave no slow transient near the threshold).
pub const CLOSE_TOL: f64 = 1e-8;
/// Newton stops below this residual (units of the scales): a stopping rule, safe when it
/// lies above the residual the map can resolve, twice its evaluation error (the computed
/// P(s) off by `run_error` at s and at the true fixed point): 4.1e-13 (authors') and
/// 1.4e-14 (self-locking), 25 and 700 times below it. Newton converges quadratically
/// above that floor, so its last step lands far below the rule (measured residuals
/// 2.0e-12 and 1.0e-14). The claim `limit-cycle-fixed-point` checks the rule's margin
/// over the floor in the run (`cycle_claims.rs`).
pub const NEWTON_TOL: f64 = 1e-11;
/// Displacement of the start of the decay run from the fixed point (units of the scales).
pub const DISPLACEMENT: f64 = 1e-5;
/// Periods of the decay run.
pub const DECAY_PERIODS: usize = 30;

/// The options of every limit-cycle run: DOP853 at [`RTOL`].
pub fn options() -> Options {
    Options {
        method: Method::Dop853,
        control: StepControl::tol(RTOL, RTOL),
        ..Options::default()
    }
}

/// Everything the limit-cycle claims and results read about one scene.
#[derive(Debug, Clone)]
pub struct Analysis {
    /// What the run from the static start settled into.
    pub gait: Gait,
    /// The fixed point of `P^n` found by Newton (from the settled orbit, or from the
    /// last point of an orbit that did not settle), its period `n` and residual.
    pub fixed: Option<(Point, usize, f64)>,
    /// Multipliers from central differences at each step of [`LADDER`], then at
    /// [`H_FINE`], and from forward differences at the ladder's steps.
    pub central: Vec<Vec<(f64, f64)>>,
    /// See `central`.
    pub forward: Vec<Vec<(f64, f64)>>,
    /// Multipliers from the variational flows and saltation matrices, or why not.
    pub saltation: Result<Vec<(f64, f64)>, String>,
    /// The monodromy matrix of the saltation method (section coordinates).
    pub monodromy: Option<DMatrix<f64>>,
    /// The same without the saltation term (resets' Jacobians only).
    pub flows_only: Result<Vec<(f64, f64)>, String>,
    /// Rate per period at which a displaced start approaches (< 1) or leaves (> 1) the
    /// fixed point along the leading multiplier, measured by simulation.
    pub decay_rate: Option<f64>,
    /// Global error of one run of `P^n` at [`RTOL`] (units of the scales), measured
    /// against the same run at `RTOL / 100`.
    pub run_error: f64,
    /// Second derivative scale of the map, `2 |J_forward - J_central| / h` at the
    /// ladder's first step (units of the scales): the size of the nonlinear remainder.
    pub curvature: f64,
}

/// The analysis of `p` ([`TRANSIENT`] periods from the static start).
pub fn analyse(p: &StickParams) -> Analysis {
    let model = StickModel::new(*p);
    let opts = options();
    let gait = match static_start(&model) {
        Some(x0) => settle(&model, &opts, &x0, (TRANSIENT, MAX_PERIOD, CLOSE_TOL)),
        None => Gait::Stopped("invalid"),
    };
    let fixed = find_fixed(&model, &opts, &gait);
    let mut a = Analysis {
        gait,
        fixed: fixed.clone(),
        central: Vec::new(),
        forward: Vec::new(),
        saltation: Err("no fixed point".into()),
        flows_only: Err("no fixed point".into()),
        monodromy: None,
        decay_rate: None,
        curvature: f64::NAN,
        run_error: f64::NAN,
    };
    let Some((x, n, _)) = fixed else { return a };
    let fine = Options {
        control: StepControl::tol(RTOL / 100.0, RTOL / 100.0),
        ..opts
    };
    if let (Ok(p1), Ok(p2)) = (strobe(&model, &opts, &x, n), strobe(&model, &fine, &x, n)) {
        a.run_error = distance(&model, &p1, &p2); // formula: error at rtol ~ |P_rtol - P_(rtol/100)|
    }
    let jac = |h: f64, how| jacobian(&model, &opts, &x, n, h, how);
    let mut js = Vec::new();
    for &h in LADDER.iter().chain([&H_FINE]) {
        js.push(jac(h, Difference::Central));
    }
    a.central = js.iter().flatten().map(multipliers).collect();
    let fwd: Vec<_> = LADDER
        .iter()
        .map(|&h| jac(h, Difference::Forward))
        .collect();
    a.forward = fwd.iter().flatten().map(multipliers).collect();
    if let (Some(jf), Some(jc)) = (&fwd[0], &js[0]) {
        a.curvature = 2.0 * (jf - jc).abs().max() / LADDER[0]; // formula: J_f - J_c = (h/2) P'' + O(h^2)
    }
    let m = monodromy(&model, &opts, &x, n, true);
    a.saltation = m.as_ref().map(multipliers).map_err(|e| e.clone());
    a.monodromy = m.ok();
    a.flows_only = monodromy(&model, &opts, &x, n, false).map(|m| multipliers(&m));
    if let Some(j) = js.last().cloned().flatten() {
        a.decay_rate = decay_rate(&model, &opts, (&x, n), &j);
    }
    a
}

/// Newton from the settled orbit's point with its period, or (an orbit that did not
/// settle) from the last point of the orbit with periods 1 and 2 in turn.
fn find_fixed(model: &StickModel, opts: &Options, gait: &Gait) -> Option<(Point, usize, f64)> {
    let settings = (H_FINE, NEWTON_TOL, 20);
    match gait {
        Gait::Periodic(n, x) => newton(model, opts, x, *n, settings).map(|(p, r)| (p, *n, r)),
        Gait::NotSettled(x) => {
            (1..=2).find_map(|n| newton(model, opts, x, n, settings).map(|(p, r)| (p, n, r)))
        }
        _ => None,
    }
}

/// The rate per period of a start displaced by [`DISPLACEMENT`] along the real part of
/// the leading eigenvector of `j`, measured in the eigenbasis of `j` after
/// [`DECAY_PERIODS`] periods of the map: `(|w_K| / |w_0|)^(1/K)` with `w` the leading
/// eigen-coordinate (it moves as `lambda^k w_0` while the motion is linear).
fn decay_rate(
    model: &StickModel,
    opts: &Options,
    (x, n): (&Point, usize),
    j: &DMatrix<f64>,
) -> Option<f64> {
    let sc = DVector::from_vec(scales(model, x.mode));
    let scaled = j.map_with_location(|r, c, v| v * sc[c] / sc[r]); // formula: D^-1 J D
    let eig = scaled.clone().complex_eigenvalues();
    let lead = (0..eig.len()).max_by(|&a, &b| eig[a].norm().total_cmp(&eig[b].norm()))?;
    let v = null_vector(&scaled.map(|e| Complex::new(e, 0.0)), eig[lead])?;
    let vr = v.map(|z| z.re);
    let dir = &vr / vr.norm();
    let mut y = x.clone();
    for (k, s) in y.s.iter_mut().enumerate() {
        *s += DISPLACEMENT * dir[k] * sc[k];
    }
    let coord = |p: &Point| -> Option<f64> {
        if p.mode != x.mode {
            return None; // the displaced run left the gait's mode: no linear picture
        }
        let d =
            DVector::from_iterator(p.s.len(), (0..p.s.len()).map(|k| (p.s[k] - x.s[k]) / sc[k]));
        let w = invert_basis(&scaled)?
            .row(lead)
            .transpose()
            .dot(&d.map(|e| Complex::new(e, 0.0)));
        Some(w.norm())
    };
    let w0 = coord(&y)?;
    for _ in 0..DECAY_PERIODS {
        y = strobe(model, opts, &y, n).ok()?;
    }
    Some((coord(&y)? / w0).powf(1.0 / DECAY_PERIODS as f64)) // formula: |w_K/w_0|^(1/K) = |lambda|
}

/// A unit vector spanning the null space of `a - lambda I` (the eigenvector of `lambda`).
fn null_vector(a: &DMatrix<Complex<f64>>, lambda: Complex<f64>) -> Option<DVector<Complex<f64>>> {
    let d = a.nrows();
    let m = a - DMatrix::<Complex<f64>>::identity(d, d) * lambda;
    let svd = m.svd(false, true);
    let vt = svd.v_t?;
    let k = (0..d).min_by(|&p, &q| svd.singular_values[p].total_cmp(&svd.singular_values[q]))?;
    Some(vt.row(k).adjoint())
}

/// The condition number of the eigenvector matrix of `a` (columns of unit length): the
/// factor by which a perturbation of `a` can move its eigenvalues (Bauer-Fike).
pub fn eigen_condition(a: &DMatrix<f64>) -> f64 {
    let ac = a.map(|e| Complex::new(e, 0.0));
    let eig = a.clone().complex_eigenvalues();
    let d = a.nrows();
    let mut v = DMatrix::<Complex<f64>>::zeros(d, d);
    for (c, &l) in eig.iter().enumerate() {
        match null_vector(&ac, l) {
            Some(col) => v.set_column(c, &col),
            None => return f64::INFINITY,
        }
    }
    match v.clone().try_inverse() {
        Some(vi) => v.norm() * vi.norm(), // formula: kappa(V) = |V| |V^-1| (Frobenius)
        None => f64::INFINITY,
    }
}

/// The inverse of the eigenvector matrix of `a` (rows: the left eigenvectors, in the
/// order of `complex_eigenvalues`).
fn invert_basis(a: &DMatrix<f64>) -> Option<DMatrix<Complex<f64>>> {
    let d = a.nrows();
    let ac = a.map(|e| Complex::new(e, 0.0));
    let eig = a.clone().complex_eigenvalues();
    let mut v = DMatrix::<Complex<f64>>::zeros(d, d);
    for (c, &l) in eig.iter().enumerate() {
        v.set_column(c, &null_vector(&ac, l)?);
    }
    v.try_inverse()
}

/// Largest modulus of a set of multipliers.
pub fn spectral_radius(m: &[(f64, f64)]) -> f64 {
    moduli(m).into_iter().fold(0.0, f64::max)
}

/// The leading multiplier: largest modulus, non-negative imaginary part.
pub fn leading(m: &[(f64, f64)]) -> (f64, f64) {
    m.iter()
        .copied()
        .max_by(|x, y| {
            let (a, b) = (x.0.hypot(x.1), y.0.hypot(y.1));
            ((a * 1e9).round().total_cmp(&(b * 1e9).round())).then(x.1.total_cmp(&y.1))
        })
        .unwrap_or((f64::NAN, f64::NAN))
}

/// Largest distance between two multiplier sets sorted the same way (by modulus, then
/// the conjugate pairs matched by the sign of the imaginary part).
pub fn max_difference(a: &[(f64, f64)], b: &[(f64, f64)]) -> f64 {
    let key = |v: &[(f64, f64)]| {
        let mut v = v.to_vec();
        v.sort_by(|x, y| {
            let m = (y.0.hypot(y.1) * 1e6)
                .round()
                .total_cmp(&(x.0.hypot(x.1) * 1e6).round());
            m.then(y.1.total_cmp(&x.1))
        });
        v
    };
    let (a, b) = (key(a), key(b));
    if a.len() != b.len() {
        return f64::INFINITY;
    }
    a.iter()
        .zip(&b)
        .map(|(x, y)| (x.0 - y.0).hypot(x.1 - y.1))
        .fold(0.0, f64::max)
}
