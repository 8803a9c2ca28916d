//! Model economy: cheap averaged laws for the block's drift against the exact
//! (event-driven, closed-form) simulation.
//!
//! - The document's law (section 3.1.2): `mu_eff = v_ave / v_z`, i.e.
//!   `v_ave = (F / m g) v_z = b delta omega`: flights of `2 v_z / g` filling the time.
//! - The flight map: the block leaves the plate when `z_p'' = -g`, i.e. at the phase
//!   `phi = asin(1/Gamma)`, with the plate's velocity `delta omega cos(phi)`; it flies
//!   ballistically until it meets the plate again after `t_f` (one scalar root), and
//!   the landing is a sticking collision. It then waits for the next takeoff, `n` whole
//!   periods after the last one: `v_ave = b g t_f^2 / (2 n T)`. It neglects the slip
//!   before takeoff (while `mu N < F`) and holds for periodic (period-n) bouncing.

use super::block_scene::BlockScene;
use crate::numerics::events::{illinois, time_tolerance};
use crate::physics::plate::PlateMotion;

/// One row of the economy sweep: (Gamma, exact drift m/s, flight-map drift m/s if any,
/// mu_eff-law drift m/s).
pub type SweepRow = (f64, f64, Option<f64>, f64);

/// The document's averaged law: `v_ave = b v_z`, `v_z = delta omega` (m/s).
pub fn law_drift(scene: &BlockScene) -> f64 {
    scene.bias * scene.plate.peak_velocity_mps() // formula: v_ave = F v_z / (m g)
}

/// The flight-map drift (m/s), or `None` when there is no flight (Gamma <= 1), no
/// landing within 20 periods, or the landing falls where the plate pulls away
/// faster than g (then the motion is not a sticking period-n orbit).
pub fn flight_map_drift(scene: &BlockScene) -> Option<f64> {
    let p = &scene.plate;
    let (w, g) = (p.omega_rad_s, scene.g);
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
    if scene.g + p.az_mps2(t_land) <= 0.0 {
        return None; // landing in the takeoff window: not a sticking orbit
    }
    let n = (t_f / period).ceil(); // next takeoff: the first takeoff phase after landing
    Some(scene.bias * g * t_f * t_f / (2.0 * n * period)) // formula: v_ave = (F/m) t_f^2 / (2 n T)
}
