//! Chapter `stick-with-inertia` (document sections 2, 4): the stick of chapter 6 with a
//! rod of real mass. The model is `physics::stick_inertia`; this chapter checks the
//! section-2 impulse ratios by simulated drops, the Painleve boundary by bisection on a
//! simulated slide, the impacts' energy, and sets the scene's gait beside chapter 6's.
//!
//! Shape: `statements.rs` (the statements as data), `evidence.rs` (the runs, once),
//! `claims.rs` (pure functions of both), `figures.rs`, `gif.rs`, `answers.rs` (the
//! chapter's measured answers), `mutations.rs` (10 % edits of the statements); this
//! file: flags and orchestration.

mod answers;
mod claims;
mod evidence;
mod figures;
mod gif;
mod mutations;
mod statements;

pub use statements::{Statements, PRINTED};

use super::Context;
use crate::error::{check, range, Result, WorkbookError};
use crate::physics::stick::{authors_scene, jamming_scene, StickParams};
use crate::physics::stick_inertia::limit;
use crate::physics::stick_inertia::run::{InertiaOutcome, InertiaRun};
use crate::physics::stick_inertia::InertiaParams;
use crate::report::{ChapterReport, Mutation};
use serde_json::json;

/// Chapter id.
pub const ID: &str = "stick-with-inertia";

/// The scene whose values the flags override (chapter 6's scenes).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Scene {
    /// Chapter 6's self-locking scene (theta_0 = 0.3 rad, Gamma = 3, g = 9.81 m/s^2).
    Jamming,
    /// The authors' scene (static angle 0.5 rad, Gamma = 10, g = 10 m/s^2).
    Authors,
}

/// Flags of the chapter: chapter 6's (same names, same ranges) with the tip mass and the
/// rod's mass in place of `--mass-kg`, and the restitution of impacts.
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Scene whose values the other flags override [default: jamming].
    #[arg(long, value_enum, default_value_t = Scene::Jamming)]
    pub scene: Scene,
    /// Rod length L (m, 0.015 to 1.5) [scene: 0.15].
    #[arg(long = "length-m")]
    pub length_m: Option<f64>,
    /// Point mass m at the top P (kg, 0 to 10; 0 is a uniform stick, a toothpick) [1].
    #[arg(long = "tip-mass-kg", default_value_t = 1.0)]
    pub tip_mass_kg: f64,
    /// Mass of the rod, uniform along C-P (kg, 0 to 10; 0 is chapter 6's massless rod;
    /// m + m_r >= 1e-3 kg) [0.01: 1 % of the tip mass].
    #[arg(long = "rod-mass-kg", default_value_t = 0.01)]
    pub rod_mass_kg: f64,
    /// Torsion-spring stiffness k (N m/rad, 0 to 100) [scene: 10].
    #[arg(long)]
    pub stiffness: Option<f64>,
    /// Torsion damper gamma (N m s/rad, 0 to 0.1; above 0 when m_r = 0) [scene: 0.01].
    #[arg(long)]
    pub damping: Option<f64>,
    /// Coulomb friction coefficient mu at the foot C (1, 0 to 2) [scene: 0.4].
    #[arg(long)]
    pub mu: Option<f64>,
    /// Spring rest angle theta_0 from the vertical (rad), in (-pi/2, pi/2) [scene].
    #[arg(long = "theta0-rad")]
    pub theta0_rad: Option<f64>,
    /// Peak plate acceleration over g, Gamma = delta omega^2 / g (1, 0 to 50) [scene].
    #[arg(long)]
    pub gamma: Option<f64>,
    /// Plate frequency f (Hz, 1 to 1000) [scene: 30].
    #[arg(long = "frequency-hz")]
    pub frequency_hz: Option<f64>,
    /// Simulated time (s, above 0, at most 100) [10; 2 with --quick].
    #[arg(long = "duration-s")]
    pub duration_s: Option<f64>,
    /// Relative (and absolute) tolerance of DOP853 in the contact modes (1, 1e-14 to 1e-2) [1e-10].
    #[arg(long, default_value_t = 1e-10)]
    pub rtol: f64,
    /// Restitution e of impacts at C (Stronge's energetic coefficient, 0 to 1; 0 is the
    /// document's plastic impact) [0].
    #[arg(long, default_value_t = 0.0)]
    pub restitution: f64,
}

/// Validated parameters and duration (s).
pub fn setup(args: &Args, ctx: &Context) -> Result<(InertiaParams, f64)> {
    let base = match args.scene {
        Scene::Authors => authors_scene(ctx.g_mps2.unwrap_or(10.0)),
        Scene::Jamming => jamming_scene(ctx.g_mps2.unwrap_or(Context::G_DEFAULT_MPS2)),
    };
    crate::chapters::check_g(base.g_mps2)?;
    let (l, m, m_r) = length_and_masses(args, &base)?;
    let (k, c, mu, th0) = spring_and_contact(args, &base, m_r)?;
    let (gam, f, dur, e) = drive_and_run(args, &base, ctx)?;
    let mut b = StickParams::new(l, m, k, c, mu, th0, base.g_mps2, gam, f);
    b.mass_kg = m;
    let p = InertiaParams {
        base: b,
        rod_mass_kg: m_r,
        restitution: e,
    };
    if m_r > 0.0 && c == 0.0 && p.geometry().alpha() >= limit::ALPHA_SWITCH {
        return Err(WorkbookError::bad_input(
            "--damping",
            c,
            "above 0 (N m s/rad) for a rod this light (alpha = M l_G^2/I_G >= 1e9): its impacts lose 9 digits, and without a damper chapter 6's model is no limit to replace them",
        ));
    }
    Ok((p, dur))
}

/// `--length-m`, `--tip-mass-kg`, `--rod-mass-kg` (m, kg, kg).
fn length_and_masses(args: &Args, base: &StickParams) -> Result<(f64, f64, f64)> {
    let box10 = "within a factor 10 of the authors' stick, as in stick-state-machine";
    let l = range(
        "--length-m",
        args.length_m.unwrap_or(base.length_m),
        0.015,
        1.5,
        "m",
        box10,
    )?;
    let why_m =
        "0 allowed (a uniform stick, or chapter 6's massless rod) up to 10 x the authors' 1 kg";
    let m = range("--tip-mass-kg", args.tip_mass_kg, 0.0, 10.0, "kg", why_m)?;
    let m_r = range("--rod-mass-kg", args.rod_mass_kg, 0.0, 10.0, "kg", why_m)?;
    if m + m_r < 1e-3 {
        return Err(WorkbookError::bad_input(
            "--rod-mass-kg",
            m_r,
            "m + m_r >= 1e-3 kg (kg): a lighter stick makes the pivot's time scale I_C/gamma shorter than the explicit integrator can follow at the drive's step",
        ));
    }
    Ok((l, m, m_r))
}

/// `--stiffness`, `--damping`, `--mu`, `--theta0-rad` (N m/rad, N m s/rad, 1, rad).
fn spring_and_contact(args: &Args, base: &StickParams, m_r: f64) -> Result<(f64, f64, f64, f64)> {
    let k = range(
        "--stiffness",
        args.stiffness.unwrap_or(base.stiffness_nm_per_rad),
        0.0,
        100.0,
        "N m/rad",
        "0 (a free hinge) to 10 x the authors' spring",
    )?;
    let c = range(
        "--damping",
        args.damping.unwrap_or(base.damping_nms_per_rad),
        0.0,
        0.1,
        "N m s/rad",
        "0 to 10 x the authors' damper",
    )?;
    if m_r == 0.0 && c == 0.0 && k > 0.0 {
        return Err(WorkbookError::bad_input("--damping", c, "above 0 (N m s/rad) when --rod-mass-kg is 0: the massless rod's angle in flight needs the damper"));
    }
    let mu = range(
        "--mu",
        args.mu.unwrap_or(base.mu),
        0.0,
        2.0,
        "1",
        "dry friction at the foot",
    )?;
    let th0 = check(
        "--theta0-rad",
        args.theta0_rad.unwrap_or(base.theta0_rad),
        |v| v.abs() < std::f64::consts::FRAC_PI_2,
        "-pi/2 < value < pi/2 (rad)",
    )?;
    Ok((k, c, mu, th0))
}

/// `--gamma`, `--frequency-hz`, `--duration-s`, `--rtol` (checked), `--restitution`.
fn drive_and_run(args: &Args, base: &StickParams, ctx: &Context) -> Result<(f64, f64, f64, f64)> {
    let gam = range(
        "--gamma",
        args.gamma.unwrap_or(base.gamma_accel()),
        0.0,
        50.0,
        "1",
        "a still plate to 5 x the authors' Gamma = 10",
    )?;
    let f = range(
        "--frequency-hz",
        args.frequency_hz.unwrap_or(base.frequency_hz()),
        1.0,
        1000.0,
        "Hz",
        "1 Hz to 1 kHz",
    )?;
    let dur = check(
        "--duration-s",
        args.duration_s
            .unwrap_or(if ctx.quick { 2.0 } else { 10.0 }),
        |v| v > 0.0 && v <= 100.0,
        "0 < value <= 100 (s): the work budget of one chapter run",
    )?;
    check(
        "--rtol",
        args.rtol,
        |v| (1e-14..=1e-2).contains(&v),
        "1e-14 <= value <= 1e-2 (1)",
    )?;
    let e = range(
        "--restitution",
        args.restitution,
        0.0,
        1.0,
        "1",
        "Stronge's energetic coefficient: above 1 an impact would create energy",
    )?;
    Ok((gam, f, dur, e))
}

/// Runs the chapter.
pub fn run(args: &Args, ctx: &Context) -> Result<ChapterReport> {
    run_with(args, ctx, &PRINTED)
}

/// Runs the chapter against the statements `doc`.
pub fn run_with(args: &Args, ctx: &Context, doc: &Statements) -> Result<ChapterReport> {
    let (p, dur) = setup(args, ctx)?;
    let mut r = crate::chapters::info(ID).expect("registered").report();
    record_params(&mut r, &p, dur, args.rtol);
    let ev = evidence::gather();
    for c in claims::all(doc, &ev, evidence::impact_energy(doc.restitution_max)) {
        r.claim(c);
    }
    scene_results(&mut r, &p, dur, args.rtol);
    r.table("validity-map", answers::validity_table(&ev.ladders));
    answer_results(&mut r, ctx);
    let map = answers::painleve_map(
        if ctx.quick { 5 } else { 12 },
        if ctx.quick { 0.5 } else { 1.0 },
    );
    r.table("painleve-map", answers::map_table(&map));
    if let Some(dir) = ctx.figure_dir(ID) {
        r.figures.extend(figures::painleve_boundary(&ev, &dir)?);
        r.figures.extend(figures::validity_map(&ev, &dir)?);
        r.figures.extend(figures::painleve_map(&map, &dir)?);
        r.figures.extend(figures::gaits(&dir)?);
        r.figures.extend(gif::write(&dir)?);
    }
    Ok(r)
}

/// The run's parameters into the report.
fn record_params(r: &mut ChapterReport, p: &InertiaParams, dur: f64, rtol: f64) {
    let b = &p.base;
    for (k, v) in [
        ("length_m", b.length_m),
        ("tip_mass_kg", b.mass_kg),
        ("rod_mass_kg", p.rod_mass_kg),
        ("stiffness_nm_per_rad", b.stiffness_nm_per_rad),
        ("damping_nms_per_rad", b.damping_nms_per_rad),
        ("mu", b.mu),
        ("theta0_rad", b.theta0_rad),
        ("gamma", b.gamma_accel()),
        ("frequency_hz", b.frequency_hz()),
        ("duration_s", dur),
        ("rtol", rtol),
        ("restitution", p.restitution),
        ("g_mps2", b.g_mps2),
    ] {
        r.param(k, v);
    }
}

/// The scene's run: chapter 6's model for `m_r = 0`, the singular-perturbation composite
/// for a rod too light for the full model's impacts, the full model otherwise.
fn scene_results(r: &mut ChapterReport, p: &InertiaParams, dur: f64, rtol: f64) {
    let massless = evidence::massless_speed(p, dur, rtol);
    if p.rod_mass_kg == 0.0 {
        // m_r = 0 is chapter 6's model: its run is the run
        r.result("mean_velocity_mps", massless);
        r.result("method", "massless (chapter 6)");
        r.result("outcome", "completed");
        r.result("painleve_events", json!([]));
        r.result("impacts", 0);
        r.result("alpha", "infinite (massless rod)");
        r.result("inertia_ratio", 0.0);
    } else if limit::uses_composite(p) {
        let c = limit::composite(p, dur, &evidence::options(rtol));
        r.result("mean_velocity_mps", c.mean_velocity_mps);
        r.result(
            "method",
            "singular perturbation (chapter 6's run + first-order correction)",
        );
        r.result("massless_limit_error_bound_mps", c.error_bound_mps);
        r.result("reference_rod_mass_kg", c.reference_rod_kg);
        full_run_results(r, &c.reference, "reference_");
        let alpha = p.geometry().alpha();
        if alpha.is_finite() {
            r.result("alpha", alpha);
        } else {
            r.result("alpha", "above 1e308 (a rod of the smallest doubles)");
        }
        r.result("inertia_ratio", p.inertia_ratio());
    } else {
        let run = evidence::scene_run(p, dur, rtol, 0.0);
        r.result("mean_velocity_mps", run.mean_velocity_mps);
        r.result("method", "event-driven (full model)");
        full_run_results(r, &run, "");
        r.result("alpha", p.geometry().alpha());
        r.result("inertia_ratio", p.inertia_ratio());
        r.result(
            "energy_budget_relative_residual",
            run.budget.relative_residual(),
        );
    }
    r.result("massless_mean_velocity_mps", massless);
}

/// Outcome, Painleve events and impacts of a full-model run, keys prefixed by `pre`
/// (the composite reports its reference run's under `reference_`, and its own outcome).
fn full_run_results(r: &mut ChapterReport, run: &InertiaRun, pre: &str) {
    r.result("outcome", run.outcome.label());
    if let InertiaOutcome::Invalid(why) = &run.outcome {
        r.result("outcome_reason", why.as_str());
    }
    let events: Vec<_> = run
        .painleve
        .iter()
        .take(100)
        .map(|e| json!({"t_s": e.t_s, "theta_rad": e.theta_rad, "mu": e.mu, "mu_p": e.mu_p, "case": e.case.name(), "slide": if e.sigma > 0.0 {"left"} else {"right"}}))
        .collect();
    r.result(&format!("{pre}painleve_event_count"), run.painleve.len());
    r.result(&format!("{pre}painleve_events"), json!(events));
    r.result(&format!("{pre}impacts"), run.impact_count);
    if !pre.is_empty() {
        // the composite has no events of its own: the outer (massless) model has none
        r.result("painleve_events", json!([]));
        r.result("impacts", run.impact_count);
    }
}

/// The chapter's answers that do not depend on the flags: the Glocker scene and the
/// toothpick.
fn answer_results(r: &mut ChapterReport, ctx: &Context) {
    let gl = evidence::glocker_scene();
    if let (Some(e), Some(i)) = (gl.painleve.first(), gl.impacts.first()) {
        r.result("glocker_painleve_time_s", e.t_s);
        r.result("glocker_painleve_theta_rad", e.theta_rad);
        r.result("glocker_iwc_impulse_ns", json!([i.j_t_ns, i.j_n_ns]));
    }
    r.result("glocker_outcome", gl.outcome.label());
    let tooth = answers::toothpicks(if ctx.quick { 2.0 } else { 10.0 });
    if let Some(t) = tooth.iter().find(|t| t.spring && t.scene == "self-locking") {
        r.result("toothpick_mean_velocity_mps", t.speed_mps);
    }
    r.table("toothpick", answers::toothpick_table(&tooth));
}

/// Falsification: each statement's printed number off by 10 % ([`mutations`]).
pub fn mutations() -> Vec<Mutation> {
    mutations::all()
}
