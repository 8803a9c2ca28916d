//! The model evaluated once at the recorded states of the evidence runs: every number
//! the claims read at a trace sample, a landing, a pivot exit or a slide exit (the tip's
//! motion, the plate's, the contact forces, the Newton-Euler impulse, the second method
//! of `lagrange.rs`), gathered with the evidence so that the claims only compare.
//!
//! Only raw physical quantities are kept (forces, velocities, angles, the plate's
//! motion): where a verdict depends on a printed statement (a coefficient, an
//! inequality, a sign), the claim applies the statement to them.

use super::impulse::{newton_euler, NewtonEuler};
use super::lagrange::{self, Derivative};
use crate::physics::stick::contact::ContactEval;
use crate::physics::stick::rules::Next;
use crate::physics::stick::run::{Landing, RunSummary};
use crate::physics::stick::{Mode, State, StickModel, StickParams, NSTATE, OM, TH, VXC, XC};

/// The state of `run` at an event at time `t` (s) in `mode` (the end of the segment
/// before the event, kept in the trace), if traced.
pub fn state_at(run: &RunSummary, t: f64, mode: Mode) -> Option<State> {
    run.trace
        .iter()
        .find(|x| x.t_s == t && x.mode == mode)
        .map(|x| x.y)
}

/// The second method (`lagrange.rs`, the Euler-Lagrange equations differentiated
/// numerically) at a trace sample, each value with its finite-difference error estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Lagrange {
    /// A flight sample: `z_p''` (m/s²) and θ' (rad/s).
    Flight {
        /// z_p'' (m/s²) with its halved-step change and rounding bound.
        z_p_dd: Derivative,
        /// θ' (rad/s) with its halved-step change and rounding bound.
        theta_d: Derivative,
    },
    /// A pivot sample: θ'' (rad/s²), and the plate's acceleration from std
    /// trigonometry, `-A ω² sin(ω t + φ)` (m/s², not the model's table).
    Pivot {
        /// θ'' (rad/s²) with its halved-step change, rounding bound and step ratio.
        theta_dd: Derivative,
        /// z_s'' (m/s²).
        plate_acc_mps2: f64,
    },
    /// A slide sample: not evaluated.
    None,
}

/// The model at one trace sample of an evidence run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AtSample {
    /// The scene: an index into `Evidence::params` (0 authors, 1 self-locking).
    pub scene: usize,
    /// Time (s).
    pub t_s: f64,
    /// Mode.
    pub mode: Mode,
    /// State.
    pub y: State,
    /// `[x_p m, z_p m, x_p' m/s, z_p' m/s]` (C.1, C.3).
    pub tip: [f64; 4],
    /// The plate `(z_s m, z_s' m/s, z_s'' m/s²)` at `t_s` (the model's).
    pub plate: (f64, f64, f64),
    /// The second method at this sample.
    pub lagrange: Lagrange,
}

/// The recorded landing behind an [`Impact`] (not a mirror image or a turned state).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RecordedLanding {
    /// The run's record of the landing.
    pub landing: Landing,
    /// The rounding budget of `h_c` at the landing state (m,
    /// `StickModel::penetration_budget_m`).
    pub penetration_budget_m: f64,
}

/// A landing state (the flight state at the located event, its mirror image, or a
/// state turned to the friction cone's edge) with the Newton-Euler impulse there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Impact {
    /// The scene (index into `Evidence::params`).
    pub scene: usize,
    /// The state before the impact.
    pub y: State,
    /// The mode after (mirrored for a mirror image).
    pub to: Mode,
    /// P's velocity `(x_p', z_p')` (m/s).
    pub tip_v_mps: (f64, f64),
    /// The plate's velocity z_s' (m/s).
    pub plate_v_mps: f64,
    /// Rod length L (m).
    pub length_m: f64,
    /// Friction coefficient μ (1).
    pub mu: f64,
    /// The Newton-Euler impulse (`impulse.rs`).
    pub ne: NewtonEuler,
    /// Mass m (kg).
    pub mass_kg: f64,
    /// The Newton-Euler system's residual fl(b - A^ x^) as computed at `ne` (rows in
    /// m/s, m/s, N s), for its rounding bound (`rounding.rs`).
    pub ne_residual: [f64; 3],
    /// The run's landing, for the recorded states only.
    pub recorded: Option<RecordedLanding>,
}

impl Impact {
    /// The Newton-Euler solution as a vector `(J_x, J_z, ω+)`.
    pub fn ne_x(&self) -> [f64; 3] {
        [self.ne.jx, self.ne.jz, self.ne.omega_after]
    }

    /// Relative velocity `(x_p', z_p' - z_s')` (m/s) and `r_CP` (m), read from C to P
    /// (`from_c`) or from P to C.
    pub fn geometry(&self, from_c: bool) -> ((f64, f64), (f64, f64)) {
        let (vxp, vzp) = self.tip_v_mps;
        let l = self.length_m;
        let (s, c) = self.y[TH].sin_cos();
        let sign = if from_c { 1.0 } else { -1.0 };
        ((vxp, vzp - self.plate_v_mps), (sign * l * s, sign * l * c))
    }
}

/// A mode switch out of the pivot: the pivot's reaction at the state before it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PivotExit {
    /// The scene (index into `Evidence::params`).
    pub scene: usize,
    /// The mode taken.
    pub to: Mode,
    /// The pivot's reaction (C.6, C.7).
    pub pivot: ContactEval,
    /// Whether a flight from this state lifts C (`StickModel::takeoff`).
    pub lifts: bool,
}

/// A mode switch out of a slide: the contact forces at the state before it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlideExit {
    /// The scene (index into `Evidence::params`).
    pub scene: usize,
    /// The slide left.
    pub from: Mode,
    /// The mode taken.
    pub to: Mode,
    /// C's slip velocity x_c' (m/s).
    pub vxc_mps: f64,
    /// The pivot's reaction at this state (C.6, C.7).
    pub pivot: ContactEval,
    /// The normal force F_z (N) of the left and the right slide at this state (C.9, C.11).
    pub slide_fz_n: [f64; 2],
}

impl SlideExit {
    /// The normal force (N) of slide `mode` at this state.
    pub fn slide_fz(&self, mode: Mode) -> f64 {
        if mode == Mode::SlideLeft {
            self.slide_fz_n[0]
        } else {
            self.slide_fz_n[1]
        }
    }
}

/// Everything the claims read at the recorded states of the evidence runs.
#[derive(Debug, Clone, PartialEq)]
pub struct AtStates {
    /// Every trace sample of both runs, in order (authors', then self-locking).
    pub samples: Vec<AtSample>,
    /// Every landing of both runs with a traced state, each followed by its mirror
    /// image (θ, θ', x_c, x_c' negated): the scenes lean one way only.
    pub impacts: Vec<Impact>,
    /// The first landing state of each scene turned to `θ = ±atan(s μ)`, s = 0.5, 0.9,
    /// 0.95, 1.05, 1.1, 1.5: impacts just inside and outside the friction cone.
    pub edge_impacts: Vec<Impact>,
    /// Every pivot exit of both runs with a traced state.
    pub pivot_exits: Vec<PivotExit>,
    /// Every slide exit of both runs with a traced state.
    pub slide_exits: Vec<SlideExit>,
    /// The first slide sample of the runs evaluated with the authors' parameters at
    /// μ = 0: `(F_x N, F_z N)`.
    pub slide_at_mu0: Option<(f64, f64)>,
}

/// Gathers [`AtStates`] over `runs` (scene `i` is `runs[i]`).
pub fn gather(runs: &[(&RunSummary, &StickParams)]) -> AtStates {
    let models: Vec<StickModel> = runs.iter().map(|(_, q)| StickModel::new(**q)).collect();
    let mut samples = Vec::new();
    for (i, (run, q)) in runs.iter().enumerate() {
        samples.extend(run.trace.iter().map(|x| sample(i, &models[i], q, x)));
    }
    let impacts = impacts(runs, &models);
    let edge_impacts = edge_impacts(&impacts, &models);
    let (pivot_exits, slide_exits) = exits(runs, &models);
    let slide_at_mu0 = samples
        .iter()
        .find(|s| matches!(s.mode, Mode::SlideLeft | Mode::SlideRight))
        .map(|s| {
            let mut q = *runs[0].1;
            q.mu = 0.0;
            let f = StickModel::new(q).slide_eval(s.mode.sigma(), s.t_s, &s.y);
            (f.fx, f.fz)
        });
    AtStates {
        samples,
        impacts,
        edge_impacts,
        pivot_exits,
        slide_exits,
        slide_at_mu0,
    }
}

/// The model and the second method at one trace sample.
fn sample(scene: usize, m: &StickModel, q: &StickParams, x: &crate::physics::stick::run::Sample) -> AtSample {
    let tip = m.tip(&x.y);
    let lagrange = match x.mode {
        Mode::Flight => {
            let [z_p_dd, theta_d] = lagrange::flight_rates(q, tip[1], x.y[TH]);
            Lagrange::Flight { z_p_dd, theta_d }
        }
        Mode::Pivot => {
            let pl = &q.plate;
            let plate_acc_mps2 = -pl.amplitude_m
                * pl.omega_rad_s
                * pl.omega_rad_s
                * (pl.omega_rad_s * x.t_s + pl.phase_rad).sin(); // formula: z_s'' = -A w^2 sin(w t + phi)
            Lagrange::Pivot {
                theta_dd: lagrange::pivot_theta_dd(q, x.y[TH], x.y[OM], x.t_s),
                plate_acc_mps2,
            }
        }
        _ => Lagrange::None,
    };
    AtSample {
        scene,
        t_s: x.t_s,
        mode: x.mode,
        y: x.y,
        tip,
        plate: m.plate(x.t_s),
        lagrange,
    }
}

/// The impact at state `y` (time `t`) of scene `scene`.
pub(super) fn impact(scene: usize, m: &StickModel, t: f64, y: State, to: Mode) -> Impact {
    let [_, _, vxp, vzp] = m.tip(&y);
    let ne = newton_euler(m, t, &y);
    Impact {
        scene,
        y,
        to,
        tip_v_mps: (vxp, vzp),
        plate_v_mps: m.plate(t).1,
        length_m: m.p.length_m,
        mu: m.p.mu,
        ne,
        mass_kg: m.p.mass_kg,
        ne_residual: ne_residual(m, t, &y, &ne),
        recorded: None,
    }
}

/// The residual fl(b - A^ x^) of `impulse.rs`'s system as built there (the same rows,
/// the same roundings), at its computed solution.
fn ne_residual(m: &StickModel, t: f64, y: &State, ne: &NewtonEuler) -> [f64; 3] {
    let a = super::impulse::system(m, t, y);
    let x = [ne.jx, ne.jz, ne.omega_after];
    // formula: r = b - A x, row by row
    a.map(|row| row[3] - (row[0] * x[0] + row[1] * x[1] + row[2] * x[2]))
}

/// Every landing with a traced state, followed by its mirror image.
fn impacts(runs: &[(&RunSummary, &StickParams)], models: &[StickModel]) -> Vec<Impact> {
    let mut v = Vec::new();
    for (i, (run, _)) in runs.iter().enumerate() {
        let m = &models[i];
        for l in &run.landings {
            let Some(y) = state_at(run, l.t_s, Mode::Flight) else {
                continue;
            };
            let mut at = impact(i, m, l.t_s, y, l.to);
            at.recorded = Some(RecordedLanding {
                landing: *l,
                penetration_budget_m: m.penetration_budget_m(l.t_s, &y),
            });
            v.push(at);
            let mut z = y;
            for k in [TH, OM, VXC, XC] {
                z[k] = -z[k];
            }
            let to = match l.to {
                Mode::SlideLeft => Mode::SlideRight,
                Mode::SlideRight => Mode::SlideLeft,
                other => other,
            };
            v.push(impact(i, m, l.t_s, z, to));
        }
    }
    v
}

/// The first landing state of each scene turned to `θ = ±atan(s μ)`.
fn edge_impacts(impacts: &[Impact], models: &[StickModel]) -> Vec<Impact> {
    let mut v = Vec::new();
    let mut seen: Vec<usize> = Vec::new();
    for at in impacts.iter().filter(|a| a.recorded.is_some()) {
        if seen.contains(&at.scene) {
            continue;
        }
        seen.push(at.scene);
        let t = at.recorded.map_or(0.0, |r| r.landing.t_s);
        for s in [0.5, 0.9, 0.95, 1.05, 1.1, 1.5] {
            for sign in [-1.0, 1.0] {
                let mut z = at.y;
                z[TH] = sign * (s * at.mu).atan(); // formula: |tan(theta)| = s mu
                v.push(impact(at.scene, &models[at.scene], t, z, at.to));
            }
        }
    }
    v
}

/// The pivot exits and the slide exits of the runs.
fn exits(
    runs: &[(&RunSummary, &StickParams)],
    models: &[StickModel],
) -> (Vec<PivotExit>, Vec<SlideExit>) {
    let (mut pivot, mut slide) = (Vec::new(), Vec::new());
    for (i, (run, _)) in runs.iter().enumerate() {
        let m = &models[i];
        for &(t, from, to) in &run.events {
            let Some(to) = to else { continue };
            if !matches!(from, Mode::Pivot | Mode::SlideLeft | Mode::SlideRight) {
                continue;
            }
            let Some(y) = state_at(run, t, from) else {
                continue;
            };
            let f = m.pivot_eval(t, &y);
            if from == Mode::Pivot {
                pivot.push(PivotExit {
                    scene: i,
                    to,
                    pivot: f,
                    lifts: matches!(m.takeoff(t, &y), Next::To(..)),
                });
            } else {
                slide.push(SlideExit {
                    scene: i,
                    from,
                    to,
                    vxc_mps: y[VXC],
                    pivot: f,
                    slide_fz_n: [m.slide_eval(1.0, t, &y).fz, m.slide_eval(-1.0, t, &y).fz],
                });
            }
        }
    }
    (pivot, slide)
}

/// A vertical stick at rest on the authors' plate at Γ = 0.5 (θ₀ = 0), over one cycle
/// at 64 phases: the pivot equations' reaction `(F_x N, F_z N)` and the closed form
/// `F_z = m (g + z_s'')` (N).
pub fn vertical_pivot(authors: &StickParams) -> Vec<(f64, f64, f64)> {
    let mut q = *authors;
    q.theta0_rad = 0.0;
    q.plate.amplitude_m = 0.5 * q.g_mps2 / (q.plate.omega_rad_s * q.plate.omega_rad_s);
    let m = StickModel::new(q);
    (0..64)
        .map(|k| {
            let t = m.period_s * k as f64 / 64.0;
            let f = m.pivot_eval(t, &[0.0; NSTATE]);
            let closed = q.mass_kg * (q.g_mps2 + m.plate(t).2); // formula: F_z = m (g + z_s'')
            (f.fx, f.fz, closed)
        })
        .collect()
}
