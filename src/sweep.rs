//! Parallel parameter sweeps: rayon for the work, indicatif for a progress bar on a
//! terminal. Bars draw only when the top-level command line turned them on
//! ([`show_progress`], from `main`) and stderr is a terminal: the library, the lab and
//! the tests (which run the CLI in-process, often on a terminal) stay quiet.
//!
//! Results come back in input order, so every figure and number is the same whatever
//! the thread count. Sum the returned vector in order; never use a parallel float sum.

use indicatif::{ParallelProgressIterator, ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};

/// Whether progress bars may draw (off until the top-level CLI turns them on).
static PROGRESS: AtomicBool = AtomicBool::new(false);

/// Lets progress bars and spinners draw on stderr when it is a terminal. Called once by
/// the `workbook` binary's `main`; never by the library or a test harness.
pub fn show_progress(on: bool) {
    PROGRESS.store(on, Ordering::Relaxed);
}

/// Where a bar draws: stderr when [`show_progress`] is on and stderr is a terminal,
/// nowhere otherwise.
fn draw_target() -> ProgressDrawTarget {
    if PROGRESS.load(Ordering::Relaxed) && std::io::stderr().is_terminal() {
        ProgressDrawTarget::stderr()
    } else {
        ProgressDrawTarget::hidden()
    }
}

/// Maps `f` over `items` in parallel with a progress bar labelled `label`; the output
/// is in input order.
pub fn par_map<T, R, F>(items: &[T], label: &str, f: F) -> Vec<R>
where
    T: Sync,
    R: Send,
    F: Fn(&T) -> R + Sync + Send,
{
    let bar = ProgressBar::with_draw_target(Some(items.len() as u64), draw_target());
    if let Ok(style) = ProgressStyle::with_template("{msg:>28} [{bar:30}] {pos}/{len} ({eta})") {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(label.to_string());
    let out: Vec<R> = items.par_iter().progress_with(bar.clone()).map(f).collect();
    bar.finish_and_clear();
    out
}

/// The work budget of one chapter run (seconds of wall time): beyond it a run is
/// refused unless `--allow-long-runs` is given. Ten minutes: a reader waits for a
/// chapter, not for a batch job.
pub const BUDGET_S: f64 = 600.0;

/// Runs estimated to take longer than this (s) show a progress indicator on a terminal.
pub const PROGRESS_AFTER_S: f64 = 3.0;

/// Checks an estimate of `units` units of work (for example drive cycles) at
/// `seconds_per_unit` against [`BUDGET_S`]; the error names `flag`, the flag to lower.
/// `allow` is `--allow-long-runs`.
pub fn check_budget(
    flag: &str,
    units: f64,
    unit_name: &str,
    seconds_per_unit: f64,
    allow: bool,
) -> crate::error::Result<f64> {
    let estimate_s = units * seconds_per_unit;
    if estimate_s > BUDGET_S && !allow {
        return Err(crate::error::WorkbookError::OverBudget {
            flag: flag.to_string(),
            estimate: format!(
                "{} {unit_name} (about {:.0} min)",
                crate::error::num(units.round()),
                estimate_s / 60.0
            ),
            budget: format!(
                "{} {unit_name} ({:.0} min)",
                crate::error::num((BUDGET_S / seconds_per_unit).round()),
                BUDGET_S / 60.0
            ),
        });
    }
    Ok(estimate_s)
}

/// A spinner with the elapsed time and the estimate, for a run estimated to take more
/// than [`PROGRESS_AFTER_S`]; hidden unless bars are on ([`show_progress`]). Finish it with
/// `finish_and_clear`.
pub fn spinner(label: &str, estimate_s: f64) -> ProgressBar {
    if estimate_s <= PROGRESS_AFTER_S {
        return ProgressBar::hidden();
    }
    let target = draw_target();
    if target.is_hidden() {
        return ProgressBar::hidden(); // no ticker thread when nothing is drawn
    }
    let bar = ProgressBar::with_draw_target(None, target);
    if let Ok(style) = ProgressStyle::with_template("{spinner} {msg} {elapsed}") {
        bar.set_style(style);
    }
    bar.set_message(format!("{label} (estimate {estimate_s:.0} s)"));
    bar.enable_steady_tick(std::time::Duration::from_millis(200));
    bar
}

/// `n` evenly spaced values from `a` to `b` inclusive (`n >= 2`; `n == 1` gives `[a]`).
pub fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    match n {
        0 => Vec::new(),
        1 => vec![a],
        _ => (0..n)
            .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
            .collect(),
    }
}

/// `n` logarithmically spaced values from `a` to `b` inclusive (both > 0).
pub fn logspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    linspace(a.ln(), b.ln(), n)
        .into_iter()
        .map(f64::exp)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn par_map_keeps_order() {
        let xs: Vec<u64> = (0..1000).collect();
        let ys = par_map(&xs, "squares", |x| x * x);
        assert!(ys.iter().enumerate().all(|(i, &y)| y == (i * i) as u64));
    }

    #[test]
    fn bars_stay_quiet_unless_the_top_level_cli_turns_them_on() {
        // The library (and so every in-process test, on a terminal or not) never draws:
        // only `main` calls show_progress(true). Nothing here turns it on.
        assert!(draw_target().is_hidden());
        assert!(spinner("a long run", 1e3).is_hidden());
    }

    #[test]
    fn budget_refuses_beyond_ten_minutes_unless_allowed() {
        assert!(check_budget("--duration-s", 1e3, "cycles", 1e-3, false).is_ok());
        let e = check_budget("--duration-s", 1e7, "cycles", 1e-3, false).unwrap_err();
        assert_eq!(e.exit_code(), 2);
        assert!(e.to_string().contains("--duration-s"), "{e}");
        assert!(check_budget("--duration-s", 1e7, "cycles", 1e-3, true).is_ok());
    }

    #[test]
    fn spacing_hits_the_ends() {
        let l = linspace(0.0, 1.0, 5);
        assert_eq!(l, [0.0, 0.25, 0.5, 0.75, 1.0]);
        let g = logspace(1e-3, 1.0, 4);
        assert!((g[0] - 1e-3).abs() < 1e-15 && (g[3] - 1.0).abs() < 1e-12);
        assert!((g[1] - 1e-2).abs() < 1e-14);
    }
}
