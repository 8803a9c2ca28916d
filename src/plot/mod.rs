//! The one figure style: embedded font, SVG + PNG, a colour-blind-safe palette.
//!
//! ```no_run
//! use locomotion_workbook::plot::{save_chart, Chart};
//! let c = Chart::new("Decay", "t (s)", "x (m)")
//!     .line("exact", vec![(0.0, 1.0), (1.0, 0.37)])
//!     .points("RK4", vec![(0.5, 0.6)])
//!     .vline(0.5, "half")
//!     .band(0.0, 0.2, "phase A");
//! let paths = save_chart(&c, "figures/demo", "decay").unwrap(); // demo.svg + demo.png
//! ```
//!
//! Figures are deterministic (the same bytes on every run: no time stamps, no random
//! state), use the DejaVu Sans font embedded in the binary (no system fonts needed), and
//! never panic on bad data: NaN and infinite points are dropped (they break lines),
//! non-positive values on log axes are dropped, empty and zero ranges are padded.
//! A log axis is a linear axis in log10 units with tick labels such as `1e-3`.

mod axis;
mod chart;
mod heatmap;
mod layout;
mod save;
mod series;
#[cfg(test)]
mod tests;

pub use heatmap::{viridis, HeatMap};
pub use save::{is_kebab, save_chart, save_drawing, save_gif, save_heatmap, save_panels};

use crate::error::{Result, WorkbookError};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

/// Size of a single chart in pixels (SVG and PNG alike).
pub const CHART_SIZE: (u32, u32) = (1000, 650);
/// Size of one panel of [`save_panels`] in pixels.
pub const PANEL_SIZE: (u32, u32) = (800, 540);
/// Font sizes in pixels: title, axis labels, tick labels and legend.
pub const TITLE_PX: f64 = 26.0;
/// Axis description font size in pixels.
pub const LABEL_PX: f64 = 20.0;
/// Tick label and legend font size in pixels.
pub const TICK_PX: f64 = 16.0;

/// The Okabe-Ito palette (colour-blind safe), in the order series get their colours.
pub const PALETTE: [RGBColor; 8] = [
    RGBColor(0, 114, 178),   // blue
    RGBColor(213, 94, 0),    // vermillion
    RGBColor(0, 158, 115),   // bluish green
    RGBColor(230, 159, 0),   // orange
    RGBColor(204, 121, 167), // reddish purple
    RGBColor(86, 180, 233),  // sky blue
    RGBColor(0, 0, 0),       // black
    RGBColor(240, 228, 66),  // yellow
];

/// Colour of reference lines (`vline`, `hline`).
pub const REFERENCE: RGBColor = RGBColor(60, 60, 60);
/// Colour of the grid.
pub const GRID: RGBColor = RGBColor(225, 225, 225);

/// The palette colour number `i` (cycling).
pub fn color(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

/// Draws a chart's legend box in the house style (framed, translucent white, tick-size
/// font) at `pos`. For custom [`Drawing`]s, so that their legends match the charts'.
pub fn draw_legend<'a, DB: DrawingBackend + 'a, CT: plotters::coord::CoordTranslate>(
    ch: &mut ChartContext<'a, DB, CT>,
    pos: SeriesLabelPosition,
) -> std::result::Result<(), String> {
    ch.configure_series_labels()
        .position(pos)
        .margin(12)
        .border_style(BLACK.mix(0.5))
        .background_style(WHITE.mix(0.92))
        .label_font(font(TICK_PX))
        .draw()
        .map_err(|e| e.to_string())
}

static FONT: Once = Once::new();

/// Registers the embedded DejaVu Sans as the `sans-serif` family (once per process).
/// The save functions call it; call it yourself only when drawing outside them.
pub fn ensure_font() {
    FONT.call_once(|| {
        // The bytes are a valid TrueType font shipped by the `dejavu` crate; a failure
        // here would surface as a FontUnavailable error from the first text drawn.
        let _ = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            dejavu::sans::regular(),
        );
    });
}

/// The text style of the figures at `size_px` pixels (black, sans-serif).
pub fn font(size_px: f64) -> TextStyle<'static> {
    ("sans-serif", size_px).into_font().color(&BLACK)
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A solid line through the points.
    Line,
    /// A dashed line through the points.
    Dashed,
    /// Markers only.
    Points,
    /// A solid line with a marker on every point (work-precision ladders).
    LinePoints,
}

/// One data series: label (empty = not in the legend), points in data units, style.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend label; an empty label keeps the series out of the legend.
    pub label: String,
    /// The points `(x, y)` in data units.
    pub points: Vec<(f64, f64)>,
    /// Line, dashed line or markers.
    pub kind: Kind,
    /// Palette index; `None` takes the next colour in order.
    pub color: Option<usize>,
}

impl Series {
    /// A solid line.
    pub fn line(label: &str, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.to_string(),
            points,
            kind: Kind::Line,
            color: None,
        }
    }
    /// A dashed line.
    pub fn dashed(label: &str, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.to_string(),
            points,
            kind: Kind::Dashed,
            color: None,
        }
    }
    /// A solid line with a marker on every point.
    pub fn line_points(label: &str, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.to_string(),
            points,
            kind: Kind::LinePoints,
            color: None,
        }
    }
    /// Markers.
    pub fn points(label: &str, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.to_string(),
            points,
            kind: Kind::Points,
            color: None,
        }
    }
    /// Uses palette colour `i` (to pair a line with its markers, for example).
    pub fn color(mut self, i: usize) -> Self {
        self.color = Some(i);
        self
    }
}

/// Where the legend goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Legend {
    /// The corner that covers the least data; headroom above the data when every
    /// corner covers some (the default of [`Chart::new`]).
    Auto,
    /// Upper right corner of the plotting area.
    UpperRight,
    /// Upper left corner.
    UpperLeft,
    /// Lower right corner.
    LowerRight,
    /// Lower left corner.
    LowerLeft,
    /// No legend.
    Hidden,
}

/// A 2-D chart: series, optional log axes and ranges, reference lines and bands.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    /// Title drawn above the chart.
    pub title: String,
    /// x-axis description with its unit.
    pub x_label: String,
    /// y-axis description with its unit.
    pub y_label: String,
    /// The data series, drawn in order.
    pub series: Vec<Series>,
    /// log10 x axis.
    pub log_x: bool,
    /// log10 y axis.
    pub log_y: bool,
    /// Explicit x range in data units.
    pub x_range: Option<(f64, f64)>,
    /// Explicit y range in data units.
    pub y_range: Option<(f64, f64)>,
    /// Vertical reference lines `(x, label)`.
    pub vlines: Vec<(f64, String)>,
    /// Horizontal reference lines `(y, label)`.
    pub hlines: Vec<(f64, String)>,
    /// Shaded x intervals `(x0, x1, label)`.
    pub bands: Vec<(f64, f64, String)>,
    /// Legend position.
    pub legend: Legend,
    /// Text notes `(x, y, text)` in data units, left-centred at the point, on a white box.
    pub notes: Vec<(f64, f64, String)>,
}

impl Chart {
    /// An empty chart with a title and axis labels (put units in the labels).
    pub fn new(title: &str, x_label: &str, y_label: &str) -> Self {
        Chart {
            title: title.to_string(),
            x_label: x_label.to_string(),
            y_label: y_label.to_string(),
            series: Vec::new(),
            log_x: false,
            log_y: false,
            x_range: None,
            y_range: None,
            vlines: Vec::new(),
            hlines: Vec::new(),
            bands: Vec::new(),
            legend: Legend::Auto,
            notes: Vec::new(),
        }
    }
    /// Adds a solid line.
    pub fn line(self, label: &str, points: Vec<(f64, f64)>) -> Self {
        self.series(Series::line(label, points))
    }
    /// Adds a dashed line.
    pub fn dashed(self, label: &str, points: Vec<(f64, f64)>) -> Self {
        self.series(Series::dashed(label, points))
    }
    /// Adds a solid line with a marker on every point.
    pub fn line_points(self, label: &str, points: Vec<(f64, f64)>) -> Self {
        self.series(Series::line_points(label, points))
    }
    /// Adds markers.
    pub fn points(self, label: &str, points: Vec<(f64, f64)>) -> Self {
        self.series(Series::points(label, points))
    }
    /// Adds a prepared series.
    pub fn series(mut self, s: Series) -> Self {
        self.series.push(s);
        self
    }
    /// log10 x axis (points with x <= 0 are dropped).
    pub fn log_x(mut self) -> Self {
        self.log_x = true;
        self
    }
    /// log10 y axis (points with y <= 0 are dropped).
    pub fn log_y(mut self) -> Self {
        self.log_y = true;
        self
    }
    /// Fixes the x range (data units); parts of lines outside are clipped.
    pub fn x_range(mut self, a: f64, b: f64) -> Self {
        self.x_range = Some((a, b));
        self
    }
    /// Fixes the y range (data units).
    pub fn y_range(mut self, a: f64, b: f64) -> Self {
        self.y_range = Some((a, b));
        self
    }
    /// A vertical reference line at `x`, labelled next to it.
    pub fn vline(mut self, x: f64, label: &str) -> Self {
        self.vlines.push((x, label.to_string()));
        self
    }
    /// A horizontal reference line at `y`, labelled next to it.
    pub fn hline(mut self, y: f64, label: &str) -> Self {
        self.hlines.push((y, label.to_string()));
        self
    }
    /// A shaded x interval (a phase, a regime), listed in the legend.
    pub fn band(mut self, x0: f64, x1: f64, label: &str) -> Self {
        self.bands.push((x0, x1, label.to_string()));
        self
    }
    /// Moves (or hides) the legend.
    pub fn legend(mut self, at: Legend) -> Self {
        self.legend = at;
        self
    }
    /// A text note left-centred at `(x, y)` (data units), on a white box.
    pub fn note(mut self, x: f64, y: f64, text: &str) -> Self {
        self.notes.push((x, y, text.to_string()));
        self
    }
}

/// A picture drawn into a plotters drawing area: implement it for custom figures
/// (hulls, stick snapshots) and save with [`save_drawing`]. [`Chart`] and [`HeatMap`]
/// implement it too, so a drawing can place charts into parts of its area.
pub trait Drawing {
    /// Draws into `area` (already filled white). Errors are messages.
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String>;
}

impl Drawing for Chart {
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        chart::draw_chart(self, area)
    }
}

/// A chart with a second chart drawn over it as an inset (a zoom, for example) on a
/// white, framed box at `frac = (left, top, width, height)`, fractions of the area.
#[derive(Debug, Clone, PartialEq)]
pub struct WithInset {
    /// The main chart.
    pub main: Chart,
    /// The inset chart.
    pub inset: Chart,
    /// The inset's box: left, top, width, height as fractions of the whole area.
    pub frac: (f64, f64, f64, f64),
}

impl Drawing for WithInset {
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        self.main.draw(area)?;
        let (w, h) = area.dim_in_pixel();
        let f = |v: f64, n: u32| (v.clamp(0.0, 1.0) * n as f64).round() as i32;
        let (l, t) = (f(self.frac.0, w), f(self.frac.1, h));
        let size = (
            f(self.frac.2, w).max(1) as u32,
            f(self.frac.3, h).max(1) as u32,
        );
        let sub = area.clone().shrink((l, t), size);
        sub.fill(&WHITE).map_err(|e| e.to_string())?;
        self.inset.draw(&sub)?;
        let (sw, sh) = sub.dim_in_pixel();
        let frame = Rectangle::new(
            [(0, 0), (sw as i32 - 1, sh as i32 - 1)],
            REFERENCE.stroke_width(1),
        );
        sub.draw(&frame).map_err(|e| e.to_string())
    }
}

struct Panels<'a> {
    charts: &'a [Chart],
    cols: usize,
}

impl Drawing for Panels<'_> {
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        let rows = self.charts.len().div_ceil(self.cols).max(1);
        for (c, a) in self.charts.iter().zip(area.split_evenly((rows, self.cols))) {
            c.draw(&a)?;
        }
        Ok(())
    }
}
