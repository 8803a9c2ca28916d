//! The stick with inertia as a Moreau-Jean system ([`crate::numerics::timestepping`]):
//! the second method beside the event-driven run.
//!
//! Coordinates `q = (x_G, z_G, theta)`, velocities `v = (vx_G, vz_G, theta')`, mass
//! matrix `diag(M, M, I_G)`. C's velocities are `u_n = vz_G + l_G theta' sin(theta)` and
//! `u_t = vx_G - l_G theta' cos(theta)` (from `r_C = r_G - l_G e_r`), so the contact
//! Jacobians are `w_n = (0, 1, l_G sin)`, `w_t = (1, 0, -l_G cos)`; the Delassus matrix
//! they give is the mobility `W` of [`super::contact`]. The free update takes gravity
//! explicitly and the damper implicitly (the rod's own time scale `I_G/gamma` may be far
//! shorter than the step): `theta'_free = (theta' - h k (theta - theta_0)/I_G) / (1 + h gamma / I_G)`.

use super::{InertiaModel, State, OM, TH};
use crate::numerics::timestepping::ContactModel;

/// The Moreau-Jean view of an [`InertiaModel`] (`I_G > 0`).
pub struct MjStick<'a>(pub &'a InertiaModel);

impl ContactModel<3> for MjStick<'_> {
    fn inv_mass(&self, _t: f64, _q: &[f64; 3], _h: f64) -> [[f64; 3]; 3] {
        let g = &self.0.geo;
        [
            [1.0 / g.total_kg, 0.0, 0.0],
            [0.0, 1.0 / g.total_kg, 0.0],
            [0.0, 0.0, 1.0 / g.i_g],
        ]
    }

    fn free_velocity(&self, _t: f64, q: &[f64; 3], v: &[f64; 3], h: f64) -> [f64; 3] {
        let b = &self.0.p.base;
        let ig = self.0.geo.i_g;
        let om = (v[2] - h * b.stiffness_nm_per_rad * (q[2] - b.theta0_rad) / ig)
            / (1.0 + h * b.damping_nms_per_rad / ig); // formula: I_G (w+ - w) = -h (k (theta - theta_0) + gamma w+)
        [v[0], v[1] - h * b.g_mps2, om] // formula: M (v+ - v) = -h M g e_z
    }

    fn gap(&self, t: f64, q: &[f64; 3]) -> f64 {
        q[1] - self.0.geo.l_g_m * q[2].cos() - self.0.plate(t).0 // formula: z_C - z_s
    }

    fn jacobians(&self, _t: f64, q: &[f64; 3]) -> ([f64; 3], [f64; 3]) {
        let l = self.0.geo.l_g_m;
        let (s, c) = q[2].sin_cos();
        ([0.0, 1.0, l * s], [1.0, 0.0, -l * c]) // formula: u_n = vz_G + l_G w sin, u_t = vx_G - l_G w cos
    }

    fn obstacle_velocity(&self, t: f64) -> (f64, f64) {
        (self.0.plate(t).1, 0.0)
    }

    fn restitution(&self) -> f64 {
        self.0.p.restitution
    }

    fn mu(&self) -> f64 {
        self.0.p.base.mu
    }
}

impl InertiaModel {
    /// `(q, v)` of the Moreau-Jean form from a state of the event-driven form.
    pub(crate) fn to_mj(&self, y: &State) -> ([f64; 3], [f64; 3]) {
        let [xg, zg, vx, vz] = self.centre(y);
        ([xg, zg, y[TH]], [vx, vz, y[OM]])
    }

    /// x of C from Moreau-Jean coordinates (m).
    pub(crate) fn mj_xc(&self, q: &[f64; 3]) -> f64 {
        q[0] - self.geo.l_g_m * q[2].sin()
    }
}

/// Which solution a Moreau-Jean step takes where its contact problem has more than one
/// ([`crate::numerics::timestepping::contact_solutions`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MjSelection {
    /// The first in the order open, stick, slide +t, slide -t
    /// ([`crate::numerics::timestepping::solve_contact`]): separation wherever it is
    /// consistent.
    FirstOpen,
    /// A stuck contact stays stuck while sticking is consistent (the event-driven rules'
    /// pivot, which ends only at the cone's edge or at zero normal force); otherwise as
    /// [`MjSelection::FirstOpen`].
    StickPersists,
}

/// The result of a Moreau-Jean run of the stick.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MjSummary {
    /// Mean speed of C (m/s).
    pub mean_velocity_mps: f64,
    /// Steps in which the contact problem had a stick solution beside the open one (the
    /// rigid problem does not decide there; `FirstOpen` took the open one).
    pub ambiguous_steps: u64,
}

/// Moreau-Jean with step `h_s` from the static start of the event-driven run (`y0`)
/// over `duration_s`, choosing by `sel` where a step's contact problem has two
/// solutions; `None` if a step had none or the state became non-finite.
pub fn mj_run(
    md: &InertiaModel,
    y0: &State,
    duration_s: f64,
    h_s: f64,
    sel: MjSelection,
) -> Option<MjSummary> {
    mj_run_observed(md, y0, duration_s, h_s, sel, |_, _, _| {})
}

/// [`mj_run`], calling `obs(k, t, x_C - x_C(0))` after every step `k = 1, 2, ...` (time
/// `t = k h_s` s, C's displacement in m): a caller samples the displacement at chosen
/// steps (a drive period is a whole number of steps when `h_s = T/n`).
#[allow(clippy::needless_range_loop)] // q, v1, m_wn, m_wt: one index over four arrays
pub fn mj_run_observed(
    md: &InertiaModel,
    y0: &State,
    duration_s: f64,
    h_s: f64,
    sel: MjSelection,
    mut obs: impl FnMut(u64, f64, f64),
) -> Option<MjSummary> {
    use crate::numerics::timestepping::{
        contact_solutions, local_problem, solve_contact, ContactStatus,
    };
    let model = MjStick(md);
    let (q0, v0) = md.to_mj(y0);
    let (mut q, mut v) = (q0, v0);
    let (mut t, mut k, mut prev) = (0.0, 0u64, ContactStatus::Inactive);
    let mut ambiguous = 0u64;
    while t < duration_s {
        let mut t1 = (k + 1) as f64 * h_s; // time as k h: no accumulated round-off
        if t1 > duration_s - 1e-9 * h_s {
            t1 = duration_s;
        }
        let h = t1 - t;
        let (q_m, v_free, problem) = local_problem(&model, t, &q, &v, h, 0.5);
        let mut v1 = v_free;
        let mut status = ContactStatus::Inactive;
        if let Some(lp) = problem {
            let all = contact_solutions(lp.w, lp.u_free, lp.s0, md.p.base.mu);
            let (open, stick) = (all[0], all[1]);
            if open.is_some() && stick.is_some_and(|s| s.p_n > 0.0) {
                ambiguous += 1;
            }
            let imp = match (sel, prev, stick) {
                (MjSelection::StickPersists, ContactStatus::Stick, Some(s)) => s,
                _ => solve_contact(lp.w, lp.u_free, lp.s0, md.p.base.mu)?,
            };
            for i in 0..3 {
                v1[i] += lp.m_wn[i] * imp.p_n + lp.m_wt[i] * imp.p_t; // formula: v_{k+1} = v_free + M^-1 (w_n P_n + w_t P_t)
            }
            status = imp.status;
        }
        for i in 0..3 {
            q[i] = q_m[i] + 0.5 * h * v1[i]; // formula: q_{k+1} = q_m + h v_{k+1} / 2
        }
        v = v1;
        if !q.iter().chain(v.iter()).all(|x| x.is_finite()) {
            return None;
        }
        (t, k, prev) = (t1, k + 1, status);
        obs(k, t, md.mj_xc(&q) - md.mj_xc(&q0));
    }
    Some(MjSummary {
        mean_velocity_mps: (md.mj_xc(&q) - md.mj_xc(&q0)) / duration_s,
        ambiguous_steps: ambiguous,
    })
}

/// Mean speed of C (m/s) by Moreau-Jean with step `h_s` from the static start of the
/// event-driven run (`y0`) over `duration_s`; `None` if the run failed.
pub fn mj_mean_speed(md: &InertiaModel, y0: &State, duration_s: f64, h_s: f64) -> Option<f64> {
    use crate::numerics::timestepping::{simulate, MjOptions};
    let (q0, v0) = md.to_mj(y0);
    let run = simulate(
        &MjStick(md),
        0.0,
        q0,
        v0,
        duration_s,
        &MjOptions::midpoint(h_s),
        |_| {},
    )
    .ok()?;
    Some((md.mj_xc(&run.q) - md.mj_xc(&q0)) / duration_s)
}
