//! Chapter `asymmetric-shaking` (document section 3.2): linear friction cannot make a
//! block walk on a zero-mean shaken plate, Coulomb friction can.
//!
//! The chapter shape (ARCHITECTURE.md): the document's statements as data
//! ([`statements`]), the runs computed once ([`evidence`], on the event-driven block
//! model of `physics::block` driven by [`sims`], and the work-precision ladder of
//! [`work`]), the claims as pure functions of both ([`claims`]), the figures, and the
//! falsification mutations ([`mutations`]: edits of the statements judged by the same
//! claims). Closed forms: `physics::sawtooth` (two-velocity sawtooth, linear orbit) and
//! `physics::sawtooth::biharmonic` (smooth drive).

mod claims;
mod evidence;
mod figures;
mod mutations;
pub use mutations::Document;
mod sims;
mod statements;
mod work;

use super::{info, Context};
use crate::error::Result;
use crate::flags::Flag;
use crate::physics::domain::Interval;
use crate::physics::plate::{PlateMotion, Sawtooth};
use crate::physics::sawtooth::mu_min_for_lock;
use crate::report::ChapterReport;

/// The chapter id.
pub const ID: &str = "asymmetric-shaking";

/// Longest transient (whole periods from rest to the first stick) the chapter accepts:
/// bounds `--mu` from below.
pub const MAX_LOCK_PERIODS: f64 = 1e4;

/// Largest friction coefficient accepted (dimensionless).
pub const MU_MAX: f64 = 10.0;

/// Largest ratio of the fast to the slow speed accepted.
pub const MAX_SPEED_RATIO: f64 = 1e3;

/// Flags of the chapter: the two-velocity sawtooth and the two friction laws. Their
/// help lines: [`FLAGS`].
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Coulomb friction coefficient mu between block and plate, [`MU`].
    #[arg(long, default_value_t = MU.default_value())]
    pub mu: f64,
    /// Plate speed of the slow stroke (m/s), [`SLOW_VELOCITY_MPS`].
    #[arg(long, default_value_t = SLOW_VELOCITY_MPS.default_value())]
    pub slow_velocity_mps: f64,
    /// Plate speed of the fast stroke back (m/s), [`FAST_VELOCITY_MPS`].
    #[arg(long, default_value_t = FAST_VELOCITY_MPS.default_value())]
    pub fast_velocity_mps: f64,
    /// Duration of the slow stroke (s), [`SLOW_DURATION_S`].
    #[arg(long, default_value_t = SLOW_DURATION_S.default_value())]
    pub slow_duration_s: f64,
    /// Duration of the fast stroke (s), optional, [`FAST_DURATION_S`].
    #[arg(long)]
    pub fast_duration_s: Option<f64>,
    /// Linear viscous friction coefficient per unit mass c (1/s), [`VISCOUS_C`].
    #[arg(long, default_value_t = VISCOUS_C.default_value())]
    pub viscous_c: f64,
}

/// `--mu`.
pub const MU: Flag = Flag::new(
    "--mu",
    "Coulomb friction coefficient mu between block and plate",
    "dimensionless",
    Interval::closed(0.0, MU_MAX).open_below(),
)
.why("dry friction; it must also let the block reach its steady state within 1e4 periods: mu >= a/(g (T_s + 1e4 (T_s - T_f)))")
.default_value_is(0.3);

/// `--slow-velocity-mps`.
pub const SLOW_VELOCITY_MPS: Flag = Flag::new(
    "--slow-velocity-mps",
    "Plate speed of the slow stroke, towards +x",
    "m/s",
    Interval::closed(1e-4, 10.0),
)
.why("0.1 mm/s to 10 m/s; with --slow-duration-s it sets the stroke, bounded with --mu below")
.default_value_is(0.1);

/// `--fast-velocity-mps`: its range is relative to the slow speed (here at its default).
pub const FAST_VELOCITY_MPS: Flag = Flag::new(
    "--fast-velocity-mps",
    "Plate speed of the fast stroke back, towards -x",
    "m/s",
    Interval::closed(0.1, 100.0).open_below(),
)
.shown_as("slow speed < value <= 1000 x slow speed")
.why("above the slow speed and at most 1000 times it")
.coupled()
.default_value_is(0.3);

/// `--slow-duration-s`.
pub const SLOW_DURATION_S: Flag = Flag::new(
    "--slow-duration-s",
    "Duration of the slow stroke; the fast stroke lasts slow speed x slow duration / fast speed (zero net displacement)",
    "s",
    Interval::closed(1e-4, 10.0),
)
.why("0.1 ms to 10 s; with the speeds and --mu it must let the block lock within 1e4 periods")
.default_value_is(0.03);

/// `--fast-duration-s`: set by the other strokes (here at their defaults).
pub const FAST_DURATION_S: Flag = Flag::new(
    "--fast-duration-s",
    "Duration of the fast stroke, optional (unset: computed from the slow stroke, 0.01 s at the defaults)",
    "s",
    Interval::closed(0.01, 0.01),
)
.shown_as("value = slow speed x slow duration / fast speed")
.why("zero net displacement of the plate")
.coupled();

/// `--viscous-c`: its range is relative to the period (here at the default strokes).
pub const VISCOUS_C: Flag = Flag::new(
    "--viscous-c",
    "Linear viscous friction coefficient per unit mass c for the linear law F = -m c v_rel",
    "1/s",
    Interval::closed(0.25, 2.5e5),
)
.shown_as("0.01/T <= c <= 1e4/T with T the period")
.why("six decades scaled by the period T of the sawtooth")
.coupled()
.default_value_is(30.0);

/// The table of the chapter's physical flags.
pub const FLAGS: &[Flag] = &[
    MU,
    SLOW_VELOCITY_MPS,
    FAST_VELOCITY_MPS,
    SLOW_DURATION_S,
    FAST_DURATION_S,
    VISCOUS_C,
    crate::flags::G,
];

/// The validated scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scene {
    /// The plate.
    pub saw: Sawtooth,
    /// Friction coefficient mu.
    pub mu: f64,
    /// Gravity g (m/s^2).
    pub g_mps2: f64,
    /// Viscous coefficient c (1/s).
    pub c_per_s: f64,
}

impl Scene {
    /// The friction bound `k = mu g` (m/s^2).
    pub fn k_mps2(&self) -> f64 {
        self.mu * self.g_mps2
    }
}

/// Checks every flag (one line naming the flag, value and valid range on error).
pub fn validate(a: &Args, g_mps2: f64) -> Result<Scene> {
    let g_mps2 = super::check_g(g_mps2)?;
    let vs = SLOW_VELOCITY_MPS.check(a.slow_velocity_mps)?;
    let vf = FAST_VELOCITY_MPS.check_coupled(
        a.fast_velocity_mps,
        |v| v > vs && v <= MAX_SPEED_RATIO * vs,
        &format!("{vs} < value <= {}", MAX_SPEED_RATIO * vs),
        FAST_VELOCITY_MPS.reason,
    )?;
    let ts = SLOW_DURATION_S.check(a.slow_duration_s)?;
    let saw = Sawtooth {
        slow_velocity_mps: vs,
        fast_velocity_mps: vf,
        slow_duration_s: ts,
    };
    let tf = saw.fast_duration_s();
    if let Some(given) = a.fast_duration_s {
        // Zero net displacement: v_s t_s = v_f t_f, to 1e-9 relative (typed decimals).
        FAST_DURATION_S.check_coupled(
            given,
            |t| t > 0.0 && (t - tf).abs() <= 1e-9 * tf,
            &format!("value = {tf} = slow speed x slow duration / fast speed"),
            FAST_DURATION_S.reason,
        )?;
    }
    let mu_min = mu_min_for_lock(&saw, g_mps2, MAX_LOCK_PERIODS);
    let mu = MU.check(a.mu)?;
    if mu < mu_min {
        // The lock condition combines five flags: name the one the user set.
        let d: Args = super::default_args();
        let (who, value) = crate::flags::blame(&[
            (&MU, mu, d.mu),
            (&SLOW_DURATION_S, ts, d.slow_duration_s),
            (&SLOW_VELOCITY_MPS, vs, d.slow_velocity_mps),
            (&FAST_VELOCITY_MPS, vf, d.fast_velocity_mps),
            (&crate::flags::G, g_mps2, super::Context::G_DEFAULT_MPS2),
        ]);
        who.check_coupled(
            value,
            |_| false,
            &format!("values with mu >= a/(g (T_s + 1e4 (T_s - T_f))), here {mu_min:.3e} > mu = {mu}"),
            "the block must reach its steady state within 1e4 periods of the slow speed a, slow duration T_s, fast duration T_f",
        )?;
    }
    let period = saw.period_s();
    let (c_lo, c_hi) = (0.01 / period, 1e4 / period);
    let c = VISCOUS_C.check_coupled(
        a.viscous_c,
        |c| c >= c_lo && c <= c_hi,
        &format!("{c_lo:.4} <= c <= {c_hi:.4e} (0.01/T to 1e4/T, T = {period} s)"),
        VISCOUS_C.reason,
    )?;
    Ok(Scene {
        saw,
        mu,
        g_mps2,
        c_per_s: c,
    })
}

/// Runs the chapter.
pub fn run(args: &Args, ctx: &Context) -> Result<ChapterReport> {
    let scene = validate(args, ctx.g())?;
    let mut r = info(ID).expect("registered chapter").report();
    r.param("mu", scene.mu);
    r.param("slow_velocity_mps", scene.saw.slow_velocity_mps);
    r.param("fast_velocity_mps", scene.saw.fast_velocity_mps);
    r.param("slow_duration_s", scene.saw.slow_duration_s);
    r.param("fast_duration_s", scene.saw.fast_duration_s());
    r.param("viscous_c_per_s", scene.c_per_s);
    r.param("g_mps2", scene.g_mps2);
    let dir = ctx.figure_dir(ID);
    let ev = evidence::gather(&scene, ctx.quick, dir.is_some());
    r.result("drift_velocity_coulomb_mps", ev.main.mean_velocity_mps);
    r.result("drift_velocity_formula_mps", ev.v_formula_mps);
    r.result("regime", ev.regime.label());
    r.result("drift_velocity_mirrored_mps", ev.mirrored_mps);
    r.result("lock_time_s", ev.lock_time_s);
    r.result("drift_velocity_linear_mps", ev.linear.drifts_mps[0]);
    r.result("drift_velocity_biharmonic_mps", ev.biharmonic_mps.0);
    r.result("drift_velocity_biharmonic_formula_mps", ev.biharmonic_mps.1);
    for c in claims::all(&statements::PRINTED, &ev) {
        r.claim(c);
    }
    if let Some((table, _)) = &ev.work {
        r.table("work_precision", table.clone());
    }
    if let Some(dir) = dir {
        r.figures
            .extend(figures::draw(&scene, ctx.quick, &ev, &dir)?);
    }
    Ok(r)
}


#[cfg(test)]
mod tests;
