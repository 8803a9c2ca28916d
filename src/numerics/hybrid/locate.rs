//! Locating the event on a piece of trajectory: for each guard of the mode, a bracket
//! of its crossing (a sign change at the piece's check points, or else a hidden pair of
//! crossings from the certified search), refined by the Illinois method; the earliest
//! crossing wins, ties going to the lowest guard index.

use super::driver::{Driver, Piece};
use super::HybridSystem;
use crate::numerics::events::{illinois, illinois_from, time_tolerance};

/// A bracket `(a, b, g(a), g(b))` of one guard's crossing.
type Bracket = (f64, f64, f64, f64);

impl<'a, S: HybridSystem<N>, const N: usize> Driver<'a, S, N> {
    /// The earliest crossing among the mode's guards on the piece: (guard, time).
    pub(super) fn earliest_crossing(&mut self, p: &Piece<'a, '_, S, N>) -> Option<(usize, f64)> {
        let mut best: Option<(usize, f64)> = None;
        for i in 0..self.guards0.len() {
            // Only a crossing before the earliest one located so far matters: the search
            // ends there (one guard evaluation decides whether this guard fires first).
            let t_stop = best.map_or(p.t1, |(_, tb)| tb);
            if let Some(bracket) = self.bracket(p, i, t_stop) {
                let te = self.refine(p, i, bracket);
                if best.is_none_or(|(_, tb)| te < tb) {
                    best = Some((i, te));
                }
            }
        }
        best
    }

    /// A bracket of a crossing of guard `i` before `t_stop`: a sign change at the check
    /// points, or else (on an integrator step whose guard failed the cheap one-sided
    /// test) a hidden pair of crossings found by the certified search.
    fn bracket(&mut self, p: &Piece<'a, '_, S, N>, i: usize, t_stop: f64) -> Option<Bracket> {
        let seen = self.sign_change(p, i, t_stop);
        if seen.is_some() || !self.rates.suspect(i) || p.step.is_none() {
            return seen;
        }
        self.rates
            .hidden(
                self.sys,
                p.flow.mode,
                i,
                self.dirs[i],
                &|s| p.guard_state(s),
                (p.t0, self.guards0[i]),
                (p.t1, self.guards1[i]),
                &mut self.run.certify,
            )
            .filter(|&(a, ..)| a < t_stop)
    }

    /// The first sign change of guard `i` in its direction among the check points: the
    /// `interior_checks` evenly spaced points of the piece and its end (or `t_stop`).
    fn sign_change(&self, p: &Piece<'a, '_, S, N>, i: usize, t_stop: f64) -> Option<Bracket> {
        let (dir, checks) = (self.dirs[i], self.opts.interior_checks);
        let (mut ta, mut ga) = (p.t0, self.guards0[i]);
        for k in 1..=checks + 1 {
            let tb = if k == checks + 1 {
                t_stop
            } else {
                p.t0 + (p.t1 - p.t0) * k as f64 / (checks + 1) as f64
            };
            if tb > t_stop {
                break;
            }
            let gb = if tb == p.t1 {
                self.guards1[i]
            } else {
                self.sys.guard(p.flow.mode, i, tb, &p.guard_state(tb))
            };
            if dir.fires(ga, gb) {
                return Some((ta, tb, ga, gb));
            }
            (ta, ga) = (tb, gb);
        }
        None
    }

    /// The crossing time of guard `i` inside `bracket`: located by the Illinois method
    /// (from the guard's Hermite model when the bracket is the whole step), or the
    /// bracket's end when events are not located.
    fn refine(&mut self, p: &Piece<'a, '_, S, N>, i: usize, (a, b, ga, gb): Bracket) -> f64 {
        if !self.opts.locate_events {
            return b;
        }
        let tol = self.opts.event_tol_s.unwrap_or_else(|| time_tolerance(b));
        let g = |s: f64| self.sys.guard(p.flow.mode, i, s, &p.guard_state(s));
        let whole = p.step.is_some() && a == p.t0 && b == p.t1;
        let (te, n) = match self.rates.start(i, (a, ga), (b, gb)).filter(|_| whole) {
            Some(start) => illinois_from(g, a, b, ga, gb, tol, start),
            None => illinois(g, a, b, ga, gb, tol),
        };
        self.run.locate_evals += u64::from(n);
        te
    }
}
