//! Falsification: edits of the document's statements, each judged by the same claim
//! functions ([`super::claims`]) on the evidence of the default scene in quick mode,
//! computed once.

use super::claims;
use super::evidence::{gather, Evidence};
use super::statements::{Statements, PRINTED};
use crate::chapters::{default_args, Context};
use crate::report::{Claim, DocEdit, Falsifiable};

/// The chapter's document for the generic judge (`crate::report::falsify`): the
/// default scene's evidence in quick mode.
pub struct Document;

impl Falsifiable for Document {
    type Statements = Statements;
    type Evidence = Evidence;
    fn printed() -> Statements {
        PRINTED
    }
    fn quick_evidence() -> Evidence {
        let scene = super::validate(&default_args(), Context::G_DEFAULT_MPS2)
            .expect("default flags are valid");
        gather(&scene, true, false)
    }
    fn claims(st: &Statements, ev: &Evidence) -> Vec<Claim> {
        claims::all(st, ev)
    }
    const EDITS: &'static [DocEdit<Statements>] = EDITS;
    const WITHOUT_TEN_PERCENT: &'static [(&'static str, &'static str)] = PRINTS_NO_NUMBER;
}

/// The claims of the chapter that print no number a 10 % change could move, with the
/// reason; their mutations flip the sign, inequality or statement instead.
pub const PRINTS_NO_NUMBER: &[(&str, &str)] = &[
    (
        "nonlinear-law-changes-result",
        "a statement that the result changes (a non-linear law gives a drift), no number: the mutation says it does not",
    ),
    (
        "stroke-inequalities",
        "inequalities between the two strokes (v_l > v_r, t_r > t_l), no number: the mutation prints the corrected ones",
    ),
    (
        "drift-direction",
        "a direction (the bias runs along the slow stroke), no number: the mutation reverses it",
    ),
    (
        "locomotion-needs-slip",
        "'generically': no number; the mutations print the correction and move the workbook's derived threshold",
    ),
    (
        "window-length-not-ratio",
        "a condition on the averaging window ('t2 so much greater than t1'), no number: the mutation prints the corrected condition (t2 - t1 many periods)",
    ),
    ("drift-closed-form", DERIVED),
    ("drift-regime", DERIVED),
    ("lock-time", DERIVED),
    ("mirror-reverses", DERIVED),
    ("biharmonic-always-slipping", DERIVED),
    ("biharmonic-stuck", DERIVED),
];

/// Why a claim of the workbook's own closed forms has no 10 % mutation of a printed number.
const DERIVED: &str = "the workbook's derived closed form: the document prints no number here (the mutations move the derived value, a check of the derivation)";

/// The falsification mutations (a data table): every document claim gets a 10 %
/// change of a number its statement prints ("x -> 1.1 x"; thresholds both ways), and
/// a sign or an inequality reversed where it states one. The claims that print no
/// number are listed in [`PRINTS_NO_NUMBER`].
const EDITS: &[DocEdit<Statements>] = &[
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
        "derived v_slow - mu g t_fast^2/T -> v_slow - 1.1 mu g t_fast^2/T",
        |d| d.drift_factor = 1.1,
    ),
    (
        "drift-closed-form",
        "derived v_slow - mu g t_fast^2/T -> v_slow - 0.9 mu g t_fast^2/T",
        |d| d.drift_factor = 0.9,
    ),
    ("drift-regime", "mu g t_fast >= v_slow + v_fast -> <", |d| {
        d.regime_reversed = true
    }),
    (
        "drift-regime",
        "derived mu g t_fast >= v_slow + v_fast -> >= 1.1 (v_slow + v_fast)",
        |d| d.regime_threshold = 1.1,
    ),
    (
        "drift-regime",
        "derived mu g t_fast >= v_slow + v_fast -> >= 0.9 (v_slow + v_fast)",
        |d| d.regime_threshold = 0.9,
    ),
    ("lock-time", "derived t* -> 1.1 t*", |d| d.lock_factor = 1.1),
    ("mirror-reverses", "v_d(mirror) = -v_d -> +v_d", |d| {
        d.mirror_sign = 1.0
    }),
    (
        "mirror-reverses",
        "derived v_d(mirror) = -v_d -> -1.1 v_d",
        |d| d.mirror_sign = -1.1,
    ),
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
        "J = mu m g (t_l - t_r) -> 1.1 mu m g (t_l - t_r) (10 %)",
        |d| d.impulse_factor = 1.1,
    ),
    (
        "reaches-slow-speed",
        "reaches v_l -> reaches 1.1 v_l (10 %)",
        |d| d.reach_factor = 1.1,
    ),
    (
        "locomotion-needs-slip",
        "'generically' -> the corrected condition printed (a drift only while mu g t_fast < v_slow + v_fast)",
        |d| d.generic_drift = false,
    ),
    (
        "locomotion-needs-slip",
        "derived threshold mu g t_fast < v_slow + v_fast -> < 1.1 (v_slow + v_fast)",
        |d| d.slip_threshold = 1.1,
    ),
    (
        "locomotion-needs-slip",
        "derived threshold mu g t_fast < v_slow + v_fast -> < 0.9 (v_slow + v_fast)",
        |d| d.slip_threshold = 0.9,
    ),
    (
        "biharmonic-always-slipping",
        "derived 1 - pi^2/(2 Gamma^2) -> 1 - 1.1 pi^2/(2 Gamma^2)",
        |d| d.biharmonic_factor = 1.1,
    ),
    ("biharmonic-stuck", "Gamma_stick -> 1.5 Gamma_stick", |d| {
        d.stick_gamma_factor = 1.5
    }),
    (
        "biharmonic-stuck",
        "derived Gamma_stick -> 1.1 Gamma_stick",
        |d| d.stick_gamma_factor = 1.1,
    ),
    (
        "biharmonic-stuck",
        "derived Gamma_stick -> 0.9 Gamma_stick",
        |d| d.stick_gamma_factor = 0.9,
    ),
    (
        "window-length-not-ratio",
        "t2 >> t1 -> the corrected t2 - t1 >> T (a window of many periods)",
        |d| d.window_ratio_condition = false,
    ),
];
