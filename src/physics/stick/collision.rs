//! Impulsive maps: the landing collision (C.15) and the jam that stops a slide.
//!
//! The rod is massless and the spring and damper carry no impulsive moment, so an
//! impulse at C reaches P along the rod: `J = lambda e_r`, `e_r = (sin, cos)`. Hence
//! the angular momentum of P about C is conserved (C.15) and only the velocity of P
//! along the rod, relative to the plate, `w = (v_P - zdot_s e_z) . e_r`, is destroyed:
//! `lambda = -m w` (compressive only if `w < 0`, the rod is shortening), the plate does
//! work `lambda cos(theta) zdot_s` and the impact dissipates `m w^2 / 2`. The impulse is
//! inside the friction cone only if `|tan(theta)| <= mu`; otherwise no impulse can act
//! and C lands sliding (see [`StickModel::impulse_free_landing`]).

use super::{State, StickModel, D_IMPACT, OM, TH, VXC, VZC, W_PLATE, ZC};

/// What a sticking impact did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Impact {
    /// The state just after (C stuck on the plate).
    pub after: State,
    /// Along-rod velocity of P relative to the plate before the impact (m/s).
    pub w_mps: f64,
    /// Impulse magnitude along the rod (N s), `-m w`.
    pub lambda_ns: f64,
    /// Angular momentum of P about C per unit mass before, `L^2 theta'` form (m^2/s).
    pub h_before: f64,
    /// The same after (m^2/s).
    pub h_after: f64,
}

impl StickModel {
    /// Angular momentum of P about C relative to the plate, per unit mass, in the
    /// document's sign: `-(r_P/C x (v_P - zdot_s e_z))_y` = `(z_p - z_c)(xdot_p) -
    /// (x_p - x_c)(zdot_p - zdot_s)` with lever arm at `theta_lever` (m^2/s).
    pub(crate) fn angular_momentum_about_c(&self, t: f64, y: &State, theta_lever: f64) -> f64 {
        let l = self.p.length_m;
        let [_, _, vxp, vzp] = self.tip(y);
        let (_, vs, _) = self.plate(t);
        let (s, c) = theta_lever.sin_cos();
        l * c * vxp - l * s * (vzp - vs) // formula: C.15 r x (v_p - zdot_s k)
    }

    /// The sticking impact (C.15) at `(t, y)` with lever arm at `theta_lever` (the actual
    /// angle, or theta_0 for the document's reset). C ends stuck on the plate at the
    /// angle `theta_lever`.
    pub fn sticking_impact(&self, t: f64, y: &State, theta_lever: f64) -> Impact {
        let p = &self.p;
        let (l, m) = (p.length_m, p.mass_kg);
        let [_, _, vxp, vzp] = self.tip(y);
        let (zs, vs, _) = self.plate(t);
        let (s, c) = theta_lever.sin_cos();
        let (ux, uz) = (vxp, vzp - vs);
        let w = ux * s + uz * c; // formula: w = (v_P - v_s).e_r
        let h_before = self.angular_momentum_about_c(t, y, theta_lever);
        let om = (ux * c - uz * s) / l; // formula: C.15 theta'+ = r x (v_p - v_s) / L^2
        let lambda = -m * w;
        let mut a = *y;
        a[TH] = theta_lever;
        a[ZC] = zs;
        a[VXC] = 0.0;
        a[VZC] = vs;
        a[OM] = om;
        a[W_PLATE] += lambda * c * vs; // formula: plate work of the impulse J_z zdot_s
        a[D_IMPACT] += 0.5 * m * w * w; // formula: impact loss m w^2 / 2
        let h_after = self.angular_momentum_about_c(t, &a, theta_lever);
        Impact {
            after: a,
            w_mps: w,
            lambda_ns: lambda,
            h_before,
            h_after,
        }
    }

    /// Landing without an impulse: P keeps its velocity, the rod's rate jumps so that C
    /// moves with the plate vertically, `theta' = (zdot_s - zdot_p) / (L sin(theta))`,
    /// and C slides at `xdot_c = xdot_p - L theta' cos(theta)` (Algorithm 2's third
    /// branch). `None` when `sin(theta) = 0` (the rod vertical: no such motion).
    pub(crate) fn impulse_free_landing(&self, t: f64, y: &State) -> Option<State> {
        let l = self.p.length_m;
        let [_, _, vxp, vzp] = self.tip(y);
        let (zs, vs, _) = self.plate(t);
        let (s, c) = y[TH].sin_cos();
        if s.abs() < 1e-9 {
            return None;
        }
        let om = (vs - vzp) / (l * s); // formula: Alg. 2 theta' <- -(zdot_p - zdot_s)/(L sin)
        let mut a = *y;
        a[ZC] = zs;
        a[OM] = om;
        a[VXC] = vxp - l * om * c; // formula: Alg. 2 xdot_c <- xdot_p + (zdot_p - zdot_s) cot
        a[VZC] = vs;
        Some(a)
    }
}
