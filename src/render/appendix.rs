//! The appendix "The document's errata and claims" (`chapters/errata.md`): the audit
//! material of every chapter, generated beside the lessons rather than inside them.
//!
//! The file is course text with one section per chapter; its generated blocks are named
//! `<chapter-id>:<table>`, where `<table>` is any block name a chapter text may use
//! (`claims`, `results`, or a table the chapter adds with
//! [`crate::report::ChapterReport::table`]), or `summary`: the chapter's verdict counts
//! and every claim that is an erratum or an approximation, with its statement (which
//! states the correction or the limit). The prose around the blocks (the readings, the
//! kinds of evidence, the coverage of the document's sections) is written by hand.

use super::{block_names, table_of};
use crate::chapters::CHAPTERS;
use crate::error::{Result, WorkbookError};
use crate::report::{ChapterReport, Verdict};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// File name of the appendix in the course-text folder.
pub const FILE: &str = "errata.md";

/// The line of the appendix above which `workbook render` adds the section of every
/// registered chapter that has none (a copy without the line gets no sections added).
pub const NEW_SECTIONS: &str =
    "<!-- new chapters: `workbook render` adds their sections above this line -->";

/// The blocks of a chapter's section: its summary, its claims and its results.
pub const SECTION_TABLES: [&str; 3] = ["summary", "claims", "results"];

/// `text` with a section (heading, then the [`SECTION_TABLES`] blocks, empty until
/// filled) added above [`NEW_SECTIONS`] for every registered chapter without one, in
/// course order; the prose around the blocks is then the author's to write.
pub fn with_missing_sections(text: &str) -> String {
    let Some(at) = text.find(NEW_SECTIONS) else {
        return text.to_string();
    };
    let mut added = String::new();
    for info in CHAPTERS.iter().filter(|i| !names_chapter(text, i.id)) {
        let _ = writeln!(
            added,
            "## {}. {}
",
            info.number, info.title
        );
        for (table, heading) in
            SECTION_TABLES
                .iter()
                .zip(["", "### Claims", "### Results (default flags)"])
        {
            if !heading.is_empty() {
                let _ = writeln!(
                    added,
                    "{heading}
"
                );
            }
            let _ = writeln!(
                added,
                "<!-- BEGIN generated:{}:{table} -->\n<!-- END -->\n",
                info.id
            );
        }
    }
    format!("{}{added}{}", &text[..at], &text[at..])
}

/// The appendix in `dir` with its text, when it exists and holds generated blocks; a
/// file that `render` would have to rewrite and cannot is an output error naming it.
pub fn read(dir: &Path, check: bool) -> Result<Option<(PathBuf, String)>> {
    let path = dir.join(FILE);
    let Ok(text) = std::fs::read_to_string(&path) else {
        return Ok(None);
    };
    if block_names(&text).is_empty() {
        return Ok(None);
    }
    if !check {
        crate::output::probe_file(&path).map_err(|e| WorkbookError::Output {
            flag: "--dir".into(),
            path: path.display().to_string(),
            why: e.to_string(),
        })?;
    }
    Ok(Some((path, text)))
}

/// Whether a block of the appendix `text` names chapter `id` (`<id>:<table>`).
pub fn names_chapter(text: &str, id: &str) -> bool {
    block_names(text)
        .iter()
        .any(|n| n.split_once(':').is_some_and(|(c, _)| c == id))
}

/// `text` with every block `<chapter-id>:<table>` filled from that chapter's report.
pub fn fill(text: &str, reports: &[ChapterReport]) -> std::result::Result<String, String> {
    super::fill_blocks(text, &|name| {
        let (id, table) = name.split_once(':')?;
        if (id, table) == ("all", "causes") {
            return Some(causes(reports));
        }
        let report = reports.iter().find(|r| r.chapter == id)?;
        match table {
            "summary" => Some(summary(report)),
            other => table_of(report, other),
        }
    })
}

/// The distinct errors of the document (block `all:causes`): one line per cause with
/// the erratum claims that report it, then the count.
pub fn causes(reports: &[ChapterReport]) -> String {
    let mut body = String::new();
    let keys = crate::report::causes::causes_of(reports);
    for c in crate::report::causes::CAUSES
        .iter()
        .filter(|c| keys.contains(c.key))
    {
        let claims: Vec<String> = c
            .claims
            .iter()
            .flat_map(|&id| {
                reports
                    .iter()
                    .filter(move |r| {
                        r.claims
                            .iter()
                            .any(|x| x.id == id && x.verdict == Verdict::Erratum)
                    })
                    .map(move |r| format!("`{}/{id}`", r.chapter))
            })
            .collect();
        let _ = writeln!(body, "- **{}**: {} ({}).", c.key, c.what, claims.join(", "));
    }
    for k in keys.iter().filter(|k| k.contains('/')) {
        let _ = writeln!(body, "- `{k}` (a cause of its own).");
    }
    let claims: usize = reports.iter().map(|r| r.count(Verdict::Erratum)).sum();
    let _ = writeln!(
        body,
        "\n{} distinct errors of the document, reported by {claims} erratum claims.",
        keys.len()
    );
    body
}

/// The chapter's verdict counts, then its errata and approximations, one line each.
pub fn summary(r: &ChapterReport) -> String {
    let (number, file) = CHAPTERS
        .iter()
        .find(|i| i.id == r.chapter)
        .map(|i| {
            let file = i.markdown_path();
            let name = file.file_name().map(|f| f.to_string_lossy().to_string());
            (i.number, name.unwrap_or_default())
        })
        .unwrap_or_default();
    let mut body = String::new();
    let _ = writeln!(
        body,
        "[Chapter {number}]({file}), section {} of the document, `workbook {}`: {} claims, {} confirmed (+{} consistency checks), {} errata, {} approximations, {} failed.\n",
        r.section,
        r.chapter,
        r.claims.len(),
        r.confirmed(),
        r.consistency_checks(),
        r.count(Verdict::Erratum),
        r.count(Verdict::Approximation),
        r.count(Verdict::Failed)
    );
    for (verdict, label) in [
        (Verdict::Erratum, "erratum"),
        (Verdict::Approximation, "approximation"),
    ] {
        for c in r.claims.iter().filter(|c| c.verdict == verdict) {
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
    body
}

#[cfg(test)]
mod tests {
    use super::*;

    fn repository_file(path: &str) -> String {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        std::fs::read_to_string(root.join(path)).expect(path)
    }

    #[test]
    fn a_missing_chapter_gets_its_section_above_the_marker_only() {
        let last = CHAPTERS.last().expect("a chapter");
        let full = repository_file(&format!("chapters/{FILE}"));
        let without = full.replace(&format!("generated:{}:", last.id), "generated:gone:");
        let added = with_missing_sections(&without);
        for table in SECTION_TABLES {
            let block = format!("<!-- BEGIN generated:{}:{table} -->", last.id);
            assert_eq!(added.matches(&block).count(), 1, "{block}");
        }
        assert!(
            added.find(&format!("## {}. {}", last.number, last.title)) < added.find(NEW_SECTIONS)
        );
        assert_eq!(
            with_missing_sections(&full),
            full,
            "every chapter has its section"
        );
        let no_marker = without.replace(NEW_SECTIONS, "");
        assert_eq!(with_missing_sections(&no_marker), no_marker);
    }

    /// Every erratum of the appendix (its generated summaries) is listed under a cause
    /// in `report::causes`, so that distinct errata count causes.
    #[test]
    fn every_erratum_has_a_cause() {
        let text = repository_file(&format!("chapters/{FILE}"));
        let mut chapter = "";
        let mut missing = Vec::new();
        for line in text.lines() {
            if let Some(rest) = line.strip_prefix("<!-- BEGIN generated:") {
                if let Some((id, _)) = rest.split_once(':') {
                    chapter = CHAPTERS
                        .iter()
                        .find(|c| c.id == id)
                        .map_or(chapter, |c| c.id);
                }
            }
            let Some(rest) = line.strip_prefix("- **") else {
                continue;
            };
            if let Some((id, tail)) = rest.split_once("** (erratum;") {
                let _ = tail;
                if !crate::report::causes::is_listed(id) {
                    missing.push(format!("{chapter}/{id}"));
                }
            }
        }
        assert!(missing.is_empty(), "errata without a cause: {missing:?}");
    }

    #[test]
    fn blocks_are_named_by_chapter() {
        let text = "a\n<!-- BEGIN generated:x-y:claims -->\n<!-- END -->\n";
        assert!(names_chapter(text, "x-y"));
        assert!(!names_chapter(text, "x"));
        assert_eq!(
            fill(text, &[]),
            Err("unknown generated block 'x-y:claims'".into())
        );
    }
}
