//! The document's statements of section 3.2 (and the workbook's closed forms the
//! checks compare with), as data, no logic: the claims of [`super::claims`] judge them,
//! and the mutations of [`super::mutations`] feed the same claims wrong variants.

/// The statements, as data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statements {
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
    /// ... with the threshold k (v_slow + v_fast) (derived k = 1).
    pub regime_threshold: f64,
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
    /// 3.2.1-3.2.2 as printed: asymmetric shaking with Coulomb friction induces a drift
    /// "generically" (`true`); `false` prints the corrected condition (a drift only
    /// while the block slips, mu g t_fast < v_slow + v_fast).
    pub generic_drift: bool,
    /// Drift only while mu g t_fast < k (v_slow + v_fast) (derived k = 1).
    pub slip_threshold: f64,
    /// The workbook's v_d = eps V (1 - k pi^2/(2 Gamma^2)) (derived k = 1).
    pub biharmonic_factor: f64,
    /// The workbook's Gamma_stick, scaled by this factor (derived 1).
    pub stick_gamma_factor: f64,
    /// 3.2.1 as printed: a window with "t2 so much greater than t1" has a small error
    /// from a non-integer number of cycles (`true`, the erratum); `false` prints the
    /// corrected condition, a window of many periods (t2 - t1 >> T).
    pub window_ratio_condition: bool,
}

/// The document as printed (and the workbook's closed forms as derived).
pub const PRINTED: Statements = Statements {
    linear_drift_fraction: 0.0,
    linear_force_factor: 1.0,
    nonlinear_changes: true,
    drift_factor: 1.0,
    regime_reversed: false,
    regime_threshold: 1.0,
    lock_factor: 1.0,
    mirror_sign: -1.0,
    printed_fast_left: true,
    along_slow_stroke: true,
    impulse_factor: 1.0,
    reach_factor: 1.0,
    generic_drift: true,
    slip_threshold: 1.0,
    biharmonic_factor: 1.0,
    stick_gamma_factor: 1.0,
    window_ratio_condition: true,
};
