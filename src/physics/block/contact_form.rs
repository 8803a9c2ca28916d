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
    pub fn on_plate(&self, t: f64, u: f64, w: f64) -> ([f64; 2], [f64; 2]) {
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
