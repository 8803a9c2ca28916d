//! One run of the stick with inertia through chapter 6's hybrid driver, and its summary.

use super::{
    ImpactRecord, InertiaModel, InertiaStop, Log, Mode, PainleveEvent, State, D_DAMP, D_FRIC,
    D_IMPACT, NSTATE, TH, W_PLATE, XC,
};
use crate::numerics::hybrid::{simulate, Observer, Options, Outcome, Segment, Transition};

/// The typed outcome of a run.
#[derive(Debug, Clone, PartialEq)]
pub enum InertiaOutcome {
    /// Reached the end time.
    Completed,
    /// The stick fell.
    Fell,
    /// Events accumulated (Zeno).
    Zeno,
    /// A Painleve case the rules could not resolve.
    PainleveUnresolved,
    /// The state left the model's validity, or the integration failed (the reason).
    Invalid(String),
}

impl InertiaOutcome {
    /// `completed`, `fell`, `zeno`, `painleve-unresolved` or `invalid`.
    pub fn label(&self) -> &'static str {
        match self {
            InertiaOutcome::Completed => "completed",
            InertiaOutcome::Fell => "fell",
            InertiaOutcome::Zeno => "zeno",
            InertiaOutcome::PainleveUnresolved => "painleve-unresolved",
            InertiaOutcome::Invalid(_) => "invalid",
        }
    }
}

/// The energy budget of a run (J): chapter 6's, `W_plate = Delta E + D_friction +
/// D_damper + D_impact + residual`.
pub use crate::physics::stick::energy::Budget;

/// One sample of a trace.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Time (s).
    pub t_s: f64,
    /// Mode.
    pub mode: Mode,
    /// State.
    pub y: State,
}

/// Summary of a run.
#[derive(Debug, Clone)]
pub struct InertiaRun {
    /// How it ended.
    pub outcome: InertiaOutcome,
    /// End time (s).
    pub end_time_s: f64,
    /// Mean horizontal velocity of C (m/s).
    pub mean_velocity_mps: f64,
    /// Time in each mode, [`Mode::ALL`] order (s).
    pub mode_time_s: [f64; 4],
    /// Mode switches.
    pub switches: usize,
    /// Painleve events.
    pub painleve: Vec<PainleveEvent>,
    /// Impacts (capped) and their count.
    pub impacts: Vec<ImpactRecord>,
    /// Number of impacts.
    pub impact_count: usize,
    /// Largest energy an impact created (J).
    pub max_impact_energy_gain_j: f64,
    /// The energy budget.
    pub budget: Budget,
    /// Right-hand-side evaluations.
    pub rhs_evals: u64,
    /// Trace (if asked for).
    pub trace: Vec<Sample>,
}

struct Watch<'a> {
    md: &'a InertiaModel,
    acc: [f64; 4],
    trace_dt_s: f64,
    next_t: f64,
    trace: Vec<Sample>,
    switches: usize,
}

impl Observer<Mode, NSTATE> for Watch<'_> {
    fn segment(&mut self, mode: Mode, seg: &Segment<'_, NSTATE>) {
        if self.trace_dt_s > 0.0 {
            while self.next_t <= seg.t1 {
                let t = self.next_t.max(seg.t0);
                // canonical: in contact C's height is the plate's (not integrated)
                let y = self.md.canonical(mode, t, &seg.eval(t));
                self.trace.push(Sample { t_s: t, mode, y });
                self.next_t += self.trace_dt_s;
            }
        }
    }

    fn event(
        &mut self,
        _t: f64,
        _from: Mode,
        _g: usize,
        before: &State,
        after: Option<(Mode, &State)>,
    ) {
        if after.is_some() {
            for k in 0..4 {
                self.acc[k] += before[W_PLATE + k];
            }
            self.switches += 1;
        }
    }
}

/// Runs `model` from `(t0, y0)` with C on the plate at rest relative to it (the rules
/// choose the mode) or above it (flight), to `t_end`; a trace every `trace_dt_s` (0: none).
pub fn simulate_inertia(
    model: &InertiaModel,
    t0: f64,
    y0: State,
    t_end: f64,
    opts: &Options,
    trace_dt_s: f64,
) -> InertiaRun {
    *model.log.borrow_mut() = Log::default();
    let start = start_transition(model, t0, &y0);
    let mut w = Watch {
        md: model,
        acc: [0.0; 4],
        trace_dt_s,
        next_t: t0,
        trace: Vec::new(),
        switches: 0,
    };
    let opts = Options {
        record_events: false,
        ..*opts
    };
    let (outcome, t_end_s, y_end, rhs) = match start {
        Transition::To { mode, state } => {
            // the start's own reset (an impact without collision) is booked like an event's
            w.acc = [
                state[W_PLATE],
                state[D_FRIC],
                state[D_DAMP],
                state[D_IMPACT],
            ];
            let mut s = state;
            s[W_PLATE..=D_IMPACT].fill(0.0);
            let run = simulate(model, mode, t0, s, t_end, &opts, &mut w);
            (
                driver_outcome(run.outcome),
                run.t_end_s,
                model.canonical(run.mode_end, run.t_end_s, &run.y_end),
                run.stats.rhs_evals,
            )
        }
        Transition::Stop(x) => (stop_outcome(x), t0, y0, 0),
    };
    let mut y1 = y_end;
    for k in 0..4 {
        y1[W_PLATE + k] += w.acc[k];
    }
    let budget = budget(model, &y0, &y1);
    let log = model.log.borrow().clone();
    let dur = t_end_s - t0;
    InertiaRun {
        outcome,
        end_time_s: t_end_s,
        mean_velocity_mps: if dur > 0.0 {
            (y1[XC] - y0[XC]) / dur
        } else {
            0.0
        },
        mode_time_s: [0.0; 4],
        switches: w.switches,
        painleve: log.painleve,
        impacts: log.impacts,
        impact_count: log.impact_count,
        max_impact_energy_gain_j: log.max_energy_gain_j,
        budget,
        rhs_evals: rhs,
        trace: w.trace,
    }
}

/// The first transition from `(t0, y0)`: flight above the plate, the slide of a slipping
/// foot, the contact rules for a foot at rest on it.
fn start_transition(
    model: &InertiaModel,
    t0: f64,
    y0: &State,
) -> Transition<Mode, InertiaStop, NSTATE> {
    if model.h_c(t0, y0) > 0.0 {
        Transition::To {
            mode: Mode::Flight,
            state: *y0,
        }
    } else if y0[super::VXC] != 0.0 {
        model.enter_slide(t0, &model.canonical(Mode::Pivot, t0, y0), 0)
    } else {
        model.select_contact(t0, &model.canonical(Mode::Pivot, t0, y0), true, 0)
    }
}

/// The typed outcome of a model stop.
fn stop_outcome(x: InertiaStop) -> InertiaOutcome {
    match x {
        InertiaStop::Fell => InertiaOutcome::Fell,
        InertiaStop::PainleveUnresolved(_) => InertiaOutcome::PainleveUnresolved,
        InertiaStop::Invalid(r) => InertiaOutcome::Invalid(r),
    }
}

/// The typed outcome of the driver's run.
fn driver_outcome(o: Outcome<InertiaStop>) -> InertiaOutcome {
    match o {
        Outcome::Completed => InertiaOutcome::Completed,
        Outcome::Stopped(x) => stop_outcome(x),
        Outcome::Zeno { .. } => InertiaOutcome::Zeno,
        Outcome::Failed(e) => InertiaOutcome::Invalid(format!("integration failed: {e}")),
    }
}

/// The energy budget between the start `y0` and the end `y1` (accumulators summed).
fn budget(model: &InertiaModel, y0: &State, y1: &State) -> Budget {
    let (plate_w, de) = (
        y1[W_PLATE],
        model.mechanical_energy(y1) - model.mechanical_energy(y0),
    );
    Budget {
        plate_work_j: plate_w,
        delta_mechanical_j: de,
        friction_j: y1[D_FRIC],
        damper_j: y1[D_DAMP],
        impact_j: y1[D_IMPACT],
        residual_j: plate_w - de - y1[D_FRIC] - y1[D_DAMP] - y1[D_IMPACT], // formula: budget residual
    }
}

/// Start state: C at x = 0 on the plate at `t0`, at rest relative to it at `theta`.
pub fn initial_state(model: &InertiaModel, t0: f64, theta: f64) -> State {
    let mut y = [0.0; NSTATE];
    y[TH] = theta;
    model.canonical(Mode::Pivot, t0, &y)
}

/// A run from the static angle (or theta_0 when the spring cannot hold the stick).
pub fn run_from_rest(
    model: &InertiaModel,
    t_end: f64,
    opts: &Options,
    trace_dt_s: f64,
) -> InertiaRun {
    let th = model.p.static_angle().unwrap_or(model.p.base.theta0_rad);
    simulate_inertia(
        model,
        0.0,
        initial_state(model, 0.0, th),
        t_end,
        opts,
        trace_dt_s,
    )
}
