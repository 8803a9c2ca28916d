//! The claims of section 1: pure functions of the statements. Each runs the document's
//! definition on the document's own example ([`Check::LiteralExecution`]).

use super::evidence::locomotes;
use super::statements::{Statements, CASES, WATER, WIND};
use crate::report::{Check, Claim};

/// Every claim of the chapter under the statements `st`, in the order of the report.
pub fn all(st: &Statements) -> Vec<Claim> {
    let mut out: Vec<Claim> = CASES
        .iter()
        .map(|c| {
            let said = c.locomotion != (st.flipped == Some(c.id));
            let draft = Claim::draft(
                Check::LiteralExecution,
                c.id,
                "1, sailing as locomotion",
                c.statement,
            );
            let at = |v| locomotes(st, v, c.media, c.dragged);
            match c.sharp {
                // the example and the point 5 % from the boundary: [example, sharp]
                Some(v) => draft.exact(vec![said, said], vec![at(c.object), at(v)]),
                None => draft.exact(said, at(c.object)),
            }
        })
        .collect();
    out.push(convex_combination(st));
    out.push(three_media(st));
    out
}

/// v = s v1 + (1 - s) v2 for s = k/64 up to s_max: dyadic s keeps v exact.
fn convex_combination(st: &Statements) -> Claim {
    let n = 64;
    let k_max = (st.s_max * n as f64).round() as u64;
    let inside = (0..=k_max)
        .filter(|&k| {
            let s = k as f64 / n as f64;
            let v = [
                s * WIND[0] + (1.0 - s) * WATER[0],
                s * WIND[1] + (1.0 - s) * WATER[1],
            ];
            !locomotes(st, v, &[WIND, WATER], false)
        })
        .count() as u64;
    Claim::draft(Check::LiteralExecution, "convex-combination", "1, sailing as locomotion", "Every v = s v1 + (1 - s) v2 with 0 <= s <= 1 is in the hull (not locomotion): count of the values s = k/64 classified as not locomotion, out of 65.")
        .exact(k_max + 1, inside)
}

/// Three media: interior, edge and just outside, found exactly.
fn three_media(st: &Statements) -> Claim {
    let tri = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]];
    let three = [
        ([1.0, 1.0], false),
        ([2.0, 2.0], false),
        ([2.0, 2.0 + 2f64.powi(-50)], true),
    ];
    let ok = three
        .iter()
        .all(|&(v, loco)| locomotes(st, v, &tri, false) == loco);
    Claim::draft(Check::LiteralExecution, "three-media", "1, multiple media", "With three media (a triangle of velocities) a velocity inside or on an edge is not locomotion, one 2^-50 m/s beyond the edge is (interior, boundary, outside found exactly).")
        .exact(true, ok)
}
