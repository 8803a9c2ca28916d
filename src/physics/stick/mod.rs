//! The leaning stick on a vertically vibrating plate (document sections 4 and 5).
//!
//! A massless rod CP of length `L` carries a point mass `m` at its top P; a torsion
//! spring `k` and a damper `gamma` pull its angle `theta` (from the vertical, positive
//! when P is to the right of C) towards `theta_0`; its foot C touches a plate that moves
//! as `z_s = delta cos(omega t)`, with Coulomb friction `mu`.
//!
//! Four modes ([`Mode`]): flight (closed form, [`flight`]), pivot and the two slides
//! (integrated, [`contact`]); the landing and jamming impulses ([`collision`]); the
//! transition rules ([`rules`]); the energy bookkeeping ([`energy`]); the driver
//! wrapper and its summary ([`run`]). [`StickModel`] implements
//! [`crate::numerics::hybrid::HybridSystem`] with `N = 12` states:
//!
//! | index | meaning | unit |
//! |---|---|---|
//! | [`TH`], [`OM`] | angle theta and its rate theta' | rad, rad/s |
//! | [`VXC`] | x velocity of C | m/s |
//! | [`ROD_X`], [`ROD_Z`] | the rod's direction from C to P, `(sin theta, cos theta)` | 1 |
//! | [`XC`], [`ZC`] | position of the foot C | m |
//! | [`VZC`] | z velocity of C | m/s |
//! | [`W_PLATE`] | work done by the plate on the stick since t0 | J |
//! | [`D_FRIC`], [`D_DAMP`], [`D_IMPACT`] | energy dissipated by friction, damper, impacts | J |
//!
//! The contact flows read only the first [`FLOW_ARGS`] components; the rest are
//! outputs of the integration (C's position, the energy account) or the plate's own
//! values in contact, and the integrator spends no stage arithmetic on them.
//!
//! The rod's direction turns at the rate theta': `(sin theta)' = theta' cos theta`,
//! `(cos theta)' = -theta' sin theta`. It is integrated with the rest of the state (it
//! enters the error control like any other component), so the contact equations read
//! `sin theta` and `cos theta` off the state: no trigonometry on the chain of dependent
//! stages, where it cost about 15 % of the simulator's time. Every mode entry resets
//! the direction to its exact value ([`StickModel::canonical`]); between entries it
//! drifts from it by the integration error only (checked in the tests). The plate's
//! phase depends on time alone and comes from [`crate::numerics::trig`]. In contact,
//! C's height and vertical velocity are the plate's and are not integrated.
//!
//! Public API used by other chapters: [`StickParams`] (and the scenes
//! [`authors_scene`], [`jamming_scene`]), [`StickModel::new`], [`run::simulate_stick`]
//! (one run with a chosen [`crate::numerics::hybrid::Options`], returns a
//! [`run::RunSummary`]), [`run::initial_state`].

pub mod collision;
pub mod contact;
pub mod energy;
pub mod flight;
mod guard_rates;
pub mod params;
pub mod printed;
pub mod rules;
pub mod run;
pub mod soft;
mod system;
pub mod timestepping;

use crate::numerics::trig::{sin_cos, Table};
use std::f64::consts::TAU;

pub use params::{
    authors_scene, domain, jamming_scene, theta0_for_static_angle, CollisionAngle, StickParams,
};

/// State index: theta (rad).
pub const TH: usize = 0;
/// State index: theta' (rad/s).
pub const OM: usize = 1;
/// State index: x velocity of C (m/s).
pub const VXC: usize = 2;
/// State index: `sin(theta)`, the x component of the rod's unit vector from C to P (1).
pub const ROD_X: usize = 3;
/// State index: `cos(theta)`, the z component of the rod's unit vector from C to P (1).
pub const ROD_Z: usize = 4;
/// State index: x of C (m).
pub const XC: usize = 5;
/// State index: z of C (m).
pub const ZC: usize = 6;
/// State index: z velocity of C (m/s).
pub const VZC: usize = 7;
/// State index: plate work (J).
pub const W_PLATE: usize = 8;
/// State index: friction dissipation (J).
pub const D_FRIC: usize = 9;
/// State index: damper dissipation (J).
pub const D_DAMP: usize = 10;
/// State index: impact dissipation (J).
pub const D_IMPACT: usize = 11;
/// The contact flows read the first five components only ([`TH`] to [`ROD_Z`]): the
/// integrator forms stage arguments for those alone (see
/// [`crate::numerics::ode::OdeSystem::ARGS`]).
pub const FLOW_ARGS: usize = 5;
/// Number of states.
pub const NSTATE: usize = 12;

/// The stick's state vector (see the module table).
pub type State = [f64; NSTATE];

/// The contact modes of Table 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Mode {
    /// No contact: P ballistic, theta relaxing to theta_0 (C.3, C.5).
    Flight,
    /// C stuck on the plate (hinge), one degree of freedom (C.6, C.7).
    Pivot,
    /// C sliding towards -x, friction `F_x = +mu F_z` (C.9, C.10).
    SlideLeft,
    /// C sliding towards +x, friction `F_x = -mu F_z` (C.11, C.13, C.14).
    SlideRight,
}

impl Mode {
    /// All modes, in the order of the results' `phase_fractions`.
    pub const ALL: [Mode; 4] = [Mode::Flight, Mode::Pivot, Mode::SlideLeft, Mode::SlideRight];

    /// snake_case name for JSON keys.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Flight => "flight",
            Mode::Pivot => "pivot",
            Mode::SlideLeft => "slide_left",
            Mode::SlideRight => "slide_right",
        }
    }

    /// One letter for phase sequences: F, P, L, R.
    pub(crate) fn letter(self) -> char {
        match self {
            Mode::Flight => 'F',
            Mode::Pivot => 'P',
            Mode::SlideLeft => 'L',
            Mode::SlideRight => 'R',
        }
    }

    /// Index in [`Mode::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// Sign of the friction force of a slide, `F_x = sigma mu F_z` (+1 left, -1 right).
    pub fn sigma(self) -> f64 {
        match self {
            Mode::SlideLeft => 1.0,
            Mode::SlideRight => -1.0,
            _ => 0.0,
        }
    }
}

/// Why a run left the model's validity: typed where a caller decides by it (the
/// fallback to DOPRI5 on a non-finite state, the count of C.14's singularity), its
/// message printed from it ([`std::fmt::Display`]).
#[derive(Debug, Clone, PartialEq)]
pub enum InvalidReason {
    /// The integration produced a non-finite state at `t_s` (s); `near_vertical`: the
    /// rod leans less than 1e-3 rad, where the slides' C.14 divides by sin(theta) (the
    /// message then names the remedy).
    NonFinite {
        /// Time (s).
        t_s: f64,
        /// See the variant.
        near_vertical: bool,
    },
    /// A slide reached (or would start at) theta = 0, where C.14 divides by sin(theta).
    SingularSlide {
        /// Time (s).
        t_s: f64,
        /// A slide would start there (true) or a sliding rod reached it (false).
        entering: bool,
    },
    /// Any other reason, as its message.
    Other(String),
}

impl std::fmt::Display for InvalidReason {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            InvalidReason::NonFinite { t_s, near_vertical } => {
                write!(f, "integration failed: non-finite state at t = {t_s} s")?;
                if *near_vertical {
                    write!(f, "; the rod leans less than 1e-3 rad, where the slides' C.14 divides by sin(θ): --method dopri5 integrates this scene")?;
                }
                Ok(())
            }
            InvalidReason::SingularSlide {
                t_s,
                entering: true,
            } => write!(
                f,
                "slide from theta = 0 at t = {t_s:.6} s: the sliding equations (C.14) are singular"
            ),
            InvalidReason::SingularSlide {
                t_s,
                entering: false,
            } => write!(
                f,
                "the sliding rod reached theta = 0 at t = {t_s:.6} s: C.14 is singular there"
            ),
            InvalidReason::Other(why) => f.write_str(why),
        }
    }
}

impl From<String> for InvalidReason {
    fn from(why: String) -> Self {
        InvalidReason::Other(why)
    }
}

impl From<&str> for InvalidReason {
    fn from(why: &str) -> Self {
        InvalidReason::Other(why.to_string())
    }
}

/// Why a run stopped early.
#[derive(Debug, Clone, PartialEq)]
pub enum StickStop {
    /// The top P reached the plate (|theta| reached 90 degrees).
    Fell,
    /// The state left the model's validity (the reason).
    Invalid(InvalidReason),
    /// A printed rule chose ABORT (which rule, where).
    Aborted(String),
}

impl StickStop {
    /// An invalid stop with a reason given as its message.
    pub fn invalid(why: String) -> Self {
        StickStop::Invalid(InvalidReason::Other(why))
    }
}

/// The stick model: parameters plus derived constants. Implements
/// [`crate::numerics::hybrid::HybridSystem`].
#[derive(Debug, Clone, Copy)]
pub struct StickModel {
    /// The parameters.
    pub p: StickParams,
    /// `k/gamma` (1/s).
    pub rate: f64,
    /// Drive period (s).
    pub period_s: f64,
    /// Shortest sampling interval of the landing search in flight (s).
    pub min_flight_sample_s: f64,
    /// Longest step in contact modes (s).
    pub max_contact_step_s: f64,
    /// `atan(mu)`: the edge of the self-locking range (rad).
    pub atan_mu: f64,
    /// Penetration depth below which a missed landing is reported as invalid (m).
    pub penetration_tol_m: f64,
    /// `1/m` (1/kg), `1/L` (1/m) and `1/(m L^2)` (1/(kg m^2)): the contact equations
    /// multiply by these instead of dividing on every evaluation.
    pub inv_mass: f64,
    /// See `inv_mass`.
    pub inv_length: f64,
    /// See `inv_mass`.
    pub inv_ml2: f64,
    /// The plate's frequency `omega / (2 pi)` (Hz).
    pub frequency_hz: f64,
    /// The plate's phase `phi / (2 pi)` (turns).
    pub phase_turns: f64,
    /// The sine-cosine table of [`crate::numerics::trig`], held so that the plate's phase,
    /// evaluated on every right-hand side, skips the table's initialisation check.
    pub trig: Table,
}

impl StickModel {
    /// A model for `p`.
    pub fn new(p: StickParams) -> Self {
        let period = p.period_s();
        StickModel {
            p,
            rate: p.relax_rate(),
            atan_mu: p.mu.atan(),
            period_s: period,
            // A landing missed inside one such interval would need a dip below the plate
            // of at most A h^2/8 with |h_c''| <= A: about 0.1 micrometre here.
            min_flight_sample_s: period / 256.0,
            // Guards are compared at step ends: 14 looks per cycle. DOP853's own step
            // at rtol 1e-10 is about T/13, DP5's T/55. On the default scene a cap of
            // T/14 costs 14.8 accepted and 1.1 rejected steps a cycle (the rejection
            // falls where the motion is fastest), T/16 16.4 and 0.1; beyond T/13 the
            // rejections outgrow the saving.
            max_contact_step_s: period / 14.0,
            penetration_tol_m: 1e-9 * p.length_m.max(1e-3),
            inv_mass: 1.0 / p.mass_kg,
            inv_length: 1.0 / p.length_m,
            inv_ml2: 1.0 / (p.mass_kg * p.length_m * p.length_m),
            frequency_hz: p.plate.omega_rad_s / TAU,
            phase_turns: p.plate.phase_rad / TAU,
            trig: crate::numerics::trig::table(),
        }
    }

    /// Plate height, velocity and acceleration at `t`.
    #[inline]
    pub fn plate(&self, t: f64) -> (f64, f64, f64) {
        let pl = &self.p.plate;
        // phase in turns: f t + phi/(2 pi) (the table's sine and cosine take turns)
        let (s, c) = self
            .trig
            .sin_cos_turns(self.frequency_hz * t + self.phase_turns);
        let w = pl.omega_rad_s;
        let d = pl.amplitude_m;
        (d * s, d * w * c, -d * w * w * s) // formula: z_s = delta cos(wt): phase pi/2 in sin(wt + phi)
    }

    /// The state with its carried trigonometry made exact: in contact modes C's height
    /// and vertical velocity become the plate's at `t`, and in every mode the rod's
    /// direction becomes `(sin theta, cos theta)`. The integrated values differ from
    /// these by the integration error only; every mode entry starts from this state.
    #[inline]
    pub fn canonical(&self, mode: Mode, t: f64, y: &State) -> State {
        let mut y = *y;
        if mode != Mode::Flight {
            let (zs, vs, _) = self.plate(t);
            y[ZC] = zs;
            y[VZC] = vs;
        }
        (y[ROD_X], y[ROD_Z]) = sin_cos(y[TH]);
        y
    }

    /// Position and velocity of P from the state: `P = C + L (sin, cos)` (C.1),
    /// `v_P = v_C + L theta' (cos, -sin)` (C.3).
    #[inline]
    pub fn tip(&self, y: &State) -> [f64; 4] {
        let l = self.p.length_m;
        let (s, c) = sin_cos(y[TH]);
        [
            y[XC] + l * s,          // formula: C.1 x_p = x_c + L sin
            y[ZC] + l * c,          // formula: C.1 z_p = z_c + L cos
            y[VXC] + l * c * y[OM], // formula: C.3 xdot_p = xdot_c + L theta' cos
            y[VZC] - l * s * y[OM], // formula: C.3 zdot_p = zdot_c - L theta' sin
        ]
    }
}
