//! Closed forms for a Coulomb block on the smooth asymmetric drive
//! `v_p = V (sin(theta) + eps cos(2 theta))`, `theta = omega t` ([`Biharmonic`]).
//!
//! Velocities are in units of `V`, time in radians of `theta`; the friction bound
//! `k = mu g` enters through the drive number `Gamma = V omega / (mu g)`: in these units
//! the block's slip acceleration is `+-1/Gamma` per radian.
//!
//! - **Always slipping** (large `Gamma`): the block's velocity is a triangle wave that
//!   meets the plate twice a period, at `theta_1 = pi - asin(pi/(2 Gamma))` and
//!   `theta_1 + pi`; its mean is exactly `eps V (1 - pi^2 / (2 Gamma^2))`, tending to
//!   `eps V` (the median of `v_p` over a period, for `|eps| < 1/2`).
//! - **Stuck for good** (`Gamma <= Gamma_stick(eps)`): the plate's acceleration never
//!   exceeds `mu g`, so a block that once moves with the plate stays with it: no drift.
//!
//! [`Biharmonic`]: crate::physics::plate::Biharmonic

use std::f64::consts::{PI, TAU};

/// `f(theta) = sin(theta) + eps cos(2 theta)`: plate velocity in units of `V`.
pub(crate) fn plate_velocity(eps: f64, theta: f64) -> f64 {
    theta.sin() + eps * (2.0 * theta).cos() // formula: v_p / V
}

/// `f'(theta) = cos(theta) - 2 eps sin(2 theta)`: plate acceleration in units of `V omega`.
pub(crate) fn plate_acceleration(eps: f64, theta: f64) -> f64 {
    theta.cos() - 2.0 * eps * (2.0 * theta).sin() // formula: a_p / (V omega)
}

/// Largest `|f'|` over a period: `sqrt(1 - s^2) |1 - 4 eps s|` at
/// `s = sin(theta) = (1 - sqrt(1 + 128 eps^2)) / (16 eps)` (`1` for `eps = 0`).
pub(crate) fn peak_acceleration(eps: f64) -> f64 {
    if eps == 0.0 {
        return 1.0;
    }
    // formula: d/ds[(1 - s^2)(1 - 4 eps s)^2] = 0  =>  8 eps s^2 - s - 4 eps = 0
    let s = (1.0 - (1.0 + 128.0 * eps * eps).sqrt()) / (16.0 * eps);
    (1.0 - s * s).sqrt() * (1.0 - 4.0 * eps * s).abs()
}

/// `Gamma_stick = 1 / max|f'|`: at or below it a block moving with the plate never slips.
pub fn stick_forever_gamma(eps: f64) -> f64 {
    1.0 / peak_acceleration(eps) // formula: V omega max|f'| <= mu g
}

/// The always-slipping periodic orbit of a Coulomb block on the bi-harmonic drive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipOrbit {
    /// Drive number `Gamma = V omega / (mu g)`.
    pub gamma: f64,
    /// Asymmetry eps.
    pub eps: f64,
    /// Phase where the block overtakes the plate and starts slowing down (rad).
    pub theta1: f64,
    /// Block velocity at `theta1` (its maximum), units of `V`.
    pub u_max: f64,
}

impl SlipOrbit {
    /// The orbit for `(gamma, eps)` if it exists: `Gamma >= pi/2`, the plate outruns
    /// friction at both meetings (`|f'| > 1/Gamma`, so the block cannot stick), and the
    /// block meets the plate nowhere else (checked on 4096 points of each half period).
    pub fn new(gamma: f64, eps: f64) -> Option<SlipOrbit> {
        let s = PI / (2.0 * gamma); // formula: sin(theta_1) = pi / (2 Gamma)
        if !(gamma.is_finite() && gamma > 0.0 && s <= 1.0 && eps.abs() < 0.5) {
            return None;
        }
        let theta1 = PI - s.asin();
        let orbit = SlipOrbit {
            gamma,
            eps,
            theta1,
            u_max: plate_velocity(eps, theta1),
        };
        let at_meetings = plate_acceleration(eps, theta1) < -1.0 / gamma
            && plate_acceleration(eps, theta1 + PI) > 1.0 / gamma;
        let n = 4096;
        let apart = (1..n).all(|i| {
            let th = theta1 + PI * i as f64 / n as f64;
            orbit.velocity(th) > plate_velocity(eps, th)
                && orbit.velocity(th + PI) < plate_velocity(eps, th + PI)
        });
        (at_meetings && apart).then_some(orbit)
    }

    /// Block velocity (units of `V`) at phase `theta`: slope `-1/Gamma` on
    /// `[theta1, theta1 + pi]`, `+1/Gamma` on the next half period.
    pub fn velocity(&self, theta: f64) -> f64 {
        let d = (theta - self.theta1).rem_euclid(TAU);
        if d <= PI {
            self.u_max - d / self.gamma // formula: u = u_max - (theta - theta_1)/Gamma
        } else {
            self.u_max - PI / self.gamma + (d - PI) / self.gamma
        }
    }

    /// Mean block velocity (units of `V`): `(u_max + u_min)/2 = eps (1 - pi^2/(2 Gamma^2))`.
    pub fn drift(&self) -> f64 {
        self.u_max - PI / (2.0 * self.gamma) // formula: u_max - pi/(2 Gamma)
    }
}

/// The always-slipping drift `eps (1 - pi^2 / (2 Gamma^2))` (units of `V`) where the
/// always-slipping orbit exists, else `None`.
pub fn always_slipping_drift(gamma: f64, eps: f64) -> Option<f64> {
    SlipOrbit::new(gamma, eps).map(|_| eps * (1.0 - PI * PI / (2.0 * gamma * gamma)))
    // formula: v_d/V = eps (1 - pi^2/(2 Gamma^2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn peak_acceleration_matches_a_dense_scan() {
        // A scan on 2e5 points finds the maximum to ~ (2 pi / 2e5)^2 relative.
        for eps in [-0.4, -0.1, 0.0, 0.05, 0.2, 0.45] {
            let n = 200_000;
            let scan = (0..n)
                .map(|i| plate_acceleration(eps, TAU * i as f64 / n as f64).abs())
                .fold(0.0, f64::max);
            assert!(
                (scan - peak_acceleration(eps)).abs() < 1e-8,
                "eps {eps}: {scan} vs {}",
                peak_acceleration(eps)
            );
        }
    }

    #[test]
    fn slip_limit_is_the_median_of_the_plate_velocity() {
        // Fraction of a period with f > eps: 1/2 exactly; counted on 1e5 midpoints
        // (resolution 1e-5 of the period).
        for eps in [-0.45, -0.2, 0.1, 0.3, 0.49] {
            let n = 100_000;
            let above = (0..n)
                .filter(|&i| plate_velocity(eps, TAU * (i as f64 + 0.5) / n as f64) > eps)
                .count();
            assert!(
                (above as f64 / n as f64 - 0.5).abs() <= 2.0 / n as f64,
                "eps {eps}"
            );
        }
    }

    #[test]
    fn slip_orbit_is_periodic_and_its_mean_is_the_closed_form() {
        for (gamma, eps) in [(5.0, 0.2), (20.0, -0.3), (3.0, 0.1)] {
            let o = SlipOrbit::new(gamma, eps).expect("orbit exists");
            // meets the plate at theta1 and theta1 + pi (round-off)
            assert!((o.velocity(o.theta1) - plate_velocity(eps, o.theta1)).abs() < 1e-14);
            assert!((o.velocity(o.theta1 + PI) - plate_velocity(eps, o.theta1 + PI)).abs() < 1e-14);
            // midpoint rule on a piecewise-linear function with kinks: error ~ 1/n^2
            let n = 100_000;
            let mean = (0..n)
                .map(|i| o.velocity(TAU * (i as f64 + 0.5) / n as f64))
                .sum::<f64>()
                / n as f64;
            let closed = always_slipping_drift(gamma, eps).unwrap();
            assert!(
                (mean - closed).abs() < 1e-9,
                "{gamma} {eps}: {mean} vs {closed}"
            );
            assert!((o.drift() - closed).abs() < 1e-14);
        }
        // too weak a drive: the block would have to stick
        assert!(SlipOrbit::new(1.2, 0.1).is_none());
        assert!(SlipOrbit::new(1.0, 0.0).is_none());
    }
}
