//! `workbook render [--check]`: the generated tables of the course text.
//!
//! A chapter's Markdown file (`chapters/NN-<id>.md`) may hold blocks
//!
//! ```text
//! <!-- BEGIN generated:claims -->
//! ... replaced by the table ...
//! <!-- END -->
//! ```
//!
//! The names `claims` and `results` are the chapter's verdict and result tables; other
//! names are tables the chapter adds with [`crate::report::ChapterReport::table`].
//! Tables come from the chapter run in full mode with its default flags and no figures,
//! so that the text always shows what `workbook <id>` computes.
//!
//! The appendix `chapters/errata.md` ("The document's errata and claims") holds the audit
//! material the lessons link to: one section per chapter, whose blocks are named
//! `<chapter-id>:<table>` (`stick-state-machine:claims`, `speed-vs-accuracy:work_precision`)
//! plus `<chapter-id>:summary`, the chapter's verdict counts and its errata and
//! approximations (see [`appendix`]).

mod appendix;
mod lists;

use crate::chapters::{self, Context, CHAPTERS};
use crate::error::{Result, WorkbookError};
use crate::report::ChapterReport;
use std::io::Write;
use std::path::{Path, PathBuf};

const BEGIN: &str = "<!-- BEGIN generated:";
const END: &str = "<!-- END -->";

/// Names of the generated blocks in `text`, in order.
pub fn block_names(text: &str) -> Vec<String> {
    let mut names = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find(BEGIN) {
        let after = &rest[i + BEGIN.len()..];
        if let Some(j) = after.find("-->") {
            names.push(after[..j].trim().to_string());
            rest = &after[j..];
        } else {
            break;
        }
    }
    names
}

/// Replaces the body of every generated block with `table(name)`. Errors on an
/// unknown name or an unterminated block.
pub fn fill_blocks(
    text: &str,
    table: &dyn Fn(&str) -> Option<String>,
) -> std::result::Result<String, String> {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find(BEGIN) {
        let after = &rest[i + BEGIN.len()..];
        let j = after.find("-->").ok_or("unterminated BEGIN marker")?;
        let name = after[..j].trim();
        let body_start = i + BEGIN.len() + j + 3;
        let end_rel = rest[body_start..]
            .find(END)
            .ok_or_else(|| format!("block '{name}' has no {END}"))?;
        let content = table(name).ok_or_else(|| format!("unknown generated block '{name}'"))?;
        out.push_str(&rest[..body_start]);
        out.push('\n');
        out.push_str(content.trim_end());
        out.push('\n');
        out.push_str(END);
        rest = &rest[body_start + end_rel + END.len()..];
    }
    out.push_str(rest);
    Ok(out)
}

/// The table named `name` of a report.
pub fn table_of(report: &ChapterReport, name: &str) -> Option<String> {
    match name {
        "claims" => Some(report.claims_markdown()),
        "results" => Some(report.results_markdown()),
        other => report
            .tables
            .iter()
            .find(|(n, _)| n == other)
            .map(|(_, t)| t.clone()),
    }
}

/// Exit code of `render --check` when a generated table is out of date: 4, apart from
/// 1 (a claim failed, a regression), 2 (bad input) and 3 (output cannot be written).
pub const STALE_EXIT: i32 = 4;

/// Refreshes (or with `check`, verifies) every chapter text in `dir`, the appendix
/// `dir/errata.md` (its blocks `<chapter-id>:<table>`, see [`appendix`]; a registered
/// chapter without a section gets one), the blocks `findings` (generated from the claims
/// of every chapter by [`crate::report::findings_markdown`]) and `chapters` (the
/// registry's table, [`lists`]) of the README beside it (`dir/../README.md`), and the
/// book's table of contents (`dir/../book/SUMMARY.md`, block `chapters`). Returns the exit code: 0 when
/// up to date (or refreshed), [`STALE_EXIT`] when `check` found a stale table.
///
/// `dir` is checked before any chapter runs: it must hold course text with generated
/// blocks (else bad input, exit 2), and without `check` every file to refresh must be
/// writable (else exit 3, naming the file).
pub fn render(dir: &Path, check: bool, out: &mut dyn Write) -> Result<i32> {
    let texts = course_texts(dir, check)?;
    let readme_path = dir
        .parent()
        .unwrap_or_else(|| Path::new(""))
        .join("README.md");
    let readme = std::fs::read_to_string(&readme_path)
        .ok()
        .filter(|t| !block_names(t).is_empty());
    let appendix = appendix::read(dir, check)?.map(|(path, text)| {
        let extended = appendix::with_missing_sections(&text);
        (path, text, extended)
    });
    if texts.is_empty() && appendix.is_none() {
        return Err(WorkbookError::bad_input(
            "--dir",
            dir.display(),
            "a folder holding the course text chapters/NN-<id>.md with generated blocks (none found there)",
        ));
    }
    let ctx = Context::headless(false);
    let mut stale = 0;
    let mut reports = Vec::new();
    for info in CHAPTERS.iter() {
        let text = texts.iter().find(|(p, _)| *p == chapter_path(dir, info));
        let in_appendix = appendix
            .as_ref()
            .is_some_and(|(_, _, t)| appendix::names_chapter(t, info.id));
        if text.is_none() && readme.is_none() && !in_appendix {
            continue; // neither its text, the README's findings nor the appendix need it
        }
        let report = info.run_default(&ctx)?;
        if let Some((path, text)) = text {
            let new = fill_blocks(text, &|n| table_of(&report, n))
                .map_err(|e| WorkbookError::Io(format!("{}: {e}", path.display())))?;
            stale += refresh(path, text, &new, check, out)?;
        }
        reports.push(report);
    }
    if let Some(text) = readme {
        let findings = crate::report::findings_markdown(&reports);
        let root = readme_path.parent().unwrap_or_else(|| Path::new(""));
        let table = lists::readme_table(root);
        let new = fill_blocks(&text, &|n| match n {
            "findings" => Some(findings.clone()),
            lists::BLOCK => Some(table.clone()),
            _ => None,
        })
        .map_err(|e| WorkbookError::Io(format!("{}: {e}", readme_path.display())))?;
        stale += refresh(&readme_path, &text, &new, check, out)?;
    }
    if let Some((path, text, extended)) = appendix {
        let new = appendix::fill(&extended, &reports)
            .map_err(|e| WorkbookError::Io(format!("{}: {e}", path.display())))?;
        stale += refresh(&path, &text, &new, check, out)?;
    }
    stale += refresh_summary(dir, check, out)?;
    Ok(if stale > 0 { STALE_EXIT } else { 0 })
}

/// The book's table of contents beside `dir` (`dir/../book/SUMMARY.md`), when it has
/// the block `chapters`: the registry's chapters, in course order.
fn refresh_summary(dir: &Path, check: bool, out: &mut dyn Write) -> Result<i32> {
    let path = dir
        .parent()
        .unwrap_or_else(|| Path::new(""))
        .join("book")
        .join("SUMMARY.md");
    let Some(text) = std::fs::read_to_string(&path)
        .ok()
        .filter(|t| block_names(t).iter().any(|n| n == lists::BLOCK))
    else {
        return Ok(0);
    };
    let lines = lists::summary_lines();
    let new = fill_blocks(&text, &|n| (n == lists::BLOCK).then(|| lines.clone()))
        .map_err(|e| WorkbookError::Io(format!("{}: {e}", path.display())))?;
    refresh(&path, &text, &new, check, out)
}

/// The course text of chapter `info` in `dir`.
fn chapter_path(dir: &Path, info: &chapters::ChapterInfo) -> PathBuf {
    dir.join(info.markdown_path().file_name().expect("file name"))
}

/// The chapter texts in `dir` that hold generated blocks, read before any computation (a
/// folder with none of them and no appendix is bad input: a wrong `--dir` must not pass
/// as "up to date"); a file that `render` would have to rewrite and cannot is an output
/// error naming it.
fn course_texts(dir: &Path, check: bool) -> Result<Vec<(PathBuf, String)>> {
    let mut texts = Vec::new();
    for info in CHAPTERS.iter() {
        let path = chapter_path(dir, info);
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        if block_names(&text).is_empty() {
            continue;
        }
        if !check {
            crate::output::probe_file(&path).map_err(|e| WorkbookError::Output {
                flag: "--dir".into(),
                path: path.display().to_string(),
                why: e.to_string(),
            })?;
        }
        texts.push((path, text));
    }
    Ok(texts)
}

/// Writes `new` to `path` (or with `check` reports it stale) when it differs from
/// `text`; returns 1 when stale under `check`, else 0.
pub(crate) fn refresh(
    path: &Path,
    text: &str,
    new: &str,
    check: bool,
    out: &mut dyn Write,
) -> Result<i32> {
    if new == text {
        writeln!(out, "up to date: {}", path.display())?;
        return Ok(0);
    }
    if check {
        writeln!(out, "stale: {} (run `workbook render`)", path.display())?;
        return Ok(1);
    }
    crate::output::write_atomic(path, new.as_bytes()).map_err(WorkbookError::Io)?;
    writeln!(out, "updated: {}", path.display())?;
    Ok(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_are_replaced_and_idempotent() {
        let text = "intro\n<!-- BEGIN generated:a -->\nold\n<!-- END -->\nmid\n<!-- BEGIN generated:b -->\n<!-- END -->\nend\n";
        let f = |n: &str| Some(format!("table {n}"));
        let once = fill_blocks(text, &f).unwrap();
        assert_eq!(
            once,
            "intro\n<!-- BEGIN generated:a -->\ntable a\n<!-- END -->\nmid\n<!-- BEGIN generated:b -->\ntable b\n<!-- END -->\nend\n"
        );
        assert_eq!(fill_blocks(&once, &f).unwrap(), once);
        assert_eq!(block_names(text), ["a", "b"]);
    }

    #[test]
    fn unknown_and_unterminated_blocks_are_errors() {
        let none = |_: &str| None;
        assert!(fill_blocks("<!-- BEGIN generated:x -->\n<!-- END -->", &none).is_err());
        assert!(fill_blocks("<!-- BEGIN generated:x -->\nno end", &|_| Some(
            String::new()
        ))
        .is_err());
    }
}
