//! Claims, verdicts and chapter reports: the human table and the JSON contract.
//!
//! A [`Claim`] is one statement of the source document together with an independent
//! computation that checks it. Its [`Verdict`] is decided by that check (see
//! [`Claim::draft`]): a claim never carries a verdict that no computation supports.
//!
//! The JSON form of a [`ChapterReport`] is the contract of `DESIGN.md`:
//! `{"chapter", "title", "section", "params", "claims", "results", "figures"}`, and a
//! claim is `{"id", "section", "statement", "expected", "computed", "tolerance", "verdict"}`.

pub mod causes;
mod claim;
pub mod falsify;
mod format;
mod summary;

use claim::finite_or_text;
pub use claim::{is_close, Check, Claim, ClaimDraft, DocEdit, Mutation, Verdict};
pub use falsify::Falsifiable;
pub use format::{fmt_num, fmt_value, NON_FINITE};
use serde::Serialize;
use serde_json::{Map, Value};
use std::fmt::Write as _;
pub use summary::{findings_markdown, kinds_of, summary_table};

/// The report of one chapter run.
#[derive(Debug, Clone, Serialize)]
pub struct ChapterReport {
    /// Chapter id (kebab-case), as on the command line.
    pub chapter: String,
    /// Chapter title.
    pub title: String,
    /// Section of the document the chapter covers.
    pub section: String,
    /// The physical parameters the chapter ran with (SI units, unit in the key).
    pub params: Map<String, Value>,
    /// The checked claims.
    pub claims: Vec<Claim>,
    /// Named results (snake_case, SI units in the name where needed).
    pub results: Map<String, Value>,
    /// Paths of the figures written, relative to the working directory.
    pub figures: Vec<String>,
    /// Markdown tables for the course text, by block name (`workbook render`); not in JSON.
    #[serde(skip)]
    pub tables: Vec<(String, String)>,
    /// Free-text status line for the human table (e.g. "not built yet"); not in JSON.
    #[serde(skip)]
    pub status: Option<String>,
    /// Notes for the reader about this run (a fallback taken, a start that was not the
    /// one asked for, a list cut short): the command line prints each on stderr as
    /// `note: ...`, so in-process callers and tests see them too; not in JSON (the
    /// results carry the same facts as keys).
    #[serde(skip)]
    pub notes: Vec<String>,
}

impl ChapterReport {
    /// An empty report for a chapter.
    pub fn new(chapter: &str, title: &str, section: &str) -> Self {
        ChapterReport {
            chapter: chapter.to_string(),
            title: title.to_string(),
            section: section.to_string(),
            params: Map::new(),
            claims: Vec::new(),
            results: Map::new(),
            figures: Vec::new(),
            tables: Vec::new(),
            status: None,
            notes: Vec::new(),
        }
    }

    /// Records a note for the reader (printed on stderr by the command line).
    pub fn note(&mut self, text: impl Into<String>) {
        self.notes.push(text.into());
    }

    /// Records a parameter.
    pub fn param(&mut self, key: &str, value: impl Into<Value>) {
        self.params.insert(key.to_string(), value.into());
    }

    /// Records a named result. A non-finite number is stored as text and adds a
    /// failed claim, so a NaN can never pass unnoticed.
    pub fn result(&mut self, key: &str, value: impl Into<Value>) {
        let v = value.into();
        if v.is_null() || contains_null(&v) {
            self.claims.push(
                Claim::draft(
                    Check::Consistency,
                    &format!("finite-{key}"),
                    "workbook",
                    &format!("result {key} is a finite number"),
                )
                .values("finite", NON_FINITE, "exact")
                .confirmed_if(false),
            );
        }
        self.results.insert(key.to_string(), finite_or_text(v));
    }

    /// Adds a claim.
    pub fn claim(&mut self, claim: Claim) {
        self.claims.push(claim);
    }

    /// Adds a Markdown table for the course text under the block name `name`.
    pub fn table(&mut self, name: &str, markdown: String) {
        self.tables.push((name.to_string(), markdown));
    }

    /// Number of claims with the given verdict.
    pub fn count(&self, verdict: Verdict) -> usize {
        self.claims.iter().filter(|c| c.verdict == verdict).count()
    }

    /// True when some claim failed (exit code 1).
    pub fn has_failures(&self) -> bool {
        self.count(Verdict::Failed) > 0
    }

    /// Distinct errata: the distinct causes of the chapter's errata
    /// ([`causes::cause_key`]: claims that report the same error of the document count
    /// once).
    pub fn distinct_errata(&self) -> usize {
        causes::causes_of(std::slice::from_ref(self)).len()
    }

    /// Number of claims whose evidence is of kind `kind`.
    pub fn count_check(&self, kind: Check) -> usize {
        self.claims.iter().filter(|c| c.check == kind).count()
    }

    /// Confirmed claims backed by evidence that could have failed (every kind but
    /// [`Check::Consistency`]): the only ones counted as confirmation of the document.
    pub fn confirmed(&self) -> usize {
        self.claims
            .iter()
            .filter(|c| c.verdict == Verdict::Confirmed && c.check != Check::Consistency)
            .count()
    }

    /// Confirmed claims that hold by construction ([`Check::Consistency`]): sanity
    /// checks, counted apart and never as confirmation.
    pub fn consistency_checks(&self) -> usize {
        self.claims
            .iter()
            .filter(|c| c.verdict == Verdict::Confirmed && c.check == Check::Consistency)
            .count()
    }

    /// The counts by kind of evidence, e.g. `"closed_form 3, simulation 2"` (kinds with
    /// no claim left out).
    pub fn kinds_summary(&self) -> String {
        let parts: Vec<String> = Check::ALL
            .iter()
            .map(|&k| (k, self.count_check(k)))
            .filter(|&(_, n)| n > 0)
            .map(|(k, n)| format!("{} {n}", k.as_str()))
            .collect();
        if parts.is_empty() {
            "none".into()
        } else {
            parts.join(", ")
        }
    }

    /// One-line summary of the verdicts and of the kinds of evidence. Consistency
    /// checks are counted apart from the confirmed claims.
    pub fn summary(&self) -> String {
        format!(
            "{} claims: {} confirmed (+{} consistency checks), {} erratum, {} approximation, {} failed; by check: {}",
            self.claims.len(),
            self.confirmed(),
            self.consistency_checks(),
            self.count(Verdict::Erratum),
            self.count(Verdict::Approximation),
            self.count(Verdict::Failed),
            self.kinds_summary()
        )
    }

    /// The first place (`params.x`, `results.y`, `claims[i].computed`) that holds a
    /// non-finite number, or `None`. JSON has no NaN or inf: a non-finite f64 becomes
    /// `null` (or the text `non-finite` in results) on its way in, so this finds it. The
    /// CLI refuses to print such a report (the run ends `invalid`, naming the place).
    pub fn first_non_finite(&self) -> Option<String> {
        let bad = |v: &Value| contains_null(v) || non_finite_text(v);
        let maps = [("params", &self.params), ("results", &self.results)];
        for (name, map) in maps {
            if let Some((k, _)) = map.iter().find(|(_, v)| bad(v)) {
                return Some(format!("{name}.{k}"));
            }
        }
        for (i, c) in self.claims.iter().enumerate() {
            for (f, v) in [
                ("expected", &c.expected),
                ("computed", &c.computed),
                ("tolerance", &c.tolerance),
            ] {
                if bad(v) {
                    return Some(format!("claims[{i}] ({}).{f}", c.id));
                }
            }
        }
        None
    }

    /// The JSON object of the contract (pretty-printed is not required; compact).
    pub fn to_json(&self) -> Value {
        serde_json::to_value(self).expect("report serialises")
    }

    /// The generated Markdown table of claims, for the course text (block `claims`).
    pub fn claims_markdown(&self) -> String {
        let mut s = String::from("| # | claim | section | verdict | check | expected | computed | tolerance |\n|---|---|---|---|---|---|---|---|\n");
        for (i, c) in self.claims.iter().enumerate() {
            let _ = writeln!(
                s,
                "| {} | **{}**: {} | {} | {} | {} | {} | {} | {} |",
                i + 1,
                c.id,
                c.statement.replace('|', "\\|"),
                c.section,
                c.verdict.as_str(),
                c.check.as_str(),
                fmt_value(&c.expected).replace('|', "\\|"),
                fmt_value(&c.computed).replace('|', "\\|"),
                fmt_value(&c.tolerance).replace('|', "\\|")
            );
        }
        s
    }

    /// The generated Markdown table of results (block `results`).
    pub fn results_markdown(&self) -> String {
        let mut s = String::from("| result | value |\n|---|---|\n");
        for (k, v) in &self.results {
            let _ = writeln!(s, "| `{k}` | {} |", fmt_value(v).replace('|', "\\|"));
        }
        s
    }
}

fn non_finite_text(v: &Value) -> bool {
    match v {
        Value::String(t) => t == NON_FINITE,
        Value::Array(a) => a.iter().any(non_finite_text),
        Value::Object(o) => o.values().any(non_finite_text),
        _ => false,
    }
}

fn contains_null(v: &Value) -> bool {
    match v {
        Value::Null => true,
        Value::Array(a) => a.iter().any(contains_null),
        Value::Object(o) => o.values().any(contains_null),
        _ => false,
    }
}

#[cfg(test)]
mod tests;
