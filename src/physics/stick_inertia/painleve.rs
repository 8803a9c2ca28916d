//! Painleve cases of the sliding rod: typed events and the closed-form boundary.
//!
//! In a slide the normal acceleration of C is `a_Cz = A F_z + b_z` with
//! `A = D / (M I_G)` ([`super::InertiaModel::slide_coefficient`]). For `A > 0` the
//! contact problem (`F_z >= 0`, `a_Cz - a_s >= 0`, one of them zero) has one solution.
//! For `A < 0`: if the free motion would press C into the plate (`b_z < a_s`) there is
//! none (**inconsistent**); if it would lift C (`b_z > a_s`) there are two, `F_z = 0`
//! and `F_z = (a_s - b_z)/A > 0` (**indeterminate**). `A < 0` needs
//! `sigma mu sin(theta) cos(theta) > 0` and `mu > mu_P(theta)`.
//!
//! Rules (stated in the chapter): inconsistent -> an impact without collision, the
//! Darboux-Keller impulse of [`super::impact`] from `u_n = 0`; indeterminate -> the
//! solution without force (lift-off), the one a stiff compliant contact reaches from
//! exact contact (its zero-force state is unstable when `A < 0`).

/// Which Painleve case.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PainleveCase {
    /// No normal force solves the slide.
    Inconsistent,
    /// Two solutions (lift-off, and a compressive force).
    Indeterminate,
}

impl PainleveCase {
    /// snake_case name.
    pub fn name(self) -> &'static str {
        match self {
            PainleveCase::Inconsistent => "inconsistent",
            PainleveCase::Indeterminate => "indeterminate",
        }
    }
}

/// One Painleve event of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PainleveEvent {
    /// Time (s).
    pub t_s: f64,
    /// Angle (rad).
    pub theta_rad: f64,
    /// Friction coefficient (1).
    pub mu: f64,
    /// The boundary `mu_P(theta)` for this rod and slide direction (1).
    pub mu_p: f64,
    /// The case.
    pub case: PainleveCase,
    /// Friction sign of the slide (+1 left, -1 right).
    pub sigma: f64,
}

/// The Painleve boundary `mu_P = tan(theta) + 1/(alpha sin(theta) cos(theta))` (1), for
/// the slide whose friction points along `sign(sin theta cos theta)` (`sigma = +1` for
/// `0 < theta < 90 deg`: C slipping away from the side P leans to). Derived in the
/// chapter from `D = 0`; infinite for `theta = 0`.
pub fn mu_painleve(theta: f64, alpha: f64) -> f64 {
    let (s, c) = theta.sin_cos();
    theta.tan().abs() + 1.0 / (alpha * (s * c).abs()) // formula: mu_P = |tan| + 1/(alpha |sin cos|)
}

/// Angle of the least `mu_P` (rad): `tan(theta*) = 1/sqrt(1 + alpha)`, from
/// `d mu_P / d theta = 0`; `atan(1/2)` for the uniform rod (alpha = 3).
pub fn painleve_min_angle(alpha: f64) -> f64 {
    (1.0 / (1.0 + alpha).sqrt()).atan() // formula: tan theta* = (1+alpha)^(-1/2)
}

/// The least `mu_P`: `2 sqrt(1 + alpha)/alpha` (1); 4/3 for alpha = 3.
pub fn painleve_min(alpha: f64) -> f64 {
    2.0 * (1.0 + alpha).sqrt() / alpha // formula: mu_P(theta*) = 2 sqrt(1+alpha)/alpha
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn minimum_is_where_the_closed_form_says() {
        for alpha in [0.5, 3.0, 10.0, 100.0] {
            let th = painleve_min_angle(alpha);
            let m = mu_painleve(th, alpha);
            assert!((m - painleve_min(alpha)).abs() < 1e-12);
            for dt in [-1e-3, 1e-3] {
                assert!(mu_painleve(th + dt, alpha) > m);
            }
        }
        assert!((painleve_min(3.0) - 4.0 / 3.0).abs() < 1e-15);
    }
}
