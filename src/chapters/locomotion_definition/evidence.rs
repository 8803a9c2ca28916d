//! The chapter has no runs: its evidence is the workbook's exact hull test
//! ([`crate::physics::locomotion`]: exact predicates, degenerate hulls, boundary = not
//! locomotion) executed on the document's examples under a definition.

use super::statements::{Rule, Statements};
use crate::physics::locomotion::{classify, hull, is_locomotion, Position, V2};

/// Whether `object` is locomotion among `media` under the statements `st`, for an
/// object moved by its own means or by the media (`dragged = false`) or by a force from
/// outside the environment (`dragged = true`: section 1, "Dragging is not locomotion").
/// With two media `[v1, v2]` (wind, water) the hull's end at the wind is where
/// `st.downwind_ratio` puts the largest dragging speed: `v2 + r (v1 - v2)` (exactly
/// `v1` as printed, r = 1).
pub fn locomotes(st: &Statements, object: V2, media: &[V2], dragged: bool) -> bool {
    let r = st.downwind_ratio;
    let moved;
    let media = match media {
        [v1, v2] if r != 1.0 => {
            moved = [
                [v2[0] + r * (v1[0] - v2[0]), v2[1] + r * (v1[1] - v2[1])],
                *v2,
            ];
            &moved[..]
        }
        _ => media,
    };
    match st.rule {
        Rule::OutsideHull => !dragged && is_locomotion(object, media),
        Rule::HullOnly => is_locomotion(object, media),
        Rule::OutsideOrOnHull => !dragged && classify(&hull(media), object) != Position::Interior,
        Rule::FasterThanMedia => {
            let speed = |v: V2| v[0].hypot(v[1]);
            !dragged && media.iter().all(|&m| speed(object) > speed(m))
        }
    }
}
