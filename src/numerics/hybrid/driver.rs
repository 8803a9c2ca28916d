//! The stepping loop of [`simulate`]: one piece of trajectory at a time (a closed form
//! or one integrator step), the earliest guard crossing on it, then the event's or the
//! breakpoint's transition.

use super::certify::Rates;
use super::{EventRecord, HybridSystem, Observer, Options, Outcome, Run, Segment, Transition};
use crate::numerics::events::{illinois, illinois_from, time_tolerance, CertifyStats, Direction};
use crate::numerics::ode::{Integrator, OdeError, OdeSystem, Stats, Step};
use std::collections::VecDeque;

/// The flow of one mode as an ODE.
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
    let mut d = Driver::new(sys, opts, (t0, y0, mode0));
    // A control out of range (a NaN rtol, say) ends the run before it starts, with the
    // error naming the range, even when the first modes have closed forms.
    if let Err(e) = opts.control.check() {
        return d.finish(Outcome::Failed(e), Stats::default());
    }
    let outcome = loop {
        if let Some(outcome) = d.advance(&mut integ, t_end, obs) {
            break outcome;
        }
    };
    d.finish(outcome, integ.stats)
}

/// The driver's state between pieces of trajectory.
struct Driver<'a, S: HybridSystem<N>, const N: usize> {
    sys: &'a S,
    opts: &'a Options,
    t: f64,
    y: [f64; N],
    mode: S::Mode,
    run: Run<S::Mode, S::Stop, N>,
    /// Guard rates at the start and end of the current step (certified search only).
    rates: Rates,
    /// Times of the latest events, for the Zeno guard.
    recent: VecDeque<f64>,
    /// Guard values at the start and end of the current step; buffers reused, so the
    /// stepping loop does not allocate.
    guards0: Vec<f64>,
    guards1: Vec<f64>,
    /// Are the guards (and their directions) to be evaluated afresh (a new mode)?
    fresh_mode: bool,
    /// The directions of the mode's guards, asked once per mode entry.
    dirs: Vec<Direction>,
    /// Evaluations spent on interpolants built after their step (DOP853's extension).
    dense_evals: u64,
}

/// One piece of trajectory: its start, its end, and the integrator step it is (`None`:
/// a closed form).
struct Piece<'s, const N: usize> {
    ts: f64,
    ys: [f64; N],
    t1: f64,
    y1: [f64; N],
    step: Option<&'s Step<N>>,
}

impl<'a, S: HybridSystem<N>, const N: usize> Driver<'a, S, N> {
    fn new(sys: &'a S, opts: &'a Options, (t0, y0, mode0): (f64, [f64; N], S::Mode)) -> Self {
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
            fresh_mode: true,
            dirs: Vec::with_capacity(8),
            dense_evals: 0,
        }
    }

    /// The run as it ended.
    fn finish(mut self, outcome: Outcome<S::Stop>, stats: Stats) -> Run<S::Mode, S::Stop, N> {
        self.run.outcome = outcome;
        self.run.t_end_s = self.t;
        self.run.y_end = self.y;
        self.run.mode_end = self.mode;
        self.run.stats = stats;
        self.run.stats.rhs_evals += self.dense_evals;
        self.run
    }

    /// One piece of trajectory and what ends it; `Some`: the run ends so.
    fn advance(
        &mut self,
        integ: &mut Integrator<N>,
        t_end: f64,
        obs: &mut impl Observer<S::Mode, N>,
    ) -> Option<Outcome<S::Stop>> {
        if self.t >= t_end {
            return Some(Outcome::Completed);
        }
        if self.fresh_mode {
            if let Some(failed) = self.enter_mode() {
                return Some(failed);
            }
        }
        let (sys, mode, t) = (self.sys, self.mode, self.t);
        let bp = sys.breakpoint_after(t).filter(|&b| b < t_end);
        let t_lim = self.step_limit(bp.unwrap_or(t_end));
        if t_lim <= t {
            return Some(self.too_small(t, OdeError::StepTooSmall { t_s: t }));
        }
        let flow = ModeFlow { sys, mode };
        let piece = match self.piece(integ, &flow, t_lim) {
            Ok(piece) => piece,
            Err(end) => return Some(end),
        };
        let (ts, ys, step) = (piece.ts, piece.ys, piece.step);
        let eval = |s: f64| -> [f64; N] {
            match step {
                Some(st) => st.eval(&flow, s),
                None => sys.exact(mode, ts, &ys, s).expect("closed form"),
            }
        };
        // The same for the guards, which read only the first GUARD_ARGS components (two
        // closures, not one with the count as an argument: the count must stay a constant
        // where the interpolant is inlined, or the guard search costs 3.6 % more).
        let geval = |s: f64| -> [f64; N] {
            match step {
                Some(st) => st.eval_first(&flow, s, S::GUARD_ARGS),
                None => sys.exact(mode, ts, &ys, s).expect("closed form"),
            }
        };
        let best = match self.earliest(&piece, &geval) {
            Ok(best) => best,
            Err(outcome) => return Some(outcome),
        };
        // The piece of trajectory up to the earliest event, or the whole step.
        let (te, ye) = match best {
            Some((_, te)) => (te, eval(te)),
            None => (piece.t1, piece.y1),
        };
        let seg = Segment {
            t0: ts,
            t1: te,
            y0: ys,
            y1: ye,
            eval: &eval,
        };
        obs.segment(mode, &seg);
        self.dense_evals += step.map_or(0, |s| s.dense_evals());
        add_time(&mut self.run.mode_time_s, mode, te - ts);
        let end = match best {
            Some((i, _)) => self.on_event(integ, i, (te, ye), obs),
            None => {
                self.t = piece.t1;
                self.y = piece.y1;
                std::mem::swap(&mut self.guards0, &mut self.guards1);
                self.rates.advance();
                None
            }
        };
        if end.is_some() {
            return end;
        }
        // On a breakpoint (reached by a step, or by an event located exactly on it,
        // after that event's transition): the breakpoint's transition.
        if Some(self.t) == bp {
            integ.restart();
            return self.on_breakpoint();
        }
        None
    }

    /// One piece of trajectory from the current state up to `t_lim`: the closed form,
    /// or one integrator step (which may end sooner). `Err`: the run ends there.
    fn piece<'s>(
        &self,
        integ: &'s mut Integrator<N>,
        flow: &ModeFlow<'_, S, S::Mode>,
        t_lim: f64,
    ) -> Result<Piece<'s, N>, Outcome<S::Stop>> {
        let (t, y) = (self.t, self.y);
        if let Some(y_lim) = self.sys.exact(self.mode, t, &y, t_lim) {
            // The integrator checks its own states; a closed form is checked here.
            if !all_finite(&y_lim) {
                return Err(Outcome::Failed(OdeError::NonFinite { t_s: t_lim }));
            }
            return Ok(Piece {
                ts: t,
                ys: y,
                t1: t_lim,
                y1: y_lim,
                step: None,
            });
        }
        match integ.step(flow, t, &y, t_lim) {
            Ok(s) => Ok(Piece {
                ts: t,
                ys: y,
                t1: s.t1,
                y1: s.y1,
                step: Some(s),
            }),
            Err(e) => Err(self.too_small(t, e)),
        }
    }

    /// A new mode: its guards and their directions. `Some`: the run fails there (a
    /// state or guard the model made NaN/inf, at the start or by a transition: end
    /// here, so the outcome says where it arose).
    fn enter_mode(&mut self) -> Option<Outcome<S::Stop>> {
        let (sys, mode, t) = (self.sys, self.mode, self.t);
        sys.guards(mode, t, &self.y, &mut self.guards0);
        self.dirs.clear();
        self.dirs
            .extend((0..self.guards0.len()).map(|i| sys.direction(mode, i)));
        self.fresh_mode = false;
        (!all_finite(&self.y) || !all_finite(&self.guards0))
            .then_some(Outcome::Failed(OdeError::NonFinite { t_s: t }))
    }

    /// The end of the next piece: the model's longest step, or the horizon (a
    /// breakpoint or the end) when the step would stop a few ulps short of it (no
    /// sliver steps before a breakpoint).
    fn step_limit(&self, horizon: f64) -> f64 {
        let max_step = self.sys.max_step(self.mode, self.t, &self.y);
        if self.t + max_step < horizon - 64.0 * f64::EPSILON * horizon.abs() {
            self.t + max_step
        } else {
            horizon
        }
    }

    /// A step too short to advance time right after a run of events is Zeno
    /// accumulation below the time resolution; otherwise a failure. Either way:
    /// report, never spin.
    fn too_small(&self, t: f64, e: OdeError) -> Outcome<S::Stop> {
        let window_s = self.opts.zeno.window_s;
        let in_window = self.recent.iter().filter(|&&te| t - te < window_s).count();
        match e {
            OdeError::StepTooSmall { .. } if in_window > 0 => Outcome::Zeno {
                t_s: t,
                events: in_window,
                window_s,
            },
            e => Outcome::Failed(e),
        }
    }

    /// The earliest located crossing among the guards on `piece`: `(guard, time)`,
    /// `None` when no guard fires; `Err`: a guard at the piece's end is not finite.
    #[allow(clippy::type_complexity)]
    fn earliest(
        &mut self,
        piece: &Piece<'_, N>,
        geval: &impl Fn(f64) -> [f64; N],
    ) -> Result<Option<(usize, f64)>, Outcome<S::Stop>> {
        let (sys, mode) = (self.sys, self.mode);
        sys.guards(mode, piece.t1, &piece.y1, &mut self.guards1);
        if !all_finite(&self.guards1) {
            return Err(Outcome::Failed(OdeError::NonFinite { t_s: piece.t1 }));
        }
        if let Some(st) = piece.step {
            self.rates
                .update(sys, mode, st, &self.guards0, &self.guards1);
        }
        let mut best: Option<(usize, f64)> = None;
        for i in 0..self.guards0.len() {
            // Only a crossing before the earliest one located so far matters: the search
            // ends there (one guard evaluation decides whether this guard fires first).
            let t_stop = best.map_or(piece.t1, |(_, tb)| tb);
            if let Some(bracket) = self.bracket(i, piece, t_stop, geval) {
                let te = self.locate(i, piece, bracket, geval);
                if best.is_none_or(|(_, tb)| te < tb) {
                    best = Some((i, te));
                }
            }
        }
        Ok(best)
    }

    /// A bracket `(a, b, g(a), g(b))` of a crossing of guard `i` on `piece` before
    /// `t_stop`: a sign change at the end (or at an interior check point), else a
    /// hidden pair of crossings found by the certified search.
    fn bracket(
        &mut self,
        i: usize,
        piece: &Piece<'_, N>,
        t_stop: f64,
        geval: &impl Fn(f64) -> [f64; N],
    ) -> Option<(f64, f64, f64, f64)> {
        let (sys, mode, dir) = (self.sys, self.mode, self.dirs[i]);
        let (ts, t1, checks) = (piece.ts, piece.t1, self.opts.interior_checks);
        let mut ta = ts;
        let mut ga = self.guards0[i];
        for k in 1..=checks + 1 {
            let tb = if k == checks + 1 {
                t_stop
            } else {
                ts + (t1 - ts) * k as f64 / (checks + 1) as f64
            };
            if tb > t_stop {
                break;
            }
            let gb = if tb == t1 {
                self.guards1[i]
            } else {
                sys.guard(mode, i, tb, &geval(tb))
            };
            if dir.fires(ga, gb) {
                return Some((ta, tb, ga, gb));
            }
            ta = tb;
            ga = gb;
        }
        if self.rates.suspect(i) && piece.step.is_some() {
            return self
                .rates
                .hidden(
                    sys,
                    mode,
                    i,
                    dir,
                    geval,
                    (ts, self.guards0[i]),
                    (t1, self.guards1[i]),
                    &mut self.run.certify,
                )
                .filter(|&(a, ..)| a < t_stop);
        }
        None
    }

    /// The time of the crossing of guard `i` inside `(a, b, g(a), g(b))`: located by
    /// the Illinois search (from the Hermite model of the guard when the bracket is
    /// the whole step), or the bracket's end when events are not located.
    fn locate(
        &mut self,
        i: usize,
        piece: &Piece<'_, N>,
        (a, b, ga, gb): (f64, f64, f64, f64),
        geval: &impl Fn(f64) -> [f64; N],
    ) -> f64 {
        if !self.opts.locate_events {
            return b;
        }
        let (sys, mode) = (self.sys, self.mode);
        let tol = self.opts.event_tol_s.unwrap_or_else(|| time_tolerance(b));
        let g = |s: f64| sys.guard(mode, i, s, &geval(s));
        // A crossing bracketed by the whole step starts from its Hermite model.
        let whole = piece.step.is_some() && a == piece.ts && b == piece.t1;
        let (te, n) = match self.rates.start(i, (a, ga), (b, gb)).filter(|_| whole) {
            Some(start) => illinois_from(g, a, b, ga, gb, tol, start),
            None => illinois(g, a, b, ga, gb, tol),
        };
        self.run.locate_evals += u64::from(n);
        te
    }

    /// Guard `i` fired at `(te, ye)`: the model's transition, recorded; `Some`: the run
    /// ends (the model stopped it, or events accumulate: Zeno).
    fn on_event(
        &mut self,
        integ: &mut Integrator<N>,
        i: usize,
        (te, ye): (f64, [f64; N]),
        obs: &mut impl Observer<S::Mode, N>,
    ) -> Option<Outcome<S::Stop>> {
        let mode = self.mode;
        let tr = self.sys.on_event(mode, i, te, &ye);
        self.run.event_count += 1;
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
        if self.opts.record_events {
            self.run.events.push(EventRecord {
                t_s: te,
                from: mode,
                guard: i,
                to,
            });
        }
        self.t = te;
        match tr {
            Transition::To { mode: m, state } => {
                self.mode = m;
                self.y = state;
            }
            Transition::Stop(x) => {
                self.y = ye;
                return Some(Outcome::Stopped(x));
            }
        }
        integ.restart();
        self.fresh_mode = true;
        self.rates.forget();
        self.zeno(te)
    }

    /// The Zeno guard after an event at `te`: `Some` when `max_events` events fall
    /// inside one window.
    fn zeno(&mut self, te: f64) -> Option<Outcome<S::Stop>> {
        let zeno = self.opts.zeno;
        self.recent.push_back(te);
        while self.recent.len() > zeno.max_events {
            self.recent.pop_front();
        }
        (self.recent.len() == zeno.max_events && te - self.recent[0] < zeno.window_s).then(|| {
            Outcome::Zeno {
                t_s: te,
                events: self.recent.len(),
                window_s: zeno.window_s,
            }
        })
    }

    /// The breakpoint's transition at the current time; `Some`: the model stopped the
    /// run.
    fn on_breakpoint(&mut self) -> Option<Outcome<S::Stop>> {
        let (mode, t) = (self.mode, self.t);
        match self.sys.on_breakpoint(mode, t, &self.y) {
            Transition::To { mode: m, state } => {
                if m != mode {
                    self.run.event_count += 1;
                    if self.opts.record_events {
                        self.run.events.push(EventRecord {
                            t_s: t,
                            from: mode,
                            guard: usize::MAX,
                            to: Some(m),
                        });
                    }
                }
                self.mode = m;
                self.y = state;
                // Guards may jump at a breakpoint: re-evaluate them.
                self.fresh_mode = true;
                self.rates.forget();
                None
            }
            Transition::Stop(x) => Some(Outcome::Stopped(x)),
        }
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
