//! The statements the chapter checks, as data: the document's section 2 (the uniform
//! stick's impulse ratio and the massless one) and the chapter's derived statements
//! (the ratio in between, the Painleve boundary, its minimum, impacts that dissipate).
//! A falsification mutation edits one field by 10 % and the claim must fail.

/// The statements.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statements {
    /// Uniform stick (section 2): `J_l/J_v = a q / (b + q^2)` with `(a, b) = (3, 4)`.
    pub uniform_num: f64,
    /// See `uniform_num`.
    pub uniform_den: f64,
    /// Massless rod with a tip mass: `J_l/J_v = c q`, `c = 1`.
    pub massless_factor: f64,
    /// In between: `J_l/J_v = s alpha q / (1 + alpha + q^2)`, `s = 1`.
    pub between_scale: f64,
    /// The Painleve boundary `mu_P = s (tan theta + 1/(alpha sin theta cos theta))`, `s = 1`.
    pub painleve_scale: f64,
    /// The uniform rod's least `mu_P`: 4/3.
    pub painleve_min: f64,
    /// ... at `tan(theta) = 1/2`.
    pub painleve_min_tan: f64,
    /// The massless model's error vanishes like (I_P k/gamma^2)^order, order 1.
    pub massless_order: f64,
    /// The impact without collision is the compliant limit: its normal impulse at the
    /// slip stop times this factor (1).
    pub iwc_scale: f64,
    /// Moreau-Jean converges to the event-driven speed at this order (1).
    pub mj_order: f64,
    /// Impacts with restitution up to this value never create energy (1).
    pub restitution_max: f64,
}

/// The statements as derived (and, for the uniform stick, as printed).
pub const PRINTED: Statements = Statements {
    uniform_num: 3.0,
    uniform_den: 4.0,
    massless_factor: 1.0,
    between_scale: 1.0,
    painleve_scale: 1.0,
    painleve_min: 4.0 / 3.0,
    painleve_min_tan: 0.5,
    massless_order: 1.0,
    iwc_scale: 1.0,
    mj_order: 1.0,
    restitution_max: 1.0,
};

impl Statements {
    /// The uniform stick's ratio at `q = tan(theta)`.
    pub fn uniform_ratio(&self, q: f64) -> f64 {
        self.uniform_num * q / (self.uniform_den + q * q) // formula: J_l/J_v = 3q/(4+q^2)
    }

    /// The massless rod's ratio.
    pub fn massless_ratio(&self, q: f64) -> f64 {
        self.massless_factor * q // formula: J_l/J_v = q
    }

    /// The ratio of a rod with `alpha = M l_G^2 / I_G`.
    pub fn between_ratio(&self, q: f64, alpha: f64) -> f64 {
        self.between_scale * alpha * q / (1.0 + alpha + q * q) // formula: J_l/J_v = alpha q/(1+alpha+q^2)
    }

    /// The Painleve boundary.
    pub fn mu_painleve(&self, theta: f64, alpha: f64) -> f64 {
        self.painleve_scale * crate::physics::stick_inertia::painleve::mu_painleve(theta, alpha)
    }
}
