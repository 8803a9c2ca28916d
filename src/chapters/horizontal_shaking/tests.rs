//! Unit tests of the chapter's internals (the exact periodic drift, `drift.rs`): the
//! shooting on the one-period map against a second method (a long direct run) and
//! against the averaged arcsin law in its limit Gamma_x >> 1; zero drift at zero bias
//! (symmetry); the friction force inside the Coulomb cone and never doing positive work
//! at every step. The command line's contract and the quick summary's snapshot:
//! `tests/horizontal_shaking.rs`.

use super::drift::{steady_drift, Scene};
use crate::physics::block::{
    simulate_block, simulate_block_observed, BlockOptions, ContactInvariants,
};
use crate::physics::plate::PlateMotion;

fn scene(gamma_x: f64, bias: f64) -> Scene {
    Scene {
        mu: 0.36,
        g_mps2: 9.81,
        amplitude_m: 0.02,
        frequency_hz: 5.0,
        bias,
    }
    .at_gamma_x(gamma_x)
}

#[test]
fn arcsin_law_holds_at_large_gamma_x() {
    // Averaged law v = V sin(pi b / 2): exact when the block's velocity fluctuation
    // (~ mu g / omega, i.e. V / Gamma_x) vanishes; the error is second order in
    // 1/Gamma_x, so at Gamma_x = 200 it is ~1e-4 or less: 10/Gamma_x^2 = 2.5e-4 bounds it.
    for b in [0.1, 0.5, 0.8] {
        let s = scene(200.0, b);
        let exact = steady_drift(&s).drift_mps;
        let law = s.averaged_drift_mps();
        assert!(
            ((exact - law) / law).abs() < 10.0 / (200.0f64 * 200.0),
            "b {b}: {exact} vs {law}"
        );
    }
}

#[test]
fn shooting_agrees_with_a_long_direct_run() {
    // Second method: 400 periods from rest, averaging the last 100. The velocity relaxes
    // on tau ~ pi V/(2 mu g) = 1.4 periods at Gamma_x = 3, so 300 periods of transient
    // leave exp(-200) of it; both are closed-form runs: agreement to 1e-9 of V.
    let s = scene(3.0, 0.4);
    let plate = s.plate();
    let long = simulate_block(
        &s.params(),
        &plate,
        400.0 * plate.period_s(),
        &BlockOptions {
            transient_periods: 300,
            ..BlockOptions::default()
        },
    );
    let shoot = steady_drift(&s).drift_mps;
    assert!(
        (long.mean_velocity_mps - shoot).abs() < 1e-9 * s.velocity_amplitude_mps(),
        "{} vs {shoot}",
        long.mean_velocity_mps
    );
}

#[test]
fn zero_bias_gives_zero_drift() {
    // The scene is symmetric under x -> -x with a half-period shift: no drift at b = 0
    // (to round-off of the closed forms, 1e-12 of V).
    for gx in [0.5, 2.0, 20.0] {
        let s = scene(gx, 0.0);
        assert!(
            steady_drift(&s).drift_mps.abs() < 1e-12 * s.velocity_amplitude_mps(),
            "Gamma_x {gx}"
        );
    }
}

#[test]
fn friction_stays_in_the_cone_and_dissipates_at_every_step() {
    // Gamma_x = 1.5 with bias 0.3: stick, slip both ways. Set-valued Coulomb friction:
    // |f| <= mu n (stick: the needed force, checked inside the cone up to the event
    // location's round-off, 1e-9 m/s^2), and f w <= 0 (friction never feeds energy into
    // the relative motion; w = 0 exactly while sticking).
    let s = scene(1.5, 0.3);
    let plate = s.plate();
    let mut c = ContactInvariants::new(s.params(), &plate);
    let run = simulate_block_observed(
        &s.params(),
        &plate,
        30.0 * plate.period_s(),
        &BlockOptions::default(),
        &mut c,
    );
    assert!(c.stick_segments > 0 && run.total_counts.stick_to_slip > 0);
    assert!(c.worst_cone_mps2 <= 1e-9, "{}", c.worst_cone_mps2);
    assert!(
        c.worst_power_w_per_kg <= 1e-12,
        "{}",
        c.worst_power_w_per_kg
    );
}
