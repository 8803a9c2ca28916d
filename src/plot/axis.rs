//! Axis arithmetic of the figure style: data filtering, ranges, ticks, clipping.
//!
//! Everything here is plain f64 arithmetic with no drawing, so it is unit-tested
//! directly. A log axis is a linear axis in log10 units: values are transformed by
//! [`to_axis`] and tick labels print the powers of ten back.

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::types::RangedCoordf64;
use std::ops::Range;

/// A linear axis from `lo` to `hi` (axis units) whose grid lines and labels sit at
/// exactly the given ticks (plotters' own tick choice is not used).
#[derive(Debug, Clone)]
pub struct Ticked {
    lo: f64,
    hi: f64,
    ticks: Vec<f64>,
}

impl Ticked {
    /// The axis `[lo, hi]` with ticks `ticks`.
    pub fn new(lo: f64, hi: f64, ticks: Vec<f64>) -> Self {
        Ticked { lo, hi, ticks }
    }
}

impl Ranged for Ticked {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;
    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        RangedCoordf64::from(self.lo..self.hi).map(value, limit)
    }
    fn key_points<H: KeyPointHint>(&self, hint: H) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            Vec::new()
        } else {
            self.ticks.clone()
        }
    }
    fn range(&self) -> Range<f64> {
        self.lo..self.hi
    }
}

/// A point in axis units (log10 already applied where the axis is logarithmic).
pub type Pt = (f64, f64);

/// The chart context type of the style (linear axes in axis units with fixed ticks),
/// used by `chart` to draw axes and by `series` to draw into them.
pub(super) type Ctx<'a, DB> =
    plotters::chart::ChartContext<'a, DB, plotters::coord::cartesian::Cartesian2d<Ticked, Ticked>>;

/// Maps a data value to axis units: `log10(v)` on a log axis (None for v <= 0),
/// the value itself otherwise; None for NaN and infinities.
pub fn to_axis(v: f64, log: bool) -> Option<f64> {
    if !v.is_finite() {
        return None;
    }
    if log {
        if v > 0.0 {
            Some(v.log10())
        } else {
            None
        }
    } else {
        Some(v)
    }
}

/// Splits data points into runs of drawable points (axis units): a point that cannot
/// be drawn (NaN, inf, non-positive on a log axis) breaks the line.
pub fn runs(points: &[(f64, f64)], log_x: bool, log_y: bool) -> Vec<Vec<Pt>> {
    let mut out = Vec::new();
    let mut cur = Vec::new();
    for &(x, y) in points {
        match (to_axis(x, log_x), to_axis(y, log_y)) {
            (Some(a), Some(b)) => cur.push((a, b)),
            _ => {
                if !cur.is_empty() {
                    out.push(std::mem::take(&mut cur));
                }
            }
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

/// The axis range `(lo, hi)` with `lo < hi`: the explicit range if it is usable,
/// otherwise the span of `values` widened by `pad` (a fraction of the span); an
/// empty or zero span is padded so that the axis never degenerates.
pub fn range(explicit: Option<(f64, f64)>, values: &[f64], pad: f64, log: bool) -> (f64, f64) {
    if let Some((a, b)) = explicit {
        if let (Some(a), Some(b)) = (to_axis(a, log), to_axis(b, log)) {
            if a < b {
                return (a, b);
            }
            if b < a {
                return (b, a);
            }
        }
    }
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for &v in values.iter().filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if lo > hi {
        return (0.0, 1.0);
    }
    let span = hi - lo;
    if span <= 0.0 || !span.is_finite() {
        let w = if log { 0.5 } else { (lo.abs() * 0.1).max(0.5) };
        return (lo - w, hi + w);
    }
    (lo - pad * span, hi + pad * span)
}

/// "Nice" ticks (1, 2, 5 times a power of ten) inside `[lo, hi]`, about `target`
/// of them, and the tick step.
pub fn nice_ticks(lo: f64, hi: f64, target: usize) -> (Vec<f64>, f64) {
    let span = hi - lo;
    if span.is_nan() || span <= 0.0 || !span.is_finite() {
        return (vec![lo], 1.0);
    }
    let raw = span / target.max(1) as f64;
    let mag = 10f64.powi(raw.log10().floor() as i32);
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    let k0 = (lo / step).ceil() as i64;
    let k1 = (hi / step).floor() as i64;
    let ticks = (k0..=k1).map(|k| k as f64 * step).collect();
    (ticks, step)
}

/// Formats a linear tick value with the decimals its step needs.
pub fn fmt_linear(v: f64, step: f64) -> String {
    let v = v + 0.0; // turns -0.0 into 0.0
    let a = v.abs();
    if a >= 1e5 || (a < 1e-3 && a > 0.0) || step < 1e-4 {
        let s = format!("{v:.1e}");
        return s.replace(".0e", "e");
    }
    let decimals = (-step.log10().floor()).max(0.0) as usize;
    let s = format!("{v:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string() // a tiny negative rounded to zero
    } else {
        s
    }
}

/// Ticks of a log axis in log10 units: decades, plus 2 and 5 multiples when the
/// axis spans less than two decades, plus nice linear ticks when even that is sparse.
pub fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    let d0 = lo.ceil() as i64;
    let d1 = hi.floor() as i64;
    let mut t: Vec<f64> = (d0..=d1).map(|d| d as f64).collect();
    if t.len() > 12 {
        let every = t.len().div_ceil(8) as i64;
        t = (d0..=d1)
            .filter(|d| d.rem_euclid(every) == 0)
            .map(|d| d as f64)
            .collect();
    }
    if t.len() < 3 {
        t.clear();
        for d in (lo.floor() as i64)..=(hi.ceil() as i64) {
            for m in [1.0f64, 2.0, 5.0] {
                let v = d as f64 + m.log10();
                if v >= lo && v <= hi {
                    t.push(v);
                }
            }
        }
    }
    if t.len() < 2 {
        t = nice_ticks(lo, hi, 5).0;
    }
    t
}

/// Formats a log-axis tick (given in log10 units) as the data value: `1e-3`, `0.1`,
/// `1`, `20`, `5e4`.
pub fn fmt_log(v: f64) -> String {
    let value = 10f64.powf(v);
    let d = value.log10().floor();
    let m = value / 10f64.powf(d);
    let mr = (m * 100.0).round() / 100.0;
    if (-1.0..=3.0).contains(&d) {
        let decimals = (2.0 - d).clamp(0.0, 3.0) as usize;
        let s = format!("{value:.decimals$}");
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        };
        return s;
    }
    let ms = format!("{mr}");
    format!("{ms}e{}", d as i64)
}

/// Clips the segment `a`-`b` to the box `[x0, x1] x [y0, y1]` (Liang-Barsky).
pub fn clip_segment(a: Pt, b: Pt, bx: (f64, f64, f64, f64)) -> Option<(Pt, Pt)> {
    let (x0, x1, y0, y1) = bx;
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let mut t0 = 0.0f64;
    let mut t1 = 1.0f64;
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            (a.0 + t * dx, a.1 + t * dy)
        }
    };
    Some((at(t0), at(t1)))
}

/// Clips a polyline to a box: the visible pieces, each a polyline.
pub fn clip_polyline(run: &[Pt], bx: (f64, f64, f64, f64)) -> Vec<Vec<Pt>> {
    let inside = |p: Pt| p.0 >= bx.0 && p.0 <= bx.1 && p.1 >= bx.2 && p.1 <= bx.3;
    if run.len() == 1 {
        return if inside(run[0]) {
            vec![run.to_vec()]
        } else {
            vec![]
        };
    }
    let mut out = Vec::new();
    let mut cur: Vec<Pt> = Vec::new();
    for w in run.windows(2) {
        match clip_segment(w[0], w[1], bx) {
            Some((a, b)) => {
                if cur.last() != Some(&a) {
                    if !cur.is_empty() {
                        out.push(std::mem::take(&mut cur));
                    }
                    cur.push(a);
                }
                cur.push(b);
            }
            None => {
                if !cur.is_empty() {
                    out.push(std::mem::take(&mut cur));
                }
            }
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_never_degenerate() {
        assert_eq!(range(None, &[], 0.05, false), (0.0, 1.0));
        let (a, b) = range(None, &[2.0, 2.0], 0.05, false);
        assert!(a < 2.0 && b > 2.0);
        assert_eq!(range(Some((1.0, 0.0)), &[], 0.0, false), (0.0, 1.0));
        // An explicit log range with a non-positive end falls back to the data.
        assert_eq!(range(Some((0.0, 10.0)), &[0.0, 1.0], 0.0, true), (0.0, 1.0));
        assert_eq!(range(None, &[f64::NAN], 0.0, false), (0.0, 1.0));
    }

    #[test]
    fn ticks_and_labels() {
        let (t, s) = nice_ticks(0.0, 1.0, 5);
        assert_eq!(s, 0.2);
        let labels: Vec<String> = t.iter().map(|v| fmt_linear(*v, s)).collect();
        assert_eq!(labels, ["0.0", "0.2", "0.4", "0.6", "0.8", "1.0"]);
        assert_eq!(log_ticks(-3.0, 1.0), vec![-3.0, -2.0, -1.0, 0.0, 1.0]);
        assert_eq!(fmt_log(-3.0), "1e-3");
        assert_eq!(fmt_log(-1.0), "0.1");
        assert_eq!(fmt_log(2.0), "100");
        assert_eq!(fmt_log(2f64.log10()), "2");
        assert_eq!(fmt_log(5.0 + 2f64.log10()), "2e5");
        assert_eq!(fmt_linear(-0.0, 1.0), "0");
        assert_eq!(fmt_linear(2.5e-5, 1e-5), "2.5e-5");
    }

    #[test]
    fn runs_break_at_undrawable_points_and_clipping_splits() {
        let r = runs(
            &[
                (1.0, 1.0),
                (2.0, f64::NAN),
                (3.0, 1.0),
                (4.0, -1.0),
                (5.0, 2.0),
            ],
            false,
            true,
        );
        assert_eq!(
            r,
            vec![
                vec![(1.0, 0.0)],
                vec![(3.0, 0.0)],
                vec![(5.0, 2f64.log10())]
            ]
        );
        let pieces = clip_polyline(
            &[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 0.0)],
            (-1.0, 1.0, -1.0, 1.0),
        );
        assert_eq!(
            pieces,
            vec![vec![(0.0, 0.0), (1.0, 0.0)], vec![(1.0, 1.0), (0.0, 0.0)]]
        );
        assert_eq!(
            clip_segment((2.0, 2.0), (3.0, 3.0), (0.0, 1.0, 0.0, 1.0)),
            None
        );
    }
}
