//! Where numerical methods fail, at the level of the numerics: each test shows the
//! failing method failing and the good method not, against a closed form.
//!
//! - Stiffness: the stick's flight relaxation `theta' = -(k/gamma)(theta - theta_0)` has
//!   a time constant gamma/k = 1 ms, far shorter than a sensible step for a 30 Hz drive.
//!   Explicit Euler and RK4 with a fixed step of a tenth of the period blow up (their
//!   stability intervals on the negative real axis end at h/tau = 2 and 2.785);
//!   adaptive Dormand-Prince follows the closed form.
//! - Events: fixed steps without event location take an impact or a stick-slip switch
//!   at the end of the step that saw it, late by up to one step (error ~ h); located
//!   events are exact to ~1e-12.
//! - Zeno: a ball bouncing with 0 < e < 1 makes infinitely many impacts before
//!   t_inf = t1 (1 + e)/(1 - e). The event-driven driver reports `Outcome::Zeno` there
//!   instead of hanging; Moreau-Jean passes through the accumulation to rest.
//! - 1/sin(theta): the stick's sliding equations (C.14) divide by sin(theta). Near the
//!   vertical the slide's theta'' grows as 1/theta and an adaptive integrator's step
//!   collapses (a typed StepTooSmall) before theta = 0; the pivot equation (C.6) from the
//!   same state crosses theta = 0 smoothly.

use locomotion_workbook::numerics::events::Direction;
use locomotion_workbook::numerics::hybrid::{
    simulate, HybridSystem, Options, Outcome, Run, Transition,
};
use locomotion_workbook::numerics::ode::{Integrator, Method, OdeError, StepControl};
use locomotion_workbook::numerics::timestepping::{self as mj, ContactStatus, MjOptions};
use locomotion_workbook::physics::block::contact_form::BlockContact;
use locomotion_workbook::physics::block::BlockParams;
use locomotion_workbook::physics::plate::{Axis, Harmonic};
use std::f64::consts::TAU;

const G: f64 = 9.81;

// ---------------------------------------------------------------- stiffness

/// tau = gamma / k of the stick scene (k = 10 N m/rad, gamma = 0.01 N m s/rad).
const TAU_S: f64 = 1e-3;
/// Drive frequency of the stick scene (Hz).
const F_HZ: f64 = 30.0;
/// Amplitude of the forcing of the relaxation (rad).
const A_RAD: f64 = 0.1;

/// theta' = -(theta - a cos(w t)) / tau: the relaxation towards a moving target.
fn relax(t: f64, y: &[f64; 1]) -> [f64; 1] {
    [-(y[0] - A_RAD * (TAU * F_HZ * t).cos()) / TAU_S]
}

/// Closed form from theta(0) = 0: particular solution plus decaying transient.
fn relax_exact(t: f64) -> f64 {
    let wt = TAU * F_HZ * TAU_S;
    let d = 1.0 + wt * wt;
    A_RAD * ((TAU * F_HZ * t).cos() + wt * (TAU * F_HZ * t).sin()) / d
        - A_RAD / d * (-t / TAU_S).exp()
}

fn relax_error(method: Method, control: StepControl, t_end: f64) -> Result<f64, OdeError> {
    let mut integ = Integrator::new(method, control);
    let y = integ.integrate(&relax, 0.0, [0.0], t_end, |_| {})?;
    Ok((y[0] - relax_exact(t_end)).abs())
}

#[test]
fn explicit_fixed_steps_blow_up_on_the_stiff_flight_relaxation() {
    // h = T/10 = 3.3 ms = 3.3 tau: outside both stability intervals. After 1 s (300
    // steps) the amplification |1 - h/tau|^300 = 2.3^300 overflows or is astronomically
    // large; either the integrator reports a non-finite state or the error exceeds 1e6 rad.
    let h = 1.0 / (10.0 * F_HZ);
    for m in [Method::Euler, Method::Rk4] {
        match relax_error(m, StepControl::Fixed { h_s: h }, 1.0) {
            Err(OdeError::NonFinite { .. }) => {}
            Ok(e) => assert!(e > 1e6, "{m:?} error {e} did not blow up"),
            Err(e) => panic!("{m:?}: unexpected {e}"),
        }
    }
    // The good method: adaptive DP5 at 1e-8 follows the closed form. Stiff decay is
    // damped, so the global error stays within a small multiple of the tolerance.
    let e = relax_error(Method::Dopri5, StepControl::tol(1e-8, 1e-8), 1.0).unwrap();
    assert!(e < 1e-6, "DP5 error {e}");
}

#[test]
fn the_failure_is_stability_not_accuracy() {
    // Inside the stability interval (h = 1.5 tau for Euler, 2.5 tau for RK4) the same
    // fixed-step methods stay bounded: the error is the forcing's phase error, of order
    // the amplitude at most (0.1 rad), nowhere near the blow-up above.
    assert!(
        relax_error(Method::Euler, StepControl::Fixed { h_s: 1.5 * TAU_S }, 1.0).unwrap() < A_RAD
    );
    assert!(
        relax_error(Method::Rk4, StepControl::Fixed { h_s: 2.5 * TAU_S }, 1.0).unwrap() < A_RAD
    );
}

// ---------------------------------------------------------------- events

/// A point under constant acceleration `accel` (m/s^2), state `(position, velocity)`,
/// with one guard: component `watch` falling through zero. At the event the velocity is
/// reversed and scaled by `e` if `e > 0` (a bounce), else the run stops.
/// - A ball above a fixed floor: `accel = -g`, `watch = 0` (height), restitution `e`.
/// - A block sliding on a floor: `accel = -mu g`, `watch = 1` (velocity), `e = 0`: the
///   slip-to-stick switch stops the run.
struct Uniform {
    accel: f64,
    watch: usize,
    e: f64,
}

impl Uniform {
    fn ball(e: f64) -> Self {
        Uniform {
            accel: -G,
            watch: 0,
            e,
        }
    }
    fn slider(mu: f64) -> Self {
        Uniform {
            accel: -mu * G,
            watch: 1,
            e: 0.0,
        }
    }
}

impl HybridSystem<2> for Uniform {
    type Mode = ();
    type Stop = &'static str;
    fn flow(&self, _m: (), _t: f64, y: &[f64; 2]) -> [f64; 2] {
        [y[1], self.accel]
    }
    fn max_step(&self, _m: (), _t: f64, y: &[f64; 2]) -> f64 {
        // Leaving the floor, step at most to the apex so the guard is seen positive.
        if self.watch == 0 && y[0] <= 0.0 && y[1] > 0.0 {
            y[1] / -self.accel
        } else {
            f64::INFINITY
        }
    }
    fn guard_count(&self, _m: ()) -> usize {
        1
    }
    fn guard(&self, _m: (), _i: usize, _t: f64, y: &[f64; 2]) -> f64 {
        y[self.watch]
    }
    fn direction(&self, _m: (), _i: usize) -> Direction {
        Direction::Falling
    }
    fn on_event(
        &self,
        _m: (),
        _i: usize,
        _t: f64,
        y: &[f64; 2],
    ) -> Transition<(), &'static str, 2> {
        if self.e == 0.0 {
            Transition::Stop("event")
        } else {
            Transition::To {
                mode: (),
                state: [0.0, -self.e * y[1]],
            }
        }
    }
}

fn fixed(method: Method, h: f64, locate: bool) -> Options {
    Options {
        method,
        control: StepControl::Fixed { h_s: h },
        locate_events: locate,
        ..Options::default()
    }
}

/// `sys` from `y0` at t = 0 with RK4 at the fixed step `h`, events located or not,
/// until the event stops it (or t = 2 s).
fn rk4_run(sys: &Uniform, y0: [f64; 2], h: f64, locate: bool) -> Run<(), &'static str, 2> {
    simulate(
        sys,
        (),
        0.0,
        y0,
        2.0,
        &fixed(Method::Rk4, h, locate),
        &mut (),
    )
}

#[test]
fn unlocated_impacts_are_late_by_up_to_a_step_located_ones_exact() {
    // Closed form: the ball dropped from 1 m lands at sqrt(2/g). Unlocated, the event
    // is taken at the end of the step that crossed: 0 < error <= h, and the error
    // shrinks with h (first order on average). Located on the dense output: ~1e-12
    // (RK4's Hermite interpolant is exact for the quadratic flight).
    let exact = (2.0 / G).sqrt();
    let mut errs = Vec::new();
    for h in [1e-2, 1e-3, 1e-4] {
        let run = rk4_run(&Uniform::ball(0.0), [1.0, 0.0], h, false);
        let err = run.t_end_s - exact;
        assert!(err > 0.0 && err <= h * (1.0 + 1e-9), "h {h}: late by {err}");
        errs.push(err);
        let run = rk4_run(&Uniform::ball(0.0), [1.0, 0.0], h, true);
        assert!(
            (run.t_end_s - exact).abs() < 1e-12,
            "located: {}",
            run.t_end_s - exact
        );
    }
    assert!(errs[2] < errs[0] / 10.0, "{errs:?}");
}

#[test]
fn unlocated_stick_slip_switches_are_late_by_up_to_a_step() {
    // Closed form: the block launched at 1 m/s with mu = 0.4 sticks at t = v0/(mu g).
    // RK4 integrates the constant deceleration (quadratic position) exactly and its
    // Hermite interpolant reproduces it, so the only error is the event's placement:
    // up to h unlocated, round-off located (time and stopping distance v0^2/(2 mu g)).
    let (v0, mu) = (1.0, 0.4);
    let exact = v0 / (mu * G);
    for h in [1e-2, 1e-3] {
        let run = rk4_run(&Uniform::slider(mu), [0.0, v0], h, false);
        let late = run.t_end_s - exact;
        assert!(late > 0.0 && late <= h * (1.0 + 1e-9), "h {h}: {late}");
        let run = rk4_run(&Uniform::slider(mu), [0.0, v0], h, true);
        assert!(
            (run.t_end_s - exact).abs() < 1e-12,
            "located: {}",
            run.t_end_s - exact
        );
        assert!((run.y_end[0] - v0 * v0 / (2.0 * mu * G)).abs() < 1e-12);
    }
}

// ---------------------------------------------------------------- Zeno

#[test]
fn zeno_bouncing_stops_the_event_driver_and_moreau_jean_passes_to_rest() {
    // Closed form: from 1 m, t1 = sqrt(2/g); flights 2 t1 e^k sum to
    // t_inf = t1 (1 + e)/(1 - e) = 3 t1 for e = 1/2.
    let e = 0.5;
    let t1 = (2.0 / G).sqrt();
    let t_inf = t1 * (1.0 + e) / (1.0 - e);
    // Event-driven: infinitely many events before t_inf; the driver stops there.
    let run = simulate(
        &Uniform::ball(e),
        (),
        0.0,
        [1.0, 0.0],
        5.0,
        &Options::default(),
        &mut (),
    );
    let Outcome::Zeno { t_s, .. } = run.outcome else {
        panic!("expected Zeno, got {:?}", run.outcome)
    };
    assert!(
        t_s <= t_inf + 1e-12 && t_inf - t_s < 1e-6,
        "{t_s} vs {t_inf}"
    );
    // Moreau-Jean with h = 1e-3: bounces shorter than a step are absorbed into a
    // sticking contact. It reaches rest (v = 0, status Stick) within a few flights of
    // the accumulation point: the flights left after a bounce of speed v last
    // 2 v/(g (1 - e)); bounces below ~g h are lost, so rest comes within ~4 h/(1-e) +
    // 2 e^k t1 of t_inf, and certainly within 0.05 s for h = 1 ms. It ends in
    // finitely many steps, all of them finite.
    let h = 1e-3;
    let mut rest_from = f64::NAN;
    let mut impacts = 0;
    // The same ball for Moreau-Jean: the block model's contact form (a point mass,
    // q = (x, z)) on a plate at rest, no bias.
    let floor = Harmonic::sine(Axis::Z, 0.0, 1.0);
    let mut params = BlockParams::coulomb(G, 0.5, 0.0);
    params.restitution = e;
    let mj_ball = BlockContact::new(params, &floor).expect("Coulomb friction");
    let run = mj::simulate(
        &mj_ball,
        0.0,
        [0.0, 1.0],
        [0.0, 0.0],
        5.0,
        &MjOptions::midpoint(h),
        |s| {
            let resting = s.impulse.status == ContactStatus::Stick && s.v1[1].abs() < 1e-12;
            if resting && rest_from.is_nan() {
                rest_from = s.t1;
            } else if !resting && s.impulse.status != ContactStatus::Inactive && s.v0[1] < 0.0 {
                impacts += 1;
            }
            if !resting && s.q1[1] > 0.0 {
                rest_from = f64::NAN;
            }
        },
    )
    .unwrap();
    assert!(
        run.v[1].abs() < 1e-12 && run.q[1] <= 0.0 && run.q[1] > -h * (2.0 * G).sqrt(),
        "{:?} {:?}",
        run.q,
        run.v
    );
    assert!(
        (rest_from - t_inf).abs() < 0.05,
        "rest from {rest_from} vs t_inf {t_inf}"
    );
    // log2(v1 / (g h)) = log2(4.43 / 0.0098) = 9 resolved bounces, give or take two
    assert!((5..=14).contains(&impacts), "{impacts} impacts");
}

// ---------------------------------------------------------------- 1/sin(theta)

use locomotion_workbook::numerics::ode::Step;
use locomotion_workbook::physics::stick::run::initial_state;
use locomotion_workbook::physics::stick::{authors_scene, Mode, StickModel, NSTATE, OM, TH, VXC};

#[test]
fn sliding_equations_are_singular_at_theta_zero_the_pivot_equation_is_not() {
    // C.14: theta'' = ((z_c'' - z_p'')/L - theta'^2 cos)/sin(theta): the slide's angular
    // acceleration grows as 1/theta near the vertical, while the pivot's C.6,
    // m L^2 theta'' = (g + z_s'') m L sin - k (theta - theta_0) - gamma theta', stays
    // bounded. Closed-form scaling: theta'' theta tends to a constant (to O(theta^2)).
    let m = StickModel::new(authors_scene(10.0));
    let at = |th: f64| {
        let mut y = initial_state(&m, 0.0, th);
        y[OM] = -5.0;
        (
            m.slide_eval(1.0, 0.0, &y).theta_dd,
            m.pivot_eval(0.0, &y).theta_dd,
        )
    };
    let (s3, p3) = at(1e-3);
    let (s6, p6) = at(1e-6);
    assert!(
        ((s6 * 1e-6) / (s3 * 1e-3) - 1.0).abs() < 1e-2,
        "slide theta'' theta: {} vs {}",
        s3 * 1e-3,
        s6 * 1e-6
    );
    assert!(
        s6.abs() > 1e5 * p6.abs().max(1.0),
        "slide {s6} vs pivot {p6}"
    );
    assert!(
        (p6 - p3).abs() < 1e-2 * p3.abs().max(1.0),
        "pivot bounded: {p3} {p6}"
    );
    assert!(
        !m.slide_eval(1.0, 0.0, &initial_state(&m, 0.0, 0.0))
            .theta_dd
            .is_finite(),
        "C.14 at theta = 0"
    );
}

#[test]
fn integrating_the_slide_into_theta_zero_fails_the_pivot_crosses_it() {
    // A rod sliding with C moving right (x_c' = 0.5 m/s) and theta' = -5 rad/s from
    // theta = 0.05 rad is driven to the vertical. Adaptive Dormand-Prince on C.14 cannot
    // pass theta = 0: its step collapses (a typed StepTooSmall, never a hang or a NaN)
    // with theta within 1e-6 rad of 0. The pivot flow (C.6) from the same state crosses
    // theta = 0 in one smooth sweep: the singularity belongs to the sliding equations.
    let m = StickModel::new(authors_scene(10.0));
    let mut y = initial_state(&m, 0.0, 0.05);
    y[OM] = -5.0;
    y[VXC] = 0.5;
    let flow = |mode: Mode| {
        move |t: f64, y: &[f64; NSTATE]| {
            locomotion_workbook::numerics::hybrid::HybridSystem::flow(&m, mode, t, y)
        }
    };
    let mut integ = Integrator::new(Method::Dopri5, StepControl::tol(1e-10, 1e-10));
    let mut last_theta = y[TH];
    let r = integ.integrate(&flow(Mode::SlideLeft), 0.0, y, 0.01, |s: &Step<NSTATE>| {
        last_theta = s.y1[TH]
    });
    assert!(matches!(r, Err(OdeError::StepTooSmall { .. })), "{r:?}");
    assert!(last_theta.abs() < 1e-6 && last_theta > 0.0, "{last_theta}");
    let mut integ = Integrator::new(Method::Dopri5, StepControl::tol(1e-10, 1e-10));
    let mut crossed = false;
    let y1 = integ
        .integrate(&flow(Mode::Pivot), 0.0, y, 0.02, |s: &Step<NSTATE>| {
            crossed |= s.y1[TH] < 0.0
        })
        .unwrap();
    assert!(crossed && y1.iter().all(|v| v.is_finite()), "{y1:?}");
}

// ---- Stiff soft contact: the stick standing in a penalty contact on a still plate.
//
// With the regularisation eps of `physics::stick::soft` the contact's damping time is
// m / c_n = eps tau_0 (tau_0 = T/30 = 1.1 ms at 30 Hz). Standing still, nothing moves
// on that scale, but an explicit method must keep h / (eps tau_0) inside its stability
// interval (about 3.3 for DP5): at eps = 1e-4 that is h <= 3.7e-7 s, over 0.2 s about
// 5.4e5 steps, beyond a budget of 1e5; the L-stable Rosenbrock 2(3) takes steps set by
// accuracy alone (the state is at rest): far fewer than 1e4.

use locomotion_workbook::physics::stick::soft::run::{simulate_soft, SoftOutcome};
use locomotion_workbook::physics::stick::StickParams;

fn still_plate_stick() -> StickParams {
    // The self-locking stick (L = 0.15 m, m = 1 kg, k = 10, gamma = 0.01, mu = 0.4,
    // theta_0 = 0.3) on a plate that does not move (Gamma = 0).
    StickParams::new(0.15, 1.0, 10.0, 0.01, 0.4, 0.3, 9.81, 0.0, 30.0).unwrap()
}

#[test]
fn explicit_pair_exhausts_its_budget_on_stiff_soft_contact_the_rosenbrock_method_does_not() {
    let p = still_plate_stick();
    let cycles = 6.0; // 0.2 s
                      // atol 1e-13 m: below the static penetration m g / k_n = 1.2e-10 m at eps = 1e-4
    let ctl = StepControl::tol(1e-8, 1e-13);
    let budget = 100_000;
    let ros = simulate_soft(&p, 1e-4, cycles, Method::Rosenbrock23, ctl, budget);
    assert_eq!(ros.outcome, SoftOutcome::Completed, "{ros:?}");
    assert!(ros.stats.accepted < 10_000, "{ros:?}");
    // At rest: C creeps at most at the slip scale v_eps = v_0 eps^2 = 1e-8 m/s (the
    // friction needed at the static angle is zero); the settling transient moves C
    // sideways by less than 1e-5 m/s times the span.
    assert!(ros.mean_velocity_mps.abs() < 1e-5, "{ros:?}");
    let dp = simulate_soft(&p, 1e-4, cycles, Method::Dopri5, ctl, budget);
    assert!(matches!(dp.outcome, SoftOutcome::Budget { .. }), "{dp:?}");
    // The explicit pair's steps sit at its stability limit, of the order of the
    // contact's damping time eps tau_0 = 1.1e-7 s (measured mean step 1.3e-6 s: the
    // stiff mode's rate is c_n over an effective mass that the turning rod changes, and
    // DP5's interval reaches 3.3 / rate); the band [0.3, 30] eps tau_0 still separates
    // it from the Rosenbrock method's steps (0.2 s / 73 = 2.7e-3 s).
    let tau0 = p.period_s() / 30.0;
    let h_dp = (dp.stats.accepted as f64).recip()
        * match dp.outcome {
            SoftOutcome::Budget { t_s } => t_s,
            _ => unreachable!(),
        };
    assert!(
        h_dp < 30.0 * 1e-4 * tau0 && h_dp > 0.3 * 1e-4 * tau0,
        "DP5's mean step {h_dp} s"
    );
}

#[test]
fn the_explicit_pairs_step_count_grows_as_1_over_eps_the_implicit_one_does_not() {
    // Same scene, 0.1 s, eps from 1e-2 to 1e-3: DP5's steps grow ~10x (stability-bound:
    // h ~ eps tau_0), Rosenbrock's stay within a factor 3 (accuracy-bound).
    let p = still_plate_stick();
    let ctl = StepControl::tol(1e-8, 1e-13);
    let steps = |m: Method, eps: f64| {
        let r = simulate_soft(&p, eps, 3.0, m, ctl, 1_000_000);
        assert_eq!(r.outcome, SoftOutcome::Completed, "{m:?} {eps}: {r:?}");
        r.stats.accepted as f64
    };
    let (d2, d3) = (steps(Method::Dopri5, 1e-2), steps(Method::Dopri5, 1e-3));
    let (r2, r3) = (
        steps(Method::Rosenbrock23, 1e-2),
        steps(Method::Rosenbrock23, 1e-3),
    );
    assert!(d3 / d2 > 5.0, "DP5 {d2} -> {d3}");
    assert!(r3 / r2 < 3.0, "Rosenbrock {r2} -> {r3}");
}
