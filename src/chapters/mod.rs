//! The chapter registry: one entry per chapter id of `DESIGN.md`, in [`CHAPTERS`].
//!
//! Everything that lists or runs chapters is built from it: the CLI's subcommands and
//! their `--help` (`crate::cli`), `list`, `all`, `render`, the falsification test
//! (`tests/falsification.rs` through [`mutations`]), [`run_default`], [`uses_g`], the
//! fuzz test's table of ranges and the lab's sliders (through [`ChapterInfo::flags`]).
//!
//! A chapter is a module (folder `<id with _>/` or file) that exposes
//!
//! - `Args`: its clap flags (SI units in the names, the document's scene as defaults);
//! - `FLAGS: &[crate::flags::Flag]`: the table of its physical flags (range, reason,
//!   default per scene), which writes their `--help` lines and validates them;
//! - `run(&Args, &Context) -> Result<ChapterReport>`;
//! - `Document`: its document as the one generic judge sees it ([`Falsifiable`]: the
//!   statements, the quick evidence, the claims, the edits of the statements and the
//!   claims without a 10 % mutation), from which the registry builds its mutations;
//!
//! and is plugged in by its one `chapter!` line in the registry (which declares the
//! module and its entry of [`CHAPTERS`]).
//! Chapters compose `physics` and `numerics`; they hold no stepping loops.

use crate::error::{Result, WorkbookError};
use crate::flags::Flag;
pub use crate::report::Falsifiable;
use crate::report::{ChapterReport, Mutation};
use clap::{Args as ClapArgs, FromArgMatches};
use std::path::PathBuf;

/// Sub-folder of a chapter's figure folder for the charts that plot wall time: they
/// change from run to run and machine to machine, so they are kept out of the committed,
/// byte-identical set (`.gitignore`: `figures/*/wall-time/`).
pub const WALL_TIME_DIR: &str = "wall-time";

/// What a chapter does, whatever the type of its flags: the registry's view of a
/// chapter module (implemented by [`Module`] for every module's `Args`).
pub trait Chapter: Sync {
    /// Adds the chapter's flags (its `Args`) to its subcommand.
    fn args(&self, cmd: clap::Command) -> clap::Command;
    /// Runs the chapter on the parsed flags of its subcommand.
    fn run(&self, matches: &clap::ArgMatches, ctx: &Context) -> Result<ChapterReport>;
    /// Runs the chapter with its default flags.
    fn run_default(&self, ctx: &Context) -> Result<ChapterReport>;
    /// The falsification mutations of its claims (built by the one generic judge,
    /// `crate::report::falsify`, from its `Falsifiable` document).
    fn mutations(&self) -> Vec<Mutation>;
    /// Its document claims without a 10 % mutation, with the reason.
    fn without_ten_percent(&self) -> &'static [(&'static str, &'static str)];
}

/// A chapter module's entry points, typed by its `Args` (`A`).
pub struct Module<A> {
    /// The module's `run`.
    pub run: fn(&A, &Context) -> Result<ChapterReport>,
    /// The mutations of the module's `Document` (`crate::report::falsify::mutations`).
    pub mutations: fn() -> Vec<Mutation>,
    /// Its `Document`'s `WITHOUT_TEN_PERCENT`.
    pub without_ten_percent: &'static [(&'static str, &'static str)],
}

impl<A: ClapArgs + FromArgMatches> Chapter for Module<A> {
    fn args(&self, cmd: clap::Command) -> clap::Command {
        A::augment_args(cmd)
    }

    fn run(&self, matches: &clap::ArgMatches, ctx: &Context) -> Result<ChapterReport> {
        let args = A::from_arg_matches(matches)
            .map_err(|e| WorkbookError::Invalid(format!("flags parsed but not read: {e}")))?;
        (self.run)(&args, ctx)
    }

    fn run_default(&self, ctx: &Context) -> Result<ChapterReport> {
        (self.run)(&default_args(), ctx)
    }

    fn mutations(&self) -> Vec<Mutation> {
        (self.mutations)()
    }

    fn without_ten_percent(&self) -> &'static [(&'static str, &'static str)] {
        self.without_ten_percent
    }
}

/// A registered chapter: its description and its entry points.
#[derive(Clone, Copy)]
pub struct ChapterInfo {
    /// Kebab-case id: the subcommand, figure folder and course-text name.
    pub id: &'static str,
    /// Position in the course (the `NN` of `chapters/NN-<id>.md`).
    pub number: u8,
    /// Title.
    pub title: &'static str,
    /// Section(s) of the source document.
    pub section: &'static str,
    /// The question the chapter answers (its line in `list` and `--help`).
    pub question: &'static str,
    /// The table of its physical flags (the module's `FLAGS`).
    pub flags: &'static [Flag],
    /// Its entry points.
    pub chapter: &'static dyn Chapter,
}

impl PartialEq for ChapterInfo {
    fn eq(&self, other: &Self) -> bool {
        self.id == other.id
    }
}

impl Eq for ChapterInfo {}

impl std::fmt::Debug for ChapterInfo {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ChapterInfo")
            .field("id", &self.id)
            .field("number", &self.number)
            .finish_non_exhaustive()
    }
}

impl ChapterInfo {
    /// Path of the course text, `chapters/NN-<id>.md`, relative to the repository root.
    pub fn markdown_path(&self) -> PathBuf {
        PathBuf::from(format!("chapters/{:02}-{}.md", self.number, self.id))
    }

    /// An empty report for this chapter.
    pub fn report(&self) -> ChapterReport {
        ChapterReport::new(self.id, self.title, self.section)
    }

    /// Whether its results depend on g: its table lists `--g-mps2` (chapters 1 and 2
    /// compute ratios independent of it and refuse the flag).
    pub fn uses_g(&self) -> bool {
        crate::flags::find(self.flags, "--g-mps2").is_some()
    }

    /// Whether its work grows with its flags (a [`Flag::budgeted`] entry): the one kind
    /// of chapter that accepts `--allow-long-runs`.
    pub fn work_budget(&self) -> bool {
        self.flags.iter().any(|f| f.budgeted)
    }

    /// Its subcommand: `workbook <id>`, its flags with their help lines from [`Self::flags`].
    pub fn subcommand(&self) -> clap::Command {
        let sections = match self.section {
            "all" => "all sections".to_string(),
            s if s.contains(',') => format!("sections {s}"),
            s => format!("section {s}"),
        };
        let cmd = self
            .chapter
            .args(clap::Command::new(self.id))
            .about(format!(
                "Ch. {} ({sections}): {}",
                self.number, self.question
            ))
            .long_about(None);
        crate::flags::with_help(cmd, self.flags)
    }

    /// Runs it with its default flags.
    pub fn run_default(&self, ctx: &Context) -> Result<ChapterReport> {
        self.chapter.run_default(ctx)
    }

    /// Its falsification mutations.
    pub fn mutations(&self) -> Vec<Mutation> {
        self.chapter.mutations()
    }

    /// Its document claims without a 10 % mutation, each with the reason (the statement
    /// prints no number a 10 % error could move, or the derived tolerance is coarser).
    pub fn without_ten_percent(&self) -> &'static [(&'static str, &'static str)] {
        self.chapter.without_ten_percent()
    }
}

/// The registry: one line `chapter!(module, number, "id", "title", "section",
/// "question")` per chapter declares its module (`pub(crate) mod module;`, the folder
/// `module/`: a chapter's internals are private to the crate, its tests of them are
/// its unit tests, `module/tests.rs`) and its entry of [`CHAPTERS`] (its `run`, its `FLAGS` and its
/// [`Falsifiable`] `Document`).
macro_rules! registry {
    ($(chapter!($module:ident, $number:literal, $id:literal, $title:literal, $section:literal, $question:literal)),* $(,)?) => {
        $(pub(crate) mod $module;)*

        /// All chapters, in course order: the registry.
        pub static CHAPTERS: &[ChapterInfo] = &[$(
            ChapterInfo {
                id: $id,
                number: $number,
                title: $title,
                section: $section,
                question: $question,
                flags: $module::FLAGS,
                chapter: &Module {
                    run: $module::run,
                    mutations: crate::report::falsify::mutations::<$module::Document>,
                    without_ten_percent: <$module::Document as Falsifiable>::WITHOUT_TEN_PERCENT,
                },
            }
        ),*];
    };
}

registry! {
    chapter!(locomotion_definition, 1, "locomotion-definition", "What counts as locomotion", "1", "When is a motion locomotion and not dragging? (convex hull of media velocities; sailing)"),
    chapter!(effective_mass, 2, "effective-mass", "Effective mass and dynamic jamming", "2", "Why does a vertical impulse on a leaning stick push it sideways? (m along, m/4 across; J_ℓ/J_v)"),
    chapter!(horizontal_shaking, 3, "horizontal-shaking", "Horizontal shaking turns Coulomb friction viscous", "3.1.1", "How does horizontal vibration turn Coulomb friction into an effective viscous law? (booktop)"),
    chapter!(vertical_shaking, 4, "vertical-shaking", "Vertical shaking and the law μ_eff = v_ave/v_z", "3.1.2", "How does vertical vibration make a small bias force move a block? (μ_eff = v_ave/v_z)"),
    chapter!(asymmetric_shaking, 5, "asymmetric-shaking", "Linear versus Coulomb friction under asymmetric shaking", "3.2", "Why does asymmetric shaking move a block with Coulomb friction but not with linear friction?"),
    chapter!(stick_state_machine, 6, "stick-state-machine", "The stick's hybrid state machine", "4, 5", "The hybrid simulation of the stick: flight, pivot, slide left, slide right, collision"),
    chapter!(speed_vs_accuracy, 7, "speed-vs-accuracy", "Speed versus accuracy of the numerical methods", "all", "Work-precision charts and the places where numerical methods fail"),
    chapter!(stick_with_inertia, 8, "stick-with-inertia", "The stick with inertia", "2, 4", "Does a stick with real mass walk as the massless model says? (rod mass + tip mass, impacts with friction, Painleve cases, the massless limit)"),
}

/// Looks a chapter up by id.
pub fn info(id: &str) -> Option<&'static ChapterInfo> {
    CHAPTERS.iter().find(|c| c.id == id)
}

pub use crate::flags::{G_MAX_MPS2, G_MIN_MPS2};

/// Checks `--g-mps2` against [`crate::flags::G`]: [`G_MIN_MPS2`, `G_MAX_MPS2`] (m/s^2).
pub fn check_g(g_mps2: f64) -> Result<f64> {
    crate::flags::G.check(g_mps2)
}

/// Whether chapter `id` uses g ([`ChapterInfo::uses_g`]; false for an unknown id).
/// `all --g-mps2` applies g to these chapters only.
pub fn uses_g(id: &str) -> bool {
    info(id).is_some_and(ChapterInfo::uses_g)
}

/// Refuses `--g-mps2` in a chapter whose results do not depend on g (a flag must mean
/// something wherever it is accepted).
pub fn refuse_g(id: &str, ctx: &Context) -> Result<()> {
    match ctx.g_mps2 {
        Some(g) => Err(WorkbookError::bad_input(
            "--g-mps2",
            g,
            &format!("none: {id} does not use g (its results are ratios independent of gravity); drop the flag"),
        )),
        None => Ok(()),
    }
}

/// Checks the global `--g-mps2` (its range, m/s^2; its error line names the flag) and
/// opens chapter `id`'s report with the already validated flags `params` recorded in
/// order, then `g_mps2`. Returns the report and g (m/s^2).
pub fn report_with_g(
    id: &str,
    ctx: &Context,
    params: &[(&str, f64)],
) -> Result<(ChapterReport, f64)> {
    let g_mps2 = check_g(ctx.g())?;
    let mut r = info(id).expect("registered").report();
    for &(key, value) in params {
        r.param(key, value);
    }
    r.param("g_mps2", g_mps2);
    Ok((r, g_mps2))
}

/// Settings shared by every chapter (the global flags).
#[derive(Debug, Clone)]
pub struct Context {
    /// Short mode for the tests: fewer cycles, coarser sweeps, same checks.
    pub quick: bool,
    /// Gravitational acceleration from `--g-mps2` (m/s^2); `None` means the chapter's
    /// scene default (9.81 m/s^2 unless the scene says otherwise).
    pub g_mps2: Option<f64>,
    /// Root folder for figures (`figures/` by default); `None` with `--no-figures`.
    pub figures_root: Option<PathBuf>,
    /// `--allow-long-runs`: run even when the estimated work is beyond the budget.
    pub allow_long_runs: bool,
}

impl Context {
    /// Standard gravity used when neither the flag nor the scene sets g (m/s^2).
    pub const G_DEFAULT_MPS2: f64 = 9.81;

    /// Gravitational acceleration in m/s^2: the flag, or 9.81.
    pub fn g(&self) -> f64 {
        self.g_mps2.unwrap_or(Self::G_DEFAULT_MPS2)
    }

    /// The figure folder of a chapter, `<root>/<id>`, or `None` when figures are off.
    pub fn figure_dir(&self, id: &str) -> Option<PathBuf> {
        self.figures_root.as_ref().map(|r| r.join(id))
    }

    /// A context for tests and `render`: quick as given, no figures, default g.
    pub fn headless(quick: bool) -> Self {
        Context {
            quick,
            g_mps2: None,
            figures_root: None,
            allow_long_runs: false,
        }
    }
}

/// The defaults of a chapter's flags, exactly as clap would parse an empty command
/// line: one source of truth for `--help`, `all` and `render`.
pub fn default_args<A: ClapArgs + FromArgMatches>() -> A {
    let cmd = A::augment_args(clap::Command::new("defaults"));
    let matches = cmd.get_matches_from(["defaults"]);
    A::from_arg_matches(&matches).expect("chapter defaults parse")
}

/// Runs a chapter by id with its default flags.
pub fn run_default(id: &str, ctx: &Context) -> Result<ChapterReport> {
    match info(id) {
        Some(c) => c.run_default(ctx),
        None => Err(WorkbookError::bad_input(
            "<chapter-id>",
            id,
            "one of the ids printed by `workbook list`",
        )),
    }
}

/// The falsification mutations of chapter `id`'s claims (empty for an unknown id).
pub fn mutations(id: &str) -> Vec<Mutation> {
    info(id).map(ChapterInfo::mutations).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_are_unique_and_numbered_in_order() {
        for (i, c) in CHAPTERS.iter().enumerate() {
            assert_eq!(c.number as usize, i + 1);
            assert_eq!(info(c.id), Some(c));
        }
    }

    /// The value flags of a chapter's subcommand (`--x VALUE`, not an enumeration or a
    /// path, not global).
    fn value_flags(cmd: &clap::Command) -> Vec<String> {
        cmd.get_arguments()
            .filter(|a| a.get_action().takes_values() && a.get_possible_values().is_empty())
            .filter(|a| a.get_value_hint() != clap::ValueHint::FilePath)
            .filter_map(|a| a.get_long().map(|l| format!("--{l}")))
            .collect()
    }

    #[test]
    fn every_value_flag_has_one_table_entry_and_its_help_line() {
        for c in CHAPTERS {
            let cmd = c.subcommand();
            let flags = value_flags(&cmd);
            for f in &flags {
                assert_eq!(
                    c.flags.iter().filter(|e| e.name == f).count(),
                    1,
                    "{}: {f} in the table once",
                    c.id
                );
            }
            for e in c.flags.iter().filter(|e| e.name != "--g-mps2") {
                assert!(
                    flags.contains(&e.name.to_string()),
                    "{}: {} is no flag",
                    c.id,
                    e.name
                );
                let arg = cmd
                    .get_arguments()
                    .find(|a| a.get_long() == Some(&e.name[2..]))
                    .unwrap();
                let help = arg.get_help().map(|h| h.to_string()).unwrap_or_default();
                assert_eq!(help, e.help(), "{}: {}", c.id, e.name);
                assert!(
                    help.contains(&e.range_text()) && !e.reason.is_empty(),
                    "{help}"
                );
            }
        }
    }

    #[test]
    fn g_and_the_work_budget_come_from_the_tables() {
        for c in CHAPTERS {
            assert_eq!(uses_g(c.id), c.flags.iter().any(|f| f.name == "--g-mps2"));
        }
        assert!(!uses_g("no-such-chapter"));
        // the document's chapters by name (a new chapter changes none of these)
        let get = |id| info(id).expect("registered");
        assert!(!get("locomotion-definition").uses_g() && !get("effective-mass").uses_g());
        assert!(get("vertical-shaking").uses_g() && get("stick-state-machine").uses_g());
        assert!(get("stick-state-machine").work_budget());
        assert!(!get("stick-with-inertia").work_budget() && !get("effective-mass").work_budget());
    }

    #[test]
    fn a_value_outside_its_entry_is_one_line_naming_flag_value_range_and_reason() {
        for c in CHAPTERS {
            for f in c.flags.iter().filter(|f| f.range.hi.is_finite()) {
                let e = f.check(f.range.hi * 2.0 + 1.0).unwrap_err().to_string();
                assert!(e.contains(f.name) && e.contains(&f.range_text()), "{e}");
                assert!(e.contains(f.reason) && e.lines().count() == 1, "{e}");
                assert_eq!(f.check(f64::NAN).unwrap_err().exit_code(), 2);
            }
        }
    }

    #[test]
    fn unknown_ids_run_nothing() {
        assert!(run_default("no-such-chapter", &Context::headless(true)).is_err());
        assert!(mutations("no-such-chapter").is_empty());
    }
}
