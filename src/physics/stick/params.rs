//! Parameters of the stick model and the two scenes of the chapter.

use crate::physics::domain::{within, DomainError, Interval};
use crate::physics::plate::{Axis, Harmonic};

/// Where the stick model is defined: the domains [`StickParams::new`] checks. The
/// command line accepts a narrower box (`crate::flags::stick`), inside these
/// (`tests/architecture.rs` and the flag table's unit tests check the inclusion).
pub mod domain {
    use super::Interval;
    /// Rod length L (m): positive.
    pub const LENGTH_M: Interval = Interval::above(0.0);
    /// Tip mass m (kg): 0 (a massless tip, chapter 8's uniform rod) or more.
    pub const MASS_KG: Interval = Interval::at_least(0.0);
    /// Spring stiffness k (N m/rad): 0 (a free hinge) or more.
    pub const STIFFNESS_NM_PER_RAD: Interval = Interval::at_least(0.0);
    /// Damper gamma (N m s/rad): 0 or more.
    pub const DAMPING_NMS_PER_RAD: Interval = Interval::at_least(0.0);
    /// Friction coefficient mu (1): 0 or more.
    pub const MU: Interval = Interval::at_least(0.0);
    /// Spring rest angle theta_0 (rad): strictly between -pi/2 and pi/2 (the foot below P).
    pub const THETA0_RAD: Interval =
        Interval::open(-std::f64::consts::FRAC_PI_2, std::f64::consts::FRAC_PI_2);
    /// Gravity g (m/s^2): positive (the plate's phases are measured in g).
    pub const G_MPS2: Interval = Interval::above(0.0);
    /// Peak plate acceleration over g, Gamma (1): 0 (a still plate) or more.
    pub const GAMMA: Interval = Interval::at_least(0.0);
    /// Plate frequency f (Hz): positive.
    pub const FREQUENCY_HZ: Interval = Interval::above(0.0);
}

/// Which angle the collision map (C.15) uses for the lever arm `r_P/C`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CollisionAngle {
    /// The document's choice: the rod is put back at `theta_0` at every landing and
    /// `r_P/C` is evaluated there. An approximation, good when the flight lasts many
    /// relaxation times `gamma/k`.
    Reset,
    /// The physical choice: the angle the rod actually has at the landing instant.
    Actual,
}

/// Physical parameters of the stick on its plate (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StickParams {
    /// Rod length L (m).
    pub length_m: f64,
    /// Tip mass m at P (kg).
    pub mass_kg: f64,
    /// Torsion-spring stiffness k (N m/rad).
    pub stiffness_nm_per_rad: f64,
    /// Torsion damper gamma (N m s/rad).
    pub damping_nms_per_rad: f64,
    /// Coulomb friction coefficient mu at C (1).
    pub mu: f64,
    /// Spring rest angle theta_0 from the vertical (rad), positive = P right of C.
    pub theta0_rad: f64,
    /// Gravitational acceleration g (m/s^2).
    pub g_mps2: f64,
    /// Plate motion `z_s = delta cos(omega t)`.
    pub plate: Harmonic,
    /// Lever arm used by the collision map.
    pub collision_angle: CollisionAngle,
}

impl StickParams {
    /// The same stick on a plate of peak acceleration `gamma_accel` (over g) at
    /// `frequency_hz` (Hz), built by [`StickParams::new`] (its collision angle is `new`'s
    /// default, not `self`'s).
    ///
    /// # Panics
    /// When `gamma_accel` or `frequency_hz` is outside [`domain`] (the callers sweep
    /// validated ranges).
    pub(crate) fn with_drive(&self, gamma_accel: f64, frequency_hz: f64) -> StickParams {
        StickParams::new(
            self.length_m,
            self.mass_kg,
            self.stiffness_nm_per_rad,
            self.damping_nms_per_rad,
            self.mu,
            self.theta0_rad,
            self.g_mps2,
            gamma_accel,
            frequency_hz,
        )
        .expect("a drive inside the stick's domain")
    }

    /// Parameters with the plate given by its peak acceleration over g (`gamma_accel`,
    /// `Gamma = delta omega^2 / g`) and frequency (Hz). Each value is checked against
    /// its [`domain`]: the error names the first one outside it.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        length_m: f64,
        mass_kg: f64,
        stiffness_nm_per_rad: f64,
        damping_nms_per_rad: f64,
        mu: f64,
        theta0_rad: f64,
        g_mps2: f64,
        gamma_accel: f64,
        frequency_hz: f64,
    ) -> Result<Self, DomainError> {
        within("length_m", length_m, domain::LENGTH_M, "m")?;
        within("mass_kg", mass_kg, domain::MASS_KG, "kg")?;
        within(
            "stiffness_nm_per_rad",
            stiffness_nm_per_rad,
            domain::STIFFNESS_NM_PER_RAD,
            "N m/rad",
        )?;
        within(
            "damping_nms_per_rad",
            damping_nms_per_rad,
            domain::DAMPING_NMS_PER_RAD,
            "N m s/rad",
        )?;
        within("mu", mu, domain::MU, "1")?;
        within("theta0_rad", theta0_rad, domain::THETA0_RAD, "rad")?;
        within("g_mps2", g_mps2, domain::G_MPS2, "m/s^2")?;
        within("gamma_accel", gamma_accel, domain::GAMMA, "1")?;
        within("frequency_hz", frequency_hz, domain::FREQUENCY_HZ, "Hz")?;
        let omega = std::f64::consts::TAU * frequency_hz;
        let delta = gamma_accel * g_mps2 / (omega * omega); // formula: delta = Gamma g / omega^2
        Ok(StickParams {
            length_m,
            mass_kg,
            stiffness_nm_per_rad,
            damping_nms_per_rad,
            mu,
            theta0_rad,
            g_mps2,
            plate: Harmonic::cosine(Axis::Z, delta, frequency_hz),
            collision_angle: CollisionAngle::Actual,
        })
    }

    /// Peak plate acceleration over g, `Gamma = delta omega^2 / g` (1).
    pub fn gamma_accel(&self) -> f64 {
        self.plate.peak_acceleration_mps2() / self.g_mps2
    }

    /// Drive frequency (Hz).
    pub fn frequency_hz(&self) -> f64 {
        self.plate.omega_rad_s / std::f64::consts::TAU
    }

    /// Drive period (s).
    pub fn period_s(&self) -> f64 {
        std::f64::consts::TAU / self.plate.omega_rad_s
    }

    /// Relaxation rate of the angle in flight, `k/gamma` (1/s); infinite without damper.
    pub fn relax_rate(&self) -> f64 {
        if self.stiffness_nm_per_rad == 0.0 {
            0.0
        } else if self.damping_nms_per_rad == 0.0 {
            f64::INFINITY
        } else {
            self.stiffness_nm_per_rad / self.damping_nms_per_rad // formula: C.3, theta' = -(k/gamma)(theta - theta0)
        }
    }

    /// Static equilibrium angle on a still plate, the root of
    /// `k (theta - theta_0) = m g L sin(theta)` nearest `theta_0` (rad), or `None` when
    /// the spring cannot hold the stick up (no root below 90 degrees).
    pub fn static_angle(&self) -> Option<f64> {
        let (k, w) = (
            self.stiffness_nm_per_rad,
            self.mass_kg * self.g_mps2 * self.length_m,
        );
        let f = |th: f64| k * (th - self.theta0_rad) - w * th.sin();
        let half = std::f64::consts::FRAC_PI_2;
        // bracket on the side theta_0 leans to, then bisect
        let s = if self.theta0_rad >= 0.0 { 1.0 } else { -1.0 };
        let (mut a, mut b) = (self.theta0_rad, s * (half - 1e-9));
        if f(a) == 0.0 {
            return Some(a);
        }
        if f(a).signum() == f(b).signum() {
            return None;
        }
        for _ in 0..200 {
            let c = 0.5 * (a + b);
            if f(c).signum() == f(a).signum() {
                a = c;
            } else {
                b = c;
            }
        }
        Some(0.5 * (a + b))
    }
}

/// Rest angle of the spring such that the static equilibrium angle is `theta_f`:
/// `k (theta_f - theta_0) = m g L sin(theta_f)` (the authors' choice).
pub fn theta0_for_static_angle(theta_f: f64, k: f64, m: f64, g: f64, l: f64) -> f64 {
    theta_f - m * g * l * theta_f.sin() / k // formula: theta_0 = theta_f - m g L sin(theta_f)/k
}

/// The authors' scene: L = 0.15 m, m = 1 kg, Gamma = 10, f = 30 Hz, k = 10 N m/rad,
/// gamma = 0.01 N m s/rad, mu = 0.4, static angle 0.5 rad; `g` is 10 m/s^2 in their runs.
/// Source: the authors' public code of the same model (`main_rod.m` in
/// github.com/toshankarghosh/toothpicks), not the document, which gives no numbers.
///
/// # Panics
/// When `g_mps2` is not positive and finite (the callers pass a validated g).
pub fn authors_scene(g_mps2: f64) -> StickParams {
    let (l, m, k) = (0.15, 1.0, 10.0);
    let theta0 = theta0_for_static_angle(0.5, k, m, g_mps2, l);
    StickParams::new(l, m, k, 0.01, 0.4, theta0, g_mps2, 10.0, 30.0)
        .expect("the authors' scene at a g in its domain")
}

/// The self-locking scene (default of the chapter): the authors' stick (L, m, k, gamma,
/// mu, f) with its spring rest angle inside the friction cone, `theta_0 = 0.3 rad`
/// (`tan(theta_0) = 0.309 < mu = 0.4`), on a gentler plate, `Gamma = 3`. It walks by
/// stick-slip: pivot (jammed: the rod's thrust lies inside the cone), then slide right.
///
/// # Panics
/// When `g_mps2` is not positive and finite (the callers pass a validated g).
pub fn jamming_scene(g_mps2: f64) -> StickParams {
    StickParams::new(
        0.15,
        1.0,
        10.0,
        0.01,
        0.4,
        JAMMING_THETA0_RAD,
        g_mps2,
        JAMMING_GAMMA,
        30.0,
    )
    .expect("the self-locking scene at a g in its domain")
}

/// Spring rest angle of the self-locking scene (rad).
pub const JAMMING_THETA0_RAD: f64 = 0.3;
/// Peak plate acceleration over g of the self-locking scene.
pub const JAMMING_GAMMA: f64 = 3.0;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_constructor_refuses_values_outside_the_domain_naming_them() {
        let ok = |l: f64, mu: f64, th: f64, f: f64| {
            StickParams::new(l, 1.0, 10.0, 0.01, mu, th, 9.81, 3.0, f)
        };
        assert!(ok(0.15, 0.4, 0.3, 30.0).is_ok());
        let e = ok(f64::NAN, 0.4, 0.3, 30.0).unwrap_err();
        assert_eq!(e.parameter, "length_m");
        assert!(e.to_string().contains("0 < value (m)"), "{e}");
        assert_eq!(ok(0.15, -0.1, 0.3, 30.0).unwrap_err().parameter, "mu");
        assert_eq!(
            ok(0.15, 0.4, 1.6, 30.0).unwrap_err().parameter,
            "theta0_rad"
        );
        assert_eq!(
            ok(0.15, 0.4, 0.3, 0.0).unwrap_err().parameter,
            "frequency_hz"
        );
        assert_eq!(
            ok(0.15, 0.4, 0.3, f64::INFINITY).unwrap_err().parameter,
            "frequency_hz"
        );
    }
}
