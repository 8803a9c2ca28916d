//! The time derivatives of the contact modes' guards along the flow, in closed form,
//! for the certified event search (see [`crate::numerics::hybrid::HybridSystem::guard_rates`]).
//!
//! Pivot (C.6, C.7 with `s, c` the carried `sin theta, cos theta`, `Q = k (theta - theta_0)
//! + gamma theta'`, `a_s` and `j_s = -omega^2 zdot_s` the plate's acceleration and jerk):
//!
//! ```text
//! theta''' = (j_s m L s + (g + a_s) m L c theta' - (k theta' + gamma theta'')) / (m L^2)
//! xddot_p' = L (theta''' c - 3 theta' theta'' s - theta'^3 c)
//! zddot_p' = j_s - L (theta''' s + 3 theta' theta'' c - theta'^3 s)
//! F_x' = m xddot_p',   F_z' = m zddot_p'
//! ```
//!
//! so the guards `F_z`, `mu F_z - F_x`, `mu F_z + F_x`, `pi/2 - |theta|` change at
//! `F_z'`, `mu F_z' - F_x'`, `mu F_z' + F_x'`, `-sign(theta) theta'`. The slides' guards
//! are linear in `theta`, `theta'`, `xdot_c` (the second through `Q`), so their rates
//! are read off the flow `f`: `theta' = f_theta`, `theta'' = f_theta'`, `xddot_c = f_xdot`.
//! Both agree with a directional difference of the guards to its own error (a test).

use super::{Mode, State, StickModel, OM, ROD_X, ROD_Z, TH, VXC};

impl StickModel {
    /// The rates of `mode`'s guards at `(t, y)` with `f` the flow there, into `out`
    /// (cleared first); `false` for flight (its closed form needs none).
    pub(super) fn contact_guard_rates(
        &self,
        mode: Mode,
        t: f64,
        y: &State,
        f: &State,
        out: &mut Vec<f64>,
    ) -> bool {
        let p = &self.p;
        out.clear();
        let (th, w) = (y[TH], y[OM]);
        let edge_rate = -th.signum() * w; // formula: (pi/2 - |theta|)' = -sign(theta) theta'
        match mode {
            Mode::Flight => return false,
            Mode::Pivot => {
                let (m, l, g) = (p.mass_kg, p.length_m, p.g_mps2);
                let (_, v_s, a_s) = self.plate(t);
                let omega = p.plate.omega_rad_s;
                let j_s = -omega * omega * v_s; // formula: j_s = -omega^2 zdot_s
                let (s, c) = (y[ROD_X], y[ROD_Z]);
                let wdd = f[OM];
                let q_rate = p.stiffness_nm_per_rad * w + p.damping_nms_per_rad * wdd; // formula: Q' = k theta' + gamma theta''
                let wddd = (j_s * m * l * s + (g + a_s) * m * l * c * w - q_rate) * self.inv_ml2; // formula: theta'''
                let w3 = w * w * w;
                let ax_rate = l * (wddd * c - 3.0 * w * wdd * s - w3 * c); // formula: xddot_p'
                let az_rate = j_s - l * (wddd * s + 3.0 * w * wdd * c - w3 * s); // formula: zddot_p'
                let (fx_rate, fz_rate) = (m * ax_rate, m * az_rate);
                out.extend_from_slice(&[
                    fz_rate,
                    p.mu * fz_rate - fx_rate,
                    p.mu * fz_rate + fx_rate,
                    edge_rate,
                ]);
            }
            Mode::SlideLeft | Mode::SlideRight => {
                let sigma = mode.sigma();
                let edge = th - sigma * self.atan_mu;
                let q_rate = p.stiffness_nm_per_rad * w + p.damping_nms_per_rad * f[OM]; // formula: Q' = k theta' + gamma theta''
                out.extend_from_slice(&[
                    w,                      // formula: (theta - sigma atan mu)' = theta'
                    q_rate * edge.signum(), // formula: (Q sign(edge))' = Q' sign(edge)
                    -sigma * f[VXC],        // formula: (-sigma xdot_c)' = -sigma xddot_c
                    edge_rate,
                    w, // formula: theta' (the C.14 singularity guard theta)
                    sigma * f[VXC],
                ]);
            }
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::super::run::initial_state;
    use super::super::{authors_scene, jamming_scene, Mode, StickModel, NSTATE, OM, VXC};
    use crate::numerics::hybrid::HybridSystem;

    /// Central difference of `mode`'s guards along the flow: `(g(y + d f) - g(y - d f)) /
    /// 2d` at times `t +- d`, off by `d^2 g''' / 6`.
    fn central(m: &StickModel, mode: Mode, t: f64, y: &[f64; NSTATE], d: f64) -> Vec<f64> {
        let f = m.flow(mode, t, y);
        let shifted = |s: f64| {
            let mut z = *y;
            for (zi, fi) in z.iter_mut().zip(&f) {
                *zi += s * fi;
            }
            let mut g = Vec::new();
            m.guards(mode, t + s, &z, &mut g);
            g
        };
        let (gp, gm) = (shifted(d), shifted(-d));
        gp.iter()
            .zip(&gm)
            .map(|(p, q)| (p - q) / (2.0 * d))
            .collect()
    }

    #[test]
    fn closed_form_rates_match_a_central_difference() {
        // Each contact mode's guard rates, at states with the rod moving both ways and C
        // sliding both ways, against a central difference with d = 1e-6 s: its error
        // d^2 g'''/6 is below 1e-6 of the rates' scale here (the plate's period is 1/30 s).
        for p in [jamming_scene(9.81), authors_scene(10.0)] {
            let m = StickModel::new(p);
            for (k, t) in [0.0, 0.004, 0.011, 0.023].into_iter().enumerate() {
                let mut y = initial_state(&m, t, p.static_angle().unwrap_or(p.theta0_rad));
                y[OM] = [0.8, -1.5, 3.0, -0.2][k];
                y[VXC] = [0.05, -0.03, 0.2, -0.1][k];
                for mode in [Mode::Pivot, Mode::SlideLeft, Mode::SlideRight] {
                    let f = m.flow(mode, t, &y);
                    let mut exact = Vec::new();
                    assert!(m.guard_rates(mode, t, &y, &f, &mut exact));
                    let approx = central(&m, mode, t, &y, 1e-6);
                    let scale = exact.iter().fold(1.0f64, |s, r| s.max(r.abs()));
                    for (i, (e, a)) in exact.iter().zip(&approx).enumerate() {
                        assert!(
                            (e - a).abs() <= 1e-6 * scale,
                            "{mode:?} guard {i} at t = {t}: {e} against {a}"
                        );
                    }
                }
            }
            let y = initial_state(&m, 0.0, p.theta0_rad);
            assert!(!m.guard_rates(Mode::Flight, 0.0, &y, &y, &mut Vec::new()));
        }
    }

    #[test]
    fn contact_guards_read_only_the_guard_args() {
        // GUARD_ARGS promises that the integrated modes' guards read only the leading
        // components: spoiling the others must not change them.
        let p = jamming_scene(9.81);
        let m = StickModel::new(p);
        let y = initial_state(&m, 0.01, p.static_angle().unwrap_or(p.theta0_rad));
        let mut spoiled = y;
        for v in spoiled.iter_mut().skip(StickModel::GUARD_ARGS) {
            *v = f64::NAN;
        }
        for mode in [Mode::Pivot, Mode::SlideLeft, Mode::SlideRight] {
            let (mut a, mut b) = (Vec::new(), Vec::new());
            m.guards(mode, 0.01, &y, &mut a);
            m.guards(mode, 0.01, &spoiled, &mut b);
            assert_eq!(a, b, "{mode:?}");
        }
    }
}
