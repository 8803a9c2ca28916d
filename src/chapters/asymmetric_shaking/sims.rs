//! The simulations of the chapter: the block model of `physics::block` (Coulomb or
//! viscous contact, event-driven) run on the chapter's plates, with observers that read
//! absolute velocities, the first stick and the friction direction off every segment.

use crate::numerics::hybrid::{Observer, Options, Segment};
use crate::numerics::ode::{Method, StepControl};
use crate::physics::block::{simulate_block_observed, BlockMode, BlockOptions, BlockParams, BlockRun};
use crate::physics::plate::PlateMotion;
use crate::physics::sawtooth::Snapped;

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
    /// The block model's summary (work, counts, end state).
    pub run: BlockRun,
    /// Mean block velocity over the window (m/s): `(x(t_b) - x(t_a)) / (t_b - t_a)`.
    pub mean_velocity_mps: f64,
    /// Largest absolute block velocity inside the window (m/s).
    pub v_max_mps: f64,
    /// Smallest absolute block velocity inside the window (m/s).
    pub v_min_mps: f64,
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
}

/// Plate velocity during a segment at `t`: for a plate with breakpoints (piecewise
/// constant velocity, the sawtooth) its value at the segment's midpoint, which belongs
/// to the segment's stroke even when the segment ends on a breakpoint; else at `t`.
fn plate_velocity<P: PlateMotion + ?Sized>(plate: &P, seg: &Segment<'_, 4>, t: f64) -> f64 {
    if plate.breakpoint_after(seg.t0).is_some() {
        plate.vx_mps(0.5 * (seg.t0 + seg.t1))
    } else {
        plate.vx_mps(t)
    }
}

/// The segment's state at `t`: its end states at its ends, its dense output inside.
fn state_at(seg: &Segment<'_, 4>, t: f64) -> [f64; 4] {
    if t <= seg.t0 {
        seg.y0
    } else if t >= seg.t1 {
        seg.y1
    } else {
        seg.eval(t)
    }
}

/// Absolute block velocity at `t` in a segment: relative velocity plus plate velocity.
fn abs_velocity<P: PlateMotion + ?Sized>(plate: &P, seg: &Segment<'_, 4>, t: f64) -> f64 {
    state_at(seg, t)[1] + plate_velocity(plate, seg, t) // formula: v = w + v_p
}

struct Watch<'a, P: PlateMotion + ?Sized> {
    plate: &'a P,
    window: (f64, f64),
    trace_s: (f64, f64),
    trace_dt: f64,
    tiny_s: f64,
    out: DriftRunParts,
}

#[derive(Default)]
struct DriftRunParts {
    v_max: f64,
    v_min: f64,
    first_stick: Option<f64>,
    backward_stick: bool,
    against_plate: bool,
    v_a: Option<f64>,
    v_b: Option<f64>,
    x_a: Option<f64>,
    x_b: Option<f64>,
    trace: Vec<(f64, f64, f64)>,
}

impl<P: PlateMotion + ?Sized> Observer<BlockMode, 4> for Watch<'_, P> {
    fn segment(&mut self, mode: BlockMode, seg: &Segment<'_, 4>) {
        let (a, b) = self.window;
        let o = &mut self.out;
        // Window ends: the first segment that reaches t_a, the last that reaches t_b.
        if seg.t0 <= a && a <= seg.t1 && o.v_a.is_none() {
            o.v_a = Some(abs_velocity(self.plate, seg, a));
            o.x_a = Some(state_at(seg, a)[0] + self.plate.x_m(a));
        }
        if seg.t0 <= b && b <= seg.t1 {
            o.v_b = Some(abs_velocity(self.plate, seg, b));
            o.x_b = Some(state_at(seg, b)[0] + self.plate.x_m(b));
        }
        // Segments shorter than 1e-12 T (a step onto a breakpoint from an ulp before
        // it) carry no motion: skip them. Samples below are interior points only, so
        // none depends on which side of a breakpoint an end state belongs to.
        if seg.t1 - seg.t0 < self.tiny_s {
            return;
        }
        if seg.t1 > a && seg.t0 < b {
            // Extremes: 7 interior points of the part inside the window (exact for the
            // sawtooth's stick segments, where the extremes are attained).
            let (s0, s1) = (seg.t0.max(a), seg.t1.min(b));
            for j in 1..8 {
                let v = abs_velocity(self.plate, seg, s0 + (s1 - s0) * j as f64 / 8.0);
                o.v_max = o.v_max.max(v);
                o.v_min = o.v_min.min(v);
            }
            let vp = plate_velocity(self.plate, seg, 0.5 * (seg.t0 + seg.t1));
            if mode == BlockMode::Stick && vp < 0.0 {
                o.backward_stick = true;
            }
            // SlipLeft: w < 0, friction +mu g; SlipRight: friction -mu g.
            let along = matches!((mode, vp > 0.0, vp < 0.0), (BlockMode::SlipLeft, true, _) | (BlockMode::SlipRight, _, true));
            if !along {
                o.against_plate = true;
            }
        }
        let (ta, tb) = self.trace_s;
        if seg.t1 >= ta && seg.t0 <= tb && self.trace_dt > 0.0 {
            let (s0, s1) = (seg.t0.max(ta), seg.t1.min(tb));
            let n = ((s1 - s0) / self.trace_dt).ceil().max(2.0) as usize;
            for j in 0..=n {
                // ends pulled 1e-9 of the segment inside
                let f = (j as f64 / n as f64).clamp(1e-9, 1.0 - 1e-9);
                let t = s0 + (s1 - s0) * f;
                o.trace.push((t, abs_velocity(self.plate, seg, t), plate_velocity(self.plate, seg, t)));
            }
        }
    }

    fn event(&mut self, t_s: f64, from: BlockMode, _guard: usize, _before: &[f64; 4], after: Option<(BlockMode, &[f64; 4])>) {
        if let Some((BlockMode::Stick, _)) = after {
            if from != BlockMode::Stick && self.out.first_stick.is_none() {
                self.out.first_stick = Some(t_s);
            }
        }
    }
}

/// How to run the block: closed forms (default) or integrated flows, method and steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Numerics {
    /// Use the block model's closed forms for stick and Coulomb slip.
    pub closed_forms: bool,
    /// Driver options (method, step control, event location).
    pub hybrid: Options,
    /// Guard samples per period (and longest step of integrated modes).
    pub samples_per_period: usize,
}

impl Default for Numerics {
    /// Closed forms, DP5 at rtol = atol = 1e-12 (viscous mode), located events, 64
    /// guard samples per period.
    fn default() -> Self {
        Numerics {
            closed_forms: true,
            hybrid: Options { control: StepControl::tol(1e-12, 1e-12), record_events: false, ..Options::default() },
            samples_per_period: 64,
        }
    }
}

impl Numerics {
    /// Integrated flows, DP5 with tolerance `tol`, located events.
    pub fn dopri(tol: f64) -> Self {
        Numerics { closed_forms: false, hybrid: Options { method: Method::Dopri5, control: StepControl::tol(tol, tol), ..Numerics::default().hybrid }, ..Numerics::default() }
    }

    /// Integrated flows, fixed RK4 steps of `period / steps_per_period`, events taken at
    /// the end of the step that saw them (no location).
    pub fn fixed_rk4(steps_per_period: usize, period_s: f64) -> Self {
        let h_s = period_s / steps_per_period as f64;
        Numerics {
            closed_forms: false,
            hybrid: Options { method: Method::Rk4, control: StepControl::Fixed { h_s }, locate_events: false, ..Numerics::default().hybrid },
            samples_per_period: steps_per_period,
        }
    }
}

/// Runs a block that starts at absolute velocity `v0_mps` at t = 0 (in contact, at
/// x = 0) on `plate` over `window`; traces `trace_s` every `trace_dt` (0: no trace).
pub fn run_block<P: PlateMotion + ?Sized>(
    params: &BlockParams,
    plate: &P,
    v0_mps: f64,
    window: Window,
    num: &Numerics,
    trace_s: (f64, f64),
    trace_dt: f64,
) -> DriftRun {
    // Breakpoints robust to rounding (see Snapped: the bare sawtooth can skip one).
    let plate = &Snapped(plate);
    let period = plate.period_s();
    let opts = BlockOptions {
        hybrid: num.hybrid,
        closed_forms: num.closed_forms,
        samples_per_period: num.samples_per_period,
        transient_periods: window.transient,
        record_events: false,
        start: (0.0, [-plate.x_m(0.0), v0_mps - plate.vx_mps(0.0), 0.0, 0.0]), // formula: u = x - x_p, w = v - v_p
    };
    let t_end = (window.transient + window.measured) as f64 * period;
    let win = (window.transient as f64 * period, t_end);
    let mut watch = Watch {
        plate,
        window: win,
        trace_s,
        trace_dt,
        tiny_s: 1e-12 * period,
        out: DriftRunParts { v_max: f64::NEG_INFINITY, v_min: f64::INFINITY, ..Default::default() },
    };
    let run = simulate_block_observed(params, plate, t_end, &opts, &mut watch);
    let o = watch.out;
    let mean = match (o.x_a, o.x_b) {
        (Some(xa), Some(xb)) if window.measured > 0 => (xb - xa) / (win.1 - win.0), // formula: <v> = (x(t_b) - x(t_a)) / (t_b - t_a)
        _ => f64::NAN,
    };
    DriftRun {
        run,
        mean_velocity_mps: mean,
        v_max_mps: o.v_max,
        v_min_mps: o.v_min,
        first_stick_s: o.first_stick,
        stuck_in_backward_stroke: o.backward_stick,
        friction_along_plate: !o.against_plate,
        v_window_mps: (o.v_a.unwrap_or(f64::NAN), o.v_b.unwrap_or(f64::NAN)),
        trace: o.trace,
    }
}

/// Mean block velocity over the window (m/s) of a run from rest.
pub fn drift<P: PlateMotion + ?Sized>(params: &BlockParams, plate: &P, window: Window, num: &Numerics) -> f64 {
    run_block(params, plate, 0.0, window, num, (0.0, 0.0), 0.0).mean_velocity_mps
}
