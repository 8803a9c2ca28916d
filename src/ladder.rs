//! The work-precision ladder of the block on a shaken plate: the event-driven method
//! (closed forms, and Dormand-Prince 5(4) with event location at several tolerances)
//! against a fixed-step RK4 without event location, measured on the steady drift.
//! Shared by both shaking chapters (3 and 4), so it sits below the chapters: a chapter
//! never imports another (tests/architecture.rs).

use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::block::{BlockOptions, BlockRun};
use crate::plot::{Chart, Legend};
use std::time::Instant;

/// One point of a work-precision chart.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPoint {
    /// Method family: `closed-form`, `dopri5`, `rk4-fixed`.
    pub method: &'static str,
    /// Setting: the tolerance or the steps per period.
    pub setting: f64,
    /// Relative error of the mean drift.
    pub error: f64,
    /// Right-hand-side evaluations.
    pub rhs_evals: u64,
    /// Trajectory segments (steps and closed-form pieces).
    pub segments: u64,
    /// Wall time (s), median of three runs (figures only: not deterministic).
    pub wall_s: f64,
}

/// Runs `model` (which simulates with the given options and returns the run) for
/// every method setting and compares its mean velocity with `reference` (m/s).
/// `scale` normalises the error (m/s).
pub fn work_precision(
    model: &(dyn Fn(&BlockOptions) -> BlockRun + Sync),
    reference: f64,
    scale: f64,
    quick: bool,
) -> Vec<WorkPoint> {
    let mut settings: Vec<(&'static str, f64, BlockOptions)> = Vec::new();
    let base = BlockOptions {
        record_events: false,
        ..BlockOptions::default()
    };
    settings.push(("closed-form", 0.0, base));
    let tols: &[f64] = if quick {
        &[1e-4, 1e-8]
    } else {
        &[
            1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12,
        ]
    };
    for &tol in tols {
        let hybrid = Options {
            control: StepControl::tol(tol, tol),
            ..base.hybrid
        };
        settings.push((
            "dopri5",
            tol,
            BlockOptions {
                hybrid,
                closed_forms: false,
                samples_per_period: 16,
                ..base
            },
        ));
    }
    let steps: &[usize] = if quick {
        &[64, 256]
    } else {
        &[32, 64, 128, 256, 512, 1024, 2048, 4096, 8192]
    };
    for &n in steps {
        let hybrid = Options {
            method: Method::Rk4,
            control: StepControl::Fixed { h_s: f64::INFINITY },
            locate_events: false,
            ..base.hybrid
        };
        // h = T/n: the fixed step is the model's longest step, T / samples_per_period.
        settings.push((
            "rk4-fixed",
            n as f64,
            BlockOptions {
                hybrid,
                closed_forms: false,
                samples_per_period: n,
                ..base
            },
        ));
    }
    settings
        .iter()
        .map(|(method, setting, opts)| {
            let mut walls = Vec::new();
            let mut last = None;
            for _ in 0..3 {
                let t0 = Instant::now();
                let run = model(opts);
                walls.push(t0.elapsed().as_secs_f64());
                last = Some(run);
            }
            walls.sort_by(f64::total_cmp);
            let run = last.expect("ran");
            WorkPoint {
                method,
                setting: *setting,
                error: ((run.mean_velocity_mps - reference) / scale).abs(),
                rhs_evals: run.stats.rhs_evals,
                segments: run.segments,
                wall_s: walls[1],
            }
        })
        .collect()
}

/// The Markdown table of the deterministic columns (error, evaluations, segments).
pub fn table(points: &[WorkPoint]) -> String {
    let mut s = String::from("| method | setting | relative error of the drift | rhs evaluations | segments |\n|---|---|---|---|---|\n");
    for p in points {
        let setting = match p.method {
            "closed-form" => "exact phases".to_string(),
            "dopri5" => format!("rtol = atol = {:.0e}", p.setting),
            _ => format!("h = T/{}", p.setting),
        };
        s.push_str(&format!(
            "| {} | {} | {:.1e} | {} | {} |\n",
            p.method, setting, p.error, p.rhs_evals, p.segments
        ));
    }
    s
}

/// Two panels: error against rhs evaluations, and against wall time.
pub fn charts(points: &[WorkPoint], title: &str) -> [Chart; 2] {
    let floor = 1e-16;
    let pts = |m: &str, f: &dyn Fn(&WorkPoint) -> f64| -> Vec<(f64, f64)> {
        points
            .iter()
            .filter(|p| p.method == m)
            .map(|p| (f(p), p.error.max(floor)))
            .collect()
    };
    let evals = Chart::new(
        &format!("{title}: error vs work"),
        "right-hand-side evaluations",
        "relative error of the drift",
    )
    .log_x()
    .log_y()
    .line_points(
        "DP5 + event location",
        pts("dopri5", &|p| p.rhs_evals as f64),
    )
    .line_points(
        "RK4 fixed step, no location",
        pts("rk4-fixed", &|p| p.rhs_evals as f64),
    );
    let wall = Chart::new(
        &format!("{title}: error vs wall time"),
        "wall time (s)",
        "relative error of the drift",
    )
    .log_x()
    .log_y()
    .line("DP5 + event location", pts("dopri5", &|p| p.wall_s))
    .line(
        "RK4 fixed step, no location",
        pts("rk4-fixed", &|p| p.wall_s),
    )
    .points(
        "closed-form phases + location",
        pts("closed-form", &|p| p.wall_s),
    )
    .legend(Legend::UpperRight);
    [evals, wall]
}
