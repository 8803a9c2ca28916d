//! Tests of the hybrid driver against closed forms.
use super::*;
use crate::numerics::events::Direction;

const G: f64 = 9.81;

/// A ball in free fall above a fixed floor: y = [height m, velocity m/s].
/// Guard 0: height (falling). On impact: restitution `e` (0: stop), or stop.
struct Ball {
    e: f64,
    closed_form: bool,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum BallMode {
    Flight,
}

impl HybridSystem<2> for Ball {
    type Mode = BallMode;
    type Stop = &'static str;
    fn flow(&self, _m: BallMode, _t: f64, y: &[f64; 2]) -> [f64; 2] {
        [y[1], -G]
    }
    fn exact(&self, _m: BallMode, t0: f64, y0: &[f64; 2], t: f64) -> Option<[f64; 2]> {
        let s = t - t0;
        self.closed_form
            .then(|| [y0[0] + y0[1] * s - 0.5 * G * s * s, y0[1] - G * s])
    }
    fn max_step(&self, _m: BallMode, _t: f64, y: &[f64; 2]) -> f64 {
        // Leaving the floor: stop at the apex (time v/g), so the height guard is seen
        // positive before it can fall back through zero. Otherwise any step (closed
        // form: sampled every 0.05 s).
        let apex = if y[0] <= 0.0 && y[1] > 0.0 {
            y[1] / G
        } else {
            f64::INFINITY
        };
        apex.min(if self.closed_form {
            0.05
        } else {
            f64::INFINITY
        })
    }
    fn guard_count(&self, _m: BallMode) -> usize {
        1
    }
    fn guard(&self, _m: BallMode, _i: usize, _t: f64, y: &[f64; 2]) -> f64 {
        y[0]
    }
    fn direction(&self, _m: BallMode, _i: usize) -> Direction {
        Direction::Falling
    }
    fn on_event(
        &self,
        m: BallMode,
        _i: usize,
        _t: f64,
        y: &[f64; 2],
    ) -> Transition<BallMode, &'static str, 2> {
        if self.e == 0.0 {
            Transition::Stop("landed")
        } else {
            Transition::To {
                mode: m,
                state: [0.0, -self.e * y[1]],
            }
        }
    }
}

#[test]
fn dropped_ball_impact_time_to_1e_12() {
    // Closed form: t = sqrt(2 h / g). DP5 integrates a quadratic exactly and its dense
    // output reproduces it, so the only error is the root finder's (a few ulps).
    for h in [0.1, 1.0, 10.0] {
        for closed_form in [false, true] {
            let ball = Ball {
                e: 0.0,
                closed_form,
            };
            let run = simulate(
                &ball,
                BallMode::Flight,
                0.0,
                [h, 0.0],
                100.0,
                &Options::default(),
                &mut (),
            );
            assert_eq!(run.outcome, Outcome::Stopped("landed"));
            let exact = (2.0 * h / G).sqrt();
            assert!(
                (run.t_end_s - exact).abs() < 1e-12,
                "h {h} closed {closed_form}: {} vs {exact}",
                run.t_end_s
            );
        }
    }
}

#[test]
fn bouncing_ball_with_restitution_ends_in_zeno_at_the_accumulation_time() {
    // t_inf = t1 + (2 v1 / g) e / (1 - e), t1 = sqrt(2h/g), v1 = g t1.
    let (h, e) = (1.0, 0.5);
    let t1 = (2.0 * h / G).sqrt();
    let t_inf = t1 + 2.0 * t1 * e / (1.0 - e);
    for closed_form in [true, false] {
        let ball = Ball { e, closed_form };
        let run = simulate(
            &ball,
            BallMode::Flight,
            0.0,
            [h, 0.0],
            10.0,
            &Options::default(),
            &mut (),
        );
        let Outcome::Zeno {
            t_s,
            events,
            window_s,
        } = run.outcome
        else {
            panic!("expected Zeno, got {:?}", run.outcome)
        };
        // Either 100 events inside the window or accumulation below the resolution of t.
        assert!((1..=100).contains(&events), "{events}");
        // The remaining flights after the guard fires sum to less than the window.
        assert!(
            t_s <= t_inf + 1e-12 && t_inf - t_s < window_s,
            "closed {closed_form}: {t_s} vs {t_inf}"
        );
        // Flights shrink by e = 0.5 from 2 t1 e = 0.45 s; reaching the resolution of t
        // (ulp(1.35) = 2.2e-16 s) takes log2(0.45 / 2.2e-16) = 51 bounces, and the
        // window rule stops at 100 events inside 1 us plus the log2(0.45 / 1e-6) = 19
        // longer flights before them: the count lies between 45 and 125.
        assert!((45..=125).contains(&run.event_count), "{}", run.event_count);
    }
}

#[test]
fn event_blind_baseline_places_the_event_late() {
    // Without location the event is taken at the end of the step that saw the sign
    // change: late by up to one step (0.05 s here).
    let ball = Ball {
        e: 0.0,
        closed_form: false,
    };
    let opts = Options {
        method: Method::Rk4,
        control: StepControl::Fixed { h_s: 0.05 },
        locate_events: false,
        ..Options::default()
    };
    let run = simulate(
        &ball,
        BallMode::Flight,
        0.0,
        [1.0, 0.0],
        10.0,
        &opts,
        &mut (),
    );
    let exact = (2.0 / G).sqrt();
    assert!(
        run.t_end_s > exact && run.t_end_s - exact <= 0.05 + 1e-12,
        "{}",
        run.t_end_s
    );
    let located = simulate(
        &ball,
        BallMode::Flight,
        0.0,
        [1.0, 0.0],
        10.0,
        &Options {
            locate_events: true,
            ..opts
        },
        &mut (),
    );
    assert!((located.t_end_s - exact).abs() < 1e-12);
}

/// Rotation y = (cos t, -sin t) with two guards crossing at the same time 3 pi / 2
/// (y0 rising and a copy of it), and one crossing earlier in the wrong direction.
struct Twin;

impl HybridSystem<2> for Twin {
    type Mode = u8;
    type Stop = usize;
    fn flow(&self, _m: u8, _t: f64, y: &[f64; 2]) -> [f64; 2] {
        [y[1], -y[0]]
    }
    fn guard_count(&self, _m: u8) -> usize {
        3
    }
    fn guard(&self, _m: u8, i: usize, _t: f64, y: &[f64; 2]) -> f64 {
        match i {
            0 => y[1], // -sin t: starts at 0, falls through 0 at 2 pi
            _ => y[0], // cos t: falls at pi / 2, rises at 3 pi / 2
        }
    }
    fn direction(&self, _m: u8, i: usize) -> Direction {
        match i {
            0 => Direction::Falling, // falls at 2 pi: later than the others
            _ => Direction::Rising,
        }
    }
    fn on_event(&self, _m: u8, i: usize, _t: f64, _y: &[f64; 2]) -> Transition<u8, usize, 2> {
        Transition::Stop(i)
    }
}

#[test]
fn directions_respected_and_ties_go_to_the_lowest_index() {
    let run = simulate(
        &Twin,
        0,
        0.0,
        [1.0, 0.0],
        10.0,
        &Options::default(),
        &mut (),
    );
    assert_eq!(run.outcome, Outcome::Stopped(1));
    assert!(
        (run.t_end_s - 1.5 * std::f64::consts::PI).abs() < 1e-9,
        "{}",
        run.t_end_s
    );
}

/// y' = +1 on [k, k + 1/2), -1 on [k + 1/2, k + 1): a triangle wave with kinks at the
/// breakpoints; the mode's sign is the slope's. Modes +-3 also have a guard, `y`
/// rising, whose event latches the mode to +-1.
struct Triangle;

impl HybridSystem<1> for Triangle {
    type Mode = i8;
    type Stop = ();
    fn flow(&self, m: i8, _t: f64, _y: &[f64; 1]) -> [f64; 1] {
        [f64::from(m.signum())]
    }
    fn guard_count(&self, m: i8) -> usize {
        usize::from(m.abs() == 3)
    }
    fn guard(&self, _m: i8, _i: usize, _t: f64, y: &[f64; 1]) -> f64 {
        y[0]
    }
    fn direction(&self, _m: i8, _i: usize) -> Direction {
        Direction::Rising
    }
    fn on_event(&self, m: i8, _i: usize, _t: f64, y: &[f64; 1]) -> Transition<i8, (), 1> {
        Transition::To {
            mode: m.signum(),
            state: *y,
        }
    }
    fn breakpoint_after(&self, t: f64) -> Option<f64> {
        Some(((t * 2.0).floor() + 1.0) / 2.0)
    }
    fn on_breakpoint(&self, m: i8, _t: f64, y: &[f64; 1]) -> Transition<i8, (), 1> {
        Transition::To {
            mode: -m,
            state: *y,
        }
    }
}

#[test]
fn breakpoints_are_stepped_onto_exactly() {
    let mut ends = Vec::new();
    struct Ends<'a>(&'a mut Vec<(f64, f64)>);
    impl Observer<i8, 1> for Ends<'_> {
        fn segment(&mut self, _m: i8, s: &Segment<'_, 1>) {
            self.0.push((s.t0, s.t1));
        }
    }
    let run = simulate(
        &Triangle,
        1,
        0.0,
        [0.0],
        3.25,
        &Options::default(),
        &mut Ends(&mut ends),
    );
    assert_eq!(run.outcome, Outcome::Completed);
    // Triangle wave at 3.25: rising from 0 at t = 3.0 for 0.25 s.
    assert!((run.y_end[0] - 0.25).abs() < 1e-14, "{}", run.y_end[0]);
    assert_eq!(run.event_count, 6);
    // Segments tile the interval without gaps.
    for w in ends.windows(2) {
        assert_eq!(w[0].1, w[1].0);
    }
    assert_eq!(ends.first().unwrap().0, 0.0);
    assert_eq!(ends.last().unwrap().1, 3.25);
    let total: f64 = run.mode_time_s.iter().map(|(_, t)| t).sum();
    assert!((total - 3.25).abs() < 1e-14);
}

/// Triangle wave whose model asks for steps that end an ulp or two before each
/// breakpoint: the driver must go onto the breakpoint, not leave a sliver step that
/// the adaptive integrator would refuse.
struct SliverTriangle;

impl HybridSystem<1> for SliverTriangle {
    type Mode = i8;
    type Stop = ();
    fn flow(&self, m: i8, t: f64, y: &[f64; 1]) -> [f64; 1] {
        Triangle.flow(m, t, y)
    }
    fn guard_count(&self, _m: i8) -> usize {
        0
    }
    fn guard(&self, _m: i8, _i: usize, _t: f64, _y: &[f64; 1]) -> f64 {
        unreachable!()
    }
    fn direction(&self, _m: i8, _i: usize) -> Direction {
        Direction::Either
    }
    fn on_event(&self, _m: i8, _i: usize, _t: f64, _y: &[f64; 1]) -> Transition<i8, (), 1> {
        unreachable!()
    }
    fn max_step(&self, _m: i8, t: f64, _y: &[f64; 1]) -> f64 {
        let b = self.breakpoint_after(t).unwrap();
        let short = f64::from_bits((b - t).to_bits() - 2);
        if short > 0.0 {
            short
        } else {
            f64::INFINITY
        }
    }
    fn breakpoint_after(&self, t: f64) -> Option<f64> {
        Triangle.breakpoint_after(t)
    }
    fn on_breakpoint(&self, m: i8, t: f64, y: &[f64; 1]) -> Transition<i8, (), 1> {
        Triangle.on_breakpoint(m, t, y)
    }
}

#[test]
fn no_sliver_steps_before_breakpoints() {
    let run = simulate(
        &SliverTriangle,
        1,
        0.0,
        [0.0],
        3.25,
        &Options::default(),
        &mut (),
    );
    assert_eq!(run.outcome, Outcome::Completed);
    assert!((run.y_end[0] - 0.25).abs() < 1e-14, "{}", run.y_end[0]);
    assert_eq!(run.event_count, 6);
}

#[test]
fn an_event_located_on_a_breakpoint_is_followed_by_the_breakpoint() {
    // The triangle wave from y = -1/2 in mode 3 (slope +1, guard y rising): DP5
    // integrates y' = 1 exactly, so y reaches 0 exactly on the breakpoint t = 1/2; the
    // event latches mode 1, then the breakpoint must flip it to -1: y(1) = -1/2 exactly
    // (a lost breakpoint would give +1/2).
    let run = simulate(&Triangle, 3, 0.0, [-0.5], 1.0, &Options::default(), &mut ());
    assert_eq!(run.outcome, Outcome::Completed);
    assert_eq!(run.mode_end, -1);
    assert!((run.y_end[0] + 0.5).abs() < 1e-14, "{}", run.y_end[0]);
}

mod hidden_and_non_finite;
