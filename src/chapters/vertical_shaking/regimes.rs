//! Regimes of the completely inelastic (e = 0) bouncing block: a classifier of the
//! long-time motion, a sweep over Gamma, and boundaries located by bisection.

use super::scene::{run, Model, Scene, Stats};
use crate::sweep::par_map;

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
    /// Short label: `rest P1/1T`, `no-rest P2/2T`, `aperiodic`, `no flight`.
    pub fn label(&self) -> String {
        match (self.flights_per_cycle, self.periods_per_cycle) {
            (0, 0) => "no flight".into(),
            (0, _) => "aperiodic".into(),
            (p, m) => format!("{} P{p}/{m}T", if self.rests { "rest" } else { "no-rest" }),
        }
    }
}

/// Flight durations are compared to 1e-7 of a period: the closed-form flights are
/// exact to ~1e-13, and a converged cycle repeats to round-off.
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
    /// Mean flight time (s).
    pub mean_flight_s: f64,
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
            mean_flight_s: st.mean_flight_s(),
        }
    })
}

/// A located regime boundary.
#[derive(Debug, Clone, PartialEq)]
pub struct Boundary {
    /// Gamma of the boundary (midpoint of the final bracket, transient `n`).
    pub gamma: f64,
    /// Regime below and above.
    pub below: String,
    /// Regime above.
    pub above: String,
    /// Final bracket width of the bisection.
    pub bracket: f64,
    /// The same boundary located after a transient four times longer.
    pub gamma_long: f64,
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
    par_map(&pairs, "regime boundaries", |&(a, b, left, right)| {
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
            below: left.label(),
            above: right.label(),
            bracket: width,
            gamma_long: g_long,
        }
    })
}
