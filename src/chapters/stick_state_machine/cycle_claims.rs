//! The claims of the section "The gait as a limit cycle". The document makes no
//! limit-cycle statement: these are the workbook's own results, each claim's statement
//! says what is checked, and the falsification tests feed in wrong variants of the
//! workbook's statements ([`Statements`]).

use super::limit_cycle::{
    eigen_condition, leading, max_difference, spectral_radius, Analysis, DECAY_PERIODS,
    DISPLACEMENT, H_FINE, LADDER, NEWTON_TOL, RTOL,
};
use crate::report::{Check, Claim};
use serde_json::json;

/// The section of the course the claims belong to (not a section of the document).
const SECTION: &str = "course: limit cycle";

pub use super::statements::{CycleStatements as Statements, WORKBOOK_CYCLE as WORKBOOK};

/// The two scenes analysed: (name, analysis).
pub type Scenes<'a> = [(&'a str, &'a Analysis); 2];

/// Every limit-cycle claim under the statements `st`.
pub fn all(st: &Statements, sc: &Scenes) -> Vec<Claim> {
    vec![
        fixed_point(sc),
        order(st, sc),
        saltation(st, sc),
        stability(st, sc),
    ]
}

fn round(x: f64) -> f64 {
    super::round(x, 4)
}

/// Newton's residual at both scenes' fixed points (a consistency check).
fn fixed_point(sc: &Scenes) -> Claim {
    let res: Vec<f64> = sc
        .iter()
        .map(|(_, a)| a.fixed.as_ref().map_or(f64::INFINITY, |f| f.2))
        .collect();
    let worst = res.iter().copied().fold(0.0, f64::max);
    // Newton's stop rule is meaningful only above the residual the map resolves, twice
    // its evaluation error (`run_error`): the margin is checked here (limit_cycle.rs).
    let floor = sc
        .iter()
        .map(|(_, a)| 2.0 * a.run_error)
        .fold(0.0, f64::max); // formula: 2 |P_rtol - P_(rtol/100)|
    let labels: Vec<String> = sc
        .iter()
        .map(|(n, a)| format!("{n}: {}", a.gait.label()))
        .collect();
    let st = format!(
        "The stroboscopic map P at plate phase 0 (state after each drive period, x_c left out) has a period-1 fixed point s* = P(s*) in both scenes, found by Newton on P(s) - s = 0 with the central-difference Jacobian; from the static start the runs settle into [{}] after 400 periods. Largest |P(s*) - s*| (units: 1 rad, ω, the plate's peak velocity), below Newton's stop rule, which must lie above twice the map's evaluation error (the runs at rtol 1e-12 against 1e-14).",
        labels.join(", ")
    );
    Claim::draft(Check::Consistency, "limit-cycle-fixed-point", SECTION, &st)
        .values(json!(0.0), json!(worst), format!("{NEWTON_TOL:e} (Newton's stop rule; the map resolves {floor:.1e})"))
        .confirmed_if(worst <= NEWTON_TOL && floor < NEWTON_TOL)
}

/// Observed order of the leading finite-difference multiplier on the ladder h, h/2,
/// h/4, and the two differences it is formed from.
fn observed_order(ladder: &[Vec<(f64, f64)>]) -> (f64, f64, f64) {
    if ladder.len() < 3 {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    let l: Vec<(f64, f64)> = ladder.iter().map(|m| leading(m)).collect();
    let d1 = (l[0].0 - l[1].0).hypot(l[0].1 - l[1].1);
    let d2 = (l[1].0 - l[2].0).hypot(l[1].1 - l[2].1);
    ((d1 / d2).log2(), d1, d2) // formula: p = log2(|l(h) - l(h/2)| / |l(h/2) - l(h/4)|)
}

/// Tolerance of the observed order: 0.1 for terms of the next order (up to 7 % of the
/// leading one at h: log2(1.07) = 0.1), plus the runs' noise: a multiplier at step h
/// carries `nu(h) = kappa e / h` (measured run error `e`, eigenvector condition number
/// `kappa`), which moves `log2(d1 / d2)` by at most `((nu0 + nu1)/d1 + (nu1 + nu2)/d2) / ln 2`.
fn order_tolerance(a: &Analysis, d1: f64, d2: f64) -> f64 {
    let kappa = a.monodromy.as_ref().map_or(f64::INFINITY, eigen_condition);
    let nu: Vec<f64> = LADDER
        .iter()
        .map(|h| kappa * a.run_error.max(f64::EPSILON) / h) // formula: nu(h) = kappa e / h
        .collect();
    0.1 + ((nu[0] + nu[1]) / d1 + (nu[1] + nu[2]) / d2) / std::f64::consts::LN_2
}

/// The central differences converge at second order (convergence).
fn order(st: &Statements, sc: &Scenes) -> Claim {
    let mut orders = Vec::new();
    let mut tols = Vec::new();
    for (_, a) in sc {
        let (p, d1, d2) = observed_order(if st.central { &a.central } else { &a.forward });
        orders.push(p);
        tols.push(order_tolerance(a, d1, d2));
    }
    let holds = orders
        .iter()
        .zip(&tols)
        .all(|(p, t)| (p - st.order).abs() <= *t);
    let what = if st.central { "central" } else { "forward" };
    let text = format!(
        "The leading Floquet multiplier (eigenvalue of the Jacobian of P of largest modulus) from {what} differences of the map converges at order {} in the step: observed order log2(|l(h) - l(h/2)| / |l(h/2) - l(h/4)|) at h = {} of each coordinate's scale, [authors, self-locking]. Tolerance per scene: 0.1 for terms of the next order (up to 7 % of the leading one at h) plus the runs' noise (measured run error times the eigenvector condition number over each step) carried into the log of the ratio. Above h = 5e-4 the authors' map is not smooth at the step's scale (a perturbed cycle switches differently) and the quotients stop converging.",
        st.order, LADDER[0]
    );
    Claim::draft(
        Check::Convergence,
        "floquet-difference-order",
        SECTION,
        &text,
    )
    .values(
        json!([st.order, st.order]),
        json!(orders.iter().map(|p| round(*p)).collect::<Vec<_>>()),
        json!(tols.iter().map(|t| super::round(*t, 2)).collect::<Vec<_>>()),
    )
    .confirmed_if(holds)
}

/// The error bound of the finite-difference multipliers at [`H_FINE`]: the truncation
/// `C h^2` with `C` from the ladder, plus the runs' noise `2 e / (2 h)` moved into
/// the eigenvalues by the eigenvector condition number (Bauer-Fike); the runs' global
/// error is the measured one (a run at rtol against one at rtol / 100).
pub fn difference_error(a: &Analysis) -> f64 {
    let (l, m) = (&a.central, &a.monodromy);
    let (Some(mono), true) = (m, l.len() >= 4) else {
        return f64::NAN;
    };
    let c = max_difference(&l[1], &l[2]) / (LADDER[1].powi(2) - LADDER[2].powi(2)); // formula: |l(h) - l(h/2)| = C (h^2 - h^2/4)
    let noise = 2.0 * a.run_error.max(f64::EPSILON) / (2.0 * H_FINE); // formula: two runs' global errors over the width 2h
    c * H_FINE * H_FINE + eigen_condition(mono) * noise
}

/// Finite differences against the variational flows and saltation matrices (second method).
fn saltation(st: &Statements, sc: &Scenes) -> Claim {
    let mut diffs = Vec::new();
    let mut tols = Vec::new();
    let mut radii = Vec::new();
    for (_, a) in sc {
        let other = if st.saltation {
            &a.saltation
        } else {
            &a.flows_only
        };
        let fd = a.central.last().cloned().unwrap_or_default();
        let d = other
            .as_ref()
            .map_or(f64::INFINITY, |m| max_difference(&fd, m));
        diffs.push(d);
        tols.push(difference_error(a));
        radii.push(
            other
                .as_ref()
                .map_or(f64::NAN, |m| round(spectral_radius(m))),
        );
    }
    let holds = diffs.iter().zip(&tols).all(|(d, t)| d <= t);
    let how = if st.saltation {
        "the product of the variational flows and the saltation matrices S = DR + (f+ - DR f-) grad(g)^T / g' over the hybrid cycle"
    } else {
        "the product of the variational flows and the resets' Jacobians DR alone (no saltation term)"
    };
    let text = format!(
        "The Floquet multipliers of both fixed points from central differences of P (step {H_FINE:e} of the scales) equal those of {how}; largest |λ| by the second method [authors, self-locking] = {radii:?}. Largest distance between matched multipliers; tolerance per scene: the truncation C h^2 (C from the step ladder) plus the global error of each run (rtol {RTOL:e}, measured against rtol / 100) over the width 2h, times the eigenvector condition number (Bauer-Fike)."
    );
    Claim::draft(Check::SecondMethod, "floquet-saltation", SECTION, &text)
        .values(
            json!([0, 0]),
            json!(diffs
                .iter()
                .map(|d| super::round(*d, 3))
                .collect::<Vec<_>>()),
            json!(tols.iter().map(|d| super::round(*d, 3)).collect::<Vec<_>>()),
        )
        .confirmed_if(holds)
}

/// A displaced start approaches (stable) or leaves (unstable) at the rate |lambda|max.
fn stability(st: &Statements, sc: &Scenes) -> Claim {
    let mut expected = Vec::new();
    let mut computed = Vec::new();
    let mut tols = Vec::new();
    let mut holds = true;
    for (_, a) in sc {
        let rho = a
            .saltation
            .as_ref()
            .map_or(f64::NAN, |m| spectral_radius(m));
        let stated = st.rate_factor * rho;
        let rate = a.decay_rate.unwrap_or(f64::NAN);
        let k = DECAY_PERIODS as i32;
        let far = DISPLACEMENT * rho.powi(k).max(1.0); // formula: largest displacement of the run
        let near = DISPLACEMENT * rho.powi(k).min(1.0); // formula: smallest one
        let tol = a.curvature * far + rho * a.run_error.max(f64::EPSILON) / near; // formula: nonlinear remainder + noise at the end
        holds &= (rate - stated).abs() <= tol && (rate < 1.0) == (stated < 1.0);
        expected.push(round(stated));
        computed.push(round(rate));
        tols.push(super::round(tol, 2));
    }
    let text = format!(
        "Stable and unstable gaits: the self-locking gait is stable (all multipliers inside the unit circle) and the authors' gait is unstable (a complex pair outside it: its orbit circles the fixed point without settling). Stated: the rate per period |λ|max x {} of the saltation method; computed: a start displaced by {DISPLACEMENT:e} along the leading eigenvector, simulated for {DECAY_PERIODS} periods, its leading eigen-coordinate's growth |w_K / w_0|^(1/K) [authors, self-locking]. Tolerance: the map's nonlinear remainder (curvature from forward vs central differences) times the largest displacement, plus the runs' noise at the smallest one.",
        st.rate_factor
    );
    Claim::draft(Check::Simulation, "gait-stability", SECTION, &text)
        .values(json!(expected), json!(computed), json!(tols))
        .confirmed_if(holds)
}
