//! Data series drawn into a chart: lines clipped to the frame, markers in four shapes,
//! legend entries.

use super::axis::{self, Ctx, Pt};
use super::{Kind, Series};
use plotters::prelude::*;

/// Draws data series (clipped to the box `bx` in axis units) with colours from
/// `pal`; returns whether any series got a legend label.
pub(super) fn draw_series<'a, DB: DrawingBackend + 'a>(
    ch: &mut Ctx<'a, DB>,
    series: &[Series],
    logs: (bool, bool),
    bx: (f64, f64, f64, f64),
    pal: fn(usize) -> RGBColor,
) -> Result<bool, String> {
    let mut any_label = false;
    let (mut auto, mut shapes) = (0usize, 0usize);
    for s in series {
        let r = axis::runs(&s.points, logs.0, logs.1);
        let ci = s.color.unwrap_or_else(|| {
            auto += 1;
            auto - 1
        });
        let col = pal(ci);
        let shape = shapes;
        if s.kind == Kind::LinePoints {
            // the line first (no legend entry), then the markers as a points series
            let line = Series {
                label: String::new(),
                kind: Kind::Line,
                color: Some(ci),
                ..s.clone()
            };
            draw_series(ch, &[line], logs, bx, pal)?;
        }
        if matches!(s.kind, Kind::Points | Kind::LinePoints) {
            shapes += 1;
        }
        let label = s.label.as_str();
        for (k, piece) in pieces(ch, s, &r, bx).into_iter().enumerate() {
            let first = k == 0 && !label.is_empty();
            any_label |= first;
            let kind = if s.kind == Kind::LinePoints {
                Kind::Points
            } else {
                s.kind
            };
            draw_piece(ch, (kind, shape), piece, first.then_some(label), col)?;
        }
    }
    Ok(any_label)
}

/// The pieces of series `s` (its runs `r`) to draw: the markers inside the box `bx`, or
/// the line clipped to the box and split where it turns back; at least one (empty)
/// piece, so that the legend still lists the series.
fn pieces<'a, DB: DrawingBackend + 'a>(
    ch: &Ctx<'a, DB>,
    s: &Series,
    r: &[Vec<Pt>],
    bx: (f64, f64, f64, f64),
) -> Vec<Vec<Pt>> {
    let (x0, x1, y0, y1) = bx;
    let mut pieces: Vec<Vec<Pt>> = match s.kind {
        Kind::Points | Kind::LinePoints => {
            let inside = |p: &&Pt| p.0 >= x0 && p.0 <= x1 && p.1 >= y0 && p.1 <= y1;
            vec![r.iter().flatten().filter(inside).copied().collect()]
        }
        _ => r
            .iter()
            .flat_map(|run| axis::clip_polyline(run, bx))
            .collect(),
    };
    if s.kind != Kind::Points {
        // The bitmap backend joins wide segments with miters, and a miter at a
        // near-reversal (a noisy trace) is a spike far out of the frame: drop points
        // on the previous one's pixel and split the line where it turns back.
        pieces = pieces
            .into_iter()
            .flat_map(|mut piece| {
                piece.dedup_by(|b, a| ch.backend_coord(a) == ch.backend_coord(b));
                let px: Vec<(i32, i32)> = piece.iter().map(|p| ch.backend_coord(p)).collect();
                split_at_reversals(piece, &px)
            })
            .filter(|p| !p.is_empty())
            .collect();
    }
    if pieces.is_empty() {
        pieces.push(Vec::new()); // drawn empty so that the legend still lists it
    }
    pieces
}

/// Draws one piece of a series as `kind` (markers cycle through four shapes by the
/// series' marker index `shape`) in colour `col`; `legend` names its legend entry.
fn draw_piece<'a, DB: DrawingBackend + 'a>(
    ch: &mut Ctx<'a, DB>,
    (kind, shape): (Kind, usize),
    piece: Vec<Pt>,
    legend: Option<&str>,
    col: RGBColor,
) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let st = col.stroke_width(2);
    let fill = col.filled();
    // Draws elements and, with a legend name, the legend entry.
    macro_rules! put {
        ($elems:expr, $glyph:expr) => {{
            let anno = ch.draw_series($elems).map_err(e)?;
            if let Some(label) = legend {
                anno.label(label).legend($glyph);
            }
        }};
    }
    let sq = |at| EmptyElement::at(at) + Rectangle::new([(-5, -5), (5, 5)], fill);
    match (kind, shape % 4) {
        (Kind::Line, _) => put!(LineSeries::new(piece, st), move |(x, y)| PathElement::new(
            vec![(x, y), (x + 22, y)],
            st
        )),
        (Kind::Dashed, _) => {
            put!(DashedLineSeries::new(piece, 10, 6, st), move |(x, y)| {
                EmptyElement::at((x, y))
                    + PathElement::new(vec![(0, 0), (8, 0)], st)
                    + PathElement::new(vec![(14, 0), (22, 0)], st)
            })
        }
        (Kind::Points, 0) => {
            put!(
                piece.iter().map(|&p| Circle::new(p, 5, fill)),
                move |(x, y)| { Circle::new((x + 11, y), 5, fill) }
            )
        }
        (Kind::Points, 1) => put!(
            piece.iter().map(|&p| TriangleMarker::new(p, 7, fill)),
            move |(x, y)| { TriangleMarker::new((x + 11, y), 7, fill) }
        ),
        (Kind::Points, 2) => put!(piece.iter().map(|&p| sq(p)), move |(x, y)| {
            EmptyElement::at((x + 11, y)) + Rectangle::new([(-5, -5), (5, 5)], fill)
        }),
        (Kind::Points | Kind::LinePoints, _) => put!(
            piece.iter().map(|&p| Cross::new(p, 5, st)),
            move |(x, y)| { Cross::new((x + 11, y), 5, st) }
        ),
    }
    Ok(())
}

/// Splits a polyline (points `pts`, their pixels `px`) where it turns back by more than
/// 120 degrees; the pieces share the turning point, so the drawn line stays connected.
fn split_at_reversals(pts: Vec<Pt>, px: &[(i32, i32)]) -> Vec<Vec<Pt>> {
    let mut out = Vec::new();
    let mut cur: Vec<Pt> = Vec::new();
    for (i, p) in pts.iter().enumerate() {
        cur.push(*p);
        if i == 0 || i + 1 >= pts.len() {
            continue;
        }
        let (a, b, c) = (px[i - 1], px[i], px[i + 1]);
        let u = ((b.0 - a.0) as f64, (b.1 - a.1) as f64);
        let v = ((c.0 - b.0) as f64, (c.1 - b.1) as f64);
        let cos = (u.0 * v.0 + u.1 * v.1) / (u.0.hypot(u.1) * v.0.hypot(v.1)).max(1e-12);
        if cos < -0.5 {
            out.push(std::mem::replace(&mut cur, vec![*p])); // formula: turn > 120 deg
        }
    }
    out.push(cur);
    out
}
