//! The claims of section 3.2: pure functions of the document's statements
//! ([`Statements`]) and the chapter's runs ([`Evidence`]): the closed forms of
//! `physics::sawtooth` against the event-driven simulation of `physics::block`.

use super::evidence::{Evidence, EPS_CHECK, GAMMA_CHECK};
use super::statements::Statements;
use crate::physics::plate::PlateMotion;
use crate::physics::sawtooth::Regime;
use crate::report::{fmt_num, is_close, Check, Claim};

/// Every claim of the chapter, in the report's order.
pub fn all(doc: &Statements, ev: &Evidence) -> Vec<Claim> {
    let mut out = vec![
        linear_no_drift(doc, ev),
        linear_average_force(doc, ev),
        nonlinear_changes(doc, ev),
        drift_closed_form(doc, ev),
        drift_regime(doc, ev),
        lock_time(doc, ev),
        mirror_reverses(doc, ev),
        stroke_inequalities(doc, ev),
        drift_direction(doc, ev),
    ];
    out.extend(slip_impulse(doc, ev));
    out.extend([
        reaches_slow_speed(doc, ev),
        locomotion_needs_slip(doc, ev),
        biharmonic_always_slipping(doc, ev),
        biharmonic_stuck(doc, ev),
        window_length_not_ratio(doc, ev),
    ]);
    out
}

/// Linear friction: no drift on any zero-mean drive.
pub fn linear_no_drift(doc: &Statements, ev: &Evidence) -> Claim {
    let lin = &ev.linear.drifts_mps;
    let worst = lin.iter().fold(0.0f64, |m, v| {
        if v.is_nan() || m.is_nan() {
            f64::NAN
        } else {
            m.max(v.abs())
        }
    }); // NaN propagates
    Claim::draft(
        Check::Simulation,
        "linear-no-drift",
        "3.2.1",
        &format!("With linear friction F = -c v_rel the mean velocity of the block equals the plate's (zero) whatever the asymmetry of the shaking. Largest |mean velocity| over {} drives (sawtooth, its mirror, bi-harmonic ε = 0 and 0.3, sine), DP5 after the transient.", lin.len()),
    )
    .close(doc.linear_drift_fraction * ev.vb_mps, worst, ev.tol.lin_mps)
}

/// The averaged linear law: the identity inside the transient (a consistency check).
pub fn linear_average_force(doc: &Statements, ev: &Evidence) -> Claim {
    let early = &ev.linear.early;
    let (v0, v1) = early.v_window_mps;
    let span = 2.0 * ev.scene.saw.period_s();
    let identity = -(v1 - v0) / (ev.scene.c_per_s * span); // formula: <v> - <v_p> = -(v(t1) - v(t0))/(c (t1 - t0))
    Claim::draft(
        Check::Consistency,
        "linear-average-force",
        "3.2.1",
        "0 = F_ave = -c (v_obj_ave - v_sup_ave): over any window the mean friction force is -c times the mean relative velocity, so <v> = <v_p> - (v(t1) - v(t0))/(c (t1 - t0)); checked over the first two periods from rest (still in the transient). Consistency check: the identity is the integral of the model's own linear-friction equation m v' = -c (v - v_p); no document could fail it here, so it is not counted as confirmation.",
    )
    .close(identity / doc.linear_force_factor, early.mean_velocity_mps, ev.tol.lin_mps)
}

/// A non-linear law changes the result: the Coulomb block drifts.
pub fn nonlinear_changes(doc: &Statements, ev: &Evidence) -> Claim {
    let v_dir = ev.direction_mps.0;
    let tol_v = ev.tol.v_mps;
    Claim::draft(
        Check::Simulation,
        "nonlinear-law-changes-result",
        "3.2.1",
        "A non-linear friction law changes this result: with Coulomb friction on the same sawtooth the block drifts (default scene).",
    )
    .values(
        if doc.nonlinear_changes { "nonzero drift" } else { "zero drift" },
        v_dir,
        tol_v,
    )
    .confirmed_if((v_dir.abs() > 1e3 * tol_v) == doc.nonlinear_changes)
}

/// The closed-form drift against the simulation.
pub fn drift_closed_form(doc: &Statements, ev: &Evidence) -> Claim {
    let (saw, k) = (ev.scene.saw, ev.scene.k_mps2());
    let drift_doc = if ev.regime != Regime::StickBoth {
        let (tf, t) = (saw.fast_duration_s(), saw.period_s());
        saw.slow_velocity_mps - doc.drift_factor * k * tf * tf / t // formula: v_d = v_slow - mu g t_fast^2/T
    } else {
        0.0
    };
    Claim::draft(
        Check::Simulation,
        "drift-closed-form",
        "3.2.2",
        &format!("Steady drift of the Coulomb block: v_d = v_slow - μ g t_fast² / T if μ g t_fast < v_slow + v_fast, else 0 (workbook's closed form; regime {}), against the event-driven simulation over {} periods after the first stick.", ev.regime.label(), ev.measured),
    )
    .close(drift_doc, ev.main.mean_velocity_mps, ev.tol.v_mps)
}

/// The closed-form steady regime against the simulated one, on the scene and 5 % on
/// either side of the threshold (a threshold 10 % off either way mislabels one side).
pub fn drift_regime(doc: &Statements, ev: &Evidence) -> Claim {
    let saw = ev.scene.saw;
    let (a, b) = (saw.slow_velocity_mps, saw.fast_velocity_mps);
    let ratio = ev.scene.k_mps2() * saw.fast_duration_s() / (a + b); // formula: mu g t_fast/(v_slow + v_fast)
    let predicted = |r: f64| {
        let both = r >= doc.regime_threshold; // formula: stick in both iff mu g t_fast >= v_slow + v_fast
        if both != doc.regime_reversed {
            Regime::StickBoth
        } else {
            Regime::StickSlow
        }
    };
    let simulated = |stuck_back: bool| {
        if stuck_back {
            Regime::StickBoth
        } else {
            Regime::StickSlow
        }
    };
    let s = ev.slip_sides;
    let labels = |r: [Regime; 3]| r.map(Regime::label).join(", ");
    let expected = labels([
        predicted(ratio),
        predicted(0.95 * s.threshold),
        predicted(1.05 * s.threshold),
    ]);
    let computed = labels([
        simulated(ev.main.stuck_in_backward_stroke),
        simulated(s.stuck_back.0),
        simulated(s.stuck_back.1),
    ]);
    Claim::draft(
        Check::Simulation,
        "drift-regime",
        "3.2.2",
        &format!("Steady regime from the closed form (μ g t_fast >= v_slow + v_fast: stick in both strokes) equals the simulated one (does the block stick while the plate moves back?), on the scene (μ g t_fast = {ratio:.3} (v_slow + v_fast)) and at 0.95 and 1.05 (v_slow + v_fast) with the same speeds (a threshold 10 % off either way mislabels one of them)."),
    )
    .exact(expected.as_str(), computed.as_str())
}

/// The closed-form lock time against the simulated first stick.
pub fn lock_time(doc: &Statements, ev: &Evidence) -> Claim {
    Claim::draft(
        Check::Simulation,
        "lock-time",
        "3.2.2",
        "A block started at rest slips until it first reaches the slow speed: t* = n T + (v_slow - v_n)/(μ g), v_n = n μ g (t_slow - t_fast) (workbook's closed form), against the first stick of the simulation.",
    )
    .close(
        doc.lock_factor * ev.lock_time_s,
        ev.main.first_stick_s.unwrap_or(f64::NAN),
        ev.tol.t_s,
    )
}

/// Mirroring the drive reverses the drift.
pub fn mirror_reverses(doc: &Statements, ev: &Evidence) -> Claim {
    Claim::draft(
        Check::Simulation,
        "mirror-reverses",
        "3.2.2",
        "Mirroring the drive (slow stroke towards -x) reverses the drift: v_d(mirror) = -v_d.",
    )
    .close(
        doc.mirror_sign * ev.main.mean_velocity_mps,
        ev.mirrored_mps,
        ev.tol.v_mps,
    )
}

/// The printed stroke inequalities (an erratum): both readings are judged.
pub fn stroke_inequalities(doc: &Statements, ev: &Evidence) -> Claim {
    // Printed reading: left stroke fast and short (v_l > v_r, t_r > t_l): our sawtooth
    // with +x = right. Corrected reading: slow, long stroke to the left: the mirror.
    // With the corrected inequalities printed (a wrong variant of the printed text),
    // the "printed" reading is the slow stroke to the left: the mirror.
    let (v_dir, v_dir_mirror) = ev.direction_mps;
    let (printed_v, corrected_v) = if doc.printed_fast_left {
        (v_dir, v_dir_mirror)
    } else {
        (v_dir_mirror, v_dir)
    };
    let printed_goes_right = printed_v > 0.0;
    let corrected_goes_left = corrected_v < 0.0;
    let side = |right: bool| if right { "right" } else { "left" };
    Claim::draft(
        Check::Simulation,
        "stroke-inequalities",
        "3.2.2",
        "As printed: the plate moves at v_r to the right and at a 'smaller velocity v_l > v_r to the left, acting for a longer period', with t_r > t_l and v_r t_r = v_l t_l; then the impulse μ m g (t_l - t_r) is negative and the block drifts right, not left. Correct: v_l < v_r and t_l > t_r (the slow stroke is the long one). Check: the printed reading (fast stroke left) drifts right, the corrected one (slow stroke left) drifts left.",
    )
    .values(
        "printed: right; corrected: left",
        format!(
            "printed: {}; corrected: {}",
            side(printed_goes_right),
            side(!corrected_goes_left)
        ),
        "sign",
    )
    .printed_or_corrected(printed_v < 0.0, corrected_goes_left)
}

/// The bias runs along the slow, long stroke.
pub fn drift_direction(doc: &Statements, ev: &Evidence) -> Claim {
    let (v_dir, v_dir_mirror) = ev.direction_mps;
    Claim::draft(
        Check::Simulation,
        "drift-direction",
        "3.2.2",
        "With the corrected labels, asymmetries lead to a bias to the left: along the slow, long stroke (friction on a slower block points along the plate's velocity and acts longer in the slow stroke). Check: slow stroke +x drifts +x, slow stroke -x drifts -x.",
    )
    .values(
        "along the slow stroke",
        format!("slow +x: {}; slow -x: {}", fmt_num(v_dir), fmt_num(v_dir_mirror)),
        ev.tol.v_mps,
    )
    .confirmed_if((v_dir > 0.0 && v_dir_mirror < 0.0) == doc.along_slow_stroke)
}

/// The net friction impulse of an always-slipping period (when the scene has one).
pub fn slip_impulse(doc: &Statements, ev: &Evidence) -> Option<Claim> {
    let (j_closed, probe) = ev.slip_probe.as_ref()?;
    let dv = probe.v_window_mps.1 - probe.v_window_mps.0;
    let j = doc.impulse_factor * j_closed;
    let tol_v = ev.tol.v_mps;
    Some(
        Claim::draft(
            Check::Simulation,
            "slip-impulse",
            "3.2.2",
            "So long as the block is slower than the slow stroke it slips against the plate's motion at every instant, and the net friction impulse per period is J = μ m g (t_l - t_r) along the slow stroke (t_l, t_r: slow and fast durations with the corrected labels). Check: J/m = change of the block's velocity over one period started at v = (v_slow - μ g t_slow - v_fast)/2 (m/s), and the friction direction in every segment.",
        )
        .values(j, dv, tol_v)
        .confirmed_if(is_close(j, dv, tol_v) && probe.friction_along_plate),
    )
}

/// The largest steady velocity is the slow speed.
pub fn reaches_slow_speed(doc: &Statements, ev: &Evidence) -> Claim {
    Claim::draft(
        Check::Simulation,
        "reaches-slow-speed",
        "3.2.2",
        "The block is accelerated along the slow stroke until its speed reaches v_l (the slow speed, with the corrected labels) for part of a cycle: the largest steady velocity equals the slow speed.",
    )
    .close(
        doc.reach_factor * ev.scene.saw.slow_velocity_mps,
        ev.main.v_max_mps,
        ev.tol.v_mps,
    )
}

/// "Horizontal motion (locomotion) is generally (generically) induced" by asymmetric
/// shaking with Coulomb friction (3.2.1, and 3.2.2's "asymmetries in the shaking lead
/// to locomotion"): an erratum. The block drifts only while it slips; where friction
/// can carry it through both strokes (mu g t_fast >= v_slow + v_fast, an open set of
/// parameters) there is no drift at all.
pub fn locomotion_needs_slip(doc: &Statements, ev: &Evidence) -> Claim {
    let s = ev.slip_sides;
    let (tol_v, thr) = (ev.tol.v_mps, doc.slip_threshold);
    // The corrected condition (derived threshold k (v_slow + v_fast)): the drift equals
    // the closed form just below the threshold and vanishes just above it.
    let corrected = is_close(s.below_mps, s.closed_below_mps, tol_v)
        && (s.below_mps.abs() > tol_v) == (0.95 * s.threshold < thr)
        && (s.above_mps.abs() <= tol_v) == (1.05 * s.threshold >= thr);
    // As printed: a drift on both sides (generically, whatever the friction).
    let printed = if doc.generic_drift {
        s.below_mps.abs() > tol_v && s.above_mps.abs() > tol_v
    } else {
        corrected
    };
    Claim::draft(
        Check::Simulation,
        "locomotion-needs-slip",
        "3.2.1, 3.2.2",
        "As printed: with Coulomb friction, asymmetrical horizontal shaking 'generally (generically)' induces locomotion (3.2.1; 3.2.2: 'asymmetries in the shaking lead to locomotion'). Correct: only while the block slips, μ g t_fast < v_slow + v_fast (the fast stroke's speed change exceeds what friction supplies in its duration). Beyond it the block follows the plate through both strokes and there is no drift at all, on an open set of parameters (every μ g t_fast >= v_slow + v_fast): not a measure-zero exception, so 'generically' is wrong. Check at μ g t_fast = 0.95 and 1.05 (v_slow + v_fast), same speeds: the drift equals the closed form just below the threshold and vanishes just above it.",
    )
    .values(
        format!("{} and 0", fmt_num(s.closed_below_mps)),
        format!("{} and {}", fmt_num(s.below_mps), fmt_num(s.above_mps)),
        tol_v,
    )
    .printed_or_corrected(printed, corrected)
}

/// The bi-harmonic always-slipping drift against the simulation.
pub fn biharmonic_always_slipping(doc: &Statements, ev: &Evidence) -> Claim {
    let vb = ev.vb_mps;
    // The closed form with the mutable coefficient: eps V (1 - k pi^2/(2 Gamma^2)).
    let bh_corr = std::f64::consts::PI.powi(2) / (2.0 * GAMMA_CHECK * GAMMA_CHECK);
    let v_bh_doc = EPS_CHECK * vb * (1.0 - doc.biharmonic_factor * bh_corr); // formula: v_d = eps V (1 - pi^2/(2 Gamma^2))
    Claim::draft(
        Check::Simulation,
        "biharmonic-always-slipping",
        "3.2.2",
        &format!("Smooth drive v_p = V (sin ω t + ε cos 2 ω t), always slipping: v_d = ε V (1 - π²/(2 Γₓ²)), Γₓ = V ω/(μ g) (workbook's closed form; -> ε V as Γₓ -> infinity). ε = {EPS_CHECK}, Γₓ = {GAMMA_CHECK}, V = {} m/s.", fmt_num(vb)),
    )
    .close(v_bh_doc, ev.biharmonic_mps.0, ev.tol.v_mps) // closed forms, located crossings, transient decayed below 1e-13 m/s
}

/// Below Gamma_stick the block moves with the plate for good; above it, it drifts.
pub fn biharmonic_stuck(doc: &Statements, ev: &Evidence) -> Claim {
    // Judged 5 % on either side of the derived threshold: the statement's threshold
    // predicts stuck (zero drift) or moving at each; a threshold 10 % off either way
    // predicts one side wrong.
    let s = ev.stick_sides;
    let g_stick = doc.stick_gamma_factor * s.threshold;
    let tol_v = ev.tol.v_mps;
    let agrees = |gamma: f64, v: f64| (v.abs() <= tol_v) == (gamma < g_stick);
    Claim::draft(
        Check::Simulation,
        "biharmonic-stuck",
        "3.2.2",
        &format!("Below Γₓ,stick = 1/max|cos ω t - 2 ε sin 2 ω t| = {} the plate never needs more than μ g: once the block moves with it, it stays: zero drift at Γₓ = 0.95 Γₓ,stick; just above (1.05 Γₓ,stick) the block slips and drifts (ε = {EPS_CHECK}).", fmt_num(g_stick)),
    )
    .values(
        "0 and nonzero",
        format!("{} and {}", fmt_num(s.below_mps), fmt_num(s.above_mps)),
        tol_v,
    )
    .confirmed_if(
        agrees(0.95 * s.threshold, s.below_mps) && agrees(1.05 * s.threshold, s.above_mps),
    )
}

/// The plate's mean velocity over [t1, t2], twice: the closed form
/// (x(t2) - x(t1))/(t2 - t1), and the velocity integrated stroke by stroke (a second
/// method that never evaluates x). Returns (closed form, second method), m/s.
fn plate_mean_velocity_mps(saw: &crate::physics::plate::Sawtooth, t1: f64, t2: f64) -> (f64, f64) {
    let closed = (saw.x_m(t2) - saw.x_m(t1)) / (t2 - t1); // formula: mean v = (x(t2) - x(t1))/(t2 - t1)
    let (mut t, mut integral) = (t1, 0.0);
    while t < t2 {
        let next = saw.breakpoint_after(t).unwrap_or(t2).min(t2);
        integral += saw.vx_mps(t) * (next - t); // formula: the integral of a piecewise-constant velocity
        t = next;
    }
    (closed, integral / (t2 - t1))
}

/// 3.2.1: "or so that t2 is so much greater than t1 that there is a small error from
/// being a non-integer number of cycles": an erratum. The error of a window that is not
/// a whole number of periods is set by its length in periods, (t2 - t1)/T, not by the
/// ratio t2/t1: the plate's mean velocity over [t1, t2] is (x(t2) - x(t1))/(t2 - t1),
/// at most x_pp/(t2 - t1), whatever t1.
pub fn window_length_not_ratio(doc: &Statements, ev: &Evidence) -> Claim {
    let saw = ev.scene.saw;
    let (period, v_slow) = (saw.period_s(), saw.slow_velocity_mps);
    // Window A: t2 = 100 t1 (the printed condition), but only T/10 long, inside the slow
    // stroke (the long one, t_slow > T/2). Window B: t2/t1 = 1.04, but 40.25 periods long.
    let (a1, a2) = (period / 1000.0, period / 10.0);
    let (b1, b2) = (1000.0 * period, 1040.25 * period);
    let (ma, ma2) = plate_mean_velocity_mps(&saw, a1, a2);
    let (mb, mb2) = plate_mean_velocity_mps(&saw, b1, b2);
    // Both methods agree to the rounding of a time near 1000 T (a few ulps of t, times
    // the stroke speeds, over the window).
    let round = 64.0 * f64::EPSILON * b2 * (v_slow + saw.fast_velocity_mps) / (b2 - b1);
    let small = 0.05 * v_slow; // "a small error": 5 % of the slow stroke's speed
    let x_pp = v_slow * saw.slow_duration_s; // formula: peak-to-peak stroke x_pp = v_slow t_slow
    let bound_b = x_pp / (b2 - b1); // formula: |mean v| <= x_pp/(t2 - t1)
    let methods_agree = is_close(ma, ma2, round) && is_close(mb, mb2, round);
    let ratio_rule = ma.abs() <= small; // as printed: t2/t1 = 100 suffices
    let length_rule = mb.abs() <= bound_b + round && bound_b <= small && ma.abs() > small;
    let (printed, corrected) = if doc.window_ratio_condition {
        (ratio_rule && methods_agree, length_rule && methods_agree)
    } else {
        (length_rule && methods_agree, length_rule && methods_agree)
    };
    Claim::draft(
        Check::ClosedForm,
        "window-length-not-ratio",
        "3.2.1",
        "As printed: the averaging window [t1, t2] is chosen with an integer number of cycles 'or so that t2 is so much greater than t1 that there is a small error from being a non-integer number of cycles'. Correct: the error is set by the window's length in periods, not by t2/t1: the plate's mean velocity over the window is (x(t2) - x(t1))/(t2 - t1), at most x_pp/(t2 - t1) (x_pp the plate's peak-to-peak stroke), whatever t1; so the condition is t2 - t1 >> T. Check (closed form, and the velocity integrated stroke by stroke): t1 = T/1000, t2 = 100 t1 (window T/10) against t1 = 1000 T, t2 = 1.04 t1 (40.25 periods); 'small': at most 5 % of the slow stroke's speed.",
    )
    .values(
        "t2 = 100 t1: <= 0.05 v_slow",
        format!(
            "t2 = 100 t1: {} v_slow; t2 - t1 = 40.25 T: {} v_slow (bound {})",
            fmt_num(ma / v_slow),
            fmt_num(mb / v_slow),
            fmt_num(bound_b / v_slow)
        ),
        "0.05 v_slow",
    )
    .printed_or_corrected(printed, corrected)
}
