//! Effective mass matrices and impact maps of a planar rigid body (document section 2).
//!
//! Frame: x horizontal (right positive), z vertical (up positive). A stick leans at
//! angle `theta` from the vertical towards +x; C is its bottom (contact) end, P its top.
//! The unit vector along the stick from C to P is `e = (sin theta, cos theta)` and
//! `n = (cos theta, -sin theta)` is orthogonal to it (the document's x' and z').
//!
//! Rotations: the motion is in the x-z plane, so an angular velocity or a moment points
//! along the normal of that plane, `j` (the y axis), never along `k`, the vertical (the
//! mistake of the document's C.15, chapter 6). With x to the right and z up, `j` points
//! into the page; this module counts rotations counter-clockwise as seen on the page,
//! i.e. about `-j`: a rate `omega` here is the component of the angular velocity along
//! `-j`, and for the stick's lean `theta` (clockwise, P to the right of C) it is
//! `omega = -theta'`.
//!
//! For a body of mass m and moment of inertia `I_G` about its centre of mass G, a
//! contact point C at `r = C - G` has the mobility (inverse mass)
//! `W = 1/m * Id + perp(r) perp(r)^T / I_G`, with `perp(r) = (-j) x r = (-r_z, r_x)`
//! (`r` turned counter-clockwise by 90 degrees): an impulse J at C changes the velocity of
//! C by `W J` (translation `J/m` plus the rotation `cross(r, J)/I_G`, the moment's
//! component along `-j`, carrying C along `perp(r)`). The effective mass matrix is
//! `M = W^-1`. A massless rod with a tip mass has `I_G = 0` about G = P: its mobility
//! across the rod is infinite and `M = m e e^T` (rank one), the limit `I_G -> 0`.

use nalgebra::{Matrix2, Matrix5, Vector2, Vector5};

/// A planar rigid body: mass and moment of inertia about its centre of mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidBody {
    /// Mass m (kg).
    pub mass_kg: f64,
    /// Moment of inertia about the centre of mass G (kg m^2); 0 for a point mass.
    pub inertia_kgm2: f64,
}

impl RigidBody {
    /// A uniform rod of mass m and length L: `I_G = m L^2 / 12`.
    pub fn uniform_rod(mass_kg: f64, length_m: f64) -> Self {
        RigidBody {
            mass_kg,
            inertia_kgm2: mass_kg * length_m * length_m / 12.0,
        } // formula: I = m L^2/12
    }

    /// A point mass m (the tip mass of a massless rod): `I_G = 0`.
    pub fn point_mass(mass_kg: f64) -> Self {
        RigidBody {
            mass_kg,
            inertia_kgm2: 0.0,
        }
    }
}

/// Unit vector along a stick leaning `theta_rad` from the vertical, from C to P.
pub(crate) fn stick_axis(theta_rad: f64) -> Vector2<f64> {
    Vector2::new(theta_rad.sin(), theta_rad.cos())
}

/// Unit vector orthogonal to the stick (the document's z' direction).
pub(crate) fn stick_normal(theta_rad: f64) -> Vector2<f64> {
    Vector2::new(theta_rad.cos(), -theta_rad.sin())
}

/// `(-j) x r = (-r_z, r_x)`: the velocity direction of a point at `r` under a positive
/// (counter-clockwise, about `-j`) rotation; `j` is the normal of the x-z plane.
pub(crate) fn perp(r: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-r.y, r.x)
}

/// The planar cross product of `r` and an impulse or force `J`: the component of
/// `r x J` along `-j` (the normal of the x-z plane), `r_x J_z - r_z J_x`, positive for a
/// counter-clockwise moment.
pub(crate) fn cross(r: Vector2<f64>, j: Vector2<f64>) -> f64 {
    r.x * j.y - r.y * j.x
}

// ANCHOR: mobility
/// Mobility W of the point at `r = C - G` (m/s per N s); `None` when `I_G = 0`
/// (infinite mobility across `r`).
pub fn mobility(body: &RigidBody, r: Vector2<f64>) -> Option<Matrix2<f64>> {
    if body.inertia_kgm2 <= 0.0 {
        return None;
    }
    let p = perp(r);
    Some(Matrix2::identity() / body.mass_kg + p * p.transpose() / body.inertia_kgm2)
    // formula: W = I/m + r_perp r_perp^T / I_G
}
// ANCHOR_END: mobility

// ANCHOR: effective_mass
/// Effective mass matrix `M = W^-1` of the point at `r = C - G` in world
/// coordinates (kg); for `I_G = 0` the rank-one limit `m r^ r^T` (a force at C can
/// only act along the line through G).
pub fn effective_mass(body: &RigidBody, r: Vector2<f64>) -> Matrix2<f64> {
    match mobility(body, r).and_then(|w| w.try_inverse()) {
        Some(m) => m,
        None => {
            let u = r.normalize();
            body.mass_kg * u * u.transpose() // formula: M = m e e^T (massless rod, tip mass)
        }
    }
}
// ANCHOR_END: effective_mass

/// A world-frame 2x2 tensor in stick coordinates (x' along, z' across): `R^T M R`.
pub fn in_stick_frame(m: &Matrix2<f64>, theta_rad: f64) -> Matrix2<f64> {
    let r = Matrix2::from_columns(&[stick_axis(theta_rad), stick_normal(theta_rad)]);
    r.transpose() * m * r
}

/// `r = C - G` for a uniform rod leaning `theta_rad` (G at the middle).
pub fn rod_contact_offset(theta_rad: f64, length_m: f64) -> Vector2<f64> {
    -0.5 * length_m * stick_axis(theta_rad)
}

/// `r = C - G` for a massless rod with its mass at the top P (G = P).
pub fn tip_contact_offset(theta_rad: f64, length_m: f64) -> Vector2<f64> {
    -length_m * stick_axis(theta_rad)
}

/// The impulse needed to change the contact velocity by `dv` when C does not slip:
/// `J = M dv`; the ratio `J_x / J_z` for a vertical `dv` is `M_xz / M_zz`.
pub fn jam_ratio(m: &Matrix2<f64>) -> f64 {
    m[(0, 1)] / m[(1, 1)] // formula: J_l/J_v = M_xz/M_zz
}

/// Result of an impact solved from the Newton-Euler impulse equations.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Impact {
    /// Impulse J applied at C (N s).
    pub impulse: Vector2<f64>,
    /// Velocity change of the centre of mass (m/s).
    pub dv_g: Vector2<f64>,
    /// Change of angular velocity (rad/s).
    pub domega: f64,
}

/// Second method: solves `m dv_G = J`, `I_G domega = r x J`, `dv_G + domega perp(r) = dv`
/// (5 linear equations, LU) for the impulse at C that changes C's velocity by `dv`.
/// Works for `I_G = 0` too (then `r x J = 0`). `None` if the system is singular.
pub fn impulse_for_velocity_change(
    body: &RigidBody,
    r: Vector2<f64>,
    dv: Vector2<f64>,
) -> Option<Impact> {
    let (m, i) = (body.mass_kg, body.inertia_kgm2);
    let p = perp(r);
    // Unknowns (dvG_x, dvG_z, domega, J_x, J_z).
    #[rustfmt::skip]
    let a = Matrix5::new(
        m,   0.0, 0.0, -1.0, 0.0,   // formula: m dvG_x = J_x
        0.0, m,   0.0, 0.0,  -1.0,  // formula: m dvG_z = J_z
        0.0, 0.0, i,   r.y,  -r.x,  // formula: I domega = r_x J_z - r_z J_x
        1.0, 0.0, p.x, 0.0,  0.0,   // formula: dv_C = dv_G + domega (-j) x r
        0.0, 1.0, p.y, 0.0,  0.0,
    );
    let b = Vector5::new(0.0, 0.0, 0.0, dv.x, dv.y);
    let x = a.lu().solve(&b)?;
    Some(Impact {
        impulse: Vector2::new(x[3], x[4]),
        dv_g: Vector2::new(x[0], x[1]),
        domega: x[2],
    })
}

/// The document's derivation for a body at rest: a force F at C gives
/// `a_G = F/m`, `omega_dot = (r x F)/I_G` and `a_C = a_G + omega_dot perp(r)`.
/// Returns `(a_G, omega_dot, a_C)`; requires `I_G > 0`.
pub(crate) fn contact_acceleration(
    body: &RigidBody,
    r: Vector2<f64>,
    f: Vector2<f64>,
) -> (Vector2<f64>, f64, Vector2<f64>) {
    let a_g = f / body.mass_kg; // formula: a_G = F/m
    let omega_dot = cross(r, f) / body.inertia_kgm2; // formula: omega_dot = (F L/2)/I
    (a_g, omega_dot, a_g + omega_dot * perp(r)) // formula: a_C = a_G + a_C/G
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn rod_mass_matrix_is_m_and_m_over_4_in_stick_coordinates_at_any_angle() {
        let body = RigidBody::uniform_rod(2.0, 0.3);
        for deg in [-80.0f64, -30.0, 0.0, 10.0, 45.0, 89.0] {
            let t = deg.to_radians();
            let ms = in_stick_frame(&effective_mass(&body, rod_contact_offset(t, 0.3)), t);
            assert_relative_eq!(ms, Matrix2::new(2.0, 0.0, 0.0, 0.5), epsilon = 1e-12);
        }
    }

    #[test]
    fn tip_mass_is_the_limit_of_vanishing_inertia() {
        // The rank-one matrix m e e^T is the limit I_G -> 0 of the inverse mobility:
        // the across component is 1/(1/m + L^2/I_G) ~ I_G/L^2 = eps m, so at
        // I_G = eps m L^2 the two differ by about eps m (the rounding error of the
        // inversion, cond(W) * 2.2e-16 ~ 2e-10 at eps = 1e-6, is far smaller).
        let (m, l, t) = (1.5, 0.2, 0.7f64);
        let exact = effective_mass(&RigidBody::point_mass(m), tip_contact_offset(t, l));
        for eps in [1e-3, 1e-6] {
            let nearly = RigidBody {
                mass_kg: m,
                inertia_kgm2: eps * m * l * l,
            };
            let limit = effective_mass(&nearly, tip_contact_offset(t, l));
            let gap = (exact - limit).abs().max();
            assert!(
                gap <= 1.01 * eps * m && gap >= 0.9 * eps * m * 0.5,
                "eps {eps}: gap {gap}"
            );
        }
        assert_relative_eq!(jam_ratio(&exact), t.tan(), epsilon = 1e-14);
    }

    #[test]
    fn newton_euler_solve_agrees_with_the_mass_matrix() {
        for body in [
            RigidBody::uniform_rod(1.0, 0.15),
            RigidBody::point_mass(1.0),
        ] {
            for deg in [5.0f64, 45.0, 63.0, 85.0] {
                let t = deg.to_radians();
                let r = if body.inertia_kgm2 > 0.0 {
                    rod_contact_offset(t, 0.15)
                } else {
                    tip_contact_offset(t, 0.15)
                };
                let dv = Vector2::new(0.3, 1.1);
                let imp = impulse_for_velocity_change(&body, r, dv).unwrap();
                assert_relative_eq!(
                    imp.impulse,
                    effective_mass(&body, r) * dv,
                    epsilon = 1e-12,
                    max_relative = 1e-12
                );
                // Momentum and angular momentum balance hold for the solution.
                assert_relative_eq!(imp.dv_g * body.mass_kg, imp.impulse, epsilon = 1e-12);
            }
        }
    }

    #[test]
    fn documents_derivation_steps() {
        let (m, l) = (1.0, 0.15);
        let body = RigidBody::uniform_rod(m, l);
        let t = 0.4f64;
        let f = 2.0;
        let (a_g, wdot, a_c) =
            contact_acceleration(&body, rod_contact_offset(t, l), f * stick_normal(t));
        assert_relative_eq!(a_g.norm(), f / m, epsilon = 1e-12);
        assert_relative_eq!(wdot.abs(), f * l / 2.0 / (m * l * l / 12.0), epsilon = 1e-9);
        assert_relative_eq!(a_c.dot(&stick_normal(t)), 4.0 * f / m, epsilon = 1e-12);
        assert_relative_eq!(a_c.dot(&stick_axis(t)), 0.0, epsilon = 1e-12);
    }
}
