//! A second derivation of the flight and pivot equations: the Euler-Lagrange equations
//! of the model's energies, differentiated numerically. The Lagrangian is written from
//! the model's description alone (a point mass m at P, a massless rod, a torsion spring
//! k about theta_0, a damper gamma as a Rayleigh function, C pinned to the plate in
//! pivot), with no equation of motion written by hand; the document's C.3, C.5 and C.6
//! (derived by moment balances) are compared with it. Its error is that of the finite
//! differences, estimated by repeating each with halved steps.

use crate::physics::stick::StickParams;

/// `(z_s, z_s')` of the plate at `t` (m, m/s), from std trigonometry (the model's
/// table is not used here): `z_s = A sin(omega t + phi)`.
fn plate(q: &StickParams, t: f64) -> (f64, f64) {
    let (a, w, phi) = (q.plate.amplitude_m, q.plate.omega_rad_s, q.plate.phase_rad);
    let (s, c) = (w * t + phi).sin_cos();
    (a * s, a * w * c)
}

/// The pivot's Lagrangian `T - V` (J) at angle `th` (rad), rate `w` (rad/s) and time
/// `t` (s): P = C + L (sin, cos) with C at rest on the plate.
fn pivot_lagrangian(q: &StickParams, th: f64, w: f64, t: f64) -> f64 {
    let (m, l, g, k) = (q.mass_kg, q.length_m, q.g_mps2, q.stiffness_nm_per_rad);
    let (zs, vs) = plate(q, t);
    let (s, c) = th.sin_cos();
    let (vx, vz) = (l * c * w, vs - l * s * w); // formula: v_P = v_C + L theta' (cos, -sin)
    let d = th - q.theta0_rad;
    0.5 * m * (vx * vx + vz * vz) - m * g * (zs + l * c) - 0.5 * k * d * d // formula: T - V
}

/// theta'' (rad/s^2) of the pivot from the Euler-Lagrange equation with Rayleigh
/// damping `R = gamma theta'^2 / 2`, every partial derivative a central difference with
/// steps `h_th` (rad), `h_w` (rad/s) and `h_t` (s):
/// `L_ww theta'' = L_th - R_w - L_wth theta' - L_wt`.
fn pivot_el(q: &StickParams, th: f64, w: f64, t: f64, h: (f64, f64, f64)) -> f64 {
    let (h_th, h_w, h_t) = h;
    let f = |a: f64, b: f64, c: f64| pivot_lagrangian(q, a, b, c);
    let l_th = (f(th + h_th, w, t) - f(th - h_th, w, t)) / (2.0 * h_th);
    let l_ww = (f(th, w + h_w, t) - 2.0 * f(th, w, t) + f(th, w - h_w, t)) / (h_w * h_w);
    // d2L/(dtheta' dx) for x = theta or t: central differences in both
    let l_wth = (f(th + h_th, w + h_w, t) - f(th + h_th, w - h_w, t) - f(th - h_th, w + h_w, t)
        + f(th - h_th, w - h_w, t))
        / (4.0 * h_th * h_w);
    let l_wt = (f(th, w + h_w, t + h_t) - f(th, w - h_w, t + h_t) - f(th, w + h_w, t - h_t)
        + f(th, w - h_w, t - h_t))
        / (4.0 * h_t * h_w);
    let r_w = q.damping_nms_per_rad * w; // formula: dR/dtheta' with R = gamma theta'^2/2
    (l_th - r_w - l_wth * w - l_wt) / l_ww // formula: Euler-Lagrange solved for theta''
}

/// theta'' (rad/s^2) of the pivot from the Euler-Lagrange equation, and the estimate of
/// its finite-difference error (the change when every step is halved).
pub fn pivot_theta_dd(q: &StickParams, th: f64, w: f64, t: f64) -> (f64, f64) {
    let w_scale = (q.g_mps2 / q.length_m).sqrt().max(1.0);
    let h = (1e-4, w_scale, 1e-5 * q.period_s());
    let coarse = pivot_el(q, th, w, t, h);
    let fine = pivot_el(q, th, w, t, (h.0 / 2.0, h.1 / 2.0, h.2 / 2.0));
    (fine, (fine - coarse).abs())
}

/// The flight's Lagrangian in the coordinates `(x_P, z_P, theta)` (J): the massless rod
/// carries no kinetic energy, so theta enters through the spring alone.
fn flight_lagrangian(q: &StickParams, zp: f64, vxp: f64, vzp: f64, th: f64) -> f64 {
    let d = th - q.theta0_rad;
    0.5 * q.mass_kg * (vxp * vxp + vzp * vzp)
        - q.mass_kg * q.g_mps2 * zp
        - 0.5 * q.stiffness_nm_per_rad * d * d
}

/// The flight from the Euler-Lagrange equations at `(z_P, theta)`: `z_P''` (m/s^2, from
/// `m z_P'' = dL/dz_P`) and theta' (rad/s, from `dR/dtheta' = dL/dtheta`: no kinetic
/// term in theta), each with the estimate of its finite-difference error.
pub fn flight_rates(q: &StickParams, zp: f64, th: f64) -> [(f64, f64); 2] {
    // The Lagrangian is quadratic in theta and z_P' and linear in z_P: central
    // differences are exact there up to rounding, which large steps keep small
    // (eps |L| / h); the halved steps estimate what is left.
    let el = |h: f64| {
        let f = |z: f64, v: f64, a: f64| flight_lagrangian(q, z, 0.0, v, a);
        let hz = h * q.length_m;
        let hv = h * (q.g_mps2 * q.length_m).sqrt();
        let l_z = (f(zp + hz, 0.0, th) - f(zp - hz, 0.0, th)) / (2.0 * hz);
        let l_vv = (f(zp, hv, th) - 2.0 * f(zp, 0.0, th) + f(zp, -hv, th)) / (hv * hv);
        let l_th = (f(zp, 0.0, th + h) - f(zp, 0.0, th - h)) / (2.0 * h);
        let r_ww = q.damping_nms_per_rad; // formula: d2R/dtheta'^2 = gamma
        [l_z / l_vv, l_th / r_ww] // formula: z_P'' = L_z / L_vv; theta' = L_th / R_ww
    };
    let (c, f) = (el(0.1), el(0.05));
    [(f[0], (f[0] - c[0]).abs()), (f[1], (f[1] - c[1]).abs())]
}
