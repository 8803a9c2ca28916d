//! The lists of chapters outside the chapters' own text, generated from the registry
//! ([`CHAPTERS`]) so that a new chapter appears in them when `workbook render` runs: the
//! book's table of contents (`book/SUMMARY.md`, block `chapters`) and the README's table
//! of chapters (block `chapters`).

use crate::chapters::CHAPTERS;
use std::fmt::Write as _;
use std::path::Path;

/// Name of the block both lists fill.
pub const BLOCK: &str = "chapters";

/// The book's numbered chapters, one `- [title](chapters/NN-id.md)` line each.
pub fn summary_lines() -> String {
    let mut out = String::new();
    for info in CHAPTERS.iter() {
        let _ = writeln!(
            out,
            "- [{}]({})",
            info.title,
            info.markdown_path().display()
        );
    }
    out
}

/// The README's table: number, id, the document's sections, command, course text and
/// figure folder (`none` while `root/figures/<id>/` does not exist).
pub fn readme_table(root: &Path) -> String {
    let mut out = String::from(
        "| # | id | document section | command | course text | figures |\n|---|---|---|---|---|---|\n",
    );
    for info in CHAPTERS.iter() {
        let text = info.markdown_path().display().to_string();
        let figures = format!("figures/{}/", info.id);
        let figures = if root.join(&figures).is_dir() {
            format!("[{figures}]({figures})")
        } else {
            "none".to_string()
        };
        let _ = writeln!(
            out,
            "| {} | `{id}` | {} | `workbook {id}` | [{text}]({text}) | {figures} |",
            info.number,
            info.section,
            id = info.id,
        );
    }
    out
}
