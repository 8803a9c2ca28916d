//! The stick's scenes (document sections 4 and 5, and the authors' code): the
//! self-locking scene of the document, the authors' own scene, how a run starts, the
//! run of a scene under the physical or the printed rules, and the numbers every
//! reader of a run reports (phase fractions, event counts, the late mean speed of a
//! speed map's cell), and the gait as a limit cycle (the stroboscopic map `poincare`,
//! the saltation matrices `saltation`, one scene's analysis `limit_cycle`). Chapter 6
//! judges the document on these runs, chapter 8 starts its rod from the same scenes,
//! the lab animates them, the benchmarks time them and the exercises compute with them.

pub mod limit_cycle;
pub mod main_run;
pub mod poincare;
pub mod saltation;

use super::Choice;
use crate::numerics::hybrid::Options;
use crate::numerics::ode::Method;
use crate::physics::stick::printed::{simulate_printed, Printed};
use crate::physics::stick::run::{
    authors_code_state, initial_state, simulate_stick, Recording, RunSummary, StickOutcome,
};
use crate::physics::stick::XC;
use crate::physics::stick::{authors_scene, jamming_scene, Mode, State, StickModel, StickParams};
use serde_json::{json, Map, Value};
use std::collections::BTreeMap;

/// Standard gravity (m/s^2) where neither a flag nor the scene sets g.
pub const G_DEFAULT_MPS2: f64 = 9.81;

/// The scene whose values a run's flags override.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scene {
    /// The self-locking scene.
    Jamming,
    /// The authors' own scene.
    Authors,
}

impl Choice for Scene {
    const ALL: &'static [Self] = &[Scene::Jamming, Scene::Authors];

    fn name(self) -> &'static str {
        match self {
            Scene::Jamming => "jamming",
            Scene::Authors => "authors",
        }
    }

    fn about(self) -> &'static str {
        match self {
            Scene::Jamming => "Self-locking scene: the authors' stick with theta_0 = 0.3 rad (tan = 0.309 < mu = 0.4) on a plate at Gamma = 3, 30 Hz, g = 9.81 m/s^2: walks by stick-slip",
            Scene::Authors => "The authors' own scene: L = 0.15 m, m = 1 kg, k = 10 N m/rad, gamma = 0.01 N m s/rad, mu = 0.4, static angle 0.5 rad, Gamma = 10, f = 30 Hz, g = 10 m/s^2 (from the authors' public code, `main_rod.m` in toshankarghosh/toothpicks, not the document)",
        }
    }
}

impl Scene {
    /// The scene's parameters with `g` (m/s^2): the flag, or the scene's own (10 for
    /// the authors' scene, [`G_DEFAULT_MPS2`] otherwise).
    pub fn params(self, g_mps2: Option<f64>) -> StickParams {
        match self {
            Scene::Authors => authors_scene(g_mps2.unwrap_or(10.0)),
            Scene::Jamming => jamming_scene(g_mps2.unwrap_or(G_DEFAULT_MPS2)),
        }
    }
}

/// The starting state of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Start {
    /// At rest at the static angle.
    Static,
    /// The authors' `main_rod.m`, bug included.
    AuthorsCode,
}

impl Choice for Start {
    const ALL: &'static [Self] = &[Start::Static, Start::AuthorsCode];

    fn name(self) -> &'static str {
        match self {
            Start::Static => "static",
            Start::AuthorsCode => "authors-code",
        }
    }

    fn about(self) -> &'static str {
        match self {
            Start::Static => "At rest on the plate at the static angle (where the spring holds the weight), C at x = 0, t = 0",
            Start::AuthorsCode => "The authors' `main_rod.m` (github toshankarghosh/toothpicks), bug included: the rod at theta_0, not at the static angle, and `setup.IC.dyp = setup.IC.yc`, which gives P a vertical speed equal to the plate amplitude in metres (about 2.8 mm/s in their scene); the run starts in flight, as theirs does. For diffing against their code (use with `--scene authors`)",
        }
    }
}

/// The transition rules of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rules {
    /// The contact conditions decide.
    Physical,
    /// Table 1 and Algorithms 1 to 4 as printed.
    Printed,
}

impl Choice for Rules {
    const ALL: &'static [Self] = &[Rules::Physical, Rules::Printed];

    fn name(self) -> &'static str {
        match self {
            Rules::Physical => "physical",
            Rules::Printed => "printed",
        }
    }

    fn about(self) -> &'static str {
        match self {
            Rules::Physical => "The contact conditions decide (the workbook's rules, `physics::stick::rules`)",
            Rules::Printed => "Table 1 and Algorithms 1 to 4 executed as printed (`physics::stick::printed`): inequalities checked for violation, assignments in order, the last one wins",
        }
    }
}

/// The integrator of the contact modes (pivot and slides).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactMethod {
    /// DOP853.
    Dop853,
    /// DOPRI5.
    Dopri5,
}

impl Choice for ContactMethod {
    const ALL: &'static [Self] = &[ContactMethod::Dop853, ContactMethod::Dopri5];

    fn name(self) -> &'static str {
        match self {
            ContactMethod::Dop853 => "dop853",
            ContactMethod::Dopri5 => "dopri5",
        }
    }

    fn about(self) -> &'static str {
        match self {
            ContactMethod::Dop853 => "Dormand-Prince 8(5,3) (DOP853): order 8, 12 evaluations per step; at rtol 1e-10 it takes about 15 steps per drive cycle, the cheapest pair there (chapter 7)",
            ContactMethod::Dopri5 => "Dormand-Prince 5(4) (DOPRI5): order 5, 6 evaluations per step; about 55 steps per drive cycle at rtol 1e-10",
        }
    }
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

/// Palette index (`crate::plot::PALETTE`) of each mode's colour, [`Mode::ALL`] order:
/// flight blue, pivot vermillion, slide left bluish green, slide right reddish purple
/// (four distinct hues); the book's figures and the lab draw the modes with them.
pub const MODE_COLOUR: [usize; 4] = [0, 1, 2, 4];

/// Largest `omega t Gamma` accepted: the plate phase `omega t` is rounded to `eps omega
/// t`, which moves the plate acceleration, and the contact forces with it, by about
/// `3 eps omega t Gamma m g` (the factor 3 measured: 2.3e-10 m g at omega t Gamma =
/// 5.7e5); the cone check allows 1e-10 m g, so `omega t Gamma <= 1e-10 / (3 eps)`.
pub const PHASE_ROUNDING_MAX: f64 = 1.5e5;

/// Longest run (s) at frequency `f_hz` and `gamma`: `omega t Gamma <=`
/// [`PHASE_ROUNDING_MAX`] and at most 1e4 s.
pub fn max_duration_s(f_hz: f64, gamma: f64) -> f64 {
    let omega = 2.0 * std::f64::consts::PI * f_hz;
    if gamma > 0.0 {
        (PHASE_ROUNDING_MAX / (omega * gamma)).min(1e4) // formula: omega t Gamma <= 1e-10/(3 eps)
    } else {
        1e4
    }
}

/// Measured cost of one drive cycle of a run (s), for the build that runs: the test
/// (dev) build takes 3.3 s for 3e4 cycles of the jamming scene (2 cores), rounded up to
/// 1.2e-4; the release build about 1e-5 (criterion: about 100k cycles/s on the jamming
/// scene; 3 s for 2e5 cycles of a gently shaken plate at 1 kHz), rounded up to 1.5e-5,
/// so that the budget's estimate is the time a reader will wait.
pub const SECONDS_PER_CYCLE: f64 = if cfg!(debug_assertions) {
    1.2e-4
} else {
    1.5e-5
};

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
pub fn start_state(model: &StickModel, start: Start) -> State {
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
) -> (RunSummary, BTreeMap<&'static str, u64>) {
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
) -> (RunSummary, BTreeMap<&'static str, u64>) {
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
        o.insert(m.name().into(), json!(super::round(f[m.index()], 6)));
    }
    Value::Object(o)
}

/// Drive cycles of a speed map's cell (full, quick).
const MAP_CYCLES: (f64, f64) = (40.0, 12.0);
/// Start-transient cycles a cell leaves out of its late mean speed (full, quick).
const MAP_SKIP: (f64, f64) = (10.0, 4.0);

/// The late mean speed of C (m/s) of a speed map's cell, `(x_c(t_end) - x_c(t_skip)) /
/// (t_end - t_skip)` over whole drive cycles after a start transient, so that it shows
/// the steady gait and not the first hop from rest; NaN unless the run completed. The
/// cells of chapter 6's maps and of the lab's.
pub fn late_speed(p: &StickParams, opts: &Options, quick: bool) -> f64 {
    let t = p.period_s();
    let (cycles, skip) = if quick {
        (MAP_CYCLES.1, MAP_SKIP.1)
    } else {
        (MAP_CYCLES.0, MAP_SKIP.0)
    };
    let rec = Recording {
        sequence_cap: 0,
        trace_dt_s: skip * t, // samples at 0, skip T, 2 skip T, ... and at segment ends
        check_invariants: false,
        grid_only: false,
        list_cap: None,
    };
    let s = run_scene(p, cycles * t, opts, rec);
    if s.outcome != StickOutcome::Completed {
        return f64::NAN;
    }
    let t_skip = skip * t;
    let first = s.trace.iter().find(|x| x.t_s >= t_skip * (1.0 - 1e-12));
    match (first, s.trace.last()) {
        (Some(a), Some(b)) if b.t_s > a.t_s => (b.y[XC] - a.y[XC]) / (b.t_s - a.t_s), // formula: late mean speed
        _ => f64::NAN,
    }
}

/// The CSV of a run's mode switches (`workbook stick-state-machine --events`, the lab's
/// download): one header line, then one line per switch.
pub fn events_csv(s: &RunSummary) -> String {
    let mut out = String::from("t_s,from,to,theta_rad,theta_dot_rad_s,x_c_m,f_x_n,f_z_n\n");
    for w in &s.switches {
        let to = w.to.map_or("stop", |m| m.name());
        out.push_str(&format!(
            "{:.12},{},{},{:.12},{:.12},{:.12},{:.9},{:.9}\n",
            w.t_s,
            w.from.name(),
            to,
            w.theta_rad,
            w.omega_rad_s,
            w.x_c_m,
            w.fx_n,
            w.fz_n
        ));
    }
    out
}
