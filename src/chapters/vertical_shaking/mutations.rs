//! Falsification: edits of the document's statements, each judged by the same claim
//! functions ([`super::claims`]) on the evidence of the default scene in quick mode,
//! computed once.

use super::claims;
use super::evidence::{gather, Evidence};
use super::scene::Scene;
use super::statements::{Statements, PRINTED};
use crate::report::{Claim, Mutation};
use std::sync::OnceLock;

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

/// The default scene's evidence in quick mode, computed once per process.
fn evidence() -> &'static Evidence {
    static EV: OnceLock<Evidence> = OnceLock::new();
    EV.get_or_init(|| gather(&scene(), true))
}

/// The claim `id` judged under the statements `doc`.
fn judge(id: &str, doc: &Statements) -> Claim {
    claims::all(doc, evidence())
        .into_iter()
        .find(|c| c.id == id)
        .unwrap_or_else(|| panic!("no claim {id} in this chapter"))
}

/// The falsification mutations: a threshold or coefficient off by 10 %, a limit or a
/// sign changed, one per claim at least.
pub fn mutations() -> Vec<Mutation> {
    type Edit = fn(&mut Statements);
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
    Mutation::from_edits(PRINTED, list, judge)
}
