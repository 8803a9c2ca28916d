//! The chapter's answers from measurements: the validity map of the massless model and
//! the toothpick (a uniform stick) on the document's plate.

use super::evidence::{scene_run, Rung};
use crate::physics::stick::{authors_scene, jamming_scene};
use crate::physics::stick_inertia::run::{InertiaOutcome, InertiaRun};
use crate::physics::stick_inertia::InertiaParams;
use crate::report::fmt_num;

/// One toothpick run: scene, spring on, outcome, mean speed (m/s), impacts per cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct Toothpick {
    /// Scene name.
    pub scene: &'static str,
    /// Chapter 6's spring and damper present.
    pub spring: bool,
    /// Outcome label.
    pub outcome: &'static str,
    /// Mean speed of C (m/s).
    pub speed_mps: f64,
    /// Impacts per drive cycle.
    pub impacts_per_cycle: f64,
    /// Simulated time (s).
    pub time_s: f64,
}

/// A uniform stick of 1 kg (m = 0, m_r = 1 kg: the document's mass, all in the rod) on
/// both scenes, with chapter 6's spring and damper and without them.
pub fn toothpicks(duration_s: f64) -> Vec<Toothpick> {
    let mut out = Vec::new();
    for (scene, mut base) in [
        ("self-locking", jamming_scene(9.81)),
        ("authors", authors_scene(10.0)),
    ] {
        base.mass_kg = 0.0;
        for spring in [true, false] {
            let mut b = base;
            if !spring {
                b.stiffness_nm_per_rad = 0.0;
                b.damping_nms_per_rad = 0.0;
            }
            let p = InertiaParams {
                base: b,
                rod_mass_kg: 1.0,
                restitution: 0.0,
            };
            let r = scene_run(&p, duration_s, 1e-10, 0.0);
            out.push(Toothpick {
                scene,
                spring,
                outcome: r.outcome.label(),
                speed_mps: r.mean_velocity_mps,
                impacts_per_cycle: r.impact_count as f64
                    / (r.end_time_s * b.frequency_hz()).max(1e-12),
                time_s: r.end_time_s,
            });
        }
    }
    out
}

/// The validity map as a Markdown table.
pub fn validity_table(ladders: &[Vec<Rung>; 2]) -> String {
    let mut s = String::from("| scene | m_r (kg) | I_P k/γ² | α | speed with inertia (m/s) | massless model (m/s) | error of the massless model |\n|---|---|---|---|---|---|---|\n");
    for (name, l) in ["self-locking", "authors"].iter().zip(ladders) {
        for r in l {
            s.push_str(&format!(
                "| {name} | {} | {} | {} | {:.5} | {:.5} | {:+.2e} |\n",
                fmt_num(r.rod_mass_kg),
                fmt_num(r.inertia_ratio),
                fmt_num(r.alpha),
                r.speed_mps,
                r.massless_mps,
                r.error()
            ));
        }
    }
    s
}

/// The toothpick runs as a Markdown table.
pub fn toothpick_table(t: &[Toothpick]) -> String {
    let mut s = String::from("| scene | spring and damper | outcome | mean speed of C (m/s) | impacts per cycle | simulated (s) |\n|---|---|---|---|---|---|\n");
    for r in t {
        s.push_str(&format!(
            "| {} | {} | {} | {:+.4} | {:.2} | {:.3} |\n",
            r.scene,
            if r.spring { "chapter 6's" } else { "none" },
            r.outcome,
            r.speed_mps,
            r.impacts_per_cycle,
            r.time_s
        ));
    }
    s
}

/// One cell of the Painleve map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapCell {
    /// Spring rest angle (rad).
    pub theta0_rad: f64,
    /// Friction coefficient (1).
    pub mu: f64,
    /// Painleve events in the run.
    pub events: usize,
    /// The run ended by a fall.
    pub fell: bool,
    /// The run ended neither completed nor fallen (invalid, Zeno, unresolved).
    pub unvouched: bool,
    /// Share of the run's time in the slide that can be Painleve (the foot slipping away
    /// from the side the rod leans to: left for theta_0 > 0) (1).
    pub prone_fraction: f64,
    /// Segments handed to Moreau-Jean, and their total time (s).
    pub bridges: (usize, f64),
}

/// Mass distributions of the map: (label, tip mass kg, rod mass kg).
pub const MAP_RODS: [(&str, f64, f64); 3] = [
    ("uniform stick (alpha = 3)", 0.0, 1.0),
    ("equal masses (alpha = 5.4)", 1.0, 1.0),
    ("1 % rod (alpha = 302)", 1.0, 0.01),
];

/// The Painleve map on the authors' plate (Gamma = 10, 30 Hz, g = 10 m/s^2): for each mass distribution, runs
/// of `duration_s` over an `n x n` grid of `(theta_0, mu)` in `[0.05, 1.0] x [0.1, 2.0]`.
pub fn painleve_map(n: usize, duration_s: f64) -> Vec<Vec<MapCell>> {
    MAP_RODS
        .iter()
        .map(|&(_, m, m_r)| {
            let mut cells = Vec::new();
            for i in 0..n {
                for j in 0..n {
                    let th0 = 0.05 + 0.95 * i as f64 / (n - 1) as f64;
                    let mu = 0.1 + 1.9 * j as f64 / (n - 1) as f64;
                    let mut b = authors_scene(10.0);
                    b.mass_kg = m;
                    b.theta0_rad = th0;
                    b.mu = mu;
                    let p = InertiaParams {
                        base: b,
                        rod_mass_kg: m_r,
                        restitution: 0.0,
                    };
                    let r = scene_run(&p, duration_s, 1e-10, 0.0);
                    cells.push(MapCell {
                        theta0_rad: th0,
                        mu,
                        events: r.painleve.len(),
                        fell: r.outcome == InertiaOutcome::Fell,
                        unvouched: !matches!(
                            r.outcome,
                            InertiaOutcome::Fell | InertiaOutcome::Completed
                        ),
                        prone_fraction: left_fraction(&r),
                        bridges: (
                            r.bridges.len(),
                            r.bridges.iter().map(|b| b.t1_s - b.t0_s).sum(),
                        ),
                    });
                }
            }
            cells
        })
        .collect()
}

/// Share of a run's time in the left slide (1).
fn left_fraction(r: &InertiaRun) -> f64 {
    let total: f64 = r.mode_time_s.iter().sum();
    r.mode_time_s[2] / total.max(f64::MIN_POSITIVE) // Mode::ALL order: flight, pivot, left, right
}

/// The gait's time in each mode on both scenes of chapter 6 (1 kg tip, 10 g rod),
/// runs of `duration_s`, as a Markdown table.
pub fn gait_modes_table(duration_s: f64) -> String {
    let mut s = String::from("| scene | mean speed of C (m/s) | flight | pivot | left slide | right slide | outcome |\n|---|---|---|---|---|---|---|\n");
    for (scene, base) in [
        ("self-locking", jamming_scene(9.81)),
        ("authors", authors_scene(10.0)),
    ] {
        let p = InertiaParams {
            base,
            rod_mass_kg: 0.01,
            restitution: 0.0,
        };
        let r = scene_run(&p, duration_s, 1e-10, 0.0);
        let total: f64 = r.mode_time_s.iter().sum::<f64>().max(f64::MIN_POSITIVE);
        let pct = |i: usize| format!("{:.1} %", 100.0 * r.mode_time_s[i] / total);
        s.push_str(&format!(
            "| {scene} | {:+.4} | {} | {} | {} | {} | {} |\n",
            r.mean_velocity_mps,
            pct(0),
            pct(1),
            pct(2),
            pct(3),
            r.outcome.label()
        ));
    }
    s
}

/// The map's runs that handed segments to Moreau-Jean: `runs (segments, total time)`,
/// or `0`.
fn bridge_summary(cells: &[MapCell]) -> String {
    let runs = cells.iter().filter(|c| c.bridges.0 > 0).count();
    if runs == 0 {
        return "0".into();
    }
    let segments: usize = cells.iter().map(|c| c.bridges.0).sum();
    let ms = 1e3 * cells.iter().map(|c| c.bridges.1).sum::<f64>();
    format!("{runs} ({segments}, {ms:.2} ms)")
}

/// The map's summary as a Markdown table.
pub fn map_table(map: &[Vec<MapCell>]) -> String {
    let mut s = String::from("| rod | runs | runs with Painlevé events | events | smallest μ with an event | time in the left slide (mean) | runs that fell | runs not vouched for | runs handed to Moreau-Jean (segments, time) |\n|---|---|---|---|---|---|---|---|---|\n");
    for ((label, ..), cells) in MAP_RODS.iter().zip(map) {
        let with: Vec<_> = cells.iter().filter(|c| c.events > 0).collect();
        let min_mu = with.iter().map(|c| c.mu).fold(f64::INFINITY, f64::min);
        let prone = cells.iter().map(|c| c.prone_fraction).sum::<f64>() / cells.len() as f64;
        s.push_str(&format!(
            "| {label} | {} | {} | {} | {} | {:.1} % | {} | {} | {} |\n",
            cells.len(),
            with.len(),
            cells.iter().map(|c| c.events).sum::<usize>(),
            if min_mu.is_finite() {
                format!("{min_mu:.3}")
            } else {
                "none".into()
            },
            100.0 * prone,
            cells.iter().filter(|c| c.fell).count(),
            cells.iter().filter(|c| c.unvouched).count(),
            bridge_summary(cells)
        ));
    }
    s
}
