//! Heat maps (parameter maps) with a viridis colour bar and overlaid curves.

use super::axis::{self, Ticked};
use super::chart::{build_chart, draw_axes, tick_label, ticks};
use super::series::draw_series;
use super::{font, Drawing, Legend, Series, GRID, LABEL_PX, TICK_PX, TITLE_PX};
use plotters::coord::Shift;
use plotters::prelude::*;

/// A heat map: `values[iy][ix]` at grid points `(xs[ix], ys[iy])`, one cell per value.
/// Missing or non-finite values are drawn grey.
#[derive(Debug, Clone, PartialEq)]
pub struct HeatMap {
    /// Title.
    pub title: String,
    /// x-axis description with unit.
    pub x_label: String,
    /// y-axis description with unit.
    pub y_label: String,
    /// Grid x values (increasing), one per column.
    pub xs: Vec<f64>,
    /// Grid y values (increasing), one per row.
    pub ys: Vec<f64>,
    /// `values[iy][ix]`.
    pub values: Vec<Vec<f64>>,
    /// Label of the colour bar (quantity and unit).
    pub color_label: String,
    /// Curves drawn over the map (boundaries, theory), in data units.
    pub overlays: Vec<Series>,
    /// Legend position for the overlays ([`Legend::Auto`] means upper right here).
    pub legend: Legend,
    /// Text notes `(x, y, text)` in data units, left-centred at the point, on a white box.
    pub notes: Vec<(f64, f64, String)>,
}

impl HeatMap {
    /// A heat map of `values[iy][ix]` over the grid `xs` x `ys`.
    pub fn new(
        title: &str,
        x_label: &str,
        y_label: &str,
        xs: Vec<f64>,
        ys: Vec<f64>,
        values: Vec<Vec<f64>>,
        color_label: &str,
    ) -> Self {
        HeatMap {
            title: title.to_string(),
            x_label: x_label.to_string(),
            y_label: y_label.to_string(),
            xs,
            ys,
            values,
            color_label: color_label.to_string(),
            overlays: Vec::new(),
            legend: Legend::UpperRight,
            notes: Vec::new(),
        }
    }
    /// Draws a curve over the map.
    pub fn overlay(mut self, s: Series) -> Self {
        self.overlays.push(s);
        self
    }
    /// A text note left-centred at `(x, y)` (data units), on a white box.
    pub fn note(mut self, x: f64, y: f64, text: &str) -> Self {
        self.notes.push((x, y, text.to_string()));
        self
    }
    /// Moves (or hides) the overlay legend.
    pub fn legend(mut self, at: Legend) -> Self {
        self.legend = at;
        self
    }
}

/// Viridis anchors at 0, 0.1, ..., 1 (perceptually uniform, colour-blind safe).
const VIRIDIS: [(u8, u8, u8); 11] = [
    (0x44, 0x01, 0x54),
    (0x48, 0x24, 0x75),
    (0x41, 0x44, 0x87),
    (0x35, 0x5f, 0x8d),
    (0x2a, 0x78, 0x8e),
    (0x21, 0x91, 0x8c),
    (0x22, 0xa8, 0x84),
    (0x44, 0xbf, 0x70),
    (0x7a, 0xd1, 0x51),
    (0xbd, 0xdf, 0x26),
    (0xfd, 0xe7, 0x25),
];

/// The viridis colour of `t` in [0, 1] (clamped; NaN gives grey).
pub fn viridis(t: f64) -> RGBColor {
    if !t.is_finite() {
        return RGBColor(190, 190, 190);
    }
    let s = t.clamp(0.0, 1.0) * 10.0;
    let i = (s.floor() as usize).min(9);
    let f = s - i as f64;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    let mix = |p: u8, q: u8| (p as f64 + f * (q as f64 - p as f64)).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Cell edges around grid values: midpoints, ends extended by half a spacing.
/// Grids that are not finite and strictly increasing fall back to their indices.
fn edges(v: &[f64]) -> Vec<f64> {
    let ok = v.iter().all(|x| x.is_finite()) && v.windows(2).all(|w| w[0] < w[1]);
    let v: Vec<f64> = if ok {
        v.to_vec()
    } else {
        (0..v.len()).map(|i| i as f64).collect()
    };
    match v.len() {
        0 => vec![0.0, 1.0],
        1 => vec![v[0] - 0.5, v[0] + 0.5],
        n => {
            let mut e = vec![v[0] - 0.5 * (v[1] - v[0])];
            e.extend(v.windows(2).map(|w| 0.5 * (w[0] + w[1])));
            e.push(v[n - 1] + 0.5 * (v[n - 1] - v[n - 2]));
            e
        }
    }
}

/// The cells as an RGB image of `size` pixels covering the map's box (edges `ex`, `ey`
/// in data units, y upwards): each pixel takes the colour of the cell holding its centre.
/// One image instead of one rectangle per cell keeps a 128 x 128 map's SVG small.
fn cell_pixels(
    size: (u32, u32),
    (ex, ey): (&[f64], &[f64]),
    colour: impl Fn(usize, usize) -> RGBColor,
) -> Vec<u8> {
    let (w, h) = (size.0 as usize, size.1 as usize);
    let (x0, x1) = (ex[0], ex[ex.len() - 1]);
    let (y0, y1) = (ey[0], ey[ey.len() - 1]);
    let cell = |edges: &[f64], v: f64| {
        edges[1..edges.len() - 1].partition_point(|&b| b <= v) // index of the cell holding v
    };
    let cols: Vec<usize> = (0..w)
        .map(|i| cell(ex, x0 + (i as f64 + 0.5) / w as f64 * (x1 - x0)))
        .collect();
    let mut buf = Vec::with_capacity(w * h * 3);
    for j in 0..h {
        let iy = cell(ey, y1 - (j as f64 + 0.5) / h as f64 * (y1 - y0));
        for &ix in &cols {
            let c = colour(ix, iy);
            buf.extend([c.0, c.1, c.2]);
        }
    }
    buf
}

fn overlay_color(i: usize) -> RGBColor {
    [
        RGBColor(255, 255, 255),
        RGBColor(213, 94, 0),
        RGBColor(0, 0, 0),
        RGBColor(204, 121, 167),
    ][i % 4]
}

impl Drawing for HeatMap {
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<(), String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let (ex, ey) = (edges(&self.xs), edges(&self.ys));
        let finite: Vec<f64> = self
            .values
            .iter()
            .flatten()
            .copied()
            .filter(|v| v.is_finite())
            .collect();
        let (vmin, vmax) = axis::range(None, &finite, 0.0, false);
        let width = area.dim_in_pixel().0 as i32;
        let (main, bar) = area.split_horizontally(width - 150);

        let (x0, x1) = (ex[0], ex[ex.len() - 1]);
        let (y0, y1) = (ey[0], ey[ey.len() - 1]);
        let linear = (false, false);
        let (mut ch, steps) = build_chart(&main, &self.title, (x0, x1, y0, y1), linear)?;
        let colour = |ix: usize, iy: usize| {
            let v = self.values.get(iy).and_then(|r| r.get(ix)).copied();
            viridis((v.unwrap_or(f64::NAN) - vmin) / (vmax - vmin))
        };
        let (px, py) = ch.plotting_area().get_pixel_range();
        let size = (
            (px.end - px.start).max(1) as u32,
            (py.end - py.start).max(1) as u32,
        );
        let pixels = cell_pixels(size, (&ex, &ey), colour);
        if let Some(img) = BitMapElement::with_owned_buffer((x0, y1), size, pixels) {
            ch.plotting_area().draw(&img).map_err(e)?;
        }
        draw_axes(
            &mut ch,
            (&self.x_label, &self.y_label),
            steps,
            linear,
            false,
        )?;
        let labelled = draw_series(
            &mut ch,
            &self.overlays,
            linear,
            (x0, x1, y0, y1),
            overlay_color,
        )?;
        let pos = match self.legend {
            Legend::UpperRight | Legend::Auto => Some(SeriesLabelPosition::UpperRight),
            Legend::UpperLeft => Some(SeriesLabelPosition::UpperLeft),
            Legend::LowerRight => Some(SeriesLabelPosition::LowerRight),
            Legend::LowerLeft => Some(SeriesLabelPosition::LowerLeft),
            Legend::Hidden => None,
        };
        super::layout::draw_notes(ch.plotting_area(), &self.notes)?;
        if let (true, Some(pos)) = (labelled, pos) {
            ch.configure_series_labels()
                .position(pos)
                .margin(12)
                .border_style(BLACK.mix(0.5))
                .background_style(RGBColor(150, 150, 150).mix(0.9))
                .label_font(font(TICK_PX))
                .draw()
                .map_err(e)?;
        }

        self.draw_colour_bar(&bar, (vmin, vmax))
    }
}

impl HeatMap {
    /// The colour bar from `vmin` to `vmax` in `bar`: the same caption and x-label area
    /// as the map, so the two align.
    fn draw_colour_bar<DB: DrawingBackend>(
        &self,
        bar: &DrawingArea<DB, Shift>,
        (vmin, vmax): (f64, f64),
    ) -> Result<(), String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let (bt, bstep) = ticks(vmin, vmax, false);
        let mut cb = ChartBuilder::on(bar)
            .caption(" ", font(TITLE_PX))
            .margin(18)
            .margin_left(4)
            .x_label_area_size(58)
            .set_label_area_size(LabelAreaPosition::Right, 100)
            .build_cartesian_2d(Ticked::new(0.0, 1.0, vec![]), Ticked::new(vmin, vmax, bt))
            .map_err(e)?;
        let n = 128;
        let strips = (0..n).map(|k| {
            let (a, b) = (k as f64 / n as f64, (k + 1) as f64 / n as f64);
            let (va, vb) = (vmin + a * (vmax - vmin), vmin + b * (vmax - vmin));
            Rectangle::new([(0.0, va), (1.0, vb)], viridis(0.5 * (a + b)).filled())
        });
        cb.draw_series(strips).map_err(e)?;
        let fb = |v: &f64| format!(" {}", tick_label(*v, bstep, false));
        cb.configure_mesh()
            .disable_x_mesh()
            .bold_line_style(GRID.mix(0.0))
            .light_line_style(TRANSPARENT)
            .axis_style(BLACK.stroke_width(1))
            .y_desc(self.color_label.as_str())
            .axis_desc_style(font(LABEL_PX))
            .label_style(font(TICK_PX))
            .y_label_formatter(&fb)
            .draw()
            .map_err(e)?;
        Ok(())
    }
}
