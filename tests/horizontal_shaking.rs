//! Chapter `horizontal-shaking` (document section 3.1.1) through its command line: the
//! quick run's results and claims, the bad-input lines, a snapshot of the quick-mode
//! summary. The physics of its internals (the exact periodic drift against a long direct
//! run and the arcsin law, zero drift at zero bias, friction in the cone): its unit
//! tests, `src/chapters/horizontal_shaking/tests.rs`.

use crate::common;

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
