//! The document's statements of section 2 (and the workbook's derived maximum of the
//! rod's ratio), as data: the numbers, signs and inequalities the claims judge. No
//! logic here; a falsification mutation ([`super::mutations`]) edits one field.

/// The statements.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statements {
    /// (A.1): effective mass along the stick, in units of m.
    pub mass_along: f64,
    /// (A.1): effective mass across the stick, in units of m (printed m/4).
    pub mass_across: f64,
    /// (A.1): the off-diagonal entry of [m]' in units of m (printed 0: diagonal).
    pub mass_off_diagonal: f64,
    /// Text after (A.1): a_C = F/(m/4), the factor 4 in units of F/m.
    pub a_c_factor: f64,
    /// J_l = k q J_v for the point-mass model (printed k = 1).
    pub point_mass_factor: f64,
    /// J_l = (a q/(c + q^2)) J_v for the uniform rod (printed a = 3, c = 4).
    pub rod_numerator: f64,
    /// The constant c of the rod's denominator (printed 4).
    pub rod_denominator: f64,
    /// At 45 degrees the point mass's J_l/J_v (printed 1).
    pub example_point_mass: f64,
    /// At 45 degrees the rod gives this fraction of the point mass's J_l (printed 60 %).
    pub example_rod_fraction: f64,
    /// The workbook's derived argmax q* = 2 of the rod's ratio.
    pub best_q: f64,
    /// The workbook's derived largest rod ratio 3/4.
    pub best_ratio: f64,
    /// Fig. 1 caption: theta < atan(k mu) is self-locking (printed k = 1) ...
    pub lock_factor: f64,
    /// ... with the inequality below (`true`, as printed) or above (`false`).
    pub lock_below: bool,
    /// (A.1) as printed: "the relation between contact acceleration and contact force"
    /// with nothing else (`false`); `true` prints the general relation with C's free
    /// acceleration b (gravity and the centripetal term): a_C = [m]'^-1 F + b.
    pub a1_free_acceleration: bool,
}

/// The document as printed (and the workbook's derived argmax).
pub const PRINTED: Statements = Statements {
    mass_along: 1.0,
    mass_across: 0.25,
    mass_off_diagonal: 0.0,
    a_c_factor: 4.0,
    point_mass_factor: 1.0,
    rod_numerator: 3.0,
    rod_denominator: 4.0,
    example_point_mass: 1.0,
    example_rod_fraction: 0.6,
    best_q: 2.0,
    best_ratio: 0.75,
    lock_factor: 1.0,
    lock_below: true,
    a1_free_acceleration: false,
};
