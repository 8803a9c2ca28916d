//! Placing text off the data: the automatic legend corner and boxed notes.
//!
//! The legend's size is estimated from its entries (rows of the tick font, labels at
//! about 0.6 em per character); each corner of the plotting area is scored by how many
//! samples of the drawn data (lines densified to 1/400 of the axes) fall under a box of
//! that size. The emptiest corner wins; when every corner covers data and the y range is
//! automatic, the chart gets headroom above the data for the legend instead.

use super::axis::Pt;
use super::{font, TICK_PX};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// A legend corner: upper (true) or lower, right (true) or left.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Corner {
    pub upper: bool,
    pub right: bool,
}

impl Corner {
    /// The four corners in order of preference.
    pub const ALL: [Corner; 4] = [
        Corner {
            upper: true,
            right: true,
        },
        Corner {
            upper: true,
            right: false,
        },
        Corner {
            upper: false,
            right: true,
        },
        Corner {
            upper: false,
            right: false,
        },
    ];

    /// The plotters position of the corner.
    pub fn position(self) -> SeriesLabelPosition {
        match (self.upper, self.right) {
            (true, true) => SeriesLabelPosition::UpperRight,
            (true, false) => SeriesLabelPosition::UpperLeft,
            (false, true) => SeriesLabelPosition::LowerRight,
            (false, false) => SeriesLabelPosition::LowerLeft,
        }
    }
}

/// The legend box as fractions of the plotting area `(width, height)`, margin included,
/// for `labels` (the legend's entries) on a plotting area of `plot_px` pixels.
pub(super) fn legend_fraction(labels: &[&str], plot_px: (f64, f64)) -> (f64, f64) {
    let chars = labels.iter().map(|l| l.chars().count()).max().unwrap_or(0) as f64;
    let w = 12.0 + 40.0 + 0.6 * TICK_PX * chars + 14.0; // margin, glyph, text, padding
    let h = 12.0 + labels.len() as f64 * 1.3 * TICK_PX + 14.0;
    (w / plot_px.0.max(1.0), h / plot_px.1.max(1.0))
}

/// Samples of the drawn data in fractions of the axes: the points of `runs` (axis
/// units) inside `bx` and, for lines, points every 1/400 of the axes along segments.
pub(super) fn samples(runs: &[(bool, &[Pt])], bx: (f64, f64, f64, f64)) -> Vec<Pt> {
    let (x0, x1, y0, y1) = bx;
    let norm = |p: Pt| ((p.0 - x0) / (x1 - x0), (p.1 - y0) / (y1 - y0));
    let mut out = Vec::new();
    for (line, run) in runs {
        let pts: Vec<Pt> = run.iter().map(|&p| norm(p)).collect();
        out.extend(pts.iter().copied());
        if !*line {
            continue;
        }
        for w in pts.windows(2) {
            let len = (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1);
            let k = ((len * 400.0).ceil() as usize).min(400);
            for i in 1..k {
                let t = i as f64 / k as f64;
                out.push((
                    w[0].0 + t * (w[1].0 - w[0].0),
                    w[0].1 + t * (w[1].1 - w[0].1),
                ));
            }
        }
    }
    out.retain(|p| (0.0..=1.0).contains(&p.0) && (0.0..=1.0).contains(&p.1));
    out
}

/// How many of `pts` (fractions of the axes) lie under a box of `size` at `corner`.
pub(super) fn covered(pts: &[Pt], corner: Corner, size: (f64, f64)) -> usize {
    let in_x = |u: f64| {
        if corner.right {
            u >= 1.0 - size.0
        } else {
            u <= size.0
        }
    };
    let in_y = |v: f64| {
        if corner.upper {
            v >= 1.0 - size.1
        } else {
            v <= size.1
        }
    };
    pts.iter().filter(|p| in_x(p.0) && in_y(p.1)).count()
}

/// The emptiest corner for a legend of `size` over `pts`, and the number of samples
/// it covers.
pub(super) fn best_corner(pts: &[Pt], size: (f64, f64)) -> (Corner, usize) {
    let mut best = (Corner::ALL[0], usize::MAX);
    for c in Corner::ALL {
        let n = covered(pts, c, size);
        if n < best.1 {
            best = (c, n);
        }
    }
    best
}

/// Headroom for an upper legend of `size` at `corner`: the top of the y axis (as a
/// fraction of the current span, >= 1) that puts the data under the box below it.
pub(super) fn headroom(pts: &[Pt], corner: Corner, size: (f64, f64)) -> f64 {
    let in_x = |u: f64| {
        if corner.right {
            u >= 1.0 - size.0
        } else {
            u <= size.0
        }
    };
    let top = pts
        .iter()
        .filter(|p| in_x(p.0))
        .map(|p| p.1)
        .fold(0.0f64, f64::max);
    // formula: the data top v_max maps to 1 - h on an axis of span s: v_max / s = 1 - h
    (top / (1.0 - size.1).max(0.3)).max(1.0)
}

/// The plotting area's size in pixels of a house-style chart on an area of `area_px`
/// (margins 18, y-label area 88, x-label area 58, a caption of about 41 pixels).
pub(super) fn plot_px(area_px: (u32, u32)) -> (f64, f64) {
    (
        (area_px.0 as f64 - 36.0 - 88.0).max(1.0),
        (area_px.1 as f64 - 36.0 - 58.0 - 41.0).max(1.0),
    )
}

/// Draws `text` at pixel offset `off` from `at` (axis units of `ch`) on a white,
/// slightly translucent box so that it stays legible over lines and cells; `pos` is
/// the text's anchor.
pub(super) fn boxed_text<DB: DrawingBackend, CT: plotters::coord::CoordTranslate>(
    area: &DrawingArea<DB, CT>,
    at: CT::From,
    off: (i32, i32),
    text: &str,
    pos: Pos,
    color: RGBColor,
) -> Result<(), String>
where
    CT::From: Clone,
{
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let style = font(TICK_PX).color(&color);
    let (w, h) = area.estimate_text_size(text, &style).map_err(e)?;
    let (w, h) = (w as i32, h as i32);
    let x0 = match pos.h_pos {
        HPos::Left => off.0,
        HPos::Center => off.0 - w / 2,
        HPos::Right => off.0 - w,
    };
    let y0 = match pos.v_pos {
        VPos::Top => off.1,
        VPos::Center => off.1 - h / 2,
        VPos::Bottom => off.1 - h,
    };
    let bg = Rectangle::new(
        [(x0 - 3, y0 - 2), (x0 + w + 3, y0 + h + 2)],
        WHITE.mix(0.85).filled(),
    );
    let t = Text::new(
        text.to_string(),
        (x0, y0),
        style.pos(Pos::new(HPos::Left, VPos::Top)),
    );
    area.draw(&(EmptyElement::at(at) + bg + t)).map_err(e)
}

/// Draws notes `(x, y, text)` (axis units, left-centred at the point) on the plotting
/// area of a chart.
pub(super) fn draw_notes<DB: DrawingBackend>(
    area: &DrawingArea<
        DB,
        plotters::coord::cartesian::Cartesian2d<super::axis::Ticked, super::axis::Ticked>,
    >,
    notes: &[(f64, f64, String)],
) -> Result<(), String> {
    for (x, y, text) in notes {
        if x.is_finite() && y.is_finite() {
            let pos = Pos::new(HPos::Left, VPos::Center);
            boxed_text(area, (*x, *y), (0, 0), text, pos, RGBColor(0, 0, 0))?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_legend_goes_to_the_emptiest_corner() {
        // a rising line fills the lower left and the upper right: the upper left is free
        let run: Vec<Pt> = (0..=10).map(|i| (i as f64, i as f64)).collect();
        let pts = samples(&[(true, &run[..])], (0.0, 10.0, 0.0, 10.0));
        let (c, n) = best_corner(&pts, (0.3, 0.3));
        assert_eq!((c.upper, c.right, n), (true, false, 0));
        // a falling line: the upper right is free
        let run: Vec<Pt> = (0..=10).map(|i| (i as f64, 10.0 - i as f64)).collect();
        let pts = samples(&[(true, &run[..])], (0.0, 10.0, 0.0, 10.0));
        let (c, n) = best_corner(&pts, (0.3, 0.3));
        assert_eq!((c.upper, c.right, n), (true, true, 0));
    }

    #[test]
    fn lines_are_sampled_between_their_points() {
        // two points far apart: the segment between them covers the middle of the axes
        let run = [(0.0, 5.0), (10.0, 5.0)];
        let pts = samples(&[(true, &run[..])], (0.0, 10.0, 0.0, 10.0));
        assert!(pts.len() > 300, "{}", pts.len());
        let markers = samples(&[(false, &run[..])], (0.0, 10.0, 0.0, 10.0));
        assert_eq!(markers.len(), 2);
    }

    #[test]
    fn headroom_lifts_the_data_below_an_upper_legend() {
        // data up to the top of the axes on the right: the axis grows by 1 / (1 - h)
        let pts = vec![(0.9, 1.0), (0.1, 0.2)];
        let right = Corner::ALL[0];
        let top = headroom(&pts, right, (0.3, 0.25));
        assert!((top - 1.0 / 0.75).abs() < 1e-12, "{top}");
        // no data under the legend's columns: no headroom
        assert_eq!(headroom(&[(0.1, 1.0)], right, (0.3, 0.25)), 1.0);
    }
}
