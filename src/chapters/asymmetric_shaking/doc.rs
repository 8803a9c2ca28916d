//! The document's statements of section 3.2 (and the workbook's closed forms the
//! checks compare with), as data: the falsification tests feed the checks of
//! [`super::claims`] wrong variants of them.

use crate::report::Mutation;

/// The statements, as data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Doc {
    /// 3.2.1: with linear friction the block's mean velocity is the plate's plus this
    /// fraction of the mean stroke speed (printed: 0, no drift).
    pub linear_drift_fraction: f64,
    /// 3.2.1: F_ave = -k c (v_obj_ave - v_sup_ave) (printed k = 1).
    pub linear_force_factor: f64,
    /// 3.2.1: "a non-linear friction law changes this result" (printed `true`).
    pub nonlinear_changes: bool,
    /// The workbook's v_d = v_slow - k mu g t_fast^2/T (derived k = 1).
    pub drift_factor: f64,
    /// The regime test mu g t_fast >= v_slow + v_fast for sticking in both strokes
    /// (`false`); `true` reverses it.
    pub regime_reversed: bool,
    /// The workbook's lock time, scaled by this factor (derived 1).
    pub lock_factor: f64,
    /// v_d(mirror) = s v_d (derived s = -1).
    pub mirror_sign: f64,
    /// 3.2.2 as printed: v_l > v_r, t_r > t_l (`true`, the erratum); `false` prints
    /// the corrected v_l < v_r, t_l > t_r.
    pub printed_fast_left: bool,
    /// 3.2.2: the bias is along the slow, long stroke (`true`) or against it.
    pub along_slow_stroke: bool,
    /// 3.2.2: J = k mu m g (t_l - t_r) (printed k = 1).
    pub impulse_factor: f64,
    /// 3.2.2: the block accelerates until its speed reaches k v_l (printed k = 1).
    pub reach_factor: f64,
    /// Drift only while mu g t_fast < k (v_slow + v_fast) (derived k = 1).
    pub slip_threshold: f64,
    /// The workbook's v_d = eps V (1 - k pi^2/(2 Gamma^2)) (derived k = 1).
    pub biharmonic_factor: f64,
    /// The workbook's Gamma_stick, scaled by this factor (derived 1).
    pub stick_gamma_factor: f64,
}

impl Doc {
    /// The document as printed (and the workbook's closed forms as derived).
    pub const PRINTED: Doc = Doc {
        linear_drift_fraction: 0.0,
        linear_force_factor: 1.0,
        nonlinear_changes: true,
        drift_factor: 1.0,
        regime_reversed: false,
        lock_factor: 1.0,
        mirror_sign: -1.0,
        printed_fast_left: true,
        along_slow_stroke: true,
        impulse_factor: 1.0,
        reach_factor: 1.0,
        slip_threshold: 1.0,
        biharmonic_factor: 1.0,
        stick_gamma_factor: 1.0,
    };
}

/// The falsification mutations: a coefficient off by 10 %, a sign or an inequality
/// reversed, one per claim at least.
pub fn mutations() -> Vec<Mutation> {
    type Edit = fn(&mut Doc);
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
    Mutation::from_edits(Doc::PRINTED, list, |id, d| {
        crate::chapters::quick_claim(id, d, super::run_with)
    })
}
