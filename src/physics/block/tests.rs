//! Unit tests of the block model against closed forms.
use super::*;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::plate::{Axis, Harmonic, Sawtooth};
use std::f64::consts::{PI, TAU};

const G: f64 = 9.81;

fn both_ways() -> [BlockOptions; 2] {
    let closed = BlockOptions {
        transient_periods: 0,
        ..BlockOptions::default()
    };
    [
        closed,
        BlockOptions {
            closed_forms: false,
            ..closed
        },
    ]
}

#[test]
fn free_slide_decelerates_at_mu_g_and_stops_at_v2_over_2_mu_g() {
    // A still plate (zero amplitude); the block starts sliding at w0. Closed form:
    // stops at t = w0/(mu g), after w0^2/(2 mu g). DP5 integrates the quadratic exactly
    // and the closed form is exact, so both agree to the event tolerance (1e-12 s).
    let plate = Harmonic::sine(Axis::X, 0.0, 1.0);
    let (mu, w0) = (0.5, 1.2);
    for opts in both_ways() {
        let opts = BlockOptions {
            start: (0.0, [0.0, w0, 0.0, 0.0]),
            ..opts
        };
        let run = simulate_block(&BlockParams::coulomb(G, mu, 0.0), &plate, 1.0, &opts);
        let stop = run
            .events
            .iter()
            .find(|e| e.kind == EventKind::SlipToStick)
            .expect("stops");
        assert!((stop.t_s - w0 / (mu * G)).abs() < 1e-12, "{}", stop.t_s);
        assert!(
            (run.y_end[0] - w0 * w0 / (2.0 * mu * G)).abs() < 1e-12,
            "{}",
            run.y_end[0]
        );
        assert_eq!(run.mode_end, BlockMode::Stick);
    }
}

#[test]
fn block_sticks_on_a_slowly_shaken_plate() {
    // Peak plate acceleration 0.5 mu g < mu g: the block rides along, no event at all,
    // and its absolute position is the plate's (u stays exactly 0).
    let (mu, f) = (0.4, 5.0);
    let amp = 0.5 * mu * G / (TAU * f).powi(2);
    let plate = Harmonic::sine(Axis::X, amp, f);
    for opts in both_ways() {
        let run = simulate_block(&BlockParams::coulomb(G, mu, 0.0), &plate, 3.0, &opts);
        assert_eq!(run.total_counts, EventCounts::default());
        assert_eq!(run.y_end[0], 0.0);
        assert!(run.mean_velocity_mps.abs() < 1e-15);
        assert_eq!(run.contact_fraction, 1.0);
    }
    // Just above the threshold it must slip.
    let plate = Harmonic::sine(Axis::X, 1.05 * amp / 0.5, f);
    let run = simulate_block(
        &BlockParams::coulomb(G, mu, 0.0),
        &plate,
        1.0,
        &BlockOptions::default(),
    );
    assert!(run.total_counts.stick_to_slip > 0);
}

#[test]
fn takeoff_phase_is_asin_one_over_gamma_and_the_hop_lands_on_the_ballistic_root() {
    // Vertical plate z = delta sin(wt): the normal force g + a_zp vanishes (falling)
    // where sin(wt) = 1/Gamma. The hop then lands at the first root of the ballistic gap.
    // Event times are located to ~1e-15 s on closed forms; the integrated flight (DP5 at
    // 1e-10) carries an error ~1e-10 m/s in velocity, hence 1e-9 s on the landing time.
    let f = 20.0;
    for gamma in [1.2, 2.0, 3.0, 5.0] {
        let amp = gamma * G / (TAU * f).powi(2);
        let plate = Harmonic::sine(Axis::Z, amp, f);
        for opts in both_ways() {
            let tol = if opts.closed_forms { 1e-12 } else { 1e-9 };
            let run = simulate_block(&BlockParams::coulomb(G, 0.3, 0.0), &plate, 3.0 / f, &opts);
            let takeoff = run
                .events
                .iter()
                .find(|e| e.kind == EventKind::Takeoff)
                .expect("takes off");
            let phase = takeoff.t_s * TAU * f;
            assert!(
                (phase - (1.0 / gamma).asin()).abs() < 1e-10,
                "Gamma {gamma}: phase {phase}"
            );
            let landing = run
                .events
                .iter()
                .find(|e| e.kind == EventKind::Landing)
                .expect("lands");
            let exact = takeoff.t_s + ballistic_flight_s(&plate, takeoff.t_s, G, 4096);
            assert!(
                (landing.t_s - exact).abs() < tol,
                "Gamma {gamma} closed {}: {} vs {exact}",
                opts.closed_forms,
                landing.t_s
            );
        }
    }
}

#[test]
fn sawtooth_breakpoint_forces_a_sticking_block_to_slip() {
    // Slow stroke +0.1 m/s for 30 ms: the block sticks (no acceleration). At t = 30 ms
    // the plate jumps to -0.3 m/s: w = +0.4 m/s, decelerating at mu g = 3.924 m/s^2, which
    // takes 0.1019 s > the 10 ms fast stroke; at t = 40 ms the plate jumps back to +0.1
    // (w drops by 0.4 m/s to 0.4 - 0.01 mu g - 0.4 = -0.03924 m/s) and the block slides
    // left until w = 0 at t = 40 ms + 10 ms. Closed-form kinematics, exact to round-off.
    let saw = Sawtooth {
        slow_velocity_mps: 0.1,
        fast_velocity_mps: 0.3,
        slow_duration_s: 0.03,
    };
    let mu = 0.4;
    for opts in both_ways() {
        let run = simulate_block(&BlockParams::coulomb(G, mu, 0.0), &saw, 0.08, &opts);
        let bp: Vec<_> = run
            .events
            .iter()
            .filter(|e| e.kind == EventKind::Breakpoint)
            .collect();
        // Breakpoints at 30, 40 and 70 ms change the mode (80 ms ends the window).
        assert_eq!(bp.len(), 3, "{:?}", run.events);
        assert_eq!(
            (bp[0].from, bp[0].to),
            (BlockMode::Stick, BlockMode::SlipRight)
        );
        assert!((bp[0].after[1] - 0.4).abs() < 1e-12);
        assert_eq!(
            (bp[1].from, bp[1].to),
            (BlockMode::SlipRight, BlockMode::SlipLeft)
        );
        assert!(
            (bp[1].after[1] + 0.01 * mu * G).abs() < 1e-12,
            "{:?}",
            bp[1]
        );
        let stick = run
            .events
            .iter()
            .find(|e| e.kind == EventKind::SlipToStick)
            .expect("sticks again");
        assert!(
            (stick.t_s - 0.05).abs() < 1e-12
                || !opts.closed_forms && (stick.t_s - 0.05).abs() < 1e-10,
            "{}",
            stick.t_s
        );
    }
}

#[test]
fn friction_stays_in_the_cone_and_never_does_positive_work() {
    // A vertical plate with a bias: stick, slip, flight and impacts all occur. The
    // friction force is -mu n sign(w) or the needed force inside the cone: |f| <= mu n
    // up to round-off (1e-9 m/s^2); friction power f w <= 0 (w is 0 in stick); impacts
    // never raise the relative kinetic energy.
    let f = 15.0;
    let plate = Harmonic::sine(Axis::Z, 2.5 * G / (TAU * f).powi(2), f);
    let params = BlockParams::coulomb(G, 0.3, 0.2 * 0.3 * G);
    let mut chk = ContactInvariants::new(params, &plate);
    let run = simulate_block_observed(&params, &plate, 2.0, &BlockOptions::default(), &mut chk);
    assert!(
        run.total_counts.landings > 20 && run.total_counts.stick_to_slip > 0,
        "{:?}",
        run.total_counts
    );
    assert!(chk.worst_cone_mps2 <= 1e-9, "{}", chk.worst_cone_mps2);
    assert!(
        chk.worst_power_w_per_kg <= 1e-12,
        "{}",
        chk.worst_power_w_per_kg
    );
    assert!(
        chk.worst_impact_gain_m2ps2 <= 1e-15,
        "{}",
        chk.worst_impact_gain_m2ps2
    );
    // The plate only pushes (11 samples per contact segment, round-off 1e-9 m/s^2).
    assert!(
        chk.least_contact_normal_mps2 >= -1e-9,
        "{}",
        chk.least_contact_normal_mps2
    );
    assert!(run.mean_velocity_mps > 0.0);
}

#[test]
fn closed_forms_and_integration_agree_on_the_mean_drift() {
    // Horizontal dither with a bias: the DP5 run at rtol = atol = 1e-10 must reproduce
    // the closed-form mean velocity to ~1e-8 of V over 40 periods.
    let f = 10.0;
    let plate = Harmonic::sine(Axis::X, 5.0 * 0.36 * G / (TAU * f).powi(2), f);
    let params = BlockParams::coulomb(G, 0.36, 0.3 * 0.36 * G);
    let [a, b] = both_ways().map(|o| {
        simulate_block(
            &params,
            &plate,
            40.0 / f,
            &BlockOptions {
                transient_periods: 10,
                ..o
            },
        )
    });
    let v = plate.peak_velocity_mps();
    assert!(
        a.mean_velocity_mps > 0.0 && (a.mean_velocity_mps - b.mean_velocity_mps).abs() < 1e-8 * v,
        "{} {}",
        a.mean_velocity_mps,
        b.mean_velocity_mps
    );
    assert!(b.stats.rhs_evals > 0 && a.stats.rhs_evals == 0);
}

#[test]
fn viscous_block_under_bias_drifts_at_b_over_c() {
    // Linear friction: the mean of w' = b - c w - a_xp over a period gives <w> = b/c
    // exactly in the periodic steady state (the plate's mean velocity is zero).
    let f = 10.0;
    let plate = Harmonic::sine(Axis::X, 0.01, f);
    let (c, b) = (5.0, 0.2);
    let opts = BlockOptions {
        transient_periods: 30,
        ..BlockOptions::default()
    };
    let run = simulate_block(&BlockParams::viscous(G, c, b), &plate, 60.0 / f, &opts);
    // Transient decays as exp(-c t) = exp(-15): 3e-7 of the 0.04 m/s drift.
    assert!(
        (run.mean_velocity_mps - b / c).abs() < 1e-7,
        "{}",
        run.mean_velocity_mps
    );
    let _ = (PI, Method::Rk4, StepControl::Fixed { h_s: 1e-3 });
}

/// The two-velocity sawtooth of section 3.2.2 (slow 0.1 m/s for 30 ms, fast 0.3 m/s).
fn default_saw() -> Sawtooth {
    Sawtooth {
        slow_velocity_mps: 0.1,
        fast_velocity_mps: 0.3,
        slow_duration_s: 0.03,
    }
}

/// A run on a sawtooth from absolute rest (`w = -v_slow`) at t = 0, `transient` periods
/// dropped, ending after `periods` whole periods.
fn saw_run(
    saw: &Sawtooth,
    params: &BlockParams,
    opts: BlockOptions,
    transient: usize,
    periods: usize,
) -> BlockRun {
    let opts = BlockOptions {
        start: (0.0, [0.0, -saw.slow_velocity_mps, 0.0, 0.0]),
        transient_periods: transient,
        ..opts
    };
    simulate_block(params, saw, periods as f64 * saw.period_s(), &opts)
}

/// Runs a Coulomb block (friction `mu`) on `saw` from absolute rest both ways (closed
/// forms, integrated flows), drops `transient` periods, ends after `periods`; asserts the
/// whole-period mean velocity is the closed form v_d of physics::sawtooth and that the
/// block sticks while the plate moves back iff the closed-form regime says so. Returns
/// the closed-form run's error (m/s).
///
/// Tolerances: after the lock the motion is T-periodic, so the whole-period mean is
/// exactly v_d. Closed-form flows with located events leave round-off only (~1e-15 m/s
/// per event, a few hundred events): 1e-12. Integrated flows: DP5 is exact on the
/// constant accelerations of a sawtooth and events are located to ~1e-12 s, so the drift
/// is off by at most ~(0.4 m/s)(1e-12 s)/T per event: 1e-9.
fn check_saw_drift(saw: &Sawtooth, mu: f64, transient: usize, periods: usize) -> f64 {
    use crate::physics::sawtooth::{drift_velocity_mps, steady_regime, Regime};
    let k = mu * G;
    let expected = drift_velocity_mps(saw, k);
    let stick_both = steady_regime(saw, k) == Regime::StickBoth;
    let mut err_closed = 0.0;
    for (opts, tol) in both_ways().into_iter().zip([1e-12, 1e-9]) {
        let run = saw_run(
            saw,
            &BlockParams::coulomb(G, mu, 0.0),
            opts,
            transient,
            periods,
        );
        assert_eq!(run.outcome, crate::numerics::hybrid::Outcome::Completed);
        let err = (run.mean_velocity_mps - expected).abs();
        assert!(
            err < tol,
            "{saw:?} mu {mu} closed forms {}: {} vs {expected}",
            opts.closed_forms,
            run.mean_velocity_mps
        );
        // The regime as simulated: sticking while the plate moves back.
        let stuck_back = run
            .events
            .iter()
            .any(|e| e.to == BlockMode::Stick && saw.vx_mps(e.t_s) < 0.0);
        assert_eq!(stuck_back, stick_both, "{saw:?} mu {mu}");
        if opts.closed_forms {
            err_closed = err;
        }
    }
    err_closed
}

#[test]
fn sawtooth_coulomb_drift_is_the_closed_form() {
    // The asym engineer's repro: mu = 0.3, from absolute rest, t_end = 0.92 s, 3
    // transient periods (the closed-form lock time from rest is 0.054 s < 3 T = 0.12 s):
    // v_d = a - mu g T_f^2 / T = 0.0926425 m/s (the block gave 0.0169 m/s).
    check_saw_drift(&default_saw(), 0.3, 3, 23);
}

#[test]
fn sawtooth_viscous_mean_velocity_is_the_plates_zero() {
    // Linear law: <v> = <v_p> = 0 on the periodic orbit. Starting on that orbit
    // (physics::sawtooth::linear_periodic_start_velocity_mps) the whole-period mean is
    // zero from the first period; DP5 at rtol = atol = 1e-10 (the driver's default) gives
    // a position error ~1e-10 m over 20 periods (0.8 s): 1e-8 m/s on the mean.
    let saw = default_saw();
    for c in [5.0, 50.0, 500.0] {
        let v0 = crate::physics::sawtooth::linear_periodic_start_velocity_mps(&saw, c);
        let opts = BlockOptions {
            start: (0.0, [0.0, v0 - saw.slow_velocity_mps, 0.0, 0.0]),
            transient_periods: 0,
            ..BlockOptions::default()
        };
        let run = simulate_block(
            &BlockParams::viscous(G, c, 0.0),
            &saw,
            20.0 * saw.period_s(),
            &opts,
        );
        assert_eq!(
            run.outcome,
            crate::numerics::hybrid::Outcome::Completed,
            "c = {c}"
        );
        assert!(
            run.mean_velocity_mps.abs() < 1e-8,
            "c = {c}: {}",
            run.mean_velocity_mps
        );
    }
    // The repro: from absolute rest, t_end = 0.92 s, c = 1/s (formerly a step-size underflow).
    let run = saw_run(
        &saw,
        &BlockParams::viscous(G, 1.0, 0.0),
        BlockOptions::default(),
        3,
        23,
    );
    assert_eq!(run.outcome, crate::numerics::hybrid::Outcome::Completed);
}

#[test]
fn closed_form_segments_read_the_plate_of_their_own_piece() {
    // A segment that starts on the breakpoint B(1) = 30 ms (fast stroke, -0.3 m/s from
    // there) and lasts 0 or 1 ulp: the relative velocity must not change (the plate's
    // velocity is -0.3 m/s throughout the segment; slip decelerates w by mu g tau only).
    // Exact to round-off: w changes by at most mu g x 1 ulp.
    let saw = default_saw();
    let sys = BlockSystem::new(BlockParams::coulomb(G, 0.3, 0.0), &saw);
    let b = saw.breakpoint(1);
    let y0 = [0.0, 0.4, 0.0, 0.0];
    for t in [b, f64::from_bits(b.to_bits() + 1), b + 1e-12] {
        for mode in [BlockMode::SlipRight, BlockMode::Stick, BlockMode::Flight] {
            let y = sys.exact(mode, b, &y0, t).expect("closed form");
            let w0 = if mode == BlockMode::Stick { 0.0 } else { 0.4 };
            assert!((y[1] - w0).abs() < 1e-10, "{mode:?} at {t}: {:?}", y);
        }
    }
    // A segment that ends on the next breakpoint, B(2) = 40 ms, after 1 ulp-long and
    // ordinary lengths: the left limit there is still the fast stroke's.
    let b2 = saw.breakpoint(2);
    for t0 in [f64::from_bits(b2.to_bits() - 1), b2 - 1e-6, b] {
        let y = sys
            .exact(BlockMode::SlipRight, t0, &y0, b2)
            .expect("closed form");
        let expected = 0.4 - 0.3 * G * (b2 - t0);
        assert!((y[1] - expected).abs() < 1e-12, "from {t0}: {:?}", y);
    }
}

#[test]
fn sawtooth_drift_matches_the_closed_forms_in_every_regime() {
    // A grid of scenes: two speed ratios, two stroke durations, and friction at
    // 0.02, 0.3, 0.99, 1.01 and 3 times the regime boundary mu* = (a + b)/(g T_f)
    // (stick in the slow stroke below it, in both strokes above). Transient: the
    // closed-form lock time from absolute rest plus two periods; 8 periods measured
    // (see `check_saw_drift`).
    use crate::physics::sawtooth::{lock_time_s, steady_regime, Regime};
    let mut worst = 0.0f64;
    let mut regimes = Vec::new();
    for fast in [0.15, 0.3] {
        for ts in [0.02, 0.03] {
            let saw = Sawtooth {
                slow_velocity_mps: 0.1,
                fast_velocity_mps: fast,
                slow_duration_s: ts,
            };
            let mu_star = (0.1 + fast) / (G * saw.fast_duration_s()); // formula: k T_f = a + b
            for f in [0.02, 0.3, 0.99, 1.01, 3.0] {
                let mu = f * mu_star;
                regimes.push(steady_regime(&saw, mu * G));
                let n0 = (lock_time_s(&saw, mu * G, 0.0) / saw.period_s()).floor() as usize + 2;
                worst = worst.max(check_saw_drift(&saw, mu, n0, n0 + 8));
            }
        }
    }
    assert_eq!(
        regimes.iter().filter(|&&r| r == Regime::StickBoth).count(),
        8
    );
    eprintln!("largest block-vs-closed-form drift difference: {worst:e} m/s");
}

/// The long fuzz's Zeno stop (issue 29): at Γ just above the creep threshold 1 - b a
/// slip from rest opens its window with an acceleration near zero, and its closed-form
/// velocity rounds to -1.7e-18 m/s within the first step. Judged against zero, that was
/// a reversal, answered by the same slip 100 times in 1e-6 s; judged against the slip's
/// rounding (`slip_rounding_mps`) the run completes.
#[test]
fn a_slip_opening_at_the_creep_threshold_is_not_a_zeno_stop() {
    let (gamma, f, mu, bias) = (0.9501953125, 27.18084237584415, 0.4, 0.05);
    let omega = TAU * f;
    let plate = Harmonic::sine(Axis::Z, gamma * G / (omega * omega), f);
    let params = BlockParams::coulomb(G, mu, bias * mu * G);
    let run = simulate_block(&params, &plate, 120.0 / f, &BlockOptions::default());
    assert_eq!(run.outcome, crate::numerics::hybrid::Outcome::Completed);
}

/// The slip guard's rounding floor reads the plates' peak rates instead of their values
/// at t (`slip_rounding_mps`): they must bound those values at every t, or the floor
/// would be smaller than the one it replaces.
#[test]
fn the_plates_peak_rates_bound_their_velocities_and_accelerations() {
    use crate::physics::plate::{Biharmonic, PlateMotion, Sawtooth};
    use crate::physics::sawtooth::Mirrored;
    let saw = Sawtooth {
        slow_velocity_mps: 0.1,
        fast_velocity_mps: 0.3,
        slow_duration_s: 0.03,
    };
    let bi = |asymmetry: f64| Biharmonic {
        velocity_amplitude_mps: 0.2,
        omega_rad_s: TAU * 7.0,
        asymmetry,
    };
    let plates: Vec<Box<dyn PlateMotion>> = vec![
        Box::new(Harmonic::sine(Axis::X, 0.02, 5.0)),
        Box::new(Harmonic::sine(Axis::Z, 1e-3, 30.0)),
        Box::new(Harmonic::cosine(Axis::Z, 2e-3, 12.0)),
        Box::new(bi(0.3)),
        Box::new(bi(-0.2)),
        Box::new(saw),
        Box::new(Mirrored(saw)),
    ];
    for p in &plates {
        let peak = p.peak_rates().expect("every plate here knows its peaks");
        for i in 0..20_000 {
            let t = 3.0 * p.period_s() * f64::from(i) / 20_000.0;
            let at = [p.vx_mps(t), p.ax_mps2(t), p.vz_mps(t), p.az_mps2(t)];
            for (v, bound) in at.iter().zip(peak) {
                assert!(
                    v.abs() <= bound * (1.0 + 1e-12),
                    "t {t}: {at:?} vs {peak:?}"
                );
            }
        }
    }
}
