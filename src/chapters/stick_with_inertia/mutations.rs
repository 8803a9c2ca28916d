//! Falsification: each claim's statement with one printed number off by 10 % (a
//! coefficient, a bound, an exponent: "x -> 1.1 x"), judged by the same claim functions
//! on the same evidence. Every document claim of this chapter prints a number, so every
//! mutation is a 10 % change (none needs a sign or inequality flip instead).
//! `impacts-dissipate` is a consistency check (it holds by construction for e <= 1) and
//! has none.

use super::statements::{Statements, PRINTED};
use super::{claims, evidence};
use crate::report::{Claim, DocEdit, Mutation};

/// The claim `id` judged against the statements `doc` (quick, headless, default flags).
fn judge(id: &str, doc: &Statements) -> Claim {
    static EVIDENCE: std::sync::OnceLock<evidence::Evidence> = std::sync::OnceLock::new();
    let ev = EVIDENCE.get_or_init(evidence::gather);
    claims::all(doc, ev, (0.0, 1.0, 1))
        .into_iter()
        .find(|c| c.id == id)
        .expect("claim id of this chapter")
}

/// The mutations, one or more per claim.
pub fn all() -> Vec<Mutation> {
    let edits: Vec<DocEdit<Statements>> = vec![
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
    Mutation::from_edits(PRINTED, edits, judge)
}
