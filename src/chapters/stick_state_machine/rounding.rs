//! Rounding bounds of chapter 6's identities at single recorded states (issue 29 §2):
//! rigorous running-error bounds from the magnitudes at each state, replacing the fixed
//! relative floor of 1e-12. Pure arithmetic on the raw quantities `at_states.rs` carries
//! in an [`Impact`]; the derivation is in `chapters/06-stick-state-machine.md` ("How exact
//! are the collision checks?") and the measured headroom in `docs/stick-internals.md`.
//!
//! Model (as chapter 2's `effective_mass/rounding.rs`): IEEE binary64, u = 2^-53,
//! `fl(a op b) = (a op b)(1 + δ)`, |δ| <= u, `γ_k = k u/(1 - k u)`, γ_a + γ_b <= γ_{a+b};
//! sin and cos of the platform's libm within 1 ulp (a relative 2u each). The "exact"
//! value is the exact mathematics at the doubles the run holds: θ, the tip's velocity
//! (x_p', z_p'), the plate's z_s', L and m.

use super::at_states::Impact;
use crate::numerics::rounding::{gamma, OWN, UNDERFLOW};
use crate::physics::stick::TH;

/// Bound (rad/s) on |ω^_C.15 - ω^_NE|: the rate after a sticking landing from C.15
/// (`σ (r_x u_z - r_z u_x)/(L L)`, r = L (sin, cos), u = (x_p', z_p' - z_s'), σ = -1)
/// against the Newton-Euler solve's ω+ (`impulse.rs`), both against the exact solution
/// ω* = (c x_p' - s (z_p' - z_s'))/(L q) of the Newton-Euler system at the doubles
/// s = fl(sin θ), c = fl(cos θ), q = s² + c².
///
/// C.15 as evaluated: every term of its numerator passes through at most 6 roundings
/// (L s, z_p' - z_s', the product, the difference, L L, the quotient): γ_6 T/L with
/// T = |s||z_p' - z_s'| + |c||x_p'|; its exact value is q ω*, and |q - 1| <= (1 + 2u)² - 1
/// <= γ_5, so |1 - 1/q| <= γ_10: together γ_16 T/L.
///
/// The solve (Oettli-Prager / Skeel): with r^ = fl(b - A^ x^) as computed, the true
/// residual and the data's rounding (1/m, L c, L s and z_s' - z_p': one each) give
/// |x* - x^| <= |A^-1| v, v = |r^| + γ_6 (|b^| + |A^| |x^|) (γ_4 the residual's own
/// 3-term dot products, γ_1 the data; γ_6 covers both); the ω row of A^-1 in closed form
/// is (-c, s, -1/m)/(L q): e_ω = (|c| v_1 + |s| v_2 + v_3/m)/(L q), evaluated with 8
/// roundings (1 + γ_8).
pub fn c15_rate_bound(at: &Impact) -> f64 {
    let (vxp, vzp) = at.tip_v_mps;
    let (l, m, x) = (at.length_m, at.mass_kg, at.ne_x());
    let (s, c) = at.y[TH].sin_cos();
    let uz = vzp - at.plate_v_mps;
    let t = s.abs() * uz.abs() + c.abs() * vxp.abs(); // formula: T = |s||z_p' - z_s'| + |c||x_p'|
    let c15 = gamma(16) * t / l; // formula: γ_6 T/L + γ_10 T/L
    // |A^| |x^| + |b^| row by row (rows: J_x/m - L c ω = -x_p'; J_z/m + L s ω = z_s' - z_p'; -c J_x + s J_z = 0)
    let size = [
        x[0].abs() / m + (l * c).abs() * x[2].abs() + vxp.abs(),
        x[1].abs() / m + (l * s).abs() * x[2].abs() + uz.abs(),
        c.abs() * x[0].abs() + s.abs() * x[1].abs(),
    ];
    let v: Vec<f64> = (0..3)
        .map(|i| at.ne_residual[i].abs() + gamma(6) * size[i]) // formula: v = |r^| + γ_6 (|A^||x^| + |b^|)
        .collect();
    let q = s * s + c * c; // formula: q = s² + c²
    // formula: e_ω = (|c| v_1 + |s| v_2 + v_3/m)/(L q)
    let solve = (1.0 + gamma(8)) * (c.abs() * v[0] + s.abs() * v[1] + v[2] / m) / (l * q);
    OWN * (c15 + solve) + UNDERFLOW
}

/// Bound (m/s) on |z_p' + L θ' sin θ - z_s'| after Algorithm 2's impulse-free assignment
/// θ' = -(z_p' - z_s')/(L sin θ) (C.3's z_c', exactly z_s' in exact arithmetic):
/// L θ' sin carries 5 roundings of |z_p' - z_s'| (the difference, L s, the quotient,
/// L θ', the product with s), the two sums one each of their operands:
/// γ_5 |z_p' - z_s'| + γ_2 (|z_p'| + |z_s'| + (1 + γ_5)|z_p' - z_s'|) <= γ_8 (|z_p'| + |z_s'| + 2 |z_p' - z_s'|).
pub fn free_landing_bound(at: &Impact) -> f64 {
    let (_, vzp) = at.tip_v_mps;
    let vs = at.plate_v_mps;
    // formula: γ_8 (|z_p'| + |z_s'| + 2 |z_p' - z_s'|)
    OWN * gamma(8) * (vzp.abs() + vs.abs() + 2.0 * (vzp - vs).abs()) + UNDERFLOW
}

/// Bound (m/s²) on |x_p''(C.10/C.13) - F_x/m| at a slide sample, both sides from the
/// same computed F_z: fl(fl(±μ F_z)/m) each, 2 roundings and an exact sign, so each side
/// is within γ_2 ≤ γ_3 of ±μ F_z/m: 2 γ_3 μ |F_z|/m.
pub fn x_row_bound(friction_mps2: f64) -> f64 {
    OWN * 2.0 * gamma(3) * friction_mps2 + UNDERFLOW // formula: 2 γ_3 μ |F_z|/m
}

/// Bound (m/s²) on the difference of C.14's x_c'' row and C.1 differentiated twice at a
/// slide sample (the same computed F_z, θ', θ'', sin, cos): each side is ±μ F_z/m (3
/// roundings with its subtraction) minus L (θ'' cos - θ'² sin) (θ'θ', times sin, θ''
/// cos, their sum, times L, the subtraction: 6): 2 (γ_3 μ|F_z|/m + γ_6 L (θ'²|sin| +
/// |θ''||cos|)), `lever` being the last sum (m/s²).
pub fn xc_row_bound(friction_mps2: f64, lever_mps2: f64) -> f64 {
    // formula: 2 (γ_3 μ|F_z|/m + γ_6 L (θ'²|sin| + |θ''||cos|)), its own sum rounded (1 + γ_2)
    OWN * (1.0 + gamma(2)) * 2.0 * (gamma(3) * friction_mps2 + gamma(6) * lever_mps2) + UNDERFLOW
}

/// Bound (N) on |F_z - m (g + z_s'')| + |F_x| for the vertical stick at rest (θ = θ₀ = 0,
/// θ' = 0 exactly): the table's sin_cos(0) = (0, 1) (a unit test) and the torque vanish exactly, so the pivot equations' θ''
/// and F_x are exactly 0 and their F_z is fl(m fl(z_s'' + g)), the closed form
/// fl(m fl(g + z_s'')): each within γ_2 of m (g + z_s''), the sum's rounding being
/// relative to its result: 2 γ_2 (1 + γ_2) |closed|.
pub fn vertical_pivot_bound(closed_n: f64) -> f64 {
    OWN * 2.0 * gamma(2) * (1.0 + gamma(2)) * closed_n.abs() + UNDERFLOW // formula: 2 γ_2 (1 + γ_2) |m (g + z_s'')|
}

/// Bound (N m) on C.8's residual at a pivot sample, q_t + F_x L cos - F_z L sin with F
/// from C.7 and θ'' from C.6 (q_t = k(θ - θ₀) + γ θ'). In exact arithmetic at the
/// computed θ'' it is (q - 1) m L² θ'' + m L² q e, q = s² + c² (|q - 1| <= γ_5), e the
/// error of θ'': θ'' = ((g + z_s'') m L s - q_t)/(m L L) rounds its numerator 5 times and
/// the quotient 4 (with m L L), e <= γ_9 τ/(m L²), τ = |g + z_s''| m L |s| + |k(θ - θ₀)| +
/// |γ θ'| (`torques`): together γ_15 τ. Its evaluation takes at most 10 roundings of every
/// expanded term: γ_10 times the same expression with every term's absolute value
/// (`terms`): |k(θ - θ₀)| + |γ θ'| + m L² |c| (θ'²|s| + |θ''||c|) + m L |s| (|z_s''| + g +
/// L (θ'²|c| + |θ''||s|)).
pub fn pivot_balance_bound(terms_nm: f64, torques_nm: f64) -> f64 {
    // formula: γ_10 terms + γ_16 τ, the sum rounded (1 + γ_2)
    OWN * (1.0 + gamma(2)) * (gamma(10) * terms_nm + gamma(16) * torques_nm) + UNDERFLOW
}

/// Bound (N m) on |m L² θ''| from C.6 where the torques cancel exactly (angular momentum
/// conserved): θ'' is within γ_9 τ/(m L²) (see [`pivot_balance_bound`]) and m L L θ''
/// rounds 3 times more: γ_12 τ, τ = `torques`.
pub fn conserved_rate_bound(torques_nm: f64) -> f64 {
    OWN * gamma(12) * torques_nm + UNDERFLOW // formula: γ_12 (|g + z_s''| m L |s| + |k(θ - θ₀)| + |γ θ'|)
}

/// Bound (N m) on C.8's residual q_t + F_x L cos - F_z L sin at a slide sample with F_z
/// from C.9 / C.11, F_z = q_t/(L (s + c_μ μ c)) (c_μ = -σ = ∓1, exact), and F_x = σ μ F_z
/// (q_t = k(θ - θ₀) + γ θ', the same double on both sides). At the computed F_z^ the
/// exact residual is q_t - F_z^ D, D = L (s - σ μ c); the computed denominator D^ rounds
/// μ c, the sum and the product with L: |D^ - D| <= γ_3 L (|s| + μ|c|), and
/// F_z^ D^ = q_t (1 + δ): |q_t - F_z^ D| <= u |q_t| + γ_3 |F_z^| L (|s| + μ|c|). The
/// residual's evaluation rounds q_t twice (the two sums), F_x L c five times (σ μ exact,
/// the products with F_z, L and c, the two sums) and F_z L s four times: together
/// γ_3 |q_t| + γ_8 |F_z| L (|s| + μ|c|), `lever` = |F_z| L (|s| + μ|c|) (N m).
pub fn slide_balance_bound(qt_nm: f64, lever_nm: f64) -> f64 {
    // formula: γ_3 |q_t| + γ_8 |F_z| L (|s| + μ|c|), its own sum rounded (1 + γ_2)
    OWN * (1.0 + gamma(2)) * (gamma(3) * qt_nm.abs() + gamma(8) * lever_nm) + UNDERFLOW
}

/// Bound (m/s²) on C.4's residual z_c'' - z_s'' at a slide-left sample, z_c'' = z_p'' -
/// L(-θ'² c - θ'' s) with θ'' = ((z_s'' - z_p'')/L + θ'² c)/s (the derived C.12): exactly
/// 0 at the computed z_p'', s, c (no trigonometric identity used). C.14's angle row for
/// the right slide is the same expression, so the bound holds at every slide sample. θ'' is within
/// γ_4 (|z_s'' - z_p''|/L + θ'²|c|)/|s| (4 roundings), an error that passes through the
/// residual's 4 later roundings (γ_4 (1 + γ_4) <= γ_8 after the product with L s); the
/// evaluation rounds every expanded term at most 6 times: γ_6 (|z_p''| + |z_s''| +
/// L θ'²|c| + L |θ''||s|) + γ_8 (|z_s'' - z_p''| + L θ'²|c|).
pub fn left_c4_bound(zpdd_mps2: f64, zsdd_mps2: f64, lever_mps2: f64, thdd_lever_mps2: f64) -> f64 {
    // formula: γ_6 (|z_p''| + |z_s''| + L θ'²|c| + L|θ''||s|) + γ_8 (|z_s'' - z_p''| + L θ'²|c|), summed (1 + γ_2)
    let terms = zpdd_mps2.abs() + zsdd_mps2.abs() + lever_mps2 + thdd_lever_mps2;
    let quotient = (zsdd_mps2 - zpdd_mps2).abs() + lever_mps2;
    OWN * (1.0 + gamma(2)) * (gamma(6) * terms + gamma(8) * quotient) + UNDERFLOW
}

/// Bound (rad/s) on C.3's relaxation residual θ' + (k/γ)(θ - θ₀) at a sample, the flight's
/// closed form (`flight.rs`) having set d = θ - θ₀, θ = fl(θ₀ + d) and θ' = fl(-(k/γ) d),
/// k/γ rounded once on each side: fl(θ₀ + d) carries an absolute u|θ| (3 roundings more
/// in the residual: γ_5 (k/γ)|θ|); the d terms differ by (1 + δ)² against (1 + δ)³ and the
/// sum rounds once: γ_6 (|θ'| + (k/γ)|θ - θ₀|). Together
/// γ_6 (|θ'| + (k/γ)(|θ - θ₀| + |θ|)), `rate` = k/γ (1/s).
pub fn relaxation_bound(omega_rad_s: f64, rate_per_s: f64, dev_rad: f64, theta_rad: f64) -> f64 {
    // formula: γ_6 (|θ'| + (k/γ)(|θ - θ₀| + |θ|)), its own sum rounded (1 + γ_2)
    OWN * (1.0 + gamma(2)) * gamma(6) * (omega_rad_s.abs() + rate_per_s.abs() * (dev_rad.abs() + theta_rad.abs()))
        + UNDERFLOW
}

/// Bound (rad) on the error of a landing angle's deviation θ - θ₀ as the run holds it
/// (`Landing::theta_rad` minus θ₀), against the exact closed-form angle at the exact
/// landing time from the same take-off state: beyond it the landing angle differs from θ₀
/// by more than rounding can explain. The flight's closed form (`flight.rs`) sets
/// d = fl(d₀ fl(exp(fl(-r τ)))), d₀ = fl(θ_to - θ₀), τ = fl(t - t₀), r = fl(k/γ), and
/// θ = fl(θ₀ + d):
/// - d₀, exp (1 ulp: 2u) and the product: a relative γ_4 of |d|;
/// - the exponent rounds 3 times (r, τ, the product): exp moves by a relative
///   γ_3 r τ (to first order), and r τ = ln(|d₀|/|d|) < ln(π/|d|) (|θ| < π/2 on both
///   sides);
/// - the event time is located within t_tol = 4 ε max(|t|, 1) (`numerics::events`),
///   where θ moves at |θ'| = r |d|: r t_tol |d|;
/// - the addition θ₀ + d rounds by u |θ|, and the claim's θ - θ₀ by u |θ - θ₀|.
///
/// Together u (|θ| + |θ - θ₀|) + |d| (γ_4 + γ_3 ln(π/|d|) + r t_tol), `rate` = k/γ (1/s).
/// Every term but u |θ| is proportional to |d|, so the bound exceeds |d| only when |d| is
/// within a few ulps of θ: a landing "differs from θ₀" once |θ - θ₀| > u|θ| (1 + 1e-12)
/// roughly. Rests on the take-off angle's own integration error being below |d₀| (it
/// relaxes by the same factor).
pub fn landing_angle_bound(theta_rad: f64, dev_rad: f64, rate_per_s: f64, t_s: f64) -> f64 {
    let u = crate::numerics::rounding::U;
    let d = dev_rad.abs();
    let t_tol = 4.0 * f64::EPSILON * t_s.abs().max(1.0); // formula: t_tol = 4 ε max(|t|, 1)
    let log = (std::f64::consts::PI / d.max(f64::MIN_POSITIVE)).ln().max(0.0); // formula: r τ < ln(π/|d|)
    // formula: u (|θ| + |θ - θ₀|) + |d| (γ_4 + γ_3 ln(π/|d|) + r t_tol)
    OWN * (1.0 + gamma(2)) * (u * (theta_rad.abs() + d) + d * (gamma(4) + gamma(3) * log + rate_per_s * t_tol))
        + UNDERFLOW
}

/// Bound on C.15's axis test, `off` = |a x h|/|h| as computed (h = (0, h_y, 0), its zero
/// components exact): every component of a x h is one product of two entries (or one
/// minus an exact 0), the norm and the quotient round relatively: the computed value
/// is within γ_5 of the exact |a x ĥ|, relatively, so it is exactly 0 when (and only
/// when, barring underflow) the axis is parallel: the bound is 0.
pub const AXIS_BOUND: f64 = 0.0; // formula: |off^ - off| <= γ_5 off^, off = 0 <=> off^ = 0

#[cfg(test)]
mod tests {
    use super::super::at_states::impact;
    use super::*;
    use crate::physics::stick::{authors_scene, Mode, StickModel, NSTATE, OM, VXC, VZC, ZC};

    /// Landing states of the authors' scene at several angles and rates, both leanings.
    fn landings() -> Vec<Impact> {
        let m = StickModel::new(authors_scene(10.0));
        let mut v = Vec::new();
        for th in [-1.2, -0.3, 0.05, 0.3, 0.9] {
            for om in [-3.0, 0.5, 2.0] {
                let mut y = [0.0; NSTATE];
                (y[TH], y[OM], y[VXC], y[VZC]) = (th, om, 0.4, -1.0);
                y[ZC] = m.plate(0.01).0;
                v.push(impact(0, &m, 0.01, y, Mode::Pivot));
            }
        }
        v
    }

    #[test]
    fn the_c15_bound_holds_and_a_1e9_relative_error_exceeds_it() {
        for at in landings() {
            let ((ux, uz), (rx, rz)) = at.geometry(true);
            let l = at.length_m;
            let om = -(rx * uz - rz * ux) / (l * l);
            let (ne, bound) = (at.ne.omega_after, c15_rate_bound(&at));
            assert!((om - ne).abs() <= bound, "{om} vs {ne}: bound {bound:e}");
            assert!(bound < 1e-13 * ne.abs(), "bound {bound:e} at ω {ne}");
            assert!((om * (1.0 + 1e-9) - ne).abs() > bound);
            assert!((om - ne * (1.0 + 1e-9)).abs() > bound);
        }
    }

    #[test]
    fn the_free_landing_bound_holds_and_a_1e9_relative_error_exceeds_it() {
        for at in landings() {
            let (_, vzp) = at.tip_v_mps;
            let vs = at.plate_v_mps;
            let (l, s) = (at.length_m, at.y[TH].sin());
            let bound = free_landing_bound(&at);
            let om = -(vzp - vs) / (l * s);
            assert!((vzp + l * om * s - vs).abs() <= bound);
            let off = om * (1.0 + 1e-9);
            assert!((vzp + l * off * s - vs).abs() > bound, "bound {bound:e}");
        }
    }

    #[test]
    fn the_x_row_bounds_hold_and_a_1e9_relative_error_exceeds_them() {
        let (mu, mass, l) = (0.4f64, 1.0f64, 0.15f64);
        let states: [(f64, f64, f64, f64); 3] =
        [(3.0, 2.0, -40.0, 0.7), (0.2, -9.0, 300.0, -1.1), (12.0, 0.1, 5.0, 0.05)];
        for (fz, w, thdd, th) in states {
            let (s, co) = f64::sin_cos(th);
            let fx = -mu * fz;
            let friction = mu * f64::abs(fz) / mass;
            let xpdd = -mu * fz / mass;
            assert!((xpdd - fx / mass).abs() <= x_row_bound(friction));
            assert!((xpdd * (1.0 + 1e-9) - fx / mass).abs() > x_row_bound(friction));
            let lever = l * w * w * s.abs() + l * thdd.abs() * co.abs();
            let bound = xc_row_bound(friction, lever);
            let doc = -mu * fz / mass - l * (-w * w * s + thdd * co);
            let kin = fx / mass - l * (thdd * co - w * w * s);
            assert!((doc - kin).abs() <= bound);
            assert!(bound < 2e-15 * (friction + lever));
            // a 1e-9 relative error in the friction term or in C.1's lever term fails
            assert!(((-mu * fz / mass) * (1.0 + 1e-9) - l * (-w * w * s + thdd * co) - kin).abs() > bound);
            assert!((doc - fx / mass + l * (thdd * co - w * w * s) * (1.0 + 1e-9)).abs() > bound);
        }
    }

    #[test]
    fn the_pivot_c4_and_relaxation_bounds_hold_and_a_1e9_relative_error_exceeds_them() {
        let (m, l, g, k, gam, th0) = (0.01f64, 0.15f64, 9.81f64, 0.05f64, 0.002f64, 0.1f64);
        for (th, w, a_s) in [(0.3f64, 2.0f64, -40.0f64), (-1.1, -9.0, 300.0), (0.05, 0.1, 5.0)] {
            let (s, co) = th.sin_cos();
            let q_t = k * (th - th0) + gam * w;
            let thdd = ((g + a_s) * m * l * s - q_t) / (m * l * l);
            let (fx, fz) = (m * l * (-w * w * s + thdd * co), m * (a_s + l * (-w * w * co - thdd * s) + g));
            let c8 = q_t + fx * l * co - fz * l * s;
            let tau = (g + a_s).abs() * m * l * s.abs() + q_t.abs().max((k * (th - th0)).abs() + (gam * w).abs());
            let terms = (k * (th - th0)).abs() + (gam * w).abs() + m * l * l * co.abs() * (w * w * s.abs() + thdd.abs() * co.abs())
                + m * l * s.abs() * (a_s.abs() + g + l * (w * w * co.abs() + thdd.abs() * s.abs()));
            let b = pivot_balance_bound(terms, tau);
            assert!(c8.abs() <= b && (fz * l * s * 1e-9).abs() > b, "{c8:e} vs {b:e}");
            assert!((m * l * l * thdd).abs() > conserved_rate_bound(tau));
            // C.4 with the derived C.12, and a 1e-9 relative error in θ''
            let zpdd = 3.0 * a_s.signum() - g;
            let t12 = ((a_s - zpdd) / l - w * w * co) / s;
            let (lever, tl) = (l * w * w * co.abs(), l * (t12 * s).abs());
            let b4 = left_c4_bound(zpdd, a_s, lever, tl);
            let r4 = (zpdd - l * (-w * w * co - t12 * s) - a_s).abs();
            assert!(r4 <= b4, "{th} {r4:e} {b4:e}");
            assert!((zpdd - l * (-w * w * co - t12 * (1.0 + 1e-9) * s) - a_s).abs() > b4);
            // C.3 after the flight's closed form, and a 1e-9 relative error in θ'
            let (rate, d) = (k / gam, (th - th0) * 0.37);
            let (tf, wf) = (th0 + d, -(k / gam) * d);
            let br = relaxation_bound(wf, rate, tf - th0, tf);
            assert!((wf + rate * (tf - th0)).abs() <= br);
            assert!((wf * (1.0 + 1e-9) + rate * (tf - th0)).abs() > br);
        }
    }

    #[test]
    fn the_slide_balance_bound_holds_and_a_1e9_relative_error_exceeds_it() {
        let (l, k, gam, th0, mu) = (0.15f64, 10.0f64, 0.01f64, 0.3f64, 0.4f64);
        for (th, w) in [(0.3f64, 2.0f64), (-1.1, -9.0), (0.05, 0.1), (0.9, 40.0), (0.31, -0.02)] {
            let (s, co) = th.sin_cos();
            let q_t = k * (th - th0) + gam * w;
            for sigma in [1.0f64, -1.0] {
                let fz = q_t / (l * (s + -sigma * mu * co)); // C.9 / C.11
                let fx = sigma * mu * fz;
                let res = q_t + fx * l * co - fz * l * s;
                let b = slide_balance_bound(q_t, fz.abs() * l * (s.abs() + mu * co.abs()));
                assert!(res.abs() <= b, "{th} {sigma}: {res:e} vs {b:e}");
                // a 1e-9 relative error in F_z (or in F_x) fails
                let off = q_t + fx * l * co - fz * (1.0 + 1e-9) * l * s;
                let off_x = q_t + fx * (1.0 + 1e-9) * l * co - fz * l * s;
                assert!(off.abs() > b && off_x.abs() > b, "{th} {sigma}: bound {b:e}");
            }
        }
    }

    #[test]
    fn the_landing_angle_bound_holds_and_a_1e9_relative_deviation_exceeds_it() {
        let (th0, rate) = (0.3f64, 1000.0f64);
        for d0 in [0.05f64, -0.2, 1e-3] {
            for (t0, tau) in [(0.0f64, 0.004f64), (3.7, 0.021), (811.0, 0.035)] {
                let t1: f64 = t0 + tau;
                let tau_c = t1 - t0; // the rounded flight time
                let d = d0 * (-rate * tau_c).exp(); // flight.rs
                let th = th0 + d;
                // reference: the same deviation by a different rounding path (half steps)
                let half = (-rate * tau_c / 2.0).exp();
                let d_ref = d0 * half * half;
                let b = landing_angle_bound(th, th - th0, rate, t1);
                assert!(((th - th0) - d_ref).abs() <= b, "{d0} {tau}: {:e} vs {b:e}", (th - th0) - d_ref);
                // the event time off by its tolerance moves θ within the bound
                let t_tol = 4.0 * f64::EPSILON * t1.max(1.0);
                let d_late = d0 * (-rate * (tau_c + t_tol)).exp();
                assert!(((th - th0) - d_late).abs() <= b);
                // a deviation of 1e-9 of θ₀ is far beyond the bound
                assert!(b < 1e-9 * th0 || d.abs() > 1e-9 * th0);
                assert!(1e-9 * th0 > landing_angle_bound(th0 + 1e-9 * th0, 1e-9 * th0, rate, t1));
            }
        }
        // a landing at θ₀ exactly (fully relaxed) does not count as different
        assert!(landing_angle_bound(th0, 0.0, rate, 5.0) > 0.0);
    }

    #[test]
    fn the_vertical_pivot_and_axis_bounds_reject_a_1e9_relative_error() {
        // the bound rests on the pivot equations' trigonometry being exact at 0
        assert_eq!(crate::numerics::trig::sin_cos(0.0), (0.0, 1.0));
        let (m, g) = (1.0f64, 9.81f64);
        for a_s in [-4.9f64, 0.0, 3.3] {
            let closed = m * (g + a_s);
            let fz = m * (a_s + g);
            assert!((fz - closed).abs() <= vertical_pivot_bound(closed));
            assert!((fz * (1.0 + 1e-9) - closed).abs() > vertical_pivot_bound(closed));
        }
        // an axis tilted by 1e-9 rad off j: |a x h|/|h| = 1e-9 > 0
        let (a, hy) = ([1e-9f64, -1.0, 0.0], 0.37f64);
        let off = (a[0] * hy).abs().max((a[2] * hy).abs()) / hy.abs();
        assert!(off > AXIS_BOUND);
    }
}
