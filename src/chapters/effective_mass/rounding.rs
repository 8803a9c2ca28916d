//! Rounding bounds of the chapter's computed quantities (issue 29 §2): rigorous, from the
//! run's own numbers, one per way a quantity is computed. Pure arithmetic on the raw
//! quantities `evidence.rs` carries (the matrices as built, the computed inverses and
//! their computed residuals); the derivation is in `chapters/02-effective-mass.md`
//! ("How exact are the checks?") and the measured headroom in
//! `docs/effective-mass-rounding.md`.
//!
//! Model: IEEE binary64 with unit roundoff u = 2^-53, `fl(a op b) = (a op b)(1 + δ)`,
//! |δ| <= u, and `γ_k = k u/(1 - k u)`; sin, cos and tan of the platform's libm within
//! 1 ulp, counted as two roundings each ([`TRIG`]). The "exact" value of a quantity is
//! the exact mathematics at the double θ the run holds and at the double constants
//! (L = fl(0.15), m = 1 kg), with I_G = m L²/12 exact.

pub use crate::numerics::rounding::{gamma, OWN, TRIG, U, UNDERFLOW};
use nalgebra::{Matrix2, Matrix5, Vector5};

// UNDERFLOW (numerics::rounding) is reached only at |θ| below ~1e-300 rad, the flag's
// corner 1e-308 degrees; the 5x5 system's ||A^-1|| is below 1e3 there.

/// A 2x2 inversion as it ran: the mobility W^ as built, its computed inverse M^ (the
/// rod's world-frame mass matrix, kg) and the computed residual fl(I - W^ M^).
#[derive(Debug, Clone, Copy)]
pub struct Inversion2 {
    /// W^ (m/s per N s).
    pub mobility: Matrix2<f64>,
    /// M^ = inv(W^) as computed (kg).
    pub inverse: Matrix2<f64>,
    /// fl(I - W^ M^), as computed.
    pub residual: Matrix2<f64>,
}

/// A 5x5 solve as it ran: A^ and b as built and the computed x^ with the computed
/// residual fl(b - A^ x^).
#[derive(Debug, Clone, Copy)]
pub struct Solve5 {
    /// A^ (the Newton-Euler impulse equations, unknowns dv_G, dω, J).
    pub a: Matrix5<f64>,
    /// b (C's velocity change, m/s).
    pub b: Vector5<f64>,
    /// x^ as computed.
    pub x: Vector5<f64>,
    /// fl(b - A^ x^).
    pub residual: Vector5<f64>,
}

/// Row-sum (∞) norm of a 2x2 matrix's absolute value.
fn norm2(m: &Matrix2<f64>) -> f64 {
    m.abs().row_sum().max()
}

/// Largest entry error (kg) of the rod's computed mass matrix M^ against the exact
/// M(θ) = W(θ)^-1: the inversion's a posteriori bound plus the data error of W^.
pub fn mass_matrix_error(inv: &Inversion2) -> f64 {
    let (w, m) = (&inv.mobility, &inv.inverse);
    // formula: |I - W^ M^| <= |R^| + γ_3 (I + |W^| |M^|), g = its ∞-norm
    let g = norm2(&(inv.residual.abs() + (Matrix2::identity() + w.abs() * m.abs()) * gamma(3)));
    if g.is_nan() || g >= 1.0 {
        return f64::INFINITY;
    }
    let e_inv = norm2(m) * g / (1.0 - g); // formula: ||W^-1 - M^|| <= ||M^|| g/(1 - g)
    let x = norm2(m) + e_inv; // formula: ||inv(W^)|| <= ||M^|| + e_inv
    let d = gamma(13) * norm2(w); // formula: |W^ - W| <= γ_13 |W^| (11 to 12 roundings per entry)
    if (x * d).is_nan() || x * d >= 1.0 {
        return f64::INFINITY;
    }
    let e_data = x * x * d / (1.0 - x * d); // formula: ||W^-1 - inv(W^)|| <= ||X||² d/(1 - ||X|| d)
    OWN * (e_inv + e_data)
}

/// Entry error bound (kg) of the mass matrix in stick coordinates, `R^T M^ R` as
/// computed (`in_stick_frame`), from the world-frame bound `e_m` and the largest entry
/// of M^: R^T (M^ - M) R carries e_m into at most (|sin| + |cos|)² (1 + γ_4) e_m <=
/// 2 (1 + γ_4) e_m; the rounded R (trig, 2u an entry: γ_4 on R^T M R) and the two
/// rounded 2x2 products (γ_4) add γ_8 |R|^T |M| |R| <= 2 (1 + γ_4) γ_8 (max|M^| + e_m).
pub fn stick_error(e_m: f64, inv: &Inversion2) -> f64 {
    let big = inv.inverse.amax();
    // formula: 2 (1 + γ_4)((1 + γ_9) e_M + γ_9 max|M^|)
    OWN * 2.0 * (1.0 + gamma(4)) * ((1.0 + gamma(9)) * e_m + gamma(9) * big)
}

/// Error bound of a computed quotient fl(n^/d^) against n/d, with |n^ - n| <= e_n and
/// |d^ - d| <= e_d: (e_n + |n^/d^| e_d)/(|d^| - e_d) plus the division's rounding.
pub fn quotient_error(n: f64, d: f64, e_n: f64, e_d: f64) -> f64 {
    if d.is_nan() || e_d.is_nan() || d.abs() <= e_d {
        return f64::INFINITY;
    }
    let q = (n / d).abs() * (1.0 + U);
    OWN * ((e_n + q * e_d) / (d.abs() - e_d) + U * q) + UNDERFLOW // formula: (e_n + |q| e_d)/(|d^| - e_d) + u |q|
}

/// The rod's J_ℓ/J_v from its mass matrix, M^_xz/M^_zz (`jam_ratio`): the smaller of
/// two rigorous bounds. (a) The inversion's a posteriori bound carried through the
/// quotient (any inversion method). (b) The formula nalgebra evaluates for a 2x2
/// inverse, adj(W^)/det^ (pinned by a unit test): det^ cancels exactly from the quotient,
/// fl(fl(-W^_xz/det^)/fl(W^_xx/det^)) is -W^_xz/W^_xx to γ_3, and W^_xz, W^_xx carry
/// γ_11 and γ_12 from θ: γ_26 against the exact ratio, γ_27 of the computed one, which
/// stays relative where the ratio goes to 0 (θ near 0 and 90 degrees).
pub fn rod_ratio_error(inv: &Inversion2) -> f64 {
    let e = mass_matrix_error(inv);
    let (n, d) = (inv.inverse[(0, 1)], inv.inverse[(1, 1)]);
    let by_residual = quotient_error(n, d, e, e);
    let by_formula = OWN * gamma(27) * (n / d).abs() + UNDERFLOW; // formula: γ_27 |ρ^|
    by_residual.min(by_formula)
}

/// The point mass's J_ℓ/J_v from its rank-one matrix m u u^T (`effective_mass` with
/// I_G = 0), as evaluated: fl(fl(m u_x) u_z)/fl(fl(m u_z) u_z) with u = r/|r|,
/// r = -L (sin θ, cos θ). Every factor cancels but the roundings: 2 (m u), 2 (times
/// u_z), 1 (division), 2 (normalize: r_x/|r|, r_z/|r|), 2 (-L sin, -L cos) and 2 TRIG:
/// a relative γ_13 against tan θ, γ_14 of the computed value.
pub fn point_mass_ratio_error(ratio: f64) -> f64 {
    OWN * gamma(9 + 2 * TRIG + 1) * ratio.abs() + UNDERFLOW // formula: γ_14 |ρ^|
}

/// |A^-1| of the Newton-Euler system in closed form, from its entries m, I_G and
/// r = C - G (A's rows: m v - J = ., I_G w + r_z J_x - r_x J_z = ., v + w perp(r) = .).
/// Eliminating v and J leaves w (I_G + m |r|²) = r3 - r_z (m r4 - r1) + r_x (m r5 - r2),
/// a denominator without cancellation; every entry of the inverse is a signed product
/// over D = I_G + m |r|², so |A^-1| is a sum of products of |r_x|, |r_z|, m and I_G.
fn abs_inverse(a: &Matrix5<f64>) -> Matrix5<f64> {
    let (m, i, rz, rx) = (a[(0, 0)], a[(2, 2)], a[(2, 3)], -a[(2, 4)]);
    let (x, z, xz) = (rx.abs(), rz.abs(), (rx * rz).abs());
    let (ax, az) = (i + m * rx * rx, i + m * rz * rz); // formula: I_G + m r_x², I_G + m r_z²
    let d = i + m * (rx * rx + rz * rz); // formula: D = I_G + m |r|²
    #[rustfmt::skip]
    let n = Matrix5::new(
        z * z,  xz,     z,     ax,         m * xz,     // dv_G,x = r4 + r_z w
        xz,     x * x,  x,     m * xz,     az,         // dv_G,z = r5 - r_x w
        z,      x,      1.0,   m * z,      m * x,      // w
        ax,     m * xz, m * z, m * ax,     m * m * xz, // J_x = m dv_G,x - r1
        m * xz, az,     m * x, m * m * xz, m * az,     // J_z = m dv_G,z - r2
    );
    n / d
}

/// Componentwise error bound of the 5x5 solve x^ against the exact x(θ): with the
/// true residual r_t = b - A^ x^ and A^ = A(θ) + δA, x(θ) - x^ = A(θ)^-1 (r_t + δA x^),
/// so (Oettli-Prager / Skeel) |x - x^| <= |A^-1| (|r^| + γ_6 (|A^| |x^| + |b|) +
/// γ_4 |A^| |x^|): γ_6 the residual's own rounding (5-term dot products), γ_4 the data
/// (r = -(L/2)(sin θ, cos θ) or -L(...): TRIG + 1 roundings; I_G = m L L/12: 3).
/// |A^-1| from its closed form ([`abs_inverse`]), evaluated from the rounded entries: a
/// sum of products of at most 12 rounded factors over D (<= 9): 1 + γ_30 covers it.
/// (The computed inverse's norm would smear ||A^-1|| over every entry and could not
/// vouch for J_z ~ m cos²θ near 90 degrees, which the LU gets to full precision.)
pub fn solve_error(s: &Solve5) -> Vector5<f64> {
    let abs_a = s.a.abs();
    // formula: |r_t| + |δA| |x^| <= |r^| + γ_10 (|A^| |x^| + |b|)
    let v = s.residual.abs() + (abs_a * s.x.abs() + s.b.abs()) * gamma(10);
    let e = abs_inverse(&s.a) * v * (1.0 + gamma(30)); // formula: |A^-1| v
    (e * OWN).add_scalar(UNDERFLOW)
}

/// J_ℓ/J_v = x_4/x_5 from the 5x5 solve, with [`solve_error`].
pub fn newton_euler_ratio_error(s: &Solve5) -> f64 {
    let e = solve_error(s);
    quotient_error(s.x[3], s.x[4], e[3], e[4])
}

/// Evaluation error of the rod's law a q/(c + q²) at q = fl(tan θ) (c > 0, no
/// cancellation): 4 roundings, and tan's 2u, passed on at most once by the law's relative
/// sensitivity to q, |c - q²|/(c + q²) <= 1, plus 1 for the second order: γ_7 of the
/// exact law, γ_8 of the computed value.
pub fn rod_law_error(value: f64) -> f64 {
    OWN * gamma(4 + TRIG + 2) * value.abs() + UNDERFLOW // formula: γ_8 |a q/(c + q²)|
}

/// Evaluation error of the point mass's law k q at q = fl(tan θ): TRIG + 1, γ_4 of the
/// computed value.
pub fn point_mass_law_error(value: f64) -> f64 {
    OWN * gamma(TRIG + 2) * value.abs() + UNDERFLOW // formula: γ_4 |k q|
}

/// A sum of rounded terms: `γ_k` times the sum of the magnitudes involved (`size`).
pub fn terms_error(k: u32, size: f64) -> f64 {
    OWN * gamma(k) * size + UNDERFLOW // formula: γ_k Σ|terms|
}

/// The error of a computed value at the rounded angle θ^ = fl(θ₀) against the exact
/// value at the document's θ₀: `slope` (a bound on the value's θ-derivative near θ₀)
/// times |θ^ - θ₀| <= u |θ^| (θ^ correctly rounded: `FRAC_PI_4`).
pub fn angle_error(slope: f64, theta: f64) -> f64 {
    OWN * slope.abs() * U * theta.abs() * (1.0 + 1e-6) // formula: |f'(θ)| u |θ|
}
