//! The scenes, below the chapters: the document's scenes, the default ones and the
//! authors' ones, how a run of a scene starts, and the standard runs of them (the run a
//! chapter reports, the cell of a speed map, the stroboscopic map), so that the
//! chapters, the lab, the benchmarks and the tests run the same scene with the same
//! code and none of them names a chapter's internals.
//!
//! A scene knows its model (`physics`) and the integrators (`numerics`); it knows no
//! chapter, no claim, no figure, no command line (ARCHITECTURE.md, checked by
//! `tests/architecture.rs`). Its names and descriptions ([`Choice`]) are plain data:
//! the flag table (`crate::flags`) turns them into the command line's choices.

pub mod block;
pub mod measure;
pub mod stick;

/// An enumeration a flag chooses from: its values, each with its name as typed and a
/// one-line description (the command line's `--help` prints both, `crate::flags::choice`).
pub trait Choice: Copy + PartialEq + Send + Sync + 'static {
    /// Every value, the default first.
    const ALL: &'static [Self];
    /// The name as typed (`jamming`).
    fn name(self) -> &'static str;
    /// What it is, one line.
    fn about(self) -> &'static str;
}

/// Rounds `x` to `d` significant digits for the reported numbers (keeps JSON and
/// tables stable beyond the checked accuracy); 0 stays 0 and a non-finite number NaN.
pub fn round(x: f64, d: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return if x.is_finite() { 0.0 } else { f64::NAN };
    }
    let e = d - 1 - x.abs().log10().floor() as i32;
    if e > 300 {
        return x; // 10^e would overflow: x is tiny and already short enough
    }
    let s = 10f64.powi(e);
    (x * s).round() / s
}
