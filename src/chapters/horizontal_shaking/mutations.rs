//! Falsification: edits of the statements, judged by the same claim functions on the
//! evidence of the default scene (quick mode), computed once. Each printed number is
//! moved by 10 %; the claims whose statement prints no number are in
//! [`PRINTS_NO_NUMBER`] with the reason: `booktop-slides-at-small-tilt` ("the coin will
//! slide in the direction of any small tilt": a direction, judged by reversing it; the
//! printed "5 oscillations/s" and "something like 20 degrees" are the scene, not a
//! threshold of the statement), and the claims of the workbook's derived laws, whose
//! mutations move a derived number (described without "10 %": no printed number moves).

use super::evidence::{gather, Evidence};
use super::statements::{Statements, PRINTED};
use crate::report::{Claim, DocEdit, Falsifiable};

/// The chapter's document for the generic judge (`crate::report::falsify`).
pub struct Document;

impl Falsifiable for Document {
    type Statements = Statements;
    type Evidence = Evidence;
    fn printed() -> Statements {
        PRINTED
    }
    fn quick_evidence() -> Evidence {
        let args: super::Args = crate::chapters::default_args();
        let ctx = crate::chapters::Context::headless(true);
        let scene = super::validate(&args, &ctx).expect("default flags are valid");
        gather(&scene, true)
    }
    fn claims(st: &Statements, ev: &Evidence) -> Vec<Claim> {
        super::claims::all(st, ev)
    }
    const EDITS: &'static [DocEdit<Statements>] = EDITS;
    const WITHOUT_TEN_PERCENT: &'static [(&'static str, &'static str)] = PRINTS_NO_NUMBER;
}

/// The chapter's document claims whose statement prints no number, and why.
pub const PRINTS_NO_NUMBER: &[(&str, &str)] = &[
    (
        "booktop-slides-at-small-tilt",
        "'the coin will slide in the direction of any small tilt': a direction (the mutation reverses it); 5 oscillations/s and 20 degrees describe the scene, not a threshold",
    ),
    (
        "arcsin-law-large-gamma",
        "the averaged law is the workbook's derivation: the document prints no number for it (the mutation moves the derived factor, a check of the derivation, not of the document)",
    ),
    (
        "velocity-fluctuation-small",
        "'the fluctuation in object velocities is small': no number; the swing (1 - b^2) pi V/Gamma_x is the workbook's derivation (the mutation moves its derived pi)",
    ),
    (
        "fast-shaking-needs-growing-v",
        "the fixed-V friction (2/pi) asin(v/V) is the workbook's derivation: the document fixes delta_x and prints no number here (the mutations move the derived coefficient or set it to 0)",
    ),
];

/// The falsification mutations: each statement's coefficient off by 10 % (or more
/// where the statement has slack), the direction reversed (a data table).
const EDITS: &[DocEdit<Statements>] = &[
        (
            "fast-shaking-zero-mean-friction",
            "mean friction -> 0 replaced by -> 0.1 mu m g (10 % of the Coulomb friction mu m g; 0 has no 10 %)",
            |d| d.fast_limit = 0.1,
        ),
        (
            "fast-shaking-zero-mean-friction",
            "mean friction -> 0 replaced by -> 0.05 mu m g",
            |d| d.fast_limit = 0.05,
        ),
        (
            "remaining-friction-viscous",
            "viscous F ~ v -> F ~ v^1.1 (exponent 10 %)",
            |d| d.friction_exponent = 1.1,
        ),
        (
            "arcsin-law-large-gamma",
            "derived sin(pi F/(2 mu m g)) -> sin(1.1 pi F/(2 mu m g))",
            |d| d.arcsin_factor = 1.1,
        ),
        (
            "velocity-fluctuation-small",
            "derived swing (1 - b^2) pi V/Gamma_x -> 1.1 x",
            |d| d.fluctuation_coeff *= 1.1,
        ),
        (
            "fast-shaking-needs-growing-v",
            "derived (2/pi) asin(v/V) at fixed V -> 1.1 x",
            |d| d.fixed_v_coeff *= 1.1,
        ),
        (
            "fast-shaking-needs-growing-v",
            "at fixed V the mean friction -> 0 too (the reading the claim rules out)",
            |d| d.fixed_v_coeff = 0.0,
        ),
        (
            "booktop-slides-at-small-tilt",
            "slides down the tilt -> up the tilt",
            |d| d.slides_down = false,
        ),
];
