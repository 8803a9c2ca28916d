//! Falsification: edits of the statements, judged by the same claim functions: every
//! example's verdict reversed, the definition replaced by wrong variants, the range of
//! s widened.

use super::statements::{Rule, Statements, PRINTED};
use crate::report::{Claim, DocEdit, Mutation};

/// The claim `id` judged against the statements `st`.
fn judge(id: &str, st: &Statements) -> Claim {
    super::claims::all(st)
        .into_iter()
        .find(|c| c.id == id)
        .expect("claim id of this chapter")
}

/// The falsification mutations of this chapter's claims.
pub fn all() -> Vec<Mutation> {
    const REVERSED: &str = "the document's verdict on this case reversed";
    const BOUNDARY: &str = "the hull's boundary counts as locomotion";
    let list: Vec<DocEdit<Statements>> = vec![
        ("downwind-slower-than-wind", REVERSED, |d| {
            d.flipped = Some("downwind-slower-than-wind")
        }),
        ("downwind-at-wind-speed", REVERSED, |d| {
            d.flipped = Some("downwind-at-wind-speed")
        }),
        ("downwind-faster-than-wind", REVERSED, |d| {
            d.flipped = Some("downwind-faster-than-wind")
        }),
        ("reaching", REVERSED, |d| d.flipped = Some("reaching")),
        ("upwind", REVERSED, |d| d.flipped = Some("upwind")),
        ("seaweed-with-wind", REVERSED, |d| {
            d.flipped = Some("seaweed-with-wind")
        }),
        ("water-skier-dragged", REVERSED, |d| {
            d.flipped = Some("water-skier-dragged")
        }),
        ("one-medium-riding", REVERSED, |d| {
            d.flipped = Some("one-medium-riding")
        }),
        ("motorboat-still-water", REVERSED, |d| {
            d.flipped = Some("motorboat-still-water")
        }),
        ("downwind-at-wind-speed", BOUNDARY, |d| {
            d.rule = Rule::OutsideOrOnHull
        }),
        ("reaching", "locomotion = faster than every medium", |d| {
            d.rule = Rule::FasterThanMedia
        }),
        (
            "water-skier-dragged",
            "the hull test alone (dragging by an outside force ignored)",
            |d| d.rule = Rule::HullOnly,
        ),
        ("three-media", BOUNDARY, |d| d.rule = Rule::OutsideOrOnHull),
        ("convex-combination", BOUNDARY, |d| {
            d.rule = Rule::OutsideOrOnHull
        }),
        ("convex-combination", "0 <= s <= 1 -> 0 <= s <= 1.1", |d| {
            d.s_max = 1.1
        }),
    ];
    Mutation::from_edits(PRINTED, list, judge)
}
