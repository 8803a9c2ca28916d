//! The stick's runs of the chapter: the work-precision ladder of its mean speed, its
//! reference check, DOP853 against DP5 and the simulator's speed in drive cycles per
//! second, gathered once into [`StickEvidence`]; the claims on them are in `claims.rs`.

use super::budget::{rounding_mps, Scales};
use super::measure::{stick_speed, Measured};
use super::work_precision::{ladder, measure, rhs_evals_at, Solver, WpPoint};
use crate::ladder::{timed, Timing};
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::stick::{authors_scene, StickModel};

/// g of the authors' scene in their code (m/s^2): the scene of the DOP853 claim.
pub const AUTHORS_G_MPS2: f64 = 10.0;

/// The stick's evidence.
#[derive(Debug, Clone, PartialEq)]
pub struct StickEvidence {
    /// The reference: DP5 at 1e-13 with located events (m/s).
    pub reference_mps: f64,
    /// DP5's mean speed at 1e-11 and 1e-12 (m/s).
    pub dopri5_11_12: (f64, f64),
    /// The rounding budgets R (m/s, `budget.rs`) of the runs at 1e-11, 1e-12 and 1e-13.
    pub rounding_11_12_13_mps: [f64; 3],
    /// The scales of the rounding budget of a run of the ladder (`budget.rs`).
    pub scales: Scales,
    /// Events of the reference run (every located run of the ladder handles as many).
    pub reference_events: u64,
    /// The ladder.
    pub points: Vec<WpPoint>,
    /// Why each run of the ladder that did not complete broke down: (index, reason).
    pub broken: Vec<(usize, String)>,
    /// Fixed steps per period of the ladder.
    pub steps: Vec<u32>,
    /// Tolerances of the ladder.
    pub tols: Vec<f64>,
    /// Drive period (s).
    pub period_s: f64,
    /// Drive cycles per run.
    pub cycles: f64,
    /// On the authors' scene at g = 10 m/s^2, rtol = atol = 1e-10: the relative errors of
    /// DP5 and DOP853 and their right-hand-side evaluations.
    pub dop853_vs_dopri5: ((f64, f64), (u64, u64)),
    /// Drive cycles per second of wall time at rtol 1e-10, DOP853 and DP5 (NaN for a run
    /// that did not complete).
    pub cycles_per_second: (f64, f64),
}

/// Runs the stick ladder on the authors' scene (section 4; g = `g_mps2`) over 10
/// (`quick`) or 50 drive periods.
pub fn gather(g_mps2: f64, quick: bool) -> StickEvidence {
    let model = StickModel::new(authors_scene(g_mps2));
    let period_s = model.period_s;
    let cycles = if quick { 10.0 } else { 50.0 };
    let speed = |opts: &Options| stick_speed(&model, cycles, opts);
    let dp = |tol: f64| {
        let opts = Options {
            control: StepControl::tol(tol, tol),
            ..Options::default()
        };
        speed(&opts).0
    };
    let runs = [dp(1e-11), dp(1e-12), dp(1e-13)];
    let reference_mps = runs[2].value;
    let dopri5_11_12 = (runs[0].value, runs[1].value);
    let plate = &model.p.plate;
    let v_p_mps = plate.amplitude_m * plate.omega_rad_s; // formula: v_p = delta omega
    let t_end_s = cycles * period_s;
    let scales = Scales::new(v_p_mps, reference_mps, t_end_s, t_end_s, period_s);
    let rounding_11_12_13_mps = runs.map(|m| rounding_mps(&m, &scales));
    let (steps, tols): (Vec<u32>, Vec<f64>) = if quick {
        (vec![32, 128, 512], vec![1e-4, 1e-7, 1e-10])
    } else {
        (
            vec![32, 64, 128, 256, 512, 1024, 2048],
            (3..=12).map(|k| 10f64.powi(-k)).collect(),
        )
    };
    let solvers = ladder(period_s, &steps, &tols, &[]);
    let repeats = if quick { 1 } else { 3 };
    let points = measure(&solvers, reference_mps, repeats, |s| {
        speed(&s.options(0).expect("hybrid")).0
    });
    let broken = points
        .iter()
        .enumerate()
        .filter(|(_, p)| !p.completed)
        .map(|(i, p)| {
            let why = speed(&p.setting.options(0).expect("hybrid")).1;
            (i, why.unwrap_or_else(|| "did not complete".into()))
        })
        .collect();
    // The DOP853 claim is pinned to one scene, the authors' at g = 10 m/s^2 (the
    // chapter's default), whatever --g-mps2: its own three runs when the flag moves g.
    let dop853_vs_dopri5 = if g_mps2 == AUTHORS_G_MPS2 {
        let err_of = |label: &str| super::work_precision::error_at(&points, label, 1e-10);
        (
            (err_of("dopri5-located"), err_of("dop853-located")),
            (
                rhs_evals_at(&points, "dopri5-located", 1e-10),
                rhs_evals_at(&points, "dop853-located", 1e-10),
            ),
        )
    } else {
        dop853_against_dopri5(cycles)
    };
    StickEvidence {
        reference_mps,
        dopri5_11_12,
        rounding_11_12_13_mps,
        scales,
        reference_events: runs[2].events,
        points,
        broken,
        steps,
        tols,
        period_s,
        cycles,
        dop853_vs_dopri5,
        cycles_per_second: (
            cycles_per_second(&model, cycles, Method::Dop853, quick),
            cycles_per_second(&model, cycles, Method::Dopri5, quick),
        ),
    }
}

/// The simulator's speed: drive cycles per second of wall time with `method` at rtol
/// 1e-10 (minimum of 1 run in `quick` mode, else 5), NaN if the run did not complete.
fn cycles_per_second(model: &StickModel, cycles: f64, method: Method, quick: bool) -> f64 {
    let opts = Options {
        method,
        ..Options::default()
    };
    let repeats = Timing::MinOf(if quick { 1 } else { 5 });
    let (run, wall) = timed(repeats, || stick_speed(model, cycles, &opts).0);
    if run.completed {
        cycles / wall
    } else {
        f64::NAN
    }
}

/// The step or the tolerance of `s` as the failures table names it.
pub fn knob_text(s: &Solver, period: f64) -> String {
    match s {
        Solver::Adaptive { tol, .. } => format!("tol = {tol:e}"),
        other => format!("h = T/{}", (period / other.knob()).round()),
    }
}

/// On the authors' scene at g = 10 m/s^2: the relative errors of DP5 and DOP853 at
/// rtol = atol = 1e-10 against DP5 at 1e-13, and their right-hand-side evaluations.
fn dop853_against_dopri5(cycles: f64) -> ((f64, f64), (u64, u64)) {
    let model = StickModel::new(authors_scene(AUTHORS_G_MPS2));
    let run = |method: Method, tol: f64| -> Measured {
        let opts = Options {
            method,
            control: StepControl::tol(tol, tol),
            ..Options::default()
        };
        stick_speed(&model, cycles, &opts).0
    };
    let reference = run(Method::Dopri5, 1e-13).value;
    let (d5, d8) = (run(Method::Dopri5, 1e-10), run(Method::Dop853, 1e-10));
    let rel = |v: f64| ((v - reference) / reference).abs();
    ((rel(d5.value), rel(d8.value)), (d5.rhs_evals, d8.rhs_evals))
}
