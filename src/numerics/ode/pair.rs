//! What the two Dormand-Prince pairs share: the step-size controller of Hairer's codes
//! around a trial step (error-controlled), or one trial taken as it is (fixed steps).

use super::common::{initial_step, place_step, Tol};
use super::stepper::{accept_fixed, fixed_step, At, Memory, Stepper};
use super::{OdeError, OdeSystem, Stats, StepControl};

/// An explicit embedded Runge-Kutta pair: a trial step with its error norm, and the
/// acceptance that makes a trial the kept step.
pub(super) trait Pair<const N: usize> {
    /// The method's order (the starting-step heuristic's exponent).
    const ORDER: u32;
    /// Limits of the step-size factor after an accepted step.
    const FAC_MIN: f64;
    /// See [`Pair::FAC_MIN`].
    const FAC_MAX: f64;
    /// `e^(-1/(q+1))`, the controller's root of the error norm.
    fn root(e: f64) -> f64;
    /// One trial step of size `h` from `at` and its error norm (1 = at the tolerance).
    fn trial<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        at: &At<'_, N>,
        h: f64,
        tol: Tol,
        mem: &mut Memory<N>,
        stats: &mut Stats,
    ) -> ([f64; N], f64);
    /// Makes the last trial, ending at `(t1, y1)`, the kept step.
    fn accept<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        at: &At<'_, N>,
        end: (f64, [f64; N]),
        mem: &mut Memory<N>,
        stats: &mut Stats,
    );
}

/// One accepted step of the pair `p` under `control`.
pub(super) fn step<P: Pair<N>, S: OdeSystem<N> + ?Sized, const N: usize>(
    p: &mut P,
    sys: &S,
    at: At<'_, N>,
    control: StepControl,
    mem: &mut Memory<N>,
    stats: &mut Stats,
) -> Result<(), OdeError> {
    match control {
        StepControl::Adaptive {
            rtol,
            atol,
            h_max_s,
        } => adaptive(p, sys, &at, Tol { rtol, atol }, h_max_s, (mem, stats)),
        StepControl::Fixed { .. } => {
            let (h, t1) = fixed_step(&at, control);
            let (trial, _) = p.trial(sys, &at, h, Tol::UNUSED, mem, stats);
            p.accept(sys, &at, (t1, trial), mem, stats);
            accept_fixed(mem, stats, t1)
        }
    }
}

/// Error-controlled step: trials shrink until one meets the tolerance.
fn adaptive<P: Pair<N>, S: OdeSystem<N> + ?Sized, const N: usize>(
    p: &mut P,
    sys: &S,
    at: &At<'_, N>,
    tol: Tol,
    h_max: f64,
    (mem, stats): (&mut Memory<N>, &mut Stats),
) -> Result<(), OdeError> {
    // Step-size controller of each pair (Hairer's codes): the error estimate is of
    // order q + 1 in h (q = 4 for DP5, 7 for DOP853), so h_new = h (0.9 / e)^(1/(q+1)),
    // limited to [fac_min, fac_max] after an accepted step.
    let (t, span) = (at.t, at.span());
    let mut h = match mem.h_next {
        Some(h) => h,
        None => initial_step(sys, t, at.y, &at.f0, tol, P::ORDER, stats),
    }
    .min(h_max);
    loop {
        let (h_placed, t1, last) = place_step(t, span, h)?;
        h = h_placed;
        let (y1, e) = p.trial(sys, at, h, tol, mem, stats);
        if e.is_finite() && e <= 1.0 {
            // formula: h_new = h min(fac_max, max(fac_min, 0.9 e^(-1/(q+1))))
            let fac = if e == 0.0 {
                P::FAC_MAX
            } else {
                (0.9 * P::root(e)).clamp(P::FAC_MIN, P::FAC_MAX)
            };
            if !last {
                mem.h_next = Some((h * fac).min(h_max));
            } else if mem.h_next.is_none() {
                mem.h_next = Some(h);
            }
            stats.accepted += 1;
            p.accept(sys, at, (t1, y1), mem, stats);
            return Ok(());
        }
        stats.rejected += 1;
        let fac = if e.is_finite() {
            (0.9 * P::root(e)).clamp(0.1, 0.9)
        } else {
            0.1
        };
        h *= fac;
        mem.h_next = Some(h);
    }
}

/// Every embedded pair steps the same way: [`step`].
impl<P: Pair<N> + Default, const N: usize> Stepper<N> for P {
    fn step<S: OdeSystem<N> + ?Sized>(
        &mut self,
        sys: &S,
        at: At<'_, N>,
        control: StepControl,
        mem: &mut Memory<N>,
        stats: &mut Stats,
    ) -> Result<(), OdeError> {
        step(self, sys, at, control, mem, stats)
    }
}
