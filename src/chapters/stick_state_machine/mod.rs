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
//! and `cycle_report.rs` (the analysis they judge, `crate::scenes::stick::limit_cycle`,
//! is a scene-level tool the exercises use too). Unit tests of the chapter's internals:
//! `tests.rs`. This file: the flags and the orchestration.

mod at_states;
mod claims;
mod collision_claims;
mod cycle_claims;
mod cycle_report;
mod events;
mod evidence;
mod figures;
mod gait;
mod gait_map;
mod gap_claims;
mod impulse;
mod lagrange;
mod maps;
mod mutations;
mod printed_table;
mod rest_scan;
mod rounding;
mod rule_claims;
mod sensitivity;
mod slide_rules;
mod statements;
mod table1_claims;

pub use mutations::Document;

use super::Context;
use crate::error::Result;
use crate::flags::main_run::RunFlags;
use crate::flags::Flag;
// The scenes this chapter judges the document on, and their runs (`crate::scenes`):
// named here so that the chapter's files use them as `super::...`.
use crate::scenes::round;
use crate::scenes::stick::main_run;
use crate::scenes::stick::{limit_cycle, poincare, Rules, Scene, Start};
use crate::scenes::stick::{run_printed, run_scene, run_scene_from};
use events::EVENTS_CAP;
use serde_json::json;

/// Chapter id.
pub const ID: &str = "stick-state-machine";

/// Flags of the chapter: the main run's ([`crate::flags::main_run::RunFlags`], which
/// the lab validates too) and the `--events` file.
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// The main run's flags, the stick's and its scene's among them.
    #[command(flatten)]
    pub run: RunFlags,
    /// Write every mode switch of the main run as CSV to this file (time s, from-mode,
    /// to-mode, theta rad, theta' rad/s, x_C m, F_x N, F_z N of the mode left), for
    /// diffing against another simulator.
    #[arg(long = "events", value_name = "FILE", value_hint = clap::ValueHint::FilePath)]
    pub events: Option<std::path::PathBuf>,
}

/// The table of the chapter's physical flags: the main run's.
pub const FLAGS: &[Flag] = crate::flags::main_run::FLAGS;

/// Runs the chapter.
pub fn run(args: &Args, ctx: &Context) -> Result<crate::report::ChapterReport> {
    let (p, dur, opts) = args.run.setup(ctx.g_mps2, ctx.quick)?;
    let settings = args.run.settings();
    let mut r = super::info(ID).expect("registered").report();
    for (key, value) in main_run::params(&settings, &p, dur) {
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
    let (mut physical, mut main, mut fired) = main_run::run_main(&settings, &p, dur, &opts, rec);
    let mut main_opts = opts; // the evidence runs keep the chosen method
    if let Some(o) = main_run::dopri5_fallback(&physical, &opts) {
        let why = format!("DOP853 produced a non-finite state ({}); the run was repeated with DOPRI5 at the same tolerance (near the vertical the slides' C.14 divides by sin(θ) and the order-8 stages overflow)", physical.outcome.label());
        r.note(why.clone());
        r.result("contact_method_fallback", why);
        (physical, main, fired) = main_run::run_main(&settings, &p, dur, &o, rec);
        main_opts = o;
    }
    bar.finish_and_clear();
    if let Some(path) = &args.events {
        events::write_events(&mut r, path, &main).map_err(|e| events::events_error(args, &e))?;
    }
    for (key, value) in main_run::results(&mut main, &p, &fired) {
        r.result(key, value);
    }
    sensitivity::start_note(&mut r, &p, settings.start);
    if settings.rules == Rules::Physical {
        sensitivity::tolerance_sensitivity(
            &mut r,
            &p,
            settings.start,
            dur,
            &main_opts,
            settings.rtol,
            &physical,
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
    claims::add_all(&mut r, &ev, &physical, &p, settings.rtol);
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


#[cfg(test)]
mod tests;
