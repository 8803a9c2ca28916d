//! The claims of section 2: pure functions of the statements ([`Statements`]) and the
//! rigid-body computations ([`Evidence`]: mass-matrix inversion, Newton-Euler impulse
//! equations).

use super::evidence::{
    bisect, point_mass_ratio, rod_lock_angles_closed_form, rod_ratio, Evidence, Ratios,
    FREE_G_MPS2, FREE_SPIN_RAD_S,
};
use super::rounding::{
    angle_error, mass_matrix_error, newton_euler_ratio_error, point_mass_law_error,
    point_mass_ratio_error, quotient_error, rod_law_error, rod_ratio_error, stick_error,
    terms_error, OWN,
};
use super::statements::Statements;
use super::{LENGTH_M, MASS_KG};
use crate::report::{fmt_num, is_close, Check, Claim};
use nalgebra::Vector2;

/// The tolerance sentence of the rounding-bounded claims.
const BOUND: &str = "Tolerance: rigorous rounding bounds of both sides, from the run (chapter text, 'How exact are the checks?').";

/// Every claim of the chapter at friction `mu`, in the order of the report.
pub fn all(st: &Statements, ev: &Evidence, mu: f64) -> Vec<Claim> {
    let mut out = mass_matrix(st, ev);
    out.push(a1_needs_free_acceleration(st, ev));
    out.extend(derivation(st, ev));
    out.extend(ratios(st, ev));
    out.extend(example_45(st, ev));
    out.extend(best_angle(st, ev));
    out.push(self_locking(st, mu));
    out
}

/// (A.1): the rod's mass matrix in stick coordinates.
fn mass_matrix(st: &Statements, ev: &Evidence) -> Vec<Claim> {
    let sec = "2, eq. (A.1)";
    let inv = Check::SecondMethod; // the mobility matrix inverted numerically
    let m = &ev.stick;
    // formula: |S^ - S| <= 2 (1 + γ_3)(e_M + γ_9 max|M^|), e_M from the inversion's residual
    let e_s = stick_error(mass_matrix_error(&ev.inversion), &ev.inversion);
    let tol = |printed: f64| e_s + terms_error(1, printed); // formula: + u |printed m|
    let (along, across, off) = (
        st.mass_along * MASS_KG,
        st.mass_across * MASS_KG,
        st.mass_off_diagonal * MASS_KG,
    );
    vec![
        Claim::draft(inv, "rod-mass-along", sec, &format!("Effective mass of C along the uniform stick: m (kg). Computed: the mobility matrix Id/m + perp(r) perp(r)^T/I_G inverted numerically, turned into stick coordinates. {BOUND}")).close(along, m[(0, 0)], tol(along)),
        Claim::draft(inv, "rod-mass-across", sec, "Effective mass of C across the uniform stick: m/4 (kg).").close(across, m[(1, 1)], tol(across)),
        Claim::draft(inv, "rod-mass-diagonal", sec, "[m]' is diagonal in stick coordinates x'-z' (off-diagonal entry, kg).").close(off, m[(0, 1)], tol(off)),
    ]
}

/// The document's step-by-step derivation with a unit force (F = 1 N) across the
/// stick at C.
fn derivation(st: &Statements, ev: &Evidence) -> Vec<Claim> {
    let f = 1.0;
    let sec = "2, text after (A.1)";
    let wd = f * LENGTH_M / 2.0 / ev.inertia_kgm2;
    let a_cg = (ev.a_c - ev.a_g).dot(&ev.normal);
    let a_c = ev.a_c.dot(&ev.normal);
    let (a_g, w) = (ev.a_g.norm(), ev.omega_dot.abs());
    // formula: the vector steps' magnitudes, |e| + |c| + 2 |a_G|_1 + |a_C|_1
    let size = |e: f64, c: f64| e.abs() + c.abs() + 2.0 * ev.a_g.abs().sum() + ev.a_c.abs().sum();
    // The workbook's contact_acceleration evaluates the same three formulas: these
    // three steps are consistency checks of the code, not evidence about the document.
    let cons = Check::Consistency;
    let e_ac = st.a_c_factor * f / MASS_KG;
    vec![
        Claim::draft(cons, "derivation-a-g", sec, "a_G = F/m (m/s² for F = 1 N across the stick); the workbook evaluates the same formula (consistency).").close(f / MASS_KG, a_g, terms_error(1, f / MASS_KG) + terms_error(7, a_g)), // formula: u |F/m| + γ_7 |a_G^|
        Claim::draft(cons, "derivation-omega-dot", sec, "dω/dt = (F L/2)/I (rad/s² for F = 1 N); the workbook evaluates r x F / I_G (consistency).").close(wd, w, terms_error(3, wd) + terms_error(9, w)), // formula: γ_3 |e| + γ_9 |ω^|
        Claim::draft(cons, "derivation-a-c-g", sec, "a_C/G = dω/dt L/2 (m/s² for F = 1 N); the workbook evaluates dω/dt r^⊥, r turned by 90° in the x-z plane (consistency).").close(wd * LENGTH_M / 2.0, a_cg, terms_error(16, size(wd * LENGTH_M / 2.0, a_cg))), // formula: γ_16 Σ|terms|
        Claim::draft(Check::SecondMethod, "derivation-a-c", sec, &format!("a_C = F/(m/4): effective mass m/4 across the stick (m/s² for F = 1 N): the sum of the two contributions, computed as vectors, against the printed factor 4. {BOUND}")).close(e_ac, a_c, terms_error(20, size(e_ac, a_c))), // formula: γ_20 Σ|terms|
    ]
}

/// One general law judged at the chosen angle (the claim's numbers) and at 30 degrees
/// (q = 0.577, where a law in q cannot pass for one in 1/q or q²; at the default 45
/// degrees q = 1/q = q² = 1).
struct Law<'a> {
    id: &'a str,
    statement: &'a str,
    /// The law as stated, at `q`.
    law: &'a dyn Fn(f64) -> f64,
    /// The computed ratio from the evidence at an angle.
    computed: fn(&Ratios) -> f64,
    /// Tolerance from the law's value and the ratios' raw quantities: the law's
    /// evaluation bound plus the computed ratio's.
    tol: fn(f64, &Ratios) -> f64,
}

fn judge_law(l: &Law, ev: &Evidence) -> Claim {
    let (q, qa) = (ev.at.theta.tan(), ev.at30.theta.tan()); // formula: slope 1/q, q = tan(theta)
    let (e, ea) = ((l.law)(q), (l.law)(qa));
    let (c, ca) = ((l.computed)(&ev.at), (l.computed)(&ev.at30));
    let (tol, tola) = ((l.tol)(e, &ev.at), (l.tol)(ea, &ev.at30));
    let holds = is_close(e, c, tol) && is_close(ea, ca, tola);
    Claim::draft(Check::SecondMethod, l.id, "2, J_ℓ formula", &format!("{} Judged at the given angle (shown) and at 30 degrees (q = 0.577, where q, 1/q and q² differ: expected {ea:.6}, computed {ca:.6}). {BOUND}", l.statement))
        .values(e, c, tol)
        .confirmed_if(holds)
}

/// The impulse ratios J_l/J_v of the two models, by two methods each.
fn ratios(st: &Statements, ev: &Evidence) -> Vec<Claim> {
    let pm = |q: f64| st.point_mass_factor * q; // formula: J_l/J_v = q
    let rod = |q: f64| st.rod_numerator * q / (st.rod_denominator + q * q); // formula: 3q/(4+q^2)
    // formula: tolerance = law evaluation (γ_4 or γ_8 of it) + the computed ratio's bound
    let laws = [
        Law { id: "ratio-point-mass", statement: "Point-mass model: J_ℓ = q J_v (ratio; computed from the inverted mass matrix).", law: &pm, computed: |r| r.point_mass, tol: |e, r| point_mass_law_error(e) + point_mass_ratio_error(r.point_mass) },
        Law { id: "ratio-uniform-rod", statement: "Uniform rod: J_ℓ = (3q/(4+q²)) J_v (ratio; computed from the inverted mass matrix).", law: &rod, computed: |r| r.rod, tol: |e, r| rod_law_error(e) + rod_ratio_error(&r.rod_inversion) },
        Law { id: "ratio-rod-newton-euler", statement: "Second method (Newton-Euler impulse equations, a 5x5 linear solve) gives the rod's ratio 3q/(4+q²).", law: &rod, computed: |r| r.rod_ne, tol: |e, r| rod_law_error(e) + newton_euler_ratio_error(&r.rod_solve) },
        Law { id: "ratio-point-mass-newton-euler", statement: "Second method (Newton-Euler, I_G = 0) gives the point-mass ratio q.", law: &pm, computed: |r| r.point_mass_ne, tol: |e, r| point_mass_law_error(e) + newton_euler_ratio_error(&r.point_mass_solve) },
    ];
    laws.iter().map(|l| judge_law(l, ev)).collect()
}

/// The 45 degree example: the computed ratios at θ^ = fl(π/4) against the document's
/// exact 1 and 3/5 at π/4, with the angle's rounding |θ^ - π/4| <= u θ^ carried by the
/// ratios' θ-derivatives, 1 + q² and 6 q (1 + q²)/(4 + q²)².
fn example_45(st: &Statements, ev: &Evidence) -> Vec<Claim> {
    let sec45 = "2, 45 degree example";
    let r = &ev.at45;
    let sm = Check::SecondMethod;
    let q = r.point_mass;
    let e_pm = point_mass_ratio_error(q);
    let e_rod = rod_ratio_error(&r.rod_inversion);
    let (e1, e2) = (st.example_point_mass, st.example_rod_fraction);
    // formula: |ρ^ - 1| <= γ_14 |ρ^| + (1 + q²) u θ^ + u |printed|
    let tol_pm = e_pm + angle_error(1.0 + q * q, r.theta) + terms_error(1, e1);
    let slope = 6.0 * q * (1.0 + q * q) / (4.0 + q * q).powi(2); // formula: d/dθ 3/(4 + q²)
    // formula: quotient of two bounded ratios + the angle's rounding + u |printed|
    let tol_rod =
        quotient_error(r.rod, q, e_rod, e_pm) + angle_error(slope, r.theta) + terms_error(1, e2);
    vec![
        Claim::draft(sm, "example-45-point-mass", sec45, &format!("At 45 degrees (q = 1) the point-mass model gives a horizontal impulse equal to the vertical one (J_ℓ/J_v). {BOUND}")).close(e1, q, tol_pm),
        Claim::draft(sm, "example-45-rod-60-percent", sec45, "At 45 degrees the uniform rod gives 60 % of the point mass's sideways impulse.").close(e2, r.rod / q, tol_rod),
    ]
}

/// The angle of largest sideways impulse of the rod (the workbook's derivation).
///
/// The golden section's argmax θ^ is certified by the evidence's probe: the computed
/// ratio at θ^ exceeds those at θ^ ± h by more than the three rounding bounds, so the
/// exact ratio (unimodal) peaks within h of θ^. Its value there is below the peak by at
/// most the larger drop for a parabola (doubled for the cubic term, about h |f3/f2| ~ 1e-7
/// of it, f2 and f3 the second and third θ-derivatives).
fn best_angle(st: &Statements, ev: &Evidence) -> Vec<Claim> {
    let p = &ev.best;
    let best_cf = st.best_q.atan(); // formula: q* = 2, theta* = atan 2
    let (e_deg, c_deg) = (best_cf.to_degrees(), p.theta_rad.to_degrees());
    // formula: |θ^ - θ*| < h; atan (2u) and two conversions to degrees: γ_4 (|e| + |c|)
    let tol_deg =
        OWN * p.h_rad.to_degrees() * (1.0 + 1e-6) + terms_error(4, e_deg.abs() + c_deg.abs());
    let e = p.inversion.map(|i| rod_ratio_error(&i));
    let drop = (p.ratio[1] - p.ratio[0] + e[0] + e[1]).max(p.ratio[1] - p.ratio[2] + e[1] + e[2]);
    let tol_ratio = e[1] + 2.0 * drop; // formula: e(θ^) + 2 max(true drop)
    let ok = |t: f64| if p.certified() { t } else { f64::NAN };
    vec![
        Claim::draft(Check::SecondMethod, "rod-best-angle", "2 (workbook)", &format!("The uniform rod's sideways impulse is largest at q = 2, θ = atan 2 (degrees; golden-section search on the mass-matrix ratio). Tolerance: the half-width h = {} rad of a probe on which the computed ratio falls on both sides by more than its rounding bounds (chapter text).", fmt_num(p.h_rad))).close(e_deg, c_deg, ok(tol_deg)),
        Claim::draft(Check::SecondMethod, "rod-best-ratio", "2 (workbook)", "The largest ratio of the uniform rod is 3/4 (J_ℓ/J_v at the located argmax; tolerance: the ratio's rounding bound plus twice the probe's larger drop).").close(st.best_ratio, p.ratio[1], ok(tol_ratio)),
    ]
}

/// Fig. 1 caption: theta < atan(mu) puts the stick in the self-locking regime.
///
/// Reading: the caption claims a sufficient condition (C does not slip when the tip
/// angle is below atan mu). Checked: over 2001 angles of the set the caption names, the
/// uniform rod's impulse ratio from its mass matrix stays inside the friction cone.
fn self_locking(st: &Statements, mu: f64) -> Claim {
    let bound = (st.lock_factor * mu).atan();
    let top = std::f64::consts::FRAC_PI_2 - 1e-6;
    let (lo, hi) = if st.lock_below {
        (0.0, bound)
    } else {
        (bound, top)
    };
    let n = 2000;
    let worst = (0..=n)
        .map(|k| lo + (hi - lo) * (k as f64 / n as f64) * (1.0 - 1e-12))
        .filter(|&t| t < hi)
        .map(|t| rod_ratio(t).abs())
        .fold(0.0f64, f64::max);
    // The caption's bound is the point-mass model's exact one (tan theta < mu): reported,
    // not judged; the caption is about the uniform stick, which the verdict is about.
    let (pm_below, pm_beyond) = (
        point_mass_ratio(bound - 1e-6),
        point_mass_ratio(bound + 1e-6),
    );
    let tight_for_point_mass = mu == 0.0 || (pm_beyond > mu && pm_below <= mu);
    let range = if st.lock_below {
        format!("θ < {} deg", fmt_num(bound.to_degrees()))
    } else {
        format!("θ > {} deg", fmt_num(bound.to_degrees()))
    };
    Claim::draft(
        Check::SecondMethod,
        "self-locking-bound",
        "2, Fig. 1 caption",
        &self_locking_statement(mu, tight_for_point_mass),
    )
    .values(
        format!("|J_ℓ|/J_v <= μ = {} for {range}", fmt_num(mu)),
        format!("largest |J_ℓ|/J_v there: {}", fmt_num(worst)),
        "exact inequality",
    )
    .confirmed_if(worst <= mu)
}

/// The statement of `self-locking-bound` at friction `mu`, with where else the rod jams.
fn self_locking_statement(mu: f64, tight_for_point_mass: bool) -> String {
    let t = mu.atan();
    let deg = |x: f64| fmt_num(x.to_degrees());
    let also = match rod_lock_angles_closed_form(mu) {
        Some((a1, a2)) => {
            let b1 = bisect(|x| rod_ratio(x) - mu, 0.0, 2f64.atan(), 1e-13);
            format!("the rod also jams for {} < θ <= {} degrees (closed form; bisection on the mass-matrix ratio: {}) and for θ >= {} degrees", deg(t), deg(a1), deg(b1), deg(a2))
        }
        None if mu > 0.0 => "for μ >= 3/4 the rod jams at every angle".to_string(),
        None => "with μ = 0 only the upright stick jams".to_string(),
    };
    format!(
        "Fig. 1: the tip angle θ < atan(μ) puts the uniform stick in the self-locking regime (C does not slip under a vertical impulse or acceleration). Reading: a sufficient condition, which is all the caption claims. Checked on 2001 angles of that range: the uniform stick's |J_ℓ|/J_v from its mass matrix stays <= μ. The bound is the point-mass model's exact one ({pm}); for the uniform stick, whose ratio 3q/(4+q²) is below q, it is sufficient with at least 33 % of slack (its own bound q₁(μ) >= 4μ/3), so no 10 % change of the printed bound can fail for the stick the caption is about, and it is not necessary: {also}. Both criteria are results: self_locking (tan θ < μ) and rod_jams_under_vertical_impulse (3q/(4+q²) <= μ).",
        pm = if tight_for_point_mass {
            "1e-6 rad below it the point mass holds, 1e-6 rad beyond it slips"
        } else {
            "but here the point mass does not switch at it"
        }
    )
}

/// (A.1) as "the relation between contact acceleration and contact force": it holds
/// for a stick at rest with the contact force the only force (and for impulses,
/// J = [m]' Δv_C); in general a_C = [m]'^-1 F + b with C's free acceleration
/// b = -g e_z + θ'² (L/2) e_r (gravity, and the centripetal term: C accelerates towards
/// G). An approximation: the limit m |b| << |F| (impulsive forces). Judged by a second
/// method that never forms the mass matrix (Lagrange's equations integrated, C's
/// acceleration by central differences), at rest without gravity and spinning under it.
pub fn a1_needs_free_acceleration(st: &Statements, ev: &Evidence) -> Claim {
    let theta = ev.at.theta;
    let (spin, g) = (FREE_SPIN_RAD_S, FREE_G_MPS2);
    let force = ev.normal; // 1 N across the stick, as in the document's derivation
    let e_r = Vector2::new(theta.sin(), theta.cos());
    // formula: (A.1) as printed, in stick coordinates: a_x' = F_x'/m, a_z' = F_z'/(m/4)
    let a1 = force.dot(&e_r) / (st.mass_along * MASS_KG) * e_r
        + force.dot(&ev.normal) / (st.mass_across * MASS_KG) * ev.normal;
    let b = Vector2::new(0.0, -g) + spin * spin * 0.5 * LENGTH_M * e_r; // formula: b = -g e_z + θ'² (L/2) e_r
    let (rest, spinning) = (ev.free_at_rest, ev.free_spinning); // the second method, at `force`
    // formula: the differences' error estimate + γ_12 (|F| (1/m_along + 1/m_across) + |b|),
    // the rounding of (A.1)'s and b's evaluation
    let size = force.norm() * (1.0 / (st.mass_along * MASS_KG) + 1.0 / (st.mass_across * MASS_KG));
    let tol = rest.error_mps2.max(spinning.error_mps2) + terms_error(12, size + b.norm());
    let at_rest_holds = (rest.a_c - a1).norm() <= tol;
    let departure = (spinning.a_c - a1).norm();
    let general_holds = (spinning.a_c - a1 - b).norm() <= tol;
    let claim = Claim::draft(
        Check::SecondMethod,
        "a1-needs-free-acceleration",
        "2, eq. (A.1)",
        &format!("As printed, (A.1) is 'the relation between contact acceleration and contact force': F = [m]' a_C. It holds for a stick at rest with the contact force the only force (and for impulses, J = [m]' Δv_C, the collision that follows); in general a_C = [m]'^-1 F + b, with C's free acceleration b = -g e_z + θ'² (L/2) e_r (gravity, and the centripetal term: C accelerates towards G). An approximation, exact in the limit m |b| << |F| (impulsive forces). Second method, no mass matrix: Lagrange's equations of the rod (m a_G = F - m g e_z, I_G θ'' = F . dC/dθ) integrated by RK4, C's acceleration by central differences, F = 1 N across the stick at θ = {:.1} deg: at rest without gravity it matches (A.1) (difference {}, the central difference's truncation), spinning at {spin} rad/s under g = {g} m/s² it departs by |b| and matches (A.1) plus b. Shown: |b| (closed form) against |a_C - [m]'^-1 F| spinning (m/s²); tolerance the differences' error estimate (Richardson).", theta.to_degrees(), fmt_num((rest.a_c - a1).norm())),
    )
    .values(b.norm(), departure, tol);
    if st.a1_free_acceleration {
        // The general relation printed: it must hold in both states.
        claim.confirmed_if(at_rest_holds && general_holds)
    } else {
        claim.approximation_if(at_rest_holds && general_holds && departure > 100.0 * tol)
    }
}
