//! The benchmark scene of the block: a block on a vertically vibrating plate
//! `z_p = delta sin(omega t)` pushed sideways by a small bias force `F = b m g`, with
//! Coulomb friction `mu` and Newton restitution `e` (section 3.1.2's scene).
//!
//! The same physics in two forms, so that the chapter can compare methods on it:
//! - [`BlockScene`] as a [`HybridSystem`] (modes flight, stick, slide +/-), whose flows
//!   are integrated by the chosen method, or taken in closed form (`closed_form`);
//! - [`BlockScene`] as a Moreau-Jean [`ContactModel`] (one frictional contact).
//!
//! State of the hybrid form: `y = [x, x', z, z']` (m, m/s). In contact `z = z_p(t)`.
//! Contact force `N = m (g + z_p'')`; takeoff when `N` falls to zero. Impacts are
//! Newton's law with impulsive Coulomb friction: the normal impulse `P_n = m (1 + e)
//! (z_p' - z')` removes up to `mu P_n / m` of horizontal speed (to zero: a sticking
//! collision, the document's "instantaneous sticking collisions").

use crate::numerics::events::Direction;
use crate::numerics::hybrid::{HybridSystem, Transition};
use crate::numerics::timestepping::ContactModel;
use crate::physics::plate::{Axis, Harmonic, PlateMotion};

/// Modes of the block.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BlockMode {
    /// Off the plate: ballistic, pushed by the bias force.
    Flight,
    /// On the plate, not sliding.
    Stick,
    /// On the plate, sliding towards +x.
    SlidePos,
    /// On the plate, sliding towards -x.
    SlideNeg,
}

/// The scene's parameters and the choice of flow (integrated or closed form).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlockScene {
    /// The plate's vertical motion.
    pub plate: Harmonic,
    /// Coulomb friction coefficient.
    pub mu: f64,
    /// Bias force over weight, `b = F/(m g)`.
    pub bias: f64,
    /// Restitution coefficient in `[0, 1)`.
    pub e: f64,
    /// Gravity (m/s^2).
    pub g: f64,
    /// Rebounds slower than this relative speed (m/s) end in contact: the sticking
    /// transition that cuts a Zeno accumulation short. 0: never (Zeno possible).
    pub stick_below_mps: f64,
    /// Use the closed forms of every mode (true) or integrate the flows (false).
    pub closed_form: bool,
}

impl BlockScene {
    /// A scene at peak plate acceleration `gamma g` and frequency `frequency_hz`.
    pub fn new(frequency_hz: f64, gamma: f64, mu: f64, bias: f64, g: f64) -> Self {
        let omega = std::f64::consts::TAU * frequency_hz;
        let plate = Harmonic::sine(Axis::Z, gamma * g / (omega * omega), frequency_hz); // formula: delta = Gamma g / omega^2
        BlockScene {
            plate,
            mu,
            bias,
            e: 0.0,
            g,
            stick_below_mps: 0.0,
            closed_form: false,
        }
    }

    /// Drive period (s).
    pub fn period_s(&self) -> f64 {
        self.plate.period_s()
    }

    /// Normal force per unit mass in contact, `g + z_p''` (m/s^2).
    fn normal(&self, t: f64) -> f64 {
        self.g + self.plate.az_mps2(t) // formula: N/m = g + z_p''
    }

    /// The contact mode entered with horizontal velocity `vx` at `t`.
    fn contact_mode(&self, t: f64, vx: f64) -> BlockMode {
        if vx > 0.0 {
            BlockMode::SlidePos
        } else if vx < 0.0 {
            BlockMode::SlideNeg
        } else if self.mu * self.normal(t) >= self.bias.abs() * self.g {
            BlockMode::Stick // formula: |F| <= mu N
        } else if self.bias > 0.0 {
            BlockMode::SlidePos
        } else {
            BlockMode::SlideNeg
        }
    }

    /// The state on the plate at `t` with horizontal position and velocity `(x, vx)`.
    fn on_plate(&self, t: f64, x: f64, vx: f64) -> [f64; 4] {
        [x, vx, self.plate.z_m(t), self.plate.vz_mps(t)]
    }

    /// Sliding direction of a slide mode (0 otherwise).
    fn sigma(mode: BlockMode) -> f64 {
        match mode {
            BlockMode::SlidePos => 1.0,
            BlockMode::SlideNeg => -1.0,
            _ => 0.0,
        }
    }
}

impl HybridSystem<4> for BlockScene {
    type Mode = BlockMode;
    type Stop = ();

    fn flow(&self, mode: BlockMode, t: f64, y: &[f64; 4]) -> [f64; 4] {
        let f = self.bias * self.g; // formula: F/m = b g
        match mode {
            BlockMode::Flight => [y[1], f, y[3], -self.g], // formula: x'' = F/m, z'' = -g
            BlockMode::Stick => [0.0, 0.0, y[3], self.plate.az_mps2(t)],
            s => {
                let sg = Self::sigma(s);
                // formula: x'' = F/m - sigma mu (g + z_p'')
                [
                    y[1],
                    f - sg * self.mu * self.normal(t),
                    y[3],
                    self.plate.az_mps2(t),
                ]
            }
        }
    }

    fn exact(&self, mode: BlockMode, t0: f64, y0: &[f64; 4], t: f64) -> Option<[f64; 4]> {
        if !self.closed_form {
            return None;
        }
        let s = t - t0;
        let f = self.bias * self.g;
        Some(match mode {
            // formula: ballistic x = x0 + v0 s + F/(2m) s^2, z = z0 + w0 s - g s^2 / 2
            BlockMode::Flight => [
                y0[0] + y0[1] * s + 0.5 * f * s * s,
                y0[1] + f * s,
                y0[2] + y0[3] * s - 0.5 * self.g * s * s,
                y0[3] - self.g * s,
            ],
            BlockMode::Stick => self.on_plate(t, y0[0], 0.0),
            m => {
                let sg = Self::sigma(m);
                let (p, a) = (&self.plate, f - sg * self.mu * self.g);
                // formula: vx = vx0 + (F/m - sigma mu g) s - sigma mu (z_p'(t) - z_p'(t0))
                let vx = y0[1] + a * s - sg * self.mu * (p.vz_mps(t) - p.vz_mps(t0));
                // formula: x = x0 + vx0 s + (F/m - sigma mu g) s^2/2 - sigma mu (z_p(t) - z_p(t0) - z_p'(t0) s)
                let x = y0[0] + y0[1] * s + 0.5 * a * s * s
                    - sg * self.mu * (p.z_m(t) - p.z_m(t0) - p.vz_mps(t0) * s);
                self.on_plate(t, x, vx)
            }
        })
    }

    fn guard_count(&self, mode: BlockMode) -> usize {
        match mode {
            BlockMode::Flight => 1,
            _ => 2,
        }
    }

    fn guard(&self, mode: BlockMode, i: usize, t: f64, y: &[f64; 4]) -> f64 {
        match (mode, i) {
            (BlockMode::Flight, _) => y[2] - self.plate.z_m(t), // gap
            (_, 0) => self.normal(t),                           // takeoff: N/m falls to 0
            (BlockMode::Stick, _) => self.mu * self.normal(t) - self.bias.abs() * self.g, // slip: mu N falls to |F|
            (m, _) => Self::sigma(m) * y[1], // slide stops: sigma x' falls to 0
        }
    }

    fn direction(&self, _mode: BlockMode, _i: usize) -> Direction {
        Direction::Falling
    }

    fn on_event(
        &self,
        mode: BlockMode,
        i: usize,
        t: f64,
        y: &[f64; 4],
    ) -> Transition<BlockMode, (), 4> {
        let next = match (mode, i) {
            (BlockMode::Flight, _) => {
                let u = y[3] - self.plate.vz_mps(t); // relative normal velocity (< 0)
                let pn = (1.0 + self.e) * (-u).max(0.0); // formula: P_n/m = (1 + e)(z_p' - z')
                let slip = self.mu * pn; // formula: |dP_t| <= mu P_n
                let vx = if y[1].abs() <= slip {
                    0.0
                } else {
                    y[1] - y[1].signum() * slip
                };
                let rebound = -self.e * u; // formula: u+ = -e u-
                if rebound > self.stick_below_mps || self.normal(t) <= 0.0 {
                    let z = self.plate.z_m(t);
                    return Transition::To {
                        mode: BlockMode::Flight,
                        state: [y[0], vx, z, self.plate.vz_mps(t) + rebound],
                    };
                }
                (self.contact_mode(t, vx), vx)
            }
            (_, 0) => (BlockMode::Flight, y[1]),
            (BlockMode::Stick, _) => (
                if self.bias >= 0.0 {
                    BlockMode::SlidePos
                } else {
                    BlockMode::SlideNeg
                },
                0.0,
            ),
            (_, _) => (self.contact_mode(t, 0.0), 0.0),
        };
        Transition::To {
            mode: next.0,
            state: self.on_plate(t, y[0], next.1),
        }
    }

    fn max_step(&self, mode: BlockMode, t: f64, y: &[f64; 4]) -> f64 {
        let sample = self.period_s() / 20.0;
        if mode == BlockMode::Flight {
            // Leaving the plate the gap starts at 0: the first step must end before it
            // can close again. With relative speed u and relative acceleration at most
            // g (1 + Gamma), the gap stays positive for 2u / (g (1 + Gamma)).
            let gap = y[2] - self.plate.z_m(t);
            let u = y[3] - self.plate.vz_mps(t);
            if gap <= 0.0 && u > 0.0 {
                let a = self.g + self.plate.peak_acceleration_mps2();
                return sample.min(u / a);
            }
        }
        sample
    }
}

impl ContactModel<2> for BlockScene {
    // q = (x, z), v = (x', z'); unit mass (the scene is per unit mass).
    fn inv_mass(&self, _t: f64, _q: &[f64; 2], _h: f64) -> [[f64; 2]; 2] {
        [[1.0, 0.0], [0.0, 1.0]]
    }
    fn free_velocity(&self, _t: f64, _q: &[f64; 2], v: &[f64; 2], h: f64) -> [f64; 2] {
        [v[0] + h * self.bias * self.g, v[1] - h * self.g] // formula: v_free = v + h (F/m, -g)
    }
    fn gap(&self, t: f64, q: &[f64; 2]) -> f64 {
        q[1] - self.plate.z_m(t)
    }
    fn jacobians(&self, _t: f64, _q: &[f64; 2]) -> ([f64; 2], [f64; 2]) {
        ([0.0, 1.0], [1.0, 0.0])
    }
    fn obstacle_velocity(&self, t: f64) -> (f64, f64) {
        (self.plate.vz_mps(t), 0.0)
    }
    fn restitution(&self) -> f64 {
        self.e
    }
    fn mu(&self) -> f64 {
        self.mu
    }
}
