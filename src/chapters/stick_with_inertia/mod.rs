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
mod rounding;
#[cfg(test)]
mod tests;
pub use mutations::Document;
mod statements;

pub use statements::{Statements, PRINTED};

use super::Context;
use crate::error::Result;
use crate::flags::stick::{self as stick_flags, StickFlags};
use crate::flags::Flag;
use crate::physics::domain::Interval;
use crate::physics::stick_inertia::limit;
use crate::physics::stick_inertia::run::{InertiaOutcome, InertiaRun};
use crate::physics::stick_inertia::InertiaParams;
use crate::report::ChapterReport;
use serde_json::json;

/// Chapter id.
pub const ID: &str = "stick-with-inertia";

/// Flags of the chapter: chapter 6's (the same entries, [`crate::flags::stick`]) with
/// the tip mass and the rod's mass in place of `--mass-kg`, and the restitution of
/// impacts. The help lines of the physical flags come from [`FLAGS`].
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// The stick's flags and its scene, shared with chapter 6.
    #[command(flatten)]
    pub stick: StickFlags,
    /// Point mass m at the top P (kg), [`TIP_MASS_KG`].
    #[arg(long = "tip-mass-kg", default_value_t = TIP_MASS_KG.default_value())]
    pub tip_mass_kg: f64,
    /// Mass of the rod (kg), [`crate::flags::stick::ROD_MASS_KG`] (shared with the lab).
    #[arg(long = "rod-mass-kg", default_value_t = stick_flags::ROD_MASS_KG.default_value())]
    pub rod_mass_kg: f64,
    /// Simulated time (s), [`DURATION_S`].
    #[arg(long = "duration-s")]
    pub duration_s: Option<f64>,
    /// Relative (and absolute) tolerance in the contact modes,
    /// [`crate::flags::stick::RTOL`].
    #[arg(long, default_value_t = stick_flags::RTOL.default_value())]
    pub rtol: f64,
    /// Restitution e of impacts at C, [`RESTITUTION`].
    #[arg(long, default_value_t = RESTITUTION.default_value())]
    pub restitution: f64,
}

/// `--tip-mass-kg`.
pub const TIP_MASS_KG: Flag = Flag::new(
    "--tip-mass-kg",
    "Point mass m at the top P (0 is a uniform stick, a toothpick)",
    "kg",
    Interval::closed(0.0, 10.0),
)
.why(stick_flags::WHY_MASS)
.default_value_is(1.0)
.coupled(); // m + m_r >= 1e-3 kg

/// `--duration-s`.
pub const DURATION_S: Flag = Flag::new(
    "--duration-s",
    "Simulated time",
    "s",
    Interval::closed(0.0, 100.0).open_below(),
)
.why("the work budget of one chapter run")
.default_is("10; 2 with --quick");

/// `--restitution`.
pub const RESTITUTION: Flag = Flag::new(
    "--restitution",
    "Restitution e of impacts at C (0 is the document's plastic impact)",
    "1",
    Interval::closed(0.0, 1.0),
)
.why("Stronge's energetic coefficient: above 1 an impact would create energy")
.default_value_is(0.0);

/// The table of the chapter's physical flags: chapter 6's entries and its own.
pub const FLAGS: &[Flag] = &[
    stick_flags::LENGTH_M,
    TIP_MASS_KG,
    stick_flags::ROD_MASS_KG,
    stick_flags::STIFFNESS,
    stick_flags::DAMPING,
    stick_flags::MU,
    stick_flags::THETA0_RAD,
    stick_flags::GAMMA,
    stick_flags::FREQUENCY_HZ,
    DURATION_S,
    stick_flags::RTOL,
    RESTITUTION,
    crate::flags::G,
];

/// Validated parameters and duration (s): each flag checked against its entry of
/// [`FLAGS`], the couplings of the masses and the damper, then the model's constructor.
pub fn setup(args: &Args, ctx: &Context) -> Result<(InertiaParams, f64)> {
    let base = args.stick.scene.params(ctx.g_mps2);
    crate::chapters::check_g(base.g_mps2)?;
    let v = args.stick.resolve(&base)?;
    let m = TIP_MASS_KG.check(args.tip_mass_kg)?;
    let m_r = stick_flags::ROD_MASS_KG.check(args.rod_mass_kg)?;
    stick_flags::ROD_MASS_KG.check_coupled(
        m_r,
        |m_r| m + m_r >= 1e-3,
        "m + m_r >= 1e-3 kg",
        "a lighter stick makes the pivot's time scale I_C/gamma shorter than the explicit integrator can follow at the drive's step",
    )?;
    stick_flags::DAMPING.check_coupled(
        v.damping,
        |d| d > 0.0 || m_r > 0.0 || v.stiffness == 0.0,
        "above 0 when --rod-mass-kg is 0 and --stiffness above 0",
        "the massless rod's angle in flight needs the damper",
    )?;
    let dur = DURATION_S.check(
        args.duration_s
            .unwrap_or(if ctx.quick { 2.0 } else { 10.0 }),
    )?;
    stick_flags::RTOL.check(args.rtol)?;
    let e = RESTITUTION.check(args.restitution)?;
    let p = InertiaParams {
        base: crate::flags::stick_params(&base, &v, m)?,
        rod_mass_kg: m_r,
        restitution: e,
    };
    let light = m_r > 0.0 && p.geometry().alpha() >= limit::ALPHA_SWITCH;
    stick_flags::DAMPING.check_coupled(
        v.damping,
        |d| d > 0.0 || !light,
        "above 0 for a rod this light (alpha = M l_G^2/I_G >= 1e9)",
        "its impacts lose 9 digits, and without a damper chapter 6's model is no limit to replace them",
    )?;
    Ok((p, dur))
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
    r.table(
        "gait-modes",
        answers::gait_modes_table(if ctx.quick { 2.0 } else { 10.0 }),
    );
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
        r.result("massless_limit_truncation_mps", c.truncation_mps);
        r.result("massless_limit_integration_mps", c.integration_mps);
        r.result("reference_rod_mass_kg", c.reference_rod_kg);
        full_run_results(r, &c.reference, "reference_");
        let alpha = p.geometry().alpha();
        if alpha.is_finite() {
            r.result("alpha", alpha);
        } else {
            r.result("alpha", "above 1e308 (a rod of the smallest doubles)");
        }
        inertia_ratio_result(r, p);
    } else {
        let run = evidence::scene_run(p, dur, rtol, 0.0);
        r.result("mean_velocity_mps", run.mean_velocity_mps);
        r.result("method", "event-driven (full model)");
        full_run_results(r, &run, "");
        r.result("alpha", p.geometry().alpha());
        inertia_ratio_result(r, p);
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
    r.result(&format!("{pre}max_penetration_m"), run.max_penetration_m);
    r.result(
        &format!("{pre}penetration_bound_m"),
        run.penetration_bound_m,
    );
    r.result(
        &format!("{pre}max_complementarity_ratio"),
        run.max_complementarity_ratio,
    );
    r.result(
        &format!("{pre}max_normal_residual_mps"),
        run.max_normal_residual_mps,
    );
    let total: f64 = run.mode_time_s.iter().sum();
    let frac: serde_json::Map<String, serde_json::Value> = crate::physics::stick::Mode::ALL
        .iter()
        .zip(run.mode_time_s)
        .map(|(m, s)| {
            (
                m.name().to_string(),
                json!(s / total.max(f64::MIN_POSITIVE)),
            )
        })
        .collect();
    r.result(&format!("{pre}mode_time_fraction"), json!(frac));
    let bridges: Vec<_> = run
        .bridges
        .iter()
        .take(100)
        .map(|b| json!({"t0_s": b.t0_s, "t1_s": b.t1_s, "step_s": b.h_s, "error_xc_m": b.error_xc_m}))
        .collect();
    r.result(&format!("{pre}moreau_jean_bridges"), json!(bridges));
    r.result(
        &format!("{pre}moreau_jean_bridge_count"),
        run.bridges.len(),
    );
    let bridge_s: f64 = run.bridges.iter().map(|b| b.t1_s - b.t0_s).sum();
    r.result(&format!("{pre}moreau_jean_bridge_time_s"), bridge_s);
    if !pre.is_empty() {
        // the composite has no events of its own: the outer (massless) model has none
        r.result("painleve_events", json!([]));
        r.result("impacts", run.impact_count);
    }
}

/// The chapter's answers that do not depend on the flags: the Glocker scene and the
/// toothpick.
fn answer_results(r: &mut ChapterReport, ctx: &Context) {
    use crate::physics::stick_inertia::PainleveRule;
    let gl = evidence::glocker_scene(PainleveRule::PreferContact);
    if let (Some(e), Some(i)) = (gl.painleve.first(), gl.impacts.first()) {
        r.result("glocker_painleve_time_s", e.t_s);
        r.result("glocker_painleve_theta_rad", e.theta_rad);
        r.result("glocker_iwc_impulse_ns", json!([i.j_t_ns, i.j_n_ns]));
    }
    r.result("glocker_outcome", gl.outcome.label());
    // the singular point: both rules, both answers
    let sep = evidence::glocker_scene(PainleveRule::PreferSeparation);
    if let (Some(c), Some(s)) = (
        evidence::glocker_rate_after(&gl),
        evidence::glocker_rate_after(&sep),
    ) {
        r.result("glocker_rate_prefer_contact_rad_s", c);
        r.result("glocker_rate_prefer_separation_rad_s", s);
    }
    r.result("glocker_outcome_prefer_separation", sep.outcome.label());
    let tooth = answers::toothpicks(if ctx.quick { 2.0 } else { 10.0 });
    if let Some(t) = tooth.iter().find(|t| t.spring && t.scene == "self-locking") {
        r.result("toothpick_mean_velocity_mps", t.speed_mps);
    }
    r.table("toothpick", answers::toothpick_table(&tooth));
}


/// `inertia_ratio` = I_P k / gamma^2 (dimensionless), or a text when there is no damper
/// (gamma = 0: the massless model has no flight law to be the limit of, the ratio is
/// infinite).
fn inertia_ratio_result(r: &mut ChapterReport, p: &InertiaParams) {
    let ratio = p.inertia_ratio();
    if ratio.is_finite() {
        r.result("inertia_ratio", ratio);
    } else {
        r.result(
            "inertia_ratio",
            "infinite (no damper: gamma = 0, the massless model has no flight law to compare)",
        );
    }
}
