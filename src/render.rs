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

use crate::chapters::{self, Context, CHAPTERS};
use crate::error::{Result, WorkbookError};
use crate::report::ChapterReport;
use std::io::Write;
use std::path::Path;

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

/// Refreshes (or with `check`, verifies) every chapter text in `dir`, and the block
/// `findings` of the README beside it (`dir/../README.md`, generated from the claims of
/// every chapter by [`crate::report::findings_markdown`]). Returns the exit code: 0 when
/// up to date (or refreshed), 1 when `check` found a stale table.
pub fn render(dir: &Path, check: bool, out: &mut dyn Write) -> Result<i32> {
    let ctx = Context::headless(false);
    let mut stale = 0;
    let mut reports = Vec::new();
    let mut seen = 0;
    for info in CHAPTERS.iter() {
        let report = chapters::run_default(info.id, &ctx)?;
        let path = dir.join(info.markdown_path().file_name().expect("file name"));
        if let Ok(text) = std::fs::read_to_string(&path) {
            if !block_names(&text).is_empty() {
                seen += 1;
                let new = fill_blocks(&text, &|n| table_of(&report, n))
                    .map_err(|e| WorkbookError::Io(format!("{}: {e}", path.display())))?;
                stale += refresh(&path, &text, &new, check, out)?;
            }
        }
        reports.push(report);
    }
    let readme = dir
        .parent()
        .unwrap_or_else(|| Path::new(""))
        .join("README.md");
    if let Ok(text) = std::fs::read_to_string(&readme) {
        if !block_names(&text).is_empty() {
            let findings = crate::report::findings_markdown(&reports);
            let new = fill_blocks(&text, &|n| (n == "findings").then(|| findings.clone()))
                .map_err(|e| WorkbookError::Io(format!("{}: {e}", readme.display())))?;
            stale += refresh(&readme, &text, &new, check, out)?;
        }
    }
    stale += render_errata_appendix(dir, &reports, check, out)?;
    if seen == 0 {
        // Nothing checked is not "up to date": a wrong --dir must not pass.
        return Err(WorkbookError::bad_input(
            "--dir",
            dir.display(),
            "a folder holding the course text chapters/NN-<id>.md with generated blocks (none found there)",
        ));
    }
    Ok(i32::from(stale > 0))
}

/// Writes `new` to `path` (or with `check` reports it stale) when it differs from
/// `text`; returns 1 when stale under `check`, else 0.
fn refresh(path: &Path, text: &str, new: &str, check: bool, out: &mut dyn Write) -> Result<i32> {
    if new == text {
        writeln!(out, "up to date: {}", path.display())?;
        return Ok(0);
    }
    if check {
        writeln!(out, "stale: {} (run `workbook render`)", path.display())?;
        return Ok(1);
    }
    std::fs::write(path, new)?;
    writeln!(out, "updated: {}", path.display())?;
    Ok(0)
}

/// Refreshes (or with `check` verifies) the block `errata` of the course's appendix
/// `dir/errata.md`, when the file exists: per chapter, its verdict counts and every claim
/// that is an erratum or an approximation, with its statement (which states the
/// correction or the limit). Returns 1 when `check` finds it stale, else 0.
fn render_errata_appendix(
    dir: &Path,
    reports: &[ChapterReport],
    check: bool,
    out: &mut dyn Write,
) -> Result<i32> {
    use crate::report::Verdict;
    use std::fmt::Write as _;
    let path = dir.join("errata.md");
    let Ok(text) = std::fs::read_to_string(&path) else {
        return Ok(0);
    };
    let mut body = String::new();
    for (n, r) in reports.iter().enumerate() {
        let file = CHAPTERS
            .iter()
            .find(|i| i.id == r.chapter)
            .and_then(|i| {
                i.markdown_path()
                    .file_name()
                    .map(|f| f.to_string_lossy().to_string())
            })
            .unwrap_or_default();
        let _ = writeln!(body, "## {}. {}\n", n + 1, r.title);
        let _ = writeln!(
            body,
            "[Chapter {}]({file}), section {} of the document, `workbook {}`: {} claims, {} confirmed (+{} consistency checks), {} errata, {} approximations, {} failed.\n",
            n + 1,
            r.section,
            r.chapter,
            r.claims.len(),
            r.confirmed(),
            r.consistency_checks(),
            r.count(Verdict::Erratum),
            r.count(Verdict::Approximation),
            r.count(Verdict::Failed)
        );
        let mut listed = 0;
        for (verdict, label) in [
            (Verdict::Erratum, "erratum"),
            (Verdict::Approximation, "approximation"),
        ] {
            for c in r.claims.iter().filter(|c| c.verdict == verdict) {
                listed += 1;
                let _ = writeln!(
                    body,
                    "- **{}** ({label}; section {}; evidence: {}): {}",
                    c.id,
                    c.section,
                    c.check.as_str(),
                    c.statement
                );
            }
        }
        if listed > 0 {
            body.push('\n');
        }
    }
    let new = fill_blocks(&text, &|n| (n == "errata").then(|| body.clone()))
        .map_err(|e| WorkbookError::Io(format!("{}: {e}", path.display())))?;
    refresh(&path, &text, &new, check, out)
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
