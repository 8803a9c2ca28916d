//! The document's statements of section 1, as data: the definition of locomotion (a
//! velocity strictly outside the convex hull of the media velocities), the verdict it
//! gives each of its examples, and the range of s in "v = s v1 + (1 - s) v2 with
//! 0 <= s <= 1 is inside the hull". No logic here; a falsification mutation
//! ([`super::mutations`]) edits one field.

use crate::physics::locomotion::V2;

/// The document's sailing scene: wind 5 m/s along +x ...
pub const WIND: V2 = [5.0, 0.0];
/// ... over still water.
pub const WATER: V2 = [0.0, 0.0];

/// The definition of locomotion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rule {
    /// As printed: the average velocity strictly outside the convex hull of the media
    /// velocities (on the boundary is not locomotion), and not moved by a force from
    /// outside the environment ("Dragging is not locomotion").
    OutsideHull,
    /// A wrong variant: the hull's boundary counts as locomotion too.
    OutsideOrOnHull,
    /// A wrong variant: faster than every medium (speed above the largest medium speed).
    FasterThanMedia,
    /// A wrong variant: the hull test alone, dragging by an outside force ignored.
    HullOnly,
}

/// One of the document's examples: the media, the object's velocity, and the verdict.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Case {
    /// Claim id.
    pub id: &'static str,
    /// The claim's statement.
    pub statement: &'static str,
    /// Label in the figure ("" = not drawn).
    pub label: &'static str,
    /// Media velocities (m/s).
    pub media: &'static [V2],
    /// The object's average velocity (m/s): the example shown in the figure.
    pub object: V2,
    /// A second velocity 5 % of the wind speed from the hull's boundary, where a
    /// threshold printed 10 % off gives the other verdict (`None`: the example lies on
    /// the boundary already, or the statement prints no number, see
    /// [`super::mutations::PRINTS_NO_NUMBER`]).
    pub sharp: Option<V2>,
    /// Moved by a force from outside the environment (a tow rope): dragging.
    pub dragged: bool,
    /// The document's verdict: locomotion.
    pub locomotion: bool,
}

/// The sailing scene's media.
const SAILING: &[V2] = &[WIND, WATER];

/// The document's examples.
pub const CASES: [Case; 9] = [
    Case { id: "downwind-slower-than-wind", statement: "Sailing downwind slower than the wind (3 m/s in a 5 m/s wind, still water) is dragging, not locomotion; judged at 3 m/s and at 4.75 m/s, 5 % below the wind's speed, where a threshold printed 10 % low would say locomotion.", label: "downwind slower", media: SAILING, object: [3.0, 0.0], sharp: Some([4.75, 0.0]), dragged: false, locomotion: false },
    Case { id: "downwind-at-wind-speed", statement: "Sailing downwind is not locomotion so long as the boat's speed is not greater than the wind's (at exactly 5 m/s: on the hull's boundary).", label: "at wind speed", media: SAILING, object: [5.0, 0.0], sharp: None, dragged: false, locomotion: false },
    Case { id: "downwind-faster-than-wind", statement: "Sailing downwind faster than the wind (7 m/s) is locomotion; judged at 7 m/s and at 5.25 m/s, 5 % above the wind's speed, where a threshold printed 10 % high would say dragging.", label: "downwind faster", media: SAILING, object: [7.0, 0.0], sharp: Some([5.25, 0.0]), dragged: false, locomotion: true },
    Case { id: "reaching", statement: "Crosswind sailing ('reaching', 3 m/s across the wind) is locomotion.", label: "reaching", media: SAILING, object: [0.0, 3.0], sharp: None, dragged: false, locomotion: true },
    Case { id: "upwind", statement: "Sailing upwind, directly into the wind (2 m/s against it), is locomotion.", label: "upwind", media: SAILING, object: [-2.0, 0.0], sharp: None, dragged: false, locomotion: true },
    Case { id: "seaweed-with-wind", statement: "Seaweed dragged with the wind (moving at the wind's velocity) is not locomotion.", label: "", media: SAILING, object: WIND, sharp: None, dragged: false, locomotion: false },
    // Section 1: "Motion caused by an external force from outside the environment is
    // not locomotion. A motorboat on water is locomoting; the water skier dragged
    // behind is not." The skier's velocity (the boat's, 10 m/s) lies outside the hull
    // of the one medium (still water) as the motorboat's does: the hull test is
    // necessary, not sufficient; the outside force decides.
    Case { id: "water-skier-dragged", statement: "The water skier dragged behind a motorboat (10 m/s on still water, moved by the tow rope: a force from outside the environment) is not locomotion, though the skier's velocity lies outside the hull of the media velocities as the boat's does: the hull test is necessary, not sufficient (the document's definition, run with the outside force as an input).", label: "", media: &[WATER], object: [10.0, 0.0], sharp: None, dragged: true, locomotion: false },
    Case { id: "one-medium-riding", statement: "With one medium, moving with it (zero relative velocity) is not locomotion.", label: "", media: &[[1.0, -2.0]], object: [1.0, -2.0], sharp: None, dragged: false, locomotion: false },
    Case { id: "motorboat-still-water", statement: "A motorboat on still water (one medium at rest) moving at 4 m/s is locomoting.", label: "", media: &[WATER], object: [4.0, 0.0], sharp: None, dragged: false, locomotion: true },
];

/// The statements.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statements {
    /// The definition of locomotion.
    pub rule: Rule,
    /// The id of a case whose printed verdict is reversed (`None` as printed).
    pub flipped: Option<&'static str>,
    /// Upper end of s in "v = s v1 + (1 - s) v2 with 0 <= s <= 1 is inside the hull".
    pub s_max: f64,
    /// "Sailing in the direction of the wind would not be locomotion so long as the
    /// boat's speed is not greater than the wind": the largest downwind speed that is
    /// dragging, in units of the wind's speed (printed 1).
    pub downwind_ratio: f64,
}

/// The document as printed.
pub const PRINTED: Statements = Statements {
    rule: Rule::OutsideHull,
    flipped: None,
    s_max: 1.0,
    downwind_ratio: 1.0,
};
