//! The chapter's figures (drawn only when figures are on; the results never depend on
//! them). Sweeps run in parallel with `sweep::par_map` and are summed in order.

use super::evidence::Evidence;
use super::{gait, run_scene};
use crate::chapters::Context;
use crate::error::Result;
use crate::numerics::hybrid::Options;
use crate::physics::stick::run::{Recording, RunSummary, Sample, StickOutcome};
use crate::physics::stick::{
    StickModel, StickParams, D_DAMP, D_FRIC, D_IMPACT, TH, W_PLATE, XC, ZC,
};
use crate::plot::{save_drawing, save_panels, Chart, Drawing, Series};
use crate::sweep::{linspace, par_map};
use std::path::Path;

/// Draws every figure; returns the written paths.
pub fn draw_all(
    dir: &Path,
    p: &StickParams,
    _main: &RunSummary,
    ev: &Evidence,
    ctx: &Context,
    opts: &Options,
) -> Result<Vec<String>> {
    let mut out = Vec::new();
    let t = p.period_s();
    // a traced run of 14 cycles; show cycles 10 to 14 (past the start transient)
    let traced = run_scene(
        p,
        14.0 * t,
        opts,
        Recording {
            sequence_cap: 0,
            trace_dt_s: t / 200.0,
            check_invariants: false,
            grid_only: false,
            list_cap: None,
        },
    );
    let window: Vec<&Sample> = traced.trace.iter().filter(|s| s.t_s >= 10.0 * t).collect();
    out.extend(time_series(dir, p, &window)?);
    out.extend(snapshots(dir, p, opts)?);
    out.extend(gifs(dir, ev, opts, ctx)?);
    out.extend(energy(dir, p, opts)?);
    out.extend(speed_sweeps(dir, ev, opts, ctx)?);
    out.extend(super::maps::draw(dir, ev, opts, ctx)?);
    Ok(out)
}

/// Shades the phases of `samples` on `c`, one colour per mode (band colours cycle with
/// the band index: pad with empty bands so that the index modulo 5 is the mode's).
fn shade(mut c: Chart, samples: &[&Sample]) -> Chart {
    let mut labelled = [false; 4];
    let mut i = 0;
    while i < samples.len() {
        let m = samples[i].mode;
        let mut j = i;
        while j + 1 < samples.len() && samples[j + 1].mode == m {
            j += 1;
        }
        let (a, b) = (samples[i].t_s, samples[(j + 1).min(samples.len() - 1)].t_s);
        while c.bands.len() % 5 != m.index() {
            c = c.band(-1e9, -1e9, "");
        }
        let label = if labelled[m.index()] {
            String::new()
        } else {
            m.name().replace('_', " ")
        };
        labelled[m.index()] = true;
        c = c.band(a, b, &label);
        i = j + 1;
    }
    c
}

fn time_series(dir: &Path, p: &StickParams, w: &[&Sample]) -> Result<Vec<String>> {
    let m = StickModel::new(*p);
    let pts = |f: &dyn Fn(&Sample) -> f64| w.iter().map(|s| (s.t_s, f(s))).collect::<Vec<_>>();
    let mm = 1e3;
    let c1 = shade(Chart::new("Foot C and plate", "t (s)", "height (mm)"), w)
        .line("z_c (foot)", pts(&|s| s.y[ZC] * mm))
        .dashed("z_s (plate)", pts(&|s| m.plate(s.t_s).0 * mm));
    let c2 = shade(Chart::new("Tip P", "t (s)", "z_p (mm)"), w)
        .line("z_p", pts(&|s| m.tip(&s.y)[1] * mm));
    let c3 = shade(Chart::new("Angle", "t (s)", "θ (rad)"), w)
        .line("θ", pts(&|s| s.y[TH]))
        .hline(p.theta0_rad, "θ₀")
        .hline(p.mu.atan(), "arctan μ");
    let c4 = shade(Chart::new("Foot position", "t (s)", "x_c (mm)"), w)
        .line("x_c", pts(&|s| s.y[XC] * mm));
    save_panels(&[c1, c2, c3, c4], 1, dir, "time-series") // one column: 800 px wide, shown near full size in the book's ~750 px column
}

/// Four frames of the gait a quarter period apart over one drive cycle (after ten
/// cycles of start transient), each drawn to scale with the foot's close-up, in one
/// column 720 px wide: the book's ~750 px column shows it at full size (labels 16 and
/// 20 px), where two columns (1440 px) showed them at about half.
fn snapshots(dir: &Path, p: &StickParams, opts: &Options) -> Result<Vec<String>> {
    let fr = gait::frames(p, opts, 10.0, 1.0, 4);
    let v = gait::view(&fr, p.length_m * 1e3, p.mass_kg * p.g_mps2);
    let pics: Vec<gait::Picture> = fr
        .iter()
        .map(|frame| gait::Picture {
            frame,
            view: v,
            scene: "",
        })
        .collect();
    let grid = Grid {
        cells: &pics,
        cols: 1,
    };
    let rows = pics.len().max(1) as u32;
    save_drawing(&grid, dir, "snapshots", (720, rows * 400))
}

/// Drawings in a grid, `cols` per row.
struct Grid<'a, D> {
    cells: &'a [D],
    cols: usize,
}

impl<D: Drawing> Drawing for Grid<'_, D> {
    fn draw<DB: plotters::prelude::DrawingBackend>(
        &self,
        area: &plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    ) -> std::result::Result<(), String> {
        let rows = self.cells.len().div_ceil(self.cols).max(1);
        for (c, a) in self.cells.iter().zip(area.split_evenly((rows, self.cols))) {
            c.draw(&a)?;
        }
        Ok(())
    }
}

/// The animated gait of both scenes: `gait-self-locking.gif` and `gait-authors.gif`.
fn gifs(dir: &Path, ev: &Evidence, opts: &Options, ctx: &Context) -> Result<Vec<String>> {
    // 30 frames per drive cycle (issue 24: a smooth gait), two cycles, shown 60 ms
    // each: one 33 ms drive cycle lasts 1.8 s on screen (time slowed 54 times)
    let shape = if ctx.quick { (1.0, 6) } else { (2.0, 30) };
    let mut out = gait::write_gif(
        dir,
        "gait-self-locking",
        "self-locking scene",
        &ev.params[1],
        opts,
        shape,
    )?;
    out.extend(gait::write_gif(
        dir,
        "gait-authors",
        "authors' scene",
        &ev.params[0],
        opts,
        shape,
    )?);
    Ok(out)
}

fn energy(dir: &Path, p: &StickParams, opts: &Options) -> Result<Vec<String>> {
    let s = run_scene(
        p,
        2.0,
        opts,
        Recording {
            sequence_cap: 0,
            trace_dt_s: p.period_s() / 8.0,
            check_invariants: false,
            grid_only: false,
            list_cap: None,
        },
    );
    let m = StickModel::new(*p);
    let Some(first) = s.trace.first() else {
        return Ok(Vec::new());
    };
    let e0 = m.mechanical_energy(&first.y);
    let pts =
        |f: &dyn Fn(&Sample) -> f64| s.trace.iter().map(|x| (x.t_s, f(x))).collect::<Vec<_>>();
    let c = Chart::new("Energy budget (cumulative)", "t (s)", "energy (J)")
        .line("plate work W", pts(&|x| x.y[W_PLATE]))
        .line("friction", pts(&|x| x.y[D_FRIC]))
        .line("damper", pts(&|x| x.y[D_DAMP]))
        .line("impacts", pts(&|x| x.y[D_IMPACT]))
        .line(
            "change of mechanical energy ΔE",
            pts(&|x| m.mechanical_energy(&x.y) - e0),
        );
    let r = Chart::new("Budget residual W − ΔE − losses", "t (s)", "|residual| (J)")
        .line(
            "|residual|",
            pts(&|x| {
                let b = x.y[W_PLATE]
                    - (m.mechanical_energy(&x.y) - e0)
                    - x.y[D_FRIC]
                    - x.y[D_DAMP]
                    - x.y[D_IMPACT];
                b.abs().max(1e-16)
            }),
        )
        .log_y();
    save_panels(&[c, r], 1, dir, "energy-budget")
}

fn mean_speed(s: &RunSummary) -> f64 {
    if s.outcome == StickOutcome::Completed {
        s.mean_velocity_mps
    } else {
        f64::NAN
    }
}

fn speed_sweeps(dir: &Path, ev: &Evidence, opts: &Options, ctx: &Context) -> Result<Vec<String>> {
    let n = if ctx.quick { 5 } else { 23 };
    let dur = if ctx.quick { 1.0 } else { 3.0 };
    let gammas = linspace(1.0, 12.0, n);
    let freqs = linspace(10.0, 60.0, n);
    let mut items = Vec::new();
    for (si, base) in ev.params.iter().enumerate() {
        for &g in &gammas {
            items.push((si, 0usize, g, *base));
        }
        for &f in &freqs {
            items.push((si, 1usize, f, *base));
        }
    }
    let speeds = par_map(&items, "stick speed sweeps", |&(_, kind, v, b)| {
        let p = if kind == 0 {
            b.with_drive(v, b.frequency_hz())
        } else {
            b.with_drive(b.gamma_accel(), v)
        };
        mean_speed(&run_scene(&p, dur, opts, Recording::default()))
    });
    let series = |si: usize, kind: usize| -> Vec<(f64, f64)> {
        items
            .iter()
            .zip(&speeds)
            .filter(|((s, k, _, _), _)| *s == si && *k == kind)
            .map(|((_, _, v, _), &sp)| (*v, sp))
            .collect()
    };
    let names = ["authors' scene", "self-locking scene"];
    let mut cg = Chart::new(
        "Mean speed of C against Γ (f fixed)",
        "Γ = δω² / g",
        "mean velocity (m/s)",
    );
    let mut cf = Chart::new(
        "Mean speed of C against frequency (Γ fixed)",
        "f (Hz)",
        "mean velocity (m/s)",
    );
    for (si, name) in names.iter().enumerate() {
        cg = cg.series(Series::line(name, series(si, 0)).color(si));
        cf = cf.series(Series::line(name, series(si, 1)).color(si));
    }
    save_panels(&[cg, cf], 1, dir, "speed-sweeps")
}
