//! The flags of a stick scene's main run: `workbook stick-state-machine`'s (chapter 6
//! flattens [`RunFlags`] into its `Args`) and the lab's, which builds the same flags
//! from its sliders and validates them here, with the command's own lines.

use super::stick::{self as stick_flags, StickFlags, BOX10};
use super::{choice, Control, Flag, Scale};
use crate::error::Result;
use crate::numerics::hybrid::Options;
use crate::numerics::ode::StepControl;
use crate::physics::domain::Interval;
use crate::physics::stick::{CollisionAngle, StickParams};
use crate::scenes::stick::main_run::Settings;
use crate::scenes::stick::{self as scenes, ContactMethod, Rules, Start};
use crate::scenes::Choice as _;

/// `--mass-kg`: the tip mass of chapter 6's stick.
pub const MASS_KG: Flag = Flag::new("--mass-kg", "Tip mass m", "kg", Interval::closed(0.1, 10.0))
    .why(BOX10)
    .default_is("scene: 1")
    .shown_in_lab(Control::slider("m", "tip mass at P", Scale::Log(None)));

/// `--duration-s`: its bound depends on `--frequency-hz` and `--gamma` (the range
/// field holds it at the jamming scene: 1.5e5/(2 pi 30 x 3) = 265.26 s).
pub const DURATION_S: Flag = Flag::new(
    "--duration-s",
    "Simulated time",
    "s",
    Interval::closed(0.0, 265.0).open_below(),
)
.shown_as("0 < t <= 1e4 s and omega t Gamma <= 1.5e5")
.why("the rounding of the plate phase must stay under the cone check's 1e-10 m g; runs estimated beyond 10 minutes (f t > 4e7 drive cycles in a release build, 5e6 in a debug build) need --allow-long-runs")
.default_is("10; 2 with --quick")
.coupled()
.budgeted()
.shown_in_lab(Control::slider("duration", "simulated time", Scale::Linear(0.1)).within(0.2, 10.0));

/// The table of the main run's physical flags (chapter 6's `FLAGS`).
pub const FLAGS: &[Flag] = &[
    stick_flags::LENGTH_M,
    MASS_KG,
    stick_flags::STIFFNESS,
    stick_flags::DAMPING,
    stick_flags::MU,
    stick_flags::THETA0_RAD,
    stick_flags::GAMMA,
    stick_flags::FREQUENCY_HZ,
    DURATION_S,
    stick_flags::RTOL,
    super::G,
];

/// The lab's controls, in the page's order: the main run's entries the lab shows, and
/// chapter 8's rod mass after the tip mass (the lab's rod, `crate::lab`).
pub const LAB: &[Flag] = &[
    stick_flags::THETA0_RAD,
    stick_flags::MU,
    stick_flags::GAMMA,
    stick_flags::FREQUENCY_HZ,
    stick_flags::STIFFNESS,
    stick_flags::DAMPING,
    stick_flags::LENGTH_M,
    MASS_KG,
    stick_flags::ROD_MASS_KG,
    DURATION_S,
    stick_flags::RTOL,
];

/// The parser of `--collision-angle` (the physics enum stays free of clap).
fn collision_angle_parser() -> impl clap::builder::TypedValueParser<Value = CollisionAngle> {
    use clap::builder::TypedValueParser as _;
    clap::builder::PossibleValuesParser::new(["actual", "reset"]).map(|s| match s.as_str() {
        "reset" => CollisionAngle::Reset,
        _ => CollisionAngle::Actual,
    })
}

/// The flags of the main run. Unset physical flags take the chosen scene's value.
/// Ranges: a box within a factor 10 of the authors' stick (wider where a limit is
/// physical: a free hinge, a still plate), over which the chapter's checks are run at
/// the corners (tests/cli.rs); the duration is bounded by the rounding of the plate
/// phase. The help lines of the physical flags come from [`FLAGS`].
#[derive(clap::Args, Debug, Clone)]
pub struct RunFlags {
    /// The stick's flags and its scene, shared with chapter 8 ([`crate::flags::stick`]).
    #[command(flatten)]
    pub stick: StickFlags,
    /// Tip mass m (kg), [`MASS_KG`].
    #[arg(long = "mass-kg")]
    pub mass_kg: Option<f64>,
    /// Simulated time (s), [`DURATION_S`].
    #[arg(long = "duration-s")]
    pub duration_s: Option<f64>,
    /// Lever arm of the collision map: `actual` (the angle at landing, what the physics
    /// supports) or `reset` (the document's theta_0).
    #[arg(long = "collision-angle", default_value = "actual", value_parser = collision_angle_parser())]
    pub collision_angle: CollisionAngle,
    /// Relative (and absolute) tolerance in the contact modes, [`stick_flags::RTOL`].
    #[arg(long, default_value_t = stick_flags::RTOL.default_value())]
    pub rtol: f64,
    /// Integrator of the contact modes; both locate events on their dense output.
    #[arg(long, default_value = ContactMethod::Dop853.name(), value_parser = choice::<ContactMethod>())]
    pub method: ContactMethod,
    /// Starting state of the main run.
    #[arg(long, default_value = Start::Static.name(), value_parser = choice::<Start>())]
    pub start: Start,
    /// Transition rules: `physical` (the contact conditions) or `printed` (the document's
    /// Table 1 and Algorithms 1 to 4, run as printed).
    #[arg(long, default_value = Rules::Physical.name(), value_parser = choice::<Rules>())]
    pub rules: Rules,
}

/// `x` (> 0) rounded down to `digits` significant digits, as text: a bound printed in
/// an error line that is never above the bound checked.
fn floor_digits(x: f64, digits: i32) -> String {
    let scale = 10f64.powi(digits - 1 - x.log10().floor() as i32);
    crate::error::num((x * scale).floor() / scale)
}

impl RunFlags {
    /// The main run's settings ([`Settings`]).
    pub fn settings(&self) -> Settings {
        Settings {
            scene: self.stick.scene,
            start: self.start,
            rules: self.rules,
            method: self.method,
            rtol: self.rtol,
        }
    }

    /// Validated parameters, duration (s) and options, with `g_mps2` the global flag and
    /// `quick` the short mode: each flag checked against its entry of [`FLAGS`] (the
    /// coupled ones with [`Flag::check_coupled`]), then by the model's constructor.
    pub fn setup(&self, g_mps2: Option<f64>, quick: bool) -> Result<(StickParams, f64, Options)> {
        let base = self.stick.scene.params(g_mps2);
        let v = self.stick.resolve(&base)?;
        // formula: in flight the massless rod's moment balance is k (theta - theta_0) + gamma theta' = 0 (C.3)
        stick_flags::DAMPING.check_coupled(
            v.damping,
            |d| d > 0.0 || v.stiffness == 0.0,
            "0 < value <= 0.1 when --stiffness is above 0 (0 only with --stiffness 0)",
            "in flight the massless rod follows θ' = -(k/γ)(θ - θ₀) (C.3), undetermined at γ = 0",
        )?;
        let m = MASS_KG.check(self.mass_kg.unwrap_or(base.mass_kg))?;
        let default_duration = if quick { 2.0 } else { 10.0 };
        let t_max = scenes::max_duration_s(v.frequency_hz, v.gamma);
        let dur = DURATION_S.check_coupled(
            self.duration_s.unwrap_or(default_duration),
            |t| t > 0.0 && t <= t_max,
            &format!(
                "0 < value <= {} (omega t Gamma <= {} and t <= 1e4 s at this --frequency-hz and --gamma)",
                floor_digits(t_max, 6),
                crate::error::num(scenes::PHASE_ROUNDING_MAX)
            ),
            "the plate phase omega t carries a rounding of eps omega t, a force error of ~3 eps omega t Gamma m g that the cone check's 1e-10 m g must cover",
        )?;
        let rtol = stick_flags::RTOL.check(self.rtol)?;
        let mut p = super::stick_params(&base, &v, m)?;
        p.collision_angle = self.collision_angle;
        let opts = Options {
            method: self.method.method(),
            control: StepControl::tol(rtol, rtol),
            ..Options::default()
        };
        Ok((p, dur, opts))
    }
}
