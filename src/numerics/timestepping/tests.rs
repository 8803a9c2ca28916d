//! Tests of Moreau-Jean against closed forms: a ball on a fixed floor (rest, bounce
//! height, first-order convergence) and a block sliding to rest under Coulomb friction.
use super::*;

const G: f64 = 9.81;

/// A point mass in the plane above a fixed floor z = 0: q = (x, z), v = (x', z').
struct PointMass {
    m: f64,
    e: f64,
    mu: f64,
}

impl ContactModel<2> for PointMass {
    fn inv_mass(&self, _t: f64, _q: &[f64; 2], _h: f64) -> [[f64; 2]; 2] {
        [[1.0 / self.m, 0.0], [0.0, 1.0 / self.m]]
    }
    fn free_velocity(&self, _t: f64, _q: &[f64; 2], v: &[f64; 2], h: f64) -> [f64; 2] {
        [v[0], v[1] - G * h]
    }
    fn gap(&self, _t: f64, q: &[f64; 2]) -> f64 {
        q[1]
    }
    fn jacobians(&self, _t: f64, _q: &[f64; 2]) -> ([f64; 2], [f64; 2]) {
        ([0.0, 1.0], [1.0, 0.0])
    }
    fn restitution(&self) -> f64 {
        self.e
    }
    fn mu(&self) -> f64 {
        self.mu
    }
}

#[test]
fn contact_cases_are_recognised_and_satisfy_their_laws() {
    // A point mass of 1 kg: W = identity. Closed forms of each case by hand.
    let w = [[1.0, 0.0], [0.0, 1.0]];
    // separating: open
    assert_eq!(
        solve_contact(w, [0.5, 3.0], 0.0, 0.3).unwrap().status,
        ContactStatus::Open
    );
    // approaching slowly sideways: stick, P = -(u_n, u_t)
    let i = solve_contact(w, [-1.0, 0.2], 0.0, 0.3).unwrap();
    assert_eq!(i.status, ContactStatus::Stick);
    assert!((i.p_n - 1.0).abs() < 1e-15 && (i.p_t + 0.2).abs() < 1e-15);
    // fast sideways: slides towards +t, P_t = -mu P_n, u_t reduced by mu P_n
    let i = solve_contact(w, [-1.0, 2.0], 0.0, 0.3).unwrap();
    assert_eq!(i.status, ContactStatus::SlidePositive);
    assert!((i.p_n - 1.0).abs() < 1e-15 && (i.p_t + 0.3).abs() < 1e-15);
    let i = solve_contact(w, [-1.0, -2.0], 0.0, 0.3).unwrap();
    assert_eq!(i.status, ContactStatus::SlideNegative);
    // restitution target: u_n,{k+1} = -e u_n,k
    let i = solve_contact(w, [-1.0, 0.0], -0.5, 0.3).unwrap();
    assert!((i.p_n - 1.5).abs() < 1e-15);
}

#[test]
fn contact_solutions_hold_for_coupled_delassus_matrices() {
    // Pseudo-random SPD W with coupling |W_nt| < W_nn / (2 mu): a solution exists and
    // is unique; check complementarity and the cone on every one (round-off only).
    let mut seed: u64 = 12345;
    let mut rnd = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..2000 {
        let mu = rnd();
        let (a, b) = (0.5 + rnd(), 0.5 + rnd());
        let c = (rnd() - 0.5) * a.min(b) / (1.0 + 2.0 * mu);
        let w = [[a, c], [c, b]];
        let u = [4.0 * rnd() - 2.0, 4.0 * rnd() - 2.0];
        let i = solve_contact(w, u, 0.0, mu).expect("solution exists");
        let un = u[0] + w[0][0] * i.p_n + w[0][1] * i.p_t;
        let ut = u[1] + w[1][0] * i.p_n + w[1][1] * i.p_t;
        assert!(
            un >= -1e-12 && i.p_n >= 0.0 && (un * i.p_n).abs() < 1e-12,
            "{i:?} un {un}"
        );
        assert!(i.p_t.abs() <= mu * i.p_n + 1e-12, "{i:?}");
        if ut.abs() > 1e-12 {
            assert!(
                (i.p_t + mu * i.p_n * ut.signum()).abs() < 1e-12,
                "{i:?} ut {ut}"
            );
        }
    }
}

/// Runs a ball dropped from `z0` at rest and returns (run, first contact time, min z).
fn drop_ball(
    e: f64,
    z0: f64,
    h: f64,
    t_end: f64,
    mut watch: impl FnMut(&MjStep<2>),
) -> (MjRun<2>, f64, f64) {
    let ball = PointMass { m: 0.2, e, mu: 0.5 };
    let mut first = f64::NAN;
    let mut zmin = f64::INFINITY;
    let run = simulate(
        &ball,
        0.0,
        [0.0, z0],
        [0.0, 0.0],
        t_end,
        &MjOptions::midpoint(h),
        |s| {
            if s.impulse.status != ContactStatus::Inactive && first.is_nan() {
                first = s.t0;
            }
            zmin = zmin.min(s.q1[1]);
            watch(s)
        },
    )
    .unwrap();
    (run, first, zmin)
}

#[test]
fn ball_without_restitution_comes_to_rest_with_penetration_below_h_v() {
    // Closed form: contact at t = sqrt(2 z0 / g) with speed v = sqrt(2 g z0). The
    // midpoint rule activates the contact when z_k + h v_k / 2 <= 0; z_k itself may be
    // up to h v / 2 below the floor (the previous midpoint was just above it), so the
    // ball stops at most h v below the floor (plus the g h^2 of one step).
    for h in [1e-2, 1e-3, 1e-4] {
        let (run, first, zmin) = drop_ball(0.0, 1.0, h, 1.0, |_| {});
        let (t_land, v_land) = ((2.0 / G).sqrt(), (2.0 * G).sqrt());
        assert!(
            run.v[1].abs() < 1e-12 && run.v[0] == 0.0,
            "h {h}: v {:?}",
            run.v
        );
        assert!(
            zmin >= -(h * v_land + G * h * h) && zmin <= 0.0,
            "h {h}: zmin {zmin}"
        );
        assert!((run.q[1] - zmin).abs() < 1e-12, "stays where it stopped");
        assert!(
            (first - t_land).abs() <= h,
            "h {h}: first contact {first} vs {t_land}"
        );
    }
}

#[test]
fn bounce_apex_is_e_squared_times_the_drop_height_to_order_h() {
    // Closed form: after the first impact the ball leaves at e v and rises to e^2 z0.
    // The impact is resolved within one step: the apex is off by O(h v).
    let (e, z0) = (0.6, 1.0);
    for h in [1e-3, 1e-4] {
        let t1 = (2.0 * z0 / G).sqrt();
        let mut apex: f64 = f64::NEG_INFINITY;
        drop_ball(e, z0, h, t1 + e * t1 * 1.5, |s| {
            if s.t0 > t1 + 0.5 * e * t1 {
                apex = apex.max(s.q1[1]);
            }
        });
        let v = (2.0 * G * z0).sqrt();
        assert!(
            (apex - e * e * z0).abs() <= 2.0 * h * v,
            "h {h}: apex {apex}"
        );
    }
}

#[test]
fn moreau_jean_is_first_order_across_an_impact() {
    // Height at T = 0.7 s, between the first and second bounce (e = 0.5): closed form
    // z = e v1 s - g s^2 / 2, s = T - t1. The error is O(h) with a factor that depends on
    // where the impact falls inside its step, so the order is the least-squares slope of
    // log error against log h over two decades (10 steps each): it must lie in [0.7, 1.3].
    let (e, z0, t_obs) = (0.5, 1.0, 0.7);
    let t1 = (2.0 * z0 / G).sqrt();
    let s = t_obs - t1;
    let exact = e * G * t1 * s - 0.5 * G * s * s;
    let mut pts = Vec::new();
    for k in 0..20 {
        let h = 1e-2 * 10f64.powf(-2.0 * k as f64 / 19.0);
        // land exactly on t_obs
        let n = (t_obs / h).round();
        let (run, _, _) = drop_ball(e, z0, t_obs / n, t_obs, |_| {});
        pts.push(((t_obs / n).ln(), (run.q[1] - exact).abs().ln()));
    }
    let n = pts.len() as f64;
    let (mx, my) = (
        pts.iter().map(|p| p.0).sum::<f64>() / n,
        pts.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let slope = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>()
        / pts.iter().map(|p| (p.0 - mx).powi(2)).sum::<f64>();
    assert!((0.7..=1.3).contains(&slope), "observed order {slope}");
}

#[test]
fn block_slides_to_rest_at_v_squared_over_two_mu_g() {
    // Closed form: a block launched at v0 on the floor decelerates at mu g and stops after
    // v0^2 / (2 mu g). Each contact step removes mu g h of speed exactly; the stop falls
    // inside a step, so the distance is off by at most v h (first order), and it sticks.
    let (v0, mu) = (1.5, 0.4);
    let block = PointMass { m: 2.0, e: 0.0, mu };
    let d = v0 * v0 / (2.0 * mu * G);
    let mut errs = Vec::new();
    for h in [1e-2, 1e-3, 1e-4] {
        let mut last = ContactStatus::Inactive;
        let run = simulate(
            &block,
            0.0,
            [0.0, 0.0],
            [v0, 0.0],
            1.0,
            &MjOptions::midpoint(h),
            |s| last = s.impulse.status,
        )
        .unwrap();
        assert_eq!(last, ContactStatus::Stick);
        assert!(run.v[0].abs() < 1e-12 && run.v[1].abs() < 1e-12);
        // resting on the floor: one step of gravity into it, g h^2 / 2 deep at most
        assert!(run.q[1] <= 0.0 && run.q[1] >= -G * h * h, "z {}", run.q[1]);
        let err = (run.q[0] - d).abs();
        assert!(err <= v0 * h, "h {h}: {} vs {d}", run.q[0]);
        errs.push(err);
    }
    assert!(errs[2] < errs[0], "{errs:?}");
}
