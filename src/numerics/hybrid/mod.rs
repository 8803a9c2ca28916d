//! The event-driven hybrid-automaton driver.
//!
//! A [`HybridSystem`] has discrete modes. In each mode the state follows a flow (an
//! ODE integrated by the chosen [`Method`], or a closed form supplied by the model
//! through [`HybridSystem::exact`]) until one of the mode's guards crosses zero in its
//! [`Direction`]. The crossing is located on the step's dense output (or on the closed
//! form) by [`illinois`](super::events::illinois), and the model's [`HybridSystem::on_event`] decides the next
//! mode and the reset state, or stops the run with a typed reason.
//!
//! Rules (stated once, used by every model):
//! - **Simultaneous events**: the earliest located crossing wins; crossings at the
//!   same time go to the guard with the lowest index (models order guards by priority).
//! - **Breakpoints**: a model whose data are not smooth at known times (a sawtooth
//!   plate) names them with [`HybridSystem::breakpoint_after`]; the driver steps exactly
//!   to each one and calls [`HybridSystem::on_breakpoint`].
//! - **Zeno guard**: if `zeno.max_events` events fall inside a window shorter than
//!   `zeno.window_s`, the run ends with [`Outcome::Zeno`] instead of hanging.
//! - Guards that start a mode at exactly zero do not fire (see [`Direction::fires`]).

use super::events::{CertifyStats, Direction};
use super::ode::{Method, OdeError, Stats, StepControl};
use std::fmt::Debug;

/// What an event or breakpoint leads to.
#[derive(Debug, Clone, PartialEq)]
pub enum Transition<M, X, const N: usize> {
    /// Continue in `mode` from `state` (the reset map's image).
    To {
        /// The next mode.
        mode: M,
        /// The state after the reset.
        state: [f64; N],
    },
    /// End the run with a model-defined reason (the stick fell, the model's validity ended).
    Stop(X),
}

/// A hybrid system with `N` continuous states.
pub trait HybridSystem<const N: usize> {
    /// The discrete modes.
    type Mode: Copy + PartialEq + Debug;
    /// Model-defined reasons to stop a run.
    type Stop: Clone + Debug;

    /// How many leading state components the flows read (default: all); see
    /// [`OdeSystem::ARGS`](super::ode::OdeSystem::ARGS). The rest are outputs only (accumulated work, say).
    const FLOW_ARGS: usize = N;

    /// How many leading state components the guards of the integrated modes (those
    /// without a closed form) read (default: all). Event location interpolates only
    /// these; the state handed to the model at an event is always whole.
    const GUARD_ARGS: usize = N;

    /// The flow `y' = f(mode, t, y)` (used when [`HybridSystem::exact`] gives `None`).
    fn flow(&self, mode: Self::Mode, t: f64, y: &[f64; N]) -> [f64; N];

    /// The closed-form state at `t` of a mode entered at `(t0, y0)`, for modes that have
    /// one (ballistic flight, constant acceleration). `None`: integrate the flow. Whether it
    /// is `Some` must depend on the mode only (the driver asks once per step, at its end).
    fn exact(&self, _mode: Self::Mode, _t0: f64, _y0: &[f64; N], _t: f64) -> Option<[f64; N]> {
        None
    }

    /// Number of guards of `mode`.
    fn guard_count(&self, mode: Self::Mode) -> usize;

    /// Value of guard `i` of `mode` at `(t, y)`.
    fn guard(&self, mode: Self::Mode, i: usize, t: f64, y: &[f64; N]) -> f64;

    /// All guards of `mode` at `(t, y)`, in index order, into `out` (cleared first).
    /// The default asks [`HybridSystem::guard`] for each; a model whose guards share
    /// work (one force evaluation behind several of them) computes it once here. Must
    /// agree with `guard` exactly.
    fn guards(&self, mode: Self::Mode, t: f64, y: &[f64; N], out: &mut Vec<f64>) {
        out.clear();
        out.extend((0..self.guard_count(mode)).map(|i| self.guard(mode, i, t, y)));
    }

    /// The time derivatives of all guards of `mode` along the flow at `(t, y)`, where
    /// `f` is the flow there, into `out` (cleared first), for the certified search;
    /// `false` (the default) when the model gives none: the driver then takes a
    /// directional difference of [`HybridSystem::guards`], one more evaluation of
    /// them per step.
    fn guard_rates(
        &self,
        _mode: Self::Mode,
        _t: f64,
        _y: &[f64; N],
        _f: &[f64; N],
        _out: &mut Vec<f64>,
    ) -> bool {
        false
    }

    /// The direction in which guard `i` of `mode` fires.
    fn direction(&self, mode: Self::Mode, i: usize) -> Direction;

    /// The transition when guard `i` of `mode` fires at `(t, y)`.
    fn on_event(
        &self,
        mode: Self::Mode,
        i: usize,
        t: f64,
        y: &[f64; N],
    ) -> Transition<Self::Mode, Self::Stop, N>;

    /// Longest step from `(t, y)` in `mode` (s). Guards are compared only at the ends
    /// of a step (and at `interior_checks` points), so the model must keep this short
    /// enough that no guard crosses zero twice within one step; in particular a guard
    /// that starts a mode at zero (a ball leaving the floor) must be seen to leave
    /// zero before it can come back (bound the first step by the time to the apex).
    /// For closed-form modes this is the sampling interval of the guard search.
    fn max_step(&self, _mode: Self::Mode, _t: f64, _y: &[f64; N]) -> f64 {
        f64::INFINITY
    }

    /// The first time strictly after `t` at which the model's data are not smooth.
    fn breakpoint_after(&self, _t: f64) -> Option<f64> {
        None
    }

    /// The transition at a breakpoint (default: carry on in the same mode).
    fn on_breakpoint(
        &self,
        mode: Self::Mode,
        _t: f64,
        y: &[f64; N],
    ) -> Transition<Self::Mode, Self::Stop, N> {
        Transition::To { mode, state: *y }
    }
}

/// The Zeno guard: at most `max_events` events within any `window_s`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZenoGuard {
    /// Events allowed inside one window.
    pub max_events: usize,
    /// Window length (s).
    pub window_s: f64,
}

/// Options of a hybrid run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Integration method for integrated modes.
    pub method: Method,
    /// Step-size control for integrated modes.
    pub control: StepControl,
    /// Locate crossings on the dense output (true) or take the end of the step where
    /// the sign change was seen (false: the event-blind baseline).
    pub locate_events: bool,
    /// Event-time tolerance (s); `None`: a few ulps of t.
    pub event_tol_s: Option<f64>,
    /// Extra interior points per step at which guards are checked for sign changes
    /// (0: ends only). Catches a guard that crosses twice inside one long step only
    /// when a point happens to fall inside the excursion; see `certify`.
    pub interior_checks: usize,
    /// Certified event detection in integrated modes: a guard with the same sign at
    /// both ends of a step is searched for a hidden pair of crossings from its values
    /// and rates ([`crate::numerics::events::hidden_crossing`]). Off: the sign test at
    /// the ends (and `interior_checks`) only, which misses a short excursion.
    pub certify: bool,
    /// The Zeno guard.
    pub zeno: ZenoGuard,
    /// Keep a record of every event (counts are kept regardless).
    pub record_events: bool,
}

impl Default for Options {
    /// Dormand-Prince 5(4) at rtol = atol = 1e-10, located events, Zeno guard of 100
    /// events within 1 microsecond.
    fn default() -> Self {
        Options {
            method: Method::Dopri5,
            control: StepControl::tol(1e-10, 1e-10),
            locate_events: true,
            event_tol_s: None,
            interior_checks: 0,
            certify: true,
            zeno: ZenoGuard {
                max_events: 100,
                window_s: 1e-6,
            },
            record_events: true,
        }
    }
}

/// One event of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct EventRecord<M> {
    /// Time (s).
    pub t_s: f64,
    /// Mode before.
    pub from: M,
    /// Index of the guard that fired (`usize::MAX` for a breakpoint).
    pub guard: usize,
    /// Mode after, `None` if the run stopped.
    pub to: Option<M>,
}

/// How a run ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome<X> {
    /// Reached the end time.
    Completed,
    /// The model stopped it (its reason).
    Stopped(X),
    /// Events accumulated: `events` of them within `window_s` ending at `t_s`.
    Zeno {
        /// Time of the last event (s).
        t_s: f64,
        /// Events in the window.
        events: usize,
        /// Window (s).
        window_s: f64,
    },
    /// The integrator failed (step underflow, non-finite state).
    Failed(OdeError),
}

/// The result of a hybrid run.
#[derive(Debug, Clone)]
pub struct Run<M, X, const N: usize> {
    /// How the run ended.
    pub outcome: Outcome<X>,
    /// Time at the end (s).
    pub t_end_s: f64,
    /// State at the end.
    pub y_end: [f64; N],
    /// Mode at the end.
    pub mode_end: M,
    /// The events, if recorded.
    pub events: Vec<EventRecord<M>>,
    /// Number of events (guards fired and breakpoints that changed the mode).
    pub event_count: usize,
    /// Integration work.
    pub stats: Stats,
    /// Guard evaluations spent locating events.
    pub locate_evals: u64,
    /// Work of the certified search (zero when `Options::certify` is off).
    pub certify: CertifyStats,
    /// Time spent in each mode (s), in order of first visit.
    pub mode_time_s: Vec<(M, f64)>,
}

/// One piece of trajectory inside a mode: a step, or the part of it before an event.
pub struct Segment<'a, const N: usize> {
    /// Start time (s).
    pub t0: f64,
    /// End time (s).
    pub t1: f64,
    /// State at `t0`.
    pub y0: [f64; N],
    /// State at `t1`.
    pub y1: [f64; N],
    eval: &'a dyn Fn(f64) -> [f64; N],
}

impl<const N: usize> Segment<'_, N> {
    /// The state at `t` in `[t0, t1]` (dense output or closed form).
    pub fn eval(&self, t: f64) -> [f64; N] {
        (self.eval)(t)
    }
}

/// Watches a run: every segment (accepted step) and every event.
pub trait Observer<M, const N: usize> {
    /// Called for every piece of trajectory, in time order.
    fn segment(&mut self, _mode: M, _seg: &Segment<'_, N>) {}
    /// Called at every event with the state before the reset and the next mode and
    /// state after it (`None` if the run stops).
    fn event(
        &mut self,
        _t_s: f64,
        _from: M,
        _guard: usize,
        _before: &[f64; N],
        _after: Option<(M, &[f64; N])>,
    ) {
    }
}

impl<M, const N: usize> Observer<M, N> for () {}

mod driver;
pub use driver::simulate;

mod certify;
#[cfg(test)]
mod tests;
