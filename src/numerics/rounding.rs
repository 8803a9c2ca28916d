//! The floating-point rounding model that the chapters' rounding bounds share
//! (chapter 2's `effective_mass/rounding.rs`, chapter 6's `stick_state_machine/rounding.rs`).
//!
//! IEEE binary64 with unit roundoff u = 2^-53: `fl(a op b) = (a op b)(1 + δ)`, |δ| <= u;
//! a product of k factors (1 + δ_i)^(±1) lies within 1 ± γ_k, `γ_k = k u/(1 - k u)`
//! (Higham, *Accuracy and Stability of Numerical Algorithms*, lemma 3.1), and
//! γ_a + γ_b <= γ_(a+b).

/// The unit roundoff u = 2^-53.
pub const U: f64 = f64::EPSILON / 2.0;

/// A bound evaluated in floating point is itself rounded, by a relative γ_k with k
/// below 100 (1e-14): every bound is multiplied by 1 + 1e-12.
pub const OWN: f64 = 1.0 + 1e-12;

/// An absolute allowance for gradual underflow: each underflowing operation adds at
/// most η/2 (η = 2^-1074), a quantity passes through fewer than 100 of them and no step
/// magnifies by more than 1e4: 1e6 η.
pub const UNDERFLOW: f64 = 5e-318; // formula: >= 1e6 η, η = 2^-1074 = 4.94e-324

/// A libm sin, cos, tan or atan within 1 ulp: a relative error below 2u, counted as
/// two roundings.
pub const TRIG: u32 = 2;

/// `γ_k = k u / (1 - k u)`.
pub fn gamma(k: u32) -> f64 {
    let ku = k as f64 * U;
    ku / (1.0 - ku) // formula: γ_k = k u/(1 - k u)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_is_k_unit_roundoffs_to_first_order_and_subadditive() {
        assert_eq!(U, 2f64.powi(-53));
        assert!((gamma(10) / (10.0 * U) - 1.0).abs() < 1e-14);
        assert!(gamma(3) + gamma(4) <= gamma(7));
    }
}
