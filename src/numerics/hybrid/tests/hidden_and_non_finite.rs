//! Tests of the driver on what the end-point sign test cannot see: a guard's short
//! excursion inside one step, and a guard or closed form that stops being finite.
use super::super::*;
use crate::numerics::events::Direction;

/// A point moving at unit speed, y = t, with one guard `(y - c)^2 - w^2` (falling) that
/// dips below zero on `(c - w, c + w)` and is positive at both ends of any step that
/// spans the dip. Max step 0.25 s: the dip lies inside one step.
struct Dip {
    c: f64,
    w: f64,
}

impl HybridSystem<1> for Dip {
    type Mode = u8;
    type Stop = f64;
    fn flow(&self, _m: u8, _t: f64, _y: &[f64; 1]) -> [f64; 1] {
        [1.0]
    }
    fn guard_count(&self, _m: u8) -> usize {
        1
    }
    fn guard(&self, _m: u8, _i: usize, _t: f64, y: &[f64; 1]) -> f64 {
        (y[0] - self.c) * (y[0] - self.c) - self.w * self.w
    }
    fn direction(&self, _m: u8, _i: usize) -> Direction {
        Direction::Falling
    }
    fn on_event(&self, _m: u8, _i: usize, t: f64, _y: &[f64; 1]) -> Transition<u8, f64, 1> {
        Transition::Stop(t)
    }
    fn max_step(&self, _m: u8, _t: f64, _y: &[f64; 1]) -> f64 {
        0.25
    }
}

#[test]
fn a_short_excursion_inside_one_step_is_found_only_by_the_certified_search() {
    // The end-point test sees the guard positive at both ends of the step that holds
    // the dip and runs on; the certified search stops at the first root, c - w.
    for method in [Method::Dop853, Method::Dopri5, Method::Rk4] {
        for (c, w) in [(0.6, 0.01), (0.37, 1e-4)] {
            let sys = Dip { c, w };
            let run_with = |certify: bool| {
                let opts = Options {
                    method,
                    control: if method == Method::Rk4 {
                        StepControl::Fixed { h_s: 0.25 }
                    } else {
                        StepControl::tol(1e-10, 1e-10)
                    },
                    certify,
                    ..Options::default()
                };
                simulate(&sys, 0u8, 0.0, [0.0], 1.0, &opts, &mut ())
            };
            let blind = run_with(false);
            assert_eq!(blind.outcome, Outcome::Completed, "{method:?} {c}");
            let run = run_with(true);
            match run.outcome {
                Outcome::Stopped(t) => assert!((t - (c - w)).abs() < 1e-12, "{t}"),
                other => panic!("{method:?} dip at {c}: {other:?}"),
            }
            assert_eq!(run.certify.hidden_found, 1);
        }
    }
}

/// x' = -1 from x = 1 (x = 0 at t = 1), sampled every 0.1 s. Guard 0 is sqrt(x) + 1
/// (never crosses zero; NaN once x < 0). Closed form: the state itself is
/// sqrt(1 - t) (NaN after t = 1) and the guard is x + 1.
struct Root {
    closed_form: bool,
}

impl HybridSystem<1> for Root {
    type Mode = ();
    type Stop = ();
    fn flow(&self, _m: (), _t: f64, _y: &[f64; 1]) -> [f64; 1] {
        [-1.0]
    }
    fn exact(&self, _m: (), _t0: f64, _y0: &[f64; 1], t: f64) -> Option<[f64; 1]> {
        self.closed_form.then(|| [(1.0 - t).sqrt()])
    }
    fn max_step(&self, _m: (), _t: f64, _y: &[f64; 1]) -> f64 {
        0.1
    }
    fn guard_count(&self, _m: ()) -> usize {
        1
    }
    fn guard(&self, _m: (), _i: usize, _t: f64, y: &[f64; 1]) -> f64 {
        if self.closed_form {
            y[0] + 1.0
        } else {
            y[0].sqrt() + 1.0
        }
    }
    fn direction(&self, _m: (), _i: usize) -> Direction {
        Direction::Falling
    }
    fn on_event(&self, _m: (), _i: usize, _t: f64, y: &[f64; 1]) -> Transition<(), (), 1> {
        Transition::To {
            mode: (),
            state: *y,
        }
    }
}

#[test]
fn a_non_finite_guard_or_closed_form_ends_the_run_where_it_arose() {
    // Both variants go NaN at the first sample past t = 1 (the steps end on multiples
    // of 0.1 s up to rounding): the outcome names that time, inside (1, 1.1 + 1e-9].
    for closed_form in [false, true] {
        let run = simulate(
            &Root { closed_form },
            (),
            0.0,
            [1.0],
            3.0,
            &Options::default(),
            &mut (),
        );
        match run.outcome {
            Outcome::Failed(OdeError::NonFinite { t_s }) => {
                assert!(
                    t_s > 1.0 && t_s <= 1.1 + 1e-9,
                    "closed {closed_form}: {t_s}"
                )
            }
            ref o => panic!("closed {closed_form}: {o:?}"),
        }
    }
    // Started at a NaN state: ends at once, at the start time.
    let run = simulate(
        &Root { closed_form: false },
        (),
        0.5,
        [f64::NAN],
        3.0,
        &Options::default(),
        &mut (),
    );
    assert_eq!(
        run.outcome,
        Outcome::Failed(OdeError::NonFinite { t_s: 0.5 })
    );
}

#[test]
fn a_nan_rtol_ends_the_run_at_its_start_with_the_range_named() {
    let opts = Options {
        control: crate::numerics::ode::StepControl::tol(f64::NAN, 1e-10),
        ..Options::default()
    };
    for closed_form in [false, true] {
        let run = simulate(&Root { closed_form }, (), 0.0, [1.0], 1.0, &opts, &mut ());
        match run.outcome {
            Outcome::Failed(e @ OdeError::InvalidControl { name: "rtol", .. }) => {
                assert!(e.to_string().contains("[0, 1]"), "{e}")
            }
            o => panic!("{o:?}"),
        }
        assert_eq!((run.t_end_s, run.stats.rhs_evals), (0.0, 0));
    }
}
