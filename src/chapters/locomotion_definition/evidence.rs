//! The chapter has no runs: its evidence is the workbook's exact hull test
//! ([`crate::physics::locomotion`]: exact predicates, degenerate hulls, boundary = not
//! locomotion) executed on the document's examples under a definition.

use super::statements::Rule;
use crate::physics::locomotion::{classify, hull, is_locomotion, Position, V2};

/// Whether `object` is locomotion among `media` under `rule`, for an object moved by
/// its own means or by the media (`dragged = false`) or by a force from outside the
/// environment (`dragged = true`: section 1, "Dragging is not locomotion").
pub fn locomotes(rule: Rule, object: V2, media: &[V2], dragged: bool) -> bool {
    match rule {
        Rule::OutsideHull => !dragged && is_locomotion(object, media),
        Rule::HullOnly => is_locomotion(object, media),
        Rule::OutsideOrOnHull => !dragged && classify(&hull(media), object) != Position::Interior,
        Rule::FasterThanMedia => {
            let speed = |v: V2| v[0].hypot(v[1]);
            !dragged && media.iter().all(|&m| speed(object) > speed(m))
        }
    }
}
