//! Falsification: edits of the statements, judged by the same claim functions: the
//! printed numbers off by 10 % (the downwind threshold, "not greater than the wind",
//! and the range 0 <= s <= 1), every example's verdict reversed, the definition
//! replaced by wrong variants.
//!
//! Claims whose statement prints no number (their mutations reverse the verdict or
//! swap the definition instead), with the reason, are in [`PRINTS_NO_NUMBER`]:
//! `reaching` (any speed across the wind: the hull is a segment on the wind's line and
//! no printed number moves it off that line), `upwind` ("directly into the wind": any
//! speed; the document prints no threshold), `water-skier-dragged` (a rule: dragging by
//! an outside force is not locomotion), `one-medium-riding` (riding with a medium:
//! zero relative velocity, no number), `motorboat-still-water` (any nonzero speed on
//! one medium), `three-media` ("two (or possibly more) media": the workbook's triangle,
//! no printed number).

use super::statements::{Rule, Statements, PRINTED};
use crate::report::{Claim, DocEdit, Falsifiable};

/// The chapter's document for the generic judge (`crate::report::falsify`): its
/// claims need no evidence beyond the statements (closed-form hull tests).
pub struct Document;

impl Falsifiable for Document {
    type Statements = Statements;
    type Evidence = ();
    fn printed() -> Statements {
        PRINTED
    }
    fn quick_evidence() {}
    fn claims(st: &Statements, _: &()) -> Vec<Claim> {
        super::claims::all(st)
    }
    const EDITS: &'static [DocEdit<Statements>] = EDITS;
    const WITHOUT_TEN_PERCENT: &'static [(&'static str, &'static str)] = PRINTS_NO_NUMBER;
}

/// The chapter's document claims whose statement prints no number, and why.
pub const PRINTS_NO_NUMBER: &[(&str, &str)] = &[
    ("reaching", "any speed across the wind is locomotion; the hull is a segment on the wind's line and no printed number moves it off that line"),
    ("upwind", "'directly into the wind': any speed; no threshold is printed"),
    ("water-skier-dragged", "a rule: motion by a force from outside the environment is not locomotion"),
    ("one-medium-riding", "riding with a medium: zero relative velocity, no number"),
    ("motorboat-still-water", "any nonzero speed on one medium at rest is locomotion; no number"),
    ("three-media", "'two (or possibly more) media': the triangle is the workbook's example, no printed number"),
];

const REVERSED: &str = "the document's verdict on this case reversed";
const BOUNDARY: &str = "the hull's boundary counts as locomotion";
const LOW: &str = "dragging while the boat's speed is not greater than the wind's -> than 0.9 x the wind's (10 %)";
const HIGH: &str = "dragging while the boat's speed is not greater than the wind's -> than 1.1 x the wind's (10 %)";

/// The falsification mutations of this chapter's claims (a data table).
const EDITS: &[DocEdit<Statements>] = &[
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
        ("downwind-slower-than-wind", LOW, |d| d.downwind_ratio = 0.9),
        ("downwind-at-wind-speed", LOW, |d| d.downwind_ratio = 0.9),
        ("seaweed-with-wind", LOW, |d| d.downwind_ratio = 0.9),
        ("downwind-faster-than-wind", HIGH, |d| {
            d.downwind_ratio = 1.1
        }),
        (
            "convex-combination",
            "0 <= s <= 1 -> 0 <= s <= 1.1 (10 %)",
            |d| d.s_max = 1.1,
        ),
];
