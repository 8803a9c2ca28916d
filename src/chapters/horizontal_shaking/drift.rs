//! The periodic steady drift of a block on a horizontally shaken plate, by shooting on
//! the one-period (Poincare) map of the exact hybrid simulation.

use crate::numerics::events::illinois;
use crate::physics::block::{simulate_block, BlockOptions, BlockParams, BlockRun};
use crate::physics::plate::{Axis, Harmonic, PlateMotion};
use std::f64::consts::TAU;

/// A horizontal-dither scene (per unit mass).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scene {
    /// Coulomb coefficient mu.
    pub mu: f64,
    /// Normal gravity g (m/s^2) (g cos(tilt) on a tilted book).
    pub g_mps2: f64,
    /// Plate amplitude delta_x (m).
    pub amplitude_m: f64,
    /// Plate frequency (Hz).
    pub frequency_hz: f64,
    /// Bias F/(mu m g) (dimensionless).
    pub bias: f64,
}

impl Scene {
    /// The plate `u_x = delta_x sin(omega t)`.
    pub fn plate(&self) -> Harmonic {
        Harmonic::sine(Axis::X, self.amplitude_m, self.frequency_hz)
    }
    /// Velocity amplitude V = delta_x omega (m/s).
    pub fn velocity_amplitude_mps(&self) -> f64 {
        self.amplitude_m * TAU * self.frequency_hz // formula: V = delta_x omega
    }
    /// Gamma_x = delta_x omega^2 / (mu g).
    pub fn gamma_x(&self) -> f64 {
        self.amplitude_m * (TAU * self.frequency_hz).powi(2) / (self.mu * self.g_mps2)
        // formula: Gamma_x = delta_x omega^2/(mu g)
    }
    /// The block parameters (Coulomb, bias b mu g).
    pub fn params(&self) -> BlockParams {
        BlockParams::coulomb(self.g_mps2, self.mu, self.bias * self.mu * self.g_mps2)
    }
    /// The same scene at another Gamma_x (amplitude changed, frequency kept).
    pub fn at_gamma_x(&self, gamma_x: f64) -> Scene {
        Scene {
            amplitude_m: gamma_x * self.mu * self.g_mps2 / (TAU * self.frequency_hz).powi(2),
            ..*self
        }
    }
    /// The averaged-law drift V sin(pi b / 2) (m/s).
    pub fn averaged_drift_mps(&self) -> f64 {
        crate::physics::friction::averaged_drift_velocity(self.bias, self.velocity_amplitude_mps())
    }
}

/// One period of the exact motion from absolute velocity `v0` at phase 0.
pub fn one_period(scene: &Scene, v0: f64, opts: &BlockOptions) -> BlockRun {
    let plate = scene.plate();
    let w0 = v0 - plate.vx_mps(0.0);
    let o = BlockOptions {
        start: (0.0, [0.0, w0, 0.0, 0.0]),
        transient_periods: 0,
        ..*opts
    };
    simulate_block(&scene.params(), &plate, plate.period_s(), &o)
}

/// The periodic steady state found by shooting.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Steady {
    /// Block velocity at phase 0 on the periodic orbit (m/s).
    pub v0_mps: f64,
    /// Mean velocity over the period (m/s).
    pub drift_mps: f64,
    /// Periods simulated to find it.
    pub periods: usize,
    /// Bound on the numerical error of `drift_mps` (m/s): see [`numerical_error_mps`].
    pub err_mps: f64,
}

/// The numerical error budget of a periodic drift found by shooting (m/s): the fixed
/// point is bracketed to `bracket` (m/s); each of the `switches` located switches of the
/// period sits up to one event tolerance `t_tol` (s) past the true one, moving the
/// velocity by at most `a_max t_tol`, and the closed forms round to 16 ulps of V per
/// segment: a map residual of at most `noise = switches (a_max t_tol + 16 eps V)`. The
/// map `v0 -> v(T) - v0` has slope `slope` (its secant over the first bracket, 1/s x T),
/// so the fixed point can sit `noise/slope` off, and the period's mean velocity carries
/// that plus the residual itself.
pub fn numerical_error_mps(
    bracket: f64,
    switches: f64,
    a_max: f64,
    t_tol: f64,
    vamp: f64,
    slope: f64,
) -> f64 {
    let noise = switches.max(1.0) * (a_max * t_tol + 16.0 * f64::EPSILON * vamp); // formula: n (a_max t_tol + 16 eps V)
    bracket + noise / slope.abs().max(f64::MIN_POSITIVE) + noise // formula: bracket + noise/|slope| + noise
}

/// The fixed point of the one-period map `v0 -> v(T)` (Illinois on `[-V, V]`, to
/// 1e-13 V), and the drift on it: the exact periodic steady state.
pub fn steady_drift(scene: &Scene) -> Steady {
    let opts = BlockOptions {
        record_events: false,
        ..BlockOptions::default()
    };
    let vamp = scene.velocity_amplitude_mps();
    let plate = scene.plate();
    let mut periods = 0;
    let mut map = |v: f64| {
        periods += 1;
        let r = one_period(scene, v, &opts);
        r.y_end[1] + plate.vx_mps(r.t_end_s) - v
    };
    // Bracket the fixed point around the averaged law's drift, widening by doubling
    // (the velocity changes by at most mu g (1 + b) T per period); the extremes +-V are
    // degenerate (the block touches the plate's extreme velocity) and are never used.
    let centre = scene.averaged_drift_mps();
    let mut d = scene.mu * scene.g_mps2 * (1.0 + scene.bias) * plate.period_s();
    let lim = vamp * (1.0 - 1e-9);
    let (mut a, mut b, mut fa, mut fb);
    loop {
        a = (centre - d).max(-lim);
        b = (centre + d).min(lim);
        fa = map(a);
        fb = map(b);
        if fa.signum() != fb.signum() || (a <= -lim && b >= lim) {
            break;
        }
        d *= 2.0;
    }
    let slope = (fb - fa) / (b - a); // formula: secant of the map over the bracket
    let v0 = if fb.abs() <= 1e-13 * vamp {
        b
    } else if fa.abs() <= 1e-13 * vamp {
        a
    } else if fa.signum() == fb.signum() {
        // No bracket: the block rides at the plate's extreme (it sticks through phase 0).
        lim
    } else {
        illinois(&mut map, a, b, fa, fb, 1e-13 * vamp).0
    };
    let r = one_period(scene, v0, &opts);
    periods += 1;
    let x = &r.period_x_m;
    let drift = (x[x.len() - 1].1 - x[0].1) / plate.period_s(); // formula: <v> = (x(T) - x(0))/T
    let c = r.total_counts;
    let switches =
        (c.stick_to_slip + c.slip_to_stick + c.reversals + c.takeoffs + c.landings) as f64;
    let a_max = scene.amplitude_m * (TAU * scene.frequency_hz).powi(2)
        + scene.mu * scene.g_mps2 * (1.0 + scene.bias.abs()); // formula: delta omega^2 + mu g (1 + b)
    let t_tol = crate::physics::block::time_tolerance_of_run(0.0, plate.period_s())
        .unwrap_or_else(|| crate::numerics::events::time_tolerance(plate.period_s()));
    // Residuals below 1e-13 V accepted at an end count as the bracket too.
    let err = numerical_error_mps(1e-13 * vamp, switches, a_max, t_tol, vamp, slope);
    Steady {
        v0_mps: v0,
        drift_mps: drift,
        periods,
        err_mps: err,
    }
}

/// Relative error of the averaged law (`|law - exact| / |exact|`; over V when the
/// exact drift vanishes, as at zero bias).
pub fn relative_error(scene: &Scene, exact: f64) -> f64 {
    let denom = if exact.abs() > 1e-12 * scene.velocity_amplitude_mps() {
        exact.abs()
    } else {
        scene.velocity_amplitude_mps()
    };
    (scene.averaged_drift_mps() - exact).abs() / denom
}

/// The Gamma_x above which the averaged law is within 1 %: bisection in log Gamma_x on
/// the exact relative error, bracketed by the last crossing of 1 % in `sweep`.
/// Returns `(gamma, bracket width)`.
pub fn gamma_for_1pct(scene: &Scene, sweep: &[(f64, f64, f64)], iterations: usize) -> (f64, f64) {
    let err = |g: f64| {
        let s = scene.at_gamma_x(g);
        relative_error(&s, steady_drift(&s).drift_mps) - 0.01
    };
    let last_above = sweep.iter().rposition(|&(_, e, _)| e > 0.01);
    let (mut a, mut b) = match last_above {
        Some(i) if i + 1 < sweep.len() => (sweep[i].0.ln(), sweep[i + 1].0.ln()),
        Some(_) => return (f64::INFINITY, 0.0),
        None => return (sweep[0].0, 0.0),
    };
    for _ in 0..iterations {
        let m = 0.5 * (a + b);
        if err(m.exp()) > 0.0 {
            a = m;
        } else {
            b = m;
        }
    }
    (b.exp(), b.exp() - a.exp())
}
