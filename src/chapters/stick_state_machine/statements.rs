//! The document's statements of sections 4 and 5 as data, no logic: each claim
//! (`claims.rs`) reads the coefficient, sign, inequality or rule it tests from a
//! [`Statements`], so a falsification mutation (`mutations.rs`) can feed it a wrong
//! variant.

/// A printed inequality on the hinge forces, `mu F_z + fx_sign F_x (> or <) 0`
/// (evaluated by `rule_claims::fires`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Test {
    /// Sign of `F_x` in the test (1).
    pub fx_sign: f64,
    /// `>` (true) or `<` (false).
    pub greater: bool,
    /// Coefficient of `mu F_z` (printed 1).
    pub mu_coef: f64,
}

/// The statements (see [`PRINTED`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statements {
    /// C.3: `theta' = -flight_rate (k/gamma)(theta - theta_0)` in flight (1).
    pub flight_rate: f64,
    /// C.5: `zddot_p = -flight_gravity g` (1).
    pub flight_gravity: f64,
    /// C.3's third row is printed among the general kinematics (true) or for flight only.
    pub c3_general: bool,
    /// C.6: `m L^2 theta'' = (g + c6_plate zddot_s) m L sin - c6_spring k (theta - theta_0) - gamma theta'`.
    pub c6_plate: f64,
    /// See `c6_plate` (1).
    pub c6_spring: f64,
    /// Section 4.2: C.6 comes "from the conservation of angular momentum" (true).
    pub c6_conservation: bool,
    /// C.9: `F_z = Q / (L (sin + c9_mu mu cos))` for sliding left (printed -1).
    pub c9_mu: f64,
    /// C.11: `F_z = Q / (L (sin + c11_mu mu cos))` for sliding right (printed +1).
    pub c11_mu: f64,
    /// C.14: `theta'' = (1/sin)((zddot_c - zddot_p)/L + c14_w2 theta'^2 cos)` (printed -1).
    pub c14_w2: f64,
    /// C.15: `theta'+ = c15_sign (r x (v_p - zdot_s k)) / L^2` (printed -1).
    pub c15_sign: f64,
    /// C.15: the axis of the angular momentum `r x v` (printed k, the vertical).
    pub c15_axis: [f64; 3],
    /// Section 4.4: "A collision event happens when the stick exits the flight phase
    /// ... θ' needs to be evaluated by equating the angular moment H about the point
    /// C": C.15 applies at every collision (true, as printed) or at the sticking ones.
    pub s44_every_collision: bool,
    /// Section 4.4: after the collision `theta = reset_factor theta_0 + reset_offset`
    /// (printed 1).
    pub reset_factor: f64,
    /// See `reset_factor` (rad; printed 0).
    pub reset_offset_rad: f64,
    /// Section 4.3: in sliding left "the point P moves down vertically" (true).
    pub s43_p_vertical: bool,
    /// C.10's first row: x_p'' = c10_x mu F_z/m (1 as printed).
    pub c10_x: f64,
    /// C.13's first row: x_p'' = c13_x mu F_z/m (-1 as printed).
    pub c13_x: f64,
    /// C.14's x_c'' row: -mu F_z/m - L(c14_xc_w2 theta'^2 sin + theta'' cos) (-1 printed).
    pub c14_xc_w2: f64,
    /// C.12 (the sliding-left angle equation) printed (`false`: blank, as printed).
    pub c12_printed: bool,
    /// Section 4.3 (Sliding Left): "in the pivot mode the system has two degrees of
    /// freedom" (`true`, as printed; `false`: the sentence names the sliding mode).
    pub pivot_two_dof: bool,
    /// Section 4.3: the number of degrees of freedom the sentence prints (2).
    pub s43_dof: f64,
    /// Table 1, Sliding Left: the sign of `v_x` (printed -1, `v_x < 0`).
    pub t1_left_v: f64,
    /// Table 1, Sliding Right: the sign of `v_x` (printed -1, `v_x < 0`).
    pub t1_right_v: f64,
    /// Alg. 1: the SLIDE RIGHT test (printed `mu F_z + F_x > 0`).
    pub a1_right: Test,
    /// Alg. 1: the SLIDE LEFT test (printed `mu F_z - F_x > 0`).
    pub a1_left: Test,
    /// Alg. 1: FLIGHT if `F_z > 0` (true) or `F_z < 0` (false).
    pub a1_flight_positive: bool,
    /// Alg. 1: `|theta| = 0` -> FLIGHT (true).
    pub a1_vertical_flight: bool,
    /// Alg. 1-4: ABORT heights measured from z = 0 (true) or from the plate.
    pub abort_absolute: bool,
    /// Alg. 2: the sticking test uses `tan(theta)` (false) or `|tan(theta)|` (true).
    pub a2_tan_abs: bool,
    /// Alg. 2: the sticking test's coefficient of `mu`, `tan(theta) <= a2_tan_mu mu` (1).
    pub a2_tan_mu: f64,
    /// Alg. 2: `r_CP` points from C to P (true: the authors' fsm.m, `vec_rcp = L (sin,
    /// cos)`) or from P to C (the reading fsm.m rules out).
    pub rcp_from_c: bool,
    /// Alg. 2: the impulse is applied when `(v_p - v_s) . r_CP >= 0` (true, "rod not
    /// shortening") or when it is `< 0`.
    pub a2_impulse_if_nonnegative: bool,
    /// Alg. 2: `theta' = a2_theta_sign (r_CP x (v_p - v_s)) / L^2` (printed +1).
    pub a2_theta_sign: f64,
    /// Alg. 2: HINGE if `mu F_z < |F_x|` (true) or `mu F_z >= |F_x|`.
    pub a2_hinge_lt: bool,
    /// Alg. 2: the hinge test's coefficient of `mu F_z` (printed 1).
    pub a2_hinge_mu: f64,
    /// Alg. 2: the slide choice after the hinge test is a separate `if` (false) or its `else`.
    pub a2_slide_is_else: bool,
    /// Alg. 2: `assert` read as an assignment (true, the last wins) or a return.
    pub last_assert_wins: bool,
    /// Alg. 2: `if F_x > 0` SLIDE LEFT (true) else SLIDE RIGHT.
    pub a2_left_if_fx_positive: bool,
    /// Alg. 2: a tensional ground reaction implies FLIGHT (true).
    pub a2_tension_flight: bool,
    /// Alg. 2: after the angular-momentum map, `if x_c' > 0` picks the slide (true).
    pub a2_dead_branch: bool,
    /// Alg. 2, `tan > mu` branch: the slide test reads `x_c'` before its assignment (true).
    pub a2_test_before_assign: bool,
    /// Alg. 2, `tan > mu` branch: `theta' <- a2_free_sign (z_p' - z_s')/(L sin)` (printed -1).
    pub a2_free_sign: f64,
    /// Alg. 3, 4: the hinge test applies while C slips (true) or once it stopped.
    pub slide_hinge_while_slipping: bool,
    /// Alg. 3, 4: the hinge test's coefficient of `mu F_z`, `mu F_z >= |F_x|` (printed 1).
    pub slide_hinge_mu: f64,
    /// Alg. 3, 4: a failed hinge test goes to the other slide (true) or the same one.
    pub slide_to_other: bool,
    /// Alg. 3, 4: the new slide's `F_z <= 0` -> ABORT (true) or FLIGHT.
    pub slide_abort: bool,
    /// Alg. 3, 4: FLIGHT also when `F_x = 0` (true).
    pub slide_flight_on_fx: bool,
    /// Algorithms 1 to 4: "Compute Fx and Fz in the HINGE Phase" has a formula in
    /// section 4.2 (`false`: as printed, C.6 and C.7 give theta'' and a_P, not F).
    pub hinge_force_printed: bool,
    /// Alg. 2: landing when `z_c - z_s = 0`, an equality tested at every instant, after
    /// lift-offs that set `z_c <- z_s` (true, as printed), or a falling crossing after
    /// the flight's start (false).
    pub landing_equality: bool,
    /// Alg. 2 applies section 4.4's `theta = theta_0` after a collision (`false`: as
    /// printed, no line of Algorithm 2 assigns theta).
    pub a2_resets_theta: bool,
    /// Table 1's Flight row (three entries, `> 0 = 0 = 0`, for four columns) read
    /// left-aligned: `v_x = 0` and `F_z = 0` (true, as typeset) or under F_z and F_x.
    pub t1_flight_vx_zero: bool,
    /// Section 4.3: the pivot slips when "F_x exceeds the frictional force", `F_x > mu
    /// F_z` signed (`false`, as printed) or `|F_x| > mu F_z`.
    pub s43_exceeds_abs: bool,
    /// Table 1's caption: the new state is the one whose inequalities hold "for the
    /// present values of the state variables" (true, as printed) or a moment later.
    pub caption_present_values: bool,
    /// Alg. 3, 4: at a slip stop where neither the hinge nor the other slide holds,
    /// ABORT (true, as printed) or the first consistent mode (flight if it lifts C).
    pub slip_stop_abort: bool,
    /// Sections 4.3 and 5 give a rule for a slide reaching the zero of C.9's (C.11's)
    /// denominator, `tan(theta) = sigma mu` (`false`: none printed).
    pub edge_rule_printed: bool,
    /// The rtol pair at which the phase sequence is claimed identical (section 5's state
    /// machine is discrete: its history must not depend on the tolerance).
    pub sequence_rtols: [f64; 2],
    /// Events located on the dense output (true) or taken at step ends.
    pub sequence_located: bool,
    /// The workbook's statements of the limit-cycle section (`cycle_claims.rs`).
    pub cycle: CycleStatements,
}

/// The statements as printed.
pub const PRINTED: Statements = Statements {
    flight_rate: 1.0,
    flight_gravity: 1.0,
    c3_general: true,
    c6_plate: 1.0,
    c6_spring: 1.0,
    c6_conservation: true,
    c9_mu: -1.0,
    c11_mu: 1.0,
    c14_w2: -1.0,
    c15_sign: -1.0,
    c15_axis: [0.0, 0.0, 1.0],
    s44_every_collision: true,
    reset_factor: 1.0,
    reset_offset_rad: 0.0,
    s43_p_vertical: true,
    c10_x: 1.0,
    c13_x: -1.0,
    c14_xc_w2: -1.0,
    c12_printed: false,
    pivot_two_dof: true,
    s43_dof: 2.0,
    t1_left_v: -1.0,
    t1_right_v: -1.0,
    a1_right: Test {
        fx_sign: 1.0,
        greater: true,
        mu_coef: 1.0,
    },
    a1_left: Test {
        fx_sign: -1.0,
        greater: true,
        mu_coef: 1.0,
    },
    a1_flight_positive: true,
    a1_vertical_flight: true,
    abort_absolute: true,
    a2_tan_abs: false,
    a2_tan_mu: 1.0,
    rcp_from_c: true,
    a2_impulse_if_nonnegative: true,
    a2_theta_sign: 1.0,
    a2_hinge_lt: true,
    a2_hinge_mu: 1.0,
    a2_slide_is_else: false,
    last_assert_wins: true,
    a2_left_if_fx_positive: true,
    a2_tension_flight: true,
    a2_dead_branch: true,
    a2_test_before_assign: true,
    a2_free_sign: -1.0,
    slide_hinge_while_slipping: true,
    slide_hinge_mu: 1.0,
    slide_to_other: true,
    slide_abort: true,
    slide_flight_on_fx: true,
    hinge_force_printed: false,
    landing_equality: true,
    a2_resets_theta: false,
    t1_flight_vx_zero: true,
    s43_exceeds_abs: false,
    caption_present_values: true,
    slip_stop_abort: true,
    edge_rule_printed: false,
    sequence_rtols: [1e-10, 1e-8],
    sequence_located: true,
    cycle: WORKBOOK_CYCLE,
};

/// What the claims of the section "The gait as a limit cycle" state (the workbook's
/// statements, not the document's: it makes none about a limit cycle; the mutations
/// change one field).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleStatements {
    /// The convergence claim reads central differences (true) or forward ones.
    pub central: bool,
    /// The order of convergence stated for it.
    pub order: f64,
    /// The second method multiplies the saltation matrices in (true) or only the
    /// resets' Jacobians.
    pub saltation: bool,
    /// Factor on the stated rate of approach (1: the largest multiplier modulus).
    pub rate_factor: f64,
}

/// The workbook's statements of the limit-cycle section.
pub const WORKBOOK_CYCLE: CycleStatements = CycleStatements {
    central: true,
    order: 2.0,
    saltation: true,
    rate_factor: 1.0,
};
