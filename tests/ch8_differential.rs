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
use locomotion_workbook::physics::stick_inertia::timestepping::mj_mean_speed;
use locomotion_workbook::physics::stick_inertia::{ImpactLaw, InertiaModel, InertiaParams};

/// Chapter 8's seed (each chapter's random tests draw from their own);
/// `WORKBOOK_FUZZ_SEED` replaces it, to try fresh scenes.
const DEFAULT_SEED: u64 = 0x0008_D1FF_0008_0029;
/// Scenes of the CI run.
const CI_SCENES: usize = 8;
/// Steps per drive period of the coarsest Moreau-Jean run.
const MJ_STEPS: f64 = 800.0;
/// Step refinements of the ladder (the last three give the estimate).
const MJ_LADDER: [f64; 5] = [1.0, 2.0, 4.0, 8.0, 16.0];

fn opts() -> Options {
    Options {
        method: Method::Dop853,
        control: StepControl::tol(1e-10, 1e-10),
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
    /// Within the time-stepper's estimate: (gap, estimate) in m.
    Agree(f64, f64),
    /// The event-driven run said it cannot vouch for its answer (its outcome).
    SaysInvalid(String),
    /// The time-stepper gave no finite answer (d1/d2, the event-driven displacement,
    /// the ladder).
    Unresolved(f64, f64, Vec<f64>),
    /// A disagreement (the description).
    Disagree(String),
}

/// Does any impact of `run` reverse the slip (the laws differ there)?
fn reverses(run: &InertiaRun) -> bool {
    run.impacts
        .iter()
        .any(|i| i.j_t_ns != 0.0 && i.slip_after_mps * i.j_t_ns > 0.0 && i.slip_after_mps != 0.0)
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

/// Compares the event-driven model with Moreau-Jean on `p` over `dur`.
fn compare(p: &InertiaParams, dur: f64) -> Verdict {
    let mut md = InertiaModel::new(*p);
    md.impact_law = ImpactLaw::VelocityCoulomb;
    let (run, d_ev) = event_driven(&md, dur);
    match &run.outcome {
        InertiaOutcome::Completed | InertiaOutcome::Fell => {}
        o => return Verdict::SaysInvalid(format!("{} {o:?}", o.label())),
    }
    if let Some(w) = painleve_persists(&md, dur, &run) {
        return Verdict::Disagree(w);
    }
    let t = run.end_time_s;
    if !d_ev.is_finite() {
        return Verdict::Disagree(format!("non-finite displacement {d_ev}"));
    }
    let y0 = initial_state(&md, 0.0, p.static_angle().unwrap_or(p.base.theta0_rad));
    let x: Vec<f64> = MJ_LADDER
        .iter()
        .map(|f| mj_mean_speed(&md, &y0, t, md.period_s / (MJ_STEPS * f)).unwrap_or(f64::NAN) * t)
        .collect();
    let n = x.len();
    if x.iter().any(|v| !v.is_finite()) {
        return Verdict::Unresolved(f64::NAN, d_ev, x);
    }
    let (d1, d2) = (x[n - 3] - x[n - 2], x[n - 2] - x[n - 1]);
    let last = &x[n - 3..];
    let spread = last.iter().fold(f64::NEG_INFINITY, |a, &b| a.max(b))
        - last.iter().fold(f64::INFINITY, |a, &b| a.min(b));
    // in the asymptotic range the Richardson value and |d2|; otherwise (events
    // quantized to the step make the error erratic) the finest value and the spread of
    // the last three
    let (reference, est) = if (1.4..=2.8).contains(&(d1 / d2)) {
        (2.0 * x[n - 1] - x[n - 2], d2.abs()) // formula: Richardson, order one
    } else {
        (x[n - 1], spread)
    };
    let gap = (d_ev - reference).abs();
    if gap > est {
        return Verdict::Disagree(format!(
            "velocity-Coulomb law: event-driven {d_ev:.9} m, Moreau-Jean {reference:.9} m (estimate {est:.2e}, ladder {x:?})"
        ));
    }
    // the model's own law (Darboux-Keller) where no impact reverses the slip
    let (dk, d_dk) = event_driven(&InertiaModel::new(*p), dur);
    if dk.outcome == run.outcome && !reverses(&dk) && (d_dk - reference).abs() > est {
        return Verdict::Disagree(format!(
            "Darboux-Keller: event-driven {d_dk:.9} m, Moreau-Jean {reference:.9} m (estimate {est:.2e}), no reversing impact"
        ));
    }
    Verdict::Agree(gap, est)
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
    Verdict::Agree(gap, tol)
}

/// Draws `n` scenes of `dur` and compares them; panics on a disagreement or when more
/// than a third are outside the time-stepper's range.
fn differential(n: usize, dur: f64) {
    let seed = std::env::var("WORKBOOK_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(DEFAULT_SEED);
    eprintln!("ch8 differential: seed {seed} (WORKBOOK_FUZZ_SEED to change)");
    let mut rng = Rng(seed.max(1));
    let (mut agree, mut said, mut unresolved, mut wrong) = (0, 0, 0, Vec::new());
    for i in 0..n {
        let p = draw(&mut rng);
        let v = compare(&p, dur);
        eprintln!("scene {i}: {v:?}");
        match v {
            Verdict::Agree(..) => agree += 1,
            Verdict::SaysInvalid(_) => said += 1,
            Verdict::Unresolved(..) => unresolved += 1,
            Verdict::Disagree(w) => wrong.push(format!("scene {i} {p:?}: {w}")),
        }
    }
    // and one light rod past the switch, where the run takes the composite
    let mut p = draw(&mut rng);
    p.base.mass_kg = 1.0;
    p.rod_mass_kg = rng.log_uniform(1e-12, 2e-9);
    let v = compare_composite(&p, dur);
    eprintln!("composite scene: {v:?}");
    if let Verdict::Disagree(w) = v {
        wrong.push(format!("composite scene {p:?}: {w}"));
    }
    eprintln!(
        "ch8 differential: {n} scenes, {agree} agree, {said} say invalid, {unresolved} outside Moreau-Jean's asymptotic range, {} disagree",
        wrong.len()
    );
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert!(
        3 * unresolved <= n,
        "{unresolved} of {n} scenes without a Moreau-Jean answer"
    );
    assert!(agree > 0);
}

#[test]
fn event_driven_and_moreau_jean_agree_on_random_scenes() {
    differential(CI_SCENES, 0.3);
}

/// The longer version (`scripts/ch8-differential.sh`).
#[test]
#[ignore = "minutes: run by scripts/ch8-differential.sh before a change to the contact code"]
fn event_driven_and_moreau_jean_agree_on_many_random_scenes() {
    let n = std::env::var("CH8_DIFF_SCENES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(200);
    differential(n, 1.0);
}
