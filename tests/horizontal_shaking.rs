//! Chapter `horizontal-shaking` (document section 3.1.1): a block on a plate shaken
//! horizontally, u_x = delta_x sin(omega t), with Coulomb friction and a bias force.
//!
//! Physics checked: the exact periodic drift (shooting on the one-period map) against a
//! second method (a long direct run) and against the averaged arcsin law in its limit
//! Gamma_x >> 1; zero drift at zero bias (symmetry); the friction force inside the
//! Coulomb cone and never doing positive work at every step; the CLI contract and the
//! bad-input lines; a snapshot of the quick-mode summary.

use crate::common;

use locomotion_workbook::chapters::horizontal_shaking::drift::{steady_drift, Scene};
use locomotion_workbook::physics::block::{
    simulate_block, simulate_block_observed, BlockOptions, ContactInvariants,
};
use locomotion_workbook::physics::plate::PlateMotion;

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

#[test]
fn quick_json_has_every_result_and_no_failed_claim() {
    let v = common::quick_json("horizontal-shaking");
    common::assert_numbers_and_no_failed_claim(
        &v,
        &[
            "velocity_amplitude_mps",
            "gamma_x",
            "drift_velocity_mps",
            "drift_velocity_averaged_mps",
            "averaged_law_relative_error",
            "gamma_x_for_1pct",
        ],
    );
    // V = delta_x omega = 0.02 * 2 pi * 5 (closed form)
    assert!(
        (v["results"]["velocity_amplitude_mps"].as_f64().unwrap()
            - 0.02 * std::f64::consts::TAU * 5.0)
            .abs()
            < 1e-12
    );
}

#[test]
fn bad_inputs_give_one_line_naming_the_flag() {
    for (flag, bad) in [
        ("--mu", "NaN"),
        ("--mu", "-0.3"),
        ("--mu", "2"),
        ("--amplitude-m", "-0.01"),
        ("--amplitude-m", "0"),
        ("--frequency-hz", "0"),
        ("--frequency-hz", "inf"),
        ("--bias", "1"),
        ("--bias", "-0.1"),
        ("--bias", "NaN"),
    ] {
        common::assert_bad_input(
            &["horizontal-shaking", flag, bad, "--quick", "--no-figures"],
            flag,
        );
    }
}

#[test]
fn quick_summary_snapshot() {
    // Numbers to 3 significant digits: the drift is exact to ~1e-12 and the 1 % point is
    // bracketed to 2e-4 relative in quick mode.
    let (v, mut s) = common::quick_summary(
        "horizontal-shaking",
        &[
            "gamma_x",
            "drift_velocity_mps",
            "drift_velocity_averaged_mps",
            "averaged_law_relative_error",
        ],
    );
    s.push_str(&format!(
        "gamma_x_for_1pct = {:.1}\n",
        v["results"]["gamma_x_for_1pct"].as_f64().unwrap()
    ));
    insta::assert_snapshot!(s);
}
