//! The runs of the chapter, computed once into one [`Evidence`] value: the Coulomb and
//! linear blocks on the document's sawtooth, its mirror and the smooth drives, the runs
//! on either side of the thresholds, and (full mode) the work-precision ladder. Nothing
//! here reads the document's statements: the claims of [`super::claims`] judge them
//! against this evidence.

use super::sims::{
    biharmonic, run_block, scaled, slip_transient, transient, DriftRun, Law, Numerics, Window,
};
use super::work::{work_precision, WorkRow};
use super::Scene;
use crate::physics::plate::{Axis, Biharmonic, Harmonic, PlateMotion, Sawtooth};
use crate::physics::sawtooth::biharmonic::{always_slipping_drift, stick_forever_gamma};
use crate::physics::sawtooth::{
    drift_velocity_mps, lock_time_s, slipping_impulse_per_mass, steady_regime, Mirrored, Regime,
};
use std::f64::consts::TAU;

/// Bi-harmonic asymmetry used for the checks (the drift's sign and size are odd and
/// linear in it at large drive numbers).
pub const EPS_CHECK: f64 = 0.2;

/// Drive number of the bi-harmonic always-slipping check.
pub const GAMMA_CHECK: f64 = 10.0;

/// The claims' tolerances: the error budgets of the runs they judge.
///
/// - Velocities of the Coulomb block: closed forms and event-located switches, so
///   rounding only: the largest of the runs' own budgets
///   ([`super::sims::mean_velocity_budget_mps`]: eps times the speed times the number of
///   segments and the window's length in time) plus the overshoot of the located
///   switches (`mu g` times 4 ulps of t, over the run, 64 eps k t_run).
/// - Times (the lock time): each of the n_lock + 1 periods before the lock adds a
///   period and a slip of (v_slow + v_fast)/k, each rounded by a few (64) ulps.
/// - Velocities of the linear block (DP5 at rtol = atol = 1e-12): the largest of the
///   runs' budgets, the local error bound per accepted step summed over the steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    /// Velocities of the Coulomb block (m/s).
    pub v_mps: f64,
    /// Times of the Coulomb block (s).
    pub t_s: f64,
    /// Velocities of the linear block (m/s).
    pub lin_mps: f64,
}

impl Tolerances {
    /// The tolerances of scene `sc` for runs of `measured` periods after the lock, from
    /// the error budgets (m/s) of the Coulomb runs (`coulomb`) and the linear ones
    /// (`linear`) that the claims judge.
    pub fn of(sc: &Scene, measured: usize, coulomb: &[f64], linear: &[f64]) -> Tolerances {
        let saw = sc.saw;
        let (a, b) = (saw.slow_velocity_mps, saw.fast_velocity_mps);
        let (k, period) = (sc.k_mps2(), saw.period_s());
        let t_run = (transient(&saw, k) + measured) as f64 * period;
        let n_lock = (lock_time_s(&saw, k, 0.0) / period).floor();
        let largest = |xs: &[f64]| xs.iter().fold(0.0f64, |m, &x| m.max(x));
        Tolerances {
            v_mps: largest(coulomb) + 64.0 * f64::EPSILON * k * t_run.max(1.0), // formula: max budget + 64 eps k t
            t_s: 64.0 * f64::EPSILON * (n_lock + 1.0) * (period + (a + b) / k), // formula: 64 eps (n_lock + 1)(T + (a + b)/k)
            lin_mps: largest(linear),
        }
    }
}

/// The linear-friction runs.
#[derive(Debug, Clone)]
pub struct Linear {
    /// Mean velocity on each drive (m/s): sawtooth, its mirror, bi-harmonic eps = 0 and
    /// 0.3, sine.
    pub drifts_mps: Vec<f64>,
    /// The first two periods from rest on the sawtooth (inside the transient).
    pub early: DriftRun,
    /// The run from rest over the figure's span (figures only).
    pub trace: Vec<(f64, f64, f64)>,
    /// The error budgets of the drifts and of `early` (m/s).
    pub budgets_mps: Vec<f64>,
}

/// The Coulomb block on either side of a threshold.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sides {
    /// Where the threshold is (its own units: Gamma, or mu g t_fast/(v_slow + v_fast)).
    pub threshold: f64,
    /// Drift at 0.95 of it (m/s).
    pub below_mps: f64,
    /// Drift at 1.05 of it (m/s).
    pub above_mps: f64,
    /// The closed-form drift at 0.95 of it (m/s; the sawtooth only).
    pub closed_below_mps: f64,
    /// Did the block stick while the plate moved back, at 0.95 and at 1.05 of it (the
    /// sawtooth only)?
    pub stuck_back: (bool, bool),
    /// The larger error budget of the two runs (m/s).
    pub budget_mps: f64,
}

/// Everything the claims and figures read.
#[derive(Debug, Clone)]
pub struct Evidence {
    /// The scene.
    pub scene: Scene,
    /// Periods averaged after the lock.
    pub measured: usize,
    /// The claims' tolerances.
    pub tol: Tolerances,
    /// The Coulomb block on the document's sawtooth from rest.
    pub main: DriftRun,
    /// The closed-form drift (m/s).
    pub v_formula_mps: f64,
    /// The closed-form steady regime.
    pub regime: Regime,
    /// The closed-form lock time (s).
    pub lock_time_s: f64,
    /// The drift on the mirrored sawtooth (m/s).
    pub mirrored_mps: f64,
    /// Drifts with the slow stroke towards +x and towards -x on a scene that drifts
    /// (m/s): the document's sawtooth, or one with mu g t_fast = (v_slow + v_fast)/2.
    pub direction_mps: (f64, f64),
    /// The linear-friction runs.
    pub linear: Linear,
    /// One always-slipping period from the middle of the slip band (when the scene has
    /// one): the closed-form impulse per mass (m/s) and the run.
    pub slip_probe: Option<(f64, DriftRun)>,
    /// The sawtooth at mu g t_fast = 0.95 and 1.05 (v_slow + v_fast).
    pub slip_sides: Sides,
    /// Velocity amplitude of the bi-harmonic drives (m/s).
    pub vb_mps: f64,
    /// Bi-harmonic drift at `GAMMA_CHECK`, `EPS_CHECK`: simulated and closed form (m/s).
    pub biharmonic_mps: (f64, f64),
    /// The bi-harmonic drive at 0.95 and 1.05 Gamma_stick.
    pub stick_sides: Sides,
    /// Work-precision: the table and the figure's rows (full mode only).
    pub work: Option<(String, Vec<WorkRow>)>,
}

/// Runs everything once for scene `sc` (`quick`: shorter windows, no work-precision
/// ladder; `traces`: sample the velocities for the figures).
pub fn gather(sc: &Scene, quick: bool, traces: bool) -> Evidence {
    let saw = sc.saw;
    let k = sc.k_mps2();
    let coul = Law::Coulomb { k_mps2: k };
    let num = Numerics::default();
    let measured = if quick { 4 } else { 20 };
    let period = saw.period_s();
    let trace_span = (0.0, (transient(&saw, k) as f64 + 2.0) * period);
    let (tspan, tdt) = if traces {
        (trace_span, period / 200.0)
    } else {
        ((0.0, 0.0), 0.0)
    };
    let win = Window {
        transient: transient(&saw, k),
        measured,
    };
    let main = run_block(coul, &saw, 0.0, win, &num, tspan, tdt);
    let mirrored = run_block(coul, &Mirrored(saw), 0.0, win, &num, (0.0, 0.0), 0.0);
    let mirrored_mps = mirrored.mean_velocity_mps;
    let regime = steady_regime(&saw, k);
    let own = (main.mean_velocity_mps, mirrored.mean_velocity_mps);
    let (direction_mps, direction_budget) = direction(sc, regime, measured, own);
    let vb_mps = 0.5 * (saw.slow_velocity_mps + saw.fast_velocity_mps);
    let v_formula_mps = drift_velocity_mps(&saw, k);
    let linear = linear(sc, measured, traces.then_some(trace_span));
    let slip_probe = slip_probe(sc);
    let slip_sides = slip_sides(sc, measured);
    let (biharmonic_mps, biharmonic_budget) = biharmonic_check(sc, quick, vb_mps);
    let stick_sides = stick_sides(sc, vb_mps);
    let coulomb = [
        main.budget_mps,
        mirrored.budget_mps,
        direction_budget,
        slip_probe.as_ref().map_or(0.0, |p| p.1.budget_mps),
        slip_sides.budget_mps,
        biharmonic_budget,
        stick_sides.budget_mps,
    ];
    let tol = Tolerances::of(sc, measured, &coulomb, &linear.budgets_mps);
    Evidence {
        scene: *sc,
        measured,
        tol,
        v_formula_mps,
        regime,
        lock_time_s: lock_time_s(&saw, k, 0.0),
        mirrored_mps,
        direction_mps,
        linear,
        slip_probe,
        slip_sides,
        vb_mps,
        biharmonic_mps,
        stick_sides,
        work: (!quick).then(|| work_precision(&saw, k, vb_mps, v_formula_mps, &num)),
        main,
    }
}

/// The direction checks need a drift: if the flags put the scene in the stick-in-both
/// regime, they use the same speeds with mu g t_fast = (v_slow + v_fast)/2. `own`: the
/// scene's drifts (m/s), reused when it drifts. Also returns the runs' larger error
/// budget (m/s; 0 when `own` is reused: its budgets are the main runs').
fn direction(sc: &Scene, regime: Regime, measured: usize, own: (f64, f64)) -> ((f64, f64), f64) {
    if regime == Regime::StickSlow {
        return (own, 0.0);
    }
    let k = sc.k_mps2();
    let dir_saw = scaled(&sc.saw, k, 0.5);
    let win = Window {
        transient: transient(&dir_saw, k),
        measured,
    };
    let coul = Law::Coulomb { k_mps2: k };
    let num = Numerics::default();
    let f = |p: &dyn PlateMotion| run_block(coul, p, 0.0, win, &num, (0.0, 0.0), 0.0);
    let (a, b) = (f(&dir_saw), f(&Mirrored(dir_saw)));
    (
        (a.mean_velocity_mps, b.mean_velocity_mps),
        a.budget_mps.max(b.budget_mps),
    )
}

/// The linear block on five drives, its first two periods, and its trace over
/// `trace_span` (s) when figures are on.
fn linear(sc: &Scene, measured: usize, trace_span: Option<(f64, f64)>) -> Linear {
    let saw = sc.saw;
    let period = saw.period_s();
    let visc = Law::Viscous {
        c_per_s: sc.c_per_s,
    };
    let num = Numerics::default();
    let w_lin = Window {
        transient: (36.0 / (sc.c_per_s * period)).ceil() as usize,
        measured,
    };
    let vb = 0.5 * (saw.slow_velocity_mps + saw.fast_velocity_mps);
    let om = TAU / period;
    let bi = |eps: f64| Biharmonic {
        velocity_amplitude_mps: vb,
        omega_rad_s: om,
        asymmetry: eps,
    };
    let drives: Vec<Box<dyn PlateMotion>> = vec![
        Box::new(saw),
        Box::new(Mirrored(saw)),
        Box::new(bi(0.0)),
        Box::new(bi(0.3)),
        Box::new(Harmonic::sine(Axis::X, vb / om, 1.0 / period)),
    ];
    let runs: Vec<_> = drives
        .iter()
        .map(|p| run_block(visc, p.as_ref(), 0.0, w_lin, &num, (0.0, 0.0), 0.0))
        .collect();
    let drifts_mps = runs.iter().map(|r| r.mean_velocity_mps).collect();
    let trace = trace_span.map_or_else(Vec::new, |span| {
        let n = (span.1 / period).round() as usize;
        let w = Window {
            transient: 0,
            measured: n,
        };
        run_block(visc, &saw, 0.0, w, &num, span, period / 200.0).trace
    });
    let w2 = Window {
        transient: 0,
        measured: 2,
    };
    let early = run_block(visc, &saw, 0.0, w2, &num, (0.0, 0.0), 0.0);
    let mut budgets_mps: Vec<f64> = runs.iter().map(|r| r.budget_mps).collect();
    budgets_mps.push(early.budget_mps);
    Linear {
        drifts_mps,
        early,
        trace,
        budgets_mps,
    }
}

/// One always-slipping period from the middle of (-b, a - k T_s), when the scene slips
/// all period long from there: the closed-form impulse per mass and the run.
fn slip_probe(sc: &Scene) -> Option<(f64, DriftRun)> {
    let saw = sc.saw;
    let (a, b, k) = (saw.slow_velocity_mps, saw.fast_velocity_mps, sc.k_mps2());
    if k * saw.slow_duration_s >= a + b {
        return None;
    }
    let v_start = 0.5 * (-b + a - k * saw.slow_duration_s);
    let w = Window {
        transient: 0,
        measured: 1,
    };
    let coul = Law::Coulomb { k_mps2: k };
    let probe = run_block(
        coul,
        &saw,
        v_start,
        w,
        &Numerics::default(),
        (0.0, 0.0),
        0.0,
    );
    Some((slipping_impulse_per_mass(&saw, k), probe))
}

/// Locomotion needs mu g t_fast < v_slow + v_fast: the drift 5 % on either side of the
/// threshold, so that a threshold off by 10 % (either way) puts one point on the wrong
/// side. The closed-form drift at 0.95 is small but resolved (it vanishes linearly at
/// the threshold, here ~5 % of the slow speed).
fn slip_sides(sc: &Scene, measured: usize) -> Sides {
    let k = sc.k_mps2();
    let coul = Law::Coulomb { k_mps2: k };
    let num = Numerics::default();
    let below = scaled(&sc.saw, k, 0.95);
    let above = scaled(&sc.saw, k, 1.05);
    let after_lock = |saw: &Sawtooth| {
        let w = Window {
            transient: transient(saw, k),
            measured,
        };
        run_block(coul, saw, 0.0, w, &num, (0.0, 0.0), 0.0)
    };
    let (rb, ra) = (after_lock(&below), after_lock(&above));
    Sides {
        threshold: 1.0,
        below_mps: rb.mean_velocity_mps,
        above_mps: ra.mean_velocity_mps,
        closed_below_mps: drift_velocity_mps(&below, k),
        stuck_back: (rb.stuck_in_backward_stroke, ra.stuck_in_backward_stroke),
        budget_mps: rb.budget_mps.max(ra.budget_mps),
    }
}

/// The bi-harmonic drift at `GAMMA_CHECK`, `EPS_CHECK`: simulated and closed form (m/s),
/// and the run's error budget (m/s).
fn biharmonic_check(sc: &Scene, quick: bool, vb: f64) -> ((f64, f64), f64) {
    let k = sc.k_mps2();
    let bw = Window {
        transient: slip_transient(GAMMA_CHECK),
        measured: if quick { 4 } else { 10 },
    };
    let bh = biharmonic(vb, GAMMA_CHECK, EPS_CHECK, k);
    let coul = Law::Coulomb { k_mps2: k };
    let v = run_block(coul, &bh, 0.0, bw, &Numerics::default(), (0.0, 0.0), 0.0);
    let formula = always_slipping_drift(GAMMA_CHECK, EPS_CHECK).map_or(f64::NAN, |d| d * vb);
    ((v.mean_velocity_mps, formula), v.budget_mps)
}

/// The bi-harmonic drive 5 % on either side of the derived Gamma_stick: stuck (zero
/// drift) just below, moving just above.
fn stick_sides(sc: &Scene, vb: f64) -> Sides {
    let k = sc.k_mps2();
    let g_stick = stick_forever_gamma(EPS_CHECK);
    let coul = Law::Coulomb { k_mps2: k };
    let drift_at = |gamma: f64| {
        let w = Window {
            transient: 10,
            measured: 4,
        };
        let p = biharmonic(vb, gamma, EPS_CHECK, k);
        run_block(coul, &p, 0.0, w, &Numerics::default(), (0.0, 0.0), 0.0)
    };
    let (below, above) = (drift_at(0.95 * g_stick), drift_at(1.05 * g_stick));
    Sides {
        threshold: g_stick,
        below_mps: below.mean_velocity_mps,
        above_mps: above.mean_velocity_mps,
        closed_below_mps: 0.0,
        stuck_back: (false, false),
        budget_mps: below.budget_mps.max(above.budget_mps),
    }
}
