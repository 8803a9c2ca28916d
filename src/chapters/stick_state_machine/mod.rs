//! Chapter `stick-state-machine` (document sections 4 and 5): the hybrid simulation of
//! the leaning stick: flight in closed form, pivot and slides integrated with a
//! Dormand-Prince pair (8(5,3) by default, 5(4) on request), the collision map, the transition rules decided by the contact
//! conditions, and the energy budget. Every equation, every row of Table 1 and every
//! rule of Algorithms 1 to 4 gets a claim (see `claims.rs`).
//!
//! Shape (ARCHITECTURE.md): `statements.rs` (the document's statements as data),
//! `evidence.rs` (the runs, computed once), `claims.rs` with its parts `collision_claims.rs`,
//! `rule_claims.rs`, `slide_rules.rs` and `table1_claims.rs` (pure functions of statements and evidence),
//! `figures.rs`, `mutations.rs`; the limit-cycle section has its own `cycle_claims.rs`
//! and `cycle_report.rs`. This file: the flags and the orchestration.

mod claims;
mod collision_claims;
pub mod cycle_claims;
mod cycle_report;
mod events;
mod evidence;
mod figures;
pub mod gait;
mod gait_map;
mod gap_claims;
mod impulse;
mod lagrange;
pub mod limit_cycle;
pub mod main_run;
mod maps;
mod mutations;
pub mod poincare;
mod printed_table;
mod rest_scan;
mod rule_claims;
pub mod saltation;
mod sensitivity;
mod slide_rules;
mod statements;
mod table1_claims;

pub use events::{events_csv, EVENTS_CAP};
pub use mutations::Document;

use super::Context;
use crate::error::{check, Result};
use crate::flags::stick::{self as stick_flags, StickFlags};
use crate::flags::Flag;
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::domain::Interval;
use crate::physics::stick::printed::{simulate_printed, Printed};
use crate::physics::stick::run::{
    authors_code_state, initial_state, simulate_stick, Recording, RunSummary,
};
use crate::physics::stick::{
    authors_scene, jamming_scene, CollisionAngle, Mode, StickModel, StickParams,
};
use serde_json::{json, Map, Value};

/// Chapter id.
pub const ID: &str = "stick-state-machine";

/// The scene whose values the flags override.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Scene {
    /// Self-locking scene: the authors' stick with theta_0 = 0.3 rad (tan = 0.309 < mu =
    /// 0.4) on a plate at Gamma = 3, 30 Hz, g = 9.81 m/s^2: walks by stick-slip.
    Jamming,
    /// The authors' own scene: L = 0.15 m, m = 1 kg, k = 10 N m/rad, gamma = 0.01 N m
    /// s/rad, mu = 0.4, static angle 0.5 rad, Gamma = 10, f = 30 Hz, g = 10 m/s^2 (from
    /// the authors' public code, `main_rod.m` in toshankarghosh/toothpicks, not the document).
    Authors,
}

/// The starting state of the main run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Start {
    /// At rest on the plate at the static angle (where the spring holds the weight),
    /// C at x = 0, t = 0.
    Static,
    /// The authors' `main_rod.m` (github toshankarghosh/toothpicks), bug included: the
    /// rod at theta_0, not at the static angle, and `setup.IC.dyp = setup.IC.yc`, which
    /// gives P a vertical speed equal to the plate amplitude in metres (about 2.8 mm/s
    /// in their scene); the run starts in flight, as theirs does. For diffing against
    /// their code (use with `--scene authors`).
    AuthorsCode,
}

/// The integrator of the contact modes (pivot and slides).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ContactMethod {
    /// Dormand-Prince 8(5,3) (DOP853): order 8, 12 evaluations per step; at rtol 1e-10
    /// it takes about 15 steps per drive cycle, the cheapest pair there (chapter 7).
    Dop853,
    /// Dormand-Prince 5(4) (DOPRI5): order 5, 6 evaluations per step; about 55 steps per
    /// drive cycle at rtol 1e-10.
    Dopri5,
}

impl ContactMethod {
    /// The numerics method.
    pub fn method(self) -> Method {
        match self {
            ContactMethod::Dop853 => Method::Dop853,
            ContactMethod::Dopri5 => Method::Dopri5,
        }
    }
}

/// The parser of `--collision-angle` (the physics enum stays free of clap).
fn collision_angle_parser() -> impl clap::builder::TypedValueParser<Value = CollisionAngle> {
    use clap::builder::TypedValueParser as _;
    clap::builder::PossibleValuesParser::new(["actual", "reset"]).map(|s| match s.as_str() {
        "reset" => CollisionAngle::Reset,
        _ => CollisionAngle::Actual,
    })
}

/// The transition rules of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Rules {
    /// The contact conditions decide (the workbook's rules, `physics::stick::rules`).
    Physical,
    /// Table 1 and Algorithms 1 to 4 executed as printed (`physics::stick::printed`):
    /// inequalities checked for violation, assignments in order, the last one wins.
    Printed,
}

/// Flags of the chapter. Unset physical flags take the chosen scene's value. Ranges: a
/// box within a factor 10 of the authors' stick (wider where a limit is physical: a free
/// hinge, a still plate), over which the chapter's checks are run at the corners
/// (tests/cli.rs); the duration is bounded by the rounding of the plate phase. The help
/// lines of the physical flags come from [`FLAGS`].
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Scene whose values the other flags override [default: jamming].
    #[arg(long, value_enum, default_value_t = Scene::Jamming)]
    pub scene: Scene,
    /// The stick's flags, shared with chapter 8 ([`crate::flags::stick`]).
    #[command(flatten)]
    pub stick: StickFlags,
    /// Tip mass m (kg), [`MASS_KG`].
    #[arg(long = "mass-kg")]
    pub mass_kg: Option<f64>,
    /// Simulated time (s), [`DURATION_S`].
    #[arg(long = "duration-s")]
    pub duration_s: Option<f64>,
    /// Lever arm of the collision map: `actual` (the angle at landing, what the physics
    /// supports) or `reset` (the document's theta_0) [default: actual].
    #[arg(long = "collision-angle", default_value = "actual", value_parser = collision_angle_parser())]
    pub collision_angle: CollisionAngle,
    /// Relative (and absolute) tolerance in the contact modes,
    /// [`crate::flags::stick::RTOL`].
    #[arg(long, default_value_t = 1e-10)]
    pub rtol: f64,
    /// Integrator of the contact modes; both locate events on their dense output
    /// [default: dop853].
    #[arg(long, value_enum, default_value_t = ContactMethod::Dop853)]
    pub method: ContactMethod,
    /// Starting state of the main run: `static` (at rest at the static angle) or
    /// `authors-code` (the authors' main_rod.m initial state, bug included) [default: static].
    #[arg(long, value_enum, default_value_t = Start::Static)]
    pub start: Start,
    /// Write every mode switch of the main run as CSV to this file (time s, from-mode,
    /// to-mode, theta rad, theta' rad/s, x_C m, F_x N, F_z N of the mode left), for
    /// diffing against another simulator.
    #[arg(long = "events", value_name = "FILE", value_hint = clap::ValueHint::FilePath)]
    pub events: Option<std::path::PathBuf>,
    /// Transition rules: `physical` (the contact conditions) or `printed` (the document's
    /// Table 1 and Algorithms 1 to 4, run as printed) [default: physical].
    #[arg(long, value_enum, default_value_t = Rules::Physical)]
    pub rules: Rules,
}

/// `--mass-kg`: the tip mass of chapter 6's stick.
pub const MASS_KG: Flag = Flag::new("--mass-kg", "Tip mass m", "kg", Interval::closed(0.1, 10.0))
    .why(stick_flags::BOX10)
    .default_is("scene: 1");

/// `--duration-s`: its bound depends on `--frequency-hz` and `--gamma` (the range
/// field holds it at the jamming scene: 1.5e5/(2 pi 30 x 3) = 265.26 s).
pub const DURATION_S: Flag = Flag::new(
    "--duration-s",
    "Simulated time",
    "s",
    Interval::closed(0.0, 265.0).open_below(),
)
.shown_as("0 < t <= 1e4 s and omega t Gamma <= 1.5e5")
.why("the rounding of the plate phase must stay under the cone check's 1e-10 m g; runs estimated beyond 10 minutes (f t > 4e7 drive cycles in a release build, 5e6 in a debug build) need --allow-long-runs")
.default_is("10; 2 with --quick")
.coupled()
.budgeted();

/// The table of the chapter's physical flags (`crate::flags`).
pub const FLAGS: &[Flag] = &[
    stick_flags::LENGTH_M,
    MASS_KG,
    stick_flags::STIFFNESS,
    stick_flags::DAMPING,
    stick_flags::MU,
    stick_flags::THETA0_RAD,
    stick_flags::GAMMA,
    stick_flags::FREQUENCY_HZ,
    DURATION_S,
    stick_flags::RTOL,
    crate::flags::G,
];

/// The scene's parameters with `g` (m/s^2): the flag, or the scene's own (10 for the
/// authors' scene, 9.81 otherwise).
pub fn scene_params(scene: Scene, g_flag: Option<f64>) -> StickParams {
    match scene {
        Scene::Authors => authors_scene(g_flag.unwrap_or(10.0)),
        Scene::Jamming => jamming_scene(g_flag.unwrap_or(Context::G_DEFAULT_MPS2)),
    }
}

/// Largest `omega t Gamma` accepted: the plate phase `omega t` is rounded to `eps omega
/// t`, which moves the plate acceleration, and the contact forces with it, by about
/// `3 eps omega t Gamma m g` (the factor 3 measured: 2.3e-10 m g at omega t Gamma =
/// 5.7e5); the cone check allows 1e-10 m g, so `omega t Gamma <= 1e-10 / (3 eps)`.
pub const PHASE_ROUNDING_MAX: f64 = 1.5e5;

/// Longest accepted duration (s) at frequency `f_hz` and `gamma`: `omega t Gamma <=`
/// [`PHASE_ROUNDING_MAX`] and at most 1e4 s.
pub fn max_duration_s(f_hz: f64, gamma: f64) -> f64 {
    let omega = 2.0 * std::f64::consts::PI * f_hz;
    if gamma > 0.0 {
        (PHASE_ROUNDING_MAX / (omega * gamma)).min(1e4) // formula: omega t Gamma <= 1e-10/(3 eps)
    } else {
        1e4
    }
}

/// `x` (> 0) rounded down to `digits` significant digits, as text: a bound printed in
/// an error line that is never above the bound checked.
fn floor_digits(x: f64, digits: i32) -> String {
    let scale = 10f64.powi(digits - 1 - x.log10().floor() as i32);
    crate::error::num((x * scale).floor() / scale)
}

/// Measured cost of one drive cycle of the main run (s), for the build that runs: the
/// test (dev) build takes 3.3 s for 3e4 cycles of the jamming scene (2 cores), rounded
/// up to 1.2e-4; the release build about 1e-5 (criterion: about 100k cycles/s on the
/// jamming scene; 3 s for 2e5 cycles of a gently shaken plate at 1 kHz), rounded up to
/// 1.5e-5, so that the budget's estimate is the time a reader will wait.
pub const SECONDS_PER_CYCLE: f64 = if cfg!(debug_assertions) {
    1.2e-4
} else {
    1.5e-5
};

/// Validated parameters, duration (s) and options from the flags: each checked
/// against its entry of [`FLAGS`], then by the model's constructor.
pub fn setup(args: &Args, ctx: &Context) -> Result<(StickParams, f64, Options)> {
    let base = scene_params(args.scene, ctx.g_mps2);
    let v = args.stick.resolve(&base)?;
    if v.damping == 0.0 && v.stiffness > 0.0 {
        // formula: in flight the massless rod's moment balance is k (theta - theta_0) + gamma theta' = 0 (C.3)
        return Err(crate::error::WorkbookError::bad_input(
            "--damping",
            v.damping,
            "0 < value <= 0.1 (N m s/rad) when --stiffness is above 0: in flight the massless rod follows θ' = -(k/γ)(θ - θ₀) (C.3), undetermined at γ = 0 (0 is accepted only with --stiffness 0)",
        ));
    }
    let m = MASS_KG.check(args.mass_kg.unwrap_or(base.mass_kg))?;
    let default_duration = if ctx.quick { 2.0 } else { 10.0 };
    let t_max = max_duration_s(v.frequency_hz, v.gamma);
    let dur = check(
        "--duration-s",
        args.duration_s.unwrap_or(default_duration),
        |v| v > 0.0 && v <= t_max,
        &format!(
            "0 < value <= {} (s): omega t Gamma <= {} and t <= 1e4 s; the plate phase omega t carries a rounding of eps omega t, a force error of ~3 eps omega t Gamma m g that the cone check's 1e-10 m g must cover",
            floor_digits(t_max, 6),
            crate::error::num(PHASE_ROUNDING_MAX)
        ),
    )?;
    let rtol = stick_flags::RTOL.check(args.rtol)?;
    let mut p = crate::flags::stick_params(&base, &v, m)?;
    p.collision_angle = args.collision_angle;
    let opts = Options {
        method: args.method.method(),
        control: StepControl::tol(rtol, rtol),
        ..Options::default()
    };
    Ok((p, dur, opts))
}

/// One run of a scene from its static equilibrium (or theta_0 if the spring cannot hold
/// the stick up), C at x = 0 on the plate at t = 0.
pub fn run_scene(p: &StickParams, duration_s: f64, opts: &Options, rec: Recording) -> RunSummary {
    run_scene_from(p, Start::Static, duration_s, opts, rec)
}

/// One run of a scene from the chosen starting state.
pub fn run_scene_from(
    p: &StickParams,
    start: Start,
    duration_s: f64,
    opts: &Options,
    rec: Recording,
) -> RunSummary {
    let model = StickModel::new(*p);
    simulate_stick(
        &model,
        0.0,
        start_state(&model, start),
        duration_s,
        opts,
        rec,
    )
}

/// The state a run starts from.
fn start_state(model: &StickModel, start: Start) -> crate::physics::stick::State {
    let p = &model.p;
    match start {
        Start::Static => initial_state(model, 0.0, p.static_angle().unwrap_or(p.theta0_rad)),
        Start::AuthorsCode => authors_code_state(model),
    }
}

/// One run of a scene under a printed rule set, from the same start as [`run_scene`]:
/// the summary and the counts of the printed lines that fired.
pub fn run_printed(
    p: &StickParams,
    rules: Printed,
    duration_s: f64,
    opts: &Options,
    rec: Recording,
) -> (RunSummary, std::collections::BTreeMap<&'static str, u64>) {
    run_printed_from(p, rules, Start::Static, duration_s, opts, rec)
}

/// [`run_printed`] from the chosen starting state.
pub fn run_printed_from(
    p: &StickParams,
    rules: Printed,
    start: Start,
    duration_s: f64,
    opts: &Options,
    rec: Recording,
) -> (RunSummary, std::collections::BTreeMap<&'static str, u64>) {
    let model = StickModel::new(*p);
    simulate_printed(
        &model,
        rules,
        0.0,
        start_state(&model, start),
        duration_s,
        opts,
        rec,
    )
}

/// The `event_counts` object: transitions `from_to_to` that occurred, plus `jams`.
pub fn event_counts(s: &RunSummary) -> Value {
    let mut o = Map::new();
    for from in Mode::ALL {
        for to in Mode::ALL {
            let n = s.transitions[from.index()][to.index()];
            if n > 0 {
                o.insert(format!("{}_to_{}", from.name(), to.name()), json!(n));
            }
        }
    }
    o.insert("jams".into(), json!(s.jams));
    Value::Object(o)
}

/// The `phase_fractions` object.
pub fn phase_fractions(s: &RunSummary) -> Value {
    let f = s.phase_fractions();
    let mut o = Map::new();
    for m in Mode::ALL {
        o.insert(m.name().into(), json!(round(f[m.index()], 6)));
    }
    Value::Object(o)
}

/// Rounds to `d` significant digits for the results (keeps JSON and tables stable
/// beyond the checked accuracy).
pub fn round(x: f64, d: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return if x.is_finite() { 0.0 } else { f64::NAN };
    }
    let e = d - 1 - x.abs().log10().floor() as i32;
    if e > 300 {
        return x; // 10^e would overflow: x is tiny and already short enough
    }
    let s = 10f64.powi(e);
    (x * s).round() / s
}

/// Runs the chapter.
pub fn run(args: &Args, ctx: &Context) -> Result<crate::report::ChapterReport> {
    let (p, dur, opts) = setup(args, ctx)?;
    let mut r = super::info(ID).expect("registered").report();
    for (key, value) in main_run::params(args, &p, dur) {
        r.param(key, value);
    }
    // The events file is checked before the run (an unwritable path fails at once) but
    // written only after it, whole (a refused or interrupted run leaves it as it was).
    if let Some(path) = &args.events {
        crate::output::probe_file(path).map_err(|e| events::events_error(args, &e.to_string()))?;
    }
    let est = main_run::check_work(&p, dur, ctx.allow_long_runs)?;
    let bar = crate::sweep::spinner("stick-state-machine: main run", est);
    // the claims are judged on the physical run; --rules printed reports the printed one
    let mut rec = main_run::recording(0.0);
    if args.events.is_some() {
        rec.sequence_cap = EVENTS_CAP; // every switch, up to the cap (then the cut is said)
    }
    let (mut physical, mut main, mut fired) = main_run::run_main(args, &p, dur, &opts, rec);
    let mut main_opts = opts; // the evidence runs keep the chosen method
    if let Some(o) = main_run::dopri5_fallback(&physical, &opts) {
        let why = format!("DOP853 produced a non-finite state ({}); the run was repeated with DOPRI5 at the same tolerance (near the vertical the slides' C.14 divides by sin(θ) and the order-8 stages overflow)", physical.outcome.label());
        r.note(why.clone());
        r.result("contact_method_fallback", why);
        (physical, main, fired) = main_run::run_main(args, &p, dur, &o, rec);
        main_opts = o;
    }
    bar.finish_and_clear();
    if let Some(path) = &args.events {
        events::write_events(&mut r, path, &main).map_err(|e| events::events_error(args, &e))?;
    }
    for (key, value) in main_run::results(&mut main, &p, &fired) {
        r.result(key, value);
    }
    sensitivity::start_note(&mut r, &p, args.start);
    if args.rules == Rules::Physical {
        sensitivity::tolerance_sensitivity(
            &mut r, &p, args.start, dur, &main_opts, args.rtol, &physical,
        );
    }

    // The evidence runs are the document's two scenes with the document's values, g
    // included (10 and 9.81 m/s^2): like every other physical flag, --g-mps2 sets this
    // run (`params`), not the scenes the document's claims are checked on.
    let scenes = Context {
        g_mps2: None,
        ..ctx.clone()
    };
    let ev = evidence::collect(&scenes, &opts);
    r.param(
        "evidence_g_mps2",
        json!({"authors": ev.params[0].g_mps2, "jamming": ev.params[1].g_mps2}),
    );
    claims::add_all(&mut r, &ev, &physical, &p, args.rtol);
    cycle_report::add(&mut r, &ev, &p); // the gait as a limit cycle (course section)
    r.table("stick-scenes", evidence::scenes_table(&ev));
    r.table(
        "stick-printed-errata",
        printed_table::errata_table(&ev, &opts),
    );

    if let Some(dir) = ctx.figure_dir(ID) {
        let paths = figures::draw_all(&dir, &p, &physical, &ev, ctx, &main_opts)?;
        r.figures.extend(paths);
        r.figures
            .extend(cycle_report::figure(&dir, &ev, &opts, ctx)?);
    }
    Ok(r)
}

