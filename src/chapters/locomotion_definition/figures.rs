//! The hull figure: the reader's scene and the document's sailing cases, each a panel
//! with the media velocities, their convex hull and the labelled test velocities.

use super::statements::{WATER, WIND};
use crate::physics::locomotion::{classify, hull, Hull, Position, V2};
use crate::plot::{color, font, Drawing, GRID, LABEL_PX, TICK_PX, TITLE_PX};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// One panel of the hull figure: the media velocities and labelled test velocities.
pub struct Panel {
    /// Panel title.
    pub title: String,
    /// Media velocities (m/s).
    pub media: Vec<V2>,
    /// Test velocities (m/s) and their labels.
    pub tests: Vec<(V2, String)>,
}

/// The hull figure: panels stacked top to bottom, equal axis scales, laid out for the
/// book's content column (about 750 px): see [`WIDTH_PX`].
pub struct HullFigure {
    /// The panels, left to right.
    pub panels: Vec<Panel>,
}

impl HullFigure {
    /// The canvas (px): the column's width, one panel height per panel.
    pub fn size_px(&self) -> (u32, u32) {
        (WIDTH_PX, PANEL_HEIGHT_PX * self.panels.len().max(1) as u32)
    }
}

impl Drawing for HullFigure {
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        for (p, a) in self
            .panels
            .iter()
            .zip(area.split_evenly((self.panels.len().max(1), 1)))
        {
            draw_panel(p, &a)?;
        }
        Ok(())
    }
}

/// Width of the figure (px). The SVG backend writes a font of `s` px as `s/1.24`, so
/// the smallest text (ticks and legend, `TICK_PX` = 16) is 12.9 px in the file; shown
/// in a 750 px column at 750/800 of its size it is 12.1 px, above the 11 px a reader
/// needs (issue 24).
pub const WIDTH_PX: u32 = 800;

/// Height of one panel (px).
pub const PANEL_HEIGHT_PX: u32 = 620;

/// A panel's chart in m/s on both axes.
type Ch<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

fn err<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

fn draw_panel<DB: DrawingBackend>(
    p: &Panel,
    area: &DrawingArea<DB, Shift>,
) -> std::result::Result<(), String> {
    let mut ch = frame(p, area)?;
    let h = hull(&p.media);
    draw_hull(&mut ch, &h)?;
    draw_media(&mut ch, &p.media)?;
    draw_tests(&mut ch, &h, &p.tests)?;
    crate::plot::draw_legend(&mut ch, SeriesLabelPosition::UpperLeft)?;
    Ok(())
}

/// The titled chart with its mesh, equal scales, every velocity of the panel in view.
fn frame<'a, DB: DrawingBackend>(
    p: &Panel,
    area: &'a DrawingArea<DB, Shift>,
) -> std::result::Result<Ch<'a, DB>, String> {
    let all: Vec<V2> = p
        .media
        .iter()
        .copied()
        .chain(p.tests.iter().map(|t| t.0))
        .chain([[0.0, 0.0]])
        .collect();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for v in &all {
        (x0, x1, y0, y1) = (x0.min(v[0]), x1.max(v[0]), y0.min(v[1]), y1.max(v[1]));
    }
    // Equal scales: widen the shorter side to the plotting area's aspect ratio.
    let (w, h) = area.dim_in_pixel();
    let (pw, ph) = ((w as f64 - 110.0).max(10.0), (h as f64 - 130.0).max(10.0));
    let span = ((x1 - x0) / pw).max((y1 - y0) / ph).max(1e-300) * 1.3;
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let (xr, yr) = (
        cx - 0.5 * span * pw..cx + 0.5 * span * pw,
        cy - 0.5 * span * ph..cy + 0.5 * span * ph,
    );
    let mut ch = ChartBuilder::on(area)
        .caption(&p.title, font(TITLE_PX))
        .margin(18)
        .x_label_area_size(58)
        .y_label_area_size(70)
        .build_cartesian_2d(xr, yr)
        .map_err(err)?;
    ch.configure_mesh()
        .bold_line_style(GRID.stroke_width(1))
        .light_line_style(TRANSPARENT)
        .x_desc("v_x (m/s)")
        .y_desc("v_y (m/s)")
        .axis_desc_style(font(LABEL_PX))
        .label_style(font(TICK_PX))
        .draw()
        .map_err(err)?;
    Ok(ch)
}

/// The hull: a filled polygon, a thick segment, or nothing for a point.
fn draw_hull<DB: DrawingBackend>(ch: &mut Ch<'_, DB>, h: &Hull) -> Result<(), String> {
    let fill = color(5);
    match h {
        Hull::Polygon(vs) => {
            let pts: Vec<(f64, f64)> = vs.iter().map(|v| (v[0], v[1])).collect();
            ch.draw_series(std::iter::once(Polygon::new(
                pts.clone(),
                fill.mix(0.3).filled(),
            )))
            .map_err(err)?;
            let mut closed = pts.clone();
            closed.push(pts[0]);
            ch.draw_series(LineSeries::new(closed, fill.stroke_width(3)))
                .map_err(err)?
                .label("convex hull of the media velocities")
                .legend(move |(x, y)| {
                    Rectangle::new([(x, y - 7), (x + 22, y + 7)], fill.mix(0.5).filled())
                });
        }
        Hull::Segment(a, b) => {
            ch.draw_series(LineSeries::new(
                vec![(a[0], a[1]), (b[0], b[1])],
                fill.stroke_width(6),
            ))
            .map_err(err)?
            .label("convex hull of the media velocities (a segment)")
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 22, y)], fill.stroke_width(6))
            });
        }
        Hull::Point(_) => {}
    }
    Ok(())
}

/// The media velocities: black squares, named wind and water in the sailing scene.
fn draw_media<DB: DrawingBackend>(ch: &mut Ch<'_, DB>, media: &[V2]) -> Result<(), String> {
    let black = RGBColor(0, 0, 0);
    ch.draw_series(media.iter().map(|m| {
        EmptyElement::at((m[0], m[1])) + Rectangle::new([(-6, -6), (6, 6)], black.filled())
    }))
    .map_err(err)?
    .label("media velocities")
    .legend(move |(x, y)| Rectangle::new([(x + 5, y - 6), (x + 17, y + 6)], black.filled()));
    for (i, m) in media.iter().enumerate() {
        let name = if media.len() == 2 && *m == WIND {
            "wind".to_string()
        } else if media.len() == 2 && *m == WATER {
            "water".to_string()
        } else {
            format!("medium {}", i + 1)
        };
        let t = Text::new(
            name,
            (8, 8),
            font(TICK_PX).pos(Pos::new(HPos::Left, VPos::Top)),
        );
        ch.plotting_area()
            .draw(&(EmptyElement::at((m[0], m[1])) + t))
            .map_err(err)?;
    }
    Ok(())
}

/// The test velocities: green outside the hull, red in or on it, labelled.
fn draw_tests<DB: DrawingBackend>(
    ch: &mut Ch<'_, DB>,
    h: &Hull,
    tests: &[(V2, String)],
) -> Result<(), String> {
    let (yes, no) = (color(2), color(1));
    let mut labelled = (false, false);
    for (k, (v, label)) in tests.iter().enumerate() {
        let loco = classify(h, *v) == Position::Outside;
        let col = if loco { yes } else { no };
        let anno = ch
            .draw_series(std::iter::once(Circle::new((v[0], v[1]), 7, col.filled())))
            .map_err(err)?;
        if loco && !labelled.0 {
            labelled.0 = true;
            anno.label("locomotion (outside the hull)")
                .legend(move |(x, y)| Circle::new((x + 11, y), 7, yes.filled()));
        } else if !loco && !labelled.1 {
            labelled.1 = true;
            anno.label("not locomotion (in or on the hull)")
                .legend(move |(x, y)| Circle::new((x + 11, y), 7, no.filled()));
        }
        // Alternate labels below and above the markers so neighbours do not collide.
        let (dy, vp) = if k % 2 == 0 {
            (12, VPos::Top)
        } else {
            (-12, VPos::Bottom)
        };
        let t = Text::new(
            label.clone(),
            (0, dy),
            font(TICK_PX).color(&col).pos(Pos::new(HPos::Center, vp)),
        );
        ch.plotting_area()
            .draw(&(EmptyElement::at((v[0], v[1])) + t))
            .map_err(err)?;
    }
    Ok(())
}
