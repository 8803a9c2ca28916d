//! `--events`: every mode switch of the main run written as CSV.

use super::Args;
use crate::scenes::stick::events_csv;
use crate::physics::stick::run::RunSummary;

/// The output error of `--events` (exit code 3).
pub fn events_error(args: &Args, why: &str) -> crate::error::WorkbookError {
    crate::error::WorkbookError::Output {
        flag: "--events".into(),
        path: args
            .events
            .as_ref()
            .map_or(String::new(), |p| p.display().to_string()),
        why: why.to_string(),
    }
}

/// Most switches `--events` keeps in memory and writes (about 64 bytes each: 64 MB).
/// A longer run's file is cut there, and the cut is said in the results
/// (`events_written`, `events_total`, `events_cut_at_s`) and on stderr.
pub const EVENTS_CAP: usize = 1_000_000;

/// Writes the `--events` CSV of `run` to `path` atomically and records in the report
/// how many switches it holds of how many the run had.
pub fn write_events(
    r: &mut crate::report::ChapterReport,
    path: &std::path::Path,
    run: &RunSummary,
) -> std::result::Result<(), String> {
    crate::output::write_atomic(path, events_csv(run).as_bytes())?;
    let (written, total) = (run.switches.len(), run.event_count);
    r.result("events_written", written as f64);
    r.result("events_total", total as f64);
    if written < total {
        let cut_s = run.switches.last().map_or(0.0, |w| w.t_s);
        r.result("events_cut_at_s", cut_s);
        r.note(format!(
            "--events {} holds the first {written} of {total} switches (cut at t = {cut_s:.6} s; at most {EVENTS_CAP} are kept)",
            path.display()
        ));
    }
    Ok(())
}
