//! The document's own transition rules, executed as printed: Table 1 and Algorithms 1
//! to 4 of section 5 (`--rules printed`), beside the physical rules of [`super::rules`].
//!
//! Semantics (the document's Table 1 caption, and the readings the printed text needs):
//! - **Table 1**: "the inequalities are checked for violation. If an inequality is
//!   violated, the state transitions to another state". Each phase's inequalities are
//!   its guards (flight `h_c > 0`; pivot `F_z >= 0`, `|F_x| <= mu F_z`; slides `F_z >= 0`
//!   and the row's `v_x` sign, printed or corrected); a violation runs the phase's
//!   algorithm (FLIGHT: Alg. 2, HINGE: Alg. 1, SLIDE RIGHT: Alg. 3, SLIDE LEFT: Alg. 4).
//!   The equalities (`h_c = 0`, `v_x = 0`) are "enforced by the equations of motion":
//!   imposed on entry. A phase entered with one of its inequalities already violated
//!   runs its own algorithm at once ("the new state is the one in which the
//!   inequalities are satisfied"); eight such re-selections at one instant without a
//!   phase that holds stop the run as `invalid`.
//! - **Algorithms**: lines run in order; `assert(Next Phase <- X)` assigns a variable
//!   ([`Semantics::LastWins`], the literal reading: a later assignment overrides an
//!   earlier one) or ends the algorithm at the end of its block
//!   ([`Semantics::FirstWins`]). Assignments to `x_c'`, `z_c`, `theta'`, `x_p'`, `z_p'`
//!   change the state; an algorithm that assigns no phase leaves the run in a phase
//!   whose inequality is violated: `invalid`, naming the algorithm.
//! - **Equalities** (`z_c - z_s = 0`, `F_z = 0`, `F_x = 0`, `|theta| = 0`) are tested to the
//!   event location's accuracy: `1e-9` of the length, of the weight, of a radian.
//! - **`r_CP`** is the vector from C to P, `L (sin, cos)` (as `r_P/C` of C.15); the other
//!   reading (from P to C) equals correcting [`Erratum::A2ShorteningBranch`] and
//!   [`Erratum::A2ThetaDotSign`] together.
//! - **Heights** `z_c`, `z_p` are absolute (the plate moves as `z_s = delta cos(omega t)`).
//!
//! Each [`Erratum`] can be corrected on its own ([`Printed::fixed`]), so each erratum's
//! consequence shows on a trajectory. Where the printed text cannot be executed (the
//! sliding-left angle equation is missing; a division by `sin(theta) = 0`) the run stops
//! as `invalid` naming the line; ABORT chosen by a printed line stops it as `aborted`.
//! Every run ends: the driver's Zeno guard, the re-selection bound and an event budget
//! (64 events per drive cycle plus 1000).

mod algorithms;

use super::rules::Next;
use super::{Mode, State, StickModel, StickStop, NSTATE, OM, TH, VXC, VZC, ZC};
use crate::numerics::events::Direction;
use crate::numerics::hybrid::{HybridSystem, Transition};
use std::cell::{Cell, RefCell};
use std::collections::BTreeMap;

/// One printed rule of sections 4 and 5 that the workbook finds wrong; correcting it
/// replaces the printed line by the stated correction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Erratum {
    /// Table 1: Sliding Right `v_x < 0` -> `v_x > 0`.
    T1SlideRightSign,
    /// Section 4.3: the sliding-left angle equation is missing -> C.14 with `+mu`.
    SlideLeftTheta,
    /// Alg. 1: `mu F_z + F_x > 0` -> SLIDE RIGHT becomes `< 0`.
    A1SlideRightTest,
    /// Alg. 1: `|theta| = 0` -> FLIGHT: removed (a vertical stick pivots).
    A1VerticalFlight,
    /// Alg. 1: `mu F_z - F_x > 0` -> SLIDE LEFT becomes `< 0`.
    A1SlideLeftTest,
    /// Alg. 1: `F_z > 0` -> FLIGHT becomes `F_z < 0`.
    A1FlightTest,
    /// Alg. 1-4: ABORT if `z_c < 0 or z_p < 0` -> heights above the plate, `z_p - z_s < 0`.
    AbortHeights,
    /// Alg. 2: `tan(theta) <= mu` -> `|tan(theta)| <= mu`.
    A2TanTest,
    /// Alg. 2: the impulse when the rod is "not shortening" -> when it shortens.
    A2ShorteningBranch,
    /// Alg. 2: `theta' = r_CP x (v_p - v_s)/L^2` -> `-r_CP x (v_p - v_s)/L^2` (C.15).
    A2ThetaDotSign,
    /// Alg. 2: `mu F_z < |F_x|` -> HINGE becomes `mu F_z >= |F_x|`.
    A2HingeTest,
    /// Alg. 2: the `if F_x > 0` slide choice after the hinge test overrides it -> `else`.
    A2SlideOverridesHinge,
    /// Alg. 2: a tensional reaction implies FLIGHT -> only if the flight lifts C.
    A2TensionFlight,
    /// Alg. 2: `if x_c' > 0` right after `x_c' <- 0` (always SLIDE LEFT) -> removed.
    A2DeadBranch,
    /// Alg. 2: the impulse-free branch tests `x_c' > 0` before assigning `x_c'` -> after.
    A2FreeLandingOrder,
    /// Alg. 3, 4: the hinge test while C still slips -> only once the slip has stopped.
    SlideHingeWhileSlipping,
    /// Alg. 3, 4: a failed hinge test goes to the other slide -> the slide the hinge's
    /// tangential force drives.
    SlideOtherSlide,
    /// Alg. 3, 4: the new slide's `F_z <= 0` -> ABORT becomes FLIGHT.
    SlideAbort,
    /// Alg. 3, 4: FLIGHT if `F_z = 0 or F_x = 0` -> `F_z = 0` only.
    SlideFlightFx,
}

impl Erratum {
    /// Every erratum, in the order of the document.
    pub const ALL: [Erratum; 19] = [
        Erratum::T1SlideRightSign,
        Erratum::SlideLeftTheta,
        Erratum::A1SlideRightTest,
        Erratum::A1VerticalFlight,
        Erratum::A1SlideLeftTest,
        Erratum::A1FlightTest,
        Erratum::AbortHeights,
        Erratum::A2TanTest,
        Erratum::A2ShorteningBranch,
        Erratum::A2ThetaDotSign,
        Erratum::A2HingeTest,
        Erratum::A2SlideOverridesHinge,
        Erratum::A2TensionFlight,
        Erratum::A2DeadBranch,
        Erratum::A2FreeLandingOrder,
        Erratum::SlideHingeWhileSlipping,
        Erratum::SlideOtherSlide,
        Erratum::SlideAbort,
        Erratum::SlideFlightFx,
    ];

    /// Short id (as the chapter's claims and tables name it).
    pub fn id(self) -> &'static str {
        match self {
            Erratum::T1SlideRightSign => "t1-slide-right-sign",
            Erratum::SlideLeftTheta => "s43-slide-left-theta-missing",
            Erratum::A1SlideRightTest => "a1-slide-right-test",
            Erratum::A1VerticalFlight => "a1-vertical-flight",
            Erratum::A1SlideLeftTest => "a1-slide-left-test",
            Erratum::A1FlightTest => "a1-flight-test",
            Erratum::AbortHeights => "a1-abort-heights",
            Erratum::A2TanTest => "a2-tan-test",
            Erratum::A2ShorteningBranch => "a2-shortening-branch",
            Erratum::A2ThetaDotSign => "a2-theta-dot-sign",
            Erratum::A2HingeTest => "a2-hinge-test",
            Erratum::A2SlideOverridesHinge => "a2-slide-overrides-hinge",
            Erratum::A2TensionFlight => "a2-tension-flight",
            Erratum::A2DeadBranch => "a2-dead-branch",
            Erratum::A2FreeLandingOrder => "a2-free-landing-order",
            Erratum::SlideHingeWhileSlipping => "a34-hinge-while-slipping",
            Erratum::SlideOtherSlide => "a34-other-slide",
            Erratum::SlideAbort => "a34-abort",
            Erratum::SlideFlightFx => "a34-flight-test",
        }
    }

    fn bit(self) -> u32 {
        1 << (self as u32)
    }
}

/// How `assert(Next Phase <- X)` reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Semantics {
    /// An assignment: the algorithm runs to its end, the last assignment wins.
    LastWins,
    /// A return: the first assignment ends the algorithm (after its block's assignments).
    FirstWins,
}

/// A rule set: the printed rules with some errata corrected.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Printed {
    fixed: u32,
    /// How `assert(Next Phase <- X)` reads.
    pub semantics: Semantics,
}

impl Printed {
    /// All rules as printed, assignments read literally ([`Semantics::LastWins`]).
    pub const AS_PRINTED: Printed = Printed {
        fixed: 0,
        semantics: Semantics::LastWins,
    };

    /// The same rule set with `e` corrected.
    pub(crate) fn with_fix(mut self, e: Erratum) -> Self {
        self.fixed |= e.bit();
        self
    }

    /// The same rule set read with `semantics`.
    pub(crate) fn with_semantics(mut self, semantics: Semantics) -> Self {
        self.semantics = semantics;
        self
    }

    /// The same rule set with `e` as printed.
    pub fn without_fix(mut self, e: Erratum) -> Self {
        self.fixed &= !e.bit();
        self
    }

    /// Every erratum corrected.
    pub fn all_fixed(self) -> Self {
        Erratum::ALL.iter().fold(self, |p, &e| p.with_fix(e))
    }

    /// Whether `e` is corrected in this rule set.
    pub fn fixed(&self, e: Erratum) -> bool {
        self.fixed & e.bit() != 0
    }
}

/// The stick under a printed rule set: flows of [`StickModel`], guards from Table 1,
/// transitions from Algorithms 1 to 4. Counts the printed lines that fire.
pub struct PrintedStick {
    /// The model (flows, forces, geometry).
    pub m: StickModel,
    /// The rule set.
    pub rules: Printed,
    fired: RefCell<BTreeMap<&'static str, u64>>,
    events: Cell<usize>,
    max_events: usize,
}

/// What an algorithm chose.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Target {
    Phase(Mode),
    Abort(&'static str),
}

/// An algorithm's result: the phase (None: none assigned) and the state after its
/// assignments, or a line that cannot be executed.
type AlgResult = Result<(Option<Target>, State), String>;

impl PrintedStick {
    /// The printed rules `rules` on `m`, for a run of `duration_s` (s): the event budget.
    pub fn new(m: StickModel, rules: Printed, duration_s: f64) -> Self {
        let cycles = (duration_s / m.period_s).clamp(0.0, 1e7);
        PrintedStick {
            m,
            rules,
            fired: RefCell::new(BTreeMap::new()),
            events: Cell::new(0),
            max_events: 64 * cycles as usize + 1000,
        }
    }

    /// Counts of the printed lines that fired, by rule id.
    pub(crate) fn fired(&self) -> BTreeMap<&'static str, u64> {
        self.fired.borrow().clone()
    }

    fn fire(&self, id: &'static str) {
        *self.fired.borrow_mut().entry(id).or_insert(0) += 1;
    }

    fn fix(&self, e: Erratum) -> bool {
        self.rules.fixed(e)
    }

    /// The first mode of a run from `(t, y)` with C on the plate at rest: the pivot, or
    /// Algorithm 1 at once if the pivot's inequalities are violated there.
    pub fn start(&self, t: f64, y: &State) -> Next {
        if self.m.h_c(t, y) > 0.0 {
            return Next::To(Mode::Flight, *y);
        }
        self.enter(Mode::Pivot, t, *y, 0)
    }

    /// Table 1's inequalities of `mode` that bear a rule (guard values, >= 0 holds).
    fn inequalities(&self, mode: Mode, t: f64, y: &State) -> Vec<f64> {
        let mut g = Vec::with_capacity(6);
        self.guards(mode, t, y, &mut g);
        match mode {
            Mode::Flight => vec![g[0]],
            Mode::Pivot => g[..3].to_vec(),
            _ => vec![g[1], g[2]],
        }
    }

    /// Enters `mode` at `(t, y)`: Table 1's equalities imposed, then its inequalities
    /// checked; a violated one runs the mode's algorithm again (at most 8 times).
    fn enter(&self, mode: Mode, t: f64, mut y: State, depth: usize) -> Next {
        let (zs, vs, _) = self.m.plate(t);
        match mode {
            Mode::Flight => {}
            Mode::Pivot => {
                (y[ZC], y[VZC], y[VXC]) = (zs, vs, 0.0);
            }
            Mode::SlideLeft | Mode::SlideRight => {
                if mode == Mode::SlideLeft && !self.fix(Erratum::SlideLeftTheta) {
                    return Next::Stop(StickStop::invalid(format!(
                        "section 4.3, Sliding Left at t = {t:.6} s: \"the variation of the tilt angle is obtained from Eqns. C.10, C.4, thus\" is followed by no equation: theta'' of sliding left is undefined"
                    )));
                }
                (y[ZC], y[VZC]) = (zs, vs);
            }
        }
        let y = self.m.canonical(mode, t, &y);
        if self.inequalities(mode, t, &y).iter().all(|&g| g >= 0.0) {
            return Next::To(mode, y);
        }
        if depth >= 8 {
            return Next::Stop(StickStop::invalid(format!(
                "Table 1 caption at t = {t:.6} s: the printed rules re-select 8 times without reaching a phase whose inequalities hold (last: {})",
                mode.name()
            )));
        }
        self.decide(mode, t, y, depth + 1)
    }

    /// Runs the algorithm of `mode` at `(t, y)` and enters the phase it chooses.
    fn decide(&self, mode: Mode, t: f64, y: State, depth: usize) -> Next {
        let res = match mode {
            Mode::Pivot => self.alg1(t, y),
            Mode::Flight => self.alg2(t, y),
            Mode::SlideRight => self.alg_slide(Mode::SlideRight, t, y),
            Mode::SlideLeft => self.alg_slide(Mode::SlideLeft, t, y),
        };
        match res {
            Err(line) => Next::Stop(StickStop::invalid(format!("{line} at t = {t:.6} s"))),
            Ok((None, _)) => Next::Stop(StickStop::invalid(format!(
                "{} at t = {t:.6} s assigns no next phase while an inequality of Table 1 is violated",
                alg_name(mode)
            ))),
            Ok((Some(Target::Abort(line)), _)) => {
                Next::Stop(StickStop::Aborted(format!("{line} at t = {t:.6} s")))
            }
            Ok((Some(Target::Phase(next)), y1)) => self.enter(next, t, y1, depth),
        }
    }
}

fn alg_name(mode: Mode) -> &'static str {
    match mode {
        Mode::Pivot => "Algorithm 1 (HINGE)",
        Mode::Flight => "Algorithm 2 (FLIGHT)",
        Mode::SlideRight => "Algorithm 3 (SLIDE RIGHT)",
        Mode::SlideLeft => "Algorithm 4 (SLIDE LEFT)",
    }
}

impl HybridSystem<NSTATE> for PrintedStick {
    type Mode = Mode;
    type Stop = StickStop;
    const FLOW_ARGS: usize = super::FLOW_ARGS;

    fn flow(&self, mode: Mode, t: f64, y: &State) -> State {
        self.m.flow(mode, t, y)
    }

    fn exact(&self, mode: Mode, t0: f64, y0: &State, t: f64) -> Option<State> {
        self.m.exact(mode, t0, y0, t)
    }

    fn guard_count(&self, mode: Mode) -> usize {
        self.m.guard_count(mode)
    }

    fn guard(&self, mode: Mode, i: usize, t: f64, y: &State) -> f64 {
        let mut g = Vec::with_capacity(6);
        self.guards(mode, t, y, &mut g);
        g[i]
    }

    /// The model's guards, except the slides' `v_x` row of Table 1 (printed or corrected
    /// sign) and no slip-against-friction check (the printed rules have none).
    fn guards(&self, mode: Mode, t: f64, y: &State, out: &mut Vec<f64>) {
        self.m.guards(mode, t, y, out);
        if mode == Mode::SlideRight || mode == Mode::SlideLeft {
            // Table 1: Sliding Left v_x < 0; Sliding Right v_x < 0 as printed, > 0 corrected
            let positive = mode == Mode::SlideRight && self.fix(Erratum::T1SlideRightSign);
            out[2] = if positive { y[VXC] } else { -y[VXC] } + 1e-12;
            out[5] = -1.0;
        }
    }

    fn direction(&self, mode: Mode, i: usize) -> Direction {
        self.m.direction(mode, i)
    }

    fn on_event(
        &self,
        mode: Mode,
        i: usize,
        t: f64,
        y: &State,
    ) -> Transition<Mode, StickStop, NSTATE> {
        self.events.set(self.events.get() + 1);
        let y = &self.m.canonical(mode, t, y);
        let next = if self.events.get() > self.max_events {
            Next::Stop(StickStop::invalid(format!(
                "event budget of {} events exceeded at t = {t:.6} s",
                self.max_events
            )))
        } else {
            match (mode, i) {
                (Mode::Flight, 0) => self.decide(Mode::Flight, t, *y, 0),
                (Mode::Flight, _) => Next::Stop(StickStop::invalid(format!(
                    "C went below the plate in flight at t = {t:.6} s (no printed rule brought it back)"
                ))),
                (Mode::Pivot, 3) | (_, 3) => Next::Stop(StickStop::Fell),
                (Mode::Pivot, _) | (_, 1) | (_, 2) => self.decide(mode, t, *y, 0),
                (_, 0) => Next::Stop(StickStop::invalid(format!(
                    "C.9/C.11 at t = {t:.6} s: the slide's normal force is unbounded at tan(theta) = sigma mu and no printed rule covers it"
                ))),
                _ => Next::Stop(StickStop::invalid(format!(
                    "C.14 at t = {t:.6} s divides by sin(theta) = 0"
                ))),
            }
        };
        // the energy accumulators restart in every mode, as in the physical rules
        self.m.transition(next, t, y)
    }

    fn max_step(&self, mode: Mode, t: f64, y: &State) -> f64 {
        self.m.max_step(mode, t, y)
    }
}

/// One run under the printed rule set `rules` from `(t0, y0)` (C on the plate or above
/// it) to `t_end` (s): the summary and the counts of the printed lines that fired.
pub fn simulate_printed(
    model: &StickModel,
    rules: Printed,
    t0: f64,
    y0: State,
    t_end: f64,
    opts: &crate::numerics::hybrid::Options,
    rec: super::run::Recording,
) -> (super::run::RunSummary, BTreeMap<&'static str, u64>) {
    let sys = PrintedStick::new(*model, rules, t_end - t0);
    let start = sys.start(t0, &y0);
    let s = super::run::simulate_system(&sys, model, start, t0, y0, t_end, opts, rec);
    (s, sys.fired())
}

/// Helpers shared by the algorithms.
impl PrintedStick {
    /// Tolerances of the printed equalities: heights (m), forces (N), angles (rad).
    fn tol_h(&self) -> f64 {
        1e-9 * self.m.p.length_m
    }

    fn tol_f(&self) -> f64 {
        1e-9 * self.m.p.mass_kg * self.m.p.g_mps2
    }

    /// ABORT test of Algorithms 1 to 4 at `(t, y)`.
    fn abort_test(&self, t: f64, y: &State) -> bool {
        let [_, zp, _, _] = self.m.tip(y);
        if self.fix(Erratum::AbortHeights) {
            let zs = self.m.plate(t).0;
            zp - zs < 0.0 || y[ZC] - zs < -self.tol_h()
        } else {
            y[ZC] < 0.0 || zp < 0.0
        }
    }

    /// Whether the slip has stopped (|v_x| to 1e-9 m/s).
    fn slip_stopped(&self, y: &State) -> bool {
        y[VXC].abs() <= 1e-9
    }

    /// `(v_p - v_s)` relative to the plate, `(xdot_p, zdot_p - zdot_s)` (m/s).
    fn rel_velocity(&self, t: f64, y: &State) -> (f64, f64) {
        let [_, _, vxp, vzp] = self.m.tip(y);
        (vxp, vzp - self.m.plate(t).1)
    }

    /// `theta` and `theta'` of the state.
    fn angle(&self, y: &State) -> (f64, f64) {
        (y[TH], y[OM])
    }
}

#[cfg(test)]
mod tests;
