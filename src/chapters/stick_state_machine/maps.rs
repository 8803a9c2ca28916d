//! The chapter's parameter maps: the stick's mean speed over (θ₀, μ) and over (Γ, f),
//! 128 x 128 cells in full mode (6 x 6 with `--quick`), each cell one hybrid run in a
//! parallel sweep ([`crate::sweep::par_map`], with its progress bar).
//!
//! A cell's speed is the late mean `(x_c(t_end) - x_c(t_skip)) / (t_end - t_skip)` over
//! whole drive cycles after a start transient ([`crate::scenes::stick::late_speed`]),
//! so that the colour shows the steady gait and not the first hop from rest.

use super::evidence::Evidence;
use crate::scenes::stick::late_speed;
use crate::chapters::Context;
use crate::error::Result;
use crate::numerics::hybrid::Options;
use crate::plot::{save_heatmap, HeatMap, Legend, Series};
use crate::sweep::{linspace, par_map};
use std::path::Path;

/// Cells per side of a map (full mode, quick mode).
const CELLS: (usize, usize) = (128, 6);

/// Draws both maps; returns the written paths.
pub fn draw(dir: &Path, ev: &Evidence, opts: &Options, ctx: &Context) -> Result<Vec<String>> {
    let mut out = theta_mu(dir, ev, opts, ctx)?;
    out.extend(gamma_f(dir, ev, opts, ctx)?);
    Ok(out)
}

fn cells(ctx: &Context) -> usize {
    if ctx.quick {
        CELLS.1
    } else {
        CELLS.0
    }
}

fn theta_mu(dir: &Path, ev: &Evidence, opts: &Options, ctx: &Context) -> Result<Vec<String>> {
    let n = cells(ctx);
    let ths = linspace(0.05, 0.9, n);
    let mus = linspace(0.1, 0.9, n);
    let base = ev.params[1];
    let items: Vec<(f64, f64)> = mus
        .iter()
        .flat_map(|&mu| ths.iter().map(move |&th| (th, mu)))
        .collect();
    let speeds = par_map(&items, "stick (θ₀, μ) map", |&(th, mu)| {
        let mut p = base;
        p.theta0_rad = th;
        p.mu = mu;
        late_speed(&p, opts, ctx.quick)
    });
    let edge: Vec<(f64, f64)> = linspace(0.05, 0.9, 200)
        .into_iter()
        .map(|t| (t, t.tan())) // formula: self-locking edge μ = tan θ₀
        .filter(|(_, m)| *m <= 0.9)
        .collect();
    let h = HeatMap::new(
        &format!(
            "Mean speed of C over (θ₀, μ), Γ = {}, f = {} Hz",
            super::round(base.gamma_accel(), 6),
            super::round(base.frequency_hz(), 6)
        ),
        "spring rest angle θ₀ (rad)",
        "friction coefficient μ",
        ths,
        mus,
        speeds.chunks(n).map(|r| r.to_vec()).collect(),
        "mean speed of C (m/s)",
    )
    .overlay(Series::dashed("", edge).color(0))
    .note(0.56, 0.80, "μ = tan θ₀")
    .note(0.56, 0.74, "(self-locking edge)")
    .legend(Legend::Hidden);
    save_heatmap(&h, dir, "speed-map")
}

fn gamma_f(dir: &Path, ev: &Evidence, opts: &Options, ctx: &Context) -> Result<Vec<String>> {
    let n = cells(ctx);
    let gammas = linspace(0.5, 12.0, n);
    let freqs = linspace(10.0, 60.0, n);
    let base = ev.params[1];
    let items: Vec<(f64, f64)> = freqs
        .iter()
        .flat_map(|&f| gammas.iter().map(move |&g| (g, f)))
        .collect();
    let speeds = par_map(&items, "stick (Γ, f) map", |&(g, f)| {
        let p = base.with_drive(g, f);
        late_speed(&p, opts, ctx.quick)
    });
    let h = HeatMap::new(
        &format!(
            "Mean speed of C over (Γ, f), θ₀ = {} rad, μ = {}",
            super::round(base.theta0_rad, 6),
            super::round(base.mu, 6)
        ),
        "peak plate acceleration Γ = δω²/g",
        "drive frequency f (Hz)",
        gammas,
        freqs,
        speeds.chunks(n).map(|r| r.to_vec()).collect(),
        "mean speed of C (m/s)",
    )
    .overlay(Series::dashed("", vec![(1.0, 10.0), (1.0, 60.0)]).color(0))
    .note(1.3, 57.0, "Γ = 1")
    .legend(Legend::Hidden);
    save_heatmap(&h, dir, "speed-map-drive")
}
