//! Chapter `vertical-shaking` (document section 3.1.2): vertical vibration and the bias
//! law `mu_eff = v_ave / v_z`.
//!
//! A block on a plate `u_z = delta_z sin(omega t)`, completely inelastic landings
//! (e = 0), Coulomb friction in contact and at impacts, a bias force `F = b mu m g`.
//! The chapter checks the document's claims with the exact hybrid simulation, measures
//! what each approximation of the bias law costs by switching it off in the model, and
//! maps the regimes of the e = 0 bouncing block over 1 < Gamma < 10 with boundaries
//! located by bisection on a regime classifier.

//!
//! The chapter shape (ARCHITECTURE.md): the document's statements as data
//! ([`statements`]), the runs computed once ([`evidence`], on the scene and model runs
//! of [`scene`], the regime classifier of [`regimes`] and the Chladni demonstration of
//! [`chladni`]), the claims as pure functions of both ([`claims`]), the generated
//! tables, the figures, and the falsification mutations ([`mutations`]: edits of the
//! statements judged by the same claims).

use super::{report_with_g, Context};
use crate::error::Result;
use crate::flags::Flag;
use crate::physics::domain::Interval;
use crate::report::ChapterReport;
use scene::Scene;

mod chladni;
mod claims;
mod evidence;
mod figures;
mod landing;
mod mutations;
pub use mutations::Document;
mod regimes;
mod scene;
mod statements;
mod tables;

/// Flags of the chapter (defaults: the authors' vibrating plate at 30 Hz, mu = 0.4).
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Peak plate acceleration in units of g, [`GAMMA`].
    #[arg(long, default_value_t = GAMMA.default_value())]
    pub gamma: f64,
    /// Plate frequency f (Hz), [`FREQUENCY_HZ`].
    #[arg(long = "frequency-hz", default_value_t = FREQUENCY_HZ.default_value())]
    pub frequency_hz: f64,
    /// Coulomb friction coefficient mu, [`MU`].
    #[arg(long, default_value_t = MU.default_value())]
    pub mu: f64,
    /// Bias force F as a fraction of mu m g, [`BIAS`].
    #[arg(long, default_value_t = BIAS.default_value())]
    pub bias: f64,
}

/// Periods of transient and of observation (quick, full); the observation spans a
/// multiple of every cycle length up to 6 periods.
pub fn budget(quick: bool) -> (usize, usize) {
    if quick {
        (60, 60)
    } else {
        (100, 120)
    }
}

/// Smallest accepted Gamma (dimensionless): 1 + 1e-6.
pub const GAMMA_MIN: f64 = 1.000001;

/// `--gamma`.
pub const GAMMA: Flag = Flag::new(
    "--gamma",
    "Peak plate acceleration in units of g, Gamma = delta_z omega^2 / g",
    "dimensionless",
    Interval::closed(GAMMA_MIN, 100.0),
)
.why("at Gamma <= 1 the plate never throws the block; flights last ~ (Gamma - 1) T, and below 1 + 1e-6 they shrink under the resolution of the take-off phase and the flight-time table")
.default_value_is(2.0);

/// `--frequency-hz`.
pub const FREQUENCY_HZ: Flag = Flag::new(
    "--frequency-hz",
    "Plate frequency f = omega / (2 pi)",
    "Hz",
    Interval::closed(0.1, 1000.0),
)
.why("the plate amplitude Gamma g/omega^2 stays between a nanometre and kilometres, where the block model's absolute tolerances resolve a period")
.default_value_is(30.0);

/// `--mu`.
pub const MU: Flag = Flag::new(
    "--mu",
    "Coulomb friction coefficient mu",
    "dimensionless",
    Interval::closed(0.01, 2.0).open_above(),
)
.why("dry friction between block and plate")
.default_value_is(0.4);

/// `--bias`.
pub const BIAS: Flag = Flag::new(
    "--bias",
    "Bias force F as a fraction of mu m g",
    "fraction of mu m g",
    Interval::closed(0.0, 1.0).open_above(),
)
.why("the law is stated for F < mu m g")
.default_value_is(0.1);

/// The table of the chapter's physical flags.
pub const FLAGS: &[Flag] = &[GAMMA, FREQUENCY_HZ, MU, BIAS, crate::flags::G];

/// Runs the chapter.
pub fn run(args: &Args, ctx: &Context) -> Result<ChapterReport> {
    let gamma = GAMMA.check(args.gamma)?;
    let freq = FREQUENCY_HZ.check(args.frequency_hz)?;
    let mu = MU.check(args.mu)?;
    let bias = BIAS.check(args.bias)?;
    let (mut r, g) = report_with_g(
        "vertical-shaking",
        ctx,
        &[
            ("gamma", gamma),
            ("frequency_hz", freq),
            ("mu", mu),
            ("bias", bias),
        ],
    )?;
    let scene = Scene {
        gamma,
        frequency_hz: freq,
        mu,
        bias,
        g_mps2: g,
    };
    let ev = evidence::gather(&scene, ctx.quick);
    report_results(&mut r, &ev);
    for c in claims::all(&statements::PRINTED, &ev) {
        r.claim(c);
    }
    r.result("chladni", chladni::summary(&ev.chladni));
    r.table(
        "law-decomposition",
        tables::decomposition(&ev.decomposition),
    );
    r.table("work-precision", crate::ladder::table(&ev.work));
    if let Some(dir) = ctx.figure_dir("vertical-shaking") {
        let paths = figures::draw(&dir, &scene, &ev.sweep, &ev.bounds, &ev.work, ctx.quick)?;
        r.figures.extend(paths);
        r.figures.extend(figures::chladni(&dir, &ev.chladni)?);
    }
    Ok(r)
}

/// The results of the scene and of the regime sweep, and the boundaries' table.
fn report_results(r: &mut ChapterReport, ev: &evidence::Evidence) {
    let scene = &ev.scene;
    let st = &ev.stats;
    let vz = scene.vz_mps();
    let v = st.cycle_velocity_mps;
    r.result("amplitude_m", scene.amplitude_m());
    r.result("takeoff_phase_rad", ev.takeoff_phase_rad);
    r.result(
        "flight_time_over_period",
        st.mean_flight_s() / st.run.period_s,
    );
    r.result("contact_fraction", st.run.contact_fraction);
    r.result("mean_velocity_mps", v);
    r.result("mean_velocity_law_mps", scene.law_velocity_mps());
    // The two sides of the document's law mu_eff = v_ave/v_z, each named by what it
    // holds: the bias force's mu_eff = F/(m g) (what the law predicts for v_ave/v_z),
    // and v_ave/v_z measured from the simulated drift (the law's estimate of mu_eff).
    r.result("mu_eff_from_force", scene.bias * scene.mu); // formula: mu_eff = F/(m g)
    r.result("mu_eff_from_drift", v / vz); // formula: mu_eff = v_ave / v_z (the document's law)
    let located: Vec<f64> = ev.bounds.iter().map(|b| b.gamma).collect();
    r.result("regime_boundaries_gamma", located);
    r.result("regime_at_gamma", regimes::classify(st).label());
    let pd: Vec<f64> = (1..=3)
        .map(|n| regimes::period_doubling_gamma(f64::from(n)))
        .collect();
    r.result("period_doubling_gamma", pd);
    r.table("regime-boundaries", tables::regime_boundaries(&ev.bounds));
}


#[cfg(test)]
mod tests;
