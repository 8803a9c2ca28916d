//! A rigorous bound on how far Moreau-Jean's rest time lies from the accumulation time
//! t_inf of a ball dropped on a fixed floor, for the scheme as `numerics::timestepping`
//! implements it (theta = 1/2, contact active when the predicted midpoint gap
//! z_k + h v_k / 2 <= 0, Newton's law on the step-start velocity, rest: a sticking step
//! ending with |v| < 1e-12 m/s). Derivation: chapter 7's text, "How far Moreau-Jean's
//! rest lies from t_inf".
//!
//! In units of g h (speed) and g h^2 (height) the impact steps change the invariant
//! P = t + v/g + c U/g (U = sqrt(v^2 + 2 g z), c = (1 + e)/(1 - e); P = t_inf exactly
//! along every exact flight, and the scheme's flights are exact) by Delta P / h within
//! closed-form envelopes of the impact speed x = |v_k|/(g h); summed along an envelope
//! of the impact speeds and energies, they bound t_rest - t_inf.
//!
//! The same invariant bounds the event-driven run's stop ([`event_driven_bound_s`]):
//! there only the event times' rounding moves P.

use super::budget::EVENT_ULPS;
use crate::numerics::rounding::{gamma, OWN};

/// The per-impact envelopes of Delta P / h for restitution `e`, in the scaled impact
/// speed x = |v_k|/(g h) (dimensionless).
struct Envelopes {
    e: f64,
    /// c = (1 + e)/(1 - e).
    c: f64,
    /// x_k = (2 - e)/e^2: above it the post-impact energy stays positive.
    x_k: f64,
    /// p = (2 - e)/(2 e).
    p: f64,
}

impl Envelopes {
    fn new(e: f64) -> Self {
        Envelopes {
            e,
            c: (1.0 + e) / (1.0 - e),  // formula: c = (1 + e)/(1 - e)
            x_k: (2.0 - e) / (e * e),  // formula: x_k = (2 - e)/e^2
            p: (2.0 - e) / (2.0 * e), // formula: p = (2 - e)/(2 e)
        }
    }

    /// Below x_k: the minimum over the phase, at zero post-impact energy (decreasing).
    fn m(&self, x: f64) -> f64 {
        let (e, c) = (self.e, self.c);
        1.0 + (1.0 + e) * x - c * ((1.0 - e) * x * ((1.0 + e) * x + 1.0)).sqrt() // formula: M(x) = 1 + (1+e) x - c sqrt((1-e) x ((1+e) x + 1))
    }

    /// From x_k on: a lower bound of the minimum over the phase (increasing).
    fn right(&self, x: f64) -> f64 {
        let (e, p) = (self.e, self.p);
        -1.0 / e - self.c * p * p / (e * x - p) // formula: L(x) >= -1/e - c p^2/(e x - p)
    }

    /// The least Delta P / h of an impact with x in [lo, hi].
    fn low_min(&self, lo: f64, hi: f64) -> f64 {
        if hi <= self.x_k {
            self.m(hi)
        } else if lo >= self.x_k {
            self.right(lo)
        } else {
            self.right(self.x_k) // formula: min over the V at x_k (right(x_k) <= M(x_k))
        }
    }

    /// The largest Delta P / h of an impact with x in [lo, hi]: <= 1 from the top of
    /// the phase range; from its bottom 1 + (1+e) x - c sqrt(max(0, x^2 - x)) below x_k
    /// (increasing to 2 + e at x = 1, decreasing after).
    fn high_max(&self, lo: f64, hi: f64) -> f64 {
        let (e, c) = (self.e, self.c);
        if hi <= 1.0 {
            1.0 + (1.0 + e) * hi
        } else if lo >= self.x_k {
            1.0
        } else if lo >= 1.0 {
            (1.0 + (1.0 + e) * lo - c * (lo * lo - lo).sqrt()).max(1.0)
        } else {
            2.0 + e
        }
    }
}

/// The least impact speed at energy E (both scaled): x^2 + x >= E.
fn x_min(energy: f64) -> f64 {
    -0.5 + (0.25 + energy.max(0.0)).sqrt() // formula: x >= -1/2 + sqrt(1/4 + E)
}

/// The largest impact speed at energy E: x^2 - x < E.
fn x_max(energy: f64) -> f64 {
    0.5 + (0.25 + energy.max(0.0)).sqrt() // formula: x < 1/2 + sqrt(1/4 + E)
}

/// The bound (s) on |t_rest - t_inf| for Moreau-Jean at step `h_s` on a ball of
/// restitution `e` (0 < e < 1) dropped from `drop_m` under gravity `g_mps2`, as the
/// chapter runs it (rest: a sticking step ending with |v| < 1e-12 m/s).
pub fn mj_rest_bound_s(e: f64, g_mps2: f64, h_s: f64, drop_m: f64) -> f64 {
    let env = Envelopes::new(e);
    let d = |x: f64| (1.0 - e * e) * x * x + (1.0 - e) * x; // formula: E - E' = (1-e^2) x^2 + (1-e) x
    let d2 = (1.0 - e) * (3.0 + e) / 2.0; // formula: two impacts dissipate >= (1-e)(3+e)/2
    let big_x = (2.0 * drop_m / g_mps2).sqrt() / h_s; // formula: X = t1/h, E_0 = X^2
    let (mut e_hi, mut lo, mut hi) = (big_x * big_x, x_min(big_x * big_x), x_max(big_x * big_x));
    let (mut s_lo, mut s_hi) = (0.0_f64, 0.0_f64);
    let (mut best_lo, mut best_hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for _ in 0..100_000 {
        // the tail from this impact on: at most K impacts (pairs), or telescoped
        let k = 2.0 * ((e_hi + 0.25) / d2).ceil(); // formula: K <= 2 ceil((E + 1/4)/d2)
        let x_top = x_max(e_hi);
        let pairs_lo = k * env.low_min(0.0, x_top).min(0.0);
        let tele_lo = -env.c * e_hi.sqrt(); // formula: tail >= -c sqrt(E)
        best_lo = best_lo.max(s_lo + pairs_lo.max(tele_lo));
        best_hi = best_hi.min(s_hi + k * env.high_max(0.0, x_top).max(0.0) + 1.0); // formula: + 1: the rest step, Delta P <= h
        if e_hi < 1e-9 {
            break;
        }
        s_lo += env.low_min(lo, hi).min(0.0);
        s_hi += env.high_max(lo, hi).max(0.0);
        e_hi -= d(x_min(e_hi)); // formula: E_{n+1} <= E_n - D(x_min(E_n))
        hi = (e * hi + 1.0).min(x_max(e_hi)); // formula: x_{n+1} < e x_n + 1
        lo = x_min(e * e * lo * lo - (2.0 - e) * lo); // formula: E_{n+1} >= e^2 x^2 - (2-e) x
    }
    let g = g_mps2;
    let rest_v = 2e-12; // the rest criterion 1e-12 m/s, doubled for its rounding
    let rest_tiny = (rest_v + env.c * (rest_v * (rest_v + g * h_s)).sqrt()) / g; // formula: (v + c U)/g of a state called at rest
    let n_steps = (big_x * (1.0 + e) / (1.0 - e) + 1.0 / h_s) + 1.0;
    let dz = 4.0 * n_steps * f64::EPSILON * drop_m; // formula: delta z = 4 N eps z_0
    let rounding = env.c * (2.0 * g * dz).sqrt() / g; // formula: delta P <= c sqrt(2 g delta z)/g
    h_s * (-best_lo).max(best_hi) + rest_tiny + rounding
}

/// What the event-driven ball run reports at its Zeno stop, for [`event_driven_bound_s`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZenoStop {
    /// Time of the stop (s).
    pub t_s: f64,
    /// Landings over the run.
    pub landings: u64,
    /// Events inside the guard's window at the stop.
    pub in_window: usize,
    /// The guard: events allowed in a window, and the window (s).
    pub guard: (usize, f64),
}

/// The bound (s) on |t_stop - t_inf| of the event-driven ball (restitution `e` in
/// (0, 1), dropped from `drop_m` under `g_mps2`) that stopped as `stop` says. Derivation:
/// chapter 7's text, "How far the event-driven stop lies from t_inf".
///
/// The invariant P = t + v/g + c U/g of [`mj_rest_bound_s`] equals t_inf along exact
/// flights and impacts; only the event times move it. The impact map
/// (`physics::block`, `impact`) puts the ball back on the floor (gap 0) with rebound
/// w = e |v⁻| taken at the located time: a landing of speed V located δ off (either
/// side) leaves w = e (V + g δ) at t + δ, so P moves by exactly
/// δ + (1 + c) e δ = c δ (c = (1 + e)/(1 - e)). δ = [`EVENT_ULPS`] ulps of t
/// (assumed, as in every budget of the chapter); the rounding of w = e |v⁻| adds
/// (1 + c) V_1 γ_2/g per landing (V_1 = sqrt(2 g z_0), the fastest landing). The stop
/// itself: when the guard fired (`in_window` = its count m within the window W), the
/// flights shrink by e, so the last is below W (1 - e) e^(m-2)/(1 - e^(m-1)) and the
/// flights after it sum to (1 + c) e/2 of it; when time stopped advancing (fewer
/// events), the flight in progress is shorter than the driver's smallest step,
/// 16 ε t (assumed), and the rest sum to (1 + c)/2 of it. Plus t_inf's own rounding,
/// γ_8 t_inf.
pub fn event_driven_bound_s(e: f64, g_mps2: f64, drop_m: f64, t_inf_s: f64, stop: &ZenoStop) -> f64 {
    let g = g_mps2;
    let c = (1.0 + e) / (1.0 - e); // formula: c = (1 + e)/(1 - e)
    let v1 = (2.0 * g * drop_m).sqrt(); // formula: V_1 = sqrt(2 g z_0)
    let t = stop.t_s.abs().max(t_inf_s);
    let delta = EVENT_ULPS * f64::EPSILON * t; // formula: δ = 256 ε t
    let per_landing = c * delta + (1.0 + c) * v1 * gamma(2) / g; // formula: |ΔP| <= c δ + (1 + c) V_1 γ_2/g
    let (max_events, window_s) = stop.guard;
    let tail = if stop.in_window >= max_events {
        let m = max_events as f64;
        let last = window_s * (1.0 - e) * e.powf(m - 2.0) / (1.0 - e.powf(m - 1.0)); // formula: f_last <= W (1 - e) e^(m-2)/(1 - e^(m-1))
        (1.0 + c) * e / 2.0 * last // formula: remaining = (1 + c) e f_last/2
    } else {
        (1.0 + c) / 2.0 * 16.0 * f64::EPSILON * t // formula: remaining <= (1 + c)/2 16 ε t
    };
    (stop.landings as f64 * per_landing + tail + gamma(8) * t_inf_s) * OWN
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_envelopes_bound_the_exact_impact_map() {
        // Delta P / h of one impact, computed from its definition over a fine grid of
        // phases zeta in (-x/2, x/2], lies within [low_min, high_max] at that x.
        for e in [0.01, 0.1, 0.3, 0.5, 0.7, 0.8] {
            let env = Envelopes::new(e);
            for i in 1..400 {
                let x = 10f64.powf(-2.0 + 6.0 * f64::from(i) / 400.0);
                let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
                for j in 0..=400 {
                    let zeta = x * (f64::from(j) / 400.0 - 0.5).max(-0.5 + 1e-9);
                    let u = (x * x + 2.0 * zeta).max(0.0).sqrt();
                    let u1 = (e * e * x * x + 2.0 * zeta - (1.0 - e) * x).max(0.0).sqrt();
                    let dp = 1.0 + (1.0 + e) * x + env.c * (u1 - u);
                    lo = lo.min(dp);
                    hi = hi.max(dp);
                }
                // Counted rounding of both sides. The sqrt arguments x^2 + 2 zeta and
                // e^2 x^2 + 2 zeta - (1 - e) x cancel: each is off by at most
                // γ_4 (x^2 + 2x) absolutely, which moves its sqrt by at most the sqrt of
                // that; every other operation adds a relative γ_8 of the terms' sizes
                // 1, (1 + e) x and c (u + u1 + 2(x + 1)) (the envelopes' sqrt included).
                let cancel = 2.0 * (gamma(4) * (x * x + 2.0 * x)).sqrt(); // formula: 2 sqrt(γ_4 (x^2 + 2x))
                let tol = env.c * cancel + gamma(8) * (2.0 + 2.0 * (1.0 + e) * x + env.c * (2.0 * x + 2.0) * 2.0); // formula: c 2 sqrt(γ_4 (x^2 + 2x)) + γ_8 (2 + 2(1+e)x + 4c(x + 1))
                assert!(lo >= env.low_min(x, x) - tol, "e {e} x {x}: {lo} < {}", env.low_min(x, x));
                assert!(hi <= env.high_max(x, x) + tol, "e {e} x {x}: {hi} > {}", env.high_max(x, x));
            }
        }
    }

    #[test]
    fn the_bound_is_finite_and_at_least_a_step_at_the_flag_box_corners() {
        // --restitution accepts any e in (0, 0.8]: the envelopes must stay finite at
        // e -> 0 (x_k and p overflow to infinity there and are never evaluated).
        for e in [1e-300, 1e-12, 1e-6, 0.8] {
            for g in [1.0, 25.0] {
                let b = mj_rest_bound_s(e, g, 1e-3, 1.0);
                assert!((1e-3..0.2).contains(&b), "e {e} g {g}: {b}");
            }
        }
    }
}
