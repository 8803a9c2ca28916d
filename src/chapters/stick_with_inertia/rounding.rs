//! Error bounds of the chapter's claims (issue 29 §2), from the run's own numbers: each
//! tolerance is the counted rounding of the code that produced the checked number (and
//! of the statement's evaluation), divided where it must be by the derivative that turns
//! a rounding of the deciding quantity into an error of the located number. Pure
//! arithmetic on what `evidence.rs` carries; the derivations are in
//! `chapters/08-stick-with-inertia.md` ("How exact are the checks?") and the measured
//! headroom in `docs/ch8-contact-checks.md`.
//!
//! Model: IEEE binary64, `fl(a op b) = (a op b)(1 + δ)`, |δ| <= u = 2^-53,
//! `γ_k = k u/(1 - k u)`; sin, cos, tan and atan of the platform's libm within 1 ulp,
//! counted as two roundings each ([`TRIG`]). The "exact" value of a quantity is the exact
//! mathematics at the doubles the run holds: the angle θ as a double, and the rod as
//! its stored constants `M`, `l_G`, `I_G` (their own rounding from `m_r`, `m`, `L` is
//! common to the simulator and the closed form, except where a statement names a
//! number such as α = 3, which is then a separate term).

pub use crate::numerics::rounding::{gamma, OWN, TRIG, U};

/// One bisected Painleve boundary as it ran (see `evidence::painleve_boundary`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Boundary {
    /// Angle (rad).
    pub theta_rad: f64,
    /// `alpha = M l_G^2 / I_G` as computed (1).
    pub alpha: f64,
    /// The located boundary: the least double the simulator calls a Painleve case (1).
    pub mu: f64,
    /// The largest double below `mu`, which it calls a slide (1): `mu - lo` is one ulp.
    pub lo: f64,
    /// The simulator's threshold `eta_D` at `mu` as computed
    /// (`InertiaModel::coefficient_rounding`, kg m^2).
    pub threshold_kgm2: f64,
    /// The terms of `D` at `mu`: `I_G + M l_G^2 sin^2 + mu M l_G^2 |sin cos|` (kg m^2).
    pub terms_kgm2: f64,
    /// `|dD/dmu| = M l_G^2 |sin cos|` (kg m^2).
    pub slope_kgm2: f64,
}

/// Absolute error bound (1) of a located boundary against the exact `D = 0` of the
/// stored rod, `mu_e = tan θ + I_G/(M l_G^2 sin θ cos θ)`.
///
/// The simulator calls a slide a Painleve case when its computed `D^` is at most its
/// threshold `eta_D` (`!(D^ > eta_D)`, `system::enter_slide`). `D^ = fl(I_G +
/// fl(fl(fl(fl(M l) l) s^) fl(s^ - fl(mu c^))))` (`slide_coefficient`): the `s^2` term
/// carries 3 products, the subtraction, the product and 2 TRIG of `s^` (9 roundings),
/// the `mu s c` term also `mu c^` and `c^`'s TRIG (10), the final sum one more, so
/// `|D^ - D| <= ε_D = γ_11 (I_G + M l^2 s^2 + mu M l^2 |s c|)`. `D` is linear in `mu`
/// with slope `-K`, `K = M l^2 |s c|`, zero at `mu_e`. The bisection ends on adjacent
/// doubles `lo < mu`: `D^(lo) > eta_D(lo) >= 0` gives `lo < mu_e + ε_D/K`, and
/// `D^(mu) <= eta_D(mu)` gives `mu >= mu_e - (eta_D + ε_D)/K`; with `mu - lo` one ulp,
/// `|mu - mu_e| <= (eta_D + ε_D)/K + (mu - lo)`. The computed terms and `K` carry at
/// most γ_8 each (positive products and sums, 2 TRIG): a factor `1 + γ_16`.
pub fn switch_error(b: &Boundary) -> f64 {
    let eps_d = gamma(11) * b.terms_kgm2; // formula: ε_D = γ_11 (I_G + M l^2 s^2 + mu M l^2 |s c|)
    // formula: |mu - mu_e| <= (eta_D + ε_D)/K + (mu - lo)
    OWN * ((1.0 + gamma(16)) * (b.threshold_kgm2 + eps_d) / b.slope_kgm2 + (b.mu - b.lo))
}

/// Relative tolerance (1) of `painleve-boundary` at one angle: the switch's error
/// ([`switch_error`]) plus the closed form's evaluation `fl(|tan θ| + 1/fl(α^ fl(|s^
/// c^|)))` (`painleve::mu_painleve`): α^ = fl(fl(M l) l)/I_G carries 3 roundings, the
/// second term 3 + 2 TRIG + 3 more, the sum 1, tan 2 TRIG: two positive terms each within
/// γ_11, so γ_11 of the value, γ_13 with the claim's division and the value's offset
/// from the located `mu`.
pub fn boundary_tol(b: &Boundary) -> f64 {
    OWN * (switch_error(b) / b.mu + gamma(13)) // formula: (|mu - mu_e| + γ_13 mu)/mu
}

/// The uniform rod's least boundary as located: the golden-section point and two
/// points beside it, on either side, each a located boundary.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeastBoundary {
    /// The golden-section point.
    pub centre: Boundary,
    /// The nearest point left of it at which the boundary is certainly higher.
    pub left: Boundary,
    /// ... and right of it.
    pub right: Boundary,
}

/// The exact boundary `mu_e(θ) = tan θ + 1/(α* sin θ cos θ)` is convex on (0, π/2)
/// (tan and 1/sin(2θ) are): if it is certainly higher at `θ_g - h_-` and at `θ_g + h_+`
/// than at `θ_g` (the located values apart by more than their [`switch_error`]s), its
/// minimum lies between them, and a convex function's secant bounds the minimum from
/// below: `min >= g_0 - max((g_- - g_0) h_+/h_-, (g_+ - g_0) h_-/h_+)`. Returns that
/// excess of `g(θ_g)` over the minimum, with `g_±` and `g_0` at their worst (1).
pub fn min_excess(lb: &LeastBoundary) -> f64 {
    let (c, l, r) = (&lb.centre, &lb.left, &lb.right);
    let (h_m, h_p) = (c.theta_rad - l.theta_rad, r.theta_rad - c.theta_rad);
    let g0 = c.mu - switch_error(c);
    let (g_m, g_p) = (l.mu + switch_error(l), r.mu + switch_error(r));
    // formula: excess <= max((g_- - g_0) h_+/h_-, (g_+ - g_0) h_-/h_+)
    OWN * ((g_m - g0) * h_p / h_m).max((g_p - g0) * h_m / h_p)
}

/// `|α* - 3|` at most (1): `α^` is within γ_3 of the stored rod's `α*`.
fn alpha_from_three(alpha: f64) -> f64 {
    (alpha - 3.0).abs() + gamma(3) * alpha // formula: |α* - 3| <= |α^ - 3| + γ_3 α^
}

/// Uncertainty of the stored rod's `α*` against the statement's 3 (1): `|α^ - 3| + γ_3
/// α^` (α^ is within γ_3 of α*); infinite when α^ is not within 1e-6 of 3 (the
/// sensitivities below hold near 3 only).
fn alpha_offset(alpha: f64) -> f64 {
    let d = alpha_from_three(alpha);
    if d <= 1e-6 {
        d
    } else {
        f64::INFINITY
    }
}

/// Absolute tolerance (1) of `painleve-minimum-uniform`: the located value's own error,
/// its excess over the convex boundary's minimum ([`min_excess`]), the minimum's shift
/// with α (`d/dα 2 sqrt(1+α)/α = -0.278` at 3: at most `|α* - 3|/3`) and the rounding
/// of the statement's 4/3.
pub fn min_tol(lb: &LeastBoundary) -> f64 {
    let c = &lb.centre;
    // formula: |mu_g - 4/3| <= err_g + excess + |α* - 3|/3 + u 4/3
    OWN * (switch_error(c) + min_excess(lb) + alpha_offset(c.alpha) / 3.0 + U * c.mu)
}

/// Tolerance (rad) of `painleve-minimum-angle`: the convex boundary's minimum lies
/// within the larger of `h_-` and `h_+` of the golden-section point (see
/// [`min_excess`]); `θ* = atan(1/sqrt(1 + α))` moves with α by at most `|α* - 3|/20`
/// near 3; `fl(atan(1/2))` is within 2 ulp.
pub fn min_angle_tol(lb: &LeastBoundary) -> f64 {
    let c = &lb.centre;
    let h = (c.theta_rad - lb.left.theta_rad).max(lb.right.theta_rad - c.theta_rad);
    // formula: |θ_g - atan(1/2)| <= max(h_-, h_+) + |α* - 3|/20 + 2 TRIG u θ
    OWN * (h + alpha_offset(c.alpha) / 20.0 + 2.0 * TRIG as f64 * U * c.theta_rad)
}

/// Relative error bound (1) of a simulated drop's `J_t/J_n` against the section-2 law
/// `α q/(1 + α + q^2)` (at the run's α^), evaluated at `q`.
///
/// The drop lands at rest in x (sticking, μ = 10): the Darboux-Keller loop takes one
/// sticking piece, `r = -W^_tn/W^_tt`, `P_t = fl(r dp)`, `P_n = dp`, and the ratio is
/// `fl(P_t/P_n)`: the 2x2 impulse solve's condition number (that of `W`, `1 + α`)
/// enters `P_n`, not the ratio, which is one quotient of two mobility entries.
/// `W^_tn = fl(fl(fl(-α^ s^) c^)/M)`: 3 + 2 TRIG = 7; `W^_tt = fl(fl(1 + fl(fl(α^
/// c^) c^))/M)`: 4 + 2 TRIG = 8 (a positive sum); the quotient 1, `r dp` 1, `P_t/P_n`
/// 1: γ_18. The law's evaluation `fl(fl(fl(s α) q)/fl(fl(1 + α) + fl(q q)))`: γ_6. The
/// landing angle `θ_l` (from the run) against `atan q`: `θ_in = fl(atan q)` is within 2
/// TRIG u, and `|d ln r / dθ| <= (1 + q^2)/q` (`|d ln r / d ln q| <= 1`).
pub fn ratio_error(q: f64, theta_in: f64, theta_landing: f64) -> f64 {
    let angle = (theta_landing - theta_in).abs() + 2.0 * TRIG as f64 * U * theta_in.abs(); // formula: |θ_l - atan q|
    OWN * (gamma(18) + gamma(6) + (1.0 + q * q) / q * angle) // formula: γ_18 + γ_6 + (1 + q^2)/q |θ_l - atan q|
}

/// Relative tolerance (1) of `impulse-ratio-uniform` at one drop: [`ratio_error`] plus
/// the law's α = 3 against the run's α^ (`|d ln r / d ln α| = (1 + q^2)/(1 + α + q^2)
/// <= 1`).
pub fn uniform_ratio_tol(q: f64, theta_in: f64, theta_landing: f64, alpha: f64) -> f64 {
    let d_alpha = alpha_from_three(alpha) / 3.0; // formula: |α* - 3|/3
    OWN * (ratio_error(q, theta_in, theta_landing) + d_alpha)
}

/// Relative tolerance (1) of `impulse-ratio-massless` at one drop of a rod with
/// `alpha` (finite): the model error of a finite rod, `|α q/(1 + α + q^2) - q|/q =
/// (1 + q^2)/(1 + α + q^2)`, plus [`ratio_error`].
pub fn massless_ratio_tol(q: f64, theta_in: f64, theta_landing: f64, alpha: f64) -> f64 {
    let model = (1.0 + q * q) / (1.0 + alpha + q * q); // formula: (1 + q^2)/(1 + α + q^2)
    OWN * (model * (1.0 + gamma(8)) + ratio_error(q, theta_in, theta_landing))
}

/// Bound (J) on the rounding of one impact's energy gain as computed,
/// `fl(fl(T^(a) - T^(y)) - fl(P_n zdot_s))` (`system::impact`), for a run whose
/// kinetic energy stays below `energy_j` on a still plate (`zdot_s = 0`).
///
/// `T^ = fl(fl(0.5 M) fl(fl(v_x^2) + fl(v_z^2)) + fl(fl(0.5 I_G θ') θ'))` with
/// `v_x = fl(v_Cx + fl(fl(l c^) θ'))` (`centre`): `|v_x^ - v_x| <= γ_5 a_x`,
/// `a_x = |v_Cx| + l |c θ'|`, so `|v_x^2 - v_x^2| <= γ_10 a_x^2`; the squares, the sum,
/// the product and the final sum add 4: `|T^ - T| <= γ_14 T~` with
/// `T~ = M (a_x^2 + a_z^2)/2 + I_G θ'^2/2`. The two differences add 2:
/// `γ_16 (T~(a) + T~(y))`. With `v_C = v_G - l θ' e_θ`,
/// `a_x^2 + a_z^2 <= 2 |v_G|^2 + 8 l^2 θ'^2`, so `T~ <= (1 + 8 α) T`. Not counted: the
/// rounding of the impulse and of the state update (the states are the simulator's;
/// the check asks whether they gained energy).
pub fn energy_gain_bound(energy_j: f64, alpha: f64) -> f64 {
    OWN * gamma(16) * 2.0 * (1.0 + 8.0 * alpha) * energy_j // formula: γ_16 (T~_a + T~_y) <= γ_16 2 (1 + 8α) E
}
