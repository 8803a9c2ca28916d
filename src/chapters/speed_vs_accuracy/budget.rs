//! The error budgets of the chapter's reference checks, from the runs themselves: the
//! rounding of one run (unit roundoff times its number of roundings times the state's
//! scale, plus the event times located to a few ulps times the velocity jump), and the
//! truncation error of an adaptive run at tolerance tau bounded from the runs at tau and
//! tau/10 (Richardson with an assumed contraction per decade), and a first-order method's
//! error from its runs at h, h/2 and h/4. Derivation: chapter 7's
//! text, "How far the references can be trusted".

use super::measure::Measured;

/// The contraction per decade of tolerance assumed for an adaptive pair's truncation
/// error, c = 10^(-1/2): at least half a decade of accuracy per decade of tolerance
/// (assumed; Dormand-Prince 5(4) under local control gives 10^(-5/6) = 0.15, and the
/// chapter's convergence study measures the ratio).
pub const DECADE_CONTRACTION: f64 = 0.316_227_766_016_837_94;

/// Ulps of t to which an event time is located (the locator's bracketing and the closed
/// forms' own rounding: a few hundred ulps, as in the block's rounding floor).
pub const EVENT_ULPS: f64 = 256.0;

/// The scales of one run's observable, a mean velocity over a window.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scales {
    /// The speed scale v_s of the state (m/s): twice the plate's peak speed plus the
    /// observable's magnitude (assumed: no velocity of the run exceeds it).
    pub speed_mps: f64,
    /// The observable's magnitude |d| (m/s).
    pub drift_mps: f64,
    /// End time of the run (s).
    pub t_end_s: f64,
    /// The averaging window (s).
    pub window_s: f64,
    /// The drive period (s): the excursion of a position within a period is <= v_s T.
    pub period_s: f64,
}

impl Scales {
    /// The scales of a mean velocity `drift_mps` on a plate of peak speed `v_p_mps`.
    pub fn new(v_p_mps: f64, drift_mps: f64, t_end_s: f64, window_s: f64, period_s: f64) -> Self {
        Scales {
            speed_mps: 2.0 * v_p_mps + drift_mps.abs(), // formula: v_s = 2 v_p + |d|
            drift_mps: drift_mps.abs(),
            t_end_s,
            window_s,
            period_s,
        }
    }
}

/// The rounding budget of one run's mean velocity (m/s): each right-hand-side
/// evaluation and each event rounds the state once (a worst-case, linear accumulation
/// over N = evaluations + events), a rounding of the position (scale x_s = |d| t_end +
/// v_s T) and of the velocity (carried to the end: v_s t_end); the window's two ends
/// double it. Each event time, located to [`EVENT_ULPS`] ulps of t, shifts the
/// displacement by at most the velocity jump (at most v_s) times that time.
pub fn rounding_mps(run: &Measured, s: &Scales) -> f64 {
    let eps = f64::EPSILON;
    let n = (run.rhs_evals + run.events) as f64;
    let x_scale = s.drift_mps * s.t_end_s + s.speed_mps * s.period_s; // formula: x_s = |d| t_end + v_s T
    let state = 2.0 * n * eps * (x_scale + s.speed_mps * s.t_end_s) / s.window_s; // formula: R_state = 2 N eps (x_s + v_s t_end) / T_w
    let events =
        EVENT_ULPS * eps * s.t_end_s * s.speed_mps * run.events.max(1) as f64 / s.window_s; // formula: R_event = 256 eps t_end v_s N_events / T_w
    state + events
}

/// A bound on the error of an adaptive run's value `d_tau` at tolerance tau from the run
/// at tau/10 and both rounding budgets: with e = T + r, |r| <= R and |T(tau/10)| <= c
/// |T(tau)|, |T(tau)| <= K (|d(tau) - d(tau/10)| + R(tau) + R(tau/10)), K = 1/(1 - c),
/// and |e(tau)| <= |T(tau)| + R(tau). Returns (|e(tau)| bound, |T(tau)| bound).
pub fn adaptive_error_bound(
    (d_tau, r_tau): (f64, f64),
    (d_tenth, r_tenth): (f64, f64),
) -> (f64, f64) {
    let k = 1.0 / (1.0 - DECADE_CONTRACTION); // formula: K = 1/(1 - c)
    let truncation = k * ((d_tau - d_tenth).abs() + r_tau + r_tenth); // formula: |T(tau)| <= K (|d(tau) - d(tau/10)| + R(tau) + R(tau/10))
    (truncation + r_tau, truncation)
}

/// An estimate of a first-order method's error at step h from the runs at h, h/2 and
/// h/4: e(h) = d(h) - d(0) telescopes into the differences D_k = d(h/2^k) - d(h/2^(k+1));
/// D_0 and D_1 are measured, and from h/2 on the differences are assumed to halve with
/// the step (first order), |D_k| <= |D_1| 2^(1-k), so |e(h)| <= |D_0| + 2 |D_1|. (From h
/// and h/2 alone, Richardson's 2 |D_0| can land on a cancellation: a method with events
/// has an O(h) error whose coefficient moves with the phase of the steps against the
/// events.)
pub fn first_order_error((d_h, d_half, d_quarter): (f64, f64, f64)) -> f64 {
    (d_h - d_half).abs() + 2.0 * (d_half - d_quarter).abs() // formula: |e(h)| <= |D_0| + 2 |D_1|
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bound_holds_on_a_geometric_sequence_and_grows_with_rounding() {
        // truncation errors 1e-9 and 1e-10 at tau and tau/10, no rounding
        let (e, t) = adaptive_error_bound((1.0 + 1e-9, 0.0), (1.0 + 1e-10, 0.0));
        assert!(e >= 1e-9 && t >= 1e-9 && e < 2e-9);
        let (e2, _) = adaptive_error_bound((1.0 + 1e-9, 1e-10), (1.0 + 1e-10, 1e-10));
        assert!(e2 > e + 2e-10);
    }

    #[test]
    fn rounding_grows_with_the_number_of_evaluations_and_time() {
        let run = |n: u64| Measured {
            value: 1.0,
            rhs_evals: n,
            steps: n,
            events: 10,
            completed: true,
            note: "completed",
        };
        let s = Scales::new(0.1, 0.01, 1.0, 0.5, 0.1);
        let long = Scales::new(0.1, 0.01, 100.0, 0.5, 0.1);
        assert!(rounding_mps(&run(2000), &s) > rounding_mps(&run(1000), &s));
        assert!(rounding_mps(&run(1000), &long) > 10.0 * rounding_mps(&run(1000), &s));
        assert_eq!(first_order_error((1.0, 1.5, 1.75)), 1.0);
    }
}
