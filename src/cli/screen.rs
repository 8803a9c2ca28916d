//! What a student reads on the terminal: per chapter the question, the answer with its
//! numbers, where the document is wrong, a one-line verdict count and where to read and
//! try more; the full claim tables only with `--claims`. Every line of this text fits
//! [`WIDTH`] columns (the claim tables of `--claims` may be wider).

use super::lead::answer;
use crate::chapters::ChapterInfo;
use crate::report::{fmt_value, ChapterReport, Verdict};
use std::fmt::Write as _;

/// The widest line of the first screen, in characters: a usual terminal's 100 columns.
pub const WIDTH: usize = 100;

/// Width of the labels in the left column (`Question: `).
const LABEL: usize = 10;

/// `text` cut to `width` characters, with `...` where it was cut.
fn clip(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        return text.to_string();
    }
    let mut s: String = text.chars().take(width.saturating_sub(3)).collect();
    s.push_str("...");
    s
}

/// `text` wrapped at word boundaries into lines of at most [`WIDTH`] characters: the
/// first after `first`, the others after as many spaces (a word longer than a line is
/// clipped).
pub fn wrap(first: &str, text: &str) -> String {
    let indent = first.chars().count();
    let room = WIDTH.saturating_sub(indent).max(20);
    let mut lines: Vec<String> = vec![String::new()];
    for word in text.split_whitespace() {
        let word = clip(word, room);
        let last = lines.last_mut().expect("one line");
        let len = last.chars().count();
        if len > 0 && len + 1 + word.chars().count() > room {
            lines.push(word);
        } else {
            if len > 0 {
                last.push(' ');
            }
            last.push_str(&word);
        }
    }
    let mut out = String::new();
    for (i, l) in lines.iter().enumerate() {
        let lead = if i == 0 {
            first.to_string()
        } else {
            " ".repeat(indent)
        };
        let _ = writeln!(out, "{}", format!("{lead}{l}").trim_end());
    }
    out
}

/// `n` and the noun, singular or plural (`1 erratum`, `28 errata`).
fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// One line: the claims and their verdicts, consistency checks apart.
pub fn verdicts(r: &[&ChapterReport]) -> String {
    let sum = |f: &dyn Fn(&ChapterReport) -> usize| -> usize { r.iter().map(|x| f(x)).sum() };
    let errata = sum(&|x| x.count(Verdict::Erratum));
    let distinct = sum(&|x| x.distinct_errata());
    let distinct = if distinct == errata {
        String::new()
    } else {
        format!(" ({distinct} distinct)")
    };
    format!(
        "{}: {} confirmed, {}{distinct}, {}, {} failed (+{})",
        count(sum(&|x| x.claims.len()), "claim", "claims"),
        sum(&|x| x.confirmed()),
        count(errata, "erratum", "errata"),
        count(
            sum(&|x| x.count(Verdict::Approximation)),
            "approximation",
            "approximations"
        ),
        sum(&|x| x.count(Verdict::Failed)),
        count(
            sum(&|x| x.consistency_checks()),
            "consistency check",
            "consistency checks"
        ),
    )
}

/// Where the document is wrong: the errata's count and the first one's statement.
fn errata(r: &ChapterReport) -> String {
    let mut wrong = r.claims.iter().filter(|c| c.verdict == Verdict::Erratum);
    match wrong.next() {
        None => match r.count(Verdict::Approximation) {
            0 => "none: the document holds wherever this chapter checks it".into(),
            n => format!(
                "none; {} where it holds only in a limit (the claim names it)",
                count(n, "statement", "statements")
            ),
        },
        Some(first) => format!(
            "{}, for example [{}] {}",
            count(
                r.count(Verdict::Erratum),
                "statement is wrong",
                "statements are wrong"
            ),
            first.section,
            clip(&first.statement, 2 * (WIDTH - LABEL) - 60)
        ),
    }
}

/// The first-screen block of one chapter: question, answer, errata, verdicts, more.
pub fn lead(r: &ChapterReport, c: &ChapterInfo) -> String {
    let sections = if c.section.contains(',') {
        "sections"
    } else {
        "section"
    };
    let mut s = wrap(
        &format!("{}. ", c.number),
        &format!("{} (document {sections} {})", c.title, c.section),
    );
    let label = |name: &str| format!("   {name:<LABEL$}");
    if let Some(status) = &r.status {
        s.push_str(&wrap(&label("Status:"), status));
    }
    s.push_str(&wrap(&label("Question:"), c.question));
    for (i, a) in answer(r).iter().enumerate() {
        let name = if i == 0 { "Answer:" } else { "" };
        s.push_str(&wrap(&label(name), a));
    }
    s.push_str(&wrap(&label("Errata:"), &errata(r)));
    s.push_str(&wrap(&label("Verdicts:"), &verdicts(&[r])));
    let more = format!(
        "read {}, try `workbook {} --help`",
        c.markdown_path().display(),
        c.id
    );
    s.push_str(&wrap(&label("More:"), &more));
    s
}

/// The folder of a report's figures (`figures/<chapter>/`), or `None` without figures.
fn figure_folder(r: &ChapterReport) -> Option<String> {
    let first = r.figures.first()?;
    let key = format!("/{}/", r.chapter);
    Some(match first.find(&key) {
        Some(i) => first[..i + key.len()].to_string(),
        None => first
            .rsplit_once('/')
            .map_or(first.clone(), |(d, _)| format!("{d}/")),
    })
}

/// After a chapter's lead, on a run of that chapter alone: its parameters, its results
/// (each clipped to one line; `--json` has them whole) and its figures.
pub fn details(r: &ChapterReport) -> String {
    let mut s = String::from("\n");
    let p: Vec<String> = r
        .params
        .iter()
        .map(|(k, v)| format!("{k} = {},", fmt_value(v)))
        .collect();
    if !p.is_empty() {
        let joined = p.join(" ");
        s.push_str(&wrap("Parameters: ", joined.trim_end_matches(',')));
    }
    if !r.results.is_empty() {
        let _ = writeln!(s, "Results (whole in --json):");
        for (k, v) in &r.results {
            let _ = writeln!(s, "{}", clip(&format!("  {k} = {}", fmt_value(v)), WIDTH));
        }
    }
    if let Some(dir) = figure_folder(r) {
        let files = count(r.figures.len(), "file", "files");
        let _ = writeln!(s, "Figures: {files} in {dir}");
    }
    s.push_str("Every claim with its evidence: add --claims; everything as JSON: add --json.\n");
    s.push_str("The walking stick live in your browser: `workbook lab`.\n");
    s
}

/// The first line of `workbook all`, before the first chapter's answer.
pub fn all_header(chapters: usize) -> String {
    wrap(
        "",
        &format!(
            "The course in {chapters} answers, each chapter at the document's scene: its \
             question, its answer, where the document is wrong, its verdicts."
        ),
    ) + "\n"
}

/// The last lines of `workbook all`: the totals and where to go next.
pub fn all_footer(reports: &[ChapterReport]) -> String {
    let all: Vec<&ChapterReport> = reports.iter().collect();
    let mut s = wrap("All chapters: ", &verdicts(&all));
    s.push_str(&wrap(
        "More: ",
        "`workbook all --claims` prints every claim with its evidence; `workbook all --json` \
         the same as JSON; `workbook lab` runs the walking stick live in your browser; \
         `workbook <chapter> --help` lists a chapter's flags; the course text is in chapters/.",
    ));
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrapped_lines_fit_and_keep_every_word() {
        let text = "word ".repeat(80) + &"x".repeat(150);
        let out = wrap("   Answer:   ", &text);
        assert!(out.lines().all(|l| l.chars().count() <= WIDTH), "{out}");
        assert_eq!(out.matches("word").count(), 80);
        assert!(out.lines().skip(1).all(|l| l.starts_with(&" ".repeat(13))));
    }

    #[test]
    fn verdicts_count_in_words() {
        let r = ChapterReport::new("x", "X", "1");
        assert_eq!(
            verdicts(&[&r]),
            "0 claims: 0 confirmed, 0 errata, 0 approximations, 0 failed (+0 consistency checks)"
        );
    }
}
