//! The stick-by-three-methods section of the chapter: results, claims and the charts
//! of error against force evaluations (one per scene).

use super::stick_methods::{claims, measure_scene, soft_ladder, Plan, SceneMethods};
use super::stick_methods_soft::{soft_claims, soft_json, SOFT_ORDER};
use crate::error::Result;
use crate::physics::stick::soft::SoftParams;
use crate::physics::stick::{authors_scene, jamming_scene};
use crate::plot::{save_panels, Chart, Legend, Series};
use crate::report::{ChapterReport, Mutation};
use std::path::Path;
use std::sync::OnceLock;

/// Labels and colours of the methods in the charts.
const STYLE: [(&str, &str, usize); 4] = [
    ("event_dop853", "event-driven DOP853 (rtol)", 4),
    ("event_dopri5", "event-driven DP5 (rtol)", 2),
    ("moreau_jean", "Moreau-Jean (step h)", 3),
    ("soft_contact", "soft contact + Rosenbrock (ε)", 0),
];

/// Errors below this are drawn at it (log axis).
const FLOOR: f64 = 1e-15;

/// Measures both scenes, adds results and the default scene's claims to `r`, and
/// draws the charts into `dir` (when given). The scenes are the stick chapter's own, each
/// with its g (9.81 and 10 m/s^2), whatever `--g-mps2`: the claims are measurements of
/// those scenes (at g = 17 m/s^2 Moreau-Jean's error is not yet in its asymptotic range
/// at the ladder's finest step, so its Richardson estimate misses by a factor 5).
pub fn build(r: &mut ChapterReport, quick: bool, dir: Option<&Path>) -> Result<()> {
    let plan = Plan::new(quick);
    let default = measure_scene(&jamming_scene(9.81), &plan);
    let authors = measure_scene(&authors_scene(10.0), &plan);
    r.result("stick_methods", with_convergence(&default));
    r.result("stick_methods_authors", with_convergence(&authors));
    for c in claims(&default, 1.0) {
        r.claim(c);
    }
    for c in soft_claims(&default, SOFT_ORDER) {
        r.claim(c);
    }
    if let Some(dir) = dir {
        r.figures.extend(chart(
            dir,
            &default,
            "Stick by three methods: self-locking scene",
            "stick-methods-default",
        )?);
        r.figures.extend(chart(
            dir,
            &authors,
            "Stick by three methods: authors' scene",
            "stick-methods-authors",
        )?);
    }
    Ok(())
}

/// The scene's results with the soft ladder's convergence study in
/// `soft_contact.convergence`.
fn with_convergence(s: &SceneMethods) -> serde_json::Value {
    let mut v = s.to_json();
    v["soft_contact"]["convergence"] = soft_json(s);
    v
}

fn chart(dir: &Path, s: &SceneMethods, title: &str, name: &str) -> Result<Vec<String>> {
    let mut c = Chart::new(
        title,
        "force evaluations",
        "relative difference of the mean speed",
    )
    .log_x()
    .log_y()
    .legend(Legend::LowerRight);
    for (key, label, col) in STYLE {
        let pts: Vec<(f64, f64)> = s
            .ladder(key)
            .rungs
            .iter()
            .filter(|r| r.rel.is_finite() && r.evals > 0)
            .map(|r| (r.evals as f64, r.rel.max(FLOOR)))
            .collect();
        c = c
            .series(Series::line(label, pts.clone()).color(col))
            .series(Series::points("", pts).color(col));
    }
    save_panels(&[c], 1, dir, name)
}

/// One quick measurement of the default scene serves every mutation (the ladders do
/// not depend on the claims).
fn quick() -> &'static SceneMethods {
    static QUICK: OnceLock<SceneMethods> = OnceLock::new();
    QUICK.get_or_init(|| measure_scene(&jamming_scene(9.81), &Plan::new(true)))
}

/// The claim `id` among `claims`.
fn pick(claims: Vec<crate::report::Claim>, id: &str) -> crate::report::Claim {
    claims.into_iter().find(|c| c.id == id).expect("the claim")
}

/// Mutations of this section's claims: the claimed order off by one, and soft
/// contact's first family (v_ε = 0.1 ε m/s, not first order) in place of its own.
pub fn mutations() -> Vec<Mutation> {
    let mj = |id: &'static str| move || pick(claims(quick(), 2.0), id);
    let soft = |id: &'static str| move || pick(soft_claims(quick(), 2.0), id);
    vec![
        Mutation::new(
            "stick-methods-moreau-jean-order",
            "Moreau-Jean order 1 -> 2",
            mj("stick-methods-moreau-jean-order"),
        ),
        Mutation::new(
            "stick-methods-moreau-jean-gap-within-estimate",
            "Richardson estimate with order 2 instead of 1",
            mj("stick-methods-moreau-jean-gap-within-estimate"),
        ),
        Mutation::new(
            "soft-contact-order",
            "soft contact order 1 -> 2",
            soft("soft-contact-order"),
        ),
        Mutation::new(
            "soft-contact-order",
            "soft contact with friction smoothing v_ε = 0.1 ε (m/s) instead of v₀ ε²",
            || {
                let p = jamming_scene(9.81);
                let plan = Plan {
                    soft_family: SoftParams::regularised_linear_slip,
                    ..Plan::new(true)
                };
                let mut s = quick().clone();
                let l = soft_ladder(&p, &plan, s.reference_mps);
                *s.ladders
                    .iter_mut()
                    .find(|l| l.method == "soft_contact")
                    .expect("a soft ladder") = l;
                pick(soft_claims(&s, SOFT_ORDER), "soft-contact-order")
            },
        ),
        Mutation::new(
            "soft-contact-richardson-gap",
            "soft contact's Richardson estimate with order 2 instead of 1",
            soft("soft-contact-richardson-gap"),
        ),
    ]
}
