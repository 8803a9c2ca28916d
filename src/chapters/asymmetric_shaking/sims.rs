//! The simulations of the chapter: the shared block model of [`crate::physics::block`]
//! (Coulomb or viscous contact) run on the chapter's plates by the hybrid driver, with an
//! observer that reads the window's mean velocity, the velocity extremes, the first stick
//! and the friction direction off every segment.

use crate::numerics::hybrid::{Observer, Options, Outcome, Segment};
use crate::numerics::ode::{Method, Stats, StepControl};
use crate::physics::block::{
    simulate_block_observed, BlockMode, BlockOptions, BlockParams, BlockSystem,
};
use crate::physics::plate::{Biharmonic, PlateMotion, Sawtooth};
use crate::physics::sawtooth::lock_time_s;

/// The friction law of the chapter's block (the plates move horizontally only, so the
/// normal force per unit mass is g and Coulomb friction is bounded by `k = mu g`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Law {
    /// Coulomb friction: slip deceleration bound `k = mu g` (m/s^2).
    Coulomb {
        /// `mu g` (m/s^2).
        k_mps2: f64,
    },
    /// Linear viscous friction `F/m = -c (v - v_p)`.
    Viscous {
        /// `c` (1/s).
        c_per_s: f64,
    },
}

impl Law {
    /// The block's parameters: a unit normal force per unit mass (`g = 1`, exact for
    /// horizontal plates) and `mu = k`, so that `mu n = k` holds without round-off.
    fn params(self) -> BlockParams {
        match self {
            Law::Coulomb { k_mps2 } => BlockParams::coulomb(1.0, k_mps2, 0.0),
            Law::Viscous { c_per_s } => BlockParams::viscous(1.0, c_per_s, 0.0),
        }
    }
}

/// Whole periods of a run: `transient` dropped, then `measured` averaged.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Window {
    /// Periods dropped as transient.
    pub transient: usize,
    /// Periods averaged.
    pub measured: usize,
}

/// What a chapter run of the block returns.
#[derive(Debug, Clone)]
pub struct DriftRun {
    /// Mean block velocity over the window (m/s): `(x(t_b) - x(t_a)) / (t_b - t_a)`.
    pub mean_velocity_mps: f64,
    /// Largest absolute block velocity inside the window (m/s).
    pub v_max_mps: f64,
    /// Time of the first slip-to-stick event (s), if any.
    pub first_stick_s: Option<f64>,
    /// True if the block stuck during a stroke with negative plate velocity in the window.
    pub stuck_in_backward_stroke: bool,
    /// True if, in every segment of the window, the block slipped with its friction
    /// pointing along the plate's velocity (the document's "sliding relatively opposite
    /// to the direction of the instantaneous plate velocity").
    pub friction_along_plate: bool,
    /// Absolute velocity of the block at the window's ends (m/s).
    pub v_window_mps: (f64, f64),
    /// Sampled `(t, block velocity, plate velocity)` inside `trace_s` (figures).
    pub trace: Vec<(f64, f64, f64)>,
    /// Integration work (zero with closed forms).
    pub stats: Stats,
    /// Guard evaluations spent locating events.
    pub locate_evals: u64,
    /// The error budget of `mean_velocity_mps` (m/s): [`mean_velocity_budget_mps`].
    pub budget_mps: f64,
}

/// The error budget of a window's mean velocity `(x(t_b) - x(t_a))/(t_b - t_a)` (m/s)
/// for a run from 0 to `t_b` whose block speed stays below `v` (m/s), in `segments`
/// segments (`in_window` of them inside the window).
///
/// - Rounding (closed forms and integrated flows alike): each segment adds an increment
///   to x, rounded by eps |x| <= eps v t_b, and its length t_1 - t_0 is rounded by
///   eps t_b, moving x by eps v t_b again; the window's two ends add two more, so the
///   difference carries 2 eps v t_b (in_window + 2). A velocity error made before the
///   window (eps v per segment, a stick resets it, slip contracts it) moves the mean by
///   at most segments eps v.
/// - Integration (`tol = (rtol, atol)`, integrated flows over `steps` accepted steps):
///   each step's local error is below atol + rtol |y| per component in the RMS norm of
///   the 4 components, so at most 2 (atol + rtol |y|) in any one; position errors add
///   up, a velocity error adds at most 1/c of itself to x when viscous friction `c`
///   (1/s) damps it (`c` = 0: closed forms, no integration error).
///
/// The located switches' own overshoot (4 ulps of t at a change of acceleration mu g)
/// is budgeted by the chapter's tolerances.
pub fn mean_velocity_budget_mps(
    v: f64,
    (t_a, t_b): (f64, f64),
    (segments, in_window): (u64, u64),
    tol: Option<(f64, f64)>,
    (steps, c_per_s): (u64, f64),
) -> f64 {
    let eps = f64::EPSILON;
    let dt = t_b - t_a;
    let rounding = 2.0 * eps * v * t_b * (in_window as f64 + 2.0) / dt + segments as f64 * eps * v; // formula: 2 eps v t_b (n_w + 2)/dt + n eps v
    let integration = match tol {
        Some((rtol, atol)) if c_per_s > 0.0 => {
            let per_step = 2.0 * (atol + rtol * v * t_b) + 2.0 * (atol + rtol * v) / c_per_s; // formula: 2 (atol + rtol |x|) + 2 (atol + rtol |v|)/c
            steps as f64 * per_step / dt
        }
        _ => 0.0,
    };
    rounding + integration
}

/// The segment's absolute `(x, v)` at `t`: its end states at its ends, its dense output
/// inside, with the plate of the segment's own piece.
fn state_at<P: PlateMotion + ?Sized>(
    sys: &BlockSystem<'_, P>,
    seg: &Segment<'_, 4>,
    t: f64,
) -> (f64, f64) {
    let y = if t <= seg.t0 {
        seg.y0
    } else if t >= seg.t1 {
        seg.y1
    } else {
        seg.eval(t)
    };
    let t = t.clamp(seg.t0, seg.t1);
    let a = sys.absolute_in_piece(seg.t0, t, &y);
    (a[0], a[1])
}

/// Plate velocity (m/s) at `t` in the piece of the segment `[t0, t1]`.
fn plate_velocity<P: PlateMotion + ?Sized>(sys: &BlockSystem<'_, P>, t0: f64, t: f64) -> f64 {
    sys.absolute_in_piece(t0, t, &[0.0; 4])[1]
}

struct Watch<'b, 'a, P: PlateMotion + ?Sized> {
    sys: &'b BlockSystem<'a, P>,
    window: (f64, f64),
    trace_s: (f64, f64),
    trace_dt: f64,
    v_max: f64,
    v_min: f64,
    first_stick: Option<f64>,
    backward_stick: bool,
    against_plate: bool,
    ends: [Option<(f64, f64)>; 2],
    trace: Vec<(f64, f64, f64)>,
    in_window: u64,
}

impl<P: PlateMotion + ?Sized> Observer<BlockMode, 4> for Watch<'_, '_, P> {
    fn segment(&mut self, mode: BlockMode, seg: &Segment<'_, 4>) {
        let sys = self.sys;
        let (a, b) = self.window;
        // Window ends: the first segment that reaches t_a, the last that reaches t_b.
        if seg.t0 <= a && a <= seg.t1 && self.ends[0].is_none() {
            self.ends[0] = Some(state_at(sys, seg, a));
        }
        if seg.t0 <= b && b <= seg.t1 {
            self.ends[1] = Some(state_at(sys, seg, b));
        }
        if seg.t1 > a && seg.t0 < b && seg.t1 > seg.t0 {
            self.in_window += 1;
            // Extremes: ends and 7 interior points of the part inside the window.
            let (s0, s1) = (seg.t0.max(a), seg.t1.min(b));
            for j in 0..=8 {
                let v = state_at(sys, seg, s0 + (s1 - s0) * j as f64 / 8.0).1;
                self.v_max = self.v_max.max(v);
                self.v_min = self.v_min.min(v);
            }
            let vp = plate_velocity(sys, seg.t0, 0.5 * (seg.t0 + seg.t1));
            if mode == BlockMode::Stick && vp < 0.0 {
                self.backward_stick = true;
            }
            // SlipLeft (slower than the plate): friction +mu g; SlipRight: -mu g.
            let along = matches!(
                (mode, vp > 0.0, vp < 0.0),
                (BlockMode::SlipLeft, true, _) | (BlockMode::SlipRight, _, true)
            );
            self.against_plate |= !along;
        }
        let (ta, tb) = self.trace_s;
        if seg.t1 >= ta && seg.t0 <= tb && self.trace_dt > 0.0 {
            let (s0, s1) = (seg.t0.max(ta), seg.t1.min(tb));
            let n = ((s1 - s0) / self.trace_dt).ceil().max(1.0) as usize;
            for j in 0..=n {
                let t = s0 + (s1 - s0) * j as f64 / n as f64;
                let vp = plate_velocity(sys, seg.t0, t.clamp(seg.t0, seg.t1));
                self.trace.push((t, state_at(sys, seg, t).1, vp));
            }
        }
    }

    fn event(
        &mut self,
        t_s: f64,
        from: BlockMode,
        _guard: usize,
        _before: &[f64; 4],
        after: Option<(BlockMode, &[f64; 4])>,
    ) {
        if let Some((to, _)) = after {
            if to == BlockMode::Stick && from != BlockMode::Stick && self.first_stick.is_none() {
                self.first_stick = Some(t_s);
            }
        }
    }
}

/// How to run the block: closed forms (default) or integrated flows, method and steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Numerics {
    /// Use the closed forms of stick and Coulomb slip.
    pub closed_forms: bool,
    /// Driver options (method, step control, event location).
    pub hybrid: Options,
    /// Guard samples per period (and longest step) on smooth plates; a piecewise-constant
    /// plate needs one (see [`run_block`]).
    pub samples_per_period: usize,
}

impl Default for Numerics {
    /// Closed forms, DP5 at rtol = atol = 1e-12 (viscous mode), located events, 64
    /// guard samples per period.
    fn default() -> Self {
        Numerics {
            closed_forms: true,
            hybrid: Options {
                control: StepControl::tol(1e-12, 1e-12),
                record_events: false,
                ..Options::default()
            },
            samples_per_period: 64,
        }
    }
}

impl Numerics {
    /// Integrated flows, DP5 with tolerance `tol`, located events.
    pub fn dopri(tol: f64) -> Self {
        let hybrid = Options {
            method: Method::Dopri5,
            control: StepControl::tol(tol, tol),
            ..Numerics::default().hybrid
        };
        Numerics {
            closed_forms: false,
            hybrid,
            ..Numerics::default()
        }
    }

    /// Integrated flows, fixed RK4 steps of `period / steps_per_period`, switches taken
    /// at the end of the step that saw them (no location).
    pub fn fixed_rk4(steps_per_period: usize, period_s: f64) -> Self {
        let h_s = period_s / steps_per_period as f64;
        let hybrid = Options {
            method: Method::Rk4,
            control: StepControl::Fixed { h_s },
            locate_events: false,
            ..Numerics::default().hybrid
        };
        Numerics {
            closed_forms: false,
            hybrid,
            samples_per_period: steps_per_period,
        }
    }
}

/// True if the plate has breakpoints and no acceleration between them (the sawtooth:
/// checked on 64 points of a period). Then every guard is linear in time within a piece
/// and crosses zero at most once, and the steps end on the breakpoints anyway: one
/// guard sample per period is enough.
fn piecewise_constant<P: PlateMotion + ?Sized>(plate: &P) -> bool {
    let period = plate.period_s();
    plate.breakpoint_after(0.0).is_some()
        && (0..64).all(|i| plate.ax_mps2((i as f64 + 0.5) * period / 64.0) == 0.0)
}

/// The window's ends on the plate's own breakpoint floats when there are some (so no
/// sliver step is left between the last breakpoint and the end): `(t_a, t_b)` (s).
fn window_ends<P: PlateMotion + ?Sized>(plate: &P, window: Window) -> (f64, f64) {
    let period = plate.period_s();
    let on_grid = |n: usize| {
        let t = n as f64 * period;
        match plate.breakpoint_after(t - 1e-9 * period) {
            Some(b) if (b - t).abs() <= 1e-9 * period => b,
            _ => t,
        }
    };
    (
        on_grid(window.transient),
        on_grid(window.transient + window.measured),
    )
}

/// The driver's options for a run from `v0_mps` at rest-frame start on `plate`.
fn block_options<P: PlateMotion + ?Sized>(
    plate: &P,
    v0_mps: f64,
    window: Window,
    num: &Numerics,
) -> BlockOptions {
    // Fixed steps keep their own step length; otherwise a piecewise-constant plate
    // needs one guard sample per period.
    let fixed = matches!(num.hybrid.control, StepControl::Fixed { .. });
    let samples_per_period = if piecewise_constant(plate) && !fixed {
        1
    } else {
        num.samples_per_period
    };
    BlockOptions {
        hybrid: num.hybrid,
        closed_forms: num.closed_forms,
        samples_per_period,
        transient_periods: window.transient,
        record_events: false,
        start: (0.0, [0.0, v0_mps - plate.vx_mps(0.0), 0.0, 0.0]),
    }
}

/// Runs a block that starts at x = 0 with velocity `v0_mps` at t = 0 on `plate` over
/// `window`; traces `trace_s` every `trace_dt` (0: no trace).
pub fn run_block<P: PlateMotion + ?Sized>(
    law: Law,
    plate: &P,
    v0_mps: f64,
    window: Window,
    num: &Numerics,
    trace_s: (f64, f64),
    trace_dt: f64,
) -> DriftRun {
    let params = law.params();
    let sys = BlockSystem::new(params, plate);
    let win = window_ends(plate, window);
    let mut w = Watch {
        sys: &sys,
        window: win,
        trace_s,
        trace_dt,
        v_max: f64::NEG_INFINITY,
        v_min: f64::INFINITY,
        first_stick: None,
        backward_stick: false,
        against_plate: false,
        ends: [None, None],
        trace: Vec::new(),
        in_window: 0,
    };
    let opts = block_options(plate, v0_mps, window, num);
    let run = simulate_block_observed(&params, plate, win.1, &opts, &mut w);
    let mean = match w.ends {
        [Some(ya), Some(yb)] if window.measured > 0 && run.outcome == Outcome::Completed => {
            (yb.0 - ya.0) / (win.1 - win.0)
        } // formula: <v> = (x(t_b) - x(t_a)) / (t_b - t_a)
        _ => f64::NAN,
    };
    let speed = [w.v_max, w.v_min, v0_mps]
        .iter()
        .fold(0.0f64, |m, v| if v.is_finite() { m.max(v.abs()) } else { m });
    let tol = match num.hybrid.control {
        StepControl::Adaptive { rtol, atol, .. } => Some((rtol, atol)),
        _ => None,
    };
    let c_per_s = match law {
        Law::Viscous { c_per_s } => c_per_s,
        Law::Coulomb { .. } => 0.0,
    };
    let budget_mps = mean_velocity_budget_mps(
        speed,
        win,
        (run.segments, w.in_window),
        tol,
        (run.stats.accepted, c_per_s),
    );
    DriftRun {
        mean_velocity_mps: mean,
        v_max_mps: w.v_max,
        first_stick_s: w.first_stick,
        stuck_in_backward_stroke: w.backward_stick,
        friction_along_plate: !w.against_plate,
        v_window_mps: (
            w.ends[0].map_or(f64::NAN, |y| y.1),
            w.ends[1].map_or(f64::NAN, |y| y.1),
        ),
        trace: w.trace,
        stats: run.stats,
        locate_evals: run.locate_evals,
        budget_mps,
    }
}

/// Mean block velocity over the window (m/s) of a run from rest.
pub fn drift<P: PlateMotion + ?Sized>(law: Law, plate: &P, window: Window, num: &Numerics) -> f64 {
    run_block(law, plate, 0.0, window, num, (0.0, 0.0), 0.0).mean_velocity_mps
}

/// Whole periods for a block started at rest to settle on the bi-harmonic drive: the
/// distance to the always-slipping orbit decays like `exp(-4 n / Gamma)` per period
/// (measured: a factor 60 per 10 periods at Gamma = 10, 3.8 at Gamma = 30), so
/// `10 + 8 Gamma` periods take an O(V) start below 1e-13 m/s.
pub fn slip_transient(gamma: f64) -> usize {
    10 + (8.0 * gamma).ceil() as usize
}

/// Whole periods from rest to the first stick (closed form) plus two: the window after
/// it is periodic. (One period of margin: when the block reaches the slow speed exactly
/// at a stroke's end, rounding decides whether it locks then or a period later.)
pub fn transient(saw: &Sawtooth, k: f64) -> usize {
    (lock_time_s(saw, k, 0.0) / saw.period_s()).floor() as usize + 2
}

/// Mean velocity (m/s) of a block from rest on `saw` under `law`, averaged over
/// `measured` periods after the [`transient`] for friction `k_mps2 = mu g` (m/s^2).
pub fn drift_after_lock(
    law: Law,
    saw: &Sawtooth,
    k_mps2: f64,
    measured: usize,
    num: &Numerics,
) -> f64 {
    let window = Window {
        transient: transient(saw, k_mps2),
        measured,
    };
    drift(law, saw, window, num)
}

/// A sawtooth with the same speeds whose fast stroke lasts `ratio (a + b)/k`.
pub fn scaled(saw: &Sawtooth, k: f64, ratio: f64) -> Sawtooth {
    let tf = ratio * (saw.slow_velocity_mps + saw.fast_velocity_mps) / k;
    Sawtooth {
        slow_duration_s: tf * saw.fast_velocity_mps / saw.slow_velocity_mps,
        ..*saw
    } // formula: T_s = T_f b / a
}

/// The bi-harmonic plate with velocity amplitude `v` and drive number `gamma` for `k`.
pub fn biharmonic(v: f64, gamma: f64, eps: f64, k: f64) -> Biharmonic {
    Biharmonic {
        velocity_amplitude_mps: v,
        omega_rad_s: gamma * k / v,
        asymmetry: eps,
    } // formula: Gamma = V omega / (mu g)
}
