//! The build exercises (exercise N.5 of each chapter): the student implements a function
//! in `student.rs`, the checks below compare it with an independent answer. The same
//! checks run on the reference solutions (`solutions.rs`) in every `cargo test`; on the
//! student's code they run with `cargo test --release --test exercises -- --ignored yours`.
//!
//! Independent answers: closed forms derived in the chapters (the rod's impulse ratio,
//! the arcsine friction law, the dither drift, the flights of whole periods, the
//! sawtooth drift, RK4's stability function, the sticking impulse of a rod), the
//! workbook's own implementation where the student writes a second one (the hull test,
//! the pivot reaction, the rod's mobility), and properties
//! no wrong answer has (the landing is a zero of the gap with no zero before it; the
//! observed order of RK4).

use std::f64::consts::PI;

use locomotion_workbook::physics::locomotion::is_locomotion;
use locomotion_workbook::physics::stick::{StickModel, StickParams, NSTATE, OM, TH};

use super::solutions::Reference;
use super::student::Yours;

/// The stick's constants for exercise 6.5 (SI units).
#[derive(Debug, Clone, Copy)]
pub struct PivotInputs {
    /// Tip mass m (kg).
    pub mass_kg: f64,
    /// Rod length L (m).
    pub length_m: f64,
    /// Torsion spring k (N m/rad).
    pub stiffness_nm_per_rad: f64,
    /// Torsion damper gamma (N m s/rad).
    pub damping_nms_per_rad: f64,
    /// Spring rest angle theta_0 (rad).
    pub theta0_rad: f64,
    /// Gravity g (m/s^2).
    pub g_mps2: f64,
}

/// One function per build exercise; see `student.rs` for what each must do.
pub trait Exercises {
    /// 1.5: `v` strictly outside the convex hull of 1 to 3 media velocities (m/s).
    fn is_outside_hull(v: [f64; 2], media: &[[f64; 2]]) -> bool;
    /// 2.5: `J_l/J_v` of a jammed uniform rod leaning `theta_rad`, from its mass matrix.
    fn rod_impulse_ratio(theta_rad: f64) -> f64;
    /// 3.5: mean of `-sign(u - cos phi)` over a period, `u = v/V` in [0, 1].
    fn mean_friction(u: f64) -> f64;
    /// 3.5: the drift `u = v/V` at which the mean friction balances the bias `b`.
    fn dither_drift(b: f64) -> f64;
    /// 4.5: landing phase of a block leaving `z_s = sin(phi)` at `takeoff_phase` (units:
    /// delta = omega = 1, so g = 1/Gamma).
    fn landing_phase(gamma: f64, takeoff_phase: f64) -> f64;
    /// 5.5: steady mean velocity on the sawtooth (m/s) from rest; `mu_g` in m/s^2.
    fn sawtooth_drift(v_slow: f64, v_fast: f64, t_slow: f64, mu_g: f64) -> f64;
    /// 6.5: `[F_x, F_z]` (N) of the plate on C in pivot, plate acceleration `a_s` (m/s^2).
    fn pivot_reaction(p: &PivotInputs, theta: f64, theta_dot: f64, a_s: f64) -> [f64; 2];
    /// 7.5: one RK4 step of `y' = f(t, y)` from `(t, y)` with step `h`.
    fn rk4_step(f: &dyn Fn(f64, f64) -> f64, t: f64, y: f64, h: f64) -> f64;
    /// 8.5: the mobility `W` (1/kg) of the foot of a rod of length `length_m` (m), rod
    /// mass `rod_kg` and tip mass `tip_kg` (kg) leaning `theta_rad`, as
    /// `[[W_xx, W_xz], [W_zx, W_zz]]`.
    fn rod_mobility(length_m: f64, rod_kg: f64, tip_kg: f64, theta_rad: f64) -> [[f64; 2]; 2];
}

fn check_1_5<E: Exercises>() {
    let sets: [&[[f64; 2]]; 5] = [
        &[[0.0, 0.0]],
        &[[0.0, 0.0], [5.0, 0.0]],
        &[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]],
        &[[0.0, 4.0], [4.0, 0.0], [0.0, 0.0]],
        &[[1.0, 0.0], [0.0, 3.0]],
    ];
    for media in sets {
        for i in -4..=12 {
            for j in -4..=12 {
                let v = [0.5 * f64::from(i), 0.5 * f64::from(j)];
                let want = is_locomotion(v, media);
                assert_eq!(
                    E::is_outside_hull(v, media),
                    want,
                    "v = {v:?}, media = {media:?}: locomotion is {want}"
                );
            }
        }
    }
}

fn check_2_5<E: Exercises>() {
    for deg in 1..90 {
        let theta = f64::from(deg).to_radians();
        let q = theta.tan();
        let want = 3.0 * q / (4.0 + q * q); // formula: J_l/J_v = 3q/(4 + q^2)
        let got = E::rod_impulse_ratio(theta);
        assert!(
            (got - want).abs() <= 1e-12 * want.max(1.0),
            "{deg} deg: {got}, closed form {want}"
        );
    }
}

fn check_3_5<E: Exercises>() {
    for k in 0..=20 {
        let u = f64::from(k) / 20.0;
        let want = -2.0 / PI * u.asin(); // formula: <F>/(mu m g) = -(2/pi) arcsin(v/V)
        let got = E::mean_friction(u);
        assert!(
            (got - want).abs() <= 1e-3,
            "u = {u}: mean friction {got}, closed form {want}"
        );
    }
    for k in 1..20 {
        let b = f64::from(k) / 20.0;
        let want = (PI * b / 2.0).sin(); // formula: v = V sin(pi b/2)
        let got = E::dither_drift(b);
        assert!(
            (got - want).abs() <= 1e-3,
            "b = {b}: drift {got} V, closed form {want} V"
        );
    }
}

/// The gap between the flying block and the plate (units of delta).
fn gap(gamma: f64, p0: f64, p: f64) -> f64 {
    let s = p - p0;
    p0.sin() + p0.cos() * s - s * s / (2.0 * gamma) - p.sin()
}

fn check_4_5<E: Exercises>() {
    for n in 1..=3 {
        let gn = (1.0 + (f64::from(n) * PI).powi(2)).sqrt(); // formula: Gamma_n
        let p0 = (1.0 / gn).asin();
        let got = E::landing_phase(gn, p0);
        let want = p0 + 2.0 * PI * f64::from(n);
        assert!(
            (got - want).abs() <= 1e-9,
            "Gamma_{n}: landing at {got}, a flight of {n} periods lands at {want}"
        );
    }
    for gamma in [1.2f64, 1.5, 2.0, 2.5, 3.0, 4.5, 7.0] {
        let p0 = (1.0 / gamma).asin();
        let land = E::landing_phase(gamma, p0);
        assert!(
            land > p0 + 1e-6 && gap(gamma, p0, land).abs() <= 1e-9,
            "Gamma = {gamma}: no landing at {land}"
        );
        for i in 1..10_000 {
            let p = p0 + 1e-3 + (land - p0 - 2e-3) * f64::from(i) / 10_000.0;
            assert!(
                gap(gamma, p0, p) > 0.0,
                "Gamma = {gamma}: the block meets the plate at {p}, before {land}"
            );
        }
    }
}

fn check_5_5<E: Exercises>() {
    // (v_slow, v_fast, T_slow, mu g): sticking in the slow stroke, and in both strokes.
    for (vs, vf, ts, mg) in [
        (0.1, 0.3, 0.3, 0.5),
        (0.2, 0.5, 0.1, 2.0),
        (0.1, 0.15, 0.2, 1.0),
        (0.1, 0.2, 0.5, 9.0),
    ] {
        let tf = vs * ts / vf;
        let t = ts + tf;
        let want = if mg * tf < vs + vf {
            vs - mg * tf * tf / t
        } else {
            0.0
        }; // formula: v_d = v_slow - mu g T_fast^2/T
        let got = E::sawtooth_drift(vs, vf, ts, mg);
        assert!(
            (got - want).abs() <= 1e-9 * vs,
            "({vs}, {vf}, {ts}, {mg}): drift {got}, closed form {want}"
        );
    }
}

fn check_6_5<E: Exercises>() {
    let p = PivotInputs {
        mass_kg: 1.0,
        length_m: 0.15,
        stiffness_nm_per_rad: 10.0,
        damping_nms_per_rad: 0.01,
        theta0_rad: 0.3,
        g_mps2: 9.81,
    };
    let (gamma, f_hz) = (3.0, 30.0);
    let model = StickModel::new(
        StickParams::new(0.15, 1.0, 10.0, 0.01, 0.4, 0.3, 9.81, gamma, f_hz).unwrap(),
    );
    for (i, (theta, w)) in [
        (0.35, 0.0),
        (0.3, 2.0),
        (0.5, -3.0),
        (-0.2, 1.0),
        (1.2, 0.5),
    ]
    .into_iter()
    .enumerate()
    {
        let t = 0.0071 * i as f64;
        let a_s = -gamma * 9.81 * (2.0 * PI * f_hz * t).cos(); // the plate z_s = delta cos(omega t)
        let mut y = [0.0; NSTATE];
        (y[TH], y[OM]) = (theta, w);
        let e = model.pivot_eval(t, &y);
        let got = E::pivot_reaction(&p, theta, w, a_s);
        for (g, want) in got.iter().zip([e.fx, e.fz]) {
            assert!(
                (g - want).abs() <= 1e-9 * 9.81,
                "theta = {theta}, theta' = {w}: F = {got:?}, the workbook's {:?}",
                [e.fx, e.fz]
            );
        }
    }
}

fn check_7_5<E: Exercises>() {
    let decay = |_t: f64, y: f64| -y;
    let r1 = E::rk4_step(&decay, 0.0, 1.0, 1.0);
    assert!(
        (r1 - 0.375).abs() <= 1e-15,
        "R(1) = {r1}, 1 - 1 + 1/2 - 1/6 + 1/24 = 0.375"
    );
    let r = E::rk4_step(&decay, 0.0, 1.0, 2.785);
    assert!(
        (r - 1.0).abs() <= 1e-3,
        "R(2.785) = {r}: the stability bound of exercise 7.1"
    );
    // y' = y cos t, y(0) = 1: y = exp(sin t). Error at t = 2 for 20, 40, 80 steps.
    let f = |t: f64, y: f64| y * t.cos();
    let err = |n: u32| {
        let h = 2.0 / f64::from(n);
        let y = (0..n).fold(1.0, |y, i| E::rk4_step(&f, f64::from(i) * h, y, h));
        (y - 2f64.sin().exp()).abs()
    };
    let (e20, e40, e80) = (err(20), err(40), err(80));
    for (a, b) in [(e20, e40), (e40, e80)] {
        let p = (a / b).log2();
        assert!(
            (p - 4.0).abs() <= 0.3,
            "observed order {p} (errors {e20:e}, {e40:e}, {e80:e}): RK4 has order 4"
        );
    }
}

fn check_8_5<E: Exercises>() {
    use locomotion_workbook::physics::stick_inertia::{InertiaModel, InertiaParams, MassGeometry};
    let length_m = 0.15;
    for (rod_kg, tip_kg) in [
        (1.0, 0.0),
        (1.0, 1.0),
        (0.01, 1.0),
        (1e-6, 1.0),
        (0.3, 0.05),
    ] {
        let mut base = StickParams::new(length_m, 1.0, 10.0, 0.01, 0.4, 0.3, 9.81, 3.0, 30.0)
            .expect("a stick inside the model's domain");
        base.mass_kg = tip_kg;
        let model = InertiaModel::new(InertiaParams {
            base,
            rod_mass_kg: rod_kg,
            restitution: 0.0,
        });
        let alpha = MassGeometry::new(length_m, rod_kg, tip_kg).alpha();
        for theta in [-1.2, -0.3, 0.1, std::f64::consts::FRAC_PI_4, 1.4] {
            let want = model.mobility(theta);
            let got = E::rod_mobility(length_m, rod_kg, tip_kg, theta);
            let scale = want.iter().flatten().fold(0.0_f64, |a, w| a.max(w.abs()));
            for (g, w) in got.iter().flatten().zip(want.iter().flatten()) {
                assert!(
                    (g - w).abs() <= 1e-12 * scale,
                    "rod {rod_kg} kg, tip {tip_kg} kg, theta {theta}: W = {got:?}, the model's {want:?}"
                );
            }
            // A sticking landing: P = W^-1 (0, v), so P_x/P_z = -W_xz/W_xx, which section
            // 2 writes alpha q/(1 + alpha + q^2) with q = tan(theta).
            let q = theta.tan();
            let ratio = -got[0][1] / got[0][0];
            let closed = alpha * q / (1.0 + alpha + q * q); // formula: J_l/J_v = alpha q/(1+alpha+q^2)
            assert!(
                (ratio - closed).abs() <= 1e-9 * closed.abs().max(1e-3),
                "rod {rod_kg} kg, tip {tip_kg} kg, theta {theta}: J_l/J_v = {ratio}, section 2's {closed}"
            );
        }
    }
}

macro_rules! build_exercise {
    ($check:ident, $reference:ident, $yours:ident) => {
        #[test]
        fn $reference() {
            $check::<Reference>();
        }
        #[test]
        #[ignore = "your implementation in tests/exercises/student.rs: cargo test --release --test exercises -- --ignored yours"]
        fn $yours() {
            $check::<Yours>();
        }
    };
}

build_exercise!(check_1_5, reference_1_5, yours_1_5);
build_exercise!(check_2_5, reference_2_5, yours_2_5);
build_exercise!(check_3_5, reference_3_5, yours_3_5);
build_exercise!(check_4_5, reference_4_5, yours_4_5);
build_exercise!(check_5_5, reference_5_5, yours_5_5);
build_exercise!(check_6_5, reference_6_5, yours_6_5);
build_exercise!(check_7_5, reference_7_5, yours_7_5);
build_exercise!(check_8_5, reference_8_5, yours_8_5);
