//! The statements behind the chapter's claims (the document's and the workbook's own:
//! orders of methods, stability limits, closed forms), as data: the falsification
//! tests feed the checks wrong variants of them.

use crate::report::Mutation;

/// The statements, as data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Doc {
    /// The reference is checked against Dormand-Prince at this tolerance (1e-12).
    pub reference_tol: f64,
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
}

impl Doc {
    /// The statements as printed (or as derived by the workbook).
    pub const PRINTED: Doc = Doc {
        reference_tol: 1e-12,
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
    };
}

/// The falsification mutations: a neighbouring order, a reversed inequality, a limit
/// or coefficient off by 10 % or more, one per claim at least.
pub fn mutations() -> Vec<Mutation> {
    type Edit = fn(&mut Doc);
    let list: [(&'static str, &'static str, Edit); 19] = [
        (
            "reference-converged",
            "checked against DP5 at 1e-12 -> at 1e-4",
            |d| d.reference_tol = 1e-4,
        ),
        (
            "reference-convergence-study",
            "errors shrink as the tolerance tightens -> grow",
            |d| d.tightening_helps = false,
        ),
        (
            "euler-located-order",
            "at least first order -> at least second order",
            |d| d.first_order = 2.0,
        ),
        (
            "moreau-jean-order",
            "at least first order -> at least second order",
            |d| d.first_order = 2.0,
        ),
        (
            "unlocated-events-stall",
            "stalls -> converges like the located run",
            |d| d.unlocated_stalls = false,
        ),
        (
            "stiff-relaxation-explicit-blowup",
            "Euler stable for h/tau < 2 -> < 4",
            |d| d.euler_limit = 4.0,
        ),
        (
            "stiff-relaxation-explicit-blowup",
            "RK4 stable for h/tau < 2.785 -> < 4",
            |d| d.rk4_limit = 4.0,
        ),
        (
            "zeno-ball-stops-at-accumulation",
            "t_inf = t1 (1 + e)/(1 - e) -> 1.1 x",
            |d| d.zeno_factor = 1.1,
        ),
        (
            "zeno-ball-moreau-jean-rest",
            "t_inf = t1 (1 + e)/(1 - e) -> 1.1 x",
            |d| d.zeno_factor = 1.1,
        ),
        (
            "zeno-plate-resolved-two-ways",
            "same drift -> Moreau-Jean 1.1 x the event-driven drift",
            |d| d.zeno_plate_factor = 1.1,
        ),
        (
            "stick-reference-converged",
            "checked against DP5 at 1e-11, 1e-12 -> at 1e-4",
            |d| d.reference_tol = 1e-4,
        ),
        ("stick-rk4-located-order", "order 4 -> 3", |d| {
            d.rk4_order = 3.0
        }),
        ("stick-rk4-located-order", "order 4 -> 5", |d| {
            d.rk4_order = 5.0
        }),
        ("stick-euler-located-order", "order 1 -> 2", |d| {
            d.euler_order = 2.0
        }),
        ("stick-euler-located-order", "order 1 -> 0.5", |d| {
            d.euler_order = 0.5
        }),
        (
            "stick-unlocated-events-stall",
            "stalls -> converges like the located run",
            |d| d.unlocated_stalls = false,
        ),
        (
            "stick-dop853-cheaper-at-1e-10",
            "DOP853 cheaper -> DP5 cheaper",
            |d| d.dop853_cheaper = false,
        ),
        (
            "flight-map-economy",
            "v = b mu g t_f^2/(2 n T) -> 1.1 x",
            |d| d.flight_map_factor = 1.1,
        ),
        ("viscous-law-economy", "c = 2 mu m g/(pi V) -> 1.1 x", |d| {
            d.viscous_factor = 1.1
        }),
    ];
    Mutation::from_edits(Doc::PRINTED, list, |id, d| {
        crate::chapters::quick_claim(id, d, super::run_with)
    })
}
