//! The leaning stick with inertia (chapter 8): a rigid rod C-P of length `L` with a
//! uniform mass `m_r` along it and a point mass `m` at P, on the vibrating plate of
//! chapter 6 (`z_s = delta cos(omega t)`), with the same torsion spring `k` and damper
//! `gamma` and Coulomb friction `mu` at C.
//!
//! **Spring and damper.** As in chapter 6 they act between the rod and the vertical:
//! a couple `-Q`, `Q = k (theta - theta_0) + gamma theta'`, on the rod, whose reaction is
//! carried by the laboratory frame (theta is measured from the vertical, not from the
//! plate or another body). A couple is the same about every point of a rigid body, so it
//! enters every moment balance below unchanged; with `m_r = 0` the rod's moment balance
//! about P is exactly chapter 6's (C.8). This is the reading that keeps chapter 6 as the
//! limit `m_r -> 0`.
//!
//! Modes ([`Mode`]): flight (3 degrees of freedom, closed form: G ballistic, the angle a
//! damped linear oscillator, [`flight`]), pivot (C stuck, 1 DOF) and the two slides
//! (2 DOF), integrated ([`contact`]); a fall ends the run. Impacts at C with restitution
//! and friction ([`impact`]); the Painleve cases of the slides ([`painleve`]); the
//! transition rules and the [`crate::numerics::hybrid::HybridSystem`] implementation
//! ([`system`]); the run and its summary ([`run`]); the massless limit as a singular
//! perturbation ([`limit`]).
//!
//! | index | meaning | unit |
//! |---|---|---|
//! | [`TH`], [`OM`] | angle theta from the vertical (P right of C positive), theta' | rad, rad/s |
//! | [`VXC`], [`XC`] | x velocity and position of C | m/s, m |
//! | [`ZC`], [`VZC`] | z position and velocity of C | m, m/s |
//! | [`W_PLATE`] .. [`D_IMPACT`] | plate work, friction, damper and impact losses | J |

pub mod bridge;
pub mod compliant;
pub mod contact;
pub mod flight;
pub mod impact;
pub mod limit;
pub mod painleve;
pub mod params;
pub mod rounding;
pub mod run;
pub mod system;
pub mod timestepping;

pub use painleve::{PainleveCase, PainleveEvent};
pub use params::{InertiaParams, MassGeometry};

use std::cell::RefCell;
use std::f64::consts::TAU;

/// State index: theta (rad).
pub const TH: usize = 0;
/// State index: theta' (rad/s).
pub const OM: usize = 1;
/// State index: x velocity of C (m/s).
pub const VXC: usize = 2;
/// State index: x of C (m).
pub const XC: usize = 3;
/// State index: z of C (m).
pub const ZC: usize = 4;
/// State index: z velocity of C (m/s).
pub const VZC: usize = 5;
/// State index: work of the plate on the stick (J).
pub const W_PLATE: usize = 6;
/// State index: friction loss (J).
pub const D_FRIC: usize = 7;
/// State index: damper loss (J).
pub const D_DAMP: usize = 8;
/// State index: impact loss (J).
pub const D_IMPACT: usize = 9;
/// Number of states.
pub const NSTATE: usize = 10;
/// The contact flows and guards read theta, theta' and xdot_c only.
pub const FLOW_ARGS: usize = 3;

/// The state vector.
pub type State = [f64; NSTATE];

/// The contact modes: chapter 6's four (flight 3 DOF here, pivot 1, the slides 2).
pub use crate::physics::stick::Mode;

/// Why a run stopped early.
#[derive(Debug, Clone, PartialEq)]
pub enum InertiaStop {
    /// |theta| reached 90 degrees: the stick fell.
    Fell,
    /// A Painleve case the stated rule could not resolve (the event).
    PainleveUnresolved(PainleveEvent),
    /// The state left the model's validity (the reason).
    Invalid(String),
    /// The rules found no consistent contact mode (the reason): handed to Moreau-Jean.
    NoMode(String),
}

/// One impact at C (a landing or an impact without collision).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactRecord {
    /// Time (s).
    pub t_s: f64,
    /// Angle (rad).
    pub theta_rad: f64,
    /// Tangential (x) impulse of the plate on C (N s).
    pub j_t_ns: f64,
    /// Normal (z) impulse (N s).
    pub j_n_ns: f64,
    /// Kinetic energy lost in the plate's frame (J), never negative for a valid impact.
    pub loss_j: f64,
    /// Kinetic energy change in the lab minus the plate's impulse work (J): minus the
    /// loss, computed from the states (the check that no impact creates energy).
    pub energy_change_j: f64,
    /// Slip velocity of C before (m/s).
    pub slip_before_mps: f64,
    /// Slip velocity of C after (m/s).
    pub slip_after_mps: f64,
    /// Normal velocity of C relative to the plate after (m/s).
    pub normal_after_mps: f64,
    /// A landing (true) or an impact without collision (false).
    pub landing: bool,
}

/// What the model records during a run (events it decides inside its transitions).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Log {
    /// Painleve events, in time order.
    pub painleve: Vec<PainleveEvent>,
    /// Impacts (capped at [`Log::CAP`]), and their count.
    pub impacts: Vec<ImpactRecord>,
    /// Number of impacts.
    pub impact_count: usize,
    /// Largest energy created by an impact (J): zero up to rounding when none creates any.
    pub max_energy_gain_j: f64,
    /// Largest normal velocity of C relative to the plate after an impact that left C on
    /// the plate, or after a plastic one (m/s): the velocity-level complementarity
    /// residual (zero in exact arithmetic).
    pub max_normal_residual_mps: f64,
    /// Largest ratio of an impact's residual to its rounding threshold `eta_v`
    /// ([`rounding`]) (1): at most 1 when every decision was rounding-consistent.
    pub max_residual_ratio: f64,
    /// Flights shorter than this are below the run's resolution (s; 0: the check is off):
    /// set by the run from its penetration bound ([`InertiaModel::chatter_flight_s`]).
    pub chatter_flight_s: f64,
    /// Time of the last landing (s).
    pub landed_s: Option<f64>,
    /// Time of the last lift-off chosen by the rules (s).
    pub lifted_s: Option<f64>,
    /// Landings in a row whose flight began with a lift-off at the landing before and
    /// lasted at most `chatter_flight_s` (1).
    pub chatter_pairs: usize,
}

impl Log {
    /// Most records kept.
    pub const CAP: usize = 10_000;
}

/// The impact law at C.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImpactLaw {
    /// Integration in the normal impulse (Darboux-Keller) with Stronge's restitution: the
    /// slip may stop or reverse during the impact ([`impact`]). The model's law.
    DarbouxKeller,
    /// The velocity-level law of Moreau-Jean time-stepping: Newton's restitution and
    /// Coulomb's law on the velocities after the impact
    /// ([`crate::numerics::timestepping::solve_contact`]); for comparison only.
    VelocityCoulomb,
}

/// Which solution the rules take where a slide's Painleve coefficient crosses zero (a
/// "dynamic jam"; at a singular point, where the free normal acceleration vanishes too,
/// the contact problem's limits disagree).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PainleveRule {
    /// Prefer contact: an impact without collision (the model's rule).
    PreferContact,
    /// Prefer separation: lift-off where the free motion allows it (for comparison).
    PreferSeparation,
}

/// The model: parameters, derived constants and the run's log.
#[derive(Debug, Clone)]
pub struct InertiaModel {
    /// Parameters.
    pub p: InertiaParams,
    /// Mass geometry.
    pub geo: MassGeometry,
    /// Drive period (s).
    pub period_s: f64,
    /// Longest step in contact modes (s).
    pub max_contact_step_s: f64,
    /// Shortest sampling interval of the landing search (s).
    pub min_flight_sample_s: f64,
    /// Events decided inside transitions.
    pub log: RefCell<Log>,
    /// The impact law (Darboux-Keller unless a comparison asks otherwise).
    pub impact_law: ImpactLaw,
    /// The rule at a crossing of the Painleve boundary (prefer contact unless a
    /// comparison asks otherwise).
    pub painleve_rule: PainleveRule,
}

impl InertiaModel {
    /// A model for `p` (`m + m_r > 0`).
    pub fn new(p: InertiaParams) -> Self {
        let period = p.base.period_s();
        InertiaModel {
            p,
            geo: p.geometry(),
            period_s: period,
            max_contact_step_s: period / 14.0,
            min_flight_sample_s: period / 1024.0,
            log: RefCell::new(Log::default()),
            impact_law: ImpactLaw::DarbouxKeller,
            painleve_rule: PainleveRule::PreferContact,
        }
    }

    /// Plate height, velocity, acceleration at `t` (`z_s = delta cos(omega t)`).
    pub fn plate(&self, t: f64) -> (f64, f64, f64) {
        let pl = &self.p.base.plate;
        let (s, c) = (pl.omega_rad_s * t + pl.phase_rad).sin_cos();
        let (w, d) = (pl.omega_rad_s, pl.amplitude_m);
        (d * s, d * w * c, -d * w * w * s) // formula: z_s = delta sin(omega t + phi), phi = pi/2
    }

    /// The spring-damper couple `Q = k (theta - theta_0) + gamma theta'` (N m).
    pub(crate) fn couple(&self, theta: f64, omega: f64) -> f64 {
        let b = &self.p.base;
        b.stiffness_nm_per_rad * (theta - b.theta0_rad) + b.damping_nms_per_rad * omega
        // formula: Q
    }

    /// Centre-of-mass position and velocity `(x_G, z_G, vx_G, vz_G)`:
    /// `r_G = r_C + l_G e_r`, `v_G = v_C + l_G theta' e_theta`,
    /// `e_r = (sin, cos)`, `e_theta = (cos, -sin)`.
    pub fn centre(&self, y: &State) -> [f64; 4] {
        let l = self.geo.l_g_m;
        let (s, c) = y[TH].sin_cos();
        [
            y[XC] + l * s,          // formula: x_G = x_C + l_G sin
            y[ZC] + l * c,          // formula: z_G = z_C + l_G cos
            y[VXC] + l * c * y[OM], // formula: vx_G = vx_C + l_G theta' cos
            y[VZC] - l * s * y[OM], // formula: vz_G = vz_C - l_G theta' sin
        ]
    }

    /// Mechanical energy `M |v_G|^2/2 + I_G theta'^2/2 + M g z_G + k (theta-theta_0)^2/2` (J).
    pub(crate) fn mechanical_energy(&self, y: &State) -> f64 {
        self.kinetic_energy(y) + self.potential_energy(y)
    }

    /// Kinetic energy `M |v_G|^2/2 + I_G theta'^2/2` (J).
    pub(crate) fn kinetic_energy(&self, y: &State) -> f64 {
        let [_, _, vx, vz] = self.centre(y);
        0.5 * self.geo.total_kg * (vx * vx + vz * vz) + 0.5 * self.geo.i_g * y[OM] * y[OM]
        // formula: T
    }

    /// Potential energy `M g z_G + k (theta - theta_0)^2 / 2` (J).
    pub(crate) fn potential_energy(&self, y: &State) -> f64 {
        let b = &self.p.base;
        let d = y[TH] - b.theta0_rad;
        self.geo.total_kg * b.g_mps2 * self.centre(y)[1] + 0.5 * b.stiffness_nm_per_rad * d * d
        // formula: V
    }

    /// The state with C's height and vertical velocity set to the plate's in contact modes.
    pub fn canonical(&self, mode: Mode, t: f64, y: &State) -> State {
        let mut y = *y;
        if mode != Mode::Flight {
            let (zs, vs, _) = self.plate(t);
            y[ZC] = zs;
            y[VZC] = vs;
        }
        y
    }

    /// Drive frequency (Hz).
    pub fn frequency_hz(&self) -> f64 {
        self.p.base.plate.omega_rad_s / TAU
    }
}
