//! The benchmark scene of the block (section 3.1.2's scene): a block on a vertically
//! vibrating plate `z_p = delta sin(omega t)` pushed sideways by a small bias force
//! `F = b mu m g` (the bias `b = F/(mu m g)`, as in every chapter), with Coulomb friction
//! `mu` and Newton restitution `e`.
//!
//! Only the scene's data: the physics is the workbook's block model,
//! [`crate::physics::block`], run event-driven ([`crate::physics::block::simulate_block`])
//! or by Moreau-Jean through its contact form
//! ([`crate::physics::block::contact_form::BlockContact`]).

use crate::physics::block::BlockParams;
use crate::physics::plate::{Axis, Harmonic, PlateMotion};

/// The scene: block parameters, the plate, and the bias over the sliding friction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlockScene {
    /// The block's parameters (Coulomb friction, bias acceleration `b mu g`,
    /// restitution, rest velocity).
    pub params: BlockParams,
    /// The plate's vertical motion.
    pub plate: Harmonic,
    /// Bias force over the sliding friction, `b = F/(mu m g)` (dimensionless).
    pub bias: f64,
}

impl BlockScene {
    /// A scene at peak plate acceleration `gamma g` and frequency `frequency_hz`, friction
    /// `mu`, bias `bias = F/(mu m g)` and gravity `g` (m/s^2), with
    /// completely inelastic landings and no rest threshold (`restitution` and
    /// `rest_velocity_mps` of [`BlockScene::params`] are 0).
    pub fn new(frequency_hz: f64, gamma: f64, mu: f64, bias: f64, g: f64) -> Self {
        let omega = std::f64::consts::TAU * frequency_hz;
        let plate = Harmonic::sine(Axis::Z, gamma * g / (omega * omega), frequency_hz); // formula: delta = Gamma g / omega^2
        let mut params = BlockParams::coulomb(g, mu, bias * mu * g); // formula: F/m = b mu g
        params.rest_velocity_mps = 0.0;
        BlockScene {
            params,
            plate,
            bias,
        }
    }

    /// The same scene with restitution `e` and rest velocity `rest_velocity_mps` (m/s).
    pub fn with_restitution(self, e: f64, rest_velocity_mps: f64) -> Self {
        let mut s = self;
        s.params.restitution = e;
        s.params.rest_velocity_mps = rest_velocity_mps;
        s
    }

    /// Gravity (m/s^2).
    pub fn g(&self) -> f64 {
        self.params.g_mps2
    }

    /// Drive period (s).
    pub fn period_s(&self) -> f64 {
        self.plate.period_s()
    }
}
