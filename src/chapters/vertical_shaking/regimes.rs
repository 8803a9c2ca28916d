//! Regimes of the completely inelastic (e = 0) bouncing block: a classifier of the
//! long-time motion, a sweep over Gamma, and boundaries located by bisection.

use super::scene::{run, Model, Scene, Stats};
use crate::sweep::par_map;
use std::f64::consts::PI;

/// Gamma_n = sqrt(1 + (n pi)^2): a flight from rest lasts exactly n periods.
pub fn gamma_n(n: f64) -> f64 {
    (1.0 + (n * PI).powi(2)).sqrt() // formula: Gamma_n = sqrt(1 + (n pi)^2)
}

/// The character of the long-time motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Regime {
    /// Some landing of the cycle is followed by a contact phase (the block rests on the
    /// plate and takes off again at sin(phase) = 1/Gamma).
    pub rests: bool,
    /// Flights per cycle of the periodic motion (0: no period up to 16 found).
    pub flights_per_cycle: usize,
    /// Drive periods per cycle.
    pub periods_per_cycle: usize,
}

impl Regime {
    /// The touch-and-go orbit (never at rest) of `flights` flights in `periods` periods.
    pub const fn touch_and_go(flights: usize, periods: usize) -> Self {
        Regime {
            rests: false,
            flights_per_cycle: flights,
            periods_per_cycle: periods,
        }
    }

    /// A periodic motion that rests between some flights (`rest P../..T`).
    pub fn rests_between_flights(&self) -> bool {
        self.flights_per_cycle > 0 && self.rests
    }

    /// A periodic motion that never rests (`no-rest P../..T`).
    pub fn never_rests(&self) -> bool {
        self.flights_per_cycle > 0 && !self.rests
    }

    /// Flights but no period up to 16 (`aperiodic`).
    pub fn aperiodic(&self) -> bool {
        self.flights_per_cycle == 0 && self.periods_per_cycle > 0
    }

    /// Short label: `rest P1/1T`, `no-rest P2/2T`, `aperiodic`, `no flight`.
    pub fn label(&self) -> String {
        match (self.flights_per_cycle, self.periods_per_cycle) {
            (0, 0) => "no flight".into(),
            (0, _) => "aperiodic".into(),
            (p, m) => format!("{} P{p}/{m}T", if self.rests { "rest" } else { "no-rest" }),
        }
    }
}

/// Flight durations (in periods) are compared to 1e-7 of a period, a classification
/// threshold between two scales of the run. Below: the rounding of a flight. Its two
/// event times are located to 256 ulps of t (the event budget of chapter 7's
/// `budget.rs`), so a flight in periods is good to 2 x 256 ε t/T; the longest runs
/// classified are the boundaries' check with a 4x transient, 4 x 100 + 120 = 520
/// periods (full; quick 4 x 60 + 60 = 300): 5.9e-11 (3.4e-11), three decades under
/// 1e-7, and a converged cycle repeats to that. Above: the difference between the
/// distinct flights of a cycle, which a period-p label must see. It is of order one
/// (a rest against a flight, n against n + 1 periods) except next to a period doubling,
/// where the two flights of a P2 orbit part as sqrt(Gamma - Gamma_pd): there the
/// threshold moves the label by (1e-7)^2 in Gamma, under the bisection's bracket
/// (7.6e-7), and the chapter locates the doublings by the multiplier instead
/// (`period_doubling_gamma`).
const TOL: f64 = 1e-7;

/// Classifies a run: the smallest p <= 16 such that the last flights repeat with
/// period p, whether the cycle contains a rest, and its length in drive periods.
pub fn classify(st: &Stats) -> Regime {
    let f = &st.flights;
    if f.is_empty() {
        return Regime {
            rests: false,
            flights_per_cycle: 0,
            periods_per_cycle: 0,
        };
    }
    let n = f.len();
    let rests = st.rests.iter().rev().take(34).any(|&r| r);
    for p in 1..=16usize {
        let span = (2 * p).max(8);
        if n < span + p {
            break;
        }
        if (n - span..n).all(|i| (f[i] - f[i - p]).abs() < TOL) {
            let flight: f64 = f[n - p..].iter().sum();
            let cycle = flight / (1.0 - st.run.contact_fraction); // formula: cycle = flights / flight fraction
            return Regime {
                rests,
                flights_per_cycle: p,
                periods_per_cycle: cycle.round() as usize,
            };
        }
    }
    Regime {
        rests,
        flights_per_cycle: 0,
        periods_per_cycle: 1,
    }
}

/// One point of the Gamma sweep.
#[derive(Debug, Clone)]
pub struct SweepPoint {
    /// Gamma.
    pub gamma: f64,
    /// Regime.
    pub regime: Regime,
    /// The last flights (in periods), for the bifurcation diagram.
    pub flights: Vec<f64>,
    /// Exact mean velocity (m/s).
    pub v_mps: f64,
    /// Contact fraction.
    pub contact_fraction: f64,
}

/// Classifies the exact model at `gamma` after `transient` periods.
pub fn regime_at(scene: &Scene, gamma: f64, transient: usize, observe: usize) -> Regime {
    classify(&run(
        &scene.at_gamma(gamma),
        Model::Exact,
        transient,
        observe,
    ))
}

/// The sweep over `gammas`.
pub fn sweep(scene: &Scene, gammas: &[f64], transient: usize, observe: usize) -> Vec<SweepPoint> {
    par_map(gammas, "regimes", |&g| {
        let st = run(&scene.at_gamma(g), Model::Exact, transient, observe);
        SweepPoint {
            gamma: g,
            regime: classify(&st),
            flights: st.flights.iter().rev().take(32).copied().collect(),
            v_mps: st.cycle_velocity_mps,
            contact_fraction: st.run.contact_fraction,
        }
    })
}

/// A located regime boundary.
#[derive(Debug, Clone, PartialEq)]
pub struct Boundary {
    /// Gamma of the boundary (midpoint of the final bracket, transient `n`).
    pub gamma: f64,
    /// Regime below.
    pub below: Regime,
    /// Regime above.
    pub above: Regime,
    /// Final bracket width of the bisection.
    pub bracket: f64,
    /// The same boundary located after a transient four times longer.
    pub gamma_long: f64,
    /// How it was located: `classifier` (bisection on the regime label) or
    /// `multiplier` (bisection on the one-flight map's multiplier reaching -1).
    pub method: &'static str,
    /// For a period doubling: the classifier's band (last P1, first P2) it must lie in.
    pub band: Option<(f64, f64)>,
}

impl Boundary {
    /// Accuracy estimate: bracket width plus the shift under a 4x longer transient.
    pub fn accuracy(&self) -> f64 {
        self.bracket + (self.gamma - self.gamma_long).abs()
    }
}

fn bisect(
    scene: &Scene,
    a: f64,
    b: f64,
    left: Regime,
    transient: usize,
    observe: usize,
    iters: usize,
) -> (f64, f64) {
    let (mut a, mut b) = (a, b);
    for _ in 0..iters {
        let m = 0.5 * (a + b);
        if regime_at(scene, m, transient, observe) == left {
            a = m;
        } else {
            b = m;
        }
    }
    (0.5 * (a + b), b - a)
}

/// Every label change between neighbours of the sweep, located by bisection on the
/// classifier (`iters` halvings) with `transient` and with `4 transient` periods.
pub fn boundaries(
    scene: &Scene,
    pts: &[SweepPoint],
    transient: usize,
    observe: usize,
    iters: usize,
) -> Vec<Boundary> {
    let pairs: Vec<(f64, f64, Regime, Regime)> = pts
        .windows(2)
        .filter(|w| w[0].regime != w[1].regime)
        .map(|w| (w[0].gamma, w[1].gamma, w[0].regime, w[1].regime))
        .collect();
    let found = par_map(&pairs, "regime boundaries", |&(a, b, left, right)| {
        let (g, width) = bisect(scene, a, b, left, transient, observe, iters);
        // Check the final bracket after a 4x longer transient; where the label moves
        // (slow convergence near a period doubling) locate the boundary again with it.
        let (lo, hi) = (g - 0.5 * width, g + 0.5 * width);
        let long = 4 * transient;
        let g_long = if regime_at(scene, lo, long, observe) == left
            && regime_at(scene, hi, long, observe) != left
        {
            g
        } else {
            bisect(scene, a, b, left, long, observe, iters.min(12)).0
        };
        Boundary {
            gamma: g,
            below: left,
            above: right,
            bracket: width,
            gamma_long: g_long,
            method: "classifier",
            band: None,
        }
    });
    merge_period_doublings(found)
}

/// Replaces each period doubling of an n-period touch-and-go orbit (`no-rest P1/nT` to
/// `no-rest P2/2nT`, possibly through a thin `aperiodic` band that is only the slow
/// convergence near the bifurcation) by the Gamma where the one-flight map's multiplier
/// reaches -1; the classifier's band is kept as a check.
fn merge_period_doublings(found: Vec<Boundary>) -> Vec<Boundary> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < found.len() {
        let b = &found[i];
        // a touch-and-go orbit of one flight in n periods, period-doubling to two in 2n
        let n = (b.below.never_rests() && b.below.flights_per_cycle == 1)
            .then_some(b.below.periods_per_cycle);
        if let Some(n) = n {
            let p2 = Regime::touch_and_go(2, 2 * n);
            let j = if b.above == p2 {
                Some(i)
            } else if b.above.aperiodic() && found.get(i + 1).is_some_and(|c| c.above == p2) {
                Some(i + 1)
            } else {
                None
            };
            if let Some(j) = j {
                let pd = period_doubling_gamma(n as f64);
                if pd.is_finite() {
                    let lo = b.gamma - b.accuracy();
                    let hi = found[j].gamma + found[j].accuracy();
                    // Accuracy: the multiplier's central difference is good to ~1e-9 and
                    // it falls ~5 per unit Gamma there, so Gamma to ~1e-9 (bisection 1e-12).
                    out.push(Boundary {
                        gamma: pd,
                        below: b.below,
                        above: p2,
                        bracket: 1e-9,
                        gamma_long: pd,
                        method: "multiplier",
                        band: Some((lo, hi)),
                    });
                    i = j + 1;
                    continue;
                }
            }
        }
        out.push(b.clone());
        i += 1;
    }
    out
}

/// The one-flight map of a touch-and-go block, in units g = omega = 1 (plate
/// `z = Gamma sin(phi)`): leaving at phase `phi` with the plate's velocity, the phase of
/// the next landing minus `2 pi n`. Landing is the first root of the gap
/// `Gamma sin(phi) + Gamma cos(phi) s - s^2/2 - Gamma sin(phi + s)` after `s = 0`,
/// found by a scan (step 1e-3) and bisection to 1e-15.
fn landing_phase(gamma: f64, phi: f64, n: f64) -> f64 {
    let gap =
        |s: f64| gamma * phi.sin() + gamma * phi.cos() * s - 0.5 * s * s - gamma * (phi + s).sin(); // formula: ballistic gap
    let ds = 1e-3;
    let mut a = ds;
    while gap(a + ds) > 0.0 && a < 1e3 {
        a += ds;
    }
    let mut b = a + ds;
    for _ in 0..80 {
        let m = 0.5 * (a + b);
        if gap(m) > 0.0 {
            a = m;
        } else {
            b = m;
        }
    }
    phi + b - std::f64::consts::TAU * n
}

/// Multiplier `dF/dphi` of the one-flight map at the touch-and-go orbit whose flights
/// last exactly `n` periods (`cos(phi*) = n pi / Gamma`, Gamma > Gamma_n), by central
/// differences (step 1e-5: truncation ~1e-10, round-off ~1e-10).
pub fn touch_and_go_multiplier(gamma: f64, n: f64) -> f64 {
    let phi = (n * std::f64::consts::PI / gamma).acos(); // formula: Gamma cos(phi*) = n pi
    let h = 1e-5;
    (landing_phase(gamma, phi + h, n) - landing_phase(gamma, phi - h, n)) / (2.0 * h)
}

/// Gamma at which the n-period touch-and-go orbit period-doubles (multiplier -1),
/// by bisection on `[Gamma_n (1 + 1e-9), Gamma_n + 2]` to 1e-12.
pub fn period_doubling_gamma(n: f64) -> f64 {
    let gn = (1.0 + (n * std::f64::consts::PI).powi(2)).sqrt();
    let (mut a, mut b) = (gn * (1.0 + 1e-9), gn + 2.0);
    if touch_and_go_multiplier(a, n) < -1.0 || touch_and_go_multiplier(b, n) > -1.0 {
        return f64::NAN;
    }
    while b - a > 1e-12 {
        let m = 0.5 * (a + b);
        if touch_and_go_multiplier(m, n) > -1.0 {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn touch_and_go_orbit_is_superstable_at_gamma_n_and_doubles_before_gamma_n_plus_1() {
        // At Gamma_n the n-period flight lands exactly at the take-off phase where the
        // plate's acceleration is -g: the multiplier starts at 0 and falls through -1.
        for n in [1.0, 2.0] {
            let gn = (1.0 + (n * std::f64::consts::PI).powi(2)).sqrt();
            let m = touch_and_go_multiplier(gn * (1.0 + 1e-6), n);
            assert!(m < 0.0 && m > -1e-3, "n {n}: {m}");
            let pd = period_doubling_gamma(n);
            assert!(pd > gn && pd < gn + 1.0, "n {n}: {pd}");
            assert!((touch_and_go_multiplier(pd, n) + 1.0).abs() < 1e-6);
        }
    }
}
