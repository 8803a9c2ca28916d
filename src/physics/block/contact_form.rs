//! The block as one frictional unilateral contact for Moreau-Jean time-stepping: an
//! adapter of [`BlockParams`] and the plate to
//! [`crate::numerics::timestepping::ContactModel`].
//!
//! The same physics as the event-driven [`super::BlockSystem`], written as a measure
//! differential inclusion: per unit mass, in **absolute** coordinates `q = (x, z)` (m),
//! `v = (v_x, v_z)` (m/s), unit mass matrix, free forces the bias `b` along x and gravity
//! `-g` along z. The contact is the plate: gap `z - z_p(t)`, normal `(0, 1)`, tangent
//! `(1, 0)`, the plate's velocity `(v_zp, v_xp)` as the obstacle's. Newton's restitution
//! `e` and Coulomb's `mu` act on the impulses over a step, so impacts, sticking and
//! sliding all come out of the step's local problem (see the timestepping module).
//!
//! Only Coulomb friction fits this form ([`BlockContact::new`] returns `None` otherwise);
//! the impacts are Coulomb impacts whatever [`BlockParams::impact`] says, and
//! [`BlockParams::rest_velocity_mps`] has no counterpart (a rebound slower than about
//! `g h` is lost within a step anyway).

use super::BlockParams;
use crate::numerics::timestepping::ContactModel;
use crate::physics::friction::FrictionLaw;
use crate::physics::plate::PlateMotion;

/// The block on a plate `P` as a Moreau-Jean [`ContactModel`] with `N = 2`.
#[derive(Debug, Clone)]
pub struct BlockContact<'a, P: PlateMotion + ?Sized> {
    /// Parameters (Coulomb friction).
    pub params: BlockParams,
    /// The plate.
    pub plate: &'a P,
    mu: f64,
}

impl<'a, P: PlateMotion + ?Sized> BlockContact<'a, P> {
    /// The contact form of the block, or `None` unless the friction law is Coulomb's.
    pub fn new(params: BlockParams, plate: &'a P) -> Option<Self> {
        match params.friction {
            FrictionLaw::Coulomb { mu } => Some(BlockContact { params, plate, mu }),
            _ => None,
        }
    }

    /// Absolute `(q, v)` of the block resting on the plate at `t` (at the plate's
    /// horizontal position and velocity plus `(u, w)`).
    pub(crate) fn on_plate(&self, t: f64, u: f64, w: f64) -> ([f64; 2], [f64; 2]) {
        let p = self.plate;
        ([u + p.x_m(t), p.z_m(t)], [w + p.vx_mps(t), p.vz_mps(t)])
    }
}

impl<P: PlateMotion + ?Sized> ContactModel<2> for BlockContact<'_, P> {
    fn inv_mass(&self, _t: f64, _q: &[f64; 2], _h: f64) -> [[f64; 2]; 2] {
        [[1.0, 0.0], [0.0, 1.0]] // per unit mass
    }

    fn free_velocity(&self, _t: f64, _q: &[f64; 2], v: &[f64; 2], h: f64) -> [f64; 2] {
        let (g, b) = (self.params.g_mps2, self.params.bias_mps2);
        [v[0] + h * b, v[1] - h * g] // formula: v_free = v + h (b, -g)
    }

    fn gap(&self, t: f64, q: &[f64; 2]) -> f64 {
        q[1] - self.plate.z_m(t) // formula: gap = z - z_p
    }

    fn jacobians(&self, _t: f64, _q: &[f64; 2]) -> ([f64; 2], [f64; 2]) {
        ([0.0, 1.0], [1.0, 0.0])
    }

    fn obstacle_velocity(&self, t: f64) -> (f64, f64) {
        (self.plate.vz_mps(t), self.plate.vx_mps(t))
    }

    fn restitution(&self) -> f64 {
        self.params.restitution
    }

    fn mu(&self) -> f64 {
        self.mu
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::timestepping::{simulate, MjOptions};
    use crate::physics::plate::{Axis, Harmonic};

    #[test]
    fn only_coulomb_friction_has_a_contact_form() {
        let plate = Harmonic::sine(Axis::Z, 0.0, 1.0);
        assert!(BlockContact::new(BlockParams::viscous(9.81, 2.0, 0.0), &plate).is_none());
        assert!(BlockContact::new(BlockParams::coulomb(9.81, 0.3, 0.0), &plate).is_some());
    }

    #[test]
    fn a_block_sliding_on_a_plate_at_rest_stops_after_v0_squared_over_2_mu_g() {
        // Closed form: constant deceleration mu g from v0 = 1 m/s, mu = 0.5: it stops
        // after v0^2/(2 mu g) = 0.1019 m. Moreau-Jean at h = 1e-4 s is first order: the
        // distance is off by O(v0 h) = 1e-4 m; the bound is 5e-4 m.
        let (g, mu) = (9.81, 0.5);
        let plate = Harmonic::sine(Axis::Z, 0.0, 1.0);
        let c = BlockContact::new(BlockParams::coulomb(g, mu, 0.0), &plate).unwrap();
        let (q0, mut v0) = c.on_plate(0.0, 0.0, 0.0);
        v0[0] = 1.0;
        let run = simulate(&c, 0.0, q0, v0, 0.5, &MjOptions::midpoint(1e-4), |_| {}).unwrap();
        let expected = 1.0 / (2.0 * mu * g); // formula: d = v0^2 / (2 mu g)
        assert!(
            (run.q[0] - expected).abs() < 5e-4,
            "{} vs {expected}",
            run.q[0]
        );
        assert_eq!(run.v[0], 0.0, "stuck");
        assert!(
            run.q[1].abs() < 1e-9 && run.v[1].abs() < 1e-12,
            "stays on the floor"
        );
    }

    #[test]
    fn a_block_within_the_friction_cone_follows_a_horizontally_shaken_plate() {
        // Plate x_p = delta sin(omega t) with peak acceleration 0.5 g and mu = 1: the
        // needed friction stays inside the cone, so the block sticks: its velocity is the
        // plate's (the tangential obstacle velocity) and it never drifts. Moreau-Jean
        // matches the plate velocity at each step's midpoint, so the block's position
        // stays within O(h delta omega) = 2e-6 m of the plate's; the bound is 1e-5 m.
        let (g, f) = (9.81, 5.0);
        let omega = std::f64::consts::TAU * f;
        let plate = Harmonic::sine(Axis::X, 0.5 * g / (omega * omega), f);
        let c = BlockContact::new(BlockParams::coulomb(g, 1.0, 0.0), &plate).unwrap();
        let (q0, v0) = c.on_plate(0.0, 0.0, 0.0);
        let mut worst: f64 = 0.0;
        let t_end = 10.0 / f;
        let run = simulate(&c, 0.0, q0, v0, t_end, &MjOptions::midpoint(1e-4), |s| {
            worst = worst.max((s.q1[0] - plate.x_m(s.t1)).abs());
        })
        .unwrap();
        assert!(worst < 1e-5, "{worst}");
        assert!(run.stats.slide_steps == 0, "{:?}", run.stats);
    }
}
