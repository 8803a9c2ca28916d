//! When does the landing after a flight kill the sideways motion? Section 3.1.2 says that
//! for a bias F < mu m g "there is motion during the flight phase that is extinguished at
//! the next collision". With Coulomb friction at the impact (e = 0) that needs the
//! tangential impulse, at most mu times the normal one, to stop the block's sideways
//! speed: it fails above a bias b* < 1. Derivation (per unit mass, plate
//! z_p = delta sin(omega t), block from rest at t = 0, Gamma < Gamma_1 so it rests
//! between flights; the chapter text has it in full):
//!
//! - in contact the normal force is n = g (1 - Gamma sin(omega t)); friction holds the
//!   bias b mu g while b <= 1 - Gamma sin(omega t): slip starts at
//!   sin(omega t_s) = (1 - b)/Gamma and lasts until the take-off at sin(omega t_0) = 1/Gamma,
//!   giving u_0 = mu g [(b - 1)(t_0 - t_s) + (Gamma/omega)(cos(omega t_s) - cos(omega t_0))];
//! - in flight the bias alone acts: u_1 = u_0 + b mu g t_f, t_f the ballistic flight;
//! - the landing sticks iff u_1 <= mu |v_n|, v_n = v_p(t_0) - g t_f - v_p(t_0 + t_f).
//!
//! mu cancels: b* is the root of u_0/mu + b g t_f = |v_n| (increasing in b).

use super::scene::{run, Model, Scene};
use crate::physics::block::{ballistic_flight_s, BlockMode, EventKind};
use crate::physics::plate::PlateMotion;

/// The sideways speed at landing minus mu |v_n|, over mu (m/s), at bias `b`: negative
/// while the landing sticks. `scene` sets Gamma, the frequency and g.
pub fn landing_margin(scene: &Scene, b: f64) -> f64 {
    let (g, gamma, om) = (scene.g_mps2, scene.gamma, scene.omega());
    let plate = scene.plate();
    let t0 = (1.0 / gamma).asin() / om; // formula: sin(omega t_0) = 1/Gamma
    let ts = ((1.0 - b) / gamma).asin() / om; // formula: sin(omega t_s) = (1 - b)/Gamma
    let u0 = g * ((b - 1.0) * (t0 - ts) + gamma / om * ((om * ts).cos() - (om * t0).cos())); // formula: u_0/mu
    let tf = ballistic_flight_s(&plate, t0, g, 1000);
    let vn = plate.vz_mps(t0) - g * tf - plate.vz_mps(t0 + tf); // formula: v_n = v_p(t_0) - g t_f - v_p(t_1)
    u0 + b * g * tf - vn.abs() // formula: u_1/mu - |v_n|
}

/// The closed form's b* (fraction of mu m g): bisection of [`landing_margin`] on [0, 1],
/// 60 halvings (to round-off); 1 when the landing sticks for every b < 1.
pub fn closed_form_bound(scene: &Scene) -> f64 {
    if landing_margin(scene, 1.0) <= 0.0 {
        return 1.0;
    }
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if landing_margin(scene, mid) <= 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Does the exact model's first landing after a take-off from rest stick, at bias `b`?
pub fn first_landing_sticks(scene: &Scene, b: f64) -> bool {
    let s = Scene { bias: b, ..*scene };
    let st = run(&s, Model::Exact, 0, 4);
    let mut after_takeoff = false;
    for e in &st.run.events {
        match e.kind {
            EventKind::Takeoff => after_takeoff = true,
            EventKind::Landing if after_takeoff => return e.to == BlockMode::Stick,
            _ => {}
        }
    }
    false
}

/// The exact model's b*: bisection of [`first_landing_sticks`] on [0, 1], `iters`
/// halvings; returns `(b*, half-width of the last bracket)`.
pub fn located_bound(scene: &Scene, iters: usize) -> (f64, f64) {
    if first_landing_sticks(scene, 1.0 - 1e-9) {
        return (1.0, 0.0);
    }
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..iters {
        let mid = 0.5 * (lo + hi);
        if first_landing_sticks(scene, mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (0.5 * (lo + hi), 0.5 * (hi - lo))
}
