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

use super::{InertiaModel, Mode, State, OM, TH};
use crate::numerics::timestepping::{ContactModel, ContactStatus};

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

/// [`MjStick`] with its contact held active: the gap counts as at most zero. A step
/// after a stuck one under [`MjSelection::StickPersists`] uses it, so that a stuck foot
/// separates only through its contact problem (sticking no longer consistent: the
/// rules' pivot ends at zero force or at the cone's edge), never through the
/// `O(h^2)` drift of its position about the plate. (Without it the midpoint gap of a
/// stuck foot alternates in sign at 1e-13 m, a step with a positive one is inactive,
/// and the step after it chooses in the solver's order, open first: on the long
/// differential run's scene 117 that lifted the foot off a two-solution pivot at some
/// steps and not at others.)
struct Held<'a, 'b>(&'b MjStick<'a>);

impl ContactModel<3> for Held<'_, '_> {
    fn inv_mass(&self, t: f64, q: &[f64; 3], h: f64) -> [[f64; 3]; 3] {
        self.0.inv_mass(t, q, h)
    }

    fn free_velocity(&self, t: f64, q: &[f64; 3], v: &[f64; 3], h: f64) -> [f64; 3] {
        self.0.free_velocity(t, q, v, h)
    }

    fn gap(&self, t: f64, q: &[f64; 3]) -> f64 {
        self.0.gap(t, q).min(0.0) // formula: the held contact is active
    }

    fn jacobians(&self, t: f64, q: &[f64; 3]) -> ([f64; 3], [f64; 3]) {
        self.0.jacobians(t, q)
    }

    fn obstacle_velocity(&self, t: f64) -> (f64, f64) {
        self.0.obstacle_velocity(t)
    }

    fn restitution(&self) -> f64 {
        self.0.restitution()
    }

    fn mu(&self) -> f64 {
        self.0.mu()
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
    /// pivot, which ends only at the cone's edge or at zero normal force), and its
    /// contact stays active meanwhile whatever the sign of its midpoint gap; otherwise as
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
pub fn mj_run_observed(
    md: &InertiaModel,
    y0: &State,
    duration_s: f64,
    h_s: f64,
    sel: MjSelection,
    mut obs: impl FnMut(u64, f64, f64),
) -> Option<MjSummary> {
    let start = md.mj_state(0.0, Mode::Flight, y0); // no stick before the first step
    let x0 = md.mj_xc(&start.q);
    let end = mj_run_from(md, &start, duration_s, h_s, sel, |k, s| {
        obs(k, s.t_s, md.mj_xc(&s.q) - x0);
    })?;
    Some(MjSummary {
        mean_velocity_mps: (md.mj_xc(&end.state.q) - x0) / duration_s,
        ambiguous_steps: end.ambiguous_steps,
    })
}

/// A state of the Moreau-Jean run: time, `q`, `v` and the contact case of the step
/// that ended there (what [`MjSelection::StickPersists`] reads).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MjState {
    /// Time (s).
    pub t_s: f64,
    /// `(x_G, z_G, theta)` (m, m, rad).
    pub q: [f64; 3],
    /// `(vx_G, vz_G, theta')` (m/s, m/s, rad/s).
    pub v: [f64; 3],
    /// The contact case of the last step ([`ContactStatus::Stick`] for a stuck foot).
    pub status: ContactStatus,
}

/// The end of [`mj_run_from`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MjEnd {
    /// The state at the end time.
    pub state: MjState,
    /// Steps whose contact problem had a stick solution beside the open one.
    pub ambiguous_steps: u64,
}

impl InertiaModel {
    /// The Moreau-Jean state of the event-driven state `y` in `mode` at `t_s`: a pivot
    /// is a stuck contact (so [`MjSelection::StickPersists`] keeps it while sticking is
    /// consistent, as the rules do), a slide slides along C's velocity, flight has no
    /// contact.
    pub fn mj_state(&self, t_s: f64, mode: Mode, y: &State) -> MjState {
        let (q, v) = self.to_mj(y);
        let status = match mode {
            Mode::Flight => ContactStatus::Inactive,
            Mode::Pivot => ContactStatus::Stick,
            Mode::SlideLeft => ContactStatus::SlideNegative,
            Mode::SlideRight => ContactStatus::SlidePositive,
        };
        MjState { t_s, q, v, status }
    }

    /// C's position `(x_C, z_C)` and velocity `(vx_C, vz_C)` of a Moreau-Jean state (m,
    /// m/s): `r_C = r_G - l_G e_r`, `v_C = v_G - l_G theta' e_theta`.
    pub fn mj_point_c(&self, s: &MjState) -> [f64; 4] {
        let l = self.geo.l_g_m;
        let (sn, cs) = s.q[2].sin_cos();
        [
            s.q[0] - l * sn,          // formula: x_C = x_G - l_G sin
            s.q[1] - l * cs,          // formula: z_C = z_G - l_G cos
            s.v[0] - l * cs * s.v[2], // formula: vx_C = vx_G - l_G theta' cos
            s.v[1] + l * sn * s.v[2], // formula: vz_C = vz_G + l_G theta' sin
        ]
    }
}

/// Moreau-Jean with step `h_s` from `start` (any time, any state, e.g. an event-driven
/// run's state at a whole drive period: [`InertiaModel::mj_state`]) over `duration_s`,
/// choosing by `sel` where a step's contact problem has two solutions (the stuck case
/// persists from `start.status` under [`MjSelection::StickPersists`]); calls `obs(k, s)`
/// after every step `k = 1, 2, ...` (time `start.t_s + k h_s`). `None` if a step had no
/// contact solution or the state became non-finite.
#[allow(clippy::needless_range_loop)] // q, v1, m_wn, m_wt: one index over four arrays
pub fn mj_run_from(
    md: &InertiaModel,
    start: &MjState,
    duration_s: f64,
    h_s: f64,
    sel: MjSelection,
    mut obs: impl FnMut(u64, &MjState),
) -> Option<MjEnd> {
    use crate::numerics::timestepping::{contact_solutions, local_problem, solve_contact};
    let model = MjStick(md);
    let (t0, t_end) = (start.t_s, start.t_s + duration_s);
    let mut s = *start;
    let (mut k, mut ambiguous) = (0u64, 0u64);
    while s.t_s < t_end {
        let mut t1 = t0 + (k + 1) as f64 * h_s; // time as t0 + k h: no accumulated round-off
        if t1 > t_end - 1e-9 * h_s {
            t1 = t_end;
        }
        let h = t1 - s.t_s;
        let held = sel == MjSelection::StickPersists && s.status == ContactStatus::Stick;
        let (q_m, v_free, problem) = if held {
            local_problem(&Held(&model), s.t_s, &s.q, &s.v, h, 0.5)
        } else {
            local_problem(&model, s.t_s, &s.q, &s.v, h, 0.5)
        };
        let mut v1 = v_free;
        let mut status = ContactStatus::Inactive;
        if let Some(lp) = problem {
            let all = contact_solutions(lp.w, lp.u_free, lp.s0, md.p.base.mu);
            let (open, stick) = (all[0], all[1]);
            if open.is_some() && stick.is_some_and(|s| s.p_n > 0.0) {
                ambiguous += 1;
            }
            let imp = match (sel, s.status, stick) {
                (MjSelection::StickPersists, ContactStatus::Stick, Some(st)) => st,
                _ => solve_contact(lp.w, lp.u_free, lp.s0, md.p.base.mu)?,
            };
            for i in 0..3 {
                v1[i] += lp.m_wn[i] * imp.p_n + lp.m_wt[i] * imp.p_t; // formula: v_{k+1} = v_free + M^-1 (w_n P_n + w_t P_t)
            }
            status = imp.status;
        }
        for i in 0..3 {
            s.q[i] = q_m[i] + 0.5 * h * v1[i]; // formula: q_{k+1} = q_m + h v_{k+1} / 2
        }
        s.v = v1;
        if !s.q.iter().chain(s.v.iter()).all(|x| x.is_finite()) {
            return None;
        }
        (s.t_s, k, s.status) = (t1, k + 1, status);
        obs(k, &s);
    }
    Some(MjEnd {
        state: s,
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
