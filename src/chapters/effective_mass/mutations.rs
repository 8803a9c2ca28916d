//! Falsification: edits of the statements, judged by the same claim functions on the
//! evidence of the default scene (45 degrees, mu = 0.4). Every document claim of the
//! chapter that prints a number has a mutation that moves it by 10 %; the workbook's
//! derived values and the caption's bound (a sufficient condition with more than 10 %
//! of slack for the uniform stick) are in [`PRINTS_NO_NUMBER`] with the reason.

use super::evidence::{gather, Evidence};
use super::statements::{Statements, PRINTED};
use crate::chapters::default_args;
use crate::report::{Claim, DocEdit, Falsifiable};

/// The chapter's document for the generic judge (`crate::report::falsify`): the
/// evidence is the default scene's (its angle) with its mu.
pub struct Document;

impl Falsifiable for Document {
    type Statements = Statements;
    /// The default scene's evidence and its mu.
    type Evidence = (Evidence, f64);
    fn printed() -> Statements {
        PRINTED
    }
    fn quick_evidence() -> (Evidence, f64) {
        let args: super::Args = default_args();
        (gather(args.angle_deg.to_radians()), args.mu)
    }
    fn claims(st: &Statements, (ev, mu): &(Evidence, f64)) -> Vec<Claim> {
        super::claims::all(st, ev, *mu)
    }
    const EDITS: &'static [DocEdit<Statements>] = EDITS;
    const WITHOUT_TEN_PERCENT: &'static [(&'static str, &'static str)] = PRINTS_NO_NUMBER;
}

/// The chapter's claims that carry no 10 % mutation of a printed number, and why.
pub const PRINTS_NO_NUMBER: &[(&str, &str)] = &[
    ("rod-best-angle", "q* = 2 is the workbook's derivation: the document prints no best angle (the mutation moves the derived value)"),
    ("rod-best-ratio", "3/4 is the workbook's derivation: the document prints no largest ratio (the mutation moves the derived value)"),
    ("a1-needs-free-acceleration", "where (A.1) holds (a stick at rest, the contact force the only force) prints no number; (A.1)'s entries m and m/4 have their own claims and 10 % mutations: the mutation prints the general relation with C's free acceleration b"),
    ("self-locking-bound", "the caption's atan(mu) is a sufficient condition for the uniform stick with at least 33 % of slack (the stick's own bound q1(mu) >= 4 mu/3), so no 10 % change of it can fail for the stick the caption is about: the mutations reverse the inequality and move the bound past the slack (atan(1.5 mu) at mu = 0.4, where q1 = 1.44 mu)"),
];

/// The falsification mutations: each printed coefficient off by 10 %, the
/// self-locking inequality reversed (a data table).
const EDITS: &[DocEdit<Statements>] = &[
        ("rod-mass-along", "m -> 1.1 m (10 %)", |d| d.mass_along = 1.1),
        ("rod-mass-across", "m/4 -> 1.1 m/4 (10 %)", |d| d.mass_across = 0.275),
        ("rod-mass-diagonal", "off-diagonal 0 -> 0.1 m (10 % of m)", |d| d.mass_off_diagonal = 0.1),
        ("derivation-a-c", "a_C = F/(m/4) -> F/(m/4.4) (10 %)", |d| d.a_c_factor = 4.4),
        ("ratio-point-mass", "J_l = q J_v -> 1.1 q J_v (10 %)", |d| d.point_mass_factor = 1.1),
        ("ratio-point-mass-newton-euler", "J_l = q J_v -> 1.1 q J_v (10 %)", |d| d.point_mass_factor = 1.1),
        ("ratio-uniform-rod", "3q/(4+q^2) -> 3.3q/(4+q^2) (10 %)", |d| d.rod_numerator = 3.3),
        ("ratio-uniform-rod", "3q/(4+q^2) -> 3q/(4.4+q^2) (10 %)", |d| d.rod_denominator = 4.4),
        ("ratio-rod-newton-euler", "3q/(4+q^2) -> 3q/(4.4+q^2) (10 %)", |d| d.rod_denominator = 4.4),
        ("example-45-point-mass", "equal impulses -> J_l = 1.1 J_v (10 %)", |d| d.example_point_mass = 1.1),
        ("example-45-rod-60-percent", "60 % -> 66 % (10 %)", |d| d.example_rod_fraction = 0.66),
        ("rod-best-angle", "derived q* = 2 -> 2.2", |d| d.best_q = 2.2),
        ("rod-best-ratio", "derived 3/4 -> 0.825", |d| d.best_ratio = 0.825),
        ("a1-needs-free-acceleration", "(A.1) as the relation of a_C and F -> the general relation a_C = [m]'^-1 F + b printed (b: gravity and the centripetal term)", |d| d.a1_free_acceleration = true),
        ("self-locking-bound", "theta < atan(mu) -> theta > atan(mu) (the uniform stick slips between atan(q1) and atan(q2))", |d| d.lock_below = false),
        ("self-locking-bound", "theta < atan(mu) -> theta < atan(1.5 mu) (past the uniform stick's slack: it jams only up to q1 = 1.44 mu at mu = 0.4)", |d| d.lock_factor = 1.5),
];
