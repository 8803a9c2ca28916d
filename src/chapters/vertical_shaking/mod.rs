//! Chapter `vertical-shaking` (document section 3.1.2): vertical vibration and the bias
//! law `mu_eff = v_ave / v_z`.
//!
//! A block on a plate `u_z = delta_z sin(omega t)`, completely inelastic landings
//! (e = 0), Coulomb friction in contact and at impacts, a bias force `F = b mu m g`.
//! The chapter checks the document's claims with the exact hybrid simulation, measures
//! what each approximation of the bias law costs by switching it off in the model, and
//! maps the regimes of the e = 0 bouncing block over 1 < Gamma < 10 with boundaries
//! located by bisection on a regime classifier.

use super::{report_with_g, Context};
use crate::error::Result;
use crate::flags::Flag;
use crate::physics::domain::Interval;
use crate::physics::plate::PlateMotion;
use crate::report::ChapterReport;
use scene::{run as run_scene, Model, Scene};

pub mod chladni;
mod claims;
pub mod doc;
mod figures;
pub mod regimes;
pub mod scene;

/// Flags of the chapter (defaults: the authors' vibrating plate at 30 Hz, mu = 0.4).
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Peak plate acceleration in units of g, [`GAMMA`].
    #[arg(long, default_value_t = 2.0)]
    pub gamma: f64,
    /// Plate frequency f (Hz), [`FREQUENCY_HZ`].
    #[arg(long = "frequency-hz", default_value_t = 30.0)]
    pub frequency_hz: f64,
    /// Coulomb friction coefficient mu, [`MU`].
    #[arg(long, default_value_t = 0.4)]
    pub mu: f64,
    /// Bias force F as a fraction of mu m g, [`BIAS`].
    #[arg(long, default_value_t = 0.1)]
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
.why("at Gamma <= 1 the plate never throws the block; flights last ~ (Gamma - 1) T, and below 1 + 1e-6 they shrink under the resolution of the take-off phase and the flight-time table");

/// `--frequency-hz`.
pub const FREQUENCY_HZ: Flag = Flag::new(
    "--frequency-hz",
    "Plate frequency f = omega / (2 pi)",
    "Hz",
    Interval::closed(0.1, 1000.0),
)
.why("the plate amplitude Gamma g/omega^2 stays between a nanometre and kilometres, where the block model's absolute tolerances resolve a period");

/// `--mu`.
pub const MU: Flag = Flag::new(
    "--mu",
    "Coulomb friction coefficient mu",
    "dimensionless",
    Interval::closed(0.01, 2.0).open_above(),
)
.why("dry friction between block and plate");

/// `--bias`.
pub const BIAS: Flag = Flag::new(
    "--bias",
    "Bias force F as a fraction of mu m g",
    "fraction of mu m g",
    Interval::closed(0.0, 1.0).open_above(),
)
.why("the law is stated for F < mu m g");

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
    let (transient, observe) = budget(ctx.quick);

    // The scene itself: take-off, flights, contact, drift.
    let st = run_scene(&scene, Model::Exact, transient, observe);
    let hop = run_scene(&scene, Model::Exact, 0, 2);
    let takeoff_phase = hop
        .rest_takeoff_phases_rad
        .first()
        .copied()
        .unwrap_or(f64::NAN);
    let vz = scene.vz_mps();
    let v = st.cycle_velocity_mps;
    r.result("amplitude_m", scene.amplitude_m());
    r.result("takeoff_phase_rad", takeoff_phase);
    r.result(
        "flight_time_over_period",
        st.mean_flight_s() / st.run.period_s,
    );
    r.result("contact_fraction", st.run.contact_fraction);
    r.result("mean_velocity_mps", v);
    r.result("mean_velocity_law_mps", scene.law_velocity_mps());
    r.result("mu_eff", bias * mu); // formula: mu_eff = F/(m g)
    r.result("mu_eff_law", v / vz); // formula: mu_eff = v_ave / v_z (the document's law)

    // Regimes over 1 < Gamma < 10.
    let n = if ctx.quick { 19 } else { 181 };
    let gammas = crate::sweep::linspace(1.0, 10.0, n);
    let pts = regimes::sweep(&scene, &gammas, transient, observe);
    let iters = if ctx.quick { 10 } else { 16 };
    let bounds = regimes::boundaries(&scene, &pts, transient, observe, iters);
    let located: Vec<f64> = bounds.iter().map(|b| b.gamma).collect();
    r.result("regime_boundaries_gamma", located.clone());
    r.result("regime_at_gamma", regimes::classify(&st).label());
    let pd: Vec<f64> = (1..=3)
        .map(|n| regimes::period_doubling_gamma(f64::from(n)))
        .collect();
    r.result("period_doubling_gamma", pd);
    let mut t = String::from("| Γ | below | above | located by | bracket | shift with 4x transient | accuracy |\n|---|---|---|---|---|---|---|\n");
    for b in &bounds {
        t.push_str(&format!(
            "| {:.6} | {} | {} | {} | {:.1e} | {:.1e} | {:.1e} |\n",
            b.gamma,
            b.below,
            b.above,
            match b.band {
                Some((lo, hi)) => format!("multiplier = -1 (classifier band {lo:.3} to {hi:.3})"),
                None => "classifier".to_string(),
            },
            b.bracket,
            (b.gamma - b.gamma_long).abs(),
            b.accuracy()
        ));
    }
    r.table("regime-boundaries", t);

    claims::add(
        &mut r,
        &scene,
        takeoff_phase,
        &bounds,
        ctx.quick,
        &doc::Doc::PRINTED,
    );
    // Chladni patterns from a small bias (the section's closing remark).
    let chl = chladni::demonstrate(&scene, ctx.quick, transient, observe);
    chladni::report(&mut r, &chl, doc::Doc::PRINTED.bias_sign);
    let decomposition = claims::decomposition(&scene, transient, observe);
    r.table("law-decomposition", decomposition);

    // Work against accuracy: 20 periods from rest; reference: the closed-form run.
    let plate = scene.plate();
    let params = scene.params(Model::Exact);
    let end = 20.0 * plate.period_s();
    let model = |o: &crate::physics::block::BlockOptions| {
        let o = crate::physics::block::BlockOptions {
            transient_periods: 0,
            ..*o
        };
        crate::physics::block::simulate_block(&params, &plate, end, &o)
    };
    let reference = model(&crate::physics::block::BlockOptions::default()).mean_velocity_mps;
    let scale = if reference.abs() > 1e-12 * vz {
        reference.abs()
    } else {
        vz
    };
    let wp = crate::ladder::work_precision(&model, reference, scale, ctx.quick);
    r.table("work-precision", crate::ladder::table(&wp));

    if let Some(dir) = ctx.figure_dir("vertical-shaking") {
        let paths = figures::draw(&dir, &scene, &pts, &bounds, &wp, ctx.quick)?;
        r.figures.extend(paths);
        r.figures.extend(chladni::draw(&dir, &chl)?);
    }
    Ok(r)
}

/// The falsification mutations of this chapter's claims (see [`crate::report::Mutation`]).
pub fn mutations() -> Vec<crate::report::Mutation> {
    doc::mutations()
}
