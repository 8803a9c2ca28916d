//! Falsification: edits of the statements, judged by the same claim functions on the
//! evidence of the default scene (45 degrees, mu = 0.4). Every document claim of the
//! chapter prints a number and has a mutation that moves it by 10 % ([`PRINTS_NO_NUMBER`]
//! is empty); the self-locking inequality is reversed too.

use super::evidence::gather;
use super::statements::{Statements, PRINTED};
use crate::report::{Claim, DocEdit, Mutation};

/// The claim `id` judged against the statements `st` at the default scene.
fn judge(id: &str, st: &Statements) -> Claim {
    super::claims::all(st, &gather(std::f64::consts::FRAC_PI_4), 0.4)
        .into_iter()
        .find(|c| c.id == id)
        .expect("claim id of this chapter")
}

/// The chapter's document claims whose statement prints no number: none.
pub const PRINTS_NO_NUMBER: &[(&str, &str)] = &[];

/// The falsification mutations: each printed coefficient off by 10 %, the
/// self-locking inequality reversed.
pub fn all() -> Vec<Mutation> {
    let list: Vec<DocEdit<Statements>> = vec![
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
        ("rod-best-angle", "q* = 2 -> 2.2 (10 %)", |d| d.best_q = 2.2),
        ("rod-best-ratio", "3/4 -> 0.825 (10 %)", |d| d.best_ratio = 0.825),
        ("self-locking-bound", "theta < atan(mu) -> theta > atan(mu)", |d| d.lock_below = false),
        ("self-locking-bound", "theta < atan(mu) -> theta < atan(1.1 mu) (10 %)", |d| d.lock_factor = 1.1),
        ("self-locking-bound", "theta < atan(mu) -> theta < atan(0.9 mu) (10 %)", |d| d.lock_factor = 0.9),
        ("self-locking-bound", "theta < atan(mu) -> theta < atan(1.5 mu) (a 50 % error stays inside the rod's slack: 3q/(4+q^2) <= mu up to q = 1.44 mu at mu = 0.4)", |d| d.lock_factor = 1.5),
    ];
    Mutation::from_edits(PRINTED, list, judge)
}
