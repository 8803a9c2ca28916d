//! Running the block: [`simulate_block`] and the summary [`BlockRun`].

use super::{BlockMode, BlockParams, BlockStop, BlockSystem};
use crate::numerics::hybrid::{simulate, Observer, Options, Outcome, Segment, Transition};

/// Event-time tolerance of a block run from `t0_s` to `t_end_s` (s): 4 ulps of its
/// largest time when every time of the run is below 1 s, where the driver's default
/// (4 ulps of max(t, 1 s)) would be coarser than the floating-point times allow; `None`
/// (the default, 4 ulps of each event's own time) otherwise.
pub fn time_tolerance_of_run(t0_s: f64, t_end_s: f64) -> Option<f64> {
    let t_max = t0_s.abs().max(t_end_s.abs());
    (t_max < 1.0 && t_max > 0.0).then_some(4.0 * f64::EPSILON * t_max) // formula: 4 eps max|t|
}
use crate::numerics::ode::Stats;
use crate::physics::plate::PlateMotion;

/// Options of a block run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlockOptions {
    /// The hybrid driver's options (method, tolerances, event location, Zeno guard).
    pub hybrid: Options,
    /// Use the closed forms of stick, Coulomb slip and flight (see the module docs).
    pub closed_forms: bool,
    /// Guard samples per plate period in closed-form modes; also the longest step of
    /// integrated modes is `period / samples_per_period`.
    pub samples_per_period: usize,
    /// Whole periods dropped as transient before the averaging window starts.
    pub transient_periods: usize,
    /// Keep the list of events inside the averaging window ([`BlockRun::events`]).
    pub record_events: bool,
    /// Time (s) and relative state `[u, w, h, vh]` of the start; `h = vh = 0` starts on
    /// the plate (in the contact mode that `w` and the plate's acceleration imply).
    pub start: (f64, [f64; 4]),
}

impl Default for BlockOptions {
    /// Closed forms, 64 guard samples per period, 10 transient periods, events
    /// recorded, the block at rest on the plate at t = 0; the driver's default options
    /// without its own event list (the block keeps its own).
    fn default() -> Self {
        BlockOptions {
            hybrid: Options {
                record_events: false,
                ..Options::default()
            },
            closed_forms: true,
            samples_per_period: 64,
            transient_periods: 10,
            record_events: true,
            start: (0.0, [0.0; 4]),
        }
    }
}

/// What kind of switch an event is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum EventKind {
    /// Contact to flight (the normal force reached zero, or the plate jumped away).
    Takeoff,
    /// Flight to contact (an impact; may lead straight back to flight).
    Landing,
    /// Stick to slip (the needed force left the friction cone).
    StickToSlip,
    /// Slip to stick (the relative velocity reached zero inside the cone).
    SlipToStick,
    /// Slip right to slip left or back (relative velocity through zero outside the cone).
    Reversal,
    /// A mode change at a plate breakpoint (velocity jump of the plate).
    Breakpoint,
}

/// One event of a block run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlockEvent {
    /// Time (s).
    pub t_s: f64,
    /// Kind.
    pub kind: EventKind,
    /// Mode before.
    pub from: BlockMode,
    /// Mode after.
    pub to: BlockMode,
    /// Relative state `[u, w, h, vh]` before the reset.
    pub before: [f64; 4],
    /// Relative state after the reset.
    pub after: [f64; 4],
}

/// Event counts.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct EventCounts {
    /// Take-offs.
    pub takeoffs: usize,
    /// Landings (impacts).
    pub landings: usize,
    /// Stick to slip.
    pub stick_to_slip: usize,
    /// Slip to stick.
    pub slip_to_stick: usize,
    /// Slip reversals.
    pub reversals: usize,
    /// Mode changes at plate breakpoints.
    pub breakpoints: usize,
}

impl EventCounts {
    fn add(&mut self, kind: EventKind) {
        match kind {
            EventKind::Takeoff => self.takeoffs += 1,
            EventKind::Landing => self.landings += 1,
            EventKind::StickToSlip => self.stick_to_slip += 1,
            EventKind::SlipToStick => self.slip_to_stick += 1,
            EventKind::Reversal => self.reversals += 1,
            EventKind::Breakpoint => self.breakpoints += 1,
        }
    }
}

/// Fraction of the averaging window spent in each mode.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ModeFractions {
    /// Sticking.
    pub stick: f64,
    /// Slipping right.
    pub slip_right: f64,
    /// Slipping left.
    pub slip_left: f64,
    /// Viscous contact.
    pub viscous: f64,
    /// Flight.
    pub flight: f64,
}

/// The summary of a block run.
#[derive(Debug, Clone)]
pub struct BlockRun {
    /// How the run ended.
    pub outcome: Outcome<BlockStop>,
    /// End time (s).
    pub t_end_s: f64,
    /// Relative state at the end.
    pub y_end: [f64; 4],
    /// Mode at the end.
    pub mode_end: BlockMode,
    /// Plate period T (s).
    pub period_s: f64,
    /// The averaging window `[k_a T, k_b T]` (s): whole periods after the transient.
    pub window_s: (f64, f64),
    /// Absolute position at every whole period reached, `(t = k T, x)` (s, m).
    pub period_x_m: Vec<(f64, f64)>,
    /// Mean absolute velocity over the whole periods of the window (m/s); NaN if the
    /// window holds no whole period.
    pub mean_velocity_mps: f64,
    /// Fraction of the window in contact.
    pub contact_fraction: f64,
    /// Fractions of the window per mode.
    pub modes: ModeFractions,
    /// Events inside the window.
    pub counts: EventCounts,
    /// Events over the whole run.
    pub total_counts: EventCounts,
    /// Events inside the window (if recorded).
    pub events: Vec<BlockEvent>,
    /// Integration work (right-hand-side evaluations of integrated modes).
    pub stats: Stats,
    /// Guard evaluations spent locating events.
    pub locate_evals: u64,
    /// Trajectory segments (steps and closed-form pieces).
    pub segments: u64,
}

/// Runs the block on `plate` until `t_end_s` (see [`BlockOptions`]).
pub fn simulate_block<P: PlateMotion + ?Sized>(
    params: &BlockParams,
    plate: &P,
    t_end_s: f64,
    opts: &BlockOptions,
) -> BlockRun {
    simulate_block_observed(params, plate, t_end_s, opts, &mut ())
}

struct Tracker<'a, 'o, P: PlateMotion + ?Sized, O> {
    sys: &'a BlockSystem<'a, P>,
    inner: &'o mut O,
    period: f64,
    window: (f64, f64),
    next_k: i64,
    period_x: Vec<(f64, f64)>,
    modes: ModeFractions,
    counts: EventCounts,
    total: EventCounts,
    events: Vec<BlockEvent>,
    record: bool,
    last_mode: Option<BlockMode>,
    last_state: [f64; 4],
    segments: u64,
}

impl<P: PlateMotion + ?Sized, O> Tracker<'_, '_, P, O> {
    fn note(
        &mut self,
        t: f64,
        kind: EventKind,
        from: BlockMode,
        to: BlockMode,
        before: [f64; 4],
        after: [f64; 4],
    ) {
        self.total.add(kind);
        if t >= self.window.0 && t < self.window.1 {
            self.counts.add(kind);
            if self.record {
                self.events.push(BlockEvent {
                    t_s: t,
                    kind,
                    from,
                    to,
                    before,
                    after,
                });
            }
        }
    }
}

fn classify(from: BlockMode, to: BlockMode) -> EventKind {
    use BlockMode::*;
    match (from, to) {
        (Flight, _) => EventKind::Landing,
        (_, Flight) => EventKind::Takeoff,
        (Stick, _) => EventKind::StickToSlip,
        (_, Stick) => EventKind::SlipToStick,
        _ => EventKind::Reversal,
    }
}

impl<P: PlateMotion + ?Sized, O: Observer<BlockMode, 4>> Observer<BlockMode, 4>
    for Tracker<'_, '_, P, O>
{
    fn segment(&mut self, mode: BlockMode, seg: &Segment<'_, 4>) {
        self.segments += 1;
        if let Some(last) = self.last_mode {
            if last != mode {
                // A mode change that no event announced: a plate breakpoint.
                let before = self.last_state;
                self.note(seg.t0, EventKind::Breakpoint, last, mode, before, seg.y0);
            }
        }
        self.last_mode = Some(mode);
        self.last_state = seg.y1;
        // Whole-period samples of the absolute position.
        loop {
            let tk = self.next_k as f64 * self.period;
            if tk > seg.t1 {
                break;
            }
            let y = if tk <= seg.t0 { seg.y0 } else { seg.eval(tk) };
            self.period_x.push((tk, y[0] + self.sys.plate.x_m(tk)));
            self.next_k += 1;
        }
        // Time in each mode inside the window.
        let dt = seg.t1.min(self.window.1) - seg.t0.max(self.window.0);
        if dt > 0.0 {
            let m = &mut self.modes;
            match mode {
                BlockMode::Stick => m.stick += dt,
                BlockMode::SlipRight => m.slip_right += dt,
                BlockMode::SlipLeft => m.slip_left += dt,
                BlockMode::Viscous => m.viscous += dt,
                BlockMode::Flight => m.flight += dt,
            }
        }
        self.inner.segment(mode, seg);
    }

    fn event(
        &mut self,
        t_s: f64,
        from: BlockMode,
        guard: usize,
        before: &[f64; 4],
        after: Option<(BlockMode, &[f64; 4])>,
    ) {
        if let Some((to, y)) = after {
            self.note(t_s, classify(from, to), from, to, *before, *y);
            self.last_mode = Some(to);
            self.last_state = *y;
        }
        self.inner.event(t_s, from, guard, before, after);
    }
}

/// [`simulate_block`] with an observer that sees every segment and event (with the
/// block's relative state; use [`BlockSystem::contact_force`] and
/// [`BlockSystem::absolute`] on it).
pub fn simulate_block_observed<P: PlateMotion + ?Sized>(
    params: &BlockParams,
    plate: &P,
    t_end_s: f64,
    opts: &BlockOptions,
    obs: &mut impl Observer<BlockMode, 4>,
) -> BlockRun {
    let mut sys = BlockSystem::new(*params, plate);
    let period = plate.period_s();
    sys.closed_forms = opts.closed_forms;
    sys.sample_s = period / opts.samples_per_period.max(1) as f64;
    let (t0, y0) = opts.start;
    let (mode0, y0) = if y0[2] > 0.0 || y0[3] > 0.0 {
        (BlockMode::Flight, y0)
    } else {
        match sys.impact(t0, y0[0], y0[1], y0[3]) {
            Transition::To { mode, state } => (mode, state),
            Transition::Stop(x) => match x {},
        }
    };
    let k0 = (t0 / period - 1e-9).ceil() as i64;
    let k_a = k0 + opts.transient_periods as i64;
    let k_b = ((t_end_s / period) + 1e-9).floor() as i64;
    let window = (k_a as f64 * period, (k_b.max(k_a)) as f64 * period);
    let sysr = &sys;
    let mut tr = Tracker {
        sys: sysr,
        inner: obs,
        period,
        window,
        next_k: k0,
        period_x: Vec::new(),
        modes: ModeFractions::default(),
        counts: EventCounts::default(),
        total: EventCounts::default(),
        events: Vec::new(),
        record: opts.record_events,
        last_mode: None,
        last_state: y0,
        segments: 0,
    };
    if (k0 as f64 * period - t0).abs() <= 1e-12 * period.max(t0.abs()) {
        tr.period_x.push((t0, y0[0] + plate.x_m(t0)));
        tr.next_k += 1;
    }
    // Events to a few ulps of the run's own times (the driver's default is a few ulps
    // of max(t, 1 s): over a run of one 1 ms period that is 1000 times coarser, and
    // each switch located that late moves the velocity by a_plate x the delay).
    let hybrid = Options {
        event_tol_s: opts
            .hybrid
            .event_tol_s
            .or(time_tolerance_of_run(t0, t_end_s)),
        ..opts.hybrid
    };
    let run = simulate(sysr, mode0, t0, y0, t_end_s, &hybrid, &mut tr);
    let span = window.1 - window.0;
    let x_at = |k: i64| {
        tr.period_x
            .iter()
            .find(|(t, _)| (*t - k as f64 * period).abs() <= 1e-9 * period)
            .map(|p| p.1)
    };
    let mean_velocity_mps = match (x_at(k_a), x_at(k_b)) {
        (Some(xa), Some(xb)) if k_b > k_a => (xb - xa) / span, // formula: <v> = (x(k_b T) - x(k_a T)) / ((k_b - k_a) T)
        _ => f64::NAN,
    };
    let modes = tr.modes.per_time(span);
    BlockRun {
        outcome: run.outcome,
        t_end_s: run.t_end_s,
        y_end: run.y_end,
        mode_end: run.mode_end,
        period_s: period,
        window_s: window,
        period_x_m: tr.period_x,
        mean_velocity_mps,
        contact_fraction: if span > 0.0 {
            1.0 - modes.flight
        } else {
            f64::NAN
        },
        modes,
        counts: tr.counts,
        total_counts: tr.total,
        events: tr.events,
        stats: run.stats,
        locate_evals: run.locate_evals,
        segments: tr.segments,
    }
}

impl ModeFractions {
    /// The times spent in each mode as fractions of `span_s` (unchanged when the span
    /// is not positive).
    fn per_time(mut self, span_s: f64) -> ModeFractions {
        if span_s > 0.0 {
            self.stick /= span_s;
            self.slip_right /= span_s;
            self.slip_left /= span_s;
            self.viscous /= span_s;
            self.flight /= span_s;
        }
        self
    }
}
