//! A block (point mass) on a rigid plate that moves in x and z: Coulomb (set-valued) or
//! viscous friction, a constant horizontal bias force, flight, and impacts on landing.
//!
//! # State and modes
//! The state is relative to the plate, per unit mass (the mass cancels everywhere):
//! `y = [u, w, h, vh]` with `u = x - x_p` (m), `w = v_x - v_xp` (m/s), `h = z - z_p` (m),
//! `vh = v_z - v_zp` (m/s). In contact `h = vh = 0`. The absolute position is
//! `x = u + x_p(t)` ([`BlockSystem::absolute`]).
//!
//! Forces per unit mass: normal `n = g + a_zp(t)` while in contact, friction `f`,
//! bias `b` (a constant horizontal force per unit mass, `F/m`).
//!
//! | mode | flow | guards (fire -> next) |
//! |---|---|---|
//! | [`BlockMode::Stick`] | `w = 0` | `n` falls to 0 -> Flight; `mu n - f_need` falls to 0 -> SlipLeft; `mu n + f_need` falls to 0 -> SlipRight, with `f_need = a_xp - b` |
//! | [`BlockMode::SlipRight`] (`w > 0`) | `w' = b - mu n - a_xp` | `n` -> Flight; `w` falls to 0 -> stick test |
//! | [`BlockMode::SlipLeft`] (`w < 0`) | `w' = b + mu n - a_xp` | `n` -> Flight; `w` rises to 0 -> stick test |
//! | [`BlockMode::Viscous`] | `w' = b - c w - a_xp` | `n` -> Flight |
//! | [`BlockMode::Flight`] | `x'' = b`, `z'' = -g` | `h` falls to 0 -> impact |
//!
//! The stick test at `w = 0` is [`stick_test`]: stick if `|a_xp - b| <= mu n`, else slip
//! in the direction the needed force points away from.
//!
//! **Impact** (landing, restitution `e`): the plate takes the vertical velocity,
//! `vh+ = -e vh-` (below [`BlockParams::rest_velocity_mps`] it is 0); the normal impulse per
//! unit mass is `P_n = (1 + e)|vh-|` and the tangential one is limited by `mu P_n`
//! ([`coulomb_impact`]; see [`ImpactFriction`] for the other rules). If the plate's
//! downward acceleration exceeds g at the landing instant (`n <= 0`) the block leaves
//! again at once (a touch-and-go).
//!
//! **Breakpoints** of the plate (the [`crate::physics::plate::Sawtooth`]'s velocity
//! jumps): the relative velocity jumps by minus the plate's jump. A sticking block must
//! start slipping there (it cannot follow a velocity jump with a finite force); an upward
//! jump of the plate's vertical velocity is an impact, a downward one a take-off.
//!
//! # Closed forms
//! Every mode of Coulomb friction has a closed form for **any** plate, because the
//! friction force in a mode is a known function of time: in slip with `s = +1` (right)
//! or `-1` (left), `t - t0 = tau`,
//! `w(t) = w0 + (b - s mu g) tau - s mu (v_zp(t) - v_zp(t0)) - (v_xp(t) - v_xp(t0))` and
//! `u(t) = u0 + w0 tau + (b - s mu g) tau^2/2 - s mu (z_p(t) - z_p(t0) - v_zp(t0) tau) -
//! (x_p(t) - x_p(t0) - v_xp(t0) tau)`; flight is ballistic in absolute coordinates.
//!
//! These go through [`HybridSystem::exact`] when [`BlockSystem::closed_forms`] is true
//! (the default); the guards are then sampled every `period / samples_per_period` and
//! crossings located by the driver's Illinois search on the closed form. The viscous
//! contact mode (and every mode when closed forms are off) is integrated by the driver's
//! method (Dormand-Prince 5(4) by default). Plates are right-continuous and the driver
//! never lets a segment cross a breakpoint, so every closed-form segment reads the plate
//! of its own piece: at its start `t0` the plate at `t0` (on a breakpoint, the piece that
//! begins there), inside it the plate at `t`, and at an end on a breakpoint the left
//! limit read inside the segment (never across its start, however short the segment).
//! The jump is applied once, by [`HybridSystem::on_breakpoint`], which re-decides the
//! contact mode from the relative velocity in the new piece (absolute velocity is
//! continuous; a sticking block slips when the plate's velocity jumps).
//!
//! # Use
//! [`simulate_block`] runs a block from the start in [`BlockOptions::start`] and returns a [`BlockRun`] with
//! the mean velocity over whole periods, contact fraction, mode fractions and event
//! counts. [`simulate_block_observed`] also feeds an [`Observer`] every segment and event;
//! [`BlockSystem::contact_force`] gives the friction and normal force of a segment's
//! state, to check the friction cone and the dissipation at every step;
//! [`ContactInvariants`] is the observer that does so (and checks the impacts), and
//! [`ballistic_flight_s`] finds a hop's flight time without the driver.

use crate::numerics::events::time_tolerance;
use crate::numerics::hybrid::{HybridSystem, Transition};
use crate::physics::friction::{
    coulomb_impact, stick_test, FrictionLaw, ImpactFriction, StickTest,
};
use crate::physics::plate::PlateMotion;

mod checks;
pub mod contact_form;
mod hybrid_impl;
mod run;
#[cfg(test)]
mod tests;

pub use crate::numerics::hybrid::Observer;
pub use checks::{ballistic_flight_s, ContactInvariants};
pub use run::{
    simulate_block, simulate_block_observed, time_tolerance_of_run, BlockEvent, BlockOptions,
    BlockRun, EventCounts, EventKind, ModeFractions,
};

/// Physical parameters of the block scene (per unit mass).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlockParams {
    /// Gravitational acceleration normal to the plate g (m/s^2).
    pub g_mps2: f64,
    /// Friction law in contact.
    pub friction: FrictionLaw,
    /// Tangential rule at impacts.
    pub impact: ImpactFriction,
    /// Coefficient of restitution e of landings (0: completely inelastic).
    pub restitution: f64,
    /// Constant horizontal bias force per unit mass b = F/m (m/s^2), positive towards +x.
    pub bias_mps2: f64,
    /// A rebound slower than this (m/s) counts as a plastic landing (stops the
    /// geometric cascade of ever smaller bounces when e > 0).
    pub rest_velocity_mps: f64,
}

impl BlockParams {
    /// Coulomb friction `mu`, completely inelastic Coulomb impacts, bias `bias_mps2`.
    pub fn coulomb(g_mps2: f64, mu: f64, bias_mps2: f64) -> Self {
        BlockParams {
            g_mps2,
            friction: FrictionLaw::Coulomb { mu },
            impact: ImpactFriction::Coulomb,
            restitution: 0.0,
            bias_mps2,
            rest_velocity_mps: 1e-9,
        }
    }

    /// Linear viscous friction `c_per_s` (1/s), frictionless inelastic impacts.
    pub fn viscous(g_mps2: f64, c_per_s: f64, bias_mps2: f64) -> Self {
        BlockParams {
            friction: FrictionLaw::Viscous { c_per_s },
            impact: ImpactFriction::Frictionless,
            ..BlockParams::coulomb(g_mps2, 0.0, bias_mps2)
        }
    }
}

/// The modes of the block.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BlockMode {
    /// In contact, at rest relative to the plate (Coulomb or no-slip).
    Stick,
    /// In contact, sliding towards +x relative to the plate (`w > 0`, friction `-mu n`).
    SlipRight,
    /// In contact, sliding towards -x relative to the plate (`w < 0`, friction `+mu n`).
    SlipLeft,
    /// In contact with viscous friction.
    Viscous,
    /// In the air.
    Flight,
}

/// The block never stops a run by itself; the type exists for the driver's contract.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum BlockStop {}

/// Contact forces per unit mass (m/s^2) in a state: `tangential` along +x on the block,
/// `normal` upwards on the block (both zero in flight).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactForce {
    /// Tangential (friction) force per unit mass (m/s^2).
    pub tangential_mps2: f64,
    /// Normal force per unit mass (m/s^2).
    pub normal_mps2: f64,
}

/// The block on a plate `P`, as a [`HybridSystem`] with state `[u, w, h, vh]`.
#[derive(Debug, Clone)]
pub struct BlockSystem<'a, P: PlateMotion + ?Sized> {
    /// Parameters.
    pub params: BlockParams,
    /// The plate.
    pub plate: &'a P,
    /// Use the closed forms of stick, Coulomb slip and flight (true) or integrate them.
    pub closed_forms: bool,
    /// Guard sampling interval of closed-form modes and longest step of integrated ones (s).
    pub sample_s: f64,
    has_breakpoints: bool,
    /// The plate's [`PlateMotion::peak_rates`], read once.
    peak_rates: Option<[f64; 4]>,
}

impl<'a, P: PlateMotion + ?Sized> BlockSystem<'a, P> {
    /// A block system with closed forms on and 64 guard samples per plate period.
    pub fn new(params: BlockParams, plate: &'a P) -> Self {
        let has_breakpoints = plate.breakpoint_after(0.0).is_some();
        BlockSystem {
            params,
            plate,
            closed_forms: true,
            sample_s: plate.period_s() / 64.0,
            has_breakpoints,
            peak_rates: plate.peak_rates(),
        }
    }

    // ANCHOR: contact_needs
    /// Normal force per unit mass the plate must supply to carry the block (m/s^2).
    pub fn normal(&self, t: f64) -> f64 {
        self.params.g_mps2 + self.plate.az_mps2(t) // formula: n = g + a_zp
    }

    /// Tangential force per unit mass needed to keep the block at rest on the plate (m/s^2).
    pub(crate) fn needed_friction(&self, t: f64) -> f64 {
        self.plate.ax_mps2(t) - self.params.bias_mps2 // formula: f_need = a_xp - b
    }
    // ANCHOR_END: contact_needs

    /// Absolute `[x, v_x, z, v_z]` (m, m/s) of a relative state at `t`.
    pub fn absolute(&self, t: f64, y: &[f64; 4]) -> [f64; 4] {
        let p = self.plate;
        [
            y[0] + p.x_m(t),
            y[1] + p.vx_mps(t),
            y[2] + p.z_m(t),
            y[3] + p.vz_mps(t),
        ]
    }

    /// Absolute `[x, v_x, z, v_z]` (m, m/s) of the relative state `y` at `t` of a
    /// segment that starts at `t0`: like [`BlockSystem::absolute`], but with the plate
    /// velocity of the segment's own piece (its left limit when `t` ends the segment on
    /// a breakpoint, where the relative state still belongs to the old piece).
    pub(crate) fn absolute_in_piece(&self, t0: f64, t: f64, y: &[f64; 4]) -> [f64; 4] {
        let p = self.plate;
        let (vx, vz) = self.plate_velocity_in_piece(t0, t);
        [y[0] + p.x_m(t), y[1] + vx, y[2] + p.z_m(t), y[3] + vz]
    }

    /// The contact forces per unit mass in `mode` at `(t, y)`.
    pub(crate) fn contact_force(&self, mode: BlockMode, t: f64, y: &[f64; 4]) -> ContactForce {
        let n = self.normal(t);
        let f = match (mode, self.params.friction) {
            (BlockMode::Flight, _) => {
                return ContactForce {
                    tangential_mps2: 0.0,
                    normal_mps2: 0.0,
                }
            }
            (BlockMode::Stick, _) => self.needed_friction(t),
            (BlockMode::SlipRight, FrictionLaw::Coulomb { mu }) => -mu * n,
            (BlockMode::SlipLeft, FrictionLaw::Coulomb { mu }) => mu * n,
            (BlockMode::Viscous, FrictionLaw::Viscous { c_per_s }) => -c_per_s * y[1], // formula: f = -c v_rel
            _ => 0.0,
        };
        ContactForce {
            tangential_mps2: f,
            normal_mps2: n,
        }
    }

    fn mu(&self) -> f64 {
        self.params.friction.mu().unwrap_or(0.0)
    }

    /// Slip sign of a Coulomb slip mode: +1 right, -1 left.
    fn slip_sign(mode: BlockMode) -> f64 {
        if mode == BlockMode::SlipRight {
            1.0
        } else {
            -1.0
        }
    }

    /// Plate velocity `(v_xp, v_zp)` at the start `t0` of a segment: the plate read at
    /// `t0` itself (plates are right-continuous: on a breakpoint this is the velocity of
    /// the piece that begins there, the segment's own piece).
    fn plate_velocity_start(&self, t0: f64) -> (f64, f64) {
        (self.plate.vx_mps(t0), self.plate.vz_mps(t0))
    }

    /// Plate velocity `(v_xp, v_zp)` at `t` in the piece of a segment that starts at
    /// `t0 <= t` (the driver never lets a segment cross a breakpoint, so the piece is the
    /// one containing `t0`). Inside the piece that is the plate at `t`; a segment that
    /// ends on a breakpoint needs the left limit there, read at a time inside the
    /// segment ([`BlockSystem::left_limit_velocity`]).
    fn plate_velocity_in_piece(&self, t0: f64, t: f64) -> (f64, f64) {
        if self.has_breakpoints && t > t0 {
            if let Some(b) = self.plate.breakpoint_after(t0) {
                if t >= b {
                    return self.left_limit_velocity(t, 0.5 * (t - t0));
                }
            }
        }
        (self.plate.vx_mps(t), self.plate.vz_mps(t))
    }

    /// Left limit of the plate velocity at `t`, read `d = min(1e-9 T, max_back_s)`
    /// before it and extrapolated with the acceleration there: exact for
    /// piecewise-linear plates, within `d^2` times the jerk otherwise. `max_back_s`
    /// keeps the reading inside the piece that ends at `t`.
    fn left_limit_velocity(&self, t: f64, max_back_s: f64) -> (f64, f64) {
        let p = self.plate;
        let d = (1e-9 * p.period_s()).min(max_back_s);
        let s = t - d;
        (
            p.vx_mps(s) + d * p.ax_mps2(s),
            p.vz_mps(s) + d * p.az_mps2(s),
        ) // formula: v(t-) = v(t - d) + d a(t - d)
    }

    /// The contact mode a block resting relative to the plate (`w = 0`) enters at `t`.
    pub(crate) fn rest_mode(&self, t: f64) -> BlockMode {
        match self.params.friction {
            FrictionLaw::Viscous { .. } => BlockMode::Viscous,
            FrictionLaw::NoSlip => BlockMode::Stick,
            FrictionLaw::Coulomb { mu } => {
                match stick_test(self.needed_friction(t), self.normal(t), mu) {
                    StickTest::Sticks => BlockMode::Stick,
                    StickTest::SlipsLeft => BlockMode::SlipLeft,
                    StickTest::SlipsRight => BlockMode::SlipRight,
                }
            }
        }
    }

    /// Whether the needed friction at `t` is on the cone's edge `|f_need| = mu n` to
    /// within its own uncertainty: the rounding of the two sides (8 ulps of their sum)
    /// plus their change over the event-time uncertainty `time_tolerance(t)` (an event
    /// is located to that, so the switch can sit that far off the true one).
    pub(crate) fn at_cone_edge(&self, t: f64) -> bool {
        let edge = |s: f64| self.needed_friction(s).abs() - self.mu() * self.normal(s);
        let dt = time_tolerance(t);
        let (f, n) = (self.needed_friction(t).abs(), self.mu() * self.normal(t));
        let drift = 0.5 * (edge(t + dt) - edge(t - dt)).abs(); // formula: |d(edge)/dt| dt
        (f - n).abs() <= 8.0 * f64::EPSILON * (f + n) + drift
    }

    /// The rounding of a slip's relative velocity `w` at `t` (m/s). The closed form
    /// subtracts the plate's velocities at the slip's start from those at `t`; each is
    /// the plate's velocity at a rounded time (t carries ε (t + T) of rounding, through
    /// the phase ω t), so each is off by |a_p| ε (t + T) plus a few ulps of itself, and
    /// near a switch both ends are the same size: 8 ε [μ (|a_zp| (t + T) + |v_zp|) +
    /// |a_xp| (t + T) + |v_xp|]. Where the plate knows its peak rates
    /// ([`PlateMotion::peak_rates`]) they stand for the values at t: an upper bound of
    /// the same floor, so still a valid rounding guard, without the two to four
    /// plate evaluations (trigonometric for a harmonic plate) per guard evaluation.
    /// Never below the smallest positive number, so that a slip from rest starts its
    /// guard above zero.
    pub(crate) fn slip_rounding_mps(&self, t: f64) -> f64 {
        let p = self.plate;
        let span = t.abs() + p.period_s(); // formula: t + T
        let [vx, ax, vz, az] = self.peak_rates.unwrap_or_else(|| {
            [
                p.vx_mps(t).abs(),
                p.ax_mps2(t).abs(),
                p.vz_mps(t).abs(),
                p.az_mps2(t).abs(),
            ]
        });
        let z = az * span + vz;
        let x = ax * span + vx;
        (8.0 * f64::EPSILON * (self.mu() * z + x)).max(f64::MIN_POSITIVE) // formula: 8 eps [mu (|a_zp| (t + T) + |v_zp|) + |a_xp| (t + T) + |v_xp|]
    }

    /// The contact mode for relative velocity `w` at `t` (the block touches the plate).
    pub(crate) fn contact_mode(&self, t: f64, w: f64) -> BlockMode {
        match self.params.friction {
            FrictionLaw::Viscous { .. } => BlockMode::Viscous,
            FrictionLaw::NoSlip => BlockMode::Stick,
            FrictionLaw::Coulomb { .. } if w > 0.0 => BlockMode::SlipRight,
            FrictionLaw::Coulomb { .. } if w < 0.0 => BlockMode::SlipLeft,
            FrictionLaw::Coulomb { .. } => self.rest_mode(t),
        }
    }

    /// The mode and state a block in contact at `t` with relative tangential velocity `w`
    /// continues in: flight at once if the plate pulls away faster than g.
    fn continue_in_contact(&self, t: f64, u: f64, w: f64) -> Transition<BlockMode, BlockStop, 4> {
        if self.normal(t) <= 0.0 {
            return Transition::To {
                mode: BlockMode::Flight,
                state: [u, w, 0.0, 0.0],
            };
        }
        let w = if self.params.friction == FrictionLaw::NoSlip {
            0.0
        } else {
            w
        };
        Transition::To {
            mode: self.contact_mode(t, w),
            state: [u, w, 0.0, 0.0],
        }
    }

    // ANCHOR: impact
    /// The impact map: relative velocities `(w, vh)` just before (with `vh < 0`) to the
    /// mode and state just after.
    pub fn impact(&self, t: f64, u: f64, w: f64, vh: f64) -> Transition<BlockMode, BlockStop, 4> {
        let e = self.params.restitution;
        let approach = (-vh).max(0.0);
        let p_n = (1.0 + e) * approach; // formula: P_n = (1 + e) |vh-|
        let w_after = match (self.params.impact, self.params.friction) {
            (ImpactFriction::Sticking, _) | (ImpactFriction::Coulomb, FrictionLaw::NoSlip) => 0.0,
            (ImpactFriction::Frictionless, _)
            | (ImpactFriction::Coulomb, FrictionLaw::Viscous { .. }) => w,
            (ImpactFriction::Coulomb, FrictionLaw::Coulomb { mu }) => coulomb_impact(w, p_n, mu),
        };
        let rebound = e * approach; // formula: vh+ = -e vh-
        if rebound > self.params.rest_velocity_mps {
            Transition::To {
                mode: BlockMode::Flight,
                state: [u, w_after, 0.0, rebound],
            }
        } else {
            self.continue_in_contact(t, u, w_after)
        }
    }
    // ANCHOR_END: impact

    /// Ballistic flight in relative coordinates from `(t0, y0)` to `t`.
    fn flight_exact(&self, t0: f64, y0: &[f64; 4], t: f64) -> [f64; 4] {
        let p = self.plate;
        let (g, b) = (self.params.g_mps2, self.params.bias_mps2);
        let s = t - t0;
        let (vxp0, vzp0) = self.plate_velocity_start(t0);
        let (x0, vx0) = (y0[0] + p.x_m(t0), y0[1] + vxp0);
        let (z0, vz0) = (y0[2] + p.z_m(t0), y0[3] + vzp0);
        let (vxp, vzp) = self.plate_velocity_in_piece(t0, t);
        [
            x0 + vx0 * s + 0.5 * b * s * s - p.x_m(t), // formula: x = x0 + vx0 s + b s^2/2
            vx0 + b * s - vxp,
            z0 + vz0 * s - 0.5 * g * s * s - p.z_m(t), // formula: z = z0 + vz0 s - g s^2/2
            vz0 - g * s - vzp,
        ]
    }

    // ANCHOR: slip_exact
    /// Coulomb slip (sign `sg`) in closed form from `(t0, y0)` to `t`.
    fn slip_exact(&self, sg: f64, t0: f64, y0: &[f64; 4], t: f64) -> [f64; 4] {
        let p = self.plate;
        let (g, b, mu) = (self.params.g_mps2, self.params.bias_mps2, self.mu());
        let s = t - t0;
        let c = b - sg * mu * g;
        let (vxp, vzp) = self.plate_velocity_in_piece(t0, t);
        let (vxp0, vzp0) = self.plate_velocity_start(t0);
        // formula: w = w0 + (b - s mu g) tau - s mu (v_zp - v_zp0) - (v_xp - v_xp0)
        let w = y0[1] + c * s - sg * mu * (vzp - vzp0) - (vxp - vxp0);
        // formula: u = u0 + w0 tau + (b - s mu g) tau^2/2 - s mu (z_p - z_p0 - v_zp0 tau) - (x_p - x_p0 - v_xp0 tau)
        let u = y0[0] + y0[1] * s + 0.5 * c * s * s
            - sg * mu * (p.z_m(t) - p.z_m(t0) - vzp0 * s)
            - (p.x_m(t) - p.x_m(t0) - vxp0 * s);
        [u, w, 0.0, 0.0]
    }
    // ANCHOR_END: slip_exact

    /// The sampling step, shortened so that a guard dipping towards zero and back (a
    /// grazing take-off at Gamma just above 1, a grazing landing, a velocity that just
    /// touches the plate's) is sampled at its minimum: from the guard's slope and
    /// curvature (forward differences on the mode's closed form, or on time for the
    /// guards that depend on time only), the step ends at the predicted minimum when the
    /// predicted minimum value is below half the current value; never below
    /// `sample_s / 1024`. No probing when the next breakpoint is within two probe steps.
    fn graze_step(&self, mode: BlockMode, t: f64, y: &[f64; 4]) -> f64 {
        let mut step = self.sample_s;
        let h = self.sample_s / 64.0;
        // The probes must stay in the current piece of a plate with breakpoints (a
        // guard jumps there; the driver stops on the breakpoint anyway).
        if self.has_breakpoints
            && self
                .plate
                .breakpoint_after(t)
                .is_some_and(|b| t + 2.0 * h >= b)
        {
            return step;
        }
        let time_only =
            |i: usize| mode != BlockMode::Flight && (i == 0 || mode == BlockMode::Stick);
        for i in 0..self.guard_count(mode) {
            if !time_only(i) && !self.closed_forms {
                continue;
            }
            let at = |s: f64| {
                let ys = if s == t {
                    *y
                } else {
                    self.exact(mode, t, y, s).unwrap_or(*y)
                };
                self.guard(mode, i, s, &ys)
            };
            let (f0, f1, f2) = (at(t), at(t + h), at(t + 2.0 * h));
            let d1 = (-3.0 * f0 + 4.0 * f1 - f2) / (2.0 * h); // formula: forward-difference slope
            let d2 = (f0 - 2.0 * f1 + f2) / (h * h); // formula: forward-difference curvature
            let decreasing_to_min =
                (f0 > 0.0 && d1 < 0.0 && d2 > 0.0) || (f0 < 0.0 && d1 > 0.0 && d2 < 0.0);
            if decreasing_to_min {
                let s_min = -d1 / d2; // formula: time of the parabola's extremum
                let f_min = f0 - d1 * d1 / (2.0 * d2);
                if f_min.abs() < 0.5 * f0.abs() || f_min.signum() != f0.signum() {
                    step = step.min(s_min.max(self.sample_s / 1024.0));
                }
            }
        }
        step
    }

    /// First step of a flight that starts at the plate (`h = 0`): short enough that the
    /// height is seen positive before the block can come back (the relative apex bound).
    fn first_flight_step(&self, t: f64, y: &[f64; 4]) -> f64 {
        let mut s = self.sample_s;
        for _ in 0..80 {
            let e = self.flight_exact(t, y, t + s);
            if e[2] > 0.0 && e[3] > 0.0 {
                return s;
            }
            s *= 0.5;
        }
        s
    }
}
