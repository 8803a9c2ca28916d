//! Unit tests of the chapter's runs (`sims.rs`) against the closed forms of
//! `physics::sawtooth`, derived independently of the simulator:
//! - a block with Coulomb friction on a two-velocity sawtooth drifts along the slow, long
//!   stroke at `v_slow - mu g t_fast^2 / T` while `mu g t_fast < v_slow + v_fast`, and not
//!   at all beyond;
//! - from rest it slips (gaining `mu g (t_slow - t_fast)` per period) until it reaches the
//!   slow speed at the closed-form lock time, then moves periodically;
//! - with linear friction the mean velocity is the plate's, zero, for any zero-mean drive;
//! - symmetric drives give no drift, mirrored drives the opposite drift;
//! - the smooth drive's always-slipping drift `eps V (1 - pi^2/(2 Gamma^2))`.
//!
//! Tolerances: closed-form flows with event times located to a few ulps leave only
//! round-off (~1e-15 per event, a few hundred events): 1e-12 (m/s or s) here. The
//! chapter's own claims use each run's error budget (`evidence::Tolerances`,
//! `sims::mean_velocity_budget_mps`). The command line's contract and the quick
//! summary's snapshot: `tests/asymmetric_shaking.rs`.

use super::sims::{run_block, slip_transient, Law, Numerics, Window};
use crate::physics::plate::{Axis, Biharmonic, Harmonic, PlateMotion, Sawtooth};
use crate::physics::sawtooth::biharmonic::{always_slipping_drift, stick_forever_gamma};
use crate::physics::sawtooth::{
    drift_velocity_mps, linear_periodic_start_velocity_mps, lock_time_s, steady_regime,
    steady_velocity_mps, Mirrored, Regime,
};

const G: f64 = 9.81;
const EXACT: f64 = 1e-12;

fn saw(a: f64, b: f64, ts: f64) -> Sawtooth {
    Sawtooth {
        slow_velocity_mps: a,
        fast_velocity_mps: b,
        slow_duration_s: ts,
    }
}

/// Periods from rest to the lock (closed form) plus two (one of margin for a tie).
fn transient(s: &Sawtooth, k: f64) -> usize {
    (lock_time_s(s, k, 0.0) / s.period_s()).floor() as usize + 2
}

fn coulomb_drift(s: &dyn PlateMotion, mu: f64, transient: usize, measured: usize) -> f64 {
    let w = Window {
        transient,
        measured,
    };
    run_block(
        Law::Coulomb { k_mps2: mu * G },
        s,
        0.0,
        w,
        &Numerics::default(),
        (0.0, 0.0),
        0.0,
    )
    .mean_velocity_mps
}

#[test]
fn closed_form_drift_matches_simulation_in_every_regime() {
    // (a, b, t_slow, mu): stick in the slow stroke (several asymmetries and frictions),
    // stick in both (strong friction or long strokes), and the boundary's two sides.
    let cases = [
        (0.1, 0.3, 0.03, 0.3, Regime::StickSlow),
        (0.1, 0.2, 0.05, 0.05, Regime::StickSlow),
        (0.2, 0.25, 0.01, 1.0, Regime::StickSlow),
        (0.1, 0.3, 0.03, 5.0, Regime::StickBoth),
        (0.1, 0.3, 0.6, 0.3, Regime::StickBoth),
        (0.1, 0.3, 0.03, 0.4 / (0.01 * G) * 0.99, Regime::StickSlow),
        (0.1, 0.3, 0.03, 0.4 / (0.01 * G) * 1.01, Regime::StickBoth),
    ];
    for (a, b, ts, mu, regime) in cases {
        let s = saw(a, b, ts);
        let k = mu * G;
        assert_eq!(steady_regime(&s, k), regime, "{a} {b} {ts} {mu}");
        let w = Window {
            transient: transient(&s, k),
            measured: 8,
        };
        let run = run_block(
            Law::Coulomb { k_mps2: k },
            &s,
            0.0,
            w,
            &Numerics::default(),
            (0.0, 0.0),
            0.0,
        );
        let sim = run.mean_velocity_mps;
        // the simulated regime: does the block stick while the plate moves back?
        assert_eq!(
            run.stuck_in_backward_stroke,
            regime == Regime::StickBoth,
            "{a} {b} {ts} {mu}"
        );
        let formula = drift_velocity_mps(&s, k);
        assert!(
            (sim - formula).abs() < EXACT,
            "{a} {b} {ts} {mu}: sim {sim} vs {formula}"
        );
        if regime == Regime::StickBoth {
            assert!(sim.abs() < EXACT);
        } else {
            assert!(sim > 0.0 && sim < a);
        }
    }
}

#[test]
fn lock_time_and_steady_velocity_match_the_closed_forms() {
    // The always-slipping transient ends at the closed-form lock time; after it the
    // simulated velocity is the closed-form periodic one at every sampled instant.
    for (a, b, ts, mu) in [
        (0.1, 0.3, 0.03, 0.3),
        (0.1, 0.15, 0.02, 0.02),
        (0.1, 0.3, 0.03, 6.0),
    ] {
        let s = saw(a, b, ts);
        let k = mu * G;
        let p = s.period_s();
        let n0 = transient(&s, k);
        let w = Window {
            transient: n0,
            measured: 3,
        };
        let span = (n0 as f64 * p, (n0 + 3) as f64 * p);
        let run = run_block(
            Law::Coulomb { k_mps2: mu * G },
            &s,
            0.0,
            w,
            &Numerics::default(),
            span,
            p / 50.0,
        );
        let t_lock = run.first_stick_s.expect("the block sticks");
        assert!(
            (t_lock - lock_time_s(&s, k, 0.0)).abs() < EXACT,
            "{t_lock} vs {}",
            lock_time_s(&s, k, 0.0)
        );
        assert!(!run.trace.is_empty());
        for &(t, v, _) in &run.trace {
            // Away from the stroke changes (where the sampled side is ambiguous).
            let tau = t - (t / p).floor() * p;
            if tau.min((tau - ts).abs()).min(p - tau) < 1e-9 {
                continue;
            }
            let closed = steady_velocity_mps(&s, k, t);
            assert!((v - closed).abs() < EXACT, "t {t}: {v} vs {closed}");
        }
        assert!((run.v_max_mps - a).abs() < EXACT);
    }
}

#[test]
fn linear_friction_gives_no_drift_for_any_zero_mean_drive() {
    // <v> = <v_p> - (v(t1) - v(t0))/(c (t1 - t0)) = 0 on the periodic orbit. DP5 at
    // 1e-12: 1e-9 m/s.
    let c = 30.0;
    let s = saw(0.1, 0.3, 0.03);
    let w = 2.0 * std::f64::consts::PI / s.period_s();
    let drives: Vec<Box<dyn PlateMotion>> = vec![
        Box::new(s),
        Box::new(Mirrored(s)),
        Box::new(saw(0.05, 0.5, 0.02)),
        Box::new(Biharmonic {
            velocity_amplitude_mps: 0.2,
            omega_rad_s: w,
            asymmetry: 0.4,
        }),
        Box::new(Harmonic::sine(Axis::X, 0.002, 25.0)),
    ];
    for p in &drives {
        let tr = (36.0 / (c * p.period_s())).ceil() as usize;
        let run = run_block(
            Law::Viscous { c_per_s: c },
            p.as_ref(),
            0.0,
            Window {
                transient: tr,
                measured: 6,
            },
            &Numerics::default(),
            (0.0, 0.0),
            0.0,
        );
        assert!(
            run.mean_velocity_mps.abs() < 1e-9,
            "{}",
            run.mean_velocity_mps
        );
    }
    // The periodic orbit of the sawtooth: its velocity at a slow stroke's start.
    let run = run_block(
        Law::Viscous { c_per_s: c },
        &s,
        0.0,
        Window {
            transient: 30,
            measured: 1,
        },
        &Numerics::default(),
        (0.0, 0.0),
        0.0,
    );
    let v0 = linear_periodic_start_velocity_mps(&s, c);
    assert!(
        (run.v_window_mps.0 - v0).abs() < 1e-9,
        "{} vs {v0}",
        run.v_window_mps.0
    );
}

#[test]
fn symmetric_drives_give_no_coulomb_drift() {
    // eps = 0 is symmetric under v -> -v with a half-period shift: the always-slipping
    // orbit has zero mean (closed form eps (1 - ...) = 0), and so does the stuck block.
    let k = 0.3 * G;
    for gamma in [10.0, 0.9 * stick_forever_gamma(0.0)] {
        let p = Biharmonic {
            velocity_amplitude_mps: 0.2,
            omega_rad_s: gamma * k / 0.2,
            asymmetry: 0.0,
        };
        let v = coulomb_drift(&p, 0.3, slip_transient(gamma), 4);
        assert!(v.abs() < EXACT, "gamma {gamma}: {v}");
    }
}

#[test]
fn mirrored_drives_reverse_the_drift() {
    let s = saw(0.1, 0.3, 0.03);
    let k = 0.3 * G;
    let n = transient(&s, k);
    let (v, vm) = (
        coulomb_drift(&s, 0.3, n, 6),
        coulomb_drift(&Mirrored(s), 0.3, n, 6),
    );
    assert!(v > 0.05 && (v + vm).abs() < EXACT, "{v} {vm}");
    // eps -> -eps is the mirror image shifted by half a period.
    let p = |e: f64| Biharmonic {
        velocity_amplitude_mps: 0.2,
        omega_rad_s: 10.0 * k / 0.2,
        asymmetry: e,
    };
    let (vp, vn) = (
        coulomb_drift(&p(0.25), 0.3, slip_transient(10.0), 4),
        coulomb_drift(&p(-0.25), 0.3, slip_transient(10.0), 4),
    );
    assert!(vp > 0.03 && (vp + vn).abs() < EXACT, "{vp} {vn}");
}

#[test]
fn biharmonic_always_slipping_drift_matches_the_closed_form() {
    // eps V (1 - pi^2/(2 Gamma^2)): independent of the simulator (a periodicity argument).
    let k = 0.3 * G;
    for (gamma, eps) in [(4.0, 0.2), (10.0, -0.3), (30.0, 0.1)] {
        let v = 0.2;
        let p = Biharmonic {
            velocity_amplitude_mps: v,
            omega_rad_s: gamma * k / v,
            asymmetry: eps,
        };
        let sim = coulomb_drift(&p, 0.3, slip_transient(gamma), 4);
        let closed = always_slipping_drift(gamma, eps).expect("orbit exists") * v;
        assert!(
            (sim - closed).abs() < EXACT,
            "{gamma} {eps}: {sim} vs {closed}"
        );
    }
}
