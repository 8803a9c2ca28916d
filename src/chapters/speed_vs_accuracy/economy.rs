//! Model economy: cheap averaged laws for the block's drift against the exact
//! (event-driven, closed-form) simulation.
//!
//! - The document's law (section 3.1.2): `mu_eff = v_ave / v_z`, i.e.
//!   `v_ave = (F / m g) v_z = b mu delta omega` (`b = F/(mu m g)`): flights of `2 v_z / g`
//!   filling the time.
//! - The flight map: the block leaves the plate when `z_p'' = -g`, i.e. at the phase
//!   `phi = asin(1/Gamma)`, with the plate's velocity `delta omega cos(phi)`; it flies
//!   ballistically until it meets the plate again after `t_f` (one scalar root), and
//!   the landing is a sticking collision. It then waits for the next takeoff, `n` whole
//!   periods after the last one: `v_ave = b mu g t_f^2 / (2 n T)`. It neglects the slip
//!   before takeoff (while `mu N < F`) and holds for periodic (period-n) bouncing.

use super::block_scene::BlockScene;
use crate::numerics::events::{illinois, time_tolerance};
use crate::physics::plate::PlateMotion;

/// One row of the economy sweep: (Gamma, exact drift m/s, flight-map drift m/s if any,
/// mu_eff-law drift m/s).
pub type SweepRow = (f64, f64, Option<f64>, f64);

/// The document's averaged law: `v_ave = (F/(m g)) v_z = b mu v_z`, `v_z = delta omega` (m/s).
pub fn law_drift(scene: &BlockScene) -> f64 {
    scene.params.bias_mps2 / scene.g() * scene.plate.peak_velocity_mps() // formula: v_ave = F v_z / (m g) = b mu v_z
}

/// The flight-map drift (m/s), or `None` when there is no flight (Gamma <= 1), no
/// landing within 20 periods, or the landing falls where the plate pulls away
/// faster than g (then the motion is not a sticking period-n orbit).
pub fn flight_map_drift(scene: &BlockScene) -> Option<f64> {
    let (t_f, n) = flight_map_flight(scene)?;
    let f_over_m = scene.params.bias_mps2; // F/m = b mu g (BlockScene::new)
    Some(f_over_m * t_f * t_f / (2.0 * n * scene.period_s())) // formula: v_ave = (F/m) t_f^2 / (2 n T)
}

/// The flight map's relative error predicted from the slip before take-off it
/// neglects, `-b/(omega t_f sqrt(Gamma^2 - 1))` (chapter 7's text, section 5), or
/// `None` without a sticking orbit. The block slips from Gamma sin(phi) = 1 - b to the
/// take-off at Gamma sin(phi) = 1, a phase span b/sqrt(Gamma^2 - 1) to first order, over
/// which the friction deficit mu g (Gamma sin(phi) - (1 - b)) grows linearly: it leaves
/// with u = mu g b^2/(2 omega sqrt(Gamma^2 - 1)), carried through the flight (u t_f)
/// and removed at the sticking landing, against the map's b mu g t_f^2/2 per orbit.
pub fn flight_map_predicted_rel(scene: &BlockScene) -> Option<f64> {
    let (t_f, _) = flight_map_flight(scene)?;
    let p = &scene.plate;
    let gamma = p.peak_acceleration_mps2() / scene.g();
    let b = scene.bias; // b = F/(mu m g)
    Some(-b / (p.omega_rad_s * t_f * (gamma * gamma - 1.0).sqrt())) // formula: -b/(omega t_f sqrt(Gamma^2 - 1))
}

/// The flight map's flight: (t_f (s), n periods per orbit), or `None` as for
/// [`flight_map_drift`].
fn flight_map_flight(scene: &BlockScene) -> Option<(f64, f64)> {
    let p = &scene.plate;
    let (w, g) = (p.omega_rad_s, scene.g());
    let gamma = p.peak_acceleration_mps2() / g;
    if gamma <= 1.0 {
        return None;
    }
    let period = scene.period_s();
    let t_to = (1.0 / gamma).asin() / w; // formula: sin(omega t) = 1/Gamma, z_p'' = -g
    let (z0, v0) = (p.z_m(t_to), p.vz_mps(t_to));
    // gap(s) = z0 + v0 s - g s^2/2 - z_p(t_to + s): zero to third order at s = 0.
    let gap = |s: f64| z0 + v0 * s - 0.5 * g * s * s - p.z_m(t_to + s);
    let dt = period / 200.0;
    let mut a = dt;
    let ga = gap(a);
    if ga <= 0.0 {
        return None;
    }
    let mut b = a;
    let mut gb = ga;
    while gb > 0.0 {
        a = b;
        b += dt;
        gb = gap(b);
        if b > 20.0 * period {
            return None;
        }
    }
    let (t_f, _) = illinois(gap, a, b, gap(a), gb, time_tolerance(b));
    let t_land = t_to + t_f;
    if scene.g() + p.az_mps2(t_land) <= 0.0 {
        return None; // landing in the takeoff window: not a sticking orbit
    }
    let n = (t_f / period).ceil(); // next takeoff: the first takeoff phase after landing
    Some((t_f, n))
}

/// Horizontal dither (section 3.1.1): a block on a plate `x_p = delta sin(omega t)`
/// pushed by `F = b mu m g` (`bias` is `b = F/(mu m g)`). Returns `(exact drift, arcsin law, viscous law)` (m/s) for the
/// dither acceleration ratio `k_ratio = delta omega^2 / (mu g)`:
/// - exact: the workbook's block model (closed forms) over `cycles` periods after a
///   transient of `max(20, 2 k_ratio)` periods, started at the arcsin law's velocity;
/// - arcsin law (cycle average with the block's own velocity fluctuation neglected):
///   `V sin(pi b / 2)`, `V = delta omega`;
/// - effective viscous law (its small-velocity linearisation): `F / c` with
///   `c = 2 mu g / (pi V)`, i.e. `pi b V / 2`.
pub fn horizontal_drifts(
    frequency_hz: f64,
    k_ratio: f64,
    mu: f64,
    bias: f64,
    g: f64,
    cycles: u32,
) -> (f64, f64, f64) {
    use crate::physics::block::{simulate_block, BlockOptions, BlockParams};
    use crate::physics::friction::{averaged_drift_velocity, effective_viscous_coefficient};
    use crate::physics::plate::{Axis, Harmonic};
    let omega = std::f64::consts::TAU * frequency_hz;
    let delta = k_ratio * mu * g / (omega * omega); // formula: delta omega^2 = K mu g
    let plate = Harmonic::sine(Axis::X, delta, frequency_hz);
    let v_amp = plate.peak_velocity_mps();
    let arcsin = averaged_drift_velocity(bias, v_amp); // formula: V sin(pi b / 2)
    let f_over_m = bias * mu * g; // formula: F/m = b mu g
    let viscous = f_over_m / effective_viscous_coefficient(v_amp, mu, g); // formula: v = F/(m c)
    let transient = (2.0 * k_ratio).max(20.0).ceil() as usize;
    let opts = BlockOptions {
        transient_periods: transient,
        record_events: false,
        start: (0.0, [0.0, arcsin - v_amp, 0.0, 0.0]),
        ..BlockOptions::default()
    };
    let params = BlockParams::coulomb(g, mu, f_over_m);
    let t_end = (transient + cycles as usize) as f64 * plate.period_s();
    let run = simulate_block(&params, &plate, t_end, &opts);
    (run.mean_velocity_mps, arcsin, viscous)
}

/// One row of the horizontal sweep: (K = delta omega^2/(mu g), exact, arcsin law,
/// viscous law), drifts in m/s.
pub type HorizontalRow = (f64, f64, f64, f64);

/// The horizontal-dither economy: the sweep of K and the limit the viscous law names.
#[derive(Debug, Clone, PartialEq)]
pub struct Horizontal {
    /// The sweep.
    pub rows: Vec<HorizontalRow>,
    /// At K = 100, b = 0.05: (exact drift, viscous law) (m/s).
    pub limit: (f64, f64),
}

/// The limit the viscous law is checked in, whatever the flags: (K = delta omega^2/(mu
/// g), b).
pub const HORIZONTAL_LIMIT: (f64, f64) = (100.0, 0.05);

/// Sweeps K (4 values in `quick` mode, else 25, from 1.5 to 100) and runs the limit the
/// viscous law names: K = 100 and b = 0.05, whatever the flags.
pub fn gather_horizontal(
    frequency_hz: f64,
    mu: f64,
    bias: f64,
    g: f64,
    quick: bool,
) -> Horizontal {
    let ks = crate::sweep::logspace(1.5, 100.0, if quick { 4 } else { 25 });
    let rows: Vec<HorizontalRow> = ks
        .iter()
        .map(|&k| {
            let (e, a, v) = horizontal_drifts(frequency_hz, k, mu, bias, g, 20);
            (k, e, a, v)
        })
        .collect();
    let (k_lim, b_lim) = HORIZONTAL_LIMIT;
    let (e_lim, _, v_lim) = horizontal_drifts(frequency_hz, k_lim, mu, b_lim, g, 20);
    Horizontal {
        rows,
        limit: (e_lim, v_lim),
    }
}

impl Horizontal {
    /// The result `economy_horizontal`: from which K on each law is within 1 %, and the
    /// viscous law's error at the largest K.
    pub fn json(&self) -> serde_json::Value {
        let rows = &self.rows;
        let rel = |m: f64, e: f64| ((m - e) / e).abs();
        // The smallest K of the sweep from which on every larger K is within 1 %.
        let from = |f: &dyn Fn(&HorizontalRow) -> f64| -> serde_json::Value {
            let mut k_from = None;
            for row in rows.iter().rev() {
                if rel(f(row), row.1) < 0.01 {
                    k_from = Some(row.0);
                } else {
                    break;
                }
            }
            k_from.map_or(serde_json::json!("never"), serde_json::Value::from)
        };
        let last = rows
            .last()
            .copied()
            .unwrap_or((f64::NAN, f64::NAN, f64::NAN, f64::NAN));
        serde_json::json!({
            "arcsin_law_within_1pct_from_k": from(&|row| row.2),
            "viscous_law_within_1pct_from_k": from(&|row| row.3),
            "viscous_law_error_at_largest_k": rel(last.3, last.1),
        })
    }
}
