//! The map of gaits over (theta_0, mu): each cell one run of the stroboscopic map from
//! the static start, labelled by what it settles into (period-1, period-2, a longer
//! period, not settled, fell), drawn as a categorical map.

use super::poincare::{
    jacobian, moduli, multipliers, newton, settle, static_start, Difference, Gait,
};
use crate::error::Result;
use crate::numerics::hybrid::Options;
use crate::physics::stick::{StickModel, StickParams};
use crate::plot::{color, font, save_drawing, Drawing, CHART_SIZE, LABEL_PX, TICK_PX, TITLE_PX};
use crate::sweep::{linspace, par_map};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Cells per side (full, quick).
const CELLS: (usize, usize) = (24, 4);
/// Periods of the transient before the orbit is tested (full, quick).
const TRANSIENT: (usize, usize) = (250, 60);
/// Largest period tried.
const MAX_PERIOD: usize = 8;
/// An orbit closes when its points repeat to this distance (units of the section's
/// scales: 1 rad, omega, the plate's peak velocity). A classification threshold (a
/// cell's gait), not a claim's tolerance: it must lie above the map's evaluation error at
/// the map's rtol 1e-10 (the limit-cycle runs measure 2.0e-13 and 7.2e-15 at rtol 1e-12,
/// so about 2e-11 at 1e-10: 5e4 times below it) and below the distance of distinct orbit
/// points (6.7e-3 and more on the authors' unsettled orbit). A slowly settling cell can sit
/// above it after the transient (the self-locking gait contracts by 0.89 per period: 1e-6
/// after 100 periods) and is then classed not settled: the quick map's 60 periods say so
/// in its caption's terms, the full map's 250 resolve it.
const CLOSE_TOL: f64 = 1e-6;
/// Step of the Newton and stability Jacobians (units of the scales): the runs' noise at
/// the chapter's rtol 1e-10 over it is 1e-6, far below any |lambda| - 1 the map resolves.
const NEWTON_H: f64 = 1e-4;
/// The grid: theta_0 from, to (rad); mu from, to (the speed map's).
const THETA0: (f64, f64) = (0.05, 0.9);
/// See `THETA0`.
const MU: (f64, f64) = (0.1, 0.9);

/// The label of a cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Class {
    /// Settled on a period-1 gait.
    Period1,
    /// Not settled, but a period-1 fixed point with all multipliers inside the unit
    /// circle lies near the orbit: a stable gait approached slowly (|lambda| near 1).
    Slow,
    /// Settled on a period-2 gait.
    Period2,
    /// Settled on a gait of period 3 to 8.
    PeriodN,
    /// Not settled around an unstable period-1 fixed point (a multiplier outside the
    /// unit circle): the orbit circles it, quasi-periodic or chaotic.
    Unstable,
    /// No period up to 8 after the transient and no period-1 fixed point near the orbit.
    NotSettled,
    /// The stick fell.
    Fell,
    /// The run stopped otherwise (invalid state, Zeno).
    Stopped,
}

impl Class {
    /// Every class, in the legend's order.
    pub const ALL: [Class; 8] = [
        Class::Period1,
        Class::Slow,
        Class::Period2,
        Class::PeriodN,
        Class::Unstable,
        Class::NotSettled,
        Class::Fell,
        Class::Stopped,
    ];

    /// The class of a settled gait; for an orbit that did not settle, the stability of
    /// the period-1 fixed point Newton finds from its last point (if any).
    pub fn of(model: &StickModel, opts: &Options, g: &Gait) -> Class {
        match g {
            Gait::Periodic(1, _) => Class::Period1,
            Gait::Periodic(2, _) => Class::Period2,
            Gait::Periodic(..) => Class::PeriodN,
            Gait::NotSettled(x) => {
                let radius = newton(model, opts, x, 1, (NEWTON_H, 1e-9, 12))
                    .and_then(|(fp, _)| {
                        jacobian(model, opts, &fp, 1, NEWTON_H, Difference::Central)
                    })
                    .map(|j| moduli(&multipliers(&j)).into_iter().fold(0.0, f64::max));
                match radius {
                    Some(r) if r < 1.0 => Class::Slow,
                    Some(_) => Class::Unstable,
                    None => Class::NotSettled,
                }
            }
            Gait::Fell => Class::Fell,
            Gait::Stopped(_) => Class::Stopped,
        }
    }

    /// Legend text.
    pub fn label(self) -> &'static str {
        match self {
            Class::Period1 => "period-1, stable",
            Class::Slow => "period-1, stable, slow",
            Class::Period2 => "period-2",
            Class::PeriodN => "period 3 to 8",
            Class::Unstable => "unstable period-1",
            Class::NotSettled => "not settled",
            Class::Fell => "fell",
            Class::Stopped => "invalid / Zeno",
        }
    }

    fn colour(self) -> RGBColor {
        match self {
            Class::Period1 => color(2),
            Class::Slow => RGBColor(150, 215, 190),
            Class::Period2 => color(5),
            Class::PeriodN => color(0),
            Class::Unstable => color(4),
            Class::NotSettled => color(3),
            Class::Fell => color(1),
            Class::Stopped => RGBColor(170, 170, 170),
        }
    }
}

/// The computed map: `cells[iy * n + ix]` at `(thetas[ix], mus[iy])`.
#[derive(Debug, Clone)]
pub struct GaitMap {
    /// theta_0 of the columns (rad).
    pub thetas: Vec<f64>,
    /// mu of the rows.
    pub mus: Vec<f64>,
    /// The cells, row by row.
    pub cells: Vec<Class>,
    /// The base scene (its Gamma, f and stick).
    pub base: StickParams,
}

impl GaitMap {
    /// How many cells of each class, in [`Class::ALL`] order.
    pub fn counts(&self) -> Vec<(Class, usize)> {
        Class::ALL
            .iter()
            .map(|&c| (c, self.cells.iter().filter(|&&x| x == c).count()))
            .collect()
    }
}

/// The class of one cell: the gait of the static start.
pub fn classify(p: &StickParams, opts: &Options, transient: usize) -> Class {
    let model = StickModel::new(*p);
    match static_start(&model) {
        Some(x) => {
            let gait = settle(&model, opts, &x, (transient, MAX_PERIOD, CLOSE_TOL));
            Class::of(&model, opts, &gait)
        }
        None => Class::Stopped,
    }
}

/// The map over (theta_0, mu) around `base` (full or `quick`).
pub fn compute(base: &StickParams, opts: &Options, quick: bool) -> GaitMap {
    let (n, transient) = if quick {
        (CELLS.1, TRANSIENT.1)
    } else {
        (CELLS.0, TRANSIENT.0)
    };
    let thetas = linspace(THETA0.0, THETA0.1, n);
    let mus = linspace(MU.0, MU.1, n);
    let items: Vec<(f64, f64)> = mus
        .iter()
        .flat_map(|&mu| thetas.iter().map(move |&th| (th, mu)))
        .collect();
    let cells = par_map(&items, "stick gait map", |&(th, mu)| {
        let mut p = *base;
        p.theta0_rad = th;
        p.mu = mu;
        classify(&p, opts, transient)
    });
    GaitMap {
        thetas,
        mus,
        cells,
        base: *base,
    }
}

type Ctx<'b, DB> = ChartContext<
    'b,
    DB,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

impl GaitMap {
    fn half_cell(&self) -> (f64, f64) {
        let step = |v: &[f64], span: (f64, f64)| {
            if v.len() > 1 {
                0.5 * (span.1 - span.0) / (v.len() - 1) as f64
            } else {
                0.5 * (span.1 - span.0)
            }
        };
        (step(&self.thetas, THETA0), step(&self.mus, MU))
    }

    fn chart<'b, DB: DrawingBackend>(
        &self,
        area: &'b DrawingArea<DB, Shift>,
    ) -> std::result::Result<Ctx<'b, DB>, String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let (hx, hy) = self.half_cell();
        let mut ch = ChartBuilder::on(area)
            .margin(12)
            .x_label_area_size(58)
            .y_label_area_size(76)
            .build_cartesian_2d(THETA0.0 - hx..THETA0.1 + hx, MU.0 - hy..MU.1 + hy)
            .map_err(|e| e.to_string())?;
        ch.configure_mesh()
            .disable_mesh()
            .x_labels(8)
            .y_labels(8)
            .x_label_formatter(&|v| format!("{v:.1}"))
            .y_label_formatter(&|v| format!("{v:.1}"))
            .label_style(font(TICK_PX))
            .x_desc("spring rest angle θ₀ (rad)")
            .y_desc("friction coefficient μ")
            .axis_desc_style(font(LABEL_PX))
            .draw()
            .map_err(e)?;
        Ok(ch)
    }

    fn cells_and_marks<DB: DrawingBackend>(
        &self,
        ch: &mut Ctx<'_, DB>,
    ) -> std::result::Result<(), String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let (hx, hy) = self.half_cell();
        let n = self.thetas.len();
        let rects = self.cells.iter().enumerate().map(|(k, c)| {
            let (x, y) = (self.thetas[k % n], self.mus[k / n]);
            Rectangle::new([(x - hx, y - hy), (x + hx, y + hy)], c.colour().filled())
        });
        ch.draw_series(rects).map_err(e)?;
        let edge: Vec<(f64, f64)> = linspace(THETA0.0, THETA0.1, 200)
            .into_iter()
            .map(|t| (t, t.tan())) // formula: self-locking edge mu = tan theta_0
            .filter(|(_, m)| *m <= MU.1 + hy)
            .collect();
        ch.draw_series(DashedLineSeries::new(edge, 10, 6, BLACK.stroke_width(3)))
            .map_err(e)?;
        let scene = (0.3, 0.4); // the self-locking scene
        ch.draw_series([
            Circle::new(scene, 9, BLACK.stroke_width(3)),
            Circle::new(scene, 3, BLACK.filled()),
        ])
        .map_err(e)?;
        let note = |t: &str, at| Text::new(t.to_string(), at, font(TICK_PX));
        ch.draw_series([note("self-locking scene", (0.32, 0.43))])
            .map_err(e)?;
        ch.draw_series([note("μ = tan θ₀ (dashed)", (0.64, 0.62))])
            .map_err(e)?;
        Ok(())
    }

    fn legend<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let mut y = 90;
        area.draw(&Text::new("gait (cells)", (10, y - 34), font(LABEL_PX)))
            .map_err(e)?;
        for (c, k) in self.counts() {
            area.draw(&Rectangle::new(
                [(10, y), (34, y + 24)],
                c.colour().filled(),
            ))
            .map_err(e)?;
            let t = format!("{} ({k})", c.label());
            area.draw(&Text::new(t, (44, y + 3), font(TICK_PX)))
                .map_err(e)?;
            y += 40;
        }
        Ok(())
    }
}

impl Drawing for GaitMap {
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let (top, body) = area.split_vertically(48);
        let title = format!(
            "Gaits over (θ₀, μ): the stroboscopic map after {} periods, Γ = {}, f = {} Hz",
            if self.thetas.len() == CELLS.1 {
                TRANSIENT.1
            } else {
                TRANSIENT.0
            },
            super::round(self.base.gamma_accel(), 6),
            super::round(self.base.frequency_hz(), 6)
        );
        top.draw(&Text::new(title, (14, 12), font(TITLE_PX * 0.8)))
            .map_err(e)?;
        let w = body.dim_in_pixel().0;
        let (left, right) = body.split_horizontally(w - 250);
        let mut ch = self.chart(&left)?;
        self.cells_and_marks(&mut ch)?;
        self.legend(&right)
    }
}

/// Computes and draws the map as `dir/gait-map.svg` and `.png`; returns the paths and
/// the map.
pub fn draw(
    dir: &Path,
    base: &StickParams,
    opts: &Options,
    quick: bool,
) -> Result<(Vec<String>, GaitMap)> {
    let map = compute(base, opts, quick);
    let paths = save_drawing(&map, dir, "gait-map", CHART_SIZE)?;
    Ok((paths, map))
}
