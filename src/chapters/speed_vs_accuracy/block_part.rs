//! The block's part of the chapter: the reference and its convergence study, the
//! work-precision ladder, and the failures (stiffness, unlocated events, Zeno).

use super::block_scene::BlockScene;
use super::failures::{blows_up, stiff, zeno, Failure};
use super::measure::{drift_block_model, window, Measured};
use super::setup::{envelope, Setup};
use super::work_precision::{
    cheapest_json, dopri5_errors_at, error_at, fmt_err, ladder, measure, observed_order, Solver,
    WpPoint, EVENT_DRIVEN_LABELS,
};
use crate::numerics::hybrid::Options;
use crate::numerics::ode::StepControl;
use crate::report::{fmt_num, ChapterReport, Check, Claim};
use serde_json::{json, Value};

/// The reference (closed forms between located events), checked against integrated
/// Dormand-Prince and its convergence study.
pub(super) fn reference_claims(s: &Setup<'_>, r: &mut ChapterReport) -> Measured {
    let (args, doc, g, win) = (s.args, s.doc, s.g, s.win);
    // The workbook's block model (physics::block) with its closed forms: only the event
    // times carry numerical error (located to a few ulps).
    let block = |opts: &Options, closed: bool| s.block(opts, closed);
    let reference = block(&Options::default(), true);
    let dp = |tol: f64| {
        block(
            &Options {
                control: StepControl::tol(tol, tol),
                ..Options::default()
            },
            false,
        )
        .value
    };
    let (d10, d11, d12, d13) = (dp(1e-10), dp(1e-11), dp(1e-12), dp(1e-13));
    let d_ref = if doc.reference_tol == 1e-12 {
        d12
    } else {
        dp(doc.reference_tol)
    };
    let rel = |v: f64| ((v - reference.value) / reference.value).abs();
    r.result("block_drift_mps", reference.value);
    r.result(
        "block_drift_reference_check",
        json!({"dopri5_1e-10": rel(d10), "dopri5_1e-11": rel(d11), "dopri5_1e-12": rel(d12)}),
    );
    // DP5 at 1e-12 over <= 50 periods with events located to a few ulps: its error on
    // the drift is a few local errors of the velocities, whose scale is the plate's
    // peak speed v_p = Gamma g / omega, not the drift (which vanishes at the onset of
    // motion, where a relative difference blows up: 1.03e-8 of a drift of 3.8e-4 m/s at
    // Gamma 2.186, mu 0.074, only 3.4e-11 v_p). Measured 3e-11 v_p on both scenes;
    // 1e-9 v_p leaves a factor 30 and still tests far beyond any method of the ladder.
    let v_p = args.gamma * g / (std::f64::consts::TAU * args.frequency_hz); // formula: v_p = Gamma g / omega
    let diff_vp = (d_ref - reference.value).abs() / v_p;
    r.claim(Claim::draft(
        Check::SecondMethod,
        "reference-converged",
        "numerics",
        &format!("The closed-form event-driven drift (the reference) agrees with integrated Dormand-Prince at rtol = atol = {:e}: difference in units of the plate's peak speed v_p = Γ g/ω (relative to the drift: {:.1e})", doc.reference_tol, rel(d_ref)),
    )
    .close(0.0, diff_vp, 1e-9));
    // The rounding floor of the drift: every event time is located to a few ulps of t
    // (a few hundred ulps covers the locator's bracketing and the closed forms' own
    // rounding), and an event-time error dt shifts the displacement by at most the jump
    // of the relative velocity, |v_block - v_plate| <= 2 v_p with v_p = Gamma g / omega,
    // times dt. Summed over the events and divided by the window, it bounds how far two
    // runs agreeing to within the rounding can differ in drift.
    let omega = std::f64::consts::TAU * args.frequency_hz;
    let (t_a, t_b) = win;
    let floor_abs = 256.0 * f64::EPSILON * t_b * 2.0 * args.gamma * g / omega
        * reference.events.max(1) as f64
        / (t_b - t_a); // formula: F = 256 eps t_end 2 v_p N_events / T_window
    let floor = floor_abs / reference.value.abs().max(f64::MIN_POSITIVE);
    r.result("block_drift_rounding_floor_rel", floor);
    // Two decades of tolerance (1e-10 -> 1e-12) buy at least one decade of accuracy,
    // down to the run's own floor. Budget: with local error control the global error
    // of a pair of order p = 5 scales as tol^(p/(p+1)): 100^(5/6) = 46 over two decades
    // (measured 40 on the default scene); the claim asks for 10. The floor has two
    // parts, both from the runs themselves: F, the rounding of the event times above,
    // and |d(1e-12) - d(1e-13)|, the change one more decade makes: where DP5 has reached
    // its floor its error no longer shrinks with the tolerance and this change is of
    // the floor's size (measured at --frequency-hz 100 --mu 0.01 --bias 0.45: errors
    // 3.6e-9, 4.5e-9, 9.2e-9, 4.8e-9 relative from 1e-10 to 1e-13, i.e. 6e-13 ..
    // 1.5e-12 m/s, while F is 1.8e-9), where tolerance-proportional control makes it
    // about the error itself. The 1e-11 middle point is reported, not ordered: the
    // signed error is a sum of event terms of both signs, and one decade can land on a
    // cancellation (--bias 0.9: 9.8e-11, 1.3e-9, 5.4e-11).
    let floor_run = ((d12 - d13) / reference.value).abs(); // formula: |d(1e-12) - d(1e-13)| / |d|
    r.result(
        "block_drift_reference_floor_rel",
        json!({"rounding": floor, "next_decade": floor_run, "dopri5_1e-13": rel(d13)}),
    );
    r.claim(Claim::draft(
        Check::Convergence,
        "reference-convergence-study",
        "numerics",
        "Integrated Dormand-Prince approaches the reference as the tolerance tightens: err(1e-12) <= err(1e-10)/10 + F + |d(1e-12) - d(1e-13)|/|d|: two decades of tolerance buy at least one decade of accuracy (a 5(4) pair under local error control: 100^(5/6) = 46), down to the run's own floor, F the rounding of the event times (256 ulps of t per event times the relative-velocity jump 2 Γ g / ω, over the window) and the change one more decade makes (at the floor it is the floor's size)",
    )
    .exact(true, if doc.tightening_helps {
            rel(d12) <= rel(d10) / 10.0 + floor + floor_run
        } else {
            rel(d12).min(rel(d11)) >= rel(d10) + floor
        }));

    reference
}

/// The work-precision ladder on the chapter's scene, and on the default benchmark scene
/// for the observed orders (the same points when the scenes are equal).
pub(super) fn measure_ladder(s: &Setup<'_>, reference: f64) -> (Vec<WpPoint>, Vec<WpPoint>) {
    let (plan, g, scene, win) = (&s.plan, s.g, &s.scene, s.win);
    let (tr, cy, period) = (plan.transient, plan.cycles, scene.period_s());
    let block = |opts: &Options, closed: bool| s.block(opts, closed);
    let solvers = ladder(period, &plan.steps, &plan.tols, &plan.mj_steps);
    let points = measure(
        "block-drift",
        &solvers,
        reference,
        plan.repeats,
        |s| match s {
            Solver::MoreauJean {
                steps_per_period, ..
            } => super::measure::drift_mj(scene, *steps_per_period, win),
            other => block(&other.options(0).expect("hybrid"), false),
        },
    );
    // Observed orders: least-squares slopes of log error against log step, measured on
    // the default benchmark scene whatever the flags (the order a method shows on an
    // observable with events depends on the scene: near Gamma = 1 or at small mu the
    // events crowd and the asymptotic range starts beyond the ladder).
    let bench = BlockScene::new(30.0, 2.5, 0.4, 0.05, g);
    let order_points: Vec<WpPoint> = if bench == *scene {
        points.clone()
    } else {
        let bref = drift_block_model(&bench, &Options::default(), true, 64, tr, cy).value;
        let bench_solvers = ladder(bench.period_s(), &plan.steps, &plan.tols, &plan.mj_steps);
        measure(
            "block-drift-default",
            &bench_solvers,
            bref,
            1,
            |s| match s {
                Solver::MoreauJean {
                    steps_per_period, ..
                } => super::measure::drift_mj(&bench, *steps_per_period, window(&bench, tr, cy)),
                other => drift_block_model(
                    &bench,
                    &other.options(0).expect("hybrid"),
                    false,
                    20,
                    tr,
                    cy,
                ),
            },
        )
    };
    (points, order_points)
}

/// The first-order envelopes, the observed slopes and the unlocated stall on the ladder.
pub(super) fn ladder_claims(
    s: &Setup<'_>,
    points_all: &[WpPoint],
    order_points: &[WpPoint],
    r: &mut ChapterReport,
) {
    let (doc, plan) = (s.doc, &s.plan);
    let points = order_points;
    // Observed slopes on the block drift, reported (results) but not claimed as orders:
    // the signed error is a sum of terms of both signs whose balance shifts with h (it
    // passes through zero near T/290 for Euler; chapter 7's text gives the scan), so
    // the local slopes of |error| range from about 0 to 7. The convergence orders are
    // claimed on the stick, where they show cleanly.
    let mut order_json = serde_json::Map::new();
    for label in ["rk4-located", "euler-located", "moreau-jean"] {
        order_json.insert(
            label.to_string(),
            json!(observed_order(points, label, 1e-10)),
        );
    }
    // What the block's data does support for the first-order methods: an envelope
    // e(h) <= 2 e(h0) (h/h0)^p over the whole ladder (h0 = T/20), with p = 1. A method of
    // order 0 (no convergence) or 1/2 fails it over the ladder's range of h (a factor
    // 64 in quick mode, 256 and more in full); order 2 fails it too (tested).
    for (label, name) in [
        ("euler-located", "Explicit Euler with located events"),
        ("moreau-jean", "Moreau-Jean"),
    ] {
        let (worst, n) = envelope(points, label, doc.first_order);
        r.claim(Claim::draft(
            Check::Convergence,
            &format!("{label}-order"),
            "numerics",
            &format!("{name} converges on the block drift of the default scene (Γ = 2.5, b = 0.05, μ = 0.4) at least at first order: every error of the ladder is below 2 e(h0) (h/h0)^1, h0 = T/20 (computed: the largest ratio e(h) / (e(h0) (h/h0))). A lower bound only: the signed error changes sign and course with h on this observable (chapter 7's text), so no order is fitted here; the orders are fitted on the stick."),
        )
        .values(format!("<= 2 ({n} step sizes)"), worst, "factor 2 on a first-order envelope").confirmed_if(n >= 3 && worst <= 2.0));
    }
    r.result("observed_orders", Value::Object(order_json));
    let points = points_all;
    let tight = *plan.tols.last().expect("tolerances");
    let (loc, unloc) = dopri5_errors_at(points, tight);
    r.claim(Claim::draft(
        Check::Simulation,
        "unlocated-events-stall",
        "numerics",
        "Without event location Dormand-Prince's error stalls: at the tightest tolerance it is over 100 times the located error (events are taken at step ends)",
    )
    .exact(true, (unloc > 100.0 * loc.max(1e-15)) == doc.unlocated_stalls));
    let mut labels = EVENT_DRIVEN_LABELS.to_vec();
    labels.push("moreau-jean");
    r.result(
        "rhs_evals_to_reach_1e-6",
        cheapest_json(points, &labels, 1e-6),
    );
}

/// Time constant of the stiff flight relaxation, gamma/k (s).
const TAU_S: f64 = 0.01 / 10.0;

/// Explicit fixed steps on the stiff flight relaxation, against adaptive DP5.
pub(super) fn stiff_claims(s: &Setup<'_>, r: &mut ChapterReport, fails: &mut Vec<Failure>) {
    let doc = s.doc;
    let st = stiff(TAU_S, 30.0, if s.quick { 0.3 } else { 1.0 });
    for (m, e) in &st.fixed {
        let blew = e.is_none_or(|e| e > 1e3);
        if blew {
            fails.push(Failure {
                method: format!("{}-fixed", m.name()),
                scene: format!(
                    "stick flight relaxation, τ = γ/k = 1 ms, h = T/10 = {:.1} τ",
                    st.h_over_tau
                ),
                symptom: match e {
                    None => "blew up: state overflowed to non-finite".into(),
                    Some(e) => format!("blew up: error {} rad", fmt_num(*e)),
                },
            });
        }
    }
    // Each fixed-step method blows up where h/tau exceeds its stability limit on the
    // linear decay (Euler: |1 - z| < 1 -> z < 2; RK4: z < 2.785), and the limits are
    // sharp: 5 % beyond each it blows up, 5 % inside it does not (a limit stated 10 %
    // off puts one of the two on the wrong side).
    let stiff_ok = st.fixed.iter().all(|(m, e)| {
        let limit = match m.name() {
            "euler" => doc.euler_limit,
            _ => doc.rk4_limit,
        };
        e.is_none_or(|e| e > 1e3) == (st.h_over_tau > limit)
            && blows_up(*m, TAU_S, 30.0, 1.05 * limit)
            && !blows_up(*m, TAU_S, 30.0, 0.95 * limit)
    }) && st.dopri5_error < 1e-6;
    r.claim(Claim::draft(
        Check::ClosedForm,
        "stiff-relaxation-explicit-blowup",
        "4 (C.3)",
        "On the flight relaxation θ' = -(k/γ)(θ - θ₀) (k/γ = 1000/s), fixed steps of T/10 blow up for Euler and RK4 (h/τ beyond 2 and 2.785) while adaptive Dormand-Prince stays within 1e-6 rad of the closed form; the limits are sharp: at 1.05 times each limit the fixed step blows up within 400 steps, at 0.95 times it does not",
    )
    .exact(true, stiff_ok));
}

/// The unlocated runs of the ladder that fail (events late by up to a step).
pub(super) fn unlocated_failures(s: &Setup<'_>, points: &[WpPoint], fails: &mut Vec<Failure>) {
    let plan = &s.plan;
    let period = s.scene.period_s();
    let err_of = |label: &str, knob: f64| error_at(points, label, knob);
    let tight = *plan.tols.last().expect("tolerances");
    let (loc, unloc) = dopri5_errors_at(points, tight);
    let coarse = period / f64::from(plan.steps[0]);
    for m in ["euler", "rk4"] {
        let (l, u) = (
            err_of(&format!("{m}-located"), coarse),
            err_of(&format!("{m}-unlocated"), coarse),
        );
        if u > 2.0 * l {
            fails.push(Failure {
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
    if unloc > 100.0 * loc.max(1e-15) {
        fails.push(Failure {
            method: "dopri5-unlocated".into(),
            scene: format!("block drift, tol = {tight:e}"),
            symptom: format!(
                "error stalls at {} whatever the tolerance (located: {})",
                fmt_err(unloc),
                fmt_err(loc)
            ),
        });
    }
}

/// Zeno: the bouncing ball and the chattering plate, event-driven and Moreau-Jean.
pub(super) fn zeno_claims(s: &Setup<'_>, r: &mut ChapterReport, fails: &mut Vec<Failure>) {
    let (args, doc, plan, g) = (s.args, s.doc, &s.plan, s.g);
    // Zeno: a ball on a fixed floor, and the block on a plate at Gamma = 1.2, where
    // every landing turns into a chattering sequence (complete chattering).
    let gamma_zeno = 1.2;
    let zeno_scene = BlockScene::new(args.frequency_hz, gamma_zeno, args.mu, args.bias, g);
    let mj_n = if s.quick { 1000 } else { 4000 };
    let e = args.restitution;
    let z = zeno(&zeno_scene, e, plan.transient, plan.cycles, mj_n);
    if let Some(t) = z.ball_zeno_at_s {
        fails.push(Failure {
            method: "event-driven (any integrator)".into(),
            scene: format!("ball dropped from 1 m on a fixed floor, e = {e}"),
            symptom: format!("Zeno: infinitely many impacts before t_inf = {} s; the run stops there (Outcome::Zeno at {} s)", fmt_num(z.ball_t_inf_s), fmt_num(t)),
        });
    }
    if z.events_chattering > 2 * z.events_sticking {
        fails.push(Failure {
            method: "event-driven without a rest threshold".into(),
            scene: format!("block on the plate, e = {e}, Γ = {gamma_zeno}"),
            symptom: format!(
                "chattering: {} events in {} periods where the sticking transition needs {}; each cascade ends only by round-off",
                z.events_chattering,
                plan.transient + plan.cycles,
                z.events_sticking
            ),
        });
    }
    // The driver stops when 100 events fall within 1 us or time stops advancing: the
    // flights still to come then sum to less than the window, 1e-6 s.
    r.claim(Claim::draft(
        Check::ClosedForm,
        "zeno-ball-stops-at-accumulation",
        "numerics",
        "The event-driven driver stops a ball bouncing with 0 < e < 1 (dropped from 1 m) with a Zeno outcome at the accumulation time t_inf = t1 (1 + e)/(1 - e) (s)",
    )
    .close(doc.zeno_factor * z.ball_t_inf_s, z.ball_zeno_at_s.unwrap_or(f64::NAN), 1e-6));
    // Moreau-Jean at h = 1 ms loses bounces shorter than a step: it settles within a few
    // steps of the last resolved bounce, itself within ~2 v_min/(g (1-e)) of t_inf with
    // v_min ~ g h, i.e. ~2 h/(1 - e): a few ms at e = 0.5; the bound is 10 h/(1 - e), at
    // least 0.05 s.
    let mj_rest_tol = (10.0 * 1e-3 / (1.0 - e)).max(0.05);
    r.claim(Claim::draft(
        Check::ClosedForm,
        "zeno-ball-moreau-jean-rest",
        "numerics",
        "Moreau-Jean (h = 1 ms) passes through the same accumulation and keeps the ball at rest from about t_inf on (s)",
    )
    .close(doc.zeno_factor * z.ball_t_inf_s, z.ball_mj_rest_s, mj_rest_tol));
    // Moreau-Jean at T/1000..T/4000 is first order with an error of ~1e-3 relative on
    // the drift (the ladder above); the sticking threshold of 0.1 mm/s changes the drift
    // by less than that. 2 % allows both.
    r.claim(Claim::draft(
        Check::SecondMethod,
        "zeno-plate-resolved-two-ways",
        "3.1.2",
        "On the chattering plate (Γ = 1.2), the sticking transition (event-driven) and Moreau-Jean give the same drift (relative difference)",
    )
    .close(0.0, ((z.drift_mj_mps - doc.zeno_plate_factor * z.drift_sticking_mps)
            / z.drift_sticking_mps)
            .abs(), 0.02));
}

/// Moreau-Jean's first-order error at the coarsest step, next to RK4's.
pub(super) fn moreau_jean_failure(s: &Setup<'_>, points: &[WpPoint], fails: &mut Vec<Failure>) {
    let coarse = s.scene.period_s() / f64::from(s.plan.steps[0]);
    let err_of = |label: &str, knob: f64| error_at(points, label, knob);
    let mj20 = err_of("moreau-jean", coarse);
    fails.push(Failure {
        method: "moreau-jean".into(),
        scene: "block drift, h = T/20".into(),
        symptom: format!(
            "first order only: drift error {} at h = T/20 (rk4-located: {})",
            fmt_err(mj20),
            fmt_err(err_of("rk4-located", coarse))
        ),
    });
}
