//! The computations behind the claims, done once: the uniform rod's mass matrix of the
//! contact point (the mobility matrix inverted), the document's force derivation
//! evaluated as vectors, the impulse ratios from the mass matrices and from the
//! Newton-Euler impulse equations (a second method) at the chosen angle, at 30 and at
//! 45 degrees, and the rod's best angle by golden-section search; with each, the raw
//! quantities its rounding bound reads (`rounding.rs`: the matrices as built, the
//! computed inverse and residuals, the best angle's probe).

use super::rounding::{rod_ratio_error, Inversion2, Solve5};
use super::{LENGTH_M, MASS_KG};
use crate::physics::rigid::{
    contact_acceleration, effective_mass, impulse_for_velocity_change, in_stick_frame, jam_ratio,
    mobility, perp, rod_contact_offset, stick_normal, tip_contact_offset, RigidBody,
};
use nalgebra::{Matrix2, Matrix5, Vector2, Vector5};

/// Golden-section search for the maximum (moved down to the numerics layer).
pub use crate::numerics::search::golden_max;

/// The uniform rod of the scene.
pub fn rod() -> RigidBody {
    RigidBody::uniform_rod(MASS_KG, LENGTH_M)
}

/// Mass matrices (world frame) of the uniform rod and of the point-mass model.
pub fn matrices(theta: f64) -> (Matrix2<f64>, Matrix2<f64>) {
    let m_rod = effective_mass(&rod(), rod_contact_offset(theta, LENGTH_M));
    let m_pm = effective_mass(
        &RigidBody::point_mass(MASS_KG),
        tip_contact_offset(theta, LENGTH_M),
    );
    (m_rod, m_pm)
}

/// `J_l / J_v` of the uniform rod from its mass matrix.
pub fn rod_ratio(theta: f64) -> f64 {
    jam_ratio(&matrices(theta).0)
}

/// `J_l / J_v` of the point-mass model from its mass matrix.
pub fn point_mass_ratio(theta: f64) -> f64 {
    jam_ratio(&matrices(theta).1)
}

/// Bisection for the root of `f` on `[a, b]` (a sign change required), to `tol`.
pub fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, tol: f64) -> f64 {
    let fa = f(a);
    while b - a > tol {
        let m = 0.5 * (a + b);
        if (f(m) > 0.0) == (fa > 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// Angles (rad) where the rod's impulse ratio equals mu, from the closed form
/// `3q/(4+q^2) = mu`, i.e. `q = (3 -+ sqrt(9 - 16 mu^2)) / (2 mu)`. None for
/// `mu >= 3/4` (the rod then never slips under a vertical impulse) and for `mu = 0`.
pub fn rod_lock_angles_closed_form(mu: f64) -> Option<(f64, f64)> {
    let disc = 9.0 - 16.0 * mu * mu;
    if mu <= 0.0 || disc <= 0.0 {
        return None;
    }
    // formula: smaller root of mu q^2 - 3 q + 4 mu = 0, (3 - sqrt(D))/(2 mu), written
    // as 8 mu/(3 + sqrt(D)) (the same number without the cancellation at small mu)
    let q1 = 8.0 * mu / (3.0 + disc.sqrt());
    let q2 = 4.0 / q1; // formula: the product of the roots is 4
    Some((q1.atan(), q2.atan()))
}

/// The impulse ratios `J_l/J_v` at one angle, by two methods, with the raw quantities
/// their rounding bounds read (`rounding.rs`).
#[derive(Debug, Clone, Copy)]
pub struct Ratios {
    /// The lean angle (rad).
    pub theta: f64,
    /// Point-mass model, from its inverted mass matrix.
    pub point_mass: f64,
    /// Uniform rod, from its inverted mass matrix.
    pub rod: f64,
    /// Point-mass model, Newton-Euler impulse equations (I_G = 0).
    pub point_mass_ne: f64,
    /// Uniform rod, Newton-Euler impulse equations (a 5x5 linear solve).
    pub rod_ne: f64,
    /// The rod's 2x2 inversion as it ran (mobility, inverse, residual).
    pub rod_inversion: Inversion2,
    /// The rod's 5x5 solve as it ran (system, solution, residual).
    pub rod_solve: Solve5,
    /// The point mass's 5x5 solve as it ran.
    pub point_mass_solve: Solve5,
}

/// The rod's mobility W^ at `theta` (rad) as `effective_mass` builds it, its computed
/// inverse (the mass matrix, kg) and the computed residual fl(I - W^ M^).
pub fn rod_inversion(theta: f64) -> Inversion2 {
    let off = rod_contact_offset(theta, LENGTH_M);
    let w = mobility(&rod(), off).unwrap_or(Matrix2::repeat(f64::NAN)); // a rod has I_G > 0
    let m = effective_mass(&rod(), off);
    Inversion2 {
        mobility: w,
        inverse: m,
        residual: Matrix2::identity() - w * m,
    }
}

/// The Newton-Euler system `impulse_for_velocity_change` solves for C's velocity change
/// `dv` (rebuilt entry for entry: its entries are copies of m, I_G and r, no arithmetic),
/// its solution as that function returns it and the computed residual.
pub fn newton_euler_solve(body: &RigidBody, off: Vector2<f64>, dv: Vector2<f64>) -> Solve5 {
    let (m, i, p) = (body.mass_kg, body.inertia_kgm2, perp(off));
    #[rustfmt::skip]
    let a = Matrix5::new(
        m,   0.0, 0.0, -1.0,  0.0,
        0.0, m,   0.0, 0.0,   -1.0,
        0.0, 0.0, i,   off.y, -off.x,
        1.0, 0.0, p.x, 0.0,   0.0,
        0.0, 1.0, p.y, 0.0,   0.0,
    );
    let b = Vector5::new(0.0, 0.0, 0.0, dv.x, dv.y);
    let x = impulse_for_velocity_change(body, off, dv)
        .map(|s| Vector5::new(s.dv_g.x, s.dv_g.y, s.domega, s.impulse.x, s.impulse.y))
        .unwrap_or(Vector5::repeat(f64::NAN));
    Solve5 {
        a,
        b,
        x,
        residual: b - a * x,
    }
}

/// The ratios at `theta` (rad).
pub fn ratios_at(theta: f64) -> Ratios {
    let (m_rod, m_pm) = matrices(theta);
    let up = Vector2::new(0.0, 1.0);
    let rod_solve = newton_euler_solve(&rod(), rod_contact_offset(theta, LENGTH_M), up);
    let point_mass_solve = newton_euler_solve(
        &RigidBody::point_mass(MASS_KG),
        tip_contact_offset(theta, LENGTH_M),
        up,
    );
    Ratios {
        theta,
        point_mass: jam_ratio(&m_pm),
        rod: jam_ratio(&m_rod),
        point_mass_ne: point_mass_solve.x[3] / point_mass_solve.x[4], // formula: J_l/J_v
        rod_ne: rod_solve.x[3] / rod_solve.x[4],
        rod_inversion: rod_inversion(theta),
        rod_solve,
        point_mass_solve,
    }
}

/// The rod's best angle as found, and the three points that certify it: the rod's ratio
/// (from its mass matrix) at `theta_rad - h_rad`, `theta_rad` and `theta_rad + h_rad`.
#[derive(Debug, Clone, Copy)]
pub struct BestProbe {
    /// The golden-section argmax (rad).
    pub theta_rad: f64,
    /// The probe's half-width (rad).
    pub h_rad: f64,
    /// The ratios at θ - h, θ, θ + h.
    pub ratio: [f64; 3],
    /// The inversions behind them.
    pub inversion: [Inversion2; 3],
}

impl BestProbe {
    /// Both computed drops from the middle exceed the three ratios' rounding bounds:
    /// the exact ratio is then larger at θ than at θ ± h, and, unimodal, has its
    /// maximum within h of θ.
    pub fn certified(&self) -> bool {
        let e = self.inversion.map(|i| rod_ratio_error(&i));
        let drop = |k: usize| self.ratio[1] - self.ratio[k];
        drop(0) > e[0] + e[1] && drop(2) > e[1] + e[2] // formula: f^(θ) - f^(θ±h) > e(θ) + e(θ±h)
    }
}

/// Golden section for the rod's largest ratio, then the smallest probe half-width
/// h = 1e-9 2^k rad (up to 1e-3 rad) that [`BestProbe::certified`] accepts.
fn best_probe() -> BestProbe {
    let theta = golden_max(rod_ratio, 0.0, std::f64::consts::FRAC_PI_2 - 1e-9, 1e-12);
    let mut h = 1e-9;
    loop {
        let inversion = [theta - h, theta, theta + h].map(rod_inversion);
        let probe = BestProbe {
            theta_rad: theta,
            h_rad: h,
            ratio: inversion.map(|i| jam_ratio(&i.inverse)),
            inversion,
        };
        if probe.certified() || h > 1e-3 {
            return probe;
        }
        h *= 2.0;
    }
}

/// Everything the claims and results read.
#[derive(Debug, Clone)]
pub struct Evidence {
    /// The rod's mass matrix in stick coordinates (kg).
    pub stick: Matrix2<f64>,
    /// The document's derivation with a unit force (1 N) across the stick at C:
    /// acceleration of G (m/s^2, vector), dω/dt (rad/s^2), acceleration of C (vector).
    pub a_g: Vector2<f64>,
    /// See `a_g`.
    pub omega_dot: f64,
    /// See `a_g`.
    pub a_c: Vector2<f64>,
    /// The unit normal across the stick.
    pub normal: Vector2<f64>,
    /// The rod's I_G (kg m^2).
    pub inertia_kgm2: f64,
    /// The ratios at the chosen angle.
    pub at: Ratios,
    /// ... at 30 degrees (q, 1/q and q^2 differ).
    pub at30: Ratios,
    /// ... at 45 degrees (the document's example).
    pub at45: Ratios,
    /// The rod's angle of largest ratio (rad), golden-section search, with its
    /// certificate.
    pub best: BestProbe,
    /// The rod's inversion at the chosen angle (the mass matrix `stick` comes from).
    pub inversion: Inversion2,
    /// C's acceleration by the second method (no mass matrix) at the chosen angle under
    /// the unit force across the stick: at rest without gravity.
    pub free_at_rest: FreeAcceleration,
    /// ... spinning at [`FREE_SPIN_RAD_S`] under [`FREE_G_MPS2`].
    pub free_spinning: FreeAcceleration,
}

/// The spin of the second method's spinning state (rad/s): centripetal 7.5 m/s² at L = 0.15 m.
pub const FREE_SPIN_RAD_S: f64 = 10.0;
/// Its gravity (m/s²).
pub const FREE_G_MPS2: f64 = 9.81;

/// The computations at lean angle `theta` (rad).
pub fn gather(theta: f64) -> Evidence {
    let (m_rod, _) = matrices(theta);
    let (a_g, omega_dot, a_c) = contact_acceleration(
        &rod(),
        rod_contact_offset(theta, LENGTH_M),
        stick_normal(theta),
    );
    Evidence {
        stick: in_stick_frame(&m_rod, theta),
        a_g,
        omega_dot,
        a_c,
        normal: stick_normal(theta),
        inertia_kgm2: rod().inertia_kgm2,
        at: ratios_at(theta),
        at30: ratios_at(30f64.to_radians()),
        at45: ratios_at(std::f64::consts::FRAC_PI_4),
        best: best_probe(),
        inversion: rod_inversion(theta),
        free_at_rest: free_acceleration(theta, 0.0, 0.0, stick_normal(theta)),
        free_spinning: free_acceleration(theta, FREE_SPIN_RAD_S, FREE_G_MPS2, stick_normal(theta)),
    }
}

/// C's acceleration on a uniform rod under a contact force, by a second method that
/// never uses the mass matrix: Lagrange's equations in (x_G, z_G, θ), m a_G = F - m g e_z
/// and I_G θ'' = F . dC/dθ (the virtual work of F at C = G - (L/2) e_r(θ)), integrated by
/// RK4 to t = ±h from the state (θ, θ' = `spin_rad_s`, G at rest), and C's acceleration
/// taken as the central difference (C(h) - 2 C(0) + C(-h))/h².
#[derive(Debug, Clone, Copy)]
pub struct FreeAcceleration {
    /// C's acceleration at step h (m/s², world frame).
    pub a_c: Vector2<f64>,
    /// Its error estimate: the difference to the value at h/2, times 4/3 (Richardson for
    /// a second-order difference puts the h/2 value's error at a third of it: a margin
    /// of 4), plus the rounding of the difference quotient (m/s²).
    pub error_mps2: f64,
}

/// [`FreeAcceleration`] at lean `theta` (rad), spin `spin_rad_s`, gravity `g_mps2`, for
/// the contact force `force_n` (N, world frame) held constant.
fn free_acceleration(
    theta: f64,
    spin_rad_s: f64,
    g_mps2: f64,
    force_n: Vector2<f64>,
) -> FreeAcceleration {
    let body = rod();
    let half = 0.5 * LENGTH_M;
    // State: [x_G, z_G, θ, x_G', z_G', θ'].
    let rhs = |s: [f64; 6]| -> [f64; 6] {
        let dc_dtheta = Vector2::new(-half * s[2].cos(), half * s[2].sin()); // formula: dC/dθ = -(L/2) (cos θ, -sin θ)
        [
            s[3],
            s[4],
            s[5],
            force_n.x / body.mass_kg,          // formula: m x_G'' = F_x
            force_n.y / body.mass_kg - g_mps2, // formula: m z_G'' = F_z - m g
            force_n.dot(&dc_dtheta) / body.inertia_kgm2, // formula: I_G θ'' = F . dC/dθ
        ]
    };
    let axpy =
        |s: [f64; 6], k: [f64; 6], a: f64| std::array::from_fn::<f64, 6, _>(|i| s[i] + a * k[i]);
    let rk4 = |s: [f64; 6], h: f64| {
        let k1 = rhs(s);
        let k2 = rhs(axpy(s, k1, h / 2.0));
        let k3 = rhs(axpy(s, k2, h / 2.0));
        let k4 = rhs(axpy(s, k3, h));
        std::array::from_fn::<f64, 6, _>(|i| {
            s[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])
        })
    };
    let c_of = |s: [f64; 6]| Vector2::new(s[0] - half * s[2].sin(), s[1] - half * s[2].cos()); // formula: C = G - (L/2) e_r
    let s0 = [0.0, 0.0, theta, 0.0, 0.0, spin_rad_s];
    let second_difference = |h: f64| {
        let n = 16; // RK4 substeps: local error (h/16)^5 terms, far below the difference's h^2
        let (mut fwd, mut bwd) = (s0, s0);
        for _ in 0..n {
            fwd = rk4(fwd, h / n as f64);
            bwd = rk4(bwd, -h / n as f64);
        }
        (c_of(fwd) - 2.0 * c_of(s0) + c_of(bwd)) / (h * h) // formula: C'' ~ (C(h) - 2 C(0) + C(-h))/h^2
    };
    let h = 1e-3;
    let (a_h, a_half) = (second_difference(h), second_difference(h / 2.0));
    let rounding = 8.0 * f64::EPSILON * LENGTH_M / (0.25 * h * h); // a few ulps of C over (h/2)^2
    FreeAcceleration {
        a_c: a_half,
        error_mps2: (a_h - a_half).norm() * 4.0 / 3.0 + rounding,
    }
}
