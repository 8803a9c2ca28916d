//! Contact modes: pivot (C.6, C.7) and the two slides (C.8 to C.14).
//!
//! Derivation (chapter text, section "Contact modes"): the rod is massless, so the
//! forces on it balance (the plate's force F at C reaches the mass unchanged) and so do
//! the moments about P: `0 = k (theta - theta_0) + gamma theta' + F_x L cos(theta) -
//! F_z L sin(theta)` (C.8, with `z_p - z_c = L cos`, `x_p - x_c = L sin`). The mass obeys
//! `m a_P = F - m g e_z`.

use super::{Mode, State, StickModel, OM, ROD_X, ROD_Z, TH};
use crate::numerics::trig::sin_cos;

/// Accelerations and contact force of a contact mode at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactEval {
    /// theta'' (rad/s^2).
    pub theta_dd: f64,
    /// x'' of C (m/s^2): zero in pivot.
    pub xc_dd: f64,
    /// Horizontal force of the plate on C (N).
    pub fx: f64,
    /// Vertical (normal) force of the plate on C (N).
    pub fz: f64,
}

impl StickModel {
    /// Pivot (hinge at C, C moving with the plate): C.6 for theta'' and the contact force
    /// from Newton on P, `F = m (a_P + g e_z)` with `a_P` from C.7. Exact trigonometry
    /// of `t` and `theta` (the flow uses [`StickModel::pivot_eval_carried`]).
    #[inline]
    pub fn pivot_eval(&self, t: f64, y: &State) -> ContactEval {
        let (s, c) = sin_cos(y[TH]);
        self.pivot_eval_with(self.plate(t).2, s, c, y)
    }

    /// [`StickModel::pivot_eval`] with the plate's acceleration `a_s` (m/s^2) given and
    /// the rod's direction carried in the state, `(sin, cos) = (ROD_X, ROD_Z)`.
    #[inline]
    pub(crate) fn pivot_eval_carried(&self, a_s: f64, y: &State) -> ContactEval {
        self.pivot_eval_with(a_s, y[ROD_X], y[ROD_Z], y)
    }

    /// The pivot equations with the plate's acceleration `a_s` (m/s^2) and `(s, c) =
    /// (sin theta, cos theta)` given.
    #[inline]
    // ANCHOR: pivot
    fn pivot_eval_with(&self, a_s: f64, s: f64, c: f64, y: &State) -> ContactEval {
        let p = &self.p;
        let (m, l, g) = (p.mass_kg, p.length_m, p.g_mps2);
        let w = y[OM];
        let torque = p.stiffness_nm_per_rad * (y[TH] - p.theta0_rad) + p.damping_nms_per_rad * w;
        let theta_dd = ((g + a_s) * m * l * s - torque) * self.inv_ml2; // formula: C.6 theta'' = ((g + a_s) m L sin - Q) / (m L^2)
        let ax = l * (theta_dd * c - w * w * s); // formula: C.7 xddot_p
        let az = a_s - l * (theta_dd * s + w * w * c); // formula: C.7 zddot_p
        ContactEval {
            theta_dd,
            xc_dd: 0.0,
            fx: m * ax,
            fz: m * (az + g),
        } // formula: F = m (a_P + g e_z)
    }
    // ANCHOR_END: pivot

    /// Slide with friction `F_x = sigma mu F_z` (sigma = +1 left, -1 right): the normal
    /// force from the moment balance about P (C.9/C.11), theta'' from the vertical
    /// constraint `z_c = z_s` (C.14) and x'' of C from C.4. Exact trigonometry of `t`
    /// and `theta` (the flow uses [`StickModel::slide_eval_carried`]).
    #[inline]
    pub fn slide_eval(&self, sigma: f64, t: f64, y: &State) -> ContactEval {
        let (s, c) = sin_cos(y[TH]);
        self.slide_eval_with(sigma, self.plate(t).2, s, c, y)
    }

    /// [`StickModel::slide_eval`] with `a_s` (m/s^2) given and the rod's direction
    /// carried in the state.
    #[inline]
    pub(crate) fn slide_eval_carried(&self, sigma: f64, a_s: f64, y: &State) -> ContactEval {
        self.slide_eval_with(sigma, a_s, y[ROD_X], y[ROD_Z], y)
    }

    /// The slide equations with `a_s` (m/s^2) and `(s, c) = (sin theta, cos theta)` given.
    #[inline]
    // ANCHOR: slide
    fn slide_eval_with(&self, sigma: f64, a_s: f64, s: f64, c: f64, y: &State) -> ContactEval {
        let p = &self.p;
        let (l, g, mu) = (p.length_m, p.g_mps2, p.mu);
        let w = y[OM];
        let torque = p.stiffness_nm_per_rad * (y[TH] - p.theta0_rad) + p.damping_nms_per_rad * w;
        // The moment balance about P fixes the normal force (C.9, C.11); the vertical
        // balance of P then gives theta'' and the horizontal one the foot's slip (C.14).
        // The denominator s - sigma mu cos vanishes at a jam (tan theta = sigma mu).
        let (inv_den, inv_s) = (1.0 / (s - sigma * mu * c), 1.0 / s);
        let q_lm = torque * self.inv_length * self.inv_mass;
        let (lw2s, lw2c) = (l * w * w * s, l * w * w * c);
        let fz_m = q_lm * inv_den; // formula: C.9 (sigma=+1), C.11 (sigma=-1): F_z = Q / (L (sin - sigma mu cos))
        let theta_dd = (a_s + g - lw2c - fz_m) * (self.inv_length * inv_s); // formula: C.14 theta'' = (a_s + g - F_z/m - L cos theta'^2) / (L sin)
        let xc_dd = (sigma * mu * fz_m + lw2s) - (l * c) * theta_dd; // formula: C.14 xddot_c = sigma mu F_z/m - L (theta'' cos - theta'^2 sin)
        let fz = fz_m * p.mass_kg;
        ContactEval {
            theta_dd,
            xc_dd,
            fx: sigma * mu * fz,
            fz,
        }
    }
    // ANCHOR_END: slide

    /// The evaluation of a contact mode (`None` in flight).
    #[inline]
    pub(crate) fn contact_eval(&self, mode: Mode, t: f64, y: &State) -> Option<ContactEval> {
        match mode {
            Mode::Flight => None,
            Mode::Pivot => Some(self.pivot_eval(t, y)),
            Mode::SlideLeft | Mode::SlideRight => Some(self.slide_eval(mode.sigma(), t, y)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::*;

    #[test]
    fn pivot_and_slide_agree_on_the_cone_edge() {
        // At a state where the pivot force lies on the edge F_x = mu F_z, the slide-left
        // force and accelerations equal the pivot's: the moment balance is the same
        // equation, so the switch is continuous.
        let mut p = authors_scene(10.0);
        p.mu = 0.3;
        let m = StickModel::new(p);
        // at theta = 0.6, theta' = 0, find a plate phase where F_x = mu F_z (scan, bisect)
        let mut y = [0.0; NSTATE];
        y[TH] = 0.6;
        let f = |t: f64| {
            let e = m.pivot_eval(t, &y);
            e.fx - p.mu * e.fz
        };
        let n = 400;
        let dt = m.period_s / n as f64;
        let k = (0..n)
            .find(|&k| f(k as f64 * dt).signum() != f((k + 1) as f64 * dt).signum())
            .expect("a crossing");
        let (mut a, mut b) = (k as f64 * dt, (k + 1) as f64 * dt);
        for _ in 0..100 {
            let c = 0.5 * (a + b);
            if f(c).signum() == f(a).signum() {
                a = c
            } else {
                b = c
            }
        }
        let t = 0.5 * (a + b);
        let pe = m.pivot_eval(t, &y);
        let se = m.slide_eval(1.0, t, &y);
        assert!(
            (pe.fz - se.fz).abs() < 1e-9 * pe.fz.abs().max(1.0),
            "{pe:?} {se:?}"
        );
        assert!((pe.theta_dd - se.theta_dd).abs() < 1e-7 * pe.theta_dd.abs().max(1.0));
        assert!(se.xc_dd.abs() < 1e-7, "{se:?}");
    }
}
