//! Contact modes: Newton-Euler for the rigid rod with C on the plate.
//!
//! Newton for G and Euler about G, with the plate's force `F = (F_x, F_z)` at C, gravity
//! at G and the couple `-Q` (see the module docs):
//! `M a_G = F - M g e_z`, `I_G theta'' = -l_G (F . e_theta) - Q`, where
//! `e_r = (sin, cos)` points from C to P and `e_theta = (cos, -sin)` (a virtual rotation
//! `dtheta` about G moves C by `-l_G e_theta dtheta`). C's acceleration follows from
//! `r_C = r_G - l_G e_r`: `a_C = a_G - l_G theta'' e_theta + l_G theta'^2 e_r`, so
//! `a_C = W F + b` with the mobility (Delassus matrix) `W = (Id + alpha e_theta e_theta^T)/M`,
//! `alpha = M l_G^2 / I_G`, and the free acceleration
//! `b = -g e_z + (l_G Q / I_G) e_theta + l_G theta'^2 e_r`.

use super::{InertiaModel, State, OM, TH, VXC};

/// Accelerations and contact force of a contact mode.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactEval {
    /// theta'' (rad/s^2).
    pub theta_dd: f64,
    /// x'' of C (m/s^2): zero in pivot.
    pub xc_dd: f64,
    /// Horizontal force of the plate on C (N).
    pub fx: f64,
    /// Normal force of the plate on C (N).
    pub fz: f64,
    /// The slide's normal-acceleration coefficient times `M I_G` (kg m^2): `D` of
    /// [`InertiaModel::slide_coefficient`] (zero in pivot).
    pub d: f64,
    /// The slide's numerator `N` with `F_z = M N / D` (kg m^2/s^2; zero in pivot).
    pub n: f64,
}

impl InertiaModel {
    /// The mobility `W` (1/kg) at angle `theta`, `[[W_xx, W_xz], [W_zx, W_zz]]`.
    pub fn mobility(&self, theta: f64) -> [[f64; 2]; 2] {
        let (s, c) = theta.sin_cos();
        let (m, a) = (self.geo.total_kg, self.geo.alpha());
        [
            [(1.0 + a * c * c) / m, -a * s * c / m],
            [-a * s * c / m, (1.0 + a * s * s) / m],
        ] // formula: W = (Id + alpha e_theta e_theta^T)/M
    }

    /// Pivot: C moves with the plate. Euler about C (a point accelerating at `(0, a_s)`,
    /// hence the pseudo-force `-M a_s e_z` at G):
    /// `I_C theta'' = M l_G (g + a_s) sin(theta) - Q`; then `F = M (a_G + g e_z)` with
    /// `a_G = (0, a_s) + l_G (theta'' e_theta - theta'^2 e_r)`.
    pub fn pivot_eval(&self, t: f64, y: &State) -> ContactEval {
        let b = &self.p.base;
        let (m, l) = (self.geo.total_kg, self.geo.l_g_m);
        let (_, _, a_s) = self.plate(t);
        let (s, c) = y[TH].sin_cos();
        let w = y[OM];
        let q = self.couple(y[TH], w);
        let theta_dd = (m * l * (b.g_mps2 + a_s) * s - q) / self.geo.i_c; // formula: I_C theta'' = M l_G (g + a_s) sin - Q
        let ax = l * (theta_dd * c - w * w * s); // formula: a_Gx = l_G (theta'' cos - theta'^2 sin)
        let az = a_s - l * (theta_dd * s + w * w * c); // formula: a_Gz = a_s - l_G (theta'' sin + theta'^2 cos)
        ContactEval {
            theta_dd,
            xc_dd: 0.0,
            fx: m * ax,              // formula: F_x = M a_Gx
            fz: m * (az + b.g_mps2), // formula: F_z = M (a_Gz + g)
            d: 0.0,
            n: 0.0,
        }
    }

    /// The Painleve coefficient of the slide with friction `F_x = sigma mu F_z`, times
    /// `M I_G` (kg m^2): `D = I_G + M l_G^2 sin(theta) (sin(theta) - sigma mu cos(theta))`.
    /// The normal acceleration of C is `a_Cz = (D / (M I_G)) F_z + b_z`: `D > 0` gives one
    /// normal force, `D < 0` none (inconsistent) or two (indeterminate). `D = 0` at
    /// `sigma mu = tan(theta) + 1/(alpha sin(theta) cos(theta))`.
    pub(crate) fn slide_coefficient(&self, sigma: f64, theta: f64) -> f64 {
        let (s, c) = theta.sin_cos();
        let (m, l) = (self.geo.total_kg, self.geo.l_g_m);
        self.geo.i_g + m * l * l * s * (s - sigma * self.p.base.mu * c) // formula: D = M I_G (W_zz + sigma mu W_zx)
    }

    /// Slide with friction `F_x = sigma mu F_z` (sigma = +1: C slips left). The normal
    /// constraint `a_Cz = a_s` gives `F_z = M N / D` with
    /// `N = I_G (a_s + g - l_G theta'^2 cos) + l_G Q sin` (`M I_G (a_s - b_z)`); theta''
    /// from Euler about G (or, when `I_G` is small against `M l_G^2 sin^2`, from the
    /// constraint, `theta'' = (a_s + g - F_z/M - l_G theta'^2 cos)/(l_G sin)`: the same
    /// number, better conditioned); `x_C'' = a_Gx - l_G theta'' cos + l_G theta'^2 sin`.
    pub fn slide_eval(&self, sigma: f64, t: f64, y: &State) -> ContactEval {
        let b = &self.p.base;
        let (m, l, ig) = (self.geo.total_kg, self.geo.l_g_m, self.geo.i_g);
        let (_, _, a_s) = self.plate(t);
        let (s, c) = y[TH].sin_cos();
        let w = y[OM];
        let q = self.couple(y[TH], w);
        let d = self.slide_coefficient(sigma, y[TH]);
        let n = ig * (a_s + b.g_mps2 - l * w * w * c) + l * q * s; // formula: N = I_G (a_s + g - l_G theta'^2 cos) + l_G Q sin
        let fz = m * n / d; // formula: F_z = M N / D
        let fx = sigma * b.mu * fz;
        let theta_dd = if ig > 0.1 * m * l * l * s * s {
            (-l * (fx * c - fz * s) - q) / ig // formula: I_G theta'' = -l_G (F . e_theta) - Q
        } else {
            (a_s + b.g_mps2 - fz / m - l * w * w * c) / (l * s) // formula: a_Cz = a_s solved for theta''
        };
        let xc_dd = fx / m - l * theta_dd * c + l * w * w * s; // formula: a_Cx = F_x/M - l_G theta'' cos + l_G theta'^2 sin
        ContactEval {
            theta_dd,
            xc_dd,
            fx,
            fz,
            d,
            n,
        }
    }

    /// The evaluation of a contact mode (`None` in flight).
    pub(crate) fn contact_eval(&self, mode: super::Mode, t: f64, y: &State) -> Option<ContactEval> {
        match mode {
            super::Mode::Flight => None,
            super::Mode::Pivot => Some(self.pivot_eval(t, y)),
            _ => Some(self.slide_eval(mode.sigma(), t, y)),
        }
    }

    /// Velocity of C relative to the plate `(u_t, u_n)` (m/s).
    pub(crate) fn relative_velocity(&self, t: f64, y: &State) -> [f64; 2] {
        [y[VXC], y[super::VZC] - self.plate(t).1]
    }
}

#[cfg(test)]
mod tests {
    use super::super::*;
    use crate::physics::stick::jamming_scene;

    fn model(m_r: f64, m: f64) -> InertiaModel {
        let mut base = jamming_scene(9.81);
        base.mass_kg = m;
        InertiaModel::new(InertiaParams {
            base,
            rod_mass_kg: m_r,
            restitution: 0.0,
        })
    }

    #[test]
    fn slide_satisfies_newton_euler_and_the_constraint() {
        // Residuals of the three Newton-Euler equations with the computed F, theta'', x''.
        for (m_r, m) in [(0.1, 0.0), (0.01, 1.0), (0.5, 0.5)] {
            let md = model(m_r, m);
            let mut y = [0.0; NSTATE];
            y[TH] = 0.5;
            y[OM] = -1.3;
            y[VXC] = 0.2;
            for sigma in [1.0, -1.0] {
                let e = md.slide_eval(sigma, 0.003, &y);
                let (s, c) = y[TH].sin_cos();
                let (mm, l, ig) = (md.geo.total_kg, md.geo.l_g_m, md.geo.i_g);
                let w = y[OM];
                let (_, _, a_s) = md.plate(0.003);
                let agx = e.xc_dd + l * (e.theta_dd * c - w * w * s);
                let agz = a_s + l * (-e.theta_dd * s - w * w * c);
                let q = md.couple(y[TH], w);
                let r1 = mm * agx - e.fx;
                let r2 = mm * (agz + 9.81) - e.fz;
                let r3 = ig * e.theta_dd + l * (e.fx * c - e.fz * s) + q;
                let scale = mm * 9.81 + e.fz.abs();
                assert!(
                    r1.abs() < 1e-9 * scale && r2.abs() < 1e-9 * scale,
                    "{r1} {r2}"
                );
                assert!(r3.abs() < 1e-9 * scale * l, "{r3}");
            }
        }
    }

    #[test]
    fn pivot_and_massless_limit_match_chapter_6() {
        // A rod of 1e-9 of the tip mass: the pivot's theta'' and force are chapter 6's.
        let md = model(1e-9, 1.0);
        let ch6 = crate::physics::stick::StickModel::new(md.p.base);
        let mut y6 = [0.0; crate::physics::stick::NSTATE];
        y6[crate::physics::stick::TH] = 0.4;
        y6[crate::physics::stick::OM] = 0.7;
        let mut y = [0.0; NSTATE];
        y[TH] = 0.4;
        y[OM] = 0.7;
        let (a, b) = (md.pivot_eval(0.01, &y), ch6.pivot_eval(0.01, &y6));
        assert!(
            (a.theta_dd - b.theta_dd).abs() < 1e-6 * b.theta_dd.abs().max(1.0),
            "{a:?} {b:?}"
        );
        assert!((a.fz - b.fz).abs() < 1e-6 * b.fz.abs().max(1.0));
    }
}
