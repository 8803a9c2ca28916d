//! `gait-toothpick.gif`: a uniform stick (a toothpick, m = 0, 1 kg rod) beside chapter
//! 6's massless rod (1 kg at P) on the same plate of the self-locking scene, both with
//! chapter 6's spring and damper, drawn to scale frame by frame.
//!
//! Left: both sticks at their true lean on one plate, with a ground mark where each foot
//! started. Right: a close-up of each foot (magnified so that the plate's sub-millimetre
//! stroke and the hops show), with millimetre ticks fixed in the laboratory and the
//! foot's track over the last drive cycle. The heading gives the time and each stick's mode.

use crate::error::Result;
use crate::numerics::hybrid::Options;
use crate::physics::stick::run::{initial_state, simulate_stick, Recording};
use crate::physics::stick::{jamming_scene, StickModel};
use crate::physics::stick_inertia::{InertiaModel, InertiaParams, TH, XC, ZC};
use crate::plot::{color, font, Drawing, GRID, LABEL_PX, TICK_PX};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

/// Frame size (pixels).
const SIZE: (u32, u32) = (640, 360);
/// Frames per drive cycle (at least 30: the hop of the toothpick lasts about a third of a cycle).
pub const PER_CYCLE: usize = 30;
/// Drive cycles shown (after the first, the start from rest).
pub const CYCLES: usize = 2;
/// Display time of a frame (ms): a 33 ms drive cycle plays in 1.8 s.
const DELAY_MS: u32 = 60;
/// Where the toothpick's foot starts (mm right of the massless stick's).
const OFFSET_MM: f64 = 100.0;
/// Half-width and half-height of the foot close-ups (mm).
const HALF_MM: (f64, f64) = (6.0, 2.0);
/// Plate grey.
const PLATE: RGBColor = RGBColor(170, 170, 170);

/// One stick at one instant (mm, relative to its foot's start).
#[derive(Debug, Clone)]
pub struct Pose {
    /// Foot C (mm).
    pub c: (f64, f64),
    /// Top P (mm).
    pub p: (f64, f64),
    /// Mode name.
    pub mode: &'static str,
    /// C's track over the last drive cycle (mm).
    pub track: Vec<(f64, f64)>,
}

/// One frame: time, plate height (mm) and the two poses (massless, toothpick).
#[derive(Debug, Clone)]
pub struct Frame {
    /// Time (s).
    pub t_s: f64,
    /// Drive period (s).
    pub period_s: f64,
    /// Plate height (mm).
    pub z_s: f64,
    /// Chapter 6's massless rod, then the toothpick.
    pub poses: [Pose; 2],
}

/// A trace sample: time (s), C and P (m), mode name.
type Sample = (f64, (f64, f64), (f64, f64), &'static str);

/// Chapter 6's massless rod (1 kg at P) and the toothpick (1 kg rod, no tip), traced
/// every `dt` (s) to `t_end` (s) from rest on the self-locking scene.
fn traces(t_end: f64, dt: f64, opts: &Options) -> [Vec<Sample>; 2] {
    let b6 = jamming_scene(9.81);
    let m6 = StickModel::new(b6);
    let y6 = initial_state(&m6, 0.0, b6.static_angle().unwrap_or(b6.theta0_rad));
    let rec = Recording {
        trace_dt_s: dt,
        ..Recording::default()
    };
    let s6 = simulate_stick(&m6, 0.0, y6, t_end, opts, rec);
    let massless = s6
        .trace
        .iter()
        .map(|s| {
            let [xp, zp, ..] = m6.tip(&s.y);
            let c = (
                s.y[crate::physics::stick::XC],
                s.y[crate::physics::stick::ZC],
            );
            (s.t_s, c, (xp, zp), s.mode.name())
        })
        .collect();
    let mut b = b6;
    b.mass_kg = 0.0;
    let p = InertiaParams {
        base: b,
        rod_mass_kg: 1.0,
        restitution: 0.0,
    };
    let run = super::evidence::scene_run(&p, t_end, 1e-10, dt);
    let l = b.length_m;
    let tooth = run
        .trace
        .iter()
        .map(|s| {
            let (sn, cs) = s.y[TH].sin_cos();
            let c = (s.y[XC], s.y[ZC]);
            (s.t_s, c, (c.0 + l * sn, c.1 + l * cs), s.mode.name()) // formula: r_P = r_C + L e_r
        })
        .collect();
    [massless, tooth]
}

/// The frames: [`CYCLES`] drive cycles after the first, [`PER_CYCLE`] frames each.
pub fn frames() -> Vec<Frame> {
    let period = 1.0 / 30.0;
    let dt = period / (4 * PER_CYCLE) as f64;
    let t_end = (1 + CYCLES) as f64 * period;
    let opts = Options {
        record_events: false,
        ..super::evidence::options(1e-10)
    };
    let tr = traces(t_end, dt, &opts);
    let plate = InertiaModel::new(InertiaParams {
        base: jamming_scene(9.81),
        rod_mass_kg: 0.0,
        restitution: 0.0,
    });
    let mm = |v: f64| 1e3 * v;
    (0..CYCLES * PER_CYCLE)
        .map(|k| {
            let t = (1.0 + k as f64 / PER_CYCLE as f64) * period;
            let poses = [0, 1].map(|i| {
                let s = &tr[i];
                let x0 = s.first().map_or(0.0, |q| q.1 .0);
                let at = s
                    .iter()
                    .min_by(|a, b| (a.0 - t).abs().total_cmp(&(b.0 - t).abs()))
                    .copied()
                    .unwrap_or((t, (x0, 0.0), (x0, 0.0), "flight"));
                let off = i as f64 * OFFSET_MM;
                let rel = |q: (f64, f64)| (mm(q.0 - x0) + off, mm(q.1));
                Pose {
                    c: rel(at.1),
                    p: rel(at.2),
                    mode: at.3,
                    track: s
                        .iter()
                        .filter(|q| q.0 <= at.0 && q.0 >= at.0 - period)
                        .map(|q| rel(q.1))
                        .collect(),
                }
            });
            Frame {
                t_s: t,
                period_s: period,
                z_s: mm(plate.plate(t).0),
                poses,
            }
        })
        .collect()
}

type Ctx<'b, DB> = ChartContext<
    'b,
    DB,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// A chart on `area` with equal scales, the box `(x0, x1, z0, z1)` (mm) widened along one
/// axis to the area's aspect ratio; grid, tick labels, and the plate up to `z_s` (mm).
fn mm_chart<'b, DB: DrawingBackend>(
    area: &'b DrawingArea<DB, Shift>,
    bx: (f64, f64, f64, f64),
    x_desc: &str,
    z_s: f64,
) -> std::result::Result<Ctx<'b, DB>, String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let (lx, ly) = (34u32, 44u32);
    let (w, h) = area.dim_in_pixel();
    let pw = (w as f64 - 12.0 - ly as f64).max(1.0);
    let ph = (h as f64 - 12.0 - lx as f64).max(1.0);
    let s = ((bx.1 - bx.0) / pw).max((bx.3 - bx.2) / ph); // formula: mm per pixel, the larger
    let (cx, cz) = (0.5 * (bx.0 + bx.1), 0.5 * (bx.2 + bx.3));
    let mut ch = ChartBuilder::on(area)
        .margin(6)
        .x_label_area_size(lx)
        .y_label_area_size(ly)
        .build_cartesian_2d(
            cx - 0.5 * s * pw..cx + 0.5 * s * pw,
            cz - 0.5 * s * ph..cz + 0.5 * s * ph,
        )
        .map_err(e)?;
    ch.configure_mesh()
        .bold_line_style(GRID.stroke_width(1))
        .light_line_style(TRANSPARENT)
        .x_labels(5)
        .y_labels(4)
        .x_label_formatter(&|v| format!("{v:.0}"))
        .y_label_formatter(&|v| format!("{v:.0}"))
        .label_style(font(TICK_PX - 2.0))
        .x_desc(x_desc)
        .y_desc("z (mm)")
        .axis_desc_style(font(TICK_PX - 2.0))
        .draw()
        .map_err(e)?;
    let (xr, zr) = (ch.x_range(), ch.y_range());
    ch.draw_series([Rectangle::new(
        [(xr.start, zr.start), (xr.end, z_s)],
        PLATE.filled(),
    )])
    .map_err(e)?;
    Ok(ch)
}

/// A frame drawn.
pub struct Picture<'a>(pub &'a Frame);

/// Labels and colours of the two sticks.
const STICKS: [(&str, usize); 2] = [
    ("massless rod, 1 kg at P (ch. 6)", 0),
    ("uniform 1 kg stick (toothpick)", 1),
];

impl Picture<'_> {
    fn whole<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let f = self.0;
        let bx = (-15.0, OFFSET_MM + 75.0, -12.0, 160.0);
        let mut ch = mm_chart(area, bx, "x (mm)", f.z_s)?;
        let zr = ch.y_range();
        for (i, pose) in f.poses.iter().enumerate() {
            let col = color(STICKS[i].1);
            let x0 = i as f64 * OFFSET_MM;
            // the ground mark: where this foot started, fixed in the laboratory
            let mark = Polygon::new(
                vec![(x0, f.z_s), (x0 - 3.0, zr.start), (x0 + 3.0, zr.start)],
                BLACK.filled(),
            );
            ch.draw_series([mark]).map_err(e)?;
            let width = if i == 0 { 3 } else { 7 };
            ch.draw_series([PathElement::new(
                vec![pose.c, pose.p],
                col.stroke_width(width),
            )])
            .map_err(e)?;
            if i == 0 {
                ch.draw_series([Circle::new(pose.p, 9, col.filled())])
                    .map_err(e)?;
            }
            ch.draw_series([Circle::new(pose.c, 4, BLACK.filled())])
                .map_err(e)?;
        }
        Ok(())
    }

    fn closeup<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        i: usize,
    ) -> std::result::Result<(), String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let (f, pose) = (self.0, &self.0.poses[i]);
        let bx = (
            pose.c.0 - HALF_MM.0,
            pose.c.0 + HALF_MM.0,
            -HALF_MM.1,
            HALF_MM.1 + 0.5,
        );
        let desc = if i == 0 {
            "foot, ch. 6 (mm)"
        } else {
            "foot, toothpick (mm)"
        };
        let mut ch = mm_chart(area, bx, desc, f.z_s)?;
        let xr = ch.x_range();
        // lab-fixed ticks on the plate every millimetre: the foot walks past them
        let ticks = (xr.start.ceil() as i64..=xr.end.floor() as i64).map(|k| {
            let depth = if k % 5 == 0 { 0.6 } else { 0.3 };
            let x = k as f64;
            PathElement::new(vec![(x, f.z_s), (x, f.z_s - depth)], BLACK.stroke_width(1))
        });
        ch.draw_series(ticks).map_err(e)?;
        ch.draw_series([PathElement::new(
            pose.track.clone(),
            BLACK.mix(0.5).stroke_width(2),
        )])
        .map_err(e)?;
        let col = color(STICKS[i].1);
        let far = (2.0 * pose.p.0 - pose.c.0, 2.0 * pose.p.1 - pose.c.1);
        ch.draw_series([PathElement::new(vec![pose.c, far], col.stroke_width(4))])
            .map_err(e)?;
        ch.draw_series([Circle::new(pose.c, 5, BLACK.filled())])
            .map_err(e)?;
        Ok(())
    }
}

impl Drawing for Picture<'_> {
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let f = self.0;
        let (top, body) = area.split_vertically(56);
        let head = format!("t = {:.4} s = {:.2} T", f.t_s, f.t_s / f.period_s);
        top.draw(&Text::new(head, (8, 4), font(LABEL_PX - 2.0)))
            .map_err(e)?;
        let w = top.dim_in_pixel().0 as i32;
        for (i, pose) in f.poses.iter().enumerate() {
            let (label, c) = STICKS[i];
            let txt = format!("{label}: {}", pose.mode.replace('_', " "));
            let y = 6 + 24 * i as i32;
            let col = color(c);
            let style = font(TICK_PX)
                .color(&col)
                .pos(Pos::new(HPos::Right, VPos::Top));
            top.draw(&Text::new(txt, (w - 8, y), style)).map_err(e)?;
        }
        let split = (body.dim_in_pixel().0 as f64 * 0.5) as u32;
        let (left, right) = body.split_horizontally(split);
        self.whole(&left)?;
        let half = right.dim_in_pixel().1 / 2;
        let (r0, r1) = right.split_vertically(half);
        self.closeup(&r0, 0)?;
        self.closeup(&r1, 1)
    }
}

/// Writes `dir/gait-toothpick.gif`.
pub fn write(dir: &Path) -> Result<Vec<String>> {
    let fr = frames();
    let pics: Vec<Picture> = fr.iter().map(Picture).collect();
    crate::plot::save_gif(&pics, dir, "gait-toothpick", SIZE, DELAY_MS)
}
