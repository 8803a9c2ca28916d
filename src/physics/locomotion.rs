//! What counts as locomotion (document section 1): the convex-hull test.
//!
//! An object locomotes when its average velocity lies strictly outside the convex hull
//! of the (average) velocities of the media around it. A velocity inside the hull, or
//! on its boundary, is reached by riding with one medium or by dragging along a
//! combination `v = s v1 + (1 - s) v2` of them: not locomotion.
//!
//! The test is exact: orientations are signs of 2x2 determinants computed without
//! rounding (error-free transformations: TwoSum and TwoProduct via `f64::mul_add`,
//! summed into a nonoverlapping floating-point expansion, Shewchuk 1997). No epsilon:
//! a velocity exactly on the hull's boundary is found to be on it. Exactness needs no
//! overflow or underflow in the products, which holds for every coordinate that is 0
//! or has `1e-100 <= |x| <= 1e100` ([`in_exact_range`]).

use std::cmp::Ordering;

/// A velocity `[x, y]` (m/s).
pub type V2 = [f64; 2];

/// Whether `x` is in the range where the predicates are exact.
pub(crate) fn in_exact_range(x: f64) -> bool {
    x == 0.0 || (x.is_finite() && (1e-100..=1e100).contains(&x.abs()))
}

/// `a + b = s + e` exactly (Knuth's TwoSum).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a * b = p + e` exactly (TwoProduct with a fused multiply-add).
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// Adds `b` to the nonoverlapping expansion `e` (Shewchuk's Grow-Expansion with zero
/// elimination); components stay in increasing magnitude.
fn grow(e: &mut Vec<f64>, b: f64) {
    let mut q = b;
    let mut h = Vec::with_capacity(e.len() + 1);
    for &x in e.iter() {
        let (s, err) = two_sum(q, x);
        if err != 0.0 {
            h.push(err);
        }
        q = s;
    }
    if q != 0.0 {
        h.push(q);
    }
    *e = h;
}

/// The sign of `(b - a) x (c - a)`, computed exactly: `Greater` when `a, b, c` turn
/// counter-clockwise, `Less` clockwise, `Equal` when collinear.
pub fn orient2d(a: V2, b: V2, c: V2) -> Ordering {
    // Each difference is exact as a two-term sum: b - a = d + e.
    let d = |p: f64, q: f64| two_sum(p, -q);
    let (bx, ebx) = d(b[0], a[0]);
    let (by, eby) = d(b[1], a[1]);
    let (cx, ecx) = d(c[0], a[0]);
    let (cy, ecy) = d(c[1], a[1]);
    let mut e = Vec::with_capacity(32);
    // formula: det = (bx - ax)(cy - ay) - (by - ay)(cx - ax), every partial product exact.
    for (u, v, sign) in [
        (bx, cy, 1.0),
        (bx, ecy, 1.0),
        (ebx, cy, 1.0),
        (ebx, ecy, 1.0),
        (by, cx, -1.0),
        (by, ecx, -1.0),
        (eby, cx, -1.0),
        (eby, ecx, -1.0),
    ] {
        let (p, err) = two_prod(u, v);
        grow(&mut e, sign * p);
        grow(&mut e, sign * err);
    }
    // The largest component of a nonoverlapping expansion carries the sign of the sum.
    e.last().map_or(Ordering::Equal, |x| {
        x.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
    })
}

/// The convex hull of the media velocities, by its dimension.
#[derive(Debug, Clone, PartialEq)]
pub enum Hull {
    /// All media move with the same velocity.
    Point(V2),
    /// All media velocities are collinear: the segment between the extreme two.
    Segment(V2, V2),
    /// A convex polygon, vertices counter-clockwise, no three collinear.
    Polygon(Vec<V2>),
}

fn lex(a: &V2, b: &V2) -> Ordering {
    a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1]))
}

/// The convex hull (Andrew's monotone chain with exact orientations). Empty input
/// gives the point (0, 0) (a single medium at rest).
pub fn hull(points: &[V2]) -> Hull {
    let mut p: Vec<V2> = points.iter().map(|v| [v[0] + 0.0, v[1] + 0.0]).collect(); // -0 -> 0
    p.sort_by(lex);
    p.dedup();
    match p.len() {
        0 => return Hull::Point([0.0, 0.0]),
        1 => return Hull::Point(p[0]),
        _ => {}
    }
    let (first, last) = (p[0], p[p.len() - 1]);
    if p.iter()
        .all(|&c| orient2d(first, last, c) == Ordering::Equal)
    {
        return Hull::Segment(first, last);
    }
    let mut h: Vec<V2> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = h.len();
        let iter: Box<dyn Iterator<Item = &V2>> = if pass == 0 {
            Box::new(p.iter())
        } else {
            Box::new(p.iter().rev())
        };
        for &c in iter {
            while h.len() >= start + 2
                && orient2d(h[h.len() - 2], h[h.len() - 1], c) != Ordering::Greater
            {
                h.pop();
            }
            h.push(c);
        }
        h.pop(); // the last point starts the other chain
    }
    Hull::Polygon(h)
}

/// Where a velocity lies relative to the hull.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Position {
    /// Strictly outside: locomotion.
    Outside,
    /// On the boundary (for a point or a segment hull: on it): not locomotion.
    Boundary,
    /// Strictly inside a polygon hull: not locomotion.
    Interior,
}

// ANCHOR: classify
/// Classifies `v` against a hull, exactly.
pub fn classify(h: &Hull, v: V2) -> Position {
    let v = [v[0] + 0.0, v[1] + 0.0];
    match h {
        Hull::Point(p) => {
            if *p == v {
                Position::Boundary
            } else {
                Position::Outside
            }
        }
        Hull::Segment(a, b) => {
            let between = lex(a, &v) != Ordering::Greater && lex(&v, b) != Ordering::Greater;
            if orient2d(*a, *b, v) == Ordering::Equal && between {
                Position::Boundary
            } else {
                Position::Outside
            }
        }
        Hull::Polygon(vs) => {
            let mut on_edge = false;
            for i in 0..vs.len() {
                match orient2d(vs[i], vs[(i + 1) % vs.len()], v) {
                    Ordering::Less => return Position::Outside,
                    Ordering::Equal => on_edge = true,
                    Ordering::Greater => {}
                }
            }
            if on_edge {
                Position::Boundary
            } else {
                Position::Interior
            }
        }
    }
}
// ANCHOR_END: classify

// ANCHOR: is_locomotion
/// The document's test: locomotion iff the object's velocity is strictly outside the
/// convex hull of the media velocities.
pub fn is_locomotion(object: V2, media: &[V2]) -> bool {
    classify(&hull(media), object) == Position::Outside
}
// ANCHOR_END: is_locomotion

fn fmt_v(v: V2) -> String {
    format!("({}, {})", v[0] + 0.0, v[1] + 0.0)
}

/// A description of the hull for the reader.
pub(crate) fn describe(h: &Hull) -> String {
    match h {
        Hull::Point(p) => format!("the single velocity {} m/s", fmt_v(*p)),
        Hull::Segment(a, b) => format!("the segment from {} to {} m/s", fmt_v(*a), fmt_v(*b)),
        Hull::Polygon(vs) => {
            let list: Vec<String> = vs.iter().map(|v| fmt_v(*v)).collect();
            format!("the polygon {} m/s", list.join(", "))
        }
    }
}

/// Why `object` is or is not locomotion relative to `media` (one sentence).
pub fn reason(object: V2, media: &[V2]) -> String {
    let h = hull(media);
    let pos = classify(&h, object);
    let v = fmt_v(object);
    if let Hull::Point(p) = h {
        let rel = [object[0] - p[0], object[1] - p[1]];
        return match pos {
            Position::Outside => format!(
                "the object's velocity {v} m/s differs from the only medium's velocity {} m/s (relative velocity about {} m/s): locomotion",
                fmt_v(p),
                fmt_v(rel)
            ),
            _ => format!("the object's velocity {v} m/s equals the medium's velocity: it rides with the medium, not locomotion"),
        };
    }
    if let (Hull::Segment(..), Position::Boundary) = (&h, pos) {
        return format!("the object's velocity {v} m/s lies on the convex hull of the media velocities ({}), a mix v = s v1 + (1 - s) v2 of them with 0 <= s <= 1: dragging, not locomotion", describe(&h));
    }
    match pos {
        Position::Outside => format!("the object's velocity {v} m/s lies outside the convex hull of the media velocities ({}): locomotion", describe(&h)),
        Position::Boundary => format!("the object's velocity {v} m/s lies on the boundary of the convex hull of the media velocities ({}): it rides with a medium or drags along a mix of them, not locomotion", describe(&h)),
        Position::Interior => format!("the object's velocity {v} m/s lies inside the convex hull of the media velocities ({}): dragging, not locomotion", describe(&h)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orientation_is_exact_where_the_naive_formula_rounds() {
        // Points on the line y = x shifted by 2^-60 are collinear only in exact
        // arithmetic; the naive determinant of these near-equal numbers rounds.
        let a = [0.5, 0.5];
        let b = [12.0, 12.0];
        let c = [24.0, 24.0];
        assert_eq!(orient2d(a, b, c), Ordering::Equal);
        let tiny = 2f64.powi(-50);
        assert_eq!(
            orient2d(a, b, [24.0, 24.0 + 24.0 * tiny]),
            Ordering::Greater
        );
        assert_eq!(orient2d(a, b, [24.0 + 24.0 * tiny, 24.0]), Ordering::Less);
        // Cancellation: coordinates 2^20 + k 2^-32 (exact doubles).
        let big = 2f64.powi(20);
        let u = 2f64.powi(-32);
        let p = |i: f64, j: f64| [big + i * u, big + j * u];
        assert_eq!(
            orient2d(p(0.0, 0.0), p(1.0, 1.0), p(3.0, 3.0)),
            Ordering::Equal
        );
        assert_eq!(
            orient2d(p(0.0, 0.0), p(1.0, 1.0), p(3.0, 4.0)),
            Ordering::Greater
        );
    }

    #[test]
    fn degenerate_hulls() {
        assert_eq!(hull(&[[1.0, 2.0], [1.0, 2.0]]), Hull::Point([1.0, 2.0]));
        assert_eq!(
            hull(&[[2.0, 2.0], [0.0, 0.0], [1.0, 1.0]]),
            Hull::Segment([0.0, 0.0], [2.0, 2.0])
        );
        let sq = hull(&[
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
            [0.5, 0.0],
            [0.5, 0.5],
        ]);
        assert_eq!(
            sq,
            Hull::Polygon(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
        );
        assert_eq!(classify(&sq, [0.5, 0.0]), Position::Boundary);
        assert_eq!(classify(&sq, [0.5, 0.5]), Position::Interior);
        assert_eq!(classify(&sq, [0.5, -0.0]), Position::Boundary);
        assert_eq!(classify(&sq, [1.5, 0.5]), Position::Outside);
        let seg = Hull::Segment([0.0, 0.0], [5.0, 0.0]);
        assert_eq!(classify(&seg, [5.0, 0.0]), Position::Boundary);
        assert_eq!(classify(&seg, [5.000000000000001, 0.0]), Position::Outside);
        assert_eq!(
            classify(&Hull::Point([0.0, 0.0]), [-0.0, 0.0]),
            Position::Boundary
        );
    }
}
