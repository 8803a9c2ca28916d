//! The failures the evidence shows, one row each for the result `failures`: the stiff
//! relaxation, the block's unlocated runs, Zeno, Moreau-Jean's first order, the stick's
//! broken and unlocated runs, the missed event.

use super::evidence::Evidence;
use super::failures::Failure;
use super::stick_part::knob_text;
use super::work_precision::{dopri5_errors_at, error_at, fmt_err};
use crate::report::fmt_num;

/// Every failure row, in the order of the chapter's sections.
pub fn all(ev: &Evidence) -> Vec<Failure> {
    let mut out = stiff(ev);
    out.extend(block_unlocated(ev));
    out.extend(zeno(ev));
    out.push(moreau_jean(ev));
    out.extend(stick(ev));
    out.extend(ev.missed.failures());
    out
}

/// The explicit fixed-step runs that blew up on the stiff relaxation.
fn stiff(ev: &Evidence) -> Vec<Failure> {
    let st = &ev.stiff.outcome;
    st.fixed
        .iter()
        .filter(|(_, e)| e.is_none_or(|e| e > 1e3))
        .map(|(m, e)| Failure {
            method: format!("{}-fixed", m.name()),
            scene: format!(
                "stick flight relaxation, τ = γ/k = 1 ms, h = T/10 = {:.1} τ",
                st.h_over_tau
            ),
            symptom: match e {
                None => "blew up: state overflowed to non-finite".into(),
                Some(e) => format!("blew up: error {} rad", fmt_num(*e)),
            },
        })
        .collect()
}

/// The unlocated runs of the block's ladder that fail (events late by up to a step).
fn block_unlocated(ev: &Evidence) -> Vec<Failure> {
    let b = &ev.block;
    let err_of = |label: &str| error_at(&b.points, label, b.coarse_step_s);
    let mut out = Vec::new();
    for m in ["euler", "rk4"] {
        let (l, u) = (
            err_of(&format!("{m}-located")),
            err_of(&format!("{m}-unlocated")),
        );
        if u > 2.0 * l {
            out.push(Failure {
                method: format!("{m}-unlocated"),
                scene: "block drift, h = T/20".into(),
                symptom: format!(
                    "events late by up to a step: drift error {} (located: {})",
                    fmt_err(u),
                    fmt_err(l)
                ),
            });
        }
    }
    let tight = b.tightest_tol;
    let (loc, unloc) = dopri5_errors_at(&b.points, tight);
    if unloc > 100.0 * loc.max(1e-15) {
        out.push(Failure {
            method: "dopri5-unlocated".into(),
            scene: format!("block drift, tol = {tight:e}"),
            symptom: format!(
                "error stalls at {} whatever the tolerance (located: {})",
                fmt_err(unloc),
                fmt_err(loc)
            ),
        });
    }
    out
}

/// The ball's Zeno stop and the plate's chattering without a rest threshold.
fn zeno(ev: &Evidence) -> Vec<Failure> {
    let (z, e, gamma) = (&ev.zeno.outcome, ev.zeno.restitution, ev.zeno.gamma);
    let mut out = Vec::new();
    if let Some(t) = z.ball_zeno_at_s {
        out.push(Failure {
            method: "event-driven (any integrator)".into(),
            scene: format!("ball dropped from 1 m on a fixed floor, e = {e}"),
            symptom: format!("Zeno: infinitely many impacts before t_inf = {} s; the run stops there (Outcome::Zeno at {} s)", fmt_num(z.ball_t_inf_s), fmt_num(t)),
        });
    }
    if z.events_chattering > 2 * z.events_sticking {
        out.push(Failure {
            method: "event-driven without a rest threshold".into(),
            scene: format!("block on the plate, e = {e}, Γ = {gamma}"),
            symptom: format!(
                "chattering: {} events in {} periods where the sticking transition needs {}; each cascade ends only by round-off",
                z.events_chattering,
                ev.zeno.periods,
                z.events_sticking
            ),
        });
    }
    out
}

/// Moreau-Jean's first-order error at the coarsest step, next to RK4's.
fn moreau_jean(ev: &Evidence) -> Failure {
    let b = &ev.block;
    let err_of = |label: &str| error_at(&b.points, label, b.coarse_step_s);
    Failure {
        method: "moreau-jean".into(),
        scene: "block drift, h = T/20".into(),
        symptom: format!(
            "first order only: drift error {} at h = T/20 (rk4-located: {})",
            fmt_err(err_of("moreau-jean")),
            fmt_err(err_of("rk4-located"))
        ),
    }
}

/// The stick's ladder runs that broke down, and its unlocated runs far off.
fn stick(ev: &Evidence) -> Vec<Failure> {
    let st = &ev.stick;
    let mut out: Vec<Failure> = st
        .broken
        .iter()
        .map(|(i, why)| {
            let p = &st.points[*i];
            Failure {
                method: p.setting.label(),
                scene: format!(
                    "stick mean speed, {}",
                    knob_text(&p.setting, st.period_s)
                ),
                symptom: format!("run broke down: {why}"),
            }
        })
        .collect();
    for m in ["euler", "rk4"] {
        let h = st.period_s / f64::from(st.steps[0]);
        let (l, u) = (
            error_at(&st.points, &format!("{m}-located"), h),
            error_at(&st.points, &format!("{m}-unlocated"), h),
        );
        if u.is_finite() && u > 10.0 * l {
            out.push(Failure {
                method: format!("{m}-unlocated"),
                scene: format!("stick mean speed, h = T/{}", st.steps[0]),
                symptom: format!(
                    "events late by up to a step: speed error {} (located: {})",
                    fmt_err(u),
                    fmt_err(l)
                ),
            });
        }
    }
    out
}
