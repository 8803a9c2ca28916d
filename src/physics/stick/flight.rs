//! Flight in closed form (C.3, C.5).
//!
//! No contact force: the massless rod's moment balance is `k (theta - theta_0) +
//! gamma theta' = 0`, so `theta - theta_0` decays as `exp(-k t / gamma)`; P is ballistic.
//! The damper dissipates exactly the spring energy released: `k/2 (d0^2 - d^2)`.

use super::{State, StickModel, D_DAMP, OM, ROD_X, ROD_Z, TH, VXC, VZC, XC, ZC};

impl StickModel {
    /// The flight state at `t` of a flight that starts at `(t0, y0)`.
    #[inline]
    pub(crate) fn flight_state(&self, t0: f64, y0: &State, t: f64) -> State {
        let p = &self.p;
        let (l, g) = (p.length_m, p.g_mps2);
        let tau = t - t0;
        let [xp0, zp0, vxp0, vzp0] = self.tip(y0);
        let xp = xp0 + vxp0 * tau; // formula: C.5 ballistic x
        let zp = zp0 + vzp0 * tau - 0.5 * g * tau * tau; // formula: C.5 ballistic z
        let vzp = vzp0 - g * tau;
        let d0 = y0[TH] - p.theta0_rad;
        let (d, w) = if self.rate.is_finite() && self.rate > 0.0 {
            let d = d0 * (-self.rate * tau).exp(); // formula: C.3 theta - theta0 = d0 exp(-k t/gamma)
            (d, -self.rate * d) // formula: C.3 theta' = -(k/gamma)(theta - theta0)
        } else {
            (d0, 0.0)
        };
        let th = p.theta0_rad + d;
        let (s, c) = th.sin_cos();
        let mut y = *y0;
        y[TH] = th;
        y[OM] = w;
        y[XC] = xp - l * s; // formula: C.2
        y[ZC] = zp - l * c; // formula: C.2
        y[VXC] = vxp0 - l * w * c; // formula: C.3 xdot_c
        y[VZC] = vzp + l * w * s; // formula: C.3 zdot_c
        (y[ROD_X], y[ROD_Z]) = (s, c);
        y[D_DAMP] = y0[D_DAMP] + 0.5 * p.stiffness_nm_per_rad * (d0 * d0 - d * d); // formula: int gamma theta'^2 = k/2 (d0^2 - d^2)
        y
    }

    /// Height of C above the plate, `h_c = z_c - z_s` (Table 1).
    #[inline]
    pub(crate) fn h_c(&self, t: f64, y: &State) -> f64 {
        y[ZC] - self.plate(t).0
    }

    /// The rounding budget of `h_c` at a flight state `(t, y)` (m): how far below the
    /// plate a correctly located landing (or any flight state) may read. Two parts.
    /// (1) The landing is located to the event tolerance `t_tol = 4 eps max(|t|, 1)`
    /// (`numerics::events::time_tolerance`) and reported at the bracket's far end, past
    /// the root by at most `t_tol`, where `h_c` has moved by `|h_c'| t_tol`.
    /// (2) `h_c` itself is computed with an error `dh`, which also moves the root by
    /// `dh/|h_c'|`, so it enters twice: the plate's phase `f t + phi` (turns) is rounded
    /// to `eps (|f t| + |phi| + 1)` turns, which moves `z_s = A sin` by `2 pi A` times
    /// that, at the lift-off (C set onto the plate) and again now; the closed form's
    /// and the difference's arithmetic round terms of size `|z_c| + A + L` a few (16)
    /// times. This grows with `t` and with the number of cycles `f t`: a fixed bound
    /// cannot hold over long runs.
    pub(crate) fn penetration_budget_m(&self, t: f64, y: &State) -> f64 {
        let eps = f64::EPSILON;
        let a = self.p.plate.amplitude_m;
        let t_tol = 4.0 * eps * t.abs().max(1.0); // formula: numerics::events::time_tolerance
        let rate = (y[VZC] - self.plate(t).1).abs(); // |h_c'|
        let phase = 2.0
            * std::f64::consts::TAU
            * a
            * eps
            * ((self.frequency_hz * t).abs() + self.phase_turns.abs() + 1.0); // formula: 2 x 2 pi A eps (|f t| + |phi| + 1)
        let arith = 16.0 * eps * (y[ZC].abs() + a + self.p.length_m); // formula: 16 eps (|z_c| + A + L)
        rate * t_tol + 2.0 * (phase + arith) // formula: |h_c'| t_tol + 2 dh
    }

    /// Longest flight step from `(t, y)` over which `h_c` provably stays positive:
    /// with `|h_c''| <= A = g + delta omega^2 + L (k/gamma)^2 (d^2 + |d|)`,
    /// `h_c(t + s) >= h + v s - A s^2 / 2`, positive for `s < (v + sqrt(v^2 + 2 A h)) / A`.
    /// Never shorter than the model's `min_flight_sample_s`.
    pub(crate) fn flight_step(&self, t: f64, y: &State) -> f64 {
        let p = &self.p;
        let (_, vs, _) = self.plate(t);
        let h = self.h_c(t, y).max(0.0);
        let v = y[VZC] - vs;
        let d = (y[TH] - p.theta0_rad).abs();
        let r2 = if self.rate.is_finite() {
            self.rate * self.rate
        } else {
            0.0
        };
        let a = p.g_mps2 + p.plate.peak_acceleration_mps2() + p.length_m * r2 * (d * d + d);
        let safe = (v + (v * v + 2.0 * a * h).sqrt()) / a; // formula: root of h + v s - A s^2/2
        safe.max(self.min_flight_sample_s).min(4.0 * self.period_s)
    }
}
