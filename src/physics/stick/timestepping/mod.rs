//! The stick as one frictional unilateral contact for Moreau-Jean time-stepping: an
//! adapter of [`StickModel`] to [`crate::numerics::timestepping::ContactModel`] with
//! `N = 3`, and a run that measures the stick's mean speed.
//!
//! Coordinates `q = (x_p, z_p, theta)` (m, m, rad), velocities `v = (x_p', z_p',
//! theta')`. The rod is massless, so `theta` has no inertia of its own; over a step `h`
//! its moment balance about P (C.8) is integrated with the spring at the step's end
//! and the damper at the end velocity (implicit), with the contact force replaced by its
//! impulse `P = (P_t, P_n)` over the step:
//!
//! ```text
//! 0 = h [k (theta_m + th h theta'+ - theta_0) + gamma theta'+] + L (P_t cos - P_n sin)
//! ```
//!
//! (`theta_m` the step's midpoint angle, `th` the scheme's theta; `th = 1` gives the
//! issue's `theta + h theta'+`). So `theta'+` is linear in `P`, as if `theta` had the
//! "mass" `h (gamma + th k h)` and the free update `-k (theta_m - theta_0) / (gamma +
//! th k h)`. C's relative velocity after the step is then `U = W P + b` with `W = I/m +
//! alpha e_perp e_perp^T`, `alpha = L^2 / (h (gamma + th k h))`, `e_perp = (cos, -sin)`:
//! the numerics' Delassus matrix of this mass matrix and these Jacobians (derivation in
//! the chapter text, section "The stick by three methods").

use super::{StickModel, StickParams};
use crate::numerics::timestepping::{
    self as mj, contact_solutions, distinct_solutions, local_problem, ContactModel, ContactStatus,
    MjOptions, MjStats,
};

/// The stick as a Moreau-Jean contact model (the scheme's theta recorded: the model's
/// implicit rod balance must use the same one).
#[derive(Debug, Clone, Copy)]
pub struct StickContact {
    /// The stick.
    pub model: StickModel,
    /// The theta of the scheme this form is written for (1/2: midpoint).
    pub scheme_theta: f64,
}

impl StickContact {
    /// The contact form of `p` for a scheme with `opts.theta`.
    pub fn new(p: StickParams, opts: &MjOptions) -> Self {
        StickContact {
            model: StickModel::new(p),
            scheme_theta: opts.theta,
        }
    }

    /// `(q, v)` of the stick standing still on the plate at `t` at angle `theta` with C
    /// at `x_c` (m).
    pub(crate) fn on_plate(&self, t: f64, theta: f64, x_c: f64) -> ([f64; 3], [f64; 3]) {
        let l = self.model.p.length_m;
        let (zs, vs, _) = self.model.plate(t);
        let (s, c) = theta.sin_cos();
        ([x_c + l * s, zs + l * c, theta], [0.0, vs, 0.0]) // formula: C.1 P = C + L (sin, cos)
    }

    /// x of C (m): `x_p - L sin(theta)` (C.1).
    pub fn x_c(&self, q: &[f64; 3]) -> f64 {
        q[0] - self.model.p.length_m * q[2].sin()
    }

    /// The rod's implicit "mass" `h (gamma + th k h)` (N m s^2/rad).
    fn rod_mass(&self, h: f64) -> f64 {
        let p = &self.model.p;
        h * (p.damping_nms_per_rad + self.scheme_theta * p.stiffness_nm_per_rad * h)
        // formula: h (gamma + th k h)
    }
}

impl ContactModel<3> for StickContact {
    fn inv_mass(&self, _t: f64, _q: &[f64; 3], h: f64) -> [[f64; 3]; 3] {
        let im = self.model.inv_mass;
        // formula: M^-1 = diag(1/m, 1/m, 1/(h (gamma + th k h)))
        [
            [im, 0.0, 0.0],
            [0.0, im, 0.0],
            [0.0, 0.0, 1.0 / self.rod_mass(h)],
        ]
    }

    fn free_velocity(&self, _t: f64, q: &[f64; 3], v: &[f64; 3], h: f64) -> [f64; 3] {
        let p = &self.model.p;
        let spring = p.stiffness_nm_per_rad * (q[2] - p.theta0_rad);
        [
            v[0],
            v[1] - h * p.g_mps2,            // formula: gravity on P
            -h * spring / self.rod_mass(h), // formula: theta'_free = -k (theta_m - theta_0) / (gamma + th k h)
        ]
    }

    fn gap(&self, t: f64, q: &[f64; 3]) -> f64 {
        q[1] - self.model.p.length_m * q[2].cos() - self.model.plate(t).0 // formula: z_c - z_s, z_c = z_p - L cos
    }

    fn jacobians(&self, _t: f64, q: &[f64; 3]) -> ([f64; 3], [f64; 3]) {
        let l = self.model.p.length_m;
        let (s, c) = q[2].sin_cos();
        // formula: z_c' = z_p' + L sin theta', x_c' = x_p' - L cos theta' (C.3)
        ([0.0, 1.0, l * s], [1.0, 0.0, -l * c])
    }

    fn obstacle_velocity(&self, t: f64) -> (f64, f64) {
        (self.model.plate(t).1, 0.0)
    }

    fn restitution(&self) -> f64 {
        0.0 // the landing is plastic along the rod (C.15)
    }

    fn mu(&self) -> f64 {
        self.model.p.mu
    }
}

/// A Moreau-Jean run of the stick and what its local problems looked like.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MjSummary {
    /// Mean horizontal velocity of C over the run (m/s).
    pub mean_velocity_mps: f64,
    /// Work and contact counters.
    pub stats: MjStats,
    /// Contact steps whose local problem had more than one solution.
    pub ambiguous_steps: u64,
    /// Of those, steps in the self-locking range `|tan theta| < mu`.
    pub ambiguous_self_locking: u64,
    /// Steps with contact whose chosen case was open although a sliding case held too.
    pub open_over_slide: u64,
    /// Deepest penetration of C below the plate at a step's end (m).
    pub max_penetration_m: f64,
    /// Did the run reach its end with a finite state?
    pub completed: bool,
}

/// Runs the stick from rest at its static angle (C at x = 0) for `cycles` drive periods
/// with `steps_per_period` Moreau-Jean steps a period (midpoint rule). `diagnose`:
/// enumerate every local problem's solutions (costs a second solve per contact step).
pub fn simulate_stick_mj(
    p: &StickParams,
    cycles: f64,
    steps_per_period: u32,
    diagnose: bool,
) -> MjSummary {
    let period = p.period_s();
    let opts = MjOptions::midpoint(period / f64::from(steps_per_period));
    let sc = StickContact::new(*p, &opts);
    let theta = p.static_angle().unwrap_or(p.theta0_rad);
    let (q0, v0) = sc.on_plate(0.0, theta, 0.0);
    let mut out = MjSummary {
        mean_velocity_mps: f64::NAN,
        stats: MjStats::default(),
        ambiguous_steps: 0,
        ambiguous_self_locking: 0,
        open_over_slide: 0,
        max_penetration_m: 0.0,
        completed: false,
    };
    let t_end = cycles * period;
    let mu = p.mu;
    let run = mj::simulate(&sc, 0.0, q0, v0, t_end, &opts, |s| {
        out.max_penetration_m = out.max_penetration_m.max(-sc.gap(s.t1, &s.q1));
        if !diagnose || s.impulse.status == ContactStatus::Inactive {
            return;
        }
        let (_, _, lp) = local_problem(&sc, s.t0, &s.q0, &s.v0, s.t1 - s.t0, opts.theta);
        let Some(lp) = lp else { return };
        let sols = contact_solutions(lp.w, lp.u_free, lp.s0, mu);
        if distinct_solutions(&sols) > 1 {
            out.ambiguous_steps += 1;
            if lp.q_m[2].tan().abs() < mu {
                out.ambiguous_self_locking += 1;
            }
            if s.impulse.status == ContactStatus::Open && (sols[2].is_some() || sols[3].is_some()) {
                out.open_over_slide += 1;
            }
        }
    });
    if let Ok(r) = run {
        out.stats = r.stats;
        out.mean_velocity_mps = (sc.x_c(&r.q) - sc.x_c(&q0)) / (r.t_s - 0.0);
        out.completed = out.mean_velocity_mps.is_finite();
    }
    out
}

#[cfg(test)]
mod tests;
