//! Tests of event location: Illinois, the certified search's bounds and the double-root
//! cases the end-point sign test misses.

use super::*;

#[test]
fn directions() {
    assert!(Direction::Rising.fires(-1.0, 1.0));
    assert!(Direction::Rising.fires(-1.0, 0.0));
    assert!(!Direction::Rising.fires(1.0, -1.0));
    assert!(!Direction::Rising.fires(0.0, 1.0));
    assert!(Direction::Falling.fires(1.0, -1.0));
    assert!(Direction::Either.fires(1.0, -1.0) && Direction::Either.fires(-1.0, 1.0));
}

#[test]
fn illinois_finds_roots_to_machine_precision() {
    // cos(t) = 0 at pi/2 (rising from negative side of -cos)
    let f = |t: f64| -t.cos();
    let (t, n) = illinois(f, 0.0, 3.0, f(0.0), f(3.0), time_tolerance(2.0));
    assert!((t - std::f64::consts::FRAC_PI_2).abs() < 1e-15, "{t}");
    assert!(t >= std::f64::consts::FRAC_PI_2 - 1e-15);
    assert!(n < 20, "{n} evaluations");
    // a steep, lopsided function where plain regula falsi stalls
    let g = |t: f64| t.powi(9) - 1e-9;
    let (t, n) = illinois(g, 0.0, 1.0, g(0.0), g(1.0), time_tolerance(1.0));
    let root = 1e-1f64;
    assert!((t - root).abs() < 1e-15, "{t}");
    assert!(n < 60, "{n} evaluations");
}

#[test]
fn returned_time_is_past_the_crossing() {
    let f = |t: f64| t - 0.3;
    let (t, _) = illinois(f, 0.0, 1.0, f(0.0), f(1.0), 1e-15);
    assert!(f(t) >= 0.0);
}

/// A guard `(t - c)^2 - w^2` with its rate: positive at both ends of [0, 1], below
/// zero on (c - w, c + w).
fn dip(c: f64, w: f64) -> impl Fn(f64) -> (f64, f64) {
    move |t: f64| ((t - c) * (t - c) - w * w, 2.0 * (t - c))
}

fn point(f: &impl Fn(f64) -> (f64, f64), t: f64) -> GuardPoint {
    let (g, rate) = f(t);
    GuardPoint { t, g, rate }
}

#[test]
fn a_double_root_inside_one_step_is_found() {
    // The end-point sign test sees + and + and misses the dip; the certified search
    // brackets it, for a dip in the middle, near an end, and very narrow.
    for (c, w) in [(0.5, 0.01), (0.93, 0.004), (0.2, 1e-6), (0.61, 3e-7)] {
        let f = dip(c, w);
        let (a, b) = (point(&f, 0.0), point(&f, 1.0));
        assert!(!Direction::Falling.fires(a.g, b.g));
        let mut st = CertifyStats::default();
        let found = hidden_crossing(&f, a, b, time_tolerance(1.0), &mut st)
            .unwrap_or_else(|| panic!("dip at {c} of half-width {w} missed"));
        let [(tl, gl), (tm, gm), _] = found;
        assert!(Direction::Falling.fires(gl, gm), "{found:?}");
        let (te, _) = illinois(|t| f(t).0, tl, tm, gl, gm, time_tolerance(1.0));
        assert!((te - (c - w)).abs() < 1e-12, "located {te}, root {}", c - w);
        assert_eq!(st.hidden_found, 1);
        assert!(st.samples <= 64, "{st:?}");
    }
    // A dip whose depth (1e-18) is below the guard's round-off floor (64 ulps of its
    // values, ~5e-15) cannot be told from a tangency: the search gives up within its
    // sample budget and counts the piece as unresolved.
    let f = dip(0.61, 1e-9);
    let mut st = CertifyStats::default();
    let found = hidden_crossing(&f, point(&f, 0.0), point(&f, 1.0), 1e-15, &mut st);
    assert!(found.is_none() && st.unresolved == 1, "{st:?}");
    assert!(st.samples <= MAX_SAMPLES, "{st:?}");
}

#[test]
fn a_guard_that_clears_zero_is_certified_cheaply() {
    // Dips that stay above zero: no bracket; when the margin is wide, no sample.
    let mut st = CertifyStats::default();
    for (c, w) in [(0.5, -0.3), (0.2, -0.05), (0.8, -0.02)] {
        let f = move |t: f64| ((t - c) * (t - c) + w * w, 2.0 * (t - c));
        let (a, b) = (point(&f, 0.0), point(&f, 1.0));
        assert_eq!(hidden_crossing(f, a, b, 1e-15, &mut st), None);
    }
    assert!(st.samples <= 8, "{st:?}");
    // A guard that starts a hair above zero and moves away (a slide entered from
    // rest): certified by the end-weighted allowance, without sampling.
    let f = |t: f64| (1e-12 + 0.045 * t * t, 0.09 * t);
    let mut st = CertifyStats::default();
    assert_eq!(
        hidden_crossing(f, point(&f, 0.0), point(&f, 1.0), 1e-15, &mut st),
        None
    );
    assert_eq!(st.samples, 0);
}

#[test]
fn the_cheap_test_and_the_least_value_are_sound() {
    // Over a grid of cubic Hermite models: whenever the cheap test or the exact
    // least value certifies, the model minus its allowance is positive at 2001
    // points; and the least value agrees with the sampled minimum.
    let vals = [-1.0, -0.1, 0.0, 1e-9, 0.05, 0.3, 1.0];
    let mut certified_cases = 0;
    for &g0 in &vals {
        for &g1 in &vals {
            for &d0 in &vals {
                for &d1 in &vals {
                    let a = GuardPoint {
                        t: 0.0,
                        g: g0,
                        rate: -3.0 * d0,
                    };
                    let b = GuardPoint {
                        t: 1.0,
                        g: g1,
                        rate: 2.0 * d1,
                    };
                    let c = hermite_coefficients(&a, &b);
                    let allow = 0.25 * c[3].abs();
                    let sampled = (0..=2000)
                        .map(|k| {
                            let u = k as f64 / 2000.0;
                            let w = u * (1.0 - u);
                            c[0] + u * (c[1] + u * (c[2] + u * c[3])) - 16.0 * allow * w * w
                        })
                        .fold(f64::INFINITY, f64::min);
                    if g0 > 0.0
                        && g1 > 0.0
                        && (clearly_one_sided(&a, &b) || certified(&c, 1.0, allow))
                    {
                        certified_cases += 1;
                        assert!(sampled > -1e-15, "{a:?} {b:?} {sampled}");
                    }
                    let w = 16.0 * allow;
                    let q = [c[0], c[1], c[2] - w, c[3] + 2.0 * w, -w];
                    let least = least_of_quartic(&q);
                    assert!(least <= sampled + 1e-12, "{least} > {sampled}");
                    assert!(least >= sampled - 1e-6, "{least} << {sampled}");
                }
            }
        }
    }
    assert!(certified_cases > 100, "{certified_cases}");
}

#[test]
fn a_secant_on_a_converged_end_closes_the_bracket() {
    // The right end sits on the crossing (g = 0 there, as a guard evaluated at a located
    // event can be), so the secant's root is that end. The bracket must close from just
    // inside it (one or two evaluations), not by bisection from the far end (about 50
    // halvings of [0, 0.3]: 49 evaluations before this was fixed).
    let r = 0.3;
    let f = |t: f64| 1e3 * (t - r);
    let b = r;
    let (t, n) = illinois(f, 0.0, b, f(0.0), f(b), time_tolerance(1.0));
    assert!((t - r).abs() <= time_tolerance(1.0), "{t}");
    assert!(n <= 3, "{n} evaluations");
}

#[test]
fn hermite_root_is_exact_for_a_cubic_guard() {
    // g(t) = (t - 0.3)(t + 1)(t - 2): a cubic, so its Hermite model on [0, 1] is itself.
    let g = |t: f64| (t - 0.3) * (t + 1.0) * (t - 2.0);
    let dg = |t: f64| (t + 1.0) * (t - 2.0) + (t - 0.3) * (2.0 * t - 1.0);
    let p = |t: f64| GuardPoint {
        t,
        g: g(t),
        rate: dg(t),
    };
    let (t, rate) = hermite_root(&p(0.0), &p(1.0)).expect("a root inside");
    assert!((t - 0.3).abs() < 1e-14, "{t}");
    assert!((rate - dg(0.3)).abs() < 1e-12 * dg(0.3).abs(), "{rate}");
    // no sign change of the model inside: no root
    let q = |t: f64| GuardPoint {
        t,
        g: 1.0 + t * t,
        rate: 2.0 * t,
    };
    assert_eq!(hermite_root(&q(0.0), &q(1.0)), None);
}

#[test]
fn illinois_from_a_good_start_is_cheap_and_from_a_bad_one_still_exact() {
    let f = |t: f64| -t.cos();
    let (a, b) = (1.2, 1.9);
    let tol = time_tolerance(2.0);
    let root = std::f64::consts::FRAC_PI_2;
    let (plain, n_plain) = illinois(f, a, b, f(a), f(b), tol);
    // a start 1e-5 off with the true slope: two evaluations bracket the root tightly
    let (good, n_good) = illinois_from(f, a, b, f(a), f(b), tol, (root + 1e-5, 1.0));
    // a start far off with a slope of the wrong sign: no worse than two wasted ones
    let (bad, n_bad) = illinois_from(f, a, b, f(a), f(b), tol, (1.25, -3.0));
    for t in [plain, good, bad] {
        assert!((t - root).abs() <= tol && t >= root - tol, "{t}");
    }
    assert!(n_good < n_plain, "{n_good} against {n_plain}");
    assert!(n_bad <= n_plain + 2, "{n_bad} against {n_plain}");
}
