//! Tests of the soft-contact stick.
use super::run::{simulate_soft, SoftOutcome};
use super::*;
use crate::numerics::ode::{Method, StepControl};

/// The self-locking stick on a plate that does not move (Gamma = 0).
fn still() -> StickParams {
    StickParams::new(0.15, 1.0, 10.0, 0.01, 0.4, 0.3, 9.81, 0.0, 30.0)
}

#[test]
fn the_balance_root_satisfies_the_rods_moment_balance() {
    // A penetrating, moving state: theta' from the solver must make C.8 vanish.
    let sys = SoftStick::new(still(), 1e-2);
    let y = [0.05, -1e-7, 0.01, -0.02, 0.35];
    let f = sys.forces(0.0, &y);
    let (g, _) = sys.balance(&y, 0.0, y[STH].sin_cos(), f.theta_dot);
    // Round-off of the terms of C.8 (each ~ k |theta - theta_0| ~ 0.5 N m): 1e-12.
    assert!(g.abs() < 1e-12, "{g} {f:?}");
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
