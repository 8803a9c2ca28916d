//! Tests of the soft-contact stick.
use super::run::{simulate_soft, SoftOutcome};
use super::*;
use crate::numerics::ode::{Method, StepControl};

/// The self-locking stick on a plate that does not move (Gamma = 0).
fn still() -> StickParams {
    StickParams::new(0.15, 1.0, 10.0, 0.01, 0.4, 0.3, 9.81, 0.0, 30.0).unwrap()
}

#[test]
fn the_balance_root_satisfies_the_rods_moment_balance() {
    // A penetrating, moving state: theta' from the solver must make C.8 vanish.
    let sys = SoftStick::new(still(), 1e-2);
    let y = [0.05, -1e-7, 0.01, -0.02, 0.35];
    let f = sys.forces(0.0, &y);
    let (g, dg) = sys.balance(&y, 0.0, y[STH].sin_cos(), f.theta_dot);
    // Newton's distance to the root g/dg within the search's own stopping width
    // 1e-15 max(|w|, 1) rad/s. (g itself is not small: the friction's slope
    // mu F_z L cos(theta) / v_eps ~ 8e5 N m s at v_eps = 1e-4 m/s turns one ulp of w
    // into 1e-11 N m.)
    assert!(
        (g / dg).abs() <= 1e-15 * f.theta_dot.abs().max(1.0),
        "{g} {dg} {f:?}"
    );
    assert!(f.fz >= 0.0 && f.fx.abs() <= sys.model.p.mu * f.fz * (1.0 + 1e-15));
}

#[test]
fn above_the_plate_the_contact_pushes_nothing() {
    // C above the plate (d > 0), rising or falling: the contact law gives no force and
    // the rod turns at its free rate (C.3). The damper's ramp r = -d / delta_r is
    // negative there; unclamped, a rising foot got F_z = (d / delta_r) c_n d' - k_n d
    // > 0 (a runaway to d = 256 m at t = 0.042 s on the self-locking scene), and a
    // falling one without the ramp got c_n |d'| - k_n d > 0 before touching.
    let sys = SoftStick::new(still(), 0.1);
    for y in [[0.05, 1e-6, 0.0, 0.5, 0.3], [0.05, 1e-6, 0.0, -0.5, 0.3]] {
        let f = sys.forces(0.0, &y);
        assert_eq!((f.fx, f.fz), (0.0, 0.0), "{y:?} {f:?}");
        let free = -sys.model.p.stiffness_nm_per_rad * (y[STH] - sys.model.p.theta0_rad)
            / sys.model.p.damping_nms_per_rad;
        assert_eq!(f.theta_dot, free);
    }
}

#[test]
fn standing_still_the_contact_carries_the_weight_at_penetration_m_g_over_k_n() {
    // On a still plate the stick settles at its static angle with F_z = m g, so the
    // penetration is m g / k_n (closed form); the damper's ramp is fully in there.
    let p = still();
    let eps = 1e-3;
    let r = simulate_soft(
        &p,
        eps,
        3.0,
        Method::Rosenbrock23,
        StepControl::tol(1e-8, 1e-12),
        100_000,
    );
    assert_eq!(r.outcome, SoftOutcome::Completed, "{r:?}");
    let want = p.mass_kg * p.g_mps2 / SoftParams::regularised(&p, eps).stiffness_n_per_m;
    // The initial drop overshoots by at most the rebound e ~ eps of the approach: the
    // deepest penetration lies within 5 % above m g / k_n.
    assert!(
        r.max_penetration_m > 0.99 * want && r.max_penetration_m < 1.05 * want,
        "{} vs {want}",
        r.max_penetration_m
    );
}

#[test]
fn the_root_search_converges_where_newton_ping_pongs_across_the_kink() {
    // A state of the self-locking scene at eps = 0.025 (met, with the first family, at
    // t = 0.0224 s by Rosenbrock 2(3) at rtol 1e-10) where g(theta') has a kink near its root: F_z
    // reaches 0 at theta' ~ 0.44 rad/s and beyond it g has the rod's slope gamma only.
    // Plain safeguarded Newton bounced between the two branches for all its iterations
    // and returned 0.42719 or 0.42735 rad/s depending on the state's last digits (the
    // root is 0.4273496): the noise stalled the step control. Now the bracket is split
    // where g changes character (zero slip, +-3 v_eps, the damper unloading) and Newton
    // steps follow the rtsafe rule (at most half the step before last, else bisect).
    let p = crate::physics::stick::jamming_scene(9.81);
    // the family of that run (v_eps = 0.1 eps m/s; the kink is the normal law's)
    let sys = SoftStick {
        model: crate::physics::stick::StickModel::new(p),
        soft: SoftParams::regularised_linear_slip(&p, 0.025),
    };
    let t = 0.022396918310182323;
    let y = [
        0.05155766560655834,
        -8.03627653242943e-7,
        0.05886395171685171,
        0.11691420420797642,
        0.3322770593990324,
    ];
    let f = sys.forces(t, &y);
    let (_, vs, _) = sys.model.plate(t);
    let (g, dg) = sys.balance(&y, vs, y[STH].sin_cos(), f.theta_dot);
    // Converged: Newton's distance to the root g/dg within the search's stopping width
    // 1e-15 max(|w|, 1) rad/s (the two rates returned before were 1.6e-4 apart).
    assert!((g / dg).abs() <= 1e-15, "g {g} dg {dg} at {f:?}");
    assert!(f.iterations < MAX_ROOT_ITERATIONS, "{f:?}");
}
