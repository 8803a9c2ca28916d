//! The statements behind the chapter's claims (the document's and the workbook's own:
//! orders of methods, stability limits, closed forms), as data, no logic: the
//! falsification mutations (`mutations.rs`) feed the checks wrong variants of them.

/// The statements, as data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statements {
    /// The reference is checked against Dormand-Prince at this tolerance (1e-12).
    pub reference_tol: f64,
    /// The references as the workbook computes them, shifted by this relative amount
    /// (0): the mutations' wrong reference (1e-6) that the reference checks must see.
    pub reference_offset_rel: f64,
    /// Errors shrink as the tolerance tightens (`true`) or grow (`false`).
    pub tightening_helps: bool,
    /// Explicit Euler's and Moreau-Jean's order on the block: at least this (1).
    pub first_order: f64,
    /// RK4's order with located events (4).
    pub rk4_order: f64,
    /// Explicit Euler's order with located events on the stick (1).
    pub euler_order: f64,
    /// Without event location the error stalls (`true`) or converges (`false`).
    pub unlocated_stalls: bool,
    /// Explicit Euler's stability limit h/tau on a linear decay (2).
    pub euler_limit: f64,
    /// RK4's stability limit h/tau on a linear decay (2.785).
    pub rk4_limit: f64,
    /// The accumulation time t1 (1 + e)/(1 - e), scaled by this factor (1).
    pub zeno_factor: f64,
    /// Moreau-Jean's drift = k x the event-driven one on the chattering plate (1).
    pub zeno_plate_factor: f64,
    /// DOP853 needs fewer right-hand sides than DP5 at 1e-10 (`true`).
    pub dop853_cheaper: bool,
    /// The flight-map law's coefficient 1/2 in v = b mu g t_f^2/(2 n T), scaled (1).
    pub flight_map_factor: f64,
    /// The viscous law's c = 2 mu m g/(pi V), scaled (1).
    pub viscous_factor: f64,
    /// Moreau-Jean's order in the step h on the stick (1).
    pub mj_order: f64,
    /// Soft contact's order in the regularisation eps (1).
    pub soft_order: f64,
    /// Soft contact's friction smoothing is `v_eps = v_0 eps^2` (`true`); `false`: the
    /// first family's `v_eps = 0.1 eps` m/s.
    pub soft_friction_quadratic: bool,
    /// The event search that misses no short lift-off is the certified one (`true`);
    /// `false`: comparing signs at step ends suffices.
    pub certified_search: bool,
}

impl Statements {
    /// The statements as printed (or as derived by the workbook).
    pub const PRINTED: Statements = Statements {
        reference_tol: 1e-12,
        reference_offset_rel: 0.0,
        tightening_helps: true,
        first_order: 1.0,
        rk4_order: 4.0,
        euler_order: 1.0,
        unlocated_stalls: true,
        euler_limit: 2.0,
        rk4_limit: 2.785,
        zeno_factor: 1.0,
        zeno_plate_factor: 1.0,
        dop853_cheaper: true,
        flight_map_factor: 1.0,
        viscous_factor: 1.0,
        mj_order: 1.0,
        soft_order: 1.0,
        soft_friction_quadratic: true,
        certified_search: true,
    };
}
