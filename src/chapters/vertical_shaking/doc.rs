//! The document's statements of section 3.1.2 (and the workbook's derived values the
//! checks compare with), as data: the falsification tests feed the checks of
//! `super::claims` wrong variants of them, on the default scene in quick mode.

use super::claims;
use super::scene::{run as run_scene, Model, Scene};
use crate::report::{Claim, Mutation};

/// The statements, as data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Doc {
    /// Flight needs delta omega^2 > k g (printed k = 1).
    pub flight_gamma: f64,
    /// Any small force moves the block once delta omega^2 > k g (printed k = 1).
    pub flight_gamma_small_force: f64,
    /// Take-off at sin(omega t) = k/Gamma (derived k = 1).
    pub takeoff_factor: f64,
    /// The contact fraction tends to this limit as omega grows (printed 0).
    pub contact_limit: f64,
    /// c ~ omega^(-p) at fixed delta_z (printed law: p = 1).
    pub c_exponent: f64,
    /// Sliding: mean friction = k mu x mean normal force (printed k = 1).
    pub sliding_factor: f64,
    /// t_f = c v_z/g (printed c = 2).
    pub flight_coeff: f64,
    /// mu_eff = k v_ave/v_z (printed k = 1).
    pub law_coeff: f64,
    /// The multiplier-located period doublings, scaled (derived 1).
    pub pd_scale: f64,
    /// Gamma_n = sqrt(1 + (k n pi)^2) (derived k = 1).
    pub gamma_n_factor: f64,
    /// The drift threshold 1 + s b (derived s = -1).
    pub bias_sign: f64,
}

impl Doc {
    /// The document as printed.
    pub const PRINTED: Doc = Doc {
        flight_gamma: 1.0,
        flight_gamma_small_force: 1.0,
        takeoff_factor: 1.0,
        contact_limit: 0.0,
        c_exponent: 1.0,
        sliding_factor: 1.0,
        flight_coeff: 2.0,
        law_coeff: 1.0,
        pd_scale: 1.0,
        gamma_n_factor: 1.0,
        bias_sign: -1.0,
    };
}

/// The chapter's default scene (its flags' defaults, g = 9.81 m/s^2).
fn scene() -> Scene {
    Scene {
        gamma: 2.0,
        frequency_hz: 30.0,
        mu: 0.4,
        bias: 0.1,
        g_mps2: crate::chapters::Context::G_DEFAULT_MPS2,
    }
}

/// Runs the one claim `id` under `doc` (quick mode).
fn claim(id: &str, doc: &Doc) -> Claim {
    let s = scene();
    let (transient, observe) = super::budget(true);
    match id {
        "flight-needs-gamma-above-1" => claims::flight_needs_gamma(&s, doc),
        "takeoff-phase" => {
            let hop = run_scene(&s, Model::Exact, 0, 2);
            let phase = hop.rest_takeoff_phases_rad.first().copied();
            claims::takeoff(&s, phase.unwrap_or(f64::NAN), doc)
        }
        "contact-fraction-to-zero" => claims::fast_limits(&s, true, doc).0,
        "viscous-constant-to-zero" => claims::fast_limits(&s, true, doc).1,
        "sliding-contact-full-friction" => claims::sliding_contact(&s, doc),
        "small-force-moves-block" => claims::small_force(&s, doc),
        "flight-time-2vz-over-g" => claims::bias_law(&s, true, doc).0,
        "bias-law-mu-eff" => claims::bias_law(&s, true, doc).1,
        "period-doubling-multiplier" => claims::period_doublings(&s, true, doc),
        "flight-period-boundaries" => {
            let gammas = crate::sweep::linspace(1.0, 10.0, 19);
            let pts = super::regimes::sweep(&s, &gammas, transient, observe);
            let bounds = super::regimes::boundaries(&s, &pts, transient, observe, 10);
            claims::flight_boundaries(&bounds, true, doc)
        }
        "chladni-drift-threshold" => {
            let biased = Scene {
                bias: super::chladni::BIAS,
                ..s
            };
            let located =
                super::chladni::drift_threshold(&biased, (0.5, 1.0), 8, transient, observe);
            super::chladni::threshold_claim(located, doc.bias_sign, 0.25 / 256.0)
        }
        other => panic!("no claim {other} in this chapter"),
    }
}

/// The falsification mutations: a threshold or coefficient off by 10 %, a limit or a
/// sign changed, one per claim at least.
pub fn mutations() -> Vec<Mutation> {
    type Edit = fn(&mut Doc);
    let list: Vec<(&'static str, &'static str, Edit)> = vec![
        (
            "contact-fraction-to-zero",
            "fraction -> 0 replaced by -> 0.05",
            |d| d.contact_limit = 0.05,
        ),
        (
            "viscous-constant-to-zero",
            "c -> 0 replaced by c independent of omega",
            |d| d.c_exponent = 0.0,
        ),
        (
            "viscous-constant-to-zero",
            "c ~ 1/omega -> 1/omega^2",
            |d| d.c_exponent = 2.0,
        ),
        (
            "viscous-constant-to-zero",
            "c ~ 1/omega -> 1/omega^1.1",
            |d| d.c_exponent = 1.1,
        ),
        (
            "small-force-moves-block",
            "moves once delta omega^2 > g -> > 0.9 g",
            |d| d.flight_gamma_small_force = 0.9,
        ),
        (
            "flight-time-2vz-over-g",
            "t_f = 2 v_z/g -> 2.2 v_z/g",
            |d| d.flight_coeff = 2.2,
        ),
        (
            "bias-law-mu-eff",
            "mu_eff = v_ave/v_z -> 1.1 v_ave/v_z",
            |d| d.law_coeff = 1.1,
        ),
        (
            "period-doubling-multiplier",
            "period doublings at 1.1 x the located Gamma",
            |d| d.pd_scale = 1.1,
        ),
        (
            "flight-period-boundaries",
            "Gamma_n = sqrt(1 + (n pi)^2) -> sqrt(1 + (1.1 n pi)^2)",
            |d| d.gamma_n_factor = 1.1,
        ),
    ];
    Mutation::from_edits(Doc::PRINTED, list, claim)
}
