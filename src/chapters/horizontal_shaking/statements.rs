//! The document's statements of section 3.1.1 (and the workbook's derived law), as
//! data: the numbers, signs and inequalities the claims judge. No logic here; a
//! falsification mutation ([`super::mutations`]) edits one field.

/// The statements.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statements {
    /// Non-sliding only while |a_support| <= k mu g (printed k = 1).
    pub stick_factor: f64,
    /// The limit of the mean friction (fraction of mu m g) for fast shaking (printed 0).
    pub fast_limit: f64,
    /// The remaining friction grows like v^p (printed: viscous, p = 1).
    pub friction_exponent: f64,
    /// The workbook's averaged law v = V sin(k pi F/(2 mu m g)) (derived k = 1).
    pub arcsin_factor: f64,
    /// Booktop: the slip tilt is atan(k mu) (printed k = 1).
    pub tilt_factor: f64,
    /// Booktop: the shaken coin slides down the tilt (`true`, printed) or up.
    pub slides_down: bool,
    /// "The fluctuation in object velocities is small": the workbook's exact swing
    /// (peak to peak, over V) is (1 - b^2) k / Gamma_x while the block never sticks
    /// (derived k = pi).
    pub fluctuation_coeff: f64,
    /// "As the frequency goes to infinity ... the average force tends to zero", read at
    /// fixed amplitude: at fixed V = delta_x omega instead the mean friction at v tends
    /// to k asin(v/V) mu m g (derived k = 2/pi), not zero.
    pub fixed_v_coeff: f64,
}

/// The document as printed.
pub const PRINTED: Statements = Statements {
    stick_factor: 1.0,
    fast_limit: 0.0,
    friction_exponent: 1.0,
    arcsin_factor: 1.0,
    tilt_factor: 1.0,
    slides_down: true,
    fluctuation_coeff: std::f64::consts::PI,
    fixed_v_coeff: std::f64::consts::FRAC_2_PI,
};
