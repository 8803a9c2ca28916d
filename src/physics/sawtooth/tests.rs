//! Unit tests of the sawtooth closed forms: limits, continuity, consistency between
//! the formulas (drift = period mean of the steady velocity, lock time, linear orbit).
use super::*;

fn scene() -> Sawtooth {
    Sawtooth {
        slow_velocity_mps: 0.1,
        fast_velocity_mps: 0.3,
        slow_duration_s: 0.03,
    }
}

/// Midpoint-rule period mean of `f`; for piecewise-linear `f` with a few kinks the
/// error is ~ (slope jump) h^2 per kink, below 1e-12 at n = 2e5 here.
fn period_mean(period: f64, f: impl Fn(f64) -> f64) -> f64 {
    let n = 200_000;
    (0..n)
        .map(|i| f(period * (i as f64 + 0.5) / n as f64))
        .sum::<f64>()
        / n as f64
}

#[test]
fn default_scene_drift_by_hand() {
    // k = 0.3 * 9.81 = 2.943; T_f = 0.01, T = 0.04: v_d = 0.1 - 2.943e-4 / 0.04.
    let s = scene();
    let k = 0.3 * 9.81;
    assert_eq!(steady_regime(&s, k), Regime::StickSlow);
    assert!((drift_velocity_mps(&s, k) - (0.1 - 2.943e-4 / 0.04)).abs() < 1e-15);
    assert!((drift_ratio(3.0, k * 0.03 / 0.1) * 0.1 - drift_velocity_mps(&s, k)).abs() < 1e-15);
}

#[test]
fn drift_is_continuous_at_the_regime_boundary_and_zero_beyond() {
    let s = scene();
    let k_star = (0.1 + 0.3) / s.fast_duration_s(); // k T_f = a + b
    assert!(drift_velocity_mps(&s, k_star * (1.0 - 1e-12)).abs() < 1e-12);
    assert_eq!(steady_regime(&s, k_star), Regime::StickBoth);
    assert_eq!(drift_velocity_mps(&s, 3.0 * k_star), 0.0);
    // weak friction: the block rides with the slow stroke, v_d -> a
    assert!((drift_velocity_mps(&s, 1e-9) - 0.1).abs() < 1e-9);
    // always inside [0, a)
    for k in [0.01, 0.3, 3.0, 30.0, 300.0] {
        let v = drift_velocity_mps(&s, k);
        assert!((0.0..0.1).contains(&v), "{k}: {v}");
    }
}

#[test]
fn steady_velocity_is_periodic_with_the_drift_as_mean() {
    let s = scene();
    let period = s.period_s();
    for k in [0.5, 2.943, 39.0, 45.0, 200.0] {
        let v = |t: f64| steady_velocity_mps(&s, k, t);
        // continuous across the strokes and the period
        assert!((v(0.0) - v(period - 1e-13)).abs() < 1e-9, "{k}");
        assert!(
            (v(s.slow_duration_s - 1e-13) - v(s.slow_duration_s)).abs() < 1e-9,
            "{k}"
        );
        let mean = period_mean(period, v);
        assert!(
            (mean - drift_velocity_mps(&s, k)).abs() < 1e-11,
            "{k}: {mean} vs {}",
            drift_velocity_mps(&s, k)
        );
        // it stays within the plate's speeds and touches the slow speed
        let top = (0..4000)
            .map(|i| v(period * i as f64 / 4000.0))
            .fold(f64::MIN, f64::max);
        assert_eq!(top, 0.1);
    }
}

#[test]
fn lock_time_from_rest_by_hand() {
    // From rest: the first slow stroke ends at k T_s = 0.08829 < a, the fast stroke takes
    // k T_f back: v_1 = k (T_s - T_f) = 0.05886; then a is reached (0.1 - v_1)/k later.
    let s = scene();
    let k = 2.943;
    let v1 = k * 0.02;
    assert!((slipping_impulse_per_mass(&s, k) - v1).abs() < 1e-15);
    assert!((lock_time_s(&s, k, 0.0) - (0.04 + (0.1 - v1) / k)).abs() < 1e-15);
    assert_eq!((lock_time_s(&s, k, 0.0) / s.period_s()).floor(), 1.0); // whole periods before the lock
                                                                       // a block already close to a locks in the first slow stroke
    assert!((lock_time_s(&s, k, 0.09) - 0.01 / k).abs() < 1e-15);
    // the lower bound on mu gives exactly n_max periods
    let mu = mu_min_for_lock(&s, 9.81, 1000.0);
    let periods = (lock_time_s(&s, mu * 9.81 * (1.0 + 1e-9), 0.0) / s.period_s()).floor();
    assert!((periods - 1000.0).abs() <= 1.0);
}

#[test]
fn linear_orbit_is_periodic_and_has_zero_mean() {
    // Closed form of v' = -c (v - v_p) on each stroke: v_p + (v_start - v_p) e^{-c tau}.
    let s = scene();
    for c in [0.1, 30.0, 1000.0] {
        let v0 = linear_periodic_start_velocity_mps(&s, c);
        let v1 = 0.1 + (v0 - 0.1) * (-c * 0.03f64).exp();
        let v = |t: f64| {
            if t < 0.03 {
                0.1 + (v0 - 0.1) * (-c * t).exp()
            } else {
                -0.3 + (v1 + 0.3) * (-c * (t - 0.03)).exp()
            }
        };
        let end = -0.3 + (v1 + 0.3) * (-c * 0.01f64).exp();
        assert!((end - v0).abs() < 1e-15, "{c}");
        // smooth pieces: midpoint error ~ c^2 h^2 v, < 1e-10 even at c = 1000
        assert!(period_mean(0.04, v).abs() < 1e-10, "{c}");
    }
}

#[test]
fn mirrored_plate_negates_the_horizontal_motion() {
    let m = Mirrored(scene());
    assert_eq!(m.vx_mps(0.01), -0.1);
    assert_eq!(m.vx_mps(0.035), 0.3);
    assert_eq!(m.breakpoint_after(0.0), scene().breakpoint_after(0.0));
    assert_eq!(m.period_s(), 0.04);
}
