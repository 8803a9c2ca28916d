//! Markdown tables of the course text. Wall times vary from run to run, so no table
//! holds one: `workbook render --check` must see the same text every time.

use super::economy::SweepRow;
use super::failures::Failure;
use super::report_parts::fmt_err;
use super::work_precision::WpPoint;
use crate::report::{fmt_num, ChapterReport};
use std::fmt::Write as _;

/// Adds the tables `work_precision`, `failures`, `economy` and `results_stable`.
pub fn tables(r: &mut ChapterReport, points: &[WpPoint], fails: &[Failure], sweep: &[SweepRow]) {
    let mut t = String::from("| problem | method | step (s) or tolerance | relative error | rhs evaluations |\n|---|---|---|---|---|\n");
    for p in points {
        let _ = writeln!(
            t,
            "| {} | {} | {:.3e} | {} | {} |",
            p.problem,
            p.solver.label(),
            p.solver.knob(),
            fmt_err(p.error),
            p.rhs_evals
        );
    }
    r.table("work_precision", t);
    let mut t = String::from("| method | scene | symptom |\n|---|---|---|\n");
    for f in fails {
        let _ = writeln!(t, "| {} | {} | {} |", f.method, f.scene, f.symptom);
    }
    r.table("failures", t);
    let mut t = String::from("| Gamma | exact drift (m/s) | flight map: error | mu_eff law: error |\n|---|---|---|---|\n");
    let stride = (sweep.len() / 12).max(1);
    for row in sweep.iter().step_by(stride) {
        let rel = |m: f64| format!("{:+.2} %", 100.0 * (m - row.1) / row.1);
        let _ = writeln!(
            t,
            "| {} | {} | {} | {} |",
            fmt_num(row.0),
            fmt_num(row.1),
            row.2.map_or("no sticking orbit".into(), rel),
            rel(row.3)
        );
    }
    r.table("economy", t);
    let mut t = String::from("| result | value |\n|---|---|\n");
    for (k, v) in &r.results {
        if k == "work_precision" || k == "failures" || k == "stick_cycles_per_second" {
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
    let mut t = String::from("| K = delta omega^2/(mu g) | exact drift (m/s) | arcsin law: error | viscous law: error |\n|---|---|---|---|\n");
    let stride = (rows.len() / 8).max(1);
    for row in rows.iter().step_by(stride) {
        let rel = |m: f64| format!("{:+.2} %", 100.0 * (m - row.1) / row.1);
        let _ = writeln!(
            t,
            "| {} | {} | {} | {} |",
            fmt_num(row.0),
            fmt_num(row.1),
            rel(row.2),
            rel(row.3)
        );
    }
    r.table("economy_horizontal", t);
}
