//! Pictures of the gait: the stick drawn to scale (equal aspect) on its plate, frame by
//! frame, for the snapshot figure and the animated GIFs.
//!
//! A frame has two views. Left, the whole stick at its true lean, over a window fixed
//! in the laboratory with a ground mark at the foot's start position, so that the walk
//! shows as the foot leaving the mark. Right, a close-up of the foot magnified so that
//! the plate's sub-millimetre stroke, the hops and the slides are visible: the plate
//! (grey) with lab-fixed ticks every millimetre, the foot C, its track over the last
//! drive cycle, and the contact force of the plate on C as an arrow. The rod's colour
//! and the label give the mode; the text gives the time and x_c.

use super::run_scene;
use crate::scenes::stick::MODE_COLOUR;
use crate::error::Result;
use crate::numerics::hybrid::Options;
use crate::physics::stick::run::{Recording, Sample};
use crate::physics::stick::{Mode, StickModel, StickParams, XC, ZC};
use crate::plot::{color, font, Drawing, GRID, LABEL_PX, TICK_PX};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Colour of a mode.
pub fn mode_colour(m: Mode) -> RGBColor {
    color(MODE_COLOUR[m.index()])
}

/// Size of the GIF frames (pixels).
const GIF_SIZE: (u32, u32) = (700, 360);
/// Display time of a GIF frame (ms): 30 frames per 33 ms drive cycle play in 1.8 s.
const GIF_DELAY_MS: u32 = 60;

/// Plate grey.
const PLATE: RGBColor = RGBColor(170, 170, 170);

/// One picture of the stick at one instant (lengths in mm, forces in N).
#[derive(Debug, Clone)]
pub struct Frame {
    /// Time (s) and the drive period (s).
    pub t_s: f64,
    /// Drive period (s).
    pub period_s: f64,
    /// Mode.
    pub mode: Mode,
    /// Foot C (mm).
    pub c: (f64, f64),
    /// Tip P (mm).
    pub p: (f64, f64),
    /// Plate height (mm).
    pub z_s: f64,
    /// Force of the plate on C (N), zero in flight.
    pub f: (f64, f64),
    /// C's track over the last drive cycle (mm).
    pub track: Vec<(f64, f64)>,
}

/// The fixed windows of a sequence of frames: the whole-stick view's x range (mm), the
/// z range (mm), the close-up's half-width (mm) and the force scale (mm per N, close-up).
#[derive(Debug, Clone, Copy)]
pub struct View {
    /// Whole-stick view: x from, x to (mm); z from, z to (mm).
    pub whole: (f64, f64, f64, f64),
    /// Close-up: half-width and half-height around C (mm).
    pub half: (f64, f64),
    /// Force arrow length per newton in the close-up (mm/N).
    pub mm_per_n: f64,
    /// Mass times g (N): the reference arrow.
    pub weight_n: f64,
}

/// The frames of `p` from `t0` (s) over `cycles` drive cycles, `per_cycle` frames each,
/// with the run started from rest at t = 0 (x_c measured from its value at `t0`).
pub fn frames(
    p: &StickParams,
    opts: &Options,
    t0_cycles: f64,
    cycles: f64,
    per_cycle: usize,
) -> Vec<Frame> {
    let t = p.period_s();
    let n_track = 48usize;
    let rec = Recording {
        sequence_cap: 0,
        trace_dt_s: t / (per_cycle * n_track.div_ceil(per_cycle)) as f64,
        check_invariants: false,
        grid_only: false,
        list_cap: None,
    };
    let run = run_scene(p, (t0_cycles + cycles) * t, opts, rec);
    let m = StickModel::new(*p);
    let tr = &run.trace;
    let x0 = tr
        .iter()
        .find(|s| s.t_s >= t0_cycles * t * (1.0 - 1e-12))
        .map(|s| s.y[XC])
        .unwrap_or(0.0);
    let nframes = (cycles * per_cycle as f64).round() as usize;
    let mut out = Vec::with_capacity(nframes);
    for k in 0..nframes {
        let tk = (t0_cycles + k as f64 / per_cycle as f64) * t;
        let Some(s) = nearest(tr, tk) else { continue };
        let mm = |v: f64| v * 1e3;
        let [xp, zp, _, _] = m.tip(&s.y);
        let f = m
            .contact_eval(s.mode, s.t_s, &s.y)
            .map(|e| (e.fx, e.fz))
            .unwrap_or((0.0, 0.0));
        let track = tr
            .iter()
            .filter(|q| q.t_s <= s.t_s && q.t_s >= s.t_s - t)
            .map(|q| (mm(q.y[XC] - x0), mm(q.y[ZC])))
            .collect();
        out.push(Frame {
            t_s: s.t_s,
            period_s: t,
            mode: s.mode,
            c: (mm(s.y[XC] - x0), mm(s.y[ZC])),
            p: (mm(xp - x0), mm(zp)),
            z_s: mm(m.plate(s.t_s).0),
            f,
            track,
        });
    }
    out
}

/// The trace sample nearest to `t` (s).
fn nearest(tr: &[Sample], t: f64) -> Option<&Sample> {
    tr.iter()
        .min_by(|a, b| (a.t_s - t).abs().total_cmp(&(b.t_s - t).abs()))
}

/// The fixed view of a sequence of frames of a stick of length `l_mm` and weight
/// `weight_n` (N).
pub fn view(frames: &[Frame], l_mm: f64, weight_n: f64) -> View {
    let xs = frames.iter().flat_map(|f| [f.c.0, f.p.0]);
    let (lo, hi) = xs.fold((0.0f64, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
    let pad = 0.15 * l_mm;
    let dz = frames
        .iter()
        .flat_map(|f| f.track.iter().map(|q| q.1).chain([f.z_s]))
        .fold(0.0f64, |a, z| a.max(z.abs()));
    let half_h = (2.5 * dz).max(1.0);
    View {
        whole: (lo - pad, hi + pad, -0.12 * l_mm, 1.08 * l_mm),
        half: (1.6 * half_h, half_h),
        mm_per_n: 0.8 * half_h / weight_n.max(1e-9),
        weight_n,
    }
}

/// A frame drawn in its view.
pub struct Picture<'a> {
    /// The frame.
    pub frame: &'a Frame,
    /// The view.
    pub view: View,
    /// Scene name for the heading.
    pub scene: &'a str,
}

type Ctx<'b, DB> = ChartContext<
    'b,
    DB,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// A chart on `area` with equal scales on both axes: the box `(x0, x1, z0, z1)` (mm)
/// widened along one axis to the area's aspect ratio, centred.
fn equal_aspect<'b, DB: DrawingBackend>(
    area: &'b DrawingArea<DB, Shift>,
    bx: (f64, f64, f64, f64),
    label_px: (u32, u32),
) -> std::result::Result<Ctx<'b, DB>, String> {
    let (w, h) = area.dim_in_pixel();
    let pw = (w as f64 - 16.0 - label_px.1 as f64).max(1.0);
    let ph = (h as f64 - 16.0 - label_px.0 as f64).max(1.0);
    let (x0, x1, z0, z1) = bx;
    let s = ((x1 - x0) / pw).max((z1 - z0) / ph); // formula: mm per pixel, the larger of the two
    let (cx, cz) = (0.5 * (x0 + x1), 0.5 * (z0 + z1));
    let (hx, hz) = (0.5 * s * pw, 0.5 * s * ph);
    ChartBuilder::on(area)
        .margin(8)
        .x_label_area_size(label_px.0)
        .y_label_area_size(label_px.1)
        .build_cartesian_2d(cx - hx..cx + hx, cz - hz..cz + hz)
        .map_err(|e| e.to_string())
}

/// An [`equal_aspect`] view in millimetres with its grid, `labels` ticks on (x, z), the x
/// axis named `x_desc`, and the plate drawn up to `z_s` (mm).
fn mm_view<'b, DB: DrawingBackend>(
    area: &'b DrawingArea<DB, Shift>,
    bx: (f64, f64, f64, f64),
    labels: (usize, usize),
    x_desc: &str,
    z_s: f64,
) -> std::result::Result<Ctx<'b, DB>, String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let mut ch = equal_aspect(area, bx, (36, 62))?;
    let (xr, zr) = (ch.x_range(), ch.y_range());
    ch.configure_mesh()
        .bold_line_style(GRID.stroke_width(1))
        .light_line_style(TRANSPARENT)
        .x_labels(labels.0)
        .y_labels(labels.1)
        .x_label_formatter(&|v| format!("{v:.0}"))
        .y_label_formatter(&|v| format!("{v:.0}"))
        .label_style(font(TICK_PX))
        .x_desc(x_desc)
        .y_desc("z (mm)")
        .axis_desc_style(font(TICK_PX))
        .draw()
        .map_err(e)?;
    let plate = Rectangle::new([(xr.start, zr.start), (xr.end, z_s)], PLATE.filled());
    ch.draw_series([plate]).map_err(e)?;
    Ok(ch)
}

impl Picture<'_> {
    fn whole<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let (f, v) = (self.frame, self.view);
        let mut ch = mm_view(area, v.whole, (5, 6), "x (mm)", f.z_s)?;
        let (xr, zr) = (ch.x_range(), ch.y_range());
        // the ground mark: where C stood at the first frame, fixed in the laboratory
        let mark = Polygon::new(
            vec![(0.0, f.z_s), (-3.0, zr.start), (3.0, zr.start)],
            BLACK.filled(),
        );
        ch.draw_series([mark]).map_err(e)?;
        let col = mode_colour(f.mode);
        ch.draw_series([PathElement::new(vec![f.c, f.p], col.stroke_width(4))])
            .map_err(e)?;
        ch.draw_series([
            Circle::new(f.p, 9, col.filled()),
            Circle::new(f.c, 4, BLACK.filled()),
        ])
        .map_err(e)?;
        let txt = format!("x_c = {:+.1} mm", f.c.0);
        ch.draw_series([Text::new(
            txt,
            (xr.start + 0.02 * (xr.end - xr.start), zr.end),
            font(TICK_PX).pos(Pos::new(HPos::Left, VPos::Top)),
        )])
        .map_err(e)?;
        Ok(())
    }

    fn closeup<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let (f, v) = (self.frame, self.view);
        let bx = (f.c.0 - v.half.0, f.c.0 + v.half.0, -v.half.1, v.half.1);
        let mut ch = mm_view(area, bx, (4, 5), "foot close-up, x (mm)", f.z_s)?;
        let (xr, zr) = (ch.x_range(), ch.y_range());
        // lab-fixed ticks on the plate every millimetre: the foot walks past them
        let ticks = (xr.start.ceil() as i64..=xr.end.floor() as i64).map(|k| {
            let x = k as f64;
            let depth = if k % 5 == 0 { 0.3 } else { 0.15 } * v.half.1;
            PathElement::new(vec![(x, f.z_s), (x, f.z_s - depth)], BLACK.stroke_width(1))
        });
        ch.draw_series(ticks).map_err(e)?;
        ch.draw_series([PathElement::new(
            f.track.clone(),
            BLACK.mix(0.6).stroke_width(2),
        )])
        .map_err(e)?;
        let col = mode_colour(f.mode);
        // the rod leaves the close-up along its direction
        let dir = (f.p.0 - f.c.0, f.p.1 - f.c.1);
        let far = (f.c.0 + dir.0, f.c.1 + dir.1);
        ch.draw_series([PathElement::new(vec![f.c, far], col.stroke_width(4))])
            .map_err(e)?;
        ch.draw_series([Circle::new(f.c, 6, BLACK.filled())])
            .map_err(e)?;
        if f.f.0 != 0.0 || f.f.1 != 0.0 {
            let tip = (f.c.0 + v.mm_per_n * f.f.0, f.c.1 + v.mm_per_n * f.f.1); // formula: arrow = F x scale
            arrow(&mut ch, f.c, tip, RGBColor(0, 0, 0))?;
        }
        let note = format!(
            "force on C: m g = {:.1} N ↦ {:.2} mm",
            v.weight_n,
            v.mm_per_n * v.weight_n
        );
        ch.draw_series([Text::new(
            note,
            (xr.start + 0.02 * (xr.end - xr.start), zr.end),
            font(TICK_PX).pos(Pos::new(HPos::Left, VPos::Top)),
        )])
        .map_err(e)?;
        Ok(())
    }
}

use plotters::style::text_anchor::{HPos, Pos, VPos};

/// An arrow from `a` to `b` (data units) with a head of 12 pixels.
fn arrow<DB: DrawingBackend>(
    ch: &mut Ctx<'_, DB>,
    a: (f64, f64),
    b: (f64, f64),
    col: RGBColor,
) -> std::result::Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let (pa, pb) = (ch.backend_coord(&a), ch.backend_coord(&b));
    let (dx, dy) = ((pb.0 - pa.0) as f64, (pb.1 - pa.1) as f64);
    let len = dx.hypot(dy);
    ch.draw_series([PathElement::new(vec![a, b], col.stroke_width(3))])
        .map_err(e)?;
    if len < 4.0 {
        return Ok(());
    }
    let (ux, uy) = (dx / len, dy / len);
    let head = |side: f64| {
        let (hx, hy) = (-12.0 * ux + side * 6.0 * uy, -12.0 * uy - side * 6.0 * ux);
        (hx.round() as i32, hy.round() as i32)
    };
    let tri = EmptyElement::at(b) + Polygon::new(vec![(0, 0), head(1.0), head(-1.0)], col.filled());
    ch.plotting_area().draw(&tri).map_err(e)
}

impl Drawing for Picture<'_> {
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
        let f = self.frame;
        let (top, body) = area.split_vertically(34);
        let col = mode_colour(f.mode);
        let head = format!(
            "{}   t = {:.4} s = {:.2} T",
            self.scene,
            f.t_s,
            f.t_s / f.period_s
        );
        top.draw(&Text::new(head, (10, 8), font(LABEL_PX)))
            .map_err(e)?;
        let w = top.dim_in_pixel().0 as i32;
        let mode = Text::new(
            f.mode.name().replace('_', " "),
            (w - 10, 8),
            font(LABEL_PX)
                .color(&col)
                .pos(Pos::new(HPos::Right, VPos::Top)),
        );
        top.draw(&mode).map_err(e)?;
        let split = (body.dim_in_pixel().0 as f64 * 0.5) as u32;
        let (left, right) = body.split_horizontally(split);
        self.whole(&left)?;
        self.closeup(&right)
    }
}

/// Writes `dir/name.gif`: the frames of `p` over `cycles` drive cycles after a start
/// transient, `per_cycle` frames per cycle, shown [`GIF_DELAY_MS`] each.
pub fn write_gif(
    dir: &Path,
    name: &str,
    scene: &str,
    p: &StickParams,
    opts: &Options,
    (cycles, per_cycle): (f64, usize),
) -> Result<Vec<String>> {
    let fr = frames(p, opts, 10.0, cycles, per_cycle);
    let v = view(&fr, p.length_m * 1e3, p.mass_kg * p.g_mps2);
    let pics: Vec<Picture> = fr
        .iter()
        .map(|frame| Picture {
            frame,
            view: v,
            scene,
        })
        .collect();
    crate::plot::save_gif(&pics, dir, name, GIF_SIZE, GIF_DELAY_MS)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::stick::jamming_scene;

    #[test]
    fn gif_bytes_are_deterministic_and_small() {
        let p = jamming_scene(9.81);
        let opts = Options::default();
        let dir = tempfile::tempdir().unwrap();
        let write = |sub: &str| {
            let paths =
                write_gif(&dir.path().join(sub), "gait", "test", &p, &opts, (0.5, 4)).unwrap();
            std::fs::read(&paths[0]).unwrap()
        };
        let (a, b) = (write("a"), write("b"));
        assert_eq!(&a[..6], b"GIF89a");
        assert_eq!(a, b, "two renders of the same frames differ");
        // two frames of 640 x 350: well under 100 KB each when the palette works
        assert!(a.len() > 2_000 && a.len() < 200_000, "{} bytes", a.len());
    }

    #[test]
    fn frames_are_a_quarter_period_apart_and_the_stick_walks() {
        let p = jamming_scene(9.81);
        let fr = frames(&p, &Options::default(), 2.0, 2.0, 4);
        assert_eq!(fr.len(), 8);
        let t = p.period_s();
        for (k, f) in fr.iter().enumerate() {
            // the trace samples at multiples of T/48 exactly (up to rounding of the sum)
            assert!(
                (f.t_s - (2.0 + k as f64 / 4.0) * t).abs() < 1e-9 * t,
                "frame {k}"
            );
            assert!(!f.track.is_empty());
        }
        // x_c is measured from the first frame; the self-locking scene walks to +x
        assert_eq!(fr[0].c.0, 0.0);
        assert!(fr[7].c.0 > 1.0, "x_c after 7/4 cycles: {} mm", fr[7].c.0);
    }
}
