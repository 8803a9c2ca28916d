//! Chapter 8's differential test (issue 29): on random scenes drawn with chapter 8's own
//! seed, the event-driven model and the chapter's Moreau-Jean time-stepper must agree
//! within the time-stepper's own error estimate, or the event-driven run must say it
//! cannot vouch for its answer (`invalid`, `painleve-unresolved`, `zeno`).
//!
//! The time-stepper's estimate ([`mj_estimate`]): the ladder of its answers at the steps
//! `T/800, T/1600, ...` is in its asymptotic range when its differences shrink at an
//! observed order of at least 1/2; then the differences still to come sum to at most a
//! geometric tail (an observed order above 1 is not trusted: Moreau-Jean is first order).
//! Where that tail is wider than [`MJ_CONCLUSIVE_M`], the same estimate of the
//! ladder's Richardson sequence `2 x(h/2) - x(h)`, which has the same limit, may be
//! conclusive (a clean first-order ladder whose pre-asymptotic range is long).
//!
//! Where the ladder is not conclusive at the end (hopping gaits, issue 29: impacts
//! quantized to the step make its error erratic, and the gait amplifies it), or the gap
//! is within [`FS`] times its estimate, the run is checked window by window
//! ([`windows`]): Moreau-Jean started from the event-driven state at the start of every
//! window of at most a drive period must reach the event-driven state at its end within
//! its own estimate there; the verdict states why the end is out of reach: how far an
//! event-driven run started `PERTURB_RAD` away moves by the end ([`Sensitivity`]).
//!
//! One more scene per run has a rod light enough for the composite (`alpha >= 1e9`):
//! there Moreau-Jean is no reference (its steps would have to resolve the rod's own time
//! scale), so the composite is checked for continuity across its switch against the full
//! model just below it.
//!
//! Both sides use the same impact law (Moreau-Jean's velocity-level Coulomb law,
//! [`ImpactLaw::VelocityCoulomb`]): the chapter shows that Darboux-Keller's differs from
//! it on impacts that reverse the slip, a difference of laws, not of integration. The
//! Darboux-Keller run must agree too on scenes where no impact reverses the slip.
//!
//! A Painleve event the event-driven run reports must persist, at the same time, at a
//! 100 times tighter rtol.
//!
//! The CI set is [`CI_SCENES`] scenes of 0.3 s; `scripts/ch8-differential.sh` runs the
//! ignored test with `CH8_DIFF_SCENES` scenes (default 200) of 1 s in release mode.

use crate::common::Rng;
use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::{Method, StepControl};
use locomotion_workbook::physics::stick::StickParams;
use locomotion_workbook::physics::stick_inertia::run::{
    initial_state, run_from_rest, simulate_inertia, InertiaOutcome, InertiaRun,
};
use locomotion_workbook::physics::stick_inertia::timestepping::{mj_run, MjSelection};
use locomotion_workbook::physics::stick_inertia::{
    ImpactLaw, InertiaModel, InertiaParams, State, TH,
};

mod windows;

/// Chapter 8's seed (each chapter's random tests draw from their own);
/// `WORKBOOK_FUZZ_SEED` replaces it, to try fresh scenes.
const DEFAULT_SEED: u64 = 0x0008_D1FF_0008_0029;
/// Scenes of the CI run.
const CI_SCENES: usize = 8;
/// Steps per drive period of the coarsest Moreau-Jean run.
const MJ_STEPS: f64 = 800.0;
/// Moreau-Jean's answer is conclusive when its estimate is at most this (m): 1 mm, under
/// 1 % of L and of most scenes' travel; a wider estimate cannot tell a wrong gait from
/// a right one.
const MJ_CONCLUSIVE_M: f64 = 1e-3;
/// Finest Moreau-Jean step of the CI run: `T/(800 2^CI_MAX_LEVEL)`.
const CI_MAX_LEVEL: u32 = 10;
/// Finest Moreau-Jean step of the long run (`T/3276800`: two levels past the CI's
/// turned 4 of the 150 long-run scenes from inconclusive to agreeing at the end).
const LONG_MAX_LEVEL: u32 = 12;
/// The perturbation of theta(0) (rad) whose effect measures how well-conditioned C's
/// displacement is: ten times the event-driven run's rtol on an angle of order 1, so
/// the runs' own tolerance does not drown it.
const PERTURB_RAD: f64 = 1e-9;
/// Roache's factor of safety for a convergence study whose observed order is not
/// verified (P. J. Roache, Verification and Validation in Computational Science and
/// Engineering, 1998, the grid convergence index: 3, and 1.25 once three or more grids
/// confirm the order): a gap beyond Moreau-Jean's estimate but within `FS` times it is
/// not called a disagreement but unsure ([`Verdict::Unsure`]): the estimate is not
/// trusted that far. At the end an unsure scene is checked window by window; an unsure
/// window fails the scene. (On the long run's 23 hopping scenes, 1 of 410 conclusive
/// period samples of whole-run ladders missed the event-driven answer by 2.6 times its
/// estimate, long-run scene 91 at 0.95 s, on a plateau of the ladder that finer steps
/// leave; with two levels fewer, two more by 1.6 and 1.9 times.)
const FS: f64 = 3.0;
/// The event-driven runs' rtol and atol.
const RTOL: f64 = 1e-10;

fn opts() -> Options {
    Options {
        method: Method::Dop853,
        control: StepControl::tol(RTOL, RTOL),
        ..Options::default()
    }
}

/// A random scene: tip mass, rod mass, spring, damper, friction, rest angle, plate.
fn draw(rng: &mut Rng) -> InertiaParams {
    let m = rng.pick(&[0.0, 0.1, 1.0]);
    let m_r = if m == 0.0 {
        rng.log_uniform(0.01, 1.0)
    } else {
        rng.log_uniform(1e-4, 1.0)
    };
    let mut base = StickParams::new(
        0.15,
        1.0,
        rng.uniform(2.0, 30.0),
        rng.log_uniform(0.003, 0.05),
        rng.uniform(0.2, 1.5),
        rng.uniform(0.1, 0.7),
        9.81,
        rng.uniform(1.2, 10.0),
        rng.uniform(10.0, 40.0),
    )
    .expect("a drawn stick inside the domain");
    base.mass_kg = m;
    InertiaParams {
        base,
        rod_mass_kg: m_r,
        restitution: 0.0,
    }
}

/// What one scene gave (its fields are printed by `Debug`).
#[derive(Debug)]
#[allow(dead_code)]
enum Verdict {
    /// Within the time-stepper's estimate plus the event-driven run's tolerance at the
    /// end: (gap, bound) in m, and whether the time-stepper's preference for separation
    /// gives another answer (the contact problem had two solutions: the rule decides, not
    /// the integration).
    Agree(f64, f64, bool),
    /// Moreau-Jean not conclusive at the end; the event-driven run agrees with it on
    /// every window of at most a drive period, Moreau-Jean started from the
    /// event-driven state at each window's start ([`windows`]): the windows, how many
    /// halvings an inconclusive window needed, the largest ratio of a window's gap to its
    /// bound and that window, and the measured growth of a perturbation to the end.
    AgreeWindowed {
        windows: usize,
        halvings: usize,
        worst_gap_over_bound: f64,
        worst: String,
        why: Sensitivity,
    },
    /// Outside Moreau-Jean's estimate but within [`FS`] times it, or a window not
    /// conclusive even halved (the comparison).
    Unsure(String),
    /// A run said it cannot vouch for its answer (which run, and its outcome with the
    /// reason).
    SaysInvalid(String),
    /// A disagreement (the description).
    Disagree(String),
}

/// How well-conditioned C's displacement at the end is: the event-driven run started
/// from `theta(0) + PERTURB_RAD` against the run.
#[derive(Debug)]
#[allow(dead_code)]
struct Sensitivity {
    /// The perturbation as P's displacement about C, `L PERTURB_RAD` (m).
    start_m: f64,
    /// The change of C's displacement at the end (m).
    end_m: f64,
    /// `end_m / start_m`: how much the dynamics amplify a defect of the state from the
    /// start to the end (a Lyapunov-type factor).
    growth: f64,
    /// Impacts of the run and of the perturbed run (a different count: a grazing
    /// landing gained or lost).
    impacts: (usize, usize),
}

/// Does any impact of `run` reverse the slip (the laws differ there)? The slip after
/// has the opposite sign of the slip before. (This test first asked whether the slip
/// after points along the tangential impulse; but after a reversal the friction of the
/// second phase opposes the new slip, so the net impulse may oppose it too: on seed 2's
/// scene 0 the slip goes from +0.08 to -1.20 m/s under a positive impulse.)
fn reverses(run: &InertiaRun) -> bool {
    run.impacts
        .iter()
        .any(|i| i.slip_before_mps * i.slip_after_mps < 0.0)
}

/// C's displacement (m) of the event-driven run of `md` from rest over `dur`, with its
/// outcome.
fn event_driven(md: &InertiaModel, dur: f64) -> (InertiaRun, f64) {
    let run = run_from_rest(md, dur, &opts(), 0.0);
    let d = run.mean_velocity_mps * run.end_time_s;
    (run, d)
}

/// C's displacement (m) in the event-driven run of `md` from rest, its angle moved by
/// `dth_rad`, over `dur` at `rtol`, with the run.
fn event_driven_at(md: &InertiaModel, dur: f64, rtol: f64, dth_rad: f64) -> (InertiaRun, f64) {
    let th = md.p.static_angle().unwrap_or(md.p.base.theta0_rad);
    let mut y0 = initial_state(md, 0.0, th);
    y0[TH] += dth_rad;
    let o = Options {
        control: StepControl::tol(rtol, rtol),
        ..opts()
    };
    let run = simulate_inertia(md, 0.0, y0, dur, &o, 0.0);
    let d = run.mean_velocity_mps * run.end_time_s;
    (run, d)
}

/// A Painleve event the run reports must be there, at the same time, when rtol is 100
/// times tighter (a rounding artefact would move or vanish); `Some(why)` if not.
fn painleve_persists(md: &InertiaModel, dur: f64, run: &InertiaRun) -> Option<String> {
    let first = run.painleve.first()?;
    let tight = Options {
        control: StepControl::tol(1e-12, 1e-12),
        ..opts()
    };
    let r2 = run_from_rest(md, dur, &tight, 0.0);
    match r2.painleve.first() {
        Some(e) if (e.t_s - first.t_s).abs() <= 1e-6 => None,
        other => Some(format!(
            "Painleve event at t = {} s (rtol 1e-10) not at rtol 1e-12: {other:?}",
            first.t_s
        )),
    }
}

/// The geometric-tail estimate of a ladder `x` (one output at `h_0, h_0/2, ...`):
/// `Some((reference, estimate))` once the ladder is in its asymptotic range, `None`
/// before.
///
/// Moreau-Jean is first order, but where impacts and lift-offs fall between steps its
/// error changes sign from one step to the next: successive differences do not halve
/// smoothly, and a Richardson estimate from the last two (what this test used first)
/// can be far too small (on seed 32648's scene 7 it gave 1.35e-6 m where the finest
/// steps moved the answer by 1.5e-5 m). So the test reads the order from the envelope
/// of the differences: `D(k)`, the largest of the three differences ending at level `k`,
/// shrinks per halving by the observed factor `rho = (D(n)/D(n-3))^(1/3)` (order
/// `-log2 rho`). The ladder is in its asymptotic range when the observed order is at
/// least 1/2 (`rho <= 2^-1/2`) and the last difference is not larger than both of the
/// two before it (a growing difference means the step has only begun to resolve something:
/// scene 95 of the long run, whose last three differences are 6.0e-5, 4.7e-5 and
/// 9.6e-5 m on the way to the event-driven answer); then the differences still to come
/// sum to at most the geometric tail `D(n) rho/(1 - rho)`, the estimate, and the
/// reference is the finest value. An observed order above 1 is a pre-asymptotic drop,
/// not the method's (first) order: `rho` counts as at least 1/2, so the estimate is at
/// least `D(n)` (long run scene 27 at 0.75 s: a drop from 1.7e-3 to 1.1e-4 m gave
/// `rho = 0.40` and 7.8e-5 m, while the finest value was still 9.2e-5 m off).
fn tail_estimate(x: &[f64]) -> Option<(f64, f64)> {
    let n = x.len().checked_sub(1)?;
    if n < 6 {
        return None;
    }
    let big = |k: usize| {
        (k - 2..=k)
            .map(|j| (x[j] - x[j - 1]).abs())
            .fold(0.0, f64::max)
    };
    let rho = (big(n) / big(n - 3)).cbrt(); // formula: rho = (D(n)/D(n-3))^(1/3)
    let d = |k: usize| (x[k] - x[k - 1]).abs();
    let growing = d(n) > d(n - 1) && d(n) > d(n - 2); // formula: |d_n| > |d_{n-1}|, |d_{n-2}|
    let order_half = rho <= std::f64::consts::FRAC_1_SQRT_2; // false for NaN too
    if !order_half || growing {
        return None; // observed order below 1/2, no differences at all, or the last one grew
    }
    let rho = rho.max(0.5); // formula: observed order at most 1 (first-order method)
    Some((x[n], big(n) * rho / (1.0 - rho))) // formula: sum_{k>n} |d_k| <= D(n) rho/(1 - rho)
}

/// Moreau-Jean's conclusive answer from the ladder `x`: the plain ladder's tail estimate
/// ([`tail_estimate`]) when it is at most [`MJ_CONCLUSIVE_M`], else that of its
/// Richardson sequence `R_k = 2 x_k - x_{k-1}` (the same limit; where the ladder is a
/// clean first-order one whose pre-asymptotic range is long, e.g. long-run scene 64,
/// whose differences halve from 1.3e-2 m to 2.6e-4 m at `T/819200`, `R` settles
/// within 2.6e-5 m); `None` when neither is conclusive. The plain ladder comes first:
/// the choice never looks at the event-driven answer.
fn mj_estimate(x: &[f64]) -> Option<(f64, f64)> {
    mj_estimate_within(x, MJ_CONCLUSIVE_M)
}

/// [`mj_estimate`] with the conclusive bound `bound_m` (m) instead of
/// [`MJ_CONCLUSIVE_M`] (a window's share of it, [`windows`]).
fn mj_estimate_within(x: &[f64], bound_m: f64) -> Option<(f64, f64)> {
    let conclusive = |e: Option<(f64, f64)>| e.filter(|&(_, est)| est <= bound_m);
    conclusive(tail_estimate(x)).or_else(|| {
        let r: Vec<f64> = x.windows(2).map(|w| 2.0 * w[1] - w[0]).collect(); // formula: R_k = 2 x_k - x_{k-1}
        conclusive(tail_estimate(&r))
    })
}

/// One level of Moreau-Jean's ladder (the stuck contact persisting, as in the
/// event-driven rules), `steps` steps per drive period over `t`: C's displacement (m) at
/// `t`; `None` if a step had no contact solution.
fn mj_level(md: &InertiaModel, y0: &State, t: f64, steps: u64) -> Option<f64> {
    let h = md.period_s / steps as f64;
    let r = mj_run(md, y0, t, h, MjSelection::StickPersists)?;
    Some(r.mean_velocity_mps * t)
}

/// Runs Moreau-Jean down the ladder `T/800, T/1600, ...` to `T/(800 2^max_level)` and
/// stops at the first level whose conclusive estimate of the end covers the event-driven
/// `d_ev` (within `tol_ev`); otherwise the finest level's conclusive estimate, or
/// `Err(ladder)` (the answers of the levels run) when the end is not conclusive.
fn mj_answer(
    md: &InertiaModel,
    y0: &State,
    t: f64,
    d_ev: f64,
    tol_ev: f64,
    max_level: u32,
) -> Result<(f64, f64, f64), Vec<f64>> {
    let mut ladder = Vec::new();
    for k in 0..=max_level {
        let steps = (MJ_STEPS as u64) << k;
        match mj_level(md, y0, t, steps) {
            Some(x) => ladder.push(x),
            None => return Err(ladder),
        }
        if let Some((reference, est)) = mj_estimate(&ladder) {
            let covers = (d_ev - reference).abs() <= est + tol_ev;
            if covers || k == max_level {
                return Ok((reference, est, md.period_s / steps as f64));
            }
        }
    }
    Err(ladder)
}

/// The measured sensitivity of C's displacement `d_ev` at the end of the run `run` of
/// `md` over `dur`: an event-driven run from `theta(0) + PERTURB_RAD`; the growth is
/// counted from the perturbation itself as P's displacement about C (`L PERTURB_RAD`),
/// so it is how much the dynamics amplify a defect of the state from the start to the
/// end.
fn sensitivity(md: &InertiaModel, dur: f64, run: &InertiaRun, d_ev: f64) -> Sensitivity {
    let (pr, dp) = event_driven_at(md, dur, RTOL, PERTURB_RAD);
    let start_m = md.p.base.length_m * PERTURB_RAD; // formula: L dtheta
    let end_m = (dp - d_ev).abs();
    Sensitivity {
        start_m,
        end_m,
        growth: end_m / start_m, // formula: growth = |dx_C(end)| / (L dtheta(0))
        impacts: (run.impact_count, pr.impact_count),
    }
}

/// The event-driven run's own error at `t`: its budget `rtol (L + delta)(1 + t/T)`
/// (positional tolerance per drive cycle) or, where `gap` exceeds `est` plus the budget,
/// the larger of it and how much the answer moves at rtol/100 (`tight()`, run only then:
/// the verdict is the same as if it were always run).
fn ev_tolerance(md: &InertiaModel, t: f64, gap: f64, est: f64, tight: impl FnOnce() -> f64) -> f64 {
    let b = &md.p.base;
    let budget = RTOL * (b.length_m + b.plate.amplitude_m) * (1.0 + t / md.period_s); // formula: rtol (L + delta)(1 + t/T)
    if gap <= est + budget {
        budget
    } else {
        budget.max(tight())
    }
}

/// Compares the event-driven model of `p_ev` with Moreau-Jean on `p` over `dur` (the
/// two are the same except in the test that a perturbed model fails).
fn compare(p: &InertiaParams, p_ev: &InertiaParams, dur: f64, max_level: u32) -> Verdict {
    compare_with(p, p_ev, dur, max_level, forced_windowed())
}

/// [`compare`]; `windows_only`: the windowed comparison on every scene, the end
/// comparison skipped ([`windows`]).
fn compare_with(
    p: &InertiaParams,
    p_ev: &InertiaParams,
    dur: f64,
    max_level: u32,
    windows_only: bool,
) -> Verdict {
    let mut md = InertiaModel::new(*p);
    md.impact_law = ImpactLaw::VelocityCoulomb;
    let mut md_ev = InertiaModel::new(*p_ev);
    md_ev.impact_law = ImpactLaw::VelocityCoulomb;
    let (run, d_ev) = event_driven_at(&md_ev, dur, RTOL, 0.0);
    if !run.bridges.is_empty() {
        eprintln!("  Moreau-Jean bridges: {:?}", run.bridges);
    }
    match &run.outcome {
        InertiaOutcome::Completed | InertiaOutcome::Fell => {}
        o => return Verdict::SaysInvalid(format!("the event-driven run: {} {o:?}", o.label())),
    }
    if let Some(w) = painleve_persists(&md_ev, dur, &run) {
        return Verdict::Disagree(w);
    }
    let t = run.end_time_s;
    if !d_ev.is_finite() {
        return Verdict::Disagree(format!("non-finite displacement {d_ev}"));
    }
    let tol_ev = ev_tolerance(&md_ev, t, 0.0, 0.0, || 0.0); // the budget
    let y0 = initial_state(&md, 0.0, p.static_angle().unwrap_or(p.base.theta0_rad));
    if windows_only {
        return windowed(&md, &md_ev, dur, &run, d_ev, max_level);
    }
    let (reference, est, h) = match mj_answer(&md, &y0, t, d_ev, tol_ev, max_level) {
        Ok(a) => a,
        Err(_) => return windowed(&md, &md_ev, dur, &run, d_ev, max_level),
    };
    let gap = (d_ev - reference).abs();
    let tol_ev = ev_tolerance(&md_ev, t, gap, est, || {
        let (_, tight) = event_driven_at(&md_ev, dur, RTOL / 100.0, 0.0);
        (tight - d_ev).abs()
    });
    if gap > est + tol_ev {
        let w = format!(
            "velocity-Coulomb law: event-driven {d_ev:.9} m, Moreau-Jean {reference:.9} m (estimate {est:.2e} at h = T/{:.0})",
            md.period_s / h
        );
        return match beyond(gap, est, tol_ev, w) {
            Verdict::Unsure(w) => {
                eprintln!("  the end is unsure ({w}): checked window by window");
                windowed(&md, &md_ev, dur, &run, d_ev, max_level)
            }
            v => v,
        };
    }
    // the time-stepper's own preference (separation wherever consistent) at the same step
    let open = mj_run(&md, &y0, t, h, MjSelection::FirstOpen);
    let rule_dependent = open.is_none_or(|o| {
        o.ambiguous_steps > 0 && (o.mean_velocity_mps * t - reference).abs() > est + tol_ev
    });
    // the model's own law (Darboux-Keller) where no impact reverses the slip
    let (dk, d_dk) = event_driven(&InertiaModel::new(*p_ev), dur);
    if !dk.bridges.is_empty() {
        eprintln!("  Moreau-Jean bridges (Darboux-Keller): {:?}", dk.bridges);
    }
    if dk.outcome == run.outcome && !reverses(&dk) && (d_dk - reference).abs() > est + tol_ev {
        return Verdict::Disagree(format!(
            "Darboux-Keller: event-driven {d_dk:.9} m, Moreau-Jean {reference:.9} m (estimate {est:.2e}), no reversing impact"
        ));
    }
    Verdict::Agree(gap, est + tol_ev, rule_dependent)
}

/// A gap past Moreau-Jean's estimate `est` plus the event-driven tolerance: a
/// disagreement past [`FS`] times the estimate (or a NaN gap), else unsure (`what`
/// describes the comparison).
fn beyond(gap: f64, est: f64, tol_ev: f64, what: String) -> Verdict {
    if gap.is_nan() || gap > FS * est + tol_ev {
        Verdict::Disagree(what)
    } else {
        Verdict::Unsure(what)
    }
}

/// The windowed verdict ([`windows`]) of a scene whose end Moreau-Jean (model `md`)
/// cannot conclude, with the growth of the `PERTURB_RAD` perturbation of `theta(0)` from
/// the start (as P's displacement about C, `L PERTURB_RAD`) to the end: how much the
/// dynamics amplify a defect ([`sensitivity`]).
fn windowed(
    md: &InertiaModel,
    md_ev: &InertiaModel,
    dur: f64,
    run: &InertiaRun,
    d_ev: f64,
    max_level: u32,
) -> Verdict {
    let why = || sensitivity(md_ev, dur, run, d_ev);
    windows::windowed_verdict(md, md_ev, run.end_time_s, max_level, why)
}

/// `CH8_DIFF_WINDOWED=1`: every scene is checked window by window, the end comparison
/// skipped (a cross-check of the windowed comparison on scenes whose end is conclusive).
fn forced_windowed() -> bool {
    std::env::var("CH8_DIFF_WINDOWED").is_ok_and(|v| v == "1")
}

/// A light rod past the composite's switch (`alpha >= 1e9`, 1 kg tip): the composite
/// against the full event-driven model just below the switch (`m_r = 3e-9 M`,
/// `alpha ~ 1e9`), within the composite's bound plus the full model's rounding
/// threshold `eta_v` (chapter 8, section 3); and the composite at the light rod no
/// farther from it than the whole first-order correction. Moreau-Jean cannot be the reference
/// here: its asymptotic range needs steps below the rod's own time scale `I_G/gamma`
/// (on the first composite scene it is off by 0.7 % at T/51200 with a 1e-4 kg rod and by
/// 25 % with a 1e-6 kg rod).
fn compare_composite(p: &InertiaParams, dur: f64) -> Verdict {
    use locomotion_workbook::physics::stick_inertia::limit::{composite, uses_composite};
    assert!(uses_composite(p), "{p:?}");
    let c = composite(p, dur, &opts());
    if c.reference.outcome != InertiaOutcome::Completed {
        return Verdict::SaysInvalid(format!(
            "the composite's reference run: {:?}",
            c.reference.outcome
        ));
    }
    let below = InertiaParams {
        rod_mass_kg: 3e-9 * (p.base.mass_kg + p.rod_mass_kg),
        ..*p
    };
    let full = run_from_rest(&InertiaModel::new(below), dur, &opts(), 0.0);
    if full.outcome != InertiaOutcome::Completed {
        return Verdict::SaysInvalid(format!(
            "the full model below the switch: {:?}",
            full.outcome
        ));
    }
    let cb = composite(&below, dur, &opts());
    // the speed's change from the light rod to the rod below the switch is the
    // composite's own first-order term: compare like with like
    let v_full = full.mean_velocity_mps;
    // the full model's rounding: the threshold eta_v = C u (1 + alpha) V of its own
    // velocity decisions (chapter 8, section 3); 0.03 u alpha v held on the chapter's
    // scenes but not on every drawn one (0.13 u alpha v measured on one)
    let md_below = InertiaModel::new(below);
    let tol = md_below.velocity_rounding([0.0, 0.0]) + cb.error_bound_mps;
    let gap = (cb.mean_velocity_mps - v_full).abs();
    let slope = (cb.mean_velocity_mps - c.mean_velocity_mps).abs();
    if !gap.is_finite() || gap > tol || slope > (cb.mean_velocity_mps - cb.massless_mps).abs() + tol
    {
        return Verdict::Disagree(format!(
            "composite {} m/s, full model below the switch {v_full} m/s (tolerance {tol:.2e}; composite at the light rod {})",
            cb.mean_velocity_mps, c.mean_velocity_mps
        ));
    }
    Verdict::Agree(gap, tol, false)
}

/// The seed of the draws: chapter 8's, or `WORKBOOK_FUZZ_SEED`.
fn seed() -> u64 {
    std::env::var("WORKBOOK_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(DEFAULT_SEED)
}

/// Draws `n` scenes of `dur` and compares them (Moreau-Jean refined to at most
/// `T/(800 2^max_level)`); panics on a disagreement, on a scene that is inconclusive
/// (neither agreeing, at the end or window by window, nor said invalid: issue 29 allows
/// no third outcome), or when none agrees. `CH8_DIFF_ONLY=i,j,...` runs those scenes alone (the draws stay the
/// same).
fn differential(n: usize, dur: f64, max_level: u32) {
    let seed = seed();
    let only: Option<Vec<usize>> = std::env::var("CH8_DIFF_ONLY")
        .ok()
        .map(|s| s.split(',').filter_map(|i| i.trim().parse().ok()).collect());
    eprintln!("ch8 differential: seed {seed} (WORKBOOK_FUZZ_SEED to change)");
    let mut rng = Rng(seed.max(1));
    let (mut agree, mut said, mut inconclusive, mut rule, mut wrong) = (0, 0, 0, 0, Vec::new());
    let (mut windowed, mut compliant) = (0, (0, 0));
    for i in 0..n {
        let p = draw(&mut rng);
        if only.as_ref().is_some_and(|o| !o.contains(&i)) {
            continue;
        }
        let v = compare(&p, &p, dur, max_level);
        eprintln!("scene {i}: {v:?}");
        match v {
            Verdict::Agree(_, _, r) => {
                agree += 1;
                rule += usize::from(r);
                if r {
                    // which solution a stiff compliant contact takes there
                    for c in compliant_check(&p, dur) {
                        compliant.0 += usize::from(compliant_follows_rules(&c));
                        compliant.1 += 1;
                        if !compliant_follows_rules(&c) {
                            wrong.push(format!("scene {i}: a stiff compliant contact leaves the stuck foot elsewhere than the rules: (t_a, t_r, t_c, same kind) = {c:?}"));
                        }
                    }
                }
            }
            Verdict::AgreeWindowed { .. } => windowed += 1,
            Verdict::SaysInvalid(_) => said += 1,
            Verdict::Unsure(_) => inconclusive += 1,
            Verdict::Disagree(w) => wrong.push(format!("scene {i} {p:?}: {w}")),
        }
    }
    // and one light rod past the switch, where the run takes the composite
    let mut p = draw(&mut rng);
    p.base.mass_kg = 1.0;
    p.rod_mass_kg = rng.log_uniform(1e-12, 2e-9);
    if only.is_none() {
        let v = compare_composite(&p, dur);
        eprintln!("composite scene: {v:?}");
        if let Verdict::Disagree(w) = v {
            wrong.push(format!("composite scene {p:?}: {w}"));
        }
    }
    let m = only
        .as_ref()
        .map_or(n, |o| o.iter().filter(|&&i| i < n).count());
    eprintln!(
        "ch8 differential: {m} scenes, {agree} agree at the end ({rule} of them where Moreau-Jean preferring separation differs: two solutions), {windowed} agree window by window (the end out of Moreau-Jean's reach; growth measured), {said} say invalid, {inconclusive} inconclusive (a window not conclusive, or a gap within {FS} times its estimate), {} disagree",
        wrong.len()
    );
    eprintln!(
        "two-solution pivots of those scenes: a stiff compliant contact (K = 1e10 N/m) ends the stuck phase where the rules do at {} of {}",
        compliant.0, compliant.1
    );
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert!(
        inconclusive == 0,
        "{inconclusive} of {m} scenes inconclusive: neither agreeing nor said invalid"
    );
    assert!(agree + windowed > 0 || only.is_some());
}

#[test]
fn event_driven_and_moreau_jean_agree_on_random_scenes() {
    differential(CI_SCENES, 0.3, CI_MAX_LEVEL);
}

/// The comparison can fail: an event-driven model whose spring is 1 % too stiff
/// disagrees with Moreau-Jean on the unperturbed scene (all CI scenes that are
/// conclusive must say so).
#[test]
fn a_perturbed_event_driven_model_fails_the_comparison() {
    let mut rng = Rng(seed().max(1));
    let (mut caught, mut conclusive) = (0, 0);
    for i in 0..CI_SCENES {
        let p = draw(&mut rng);
        let mut q = p;
        q.base.stiffness_nm_per_rad *= 1.01;
        let v = compare(&p, &q, 0.3, CI_MAX_LEVEL);
        eprintln!("perturbed scene {i}: {v:?}");
        match v {
            Verdict::Disagree(_) => {
                caught += 1;
                conclusive += 1;
            }
            Verdict::Agree(..) | Verdict::AgreeWindowed { .. } => conclusive += 1,
            _ => {}
        }
    }
    assert!(
        caught > 0 && 2 * caught >= conclusive,
        "a 1 % stiffer spring was caught on {caught} of {conclusive} conclusive scenes"
    );
}

/// The windowed comparison ([`windows`]) on the CI scenes, whose ends are conclusive:
/// every scene agrees window by window (or its run says it cannot vouch for it); with
/// the event-driven spring 1 % too stiff no scene agrees, and at least half disagree
/// outright (a window past [`FS`] times Moreau-Jean's estimate). Measured at the default
/// seed: 8 of 8 agree, 8 of 8 perturbed disagree; at the seeds 1 to 7, 32648, 8453,
/// 17445 and 10877 87 of 88 perturbed scenes disagree and one (seed 8453, scene 4) is
/// unsure, its last three windows off by 1.6 to 2.2 times their estimates.
#[test]
fn the_windowed_comparison_agrees_and_catches_a_stiffer_spring() {
    let mut rng = Rng(seed().max(1));
    let (mut wrong, mut passed, mut caught) = (Vec::new(), Vec::new(), 0);
    for i in 0..CI_SCENES {
        let p = draw(&mut rng);
        let v = compare_with(&p, &p, 0.3, CI_MAX_LEVEL, true);
        eprintln!("scene {i}, window by window: {v:?}");
        if !matches!(v, Verdict::AgreeWindowed { .. } | Verdict::SaysInvalid(_)) {
            wrong.push(format!("scene {i}: {v:?}"));
        }
        let mut q = p;
        q.base.stiffness_nm_per_rad *= 1.01;
        let v = compare_with(&p, &q, 0.3, CI_MAX_LEVEL, true);
        eprintln!("perturbed scene {i}, window by window: {v:?}");
        match v {
            Verdict::Disagree(_) => caught += 1,
            Verdict::AgreeWindowed { .. } => passed.push(format!("scene {i}: {v:?}")),
            _ => {}
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert!(
        passed.is_empty(),
        "a 1 % stiffer spring agrees:\n{}",
        passed.join("\n")
    );
    assert!(
        2 * caught >= CI_SCENES,
        "a 1 % stiffer spring caught on {caught} of {CI_SCENES} scenes"
    );
}

/// The longer version (`scripts/ch8-differential.sh`).
#[test]
#[ignore = "minutes: run by scripts/ch8-differential.sh before a change to the contact code"]
fn event_driven_and_moreau_jean_agree_on_many_random_scenes() {
    let n = std::env::var("CH8_DIFF_SCENES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(200);
    differential(n, 1.0, LONG_MAX_LEVEL);
}

/// The Painleve map's two runs that chatter (issue 29): the 1 % rod at
/// `theta_0 = 0.05 + 0.95 * 2/11` rad, `mu = 0.1 + 1.9 j/11` (`j = 1`: 0.27, `j = 10`:
/// 1.83), the map's law (Darboux-Keller), 1 s from rest.
fn map_chatter_scene(j: u32) -> InertiaParams {
    let mut b = locomotion_workbook::physics::stick::authors_scene(10.0);
    b.mass_kg = 1.0;
    b.theta0_rad = 0.05 + 0.95 * 2.0 / 11.0;
    b.mu = 0.1 + 1.9 * f64::from(j) / 11.0;
    InertiaParams {
        base: b,
        rod_mass_kg: 0.01,
        restitution: 0.0,
    }
}

/// The bridged event-driven run of map scene `j` against Moreau-Jean's run of the whole
/// scene: `(event-driven displacement, Moreau-Jean's, its estimate + the event-driven
/// tolerance, bridges)`; panics when the run does not complete or Moreau-Jean does not
/// converge.
fn chatter_against_moreau_jean(j: u32, max_level: u32) -> (f64, f64, f64, usize) {
    let p = map_chatter_scene(j);
    let md = InertiaModel::new(p);
    let (run, d_ev) = event_driven(&md, 1.0);
    assert_eq!(run.outcome, InertiaOutcome::Completed, "{:?}", run.outcome);
    let b = &p.base;
    let t = run.end_time_s;
    let tol_ev = RTOL * (b.length_m + b.plate.amplitude_m) * (1.0 + t / md.period_s); // formula: rtol (L + delta)(1 + t/T)
    let y0 = initial_state(&md, 0.0, p.static_angle().unwrap_or(b.theta0_rad));
    let (reference, est, h) = mj_answer(&md, &y0, t, d_ev, tol_ev, max_level)
        .unwrap_or_else(|x| panic!("Moreau-Jean not converged: {x:?}"));
    eprintln!(
        "map scene mu = {:.4}: event-driven {d_ev:.9} m ({} bridges), Moreau-Jean {reference:.9} m (estimate {est:.2e} at h = T/{:.0})",
        b.mu,
        run.bridges.len(),
        md.period_s / h
    );
    (d_ev, reference, est + tol_ev, run.bridges.len())
}

/// The two chattering map runs complete through the bridge and agree with Moreau-Jean
/// run over the whole scene, within its estimate (measured: 2.3e-6 m within 5.1e-6 m at
/// T/102400, and 2.6e-5 m within 1.3e-4 m at T/51200).
#[test]
fn chattering_map_runs_agree_with_moreau_jean() {
    for j in [1, 10] {
        let (d_ev, reference, tol, bridges) = chatter_against_moreau_jean(j, LONG_MAX_LEVEL);
        assert!(bridges > 0, "no bridge on map scene j = {j}");
        assert!(
            (d_ev - reference).abs() <= tol,
            "map scene j = {j}: event-driven {d_ev} m, Moreau-Jean {reference} m, tolerance {tol:.2e}"
        );
    }
}

/// Stiffnesses of the compliant contact's ladder (N/m): the check reads the stiffest.
const COMPLIANT_K: [f64; 6] = [1e5, 1e6, 1e7, 1e8, 1e9, 1e10];
/// Trace interval of the event-driven run the compliant check reads (s).
const COMPLIANT_DT_S: f64 = 2e-6;

/// Which of the two solutions a stiff compliant contact takes (issue 29), on every
/// pivot of the event-driven run of `p` over `dur` (trace every [`COMPLIANT_DT_S`]) that
/// ends at `t_r` (the cone's edge or zero normal force) after lift-off has been
/// consistent since `t_a < t_r` (the free normal acceleration positive while the pivot
/// still pushes: the second solution, which Moreau-Jean's first-open choice takes).
/// From the pivot state 0.1 ms before `t_a` a Kelvin-Voigt normal contact of growing
/// stiffness ([`COMPLIANT_K`]) ends its stuck phase at `t_c(K)`. Returns, per such
/// pivot, `(t_a, t_r, t_c at the stiffest K, the compliant end is of the rules' kind)`.
fn compliant_check(p: &InertiaParams, dur: f64) -> Vec<(f64, f64, f64, bool)> {
    use locomotion_workbook::physics::stick_inertia::compliant::{
        free_normal_acceleration, pinned_lift_off, pivot_force,
    };
    use locomotion_workbook::physics::stick_inertia::Mode;
    let mut md = InertiaModel::new(*p);
    md.impact_law = ImpactLaw::VelocityCoulomb;
    let run = run_from_rest(&md, dur, &opts(), COMPLIANT_DT_S);
    let tr = &run.trace;
    let open = |i: usize| free_normal_acceleration(&md, tr[i].t_s, &tr[i].y) >= 0.0;
    let back = (1e-4 / COMPLIANT_DT_S) as usize;
    let mut out = Vec::new();
    let mut start = 0;
    for end in 1..tr.len() {
        if tr[end - 1].mode != Mode::Pivot {
            start = end;
            continue;
        }
        if tr[end].mode == Mode::Pivot {
            continue;
        }
        let ia = (start..end).rev().take_while(|&i| open(i)).last();
        let Some(ia) = ia.filter(|&ia| end - ia >= 3) else {
            continue; // no second solution before the pivot ends (within the trace's step)
        };
        let (t_a, t_r) = (tr[ia].t_s, tr[end].t_s);
        let i0 = ia.saturating_sub(back).max(start);
        let ladder: Vec<_> = COMPLIANT_K
            .iter()
            .map(|&k| pinned_lift_off(&md, tr[i0].t_s, &tr[i0].y, k, t_r + 0.002))
            .collect();
        // the rules' end: the cone's edge or zero force, whichever margin, extrapolated
        // from the last two pivot samples, closes first
        let margins = |i: usize| {
            let (fx, fz) = pivot_force(&md, tr[i].t_s, &tr[i].y);
            (p.base.mu * fz - fx.abs(), fz) // formula: margins mu F_z - |F_x|, F_z
        };
        let ((c1, z1), (c0, z0)) = (margins(end - 1), margins(end - 2));
        let closes = |m1: f64, m0: f64| {
            if m0 > m1 {
                m1 / (m0 - m1)
            } else {
                f64::INFINITY
            }
        }; // formula: samples until the margin is 0
        let cone = closes(c1, c0) < closes(z1, z0);
        eprintln!(
            "  two-solution pivot: lift-off consistent from {t_a:.6} s, the rules' pivot ends at {t_r:.6} s (at the cone's edge: {cone}; then {:?}); compliant stuck phase ends at {:?} s for K = {COMPLIANT_K:?} N/m",
            tr[end].mode,
            ladder.iter().map(|e| e.map(|e| e.t_s)).collect::<Vec<_>>()
        );
        let stiff = ladder[ladder.len() - 1];
        let t_c = stiff.map_or(f64::NAN, |e| e.t_s);
        let kind = stiff.is_some_and(|e| e.slides == cone);
        out.push((t_a, t_r, t_c, kind));
    }
    out
}

/// Does the stiffest compliant contact end the stuck phase where the rules do (within
/// two trace steps, the resolution of `t_r`, and nearer to it than to `t_a`), and in
/// the same way (a slide at the cone's edge, or a lift-off at zero force)?
fn compliant_follows_rules(&(t_a, t_r, t_c, kind): &(f64, f64, f64, bool)) -> bool {
    kind && (t_c - t_r).abs() <= 2.0 * COMPLIANT_DT_S && (t_c - t_r).abs() < (t_c - t_a).abs()
}

/// The two-solution scene of seed 32648 (scene 7 of its draw, a 0.374 kg rod, `mu`
/// beyond the left slide's Painleve bound): its pivot ending at 0.2542 s has lift-off
/// consistent from 0.2541 s. Measured: the compliant stuck phase ends at 0.25507,
/// 0.25459, 0.25435, 0.25424, 0.254215, 0.254215 s for K = 1e5 .. 1e10 N/m, each at the
/// cone's edge, as the rules' pivot does (0.254216 s to the trace's 2 us), not at the
/// first-open choice's 0.254066 s.
#[test]
fn a_stiff_compliant_contact_keeps_the_stuck_foot() {
    let mut rng = Rng(32648);
    let p = (0..8).map(|_| draw(&mut rng)).last().expect("eight draws");
    let pivots = compliant_check(&p, 0.2545);
    assert!(!pivots.is_empty(), "no two-solution pivot found");
    for c in &pivots {
        assert!(
            compliant_follows_rules(c),
            "{c:?}: (t_a, t_r, t_c, same kind)"
        );
    }
}
