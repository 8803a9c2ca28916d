//! The declarative table of the chapters' physical flags: for each flag its name, what
//! it sets, its unit, its accepted range, the reason for that range and its default per
//! scene. One table drives
//!
//! - `--help`: the registry writes each table flag's help line from its entry
//!   ([`Flag::help`]: what, unit, range, reason, default);
//! - validation: a chapter checks a value with [`Flag::check`] (one line naming the
//!   flag, the value, the range and the reason; exit 2);
//! - `tests/fuzz.rs`: it draws values inside, at the ends of and just outside each range
//!   from the registry's tables ([`crate::chapters::ChapterInfo::flags`]);
//! - the lab: its sliders take their ends from chapter 6's entries (`/api/scenes`).
//!
//! Each chapter lists its table as `FLAGS` beside its `Args`; entries two chapters share
//! live here ([`stick`], [`G`]), so that a second chapter reuses them instead of copying
//! (no chapter imports another).

use crate::error::{Result, WorkbookError};
use crate::physics::domain::Interval;
use crate::physics::stick::StickParams;

/// One physical flag: its entry in the table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Flag {
    /// The flag as typed: `--length-m`.
    pub name: &'static str,
    /// What it sets, with its symbol: "Rod length L".
    pub about: &'static str,
    /// Its unit (`1` when dimensionless).
    pub unit: &'static str,
    /// The accepted values (for a [`Flag::coupled`] flag: at the chapter's defaults).
    pub range: Interval,
    /// The range as printed, where its ends are not plain numbers (`-pi/2 < value < pi/2`).
    pub shown: Option<&'static str>,
    /// Why the range is what it is.
    pub reason: &'static str,
    /// The default, per scene where the scenes differ (`scene: 0.15`); empty when clap
    /// prints the default itself.
    pub default: &'static str,
    /// The range also depends on other flags (its reason says how); `range` holds it at
    /// the chapter's defaults.
    pub coupled: bool,
    /// The chapter's work grows with this flag: `--allow-long-runs` applies to it.
    pub budgeted: bool,
}

impl Flag {
    /// The entry `name` (as typed) setting `about`, in `unit`, accepting `range`.
    pub const fn new(
        name: &'static str,
        about: &'static str,
        unit: &'static str,
        range: Interval,
    ) -> Self {
        Flag {
            name,
            about,
            unit,
            range,
            shown: None,
            reason: "",
            default: "",
            coupled: false,
            budgeted: false,
        }
    }

    /// With the reason for the range.
    pub const fn why(self, reason: &'static str) -> Self {
        Flag { reason, ..self }
    }

    /// With the default shown in `--help` (per scene).
    pub const fn default_is(self, default: &'static str) -> Self {
        Flag { default, ..self }
    }

    /// With the range printed as `text`.
    pub const fn shown_as(self, text: &'static str) -> Self {
        Flag {
            shown: Some(text),
            ..self
        }
    }

    /// Marks the range as depending on other flags too.
    pub const fn coupled(self) -> Self {
        Flag {
            coupled: true,
            ..self
        }
    }

    /// Marks the flag as setting the chapter's amount of work.
    pub const fn budgeted(self) -> Self {
        Flag {
            budgeted: true,
            ..self
        }
    }

    /// The range as text: `0.015 <= value <= 1.5`.
    pub fn range_text(&self) -> String {
        self.shown.map_or_else(|| self.range.text(), str::to_string)
    }

    /// The valid values as the error line states them: `range (unit; reason)`.
    pub fn valid(&self) -> String {
        if self.reason.is_empty() {
            format!("{} ({})", self.range_text(), self.unit)
        } else {
            format!("{} ({}; {})", self.range_text(), self.unit, self.reason)
        }
    }

    /// `value` if it lies in the range, else the one-line bad-input error (exit 2)
    /// naming the flag, the value, the range and the reason.
    pub fn check(&self, value: f64) -> Result<f64> {
        crate::error::check(self.name, value, |v| self.range.contains(v), &self.valid())
    }

    /// The help line: what, unit, range and reason, and the default per scene.
    pub fn help(&self) -> String {
        let mut s = format!("{} ({}; {}", self.about, self.unit, self.range_text());
        if !self.reason.is_empty() {
            s.push_str(": ");
            s.push_str(self.reason);
        }
        s.push(')');
        if !self.default.is_empty() {
            s.push_str(&format!(" [{}]", self.default));
        }
        s
    }
}

/// Finds the entry of `name` (as typed, `--mu`) in `table`.
pub fn find<'a>(table: &'a [Flag], name: &str) -> Option<&'a Flag> {
    table.iter().find(|f| f.name == name)
}

/// Smallest accepted `--g-mps2` (m/s^2).
pub const G_MIN_MPS2: f64 = 1.0;
/// Largest accepted `--g-mps2` (m/s^2).
pub const G_MAX_MPS2: f64 = 25.0;

/// `--g-mps2`, the global flag, in the table of every chapter whose results depend on g
/// (a chapter without it refuses the flag). A chapter validated on a narrower range
/// lists its own entry (chapter 7: from 3 m/s^2).
pub const G: Flag = Flag::new(
    "--g-mps2",
    "Gravitational acceleration g",
    "m/s^2",
    Interval::closed(G_MIN_MPS2, G_MAX_MPS2),
)
.why("the scenes are table-top experiments on a planet's surface, from below the Moon's 1.62 to above Jupiter's 24.8 m/s^2; every chapter's checks are run at both ends (tests/cli.rs), and the stick's spring holds it up over this range")
.default_is("9.81");

pub mod stick;

/// Errors of a model constructor on values the table accepted: a defect of the table
/// (its ranges must lie inside the model's domain), reported as `invalid` (exit 1).
pub fn model_error(e: impl std::fmt::Display) -> WorkbookError {
    WorkbookError::Invalid(format!(
        "the flag table accepted a value the model refuses: {e}"
    ))
}

/// The stick of chapter 6's flags (`length`, `stiffness`, ...) built on `base` and
/// `mass_kg`, checked again by the model's constructor.
pub fn stick_params(base: &StickParams, v: &stick::Values, mass_kg: f64) -> Result<StickParams> {
    StickParams::new(
        v.length_m,
        mass_kg,
        v.stiffness,
        v.damping,
        v.mu,
        v.theta0_rad,
        base.g_mps2,
        v.gamma,
        v.frequency_hz,
    )
    .map_err(model_error)
}
