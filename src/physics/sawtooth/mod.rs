//! Closed forms for a block on an asymmetrically shaken plate (document section 3.2).
//!
//! Notation (SI units): the plate of a [`Sawtooth`] moves at `a = v_slow` towards +x for
//! `T_s`, then at `-b = -v_fast` for `T_f = a T_s / b` (so `T_s > T_f` when `b > a`);
//! period `T = T_s + T_f`. Coulomb friction with a rigid support gives the block the
//! acceleration `-k sign(v - v_p)` while it slips, with `k = mu g`; it sticks (`v = v_p`)
//! while the plate's acceleration stays within `k` (always, inside a stroke).
//!
//! Coulomb law, sawtooth drive (derivation in `chapters/05-asymmetric-shaking.md`):
//! - **always slipping** is never a steady state: a block inside `(-b, a)` gains
//!   `k (T_s - T_f) > 0` per period ([`slipping_impulse_per_mass`]) until it first reaches
//!   `a` in a slow stroke ([`lock_time_s`]); from then on its motion is periodic;
//! - **sticking in the slow stroke** (`k T_f < a + b`): the velocity dips from `a` to
//!   `a - k T_f` in the fast stroke, recovers in the first `T_f` of the slow stroke, and
//!   rides with the plate for `T_s - T_f`: drift `a - k T_f^2 / T` ([`drift_velocity_mps`]);
//! - **sticking in both strokes** (`k T_f >= a + b`): the two slips mirror each other and
//!   the drift is exactly zero.
//!
//! Linear law `v' = -c (v - v_p)`: the mean velocity over a period of the periodic orbit
//! equals the plate's, zero ([`linear_periodic_start_velocity_mps`] gives the orbit).
//!
//! The smooth drive `v_p = V (sin wt + eps cos 2wt)` is in [`biharmonic`]; every closed
//! form is checked against the shared block model, [`crate::physics::block`].

pub mod biharmonic;

use super::plate::{PlateMotion, Sawtooth};

/// The steady regime of a Coulomb block on a two-velocity sawtooth, or the transient.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Regime {
    /// Slipping during the whole period: only a transient (the block speeds up by
    /// `k (T_s - T_f)` per period until it reaches the slow speed).
    AlwaysSlipping,
    /// Sticking to the plate during part of the slow stroke, slipping in the fast stroke.
    StickSlow,
    /// Sticking during part of both strokes: zero drift.
    StickBoth,
}

impl Regime {
    /// The text label (the chapter's `regime` result).
    pub fn label(self) -> &'static str {
        match self {
            Regime::AlwaysSlipping => "always-slipping",
            Regime::StickSlow => "stick-in-slow-stroke",
            Regime::StickBoth => "stick-in-both-strokes",
        }
    }
}

/// The steady (periodic) regime for the deceleration bound `k = mu g` (m/s^2).
pub fn steady_regime(s: &Sawtooth, k_mps2: f64) -> Regime {
    // formula: stick in both strokes iff k T_f >= a + b
    if k_mps2 * s.fast_duration_s() >= s.slow_velocity_mps + s.fast_velocity_mps {
        Regime::StickBoth
    } else {
        Regime::StickSlow
    }
}

/// Exact steady drift velocity (m/s) of a Coulomb block: `a - k T_f^2 / T` when it
/// sticks only in the slow stroke, `0` when it sticks in both.
pub fn drift_velocity_mps(s: &Sawtooth, k_mps2: f64) -> f64 {
    let (a, tf, t) = (s.slow_velocity_mps, s.fast_duration_s(), s.period_s());
    match steady_regime(s, k_mps2) {
        Regime::StickBoth => 0.0,      // formula: v_d = (a T_s - b T_f)/T = 0
        _ => a - k_mps2 * tf * tf / t, // formula: v_d = a - k T_f^2 / T
    }
}

/// The same drift in dimensionless form: `v_d / a = max(0, 1 - y / (r (r + 1)))` with
/// `r = b / a` (speed ratio, > 1) and `y = k T_s / a` (friction number).
pub(crate) fn drift_ratio(speed_ratio: f64, friction_number: f64) -> f64 {
    let r = speed_ratio;
    (1.0 - friction_number / (r * (r + 1.0))).max(0.0) // formula: v_d/a = 1 - y/(r(r+1))
}

/// Friction impulse per unit mass and period (m/s) on a block that slips all period
/// with `-b < v < a`: friction `+k` for `T_s`, `-k` for `T_f`: `k (T_s - T_f)`, along the
/// slow stroke.
pub(crate) fn slipping_impulse_per_mass(s: &Sawtooth, k_mps2: f64) -> f64 {
    k_mps2 * (s.slow_duration_s - s.fast_duration_s()) // formula: J/m = k (T_s - T_f)
}

/// The steady block velocity (m/s) at time `t` (s) on the periodic orbit, time measured
/// from the start of a slow stroke.
pub fn steady_velocity_mps(s: &Sawtooth, k_mps2: f64, t: f64) -> f64 {
    let (a, b, ts, tf) = (
        s.slow_velocity_mps,
        s.fast_velocity_mps,
        s.slow_duration_s,
        s.fast_duration_s(),
    );
    let period = s.period_s();
    let tau = t - (t / period).floor() * period;
    let k = k_mps2;
    match steady_regime(s, k) {
        // formula: from -b at the slow stroke's start up to a (slope +k), then stuck at a;
        // from a at the fast stroke's start down to -b (slope -k), then stuck at -b
        Regime::StickBoth => {
            if tau < ts {
                (-b + k * tau).min(a)
            } else {
                (a - k * (tau - ts)).max(-b)
            }
        }
        // formula: from a - k T_f up to a (slope +k), stuck at a; then a - k (tau - T_s)
        _ => {
            if tau < ts {
                (a - k * tf + k * tau).min(a)
            } else {
                a - k * (tau - ts)
            }
        }
    }
}

/// Time (s) at which a block that starts at `v0_mps` (with `-b < v0 < a`) at the start of
/// a slow stroke (t = 0) first reaches the slow speed and sticks: after `n` whole
/// always-slipping periods (`v_n = v0 + n k (T_s - T_f)`) it reaches `a` at
/// `n T + (a - v_n)/k`, with `n` the first index where `v_n + k T_s >= a`. At a tie
/// (`v_n + k T_s = a` exactly: the block reaches `a` just as the slow stroke ends) the
/// lock time jumps by a period, and a simulation may land on either side.
pub fn lock_time_s(s: &Sawtooth, k_mps2: f64, v0_mps: f64) -> f64 {
    let (a, ts) = (s.slow_velocity_mps, s.slow_duration_s);
    let gain = slipping_impulse_per_mass(s, k_mps2);
    // formula: n = ceil((a - k T_s - v0) / (k (T_s - T_f))), at least 0
    let n = ((a - k_mps2 * ts - v0_mps) / gain).ceil().max(0.0);
    let vn = v0_mps + n * gain;
    n * s.period_s() + (a - vn) / k_mps2 // formula: t* = n T + (a - v_n)/k
}

/// The smallest `mu` for which a block starting at rest locks within `n_max` periods
/// (g in m/s^2): from `a - k T_s <= n_max k (T_s - T_f)`.
pub(crate) fn mu_min_for_lock(s: &Sawtooth, g_mps2: f64, n_max: f64) -> f64 {
    let (a, ts, tf) = (s.slow_velocity_mps, s.slow_duration_s, s.fast_duration_s());
    a / (g_mps2 * (ts + n_max * (ts - tf))) // formula: k >= a / (T_s + N (T_s - T_f))
}

/// Velocity (m/s) at the start of a slow stroke on the periodic orbit of the linear law
/// `v' = -c (v - v_p)` under a sawtooth: with `E_s = exp(-c T_s)`, `E_f = exp(-c T_f)`,
/// `v0 = (a E_f (1 - E_s) - b (1 - E_f)) / (1 - E_s E_f)`.
pub fn linear_periodic_start_velocity_mps(s: &Sawtooth, c_per_s: f64) -> f64 {
    let (a, b) = (s.slow_velocity_mps, s.fast_velocity_mps);
    let (xs, xf) = (-c_per_s * s.slow_duration_s, -c_per_s * s.fast_duration_s());
    let (ef, one_m_es, one_m_ef) = (xf.exp(), -xs.exp_m1(), -xf.exp_m1());
    let one_m_esef = -(xs + xf).exp_m1();
    (a * ef * one_m_es - b * one_m_ef) / one_m_esef // formula: periodic orbit of v' = -c (v - v_p)
}

/// A plate motion reflected through x = 0 (x, v, a negated): the mirrored drive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mirrored<P>(pub P);

impl<P: PlateMotion> PlateMotion for Mirrored<P> {
    fn x_m(&self, t: f64) -> f64 {
        -self.0.x_m(t)
    }
    fn vx_mps(&self, t: f64) -> f64 {
        -self.0.vx_mps(t)
    }
    fn ax_mps2(&self, t: f64) -> f64 {
        -self.0.ax_mps2(t)
    }
    fn z_m(&self, t: f64) -> f64 {
        self.0.z_m(t)
    }
    fn vz_mps(&self, t: f64) -> f64 {
        self.0.vz_mps(t)
    }
    fn az_mps2(&self, t: f64) -> f64 {
        self.0.az_mps2(t)
    }
    fn period_s(&self) -> f64 {
        self.0.period_s()
    }
    fn breakpoint_after(&self, t: f64) -> Option<f64> {
        self.0.breakpoint_after(t)
    }
    fn peak_rates(&self) -> Option<[f64; 4]> {
        self.0.peak_rates()
    }
}

#[cfg(test)]
mod tests;
