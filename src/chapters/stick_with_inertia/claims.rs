//! The claims: pure functions of the statements and the evidence.

use super::evidence::{Drop, Evidence};
use super::rounding;
use super::statements::Statements;
use crate::report::{Check, Claim};

/// Largest relative deviation of the drops' ratios from `expected(q, alpha)`, and the
/// largest ratio of that deviation to the drop's own tolerance `tol(drop)` (at most 1
/// when every drop is within its tolerance).
fn worst(
    drops: &[Drop],
    expected: impl Fn(f64, f64) -> f64,
    tol: impl Fn(&Drop) -> f64,
) -> (f64, f64) {
    drops.iter().fold((0.0f64, 0.0f64), |(dev, ratio), d| {
        let e = expected(d.q, d.alpha);
        let x = (d.ratio - e).abs() / e.abs();
        (dev.max(x), ratio.max(x / tol(d)))
    })
}

/// The tolerance at which a set of drops is judged: the largest of their own.
fn widest(drops: &[Drop], tol: impl Fn(&Drop) -> f64) -> f64 {
    drops.iter().map(tol).fold(0.0, f64::max)
}

/// The asymptotic range of the massless-limit fit (I_P k/gamma^2): from 7.5e-6 (a rod of
/// 1e-8 kg, alpha = 3e8, the lightest the full model resolves: its speed difference
/// 1.1e-8 is 100 times the runs' rounding) to 0.75.
pub const ORDER_RANGE: (f64, f64) = (7e-6, 0.8);

/// Local orders of a ladder `(h_i, e_i)` (sorted by `h`): `ln(e_(i+1)/e_i) /
/// ln(h_(i+1)/h_i)` (1).
pub fn local_orders(pts: &[(f64, f64)]) -> Vec<f64> {
    pts.windows(2)
        .map(|w| (w[1].1 / w[0].1).ln() / (w[1].0 / w[0].0).ln()) // formula: p_i = ln(e_(i+1)/e_i)/ln(h_(i+1)/h_i)
        .collect()
}

/// Tolerance of an observed order from the run's own ladder (1): twice the spread of its
/// local orders. A least-squares slope in log-log over sorted points is a weighted mean
/// of the successive (local) slopes with positive weights, so the fitted order lies
/// within their range; their spread is the ladder's own measure of how far it is from a
/// single power (the next term of the expansion at the large end, noise at the small
/// end). The factor 2 allows a common shift of every local order from the asymptotic
/// one as large as their spread (the assumption: no larger common shift).
pub fn order_tol(local: &[f64]) -> f64 {
    let (lo, hi) = local
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &p| (a.min(p), b.max(p)));
    2.0 * (hi - lo) // formula: 2 (max p_i - min p_i)
}

/// Aitken's extrapolated limit of three successive terms (Richardson for an unknown
/// geometric rate): `d_3 - (d_3 - d_2)^2/((d_3 - d_2) - (d_2 - d_1))`.
fn aitken(d: &[f64]) -> f64 {
    let (a, b) = (d[1] - d[0], d[2] - d[1]);
    d[2] - b * b / (b - a) // formula: Aitken delta^2
}

/// All claims, in the chapter's order.
pub fn all(doc: &Statements, ev: &Evidence, impact_gain: (f64, f64, usize)) -> Vec<Claim> {
    let mut out = vec![moreau_jean(doc, ev), compliant_limit(doc, ev)];
    out.extend(impulse_ratios(doc, ev));
    out.extend(painleve(doc, ev));
    out.push(massless_limit(doc, ev));
    out.push(impacts_dissipate(doc, impact_gain));
    out
}

/// `moreau-jean`: the second method converges to the event-driven speed at order 1.
/// The observed order is the mean of the local orders over the halvings T/400 ..
/// T/3200, judged against [`order_tol`] of those local orders; the Richardson
/// extrapolation at order 1 leaves `|2 - 2^p|/(2^p - 1)` of the estimate `|v(h) -
/// v(2h)|` when the error goes as `h^p`, at most that at the local orders' extreme
/// `p = 1 ± tol`.
fn moreau_jean(doc: &Statements, ev: &Evidence) -> Claim {
    let (v_ev, mj) = &ev.moreau_jean;
    let errs: Vec<f64> = mj.iter().map(|m| (m.1 - v_ev).abs()).collect();
    let nm = errs.len();
    let mj_order = (errs[1] / errs[nm - 1]).log2() / (nm - 2) as f64; // formula: slope of log error over the halvings T/400 .. T/3200
    let pts: Vec<(f64, f64)> = mj[1..].iter().zip(&errs[1..]).map(|(m, &e)| (1.0 / m.0, e)).collect();
    let local = local_orders(&pts);
    let tol = order_tol(&local);
    let (v_h, v_2h) = (mj[nm - 1].1, mj[nm - 2].1);
    let estimate = (v_h - v_2h).abs(); // formula: first-order error estimate |v(h) - v(2h)|
    let extrapolated = 2.0 * v_h - v_2h; // formula: Richardson, order 1
    let p_far = 2f64.powf(1.0 + tol); // formula: 2^p at p = 1 + tol
    let left = (p_far - 2.0) / (p_far - 1.0); // formula: |2 - 2^p|/(2^p - 1), its larger end
    let mj_ok = (mj_order - doc.mj_order).abs() <= tol
        && (extrapolated - v_ev).abs() <= left * estimate;
    let statement = format!(
        "Moreau-Jean time-stepping (the same rod, per-step frictional contact problem with the rod's Delassus matrix) converges to the event-driven mean speed at order 1: default scene, 3 s, event-driven {v_ev:.6} m/s; steps T/200 ... T/3200 give errors {}; fitted order (computed) over T/400 ... T/3200, within twice the spread of its local orders {} (tolerance {tol:.3}); its Richardson extrapolation {extrapolated:.6} m/s lies within {left:.3} of its own error estimate {estimate:.1e} m/s of the event-driven speed (the remainder of an order-1 extrapolation at order 1 ± {tol:.3}).",
        errs.iter().map(|e| format!("{e:.2e}")).collect::<Vec<_>>().join(", "),
        local.iter().map(|p| format!("{p:.3}")).collect::<Vec<_>>().join(", ")
    );
    Claim::draft(
        Check::SecondMethod,
        "moreau-jean",
        "4, 5 (second method)",
        &statement,
    )
    .values(doc.mj_order, mj_order, tol)
    .confirmed_if(mj_ok)
}

/// `painleve-compliant-limit`: the impact without collision is the stiff compliant limit.
/// The signed relative gaps `d_K` of the compliant impulse from the rule's shrink
/// geometrically with K; Aitken's extrapolation of the last three rungs is the ladder's
/// own estimate of the limit's gap, and the change between the last two extrapolations,
/// times `rho/(1 - rho)` with `rho` the slowest observed ratio of successive differences
/// (translation invariant: a wrong statement shifts every gap, not the differences),
/// is its uncertainty (the assumption: the extrapolations converge no slower than the
/// ladder's differences).
fn compliant_limit(doc: &Statements, ev: &Evidence) -> Claim {
    let ((rigid_pn, _), soft) = &ev.compliant;
    let gaps: Vec<f64> = soft
        .iter()
        .map(|s| (s.1 - doc.iwc_scale * rigid_pn) / rigid_pn) // formula: d_K = (P_n(K) - P_n,rule)/P_n,rule
        .collect();
    let shrinking = gaps.windows(2).all(|w| w[1].abs() < w[0].abs());
    let diffs: Vec<f64> = gaps.windows(2).map(|w| w[1] - w[0]).collect();
    let rho = diffs
        .windows(2)
        .map(|w| (w[1] / w[0]).abs())
        .fold(0.0, f64::max); // formula: rho = max |Δ_(k+1)/Δ_k|
    let n = gaps.len();
    let (prev, last) = (aitken(&gaps[n - 4..n - 1]), aitken(&gaps[n - 3..]));
    let tol = (last - prev).abs() * rho / (1.0 - rho); // formula: |L_4 - L_3| rho/(1 - rho)
    let ok = shrinking && rho < 1.0 && last.abs() <= tol;
    let decades = gaps
        .windows(2)
        .map(|w| format!("{:.2}", (w[0] / w[1]).abs()))
        .collect::<Vec<_>>()
        .join(", ");
    let mu_p = crate::physics::stick_inertia::painleve::mu_painleve(0.6, 3.0);
    let statement = format!(
        "The impact-without-collision rule is the limit of a stiff compliant contact: on a uniform rod sliding at θ = 0.6 rad with μ = 1.6 > μ_P = {mu_p:.4}, the normal impulse gathered until the slip stops tends to the rule's as the stiffness grows (relative gaps {} at K = 1e5 ... 1e8 N/m, shrinking by {decades} per decade of K); Aitken's extrapolation of the last three gives a limit gap of {last:.1e}, within its own uncertainty {tol:.1e} (the change from the previous extrapolation times ρ/(1 - ρ), ρ = {rho:.3} the slowest ratio of successive differences).",
        gaps.iter().map(|d| format!("{:.1e}", d.abs())).collect::<Vec<_>>().join(", ")
    );
    Claim::draft(
        Check::SecondMethod,
        "painleve-compliant-limit",
        "4 (the Painleve rule)",
        &statement,
    )
    .values(0.0, last, tol)
    .confirmed_if(ok)
}

/// The three impulse-ratio claims (section 2, by simulated drops), each drop judged
/// against its own counted rounding bound ([`rounding::ratio_error`]; the massless one
/// adds the finite rod's model error `(1 + q^2)/(1 + alpha + q^2)`).
fn impulse_ratios(doc: &Statements, ev: &Evidence) -> [Claim; 3] {
    let t_uniform = |d: &Drop| rounding::uniform_ratio_tol(d.q, d.theta_rad, d.landing_rad, d.alpha);
    let t_massless = |d: &Drop| rounding::massless_ratio_tol(d.q, d.theta_rad, d.landing_rad, d.alpha);
    let t_between = |d: &Drop| rounding::ratio_error(d.q, d.theta_rad, d.landing_rad);
    let uniform = worst(&ev.uniform, |q, _| doc.uniform_ratio(q), t_uniform);
    let massless = worst(&ev.massless, |q, _| doc.massless_ratio(q), t_massless);
    let between = worst(&ev.between, |q, a| doc.between_ratio(q, a), t_between);
    let (tu, tm, tb) = (
        widest(&ev.uniform, t_uniform),
        widest(&ev.massless, t_massless),
        widest(&ev.between, t_between),
    );
    let alpha_m = ev.massless.first().map_or(f64::NAN, |d| d.alpha);
    [
        Claim::draft(Check::Simulation, "impulse-ratio-uniform", "2", &format!("A uniform stick (m = 0) landing without slip takes a sideways impulse J_ℓ/J_v = 3q/(4+q^2), q = tan θ. Simulated drops at q = 0.5, 1, 2; largest relative deviation, each drop against its counted rounding (the quotient -W_tn/W_tt of the sticking impact, the law's evaluation, the landing angle; up to {tu:.1e})."))
            .values(0.0, uniform.0, tu)
            .confirmed_if(uniform.1 <= 1.0),
        Claim::draft(Check::Simulation, "impulse-ratio-massless", "2", &format!("A massless rod with a tip mass (m_r -> 0) takes J_ℓ/J_v = q: the impulse runs along the rod. Simulated drops with m_r = 1e-10 m (α = {alpha_m:.3e}) at q = 0.5, 1, 2; largest relative deviation, each drop against the finite rod's model error (1 + q^2)/(1 + α + q^2) plus its counted rounding (up to {tm:.3e}).")
            ).values(0.0, massless.0, tm)
            .confirmed_if(massless.1 <= 1.0),
        Claim::draft(Check::Simulation, "impulse-ratio-between", "2 (derived)", &format!("A rod with α = M l_G^2 / I_G takes J_ℓ/J_v = α q/(1 + α + q^2) (3q/(4+q^2) at α = 3, q as α -> infinity). Simulated drops of m_r = m (α = 27/5) and m_r = m/10 (α = 32.27) at q = 0.5, 1, 2; largest relative deviation, each drop against its counted rounding (up to {tb:.1e})."))
            .values(0.0, between.0, tb)
            .confirmed_if(between.1 <= 1.0),
    ]
}

/// The Painleve boundary and the uniform rod's least coefficient and its angle, each
/// against the run's own error bound ([`rounding::boundary_tol`], [`rounding::min_tol`],
/// [`rounding::min_angle_tol`]).
fn painleve(doc: &Statements, ev: &Evidence) -> [Claim; 3] {
    let (boundary, worst_ratio, tol) = ev.boundaries.iter().fold((0.0f64, 0.0f64, 0.0f64), |(d, r, t), b| {
        let x = (b.mu - doc.mu_painleve(b.theta_rad, b.alpha)).abs() / b.mu;
        let bt = rounding::boundary_tol(b);
        (d.max(x), r.max(x / bt), t.max(bt))
    });
    let lb = &ev.uniform_min;
    let (min_tol, angle_tol) = (rounding::min_tol(lb), rounding::min_angle_tol(lb));
    let h = (lb.centre.theta_rad - lb.left.theta_rad).max(lb.right.theta_rad - lb.centre.theta_rad);
    let boundary_text = format!("A rod sliding with its foot moving away from the side it leans to has no unique normal force (a Painleve case) once μ > μ_P(θ) = tan θ + 1/(α sin θ cos θ). Bisection in μ, to adjacent doubles, on the simulated sliding rod at θ = 0.3, 0.6, 1.0 rad for α = 3 (uniform), 27/5 (m_r = m), 32.27 (m_r = m/10); largest relative deviation, each against its own bound: the simulator's threshold on D and D's counted rounding over |dD/dμ|, one ulp, and the closed form's rounding (up to {tol:.2e}).");
    let min_text = format!("For the uniform rod the least μ_P is 4/3 (golden-section search over θ of the bisected boundary; tolerance {min_tol:.2e}: the located value's error bound and its excess over the minimum of the convex boundary, from two points {h:.1e} rad beside it where the boundary is certainly higher).");
    let angle_text = format!("... reached at θ = atan(1/2) = 0.4636 rad (tolerance {angle_tol:.2e} rad: the convex boundary's minimum lies between the two points where it is certainly higher).");
    [
        Claim::draft(Check::Simulation, "painleve-boundary", "2, 4 (derived)", &boundary_text)
            .values(0.0, boundary, tol)
            .confirmed_if(worst_ratio <= 1.0),
        Claim::draft(Check::Simulation, "painleve-minimum-uniform", "2, 4 (derived)", &min_text)
            .close(doc.painleve_min, lb.centre.mu, min_tol),
        Claim::draft(Check::Simulation, "painleve-minimum-angle", "2, 4 (derived)", &angle_text)
            .close(doc.painleve_min_tan.atan(), lb.centre.theta_rad, angle_tol),
    ]
}

/// `massless-limit`: the mean speed converges to chapter 6's at order 1 in `I_P k/gamma^2`.
/// Each scene's fitted order is judged against [`order_tol`] of its own local orders.
fn massless_limit(doc: &Statements, ev: &Evidence) -> Claim {
    let (lo, hi) = ORDER_RANGE;
    let fits = ev.ladders.each_ref().map(|l| {
        let pts: Vec<(f64, f64)> = l
            .iter()
            .filter(|r| (lo..=hi).contains(&r.inertia_ratio))
            .map(|r| (r.inertia_ratio, r.error().abs()))
            .collect();
        let order = super::evidence::fitted_order(l, lo, hi);
        (order, order_tol(&local_orders(&pts)))
    });
    let ok = fits.iter().all(|&(o, t)| (o - doc.massless_order).abs() <= t);
    let tol = fits.iter().map(|f| f.1).fold(0.0, f64::max);
    let statement = format!(
        "The document's massless rod is the limit m_r -> 0 of the rod with inertia: the mean speed converges to chapter 6's at first order in the rod's dimensionless inertia I_P k/γ^2 (fitted orders {:.4} on the self-locking scene, {:.4} on the authors', over I_P k/γ^2 in [{:.0e}, {}], rods of 1e-8 to 1e-3 kg on a 1 kg tip; each within twice the spread of its own local orders, {:.4} and {:.4}).",
        fits[0].0, fits[1].0, ORDER_RANGE.0, ORDER_RANGE.1, fits[0].1, fits[1].1
    );
    Claim::draft(
        Check::Convergence,
        "massless-limit",
        "4, 5 (the model)",
        &statement,
    )
    .values(doc.massless_order, fits[0].0, tol)
    .approximation_if(ok)
}

/// `impacts-dissipate`: no simulated impact creates energy. A consistency check: with
/// `e <= 1` the Darboux-Keller process gives back at most the work it absorbed, so the
/// inequality holds by construction; what the check adds is that the states before and
/// after (not the rule's own bookkeeping) say the same. One-sided: a gain at most the
/// rounding of its own evaluation ([`rounding::energy_gain_bound`]), any loss allowed.
fn impacts_dissipate(doc: &Statements, (gain, bound, n): (f64, f64, usize)) -> Claim {
    let statement = format!(
        "No impact creates energy (holds by construction of the impact rule for e <= 1; checked from the states): kinetic energy change minus the plate's impulse work, from the states before and after, at most the counted rounding of its evaluation, γ_16 (1 + 8α) 2E with E the run's energy (largest gain against its bound shown), over {n} simulated landings with restitution e = {} (slipping, sticking, reversing).",
        doc.restitution_max
    );
    Claim::draft(
        Check::Consistency,
        "impacts-dissipate",
        "4 (impact law)",
        &statement,
    )
    .values(
        "energy gain <= 0 (one-sided)",
        gain,
        format!("one-sided: gain <= {bound:.3e} J (the gain's counted rounding)"),
    )
    .confirmed_if(gain <= bound && n > 0)
}
