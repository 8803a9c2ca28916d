//! Falsification: edits of the document's statements, each judged by the same claim
//! functions ([`super::claims`]) on the evidence of the default scene in quick mode,
//! computed once.

use super::claims;
use super::evidence::{gather, Evidence};
use super::statements::{Statements, PRINTED};
use crate::chapters::{default_args, Context};
use crate::report::{Claim, Mutation};
use std::sync::OnceLock;

/// The default scene's evidence in quick mode, computed once per process.
fn evidence() -> &'static Evidence {
    static EV: OnceLock<Evidence> = OnceLock::new();
    EV.get_or_init(|| {
        let scene = super::validate(&default_args(), Context::G_DEFAULT_MPS2)
            .expect("default flags are valid");
        gather(&scene, true, false)
    })
}

/// The claim `id` judged under the statements `doc`.
fn judge(id: &str, doc: &Statements) -> Claim {
    claims::all(doc, evidence())
        .into_iter()
        .find(|c| c.id == id)
        .unwrap_or_else(|| panic!("no claim {id} in this chapter"))
}

/// The falsification mutations: a coefficient off by 10 %, a sign or an inequality
/// reversed, one per claim at least.
pub fn mutations() -> Vec<Mutation> {
    type Edit = fn(&mut Statements);
    let list: Vec<(&'static str, &'static str, Edit)> = vec![
        (
            "linear-no-drift",
            "no drift -> a drift of 10 % of the mean stroke speed",
            |d| d.linear_drift_fraction = 0.1,
        ),
        (
            "nonlinear-law-changes-result",
            "a non-linear law changes the result -> it does not",
            |d| d.nonlinear_changes = false,
        ),
        (
            "drift-closed-form",
            "v_slow - mu g t_fast^2/T -> v_slow - 1.1 mu g t_fast^2/T",
            |d| d.drift_factor = 1.1,
        ),
        ("drift-regime", "mu g t_fast >= v_slow + v_fast -> <", |d| {
            d.regime_reversed = true
        }),
        ("lock-time", "t* -> 1.1 t*", |d| d.lock_factor = 1.1),
        ("mirror-reverses", "v_d(mirror) = -v_d -> +v_d", |d| {
            d.mirror_sign = 1.0
        }),
        (
            "stroke-inequalities",
            "printed v_l > v_r, t_r > t_l -> the corrected v_l < v_r, t_l > t_r",
            |d| d.printed_fast_left = false,
        ),
        (
            "drift-direction",
            "bias along the slow stroke -> against it",
            |d| d.along_slow_stroke = false,
        ),
        (
            "slip-impulse",
            "J = mu m g (t_l - t_r) -> 1.1 mu m g (t_l - t_r)",
            |d| d.impulse_factor = 1.1,
        ),
        (
            "reaches-slow-speed",
            "reaches v_l -> reaches 1.1 v_l",
            |d| d.reach_factor = 1.1,
        ),
        (
            "locomotion-needs-slip",
            "mu g t_fast < v_slow + v_fast -> < 3 (v_slow + v_fast)",
            |d| d.slip_threshold = 3.0,
        ),
        (
            "locomotion-needs-slip",
            "mu g t_fast < v_slow + v_fast -> < 1.1 (v_slow + v_fast)",
            |d| d.slip_threshold = 1.1,
        ),
        (
            "locomotion-needs-slip",
            "mu g t_fast < v_slow + v_fast -> < 0.9 (v_slow + v_fast)",
            |d| d.slip_threshold = 0.9,
        ),
        (
            "biharmonic-always-slipping",
            "1 - pi^2/(2 Gamma^2) -> 1 - 1.1 pi^2/(2 Gamma^2)",
            |d| d.biharmonic_factor = 1.1,
        ),
        ("biharmonic-stuck", "Gamma_stick -> 1.5 Gamma_stick", |d| {
            d.stick_gamma_factor = 1.5
        }),
        ("biharmonic-stuck", "Gamma_stick -> 1.1 Gamma_stick", |d| {
            d.stick_gamma_factor = 1.1
        }),
        ("biharmonic-stuck", "Gamma_stick -> 0.9 Gamma_stick", |d| {
            d.stick_gamma_factor = 0.9
        }),
        (
            "drift-closed-form",
            "v_slow - mu g t_fast^2/T -> v_slow - 0.9 mu g t_fast^2/T",
            |d| d.drift_factor = 0.9,
        ),
    ];
    Mutation::from_edits(PRINTED, list, judge)
}
