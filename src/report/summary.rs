//! Summaries over several chapter reports: the `workbook all` table and the README's
//! findings list, both counting consistency checks apart from confirmations.

use super::{ChapterReport, Check, Verdict};
use std::fmt::Write as _;

/// The `workbook all` summary table: per chapter, the verdicts (consistency checks
/// apart from the confirmed claims) and the kinds of evidence, then the totals.
pub fn summary_table(reports: &[ChapterReport]) -> String {
    let mut s = String::from("== summary of verdicts ==\n");
    let _ = writeln!(
        s,
        "{:<22} {:>6} {:>9} {:>11} {:>7} {:>13} {:>6}",
        "chapter", "claims", "confirmed", "consistency", "erratum", "approximation", "failed"
    );
    let row = |s: &mut String, name: &str, n: [usize; 6], note: &str| {
        let _ = writeln!(
            s,
            "{:<22} {:>6} {:>9} {:>11} {:>7} {:>13} {:>6}{note}",
            name, n[0], n[1], n[2], n[3], n[4], n[5]
        );
    };
    let mut total = [0usize; 6];
    for r in reports {
        let n = [
            r.claims.len(),
            r.confirmed(),
            r.consistency_checks(),
            r.count(Verdict::Erratum),
            r.count(Verdict::Approximation),
            r.count(Verdict::Failed),
        ];
        for (t, x) in total.iter_mut().zip(n) {
            *t += x;
        }
        let note = if r.status.is_some() {
            "  (not built yet)"
        } else {
            ""
        };
        row(&mut s, &r.chapter, n, note);
    }
    row(&mut s, "all", total, "");
    let distinct = super::causes::causes_of(reports).len();
    let _ = writeln!(
        s,
        "distinct errata: {distinct} (by cause: claims that report the same error of the document count once)"
    );
    let _ = writeln!(s, "by check: {}", kinds_of(reports));
    s
}

/// Counts by kind of evidence over several reports, e.g. `"closed_form 12, ..."`.
pub fn kinds_of(reports: &[ChapterReport]) -> String {
    Check::ALL
        .iter()
        .map(|&k| {
            let n: usize = reports.iter().map(|r| r.count_check(k)).sum();
            format!("{} {n}", k.as_str())
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The README's findings list (block `findings`), generated from the claims of every
/// chapter: the totals, then every erratum and every approximation with its statement.
pub fn findings_markdown(reports: &[ChapterReport]) -> String {
    let sum = |f: &dyn Fn(&ChapterReport) -> usize| -> usize { reports.iter().map(f).sum() };
    let mut s = format!(
        "`workbook all` checks {} claims: {} confirmed (+{} consistency checks, not counted as confirmation), {} errata ({} distinct causes: claims that report the same error of the document, such as two algorithms printing the same line, count once), {} approximations, {} failed. By kind of evidence: {}.\n",
        sum(&|r| r.claims.len()),
        sum(&|r| r.confirmed()),
        sum(&|r| r.consistency_checks()),
        sum(&|r| r.count(Verdict::Erratum)),
        super::causes::causes_of(reports).len(),
        sum(&|r| r.count(Verdict::Approximation)),
        sum(&|r| r.count(Verdict::Failed)),
        kinds_of(reports)
    );
    for (verdict, title) in [
        (
            Verdict::Erratum,
            "Errata (the document is wrong; each claim states the correction)",
        ),
        (
            Verdict::Approximation,
            "Approximations (true in the limit each claim names)",
        ),
    ] {
        let _ = writeln!(s, "\n**{title}:**\n");
        for r in reports {
            for c in r.claims.iter().filter(|c| c.verdict == verdict) {
                let key = super::causes::cause_key(&r.chapter, &c.id, c.same_as.as_deref());
                let same = if verdict == Verdict::Erratum && !key.contains('/') {
                    format!(" (cause `{key}`)")
                } else {
                    String::new()
                };
                let _ = writeln!(
                    s,
                    "- `{}` / `{}` (section {}, {}){same}: {}",
                    r.chapter,
                    c.id,
                    c.section,
                    c.check.as_str(),
                    c.statement
                );
            }
        }
    }
    s
}
