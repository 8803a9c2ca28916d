//! The stick's flags, shared by `stick-state-machine` (chapter 6) and
//! `stick-with-inertia` (chapter 8): same names, same ranges, same reasons. A chapter
//! flattens [`StickFlags`] into its `Args` and lists these entries in its `FLAGS`.

use super::{Control, Flag, Scale};
use crate::error::Result;
use crate::physics::domain::Interval;
use crate::physics::stick::StickParams;
use crate::scenes::stick::Scene;
use crate::scenes::Choice as _;

/// Why most of the stick's ranges are what they are.
pub const BOX10: &str = "within a factor 10 of the authors' stick, the box over which the chapter's checks are run at the corners (tests/cli.rs)";

/// `--length-m`.
pub const LENGTH_M: Flag = Flag::new(
    "--length-m",
    "Rod length L",
    "m",
    Interval::closed(0.015, 1.5),
)
.why(BOX10)
.default_is("scene: 0.15")
.shown_in_lab(Control::slider("L", "rod length", Scale::Log(None)));

/// `--stiffness`.
pub const STIFFNESS: Flag = Flag::new(
    "--stiffness",
    "Torsion-spring stiffness k",
    "N m/rad",
    Interval::closed(0.0, 100.0),
)
.why("0 (a free hinge) to 10 x the authors' spring; a spring too weak to hold the stick lets it fall, which the run reports")
.default_is("scene: 10")
.shown_in_lab(Control::slider("k", "hinge spring", Scale::Linear(0.5)));

/// `--damping`.
pub const DAMPING: Flag = Flag::new(
    "--damping",
    "Torsion damper gamma",
    "N m s/rad",
    Interval::closed(0.0, 0.1),
)
.shown_as("0 <= value <= 0.1, and above 0 when a spring and a massless rod need it")
.why("0 to 10 x the authors' damper; the massless rod's flight (C.3, theta' = -(k/gamma)(theta - theta_0)) is undetermined at gamma = 0 when k > 0")
.coupled()
.default_is("scene: 0.01")
.shown_in_lab(Control::slider("γ", "hinge damper", Scale::Linear(0.0005)));

/// `--mu`.
pub const MU: Flag = Flag::new(
    "--mu",
    "Coulomb friction coefficient mu at the foot C",
    "1",
    Interval::closed(0.0, 2.0),
)
.why("dry friction at the foot")
.default_is("scene: 0.4")
.shown_in_lab(Control::slider(
    "μ",
    "friction coefficient at the foot C",
    Scale::Linear(0.01),
));

/// `--theta0-rad`.
pub const THETA0_RAD: Flag = Flag::new(
    "--theta0-rad",
    "Spring rest angle theta_0 from the vertical",
    "rad",
    Interval::open(-std::f64::consts::FRAC_PI_2, std::f64::consts::FRAC_PI_2),
)
.shown_as("-pi/2 < value < pi/2")
.why("strictly between -90 and 90 degrees: the foot C stays below the tip P")
.default_is("jamming: 0.3; authors: 0.4281, from k (0.5 - theta_0) = m g L sin(0.5)")
.shown_in_lab(Control::slider(
    "θ₀",
    "spring rest angle from the vertical",
    Scale::Linear(0.005),
));

/// `--gamma`.
pub const GAMMA: Flag = Flag::new(
    "--gamma",
    "Peak plate acceleration over g, Gamma = delta omega^2 / g",
    "1",
    Interval::closed(0.0, 50.0),
)
.why("a still plate to 5 x the authors' Gamma = 10")
.default_is("jamming: 3; authors: 10")
.shown_in_lab(Control::slider(
    "Γ",
    "peak plate acceleration over g",
    Scale::Log(Some(0.1)),
));

/// `--frequency-hz`.
pub const FREQUENCY_HZ: Flag = Flag::new(
    "--frequency-hz",
    "Plate frequency f",
    "Hz",
    Interval::closed(1.0, 1000.0),
)
.why("1 Hz to 1 kHz; the duration is bounded by omega t Gamma, see --duration-s")
.default_is("scene: 30")
.shown_in_lab(Control::slider("f", "plate frequency", Scale::Log(None)));

/// `--rtol`.
pub const RTOL: Flag = Flag::new(
    "--rtol",
    "Relative (and absolute) tolerance of the Dormand-Prince pair in the contact modes",
    "1",
    Interval::closed(1e-14, 1e-2),
)
.why("from a loose 1e-2 to 1e-14, near the rounding of the state")
.default_value_is(1e-10)
.shown_in_lab(Control::menu(
    "rtol",
    "tolerance of the contact modes",
    &[1e-6, 1e-8, 1e-10, 1e-12],
));

/// Why the masses of chapter 8's stick have their range.
pub const WHY_MASS: &str =
    "0 allowed (a uniform stick, or chapter 6's massless rod) up to 10 x the authors' 1 kg";

/// The lightest rod above 0 the lab runs (kg): lighter rods lose `log10(alpha)` digits
/// in their impacts (`alpha = M l_G^2/I_G ~ 3 M/m_r`), and chapter 8's command runs them
/// as a singular-perturbation composite, which has no trajectory for the lab to animate.
pub const ROD_MASS_MIN_KG: f64 = 1e-4;

/// `--rod-mass-kg`: chapter 8's rod, and the lab's (its slider and its check).
pub const ROD_MASS_KG: Flag = Flag::new(
    "--rod-mass-kg",
    "Mass of the rod, uniform along C-P (0 is chapter 6's massless rod; m + m_r >= 1e-3 kg, and --damping above 0 when m_r = 0 or when alpha = M l_G^2/I_G >= 1e9, a rod lighter than about 3e-9 (m + m_r)); the default is 1 % of the tip mass",
    "kg",
    Interval::closed(0.0, 10.0),
)
.why(WHY_MASS)
.default_value_is(0.01)
.coupled()
.shown_in_lab(Control::slider("m_r", "rod's own mass (chapter 8); 0: the massless rod", Scale::Log(Some(ROD_MASS_MIN_KG))));

/// The stick's flags that chapters 6 and 8 share: the scene, and the stick's
/// parameters, each unset one taking the scene's value. Their help lines come from the
/// entries above, the scenes' from [`crate::scenes::stick::Scene`].
#[derive(clap::Args, Debug, Clone)]
pub struct StickFlags {
    /// Scene whose values the other flags override.
    #[arg(long, default_value = Scene::Jamming.name(), value_parser = super::choice::<Scene>())]
    pub scene: Scene,
    /// [`LENGTH_M`].
    #[arg(long = "length-m")]
    pub length_m: Option<f64>,
    /// [`STIFFNESS`].
    #[arg(long)]
    pub stiffness: Option<f64>,
    /// [`DAMPING`].
    #[arg(long)]
    pub damping: Option<f64>,
    /// [`MU`].
    #[arg(long)]
    pub mu: Option<f64>,
    /// [`THETA0_RAD`].
    #[arg(long = "theta0-rad")]
    pub theta0_rad: Option<f64>,
    /// [`GAMMA`].
    #[arg(long)]
    pub gamma: Option<f64>,
    /// [`FREQUENCY_HZ`].
    #[arg(long = "frequency-hz")]
    pub frequency_hz: Option<f64>,
}

/// The entries of [`StickFlags`], in its order.
pub const SHARED: [Flag; 7] = [
    LENGTH_M,
    STIFFNESS,
    DAMPING,
    MU,
    THETA0_RAD,
    GAMMA,
    FREQUENCY_HZ,
];

impl Default for StickFlags {
    /// The jamming scene, every stick flag unset.
    fn default() -> Self {
        StickFlags {
            scene: Scene::Jamming,
            length_m: None,
            stiffness: None,
            damping: None,
            mu: None,
            theta0_rad: None,
            gamma: None,
            frequency_hz: None,
        }
    }
}

/// The validated values of [`StickFlags`] (SI units, as the entries).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Values {
    /// Rod length L (m).
    pub length_m: f64,
    /// Spring stiffness k (N m/rad).
    pub stiffness: f64,
    /// Damper gamma (N m s/rad).
    pub damping: f64,
    /// Friction coefficient mu (1).
    pub mu: f64,
    /// Spring rest angle theta_0 (rad).
    pub theta0_rad: f64,
    /// Peak plate acceleration over g (1).
    pub gamma: f64,
    /// Plate frequency (Hz).
    pub frequency_hz: f64,
}

impl StickFlags {
    /// The flags, each unset one from the scene `base`, checked against their entries
    /// (the first value outside its range is the error).
    pub fn resolve(&self, base: &StickParams) -> Result<Values> {
        Ok(Values {
            length_m: LENGTH_M.check(self.length_m.unwrap_or(base.length_m))?,
            stiffness: STIFFNESS.check(self.stiffness.unwrap_or(base.stiffness_nm_per_rad))?,
            damping: DAMPING.check(self.damping.unwrap_or(base.damping_nms_per_rad))?,
            mu: MU.check(self.mu.unwrap_or(base.mu))?,
            theta0_rad: THETA0_RAD.check(self.theta0_rad.unwrap_or(base.theta0_rad))?,
            gamma: GAMMA.check(self.gamma.unwrap_or(base.gamma_accel()))?,
            frequency_hz: FREQUENCY_HZ.check(self.frequency_hz.unwrap_or(base.frequency_hz()))?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::stick::domain;

    #[test]
    fn the_accepted_box_lies_inside_the_models_domain() {
        for (flag, dom) in [
            (LENGTH_M, domain::LENGTH_M),
            (STIFFNESS, domain::STIFFNESS_NM_PER_RAD),
            (DAMPING, domain::DAMPING_NMS_PER_RAD),
            (MU, domain::MU),
            (THETA0_RAD, domain::THETA0_RAD),
            (GAMMA, domain::GAMMA),
            (FREQUENCY_HZ, domain::FREQUENCY_HZ),
            (super::super::G, domain::G_MPS2),
        ] {
            assert!(
                dom.includes(&flag.range),
                "{} not inside {dom:?}",
                flag.name
            );
        }
    }

    #[test]
    fn an_unset_flag_takes_the_scene_value_and_a_bad_one_is_named() {
        let base = crate::physics::stick::jamming_scene(9.81);
        let v = StickFlags::default().resolve(&base).unwrap();
        assert_eq!((v.length_m, v.theta0_rad, v.mu), (0.15, 0.3, 0.4));
        let bad = StickFlags {
            mu: Some(f64::NAN),
            ..StickFlags::default()
        };
        let e = bad.resolve(&base).unwrap_err().to_string();
        assert!(
            e.contains("--mu") && e.contains("0 <= value <= 2 (1; dry friction"),
            "{e}"
        );
    }
}
