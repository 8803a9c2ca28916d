//! Parallel parameter sweeps: rayon for the work, indicatif for a progress bar on a
//! terminal (hidden when stderr is not a terminal, so tests and `--json` stay clean).
//!
//! Results come back in input order, so every figure and number is the same whatever
//! the thread count. Sum the returned vector in order; never use a parallel float sum.

use indicatif::{ParallelProgressIterator, ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;

/// Maps `f` over `items` in parallel with a progress bar labelled `label`; the output
/// is in input order.
pub fn par_map<T, R, F>(items: &[T], label: &str, f: F) -> Vec<R>
where
    T: Sync,
    R: Send,
    F: Fn(&T) -> R + Sync + Send,
{
    let bar = ProgressBar::with_draw_target(Some(items.len() as u64), ProgressDrawTarget::stderr());
    if let Ok(style) = ProgressStyle::with_template("{msg:>28} [{bar:30}] {pos}/{len} ({eta})") {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(label.to_string());
    let out: Vec<R> = items.par_iter().progress_with(bar.clone()).map(f).collect();
    bar.finish_and_clear();
    out
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
    fn spacing_hits_the_ends() {
        let l = linspace(0.0, 1.0, 5);
        assert_eq!(l, [0.0, 0.25, 0.5, 0.75, 1.0]);
        let g = logspace(1e-3, 1.0, 4);
        assert!((g[0] - 1e-3).abs() < 1e-15 && (g[3] - 1.0).abs() < 1e-12);
        assert!((g[1] - 1e-2).abs() < 1e-14);
    }
}
