//! Chapter `locomotion-definition` (document section 1): locomotion is motion with an
//! average velocity strictly outside the convex hull of the media velocities.
//!
//! The test itself is [`crate::physics::locomotion`] (exact predicates, degenerate
//! hulls, boundary = not locomotion). The chapter checks the document's sailing cases,
//! classifies the reader's own scene and draws the hull with the test velocities.
//!
//! Shape: `statements.rs` (the statements as data), `evidence.rs` (the hull test run
//! on an example), `claims.rs` (pure functions of the statements), `figures.rs`,
//! `mutations.rs`; this file: flags and orchestration.

mod claims;
mod evidence;
mod figures;
mod mutations;
mod statements;

use super::{info, Context};
use crate::error::{parse_pair, Result};
use crate::flags::Flag;
use crate::physics::domain::Interval;
use crate::physics::locomotion::{in_exact_range, is_locomotion, reason, V2};
use crate::plot::save_drawing;
use crate::report::ChapterReport;
use figures::{HullFigure, Panel};
pub use mutations::Document;
use statements::{CASES, WATER, WIND};

/// Flags of the chapter (their help lines: [`FLAGS`]).
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Average velocity of the object as X,Y in m/s.
    #[arg(long, value_parser = parse_pair, default_value = "1,3", allow_hyphen_values = true)]
    pub object_velocity: V2,
    /// Average velocity of one medium as X,Y in m/s; repeat the flag for several media.
    #[arg(long = "medium-velocity", value_parser = parse_pair, default_values = ["5,0", "0,0"], allow_hyphen_values = true)]
    pub medium_velocity: Vec<V2>,
}

/// A velocity pair's entry: each part 0 or `1e-100 <= |part| <= 1e100` (the range
/// field holds the magnitudes; either sign and 0 are accepted too).
const fn pair(name: &'static str, about: &'static str) -> Flag {
    Flag::new(name, about, "m/s", Interval::closed(1e-100, 1e100))
        .shown_as("X,Y with each part 0 or 1e-100 <= |part| <= 1e100")
        .why("where the hull test is exact")
}

/// The table of the chapter's flags. No `--g-mps2`: the chapter is kinematics and
/// refuses the flag.
pub const FLAGS: &[Flag] = &[
    pair("--object-velocity", "Average velocity of the object as X,Y (horizontal plane; negative parts are fine: --object-velocity -2,0)")
        .default_is("default: 1,3, a boat reaching across the wind"),
    pair("--medium-velocity", "Average velocity of one medium as X,Y; repeat the flag for several media")
        .default_is("default: wind 5,0 and still water 0,0, the document's sailing scene"),
];

fn validate(flag: &str, v: V2) -> Result<V2> {
    let entry = FLAGS.iter().find(|f| f.name == flag).unwrap_or(&FLAGS[0]);
    for x in v {
        entry.check_coupled(x, in_exact_range, &entry.range_text(), entry.reason)?;
    }
    Ok(v)
}

/// Runs the chapter.
pub fn run(args: &Args, ctx: &Context) -> Result<ChapterReport> {
    super::refuse_g("locomotion-definition", ctx)?;
    let object = validate("--object-velocity", args.object_velocity)?;
    let media: Vec<V2> = args
        .medium_velocity
        .iter()
        .map(|&m| validate("--medium-velocity", m))
        .collect::<Result<_>>()?;
    let mut r = info("locomotion-definition").expect("registered").report();
    r.param("object_velocity_mps", vec![object[0], object[1]]);
    r.param(
        "medium_velocities_mps",
        media.iter().map(|m| vec![m[0], m[1]]).collect::<Vec<_>>(),
    );

    for claim in claims::all(&statements::PRINTED) {
        r.claim(claim);
    }
    r.result("is_locomotion", is_locomotion(object, &media));
    r.result("reason", reason(object, &media));

    if let Some(dir) = ctx.figure_dir("locomotion-definition") {
        let mut scene = Panel {
            title: "Your scene".into(),
            media: media.clone(),
            tests: vec![(object, "object".into())],
        };
        if media.len() == 2 && media.contains(&WIND) && media.contains(&WATER) {
            scene.title = "Your scene (wind 5,0 m/s, still water)".into();
        }
        let sailing = Panel {
            title: "The document's sailing cases".into(),
            media: vec![WIND, WATER],
            tests: CASES
                .iter()
                .filter(|c| !c.label.is_empty())
                .map(|c| (c.object, c.label.to_string()))
                .collect(),
        };
        let fig = HullFigure {
            panels: vec![scene, sailing],
        };
        r.figures
            .extend(save_drawing(&fig, &dir, "convex-hull", fig.size_px())?);
    }
    Ok(r)
}

