//! Number and value formatting for the tables (stable across runs and platforms).

use super::ChapterReport;
use serde_json::Value;
use std::fmt::Write as _;

fn clip(s: &str, width: usize) -> String {
    if s.chars().count() <= width {
        s.to_string()
    } else {
        let mut t: String = s.chars().take(width.saturating_sub(1)).collect();
        t.push('~');
        t
    }
}

/// The one text that stands for a non-finite number (NaN, ±inf) in tables and JSON
/// (JSON has no NaN): written by [`fmt_num`], [`fmt_value`] and the report's results,
/// and the one value the report's non-finite check recognises.
pub const NON_FINITE: &str = "non-finite";

/// Formats a number for tables: integers exactly, others with 4 significant digits
/// (scientific notation outside 1e-3 .. 1e5). Stable across runs and platforms for
/// numbers that agree to ~5 digits.
pub fn fmt_num(x: f64) -> String {
    if !x.is_finite() {
        return NON_FINITE.into();
    }
    if x == x.trunc() && x.abs() < 1e9 {
        return format!("{}", x as i64);
    }
    let a = x.abs();
    if (1e-3..1e5).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{x:.digits$}");
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        };
        if s == "-0" {
            "0".into()
        } else {
            s
        }
    } else {
        format!("{x:.3e}")
    }
}

/// Formats any JSON value for tables (numbers via [`fmt_num`]).
pub fn fmt_value(v: &Value) -> String {
    match v {
        Value::Number(n) => n.as_f64().map(fmt_num).unwrap_or_else(|| n.to_string()),
        Value::String(s) => s.clone(),
        Value::Bool(b) => b.to_string(),
        Value::Null => NON_FINITE.into(),
        Value::Array(a) => format!(
            "[{}]",
            a.iter().map(fmt_value).collect::<Vec<_>>().join(", ")
        ),
        Value::Object(o) => {
            let parts: Vec<String> = o
                .iter()
                .map(|(k, v)| format!("{k}: {}", fmt_value(v)))
                .collect();
            format!("{{{}}}", parts.join(", "))
        }
    }
}

impl ChapterReport {
    /// The human-readable report: parameters, an aligned verdict table, results,
    /// figures and a one-line summary.
    pub fn human(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "== {} : {} (document section {}) ==",
            self.chapter, self.title, self.section
        );
        if let Some(status) = &self.status {
            let _ = writeln!(s, "{status}");
        }
        if !self.params.is_empty() {
            let p: Vec<String> = self
                .params
                .iter()
                .map(|(k, v)| format!("{k} = {}", fmt_value(v)))
                .collect();
            let _ = writeln!(s, "parameters: {}", p.join(", "));
        }
        if !self.claims.is_empty() {
            s.push_str(&self.claims_table());
        }
        if !self.results.is_empty() {
            let _ = writeln!(s, "results:");
            for (k, v) in &self.results {
                let _ = writeln!(s, "  {k} = {}", fmt_value(v));
            }
        }
        if !self.figures.is_empty() {
            let _ = writeln!(s, "figures: {}", self.figures.join(", "));
        }
        let _ = writeln!(s, "summary: {}", self.summary());
        s
    }

    /// The aligned verdict table of the human report: one row per claim (columns
    /// clipped at 28 characters), its section and statement on the line below.
    fn claims_table(&self) -> String {
        let mut s = String::new();
        let rows: Vec<[String; 7]> = self
            .claims
            .iter()
            .enumerate()
            .map(|(i, c)| {
                [
                    format!("{}", i + 1),
                    c.verdict.as_str().to_string(),
                    c.check.as_str().to_string(),
                    c.id.clone(),
                    fmt_value(&c.expected),
                    fmt_value(&c.computed),
                    fmt_value(&c.tolerance),
                ]
            })
            .collect();
        let header = [
            "#",
            "verdict",
            "check",
            "claim",
            "expected",
            "computed",
            "tolerance",
        ];
        let mut w: Vec<usize> = header.iter().map(|h| h.len()).collect();
        for r in &rows {
            for (wi, cell) in w.iter_mut().zip(r) {
                *wi = (*wi).max(cell.chars().count()).min(28);
            }
        }
        let line = |cells: &[&str]| {
            let mut l = String::new();
            for (i, c) in cells.iter().enumerate() {
                let c = clip(c, w[i]);
                let _ = write!(l, "{c:<width$}  ", width = w[i]);
            }
            l.trim_end().to_string()
        };
        let _ = writeln!(s, "{}", line(&header));
        for (r, c) in rows.iter().zip(&self.claims) {
            let cells: Vec<&str> = r.iter().map(String::as_str).collect();
            let _ = writeln!(s, "{}", line(&cells));
            let _ = writeln!(
                s,
                "{:indent$}[{}] {}",
                "",
                c.section,
                c.statement,
                indent = w[0] + 2
            );
        }
        s
    }
}
