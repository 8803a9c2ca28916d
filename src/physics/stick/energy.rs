//! Energy bookkeeping.
//!
//! Mechanical energy `E = m |v_P|^2 / 2 + m g z_P + k (theta - theta_0)^2 / 2`. The rod is
//! massless, so its power balance gives `F . v_P = F . v_C - (k (theta - theta_0) +
//! gamma theta') theta'` and hence `dE/dt = F . v_C - gamma theta'^2`: with the plate
//! moving only vertically, `F . v_C = F_z zdot_s + F_x xdot_c`, the plate's power minus
//! the friction loss `mu F_z |xdot_c|`. Impacts add the plate's impulse work and remove
//! `m w^2 / 2` (see [`super::collision`]). The budget
//! `W_plate = Delta E + D_friction + D_damper + D_impact`
//! is integrated alongside the state and its residual measures the simulation's error.

use super::{State, StickModel, D_DAMP, D_FRIC, D_IMPACT, W_PLATE};

/// The energy budget of a run (J).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Budget {
    /// Work done by the plate (J).
    pub plate_work_j: f64,
    /// Change of mechanical energy (J).
    pub delta_mechanical_j: f64,
    /// Dissipated by friction (J).
    pub friction_j: f64,
    /// Dissipated by the damper (J).
    pub damper_j: f64,
    /// Dissipated by impacts (J).
    pub impact_j: f64,
    /// `W - Delta E - D_f - D_d - D_i` (J).
    pub residual_j: f64,
}

impl Budget {
    /// Residual relative to the largest term, with a floor of 1e-9 J so that a stick at
    /// rest (every term zero to rounding) does not divide rounding by rounding (1).
    pub fn relative_residual(&self) -> f64 {
        self.residual_j.abs() / self.scale_j()
    }

    /// The largest term of the budget (J), at least 1e-9 J: the scale of
    /// [`Budget::relative_residual`].
    pub(crate) fn scale_j(&self) -> f64 {
        [
            self.plate_work_j,
            self.delta_mechanical_j,
            self.friction_j,
            self.damper_j,
            self.impact_j,
        ]
        .iter()
        .fold(1e-9f64, |a, b| a.max(b.abs()))
    }
}

impl StickModel {
    /// Mechanical energy of the state (J).
    pub(crate) fn mechanical_energy(&self, y: &State) -> f64 {
        let p = &self.p;
        let [_, zp, vxp, vzp] = self.tip(y);
        let d = y[super::TH] - p.theta0_rad;
        0.5 * p.mass_kg * (vxp * vxp + vzp * vzp)
            + p.mass_kg * p.g_mps2 * zp
            + 0.5 * p.stiffness_nm_per_rad * d * d
        // formula: E
    }

    /// The budget between `y0` and `y1` (the accumulators start at zero in `y0`'s run).
    pub fn budget(&self, y0: &State, y1: &State) -> Budget {
        let w = y1[W_PLATE] - y0[W_PLATE];
        let de = self.mechanical_energy(y1) - self.mechanical_energy(y0);
        let f = y1[D_FRIC] - y0[D_FRIC];
        let d = y1[D_DAMP] - y0[D_DAMP];
        let i = y1[D_IMPACT] - y0[D_IMPACT];
        Budget {
            plate_work_j: w,
            delta_mechanical_j: de,
            friction_j: f,
            damper_j: d,
            impact_j: i,
            residual_j: w - de - f - d - i, // formula: W = dE + D_f + D_d + D_i
        }
    }
}
