//! Unit tests of the chapter's internals (`evidence.rs`): the golden-section search and
//! the rod's locking angles against closed forms, and a snapshot of the quick report
//! (verdicts and results) with the locking angles at the default μ. The command line's
//! contract (results, the 25° and mirror cases, mass and length independence, one
//! bad-input test per flag): `tests/effective_mass.rs`.

use super::evidence::{golden_max, rod_lock_angles_closed_form, rod_ratio};
use super::{run, Args};
use crate::chapters::{default_args, Context};
use crate::report::fmt_num;
use serde_json::Value;

/// The chapter's quick report at `mu` (default angle), as `workbook effective-mass
/// --quick --json --no-figures --mu <mu>` prints it.
fn report(mu: Option<f64>) -> Value {
    let mut args: Args = default_args();
    if let Some(mu) = mu {
        args.mu = mu;
    }
    run(&args, &Context::headless(true))
        .expect("the quick run")
        .to_json()
}

#[test]
fn golden_section_and_rod_locking_angles_match_closed_forms() {
    // d/dq 3q/(4+q^2) = 0 at q = 2; the golden section works on the mass-matrix ratio.
    let best = golden_max(rod_ratio, 0.0, 1.5, 1e-12);
    assert!((best - 2f64.atan()).abs() < 1e-7, "{best}");
    // mu = 0.6: mu q^2 - 3q + 4 mu = 0 is q^2 - 5q + 4 = 0, roots q = 1 and q = 4
    // (3/5 = 12/20 = 0.6): the rod slips only for 45 deg < theta < atan 4 = 75.96 deg.
    let (a1, a2) = rod_lock_angles_closed_form(0.6).unwrap();
    assert!((a1 - std::f64::consts::FRAC_PI_4).abs() < 1e-14 && (a2 - 4f64.atan()).abs() < 1e-14);
    for a in [a1, a2] {
        assert!((rod_ratio(a) - 0.6).abs() < 1e-12, "{a}");
    }
    assert!(
        rod_lock_angles_closed_form(0.75).is_none() && rod_lock_angles_closed_form(0.0).is_none()
    );
}

#[test]
fn large_mu_and_the_summary_snapshot() {
    // mu >= 3/4 exceeds the rod's largest ratio: the claim says the rod jams at every
    // angle, and the document's sufficient bound holds.
    let r = report(Some(0.8));
    let c = r["claims"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["id"] == "self-locking-bound")
        .unwrap();
    assert_eq!(c["verdict"], "confirmed");
    assert!(c["statement"].as_str().unwrap().contains("every angle"));
    let r = report(None);
    let mut lines: String = r["claims"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| format!("{} {}\n", c["id"].as_str().unwrap(), c["verdict"].as_str().unwrap()))
        .collect();
    for (k, v) in r["results"].as_object().unwrap() {
        let s = v
            .as_f64()
            .map(|x| format!("{x:.4}"))
            .unwrap_or_else(|| v.to_string());
        lines += &format!("{k} = {s}\n");
    }
    lines += &format!(
        "rod lock angles mu=0.4: {:?}",
        rod_lock_angles_closed_form(0.4)
            .map(|(a, b)| (fmt_num(a.to_degrees()), fmt_num(b.to_degrees())))
    );
    insta::assert_snapshot!("effective_mass_summary", lines);
}
