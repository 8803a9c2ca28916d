//! Falsification: edits of the chapter's statements ([`Statements`]), each judged by
//! the same checks as the printed ones (the chapter re-run, quick, with the edited
//! statements), plus the missed-event and stick-methods mutations.
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
//!   ratio 1 within 0.5): the mutation is the estimate with the wrong order (a factor
//!   3 off);
//! - a tolerance or a step range printed as a setting, not a statement about the model
//!   (`stick-reference-converged`, `stick-unlocated-events-stall`,
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
    ("reference-converged", SETTING),
    ("reference-convergence-study", OWN),
    ("euler-located-order", ORDER),
    ("moreau-jean-order", ORDER),
    ("unlocated-events-stall", SETTING),
    ("stick-reference-converged", SETTING),
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
const RATIO: &str = "a ratio whose tolerance is the estimate's own uncertainty (1 within 0.5): the mutation is the estimate with the wrong order, a factor 3 off";
/// Why a tolerance printed as a setting has none.
const SETTING: &str = "a tolerance or step range printed as a setting, not a statement about the model: the mutation reverses the inequality";
/// Why the workbook's own statements have none.
const OWN: &str = "the workbook's own statement about its methods (no printed number of the document): the mutation reverses it";

use super::statements::Statements;
use crate::chapters::{default_args, Context};
use crate::report::{Claim, DocEdit, Falsifiable, Mutation};

/// The chapter's statements as the generic judge sees them. A temporary adapter until
/// the chapter has its `evidence.rs` and `claims.rs`: `legacy` names one of the
/// mutations that are not yet edits of [`Statements`] (the uncertified event search and
/// the stick methods' wrong orders, [`legacy_mutations`]).
#[derive(Debug, Clone, Copy)]
pub struct AdapterStatements {
    /// The chapter's statements.
    doc: Statements,
    /// Index into [`legacy_mutations`], or none.
    legacy: Option<usize>,
}

/// The chapter's document for the generic judge (`crate::report::falsify`); its
/// claims re-run the quick chapter (its evidence is not one value yet).
pub struct Document;

impl Falsifiable for Document {
    type Statements = AdapterStatements;
    type Evidence = ();
    fn printed() -> AdapterStatements {
        AdapterStatements {
            doc: Statements::PRINTED,
            legacy: None,
        }
    }
    fn quick_evidence() {}
    fn claims(st: &AdapterStatements, _: &()) -> Vec<Claim> {
        if let Some(i) = st.legacy {
            let mut m = legacy_mutations();
            return vec![(m.swap_remove(i).run)()];
        }
        let r = super::run_with(&default_args(), &Context::headless(true), &st.doc);
        r.expect("default flags are valid").claims
    }
    const EDITS: &'static [DocEdit<AdapterStatements>] = &{
        let mut out = [("", "", (|_| {}) as fn(&mut AdapterStatements)); EDITS.len() + 6];
        let mut i = 0;
        while i < EDITS.len() {
            out[i] = (EDITS[i].0, EDITS[i].1, ADAPTED[i]);
            i += 1;
        }
        out[i] = L0;
        out[i + 1] = L1;
        out[i + 2] = L2;
        out[i + 3] = L3;
        out[i + 4] = L4;
        out[i + 5] = L5;
        out
    };
    const WITHOUT_TEN_PERCENT: &'static [(&'static str, &'static str)] = NO_TEN_PERCENT;
}

/// The mutations that are not edits of [`Statements`] yet, in a fixed order.
fn legacy_mutations() -> Vec<Mutation> {
    let mut all = vec![super::missed_event::mutation()];
    all.extend(super::stick_methods_report::mutations());
    all
}

/// Edit `i` of [`EDITS`] lifted to the adapter's statements.
macro_rules! adapted {
    ($($i:literal),*) => {
        [$((|d: &mut AdapterStatements| (EDITS[$i].2)(&mut d.doc)) as fn(&mut AdapterStatements)),*]
    };
}
const ADAPTED: [fn(&mut AdapterStatements); 21] =
    adapted!(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20);

/// The legacy mutation `i` (see [`legacy_mutations`]; its claim id and description
/// repeated here, checked by the falsification test, which runs it).
macro_rules! legacy {
    ($name:ident, $i:literal, $id:literal, $what:literal) => {
        const $name: DocEdit<AdapterStatements> = ($id, $what, |d| d.legacy = Some($i));
    };
}
legacy!(
    L0,
    0,
    "stick-no-missed-event",
    "event search without certification (signs at step ends only)"
);
legacy!(
    L1,
    1,
    "stick-methods-moreau-jean-order",
    "Moreau-Jean order 1 -> 2"
);
legacy!(
    L2,
    2,
    "stick-methods-moreau-jean-gap-within-estimate",
    "Richardson estimate with order 2 instead of 1"
);
legacy!(L3, 3, "soft-contact-order", "soft contact order 1 -> 2");
legacy!(
    L4,
    4,
    "soft-contact-order",
    "soft contact with friction smoothing v_ε = 0.1 ε (m/s) instead of v₀ ε²"
);
legacy!(
    L5,
    5,
    "soft-contact-richardson-gap",
    "soft contact's Richardson estimate with order 2 instead of 1"
);

/// The edits of the statements: a neighbouring order, a reversed inequality, a limit
/// or coefficient off by 10 % or more, one per claim at least (a data table).
const EDITS: [DocEdit<Statements>; 21] = [
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
        "v_ave = (F/2m) t_f (section 3.1.2) -> 1.1 F/(2m) t_f, so v = 1.1 b mu g t_f^2/(2 n T) (10 %)",
        |d| d.flight_map_factor = 1.1,
    ),
    (
        "viscous-law-economy",
        "derived c = 2 mu m g/(pi V) -> 1.1 x",
        |d| d.viscous_factor = 1.1,
    ),
];
