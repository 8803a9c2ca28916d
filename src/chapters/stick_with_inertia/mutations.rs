//! Falsification: each claim's statement with one printed number off by 10 % (a
//! coefficient, a bound, an exponent: "x -> 1.1 x"), judged by the same claim functions
//! on the same evidence. Every document claim of this chapter prints a number, so every
//! mutation is a 10 % change (none needs a sign or inequality flip instead).
//! `impacts-dissipate` is a consistency check (it holds by construction for e <= 1) and
//! has none.

use super::statements::{Statements, PRINTED};
use super::{claims, evidence};
use crate::report::{Claim, DocEdit, Falsifiable};

/// The chapter's document for the generic judge (`crate::report::falsify`). Its
/// evidence is the chapter's, plus the simulated landings' energy balance at the
/// printed largest restitution (data, as `run` measures it: no claim is left out).
pub struct Document;

impl Falsifiable for Document {
    type Statements = Statements;
    /// The evidence and `evidence::impact_energy(PRINTED.restitution_max)`.
    type Evidence = (evidence::Evidence, (f64, f64, usize));
    fn printed() -> Statements {
        PRINTED
    }
    fn quick_evidence() -> Self::Evidence {
        (
            evidence::gather(),
            evidence::impact_energy(PRINTED.restitution_max),
        )
    }
    fn claims(doc: &Statements, (ev, impacts): &Self::Evidence) -> Vec<Claim> {
        claims::all(doc, ev, *impacts)
    }
    const EDITS: &'static [DocEdit<Statements>] = EDITS;
    /// Every document claim of this chapter prints a number.
    const WITHOUT_TEN_PERCENT: &'static [(&'static str, &'static str)] = &[];
}

/// The mutations, one or more per claim (a data table).
const EDITS: &[DocEdit<Statements>] = &[
        (
            "impulse-ratio-uniform",
            "3q/(4+q^2) -> 3.3q/(4+q^2) (the coefficient 3 off by 10 %)",
            |d| d.uniform_num = 3.3,
        ),
        (
            "impulse-ratio-massless",
            "q -> 1.1 q (the ratio off by 10 %)",
            |d| d.massless_factor = 1.1,
        ),
        (
            "impulse-ratio-between",
            "alpha q/(1+alpha+q^2) -> 1.1 x (off by 10 %)",
            |d| d.between_scale = 1.1,
        ),
        (
            "painleve-boundary",
            "mu_P -> 1.1 mu_P (the boundary off by 10 %)",
            |d| d.painleve_scale = 1.1,
        ),
        (
            "painleve-minimum-uniform",
            "4/3 -> 1.1 x 4/3 (the least mu_P off by 10 %)",
            |d| d.painleve_min = 1.1 * 4.0 / 3.0,
        ),
        (
            "painleve-minimum-angle",
            "atan(1/2) -> atan(0.55) (the printed 1/2 off by 10 %)",
            |d| d.painleve_min_tan = 0.55,
        ),
        (
            "massless-limit",
            "order 1 -> 1.1 (the rate off by 10 %)",
            |d| d.massless_order = 1.1,
        ),
        (
            "moreau-jean",
            "order 1 -> 1.1 (the order off by 10 %)",
            |d| d.mj_order = 1.1,
        ),
        (
            "painleve-compliant-limit",
            "rule's impulse -> 1.1 x (off by 10 %)",
            |d| d.iwc_scale = 1.1,
        ),
];
