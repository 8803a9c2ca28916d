//! The chapter's claims, as pure functions of the statements and the evidence: the
//! falsification mutations (`mutations.rs`) judge edited statements on the same
//! evidence.

use super::budget::{adaptive_error_bound, first_order_error, rounding_mps, DECADE_CONTRACTION};
use super::evidence::Evidence;
use super::setup::envelope;
use super::statements::Statements;
use super::stick_methods::{fitted_order, gap_over_estimate, SceneMethods};
use super::stick_methods_soft::asymptotic_range;
use super::economy::HORIZONTAL_LIMIT;
use super::stick_part::AUTHORS_G_MPS2;
use super::measure::Measured;
use super::work_precision::{dopri5_errors_at, Solver, WpPoint};
use crate::numerics::ode::Method;
use crate::report::{Check, Claim};
use serde_json::json;

/// Every claim of the chapter, in the order of the report.
pub fn all(doc: &Statements, ev: &Evidence) -> Vec<Claim> {
    let mut out = vec![reference_converged(doc, ev), reference_study(doc, ev)];
    out.extend(first_order_envelopes(doc, ev));
    out.extend([
        unlocated_stall(doc, ev),
        stiff_blowup(doc, ev),
        zeno_ball(doc, ev),
        zeno_ball_mj(doc, ev),
        zeno_plate(doc, ev),
        stick_reference(doc, ev),
        stick_rk4_order(doc, ev),
        stick_euler_order(doc, ev),
        stick_unlocated_stall(doc, ev),
        stick_dop853(doc, ev),
        missed_event(doc, ev),
        flight_map(doc, ev),
        viscous_law(doc, ev),
    ]);
    out.extend(stick_methods(&ev.methods_default, doc.mj_order));
    if doc.soft_friction_quadratic {
        out.extend(soft_contact(&ev.methods_default, doc.soft_order));
    } else {
        let mut s = ev.methods_default.clone();
        for l in s.ladders.iter_mut().filter(|l| l.method == "soft_contact") {
            *l = ev.soft_first_family.clone();
        }
        out.extend(soft_contact(&s, doc.soft_order));
    }
    out
}

/// The closed-form event-driven drift against integrated Dormand-Prince at tau =
/// `doc.reference_tol`, within DP5's error bound from its own runs at tau and tau/10
/// (`budget.rs`) plus the reference's rounding: in units of the plate's peak speed
/// v_p = Gamma g / omega, the scale of the velocities whose errors make the drift's (a
/// relative difference blows up at the onset of motion, where the drift vanishes).
/// Measured on the default quick scene: 3.3e-11 v_p against a bound of about 5e-11 v_p;
/// a reference off by 1e-6 relative (1.9e-8 v_p) fails it.
fn reference_converged(doc: &Statements, ev: &Evidence) -> Claim {
    let b = &ev.block;
    let reference = b.reference.value * (1.0 + doc.reference_offset_rel);
    let d_ref = b.dopri5_at(doc.reference_tol);
    let rel = |v: f64| ((v - reference) / reference).abs();
    let diff_vp = (d_ref - reference).abs() / b.v_p_mps;
    let bound_mps = b
        .decade_pair(doc.reference_tol)
        .map_or(f64::NAN, |(tau, tenth)| adaptive_error_bound(tau, tenth).0);
    let tol_vp = (bound_mps + b.reference_rounding_mps) / b.v_p_mps; // formula: |d(tau) - d_ref| <= |e(tau)| + R_ref
    Claim::draft(
        Check::SecondMethod,
        "reference-converged",
        "numerics",
        &format!("The closed-form event-driven drift (the reference) agrees with integrated Dormand-Prince at rtol = atol = {:e} within DP5's error bound from the run itself, K (|d(τ) - d(τ/10)| + R(τ) + R(τ/10)) + R(τ) + R_ref with K = 1/(1 - 10^(-1/2)) and R each run's rounding budget (unit roundoff × evaluations × state scale, event times × velocity jump): difference and bound in units of the plate's peak speed v_p = Γ g/ω (relative to the drift: {:.1e})", doc.reference_tol, rel(d_ref)),
    )
    .close(0.0, diff_vp, tol_vp)
}

/// The floor of the convergence study (relative): the error the statement allows at
/// 1e-12 beyond err(1e-10)/10 once rounding is counted. With d(tau) = d* + T(tau) +
/// r(tau), |r| <= R(tau) (`budget.rs`: every right-hand-side evaluation and event of the
/// run) and the reference d* + r_ref, |r_ref| <= R_ref: err(1e-12) <= |T(1e-12)| +
/// R(1e-12) + R_ref and |T(1e-10)| <= err(1e-10) + R(1e-10) + R_ref, so the statement
/// |T(1e-12)| <= |T(1e-10)|/10 gives err(1e-12) <= err(1e-10)/10 + G.
pub fn study_floor_rel(ev: &Evidence) -> f64 {
    let b = &ev.block;
    let (r10, r12, r_ref) = (
        b.dopri5_rounding_mps[0],
        b.dopri5_rounding_mps[2],
        b.reference_rounding_mps,
    );
    (r12 + r_ref + (r10 + r_ref) / 10.0) / b.reference.value.abs() // formula: G = (R(1e-12) + R_ref + (R(1e-10) + R_ref)/10)/|d|
}

/// Two decades of tolerance buy at least one decade of accuracy.
fn reference_study(doc: &Statements, ev: &Evidence) -> Claim {
    let b = &ev.block;
    let rel = |v: f64| ((v - b.reference.value) / b.reference.value).abs();
    let (d10, d11, d12) = (b.dopri5[0].1, b.dopri5[1].1, b.dopri5[2].1);
    let (floor, next_decade) = (study_floor_rel(ev), b.next_decade_rel);
    // Budget: with local error control the global error of a pair of order p = 5 scales
    // as tol^(p/(p+1)): 100^(5/6) = 46 over two decades (measured 40 on the default
    // scene); the claim asks for 10 of the truncation, down to two floors measured on
    // the runs. G, the runs' and the reference's rounding budgets (`study_floor_rel`):
    // where the runs sit at their rounding already at 1e-10 (--gamma 50 --g-mps2 1
    // --frequency-hz 100 --bias 0.226: errors 5.81e-12, 5.82e-12, 5.82e-12, 5.81e-12
    // relative from 1e-10 to 1e-13, i.e. 5.3e-14 m/s, against R(1e-12) = 1.0e-12 m/s),
    // err(1e-10)/10 is below it. D = |d(1e-12) - d(1e-13)|/|d|, the change one more
    // decade makes: the signed error is a sum of event terms of both signs, and 1e-10
    // can land on a cancellation (--frequency-hz 100 --mu 0.01 --bias 0.45: errors
    // 3.6e-9, 4.5e-9, 9.2e-9, 4.8e-9 relative, G = 6.2e-9, D = 1.4e-8); the truncation
    // still left at 1e-12 then shows in D. A DP5 that ignores the tolerance has D = 0
    // and err(1e-12) = err(1e-10): it fails wherever err(1e-10) > G/0.9 (default scene:
    // 7.2e-8 against G = 1.6e-9); so does a reference off by more than G.
    // The 1e-11 middle point is reported, not ordered (--bias 0.9: 9.8e-11, 1.3e-9,
    // 5.4e-11).
    let holds = if doc.tightening_helps {
        rel(d12) <= rel(d10) / 10.0 + floor + next_decade // formula: err(1e-12) <= err(1e-10)/10 + G + D
    } else {
        rel(d12).min(rel(d11)) >= rel(d10) + floor
    };
    Claim::draft(
        Check::Convergence,
        "reference-convergence-study",
        "numerics",
        "Integrated Dormand-Prince approaches the reference as the tolerance tightens: err(1e-12) <= err(1e-10)/10 + G + |d(1e-12) - d(1e-13)|/|d|: two decades of tolerance buy at least one decade of accuracy (a 5(4) pair under local error control: 100^(5/6) = 46), down to the runs' own floor: their rounding, G = (R(1e-12) + R_ref + (R(1e-10) + R_ref)/10)/|d| with R each run's rounding budget (unit roundoff × evaluations × state scale, event times × velocity jump), and the change one more decade makes (err(1e-10) can land on a cancellation of event terms of both signs)",
    )
    .exact(true, holds)
}

/// What the block's data supports for the first-order methods: an envelope
/// e(h) <= 2 e(h0) (h/h0)^p over the whole ladder (h0 = T/20), with p = 1. A method of
/// order 0 (no convergence) or 1/2 fails it over the ladder's range of h (a factor 64
/// in quick mode, 256 and more in full); order 2 fails it too (tested). The observed
/// slopes are reported, not claimed as orders (the signed error changes sign with h).
fn first_order_envelopes(doc: &Statements, ev: &Evidence) -> Vec<Claim> {
    [
        ("euler-located", "Explicit Euler with located events"),
        ("moreau-jean", "Moreau-Jean"),
    ]
    .into_iter()
    .map(|(label, name)| {
        let (worst, n) = envelope(&ev.block.order_points, label, doc.first_order);
        Claim::draft(
            Check::Convergence,
            &format!("{label}-order"),
            "numerics",
            &format!("{name} converges on the block drift of the default scene (Γ = 2.5, b = 0.05, μ = 0.4) at least at first order: every error of the ladder is below 2 e(h0) (h/h0)^1, h0 = T/20 (computed: the largest ratio e(h) / (e(h0) (h/h0))). A lower bound only: the signed error changes sign and course with h on this observable (chapter 7's text), so no order is fitted here; the orders are fitted on the stick."),
        )
        .values(format!("<= 2 ({n} step sizes)"), worst, "factor 2 on a first-order envelope")
        .confirmed_if(n >= 3 && worst <= 2.0)
    })
    .collect()
}

/// Does the unlocated run stall at the tightest tolerance (over 100 times the located
/// error, or broken down)? "100 times" is the statement's own margin (two decades; the
/// measured ratio is 10^7 on the block, 10^9 on the stick). A located error below the
/// noise of its measurement, `noise_rel` (the runs' rounding budgets and the
/// reference's error bound, relative), is no error to compare with: it counts as that
/// noise, so that a lucky cancellation cannot make a small unlocated error look large.
fn stalls(points: &[WpPoint], tight: f64, noise_rel: f64) -> bool {
    let (loc, unloc) = dopri5_errors_at(points, tight);
    unloc.is_nan() || unloc > 100.0 * loc.max(noise_rel) // formula: stall iff e_unloc > 100 max(e_loc, noise)
}

/// The noise of a located error on the block drift (relative): the largest rounding
/// budget of the integrated Dormand-Prince runs plus the reference's (`budget.rs`),
/// over the drift.
fn block_noise_rel(ev: &Evidence) -> f64 {
    let b = &ev.block;
    let r_run = b.dopri5_rounding_mps.iter().fold(0.0f64, |m, &r| m.max(r));
    (r_run + b.reference_rounding_mps) / b.reference.value.abs() // formula: n = (max R + R_ref)/|d|
}

/// The stick reference's error bound (m/s): its truncation, at most c^2 that of the run
/// at 1e-11 (`stick_reference`), plus its rounding budget R(1e-13).
fn stick_reference_error_mps(ev: &Evidence) -> f64 {
    let st = &ev.stick;
    let (d11, d12) = st.dopri5_11_12;
    let [r11, r12, r13] = st.rounding_11_12_13_mps;
    let (_, truncation) = adaptive_error_bound((d11, r11), (d12, r12));
    DECADE_CONTRACTION * DECADE_CONTRACTION * truncation + r13 // formula: |e_ref| <= c^2 |T(1e-11)| + R(1e-13)
}

/// The noise of the measured error of the stick ladder's point `p` (relative): its own
/// rounding budget (`budget.rs`, its right-hand sides and the reference's events) plus
/// the reference's error bound, over the reference.
fn stick_noise_rel(ev: &Evidence, p: &WpPoint) -> f64 {
    let st = &ev.stick;
    let run = Measured {
        value: p.value,
        rhs_evals: p.cost.rhs_evals,
        steps: p.cost.steps,
        events: st.reference_events,
        completed: p.completed,
        note: "ladder point",
    };
    (rounding_mps(&run, &st.scales) + stick_reference_error_mps(ev)) / st.reference_mps.abs() // formula: n = (R_run + |e_ref|)/|v_ref|
}

/// The stick ladder's RK4 and Euler points (located) for the results: step (s), error
/// and noise (relative), and whether the error enters the order fit.
pub fn stick_order_noise_json(ev: &Evidence) -> serde_json::Value {
    let rows: Vec<serde_json::Value> = ev
        .stick
        .points
        .iter()
        .filter(|p| matches!(p.setting.label().as_str(), "rk4-located" | "euler-located"))
        .map(|p| {
            let noise = stick_noise_rel(ev, p);
            json!({"method": p.setting.label(), "h_s": p.setting.knob(), "error": p.error, "noise": noise, "above_30_noise": p.error >= ORDER_NOISE_FACTOR * noise})
        })
        .collect();
    json!(rows)
}

/// The largest noise of the stick's located runs at the tightest tolerance (relative).
fn stick_tight_noise_rel(ev: &Evidence, tight: f64) -> f64 {
    ev.stick
        .points
        .iter()
        .filter(|p| p.setting.knob() == tight && p.setting.label().starts_with("dopri5"))
        .map(|p| stick_noise_rel(ev, p))
        .fold(0.0f64, f64::max)
}

/// Without event location DP5's error on the block drift stalls.
fn unlocated_stall(doc: &Statements, ev: &Evidence) -> Claim {
    let (loc, unloc) = dopri5_errors_at(&ev.block.points, ev.block.tightest_tol);
    let noise = block_noise_rel(ev);
    Claim::draft(
        Check::Simulation,
        "unlocated-events-stall",
        "numerics",
        "Without event location Dormand-Prince's error stalls: at the tightest tolerance it is over 100 times the located error (events are taken at step ends); a located error below the noise of its measurement (the runs' rounding budgets over the drift) counts as that noise",
    )
    .exact(true, (unloc > 100.0 * loc.max(noise)) == doc.unlocated_stalls)
}

/// Each fixed-step method blows up where h/tau exceeds its stability limit on the
/// linear decay (Euler: |1 - z| < 1 -> z < 2; RK4: z < 2.785), and the limits are sharp:
/// 5 % beyond each it blows up, 5 % inside it does not (a limit stated 10 % off puts one
/// of the two on the wrong side): the measured threshold lies within 5 % of the limit.
/// DP5's error is judged against its own budget (`failures.rs`,
/// `Relaxation::error_and_budget`): each accepted step's error scale, damped by the
/// exact contraction e^(-(t_end - t_k)/tau) of the linear flow, plus rounding. Default
/// (quick, 0.3 s, 914 steps): error 2.9e-9 rad against a budget of about 4e-8 rad.
fn stiff_blowup(doc: &Statements, ev: &Evidence) -> Claim {
    let st = &ev.stiff;
    let limit = |m: Method| match m {
        Method::Euler => doc.euler_limit,
        _ => doc.rk4_limit,
    };
    let blew_at_tenth = st.outcome.fixed.iter().all(|(m, e)| {
        e.is_none_or(|e| e > 1e3) == (st.outcome.h_over_tau > limit(*m))
    });
    let sharp = st
        .thresholds
        .iter()
        .all(|&(m, (a, b))| 0.95 * limit(m) <= a && b <= 1.05 * limit(m));
    Claim::draft(
        Check::ClosedForm,
        "stiff-relaxation-explicit-blowup",
        "4 (C.3)",
        "On the flight relaxation θ' = -(k/γ)(θ - θ₀) (k/γ = 1000/s), fixed steps of T/10 blow up for Euler and RK4 (h/τ beyond 2 and 2.785) while adaptive Dormand-Prince (rtol = atol = 1e-8) stays within its own error budget of the closed form, Σ_k (atol + rtol |θ_k|) e^(-(t_end - t_k)/τ) over its accepted steps plus rounding; the limits are sharp: at 1.05 times each limit the fixed step blows up within 400 steps, at 0.95 times it does not",
    )
    .exact(true, blew_at_tenth && sharp && st.outcome.dopri5_error <= st.outcome.dopri5_budget) // formula: |θ_DP5 - θ_exact| <= Σ_k sc_k e^(-(t_end - t_k)/τ)
}

/// The driver stops when 100 events fall within 1 us or time stops advancing; the stop
/// lies within the bound the run derives for itself (`zeno_bound.rs`,
/// `event_driven_bound_s`): every landing's time, located to 256 ulps of t (δ), moves
/// the accumulation time the ball's state predicts by exactly c δ (c = (1 + e)/(1 - e)),
/// and the flights after the stop sum to a closed form of the guard's window.
fn zeno_ball(doc: &Statements, ev: &Evidence) -> Claim {
    let z = &ev.zeno.outcome;
    let tol = z.ball_zeno_bound_s; // formula: |t_stop - t_inf| <= N_landings |ΔP|_max + tail + γ_8 t_inf
    Claim::draft(
        Check::ClosedForm,
        "zeno-ball-stops-at-accumulation",
        "numerics",
        "The event-driven driver stops a ball bouncing with 0 < e < 1 (dropped from 1 m) with a Zeno outcome at the accumulation time t_inf = t1 (1 + e)/(1 - e), within the bound of the run itself: c δ per landing (δ = 256 ulps of t, the event time's rounding; c = (1 + e)/(1 - e)), plus the flights after the stop (s)",
    )
    .close(doc.zeno_factor * z.ball_t_inf_s, z.ball_zeno_at_s.unwrap_or(f64::NAN), tol)
}

/// Moreau-Jean at h = 1 ms against the closed-form t_inf, within the bound derived for
/// the scheme as implemented (`zeno_bound.rs`, chapter 7's "How far Moreau-Jean's rest
/// lies from t_inf"): each impact step moves the invariant P = t + v/g + c U/g, which
/// every exact flight keeps at t_inf, by a closed-form envelope of its impact speed;
/// summed over the impact speeds' envelope, plus the rest step (at most h).
fn zeno_ball_mj(doc: &Statements, ev: &Evidence) -> Claim {
    let z = &ev.zeno.outcome;
    let tol = z.ball_mj_rest_bound_s; // formula: |t_rest - t_inf| <= h max(-sum low, sum high + 1) + rounding
    Claim::draft(
        Check::ClosedForm,
        "zeno-ball-moreau-jean-rest",
        "numerics",
        "Moreau-Jean (h = 1 ms) passes through the same accumulation and keeps the ball at rest from t_inf on, within a bound derived from its discrete bounce map: h times the sum, over the impact steps, of each step's largest shift of the accumulation time the ball's state predicts (a closed form of the impact speed), plus one step for the rest detection (s)",
    )
    .close(doc.zeno_factor * z.ball_t_inf_s, z.ball_mj_rest_s, tol)
}

/// On the chattering plate Moreau-Jean (first order in h) and the event-driven run with
/// the sticking transition (first order in its threshold v_r: every chattering sequence
/// loses the flights after its last rebound above v_r, a time proportional to v_r) agree
/// within the sum of their error estimates, each from runs of its own (`budget.rs`):
/// Moreau-Jean's |D_0| + 2 |D_1| from h, h/2, h/4 and the threshold's (10/9) |d(v_r) -
/// d(v_r/10)|, the sum doubled (an asymptotic estimate is trusted to a factor 2, as the
/// block's first-order envelopes; the stick's gap/estimate has Richardson's range).
/// Relative to the event-driven drift. Measured on the default quick scene: 1.35e-3
/// against 3.6e-3 (Moreau-Jean's estimate 1.8e-3 relative, doubled; its gap 1.35e-3).
fn zeno_plate(doc: &Statements, ev: &Evidence) -> Claim {
    let z = &ev.zeno.outcome;
    let d_st = z.drift_sticking_mps;
    let diff = ((z.drift_mj_mps - doc.zeno_plate_factor * d_st) / d_st).abs();
    let (half, quarter) = z.drift_mj_half_quarter_mps;
    let mj_error = first_order_error((z.drift_mj_mps, half, quarter));
    let threshold_error = (d_st - z.drift_sticking_tenth_mps).abs() * 10.0 / 9.0; // formula: e(v_r) ~ |d(v_r) - d(v_r/10)| 10/9 (first order)
    let tol = 2.0 * (mj_error + threshold_error) / d_st.abs(); // formula: |d_MJ - d_ED| <= 2 (e_MJ + e_ED)
    Claim::draft(
        Check::SecondMethod,
        "zeno-plate-resolved-two-ways",
        "3.1.2",
        "On the chattering plate (Γ = 1.2), the sticking transition (event-driven) and Moreau-Jean give the same drift (relative difference) within twice the sum of their own error estimates: Moreau-Jean's |d(h) - d(h/2)| + 2 |d(h/2) - d(h/4)| (first order in h from h/2 on) and the sticking threshold's (10/9) |d(v_r) - d(v_r/10)| (first order in v_r = 0.1 mm/s)",
    )
    .close(0.0, diff, tol)
}

/// The stick's flows are smooth between events located to ulps: DP5's global error at
/// 1e-11 is bounded from the runs at 1e-11 and 1e-12 (`budget.rs`), the reference's
/// (1e-13) by c^2 times its truncation part: |d(tau) - d(1e-13)| is at most
/// (1 + c^2) |T(1e-11)| plus max(R(1e-11), R(1e-12)) plus R(1e-13) for tau = 1e-11 and
/// 1e-12 (c < 1 makes the 1e-12 run's share the smaller). The check bites on the contraction: d(1e-12) must lie
/// within about 0.6 |d(1e-11) - d(1e-12)| of the reference, plus rounding.
fn stick_reference(doc: &Statements, ev: &Evidence) -> Claim {
    let st = &ev.stick;
    let reference = st.reference_mps * (1.0 + doc.reference_offset_rel);
    let rel = |v: f64| ((v - reference) / reference).abs();
    let (d11, d12) = st.dopri5_11_12;
    let [r11, r12, r13] = st.rounding_11_12_13_mps;
    let (_, truncation) = adaptive_error_bound((d11, r11), (d12, r12));
    let c2 = DECADE_CONTRACTION * DECADE_CONTRACTION;
    let tol_mps = (1.0 + c2) * truncation + r11.max(r12) + r13; // formula: |d(tau) - d_ref| <= (1 + c^2) |T(1e-11)| + max R + R(1e-13)
    Claim::draft(
        Check::Convergence,
        "stick-reference-converged",
        "4, 5",
        "The stick's mean speed at rtol = atol = 1e-13 (the reference) agrees with the runs at 1e-11 and 1e-12 (largest relative difference) within the bound of the runs themselves: (1 + c²) K (|d(1e-11) - d(1e-12)| + R(1e-11) + R(1e-12)) + max R + R(1e-13), c = 10^(-1/2) the assumed contraction per decade of tolerance, K = 1/(1 - c), R each run's rounding budget",
    )
    .close(0.0, rel(d11).max(rel(d12)), tol_mps / reference.abs())
}

/// A point's error enters an order fit when it is at least this many times its noise
/// (`stick_noise_rel`): then ln(error) lies within ln(1/(1 - 1/30)) = 0.034 of the
/// ln of the truncation error, and the least-squares slope, a weighted mean of the
/// consecutive slopes, moves by at most 2 x 0.034/ln 2 = 0.098 for rungs at least a
/// factor 2 apart: under a quarter of RK4's band 0.4 and a third of Euler's 0.3.
pub const ORDER_NOISE_FACTOR: f64 = 30.0;

/// The order of `label` on the stick's ladder over the points with step at most `h_max`
/// whose error is at least [`ORDER_NOISE_FACTOR`] times its noise.
fn stick_observed(ev: &Evidence, label: &str, h_max: f64) -> f64 {
    crate::ladder::observed_order(&ev.stick.points, Solver::knob, |p| {
        p.setting.label() == label
            && p.completed
            && p.setting.knob() <= h_max
            && p.error >= ORDER_NOISE_FACTOR * stick_noise_rel(ev, p) // formula: e >= 30 n
    })
}

/// RK4's order over every step whose error is at least 30 times its noise (already
/// asymptotic at T/32: the error falls 16-fold per halving).
pub fn stick_rk4_observed(ev: &Evidence) -> f64 {
    stick_observed(ev, "rk4-located", f64::INFINITY)
}

/// Euler's order over h <= T/128 (at T/32 and T/64 the error has not yet begun to
/// halve: 8.6e-4 and 9.0e-4 in the full ladder), errors at least 30 times their noise.
pub fn stick_euler_observed(ev: &Evidence) -> f64 {
    let h_asym = ev.stick.period_s / 128.0 * (1.0 + 1e-9);
    stick_observed(ev, "euler-located", h_asym)
}

/// RK4's order with located events, |p - 4| <= 0.4 (the neighbouring orders fail).
fn stick_rk4_order(doc: &Statements, ev: &Evidence) -> Claim {
    let range = "every step whose error is at least 30 times its noise, the run's rounding budget plus the reference's error bound";
    order_claim("stick-rk4-located-order", "RK4", doc.rk4_order, stick_rk4_observed(ev), 0.4, range)
}

/// Euler's order with located events, |p - 1| <= 0.3.
fn stick_euler_order(doc: &Statements, ev: &Evidence) -> Claim {
    let observed = stick_euler_observed(ev);
    let range = "h <= T/128, errors at least 30 times their noise";
    order_claim("stick-euler-located-order", "Explicit Euler", doc.euler_order, observed, 0.3, range)
}

/// An order claim: the fitted slope `observed` within `band` of the order `order`.
fn order_claim(id: &str, name: &str, order: f64, observed: f64, band: f64, range: &str) -> Claim {
    Claim::draft(
        Check::Convergence,
        id,
        "4, 5",
        &format!("{name} with located events converges at order {order} on the stick's mean speed (authors' scene): least-squares slope of log error against log step over the asymptotic range ({range}); band +-{band}, which the neighbouring orders fail"),
    )
    .values(order, observed, band).confirmed_if((observed - order).abs() <= band)
}

/// Without event location DP5's error on the stick stalls (or the run breaks down).
fn stick_unlocated_stall(doc: &Statements, ev: &Evidence) -> Claim {
    let tight = *ev.stick.tols.last().expect("tolerances");
    Claim::draft(
        Check::Simulation,
        "stick-unlocated-events-stall",
        "4, 5",
        "Without event location Dormand-Prince's error on the stick's mean speed stalls: at the tightest tolerance it is over 100 times the located error (or its noise: the run's rounding budget plus the reference's error bound, if larger), or the run breaks down",
    )
    .exact(
        true,
        stalls(&ev.stick.points, tight, stick_tight_noise_rel(ev, tight)) == doc.unlocated_stalls,
    )
}

/// The stick chapter's choice of DOP853: at rtol 1e-10 both pairs must land within 1e-9
/// of the DP5 reference at 1e-13 (an independent method: DOP853 shares no stage with
/// it), and DOP853 must do so with fewer right-hand sides; on the authors' scene at
/// g = 10 m/s^2 whatever --g-mps2.
fn stick_dop853(doc: &Statements, ev: &Evidence) -> Claim {
    let ((e5, e8), (n5, n8)) = ev.stick.dop853_vs_dopri5;
    let cycles = ev.stick.cycles;
    let cheaper = if doc.dop853_cheaper { n8 < n5 } else { n5 < n8 };
    Claim::draft(
        Check::SecondMethod,
        "stick-dop853-cheaper-at-1e-10",
        "4, 5",
        &format!("On the authors' scene (main_rod.m of toshankarghosh/toothpicks) with g = {AUTHORS_G_MPS2} m/s² and {cycles} drive cycles from the static angle, and on it only (measured on this scene whatever --g-mps2): at rtol = atol = 1e-10 Dormand-Prince 8(5,3) reaches the stick's mean speed within 1e-9 of the reference with fewer right-hand-side evaluations than Dormand-Prince 5(4) (the stick chapter's default integrator rests on this)"),
    )
    .exact(true, e5 <= 1e-9 && e8 <= 1e-9 && cheaper)
}

/// Every run of the missed-event ladder has the reference's phase sequence, with the
/// event search the statements name.
fn missed_event(doc: &Statements, ev: &Evidence) -> Claim {
    let search = if doc.certified_search {
        "certified"
    } else {
        "uncertified"
    };
    Claim::draft(
        Check::SecondMethod,
        "stick-no-missed-event",
        "4, 5",
        &format!(
            "With the {search} event search, both Dormand-Prince pairs at every rtol from 1e-8 to 1e-12 give the phase sequence of the reference (DP5 at 1e-13, certified) on the authors' stick at g = 9.81 m/s² over 0.4 s, whose ninth hop starts with a lift-off shorter than one step; the computed value lists the runs that differ"
        ),
    )
    .exact(json!([]), json!(ev.missed.differing(doc.certified_search)))
}

/// Checked inside the limit it names, whatever the flags: Gamma = 2.5 (a period-one
/// sticking orbit) and b = 1/80. The flight map neglects the slip before takeoff, whose
/// share of the drift it predicts in closed form (`economy.rs`,
/// `flight_map_predicted_rel`): -b/(omega t_f sqrt(Gamma^2 - 1)), -1.013e-3 here (and
/// -0.35 %, -0.89 %, -0.27 % at b = 0.05 and Gamma = 2.7, 1.7, 3.2, as the sweep
/// measures). The prediction neglects terms O(b) and O(b/sqrt(Gamma^2 - 1)) of itself
/// (1.25 % and 0.55 % here); the claim grants half of it (factor 0.5, stated): the map
/// is explained when its error lies within |pred|/2 of pred. Measured: -1.0113e-3,
/// 1.5e-6 from the prediction against 5.1e-4. A law off by 10 % errs by 0.1.
fn flight_map(doc: &Statements, ev: &Evidence) -> Claim {
    let (exact, map) = ev.economy.limit;
    let err = map.map_or(f64::NAN, |m| (doc.flight_map_factor * m - exact) / exact);
    let pred = ev.economy.limit_predicted_rel;
    let tol = 0.5 * pred.abs(); // formula: |err - pred| <= |pred|/2
    Claim::draft(
        Check::SecondMethod,
        "flight-map-economy",
        "3.1.2",
        "Approximation: the flight-map law v_ave = b μ g t_f²/(2 n T) (sticking landings, no slip before takeoff) reproduces the exact drift in the limit b << 1 of period-n sticking orbits, up to the slip before takeoff it neglects, whose share of the drift is -b/(ω t_f sqrt(Γ² - 1)) (derived in chapter 7's text); at Γ = 2.5, b = 1/80 the signed relative error lies within half that prediction of it",
    )
    .values(pred, err, tol).approximation_if((err - pred).abs() <= tol)
}

/// Checked inside the limit it names, whatever the flags: K = 100 and b = 0.05. The
/// viscous law is the arcsin law V sin(x), x = pi b/2, linearised: exactly x/sin(x)
/// times it, a relative error x/sin(x) - 1 (~ b^2 pi^2/24 = 1.029e-3 at b = 0.05); the
/// arcsin law itself neglects the block's velocity fluctuation, relative size a/K^2
/// with a measured 1.24 at K = 100 (and 1.2 to 1.4 over K = 12 .. 60 in the sweep). So
/// err = (x/sin x)(1 + a/K^2) - 1: the claim expects x/sin(x) - 1 and grants the
/// fluctuation up to 2/K^2 (a <= 2, stated), times x/sin(x). Measured: 1.153e-3
/// against 1.029e-3 +- 2.0e-4. A coefficient off by 10 % errs by 0.09.
fn viscous_law(doc: &Statements, ev: &Evidence) -> Claim {
    let (exact, viscous) = ev.horizontal.limit;
    let err = (viscous / doc.viscous_factor - exact) / exact; // formula: v = F/c, c scaled by the statement's factor
    let (k, b) = HORIZONTAL_LIMIT;
    let x = std::f64::consts::PI * b / 2.0; // formula: x = pi b/2
    let lin = x / x.sin(); // formula: viscous/arcsin = x/sin(x)
    let tol = lin * 2.0 / (k * k); // formula: |err - (x/sin x - 1)| <= (x/sin x) 2/K^2
    Claim::draft(
        Check::SecondMethod,
        "viscous-law-economy",
        "3.1.1",
        "Approximation: under horizontal dither the effective viscous law F = c v, c = 2 μ m g/(π V), reproduces the exact drift in the limit Γₓ = δₓ ω²/(μ g) >> 1 and small bias up to its linearisation of the arcsin law, a relative error x/sin(x) - 1 with x = π b/2, and the block's velocity fluctuation it neglects, granted up to 2/Γₓ² (times x/sin x); at Γₓ = 100, b = 0.05 (signed relative error)",
    )
    .values(lin - 1.0, err, tol).approximation_if((err - (lin - 1.0)).abs() <= tol)
}

/// The claims on the stick by three methods (the self-locking scene), with the order
/// the statements assert (`mj_order`: 1).
pub fn stick_methods(s: &SceneMethods, mj_order: f64) -> Vec<Claim> {
    let mj = s.ladder("moreau_jean");
    vec![
        // Moreau-Jean is first order (derivation in the chapter); the fit over the
        // ladder scatters by the event-phase term (measured 0.99 to 1.01 over T/2000 ..
        // T/8000): +-0.3 as for the block's first-order methods.
        Claim::draft(
            Check::Convergence,
            "stick-methods-moreau-jean-order",
            "4, 5",
            "Moreau-Jean time-stepping of the stick (the massless rod's balance implicit over each step) converges to the event-driven mean speed at order 1 in the step h (least-squares slope over the ladder)",
        )
        .close(mj_order, fitted_order(mj), MJ_ORDER_BAND),
        // The finest rung's gap from the reference against its own Richardson estimate,
        // with the order claim's band 0.3 as the range of the true local order.
        richardson_claim(
            "stick-methods-moreau-jean-gap-within-estimate",
            "Moreau-Jean's gap from the event-driven speed at its finest step equals its own Richardson error estimate |v_h - v_2h| / (2^p - 1), p = 1",
            gap_over_estimate(mj, s.reference_mps, mj_order),
            mj_order,
            MJ_ORDER_BAND,
        ),
    ]
}

/// The band of Moreau-Jean's fitted order (see `stick_methods`).
const MJ_ORDER_BAND: f64 = 0.3;

/// The band of soft contact's fitted order (see `soft_contact`).
const SOFT_ORDER_BAND: f64 = 0.25;

/// The range of the gap over its Richardson estimate for an estimate of order `p` when
/// the error's true local order over the last two rungs (a factor 2 apart) is p' in
/// [p - band, p + band]: with e = C h^p', |v_h - v_2h| = (2^p' - 1) |e(h)|, so the
/// ratio is (2^p - 1)/(2^p' - 1), between (2^p - 1)/(2^(p+band) - 1) and
/// (2^p - 1)/(2^(p-band) - 1) (Richardson's own theory). For p = 1: [0.684, 1.601] at
/// band 0.3, [0.726, 1.466] at 0.25. An estimate of the wrong order (2: the ratio times
/// 3) leaves its own range [0.76, 1.33].
pub fn richardson_range(p: f64, band: f64) -> (f64, f64) {
    let q = 2f64.powf(p) - 1.0;
    (q / (2f64.powf(p + band) - 1.0), q / (2f64.powf(p - band) - 1.0)) // formula: ratio in [(2^p - 1)/(2^(p+B) - 1), (2^p - 1)/(2^(p-B) - 1)]
}

/// A claim that the finest gap equals its Richardson estimate of order `p`: the ratio
/// `ratio` within [`richardson_range`] of the order band `band`.
fn richardson_claim(id: &str, statement: &str, ratio: f64, p: f64, band: f64) -> Claim {
    let (lo, hi) = richardson_range(p, band);
    Claim::draft(
        Check::Convergence,
        id,
        "4, 5",
        &format!("{statement} (ratio; range (2^p - 1)/(2^p' - 1) for a true local order p' within the order claim's band ±{band} of p)"),
    )
    .values(1.0, ratio, format!("[{lo:.3}, {hi:.3}]"))
    .confirmed_if((lo..=hi).contains(&ratio))
}

/// The soft-contact claims on scene `s`, asserting the order `order` (1; a mutation
/// passes another).
pub fn soft_contact(s: &SceneMethods, order: f64) -> Vec<Claim> {
    let range = asymptotic_range(s.ladder("soft_contact"), s.reference_mps);
    // A fit needs three rungs (two local orders that agree); fewer: NaN, failed.
    let fitted = if range.rungs.len() >= 3 {
        fitted_order(&range)
    } else {
        f64::NAN
    };
    vec![
        // Tolerance: the fitted order is 1 + (r - 1) phi for an error A ε + B ε^r with
        // the friction term's share phi (measured <= 0.25 of the error over the range:
        // the friction part is what stays after the normal part 0.0207 ε measured with
        // v_eps = 1e-6 m/s) and r - 1 <= 0.6 (its local orders in v_eps, <= 0.8, doubled
        // by v_eps ∝ ε², minus 1): 0.15, plus the range's own spread of local orders
        // 0.1: ±0.25. Order 2 is off by 0.9; the first family (v_eps ∝ ε) gives 0.4.
        Claim::draft(
            Check::Convergence,
            "soft-contact-order",
            "4, 5",
            "Soft contact (normal spring k_n = m/(ε τ₀²) and damper c_n = m/(ε τ₀), friction μ F_z tanh(ẋ_C/v_ε) with v_ε = v₀ ε²) converges to the event-driven mean speed at order 1 in ε (least-squares slope over the asymptotic range: the finest rungs whose local orders agree within 0.15)",
        )
        .close(order, fitted, SOFT_ORDER_BAND),
        // Ratio 1 in the asymptotic range; a true local order within the order band
        // gives the range of `richardson_range` (an assumed order 2 divides the
        // estimate by 3).
        richardson_claim(
            "soft-contact-richardson-gap",
            "Soft contact's gap from the event-driven speed at its finest ε equals its own Richardson error estimate |v_ε - v_2ε| / (2^p - 1), p = 1",
            gap_over_estimate(&range, s.reference_mps, order),
            order,
            SOFT_ORDER_BAND,
        ),
    ]
}
