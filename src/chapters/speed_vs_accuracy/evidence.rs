//! The chapter's runs, computed once into one value: the block's reference, ladder and
//! failure scenes, the stick's ladder, the missed event, the stick by three methods,
//! and the averaged models' economy. Nothing here depends on the statements: the claims
//! (`claims.rs`) judge any statements on the same evidence.

use super::block_part::{self, BlockEvidence, StiffEvidence, ZenoEvidence};
use super::block_scene::BlockScene;
use super::economy::{flight_map_drift, flight_map_predicted_rel, gather_horizontal, law_drift, Horizontal, SweepRow};
use super::measure::{drift_block_model, window};
use super::missed_event::{self, MissedEvent};
use super::setup::{Plan, Setup};
use super::stick_methods::{measure_scene, soft_ladder, Ladder, Plan as MethodsPlan, SceneMethods};
use super::stick_part::{self, StickEvidence};
use super::Args;
use crate::ladder::{timed, Timing};
use crate::numerics::hybrid::Options;
use crate::physics::stick::soft::SoftParams;
use crate::physics::stick::{authors_scene, jamming_scene};

/// Everything the chapter ran.
#[derive(Debug, Clone, PartialEq)]
pub struct Evidence {
    /// The block on the plate: reference, convergence study, ladders.
    pub block: BlockEvidence,
    /// The stiff flight relaxation.
    pub stiff: StiffEvidence,
    /// The Zeno scenes.
    pub zeno: ZenoEvidence,
    /// The stick's ladder (authors' scene).
    pub stick: StickEvidence,
    /// The missed event.
    pub missed: MissedEvent,
    /// The averaged models of vertical shaking.
    pub economy: Economy,
    /// The averaged models of horizontal dither.
    pub horizontal: Horizontal,
    /// The stick by three methods on the self-locking scene (g = 9.81 m/s^2).
    pub methods_default: SceneMethods,
    /// The stick by three methods on the authors' scene (g = 10 m/s^2).
    pub methods_authors: SceneMethods,
    /// Soft contact's first family (friction smoothing `v_eps = 0.1 eps` m/s, not first
    /// order) on the self-locking scene, on the quick plan's three rungs whatever the
    /// mode (a fit needs three): the ladder a wrong statement of the friction smoothing
    /// looks at.
    pub soft_first_family: Ladder,
}

/// The averaged laws of vertical shaking against the exact drift.
#[derive(Debug, Clone, PartialEq)]
pub struct Economy {
    /// The document's law `v_ave = b mu v_z` on the chapter's scene (m/s).
    pub law_mps: f64,
    /// The flight-map law on the chapter's scene (m/s), if the scene has a sticking orbit.
    pub flight_map_mps: Option<f64>,
    /// Wall time of the exact run and of the flight map (s, minimum of repeats).
    pub wall_s: (f64, f64),
    /// The sweep over Gamma.
    pub sweep: Vec<SweepRow>,
    /// In the limit the flight map names (Gamma = 2.5, b = 1/80): the exact drift and
    /// the flight map's (m/s).
    pub limit: (f64, Option<f64>),
    /// There: the flight map's relative error predicted from the slip before take-off
    /// it neglects, `-b/(omega t_f sqrt(Gamma^2 - 1))` (NaN without a sticking orbit).
    pub limit_predicted_rel: f64,
}

/// Runs the chapter on the flags `args`, g of the block scene `g` and of the stick
/// scene `stick_g` (m/s^2), in `quick` mode or not.
pub fn gather(args: &Args, g: f64, stick_g: f64, quick: bool) -> Evidence {
    let plan = Plan::new(quick);
    let scene = BlockScene::new(args.frequency_hz, args.gamma, args.mu, args.bias, g);
    let win = window(&scene, plan.transient, plan.cycles);
    let s = Setup {
        args,
        plan,
        g,
        scene,
        win,
        quick,
    };
    let block = block_part::gather(&s);
    let stiff = block_part::gather_stiff(quick);
    let zeno = block_part::gather_zeno(&s);
    let stick = stick_part::gather(stick_g, quick);
    let missed = missed_event::gather();
    let economy = economy(&s);
    let horizontal = gather_horizontal(args.frequency_hz, args.mu, args.bias, g, quick);
    // The stick chapter's own scenes, each with its g (9.81 and 10 m/s^2), whatever
    // `--g-mps2`: the claims are measurements of those scenes (at g = 17 m/s^2
    // Moreau-Jean's error is not yet in its asymptotic range at the ladder's finest step,
    // so its Richardson estimate misses by a factor 5).
    let mplan = MethodsPlan::new(quick);
    let methods_default = measure_scene(&jamming_scene(9.81), &mplan);
    let first = MethodsPlan {
        soft_family: SoftParams::regularised_linear_slip,
        ..MethodsPlan::new(true)
    };
    let soft_first_family = soft_ladder(&jamming_scene(9.81), &first, methods_default.reference_mps);
    Evidence {
        block,
        stiff,
        zeno,
        stick,
        missed,
        economy,
        horizontal,
        methods_default,
        methods_authors: measure_scene(&authors_scene(10.0), &mplan),
        soft_first_family,
    }
}

/// The flight map and the mu_eff law against the exact drift: on the chapter's scene,
/// over a sweep of Gamma and in the limit the flight map names.
fn economy(s: &Setup<'_>) -> Economy {
    let (args, plan, g, scene) = (s.args, &s.plan, s.g, &s.scene);
    let (tr, cy) = (plan.transient, plan.cycles);
    let repeats = Timing::MinOf(plan.repeats.max(3));
    let (_, wall_exact) = timed(repeats, || s.block(&Options::default(), true));
    let (_, wall_map) = timed(Timing::MinOf(plan.repeats.max(3) * 100), || {
        flight_map_drift(scene)
    });
    let exact = |sc: &BlockScene| drift_block_model(sc, &Options::default(), true, 64, tr, cy);
    let sweep: Vec<SweepRow> = plan
        .gammas
        .iter()
        .map(|&gm| {
            let sc = BlockScene::new(args.frequency_hz, gm, args.mu, args.bias, g);
            (gm, exact(&sc).value, flight_map_drift(&sc), law_drift(&sc))
        })
        .collect();
    // Checked inside the limit it names, whatever the flags: Gamma = 2.5 (a period-one
    // sticking orbit) and b = 1/80 (claims.rs).
    let lim = BlockScene::new(args.frequency_hz, 2.5, args.mu, 1.0 / 80.0, g);
    Economy {
        law_mps: law_drift(scene),
        flight_map_mps: flight_map_drift(scene),
        wall_s: (wall_exact, wall_map),
        sweep,
        limit: (exact(&lim).value, flight_map_drift(&lim)),
        limit_predicted_rel: flight_map_predicted_rel(&lim).unwrap_or(f64::NAN),
    }
}
