//! The event-driven hybrid-automaton driver.
//!
//! A [`HybridSystem`] has discrete modes. In each mode the state follows a flow (an
//! ODE integrated by the chosen [`Method`], or a closed form supplied by the model
//! through [`HybridSystem::exact`]) until one of the mode's guards crosses zero in its
//! [`Direction`](super::events::Direction). The crossing is located on the step's dense output (or on the closed
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
//! - Guards that start a mode at exactly zero do not fire (see [`Direction::fires`](super::events::Direction::fires)).

use super::events::CertifyStats;
use super::ode::{Integrator, Method, OdeError, Stats, StepControl};
use driver::Driver;

mod driver;
mod locate;
mod observer;
mod system;
pub use observer::{Observer, Segment};
pub use system::{HybridSystem, Transition};

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

/// Runs `sys` from `(t0, y0)` in `mode0` until `t_end` or a stop.
pub fn simulate<S: HybridSystem<N>, const N: usize>(
    sys: &S,
    mode0: S::Mode,
    t0: f64,
    y0: [f64; N],
    t_end: f64,
    opts: &Options,
    obs: &mut impl Observer<S::Mode, N>,
) -> Run<S::Mode, S::Stop, N> {
    let mut integ = Integrator::<N>::new(opts.method, opts.control);
    let mut driver = Driver::new(sys, opts, mode0, t0, y0);
    // A control out of range (a NaN rtol, say) ends the run before it starts, with the
    // error naming the range, even when the first modes have closed forms.
    let outcome = match opts.control.check() {
        Err(e) => Outcome::Failed(e),
        Ok(()) => driver.run_to(&mut integ, t_end, obs),
    };
    driver.finish(integ.stats, outcome)
}

mod certify;
#[cfg(test)]
mod tests;
