//! Unit tests of the chapter's limit-cycle section (`cycle_claims.rs`, on the analyses
//! of `crate::scenes::stick::limit_cycle`): the fixed point is a fixed point for another
//! integrator; the multipliers by differences and by saltation agree within the
//! chapter's derived tolerance; the limit-cycle claims hold and fail under wrong
//! statements; a period-three gait is found as period three; a snapshot of both
//! scenes' analyses. The stick's physics, the command line's contract and the quick
//! summaries' snapshots: `tests/stick_state_machine.rs`.

use super::cycle_claims::{self, difference_error, Statements, WORKBOOK};
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::stick::{authors_scene, jamming_scene, StickModel, StickParams};
use crate::report::Verdict;
use crate::scenes::stick::limit_cycle::{
    analyse, max_difference, spectral_radius, Analysis, H_FINE,
};
use crate::scenes::stick::poincare::{
    distance, jacobian, multipliers, newton, settle, static_start, strobe, Difference, Gait,
};

fn opts(rtol: f64, method: Method) -> Options {
    Options {
        method,
        control: StepControl::tol(rtol, rtol),
        ..Options::default()
    }
}

/// The analyses of the authors' and the self-locking scene, computed once.
fn limit_cycles() -> &'static [Analysis; 2] {
    static A: std::sync::OnceLock<[Analysis; 2]> = std::sync::OnceLock::new();
    A.get_or_init(|| [analyse(&authors_scene(10.0)), analyse(&jamming_scene(9.81))])
}

#[test]
fn the_fixed_point_is_a_fixed_point_for_another_integrator() {
    // Found with DOP853 at rtol 1e-12; checked with Dormand-Prince 5(4) at 1e-12: the
    // return after one period differs from s* by the two runs' errors only.
    for (a, p) in limit_cycles()
        .iter()
        .zip([authors_scene(10.0), jamming_scene(9.81)])
    {
        let (x, n, _) = a.fixed.clone().expect("a fixed point");
        assert_eq!(n, 1);
        let m = StickModel::new(p);
        let back = strobe(&m, &opts(1e-12, Method::Dopri5), &x, n).expect("completes");
        let d = distance(&m, &back, &x);
        assert!(d < 1e-9, "|P(s*) - s*| = {d:e} with DOPRI5");
        // and it is not a fixed point of a neighbouring scene (the check can fail)
        let mut q = p;
        q.mu *= 1.01;
        let mq = StickModel::new(q);
        let moved = strobe(&mq, &opts(1e-12, Method::Dopri5), &x, n).expect("completes");
        assert!(distance(&mq, &moved, &x) > 1e-5);
    }
}

#[test]
fn multipliers_agree_between_differences_and_saltation() {
    let [authors, jamming] = limit_cycles();
    for a in [authors, jamming] {
        let salt = a.saltation.as_ref().expect("a contact cycle");
        let fd = a.central.last().expect("multipliers at the fine step");
        let d = max_difference(fd, salt);
        let tol = difference_error(a);
        assert!(d <= tol, "{d:e} > {tol:e}");
        assert!(tol < 1e-6, "the derived tolerance stays tight: {tol:e}");
        // the slip stop erases x_c': one multiplier is zero to rounding
        let smallest = salt.iter().map(|z| z.0.hypot(z.1)).fold(1.0, f64::min);
        assert!(smallest < 1e-12, "{smallest:e}");
    }
    // the self-locking gait is stable, the authors' unstable (a complex pair)
    let (rj, ra) = (
        spectral_radius(jamming.saltation.as_ref().unwrap()),
        spectral_radius(authors.saltation.as_ref().unwrap()),
    );
    assert!(
        (rj - 0.8906).abs() < 1e-3 && (ra - 1.0143).abs() < 1e-3,
        "{rj} {ra}"
    );
    assert!(matches!(jamming.gait, Gait::Periodic(1, _)));
    assert!(matches!(authors.gait, Gait::NotSettled(_)));
}

#[test]
fn the_limit_cycle_claims_hold_and_their_mutations_fail() {
    let [a, j] = limit_cycles();
    let sc = [("authors", a), ("self-locking", j)];
    for c in cycle_claims::all(&WORKBOOK, &sc) {
        assert_eq!(c.verdict, Verdict::Confirmed, "{}: {:?}", c.id, c);
    }
    let wrong = [
        (
            "floquet-difference-order",
            Statements {
                central: false,
                ..WORKBOOK
            },
        ),
        (
            "floquet-saltation",
            Statements {
                saltation: false,
                ..WORKBOOK
            },
        ),
        (
            "gait-stability",
            Statements {
                rate_factor: 1.1,
                ..WORKBOOK
            },
        ),
    ];
    for (id, st) in wrong {
        let c = cycle_claims::all(&st, &sc)
            .into_iter()
            .find(|c| c.id == id)
            .unwrap();
        assert_eq!(c.verdict, Verdict::Failed, "{id} under a wrong statement");
    }
}

#[test]
fn a_period_three_gait_is_found_as_period_three() {
    // The self-locking stick on a slow, strong plate (Gamma = 12, f = 10 Hz) hops in a
    // gait that repeats every third period: P^3(s*) = s* while P(s*) is far from s*.
    let mut p = jamming_scene(9.81);
    p = StickParams::new(
        p.length_m,
        p.mass_kg,
        p.stiffness_nm_per_rad,
        p.damping_nms_per_rad,
        p.mu,
        p.theta0_rad,
        p.g_mps2,
        12.0,
        10.0,
    )
    .unwrap();
    let m = StickModel::new(p);
    let o = opts(1e-12, Method::Dop853);
    let x0 = static_start(&m).unwrap();
    let Gait::Periodic(n, x) = settle(&m, &o, &x0, (200, 8, 1e-8)) else {
        panic!("settles");
    };
    assert_eq!(n, 3);
    let (fp, _) = newton(&m, &o, &x, 3, (H_FINE, 1e-11, 10)).expect("Newton converges");
    assert!(distance(&m, &strobe(&m, &o, &fp, 3).unwrap(), &fp) < 1e-10);
    let once = strobe(&m, &o, &fp, 1).unwrap();
    assert!(distance(&m, &once, &fp) > 1e-3);
    // attracting: all multipliers of P^3 inside the unit circle
    let j = jacobian(&m, &o, &fp, 3, 1e-4, Difference::Central).unwrap();
    let r = multipliers(&j)
        .iter()
        .map(|z| z.0.hypot(z.1))
        .fold(0.0, f64::max);
    assert!(r < 1.0, "{r}");
}

#[test]
fn limit_cycle_summary_snapshot() {
    // Gait labels and multipliers, three digits (the methods agree to 1e-8).
    let mut out = String::new();
    for (name, a) in ["authors", "self-locking"].iter().zip(limit_cycles()) {
        let (x, n, _) = a.fixed.clone().unwrap();
        let m = a.saltation.clone().unwrap();
        let shown: Vec<String> = m
            .iter()
            .map(|z| {
                let c = |v: f64| if v.abs() < 5e-4 { 0.0 } else { v }; // no "-0.000"
                format!("{:.3}{:+.3}i", c(z.0), c(z.1))
            })
            .collect();
        out.push_str(&format!(
            "{name}: {} | fixed point of P^{n} in {} at theta = {:.3} rad | multipliers {} | |lambda|max = {:.3}\n",
            a.gait.label(),
            x.mode.name(),
            x.s[0],
            shown.join(", "),
            spectral_radius(&m)
        ));
    }
    insta::assert_snapshot!("stick_limit_cycles", out);
}
