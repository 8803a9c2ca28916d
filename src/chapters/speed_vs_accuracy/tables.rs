//! Markdown tables of the course text. Wall times vary from run to run, so no table
//! holds one: `workbook render --check` must see the same text every time.

use super::economy::SweepRow;
use super::failures::Failure;
use super::work_precision::fmt_err;
use super::work_precision::WpPoint;
use crate::report::{fmt_num, ChapterReport};
use std::fmt::Write as _;

/// Adds the tables `work_precision` (the block's points, then the stick's),
/// `failures`, `economy` and `results_stable` (the results so far).
pub fn tables(
    r: &mut ChapterReport,
    block: &[WpPoint],
    stick: &[WpPoint],
    fails: &[Failure],
    sweep: &[SweepRow],
) {
    let mut t = String::from("| problem | method | step (s) or tolerance | relative error | rhs evaluations |\n|---|---|---|---|---|\n");
    let rows = block.iter().map(|p| ("block-drift", p));
    for (problem, p) in rows.chain(stick.iter().map(|p| ("stick-speed", p))) {
        let _ = writeln!(
            t,
            "| {} | {} | {:.3e} | {} | {} |",
            problem,
            p.setting.label(),
            p.setting.knob(),
            fmt_err(p.error),
            p.cost.rhs_evals
        );
    }
    r.table("work_precision", t);
    let mut t = String::from("| method | scene | symptom |\n|---|---|---|\n");
    for f in fails {
        let _ = writeln!(t, "| {} | {} | {} |", f.method, f.scene, f.symptom);
    }
    r.table("failures", t);
    let rows: Vec<LawRow> = sweep.iter().map(|r| (r.0, r.1, r.2, Some(r.3))).collect();
    let t = law_table(
        "| Γ | exact drift (m/s) | flight map: error | μ_eff law: error |",
        &rows,
        12,
        "no sticking orbit",
    );
    r.table("economy", t);
    let mut t = String::from("| result | value |\n|---|---|\n");
    for (k, v) in &r.results {
        if k == "work_precision" || k.starts_with("stick_cycles_per_second") || k == "failures" {
            continue; // tables of their own, or wall-time measurements
        }
        let v = match (k.as_str(), v) {
            ("economy", serde_json::Value::Object(o)) => {
                let mut o = o.clone();
                o.remove("cost_ratio_exact_over_flight_map");
                serde_json::Value::Object(o)
            }
            _ => v.clone(),
        };
        let _ = writeln!(t, "| `{k}` | {} |", crate::report::fmt_value(&v));
    }
    r.table("results_stable", t);
}

/// Adds the table `economy_horizontal`.
pub fn horizontal(r: &mut ChapterReport, rows: &[super::economy::HorizontalRow]) {
    let rows: Vec<LawRow> = rows
        .iter()
        .map(|r| (r.0, r.1, Some(r.2), Some(r.3)))
        .collect();
    let t = law_table(
        "| Γₓ = δₓ ω²/(μ g) | exact drift (m/s) | arcsin law: error | viscous law: error |",
        &rows,
        8,
        "none",
    );
    r.table("economy_horizontal", t);
}

/// A row of an averaged-law table: (parameter, exact drift m/s, law 1, law 2 drifts m/s).
type LawRow = (f64, f64, Option<f64>, Option<f64>);

/// A table of the laws' relative errors against the exact drift, at most about
/// `max_rows` rows (every k-th of `rows`); `none` where a law has no value.
fn law_table(header: &str, rows: &[LawRow], max_rows: usize, none: &str) -> String {
    let mut t = format!("{header}\n|---|---|---|---|\n");
    let stride = (rows.len() / max_rows).max(1);
    for row in rows.iter().step_by(stride) {
        let rel = |m: Option<f64>| {
            m.map_or(none.to_string(), |m| {
                format!("{:+.2} %", 100.0 * (m - row.1) / row.1)
            })
        };
        let _ = writeln!(
            t,
            "| {} | {} | {} | {} |",
            fmt_num(row.0),
            fmt_num(row.1),
            rel(row.2),
            rel(row.3)
        );
    }
    t
}
