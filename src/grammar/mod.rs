//! The command line's grammar: the clap types (global flags, `list`, `all`, `render`,
//! one subcommand per chapter of the registry, `lab`), the parser [`command`] and the
//! command line as typed before and after clap (`argv.rs`). Nothing here runs anything:
//! the dispatcher ([`crate::cli`]) and the lab's request parser ([`crate::lab::api`])
//! both parse with it, so the lab accepts and refuses exactly what the CLI does.

use crate::chapters::{self, ChapterInfo, Context, CHAPTERS};
use crate::error;
use clap::{ArgMatches, CommandFactory, FromArgMatches, Parser, Subcommand};
use std::net::IpAddr;
use std::path::PathBuf;

mod argv;
pub use argv::clap_error_line;
pub(crate) use argv::{join_negative_values, non_utf8_value};

/// Runnable, verified course material on vibration-driven locomotion: a leaning stick
/// that walks on a vertically vibrating plate (dynamic jamming).
///
/// Each chapter re-derives one analysis of the source document, checks every claim
/// against an independent computation and writes its figures. On the terminal it leads
/// with the physics: the chapter's question, its answer with the numbers, where the
/// document is wrong and a one-line count of the verdicts (lines of at most 100
/// columns); `--claims` adds every claim with its evidence, `--json` gives all of it as
/// JSON. Verdicts: confirmed (the document holds), erratum (the document is wrong; the
/// correction is stated), approximation (true in a stated limit), failed (a regression
/// of the workbook itself).
///
/// Exit codes: 0 ran and no claim failed (also when the reader closes stdout early,
/// as `workbook all | head`); 1 some claim failed (a regression of the workbook); 2 bad
/// input: a flag outside its validated range, or a run beyond the work budget; 3 output
/// cannot be written (the --figures folder is checked before any computation; every file
/// is written whole or not at all); 4 `render --check` found a stale table.
///
/// Figures: the default full run of a chapter (or `all`) rewrites the committed
/// figures/ byte-identical; a run with --quick or any other flag writes them to out/
/// (ignored by git) unless --figures DIR is given.
///
/// Every physical flag accepts exactly the range over which the chapter's checks are
/// validated (each chapter's --help gives the range and its reason; the tests run each
/// chapter at the corners). Runs estimated beyond 10 minutes are refused unless
/// --allow-long-runs is given.
#[derive(Parser, Debug)]
#[command(name = "workbook", version, propagate_version = true)]
pub struct Cli {
    /// What to run.
    #[command(subcommand)]
    pub command: Command,

    /// Short mode (fewer cycles, coarser sweeps; the same checks): what the tests run.
    /// Chapters with nothing long to shorten (locomotion-definition) run as usual.
    #[arg(long, global = true)]
    pub quick: bool,

    /// Print exactly one JSON object per chapter on stdout (`all`: one JSON array), nothing else.
    #[arg(long, global = true)]
    pub json: bool,

    /// Also print every claim: a table of verdict, kind of evidence, expected, computed
    /// and tolerance with the statement under each row, then the parameters, all results
    /// and the figures (`all`: and the table of verdicts by chapter). Its lines may be
    /// wider than 100 columns.
    #[arg(long, global = true, conflicts_with = "json")]
    pub claims: bool,

    /// Root folder for figures; each chapter writes SVG and PNG into `DIR/<chapter-id>/`.
    #[arg(long, global = true, value_name = "DIR", default_value = "figures")]
    pub figures: PathBuf,

    /// Do not write figures.
    #[arg(long, global = true, conflicts_with = "figures")]
    pub no_figures: bool,

    /// Gravitational acceleration g in m/s^2, 1 <= g <= 25 (table-top scenes on a
    /// planet's surface, from below the Moon's 1.62 to above Jupiter's 24.8) [default: 9.81; the stick chapter's `authors` scene uses 10 unless
    /// this flag is given]. It sets the reader's own scene: the stick chapter's run (its
    /// evidence scenes keep the document's g) and chapter 7's block scene (its stick
    /// scene is the authors', g = 10). Refused by the chapters whose results do not
    /// depend on g (locomotion-definition, effective-mass); `all` applies it to the
    /// chapters that use it.
    #[arg(long = "g-mps2", global = true, value_name = "M_PER_S2")]
    pub g_mps2: Option<f64>,

    /// Run even when the estimated work is beyond the budget of 10 minutes: a long
    /// `--duration-s` of stick-state-machine, the one chapter whose work grows with its
    /// flags (refused by the others, whose work is fixed).
    #[arg(long, global = true)]
    pub allow_long_runs: bool,
}

/// The subcommands: `list`, `all`, `render`, and one per chapter.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// List the chapters: id, document section, question.
    List,
    /// Run every chapter with the document's defaults and summarise the verdicts.
    All,
    /// Refresh the generated tables in chapters/*.md (with --check: fail if any is stale).
    Render {
        /// Do not write; exit 4 and name each stale table if the text is out of date.
        #[arg(long)]
        check: bool,
        /// Folder of the course text.
        #[arg(long, value_name = "DIR", default_value = "chapters")]
        dir: PathBuf,
    },
    /// One subcommand per chapter of the registry (`workbook <chapter-id> [flags]`).
    #[command(flatten)]
    Chapter(ChapterRun),
    /// The live lab: a local web page (127.0.0.1) where sliders drive chapter 6's simulator.
    Lab(LabArgs),
}

/// A chapter's subcommand as parsed: its registry entry and its flags (read into the
/// chapter's own `Args` by [`chapters::Chapter::run`]). The subcommands are built from
/// [`CHAPTERS`]: nothing here names a chapter.
#[derive(Debug, Clone)]
pub struct ChapterRun {
    /// The chapter.
    pub chapter: &'static ChapterInfo,
    /// Its flags.
    pub matches: ArgMatches,
}

impl FromArgMatches for ChapterRun {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        use clap::error::ErrorKind;
        let (name, sub) = m
            .subcommand()
            .ok_or_else(|| clap::Error::new(ErrorKind::MissingSubcommand))?;
        let chapter = chapters::info(name)
            .ok_or_else(|| clap::Error::raw(ErrorKind::InvalidSubcommand, name.to_string()))?;
        Ok(ChapterRun {
            chapter,
            matches: sub.clone(),
        })
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        *self = ChapterRun::from_arg_matches(m)?;
        Ok(())
    }
}

impl Subcommand for ChapterRun {
    fn augment_subcommands(cmd: clap::Command) -> clap::Command {
        cmd.subcommands(CHAPTERS.iter().map(ChapterInfo::subcommand))
    }

    fn augment_subcommands_for_update(cmd: clap::Command) -> clap::Command {
        ChapterRun::augment_subcommands(cmd)
    }

    fn has_subcommand(name: &str) -> bool {
        chapters::info(name).is_some()
    }
}

impl Cli {
    /// The shared context of the global flags, validated.
    pub fn context(&self) -> error::Result<Context> {
        if let Some(g) = self.g_mps2 {
            chapters::check_g(g)?;
        }
        Ok(Context {
            quick: self.quick,
            g_mps2: self.g_mps2,
            figures_root: if self.no_figures {
                None
            } else {
                Some(self.figures.clone())
            },
            allow_long_runs: self.allow_long_runs,
        })
    }
}

/// The clap command with negative numbers accepted as values everywhere, so that
/// `--angle-deg -30` works as well as `--angle-deg=-30`.
pub fn command() -> clap::Command {
    fn allow_negative(cmd: clap::Command) -> clap::Command {
        cmd.mut_args(|a| {
            if a.get_action().takes_values() {
                a.allow_negative_numbers(true)
            } else {
                a
            }
        })
        .mut_subcommands(allow_negative)
    }
    allow_negative(Cli::command())
}

/// Default port of the lab.
pub const DEFAULT_PORT: u16 = 8023;

/// Flags of `workbook lab` (`crate::lab::Args`).
#[derive(clap::Args, Debug, Clone)]
pub struct LabArgs {
    /// TCP port to listen on (0: any free port; the address is printed).
    #[arg(long, default_value_t = DEFAULT_PORT)]
    pub port: u16,
    /// IP address to bind. The default, 127.0.0.1, lets only this computer in; any
    /// other address is announced on stderr, since the lab has no authentication.
    #[arg(long, default_value = "127.0.0.1")]
    pub host: IpAddr,
    /// Open the page in the default web browser.
    #[arg(long)]
    pub open: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clap_definition_is_consistent() {
        command().debug_assert();
    }

    #[test]
    fn every_registered_chapter_is_a_subcommand() {
        let cmd = Cli::command();
        for c in CHAPTERS.iter() {
            assert!(cmd.find_subcommand(c.id).is_some(), "{} missing", c.id);
        }
    }
}
