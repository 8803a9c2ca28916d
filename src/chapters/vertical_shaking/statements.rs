//! The document's statements of section 3.1.2 (and the workbook's derived values the
//! checks compare with), as data, no logic: the claims of `super::claims` judge them,
//! and the mutations of `super::mutations` feed the same claims wrong variants.

/// The statements, as data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statements {
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
    /// The flight's sideways motion is extinguished at the next collision for biases up
    /// to this fraction of mu m g (printed: 1, "a sideways load that is less than mu
    /// times the average normal force").
    pub landing_stick_bound: f64,
    /// The workbook's closed-form b* of `super::landing`, scaled by this factor (derived 1).
    pub landing_closed_form_factor: f64,
}

/// The document as printed.
pub const PRINTED: Statements = Statements {
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
    landing_stick_bound: 1.0,
    landing_closed_form_factor: 1.0,
};
