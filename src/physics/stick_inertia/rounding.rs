//! The rounding thresholds of the contact decisions (derived in chapter 8, section 3,
//! "Deciding against rounding").
//!
//! Every decision of the rules compares a computed number with zero: C's normal velocity
//! after an impact (bounce or contact?), its slip (stuck or sliding?), the slide's
//! Painleve coefficient `D` (one normal force, none or two?), the pivot's force (inside
//! the cone?). Each number carries a rounding error, and a decision taken on the sign of
//! that error is noise (issue 29: a 2e-9 m/s "bounce" after a plastic landing, 1e-13 m/s
//! "slips" after a sticking one). So each is compared with a threshold
//! `eta = C_OPS u kappa S`: the unit roundoff `u = 2^-53` times the condition number
//! `kappa` of the computation times the scale `S` of the numbers that enter it, times a
//! stated count of operations `C_OPS`.
//!
//! - **Velocities of C** (after an impact, or its slip): C's velocity is recovered from
//!   G's and the rod's rate, `v_C = v_G - l_G theta' e_theta`, where the rate took the
//!   impulse through `l_G P . e_theta / I_G`; the map from impulse to C's velocity is the
//!   mobility `W = (Id + alpha e_theta e_theta^T)/M`, whose eigenvalues are `1/M` and
//!   `(1 + alpha)/M`: condition number `kappa_W = 1 + alpha`. Scale: the largest of C's
//!   speed relative to the plate before the impact, the plate's peak speed and
//!   `sqrt(g L)`.
//! - **The Painleve coefficient** `D = I_G + M l_G^2 sin(theta) (sin(theta) - sigma mu
//!   cos(theta))`: a sum of terms of size `I_G + M l_G^2 (sin^2 + mu |sin cos|)`, each
//!   exact to a few `u`.
//! - **Forces**: the pivot's and the slide's `F` are sums of terms of size
//!   `M (g + delta omega^2 + l_G theta'^2) + |Q| / l_G`.

use super::{InertiaModel, State, OM, TH};

/// Unit roundoff of f64, `u = 2^-53` (1).
pub const UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;

/// Operations counted in a decision's number (1): the impact's at most 16 linear
/// pieces, each a handful of products and sums, and the map back to C. A stated count,
/// not fitted: every rounding error of each operation adds at most `u` of its scale.
pub const C_OPS: f64 = 64.0;

impl InertiaModel {
    /// Condition number of the mobility `W`, `1 + alpha` (1), capped at `1/u` (beyond
    /// it no digit of an impact survives).
    pub(crate) fn mobility_condition(&self) -> f64 {
        (1.0 + self.geo.alpha()).min(1.0 / UNIT_ROUNDOFF) // formula: kappa_W = (1 + alpha)/1
    }

    /// The velocity scale of C (m/s): the largest of `|u|` (C's velocity relative to the
    /// plate), the plate's peak speed and `sqrt(g L)`.
    pub(crate) fn velocity_scale(&self, u: [f64; 2]) -> f64 {
        let b = &self.p.base;
        u[0].hypot(u[1])
            .max(b.plate.peak_velocity_mps())
            .max((b.g_mps2 * b.length_m).sqrt())
    }

    /// The rounding threshold of C's velocities after an impact from `u0` (m/s):
    /// `eta_v = C_OPS u (1 + alpha) V`.
    pub fn velocity_rounding(&self, u0: [f64; 2]) -> f64 {
        C_OPS * UNIT_ROUNDOFF * self.mobility_condition() * self.velocity_scale(u0)
        // formula: eta_v = C u kappa_W V
    }

    /// The rounding threshold of `D` at `theta` (kg m^2):
    /// `eta_D = C_OPS u (I_G + M l_G^2 (sin^2 + mu |sin cos|))`.
    pub(crate) fn coefficient_rounding(&self, theta: f64) -> f64 {
        let (s, c) = theta.sin_cos();
        let (m, l) = (self.geo.total_kg, self.geo.l_g_m);
        C_OPS
            * UNIT_ROUNDOFF
            * (self.geo.i_g + m * l * l * (s * s + self.p.base.mu * (s * c).abs()))
        // formula: eta_D
    }

    /// The rounding threshold of the contact force at `y` (N):
    /// `eta_F = C_OPS u (M (g + delta omega^2 + l_G theta'^2) + |Q|/l_G)`.
    pub(crate) fn force_rounding(&self, y: &State) -> f64 {
        let b = &self.p.base;
        let (m, l) = (self.geo.total_kg, self.geo.l_g_m);
        let scale = m * (b.g_mps2 + b.plate.peak_acceleration_mps2() + l * y[OM] * y[OM])
            + self.couple(y[TH], y[OM]).abs() / l;
        C_OPS * UNIT_ROUNDOFF * scale // formula: eta_F = C u F_scale
    }
}
