//! Unit tests of the chapter's internals (`evidence.rs`): the golden-section search and
//! the rod's locking angles against closed forms, and a snapshot of the quick report
//! (verdicts and results) with the locking angles at the default μ. The command line's
//! contract (results, the 25° and mirror cases, mass and length independence, one
//! bad-input test per flag): `tests/effective_mass.rs`.

use super::evidence::{golden_max, ratios_at, rod_lock_angles_closed_form, rod_ratio, Evidence};
use super::statements::PRINTED;
use super::{claims, run, Args, Document, MASS_KG};
use crate::chapters::{default_args, Context};
use crate::numerics::double_double::Dd;
use crate::report::{fmt_num, Falsifiable, Verdict};
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

/// The default scene's claims after `edit` of its evidence: (id, verdict) pairs.
fn verdicts_after(edit: impl Fn(&mut Evidence)) -> Vec<(String, Verdict)> {
    let (mut ev, mu) = <Document as Falsifiable>::quick_evidence();
    edit(&mut ev);
    claims::all(&PRINTED, &ev, mu)
        .into_iter()
        .map(|c| (c.id.clone(), c.verdict))
        .collect()
}

#[test]
fn a_relative_error_of_1e_9_in_a_computed_quantity_fails_its_claim() {
    // The rounding bounds are ~1e-14 relative at the default scene (45 degrees): a
    // computed quantity off by 1e-9 of itself (with the raw quantities its bound is
    // computed from left as they ran) must fail its claim, and move no claim of
    // another group (a_C feeds both of the last derivation steps).
    type Edit = (&'static str, fn(&mut Evidence));
    let cases: [Edit; 10] = [
        ("rod-mass-along", |e| e.stick[(0, 0)] *= 1.0 + 1e-9),
        ("rod-mass-across", |e| e.stick[(1, 1)] *= 1.0 + 1e-9),
        ("rod-mass-diagonal", |e| e.stick[(0, 1)] += 1e-9 * MASS_KG),
        ("ratio-point-mass", |e| e.at.point_mass *= 1.0 + 1e-9),
        ("ratio-uniform-rod", |e| e.at.rod *= 1.0 + 1e-9),
        ("ratio-rod-newton-euler", |e| e.at30.rod_ne *= 1.0 + 1e-9),
        ("ratio-point-mass-newton-euler", |e| e.at.point_mass_ne *= 1.0 + 1e-9),
        ("example-45-point-mass", |e| e.at45.point_mass *= 1.0 - 1e-9),
        ("example-45-rod-60-percent", |e| e.at45.rod *= 1.0 + 1e-9),
        ("derivation-a-c", |e| e.a_c *= 1.0 + 1e-9),
    ];
    let untouched = verdicts_after(|_| {});
    assert!(untouched.iter().all(|(_, v)| *v != Verdict::Failed), "{untouched:?}");
    for (id, edit) in cases {
        let after = verdicts_after(edit);
        for ((cid, v), (_, v0)) in after.iter().zip(&untouched) {
            if cid == id {
                assert_eq!(*v, Verdict::Failed, "{id} survived a 1e-9 error");
            } else if cid.split('-').take(2).ne(id.split('-').take(2)) {
                assert_eq!(v, v0, "{id}'s edit moved {cid}");
            }
        }
    }
}

#[test]
fn the_bounds_rest_on_the_computations_as_they_ran() {
    // The 5x5 system rebuilt in evidence.rs is, bit for bit, the one
    // impulse_for_velocity_change solves; the 2x2 inverse is nalgebra's adj(W)/det,
    // the formula rod_ratio_error's second bound counts the roundings of.
    for deg in [-89.9, -30.0, 0.0, 1e-6, 17.0, 45.0, 63.4, 89.999] {
        let r = ratios_at(f64::to_radians(deg));
        for s in [r.rod_solve, r.point_mass_solve] {
            assert_eq!(s.a.lu().solve(&s.b).unwrap(), s.x, "{deg}");
        }
        let (w, m) = (r.rod_inversion.mobility, r.rod_inversion.inverse);
        let det = w[(0, 0)] * w[(1, 1)] - w[(1, 0)] * w[(0, 1)];
        assert_eq!(m[(0, 1)], -w[(0, 1)] / det, "{deg}");
        assert_eq!(m[(1, 1)], w[(0, 0)] / det, "{deg}");
    }
}


/// |computed - exact| against the bound of each computed quantity and of each law's
/// evaluation, at θ (rad): (name, actual error, bound) rows.
fn errors_at(theta: f64) -> Vec<(&'static str, f64, f64)> {
    use super::rounding::*;
    let (s, c) = Dd::sin_cos(theta);
    let q = s.div(c);
    let rod = Dd::new(3.0).mul(q).div(Dd::new(4.0).add(q.mul(q))); // formula: 3q/(4 + q²)
    let r = ratios_at(theta);
    let ev = super::evidence::gather(theta);
    let qf = theta.tan();
    let law = 3.0 * qf / (4.0 + qf * qf);
    let diff = |a: f64, b: Dd| b.add(Dd::new(a).neg()).f().abs();
    let e_s = stick_error(mass_matrix_error(&ev.inversion), &ev.inversion);
    vec![
        ("mass along (kg)", (ev.stick[(0, 0)] - MASS_KG).abs(), e_s),
        ("mass across (kg)", (ev.stick[(1, 1)] - 0.25 * MASS_KG).abs(), e_s),
        ("mass off-diagonal (kg)", ev.stick[(0, 1)].abs(), e_s),
        ("point-mass ratio, mass matrix", diff(r.point_mass, q), point_mass_ratio_error(r.point_mass)),
        ("rod ratio, mass matrix", diff(r.rod, rod), rod_ratio_error(&r.rod_inversion)),
        ("rod ratio, 5x5 solve", diff(r.rod_ne, rod), newton_euler_ratio_error(&r.rod_solve)),
        ("point-mass ratio, 5x5 solve", diff(r.point_mass_ne, q), newton_euler_ratio_error(&r.point_mass_solve)),
        ("law q, evaluated", diff(qf, q), point_mass_law_error(qf)),
        ("law 3q/(4+q²), evaluated", diff(law, rod), rod_law_error(law)),
        ("a_C across (m/s²)", (ev.a_c.dot(&ev.normal) - 4.0 / MASS_KG).abs(), terms_error(20, 8.0 + 2.0 * ev.a_g.abs().sum() + ev.a_c.abs().sum())),
    ]
}

#[test]
fn every_bound_covers_the_actual_error_against_double_double() {
    // The exact values at the double θ in double-double arithmetic (Taylor series of
    // sin and cos, about 1e-30): each bound must hold at 400 angles over the flag's
    // range and at its ends; the smallest headroom (bound / actual) is printed.
    let mut angles: Vec<f64> = (-199..=199).map(|k| k as f64 * 0.4513).collect();
    angles.extend([1e-300, 1e-10, 45.0, 30.0, 89.9999999, -89.9999999, 63.43494882]);
    let mut worst: Vec<(&str, f64, f64)> = Vec::new();
    for deg in angles {
        for (name, actual, bound) in errors_at(deg.to_radians()) {
            assert!(actual <= bound, "{name} at {deg} deg: error {actual:e} > bound {bound:e}");
            match worst.iter_mut().find(|w| w.0 == name) {
                Some(w) if actual > 0.0 && bound / actual < w.2 => *w = (name, deg, bound / actual),
                Some(_) => {}
                None => worst.push((name, deg, if actual > 0.0 { bound / actual } else { f64::INFINITY })),
            }
        }
    }
    for (name, actual, bound) in errors_at(std::f64::consts::FRAC_PI_4) {
        eprintln!("45 deg: {name}: actual {actual:.2e}, bound {bound:.2e}");
    }
    for (name, deg, headroom) in worst {
        eprintln!("least headroom: {name}: {headroom:.3e} at {deg} deg");
    }
}
