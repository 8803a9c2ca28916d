//! The chapter's answers from measurements: the validity map of the massless model and
//! the toothpick (a uniform stick) on the document's plate.

use super::evidence::{scene_run, Rung};
use crate::physics::stick::{authors_scene, jamming_scene};
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
