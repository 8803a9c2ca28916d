//! Parameters of the stick with inertia and its mass distribution.
//!
//! A rigid rod C-P of length `L` with a uniform mass `m_r` along it and a point mass `m`
//! at P. Total mass `M = m + m_r`; centre of mass G at `l_G = (m L + m_r L/2)/M` from C;
//! moment of inertia about G, `I_G = m_r L^2/12 + m_r (L/2 - l_G)^2 + m (L - l_G)^2`;
//! about C, `I_C = I_G + M l_G^2 = (m + m_r/3) L^2`. The dimensionless
//! `alpha = M l_G^2 / I_G` sets the contact point's mobility (see [`super::contact`]).

use crate::physics::stick::StickParams;

/// The stick with inertia: chapter 6's parameters (whose `mass_kg` is the tip mass m)
/// plus the rod's own mass and the restitution of impacts at C.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InertiaParams {
    /// Chapter 6's stick: L, tip mass m (may be 0 here), k, gamma, mu, theta_0, g, plate.
    pub base: StickParams,
    /// Mass of the rod, uniform along C-P (kg).
    pub rod_mass_kg: f64,
    /// Newton-Stronge restitution e of impacts at C (1, 0 = the document's plastic impact).
    pub restitution: f64,
}

/// The mass distribution's derived constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassGeometry {
    /// Total mass M (kg).
    pub total_kg: f64,
    /// Distance from C to the centre of mass G (m).
    pub l_g_m: f64,
    /// Moment of inertia about G (kg m^2).
    pub i_g: f64,
    /// Moment of inertia about C (kg m^2).
    pub i_c: f64,
    /// Moment of inertia about P (kg m^2).
    pub i_p: f64,
}

impl MassGeometry {
    /// The constants of a rod of length `l` (m), rod mass `m_r` (kg), tip mass `m` (kg).
    pub fn new(l: f64, m_r: f64, m: f64) -> Self {
        let total = m + m_r;
        let l_g = (m * l + 0.5 * m_r * l) / total; // formula: l_G = (m L + m_r L/2)/M
        let i_g = m_r * l * l / 12.0 + m_r * (0.5 * l - l_g).powi(2) + m * (l - l_g).powi(2); // formula: I_G (parallel axes)
        MassGeometry {
            total_kg: total,
            l_g_m: l_g,
            i_g,
            i_c: (m + m_r / 3.0) * l * l, // formula: I_C = (m + m_r/3) L^2
            i_p: m_r * l * l / 3.0,       // formula: I_P = m_r L^2/3
        }
    }

    /// `alpha = M l_G^2 / I_G` (1): 3 for a uniform rod, infinite for a massless one.
    pub fn alpha(&self) -> f64 {
        self.total_kg * self.l_g_m * self.l_g_m / self.i_g // formula: alpha = M l_G^2 / I_G
    }
}

impl InertiaParams {
    /// The mass geometry.
    pub fn geometry(&self) -> MassGeometry {
        MassGeometry::new(self.base.length_m, self.rod_mass_kg, self.base.mass_kg)
    }

    /// The dimensionless rod inertia `I_P k / gamma^2` (1): the ratio of the rod's own
    /// time scale `I_P/gamma` to the massless rod's relaxation time `gamma/k`.
    pub fn inertia_ratio(&self) -> f64 {
        let b = &self.base;
        self.geometry().i_p * b.stiffness_nm_per_rad
            / (b.damping_nms_per_rad * b.damping_nms_per_rad) // formula: I_P k / gamma^2
    }

    /// Static angle on a still plate: the root of `k (theta - theta_0) = M g l_G sin theta`
    /// nearest `theta_0` on its side (rad), `None` when the spring cannot hold the stick.
    pub fn static_angle(&self) -> Option<f64> {
        let g = self.geometry();
        let b = &self.base;
        let w = g.total_kg * b.g_mps2 * g.l_g_m;
        let f = |th: f64| b.stiffness_nm_per_rad * (th - b.theta0_rad) - w * th.sin(); // formula: k (theta - theta_0) = M g l_G sin theta
        let s = if b.theta0_rad >= 0.0 { 1.0 } else { -1.0 };
        let (mut a, mut c) = (b.theta0_rad, s * (std::f64::consts::FRAC_PI_2 - 1e-9));
        if f(a) == 0.0 {
            return Some(a);
        }
        if f(a).signum() == f(c).signum() {
            return None;
        }
        for _ in 0..200 {
            let mid = 0.5 * (a + c);
            if f(mid).signum() == f(a).signum() {
                a = mid;
            } else {
                c = mid;
            }
        }
        Some(0.5 * (a + c))
    }
}
