//! Unit tests of the chapter's internals (the scene's runs and the regime classifier):
//! the take-off phase asin(1/Gamma) (closed form); the first flight's duration against a
//! root of the ballistic gap equation found here by bisection; the flight that lasts
//! exactly one period at Gamma_1 = sqrt(1 + pi^2) (closed form) as the boundary between
//! resting and never resting; friction inside the cone and impacts that never create
//! relative kinetic energy (invariants). The command line's contract and the quick
//! summary's snapshot: `tests/vertical_shaking.rs`.

use super::regimes::regime_at;
use super::scene::{run as run_scene, Model, Scene};
use crate::physics::block::{
    ballistic_flight_s, simulate_block_observed, BlockOptions, ContactInvariants,
};
use crate::physics::plate::PlateMotion;
use std::f64::consts::PI;

/// The chapter's test scene: 30 Hz, μ = 0.4, bias 0.1, g = 9.81 m/s², at `gamma`.
pub(super) fn scene(gamma: f64) -> Scene {
    Scene {
        gamma,
        frequency_hz: 30.0,
        mu: 0.4,
        bias: 0.1,
        g_mps2: 9.81,
    }
}

#[test]
fn takeoff_phase_is_asin_one_over_gamma() {
    // The normal force g + a_zp = g (1 - Gamma sin(omega t)) vanishes at sin = 1/Gamma;
    // every take-off from rest happens there (events located to ~1e-15 s: 1e-9 rad).
    for gamma in [1.1, 2.0, 3.0, 5.0, 8.0] {
        let st = run_scene(&scene(gamma), Model::Exact, 5, 10);
        assert!(!st.rest_takeoff_phases_rad.is_empty(), "Gamma {gamma}");
        for &p in &st.rest_takeoff_phases_rad {
            assert!(
                (p - (1.0 / gamma).asin()).abs() < 1e-9,
                "Gamma {gamma}: {p}"
            );
        }
    }
}

#[test]
fn first_flight_lands_on_the_root_of_the_ballistic_gap() {
    // From take-off at phase phi0 with the plate's velocity, the gap
    // z_p(t0) + v0 s - g s^2 / 2 - z_p(t0 + s) first returns to zero at the landing.
    // Root found by ballistic_flight_s, a scan and bisection (independent of the driver);
    // agreement to 1e-12 s (both sides resolve the root to round-off).
    for gamma in [1.5, 2.5, 3.2] {
        let s = scene(gamma);
        let plate = s.plate();
        let st = run_scene(&s, Model::Exact, 0, 2);
        let t0 = (1.0 / gamma).asin() / s.omega();
        let b = ballistic_flight_s(&plate, t0, s.g_mps2, 10_000);
        let flight = st.flights[0] * plate.period_s();
        assert!((flight - b).abs() < 1e-12, "Gamma {gamma}: {flight} vs {b}");
    }
}

#[test]
fn one_period_flight_boundary_is_sqrt_one_plus_pi_squared() {
    // Closed form: a flight from rest lasts exactly one period when Gamma cos(phi0) = pi
    // and Gamma sin(phi0) = 1, i.e. Gamma_1 = sqrt(1 + pi^2). Below it the block rests
    // between flights, above it the landing falls where the plate pulls away faster
    // than g and the block never rests. 1e-6 either side is far outside the classifier's
    // resolution (flights compared to 1e-7 of a period).
    let g1 = (1.0 + PI * PI).sqrt();
    let s = scene(2.0);
    let below = regime_at(&s, g1 * (1.0 - 1e-6), 60, 60);
    let above = regime_at(&s, g1 * (1.0 + 1e-6), 60, 60);
    assert_eq!(below.label(), "rest P1/1T");
    assert_eq!(above.label(), "no-rest P1/1T");
}

#[test]
fn friction_in_the_cone_and_impacts_never_create_energy() {
    // Gamma = 4.2 (rests every other flight, touch-and-go landings) with bias 0.5:
    // |f| <= mu n at every sampled instant (round-off 1e-9 m/s^2); an impact only removes
    // relative kinetic energy (e = 0, tangential impulse opposing the slip).
    let s = Scene {
        bias: 0.5,
        ..scene(4.2)
    };
    let plate = s.plate();
    let p = s.params(Model::Exact);
    let mut inv = ContactInvariants::new(p, &plate);
    let run = simulate_block_observed(
        &p,
        &plate,
        40.0 * plate.period_s(),
        &BlockOptions::default(),
        &mut inv,
    );
    assert!(run.total_counts.landings > 20);
    assert!(inv.worst_cone_mps2 <= 1e-9, "{}", inv.worst_cone_mps2);
    assert!(
        inv.worst_impact_gain_m2ps2 <= 1e-15,
        "{}",
        inv.worst_impact_gain_m2ps2
    );
}
