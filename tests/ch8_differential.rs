//! Chapter 8's differential test (issue 29): on random scenes drawn with chapter 8's own
//! seed, the event-driven model and the chapter's Moreau-Jean time-stepper must agree
//! within the time-stepper's own error estimate, or the event-driven run must say it
//! cannot vouch for its answer (`invalid`, `painleve-unresolved`, `zeno`).
//!
//! The time-stepper's estimate: it is first order, so from three steps `h, h/2, h/4`
//! the differences `d1 = x(h) - x(h/2)`, `d2 = x(h/2) - x(h/4)` halve (`d1/d2 ~ 2`) and
//! the Richardson value `2 x(h/4) - x(h/2)` is within about `|d2|` of the limit. Where
//! `d1/d2` is not within [1.4, 2.8] (impacts quantized to the step make the error
//! erratic), the estimate is the spread of the last three values and the reference the
//! finest. The ladder is `h = T/800 ... T/12800`.
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
    initial_state, run_from_rest, InertiaOutcome, InertiaRun,
};
use locomotion_workbook::physics::stick_inertia::timestepping::{mj_run, MjSelection};
use locomotion_workbook::physics::stick_inertia::{ImpactLaw, InertiaModel, InertiaParams, State};

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
/// Finest Moreau-Jean step of the long run.
const LONG_MAX_LEVEL: u32 = 10;
/// At most this share of the scenes may be inconclusive (Moreau-Jean not converged).
const MAX_INCONCLUSIVE: f64 = 0.25;
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
    /// Within the time-stepper's estimate plus the event-driven run's tolerance: (gap,
    /// bound) in m, and whether the time-stepper's preference for separation gives another
    /// answer (the contact problem had two solutions: the rule decides, not the
    /// integration).
    Agree(f64, f64, bool),
    /// The event-driven run said it cannot vouch for its answer (its outcome).
    SaysInvalid(String),
    /// Moreau-Jean not converged: its ladder never reached its asymptotic range up to
    /// the finest step (the ladder), or a step had no contact solution.
    MjNotConverged(Vec<f64>),
    /// A disagreement (the description).
    Disagree(String),
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

/// Moreau-Jean's estimate from the ladder `x` (C's displacement at `h_0, h_0/2, ...`):
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
/// 9.6e-5 m on the way to the event-driven answer); then the differences still to come sum to at most the
/// geometric tail `D(n) rho/(1 - rho)`, the estimate, and the reference is the finest
/// value. For a clean first-order ladder (`rho = 1/2`) the estimate is `D(n)`.
fn mj_estimate(x: &[f64]) -> Option<(f64, f64)> {
    let n = x.len() - 1;
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
    Some((x[n], big(n) * rho / (1.0 - rho))) // formula: sum_{k>n} |d_k| <= D(n) rho/(1 - rho)
}

/// Runs Moreau-Jean (the stuck contact persisting, as in the event-driven rules) down
/// the ladder `T/800, T/1600, ...` to `T/(800 2^max_level)` and stops at the first level
/// whose conclusive estimate covers the event-driven `d_ev` (within `tol_ev`); otherwise
/// the finest level's estimate, or `Err(ladder)` when the finest level is not in the
/// asymptotic range or its estimate is wider than [`MJ_CONCLUSIVE_M`].
fn mj_answer(
    md: &InertiaModel,
    y0: &State,
    t: f64,
    d_ev: f64,
    tol_ev: f64,
    max_level: u32,
) -> Result<(f64, f64, f64), Vec<f64>> {
    let mut x = Vec::new();
    let h0 = md.period_s / MJ_STEPS;
    for k in 0..=max_level {
        let h = h0 / f64::from(1u32 << k);
        match mj_run(md, y0, t, h, MjSelection::StickPersists) {
            Some(r) => x.push(r.mean_velocity_mps * t),
            None => return Err(x),
        }
        if let Some((reference, est)) = mj_estimate(&x) {
            let covers = (d_ev - reference).abs() <= est + tol_ev;
            if est <= MJ_CONCLUSIVE_M && (covers || k == max_level) {
                return Ok((reference, est, h));
            }
        }
    }
    Err(x)
}

/// Compares the event-driven model of `p_ev` with Moreau-Jean on `p` over `dur` (the
/// two are the same except in the test that a perturbed model fails).
fn compare(p: &InertiaParams, p_ev: &InertiaParams, dur: f64, max_level: u32) -> Verdict {
    let mut md = InertiaModel::new(*p);
    md.impact_law = ImpactLaw::VelocityCoulomb;
    let mut md_ev = InertiaModel::new(*p_ev);
    md_ev.impact_law = ImpactLaw::VelocityCoulomb;
    let (run, d_ev) = event_driven(&md_ev, dur);
    if !run.bridges.is_empty() {
        eprintln!("  Moreau-Jean bridges: {:?}", run.bridges);
    }
    match &run.outcome {
        InertiaOutcome::Completed | InertiaOutcome::Fell => {}
        o => return Verdict::SaysInvalid(format!("{} {o:?}", o.label())),
    }
    if let Some(w) = painleve_persists(&md_ev, dur, &run) {
        return Verdict::Disagree(w);
    }
    let t = run.end_time_s;
    if !d_ev.is_finite() {
        return Verdict::Disagree(format!("non-finite displacement {d_ev}"));
    }
    // the event-driven run's own tolerance: its positional tolerance rtol (L + delta)
    // per drive cycle (an error budget that grows with the cycles)
    let b = &p.base;
    let tol_ev = RTOL * (b.length_m + b.plate.amplitude_m) * (1.0 + t / md.period_s); // formula: rtol (L + delta)(1 + t/T)
    let y0 = initial_state(&md, 0.0, p.static_angle().unwrap_or(b.theta0_rad));
    let (reference, est, h) = match mj_answer(&md, &y0, t, d_ev, tol_ev, max_level) {
        Ok(a) => a,
        Err(ladder) => return Verdict::MjNotConverged(ladder),
    };
    let gap = (d_ev - reference).abs();
    if gap > est + tol_ev {
        return Verdict::Disagree(format!(
            "velocity-Coulomb law: event-driven {d_ev:.9} m, Moreau-Jean {reference:.9} m (estimate {est:.2e} at h = T/{:.0})",
            md.period_s / h
        ));
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
        return Verdict::SaysInvalid(c.reference.outcome.label().to_string());
    }
    let below = InertiaParams {
        rod_mass_kg: 3e-9 * (p.base.mass_kg + p.rod_mass_kg),
        ..*p
    };
    let full = run_from_rest(&InertiaModel::new(below), dur, &opts(), 0.0);
    if full.outcome != InertiaOutcome::Completed {
        return Verdict::SaysInvalid(full.outcome.label().to_string());
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
/// `T/(800 2^max_level)`); panics on a disagreement, when more than
/// [`MAX_INCONCLUSIVE`] of the scenes are inconclusive (Moreau-Jean not converged), or
/// when none agrees. `CH8_DIFF_ONLY=i` runs scene `i` alone (the draws stay the same).
fn differential(n: usize, dur: f64, max_level: u32) {
    let seed = seed();
    let only: Option<usize> = std::env::var("CH8_DIFF_ONLY")
        .ok()
        .and_then(|s| s.parse().ok());
    eprintln!("ch8 differential: seed {seed} (WORKBOOK_FUZZ_SEED to change)");
    let mut rng = Rng(seed.max(1));
    let (mut agree, mut said, mut inconclusive, mut rule, mut wrong) = (0, 0, 0, 0, Vec::new());
    for i in 0..n {
        let p = draw(&mut rng);
        if only.is_some_and(|o| o != i) {
            continue;
        }
        let v = compare(&p, &p, dur, max_level);
        eprintln!("scene {i}: {v:?}");
        match v {
            Verdict::Agree(_, _, r) => {
                agree += 1;
                rule += usize::from(r);
            }
            Verdict::SaysInvalid(_) => said += 1,
            Verdict::MjNotConverged(..) => inconclusive += 1,
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
    let m = if only.is_some() { 1 } else { n };
    eprintln!(
        "ch8 differential: {m} scenes, {agree} agree ({rule} of them where Moreau-Jean preferring separation differs: two solutions), {said} say invalid, {inconclusive} Moreau-Jean not converged, {} disagree",
        wrong.len()
    );
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert!(
        inconclusive as f64 <= MAX_INCONCLUSIVE * m as f64,
        "{inconclusive} of {m} scenes inconclusive (Moreau-Jean not converged): at most {MAX_INCONCLUSIVE} of them may be"
    );
    assert!(agree > 0 || only.is_some());
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
            Verdict::Agree(..) => conclusive += 1,
            _ => {}
        }
    }
    assert!(
        caught > 0 && 2 * caught >= conclusive,
        "a 1 % stiffer spring was caught on {caught} of {conclusive} conclusive scenes"
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
