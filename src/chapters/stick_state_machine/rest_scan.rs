//! Closed-form evaluations the claims on sections 4 and 5 (`gap_claims.rs`) are judged
//! on, computed once with the evidence: the contact conditions at states at rest on the
//! plate, the heights of the evidence runs' flights at their lift-offs, and the slides'
//! normal force near the self-locking edge.

use crate::physics::stick::contact::ContactEval;
use crate::physics::stick::rules::Next;
use crate::physics::stick::run::{initial_state, RunSummary};
use crate::physics::stick::{Mode, StickModel, StickParams, OM};

/// The contact conditions at one state at rest on the plate (C on it, `x_c' = 0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestState {
    /// Friction coefficient of the scene (1).
    pub mu: f64,
    /// The pivot's accelerations and reaction (C.6, C.7).
    pub pivot: ContactEval,
    /// The slides' (left, right) accelerations and forces (C.9 to C.14).
    pub slides: [ContactEval; 2],
    /// Whether each slide (left, right) is consistent from rest (`try_slide`).
    pub slide_ok: [bool; 2],
    /// Whether a flight from this state lifts C (`takeoff`).
    pub flight_ok: bool,
    /// The mode the contact conditions choose (`select_contact`), if any.
    pub chosen: Option<Mode>,
}

/// States at rest on the plate over a grid: theta = +-0.1 .. +-1.2 rad, theta' = 0 ..
/// +-2 sqrt(g/L), 16 plate phases, for each scene.
pub fn rest_states(params: &[StickParams]) -> Vec<RestState> {
    let mut v = Vec::new();
    for q in params {
        let m = StickModel::new(*q);
        let w_scale = (q.g_mps2 / q.length_m).sqrt();
        for i in (-12..=12).filter(|&i| i != 0) {
            let th = 0.1 * f64::from(i); // rad; theta = 0 left out: C.14 is singular there
            for j in -4..=4 {
                for k in 0..16 {
                    let t = m.period_s * f64::from(k) / 16.0;
                    let mut y = initial_state(&m, t, th);
                    y[OM] = 0.5 * w_scale * f64::from(j);
                    let ok = |mode| matches!(m.try_slide(mode, t, &y), Next::To(..));
                    v.push(RestState {
                        mu: q.mu,
                        pivot: m.pivot_eval(t, &y),
                        slides: [m.slide_eval(1.0, t, &y), m.slide_eval(-1.0, t, &y)],
                        slide_ok: [ok(Mode::SlideLeft), ok(Mode::SlideRight)],
                        flight_ok: matches!(m.takeoff(t, &y), Next::To(..)),
                        chosen: match m.select_contact(t, &y) {
                            Next::To(mode, _) => Some(mode),
                            Next::Stop(_) => None,
                        },
                    });
                }
            }
        }
    }
    v
}

/// For every flight of the runs that ended in a landing: `h_c` (m) at its lift-off
/// state as the lift-off sets it (`z_c <- z_s`), and whether it landed later (s).
pub fn liftoff_heights(runs: &[(&RunSummary, &StickParams)]) -> Vec<(f64, bool)> {
    let mut v = Vec::new();
    for (run, q) in runs {
        let m = StickModel::new(**q);
        for (i, &(t0, from, to)) in run.events.iter().enumerate() {
            if from == Mode::Flight || to != Some(Mode::Flight) {
                continue;
            }
            // the state before the lift-off, kept in the trace at the segment's end
            let before = run.trace.iter().find(|x| x.t_s == t0 && x.mode == from);
            let Some(y) = before.map(|x| x.y) else {
                continue;
            };
            let Next::To(_, a) = m.takeoff(t0, &y) else {
                continue;
            };
            let landing = run.events[i + 1..].iter().find(|e| e.1 == Mode::Flight);
            if let Some(&(t1, _, _)) = landing {
                v.push((m.h_c(t0, &a), t1 > t0));
            }
        }
    }
    v
}

/// Largest ratio over the scenes of the slide-left normal force |F_z| at tan(theta) =
/// mu (1 + 1e-6) to that at mu (1 + 1e-3), theta' = 0: about 1e3 for a pole of order
/// one (C.9's denominator vanishes at tan(theta) = mu), about 1 for a bounded force.
pub fn edge_growth(params: &[StickParams]) -> f64 {
    let mut growth = 0.0f64;
    for p in params {
        let m = StickModel::new(*p);
        let fz_at = |delta: f64| {
            let th = (p.mu * (1.0 + delta)).atan(); // formula: tan(theta) = mu (1 + delta)
            let y = initial_state(&m, 0.0, th);
            m.slide_eval(1.0, 0.0, &y).fz.abs()
        };
        growth = growth.max(fz_at(1e-6) / fz_at(1e-3));
    }
    growth
}
