//! Chapter `effective-mass` (document section 2): the effective mass matrix of the
//! contact point of a leaning stick, and the sideways impulse a vertical collision
//! produces (dynamic jamming).
//!
//! The mass matrices come from rigid-body mechanics ([`crate::physics::rigid`]): the
//! mobility `W = Id/m + perp(r) perp(r)^T / I_G` of the contact point, inverted with
//! nalgebra. A second method (the Newton-Euler impulse equations, solved as a 5x5
//! linear system) checks every impulse ratio; the document's closed forms are checked
//! against both.
//!
//! Shape: `statements.rs` (the statements as data), `evidence.rs` (the computations,
//! once), `claims.rs` (pure functions of both), `rounding.rs` (the claims' rounding
//! bounds, arithmetic on the evidence), `figures.rs` (figures and the jamming table)
//! with `sketch.rs`, `mutations.rs`; this file: flags and orchestration.

mod claims;
mod evidence;
mod figures;
mod mutations;
mod rounding;
mod sketch;
mod statements;

use super::{info, Context};
use crate::error::Result;
use crate::flags::Flag;
use crate::physics::domain::Interval;
use crate::report::ChapterReport;
pub use mutations::Document;

/// Flags of the chapter (their help lines: [`FLAGS`]).
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Lean angle theta of the stick from the vertical (degrees), [`ANGLE_DEG`].
    #[arg(long, default_value_t = ANGLE_DEG.default_value())]
    pub angle_deg: f64,
    /// Coulomb friction coefficient mu at the contact point C, [`MU`].
    #[arg(long, default_value_t = MU.default_value())]
    pub mu: f64,
}

/// Largest accepted friction coefficient (dimensionless).
pub const MU_MAX: f64 = 2.0;

/// `--angle-deg`.
pub const ANGLE_DEG: Flag = Flag::new(
    "--angle-deg",
    "Lean angle theta of the stick from the vertical, positive towards +x; the default is the document's example (q = tan(theta) = 1)",
    "degrees",
    Interval::open(-90.0, 90.0),
)
.why("a stick leaning on its foot C: at 90 degrees it lies on the plate")
.default_value_is(45.0);

/// `--mu`.
pub const MU: Flag = Flag::new(
    "--mu",
    "Coulomb friction coefficient mu at the contact point C; the default is the authors' scene's",
    "dimensionless",
    Interval::closed(0.0, MU_MAX),
)
.why("dry contacts; the point-mass-limit check at I_G = 1e-6 m L^2 (gap ~ mu^3) holds to its 1e-5 tolerance up to 2")
.default_value_is(0.4);

/// The table of the chapter's physical flags (no `--g-mps2`: every ratio here is
/// independent of g, and the chapter refuses the flag).
pub const FLAGS: &[Flag] = &[ANGLE_DEG, MU];

/// Stick mass (kg) and length (m) of the authors' scene. Every ratio in this chapter
/// is independent of them (checked in the tests); they only set the units.
pub const MASS_KG: f64 = 1.0;
/// Stick length (m).
pub const LENGTH_M: f64 = 0.15;

/// Runs the chapter.
pub fn run(args: &Args, ctx: &Context) -> Result<ChapterReport> {
    let angle_deg = ANGLE_DEG.check(args.angle_deg)?;
    super::refuse_g("effective-mass", ctx)?;
    let mu = MU.check(args.mu)?;
    let mut r = info("effective-mass").expect("registered").report();
    r.param("angle_deg", angle_deg);
    r.param("mu", mu);
    r.param("mass_kg", MASS_KG);
    r.param("length_m", LENGTH_M);

    let theta = angle_deg.to_radians();
    let ev = evidence::gather(theta);
    for claim in claims::all(&statements::PRINTED, &ev, mu) {
        r.claim(claim);
    }
    results(&mut r, &ev, mu);
    r.table("jamming", figures::jamming_table(mu, angle_deg));
    if let Some(dir) = ctx.figure_dir("effective-mass") {
        r.figures.extend(figures::draw(&dir, &ev, mu, ctx.quick)?);
    }
    Ok(r)
}

/// The chapter's named results from the evidence at friction `mu`.
fn results(r: &mut ChapterReport, ev: &evidence::Evidence, mu: f64) {
    let theta = ev.at.theta;
    // Both criteria of C holding under a vertical impulse: the document's bound
    // tan(theta) < mu (exact for the point-mass model) and the uniform rod's own cone
    // test 3q/(4+q^2) <= mu (from its mass matrix).
    let self_locking = theta.tan().abs() < mu; // formula: tan(theta) < mu (document)
    let rod_jams = ev.at.rod.abs() <= mu; // formula: |J_l|/J_v <= mu (uniform rod)
    r.result("ratio_point_mass", ev.at.point_mass);
    r.result("ratio_uniform_rod", ev.at.rod);
    r.result("m_parallel_over_m", ev.stick[(0, 0)] / MASS_KG);
    r.result("m_perp_over_m", ev.stick[(1, 1)] / MASS_KG);
    r.result("best_angle_uniform_rod_deg", ev.best.theta_rad.to_degrees());
    r.result("self_locking", self_locking);
    r.result("rod_jams_under_vertical_impulse", rod_jams);
}


#[cfg(test)]
mod tests;
