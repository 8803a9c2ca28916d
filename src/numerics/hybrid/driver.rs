//! The driver's state and its loop, one named step per function: enter a mode, take a
//! piece of trajectory (a closed form or one integrator step), evaluate the guards at
//! its end, find the earliest crossing ([`locate`](super::locate)), record the piece,
//! then apply the event's reset or accept the whole step, and apply a breakpoint's
//! transition. A step that ends the run returns `Err(outcome)`.

use super::certify::Rates;
use super::{EventRecord, HybridSystem, Observer, Options, Outcome, Run, Segment, Transition};
use crate::numerics::events::{CertifyStats, Direction};
use crate::numerics::ode::{Integrator, OdeError, OdeSystem, Stats, Step};
use std::collections::VecDeque;

/// A step of the loop: `Ok` carries on, `Err` ends the run with that outcome.
pub(super) type Flow<T, X> = Result<T, Outcome<X>>;

/// The flow of one mode, as the integrator sees it.
pub(super) struct ModeFlow<'a, S, M> {
    pub(super) sys: &'a S,
    pub(super) mode: M,
}

impl<S: HybridSystem<N>, const N: usize> OdeSystem<N> for ModeFlow<'_, S, S::Mode> {
    const ARGS: usize = S::FLOW_ARGS;

    fn rhs(&self, t: f64, y: &[f64; N]) -> [f64; N] {
        self.sys.flow(self.mode, t, y)
    }
}

/// One piece of trajectory in one mode, from `(t0, y0)` to `(t1, y1)`: a closed form
/// (`step` is `None`) or one integrator step with its dense output.
/// The step is the integrator's own (`'s` borrows it until the next step).
pub(super) struct Piece<'a, 's, S: HybridSystem<N>, const N: usize> {
    pub(super) flow: ModeFlow<'a, S, S::Mode>,
    pub(super) t0: f64,
    pub(super) y0: [f64; N],
    pub(super) t1: f64,
    pub(super) y1: [f64; N],
    pub(super) step: Option<&'s Step<N>>,
}

impl<S: HybridSystem<N>, const N: usize> Piece<'_, '_, S, N> {
    /// The whole state at `s` in `[t0, t1]`.
    #[inline]
    pub(super) fn state(&self, s: f64) -> [f64; N] {
        match self.step {
            Some(st) => st.eval(&self.flow, s),
            None => self.closed_form(s),
        }
    }

    /// The state at `s` for the guards, which read only the first `GUARD_ARGS`
    /// components (a constant here, where the interpolant is inlined: passed as an
    /// argument, the guard search costs 3.6 % more).
    #[inline]
    pub(super) fn guard_state(&self, s: f64) -> [f64; N] {
        match self.step {
            Some(st) => st.eval_first(&self.flow, s, S::GUARD_ARGS),
            None => self.closed_form(s),
        }
    }

    fn closed_form(&self, s: f64) -> [f64; N] {
        let f = &self.flow;
        f.sys
            .exact(f.mode, self.t0, &self.y0, s)
            .expect("closed form")
    }
}

/// Everything a run carries from one step to the next, but the integrator (whose last
/// step the current piece borrows).
pub(super) struct Driver<'a, S: HybridSystem<N>, const N: usize> {
    pub(super) sys: &'a S,
    pub(super) opts: &'a Options,
    t: f64,
    y: [f64; N],
    mode: S::Mode,
    /// The result so far (its outcome and end are written by [`Driver::finish`]).
    pub(super) run: Run<S::Mode, S::Stop, N>,
    /// Guard rates at the start and end of the current step (certified search only).
    pub(super) rates: Rates,
    /// Times of the latest events, for the Zeno guard.
    recent: VecDeque<f64>,
    /// Guard values at the start and end of the current step; buffers reused, so the
    /// loop does not allocate.
    pub(super) guards0: Vec<f64>,
    pub(super) guards1: Vec<f64>,
    /// The directions of the mode's guards, asked once per mode entry.
    pub(super) dirs: Vec<Direction>,
    /// The mode was just entered (or its state jumped): guards to evaluate afresh.
    fresh_mode: bool,
    /// Evaluations spent on interpolants built after their step (DOP853's extension).
    dense_evals: u64,
}

impl<'a, S: HybridSystem<N>, const N: usize> Driver<'a, S, N> {
    /// A run of `sys` about to start from `(t0, y0)` in `mode0`.
    pub(super) fn new(
        sys: &'a S,
        opts: &'a Options,
        mode0: S::Mode,
        t0: f64,
        y0: [f64; N],
    ) -> Self {
        Driver {
            sys,
            opts,
            t: t0,
            y: y0,
            mode: mode0,
            run: Run {
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
            },
            rates: Rates::new(opts.certify),
            recent: VecDeque::with_capacity(opts.zeno.max_events + 1),
            guards0: Vec::with_capacity(8),
            guards1: Vec::with_capacity(8),
            dirs: Vec::with_capacity(8),
            fresh_mode: true,
            dense_evals: 0,
        }
    }

    /// Steps until `t_end` or an early end: how the run ended.
    pub(super) fn run_to(
        &mut self,
        integ: &mut Integrator<N>,
        t_end: f64,
        obs: &mut impl Observer<S::Mode, N>,
    ) -> Outcome<S::Stop> {
        match self.steps(integ, t_end, obs) {
            Ok(()) => Outcome::Completed,
            Err(end) => end,
        }
    }

    /// The loop: one piece of trajectory per turn, and what happens at its end.
    fn steps(
        &mut self,
        integ: &mut Integrator<N>,
        t_end: f64,
        obs: &mut impl Observer<S::Mode, N>,
    ) -> Flow<(), S::Stop> {
        loop {
            if self.t >= t_end {
                return Ok(());
            }
            if self.fresh_mode {
                self.enter_mode()?;
            }
            let bp = self.sys.breakpoint_after(self.t).filter(|&b| b < t_end);
            let piece = self.take_piece(integ, bp.unwrap_or(t_end))?;
            self.guards_at_end(&piece)?;
            let best = self.earliest_crossing(&piece);
            let (te, ye) = self.record(&piece, best, obs);
            match best {
                Some((i, _)) => self.apply_event(integ, i, te, ye, obs)?,
                None => self.accept(&piece),
            }
            // On a breakpoint (reached by a step, or by an event located exactly on it,
            // after that event's transition): the breakpoint's transition.
            if Some(self.t) == bp {
                self.apply_breakpoint(integ)?;
            }
        }
    }

    /// The guards and their directions at the start of a mode (or after a jump).
    fn enter_mode(&mut self) -> Flow<(), S::Stop> {
        let (sys, mode) = (self.sys, self.mode);
        sys.guards(mode, self.t, &self.y, &mut self.guards0);
        self.dirs.clear();
        self.dirs
            .extend((0..self.guards0.len()).map(|i| sys.direction(mode, i)));
        self.fresh_mode = false;
        // A state or guard the model made NaN/inf (at the start, or by a transition):
        // end here, so the outcome says where it arose.
        if !all_finite(&self.y) || !all_finite(&self.guards0) {
            return Err(Outcome::Failed(OdeError::NonFinite { t_s: self.t }));
        }
        Ok(())
    }

    /// The end of the next piece: the model's longest step, or the horizon (a
    /// breakpoint or the end) when the step would stop a few ulps short of it (no
    /// sliver steps before a breakpoint).
    fn piece_end(&self, horizon: f64) -> f64 {
        let max_step = self.sys.max_step(self.mode, self.t, &self.y);
        if self.t + max_step < horizon - 64.0 * f64::EPSILON * horizon.abs() {
            self.t + max_step
        } else {
            horizon
        }
    }

    /// One piece of trajectory towards `horizon`: the closed form or one integrator step.
    /// (Inlined: a call returns the piece by copy, 2 % more instructions a run.)
    #[inline(always)]
    fn take_piece<'s>(
        &self,
        integ: &'s mut Integrator<N>,
        horizon: f64,
    ) -> Flow<Piece<'a, 's, S, N>, S::Stop> {
        let t_lim = self.piece_end(horizon);
        if t_lim <= self.t {
            return Err(self.too_small(OdeError::StepTooSmall { t_s: self.t }));
        }
        let flow = ModeFlow {
            sys: self.sys,
            mode: self.mode,
        };
        let (t1, y1, step) = if let Some(y_lim) = self.sys.exact(self.mode, self.t, &self.y, t_lim)
        {
            // The integrator checks its own states; a closed form is checked here.
            if !all_finite(&y_lim) {
                return Err(Outcome::Failed(OdeError::NonFinite { t_s: t_lim }));
            }
            (t_lim, y_lim, None)
        } else {
            match integ.step(&flow, self.t, &self.y, t_lim) {
                Ok(s) => (s.t1, s.y1, Some(s)),
                Err(e) => return Err(self.too_small(e)),
            }
        };
        Ok(Piece {
            flow,
            t0: self.t,
            y0: self.y,
            t1,
            y1,
            step,
        })
    }

    /// A step too short to advance time right after a run of events is Zeno
    /// accumulation below the time resolution; otherwise a failure. Either way:
    /// report, never spin.
    fn too_small(&self, e: OdeError) -> Outcome<S::Stop> {
        let window_s = self.opts.zeno.window_s;
        let in_window = self
            .recent
            .iter()
            .filter(|&&te| self.t - te < window_s)
            .count();
        match e {
            OdeError::StepTooSmall { .. } if in_window > 0 => Outcome::Zeno {
                t_s: self.t,
                events: in_window,
                window_s,
            },
            e => Outcome::Failed(e),
        }
    }

    /// The guards at the piece's end (and, for a step, their rates at both ends).
    fn guards_at_end(&mut self, p: &Piece<'a, '_, S, N>) -> Flow<(), S::Stop> {
        self.sys.guards(p.flow.mode, p.t1, &p.y1, &mut self.guards1);
        if !all_finite(&self.guards1) {
            return Err(Outcome::Failed(OdeError::NonFinite { t_s: p.t1 }));
        }
        if let Some(st) = p.step {
            self.rates
                .update(self.sys, p.flow.mode, st, &self.guards0, &self.guards1);
        }
        Ok(())
    }

    /// The piece up to the earliest event `best` (or the whole piece) to the observer
    /// and the mode's time: its end `(te, ye)`.
    fn record(
        &mut self,
        p: &Piece<'a, '_, S, N>,
        best: Option<(usize, f64)>,
        obs: &mut impl Observer<S::Mode, N>,
    ) -> (f64, [f64; N]) {
        let (te, ye) = match best {
            Some((_, te)) => (te, p.state(te)),
            None => (p.t1, p.y1),
        };
        let seg = Segment {
            t0: p.t0,
            t1: te,
            y0: p.y0,
            y1: ye,
            eval: &|s| p.state(s),
        };
        obs.segment(p.flow.mode, &seg);
        self.dense_evals += p.step.map_or(0, |s| s.dense_evals());
        add_time(&mut self.run.mode_time_s, p.flow.mode, te - p.t0);
        (te, ye)
    }

    /// No event on the piece: its end is the next step's start.
    fn accept(&mut self, p: &Piece<'a, '_, S, N>) {
        self.t = p.t1;
        self.y = p.y1;
        std::mem::swap(&mut self.guards0, &mut self.guards1);
        self.rates.advance();
    }

    /// Guard `i` fired at `(te, ye)`: the model's transition (a reset into the next
    /// mode, or a stop), told to the observer and recorded; then the Zeno guard.
    fn apply_event(
        &mut self,
        integ: &mut Integrator<N>,
        i: usize,
        te: f64,
        ye: [f64; N],
        obs: &mut impl Observer<S::Mode, N>,
    ) -> Flow<(), S::Stop> {
        let from = self.mode;
        let tr = self.sys.on_event(from, i, te, &ye);
        self.run.event_count += 1;
        let to = match &tr {
            Transition::To { mode: m, state } => {
                obs.event(te, from, i, &ye, Some((*m, state)));
                Some(*m)
            }
            Transition::Stop(_) => {
                obs.event(te, from, i, &ye, None);
                None
            }
        };
        self.record_event(te, i, to);
        self.t = te;
        match tr {
            Transition::To { mode: m, state } => {
                self.mode = m;
                self.y = state;
            }
            Transition::Stop(x) => {
                self.y = ye;
                return Err(Outcome::Stopped(x));
            }
        }
        integ.restart();
        self.jumped();
        self.zeno_guard(te)
    }

    /// Keeps the event (guard `guard`, `usize::MAX` for a breakpoint) if asked to.
    fn record_event(&mut self, t_s: f64, guard: usize, to: Option<S::Mode>) {
        if self.opts.record_events {
            self.run.events.push(EventRecord {
                t_s,
                from: self.mode,
                guard,
                to,
            });
        }
    }

    /// The mode or state jumped: guards and rates are evaluated afresh.
    fn jumped(&mut self) {
        self.fresh_mode = true;
        self.rates.forget();
    }

    /// The Zeno guard after an event at `te`: too many events in too short a window
    /// end the run.
    fn zeno_guard(&mut self, te: f64) -> Flow<(), S::Stop> {
        let zeno = self.opts.zeno;
        self.recent.push_back(te);
        while self.recent.len() > zeno.max_events {
            self.recent.pop_front();
        }
        if self.recent.len() == zeno.max_events && te - self.recent[0] < zeno.window_s {
            return Err(Outcome::Zeno {
                t_s: te,
                events: self.recent.len(),
                window_s: zeno.window_s,
            });
        }
        Ok(())
    }

    /// The model's transition at a breakpoint (counted as an event when the mode changes).
    fn apply_breakpoint(&mut self, integ: &mut Integrator<N>) -> Flow<(), S::Stop> {
        integ.restart();
        match self.sys.on_breakpoint(self.mode, self.t, &self.y) {
            Transition::To { mode: m, state } => {
                if m != self.mode {
                    self.run.event_count += 1;
                    self.record_event(self.t, usize::MAX, Some(m));
                }
                self.mode = m;
                self.y = state;
                // Guards may jump at a breakpoint: re-evaluate them.
                self.jumped();
                Ok(())
            }
            Transition::Stop(x) => Err(Outcome::Stopped(x)),
        }
    }

    /// The result: how the run ended, where, and the work it took.
    pub(super) fn finish(
        self,
        stats: Stats,
        outcome: Outcome<S::Stop>,
    ) -> Run<S::Mode, S::Stop, N> {
        let mut run = self.run;
        run.outcome = outcome;
        run.t_end_s = self.t;
        run.y_end = self.y;
        run.mode_end = self.mode;
        run.stats = stats;
        run.stats.rhs_evals += self.dense_evals;
        run
    }
}

/// Adds `dt` to the time spent in `mode`.
fn add_time<M: PartialEq + Copy>(acc: &mut Vec<(M, f64)>, mode: M, dt: f64) {
    match acc.iter_mut().find(|(m, _)| *m == mode) {
        Some((_, t)) => *t += dt,
        None => acc.push((mode, dt)),
    }
}

/// Are all values finite (no NaN, no infinity)?
fn all_finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}
