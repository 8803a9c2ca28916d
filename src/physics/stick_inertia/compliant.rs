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

/// The stuck foot with a compliant normal contact (issue 29, the two-solution scenes):
/// C held horizontally (the stick persists; its force is checked against the cone) and
/// a Kelvin-Voigt spring-damper `F_n = max(0, K h + c h')` in the normal direction
/// (`h = z_s - z_C`), on the vibrating plate. State `y = [z_G, theta, vz_G, theta']`.
///
/// With `x_C` fixed, `x_G'' = l_G (theta'' cos - theta'^2 sin)` and `F_t = M x_G''`;
/// the rod's moment balance `I_G theta'' = -l_G (F_t cos - F_n sin) - Q` becomes
/// `(I_G + M l_G^2 cos^2) theta'' = M l_G^2 cos sin theta'^2 + l_G sin F_n - Q`.
struct PinnedSoft<'a> {
    md: &'a InertiaModel,
    k: f64,
    c: f64,
}

impl PinnedSoft<'_> {
    /// `(F_t, F_n, theta'')` (N, N, rad/s^2).
    fn forces(&self, t: f64, y: &[f64; 4]) -> (f64, f64, f64) {
        let g = &self.md.geo;
        let l = g.l_g_m;
        let (s, c) = y[1].sin_cos();
        let (zs, vs, _) = self.md.plate(t);
        let h = zs - (y[0] - l * c); // formula: h = z_s - z_C, z_C = z_G - l_G cos
        let hd = vs - (y[2] + l * y[3] * s); // formula: h' = v_s - vz_C, vz_C = vz_G + l_G theta' sin
        let fn_ = if h > 0.0 {
            (self.k * h + self.c * hd).max(0.0)
        } else {
            0.0
        };
        let q = self.md.couple(y[1], y[3]);
        let m = g.total_kg;
        let th_dd =
            (m * l * l * c * s * y[3] * y[3] + l * s * fn_ - q) / (g.i_g + m * l * l * c * c); // formula: (I_G + M l_G^2 cos^2) theta'' = M l_G^2 cos sin theta'^2 + l_G sin F_n - Q
        let ft = m * l * (th_dd * c - y[3] * y[3] * s); // formula: F_t = M l_G (theta'' cos - theta'^2 sin)
        (ft, fn_, th_dd)
    }
}

impl OdeSystem<4> for PinnedSoft<'_> {
    fn rhs(&self, t: f64, y: &[f64; 4]) -> [f64; 4] {
        let (_, fn_, th_dd) = self.forces(t, y);
        let g = &self.md.geo;
        [y[2], y[3], fn_ / g.total_kg - self.md.p.base.g_mps2, th_dd] // formula: M z_G'' = F_n - M g
    }
}

/// How the compliant stuck foot ends ([`pinned_lift_off`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompliantEnd {
    /// Time (s) at which the normal force first vanishes (lift-off), or the force first
    /// leaves Coulomb's cone (`slides`).
    pub t_s: f64,
    /// The force left the cone before it vanished.
    pub slides: bool,
}

/// The relative normal acceleration of C with no contact force (m/s^2) in the pivot
/// state `y` at `t`: `z_C'' - z_s''` with `a_G = -g e_z`, `I_G theta'' = -Q`. Lift-off
/// (the open solution) is consistent where it is at least 0.
pub fn free_normal_acceleration(md: &InertiaModel, t: f64, y: &super::State) -> f64 {
    let l = md.geo.l_g_m;
    let (s, c) = y[super::TH].sin_cos();
    let om = y[super::OM];
    let th_dd = -md.couple(y[super::TH], om) / md.geo.i_g; // formula: I_G theta'' = -Q
    -md.p.base.g_mps2 + l * (th_dd * s + om * om * c) - md.plate(t).2 // formula: z_C'' = z_G'' + l_G (theta'' sin + theta'^2 cos)
}

/// The rigid pivot's contact force `(F_x, F_z)` (N) in state `y` at `t`.
pub fn pivot_force(md: &InertiaModel, t: f64, y: &super::State) -> (f64, f64) {
    let e = md.pivot_eval(t, y);
    (e.fx, e.fz)
}

/// The stuck foot of the pivot state `y` at `t0` with the compliant normal contact of
/// stiffness `k` (N/m) and damping `2 zeta sqrt(K m_n)` (`m_n = W_tt/det W`, the normal
/// mass with the foot stuck; `zeta = 1`), from the rigid pivot's force (penetration
/// `F_z/K`) and velocities, up to `t_max_s`: when its normal force vanishes or leaves
/// the cone; `None` if neither happens or the integration fails.
pub fn pinned_lift_off(
    md: &InertiaModel,
    t0: f64,
    y: &super::State,
    k: f64,
    t_max_s: f64,
) -> Option<CompliantEnd> {
    let w = md.mobility(y[super::TH]);
    let m_n = w[0][0] / (w[0][0] * w[1][1] - w[0][1] * w[1][0]); // formula: m_n = W_tt / det W
    let sys = PinnedSoft {
        md,
        k,
        c: 2.0 * (k * m_n).sqrt(),
    };
    let [_, zg, _, vzg] = md.centre(y);
    let (_, fz) = pivot_force(md, t0, y);
    let y0 = [zg - fz / k, y[super::TH], vzg, y[super::OM]]; // formula: h_0 = F_z / K
    let mu = md.p.base.mu;
    let ends = |t: f64, y: &[f64; 4]| {
        let (ft, fn_, _) = sys.forces(t, y);
        (fn_ <= 0.0, ft.abs() > mu * fn_)
    };
    let mut integ = Integrator::<4>::new(Method::Dop853, StepControl::tol(1e-12, 1e-14));
    let (mut t, mut yc) = (t0, y0);
    while t < t_max_s {
        let st = integ.step(&sys, t, &yc, t_max_s).ok()?;
        let (lift, slide) = ends(st.t1, &st.y1);
        if lift || slide {
            let (mut a, mut b) = (st.t0, st.t1);
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                let (l, s) = ends(m, &st.eval(&sys, m));
                if l || s {
                    b = m;
                } else {
                    a = m;
                }
            }
            let (_, s) = ends(b, &st.eval(&sys, b));
            return Some(CompliantEnd { t_s: b, slides: s });
        }
        t = st.t1;
        yc = st.y1;
    }
    None
}
