//! The compliant limit of an impact without collision: the sliding rod on a still plate
//! with a stiff normal spring-damper at C instead of a rigid contact (chapter 7's
//! soft-contact idea), integrated as a plain ODE until the slip stops.
//!
//! Normal force `F_n = max(0, K h + c h')` with the penetration `h = -z_C` and
//! `c = 2 sqrt(K M)`; friction `F_t = -mu F_n sign(u_t)` while C slips. In a Painleve
//! case (`A < 0`) the compliant contact is unstable: the force grows until friction has
//! stopped the slip. As `K -> infinity` the impulse gathered by then should tend to the
//! rigid rule's (the first, slipping, piece of the Darboux-Keller impulse from `u_n = 0`).

use super::InertiaModel;
use crate::numerics::ode::{Integrator, Method, OdeSystem, StepControl};

/// The compliant rod: `y = [x_G, z_G, theta, vx_G, vz_G, theta', P_t, P_n]`.
struct Soft<'a> {
    md: &'a InertiaModel,
    k: f64,
    c: f64,
    sign: f64,
}

impl Soft<'_> {
    /// Contact force `(F_t, F_n)` (N).
    fn force(&self, y: &[f64; 8]) -> (f64, f64) {
        let l = self.md.geo.l_g_m;
        let (s, c) = y[2].sin_cos();
        let h = -(y[1] - l * c); // formula: penetration h = -z_C, z_C = z_G - l_G cos
        let hd = -(y[4] + l * y[5] * s); // formula: h' = -vz_C, vz_C = vz_G + l_G theta' sin
        let fn_ = if h > 0.0 {
            (self.k * h + self.c * hd).max(0.0)
        } else {
            0.0
        };
        (-self.sign * self.md.p.base.mu * fn_, fn_)
    }
}

impl OdeSystem<8> for Soft<'_> {
    fn rhs(&self, _t: f64, y: &[f64; 8]) -> [f64; 8] {
        let g = &self.md.geo;
        let (s, c) = y[2].sin_cos();
        let (ft, fn_) = self.force(y);
        let th_dd = -g.l_g_m * (ft * c - fn_ * s) / g.i_g; // formula: I_G theta'' = -l_G F . e_theta (no couple)
        [
            y[3],
            y[4],
            y[5],
            ft / g.total_kg,                          // formula: M a_Gx = F_t
            fn_ / g.total_kg - self.md.p.base.g_mps2, // formula: M a_Gz = F_n - M g
            th_dd,
            ft,
            fn_,
        ]
    }
}

/// The compliant run of a rod at `theta` whose foot slips at `u_t` (m/s) on a still
/// plate, from exact contact at rest vertically, with stiffness `k` (N/m): the impulse
/// `(P_t, P_n)` (N s) and C's normal velocity (m/s) when the slip stops; `None` if it
/// has not stopped within `t_max_s`.
pub(crate) fn slip_stop(
    md: &InertiaModel,
    theta: f64,
    u_t: f64,
    k: f64,
    t_max_s: f64,
) -> Option<(f64, f64, f64)> {
    let g = &md.geo;
    let c = theta.cos();
    let sys = Soft {
        md,
        k,
        c: 2.0 * (k * g.total_kg).sqrt(),
        sign: u_t.signum(),
    };
    // C at rest vertically on the plate, slipping at u_t, no rotation
    let y0 = [0.0, g.l_g_m * c, theta, u_t, 0.0, 0.0, 0.0, 0.0];
    let slip = |y: &[f64; 8]| y[3] - g.l_g_m * y[5] * y[2].cos(); // formula: u_t = vx_G - l_G theta' cos
    let mut integ = Integrator::<8>::new(Method::Dop853, StepControl::tol(1e-11, 1e-13));
    let (mut t, mut y) = (0.0, y0);
    while t < t_max_s {
        let st = integ.step(&sys, t, &y, t_max_s).ok()?;
        if slip(&st.y1) * u_t.signum() <= 0.0 {
            // locate the stop on the dense output
            let (mut a, mut b) = (st.t0, st.t1);
            for _ in 0..80 {
                let m = 0.5 * (a + b);
                if slip(&st.eval(&sys, m)) * u_t.signum() > 0.0 {
                    a = m;
                } else {
                    b = m;
                }
            }
            let ye = st.eval(&sys, b);
            let vzc = ye[4] + g.l_g_m * ye[5] * ye[2].sin();
            return Some((ye[6], ye[7], vzc));
        }
        t = st.t1;
        y = st.y1;
    }
    None
}

/// The rigid rule's prediction at the slip stop: the first piece of the impact without
/// collision, `p1 = -u_t / (W_tt r + W_tn)` with `r = -mu sign(u_t)`; returns
/// `(P_n, u_n)` at the stop (N s, m/s).
pub(crate) fn rigid_slip_stop(md: &InertiaModel, theta: f64, u_t: f64) -> (f64, f64) {
    let w = md.mobility(theta);
    let r = -u_t.signum() * md.p.base.mu;
    let p1 = -u_t / (w[0][0] * r + w[0][1]); // formula: u_t + (W_tt r + W_tn) p = 0
    (p1, (w[1][0] * r + w[1][1]) * p1) // formula: u_n = (W_nt r + W_nn) p
}
