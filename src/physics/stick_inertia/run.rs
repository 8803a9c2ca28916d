//! One run of the stick with inertia through chapter 6's hybrid driver, and its summary.

use super::{
    ImpactRecord, InertiaModel, InertiaParams, InertiaStop, Log, Mode, PainleveEvent, PainleveRule,
    State, D_DAMP, D_FRIC, D_IMPACT, NSTATE, TH, VXC, W_PLATE, XC,
};
use crate::numerics::hybrid::{simulate, Observer, Options, Outcome, Segment, Transition};
use crate::physics::stick::StickParams;

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
    /// Largest penetration of C into the plate (m), sampled on every flight segment
    /// (its ends and 7 interior points) and at every event.
    pub max_penetration_m: f64,
    /// The bound the run's own tolerances put on it (m): `rtol (L + delta)`.
    pub penetration_bound_m: f64,
    /// Largest complementarity residual relative to its rounding threshold (1): after
    /// impacts `|u_n+| / eta_v`, inside contact segments the force's excursion out of
    /// the cone `max(-F_z, |F_x| - mu F_z) / eta_F` ([`super::rounding`]). At most 1 in
    /// a run whose every decision was rounding-consistent.
    pub max_complementarity_ratio: f64,
    /// The largest velocity-level residual itself (m/s).
    pub max_normal_residual_mps: f64,
    /// The segments handed to Moreau-Jean ([`super::bridge`]).
    pub bridges: Vec<super::bridge::Bridge>,
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
    mode_time_s: [f64; 4],
    penetration_m: f64,
    force_ratio: f64,
}

impl Watch<'_> {
    /// Penetration (flight) or the force's excursion from the cone (contact) sampled on
    /// the segment: its ends (flight) and 7 interior points.
    fn sample_contact(&mut self, mode: Mode, seg: &Segment<'_, NSTATE>) {
        let md = self.md;
        for k in 0..=8 {
            let t = seg.t0 + (seg.t1 - seg.t0) * f64::from(k) / 8.0;
            if mode == Mode::Flight {
                let h = md.h_c(t, &seg.eval(t));
                self.penetration_m = self.penetration_m.max(-h);
            } else if k > 0 && k < 8 {
                let y = seg.eval(t);
                if let Some(e) = md.contact_eval(mode, t, &y) {
                    let mu = md.p.base.mu;
                    let out = (-e.fz).max(e.fx.abs() - mu * e.fz).max(0.0);
                    self.force_ratio = self.force_ratio.max(out / md.force_rounding(&y));
                }
            }
        }
    }
}

impl Observer<Mode, NSTATE> for Watch<'_> {
    fn segment(&mut self, mode: Mode, seg: &Segment<'_, NSTATE>) {
        let i = Mode::ALL.iter().position(|m| *m == mode).unwrap_or(0);
        self.mode_time_s[i] += seg.t1 - seg.t0;
        self.sample_contact(mode, seg);
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

/// The scene of cardillo's `examples/Painleve.py` (Glocker 1995, 5.3.4, "impact without
/// collision"): a uniform rod of length 2 m and 1 kg, mu = 5/3, g = 10 m/s^2, leaning
/// 59 deg from the vertical (top to the left), its lower end sliding right at 30 m/s on a
/// still floor, under the Painleve `rule`, run to `t_end_s` with a trace every
/// millisecond. The Painleve point it reaches is singular (both coefficients vanish), so
/// the rate after it depends on `rule`.
pub fn glocker_scene(rule: PainleveRule, opts: &Options, t_end_s: f64) -> InertiaRun {
    let th = -(59.0f64).to_radians(); // formula: 31 deg from the floor = -59 deg from the vertical
    let mut base = StickParams::new(2.0, 0.0, 0.0, 0.0, 5.0 / 3.0, th, 10.0, 0.0, 30.0)
        .expect("a stick inside the model's domain");
    base.mass_kg = 0.0;
    let mut md = InertiaModel::new(InertiaParams {
        base,
        rod_mass_kg: 1.0,
        restitution: 0.0,
    });
    md.painleve_rule = rule;
    let mut y = [0.0; NSTATE];
    y[TH] = th;
    y[VXC] = 30.0;
    simulate_inertia(&md, 0.0, y, t_end_s, opts, 1e-3)
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
    let eps_m = run_rtol(opts) * (model.p.base.length_m + model.p.base.plate.amplitude_m); // formula: rtol (L + delta)
    *model.log.borrow_mut() = Log {
        chatter_flight_s: model.chatter_flight_s(eps_m),
        ..Log::default()
    };
    let mut w = Watch {
        md: model,
        acc: [0.0; 4],
        trace_dt_s,
        next_t: t0,
        trace: Vec::new(),
        switches: 0,
        mode_time_s: [0.0; 4],
        penetration_m: 0.0,
        force_ratio: 0.0,
    };
    let opts = Options {
        record_events: false,
        ..*opts
    };
    let mut bridges = Vec::new();
    let (outcome, t_end_s, y_end, rhs) =
        run_pieces(model, t0, &y0, t_end, &opts, &mut w, &mut bridges);
    let mut y1 = y_end;
    y1[W_PLATE..=D_IMPACT].copy_from_slice(&w.acc);
    let budget = budget(model, &y0, &y1);
    let log = model.log.borrow().clone();
    let dur = t_end_s - t0;
    let b = &model.p.base;
    let mut run = InertiaRun {
        outcome,
        end_time_s: t_end_s,
        mean_velocity_mps: if dur > 0.0 {
            (y1[XC] - y0[XC]) / dur
        } else {
            0.0
        },
        mode_time_s: w.mode_time_s,
        switches: w.switches,
        painleve: log.painleve,
        impacts: log.impacts,
        impact_count: log.impact_count,
        max_impact_energy_gain_j: log.max_energy_gain_j,
        budget,
        max_penetration_m: w.penetration_m.max(0.0),
        penetration_bound_m: run_rtol(&opts) * (b.length_m + b.plate.amplitude_m), // formula: rtol (L + delta)
        max_complementarity_ratio: log.max_residual_ratio.max(w.force_ratio),
        max_normal_residual_mps: log.max_normal_residual_mps,
        bridges,
        rhs_evals: rhs,
        trace: w.trace,
    };
    certify_run(&mut run);
    run
}

/// The run's relative tolerance (the step for a fixed-step run: none then, `1e-10`).
fn run_rtol(opts: &Options) -> f64 {
    match opts.control {
        crate::numerics::ode::StepControl::Adaptive { rtol, .. } => rtol,
        crate::numerics::ode::StepControl::Fixed { .. } => 1e-10,
    }
}

/// A run that reached its end is `completed` only if its contact held within the bounds
/// of its own tolerances: penetration at most `rtol (L + delta)`, every complementarity
/// residual at most its rounding threshold, a finite state.
fn certify_run(run: &mut InertiaRun) {
    if run.outcome != InertiaOutcome::Completed {
        return;
    }
    let why = if !run.mean_velocity_mps.is_finite() {
        Some("the state is not finite".to_string())
    } else if run.max_penetration_m > run.penetration_bound_m {
        Some(format!(
            "C went {:.3e} m into the plate, past the bound rtol (L + delta) = {:.3e} m",
            run.max_penetration_m, run.penetration_bound_m
        ))
    } else if run.max_complementarity_ratio > 1.0 {
        Some(format!(
            "a complementarity residual reached {:.3e} of its rounding threshold (at most 1)",
            run.max_complementarity_ratio
        ))
    } else {
        None
    };
    if let Some(w) = why {
        run.outcome = InertiaOutcome::Invalid(w);
    }
}

/// Result of the driver's pieces: (outcome, end time, end state, rhs evaluations).
type Pieces = (InertiaOutcome, f64, State, u64);

/// The run as pieces of the event-driven driver, joined by Moreau-Jean bridges
/// ([`super::bridge`]) where the rules stop on a Painleve case they cannot resolve or
/// find no consistent contact mode. Accumulators are summed into `w.acc`.
fn run_pieces(
    model: &InertiaModel,
    t0: f64,
    y0: &State,
    t_end: f64,
    opts: &Options,
    w: &mut Watch<'_>,
    bridges: &mut Vec<super::bridge::Bridge>,
) -> Pieces {
    let mut start = start_transition(model, t0, y0);
    let (mut t, mut rhs, mut y_cur) = (t0, 0u64, *y0);
    loop {
        let (mode, state) = match start {
            Transition::To { mode, state } => (mode, state),
            Transition::Stop(x) => return (stop_outcome(x), t, y_cur, rhs),
        };
        // a piece's own start reset (an impact without collision) is booked like an event's
        for k in 0..4 {
            w.acc[k] += state[W_PLATE + k];
        }
        let mut s = state;
        s[W_PLATE..=D_IMPACT].fill(0.0);
        let run = simulate(model, mode, t, s, t_end, opts, w);
        rhs += run.stats.rhs_evals;
        for k in 0..4 {
            w.acc[k] += run.y_end[W_PLATE + k];
        }
        let y_end = model.canonical(run.mode_end, run.t_end_s, &run.y_end);
        t = run.t_end_s;
        let bridgeable = matches!(
            &run.outcome,
            Outcome::Stopped(InertiaStop::PainleveUnresolved(_))
                | Outcome::Stopped(InertiaStop::NoMode(_))
        );
        if !bridgeable || bridges.len() >= super::bridge::MAX_BRIDGES {
            return (driver_outcome(run.outcome), t, y_end, rhs);
        }
        match super::bridge::bridge(model, t, &y_end, t_end) {
            Ok((b, next)) => {
                for k in 0..4 {
                    w.acc[k] += b.acc[k];
                }
                t = b.t1_s;
                y_cur = b.y1;
                bridges.push(b);
                start = next;
            }
            Err(why) => return (InertiaOutcome::Invalid(why), t, y_end, rhs),
        }
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
        InertiaStop::Invalid(r) | InertiaStop::NoMode(r) => InertiaOutcome::Invalid(r),
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
