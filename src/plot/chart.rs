//! Drawing a [`Chart`] into any plotters area.

use super::axis::{self, Ctx, Pt, Ticked};
use super::layout;
use super::series::draw_series;
use super::{color, font, Chart, Kind, Legend, GRID, LABEL_PX, REFERENCE, TICK_PX, TITLE_PX};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Light colours of shaded bands, in order.
const BAND: [RGBColor; 5] = [
    RGBColor(86, 180, 233),
    RGBColor(230, 159, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(240, 228, 66),
];

/// Builds the house-style chart on `area`: caption `title`, margins, label areas, and
/// axes over `bx = (x0, x1, y0, y1)` (axis units) with the ticks of [`ticks`] for `logs`
/// (x, y). Returns the chart and the (x, y) tick steps, for [`draw_axes`].
pub(super) fn build_chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    title: &str,
    bx: (f64, f64, f64, f64),
    logs: (bool, bool),
) -> Result<(Ctx<'a, DB>, (f64, f64)), String> {
    let (x0, x1, y0, y1) = bx;
    let (xt, xstep) = ticks(x0, x1, logs.0);
    let (yt, ystep) = ticks(y0, y1, logs.1);
    let ch = ChartBuilder::on(area)
        .caption(title, font(TITLE_PX))
        .margin(18)
        .x_label_area_size(58)
        .y_label_area_size(88)
        .build_cartesian_2d(Ticked::new(x0, x1, xt), Ticked::new(y0, y1, yt))
        .map_err(|e| e.to_string())?;
    Ok((ch, (xstep, ystep)))
}

/// Draws the house-style axes of `ch`: descriptions `labels` (x, y), tick labels for
/// the tick `steps` and `logs` (x, y) of [`build_chart`], and a light grid at the major
/// ticks if `grid` (none otherwise).
pub(super) fn draw_axes<DB: DrawingBackend>(
    ch: &mut Ctx<'_, DB>,
    labels: (&str, &str),
    steps: (f64, f64),
    logs: (bool, bool),
    grid: bool,
) -> Result<(), String> {
    let fx = |v: &f64| tick_label(*v, steps.0, logs.0);
    let fy = |v: &f64| tick_label(*v, steps.1, logs.1);
    let mut mesh = ch.configure_mesh();
    if grid {
        mesh.bold_line_style(GRID.stroke_width(1))
            .light_line_style(TRANSPARENT);
    } else {
        mesh.disable_mesh();
    }
    mesh.axis_style(BLACK.stroke_width(1))
        .x_desc(labels.0)
        .y_desc(labels.1)
        .axis_desc_style(font(LABEL_PX))
        .label_style(font(TICK_PX))
        .x_label_formatter(&fx)
        .y_label_formatter(&fy)
        .draw()
        .map_err(|e| e.to_string())
}

pub(super) fn ticks(lo: f64, hi: f64, log: bool) -> (Vec<f64>, f64) {
    if log {
        (axis::log_ticks(lo, hi), 1.0)
    } else {
        axis::nice_ticks(lo, hi, 8)
    }
}

pub(super) fn tick_label(v: f64, step: f64, log: bool) -> String {
    if log {
        axis::fmt_log(v)
    } else {
        axis::fmt_linear(v, step)
    }
}

/// The legend's labels of a chart (bands first, as they are drawn).
fn legend_labels(c: &Chart) -> Vec<&str> {
    let bands = c.bands.iter().map(|b| b.2.as_str());
    let series = c.series.iter().map(|s| s.label.as_str());
    bands.chain(series).filter(|l| !l.is_empty()).collect()
}

/// The legend corner of `c` over the box `bx` (axis units) on `area_px` pixels, and the
/// top of the y axis (raised for headroom when every corner covers data and the range
/// is automatic). `None` when there is no legend.
fn place_legend(
    c: &Chart,
    runs: &[Vec<Vec<Pt>>],
    bx: (f64, f64, f64, f64),
    area_px: (u32, u32),
) -> (Option<SeriesLabelPosition>, f64) {
    let labels = legend_labels(c);
    let fixed = |p| (Some(p), bx.3);
    match c.legend {
        _ if labels.is_empty() => (None, bx.3),
        Legend::Hidden => (None, bx.3),
        Legend::UpperRight => fixed(SeriesLabelPosition::UpperRight),
        Legend::UpperLeft => fixed(SeriesLabelPosition::UpperLeft),
        Legend::LowerRight => fixed(SeriesLabelPosition::LowerRight),
        Legend::LowerLeft => fixed(SeriesLabelPosition::LowerLeft),
        Legend::Auto => {
            let size = layout::legend_fraction(&labels, layout::plot_px(area_px));
            let drawn: Vec<(bool, &[Pt])> = c
                .series
                .iter()
                .zip(runs)
                .flat_map(|(s, r)| r.iter().map(move |run| (s.kind != Kind::Points, &run[..])))
                .collect();
            let data = layout::samples(&drawn, bx);
            let mut pts = data.clone();
            pts.extend(reference_label_samples(c, bx, layout::plot_px(area_px)));
            let (corner, n) = layout::best_corner(&pts, size);
            if n == 0 || c.y_range.is_some() || size.1 > 0.5 {
                return (Some(corner.position()), bx.3);
            }
            // every corner covers data: raise the top of the axis over the emptier upper corner
            let up = |right| layout::Corner { upper: true, right };
            let (r, l) = (up(true), up(false));
            let (hr, hl) = (
                layout::headroom(&data, r, size),
                layout::headroom(&data, l, size),
            );
            let (corner, top) = if hr <= hl { (r, hr) } else { (l, hl) };
            (Some(corner.position()), bx.2 + top * (bx.3 - bx.2))
        }
    }
}

/// Samples (fractions of the axes) filling the boxes of the reference lines' labels as
/// [`draw_references`] places them, so that the legend avoids them too.
fn reference_label_samples(c: &Chart, bx: (f64, f64, f64, f64), px: (f64, f64)) -> Vec<Pt> {
    let (x0, x1, y0, y1) = bx;
    let width = |l: &str| (0.6 * TICK_PX * l.chars().count() as f64 + 10.0) / px.0;
    let row = 24.0 / px.1;
    let mut boxes = Vec::new(); // (u0, u1, v0, v1)
    let mut nv = 0.0;
    for (x, label) in c.vlines.iter().filter(|v| !v.1.is_empty()) {
        let Some(u) = axis::to_axis(*x, c.log_x).map(|x| (x - x0) / (x1 - x0)) else {
            continue;
        };
        let w = width(label);
        let (a, b) = if u > 0.7 { (u - w, u) } else { (u, u + w) };
        boxes.push((a, b, 1.0 - row * (nv + 1.0), 1.0 - row * nv));
        nv += 1.0;
    }
    for (y, label) in c.hlines.iter().filter(|h| !h.1.is_empty()) {
        let Some(v) = axis::to_axis(*y, c.log_y).map(|y| (y - y0) / (y1 - y0)) else {
            continue;
        };
        boxes.push((1.0 - width(label), 1.0, v - row, v + row));
    }
    let mut out = Vec::new();
    for (a, b, lo, hi) in boxes {
        for i in 0..=10 {
            for j in 0..=4 {
                out.push((
                    a + (b - a) * i as f64 / 10.0,
                    lo + (hi - lo) * j as f64 / 4.0,
                ));
            }
        }
    }
    out.retain(|p| (0.0..=1.0).contains(&p.0) && (0.0..=1.0).contains(&p.1));
    out
}

/// Draws the shaded bands; returns whether any got a legend label.
fn draw_bands<DB: DrawingBackend>(
    ch: &mut Ctx<'_, DB>,
    c: &Chart,
    bx: (f64, f64, f64, f64),
) -> Result<bool, String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let (x0, x1, y0, y1) = bx;
    let mut any_label = false;
    for (i, (a, b, label)) in c.bands.iter().enumerate() {
        let (Some(a), Some(b)) = (axis::to_axis(*a, c.log_x), axis::to_axis(*b, c.log_x)) else {
            continue;
        };
        let (a, b) = (a.min(b).max(x0), a.max(b).min(x1));
        if a > b {
            continue;
        }
        let col = BAND[i % BAND.len()];
        let anno = ch
            .draw_series(std::iter::once(Rectangle::new(
                [(a, y0), (b, y1)],
                col.mix(0.2).filled(),
            )))
            .map_err(e)?;
        if !label.is_empty() {
            any_label = true;
            anno.label(label.as_str()).legend(move |(x, y)| {
                Rectangle::new([(x, y - 7), (x + 22, y + 7)], col.mix(0.4).filled())
            });
        }
    }
    Ok(any_label)
}

/// Draws the reference lines with their labels on white boxes (vertical lines' labels
/// stacked from the top; horizontal lines' above the line at its right end, left end or
/// middle, whichever covers the fewest of the `data` samples, fractions of the axes).
fn draw_references<DB: DrawingBackend>(
    ch: &mut Ctx<'_, DB>,
    c: &Chart,
    bx: (f64, f64, f64, f64),
    data: &[Pt],
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let (x0, x1, y0, y1) = bx;
    let mut nv = 0;
    for (x, label) in &c.vlines {
        let Some(x) = axis::to_axis(*x, c.log_x).filter(|x| *x >= x0 && *x <= x1) else {
            continue;
        };
        let line = DashedLineSeries::new(vec![(x, y0), (x, y1)], 6, 4, REFERENCE.stroke_width(1));
        ch.draw_series(line).map_err(e)?;
        if label.is_empty() {
            continue;
        }
        let right = x > x0 + 0.7 * (x1 - x0);
        let (h, dx) = if right {
            (HPos::Right, -5)
        } else {
            (HPos::Left, 5)
        };
        let pos = Pos::new(h, VPos::Top);
        layout::boxed_text(
            ch.plotting_area(),
            (x, y1),
            (dx, 5 + 24 * nv),
            label,
            pos,
            REFERENCE,
        )?;
        nv += 1;
    }
    for (y, label) in &c.hlines {
        let Some(y) = axis::to_axis(*y, c.log_y).filter(|y| *y >= y0 && *y <= y1) else {
            continue;
        };
        let line = DashedLineSeries::new(vec![(x0, y), (x1, y)], 6, 4, REFERENCE.stroke_width(1));
        ch.draw_series(line).map_err(e)?;
        if label.is_empty() {
            continue;
        }
        // below the line when the line is near the top (the label would leave the frame)
        let near_top = y > y1 - 0.08 * (y1 - y0);
        let (v, dy) = if near_top {
            (VPos::Top, 4)
        } else {
            (VPos::Bottom, -4)
        };
        // at the end of the line (right, left or middle) whose label box covers least data
        let vf = (y - y0) / (y1 - y0);
        let (pw, ph) = ch.plotting_area().dim_in_pixel();
        let w = (0.6 * TICK_PX * label.chars().count() as f64 + 16.0) / pw.max(1) as f64;
        let h = 24.0 / ph.max(1) as f64;
        let (vlo, vhi) = if near_top { (vf - h, vf) } else { (vf, vf + h) };
        let count = |u0: f64| {
            let inside = |p: &&Pt| p.0 >= u0 && p.0 <= u0 + w && p.1 >= vlo && p.1 <= vhi;
            data.iter().filter(inside).count()
        };
        let spots = [(1.0 - w, HPos::Right, x1, -8), (0.0, HPos::Left, x0, 8)];
        let spots = spots.into_iter().chain(std::iter::once((
            0.5 - 0.5 * w,
            HPos::Center,
            0.5 * (x0 + x1),
            0,
        )));
        let (_, hp, at, dx) = spots
            .map(|sp| (count(sp.0), sp))
            .min_by_key(|(n, _)| *n)
            .map(|(_, sp)| sp)
            .unwrap_or((0.0, HPos::Right, x1, -8));
        let pos = Pos::new(hp, v);
        layout::boxed_text(ch.plotting_area(), (at, y), (dx, dy), label, pos, REFERENCE)?;
    }
    Ok(())
}

/// Draws the chart into `area`.
pub(super) fn draw_chart<DB: DrawingBackend>(
    c: &Chart,
    area: &DrawingArea<DB, Shift>,
) -> Result<(), String> {
    let runs: Vec<Vec<Vec<Pt>>> = c
        .series
        .iter()
        .map(|s| axis::runs(&s.points, c.log_x, c.log_y))
        .collect();
    let (mut xs, mut ys) = (Vec::new(), Vec::new());
    for p in runs.iter().flatten().flatten() {
        xs.push(p.0);
        ys.push(p.1);
    }
    xs.extend(c.vlines.iter().filter_map(|v| axis::to_axis(v.0, c.log_x)));
    ys.extend(c.hlines.iter().filter_map(|v| axis::to_axis(v.0, c.log_y)));
    let only_lines = c
        .series
        .iter()
        .all(|s| matches!(s.kind, Kind::Line | Kind::Dashed));
    let (x0, x1) = axis::range(c.x_range, &xs, if only_lines { 0.0 } else { 0.04 }, c.log_x);
    let (y0, y1) = axis::range(c.y_range, &ys, 0.06, c.log_y);
    let (pos, y1) = place_legend(c, &runs, (x0, x1, y0, y1), area.dim_in_pixel());
    let bx = (x0, x1, y0, y1);
    let logs = (c.log_x, c.log_y);
    let (mut ch, steps) = build_chart(area, &c.title, bx, logs)?;
    draw_axes(&mut ch, (&c.x_label, &c.y_label), steps, logs, true)?;
    let mut any_label = draw_bands(&mut ch, c, bx)?;
    any_label |= draw_series(&mut ch, &c.series, logs, bx, color)?;
    let drawn: Vec<(bool, &[Pt])> = c
        .series
        .iter()
        .zip(&runs)
        .flat_map(|(s, r)| r.iter().map(move |run| (s.kind != Kind::Points, &run[..])))
        .collect();
    draw_references(&mut ch, c, bx, &layout::samples(&drawn, bx))?;
    let notes: Vec<(f64, f64, String)> = c
        .notes
        .iter()
        .filter_map(|(x, y, t)| {
            let (x, y) = (axis::to_axis(*x, c.log_x)?, axis::to_axis(*y, c.log_y)?);
            Some((x, y, t.clone()))
        })
        .collect();
    layout::draw_notes(ch.plotting_area(), &notes)?;
    match pos {
        Some(pos) if any_label => crate::plot::draw_legend(&mut ch, pos),
        _ => Ok(()),
    }
}
