//! The sketch of the effective-mass chapter: the stick on the plate, the friction cone
//! at C, and the impulse directions of the two models at the chosen angle.

use crate::plot::{color, font, Drawing, GRID, LABEL_PX, TICK_PX, TITLE_PX};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Stick at `theta_rad` (length 1), friction coefficient `mu`, impulse ratios
/// `J_l/J_v` of the point-mass model and of the uniform rod.
pub struct Sketch {
    /// Lean angle from the vertical (rad).
    pub theta_rad: f64,
    /// Friction coefficient (1).
    pub mu: f64,
    /// J_l/J_v of the point-mass model.
    pub ratio_point_mass: f64,
    /// J_l/J_v of the uniform rod.
    pub ratio_rod: f64,
}

/// A polyline in data units.
type Path = Vec<(f64, f64)>;

/// An arrow from `from` along the unit direction `u` with length `len` (data units).
fn arrow(from: (f64, f64), u: (f64, f64), len: f64) -> (Path, Path) {
    let tip = (from.0 + len * u.0, from.1 + len * u.1);
    let (h, w) = (0.07, 0.035);
    let base = (tip.0 - h * u.0, tip.1 - h * u.1);
    let n = (-u.1, u.0);
    let head = vec![
        tip,
        (base.0 + w * n.0, base.1 + w * n.1),
        (base.0 - w * n.0, base.1 - w * n.1),
    ];
    (vec![from, base], head)
}

fn unit(x: f64, y: f64) -> (f64, f64) {
    let r = x.hypot(y);
    (x / r, y / r)
}

/// The chart of the sketch: equal scales, data units of stick lengths.
type Ch<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

impl Drawing for Sketch {
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<(), String> {
        let (mut ch, reach) = self.frame(area)?;
        self.cone(&mut ch, reach)?;
        let s = self.stick(&mut ch)?;
        self.arrows(&mut ch, reach)?;
        crate::plot::draw_legend(
            &mut ch,
            if s >= 0.0 {
                SeriesLabelPosition::UpperLeft
            } else {
                SeriesLabelPosition::UpperRight
            },
        )?;
        Ok(())
    }
}

fn err<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

impl Sketch {
    /// The titled chart with its mesh, and the reach of the cone and arrows (data units).
    fn frame<'a, DB: DrawingBackend>(
        &self,
        area: &'a DrawingArea<DB, Shift>,
    ) -> Result<(Ch<'a, DB>, f64), String> {
        let (w, h) = area.dim_in_pixel();
        // Equal scales: x from -1.1 to 1.1, y from -0.15 up to what the aspect allows.
        let scale = 2.2 / (w as f64 - 100.0).max(10.0);
        let y1 = -0.15 + scale * (h as f64 - 130.0).max(10.0);
        let title = format!(
            "Impulse at C: θ = {:.1}°, μ = {}",
            self.theta_rad.to_degrees(),
            crate::report::fmt_num(self.mu)
        );
        let mut ch = ChartBuilder::on(area)
            .caption(title, font(TITLE_PX))
            .margin(18)
            .x_label_area_size(50)
            .y_label_area_size(60)
            .build_cartesian_2d(-1.1..1.1, -0.15..y1)
            .map_err(err)?;
        ch.configure_mesh()
            .bold_line_style(GRID.stroke_width(1))
            .light_line_style(TRANSPARENT)
            .x_desc("x (stick lengths)")
            .y_desc("z (stick lengths)")
            .axis_desc_style(font(LABEL_PX))
            .label_style(font(TICK_PX))
            .draw()
            .map_err(err)?;
        Ok((ch, 0.95 * y1.min(1.3)))
    }

    /// The friction cone at C, cut where it would leave the plot.
    fn cone<DB: DrawingBackend>(&self, ch: &mut Ch<'_, DB>, reach: f64) -> Result<(), String> {
        let cone = color(2);
        // Cut the cone where it would leave the plot (half-width 1.1 at most).
        let top = if self.mu * reach > 1.1 {
            1.1 / self.mu
        } else {
            reach
        };
        let tri = vec![(0.0, 0.0), (-self.mu * top, top), (self.mu * top, top)];
        ch.draw_series(std::iter::once(Polygon::new(tri, cone.mix(0.25).filled())))
            .map_err(err)?
            .label("friction cone |J_ℓ| ≤ μ J_v (C holds inside)")
            .legend(move |(x, y)| {
                Rectangle::new([(x, y - 7), (x + 22, y + 7)], cone.mix(0.4).filled())
            });
        Ok(())
    }

    /// The plate, the stick C-P and the labels of its ends; returns sin(theta).
    fn stick<DB: DrawingBackend>(&self, ch: &mut Ch<'_, DB>) -> Result<f64, String> {
        let grey = RGBColor(120, 120, 120);
        ch.draw_series(LineSeries::new(
            vec![(-1.1, 0.0), (1.1, 0.0)],
            grey.stroke_width(4),
        ))
        .map_err(err)?;
        let (s, c) = self.theta_rad.sin_cos();
        let black = RGBColor(0, 0, 0);
        ch.draw_series(LineSeries::new(
            vec![(0.0, 0.0), (s, c)],
            black.stroke_width(6),
        ))
        .map_err(err)?
        .label("stick C-P")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], black.stroke_width(6)));
        // P above the stick's end; C below the plate, on the side away from the lean.
        let side = if s >= 0.0 { HPos::Right } else { HPos::Left };
        let dx = if s >= 0.0 { -10 } else { 10 };
        for (t, at, off, pos) in [
            ("P", (s, c), (8, -8), Pos::new(HPos::Left, VPos::Bottom)),
            ("C", (0.0, 0.0), (dx, 8), Pos::new(side, VPos::Top)),
        ] {
            let text = Text::new(t, off, font(LABEL_PX).pos(pos));
            ch.plotting_area()
                .draw(&(EmptyElement::at(at) + text))
                .map_err(err)?;
        }
        Ok(s)
    }

    /// The impulse directions of the two models.
    fn arrows<DB: DrawingBackend>(&self, ch: &mut Ch<'_, DB>, reach: f64) -> Result<(), String> {
        for (k, (ratio, name)) in [
            (self.ratio_point_mass, "point mass: J_ℓ/J_v = q"),
            (self.ratio_rod, "uniform rod: J_ℓ/J_v = 3q/(4+q²)"),
        ]
        .into_iter()
        .enumerate()
        {
            let col = color(k);
            let (shaft, head) = arrow((0.0, 0.0), unit(ratio, 1.0), 0.75 * reach);
            ch.draw_series(LineSeries::new(shaft, col.stroke_width(3)))
                .map_err(err)?
                .label(format!("{name} = {}", crate::report::fmt_num(ratio)))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 22, y)], col.stroke_width(3))
                });
            ch.draw_series(std::iter::once(Polygon::new(head, col.filled())))
                .map_err(err)?;
        }
        Ok(())
    }
}
