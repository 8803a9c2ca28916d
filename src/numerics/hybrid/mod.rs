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

use super::events::{illinois, illinois_from, time_tolerance, CertifyStats, Direction};
use super::ode::{Integrator, Method, OdeError, OdeSystem, Stats, StepControl};
use std::collections::VecDeque;

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

struct ModeFlow<'a, S, M> {
    sys: &'a S,
    mode: M,
}

impl<S: HybridSystem<N>, const N: usize> OdeSystem<N> for ModeFlow<'_, S, S::Mode> {
    const ARGS: usize = S::FLOW_ARGS;

    fn rhs(&self, t: f64, y: &[f64; N]) -> [f64; N] {
        self.sys.flow(self.mode, t, y)
    }
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
    let (mut t, mut y, mut mode) = (t0, y0, mode0);
    // A control out of range (a NaN rtol, say) ends the run before it starts, with the
    // error naming the range, even when the first modes have closed forms.
    let invalid = opts.control.check().err();
    let mut run = Run {
        outcome: Outcome::Completed,
        t_end_s: t0,
        y_end: y0,
        mode_end: mode0,
        events: Vec::new(),
        event_count: 0,
        stats: Stats::default(),
        locate_evals: 0,
        certify: CertifyStats::default(),
        mode_time_s: Vec::new(),
    };
    // Guard rates at the start and end of the current step (certified search only).
    let mut rates = certify::Rates::new(opts.certify);
    let mut recent: VecDeque<f64> = VecDeque::with_capacity(opts.zeno.max_events + 1);
    // Guard values at the start and end of the current step; buffers reused, so the
    // stepping loop does not allocate.
    let mut guards0: Vec<f64> = Vec::with_capacity(8);
    let mut guards1: Vec<f64> = Vec::with_capacity(8);
    let mut fresh_mode = true;
    // The directions of the mode's guards, asked once per mode entry.
    let mut dirs: Vec<Direction> = Vec::with_capacity(8);
    // Evaluations spent on interpolants built after their step (DOP853's extension).
    let mut dense_evals = 0u64;
    let outcome = if let Some(e) = invalid {
        Outcome::Failed(e)
    } else {
        'outer: loop {
            if t >= t_end {
                break Outcome::Completed;
            }
            if fresh_mode {
                sys.guards(mode, t, &y, &mut guards0);
                dirs.clear();
                dirs.extend((0..guards0.len()).map(|i| sys.direction(mode, i)));
                fresh_mode = false;
                // A state or guard the model made NaN/inf (at the start, or by a transition):
                // end here, so the outcome says where it arose.
                if !all_finite(&y) || !all_finite(&guards0) {
                    break Outcome::Failed(OdeError::NonFinite { t_s: t });
                }
            }
            let bp = sys.breakpoint_after(t).filter(|&b| b < t_end);
            let horizon = bp.unwrap_or(t_end);
            let max_step = sys.max_step(mode, t, &y);
            // A step that would stop a few ulps short of the horizon (a breakpoint or the
            // end) goes onto it instead: no sliver steps before a breakpoint.
            let t_lim = if t + max_step < horizon - 64.0 * f64::EPSILON * horizon.abs() {
                t + max_step
            } else {
                horizon
            };
            // A step too short to advance time right after a run of events is Zeno
            // accumulation below the time resolution; otherwise a failure. Either way:
            // report, never spin.
            let too_small = |t: f64, e: OdeError| {
                let in_window = recent
                    .iter()
                    .filter(|&&te| t - te < opts.zeno.window_s)
                    .count();
                match e {
                    OdeError::StepTooSmall { .. } if in_window > 0 => Outcome::Zeno {
                        t_s: t,
                        events: in_window,
                        window_s: opts.zeno.window_s,
                    },
                    e => Outcome::Failed(e),
                }
            };
            if t_lim <= t {
                break too_small(t, OdeError::StepTooSmall { t_s: t });
            }
            // One piece of trajectory: closed form or one integrator step.
            let (t1, y1, step);
            let flow = ModeFlow { sys, mode };
            if let Some(y_lim) = sys.exact(mode, t, &y, t_lim) {
                // The integrator checks its own states; a closed form is checked here.
                if !all_finite(&y_lim) {
                    break Outcome::Failed(OdeError::NonFinite { t_s: t_lim });
                }
                t1 = t_lim;
                y1 = y_lim;
                step = None;
            } else {
                match integ.step(&flow, t, &y, t_lim) {
                    Ok(s) => {
                        t1 = s.t1;
                        y1 = s.y1;
                        step = Some(s);
                    }
                    Err(e) => break too_small(t, e),
                }
            }
            let (ts, ys) = (t, y);
            let eval = |s: f64| -> [f64; N] {
                match &step {
                    Some(st) => st.eval(&flow, s),
                    None => sys.exact(mode, ts, &ys, s).expect("closed form"),
                }
            };
            // The same for the guards, which read only the first GUARD_ARGS components (two
            // closures, not one with the count as an argument: the count must stay a constant
            // where the interpolant is inlined, or the guard search costs 3.6 % more).
            let geval = |s: f64| -> [f64; N] {
                match &step {
                    Some(st) => st.eval_first(&flow, s, S::GUARD_ARGS),
                    None => sys.exact(mode, ts, &ys, s).expect("closed form"),
                }
            };
            // Find the earliest crossing among the guards.
            let mut best: Option<(usize, f64)> = None;
            sys.guards(mode, t1, &y1, &mut guards1);
            if !all_finite(&guards1) {
                break Outcome::Failed(OdeError::NonFinite { t_s: t1 });
            }
            if let Some(st) = &step {
                rates.update(sys, mode, st, &guards0, &guards1);
            }
            for i in 0..guards0.len() {
                let dir = dirs[i];
                let mut ta = ts;
                let mut ga = guards0[i];
                let mut bracket = None;
                // Only a crossing before the earliest one located so far matters: the search
                // ends there (one guard evaluation decides whether this guard fires first).
                let t_stop = best.map_or(t1, |(_, tb)| tb);
                for k in 1..=opts.interior_checks + 1 {
                    let tb = if k == opts.interior_checks + 1 {
                        t_stop
                    } else {
                        ts + (t1 - ts) * k as f64 / (opts.interior_checks + 1) as f64
                    };
                    if tb > t_stop {
                        break;
                    }
                    let gb = if tb == t1 {
                        guards1[i]
                    } else {
                        sys.guard(mode, i, tb, &geval(tb))
                    };
                    if dir.fires(ga, gb) {
                        bracket = Some((ta, tb, ga, gb));
                        break;
                    }
                    ta = tb;
                    ga = gb;
                }
                if bracket.is_none() && rates.suspect(i) && step.is_some() {
                    bracket = rates
                        .hidden(
                            sys,
                            mode,
                            i,
                            dir,
                            &geval,
                            (ts, guards0[i]),
                            (t1, guards1[i]),
                            &mut run.certify,
                        )
                        .filter(|&(a, ..)| a < t_stop);
                }
                if let Some((a, b, ga, gb)) = bracket {
                    let te = if opts.locate_events {
                        let tol = opts.event_tol_s.unwrap_or_else(|| time_tolerance(b));
                        let g = |s: f64| sys.guard(mode, i, s, &geval(s));
                        // A crossing bracketed by the whole step starts from its Hermite model.
                        let whole = step.is_some() && a == ts && b == t1;
                        let (te, n) = match rates.start(i, (a, ga), (b, gb)).filter(|_| whole) {
                            Some(start) => illinois_from(g, a, b, ga, gb, tol, start),
                            None => illinois(g, a, b, ga, gb, tol),
                        };
                        run.locate_evals += u64::from(n);
                        te
                    } else {
                        b
                    };
                    if best.is_none_or(|(_, tb)| te < tb) {
                        best = Some((i, te));
                    }
                }
            }
            // The piece of trajectory up to the earliest event, or the whole step.
            let (te, ye) = match best {
                Some((_, te)) => (te, eval(te)),
                None => (t1, y1),
            };
            obs.segment(
                mode,
                &Segment {
                    t0: ts,
                    t1: te,
                    y0: ys,
                    y1: ye,
                    eval: &eval,
                },
            );
            dense_evals += step.as_ref().map_or(0, |s| s.dense_evals());
            add_time(&mut run.mode_time_s, mode, te - ts);
            match best {
                Some((i, _)) => {
                    let tr = sys.on_event(mode, i, te, &ye);
                    run.event_count += 1;
                    let to = match &tr {
                        Transition::To { mode: m, state } => {
                            obs.event(te, mode, i, &ye, Some((*m, state)));
                            Some(*m)
                        }
                        Transition::Stop(_) => {
                            obs.event(te, mode, i, &ye, None);
                            None
                        }
                    };
                    if opts.record_events {
                        run.events.push(EventRecord {
                            t_s: te,
                            from: mode,
                            guard: i,
                            to,
                        });
                    }
                    t = te;
                    match tr {
                        Transition::To { mode: m, state } => {
                            mode = m;
                            y = state;
                        }
                        Transition::Stop(x) => {
                            y = ye;
                            break 'outer Outcome::Stopped(x);
                        }
                    }
                    integ.restart();
                    fresh_mode = true;
                    rates.forget();
                    recent.push_back(te);
                    while recent.len() > opts.zeno.max_events {
                        recent.pop_front();
                    }
                    if recent.len() == opts.zeno.max_events && te - recent[0] < opts.zeno.window_s {
                        break Outcome::Zeno {
                            t_s: te,
                            events: recent.len(),
                            window_s: opts.zeno.window_s,
                        };
                    }
                }
                None => {
                    t = t1;
                    y = y1;
                    std::mem::swap(&mut guards0, &mut guards1);
                    rates.advance();
                }
            }
            // On a breakpoint (reached by a step, or by an event located exactly on it,
            // after that event's transition): the breakpoint's transition.
            if Some(t) == bp {
                integ.restart();
                match sys.on_breakpoint(mode, t, &y) {
                    Transition::To { mode: m, state } => {
                        if m != mode {
                            run.event_count += 1;
                            if opts.record_events {
                                run.events.push(EventRecord {
                                    t_s: t,
                                    from: mode,
                                    guard: usize::MAX,
                                    to: Some(m),
                                });
                            }
                        }
                        mode = m;
                        y = state;
                        // Guards may jump at a breakpoint: re-evaluate them.
                        fresh_mode = true;
                        rates.forget();
                    }
                    Transition::Stop(x) => break 'outer Outcome::Stopped(x),
                }
            }
        }
    };
    run.outcome = outcome;
    run.t_end_s = t;
    run.y_end = y;
    run.mode_end = mode;
    run.stats = integ.stats;
    run.stats.rhs_evals += dense_evals;
    run
}

fn add_time<M: PartialEq + Copy>(acc: &mut Vec<(M, f64)>, mode: M, dt: f64) {
    match acc.iter_mut().find(|(m, _)| *m == mode) {
        Some((_, t)) => *t += dt,
        None => acc.push((mode, dt)),
    }
}

mod certify;
#[cfg(test)]
mod tests;

/// Are all values finite (no NaN, no infinity)?
fn all_finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}
