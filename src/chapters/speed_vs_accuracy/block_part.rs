//! The block's runs of the chapter: the reference and its convergence study, the
//! work-precision ladder, and the failure scenes (stiffness, Zeno), gathered once into
//! [`BlockEvidence`]; the claims on them are in `claims.rs`.

use super::block_scene::BlockScene;
use super::budget::{rounding_mps, Scales, EVENT_ULPS};
use super::failures::{blows_up, stiff, zeno, StiffOutcome, ZenoOutcome};
use super::measure::{drift_block_model, drift_mj, window, Measured};
use super::setup::Setup;
use super::work_precision::{ladder, measure, Solver, WpPoint};
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};

/// The block's evidence.
#[derive(Debug, Clone, PartialEq)]
pub struct BlockEvidence {
    /// The reference: closed forms between located events.
    pub reference: Measured,
    /// Integrated Dormand-Prince's drift (m/s) at rtol = atol = 1e-10, 1e-11, 1e-12, 1e-13.
    pub dopri5: [(f64, f64); 4],
    /// The rounding budgets R (m/s) of the four Dormand-Prince runs (`budget.rs`).
    pub dopri5_rounding_mps: [f64; 4],
    /// The rounding budget R (m/s) of the reference.
    pub reference_rounding_mps: f64,
    /// The plate's peak speed v_p = Gamma g / omega (m/s).
    pub v_p_mps: f64,
    /// The rounding floor of the drift, relative (256 ulps of t per event), reported: the
    /// reference's rounding budget contains it, and the convergence study's floor is the
    /// runs' whole budget (`claims::study_floor_rel`).
    pub rounding_floor_rel: f64,
    /// `|d(1e-12) - d(1e-13)| / |d|`: the change one more decade makes.
    pub next_decade_rel: f64,
    /// The ladder on the chapter's scene.
    pub points: Vec<WpPoint>,
    /// The ladder on the default benchmark scene (the observed orders).
    pub order_points: Vec<WpPoint>,
    /// The ladder's tightest tolerance and coarsest step (s), `T / steps[0]`.
    pub tightest_tol: f64,
    /// The coarsest fixed step (s).
    pub coarse_step_s: f64,
}

impl BlockEvidence {
    /// Integrated Dormand-Prince's drift (m/s) at rtol = atol = `tol` (located events,
    /// guards at T/20): one of the reference check's runs or a rung of the ladder; NaN
    /// when neither ran at `tol`.
    pub fn dopri5_at(&self, tol: f64) -> f64 {
        self.dopri5
            .iter()
            .find(|(t, _)| *t == tol)
            .map(|(_, d)| *d)
            .or_else(|| {
                self.points
                    .iter()
                    .find(|p| p.setting.label() == "dopri5-located" && p.setting.knob() == tol)
                    .map(|p| p.value)
            })
            .unwrap_or(f64::NAN)
    }

    /// The runs at `tol` and at the next decade tol/10, each as (drift m/s, rounding
    /// budget m/s): the pair the reference check bounds DP5's error with; None when
    /// `tol` is not one of the check's first three tolerances.
    pub fn decade_pair(&self, tol: f64) -> Option<((f64, f64), (f64, f64))> {
        let i = self.dopri5[..3].iter().position(|(t, _)| *t == tol)?;
        let run = |j: usize| (self.dopri5[j].1, self.dopri5_rounding_mps[j]);
        Some((run(i), run(i + 1)))
    }
}

/// The reference, its convergence study and the ladders.
pub(super) fn gather(s: &Setup<'_>) -> BlockEvidence {
    let (args, g, win) = (s.args, s.g, s.win);
    // The workbook's block model (physics::block) with its closed forms: only the event
    // times carry numerical error (located to a few ulps).
    let reference = s.block(&Options::default(), true);
    let dp = |tol: f64| {
        let opts = Options {
            control: StepControl::tol(tol, tol),
            ..Options::default()
        };
        (tol, s.block(&opts, false))
    };
    let runs = [dp(1e-10), dp(1e-11), dp(1e-12), dp(1e-13)];
    let dopri5 = runs.map(|(t, m)| (t, m.value));
    let omega = std::f64::consts::TAU * args.frequency_hz;
    let v_p_mps = args.gamma * g / omega; // formula: v_p = Gamma g / omega
    let (t_a, t_b) = win;
    let scales = Scales::new(v_p_mps, reference.value, t_b, t_b - t_a, s.scene.period_s());
    let dopri5_rounding_mps = runs.map(|(_, m)| rounding_mps(&m, &scales));
    let reference_rounding_mps = rounding_mps(&reference, &scales);
    // The rounding floor of the drift: every event time is located to a few ulps of t
    // (a few hundred ulps covers the locator's bracketing and the closed forms' own
    // rounding), and an event-time error dt shifts the displacement by at most the jump
    // of the relative velocity, |v_block - v_plate| <= 2 v_p with v_p = Gamma g / omega,
    // times dt. Summed over the events and divided by the window, it bounds how far two
    // runs agreeing to within the rounding can differ in drift.
    let floor_abs = EVENT_ULPS * f64::EPSILON * t_b * 2.0 * args.gamma * g / omega
        * reference.events.max(1) as f64
        / (t_b - t_a); // formula: F = 256 eps t_end 2 v_p N_events / T_window
    let rounding_floor_rel = floor_abs / reference.value.abs().max(f64::MIN_POSITIVE);
    let next_decade_rel = ((dopri5[2].1 - dopri5[3].1) / reference.value).abs(); // formula: |d(1e-12) - d(1e-13)| / |d|
    let (points, order_points) = measure_ladder(s, reference.value);
    BlockEvidence {
        reference,
        dopri5,
        dopri5_rounding_mps,
        reference_rounding_mps,
        v_p_mps,
        rounding_floor_rel,
        next_decade_rel,
        points,
        order_points,
        tightest_tol: *s.plan.tols.last().expect("tolerances"),
        coarse_step_s: s.scene.period_s() / f64::from(s.plan.steps[0]),
    }
}

/// The work-precision ladder on the chapter's scene, and on the default benchmark scene
/// for the observed orders (the same points when the scenes are equal).
fn measure_ladder(s: &Setup<'_>, reference: f64) -> (Vec<WpPoint>, Vec<WpPoint>) {
    let (plan, g, scene, win) = (&s.plan, s.g, &s.scene, s.win);
    let (tr, cy) = (plan.transient, plan.cycles);
    let solvers = ladder(scene.period_s(), &plan.steps, &plan.tols, &plan.mj_steps);
    let points = measure(&solvers, reference, plan.repeats, |v| match v {
        Solver::MoreauJean {
            steps_per_period, ..
        } => drift_mj(scene, *steps_per_period, win),
        other => s.block(&other.options(0).expect("hybrid"), false),
    });
    // Observed orders: least-squares slopes of log error against log step, measured on
    // the default benchmark scene whatever the flags (the order a method shows on an
    // observable with events depends on the scene: near Gamma = 1 or at small mu the
    // events crowd and the asymptotic range starts beyond the ladder).
    let bench = BlockScene::new(30.0, 2.5, 0.4, 0.05, g);
    if bench == *scene {
        return (points.clone(), points);
    }
    let bref = drift_block_model(&bench, &Options::default(), true, 64, tr, cy).value;
    let bench_solvers = ladder(bench.period_s(), &plan.steps, &plan.tols, &plan.mj_steps);
    let order_points = measure(&bench_solvers, bref, 1, |v| match v {
        Solver::MoreauJean {
            steps_per_period, ..
        } => drift_mj(&bench, *steps_per_period, window(&bench, tr, cy)),
        other => drift_block_model(
            &bench,
            &other.options(0).expect("hybrid"),
            false,
            20,
            tr,
            cy,
        ),
    });
    (points, order_points)
}

/// Time constant of the stiff flight relaxation, gamma/k (s).
pub const TAU_S: f64 = 0.01 / 10.0;

/// Drive frequency of the stiff flight relaxation (Hz).
pub const STIFF_FREQUENCY_HZ: f64 = 30.0;

/// The stiff flight relaxation: explicit fixed steps of T/10 against adaptive DP5, and
/// each fixed-step method's measured blow-up threshold.
#[derive(Debug, Clone, PartialEq)]
pub struct StiffEvidence {
    /// The fixed steps of T/10 and adaptive DP5.
    pub outcome: StiffOutcome,
    /// Per fixed-step method, the threshold of h/tau from which it blows up within 400
    /// steps, bracketed `(a, b)`: at `a` it does not, at `b` it does.
    pub thresholds: Vec<(Method, (f64, f64))>,
}

/// Runs the stiff relaxation (`quick`: 0.3 s, else 1 s).
pub(super) fn gather_stiff(quick: bool) -> StiffEvidence {
    let outcome = stiff(TAU_S, STIFF_FREQUENCY_HZ, if quick { 0.3 } else { 1.0 });
    let thresholds = [Method::Euler, Method::Rk4]
        .into_iter()
        .map(|m| (m, blow_up_threshold(m)))
        .collect();
    StiffEvidence {
        outcome,
        thresholds,
    }
}

/// Bisects h/tau in [0.5, 8] to 1e-9 for the threshold from which `method` blows up
/// within 400 steps ([`blows_up`]; one threshold, as the stability region of an explicit
/// Runge-Kutta method meets the negative real axis in one interval); NaN when the
/// bracket does not hold.
fn blow_up_threshold(method: Method) -> (f64, f64) {
    let blows = |z: f64| blows_up(method, TAU_S, STIFF_FREQUENCY_HZ, z);
    let (mut a, mut b) = (0.5, 8.0);
    if blows(a) || !blows(b) {
        return (f64::NAN, f64::NAN);
    }
    while b - a > 1e-9 {
        let m = 0.5 * (a + b);
        if blows(m) {
            b = m;
        } else {
            a = m;
        }
    }
    (a, b)
}

/// The Zeno scenes and their settings.
#[derive(Debug, Clone, PartialEq)]
pub struct ZenoEvidence {
    /// The runs.
    pub outcome: ZenoOutcome,
    /// Restitution e of the scenes.
    pub restitution: f64,
    /// Peak plate acceleration over g of the chattering plate.
    pub gamma: f64,
    /// Periods of the plate runs (transient and window).
    pub periods: u32,
}

/// Zeno: a ball on a fixed floor, and the block on a plate at Gamma = 1.2, where every
/// landing turns into a chattering sequence (complete chattering).
pub(super) fn gather_zeno(s: &Setup<'_>) -> ZenoEvidence {
    let (args, plan) = (s.args, &s.plan);
    let gamma = 1.2;
    let scene = BlockScene::new(args.frequency_hz, gamma, args.mu, args.bias, s.g);
    let mj_n = if s.quick { 1000 } else { 4000 };
    ZenoEvidence {
        outcome: zeno(&scene, args.restitution, plan.transient, plan.cycles, mj_n),
        restitution: args.restitution,
        gamma,
        periods: plan.transient + plan.cycles,
    }
}
