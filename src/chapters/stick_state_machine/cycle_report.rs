//! The section "The gait as a limit cycle" in the chapter's report: its claims (on the
//! two evidence scenes), its results (for this run's parameters) and its figure (its
//! falsification mutations are edits of `statements::CycleStatements` in `mutations.rs`).

use super::cycle_claims::{self, Scenes, Statements, WORKBOOK};
use super::evidence::Evidence;
use super::limit_cycle::{analyse, leading, spectral_radius, Analysis};
use super::poincare::moduli;
use super::round;
use crate::chapters::Context;
use crate::error::Result;
use crate::numerics::hybrid::Options;
use crate::physics::stick::StickParams;
use crate::report::{ChapterReport, Claim};
use serde_json::{json, Value};
use std::path::Path;

/// The analyses of the authors' and the self-locking scene (in that order).
pub fn scenes(ev: &Evidence) -> [Analysis; 2] {
    let v = crate::sweep::par_map(&ev.params, "stick limit cycles", analyse);
    let mut it = v.into_iter();
    [it.next().expect("two"), it.next().expect("two")]
}

/// The claims under `st` on the analyses `a` (authors', self-locking).
pub fn claims(st: &Statements, a: &[Analysis; 2]) -> Vec<Claim> {
    let sc: Scenes = [("authors", &a[0]), ("self-locking", &a[1])];
    cycle_claims::all(st, &sc)
}

/// Adds the section's claims (evidence scenes) and results (this run's `p`).
pub fn add(r: &mut ChapterReport, ev: &Evidence, p: &StickParams) {
    let a = scenes(ev);
    for c in claims(&WORKBOOK, &a) {
        r.claim(c);
    }
    r.table("stick-limit-cycle", table(&a));
    let this = if *p == ev.params[1] {
        a[1].clone()
    } else {
        analyse(p)
    };
    for (k, v) in results(&this) {
        r.result(k, v);
    }
}

/// The generated table of the section: one row per evidence scene.
pub fn table(a: &[Analysis; 2]) -> String {
    let mut t = String::from(
        "| scene | from the static start | mode at phase 0 | θ* (rad) | θ'* (rad/s) | ẋ_c* (m/s) | multipliers (saltation) | \\|λ\\|max | \\|FD - saltation\\| | gait |\n|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for (name, a) in ["authors", "self-locking"].iter().zip(a) {
        let Some((x, n, _)) = &a.fixed else {
            t.push_str(&format!(
                "| {name} | {} | no fixed point found | | | | | | | |\n",
                a.gait.label()
            ));
            continue;
        };
        let m = a.saltation.clone().unwrap_or_default();
        let shown: Vec<String> = m
            .iter()
            .map(|z| match (z.0.hypot(z.1) < 1e-9, z.1.abs() < 1e-12) {
                (true, _) => "0".to_string(),
                (false, true) => format!("{:.4}", z.0),
                (false, false) => format!(
                    "{:.4} {} {:.4}i",
                    z.0,
                    if z.1 < 0.0 { "-" } else { "+" },
                    z.1.abs()
                ),
            })
            .collect();
        let rho = spectral_radius(&m);
        let fd = a.central.last().cloned().unwrap_or_default();
        t.push_str(&format!(
            "| {name} | {} | {} (period {n}) | {:.6} | {:.6} | {:.6} | {} | {:.4} | {:.0e} | {} |\n",
            a.gait.label(),
            x.mode.name().replace('_', " "),
            x.s[0],
            x.s[1],
            x.s.get(2).copied().unwrap_or(0.0),
            shown.join(", "),
            rho,
            super::limit_cycle::max_difference(&fd, &m),
            if rho < 1.0 { "stable" } else { "unstable" }
        ));
    }
    t.push_str("\nMultipliers of P from the variational flows and saltation matrices; FD: central differences of P with step 1e-5 of each coordinate's scale (rtol 1e-12 runs).");
    t
}

/// The results of one analysis: gait type, period (of the fixed point Newton found; 0
/// when none was found, and then nothing more), fixed point and multipliers.
pub fn results(a: &Analysis) -> Vec<(&'static str, Value)> {
    let mut out = vec![("gait_type", json!(a.gait.label()))];
    let Some((x, n, _)) = &a.fixed else {
        out.push(("gait_period", json!(0))); // 0: no fixed point found
        return out;
    };
    out.push(("gait_period", json!(n)));
    let names = [
        "angle_rad",
        "angle_rate_rad_s",
        "x_c_dot_mps",
        "z_c_dot_mps",
    ];
    let mut fp = serde_json::Map::new();
    fp.insert("mode".into(), json!(x.mode.name()));
    for (k, v) in x.s.iter().enumerate() {
        let name = if x.mode == crate::physics::stick::Mode::Flight && k == 1 {
            "h_c_m"
        } else {
            names[k]
        };
        fp.insert(name.into(), json!(round(*v, 6)));
    }
    out.push(("gait_fixed_point", Value::Object(fp)));
    let (m, method) = match &a.saltation {
        Ok(m) => (m.clone(), "saltation"),
        Err(_) => (
            a.central.last().cloned().unwrap_or_default(),
            "central differences",
        ),
    };
    if m.is_empty() || m.iter().any(|z| !z.0.is_finite() || !z.1.is_finite()) {
        out.push((
            "floquet_method",
            json!("none (the perturbed runs leave the mode)"),
        ));
        return out;
    }
    // a multiplier at rounding level is the exact zero of the slip stop (shown as 0)
    let abs: Vec<f64> = moduli(&m)
        .iter()
        .map(|&v| if v < 1e-9 { 0.0 } else { round(v, 4) })
        .collect();
    out.push(("floquet_multipliers_abs", json!(abs)));
    let l = leading(&m);
    out.push(("floquet_leading", json!([round(l.0, 6), round(l.1, 6)])));
    out.push(("floquet_method", json!(method)));
    let rho = spectral_radius(&m);
    out.push(("gait_stable", json!(rho < 1.0)));
    out
}

/// The gait map figure around the self-locking scene.
pub fn figure(dir: &Path, ev: &Evidence, opts: &Options, ctx: &Context) -> Result<Vec<String>> {
    Ok(super::gait_map::draw(dir, &ev.params[1], opts, ctx.quick)?.0)
}
