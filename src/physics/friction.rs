//! Friction laws between a block and its support, and their cycle-averaged (dither) forms.
//!
//! All forces here are **per unit mass** (m/s^2): the block's mass cancels from every
//! law of section 3.1, so the models never carry it.
//!
//! - [`FrictionLaw::Coulomb`]: set-valued Coulomb friction. Sticking (`v_rel = 0`) needs a
//!   tangential force `f` with `|f| <= mu n`; sliding gets `f = -mu n sign(v_rel)`
//!   (document section 3.2.2, "Eqn. 3 of the main paper").
//! - [`FrictionLaw::Viscous`]: linear friction `f = -c v_rel` with `c` per unit mass (1/s)
//!   (section 3.2.1); independent of the normal force while in contact.
//! - [`FrictionLaw::NoSlip`]: infinite friction: the block never slips while in contact.
//!   Not physical; used to switch "slip before take-off" off in the vertical-shaking chapter.
//! - [`ImpactFriction`]: the tangential rule at a landing impact.
//! - Averaged laws: [`averaged_coulomb_force`] (the arcsin law of horizontal dither) and
//!   [`averaged_drift_velocity`] (its inverse under a bias force).

use std::f64::consts::PI;

/// The tangential friction law while the block touches the plate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FrictionLaw {
    /// Coulomb friction with coefficient `mu` (dimensionless, >= 0).
    Coulomb {
        /// Friction coefficient mu.
        mu: f64,
    },
    /// Linear viscous friction `f = -c_per_s v_rel` (force per unit mass, c in 1/s).
    Viscous {
        /// Viscous coefficient per unit mass c (1/s).
        c_per_s: f64,
    },
    /// The block cannot slip while in contact (infinite friction coefficient).
    NoSlip,
}

impl FrictionLaw {
    /// The Coulomb coefficient, if the law is Coulomb.
    pub fn mu(&self) -> Option<f64> {
        match self {
            FrictionLaw::Coulomb { mu } => Some(*mu),
            _ => None,
        }
    }
}

/// The tangential rule at an impact (landing) of the block on the plate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImpactFriction {
    /// Tangential impulse limited by mu times the normal impulse (mu of the Coulomb
    /// contact law; no tangential impulse for a viscous law, full sticking for
    /// [`FrictionLaw::NoSlip`]): the block sticks if it can, else it slides on with a
    /// reduced relative velocity.
    Coulomb,
    /// Every impact kills the tangential relative velocity (the document's "instantaneous
    /// sticking collisions" of section 3.1.2).
    Sticking,
    /// No tangential impulse: the relative tangential velocity passes through.
    Frictionless,
}

/// Outcome of the sticking test of set-valued Coulomb friction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StickTest {
    /// The needed force lies inside the cone: the block sticks.
    Sticks,
    /// The needed force exceeds `+mu n`: the block slips towards -x relative to the plate
    /// (friction then pushes it with `+mu n`).
    SlipsLeft,
    /// The needed force is below `-mu n`: the block slips towards +x relative to the plate.
    SlipsRight,
}

/// Coulomb's sticking test: the tangential force per unit mass `needed` to keep the
/// block at rest relative to the plate against the normal force per unit mass `n`.
pub(crate) fn stick_test(needed: f64, n: f64, mu: f64) -> StickTest {
    // formula: stick iff |f_needed| <= mu N
    if needed.abs() <= mu * n {
        StickTest::Sticks
    } else if needed > 0.0 {
        StickTest::SlipsLeft
    } else {
        StickTest::SlipsRight
    }
}

/// The relative tangential velocity after an impact with normal impulse per unit mass
/// `p_n >= 0` (m/s) and coefficient `mu`: stick if `|w| <= mu p_n`, else slide on with
/// `w - mu p_n sign(w)` (tangential impulse limited by the cone).
pub(crate) fn coulomb_impact(w_mps: f64, p_n_mps: f64, mu: f64) -> f64 {
    // formula: |P_t| <= mu P_n; w+ = 0 if |w-| <= mu P_n, else w- - mu P_n sign(w-)
    if w_mps.abs() <= mu * p_n_mps {
        0.0
    } else {
        w_mps - mu * p_n_mps * w_mps.signum()
    }
}

/// Cycle-averaged Coulomb friction per unit mass on a block moving at the steady velocity
/// `v_mps` over a plate whose velocity is `V cos(omega t)` (horizontal dither), in the
/// limit where the block's own velocity fluctuation is negligible (m/s^2):
/// `-(2/pi) mu n arcsin(v/V)` for `|v| <= V`, and `-mu n sign(v)` beyond.
///
/// Derivation: the slip direction is `sign(v - V cos(phi))`; over one cycle it is +1 on
/// the fraction `1 - arccos(v/V)/pi` and -1 on `arccos(v/V)/pi`, so the mean friction is
/// `-mu n (1 - 2 arccos(v/V)/pi) = -(2/pi) mu n arcsin(v/V)`.
pub fn averaged_coulomb_force(
    v_mps: f64,
    plate_velocity_amplitude_mps: f64,
    mu: f64,
    n_mps2: f64,
) -> f64 {
    let ratio = v_mps / plate_velocity_amplitude_mps;
    if ratio.abs() >= 1.0 {
        -mu * n_mps2 * ratio.signum()
    } else {
        -(2.0 / PI) * mu * n_mps2 * ratio.asin() // formula: <f> = -(2/pi) mu N arcsin(v/V)
    }
}

/// Effective viscous coefficient per unit mass of the averaged Coulomb law at small
/// velocity (1/s): `2 mu n / (pi V)`.
pub(crate) fn effective_viscous_coefficient(
    plate_velocity_amplitude_mps: f64,
    mu: f64,
    n_mps2: f64,
) -> f64 {
    2.0 * mu * n_mps2 / (PI * plate_velocity_amplitude_mps) // formula: c = 2 mu N/(pi V) (small v)
}

/// Steady drift velocity of the averaged law under a bias force `bias = F/(mu m n)`
/// (fraction of the Coulomb limit, `|bias| < 1`): `V sin(pi bias / 2)` (m/s).
pub fn averaged_drift_velocity(bias: f64, plate_velocity_amplitude_mps: f64) -> f64 {
    plate_velocity_amplitude_mps * (PI * bias / 2.0).sin() // formula: v = V sin(pi b/2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn averaged_law_matches_a_direct_cycle_average() {
        // Midpoint rule over 200000 phases: the slip-direction function has two jumps,
        // so the quadrature error is ~ 2/200000 of mu n.
        let (mu, n, vamp) = (0.36, 9.81, 0.3);
        for v in [0.0, 0.05, 0.15, 0.29, -0.2] {
            let k = 200_000;
            let mean: f64 = (0..k)
                .map(|i| {
                    let phi = (i as f64 + 0.5) * 2.0 * PI / k as f64;
                    -mu * n * (v - vamp * phi.cos()).signum()
                })
                .sum::<f64>()
                / k as f64;
            let law = averaged_coulomb_force(v, vamp, mu, n);
            assert!((mean - law).abs() < 1e-4 * mu * n, "v {v}: {mean} vs {law}");
        }
        // The averaged drift inverts the law: <f> + bias = 0.
        let b = 0.4;
        let v = averaged_drift_velocity(b, vamp);
        assert!((averaged_coulomb_force(v, vamp, mu, n) + b * mu * n).abs() < 1e-12);
        // Small-v slope is the effective viscous coefficient.
        let dv = 1e-6;
        let slope = -averaged_coulomb_force(dv, vamp, mu, n) / dv;
        assert!((slope - effective_viscous_coefficient(vamp, mu, n)).abs() < 1e-6 * slope);
    }

    #[test]
    fn stick_test_and_impact_rule() {
        assert_eq!(stick_test(0.5, 2.0, 0.3), StickTest::Sticks);
        assert_eq!(stick_test(0.7, 2.0, 0.3), StickTest::SlipsLeft);
        assert_eq!(stick_test(-0.7, 2.0, 0.3), StickTest::SlipsRight);
        assert_eq!(coulomb_impact(0.1, 1.0, 0.3), 0.0);
        assert!((coulomb_impact(0.5, 1.0, 0.3) - 0.2).abs() < 1e-15);
        assert!((coulomb_impact(-0.5, 1.0, 0.3) + 0.2).abs() < 1e-15);
    }
}
