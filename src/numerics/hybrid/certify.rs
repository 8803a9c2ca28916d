//! The certified search's bookkeeping inside the driver: the rates of a mode's guards
//! at the ends of each step, and the call into
//! [`hidden_crossing`](crate::numerics::events::hidden_crossing).
//!
//! A guard's rate along the trajectory is the model's own
//! ([`HybridSystem::guard_rates`], in closed form, from `f(t1, y1)`), or else its
//! directional difference along the flow,
//! `g' = (g(t + d, y + d f(t, y)) - g(t, y)) / d` with `d = h 2^-20`: one evaluation of
//! all guards per step, since `f(t1, y1)` is the integrator's next first stage. The
//! forward difference is off by `d g''/2`, a relative `2^-21 h / tau` of the rate for a
//! guard with time scale `tau`; the Hermite model it feeds has an allowance far larger.

use super::HybridSystem;
use crate::numerics::events::{
    clearly_one_sided, hermite_root, hidden_crossing, time_tolerance, CertifyStats, Direction,
    GuardPoint,
};
use crate::numerics::ode::Step;

/// Step fraction of the difference that gives a guard's rate (2^-20).
const RATE_STEP: f64 = 1.0 / 1_048_576.0;

/// Guard rates at the start (`r0`) and end (`r1`) of the current step.
pub(super) struct Rates {
    on: bool,
    r0: Vec<f64>,
    r1: Vec<f64>,
    have_r0: bool,
    scratch: Vec<f64>,
    /// Bit `i` set: guard `i` failed the cheap one-sided test on this step.
    suspects: u64,
}

impl Rates {
    /// Bookkeeping for a run; inert when `on` is false.
    pub(super) fn new(on: bool) -> Self {
        Rates {
            on,
            r0: Vec::with_capacity(8),
            r1: Vec::with_capacity(8),
            have_r0: false,
            scratch: Vec::with_capacity(8),
            suspects: 0,
        }
    }

    /// The rates at both ends of the step `st` just taken in `mode`, whose guards are
    /// `g0` (start) and `g1` (end); none for a step without an end derivative.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn update<S: HybridSystem<N>, const N: usize>(
        &mut self,
        sys: &S,
        mode: S::Mode,
        st: &Step<N>,
        g0: &[f64],
        g1: &[f64],
    ) {
        self.suspects = 0;
        // A method that keeps no end derivative (Euler, whose interpolant is a straight
        // line anyway) is not certified: its rates would cost a flow evaluation a step.
        let Some(f1) = st.f1 else {
            self.have_r0 = false;
            return;
        };
        if !self.on {
            return;
        }
        let d = (st.t1 - st.t0) * RATE_STEP;
        if !self.have_r0 {
            let f0 = &st.f0;
            rates_along_flow(
                sys,
                mode,
                st.t0,
                &st.y0,
                f0,
                g0,
                d,
                &mut self.r0,
                &mut self.scratch,
            );
            self.have_r0 = true;
        }
        rates_along_flow(
            sys,
            mode,
            st.t1,
            &st.y1,
            &f1,
            g1,
            d,
            &mut self.r1,
            &mut self.scratch,
        );
        let h = st.t1 - st.t0;
        for (i, (((&ga, &gb), &ra), &rb)) in
            g0.iter().zip(g1).zip(&self.r0).zip(&self.r1).enumerate()
        {
            let a = GuardPoint {
                t: 0.0,
                g: ga,
                rate: ra,
            };
            let b = GuardPoint {
                t: h,
                g: gb,
                rate: rb,
            };
            if !clearly_one_sided(&a, &b) {
                self.suspects |= 1u64 << i.min(63);
            }
        }
    }

    /// Did guard `i` fail the cheap one-sided test on this step (so it needs
    /// [`Rates::hidden`])?
    #[inline]
    pub(super) fn suspect(&self, i: usize) -> bool {
        self.on && self.suspects & (1u64 << i.min(63)) != 0
    }

    /// A start for locating a crossing of guard `i` bracketed by the whole step
    /// `[ta, tb]` (values `ga`, `gb`): the root of its Hermite model and the model's rate
    /// there ([`hermite_root`]); `None` without rates.
    pub(super) fn start(
        &self,
        i: usize,
        (ta, ga): (f64, f64),
        (tb, gb): (f64, f64),
    ) -> Option<(f64, f64)> {
        if !self.on || !self.have_r0 || i >= self.r1.len() {
            return None;
        }
        let (a, b) = self.ends(i, (ta, ga), (tb, gb));
        hermite_root(&a, &b)
    }

    /// Guard `i` at the step's ends `(ta, ga)`, `(tb, gb)` with its rates there.
    fn ends(
        &self,
        i: usize,
        (ta, ga): (f64, f64),
        (tb, gb): (f64, f64),
    ) -> (GuardPoint, GuardPoint) {
        let a = GuardPoint {
            t: ta,
            g: ga,
            rate: self.r0[i],
        };
        let b = GuardPoint {
            t: tb,
            g: gb,
            rate: self.r1[i],
        };
        (a, b)
    }

    /// The step was kept whole: its end is the next step's start.
    pub(super) fn advance(&mut self) {
        std::mem::swap(&mut self.r0, &mut self.r1);
    }

    /// The mode or state jumped: the start rates are recomputed at the next step.
    pub(super) fn forget(&mut self) {
        self.have_r0 = false;
    }

    /// A bracket `(a, b, g(a), g(b))` of a crossing of guard `i` in direction `dir`
    /// that the end-point test missed on the step `[ta, tb]`, searched on the dense
    /// output `eval`; `None` when no crossing can hide (or the search is off).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn hidden<S: HybridSystem<N>, const N: usize>(
        &self,
        sys: &S,
        mode: S::Mode,
        i: usize,
        dir: Direction,
        eval: &dyn Fn(f64) -> [f64; N],
        (ta, ga): (f64, f64),
        (tb, gb): (f64, f64),
        stats: &mut CertifyStats,
    ) -> Option<(f64, f64, f64, f64)> {
        if !self.have_r0 || !self.suspect(i) {
            return None;
        }
        let (a, b) = self.ends(i, (ta, ga), (tb, gb));
        let d = (tb - ta) * RATE_STEP;
        let at = |s: f64| {
            let g = sys.guard(mode, i, s, &eval(s));
            let s2 = s + d;
            let g2 = sys.guard(mode, i, s2, &eval(s2));
            (g, (g2 - g) / (s2 - s)) // formula: rate on the dense output, forward difference
        };
        let [l, m, r] = hidden_crossing(at, a, b, time_tolerance(tb), stats)?;
        if dir.fires(l.1, m.1) {
            Some((l.0, m.0, l.1, m.1))
        } else if dir.fires(m.1, r.1) {
            Some((m.0, r.0, m.1, r.1))
        } else {
            None
        }
    }
}

/// The model's own guard rates ([`HybridSystem::guard_rates`]), or else
/// `out[i] = (g_i(t + d, y + d f) - g[i]) / d'` with `d'` the representable time step.
#[allow(clippy::too_many_arguments)]
fn rates_along_flow<S: HybridSystem<N>, const N: usize>(
    sys: &S,
    mode: S::Mode,
    t: f64,
    y: &[f64; N],
    f: &[f64; N],
    g: &[f64],
    d: f64,
    out: &mut Vec<f64>,
    scratch: &mut Vec<f64>,
) {
    if sys.guard_rates(mode, t, y, f, out) {
        return;
    }
    let t2 = t + d;
    let dt = t2 - t;
    let mut y2 = *y;
    for (yi, fi) in y2.iter_mut().zip(f) {
        *yi += dt * fi; // formula: y + d f(t, y)
    }
    sys.guards(mode, t2, &y2, scratch);
    let inv_dt = 1.0 / dt;
    out.clear();
    out.extend(
        g.iter()
            .zip(scratch.iter())
            .map(|(g0, g1)| (g1 - g0) * inv_dt),
    ); // formula: g' ~ (g(t + d) - g(t)) / d
}
