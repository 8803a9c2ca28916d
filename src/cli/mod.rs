//! The command line: the dispatcher that parses with [`crate::grammar`] (the clap types,
//! one subcommand per chapter of the registry) and maps results to exit codes (0 ok,
//! 1 a claim failed, 2 bad input).

use crate::chapters::{self, Context, CHAPTERS};
use crate::error::{self, WorkbookError};
pub use crate::grammar::{clap_error_line, command, ChapterRun, Cli, Command};
use crate::grammar::{join_negative_values, non_utf8_value};
use crate::render;
use crate::report::ChapterReport;
use clap::FromArgMatches;
use std::ffi::OsString;
use std::io::Write;
use std::path::{Path, PathBuf};

mod lead;
mod screen;
pub use lead::answer;
pub use screen::WIDTH;

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
        Command::All => return run_all(cli, &ctx, out, err),
        Command::Render { check, dir } => return render::render(dir, *check, out),
        Command::Lab(a) => return crate::lab::run(a, out),
        Command::Chapter(c) => (c.chapter, c.chapter.chapter.run(&c.matches, &ctx)?),
    };
    let report = checked(&report)?;
    print_notes(report, None, err);
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

/// A report's notes for the reader, one `note: ` line each on stderr (under `all`,
/// each line names its chapter: `note: stick-state-machine: ...`).
fn print_notes(report: &ChapterReport, chapter: Option<&str>, err: &mut dyn Write) {
    for note in &report.notes {
        let _ = match chapter {
            Some(id) => writeln!(err, "note: {id}: {note}"),
            None => writeln!(err, "note: {note}"),
        };
    }
}

fn run_all(
    cli: &Cli,
    ctx: &Context,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> error::Result<i32> {
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
        print_notes(&r, Some(c.id), err); // the notes of each chapter, as its own command prints them
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
    fn notes_are_printed_one_line_each_and_under_all_with_their_chapter() {
        let mut r = ChapterReport::new("a-chapter", "t", "4");
        r.note("first");
        r.note("second");
        let mut err = Vec::new();
        print_notes(&r, None, &mut err);
        print_notes(&r, Some("a-chapter"), &mut err);
        assert_eq!(
            String::from_utf8(err).unwrap(),
            "note: first\nnote: second\nnote: a-chapter: first\nnote: a-chapter: second\n"
        );
    }
}
