//! Chapter `locomotion-definition` (document section 1): locomotion is motion with an
//! average velocity strictly outside the convex hull of the media velocities.
//!
//! The test itself is [`crate::physics::locomotion`] (exact predicates, degenerate
//! hulls, boundary = not locomotion). The chapter checks the document's sailing cases,
//! classifies the reader's own scene and draws the hull with the test velocities.

use super::{info, Context};
use crate::error::{check, parse_pair, Result};
use crate::flags::Flag;
use crate::physics::domain::Interval;
use crate::physics::locomotion::{
    classify, hull, in_exact_range, is_locomotion, reason, Hull, Position, V2,
};
use crate::plot::{color, font, save_drawing, Drawing, GRID, LABEL_PX, TICK_PX, TITLE_PX};
use crate::report::{ChapterReport, Check, Claim, Mutation};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Flags of the chapter (their help lines: [`FLAGS`]).
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Average velocity of the object as X,Y in m/s.
    #[arg(long, value_parser = parse_pair, default_value = "1,3", allow_hyphen_values = true)]
    pub object_velocity: V2,
    /// Average velocity of one medium as X,Y in m/s; repeat the flag for several media.
    #[arg(long = "medium-velocity", value_parser = parse_pair, default_values = ["5,0", "0,0"], allow_hyphen_values = true)]
    pub medium_velocity: Vec<V2>,
}

/// The document's sailing scene: wind 5 m/s along +x over still water.
const WIND: V2 = [5.0, 0.0];
const WATER: V2 = [0.0, 0.0];

const VALID: &str =
    "X,Y with each part 0 or 1e-100 <= |part| <= 1e100 (m/s), where the hull test is exact";

/// A velocity pair's entry: each part 0 or `1e-100 <= |part| <= 1e100` (the range
/// field holds the magnitudes; either sign and 0 are accepted too).
const fn pair(name: &'static str, about: &'static str) -> Flag {
    Flag::new(name, about, "m/s", Interval::closed(1e-100, 1e100))
        .shown_as("X,Y with each part 0 or 1e-100 <= |part| <= 1e100")
        .why("where the hull test is exact")
}

/// The table of the chapter's flags. No `--g-mps2`: the chapter is kinematics and
/// refuses the flag.
pub const FLAGS: &[Flag] = &[
    pair("--object-velocity", "Average velocity of the object as X,Y (horizontal plane; negative parts are fine: --object-velocity -2,0); default 1,3: a boat reaching across the wind"),
    pair("--medium-velocity", "Average velocity of one medium as X,Y; repeat the flag for several media; default: wind 5,0 and still water 0,0 (the document's sailing scene)"),
];

fn validate(flag: &str, v: V2) -> Result<V2> {
    for x in v {
        check(flag, x, in_exact_range, VALID)?;
    }
    Ok(v)
}

/// One checked case: velocity, label, the document's verdict (locomotion or not).
struct Case {
    id: &'static str,
    statement: &'static str,
    label: &'static str,
    media: Vec<V2>,
    object: V2,
    /// Moved by a force from outside the environment (a tow rope): dragging.
    dragged: bool,
    expected: bool,
}

fn sailing_cases() -> Vec<Case> {
    let sail = |id, statement, label, object, expected| Case {
        id,
        statement,
        label,
        media: vec![WIND, WATER],
        object,
        dragged: false,
        expected,
    };
    vec![
        sail("downwind-slower-than-wind", "Sailing downwind slower than the wind (3 m/s in a 5 m/s wind, still water) is dragging, not locomotion.", "downwind slower", [3.0, 0.0], false),
        sail("downwind-at-wind-speed", "Sailing downwind is not locomotion so long as the boat's speed is not greater than the wind's (at exactly 5 m/s: on the hull's boundary).", "at wind speed", [5.0, 0.0], false),
        sail("downwind-faster-than-wind", "Sailing downwind faster than the wind (7 m/s) is locomotion.", "downwind faster", [7.0, 0.0], true),
        sail("reaching", "Crosswind sailing ('reaching', 3 m/s across the wind) is locomotion.", "reaching", [0.0, 3.0], true),
        sail("upwind", "Sailing upwind, directly into the wind (2 m/s against it), is locomotion.", "upwind", [-2.0, 0.0], true),
        sail("seaweed-with-wind", "Seaweed dragged with the wind (moving at the wind's velocity) is not locomotion.", "", WIND, false),
        // Section 1: "Motion caused by an external force from outside the environment is
        // not locomotion. A motorboat on water is locomoting; the water skier dragged
        // behind is not." The skier's velocity (the boat's, 10 m/s) lies outside the hull
        // of the one medium (still water) as the motorboat's does: the hull test is
        // necessary, not sufficient; the outside force decides.
        Case { id: "water-skier-dragged", statement: "The water skier dragged behind a motorboat (10 m/s on still water, moved by the tow rope: a force from outside the environment) is not locomotion, though the skier's velocity lies outside the hull of the media velocities as the boat's does: the hull test is necessary, not sufficient (the document's definition, run with the outside force as an input).", label: "", media: vec![WATER], object: [10.0, 0.0], dragged: true, expected: false },
        Case { id: "one-medium-riding", statement: "With one medium, moving with it (zero relative velocity) is not locomotion.", label: "", media: vec![[1.0, -2.0]], object: [1.0, -2.0], dragged: false, expected: false },
        Case { id: "motorboat-still-water", statement: "A motorboat on still water (one medium at rest) moving at 4 m/s is locomoting.", label: "", media: vec![WATER], object: [4.0, 0.0], dragged: false, expected: true },
    ]
}

/// The document's definition, as data: which velocities count as locomotion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rule {
    /// As printed: the average velocity strictly outside the convex hull of the media
    /// velocities (on the boundary is not locomotion).
    OutsideHull,
    /// A wrong variant: the hull's boundary counts as locomotion too.
    OutsideOrOnHull,
    /// A wrong variant: faster than every medium (speed above the largest medium speed).
    FasterThanMedia,
    /// A wrong variant: the hull test alone, dragging by an outside force ignored.
    HullOnly,
}

impl Rule {
    /// Whether `object` is locomotion among `media` under this rule, for an object
    /// moved by its own means or by the media (`dragged = false`) or by a force from
    /// outside the environment (`dragged = true`: section 1, "Dragging is not
    /// locomotion").
    pub fn is_locomotion(self, object: V2, media: &[V2], dragged: bool) -> bool {
        match self {
            Rule::OutsideHull => !dragged && is_locomotion(object, media),
            Rule::HullOnly => is_locomotion(object, media),
            Rule::OutsideOrOnHull => {
                !dragged && classify(&hull(media), object) != Position::Interior
            }
            Rule::FasterThanMedia => {
                let speed = |v: V2| v[0].hypot(v[1]);
                !dragged && media.iter().all(|&m| speed(object) > speed(m))
            }
        }
    }
}

/// The document's statements of section 1, as data, so that a falsification test can
/// feed the checks a wrong variant.
#[derive(Debug, Clone, PartialEq)]
pub struct Doc {
    /// The definition of locomotion.
    pub rule: Rule,
    /// The verdict the document gives each sailing case (by case id), `true` =
    /// locomotion; a case not listed keeps its printed verdict.
    pub flipped: Vec<&'static str>,
    /// Upper end of s in "v = s v1 + (1 - s) v2 with 0 <= s <= 1 is inside the hull".
    pub s_max: f64,
}

impl Doc {
    /// The document as printed.
    pub const PRINTED: Doc = Doc {
        rule: Rule::OutsideHull,
        flipped: Vec::new(),
        s_max: 1.0,
    };
}

/// The chapter's claims under the document's statements `doc`. Each sailing case runs
/// the document's own definition on the document's own example
/// ([`Check::LiteralExecution`]).
pub fn claims(doc: &Doc) -> Vec<Claim> {
    let mut out = Vec::new();
    for c in &sailing_cases() {
        let said = c.expected != doc.flipped.contains(&c.id);
        out.push(
            Claim::exact(
                c.id,
                "1, sailing as locomotion",
                c.statement,
                said,
                doc.rule.is_locomotion(c.object, &c.media, c.dragged),
            )
            .with_check(Check::LiteralExecution),
        );
    }
    // v = s v1 + (1 - s) v2 for s = k/64 up to s_max: dyadic s keeps v exact.
    let n = 64;
    let k_max = (doc.s_max * n as f64).round() as u64;
    let inside = (0..=k_max)
        .filter(|&k| {
            let s = k as f64 / n as f64;
            let v = [
                s * WIND[0] + (1.0 - s) * WATER[0],
                s * WIND[1] + (1.0 - s) * WATER[1],
            ];
            !doc.rule.is_locomotion(v, &[WIND, WATER], false)
        })
        .count() as u64;
    out.push(Claim::exact("convex-combination", "1, sailing as locomotion", "Every v = s v1 + (1 - s) v2 with 0 <= s <= 1 is in the hull (not locomotion): count of the values s = k/64 classified as not locomotion, out of 65.", k_max + 1, inside).with_check(Check::LiteralExecution));
    let tri = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]];
    let three = [
        ([1.0, 1.0], false),
        ([2.0, 2.0], false),
        ([2.0, 2.0 + 2f64.powi(-50)], true),
    ];
    let ok = three
        .iter()
        .all(|&(v, loco)| doc.rule.is_locomotion(v, &tri, false) == loco);
    out.push(Claim::exact("three-media", "1, multiple media", "With three media (a triangle of velocities) a velocity inside or on an edge is not locomotion, one 2^-50 m/s beyond the edge is (interior, boundary, outside found exactly).", true, ok).with_check(Check::LiteralExecution));
    out
}

/// One claim of [`claims`] under `doc`, by id.
fn claim_of(doc: &Doc, id: &str) -> Claim {
    claims(doc)
        .into_iter()
        .find(|c| c.id == id)
        .expect("claim id of this chapter")
}

/// Runs the chapter.
pub fn run(args: &Args, ctx: &Context) -> Result<ChapterReport> {
    super::refuse_g("locomotion-definition", ctx)?;
    let object = validate("--object-velocity", args.object_velocity)?;
    let media: Vec<V2> = args
        .medium_velocity
        .iter()
        .map(|&m| validate("--medium-velocity", m))
        .collect::<Result<_>>()?;
    let mut r = info("locomotion-definition").expect("registered").report();
    r.param("object_velocity_mps", vec![object[0], object[1]]);
    r.param(
        "medium_velocities_mps",
        media.iter().map(|m| vec![m[0], m[1]]).collect::<Vec<_>>(),
    );

    let cases = sailing_cases();
    for claim in claims(&Doc::PRINTED) {
        r.claim(claim);
    }
    r.result("is_locomotion", is_locomotion(object, &media));
    r.result("reason", reason(object, &media));

    if let Some(dir) = ctx.figure_dir("locomotion-definition") {
        let mut scene = Panel {
            title: "Your scene".into(),
            media: media.clone(),
            tests: vec![(object, "object".into())],
        };
        if media.len() == 2 && media.contains(&WIND) && media.contains(&WATER) {
            scene.title = "Your scene (wind 5,0 m/s, still water)".into();
        }
        let sailing = Panel {
            title: "The document's sailing cases".into(),
            media: vec![WIND, WATER],
            tests: cases
                .iter()
                .filter(|c| !c.label.is_empty())
                .map(|c| (c.object, c.label.to_string()))
                .collect(),
        };
        let fig = HullFigure {
            panels: vec![scene, sailing],
        };
        r.figures
            .extend(save_drawing(&fig, &dir, "convex-hull", (1400, 650))?);
    }
    Ok(r)
}

/// One panel of the hull figure: the media velocities and labelled test velocities.
struct Panel {
    title: String,
    media: Vec<V2>,
    tests: Vec<(V2, String)>,
}

/// The hull figure: panels side by side, equal axis scales.
struct HullFigure {
    panels: Vec<Panel>,
}

impl Drawing for HullFigure {
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), String> {
        for (p, a) in self
            .panels
            .iter()
            .zip(area.split_evenly((1, self.panels.len().max(1))))
        {
            draw_panel(p, &a)?;
        }
        Ok(())
    }
}

fn draw_panel<DB: DrawingBackend>(
    p: &Panel,
    area: &DrawingArea<DB, Shift>,
) -> std::result::Result<(), String> {
    let e = |e: DrawingAreaErrorKind<DB::ErrorType>| e.to_string();
    let all: Vec<V2> = p
        .media
        .iter()
        .copied()
        .chain(p.tests.iter().map(|t| t.0))
        .chain([[0.0, 0.0]])
        .collect();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for v in &all {
        (x0, x1, y0, y1) = (x0.min(v[0]), x1.max(v[0]), y0.min(v[1]), y1.max(v[1]));
    }
    // Equal scales: widen the shorter side to the plotting area's aspect ratio.
    let (w, h) = area.dim_in_pixel();
    let (pw, ph) = ((w as f64 - 110.0).max(10.0), (h as f64 - 130.0).max(10.0));
    let span = ((x1 - x0) / pw).max((y1 - y0) / ph).max(1e-300) * 1.3;
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let (xr, yr) = (
        cx - 0.5 * span * pw..cx + 0.5 * span * pw,
        cy - 0.5 * span * ph..cy + 0.5 * span * ph,
    );
    let mut ch = ChartBuilder::on(area)
        .caption(&p.title, font(TITLE_PX))
        .margin(18)
        .x_label_area_size(58)
        .y_label_area_size(70)
        .build_cartesian_2d(xr, yr)
        .map_err(e)?;
    ch.configure_mesh()
        .bold_line_style(GRID.stroke_width(1))
        .light_line_style(TRANSPARENT)
        .x_desc("v_x (m/s)")
        .y_desc("v_y (m/s)")
        .axis_desc_style(font(LABEL_PX))
        .label_style(font(TICK_PX))
        .draw()
        .map_err(e)?;
    let h = hull(&p.media);
    let fill = color(5);
    match &h {
        Hull::Polygon(vs) => {
            let pts: Vec<(f64, f64)> = vs.iter().map(|v| (v[0], v[1])).collect();
            ch.draw_series(std::iter::once(Polygon::new(
                pts.clone(),
                fill.mix(0.3).filled(),
            )))
            .map_err(e)?;
            let mut closed = pts.clone();
            closed.push(pts[0]);
            ch.draw_series(LineSeries::new(closed, fill.stroke_width(3)))
                .map_err(e)?
                .label("convex hull of the media velocities")
                .legend(move |(x, y)| {
                    Rectangle::new([(x, y - 7), (x + 22, y + 7)], fill.mix(0.5).filled())
                });
        }
        Hull::Segment(a, b) => {
            ch.draw_series(LineSeries::new(
                vec![(a[0], a[1]), (b[0], b[1])],
                fill.stroke_width(6),
            ))
            .map_err(e)?
            .label("convex hull of the media velocities (a segment)")
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 22, y)], fill.stroke_width(6))
            });
        }
        Hull::Point(_) => {}
    }
    let black = RGBColor(0, 0, 0);
    ch.draw_series(p.media.iter().map(|m| {
        EmptyElement::at((m[0], m[1])) + Rectangle::new([(-6, -6), (6, 6)], black.filled())
    }))
    .map_err(e)?
    .label("media velocities")
    .legend(move |(x, y)| Rectangle::new([(x + 5, y - 6), (x + 17, y + 6)], black.filled()));
    for (i, m) in p.media.iter().enumerate() {
        let name = if p.media.len() == 2 && *m == WIND {
            "wind".to_string()
        } else if p.media.len() == 2 && *m == WATER {
            "water".to_string()
        } else {
            format!("medium {}", i + 1)
        };
        let t = Text::new(
            name,
            (8, 8),
            font(TICK_PX).pos(Pos::new(HPos::Left, VPos::Top)),
        );
        ch.plotting_area()
            .draw(&(EmptyElement::at((m[0], m[1])) + t))
            .map_err(e)?;
    }
    let (yes, no) = (color(2), color(1));
    let mut labelled = (false, false);
    for (k, (v, label)) in p.tests.iter().enumerate() {
        let loco = classify(&h, *v) == Position::Outside;
        let col = if loco { yes } else { no };
        let anno = ch
            .draw_series(std::iter::once(Circle::new((v[0], v[1]), 7, col.filled())))
            .map_err(e)?;
        if loco && !labelled.0 {
            labelled.0 = true;
            anno.label("locomotion (outside the hull)")
                .legend(move |(x, y)| Circle::new((x + 11, y), 7, yes.filled()));
        } else if !loco && !labelled.1 {
            labelled.1 = true;
            anno.label("not locomotion (in or on the hull)")
                .legend(move |(x, y)| Circle::new((x + 11, y), 7, no.filled()));
        }
        // Alternate labels below and above the markers so neighbours do not collide.
        let (dy, vp) = if k % 2 == 0 {
            (12, VPos::Top)
        } else {
            (-12, VPos::Bottom)
        };
        let t = Text::new(
            label.clone(),
            (0, dy),
            font(TICK_PX).color(&col).pos(Pos::new(HPos::Center, vp)),
        );
        ch.plotting_area()
            .draw(&(EmptyElement::at((v[0], v[1])) + t))
            .map_err(e)?;
    }
    crate::plot::draw_legend(&mut ch, SeriesLabelPosition::UpperLeft)?;
    Ok(())
}

/// The falsification mutations of this chapter's claims (see [`crate::report::Mutation`]):
/// every sailing verdict reversed, and the definition replaced by two wrong variants.
pub fn mutations() -> Vec<Mutation> {
    let mut m: Vec<Mutation> = sailing_cases()
        .into_iter()
        .map(|c| {
            let id = c.id;
            Mutation::new(
                id,
                "the document's verdict on this case reversed",
                move || {
                    claim_of(
                        &Doc {
                            flipped: vec![id],
                            ..Doc::PRINTED
                        },
                        id,
                    )
                },
            )
        })
        .collect();
    let with_rule = |id: &'static str, rule: Rule, what: &'static str| {
        Mutation::new(id, what, move || {
            claim_of(
                &Doc {
                    rule,
                    ..Doc::PRINTED
                },
                id,
            )
        })
    };
    m.push(with_rule(
        "downwind-at-wind-speed",
        Rule::OutsideOrOnHull,
        "the hull's boundary counts as locomotion",
    ));
    m.push(with_rule(
        "reaching",
        Rule::FasterThanMedia,
        "locomotion = faster than every medium",
    ));
    m.push(with_rule(
        "water-skier-dragged",
        Rule::HullOnly,
        "the hull test alone (dragging by an outside force ignored)",
    ));
    m.push(with_rule(
        "three-media",
        Rule::OutsideOrOnHull,
        "the hull's boundary counts as locomotion",
    ));
    m.push(with_rule(
        "convex-combination",
        Rule::OutsideOrOnHull,
        "the hull's boundary counts as locomotion",
    ));
    m.push(Mutation::new(
        "convex-combination",
        "0 <= s <= 1 -> 0 <= s <= 1.1",
        || {
            claim_of(
                &Doc {
                    s_max: 1.1,
                    ..Doc::PRINTED
                },
                "convex-combination",
            )
        },
    ));
    m
}
