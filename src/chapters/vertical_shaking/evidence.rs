//! The runs of the chapter, computed once into one [`Evidence`] value: the scene, the
//! regime sweep and its located boundaries, the fast-drive limits, the runs near the
//! thresholds and near Gamma_n, the Chladni demonstration, the law's decomposition and
//! the work-precision ladder. Nothing here reads the document's statements: the claims
//! of [`super::claims`] judge them against this evidence.

use super::chladni::{demonstrate, Chladni};
use super::regimes::{self, gamma_n, Boundary, SweepPoint};
use super::scene::{run, Model, Scene, Stats};
use crate::ladder::WorkPoint;
use crate::numerics::events::time_tolerance;
use crate::physics::block::{simulate_block, time_tolerance_of_run, BlockOptions, BlockParams};
use crate::physics::plate::PlateMotion;
use std::f64::consts::PI;

/// Everything the claims, tables and figures read.
#[derive(Debug, Clone)]
pub struct Evidence {
    /// The scene.
    pub scene: Scene,
    /// The scene after its transient.
    pub stats: Stats,
    /// The first take-off from rest (rad of the plate's phase).
    pub takeoff_phase_rad: f64,
    /// The regime sweep over 1 <= Gamma <= 10.
    pub sweep: Vec<SweepPoint>,
    /// Its located boundaries.
    pub bounds: Vec<Boundary>,
    /// Does the block take off within 50 periods at Gamma = 0.999 and 1.001?
    pub leaves: (bool, bool),
    /// The fast-drive limits.
    pub fast: FastLimits,
    /// The block kept sliding: mean friction / (mu x mean normal force), whether it
    /// slid all along (no stick, no reversal, some landings), and the ratio's rounding
    /// budget ([`sliding_budget`]).
    pub sliding: (f64, bool, f64),
    /// The take-off phase's rounding budget (rad, [`takeoff_budget_rad`]).
    pub takeoff_budget_rad: f64,
    /// Small forces: drifts at Gamma = 1.05 for F = 0.01, 0.001, 0.0001 mu m g, and at
    /// Gamma = 0.95 for F = 0.001 mu m g (m/s).
    pub small_force: (Vec<f64>, f64),
    /// Runs just below Gamma_n, n = 1, 2, 3.
    pub near_gamma_n: Vec<NearGammaN>,
    /// The scene's own t_f g/v_z and (v_ave/v_z)/mu_eff (NaN without bias).
    pub here: (f64, f64),
    /// Where the laws hold over Gamma = 2 ... 40.
    pub law_range: LawRange,
    /// The multiplier-located period doublings checked by the classifier: (n, Gamma,
    /// half-gap, label below, label above).
    pub doublings: Vec<(u32, f64, f64, regimes::Regime, regimes::Regime)>,
    /// The Chladni demonstration.
    pub chladni: Chladni,
    /// The law b*(Gamma): the largest bias (fraction of mu m g) whose landing after a
    /// flight from rest sticks, over Gamma in (1, Gamma_1): per Gamma, the closed form of
    /// [`super::landing`] and, at the checked values, the bisection on the exact model
    /// `(b*, half-width of its last bracket)`.
    pub landing: Vec<LandingPoint>,
    /// The law's decomposition: per Gamma, the drifts of the exact model, sticking
    /// impacts, no contact slip, and the four steps to the law (m/s).
    pub decomposition: Vec<[f64; 8]>,
    /// The work-precision ladder.
    pub work: Vec<WorkPoint>,
}

/// One point of the law b*(Gamma).
#[derive(Debug, Clone, Copy)]
pub struct LandingPoint {
    /// Gamma.
    pub gamma: f64,
    /// The closed form's b*.
    pub closed: f64,
    /// The exact model's b* and the half-width of its bracket, where checked.
    pub located: Option<(f64, f64)>,
}

/// The Gamma of the law b*(Gamma) over (1, Gamma_1) and, marked, the ones also located
/// on the exact model `(Gamma, full run, quick run)`: on both sides of Gamma_c =
/// [`super::landing::hold_boundary_gamma`] (2.975), past which the first landing falls
/// where the plate accelerates downwards and static friction, not the impulse, bounds
/// b* (0.927 at Gamma = 3).
pub const LANDING_GAMMAS: [(f64, bool, bool); 11] = [
    (1.05, false, false),
    (1.2, true, false),
    (1.5, false, false),
    (1.75, false, false),
    (2.0, true, true),
    (2.5, false, false),
    (2.9, false, false),
    (3.0, true, true),
    (3.1, false, false),
    (3.2, true, false),
    (3.25, false, false),
];

/// The largest frequency factor of [`FastLimits::law_sweep`] (Gamma = 32768): a range
/// wide enough (ln 128 = 4.85) that the law's oscillating error (up to ~25 %) moves the
/// fitted exponent by less than a 10 % error of it would.
pub const LAW_SWEEP_K_MAX: f64 = 128.0;

/// The frequency factors of [`FastLimits::cs`] (Gamma = 2 k^2 at fixed delta_z).
pub const FAST_FACTORS: [f64; 6] = [1.0, 2.0, 4.0, 8.0, 16.0, 32.0];

/// Contact fraction and viscous constant as omega grows at fixed delta_z.
#[derive(Debug, Clone)]
pub struct FastLimits {
    /// Contact fractions at 1, 2, 4, 8 x the frequency.
    pub fractions: Vec<f64>,
    /// c = F/(m v_ave) (1/s) at 1, 2, 4, 8, 16, 32 x the frequency.
    pub cs: Vec<f64>,
    /// The law's ratio r = c v_z/g (1 for the document's law) over the whole range:
    /// `(k, Gamma, c, r)` at frequency factors k log-spaced from 1 to
    /// [`LAW_SWEEP_K_MAX`] (Gamma = 2 k^2; 10 quick, 25 full), windows of 10 flights at
    /// least.
    pub law_sweep: Vec<(f64, f64, f64, f64)>,
}

/// Runs at Gamma_n (1 - eps): t_f g/v_z and (v_ave/v_z)/mu_eff.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NearGammaN {
    /// n.
    pub n: f64,
    /// `(t_f g/v_z, law ratio)` at eps = 1e-6.
    pub at_1e6: (f64, f64),
    /// The same at eps = 1e-5.
    pub at_1e5: (f64, f64),
    /// The law ratio of the no-contact-slip model at eps = 1e-6.
    pub law_noslip: f64,
    /// The rounding budgets of `at_1e6`'s two values ([`near_rounding`]).
    pub rounding: (f64, f64),
}

/// The rounding budget of a run's mean flight t_f g/v_z and law ratio
/// (v_ave/v_z)/mu_eff, both read off event times and positions of a run of `t_end`
/// seconds in `segments` closed-form segments.
///
/// - Times: each event is located to the driver's tolerance (at most 4 ulps of
///   max(t_end, 1 s), [`event_tolerance_s`]) and its time rounded once more (an ulp of
///   t_end), so a flight t_f = t_land - t_takeoff is off by up to
///   2 (4 eps max(t_end, 1 s) + eps t_end), relative to t_f.
/// - Positions: every segment adds a closed-form increment to x, rounding it by eps
///   |x| <= eps v_ave t_end (the block has moved at most that far), and the two ends'
///   times move them by v_ave times their time error: over `segments` segments the
///   cycle's displacement over `dt` seconds carries eps v_ave [(segments + 2) t_end +
///   2 (4 max(t_end, 1 s) + t_end)], relative to v_ave dt.
///
/// Returns the `(flight, law)` budgets (absolute, in the values' units) for the values
/// `tf`, `law` of a run of `t_end_s` in `segments` segments whose mean flight lasts
/// `flight_s` and whose velocity window lasts at least `window_s`.
pub fn near_rounding(
    (tf, law): (f64, f64),
    t_end_s: f64,
    segments: u64,
    flight_s: f64,
    window_s: f64,
) -> (f64, f64) {
    let eps = f64::EPSILON;
    let times = 2.0 * (4.0 * eps * t_end_s.max(1.0) + eps * t_end_s); // formula: 2 (4 eps max(t, 1) + eps t)
    (
        times / flight_s * tf.abs(), // formula: time error / t_f x value
        (eps * (segments as f64 + 2.0) * t_end_s + times) / window_s * law.abs(), // formula: (eps (n + 2) t_end + time error)/dt x value
    )
}

/// The event-time tolerance of a block run that ends at `t_end_s`, for an event at
/// `t_s` (s): 4 ulps of the run's end below 1 s, else 4 ulps of max(t, 1 s) (the
/// driver's rule, `physics::block::time_tolerance_of_run`).
fn event_tolerance_s(t_s: f64, t_end_s: f64) -> f64 {
    time_tolerance_of_run(0.0, t_end_s).unwrap_or_else(|| time_tolerance(t_s))
}

/// The rounding budget of the take-off phase (rad) located at `gamma`, `omega` in a
/// run that ends at `t_end_s`: the event is located to the driver's time tolerance
/// t_tol (4 ulps of the run's end below 1 s, of max(t, 1 s) beyond), phase omega t_tol,
/// and the phase omega t is rounded twice (the guard's argument and the reported
/// value), 2 eps phi_0; the guard n = g (1 - Gamma sin(omega t)) is rounded by about 4
/// ulps of its largest term g (1 + Gamma) (a sine, a product, a difference), which moves
/// its zero by that over its slope g Gamma cos(phi_0): 4 eps (1 + Gamma)/(Gamma
/// cos(phi_0)); the expected asin(1/Gamma) carries the rounding of 1/Gamma times the
/// condition of asin, eps tan(phi_0), plus an ulp. Near Gamma = 1 (cos(phi_0) -> 0) the
/// take-off is a grazing zero and the budget grows as 1/cos(phi_0).
pub fn takeoff_budget_rad(gamma: f64, omega: f64, t_end_s: f64) -> f64 {
    let eps = f64::EPSILON;
    let phi0 = (1.0 / gamma).asin();
    let c = phi0.cos();
    let located = omega * event_tolerance_s(phi0 / omega, t_end_s); // formula: omega t_tol
    located + eps * (2.0 * phi0 + 4.0 * (1.0 + gamma) / (gamma * c) + phi0.tan() + 1.0) // formula: + eps [2 phi_0 + 4 (1 + Gamma)/(Gamma cos phi_0) + tan phi_0 + 1]
}

/// The rounding budget of the sliding block's ratio <f>/(mu <N>) over a run of
/// `t_end_s` seconds in `segments` closed-form segments at `gamma`, `omega`: the
/// horizontal velocity starts at v0 = 2 mu g t_end and every segment adds a closed-form
/// increment to it, two roundings of at most eps/2 x v0 each, so <f> = (v_x - v0)/t_end
/// is off by up to segments eps v0/t_end = 2 segments eps mu g, relative 2 segments
/// eps; <N> = g + v_z/t_end, with |v_z| <= g (Gamma + 2 pi)/omega (the plate's speed
/// plus a period of free fall) rounded by eps per segment, relative
/// segments eps (Gamma + 2 pi)/(omega t_end); the final division and products add 4 eps.
/// The events' own location errors move <f> and mu <N> alike (friction is mu N at every
/// instant), so they cancel in the ratio.
pub fn sliding_budget(segments: u64, t_end_s: f64, gamma: f64, omega: f64) -> f64 {
    let eps = f64::EPSILON;
    let n = segments as f64;
    2.0 * n * eps + n * eps * (gamma + std::f64::consts::TAU) / (omega * t_end_s) + 4.0 * eps // formula: 2 n eps + n eps (Gamma + 2 pi)/(omega t) + 4 eps
}

/// One law's share of Gamma values within 10 %.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RangeStat {
    /// Values within 10 %.
    pub inside: usize,
    /// Largest error and its Gamma.
    pub worst: (f64, f64),
    /// Gamma values off by more than 10 %.
    pub out: Vec<i32>,
}

/// The laws' errors over Gamma = 2 ... 40.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LawRange {
    /// Step of the Gamma values.
    pub step: usize,
    /// Number of values.
    pub n: usize,
    /// t_f = 2 v_z/g.
    pub flight: RangeStat,
    /// mu_eff = v_ave/v_z.
    pub law: RangeStat,
}

/// The chapter's bias for the law checks: the scene's, or 0.1 without one.
fn law_bias(scene: &Scene) -> f64 {
    if scene.bias > 0.0 {
        scene.bias
    } else {
        0.1
    }
}

/// Runs everything once for `scene`.
pub fn gather(scene: &Scene, quick: bool) -> Evidence {
    let (transient, observe) = super::budget(quick);
    let stats = run(scene, Model::Exact, transient, observe);
    let hop = run(scene, Model::Exact, 0, 2);
    let takeoff_phase_rad = hop
        .rest_takeoff_phases_rad
        .first()
        .copied()
        .unwrap_or(f64::NAN);
    let n = if quick { 19 } else { 181 };
    let gammas = crate::sweep::linspace(1.0, 10.0, n);
    let sweep = regimes::sweep(scene, &gammas, transient, observe);
    let iters = if quick { 10 } else { 16 };
    let bounds = regimes::boundaries(scene, &sweep, transient, observe, iters);
    let here_ratio = if scene.bias > 0.0 {
        (stats.cycle_velocity_mps / scene.vz_mps()) / (scene.bias * scene.mu)
    } else {
        f64::NAN
    };
    let here = (
        stats.mean_flight_s() * scene.g_mps2 / scene.vz_mps(),
        here_ratio,
    );
    Evidence {
        scene: *scene,
        takeoff_phase_rad,
        sweep,
        bounds,
        leaves: (leaves(scene, 0.999), leaves(scene, 1.001)),
        fast: fast_limits(scene, quick),
        sliding: sliding(scene),
        takeoff_budget_rad: takeoff_budget_rad(scene.gamma, scene.omega(), hop.run.t_end_s),
        small_force: small_force(scene),
        near_gamma_n: [1.0, 2.0, 3.0]
            .iter()
            .map(|&n| near_gamma_n(scene, n, quick))
            .collect(),
        here,
        law_range: law_range(scene, quick),
        doublings: doublings(scene, quick),
        chladni: demonstrate(scene, quick, transient, observe),
        landing: landing_law(scene, quick),
        decomposition: decomposition(scene, transient, observe),
        work: work_precision(scene, quick),
        stats,
    }
}

/// The law b*(Gamma) at [`LANDING_GAMMAS`]: the closed form everywhere, the exact
/// model's bisection (12 halvings quick, 20 full) where marked (quick: at Gamma = 2
/// and 3).
fn landing_law(scene: &Scene, quick: bool) -> Vec<LandingPoint> {
    let iters = if quick { 12 } else { 20 };
    LANDING_GAMMAS
        .iter()
        .map(|&(gamma, full, in_quick)| {
            let at = scene.at_gamma(gamma);
            let check = if quick { in_quick } else { full };
            LandingPoint {
                gamma,
                closed: super::landing::closed_form_bound(&at),
                located: check.then(|| super::landing::located_bound(&at, iters)),
            }
        })
        .collect()
}

/// Does the block take off within 50 periods at `gamma`?
fn leaves(scene: &Scene, gamma: f64) -> bool {
    run(&scene.at_gamma(gamma), Model::Exact, 0, 50)
        .run
        .total_counts
        .takeoffs
        > 0
}

/// Contact fraction and c = F/(m v_ave) as omega grows at fixed delta_z: from the
/// amplitude of Gamma = 2 at the chapter's frequency, with a bias of at least 0.05.
/// The viscous constant c = F/(m v_ave) of scene `s` (1/s), from an exact run whose
/// transient and window cover at least 5 and `flights` flights: a flight lasts about
/// 2 v_z/g = Gamma/pi periods, so at large Gamma the windows must grow with it.
fn viscous_constant(s: &Scene, transient: usize, observe: usize, flights: usize) -> f64 {
    let flight_periods = (s.gamma / PI).ceil() as usize;
    let stk = run(
        s,
        Model::Exact,
        transient.max(5 * flight_periods),
        observe.max(flights * flight_periods),
    );
    s.bias * s.mu * s.g_mps2 / stk.cycle_velocity_mps // formula: c = F/(m v_ave)
}

fn fast_limits(scene: &Scene, quick: bool) -> FastLimits {
    let (transient, observe) = super::budget(quick);
    let base = Scene {
        gamma: 2.0,
        bias: law_bias(scene),
        ..*scene
    };
    let at = |k: f64| Scene {
        frequency_hz: k * base.frequency_hz,
        gamma: base.gamma * k * k,
        ..base
    };
    let mut fractions = Vec::new();
    let mut cs = Vec::new();
    for k in [1.0, 2.0, 4.0, 8.0] {
        let s = at(k);
        let stk = run(&s, Model::Exact, transient, 4 * observe);
        fractions.push(stk.run.contact_fraction);
        cs.push(s.bias * s.mu * s.g_mps2 / stk.cycle_velocity_mps); // formula: c = F/(m v_ave)
    }
    // the viscous constant further out, where the law's windows (up to +-15 % of
    // error) weigh less against the change in c: to 64 x the frequency
    for k in [16.0, 32.0] {
        cs.push(viscous_constant(&at(k), transient, 4 * observe, 40));
    }
    let ks = crate::sweep::logspace(1.0, LAW_SWEEP_K_MAX, if quick { 10 } else { 25 });
    let law_sweep = crate::sweep::par_map(&ks, "viscous constant over Gamma", |&k| {
        let s = at(k);
        let c = viscous_constant(&s, transient, 4 * observe, 10);
        (k, s.gamma, c, c * s.vz_mps() / s.g_mps2) // formula: r = c v_z/g
    });
    FastLimits {
        fractions,
        cs,
        law_sweep,
    }
}

/// A block kept sliding over 60 periods: mean friction / (mu x mean normal force),
/// whether it slid all along, and the ratio's rounding budget.
fn sliding(scene: &Scene) -> (f64, bool, f64) {
    let plate = scene.plate();
    let t_end = 60.0 * plate.period_s();
    let p = BlockParams::coulomb(scene.g_mps2, scene.mu, 0.0);
    let v0 = 2.0 * scene.mu * scene.g_mps2 * t_end; // fast enough never to stop
    let opts = BlockOptions {
        start: (0.0, [0.0, v0, 0.0, 0.0]),
        transient_periods: 0,
        ..BlockOptions::default()
    };
    let sl = simulate_block(&p, &plate, t_end, &opts);
    let friction = (sl.y_end[1] - v0) / t_end; // formula: <f> = delta v_x / t
    let normal = scene.g_mps2 + sl.y_end[3] / t_end; // formula: <N>/m = g + delta v_z / t
    let ratio = -friction / (scene.mu * normal);
    let always_slides = sl.total_counts.slip_to_stick == 0
        && sl.total_counts.reversals == 0
        && sl.total_counts.landings > 0;
    let budget = sliding_budget(sl.segments, t_end, scene.gamma, scene.omega());
    (ratio, always_slides, budget)
}

/// Drifts with small forces just above and just below Gamma = 1 (m/s).
fn small_force(scene: &Scene) -> (Vec<f64>, f64) {
    let v = |gamma: f64, bias: f64| {
        let s = Scene {
            bias,
            ..scene.at_gamma(gamma)
        };
        run(&s, Model::Exact, 0, 50).cycle_velocity_mps
    };
    let above = [1e-2, 1e-3, 1e-4].iter().map(|&b| v(1.05, b)).collect();
    (above, v(0.95, 1e-3))
}

/// Mean flight time and drift just below Gamma_n (the block rests between flights of
/// n periods, the limit the document's law assumes): `(t_f g/v_z, (v_ave/v_z)/(F/m g))`
/// at Gamma_n (1 - eps), and their rounding budgets ([`near_rounding`]).
fn at_gamma_n(
    scene: &Scene,
    n: f64,
    eps: f64,
    model: Model,
    quick: bool,
) -> ((f64, f64), (f64, f64)) {
    let (transient, observe) = super::budget(quick);
    let s = Scene {
        bias: law_bias(scene),
        ..scene.at_gamma(gamma_n(n) * (1.0 - eps))
    };
    let st = run(&s, model, transient, observe);
    let tf = st.mean_flight_s() * s.g_mps2 / s.vz_mps(); // formula: t_f / (v_z/g)
    let law = (st.cycle_velocity_mps / s.vz_mps()) / (s.bias * s.mu); // formula: (v_ave/v_z)/mu_eff
    // The velocity window spans at least one cycle of n periods (a flight and a rest).
    let rounding = near_rounding(
        (tf, law),
        st.run.t_end_s,
        st.run.segments,
        st.mean_flight_s(),
        n * st.run.period_s,
    );
    ((tf, law), rounding)
}

/// The runs just below Gamma_n.
fn near_gamma_n(scene: &Scene, n: f64, quick: bool) -> NearGammaN {
    let (at_1e6, rounding) = at_gamma_n(scene, n, 1e-6, Model::Exact, quick);
    NearGammaN {
        n,
        at_1e6,
        at_1e5: at_gamma_n(scene, n, 1e-5, Model::Exact, quick).0,
        law_noslip: at_gamma_n(scene, n, 1e-6, Model::NoContactSlip, quick).0 .1,
        rounding,
    }
}

/// Where the laws hold: over Gamma = 2, 3, ..., 40 (every second value in quick mode),
/// the simulated t_f g/v_z against 2 and (v_ave/v_z)/mu_eff against 1: the share of the
/// Gamma values at which each is within 10 %, the largest error and where it occurs.
fn law_range(scene: &Scene, quick: bool) -> LawRange {
    let (transient, observe) = super::budget(quick);
    let b = law_bias(scene);
    let step = if quick { 2 } else { 1 };
    let mut out = LawRange {
        step,
        ..LawRange::default()
    };
    for gi in (2..=40).step_by(step) {
        let gamma = gi as f64;
        let s = Scene {
            gamma,
            bias: b,
            ..*scene
        };
        // flights of up to ~Gamma/pi periods: windows of 10 of them at least
        let fp = (gamma / PI).ceil() as usize;
        let st = run(
            &s,
            Model::Exact,
            transient.max(5 * fp),
            observe.max(10 * fp),
        );
        let tf_err = st.mean_flight_s() * s.g_mps2 / s.vz_mps() / 2.0 - 1.0; // formula: t_f/(2 v_z/g) - 1
        let law_err = (s.bias * s.mu) / (st.cycle_velocity_mps / s.vz_mps()) - 1.0; // formula: mu_eff/(v_ave/v_z) - 1
        out.n += 1;
        for (err, stat) in [(tf_err, &mut out.flight), (law_err, &mut out.law)] {
            if err.abs() <= 0.1 {
                stat.inside += 1;
            } else {
                stat.out.push(gi);
            }
            if err.is_finite() && err.abs() > stat.worst.0.abs() {
                stat.worst = (err, gamma);
            }
        }
    }
    out
}

/// The multiplier-located period doublings (n = 1, 2, 3) classified after a long
/// transient just below and above.
fn doublings(scene: &Scene, quick: bool) -> Vec<(u32, f64, f64, regimes::Regime, regimes::Regime)> {
    // Near the doubling the multiplier falls like ~5 per unit Gamma, so at 0.01 away
    // |lambda| < 0.96 and 2000 flights-worth of transient leave < 1e-30 of a deviation.
    let (d, long) = if quick { (0.01, 2000) } else { (0.005, 4000) };
    (1..=3u32)
        .map(|k| {
            let pd = regimes::period_doubling_gamma(f64::from(k));
            let below = regimes::regime_at(scene, pd - d, long, 60);
            let above = regimes::regime_at(scene, pd + d, long, 60);
            (k, pd, d, below, above)
        })
        .collect()
}

/// The law's error taken apart: each approximation switched on in turn. Per Gamma:
/// `[Gamma, exact, sticking impacts, no contact slip, flight-weighted, mean flight,
/// take-off speed, law]` (m/s but Gamma).
fn decomposition(scene: &Scene, transient: usize, observe: usize) -> Vec<[f64; 8]> {
    let mut gammas = vec![1.5, 2.0, 3.0, 5.0, 8.0, gamma_n(3.0) * (1.0 - 1e-6)];
    if !gammas.iter().any(|g| (g - scene.gamma).abs() < 1e-9) {
        gammas.push(scene.gamma);
    }
    gammas.sort_by(f64::total_cmp);
    gammas
        .into_iter()
        .map(|g| {
            let sc = scene.at_gamma(g);
            let b = sc.bias * sc.mu * sc.g_mps2;
            let va = run(&sc, Model::Exact, transient, observe).cycle_velocity_mps;
            let vb = run(&sc, Model::StickingImpacts, transient, observe).cycle_velocity_mps;
            let c = run(&sc, Model::NoContactSlip, transient, observe);
            let vd = 0.5 * b * c.flight_weighted_s(); // formula: v = b sum t_f^2 / (2 sum t_f)
            let ve = 0.5 * b * c.mean_flight_s(); // formula: v = b <t_f>/2
            let vf = sc.bias * sc.mu * c.mean_takeoff_speed_mps(); // formula: t_f = 2 v_to/g
            [
                g,
                va,
                vb,
                c.cycle_velocity_mps,
                vd,
                ve,
                vf,
                sc.law_velocity_mps(),
            ]
        })
        .collect()
}

/// Work against accuracy: 20 periods from rest; reference: the closed-form run.
fn work_precision(scene: &Scene, quick: bool) -> Vec<WorkPoint> {
    let plate = scene.plate();
    let params = scene.params(Model::Exact);
    let end = 20.0 * plate.period_s();
    let model = |o: &BlockOptions| {
        let o = BlockOptions {
            transient_periods: 0,
            ..*o
        };
        simulate_block(&params, &plate, end, &o)
    };
    let reference = model(&BlockOptions::default()).mean_velocity_mps;
    let vz = scene.vz_mps();
    let scale = if reference.abs() > 1e-12 * vz {
        reference.abs()
    } else {
        vz
    };
    crate::ladder::work_precision(&model, reference, scale, quick)
}
