//! The runs behind the claims, computed once: simulated drops (the impulse ratio),
//! bisections in mu on a sliding rod (the Painleve boundary), simulated impacts (their
//! energy), the scene's run beside chapter 6's massless model, and the massless limit.

use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::stick::StickParams;
use crate::physics::stick_inertia::run::{run_from_rest, simulate_inertia, InertiaRun};
use crate::physics::stick_inertia::{
    InertiaModel, InertiaParams, PainleveRule, NSTATE, TH, VXC, ZC,
};

use super::rounding::{self, Boundary, LeastBoundary};

/// Driver options of every run: DOP853 at `rtol`.
pub fn options(rtol: f64) -> Options {
    Options {
        method: Method::Dop853,
        control: StepControl::tol(rtol, rtol),
        ..Options::default()
    }
}

/// A test rig: a rod of length 0.15 m with rod mass `m_r` and tip mass `m` (kg) at rest
/// over a still plate, spring at rest at `theta` (so no couple), friction `mu`.
pub fn rig(m_r: f64, m: f64, theta: f64, mu: f64, e: f64) -> InertiaModel {
    let mut base = StickParams::new(0.15, m, 10.0, 0.01, mu, theta, 9.81, 0.0, 30.0)
        .expect("a stick inside the model's domain");
    base.mass_kg = m;
    InertiaModel::new(InertiaParams {
        base,
        rod_mass_kg: m_r,
        restitution: e,
    })
}

/// The simulated drop: the rod falls from 1 cm at angle `theta` without rotating, the
/// driver locates the landing, the impact rule acts. Returns `J_t/J_n` of the first
/// impact, `alpha` and the angle at the landing (rad).
pub fn drop_ratio(m_r: f64, m: f64, theta: f64) -> (f64, f64, f64) {
    let md = rig(m_r, m, theta, 10.0, 0.0);
    let mut y = [0.0; NSTATE];
    y[TH] = theta;
    y[ZC] = 0.01;
    let r = simulate_inertia(&md, 0.0, y, 0.05, &options(1e-10), 0.0);
    let first = r.impacts.first();
    let ratio = first.map_or(f64::NAN, |i| i.j_t_ns / i.j_n_ns);
    let landing = first.map_or(f64::NAN, |i| i.theta_rad);
    (ratio, md.geo.alpha(), landing)
}

/// Does a rod sliding left at 0.1 m/s at `theta` (still plate, no couple) meet a
/// Painleve case as its run starts? (The simulator's own classification.)
pub fn painleve_at(m_r: f64, m: f64, theta: f64, mu: f64) -> bool {
    let mut md = rig(m_r, m, theta, mu, 0.0);
    md.p.base.stiffness_nm_per_rad = 0.0;
    md.p.base.damping_nms_per_rad = 0.0;
    let mut y = [0.0; NSTATE];
    y[TH] = theta;
    y[VXC] = -0.1 * theta.signum();
    let r = simulate_inertia(&md, 0.0, y, 1e-4, &options(1e-10), 0.0);
    r.painleve.first().is_some_and(|e| e.t_s == 0.0)
}

/// A bracket `[lo, hi]` of the boundary, `painleve_at` false at `lo` and true at `hi`:
/// from `guess` (a nearby boundary) outwards by steps growing 8-fold from 1e-10 of it, or
/// without one by doubling from `[0, 1]` (`hi` infinite beyond 1e6).
fn bracket(m_r: f64, m: f64, theta: f64, guess: Option<f64>) -> (f64, f64) {
    let at = |mu: f64| painleve_at(m_r, m, theta, mu);
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    match guess {
        Some(g) if g.is_finite() && g > 0.0 => {
            let mut d = 1e-10 * g;
            if at(g) {
                hi = g;
                lo = g - d;
                while lo > 0.0 && at(lo) {
                    (hi, d) = (lo, 8.0 * d);
                    lo = (g - d).max(0.0);
                }
            } else {
                lo = g;
                hi = g + d;
                while !at(hi) {
                    (lo, d) = (hi, 8.0 * d);
                    hi = g + d;
                    if hi > 1e6 {
                        return (lo, f64::INFINITY);
                    }
                }
            }
        }
        _ => {
            while !at(hi) {
                lo = hi;
                hi *= 2.0;
                if hi > 1e6 {
                    return (lo, f64::INFINITY);
                }
            }
        }
    }
    (lo, hi)
}

/// The Painleve boundary located by bisection in mu on the sliding rod, down to
/// adjacent doubles: the least double `mu` the simulator calls a Painleve case, the
/// double below it (a slide), and the simulator's threshold, terms and slope of `D` at
/// `mu` (for [`rounding::switch_error`]).
pub fn painleve_boundary(m_r: f64, m: f64, theta: f64) -> Boundary {
    painleve_boundary_near(m_r, m, theta, None)
}

/// [`painleve_boundary`], its bracket started from `guess` (see [`bracket`]): the result
/// is the same verified pair of adjacent doubles, found in fewer runs.
pub fn painleve_boundary_near(m_r: f64, m: f64, theta: f64, guess: Option<f64>) -> Boundary {
    let (mut lo, mut hi) = bracket(m_r, m, theta, guess);
    for _ in 0..200 {
        let mid = lo + 0.5 * (hi - lo);
        if mid <= lo || mid >= hi || !hi.is_finite() {
            break; // adjacent doubles
        }
        if painleve_at(m_r, m, theta, mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let md = rig(m_r, m, theta, hi, 0.0);
    let (s, c) = theta.sin_cos();
    let (mm, l, ig) = (md.geo.total_kg, md.geo.l_g_m, md.geo.i_g);
    let slope = mm * l * l * (s * c).abs(); // formula: K = |dD/dmu| = M l^2 |sin cos|
    Boundary {
        theta_rad: theta,
        alpha: md.geo.alpha(),
        mu: hi,
        lo,
        threshold_kgm2: md.coefficient_rounding(theta),
        terms_kgm2: ig + mm * l * l * s * s + hi * slope, // formula: I_G + M l^2 s^2 + mu K
        slope_kgm2: slope,
    }
}

/// Golden-section search's tolerance on the angle (rad), its start bracket (rad) and the
/// first step of the search for the points beside its result (rad).
pub const GOLDEN_TOL_RAD: f64 = 1e-7;
/// See [`GOLDEN_TOL_RAD`].
pub const GOLDEN_BRACKET_RAD: (f64, f64) = (0.1, 1.2);

/// The least boundary over the angle: golden-section search on the located boundary,
/// then on each side the nearest point (steps `GOLDEN_TOL_RAD` doubling) at which the
/// boundary is certainly higher than at the search's result (the two located values
/// apart by more than their error bounds): the convex boundary's minimum lies between
/// ([`rounding::min_excess`]).
pub fn painleve_min(m_r: f64, m: f64) -> LeastBoundary {
    let last = std::cell::Cell::new(None);
    let f = |th: f64| {
        let mu = painleve_boundary_near(m_r, m, th, last.get()).mu;
        last.set(Some(mu));
        mu
    };
    let (a, b) = GOLDEN_BRACKET_RAD;
    let th = crate::numerics::search::golden_min(f, a, b, GOLDEN_TOL_RAD);
    let centre = painleve_boundary_near(m_r, m, th, last.get());
    let top = centre.mu + rounding::switch_error(&centre);
    let side = |sign: f64| {
        let mut h = GOLDEN_TOL_RAD;
        loop {
            let p = painleve_boundary_near(m_r, m, th + sign * h, Some(centre.mu));
            if p.mu - rounding::switch_error(&p) > top || h > 0.1 {
                return p;
            }
            h *= 2.0;
        }
    };
    LeastBoundary {
        centre,
        left: side(-1.0),
        right: side(1.0),
    }
}

/// Simulated landings with restitution `e`: the rod dropped from 1 cm at several angles,
/// slips and frictions, on a still plate. Returns, for the impact whose energy gain
/// (J, from the states) exceeds its rounding bound the most, that gain and that bound
/// (J, [`rounding::energy_gain_bound`] with the run's `E = T_0 + M g (z_G0 + l_G)`,
/// which bounds the kinetic energy at every impact: the spring starts at rest, the
/// damper and friction dissipate, the still plate does no work, `z_G >= -l_G`, and the
/// margin `M g l_G` absorbs earlier impacts' gains up to their bounds), and the count.
pub fn impact_energy(e: f64) -> (f64, f64, usize) {
    let (mut worst, mut n) = ((f64::NEG_INFINITY, 0.0), 0);
    for (m_r, m) in [(0.1, 0.0), (0.01, 1.0)] {
        for theta in [-0.6, 0.3, 0.9] {
            for mu in [0.2, 1.0] {
                for vx in [-1.0, 0.0, 0.7] {
                    let md = rig(m_r, m, theta, mu, e);
                    let mut y = [0.0; NSTATE];
                    y[TH] = theta;
                    y[ZC] = 0.01;
                    y[VXC] = vx;
                    y[crate::physics::stick_inertia::OM] = 2.0;
                    let weight = md.geo.total_kg * md.p.base.g_mps2;
                    let energy = md.kinetic_energy(&y) + weight * (md.centre(&y)[1] + md.geo.l_g_m); // formula: E = T_0 + M g (z_G0 + l_G)
                    let bound = rounding::energy_gain_bound(energy, md.geo.alpha());
                    let r = simulate_inertia(&md, 0.0, y, 0.06, &options(1e-10), 0.0);
                    for i in &r.impacts {
                        if i.energy_change_j - bound > worst.0 - worst.1 {
                            worst = (i.energy_change_j, bound);
                        }
                        n += 1;
                    }
                }
            }
        }
    }
    (worst.0, worst.1, n)
}

/// Chapter 6's mean speed on the same scene (m/s), from its static angle.
pub fn massless_speed(p: &InertiaParams, duration_s: f64, rtol: f64) -> f64 {
    crate::physics::stick_inertia::limit::massless_speed(p, duration_s, &options(rtol))
}

/// The scene's run with inertia.
pub fn scene_run(p: &InertiaParams, duration_s: f64, rtol: f64, trace_dt_s: f64) -> InertiaRun {
    run_from_rest(
        &InertiaModel::new(*p),
        duration_s,
        &options(rtol),
        trace_dt_s,
    )
}

/// The evidence of the claims (independent of the statements).
#[derive(Debug, Clone)]
pub struct Evidence {
    /// Drops of the uniform rod, the near-massless rod (`m_r = 1e-10 m`) and two rods
    /// in between.
    pub uniform: Vec<Drop>,
    /// See `uniform`.
    pub massless: Vec<Drop>,
    /// See `uniform`.
    pub between: Vec<Drop>,
    /// Painleve boundaries, located.
    pub boundaries: Vec<Boundary>,
    /// The uniform rod's least boundary.
    pub uniform_min: LeastBoundary,
    /// The compliant limit of an impact without collision (uniform rod, theta = 0.6,
    /// mu = 1.6, slip 0.1 m/s left): the rigid rule's normal impulse and normal
    /// velocity at the slip stop, and the compliant runs' `(K, P_n, u_n)`.
    pub compliant: Compliant,
    /// Moreau-Jean on the default scene (3 s): the event-driven mean speed and the
    /// time-stepping ones at steps `T/n` for [`MJ_STEPS`].
    pub moreau_jean: (f64, Vec<(f64, f64)>),
    /// The massless-limit ladders on chapter 6's self-locking and authors' scenes.
    pub ladders: [Vec<Rung>; 2],
}

/// One simulated drop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drop {
    /// `q = tan(theta)` of the statement (1).
    pub q: f64,
    /// The rod's angle as dropped, `fl(atan q)` (rad).
    pub theta_rad: f64,
    /// Its angle at the landing (rad).
    pub landing_rad: f64,
    /// The measured `J_t/J_n` (1).
    pub ratio: f64,
    /// `alpha` as computed (1).
    pub alpha: f64,
}

/// Angles of the drops, as `q = tan(theta)`.
pub const DROP_Q: [f64; 3] = [0.5, 1.0, 2.0];
/// Rods of the Painleve bisections: (m_r, m) in kg.
pub const RODS: [(f64, f64); 3] = [(0.1, 0.0), (0.05, 0.05), (0.01, 0.1)];
/// Angles of the Painleve bisections (rad).
pub const BOUNDARY_THETAS: [f64; 3] = [0.3, 0.6, 1.0];

/// Duration of the ladder's runs (s): 300 drive cycles.
pub const LADDER_S: f64 = 10.0;

/// Computes the evidence.
pub fn gather() -> Evidence {
    let drops = |m_r: f64, m: f64| -> Vec<Drop> {
        DROP_Q
            .iter()
            .map(|&q| {
                let theta_rad = q.atan();
                let (ratio, alpha, landing_rad) = drop_ratio(m_r, m, theta_rad);
                Drop {
                    q,
                    theta_rad,
                    landing_rad,
                    ratio,
                    alpha,
                }
            })
            .collect()
    };
    let mut between = drops(0.05, 0.05);
    between.extend(drops(0.01, 0.1));
    let mut boundaries = Vec::new();
    for (m_r, m) in RODS {
        for th in BOUNDARY_THETAS {
            boundaries.push(painleve_boundary(m_r, m, th));
        }
    }
    Evidence {
        uniform: drops(0.1, 0.0),
        massless: drops(1e-10, 0.1),
        between,
        boundaries,
        uniform_min: painleve_min(0.1, 0.0),
        compliant: compliant_ladder(),
        moreau_jean: moreau_jean(),
        ladders: [
            ladder(&crate::physics::stick::jamming_scene(9.81), LADDER_S),
            ladder(&crate::physics::stick::authors_scene(10.0), LADDER_S),
        ],
    }
}

/// Rod masses of the massless-limit ladder (kg), on a 1 kg tip mass: down to
/// `alpha = 3e8`, the lightest rod whose impacts the full model still resolves (below
/// `limit::ALPHA_SWITCH` the runs take the singular-perturbation composite).
pub const LADDER_KG: [f64; 9] = [1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1, 1.0];

/// One rung of the ladder: the dimensionless rod inertia and both mean speeds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rung {
    /// Rod mass (kg).
    pub rod_mass_kg: f64,
    /// `I_P k / gamma^2` (1).
    pub inertia_ratio: f64,
    /// `alpha` (1).
    pub alpha: f64,
    /// Mean speed with inertia (m/s).
    pub speed_mps: f64,
    /// Chapter 6's (m/s).
    pub massless_mps: f64,
    /// Outcome label.
    pub outcome: &'static str,
}

impl Rung {
    /// Relative error of the massless model (1).
    pub fn error(&self) -> f64 {
        (self.massless_mps - self.speed_mps) / self.speed_mps.abs().max(1e-12)
    }
}

/// The ladder on scene `base` (its `mass_kg` is the tip mass), runs of `duration_s`.
pub fn ladder(base: &StickParams, duration_s: f64) -> Vec<Rung> {
    LADDER_KG
        .iter()
        .map(|&m_r| {
            let p = InertiaParams {
                base: *base,
                rod_mass_kg: m_r,
                restitution: 0.0,
            };
            let run = scene_run(&p, duration_s, 1e-10, 0.0);
            Rung {
                rod_mass_kg: m_r,
                inertia_ratio: p.inertia_ratio(),
                alpha: p.geometry().alpha(),
                speed_mps: run.mean_velocity_mps,
                massless_mps: massless_speed(&p, duration_s, 1e-10),
                outcome: run.outcome.label(),
            }
        })
        .collect()
}

/// Least-squares slope of `log|error|` against `log(inertia_ratio)` over the rungs with
/// `lo <= inertia_ratio <= hi` (the asymptotic range).
pub fn fitted_order(rungs: &[Rung], lo: f64, hi: f64) -> f64 {
    let pts: Vec<(f64, f64)> = rungs
        .iter()
        .filter(|r| (lo..=hi).contains(&r.inertia_ratio))
        .map(|r| (r.inertia_ratio.ln(), r.error().abs().ln()))
        .collect();
    crate::numerics::fit::slope(&pts) // formula: least-squares slope in log-log
}

/// The rigid rule's `(P_n, u_n)` at the slip stop and the compliant runs' `(K, P_n, u_n)`.
pub type Compliant = ((f64, f64), Vec<(f64, f64, f64)>);

/// Stiffnesses of the compliant ladder (N/m).
pub const COMPLIANT_K: [f64; 4] = [1e5, 1e6, 1e7, 1e8];

/// The compliant comparison (see [`Evidence::compliant`]).
pub fn compliant_ladder() -> Compliant {
    use crate::physics::stick_inertia::compliant::{rigid_slip_stop, slip_stop};
    let (th, mu, u_t) = (0.6, 1.6, -0.1);
    let md = rig(0.1, 0.0, th, mu, 0.0);
    let rigid = rigid_slip_stop(&md, th, u_t);
    let soft = COMPLIANT_K
        .iter()
        .map(|&k| {
            let (_, p_n, u_n) =
                slip_stop(&md, th, u_t, k, 1.0).unwrap_or((f64::NAN, f64::NAN, f64::NAN));
            (k, p_n, u_n)
        })
        .collect();
    (rigid, soft)
}

/// Steps per drive period of the Moreau-Jean ladder.
pub const MJ_STEPS: [f64; 5] = [200.0, 400.0, 800.0, 1600.0, 3200.0];

/// Moreau-Jean beside the event-driven run on the default scene (1 kg tip, 10 g rod,
/// 3 s): `(event-driven speed, [(n, speed at h = T/n)])` (m/s).
pub fn moreau_jean() -> (f64, Vec<(f64, f64)>) {
    use crate::physics::stick_inertia::run::initial_state;
    use crate::physics::stick_inertia::timestepping::mj_mean_speed;
    let p = InertiaParams {
        base: crate::physics::stick::jamming_scene(9.81),
        rod_mass_kg: 0.01,
        restitution: 0.0,
    };
    let md = InertiaModel::new(p);
    let dur = 3.0;
    let ev = run_from_rest(&md, dur, &options(1e-10), 0.0).mean_velocity_mps;
    let y0 = initial_state(&md, 0.0, p.static_angle().unwrap_or(p.base.theta0_rad));
    let mj = MJ_STEPS
        .iter()
        .map(|&n| {
            (
                n,
                mj_mean_speed(&md, &y0, dur, md.period_s / n).unwrap_or(f64::NAN),
            )
        })
        .collect();
    (ev, mj)
}

/// The scene of cardillo's `examples/Painleve.py` (Glocker 1995, 5.3.4, "impact without
/// collision"): a uniform rod of length 2 m and 1 kg, mu = 5/3, g = 10, leaning 31 deg
/// from the horizontal (59 deg from the vertical, top to the left), its lower end sliding
/// right at 30 m/s on a still floor, under the Painleve `rule` (the model's prefers
/// contact; the point is singular, see [`glocker_rate_after`]). Returns the run (first
/// Painleve event, impacts), traced every millisecond.
pub fn glocker_scene(rule: PainleveRule) -> InertiaRun {
    crate::physics::stick_inertia::run::glocker_scene(rule, &options(1e-10), 1.5)
}

/// The rod's rate just after the Glocker scene's Painleve point (rad/s): the first traced
/// sample in flight after the first Painleve event. At that point both of the slide's
/// Painleve coefficients vanish (a singular point of the dynamic jam), and the answer
/// depends on the rule: preferring contact (an impact without collision) the rod leaves
/// spinning fast; preferring separation it lifts off at its sliding rate.
pub fn glocker_rate_after(run: &InertiaRun) -> Option<f64> {
    let t = run.painleve.first()?.t_s;
    run.trace
        .iter()
        .find(|s| s.t_s > t && s.mode == crate::physics::stick::Mode::Flight)
        .map(|s| s.y[crate::physics::stick_inertia::OM].abs())
}
