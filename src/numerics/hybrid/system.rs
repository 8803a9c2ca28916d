//! What a model gives the driver: its modes, flows, closed forms, guards with their
//! directions, and the transitions at events and breakpoints.

use crate::numerics::events::Direction;
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
    /// [`OdeSystem::ARGS`]. The rest are outputs only (accumulated work, say).
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
