//! Tests of the integrators: convergence orders, tolerances, dense output, counts.
use super::*;

fn decay(_t: f64, y: &[f64; 1]) -> [f64; 1] {
    [-y[0]]
}

fn oscillator(_t: f64, y: &[f64; 2]) -> [f64; 2] {
    [y[1], -y[0]]
}

/// Global error at t = 1 of y' = -y, y(0) = 1 with fixed step h.
fn decay_error(method: Method, h: f64) -> f64 {
    let mut integ = Integrator::new(method, StepControl::Fixed { h_s: h });
    let y = integ.integrate(&decay, 0.0, [1.0], 1.0, |_| {}).unwrap();
    (y[0] - (-1.0f64).exp()).abs()
}

/// Observed order from a step-halving study: log2(e(h)/e(h/2)).
fn observed_order(method: Method, h: f64) -> f64 {
    (decay_error(method, h) / decay_error(method, h / 2.0)).log2()
}

#[test]
fn convergence_orders_from_step_halving() {
    // Step sizes are in the asymptotic range (error well above round-off), so the
    // observed order is within 0.1 of the theoretical one.
    let euler = observed_order(Method::Euler, 1.0 / 64.0);
    let rk4 = observed_order(Method::Rk4, 1.0 / 16.0);
    let dp5 = observed_order(Method::Dopri5, 1.0 / 8.0);
    assert!((euler - 1.0).abs() < 0.1, "Euler order {euler}");
    assert!((rk4 - 4.0).abs() < 0.1, "RK4 order {rk4}");
    assert!((dp5 - 5.0).abs() < 0.15, "DP5 order {dp5}");
}

#[test]
fn adaptive_dopri_meets_tolerance_on_decay_and_oscillator() {
    // Global error of a stable problem stays within a small multiple of the tolerance.
    for &tol in &[1e-6, 1e-9, 1e-12] {
        let mut integ = Integrator::new(Method::Dopri5, StepControl::tol(tol, tol));
        let y = integ.integrate(&decay, 0.0, [1.0], 5.0, |_| {}).unwrap();
        assert!(
            (y[0] - (-5.0f64).exp()).abs() < 10.0 * tol,
            "decay tol {tol}"
        );
        let mut integ = Integrator::new(Method::Dopri5, StepControl::tol(tol, tol));
        let t_end = 2.0 * std::f64::consts::PI * 3.0;
        let y = integ
            .integrate(&oscillator, 0.0, [1.0, 0.0], t_end, |_| {})
            .unwrap();
        // three periods: error grows linearly with time, hence 100 x tol
        assert!(
            (y[0] - 1.0).abs() < 100.0 * tol && y[1].abs() < 100.0 * tol,
            "osc tol {tol}: {y:?}"
        );
    }
}

#[test]
fn dense_output_is_fourth_order_accurate_inside_steps() {
    let mut integ = Integrator::new(Method::Dopri5, StepControl::tol(1e-10, 1e-10));
    let mut worst: f64 = 0.0;
    integ
        .integrate(&oscillator, 0.0, [1.0, 0.0], 10.0, |s| {
            for k in 1..10 {
                let t = s.t0 + (s.t1 - s.t0) * k as f64 / 10.0;
                let y = s.eval(&oscillator, t);
                worst = worst
                    .max((y[0] - t.cos()).abs())
                    .max((y[1] + t.sin()).abs());
            }
        })
        .unwrap();
    // The interpolant's error is of the order of the local tolerance.
    assert!(worst < 1e-8, "dense output error {worst}");
}

#[test]
fn hermite_and_linear_interpolants_match_ends() {
    for m in [Method::Euler, Method::Rk4, Method::Dopri5, Method::Dop853] {
        let mut integ = Integrator::new(m, StepControl::Fixed { h_s: 0.1 });
        let s = integ.step(&oscillator, 0.0, &[1.0, 0.0], 1.0).unwrap();
        assert_eq!(s.eval(&oscillator, s.t0), s.y0);
        assert_eq!(s.eval(&oscillator, s.t1), s.y1);
    }
}

#[test]
fn rhs_evaluations_are_counted_per_method() {
    for (m, per_step) in [
        (Method::Euler, 1u64),
        (Method::Rk4, 4),
        (Method::Dopri5, 6),
        (Method::Dop853, 12),
    ] {
        let mut integ = Integrator::new(m, StepControl::Fixed { h_s: 0.1 });
        integ.integrate(&decay, 0.0, [1.0], 1.0, |_| {}).unwrap();
        assert_eq!(integ.stats.accepted, 10, "{m:?}");
        // first step evaluates f0 once more for methods that reuse the end value
        let expected = match m {
            Method::Euler => 10,
            _ => 10 * per_step + 1,
        };
        assert_eq!(integ.stats.rhs_evals, expected, "{m:?}");
    }
}

#[test]
fn non_finite_state_is_an_error_not_a_panic() {
    let blow = |_t: f64, y: &[f64; 1]| [y[0] * y[0]];
    let mut integ = Integrator::new(Method::Euler, StepControl::Fixed { h_s: 0.5 });
    let r = integ.integrate(&blow, 0.0, [1e200], 10.0, |_| {});
    assert!(matches!(r, Err(OdeError::NonFinite { .. })));
}

#[test]
fn adaptive_dop853_meets_tolerance_with_fewer_evaluations_than_dp5_at_1e_10() {
    // Same problem, same tolerance: the eighth-order pair needs fewer right-hand sides
    // (the reason the stick simulator uses it), and its global error stays within the
    // same small multiple of the tolerance as DP5's.
    let t_end = 2.0 * std::f64::consts::PI * 3.0;
    let mut evals = [0u64; 2];
    for (n, m) in [Method::Dopri5, Method::Dop853].into_iter().enumerate() {
        for &tol in &[1e-6, 1e-10, 1e-13] {
            let mut integ = Integrator::new(m, StepControl::tol(tol, tol));
            let y = integ
                .integrate(&oscillator, 0.0, [1.0, 0.0], t_end, |_| {})
                .unwrap();
            assert!(
                (y[0] - 1.0).abs() < 100.0 * tol && y[1].abs() < 100.0 * tol,
                "{m:?} tol {tol}: {y:?}"
            );
            if tol == 1e-10 {
                evals[n] = integ.stats.rhs_evals;
            }
        }
    }
    assert!(
        2 * evals[1] < evals[0],
        "DP5 {} vs DOP853 {}",
        evals[0],
        evals[1]
    );
}

#[test]
fn dop853_interpolant_is_seventh_order_and_costs_three_evaluations_once() {
    // Error of the continuous extension inside one step of size h on the oscillator:
    // O(h^8) locally, so halving h divides it by about 2^8 = 256 (asymptotic range:
    // h = 0.8 and 0.4 give 1e-9 and 4e-12, well above round-off).
    let worst = |h: f64| -> f64 {
        let mut integ = Integrator::new(Method::Dop853, StepControl::Fixed { h_s: h });
        let s = integ.step(&oscillator, 0.0, &[1.0, 0.0], h).unwrap();
        assert_eq!(s.dense_evals(), 0, "no extension before it is asked for");
        let mut w: f64 = 0.0;
        for k in 1..10 {
            let t = h * k as f64 / 10.0;
            let y = s.eval(&oscillator, t);
            w = w.max((y[0] - t.cos()).abs()).max((y[1] + t.sin()).abs());
        }
        assert_eq!(s.dense_evals(), 3, "built once, reused by every later call");
        w
    };
    let ratio = worst(0.8) / worst(0.4);
    // local order 8 (interpolant of order 7): ratio 2^8 = 256; accept 150..400
    assert!((150.0..400.0).contains(&ratio), "ratio {ratio}");
}

/// `y0' = -y0` and `y1' = y0^2`: nothing reads `y1` (a quadrature), so stage arguments
/// need only `y0` (`ARGS = 1`); `A` is the declared count.
struct Quadrature<const A: usize>;

impl<const A: usize> OdeSystem<2> for Quadrature<A> {
    const ARGS: usize = A;
    fn rhs(&self, _t: f64, y: &[f64; 2]) -> [f64; 2] {
        [-y[0], y[0] * y[0]]
    }
}

/// The same, but `y0` also feels `y1`: declaring `ARGS = 1` breaks its contract.
struct Coupled<const A: usize>;

impl<const A: usize> OdeSystem<2> for Coupled<A> {
    const ARGS: usize = A;
    fn rhs(&self, _t: f64, y: &[f64; 2]) -> [f64; 2] {
        [-y[0] + 0.5 * y[1], y[0] * y[0]]
    }
}

fn run_to_1<S: OdeSystem<2>>(sys: &S, m: Method) -> [f64; 2] {
    let control = match m {
        Method::Dopri5 | Method::Dop853 => StepControl::tol(1e-10, 1e-10),
        _ => StepControl::Fixed { h_s: 0.01 },
    };
    let mut integ = Integrator::new(m, control);
    integ.integrate(sys, 0.0, [1.0, 0.0], 1.0, |_| {}).unwrap()
}

#[test]
fn stage_arguments_of_unread_components_are_skipped_without_effect() {
    // Skipping the stage arithmetic of a component nothing reads changes no bit of the
    // result, for every method (y1 is still integrated: its stages come from y0).
    // The closed form y1(1) = (1 - e^-2)/2 checks that y1 is integrated at all.
    let exact = 0.5 * (1.0 - (-2.0f64).exp());
    for m in [Method::Euler, Method::Rk4, Method::Dopri5, Method::Dop853] {
        let (all, lean) = (run_to_1(&Quadrature::<2>, m), run_to_1(&Quadrature::<1>, m));
        assert_eq!(all, lean, "{m:?}");
        // RK4 at h = 0.01: error ~1e-10; Euler ~4e-3 (first order); the pairs: tolerance.
        let tol = if m == Method::Euler { 1e-2 } else { 1e-8 };
        assert!((lean[1] - exact).abs() < tol, "{m:?}: {}", lean[1]);
    }
    // The contract is real: when the right-hand side does read the skipped component,
    // the lean stages see stale values and the answer changes (RK4 and the pairs; Euler
    // has no stages).
    for m in [Method::Rk4, Method::Dopri5, Method::Dop853] {
        let (all, lean) = (run_to_1(&Coupled::<2>, m), run_to_1(&Coupled::<1>, m));
        assert!((all[0] - lean[0]).abs() > 1e-6, "{m:?}: {all:?} {lean:?}");
    }
}

#[test]
fn a_nan_or_out_of_range_tolerance_is_an_error_naming_its_range() {
    for rtol in [f64::NAN, -1e-3, 2.0, f64::INFINITY] {
        let mut integ = Integrator::new(Method::Dopri5, StepControl::tol(rtol, 1e-9));
        let e = integ
            .integrate(&decay, 0.0, [1.0], 1.0, |_| {})
            .unwrap_err();
        assert!(
            matches!(e, OdeError::InvalidControl { name: "rtol", .. }),
            "{rtol}: {e:?}"
        );
        assert!(e.to_string().contains("rtol") && e.to_string().contains("[0, 1]"));
        assert_eq!(integ.stats.rhs_evals, 0, "nothing is evaluated");
    }
    for (control, name) in [
        (StepControl::tol(1e-6, f64::NAN), "atol"),
        (StepControl::tol(0.0, 0.0), "atol"),
        (StepControl::Fixed { h_s: f64::NAN }, "h_s"),
        (StepControl::Fixed { h_s: 0.0 }, "h_s"),
    ] {
        let mut integ = Integrator::new(Method::Rk4, control);
        let e = integ.step(&decay, 0.0, &[1.0], 1.0).unwrap_err();
        assert!(
            matches!(e, OdeError::InvalidControl { name: n, .. } if n == name),
            "{control:?}: {e:?}"
        );
    }
    // The edges of the range are accepted.
    for rtol in [0.0, 1.0] {
        let mut integ = Integrator::new(Method::Dopri5, StepControl::tol(rtol, 1e-9));
        assert!(integ.integrate(&decay, 0.0, [1.0], 1.0, |_| {}).is_ok());
    }
}
