//! Falsification: edits of the chapter's statements ([`Statements`]), each judged by
//! the same claim functions ([`super::claims`]) on the evidence of the default flags
//! in quick mode, computed once per process. A statement about a method (the event
//! search, soft contact's friction family) is a flag that makes its claim look at the
//! evidence's run of the other method.
//!
//! A 10 % mutation edits a number the document prints ("10 %" in its description): of
//! this chapter's claims only `flight-map-economy` rests on one (section 3.1.2's
//! `v_ave = (F/2m) t_f`, whose 1/2 becomes the flight-map law's). The others have none,
//! for a reason each:
//! - a number the workbook derived, not one the document prints
//!   (`stiff-relaxation-explicit-blowup`: the methods' stability limits 2 and 2.785 on
//!   C.3's relaxation, which prints only k/gamma; `zeno-ball-stops-at-accumulation` and
//!   `zeno-ball-moreau-jean-rest`: the accumulation time t1 (1 + e)/(1 - e) of a ball the
//!   document never mentions; `zeno-plate-resolved-two-ways`: two of the workbook's
//!   methods agreeing; `viscous-law-economy`: c = 2 mu m g/(pi V), the workbook's
//!   derivation of the viscous law section 3.1.1 states without a coefficient): their
//!   mutations move the derived number (by 10 % or more, said as "derived") to show the
//!   check is sharp, and are not counted as edits of the document;
//! - an integer order of convergence (`stick-rk4-located-order` 4,
//!   `stick-euler-located-order` 1, `stick-methods-moreau-jean-order` 1,
//!   `soft-contact-order` 1): an order off by 10 % is no order; the neighbouring
//!   orders (off by one) are the mutations, and the bands are derived so that they fail;
//! - a ratio whose tolerance is the estimate's own uncertainty
//!   (`stick-methods-moreau-jean-gap-within-estimate`, `soft-contact-richardson-gap`,
//!   ratio 1 within Richardson's range for the order band): the mutation is the
//!   estimate with the wrong order (a factor 3 off);
//! - the reference checks (`reference-converged`, `stick-reference-converged`): the
//!   workbook's self-checks of its references, judged against the runs' own error
//!   budget (`budget.rs`), so no tolerance of theirs is a printed number; the mutation is
//!   a wrong reference, off by 1e-6 relative, which the budget must see;
//! - a tolerance or a step range printed as a setting, not a statement about the model
//!   (`stick-unlocated-events-stall`,
//!   `stick-dop853-cheaper-at-1e-10`, `stick-no-missed-event`): the mutation reverses
//!   the inequality (a loose reference, "converges", "DP5 cheaper", the uncertified
//!   search);
//! - the claims of section `numerics` are the workbook's own statements about its
//!   methods, not the document's; each has its inequality reversed or its tolerance
//!   loosened as mutation.

/// The chapter's document claims without a 10 % mutation, each with its reason (the
/// list above, as data for `tests/falsification.rs`).
pub const NO_TEN_PERCENT: &[(&str, &str)] = &[
    ("stiff-relaxation-explicit-blowup", DERIVED),
    ("zeno-ball-stops-at-accumulation", DERIVED),
    ("zeno-ball-moreau-jean-rest", DERIVED),
    ("zeno-plate-resolved-two-ways", DERIVED),
    ("viscous-law-economy", DERIVED),
    ("reference-converged", REFERENCE),
    ("reference-convergence-study", OWN),
    ("euler-located-order", ORDER),
    ("moreau-jean-order", ORDER),
    ("unlocated-events-stall", SETTING),
    ("stick-reference-converged", REFERENCE),
    ("stick-rk4-located-order", ORDER),
    ("stick-euler-located-order", ORDER),
    ("stick-unlocated-events-stall", SETTING),
    ("stick-dop853-cheaper-at-1e-10", SETTING),
    ("stick-no-missed-event", OWN),
    ("stick-methods-moreau-jean-order", ORDER),
    ("stick-methods-moreau-jean-gap-within-estimate", RATIO),
    ("soft-contact-order", ORDER),
    ("soft-contact-richardson-gap", RATIO),
];

/// Why a number the workbook derived has no 10 % mutation.
const DERIVED: &str = "the document prints no number here: the number checked (a stability limit, an accumulation time, a ratio of two methods, the viscous coefficient 2 mu m g/(pi V)) is the workbook's own derivation; its mutations move that derived number to show the check is sharp, not an edit of the document";
/// Why an order of convergence has no 10 % mutation.
const ORDER: &str = "an integer order of convergence: an order off by 10 % is no order; the neighbouring order (off by one) is the mutation, and the band is derived so that it fails";
/// Why an estimate's ratio has none.
const RATIO: &str = "a ratio whose tolerance is the estimate's own uncertainty ((2^p - 1)/(2^p' - 1) for a true local order p' within the order band): the mutation is the estimate with the wrong order, a factor 3 off";
/// Why a tolerance printed as a setting has none.
const SETTING: &str = "a tolerance or step range printed as a setting, not a statement about the model: the mutation reverses the inequality";
/// Why a reference check has none.
const REFERENCE: &str = "the workbook's self-check of its reference against the runs' own error budget (rounding, and truncation bounded from the runs at tau and tau/10): no printed number; the mutation is a wrong reference, off by 1e-6 relative";
/// Why the workbook's own statements have none.
const OWN: &str = "the workbook's own statement about its methods (no printed number of the document): the mutation reverses it";

use super::claims;
use super::evidence::{gather, Evidence};
use super::statements::Statements;
use crate::chapters::Context;
use crate::report::{Claim, DocEdit, Falsifiable};

/// The chapter's document for the generic judge (`crate::report::falsify`): the
/// evidence of the default flags in quick mode (the tests' context: g = 9.81 m/s^2 for
/// the block, the authors' 10 for the stick).
pub struct Document;

impl Falsifiable for Document {
    type Statements = Statements;
    type Evidence = Evidence;
    fn printed() -> Statements {
        Statements::PRINTED
    }
    fn quick_evidence() -> Evidence {
        let ctx = Context::headless(true);
        gather(&super::Args::default(), ctx.g(), super::stick_g_mps2(&ctx), true)
    }
    fn claims(st: &Statements, ev: &Evidence) -> Vec<Claim> {
        claims::all(st, ev)
    }
    const EDITS: &'static [DocEdit<Statements>] = &EDITS;
    const WITHOUT_TEN_PERCENT: &'static [(&'static str, &'static str)] = NO_TEN_PERCENT;
}

/// The edits of the statements: a neighbouring order, a reversed inequality, a limit
/// or coefficient off by 10 % or more, one per claim at least (a data table).
const EDITS: [DocEdit<Statements>; 27] = [
    (
        "reference-converged",
        "a wrong reference: the closed-form drift off by 1e-6 relative",
        |d| d.reference_offset_rel = 1e-6,
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
        "derived Euler limit h/tau < 2 -> < 2.2",
        |d| d.euler_limit = 2.2,
    ),
    (
        "stiff-relaxation-explicit-blowup",
        "derived RK4 limit h/tau < 2.785 -> < 3.06",
        |d| d.rk4_limit = 1.1 * 2.785,
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
        "derived t_inf = t1 (1 + e)/(1 - e) -> 1.1 x",
        |d| d.zeno_factor = 1.1,
    ),
    (
        "zeno-ball-moreau-jean-rest",
        "derived t_inf = t1 (1 + e)/(1 - e) -> 1.1 x",
        |d| d.zeno_factor = 1.1,
    ),
    (
        "zeno-plate-resolved-two-ways",
        "same drift -> Moreau-Jean 1.1 x the event-driven drift (derived)",
        |d| d.zeno_plate_factor = 1.1,
    ),
    (
        "stick-reference-converged",
        "a wrong reference: DP5's mean speed at 1e-13 off by 1e-6 relative",
        |d| d.reference_offset_rel = 1e-6,
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
        "v_ave = (F/2m) t_f (section 3.1.2) -> 1.1 F/(2m) t_f, so v = 1.1 b mu g t_f^2/(2 n T) (10 %)",
        |d| d.flight_map_factor = 1.1,
    ),
    (
        "viscous-law-economy",
        "derived c = 2 mu m g/(pi V) -> 1.1 x",
        |d| d.viscous_factor = 1.1,
    ),
    (
        "stick-no-missed-event",
        "event search without certification (signs at step ends only)",
        |d| d.certified_search = false,
    ),
    (
        "stick-methods-moreau-jean-order",
        "Moreau-Jean order 1 -> 2",
        |d| d.mj_order = 2.0,
    ),
    (
        "stick-methods-moreau-jean-gap-within-estimate",
        "Richardson estimate with order 2 instead of 1",
        |d| d.mj_order = 2.0,
    ),
    ("soft-contact-order", "soft contact order 1 -> 2", |d| {
        d.soft_order = 2.0
    }),
    (
        "soft-contact-order",
        "soft contact with friction smoothing v_ε = 0.1 ε (m/s) instead of v₀ ε²",
        |d| d.soft_friction_quadratic = false,
    ),
    (
        "soft-contact-richardson-gap",
        "soft contact's Richardson estimate with order 2 instead of 1",
        |d| d.soft_order = 2.0,
    ),
];
