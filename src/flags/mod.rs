//! The declarative table of the chapters' physical flags: for each flag its name, what
//! it sets, its unit, its accepted range, the reason for that range, its default and,
//! where the lab shows it, its control. One table drives
//!
//! - `--help`: the registry writes each table flag's help line from its entry
//!   ([`with_help`], [`Flag::help`]: what, unit, range, reason, default), clap's own
//!   default hidden: the default is printed once;
//! - the defaults: `Args` takes a number from its entry ([`Flag::default_value`]);
//! - validation: a chapter checks a value with [`Flag::check`], a range that depends on
//!   other flags with [`Flag::check_coupled`] (one line naming the flag, the value, the
//!   range and the reason; exit 2);
//! - `tests/fuzz.rs` and `tests/cli.rs`: they draw values inside, at the ends of and
//!   just outside each range, and run each chapter at its table's corners, from the
//!   registry's tables (`crate::chapters::ChapterInfo::flags`);
//! - the lab: its controls, their order, ends, scales and defaults ([`Control`],
//!   [`main_run::LAB`], `/api/scenes`).
//!
//! Each chapter lists its table as `FLAGS` beside its `Args`; entries two users share
//! live here ([`stick`], [`main_run`], [`G`]), so that a second chapter, or the lab,
//! reuses them instead of copying (no chapter imports another).

use crate::error::{Result, WorkbookError};
use crate::physics::domain::Interval;
use crate::physics::stick::StickParams;
use crate::scenes::Choice;

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
    /// The default: one number that `Args` takes from here, or a text where the
    /// scene or a rule sets it (`scene: 0.15`); `--help` prints it once, from here.
    pub default: DefaultValue,
    /// The range also depends on other flags (its reason says how); `range` holds it at
    /// the chapter's defaults.
    pub coupled: bool,
    /// The chapter's work grows with this flag: `--allow-long-runs` applies to it.
    pub budgeted: bool,
    /// Its control in the lab, if the lab shows it.
    pub control: Option<Control>,
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
            default: DefaultValue::None,
            coupled: false,
            budgeted: false,
            control: None,
        }
    }

    /// With its control in the lab.
    pub const fn shown_in_lab(self, control: Control) -> Self {
        Flag {
            control: Some(control),
            ..self
        }
    }

    /// With the reason for the range.
    pub const fn why(self, reason: &'static str) -> Self {
        Flag { reason, ..self }
    }

    /// With the default set by the scene or a rule, as `--help` shows it (`scene: 0.15`).
    pub const fn default_is(self, text: &'static str) -> Self {
        Flag {
            default: DefaultValue::Text(text),
            ..self
        }
    }

    /// With the default `value` (in `unit`): the chapter's `Args` takes it with
    /// `default_value_t = ENTRY.default_value()`, and `--help` prints it.
    pub const fn default_value_is(self, value: f64) -> Self {
        Flag {
            default: DefaultValue::Value(value),
            ..self
        }
    }

    /// The default value (for `Args`' `default_value_t`); a table whose entry holds no
    /// number is a defect that the first parse of the chapter's flags shows
    /// (`every_numeric_default_comes_from_its_entry`).
    pub const fn default_value(&self) -> f64 {
        match self.default {
            DefaultValue::Value(v) => v,
            _ => panic!("this flag's entry holds no default value"),
        }
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

    /// `value` if it satisfies `holds`, the range that the other flags' values leave this
    /// [`Flag::coupled`] entry (or a range its interval cannot hold: `0, or 1e-6 <= b`); else the one-line bad-input error (exit 2) in the format of
    /// [`Flag::check`]: the flag, the value, `range` (as text, with the other flags' values
    /// worked in) and, with the entry's unit, `reason`. Every coupled check of every
    /// chapter goes through here, so that their lines have one form.
    pub fn check_coupled(
        &self,
        value: f64,
        holds: impl Fn(f64) -> bool,
        range: &str,
        reason: &str,
    ) -> Result<f64> {
        let valid = format!("{range} ({}; {reason})", self.unit);
        crate::error::check(self.name, value, holds, &valid)
    }

    /// The help line: what, unit, range and reason, and the default per scene.
    pub fn help(&self) -> String {
        let mut s = format!("{} ({}; {}", self.about, self.unit, self.range_text());
        if !self.reason.is_empty() {
            s.push_str(": ");
            s.push_str(self.reason);
        }
        s.push(')');
        match self.default {
            DefaultValue::None => {}
            DefaultValue::Value(v) => s.push_str(&format!(" [default: {}]", crate::error::num(v))),
            DefaultValue::Text(t) => s.push_str(&format!(" [{t}]")),
        }
        s
    }
}

/// How the lab shows a flag ([`Flag::shown_in_lab`]): the page builds its controls from
/// these (`/api/scenes`, `controls`), their ends from the entry's range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Control {
    /// The symbol on the page (θ₀, μ, Γ).
    pub symbol: &'static str,
    /// What it sets, a few words under the control.
    pub label: &'static str,
    /// The control's scale.
    pub scale: Scale,
    /// The lab's own ends (lo, hi) where they are narrower than the flag's range (the
    /// duration: the lab animates at most 1000 drive cycles).
    pub ends: Option<(f64, f64)>,
    /// Whether a request must carry it: a slider the page shows (a request never runs on
    /// a value its page did not show); an option in a menu may be left to its default.
    pub required: bool,
}

/// The scale of a lab control.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scale {
    /// A linear slider with this step (in the flag's unit).
    Linear(f64),
    /// A logarithmic slider over the range; with `Some(lo)`, a stop at 0 left of a
    /// logarithmic part from `lo`.
    Log(Option<f64>),
    /// A menu of these values.
    Menu(&'static [f64]),
}

impl Control {
    /// A required slider: `symbol`, `label`, `scale`.
    pub const fn slider(symbol: &'static str, label: &'static str, scale: Scale) -> Self {
        Control {
            symbol,
            label,
            scale,
            ends: None,
            required: true,
        }
    }

    /// An optional menu of `values`.
    pub const fn menu(symbol: &'static str, label: &'static str, values: &'static [f64]) -> Self {
        Control {
            symbol,
            label,
            scale: Scale::Menu(values),
            ends: None,
            required: false,
        }
    }

    /// With the lab's own ends.
    pub const fn within(self, lo: f64, hi: f64) -> Self {
        Control {
            ends: Some((lo, hi)),
            ..self
        }
    }
}

/// The default of a flag, as its entry holds it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DefaultValue {
    /// None in the table: the flag is optional (its absence has a meaning the help says).
    None,
    /// One number, whatever the scene.
    Value(f64),
    /// Set by the scene or by a rule, as `--help` shows it (`scene: 0.15`).
    Text(&'static str),
}

/// The chapter's subcommand `cmd` with the help line of every flag that has an entry in
/// `table` written from the entry ([`Flag::help`]: what, unit, range, reason, default)
/// and clap's own `[default: ...]` hidden: the default is printed once, from the table.
pub fn with_help(cmd: clap::Command, table: &'static [Flag]) -> clap::Command {
    cmd.mut_args(move |a| {
        let entry = a.get_long().and_then(|l| find(table, &format!("--{l}")));
        match entry {
            Some(f) => a.help(f.help()).hide_default_value(true),
            None => a,
        }
    })
}

/// The parser of a flag that chooses one value of a [`Choice`] (`--scene`, `--method`):
/// its names as typed, each with its description in `--help`.
pub fn choice<T: Choice>() -> impl clap::builder::TypedValueParser<Value = T> {
    use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser as _};
    PossibleValuesParser::new(
        T::ALL
            .iter()
            .map(|c| PossibleValue::new(c.name()).help(c.about())),
    )
    .map(|s| {
        // clap has checked that `s` is one of the names: the first value otherwise
        T::ALL
            .iter()
            .copied()
            .find(|c| c.name() == s)
            .unwrap_or(T::ALL[0])
    })
}

/// The flag a coupled condition blames: of `values` (entry, value, default), the first
/// whose value is not its default (the flag the user typed), else the first; with its
/// value. `values` is never empty (a condition couples at least one flag).
pub fn blame<'a>(values: &[(&'a Flag, f64, f64)]) -> (&'a Flag, f64) {
    let (f, v, _) = values
        .iter()
        .find(|(_, v, d)| v != d)
        .copied()
        .unwrap_or(values[0]);
    (f, v)
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
/// would list its own entry (none does).
pub const G: Flag = Flag::new(
    "--g-mps2",
    "Gravitational acceleration g",
    "m/s^2",
    Interval::closed(G_MIN_MPS2, G_MAX_MPS2),
)
.why("the scenes are table-top experiments on a planet's surface, from below the Moon's 1.62 to above Jupiter's 24.8 m/s^2; every chapter's checks are run at both ends (tests/cli.rs), and the stick's spring holds it up over this range")
.default_is("9.81");

pub mod main_run;
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

#[cfg(test)]
mod tests {
    use super::*;

    const A: Flag = Flag::new("--a", "a", "m", Interval::closed(0.0, 1.0)).why("because");
    const B: Flag = Flag::new("--b", "b", "s", Interval::closed(0.0, 1.0)).why("since");

    #[test]
    fn a_coupled_condition_blames_the_flag_the_user_set() {
        assert_eq!(blame(&[(&A, 1.0, 1.0), (&B, 2.0, 3.0)]), (&B, 2.0));
        assert_eq!(blame(&[(&A, 1.0, 1.0), (&B, 3.0, 3.0)]), (&A, 1.0));
    }

    #[test]
    fn a_coupled_check_has_the_one_error_format() {
        // flag, value, range, (unit; reason), exit 2, one line: as a range check
        let plain = A.check(2.0).unwrap_err();
        let coupled = B
            .check_coupled(
                0.5,
                |v| v > 0.7,
                "0.7 < value <= 1 at these flags",
                "a reason",
            )
            .unwrap_err();
        assert_eq!(
            coupled.to_string(),
            "error: invalid value 0.5 for --b: valid range is 0.7 < value <= 1 at these flags (s; a reason)"
        );
        assert_eq!(
            plain.to_string(),
            "error: invalid value 2 for --a: valid range is 0 <= value <= 1 (m; because)"
        );
        assert_eq!((plain.exit_code(), coupled.exit_code()), (2, 2));
        assert!(B.check_coupled(f64::NAN, |_| true, "r", "w").is_err());
        assert_eq!(B.check_coupled(0.8, |v| v > 0.7, "r", "w").ok(), Some(0.8));
    }

    #[test]
    fn every_numeric_default_comes_from_its_entry_and_is_printed_once() {
        for c in crate::chapters::CHAPTERS {
            let cmd = c.subcommand();
            for a in cmd.get_arguments() {
                let Some(long) = a.get_long() else { continue };
                let Some(f) = find(c.flags, &format!("--{long}")) else {
                    continue;
                };
                let clap_default: Vec<String> = a
                    .get_default_values()
                    .iter()
                    .map(|v| v.to_string_lossy().to_string())
                    .collect();
                if let DefaultValue::Value(v) = f.default {
                    // clap parses the entry's default: the same number
                    let parsed: f64 = clap_default[0].parse().expect("a number");
                    assert_eq!(parsed, v, "{}: --{long}", c.id);
                }
                assert!(a.is_hide_default_value_set(), "{}: --{long}", c.id);
                let help = a.get_help().map(|h| h.to_string()).unwrap_or_default();
                let shown = help.matches("[default").count() + help.matches("[scene").count();
                assert!(shown <= 1, "{}: --{long}: {help}", c.id);
            }
            // and the whole --help: no option prints `[default: ` twice
            let text = c.subcommand().render_long_help().to_string();
            for block in text.split("\n\n") {
                assert!(block.matches("[default:").count() <= 1, "{}: {block}", c.id);
            }
        }
    }
}
