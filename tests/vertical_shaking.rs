//! Chapter `vertical-shaking` (document section 3.1.2) through its command line: the
//! quick run's results and claims, the bad-input lines, and a snapshot of the quick-mode
//! summary. The physics of its internals (take-off phase, the first flight against a
//! root of the ballistic gap, the one-period boundary Gamma_1 = sqrt(1 + pi^2), friction
//! in the cone and impacts that never create energy): its unit tests,
//! `src/chapters/vertical_shaking/tests.rs`.

use crate::common;

use serde_json::Value;

fn run(args: &[&str]) -> (i32, String, String) {
    common::run_with(&["vertical-shaking"], args)
}

/// The report's `regime_boundaries_gamma` (dimensionless), as numbers.
fn boundaries(report: &Value) -> Vec<f64> {
    report["results"]["regime_boundaries_gamma"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

#[test]
fn quick_json_has_every_result_and_no_failed_claim() {
    let v = common::quick_json("vertical-shaking");
    common::assert_numbers_and_no_failed_claim(
        &v,
        &[
            "takeoff_phase_rad",
            "flight_time_over_period",
            "contact_fraction",
            "mean_velocity_mps",
            "mu_eff_from_force",
            "mu_eff_from_drift",
        ],
    );
    let b = boundaries(&v);
    assert!(b.windows(2).all(|w| w[0] < w[1]), "sorted: {b:?}");
}

#[test]
fn bad_inputs_give_one_line_naming_the_flag() {
    for (flag, bad) in [
        ("--gamma", "1"),
        ("--gamma", "0.5"),
        ("--gamma", "NaN"),
        ("--bias", "1"),
        ("--bias", "-0.5"),
        ("--mu", "-1"),
        ("--mu", "NaN"),
        ("--frequency-hz", "-30"),
        ("--frequency-hz", "0"),
    ] {
        common::assert_bad_input(
            &["vertical-shaking", flag, bad, "--quick", "--no-figures"],
            flag,
        );
    }
    // Gamma <= 1 says why.
    let (_, _, err) = run(&["--gamma", "0.9", "--quick", "--no-figures"]);
    assert!(err.contains("never throws the block"), "{err}");
}

#[test]
fn quick_summary_snapshot() {
    // Exact closed-form runs: 4 significant digits are far above the round-off.
    let (v, mut s) = common::quick_summary(
        "vertical-shaking",
        &[
            "takeoff_phase_rad",
            "flight_time_over_period",
            "contact_fraction",
            "mean_velocity_mps",
            "mu_eff_from_drift",
        ],
    );
    s.push_str(&format!(
        "regime = {}\n",
        v["results"]["regime_at_gamma"].as_str().unwrap()
    ));
    // Boundaries to 2 decimals: quick-mode brackets are 5e-4 wide at most, but the
    // period-doubling ones move by ~1e-2 with the transient, so only the count and
    // the three Gamma_n-type ones are pinned.
    let b = boundaries(&v);
    s.push_str(&format!("boundaries = {}\n", b.len()));
    for g in [3.297, 6.362, 9.478] {
        let near = b
            .iter()
            .copied()
            .min_by(|a, c| (a - g).abs().total_cmp(&(c - g).abs()))
            .unwrap();
        s.push_str(&format!("near {g}: {near:.3}\n"));
    }
    insta::assert_snapshot!(s);
}
