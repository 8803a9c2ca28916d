//! Moreau-Jean event-capturing time-stepping for one frictional unilateral contact.
//!
//! Instead of locating every impact and every stick-slip switch (the event-driven
//! [`super::hybrid`] driver), Moreau-Jean integrates the *measure* differential
//! inclusion `M dv = f dt + w_n dP_n + w_t dP_t` with a fixed step `h` and solves, per
//! step, for the contact *impulses* `P_n, P_t` over the step. Impacts, sticking and
//! sliding come out of one local problem; nothing is located, and accumulations of
//! impacts (Zeno) pass in finitely many steps. The price is order one.
//!
//! The theta scheme (`theta = 1/2`: Moreau's midpoint rule), for generalized
//! coordinates `q` and velocities `v = q'`:
//!
//! ```text
//! q_m     = q_k + (1 - theta) h v_k                      (midpoint position)
//! v_free  = v_k + h M^-1 f(t_m, q_m, v_k)                 (the model's free update)
//! v_{k+1} = v_free + M^-1 (w_n P_n + w_t P_t)
//! q_{k+1} = q_m + theta h v_{k+1}
//! ```
//!
//! The contact is active in a step when the gap at the midpoint is `g(t_m, q_m) <= 0`.
//! Then, with the relative contact velocities `u = (w_n . v - b_n, w_t . v - b_t)`
//! (`b`: the obstacle's velocity at the contact) the impulses solve Newton's impact law
//! and Coulomb's law at the velocity level:
//!
//! ```text
//! 0 <= u_n,{k+1} + e u_n,k  _|_  P_n >= 0
//! |P_t| <= mu P_n,   u_t,{k+1} != 0  =>  P_t = -mu P_n sign(u_t,{k+1})
//! ```
//!
//! With the Delassus matrix `W = [w_n w_t]^T M^-1 [w_n w_t]` (2 x 2), the new velocities
//! are `u_{k+1} = u_free + W P` and the problem is a small LCP that [`solve_contact`]
//! solves exactly by enumerating its four cases: open, stick, slide towards +t, slide
//! towards -t.
//!
//! The model supplies its contact data through [`ContactModel`]; this module knows
//! nothing of blocks, balls or sticks.

mod cases;
pub use cases::{contact_solutions, distinct_solutions};

/// The data a mechanical system with one frictional unilateral contact supplies.
///
/// Coordinates `q` and velocities `v` have the same dimension `N`, and `q' = v`.
pub trait ContactModel<const N: usize> {
    /// The inverse mass matrix `M^-1(t, q)` (it may depend on `h` through the model,
    /// e.g. for a massless coordinate with viscous damping).
    fn inv_mass(&self, t: f64, q: &[f64; N], h: f64) -> [[f64; N]; N];

    /// The free (contact-less) velocity update over a step of length `h` from the
    /// midpoint `(t, q)` with the velocity `v` at the start of the step:
    /// `v + h M^-1 f(t, q, v)` (or a semi-implicit variant of it chosen by the model).
    /// One call counts as one right-hand-side evaluation.
    fn free_velocity(&self, t: f64, q: &[f64; N], v: &[f64; N], h: f64) -> [f64; N];

    /// The gap `g(t, q)`: positive when the contact is open (m).
    fn gap(&self, t: f64, q: &[f64; N]) -> f64;

    /// The normal and tangential Jacobians `(w_n, w_t)`: the relative contact
    /// velocities are `u_n = w_n . v - b_n`, `u_t = w_t . v - b_t`.
    fn jacobians(&self, t: f64, q: &[f64; N]) -> ([f64; N], [f64; N]);

    /// The obstacle's velocity at the contact, `(b_n, b_t)` (m/s); zero by default
    /// (a fixed floor).
    fn obstacle_velocity(&self, _t: f64) -> (f64, f64) {
        (0.0, 0.0)
    }

    /// Newton's coefficient of restitution `e` in `[0, 1]`.
    fn restitution(&self) -> f64;

    /// Coulomb's friction coefficient `mu >= 0`.
    fn mu(&self) -> f64;
}

/// Which case of the contact problem a step ended in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContactStatus {
    /// Gap positive at the midpoint: the contact was not considered.
    Inactive,
    /// Active but no impulse needed (separating).
    Open,
    /// Sticking: tangential relative velocity zero, impulse inside the cone.
    Stick,
    /// Sliding towards +t: impulse on the cone, `P_t = -mu P_n`.
    SlidePositive,
    /// Sliding towards -t: impulse on the cone, `P_t = +mu P_n`.
    SlideNegative,
}

/// The impulses of one step and the case they came from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Impulse {
    /// The case.
    pub status: ContactStatus,
    /// Normal impulse over the step (N s).
    pub p_n: f64,
    /// Tangential impulse over the step (N s).
    pub p_t: f64,
}

/// Solves the one-contact frictional LCP `u = u_free + W P` exactly:
/// `0 <= u_n + s0 _|_ P_n >= 0` with `s0 = e u_n,k` and Coulomb's law on `(u_t, P_t)`.
///
/// The cases are tried in the order open, stick, slide +t, slide -t and the first one
/// whose conditions hold is returned. `None`: no case holds (a Painleve-type
/// inconsistency, possible only when `mu |W_nt|` is comparable with `W_nn`).
pub(crate) fn solve_contact(
    w: [[f64; 2]; 2],
    u_free: [f64; 2],
    s0: f64,
    mu: f64,
) -> Option<Impulse> {
    let s = u_free[0] + s0; // the free value of u_n + e u_n,k
    let ut = u_free[1];
    // Relative slack for the inequality checks: round-off of the 2 x 2 solves.
    let eps = 1e-12;
    if s >= 0.0 {
        return Some(Impulse {
            status: ContactStatus::Open,
            p_n: 0.0,
            p_t: 0.0,
        });
    }
    let (wnn, wnt, wtt) = (w[0][0], w[0][1], w[1][1]);
    // Stick: u_n + s0 = 0 and u_t = 0, i.e. W P = -(s, u_t).
    let det = wnn * wtt - wnt * wnt; // formula: det W
    if det > eps * (wnn * wtt).abs() && det.is_finite() {
        let p_n = (-s * wtt + ut * wnt) / det; // formula: Cramer's rule on W P = -(s, u_t)
        let p_t = (-ut * wnn + s * wnt) / det;
        if p_n >= 0.0
            && p_t.abs() <= mu * p_n * (1.0 + eps) + eps * p_n.abs().max(f64::MIN_POSITIVE)
        {
            return Some(Impulse {
                status: ContactStatus::Stick,
                p_n,
                p_t,
            });
        }
    }
    // Slide: P_t = -sigma mu P_n with sigma = +1 (towards +t) or -1.
    for (sigma, status) in [
        (1.0, ContactStatus::SlidePositive),
        (-1.0, ContactStatus::SlideNegative),
    ] {
        let denom = wnn - sigma * mu * wnt; // formula: u_n = s + (W_nn - sigma mu W_nt) P_n = 0
        if denom <= 0.0 {
            continue;
        }
        let p_n = -s / denom;
        let p_t = -sigma * mu * p_n;
        let ut1 = ut + wnt * p_n + wtt * p_t; // formula: u_t,{k+1} = u_t,free + W_tn P_n + W_tt P_t
        if p_n >= 0.0 && sigma * ut1 >= -eps * (ut.abs() + (wtt * p_t).abs()) {
            return Some(Impulse { status, p_n, p_t });
        }
    }
    None
}

/// Options of a Moreau-Jean run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MjOptions {
    /// Step size (s).
    pub h_s: f64,
    /// The theta of the scheme, in `[1/2, 1]` (1/2: Moreau's midpoint rule).
    pub theta: f64,
}

impl MjOptions {
    /// The midpoint rule (`theta = 1/2`) with step `h_s`.
    pub fn midpoint(h_s: f64) -> Self {
        MjOptions { h_s, theta: 0.5 }
    }
}

/// Work and contact counters of a run.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct MjStats {
    /// Steps taken.
    pub steps: u64,
    /// Free-velocity evaluations (one per step): the right-hand-side count.
    pub rhs_evals: u64,
    /// Steps in which the contact was active (a local problem was solved).
    pub contact_steps: u64,
    /// Steps that ended sticking.
    pub stick_steps: u64,
    /// Steps that ended sliding.
    pub slide_steps: u64,
}

/// Why a Moreau-Jean run stopped early.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MjError {
    /// The state became NaN or infinite at `t_s`.
    NonFinite {
        /// Time (s).
        t_s: f64,
    },
    /// The local contact problem had no solution at `t_s`.
    NoContactSolution {
        /// Time (s).
        t_s: f64,
    },
}

impl std::fmt::Display for MjError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MjError::NonFinite { t_s } => write!(f, "non-finite state at t = {t_s} s"),
            MjError::NoContactSolution { t_s } => {
                write!(f, "no solution of the contact problem at t = {t_s} s")
            }
        }
    }
}

/// One step `t0 -> t1` as the observer sees it.
#[derive(Debug, Clone, Copy)]
pub struct MjStep<const N: usize> {
    /// Start time (s).
    pub t0: f64,
    /// End time (s).
    pub t1: f64,
    /// Coordinates at `t0`.
    pub q0: [f64; N],
    /// Velocities at `t0`.
    pub v0: [f64; N],
    /// Coordinates at `t1`.
    pub q1: [f64; N],
    /// Velocities at `t1`.
    pub v1: [f64; N],
    /// The contact case and impulses of the step.
    pub impulse: Impulse,
}

/// The end of a run.
#[derive(Debug, Clone, Copy)]
pub struct MjRun<const N: usize> {
    /// Final time (s).
    pub t_s: f64,
    /// Final coordinates.
    pub q: [f64; N],
    /// Final velocities.
    pub v: [f64; N],
    /// Counters.
    pub stats: MjStats,
}

fn dot<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn mat_vec<const N: usize>(m: &[[f64; N]; N], x: &[f64; N]) -> [f64; N] {
    let mut out = [0.0; N];
    for (o, row) in out.iter_mut().zip(m) {
        *o = dot(row, x);
    }
    out
}

/// The local contact problem of one step, as [`step`] poses it: `u = u_free + W P`
/// with `0 <= u_n + s0 _|_ P_n >= 0` and Coulomb's law on `(u_t, P_t)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalProblem<const N: usize> {
    /// The Delassus matrix `W = [w_n w_t]^T M^-1 [w_n w_t]` (1/kg in a mass-like metric).
    pub w: [[f64; 2]; 2],
    /// The free relative velocities `(u_n, u_t)` at the end of the step (m/s).
    pub u_free: [f64; 2],
    /// Newton's target `e u_n,k` (m/s, zero or negative).
    pub s0: f64,
    /// `M^-1 w_n` and `M^-1 w_t`: the velocity change per unit impulse.
    pub m_wn: [f64; N],
    /// See `m_wn`.
    pub m_wt: [f64; N],
    /// The free velocity update `v_free`.
    pub v_free: [f64; N],
    /// The midpoint coordinates `q_m`.
    pub q_m: [f64; N],
}

/// The midpoint, the free velocity and, when the contact is active at the midpoint, the
/// local problem of a step of length `h` from `(t, q, v)`: `(q_m, v_free, problem)`.
pub(crate) fn local_problem<M: ContactModel<N> + ?Sized, const N: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    h: f64,
    theta: f64,
) -> ([f64; N], [f64; N], Option<LocalProblem<N>>) {
    let t1 = t + h;
    let t_m = t + (1.0 - theta) * h;
    let mut q_m = *q;
    for i in 0..N {
        q_m[i] += (1.0 - theta) * h * v[i]; // formula: q_m = q_k + (1 - theta) h v_k
    }
    let v_free = model.free_velocity(t_m, &q_m, v, h); // formula: v_free = v_k + h M^-1 f
    if model.gap(t_m, &q_m) > 0.0 {
        return (q_m, v_free, None);
    }
    let (wn, wt) = model.jacobians(t_m, &q_m);
    let minv = model.inv_mass(t_m, &q_m, h);
    let (m_wn, m_wt) = (mat_vec(&minv, &wn), mat_vec(&minv, &wt));
    // formula: W = [w_n w_t]^T M^-1 [w_n w_t]
    let w = [
        [dot(&wn, &m_wn), dot(&wn, &m_wt)],
        [dot(&wt, &m_wn), dot(&wt, &m_wt)],
    ];
    let (bn0, _) = model.obstacle_velocity(t);
    let (bn1, bt1) = model.obstacle_velocity(t1);
    let un_k = dot(&wn, v) - bn0; // formula: u_n,k = w_n . v_k - b_n(t_k)
    let u_free = [dot(&wn, &v_free) - bn1, dot(&wt, &v_free) - bt1];
    let s0 = model.restitution() * un_k.min(0.0); // formula: e u_n,k (approaching only)
    let problem = LocalProblem {
        w,
        u_free,
        s0,
        m_wn,
        m_wt,
        v_free,
        q_m,
    };
    (q_m, v_free, Some(problem))
}

/// One Moreau-Jean step of length `h` from `(t, q, v)`: returns `(q1, v1, impulse)`.
#[allow(clippy::needless_range_loop)] // v1, m_wn, m_wt: one index over three arrays
pub fn step<M: ContactModel<N> + ?Sized, const N: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    h: f64,
    theta: f64,
) -> Result<([f64; N], [f64; N], Impulse), MjError> {
    let t1 = t + h;
    let (q_m, v_free, problem) = local_problem(model, t, q, v, h, theta);
    let mut v1 = v_free;
    let mut impulse = Impulse {
        status: ContactStatus::Inactive,
        p_n: 0.0,
        p_t: 0.0,
    };
    if let Some(lp) = problem {
        impulse = solve_contact(lp.w, lp.u_free, lp.s0, model.mu())
            .ok_or(MjError::NoContactSolution { t_s: t })?;
        for i in 0..N {
            v1[i] += lp.m_wn[i] * impulse.p_n + lp.m_wt[i] * impulse.p_t; // formula: v_{k+1} = v_free + M^-1 (w_n P_n + w_t P_t)
        }
    }
    let mut q1 = q_m;
    for i in 0..N {
        q1[i] += theta * h * v1[i]; // formula: q_{k+1} = q_m + theta h v_{k+1}
    }
    if !(q1.iter().chain(v1.iter()).all(|x| x.is_finite())) {
        return Err(MjError::NonFinite { t_s: t1 });
    }
    Ok((q1, v1, impulse))
}

/// Runs Moreau-Jean from `(t0, q0, v0)` to `t_end` with constant step `opts.h_s` (the
/// last step is shortened to land on `t_end`), calling `on_step` after every step.
pub fn simulate<M: ContactModel<N> + ?Sized, const N: usize>(
    model: &M,
    t0: f64,
    q0: [f64; N],
    v0: [f64; N],
    t_end: f64,
    opts: &MjOptions,
    mut on_step: impl FnMut(&MjStep<N>),
) -> Result<MjRun<N>, MjError> {
    let (mut q, mut v) = (q0, v0);
    let mut stats = MjStats::default();
    let h = opts.h_s;
    // Time as t0 + k h (no accumulated round-off over millions of steps).
    let mut k: u64 = 0;
    let mut t = t0;
    while t < t_end {
        let mut t1 = t0 + (k + 1) as f64 * h;
        if t1 > t_end - 1e-9 * h {
            t1 = t_end;
        }
        let (q1, v1, impulse) = step(model, t, &q, &v, t1 - t, opts.theta)?;
        stats.steps += 1;
        stats.rhs_evals += 1;
        match impulse.status {
            ContactStatus::Inactive => {}
            ContactStatus::Open => stats.contact_steps += 1,
            ContactStatus::Stick => {
                stats.contact_steps += 1;
                stats.stick_steps += 1;
            }
            ContactStatus::SlidePositive | ContactStatus::SlideNegative => {
                stats.contact_steps += 1;
                stats.slide_steps += 1;
            }
        }
        on_step(&MjStep {
            t0: t,
            t1,
            q0: q,
            v0: v,
            q1,
            v1,
            impulse,
        });
        q = q1;
        v = v1;
        t = t1;
        k += 1;
    }
    Ok(MjRun {
        t_s: t,
        q,
        v,
        stats,
    })
}

#[cfg(test)]
mod tests;
