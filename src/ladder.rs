//! The work-precision ladder, one for every chapter: a method run at a sequence of
//! settings (tolerances, steps, regularisations), each run's error against a reference
//! and its cost (right-hand-side evaluations, steps, wall time), the observed order (the
//! log-log slope of error against setting, [`crate::numerics::fit::slope`]) and the
//! chart of error against cost.
//!
//! Chapters 3 and 4 climb the block's ladder of [`work_precision`]; chapter 7 climbs its
//! own settings (every method on the block and the stick, the stick by three methods)
//! with [`climb`]. Below the chapters: a chapter never imports another
//! (tests/architecture.rs).

use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::block::{BlockOptions, BlockRun};
use crate::plot::{Chart, Legend, Series};
use std::time::Instant;

/// What one run of a method reports.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Run {
    /// The observable (in the problem's unit, m/s for every ladder of the workbook).
    pub value: f64,
    /// Right-hand-side (force) evaluations.
    pub rhs_evals: u64,
    /// Steps, as the model counts them (trajectory segments, contact steps, hops).
    pub steps: u64,
    /// Did the run reach its end with a finite result?
    pub completed: bool,
}

/// The cost of one rung.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cost {
    /// Right-hand-side evaluations.
    pub rhs_evals: u64,
    /// Steps, as the model counts them.
    pub steps: u64,
    /// Wall time (s), by the ladder's [`Timing`]: machine-dependent, for figures under
    /// `wall-time/` and results only, never for a table or a claim.
    pub wall_s: f64,
}

/// How the wall time of a rung is taken from its repeats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Timing {
    /// The minimum of this many runs.
    MinOf(u32),
    /// The median of this many runs.
    MedianOf(u32),
}

/// One rung: the setting, the run's observable, its error and its cost.
#[derive(Debug, Clone, PartialEq)]
pub struct Rung<S> {
    /// The setting (a tolerance, a step, a method and its knob).
    pub setting: S,
    /// The observable of the last repeat.
    pub value: f64,
    /// Its error, by the ladder's error measure (NaN when the run failed).
    pub error: f64,
    /// Its cost.
    pub cost: Cost,
    /// Did the run complete?
    pub completed: bool,
}

/// Runs `run` at every setting (each `timing` times; sequential on purpose: wall times
/// of parallel runs would measure the contention) and measures `error` of the last run.
pub fn climb<S: Clone>(
    settings: impl IntoIterator<Item = S>,
    timing: Timing,
    error: impl Fn(&Run) -> f64,
    mut run: impl FnMut(&S) -> Run,
) -> Vec<Rung<S>> {
    settings
        .into_iter()
        .map(|setting| {
            let (m, wall_s) = timed(timing, || run(&setting));
            Rung {
                error: error(&m),
                value: m.value,
                cost: Cost {
                    rhs_evals: m.rhs_evals,
                    steps: m.steps,
                    wall_s,
                },
                completed: m.completed,
                setting,
            }
        })
        .collect()
}

/// Runs `f` as `timing` says; returns its (last) result and the wall time (s).
pub fn timed<R>(timing: Timing, mut f: impl FnMut() -> R) -> (R, f64) {
    let n = match timing {
        Timing::MinOf(n) | Timing::MedianOf(n) => n.max(1),
    };
    let mut walls = Vec::with_capacity(n as usize);
    let mut out = None;
    for _ in 0..n {
        let start = Instant::now();
        out = Some(f());
        walls.push(start.elapsed().as_secs_f64());
    }
    walls.sort_by(f64::total_cmp);
    let wall = match timing {
        Timing::MinOf(_) => walls[0],
        Timing::MedianOf(_) => walls[walls.len() / 2],
    };
    (out.expect("at least one run"), wall)
}

/// The relative error `|v - v_ref| / |v_ref|` of a completed run, NaN otherwise.
pub fn relative_to(reference: f64) -> impl Fn(&Run) -> f64 {
    move |r| {
        if r.completed {
            ((r.value - reference) / reference).abs() // formula: |v - v_ref| / |v_ref|
        } else {
            f64::NAN
        }
    }
}

/// The observed order: the least-squares slope of ln(error) against ln(knob) over the
/// rungs that `keep` selects and whose error is finite and positive.
pub fn observed_order<'a, S: 'a>(
    rungs: impl IntoIterator<Item = &'a Rung<S>>,
    knob: impl Fn(&S) -> f64,
    keep: impl Fn(&Rung<S>) -> bool,
) -> f64 {
    let pts: Vec<(f64, f64)> = rungs
        .into_iter()
        .filter(|r| keep(r) && r.error.is_finite() && r.error > 0.0)
        .map(|r| (knob(&r.setting).ln(), r.error.ln()))
        .collect();
    crate::numerics::fit::slope(&pts) // formula: order = cov(ln knob, ln err) / var(ln knob)
}

/// The cost a chart puts on its x axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CostAxis {
    /// Right-hand-side evaluations.
    RhsEvals,
    /// Wall time (s).
    Wall,
}

impl CostAxis {
    /// The cost of `c` on this axis.
    pub fn of(self, c: &Cost) -> f64 {
        match self {
            CostAxis::RhsEvals => c.rhs_evals as f64,
            CostAxis::Wall => c.wall_s,
        }
    }
}

/// The points `(cost, error)` of `rungs` that a log-log chart can draw (finite error,
/// positive cost), errors below `floor` drawn at it, in the rungs' order.
pub fn points<'a, S: 'a>(
    rungs: impl IntoIterator<Item = &'a Rung<S>>,
    axis: CostAxis,
    floor: f64,
) -> Vec<(f64, f64)> {
    rungs
        .into_iter()
        .filter(|r| r.error.is_finite() && axis.of(&r.cost) > 0.0)
        .map(|r| (axis.of(&r.cost), r.error.max(floor)))
        .collect()
}

/// How a method's curve is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Draw {
    /// One series: a line with a marker on every point.
    LinePoints,
    /// A line, then its markers as a second series (out of the legend).
    LineAndMarkers,
    /// A dashed line, then its markers.
    DashedAndMarkers,
    /// A line only.
    Line,
    /// Markers only.
    Points,
}

/// One method's curve on a work-precision chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// Legend label.
    pub label: String,
    /// Palette colour (`None`: the next in order).
    pub color: Option<usize>,
    /// How it is drawn.
    pub draw: Draw,
    /// The points `(cost, error)` ([`points`]).
    pub points: Vec<(f64, f64)>,
}

impl Curve {
    /// A curve of `points` labelled `label`, drawn as `draw`.
    pub fn new(label: &str, draw: Draw, points: Vec<(f64, f64)>) -> Self {
        Curve {
            label: label.to_string(),
            color: None,
            draw,
            points,
        }
    }

    /// In palette colour `i`.
    pub fn color(mut self, i: usize) -> Self {
        self.color = Some(i);
        self
    }
}

/// The log-log chart of error against cost: one curve per method, in order; a curve
/// without points is left out.
pub fn chart(title: &str, x_label: &str, y_label: &str, curves: Vec<Curve>) -> Chart {
    let mut c = Chart::new(title, x_label, y_label).log_x().log_y();
    for curve in curves.into_iter().filter(|c| !c.points.is_empty()) {
        let paint = |s: Series| match curve.color {
            Some(i) => s.color(i),
            None => s,
        };
        let (label, pts) = (curve.label.as_str(), curve.points.clone());
        c = match curve.draw {
            Draw::LinePoints => c.series(paint(Series::line_points(label, pts))),
            Draw::Line => c.series(paint(Series::line(label, pts))),
            Draw::Points => c.series(paint(Series::points(label, pts))),
            Draw::LineAndMarkers => c
                .series(paint(Series::line(label, pts.clone())))
                .series(paint(Series::points("", pts))),
            Draw::DashedAndMarkers => c
                .series(paint(Series::dashed(label, pts.clone())))
                .series(paint(Series::points("", pts))),
        };
    }
    c
}

// ---- the block's ladder of chapters 3 and 4 ----

/// A setting of the block's ladder: the method family (`closed-form`, `dopri5`,
/// `rk4-fixed`), its knob (the tolerance or the steps per period) and the model's options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlockSetting {
    /// Method family: `closed-form`, `dopri5`, `rk4-fixed`.
    pub method: &'static str,
    /// Setting: the tolerance or the steps per period (0 for the closed forms).
    pub setting: f64,
    /// The block model's options.
    pub opts: BlockOptions,
}

/// One point of the block's work-precision chart (the error of the mean drift over a
/// scale, the cost in rhs evaluations, trajectory segments and the median of three wall
/// times).
pub type WorkPoint = Rung<BlockSetting>;

/// The block's settings: the closed forms, DP5 with event location at a ladder of
/// tolerances, RK4 at fixed steps `T/n` without event location.
fn block_settings(quick: bool) -> Vec<BlockSetting> {
    let base = BlockOptions {
        record_events: false,
        ..BlockOptions::default()
    };
    let mut out = vec![BlockSetting {
        method: "closed-form",
        setting: 0.0,
        opts: base,
    }];
    let tols: Vec<f64> = if quick {
        vec![1e-4, 1e-8]
    } else {
        (3..=12).map(|k| 10f64.powi(-k)).collect()
    };
    for tol in tols {
        let hybrid = Options {
            control: StepControl::tol(tol, tol),
            ..base.hybrid
        };
        let opts = BlockOptions {
            hybrid,
            closed_forms: false,
            samples_per_period: 16,
            ..base
        };
        out.push(BlockSetting {
            method: "dopri5",
            setting: tol,
            opts,
        });
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
        let opts = BlockOptions {
            hybrid,
            closed_forms: false,
            samples_per_period: n,
            ..base
        };
        out.push(BlockSetting {
            method: "rk4-fixed",
            setting: n as f64,
            opts,
        });
    }
    out
}

/// Runs `model` (which simulates with the given options and returns the run) at every
/// setting of the block's ladder and compares its mean velocity with `reference` (m/s):
/// the error is `|v - v_ref| / scale` (`scale` in m/s).
pub fn work_precision(
    model: &(dyn Fn(&BlockOptions) -> BlockRun + Sync),
    reference: f64,
    scale: f64,
    quick: bool,
) -> Vec<WorkPoint> {
    climb(
        block_settings(quick),
        Timing::MedianOf(3),
        |r| ((r.value - reference) / scale).abs(), // formula: |v - v_ref| / scale
        |s| {
            let run = model(&s.opts);
            Run {
                value: run.mean_velocity_mps,
                rhs_evals: run.stats.rhs_evals,
                steps: run.segments,
                completed: run.mean_velocity_mps.is_finite(),
            }
        },
    )
}

/// The Markdown table of the deterministic columns (error, evaluations, segments).
pub fn table(points: &[WorkPoint]) -> String {
    let mut s = String::from("| method | setting | relative error of the drift | rhs evaluations | segments |\n|---|---|---|---|---|\n");
    for p in points {
        let setting = match p.setting.method {
            "closed-form" => "exact phases".to_string(),
            "dopri5" => format!("rtol = atol = {:.0e}", p.setting.setting),
            _ => format!("h = T/{}", p.setting.setting),
        };
        s.push_str(&format!(
            "| {} | {} | {:.1e} | {} | {} |\n",
            p.setting.method, setting, p.error, p.cost.rhs_evals, p.cost.steps
        ));
    }
    s
}

/// Two panels: error against rhs evaluations, and against wall time.
pub fn charts(wp: &[WorkPoint], title: &str) -> [Chart; 2] {
    // errors below 1e-16 are drawn at it (log axis)
    let pts =
        |m: &str, axis: CostAxis| points(wp.iter().filter(|p| p.setting.method == m), axis, 1e-16);
    let (dp5, rk4) = ("DP5 + event location", "RK4 fixed step, no location");
    let y = "relative error of the drift";
    let evals = chart(
        &format!("{title}: error vs work"),
        "right-hand-side evaluations",
        y,
        vec![
            Curve::new(dp5, Draw::LinePoints, pts("dopri5", CostAxis::RhsEvals)),
            Curve::new(rk4, Draw::LinePoints, pts("rk4-fixed", CostAxis::RhsEvals)),
        ],
    );
    let wall = chart(
        &format!("{title}: error vs wall time"),
        "wall time (s)",
        y,
        vec![
            Curve::new(dp5, Draw::Line, pts("dopri5", CostAxis::Wall)),
            Curve::new(rk4, Draw::Line, pts("rk4-fixed", CostAxis::Wall)),
            Curve::new(
                "closed-form phases + location",
                Draw::Points,
                pts("closed-form", CostAxis::Wall),
            ),
        ],
    )
    .legend(Legend::UpperRight);
    [evals, wall]
}

impl From<&crate::scenes::measure::Measured> for Run {
    /// A scene's measured run as a rung of the ladder sees it.
    fn from(m: &crate::scenes::measure::Measured) -> Self {
        Run {
            value: m.value,
            rhs_evals: m.rhs_evals,
            steps: m.steps,
            completed: m.completed,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Explicit Euler and RK4 on y' = -y, y(0) = 1, to t = 1 at fixed steps 1/n: the
    /// error against the closed form e^-1, the cost in rhs evaluations and steps.
    fn decay_ladder(method: Method, ns: &[u32]) -> Vec<Rung<f64>> {
        let exact = (-1.0f64).exp(); // formula: y(1) = e^-1
        let settings = ns.iter().map(|&n| 1.0 / f64::from(n));
        climb(settings, Timing::MinOf(1), relative_to(exact), |&h| {
            let mut integ =
                crate::numerics::ode::Integrator::new(method, StepControl::Fixed { h_s: h });
            let mut steps = 0;
            let y = integ.integrate(&|_t: f64, y: &[f64; 1]| [-y[0]], 0.0, [1.0], 1.0, |_| {
                steps += 1
            });
            Run {
                value: y.map_or(f64::NAN, |y| y[0]),
                rhs_evals: integ.stats.rhs_evals,
                steps,
                completed: y.is_ok(),
            }
        })
    }

    #[test]
    fn the_observed_orders_are_the_methods_orders() {
        // Global error C h^p (+ O(h^(p+1))): over h = 1/16 .. 1/256 the fitted slope is
        // within 0.05 of p (Euler: the next term shifts the slope by ~h/2 <= 0.03).
        let ns = [16, 32, 64, 128, 256];
        for (method, p) in [(Method::Euler, 1.0), (Method::Rk4, 4.0)] {
            let rungs = decay_ladder(method, &ns);
            let o = observed_order(&rungs, |&h| h, |_| true);
            assert!((o - p).abs() < 0.05, "{method:?}: {o}");
            // the cost: n steps, and one (Euler) or four (RK4) evaluations per step
            let per_step = if p == 1.0 { 1 } else { 4 };
            for (r, &n) in rungs.iter().zip(&ns) {
                assert_eq!(r.cost.steps, u64::from(n));
                assert!(r.cost.rhs_evals >= per_step * u64::from(n), "{:?}", r.cost);
                assert!(r.cost.wall_s >= 0.0);
            }
        }
    }

    #[test]
    fn a_run_that_did_not_complete_has_no_error_and_no_point() {
        let err = relative_to(2.0);
        let done = Run {
            value: 3.0,
            rhs_evals: 10,
            steps: 5,
            completed: true,
        };
        assert_eq!(err(&done), 0.5);
        assert!(err(&Run {
            completed: false,
            ..done
        })
        .is_nan());
        let rungs = climb([1.0, 2.0, 3.0], Timing::MedianOf(3), err, |&x| Run {
            completed: x != 2.0,
            rhs_evals: if x == 3.0 { 0 } else { 10 },
            ..done
        });
        // the failed run (NaN) and the free one (log axis) are left out of the chart
        assert_eq!(points(&rungs, CostAxis::RhsEvals, 1e-15), vec![(10.0, 0.5)]);
        let c = chart(
            "t",
            "x",
            "y",
            vec![Curve::new("none", Draw::Line, Vec::new())],
        );
        assert!(c.series.is_empty());
    }
}
