//! Work-precision ladders: every method at a ladder of steps or tolerances, its error
//! against a reference and its cost (right-hand-side evaluations, wall time).

use super::measure::Measured;
use crate::ladder::{relative_to, Rung, Timing};
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use serde_json::{json, Value};

/// A solver configuration of the ladder.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Solver {
    /// The event-driven driver with a fixed step `h_s` (Euler, RK4).
    Fixed {
        /// The method.
        method: Method,
        /// Locate events on the dense output?
        locate: bool,
        /// Step (s).
        h_s: f64,
    },
    /// The event-driven driver with an adaptive Dormand-Prince pair (5(4) or 8(5,3)) at
    /// `rtol = atol = tol`.
    Adaptive {
        /// The pair.
        method: Method,
        /// Locate events on the dense output?
        locate: bool,
        /// Tolerance.
        tol: f64,
    },
    /// Moreau-Jean with `steps_per_period` steps per drive period.
    MoreauJean {
        /// Steps per period.
        steps_per_period: u32,
        /// The resulting step (s).
        h_s: f64,
    },
}

impl Solver {
    /// The method label of tables and JSON.
    pub fn label(&self) -> String {
        match self {
            Solver::Fixed { method, locate, .. } => format!(
                "{}-{}",
                method.name(),
                if *locate { "located" } else { "unlocated" }
            ),
            Solver::Adaptive { method, locate, .. } => format!(
                "{}-{}",
                method.name(),
                if *locate { "located" } else { "unlocated" }
            ),
            Solver::MoreauJean { .. } => "moreau-jean".to_string(),
        }
    }

    /// The step (s) or tolerance of the configuration.
    pub fn knob(&self) -> f64 {
        match self {
            Solver::Fixed { h_s, .. } | Solver::MoreauJean { h_s, .. } => *h_s,
            Solver::Adaptive { tol, .. } => *tol,
        }
    }

    /// Hybrid-driver options for the event-driven configurations; the guards are also
    /// checked at `interior_checks` points inside each step.
    pub fn options(&self, interior_checks: usize) -> Option<Options> {
        let base = Options {
            interior_checks,
            record_events: false,
            ..Options::default()
        };
        match *self {
            Solver::Fixed {
                method,
                locate,
                h_s,
            } => Some(Options {
                method,
                control: StepControl::Fixed { h_s },
                locate_events: locate,
                ..base
            }),
            Solver::Adaptive {
                method,
                locate,
                tol,
            } => Some(Options {
                method,
                control: StepControl::tol(tol, tol),
                locate_events: locate,
                ..base
            }),
            Solver::MoreauJean { .. } => None,
        }
    }
}

/// The ladder for a problem with drive period `period_s`: fixed steps of
/// `period / n` for `n` in `steps`, tolerances `tols` for DP5 (located and unlocated)
/// and DOP853 (located), Moreau-Jean at `mj_steps`.
pub fn ladder(period_s: f64, steps: &[u32], tols: &[f64], mj_steps: &[u32]) -> Vec<Solver> {
    let mut out = Vec::new();
    for method in [Method::Euler, Method::Rk4] {
        for locate in [true, false] {
            for &n in steps {
                out.push(Solver::Fixed {
                    method,
                    locate,
                    h_s: period_s / f64::from(n),
                });
            }
        }
    }
    for (method, locate) in [
        (Method::Dopri5, true),
        (Method::Dopri5, false),
        (Method::Dop853, true),
    ] {
        for &tol in tols {
            out.push(Solver::Adaptive {
                method,
                locate,
                tol,
            });
        }
    }
    for &n in mj_steps {
        out.push(Solver::MoreauJean {
            steps_per_period: n,
            h_s: period_s / f64::from(n),
        });
    }
    out
}

/// One point of a work-precision diagram: a rung of [`crate::ladder`] whose setting is
/// the solver configuration; its error is relative to the reference (NaN if the run
/// failed), its wall time the minimum over the repeats.
pub type WpPoint = Rung<Solver>;

/// The JSON row of `work_precision`: {problem, method, tolerance_or_step, error, wall_s,
/// rhs_evals}.
pub fn json(p: &WpPoint, problem: &str) -> Value {
    json!({
        "problem": problem,
        "method": p.setting.label(),
        "tolerance_or_step": p.setting.knob(),
        "error": if p.error.is_finite() { json!(p.error) } else { json!("failed") },
        "wall_s": p.cost.wall_s,
        "rhs_evals": p.cost.rhs_evals,
    })
}

/// Runs every solver of `ladder` on `run` (the minimum wall time of `repeats`) and
/// measures the relative error against `reference`.
pub fn measure(
    ladder: &[Solver],
    reference: f64,
    repeats: u32,
    run: impl Fn(&Solver) -> Measured,
) -> Vec<WpPoint> {
    crate::ladder::climb(
        ladder.iter().copied(),
        Timing::MinOf(repeats),
        relative_to(reference),
        |s| crate::ladder::Run::from(&run(s)),
    )
}

/// The cheapest point (fewest rhs evaluations) of `label` whose error is below `target`.
pub fn cheapest_below<'a>(points: &'a [WpPoint], label: &str, target: f64) -> Option<&'a WpPoint> {
    points
        .iter()
        .filter(|p| p.setting.label() == label && p.completed && p.error <= target)
        .min_by_key(|p| p.cost.rhs_evals)
}

/// The error of the run of `label` at `knob` (step or tolerance), NaN if none.
pub fn error_at(points: &[WpPoint], label: &str, knob: f64) -> f64 {
    points
        .iter()
        .find(|p| p.setting.label() == label && p.setting.knob() == knob)
        .map_or(f64::NAN, |p| p.error)
}

/// Dormand-Prince's errors `(located, unlocated)` at the tolerance `tol`.
pub fn dopri5_errors_at(points: &[WpPoint], tol: f64) -> (f64, f64) {
    (
        error_at(points, "dopri5-located", tol),
        error_at(points, "dopri5-unlocated", tol),
    )
}

/// The event-driven methods of the ladder, located and unlocated.
pub const EVENT_DRIVEN_LABELS: [&str; 7] = [
    "euler-located",
    "euler-unlocated",
    "rk4-located",
    "rk4-unlocated",
    "dopri5-located",
    "dopri5-unlocated",
    "dop853-located",
];

/// Right-hand-side evaluations of the run of `label` at `knob` (0 if none).
pub fn rhs_evals_at(points: &[WpPoint], label: &str, knob: f64) -> u64 {
    points
        .iter()
        .find(|p| p.setting.label() == label && p.setting.knob() == knob)
        .map_or(0, |p| p.cost.rhs_evals)
}

/// `{label: rhs evaluations of the cheapest run within target, or "not reached"}`.
pub fn cheapest_json(points: &[WpPoint], labels: &[&str], target: f64) -> serde_json::Value {
    let map = labels
        .iter()
        .map(|&label| {
            let v = cheapest_below(points, label, target)
                .map_or(serde_json::json!("not reached"), |p| {
                    serde_json::json!(p.cost.rhs_evals)
                });
            (label.to_string(), v)
        })
        .collect();
    serde_json::Value::Object(map)
}

/// Least-squares slope of ln(error) against ln(step) over the completed points of
/// `label` whose error lies above the round-off floor `floor`: the observed order.
pub fn observed_order(points: &[WpPoint], label: &str, floor: f64) -> f64 {
    crate::ladder::observed_order(points, Solver::knob, |p| {
        p.setting.label() == label && p.completed && p.error > floor
    })
}

/// Formats an error coarsely for tables (two significant digits).
pub fn fmt_err(e: f64) -> String {
    if e.is_finite() {
        format!("{e:.1e}")
    } else {
        "failed".into()
    }
}
