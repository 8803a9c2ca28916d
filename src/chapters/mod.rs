//! The chapter registry: one entry per chapter id of `DESIGN.md`.
//!
//! Each chapter module exposes `Args` (its clap flags, SI units in the names, the
//! document's scene as defaults) and `run(&Args, &Context) -> Result<ChapterReport>`.
//! Chapters compose `physics` and `numerics`; they hold no stepping loops.

use crate::error::Result;
use crate::report::ChapterReport;
use clap::{Args as ClapArgs, FromArgMatches};
use std::path::PathBuf;

pub mod asymmetric_shaking;
pub mod effective_mass;
pub mod horizontal_shaking;
pub mod locomotion_definition;
pub mod speed_vs_accuracy;
pub mod stick_state_machine;
pub mod stick_with_inertia;
pub mod vertical_shaking;

/// Sub-folder of a chapter's figure folder for the charts that plot wall time: they
/// change from run to run and machine to machine, so they are kept out of the committed,
/// byte-identical set (`.gitignore`: `figures/*/wall-time/`).
pub const WALL_TIME_DIR: &str = "wall-time";

/// Static description of a chapter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ChapterInfo {
    /// Kebab-case id: the subcommand, figure folder and course-text name.
    pub id: &'static str,
    /// Position in the course (the `NN` of `chapters/NN-<id>.md`).
    pub number: u8,
    /// Title.
    pub title: &'static str,
    /// Section(s) of the source document.
    pub section: &'static str,
    /// The question the chapter answers.
    pub question: &'static str,
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
}

/// All chapters, in course order.
pub const CHAPTERS: [ChapterInfo; 8] = [
    ChapterInfo {
        id: "locomotion-definition",
        number: 1,
        title: "What counts as locomotion",
        section: "1",
        question: "When is a motion locomotion and not dragging? (convex hull of media velocities; sailing)",
    },
    ChapterInfo {
        id: "effective-mass",
        number: 2,
        title: "Effective mass and dynamic jamming",
        section: "2",
        question: "Why does a vertical impulse on a leaning stick push it sideways? (m along, m/4 across; J_ℓ/J_v)",
    },
    ChapterInfo {
        id: "horizontal-shaking",
        number: 3,
        title: "Horizontal shaking turns Coulomb friction viscous",
        section: "3.1.1",
        question: "How does horizontal vibration turn Coulomb friction into an effective viscous law? (booktop)",
    },
    ChapterInfo {
        id: "vertical-shaking",
        number: 4,
        title: "Vertical shaking and the law μ_eff = v_ave/v_z",
        section: "3.1.2",
        question: "How does vertical vibration make a small bias force move a block? (μ_eff = v_ave/v_z)",
    },
    ChapterInfo {
        id: "asymmetric-shaking",
        number: 5,
        title: "Linear versus Coulomb friction under asymmetric shaking",
        section: "3.2",
        question: "Why does asymmetric shaking move a block with Coulomb friction but not with linear friction?",
    },
    ChapterInfo {
        id: "stick-state-machine",
        number: 6,
        title: "The stick's hybrid state machine",
        section: "4, 5",
        question: "The hybrid simulation of the stick: flight, pivot, slide left, slide right, collision",
    },
    ChapterInfo {
        id: "speed-vs-accuracy",
        number: 7,
        title: "Speed versus accuracy of the numerical methods",
        section: "all",
        question: "Work-precision charts and the places where numerical methods fail",
    },
    ChapterInfo {
        id: "stick-with-inertia",
        number: 8,
        title: "The stick with inertia",
        section: "2, 4",
        question: "Does a stick with real mass walk as the massless model says? (rod mass + tip mass, impacts with friction, Painleve cases, the massless limit)",
    },
];

/// Looks a chapter up by id.
pub fn info(id: &str) -> Option<&'static ChapterInfo> {
    CHAPTERS.iter().find(|c| c.id == id)
}

/// Smallest accepted `--g-mps2` (m/s^2).
pub const G_MIN_MPS2: f64 = 1.0;
/// Largest accepted `--g-mps2` (m/s^2).
pub const G_MAX_MPS2: f64 = 25.0;
/// Why `--g-mps2` has its range (the error line and `--help` quote it).
pub const G_WHY: &str = "the scenes are table-top experiments on a planet's surface, from below the Moon's 1.62 to above Jupiter's 24.8 m/s^2; every chapter's checks are run at both ends (tests/cli.rs), and the stick's spring holds it up over this range";

/// Checks `--g-mps2` against [`G_MIN_MPS2`, `G_MAX_MPS2`] (m/s^2).
pub fn check_g(g_mps2: f64) -> Result<f64> {
    crate::error::range("--g-mps2", g_mps2, G_MIN_MPS2, G_MAX_MPS2, "m/s^2", G_WHY)
}

/// Whether chapter `id` uses g (chapters 1 and 2 compute ratios independent of it).
/// `all --g-mps2` applies g to these chapters only.
pub fn uses_g(id: &str) -> bool {
    !matches!(id, "locomotion-definition" | "effective-mass")
}

/// Refuses `--g-mps2` in a chapter whose results do not depend on g (a flag must mean
/// something wherever it is accepted).
pub fn refuse_g(id: &str, ctx: &Context) -> Result<()> {
    match ctx.g_mps2 {
        Some(g) => Err(crate::error::WorkbookError::bad_input(
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
    match id {
        "locomotion-definition" => locomotion_definition::run(&default_args(), ctx),
        "effective-mass" => effective_mass::run(&default_args(), ctx),
        "horizontal-shaking" => horizontal_shaking::run(&default_args(), ctx),
        "vertical-shaking" => vertical_shaking::run(&default_args(), ctx),
        "asymmetric-shaking" => asymmetric_shaking::run(&default_args(), ctx),
        "stick-state-machine" => stick_state_machine::run(&default_args(), ctx),
        "speed-vs-accuracy" => speed_vs_accuracy::run(&default_args(), ctx),
        "stick-with-inertia" => stick_with_inertia::run(&default_args(), ctx),
        other => Err(crate::error::WorkbookError::bad_input(
            "<chapter-id>",
            other,
            "one of the ids printed by `workbook list`",
        )),
    }
}

/// The claim `id` of a chapter run in quick mode, headless, with default flags and the
/// statements `doc` (`run_with` is the chapter's runner that takes them): how a mutation
/// judges a claim whose check needs the whole chapter.
pub fn quick_claim<A: ClapArgs + FromArgMatches, D>(
    id: &str,
    doc: &D,
    run_with: fn(&A, &Context, &D) -> Result<ChapterReport>,
) -> crate::report::Claim {
    let r =
        run_with(&default_args(), &Context::headless(true), doc).expect("default flags are valid");
    r.claims
        .into_iter()
        .find(|c| c.id == id)
        .expect("claim id of this chapter")
}

/// The falsification mutations of chapter `id`'s claims (empty for an unknown id).
pub fn mutations(id: &str) -> Vec<crate::report::Mutation> {
    match id {
        "locomotion-definition" => locomotion_definition::mutations(),
        "effective-mass" => effective_mass::mutations(),
        "horizontal-shaking" => horizontal_shaking::mutations(),
        "vertical-shaking" => vertical_shaking::mutations(),
        "asymmetric-shaking" => asymmetric_shaking::mutations(),
        "stick-state-machine" => stick_state_machine::mutations(),
        "speed-vs-accuracy" => speed_vs_accuracy::mutations(),
        "stick-with-inertia" => stick_with_inertia::mutations(),
        _ => Vec::new(),
    }
}

/// The report of a chapter that is not built yet: says so, no claims.
pub fn not_built(id: &str) -> ChapterReport {
    let info = info(id).expect("registered chapter");
    let mut r = info.report();
    r.status = Some("this chapter is not built yet: no claims are checked".to_string());
    r
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
}
