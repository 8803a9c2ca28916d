//! The command line: clap derive types, one subcommand per chapter of the registry,
//! and the dispatcher that maps results to exit codes (0 ok, 1 a claim failed, 2 bad input).

use crate::chapters::{self, ChapterInfo, Context, CHAPTERS};
use crate::error::{self, WorkbookError};
use crate::render;
use crate::report::ChapterReport;
use clap::{ArgMatches, CommandFactory, FromArgMatches, Parser, Subcommand};
use std::ffi::OsString;
use std::io::Write;
use std::path::{Path, PathBuf};

mod argv;
mod lead;
mod screen;
pub use argv::clap_error_line;
use argv::{join_negative_values, non_utf8_value};
pub use screen::WIDTH;

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
    /// planet's surface, from below the Moon's 1.62 to above Jupiter's 24.8; chapter 7
    /// needs g >= 3) [default: 9.81; the stick chapter's `authors` scene uses 10 unless
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
    Lab(crate::lab::Args),
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

/// Parses `args` and runs; returns the process exit code. Output goes to the given
/// writers (stdout, stderr) so that the whole CLI can be tested in-process.
pub fn run_cli<I, T>(args: I, out: &mut dyn Write, err: &mut dyn Write) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cmd = command();
    let args: Vec<OsString> = args.into_iter().map(Into::into).collect();
    if let Some(line) = non_utf8_value(&args) {
        let _ = writeln!(err, "{line}");
        return 2;
    }
    let args = join_negative_values(&cmd, args);
    let parsed = cmd
        .try_get_matches_from(args)
        .and_then(|m| Cli::from_arg_matches(&m).map(|c| (c, given_globals(&m), exploring(&m))));
    let (mut cli, given, exploring) = match parsed {
        Ok(c) => c,
        Err(e) => {
            use clap::error::ErrorKind;
            return match e.kind() {
                ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
                    let _ = write!(out, "{}", e.render());
                    0
                }
                ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
                    // no subcommand: the usage is the error message (stderr, exit 2)
                    let _ = write!(err, "{}", e.render());
                    2
                }
                _ => {
                    let _ = writeln!(err, "{}", clap_error_line(&e));
                    2
                }
            };
        }
    };
    let redirected = exploring && !given.contains(&"figures") && !cli.no_figures;
    if redirected {
        // Exploring keeps the checkout clean: the committed figures/ hold the default
        // full runs that the course's captions describe.
        cli.figures = PathBuf::from(EXPLORE_FIGURES);
    }
    match refuse_unused(&cli, &given)
        .and_then(|()| dispatch(&cli, out, err))
        .and_then(|code| out.flush().map(|()| code).map_err(Into::into))
    {
        Ok(code) => {
            if redirected && computes(&cli.command) {
                let _ = writeln!(
                    err,
                    "note: the figures of this non-default run are in {EXPLORE_FIGURES}/ (figures/ keeps the default runs; --figures DIR chooses)"
                );
            }
            code
        }
        Err(WorkbookError::BrokenPipe) => 0, // the reader closed stdout: end quietly
        Err(e) => {
            let _ = writeln!(err, "{e}");
            e.exit_code()
        }
    }
}

/// The global flags (clap ids) the user typed.
fn given_globals(m: &clap::ArgMatches) -> Vec<&'static str> {
    use clap::parser::ValueSource;
    const IDS: [&str; 7] = [
        "quick",
        "json",
        "claims",
        "figures",
        "no_figures",
        "g_mps2",
        "allow_long_runs",
    ];
    let sub = m.subcommand().map(|(_, s)| s);
    IDS.into_iter()
        .filter(|id| {
            [Some(m), sub]
                .into_iter()
                .flatten()
                .any(|mm| mm.value_source(id) == Some(ValueSource::CommandLine))
        })
        .collect()
}

/// Folder for the figures of runs with `--quick` or any non-default physical flag
/// (unless `--figures` is given): `out/`, ignored by git.
pub const EXPLORE_FIGURES: &str = "out";

/// Flags that change what is printed or saved but not what is computed: a run with only
/// these still writes the committed figures.
const OUTPUT_ONLY: [&str; 5] = ["json", "claims", "events", "figures", "no_figures"];

/// Whether the command line asks for anything but the default full run: `--quick`, a
/// physical flag, a scene or method, `--g-mps2` (every flag a user typed except
/// [`OUTPUT_ONLY`] ones).
fn exploring(m: &clap::ArgMatches) -> bool {
    use clap::parser::ValueSource;
    let typed = |mm: &clap::ArgMatches| {
        mm.ids().any(|id| {
            let id = id.as_str();
            !OUTPUT_ONLY.contains(&id) && mm.value_source(id) == Some(ValueSource::CommandLine)
        })
    };
    typed(m) || m.subcommand().is_some_and(|(_, sub)| typed(sub))
}

/// Whether a subcommand runs chapters (and may write figures).
fn computes(c: &Command) -> bool {
    !matches!(c, Command::List | Command::Render { .. } | Command::Lab(_))
}

/// Refuses a global flag where it would mean nothing (every flag means something
/// wherever it is accepted): `list` takes only --json, `render` none, and
/// --allow-long-runs only the chapter with a work budget (stick-state-machine; the
/// others do a fixed amount of work). --g-mps2 is checked by the chapters.
fn refuse_unused(cli: &Cli, given: &[&str]) -> error::Result<()> {
    const RUN_FLAGS: &[&str] = &["quick", "json", "claims", "figures", "no_figures", "g_mps2"];
    let (what, allowed): (&str, &[&str]) = match &cli.command {
        Command::List => ("list", &["json"]),
        Command::Render { .. } => ("render", &[]),
        Command::Lab(_) => ("lab", &[]),
        Command::Chapter(c) if c.chapter.work_budget() => return Ok(()),
        Command::All => ("all", RUN_FLAGS),
        Command::Chapter(_) => ("this chapter", RUN_FLAGS),
    };
    match given.iter().find(|id| !allowed.contains(id)) {
        Some(id) => {
            let budgeted: Vec<&str> = CHAPTERS
                .iter()
                .filter(|c| c.work_budget())
                .map(|c| c.id)
                .collect();
            let why = if *id == "allow_long_runs" {
                format!(
                    " (it applies to {}, the one chapter with a work budget)",
                    budgeted.join(", ")
                )
            } else {
                String::new()
            };
            Err(WorkbookError::bad_input(
                &format!("--{}", id.replace('_', "-")),
                "(given)",
                &format!("none: {what} does not use this flag{why}"),
            ))
        }
        None => Ok(()),
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

/// Checks before any computation that the figure root can be written: it is a folder
/// (created if missing) in which a file can be created. Error: exit code 3.
fn check_figures(root: &Path) -> error::Result<()> {
    let fail = |why: String| WorkbookError::Output {
        flag: "--figures".into(),
        path: root.display().to_string(),
        why,
    };
    if root.exists() && !root.is_dir() {
        return Err(fail("it exists and is not a folder".into()));
    }
    std::fs::create_dir_all(root).map_err(|e| fail(format!("cannot create the folder ({e})")))?;
    crate::output::probe_folder(root).map_err(|e| fail(format!("the folder is not writable ({e})")))
}

/// The report as JSON, refused if it carries a non-finite number (JSON has none; a
/// NaN would turn into `null`): the run then ends `invalid`, naming the field.
fn checked(report: &ChapterReport) -> error::Result<&ChapterReport> {
    match report.first_non_finite() {
        Some(path) => Err(WorkbookError::Invalid(format!(
            "{}: non-finite number at {path}",
            report.chapter
        ))),
        None => Ok(report),
    }
}

fn dispatch(cli: &Cli, out: &mut dyn Write, err: &mut dyn Write) -> error::Result<i32> {
    let ctx = cli.context()?;
    if let (true, Some(root)) = (computes(&cli.command), &ctx.figures_root) {
        check_figures(root)?;
    }
    let (info, report) = match &cli.command {
        Command::List => return list(cli.json, out),
        Command::All => return run_all(cli, &ctx, out),
        Command::Render { check, dir } => return render::render(dir, *check, out),
        Command::Lab(a) => return crate::lab::run(a, out),
        Command::Chapter(c) => (c.chapter, c.chapter.chapter.run(&c.matches, &ctx)?),
    };
    let report = checked(&report)?;
    for note in &report.notes {
        let _ = writeln!(err, "note: {note}");
    }
    if cli.json {
        writeln!(out, "{}", report.to_json())?;
    } else {
        write!(out, "{}", screen::lead(report, info))?;
        if cli.claims {
            write!(out, "\n{}", report.human())?;
        } else {
            write!(out, "{}", screen::details(report))?;
        }
    }
    Ok(i32::from(report.has_failures()))
}

/// `workbook list`: one line per chapter (with `--json`, one array).
fn list(json: bool, out: &mut dyn Write) -> error::Result<i32> {
    if json {
        let list: Vec<serde_json::Value> = CHAPTERS
            .iter()
            .map(|c| serde_json::json!({"id": c.id, "section": c.section, "title": c.title, "question": c.question}))
            .collect();
        writeln!(out, "{}", serde_json::Value::Array(list))?;
    } else {
        for c in CHAPTERS.iter() {
            writeln!(out, "{:<22} section {:<6} {}", c.id, c.section, c.question)?;
        }
    }
    Ok(0)
}

/// Checks `all --g-mps2` before the first chapter runs, against the narrowest range of
/// the chapters that use g (their tables' `--g-mps2` entries).
fn check_all_g(g: f64) -> error::Result<()> {
    let narrowest = CHAPTERS
        .iter()
        .filter_map(|c| crate::flags::find(c.flags, "--g-mps2").map(|f| (c, f)))
        .max_by(|a, b| a.1.range.lo.total_cmp(&b.1.range.lo));
    match narrowest {
        Some((c, f)) if f.range.lo > crate::flags::G.range.lo => {
            let why = format!("`all` runs chapter {}: {}", c.number, f.reason);
            let valid = format!("{} ({}; {why})", f.range_text(), f.unit);
            error::check("--g-mps2", g, |v| f.range.contains(v), &valid).map(drop)
        }
        _ => chapters::check_g(g).map(drop),
    }
}

fn run_all(cli: &Cli, ctx: &Context, out: &mut dyn Write) -> error::Result<i32> {
    if let Some(g) = ctx.g_mps2 {
        check_all_g(g)?;
    }
    let mut reports: Vec<ChapterReport> = Vec::new();
    if !cli.json {
        write!(out, "{}", screen::all_header(CHAPTERS.len()))?;
    }
    for c in CHAPTERS.iter() {
        let mut c_ctx = ctx.clone();
        if !c.uses_g() {
            c_ctx.g_mps2 = None; // documented: `all` applies g where it is used
        }
        let r = c.run_default(&c_ctx)?;
        checked(&r)?;
        if !cli.json {
            writeln!(out, "{}", screen::lead(&r, c))?;
            if cli.claims {
                writeln!(out, "{}", r.human())?;
            }
            out.flush()?; // a chapter's answer shows as soon as it is known
        }
        reports.push(r);
    }
    if cli.json {
        let arr: Vec<serde_json::Value> = reports.iter().map(ChapterReport::to_json).collect();
        writeln!(out, "{}", serde_json::Value::Array(arr))?;
    } else {
        if cli.claims {
            writeln!(out, "{}", crate::report::summary_table(&reports))?;
        }
        write!(out, "{}", screen::all_footer(&reports))?;
    }
    Ok(i32::from(reports.iter().any(ChapterReport::has_failures)))
}

impl From<std::fmt::Error> for WorkbookError {
    fn from(e: std::fmt::Error) -> Self {
        WorkbookError::Io(e.to_string())
    }
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
