//! The course's exercises: every answer the book states is computed here by the workbook
//! (the command line in-process, or the library) and compared with the text, so that the
//! book cannot drift from the code. The build exercises (the student writes a function)
//! are in `exercises/build.rs`.
//!
//! An answer is marked in the Markdown as `<b class="answer" data-answer="ID">VALUE</b>`.
//! A number printed with `d` decimals must equal the computed value rounded to `d`
//! decimals: the tolerance is half a unit of its last printed digit (plus 1e-12 for the
//! rounding of the comparison itself). A word (`yes`, `no`, a regime label) must match
//! exactly. Every marked answer has a check below and every check has its answer in the
//! book (`every_answer_is_checked_and_every_check_has_an_answer`).

mod common;

// The build exercises (exercise N.5 of each chapter): the student's code in
// tests/exercises/student.rs, the reference solutions in tests/exercises/solutions.rs,
// the checks in tests/exercises/build.rs.
#[path = "exercises/build.rs"]
mod build;
#[path = "exercises/solutions.rs"]
mod solutions;
#[path = "exercises/student.rs"]
mod student;

use std::collections::BTreeMap;

use locomotion_workbook::physics::locomotion::is_locomotion;

/// Every marked answer of `chapters/*.md`: id -> (chapter file, stated text).
fn stated_answers() -> BTreeMap<String, (String, String)> {
    let mut answers = BTreeMap::new();
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/chapters");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .expect("chapters/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    files.sort();
    let marker = "data-answer=\"";
    for path in files {
        let text = std::fs::read_to_string(&path).expect("chapter text");
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let mut rest = text.as_str();
        while let Some(i) = rest.find(marker) {
            rest = &rest[i + marker.len()..];
            let id_end = rest.find('"').expect("closing quote of data-answer");
            let id = rest[..id_end].to_string();
            let open = rest.find('>').expect("end of the answer tag") + 1;
            let close = rest[open..].find('<').expect("closing tag of the answer") + open;
            let value = rest[open..close].trim().to_string();
            let previous = answers.insert(id.clone(), (name.clone(), value));
            assert!(previous.is_none(), "answer id {id} appears twice");
            rest = &rest[close..];
        }
    }
    answers
}

fn stated(id: &str) -> String {
    let answers = stated_answers();
    let (_, value) = answers
        .get(id)
        .unwrap_or_else(|| panic!("the book states no answer {id}"));
    value.clone()
}

/// The stated number and half a unit of its last printed digit.
fn stated_number(id: &str) -> (f64, f64) {
    let text = stated(id);
    let x: f64 = text
        .parse()
        .unwrap_or_else(|_| panic!("answer {id} = {text:?} is not a number"));
    let decimals = text.split_once('.').map_or(0, |(_, d)| d.len());
    (x, 0.5 * 10f64.powi(-(decimals as i32)))
}

/// The book's number `id` is `computed` rounded to the printed digits.
fn check_number(id: &str, computed: f64) {
    let (x, half_unit) = stated_number(id);
    assert!(
        (x - computed).abs() <= half_unit + 1e-12,
        "exercise answer {id}: the book says {x}, the workbook computes {computed}"
    );
}

fn check_word(id: &str, computed: &str) {
    let text = stated(id);
    assert_eq!(text, computed, "exercise answer {id}");
}

fn yes_no(b: bool) -> &'static str {
    if b {
        "yes"
    } else {
        "no"
    }
}

/// `workbook <args> --quick --json --no-figures` (exit code 0), parsed.
fn run_json(args: &[&str]) -> serde_json::Value {
    let mut all: Vec<&str> = args.to_vec();
    all.extend(["--quick", "--json", "--no-figures"]);
    let (code, out, err) = common::run(&all);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(out.trim()).expect("one JSON object on stdout")
}

fn result(report: &serde_json::Value, key: &str) -> f64 {
    report["results"][key]
        .as_f64()
        .unwrap_or_else(|| panic!("result {key} is a number"))
}

/// Bisection for the switch of a monotone predicate on [lo, hi] (false at lo, true at hi).
fn switch_point(mut lo: f64, mut hi: f64, pred: impl Fn(f64) -> bool) -> f64 {
    assert!(!pred(lo) && pred(hi), "bracket");
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if pred(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

// ---------------------------------------------------------------- chapter 1

#[test]
fn chapter_1_locomotion_definition() {
    let triangle = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]];
    let diagonal = |s: f64| [s / 2f64.sqrt(), s / 2f64.sqrt()];
    let s = switch_point(0.0, 10.0, |s| is_locomotion(diagonal(s), &triangle));
    check_number("ex1.1-speed", s);

    let r = run_json(&[
        "locomotion-definition",
        "--medium-velocity",
        "1,0",
        "--medium-velocity",
        "0,3",
        "--object-velocity",
        "0.5,1.5",
    ]);
    check_word(
        "ex1.2-locomotion",
        yes_no(r["results"]["is_locomotion"] == true),
    );

    let r = run_json(&["locomotion-definition", "--object-velocity=-1,4"]);
    check_word(
        "ex1.3-locomotion",
        yes_no(r["results"]["is_locomotion"] == true),
    );

    let media = [[5.0, 0.0], [0.0, 0.0]];
    let v = switch_point(0.0, 10.0, |v| is_locomotion([v, 0.0], &media));
    check_number("ex1.4-speed", v);
}

// ---------------------------------------------------------------- chapter 2

fn rod_ratio_at(angle_deg: f64) -> f64 {
    let r = run_json(&["effective-mass", "--angle-deg", &angle_deg.to_string()]);
    result(&r, "ratio_uniform_rod")
}

#[test]
fn chapter_2_effective_mass() {
    check_number("ex2.1-ratio", rod_ratio_at(30.0));

    let r = run_json(&["effective-mass"]);
    let best = result(&r, "best_angle_uniform_rod_deg");
    check_number("ex2.2-angle-deg", best);
    check_number("ex2.2-ratio", rod_ratio_at(best));

    // The stated crossings, to their printed digits: the rod's ratio crosses mu = 0.4
    // between the stated angle minus and plus half a unit of its last digit.
    let mu = 0.4;
    let (first, half) = stated_number("ex2.3-first-deg");
    assert!(rod_ratio_at(first - half) <= mu && rod_ratio_at(first + half) > mu);
    let (second, half) = stated_number("ex2.3-second-deg");
    assert!(rod_ratio_at(second - half) > mu && rod_ratio_at(second + half) <= mu);

    let r = run_json(&["effective-mass", "--angle-deg", "25"]);
    check_number("ex2.4-point-mass", result(&r, "ratio_point_mass"));
    check_number("ex2.4-rod", result(&r, "ratio_uniform_rod"));
}

// ---------------------------------------------------------------- chapter 3

fn claim_number(report: &serde_json::Value, id: &str) -> f64 {
    report["claims"]
        .as_array()
        .expect("claims")
        .iter()
        .find(|c| c["id"] == id)
        .unwrap_or_else(|| panic!("claim {id}"))["computed"]
        .as_f64()
        .unwrap_or_else(|| panic!("claim {id} computes a number"))
}

#[test]
fn chapter_3_horizontal_shaking() {
    let r = run_json(&["horizontal-shaking"]);
    check_number("ex3.1-gamma-x", result(&r, "gamma_x"));
    check_number(
        "ex3.2-averaged-mps",
        result(&r, "drift_velocity_averaged_mps"),
    );
    check_number("ex3.2-exact-mps", result(&r, "drift_velocity_mps"));
    check_number(
        "ex3.3-slip-tilt-deg",
        claim_number(&r, "booktop-slip-tilt-arctan-mu"),
    );
    // The averaged law at the booktop tilt, from the library's averaged drift.
    let (mu, tilt) = (0.36, result(&r, "booktop_tilt_deg").to_radians());
    let v = result(&r, "velocity_amplitude_mps");
    let averaged =
        locomotion_workbook::physics::friction::averaged_drift_velocity(tilt.tan() / mu, v);
    check_number("ex3.3-averaged-mps", averaged);
    check_number("ex3.3-exact-mps", result(&r, "booktop_drift_mps"));

    let r = run_json(&["horizontal-shaking", "--frequency-hz", "10"]);
    check_number("ex3.4-error", result(&r, "averaged_law_relative_error"));
}

// ---------------------------------------------------------------- chapter 4

#[test]
fn chapter_4_vertical_shaking() {
    let r = run_json(&["vertical-shaking"]);
    check_number("ex4.1-phase-rad", result(&r, "takeoff_phase_rad"));
    // Gamma_n against the boundaries the chapter locates. In quick mode they are bisected
    // to brackets of 2^-12 (the first boundary, 1 + 2^-12, shows the bracket), so the
    // tolerance is half a printed unit plus that bracket.
    let boundaries: Vec<f64> = r["results"]["regime_boundaries_gamma"]
        .as_array()
        .expect("boundaries")
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let bracket = boundaries[0] - 1.0;
    assert!(bracket > 0.0 && bracket < 1e-3, "bracket {bracket}");
    for id in ["ex4.2-gamma-1", "ex4.2-gamma-2", "ex4.2-gamma-3"] {
        let (x, half) = stated_number(id);
        let nearest = boundaries
            .iter()
            .map(|b| (b - x).abs())
            .fold(f64::INFINITY, f64::min);
        assert!(
            nearest <= half + bracket,
            "{id}: {x}, nearest boundary off by {nearest}"
        );
    }
    let threshold = r["results"]["chladni"]["drift_threshold_gamma"]
        .as_f64()
        .expect("threshold");
    check_number("ex4.3-threshold", threshold);
    check_number("ex4.4-law-mps", result(&r, "mean_velocity_law_mps"));
    check_number("ex4.4-exact-mps", result(&r, "mean_velocity_mps"));
}

// ---------------------------------------------------------------- chapter 5

#[test]
fn chapter_5_asymmetric_shaking() {
    let r = run_json(&["asymmetric-shaking"]);
    check_number("ex5.1-drift-mps", result(&r, "drift_velocity_coulomb_mps"));
    check_number(
        "ex5.1-mirrored-mps",
        result(&r, "drift_velocity_mirrored_mps"),
    );
    check_number("ex5.2-lock-s", result(&r, "lock_time_s"));
    check_number("ex5.4-linear-mps", result(&r, "drift_velocity_linear_mps"));

    // The friction that stops the walk, to its printed digits: the regime changes between
    // the stated mu minus and plus half a unit of its last digit.
    let (mu, half) = stated_number("ex5.3-mu");
    let regime = |mu: f64| {
        let r = run_json(&["asymmetric-shaking", "--mu", &mu.to_string()]);
        r["results"]["regime"].as_str().expect("regime").to_string()
    };
    let both = stated("ex5.3-regime");
    assert_ne!(regime(mu - half), both);
    assert_eq!(regime(mu + half), both);
    let r = run_json(&["asymmetric-shaking", "--mu", "4.2"]);
    check_word("ex5.3-regime", r["results"]["regime"].as_str().unwrap());
    assert!(result(&r, "drift_velocity_coulomb_mps").abs() < 1e-12);
}

// ---------------------------------------------------------------- chapter 6

#[test]
fn chapter_6_stick_state_machine() {
    use locomotion_workbook::physics::stick::params::{authors_scene, jamming_scene};
    check_number("ex6.1-theta0-rad", authors_scene(10.0).theta0_rad);
    let scene = jamming_scene(9.81);
    check_number(
        "ex6.1-thetaf-rad",
        scene.static_angle().expect("a static angle"),
    );
    check_number("ex6.2-relax-ms", 1e3 / scene.relax_rate());
    check_number("ex6.3-edge-rad", scene.mu.atan());

    let r = run_json(&["stick-state-machine"]);
    let v = result(&r, "mean_velocity_mps");
    check_number("ex6.4-speed-mps", v);
    let f = r["params"]["frequency_hz"].as_f64().expect("frequency");
    check_number("ex6.4-step-mm", 1e3 * v / f);
    let r = run_json(&["stick-state-machine", "--scene", "authors"]);
    check_number("ex6.4-authors-mps", result(&r, "mean_velocity_mps"));
    let phases = &r["results"]["phase_fractions"];
    let sliding = phases["slide_left"].as_f64().unwrap() + phases["slide_right"].as_f64().unwrap();
    check_number("ex6.4-authors-sliding", sliding);
}

// ------------------------------------------- chapter 6, section 5: the limit cycle

/// The rimless wheel of exercise LC.1: spokes `2 alpha` apart, slope `psi`, spoke length
/// `l` (m). Its stride map `u -> u'` (`u` the squared rate at heel strike, rad^2/s^2) by
/// integrating the stance phase `phi'' = (g/l) sin(phi)` with RK4 from `phi = psi -
/// alpha` to `psi + alpha` (the last step cut to land on it), then the collision
/// `omega+ = cos(2 alpha) omega-`: a second method beside the chapter's energy map.
fn rimless_stride(u: f64, alpha: f64, psi: f64, l: f64) -> f64 {
    let g = 9.81;
    let f = |y: [f64; 2]| [y[1], g / l * y[0].sin()];
    let rk4 = |y: [f64; 2], h: f64| {
        let add = |a: [f64; 2], b: [f64; 2], c: f64| [a[0] + c * b[0], a[1] + c * b[1]];
        let k1 = f(y);
        let k2 = f(add(y, k1, h / 2.0));
        let k3 = f(add(y, k2, h / 2.0));
        let k4 = f(add(y, k3, h));
        [
            y[0] + h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]),
            y[1] + h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]),
        ]
    };
    let end = psi + alpha;
    let mut y = [psi - alpha, (2.0 * alpha).cos() * u.sqrt()];
    let h = 1e-4;
    loop {
        let next = rk4(y, h);
        if next[0] < end {
            y = next;
            continue;
        }
        // the step that crosses: bisect its length until it lands on phi = end
        let (mut lo, mut hi) = (0.0, h);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if rk4(y, mid)[0] < end {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return rk4(y, hi)[1].powi(2);
    }
}

#[test]
fn chapter_6_limit_cycle() {
    use locomotion_workbook::physics::stick::{jamming_scene, Mode, StickModel};
    use locomotion_workbook::scenes::stick::limit_cycle::{options, H_FINE, NEWTON_TOL};
    use locomotion_workbook::scenes::stick::poincare::{
        jacobian, moduli, multipliers, newton, Difference, Point,
    };

    // LC.1: iterate the integrated stride map to its fixed point, difference it there.
    let (alpha, psi, l) = (18f64.to_radians(), 0.1, 1.0);
    let stride = |u: f64| rimless_stride(u, alpha, psi, l);
    let u_star = (0..200).fold(1.0, |u, _| stride(u));
    let d = 1e-4;
    let lambda = (stride(u_star + d) - stride(u_star - d)) / (2.0 * d);
    check_number("exLC.1-multiplier", lambda);
    check_number("exLC.1-u-rad2ps2", u_star);
    check_number("exLC.1-steps", (100f64.ln() / (1.0 / lambda).ln()).ceil());

    // LC.2: from the table's fixed point, Newton, then central differences at 1e-5.
    let model = StickModel::new(jamming_scene(9.81));
    let opts = options();
    let table = Point {
        mode: Mode::SlideRight,
        s: vec![0.362760, -0.384174, 0.313461],
    };
    let (x, _) = newton(&model, &opts, &table, 1, (H_FINE, NEWTON_TOL, 20)).expect("a fixed point");
    let j = jacobian(&model, &opts, &x, 1, H_FINE, Difference::Central).expect("a Jacobian");
    let m = multipliers(&j);
    let modulus = moduli(&m)[0];
    check_number("exLC.2-modulus", modulus);
    check_number("exLC.2-arg-rad", m[0].1.atan2(m[0].0).abs());
    check_number("exLC.2-periods", 10f64.ln() / (1.0 / modulus).ln());
}

// ---------------------------------------------------------------- chapter 7

/// Largest fixed step (ms) for which one step of `method` on y' = -y/tau (tau = 1 ms)
/// does not amplify y: the stability limit, located by bisection on the workbook's own
/// integrator.
fn stability_limit_ms(method: locomotion_workbook::numerics::ode::Method) -> f64 {
    use locomotion_workbook::numerics::ode::{Integrator, StepControl};
    let tau = 1e-3;
    let amplifies = |h_ms: f64| {
        let h = h_ms * 1e-3;
        let mut integ = Integrator::new(method, StepControl::Fixed { h_s: h });
        let sys = |_t: f64, y: &[f64; 1]| [-y[0] / tau];
        let y = integ
            .integrate(&sys, 0.0, [1.0], h, |_| {})
            .expect("one step");
        y[0].abs() > 1.0
    };
    switch_point(0.5, 5.0, amplifies)
}

#[test]
fn chapter_7_speed_vs_accuracy() {
    use locomotion_workbook::numerics::ode::Method;
    check_number("ex7.1-euler-ms", stability_limit_ms(Method::Euler));
    check_number("ex7.1-rk4-ms", stability_limit_ms(Method::Rk4));

    let r = run_json(&["speed-vs-accuracy"]);
    // The Zeno time as the run reports it ("Outcome::Zeno at 1.355 s").
    let zeno = r["results"]["failures"]
        .as_array()
        .expect("failures")
        .iter()
        .filter_map(|f| f["symptom"].as_str())
        .find_map(|s| s.split("Outcome::Zeno at ").nth(1))
        .expect("a Zeno failure");
    let t: f64 = zeno
        .trim_end_matches(|c: char| !c.is_ascii_digit())
        .parse()
        .unwrap();
    check_number("ex7.2-zeno-s", t);
    let economy = &r["results"]["economy"];
    check_number(
        "ex7.3-flight-map",
        economy["flight_map_error"].as_f64().unwrap(),
    );
    check_number(
        "ex7.3-mu-eff-law",
        economy["mu_eff_law_error"].as_f64().unwrap(),
    );
    let evals = &r["results"]["stick_rhs_evals_at_1e-10"];
    let ratio = evals["dop853"].as_f64().unwrap() / evals["dopri5"].as_f64().unwrap();
    check_number("ex7.4-ratio", ratio);
}

// ---------------------------------------------------------------- chapter 8

#[test]
fn chapter_8_stick_with_inertia() {
    use locomotion_workbook::physics::stick::jamming_scene;
    use locomotion_workbook::physics::stick::run::{initial_state, simulate_stick, Recording};
    use locomotion_workbook::physics::stick::StickModel;
    use locomotion_workbook::physics::stick_inertia::painleve::mu_painleve;
    use locomotion_workbook::physics::stick_inertia::run::run_from_rest;
    use locomotion_workbook::physics::stick_inertia::{InertiaModel, InertiaParams, MassGeometry};
    use locomotion_workbook::scenes::stick::limit_cycle::options;

    let equal = MassGeometry::new(0.15, 1.0, 1.0).alpha();
    check_number("ex8.1-alpha", equal);
    // 8.2: the least mu_P by a golden-section search over theta (a second route to the
    // text's closed form 2 sqrt(1 + alpha)/alpha at tan theta = (1 + alpha)^(-1/2)).
    let (mut a, mut b) = (0.05, 1.5);
    let r = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..200 {
        let (c, d) = (b - r * (b - a), a + r * (b - a));
        if mu_painleve(c, equal) < mu_painleve(d, equal) {
            b = d;
        } else {
            a = c;
        }
    }
    let theta_min = 0.5 * (a + b);
    check_number("ex8.2-theta-rad", theta_min);
    check_number("ex8.2-mu", mu_painleve(theta_min, equal));
    // 8.3: the sticking impulse P = W^-1 (0, v) from the model's mobility, inverted here.
    let ratio_at_45 = |rod_kg: f64, tip_kg: f64| {
        let mut base = jamming_scene(9.81);
        base.mass_kg = tip_kg;
        let md = InertiaModel::new(InertiaParams {
            base,
            rod_mass_kg: rod_kg,
            restitution: 0.0,
        });
        let w = md.mobility(std::f64::consts::FRAC_PI_4);
        let det = w[0][0] * w[1][1] - w[0][1] * w[1][0];
        let (p_x, p_z) = (-w[0][1] / det, w[0][0] / det); // W^-1 (0, 1)
        p_x / p_z
    };
    check_number("ex8.3-uniform", ratio_at_45(1.0, 0.0));
    check_number("ex8.3-equal", ratio_at_45(1.0, 1.0));
    // 8.4: the uniform stick and chapter 6's massless one, 10 s from rest each.
    let mut base = jamming_scene(9.81);
    base.mass_kg = 0.0;
    let uniform = InertiaModel::new(InertiaParams {
        base,
        rod_mass_kg: 1.0,
        restitution: 0.0,
    });
    let v = run_from_rest(&uniform, 10.0, &options(), 0.0).mean_velocity_mps;
    let p6 = jamming_scene(9.81);
    let m6 = StickModel::new(p6);
    let y6 = initial_state(&m6, 0.0, p6.static_angle().expect("a static angle"));
    let r6 = simulate_stick(&m6, 0.0, y6, 10.0, &options(), Recording::default());
    check_number("ex8.4-speed-mps", v);
    check_number("ex8.4-ratio", v / r6.mean_velocity_mps);
}

// ---------------------------------------------------------------- the book as a whole

/// The ids checked by the tests above (kept in one list so that a new answer in the
/// book without a check, or a check whose answer left the book, fails).
const CHECKED: &[&str] = &[
    "ex1.1-speed",
    "ex1.2-locomotion",
    "ex1.3-locomotion",
    "ex1.4-speed",
    "ex2.1-ratio",
    "ex2.2-angle-deg",
    "ex2.2-ratio",
    "ex2.3-first-deg",
    "ex2.3-second-deg",
    "ex2.4-point-mass",
    "ex2.4-rod",
    "ex3.1-gamma-x",
    "ex3.2-averaged-mps",
    "ex3.2-exact-mps",
    "ex3.3-slip-tilt-deg",
    "ex3.3-averaged-mps",
    "ex3.3-exact-mps",
    "ex3.4-error",
    "ex4.1-phase-rad",
    "ex4.2-gamma-1",
    "ex4.2-gamma-2",
    "ex4.2-gamma-3",
    "ex4.3-threshold",
    "ex4.4-law-mps",
    "ex4.4-exact-mps",
    "ex5.1-drift-mps",
    "ex5.1-mirrored-mps",
    "ex5.2-lock-s",
    "ex5.3-mu",
    "ex5.3-regime",
    "ex5.4-linear-mps",
    "ex6.1-theta0-rad",
    "ex6.1-thetaf-rad",
    "ex6.2-relax-ms",
    "ex6.3-edge-rad",
    "ex6.4-speed-mps",
    "ex6.4-step-mm",
    "ex6.4-authors-mps",
    "ex6.4-authors-sliding",
    "ex7.1-euler-ms",
    "ex7.1-rk4-ms",
    "ex7.2-zeno-s",
    "ex7.3-flight-map",
    "ex7.3-mu-eff-law",
    "ex7.4-ratio",
    "exLC.1-multiplier",
    "exLC.1-u-rad2ps2",
    "exLC.1-steps",
    "exLC.2-modulus",
    "exLC.2-arg-rad",
    "exLC.2-periods",
    "ex8.1-alpha",
    "ex8.2-theta-rad",
    "ex8.2-mu",
    "ex8.3-uniform",
    "ex8.3-equal",
    "ex8.4-speed-mps",
    "ex8.4-ratio",
];

#[test]
fn every_answer_is_checked_and_every_check_has_an_answer() {
    let answers = stated_answers();
    for id in answers.keys() {
        assert!(
            CHECKED.contains(&id.as_str()),
            "answer {id} in the book has no check"
        );
    }
    for id in CHECKED {
        assert!(
            answers.contains_key(*id),
            "check {id} has no answer in the book"
        );
    }
}

/// The chapters written as lessons: all eight.
const LESSONS: &[u32] = &[1, 2, 3, 4, 5, 6, 7, 8];

/// Every chapter is a lesson: a question, three or four goals, the source, 3 to 5
/// exercises each with a collapsible solution.
#[test]
fn every_chapter_is_a_lesson() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/chapters");
    for &n in LESSONS {
        let path = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .find(|p| {
                p.file_name()
                    .unwrap()
                    .to_string_lossy()
                    .starts_with(&format!("{n:02}-"))
            })
            .unwrap_or_else(|| panic!("chapter {n}"));
        let text = std::fs::read_to_string(&path).unwrap();
        let name = path.display();
        assert!(text.contains("> **The question.**"), "{name}: question");
        assert!(text.contains("> **The source.**"), "{name}: source");
        let goals = text
            .lines()
            .skip_while(|l| !l.starts_with("> **After this chapter you can**"))
            .skip(1)
            .take_while(|l| l.starts_with(">"))
            .filter(|l| l.len() > 4 && l[2..].starts_with(|c: char| c.is_ascii_digit()))
            .count();
        assert!((3..=4).contains(&goals), "{name}: {goals} learning goals");
        // The chapter's problem set: its `## Exercises` section (a section may add a
        // subsection of its own exercises, such as chapter 6's on the limit cycle).
        let set = text
            .split("\n## Exercises")
            .nth(1)
            .and_then(|rest| rest.split("\n## ").next())
            .unwrap_or_else(|| panic!("{name}: no ## Exercises section"));
        let exercises = set.matches("\n**Exercise ").count();
        assert!(
            (3..=5).contains(&exercises),
            "{name}: {exercises} exercises"
        );
        let solutions = set.matches("<summary>Solution</summary>").count();
        assert_eq!(solutions, exercises, "{name}: a solution per exercise");
        assert!(
            set.contains(&format!("**Exercise {n}.5** (build)")),
            "{name}: exercise {n}.5 builds something"
        );
        // every exercise of the whole chapter has its folded solution
        assert_eq!(
            text.matches("\n**Exercise ").count(),
            text.matches("<summary>Solution</summary>").count(),
            "{name}: a solution per exercise"
        );
        let figures = text.matches("![").count();
        let captions = text.matches("*What to notice.*").count();
        assert_eq!(
            captions, figures,
            "{name}: a 'what to notice' caption per figure"
        );
    }
}

/// GitHub's math renderer breaks on `\,`, `\!`, `\{` and `\}` inside `$...$` (Markdown
/// eats the backslash first): the course uses `\thinspace`, `\negthinspace`, `\lbrace`
/// and `\rbrace` instead.
#[test]
fn math_reads_on_github() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/chapters");
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        for bad in ["\\,", "\\!", "\\{", "\\}"] {
            assert!(!text.contains(bad), "{}: contains {bad}", path.display());
        }
        // A tab is a TeX command that lost its backslash-t (`\tan` written in a Rust
        // string literal), and a space before a closing `$` stops it closing.
        assert!(!text.contains('\t'), "{}: contains a tab", path.display());
        // Likewise any other control character (`\a` of `\approx` becomes BEL, `\b` of
        // `\beta` a backspace, `\f` of `\frac` a form feed).
        if let Some(c) = text.chars().find(|c| c.is_control() && *c != '\n') {
            panic!("{}: contains control character {c:?}", path.display());
        }
        assert!(
            !text.contains("\\rvert $"),
            "{}: a space before a closing $",
            path.display()
        );
        // An inline formula must not run on into a quoted line: the `>` would become
        // part of the formula.
        let mut open = false;
        for (i, line) in text.lines().enumerate() {
            if open && line.trim_start().starts_with('>') {
                panic!(
                    "{}:{}: inline math continues into a quote",
                    path.display(),
                    i + 1
                );
            }
            let dollars = line
                .replace("\\$", "")
                .replace("$$", "")
                .matches('$')
                .count();
            if dollars % 2 == 1 {
                open = !open;
            }
        }
    }
}
