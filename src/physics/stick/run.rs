//! One run of the stick through the hybrid driver, and its summary.

use super::energy::Budget;
use super::{
    InvalidReason, Mode, State, StickModel, StickStop, D_DAMP, D_FRIC, NSTATE, OM, ROD_X, ROD_Z,
    TH, VXC, VZC, W_PLATE, XC, ZC,
};
use crate::numerics::events::CertifyStats;
use crate::numerics::hybrid::{simulate, HybridSystem, Observer, Options, Outcome, Segment};
use crate::numerics::ode::{OdeError, Stats};

/// The typed outcome of a run.
#[derive(Debug, Clone, PartialEq)]
pub enum StickOutcome {
    /// Reached the end time.
    Completed,
    /// The top P reached the plate (|theta| reached 90 degrees).
    Fell,
    /// Events accumulated (Zeno).
    Zeno,
    /// The state left the model's validity (the reason).
    Invalid(InvalidReason),
    /// A printed rule (Algorithms 1 to 4) chose ABORT (the rule that fired).
    Aborted(String),
}

impl StickOutcome {
    /// `completed`, `fell`, `zeno`, `invalid` or `aborted`.
    pub fn label(&self) -> &'static str {
        match self {
            StickOutcome::Completed => "completed",
            StickOutcome::Fell => "fell",
            StickOutcome::Zeno => "zeno",
            StickOutcome::Invalid(_) => "invalid",
            StickOutcome::Aborted(_) => "aborted",
        }
    }

    /// The outcome of a model stop.
    pub(crate) fn from_stop(x: StickStop) -> Self {
        match x {
            StickStop::Fell => StickOutcome::Fell,
            StickStop::Invalid(r) => StickOutcome::Invalid(r),
            StickStop::Aborted(r) => StickOutcome::Aborted(r),
        }
    }
}

/// Most entries the event and landing lists keep (16 MB and 80 MB at most), so that no
/// accepted run length can exhaust memory; the counts go on ([`RunSummary::event_count`]).
pub const LIST_CAP: usize = 1_000_000;

/// What to record during a run, beyond the counts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Recording {
    /// Keep the phase sequence (one letter per mode entered, capped at this length).
    pub sequence_cap: usize,
    /// Sample the trajectory every this many seconds (0: no trace).
    pub trace_dt_s: f64,
    /// Check the contact conditions of Table 1 at the ends of every accepted step.
    pub check_invariants: bool,
    /// Keep only the trace's samples on the `trace_dt_s` grid, not every step's end
    /// (false: both, as drawn by the chapter's figures; true: the lab's frames, which
    /// use the grid only, at a fraction of the memory).
    pub grid_only: bool,
    /// Most entries the event and landing lists keep (`None`: [`LIST_CAP`]); the counts
    /// go on.
    pub list_cap: Option<usize>,
}

impl Recording {
    /// The cap of the event and landing lists.
    fn list_cap(&self) -> usize {
        self.list_cap.unwrap_or(LIST_CAP)
    }
}

/// Largest violations of Table 1 seen at accepted steps (N, m, m/s).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Violations {
    /// Largest `-F_z` in contact modes (N).
    pub normal_n: f64,
    /// Largest `|F_x| - mu F_z` in pivot (N).
    pub cone_n: f64,
    /// Largest `-F_z` in pivot (N) (the pivot's share of `normal_n`).
    pub pivot_normal_n: f64,
    /// Largest slip against the slide's direction, `sigma xdot_c` (m/s).
    pub slip_mps: f64,
    /// Largest `-h_c` in flight (m).
    pub penetration_m: f64,
    /// Largest `-h_c` in flight over its rounding budget at that state
    /// ([`StickModel::penetration_budget_m`]); at most 1 when the event location and the
    /// flight's arithmetic work as derived.
    pub penetration_budget_ratio: f64,
    /// Largest `|xdot_c|` in pivot (m/s).
    pub pivot_slip_mps: f64,
    /// Accepted steps checked.
    pub checked: usize,
}

/// What the energy budget's error bound needs to know of a run (chapter 6's
/// `c6-c14-energy-budget`), recorded with [`Recording::check_invariants`] at the ends
/// of every accepted step (the states the error control weighs) and at every event.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Extents {
    /// Accepted steps seen (segments of the integrated modes).
    pub steps: u64,
    /// Largest `|theta'|` (rad/s).
    pub omega_max_rad_s: f64,
    /// Largest `|theta|` (rad).
    pub theta_max_rad: f64,
    /// Largest `|theta - theta_0|` (rad).
    pub spring_max_rad: f64,
    /// Largest `|xdot_c|` (m/s).
    pub vxc_max_mps: f64,
    /// Largest speed of P, `|v_P|` (m/s).
    pub v_tip_max_mps: f64,
    /// Largest `|theta''|` in contact (rad/s^2).
    pub theta_dd_max_rad_s2: f64,
    /// Largest contact force `|F|` (N).
    pub force_max_n: f64,
    /// Largest value of the mode's own (restarted) plate work, friction and damper
    /// accumulators (J).
    pub acc_max_j: f64,
    /// Integral over the integrated steps of the carried rod direction's distance from
    /// `(sin theta, cos theta)`, taken at each step's start (s): the exact flow keeps
    /// that distance constant, so it changes only at step ends.
    pub rod_drift_s: f64,
    /// Largest such distance (1).
    pub rod_drift_max: f64,
    /// Sum over landings of `|h_c|` at the located event (m): the height the landing's
    /// reset puts C onto the plate by.
    pub landing_gap_sum_m: f64,
    /// Sum over stops of a slide of `|xdot_c|` at the located stop (m/s): the slip the
    /// pivot test's reset sets to zero.
    pub stop_slip_sum_mps: f64,
    /// The same sum of squares (m^2/s^2).
    pub stop_slip_sq_sum: f64,
    /// Events (mode switches and stops).
    pub events: u64,
}

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

/// One landing (flight ended on the plate).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Landing {
    /// Time (s).
    pub t_s: f64,
    /// Angle at the landing (rad).
    pub theta_rad: f64,
    /// Height of C above the plate at the located event (m).
    pub h_c_m: f64,
    /// Along-rod approach velocity of P relative to the plate (m/s).
    pub w_mps: f64,
    /// A sticking impact (impulse along the rod inside the cone) took place.
    pub sticking: bool,
    /// Angular momentum about C per unit mass before and after, with the lever at the
    /// angle after the impact (m^2/s); equal for a sticking impact.
    pub h_before: f64,
    /// See `h_before`.
    pub h_after: f64,
    /// The mode after.
    pub to: Mode,
}

/// Summary of a run.
#[derive(Debug, Clone)]
pub struct RunSummary {
    /// How it ended.
    pub outcome: StickOutcome,
    /// End time (s).
    pub end_time_s: f64,
    /// Start time (s).
    pub start_time_s: f64,
    /// Mean horizontal velocity of C over the run (m/s).
    pub mean_velocity_mps: f64,
    /// Time in each mode, in [`Mode::ALL`] order (s).
    pub mode_time_s: [f64; 4],
    /// Transitions counted `[from][to]` in [`Mode::ALL`] order.
    pub transitions: [[usize; 4]; 4],
    /// Jams (slides stopped by the self-locking edge).
    pub jams: usize,
    /// Landings (flight phases that ended on the plate).
    pub hops: usize,
    /// Sticking impacts among the landings.
    pub sticking_landings: usize,
    /// The energy budget over the run.
    pub budget: Budget,
    /// Integration work.
    pub stats: Stats,
    /// Guard evaluations spent locating events.
    pub locate_evals: u64,
    /// Work of the certified event search (hidden crossings found among it).
    pub certify: CertifyStats,
    /// Drive cycles simulated.
    pub cycles: f64,
    /// Phase sequence (letters F, P, L, R), capped.
    pub sequence: String,
    /// Table 1 violations.
    pub violations: Violations,
    /// The run's extents for the energy budget's bound (with `check_invariants`).
    pub extents: Extents,
    /// Trace samples (canonical states; energy accumulators are running totals).
    pub trace: Vec<Sample>,
    /// Events: (time s, from, to) with `to = None` for the stop; at most [`LIST_CAP`].
    pub events: Vec<(f64, Mode, Option<Mode>)>,
    /// Every event of the run, also those beyond the recorded lists' caps.
    pub event_count: usize,
    /// The same events with the state and contact force at each switch (recorded with
    /// the phase sequence, capped at its length): what `--events FILE` writes.
    pub switches: Vec<Switch>,
    /// Landings (when recording a sequence; at most [`LIST_CAP`]).
    pub landings: Vec<Landing>,
    /// Final state.
    pub y_end: State,
    /// Final mode.
    pub mode_end: Mode,
}

impl RunSummary {
    /// Fraction of the run's time spent in each mode (1), [`Mode::ALL`] order.
    pub fn phase_fractions(&self) -> [f64; 4] {
        let total: f64 = self.mode_time_s.iter().sum();
        self.mode_time_s
            .map(|x| if total > 0.0 { x / total } else { 0.0 })
    }
}

/// One mode switch: the state just before it and the contact force of the mode being
/// left (zero for flight).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Switch {
    /// Time (s).
    pub t_s: f64,
    /// Mode left.
    pub from: Mode,
    /// Mode entered (`None`: the run stopped).
    pub to: Option<Mode>,
    /// theta just before the switch (rad).
    pub theta_rad: f64,
    /// theta' just before the switch (rad/s).
    pub omega_rad_s: f64,
    /// x of C (m).
    pub x_c_m: f64,
    /// Horizontal force of the plate on C in the mode left (N).
    pub fx_n: f64,
    /// Normal force of the plate on C in the mode left (N).
    pub fz_n: f64,
}

/// The starting state of the authors' `main_rod.m`, bug included: the rod at its
/// spring's rest angle `theta_0` (not at the static angle), `theta' = 0`, C on the
/// plate at `x = 0`, and P (so C, with `theta' = 0`) moving up at
/// `setup.IC.dyp = setup.IC.yc = delta cos(0)`: a position (m) assigned to a velocity,
/// about 2.8 mm/s in their scene. With the plate accelerating downwards at `Gamma g`
/// at `t = 0` no contact mode is consistent there, and their `selectPhase` starts in
/// flight; so does the workbook from this state.
pub(crate) fn authors_code_state(model: &StickModel) -> State {
    let p = &model.p;
    let mut y = initial_state(model, 0.0, p.theta0_rad);
    let (z_s, _, _) = model.plate(0.0);
    y[ZC] = z_s; // formula: setup.IC.yc = A cos(omega 0)
    y[VZC] = z_s; // formula: setup.IC.dyp = setup.IC.yc (the bug: metres as m/s)
    y[VXC] = 0.0;
    y[OM] = 0.0;
    y
}

/// Start state: C at x = 0 on the plate at time `t0`, standing still at `theta` with
/// rate zero (relative to the plate), accumulators zero.
pub fn initial_state(model: &StickModel, t0: f64, theta: f64) -> State {
    let mut y = [0.0; NSTATE];
    y[TH] = theta;
    model.canonical(Mode::Pivot, t0, &y) // C on the plate, the rod's direction exact
}

struct Watch<'a> {
    model: &'a StickModel,
    rec: Recording,
    sum: RunSummary,
    acc: [f64; 4],
    last_mode: Option<Mode>,
    next_sample_t: f64,
}

impl Watch<'_> {
    fn check(&mut self, mode: Mode, t: f64, y: &State) {
        let m = self.model;
        let x = &mut self.sum.extents;
        let [_, _, vxp, vzp] = m.tip(y);
        x.omega_max_rad_s = x.omega_max_rad_s.max(y[OM].abs());
        x.theta_max_rad = x.theta_max_rad.max(y[TH].abs());
        x.spring_max_rad = x.spring_max_rad.max((y[TH] - m.p.theta0_rad).abs());
        x.vxc_max_mps = x.vxc_max_mps.max(y[VXC].abs());
        x.v_tip_max_mps = x.v_tip_max_mps.max(vxp.hypot(vzp));
        if let Some(e) = m.contact_eval(mode, t, y) {
            x.theta_dd_max_rad_s2 = x.theta_dd_max_rad_s2.max(e.theta_dd.abs());
            x.force_max_n = x.force_max_n.max(e.fx.hypot(e.fz));
        }
        let v = &mut self.sum.violations;
        v.checked += 1;
        match m.contact_eval(mode, t, y) {
            None => {
                let pen = -m.h_c(t, y);
                v.penetration_m = v.penetration_m.max(pen);
                let ratio = pen / m.penetration_budget_m(t, y);
                v.penetration_budget_ratio = v.penetration_budget_ratio.max(ratio);
            }
            Some(e) => {
                v.normal_n = v.normal_n.max(-e.fz);
                if mode == Mode::Pivot {
                    v.pivot_normal_n = v.pivot_normal_n.max(-e.fz);
                    v.cone_n = v.cone_n.max(e.fx.abs() - m.p.mu * e.fz);
                    v.pivot_slip_mps = v.pivot_slip_mps.max(y[VXC].abs());
                } else {
                    v.slip_mps = v.slip_mps.max(mode.sigma() * y[VXC]);
                }
            }
        }
    }

    /// Canonical state with the energy accumulators as running totals since the start.
    fn running(&self, mode: Mode, t: f64, y: &State) -> State {
        let mut y = self.model.canonical(mode, t, y);
        for k in 0..4 {
            y[W_PLATE + k] += self.acc[k];
        }
        y
    }

    fn enter(&mut self, mode: Mode) {
        if self.last_mode != Some(mode) && self.sum.sequence.len() < self.rec.sequence_cap {
            self.sum.sequence.push(mode.letter());
        }
        self.last_mode = Some(mode);
    }
}

impl Observer<Mode, NSTATE> for Watch<'_> {
    fn segment(&mut self, mode: Mode, seg: &Segment<'_, NSTATE>) {
        if self.last_mode.is_none() {
            self.enter(mode);
        }
        if self.rec.check_invariants {
            if mode != Mode::Flight {
                let x = &mut self.sum.extents;
                x.steps += 1;
                let drift = |y: &State| {
                    let (s, c) = crate::numerics::trig::sin_cos(y[TH]);
                    (y[ROD_X] - s).hypot(y[ROD_Z] - c)
                };
                x.rod_drift_s += (seg.t1 - seg.t0) * drift(&seg.y0);
                x.rod_drift_max = x.rod_drift_max.max(drift(&seg.y0)).max(drift(&seg.y1));
                for k in [W_PLATE, D_FRIC, D_DAMP] {
                    x.acc_max_j = x.acc_max_j.max(seg.y0[k].abs()).max(seg.y1[k].abs());
                }
            }
            let y1 = self.model.canonical(mode, seg.t1, &seg.y1);
            self.check(mode, seg.t1, &y1);
        }
        if self.rec.trace_dt_s > 0.0 {
            while self.next_sample_t <= seg.t1 {
                let t = self.next_sample_t.max(seg.t0);
                let y = self.running(mode, t, &seg.eval(t));
                self.sum.trace.push(Sample { t_s: t, mode, y });
                self.next_sample_t += self.rec.trace_dt_s;
            }
            if !self.rec.grid_only {
                // keep the segment's end so that events are drawn sharply
                let y = self.running(mode, seg.t1, &seg.y1);
                self.sum.trace.push(Sample {
                    t_s: seg.t1,
                    mode,
                    y,
                });
            }
        }
    }

    fn event(
        &mut self,
        t: f64,
        from: Mode,
        guard: usize,
        _before: &State,
        after: Option<(Mode, &State)>,
    ) {
        let to = after.map(|(m, _)| m);
        self.sum.event_count += 1;
        if self.rec.check_invariants {
            let x = &mut self.sum.extents;
            x.events += 1;
            if from == Mode::Flight && guard == 0 {
                x.landing_gap_sum_m += self.model.h_c(t, _before).abs();
            } else if from != Mode::Flight && from != Mode::Pivot && guard == 2 {
                let slip = _before[VXC].abs();
                x.stop_slip_sum_mps += slip;
                x.stop_slip_sq_sum += slip * slip;
            }
        }
        if self.rec.sequence_cap > 0 && self.sum.events.len() < self.rec.list_cap() {
            self.sum.events.push((t, from, to));
            if self.sum.switches.len() < self.rec.sequence_cap {
                let y = self.model.canonical(from, t, _before);
                let f = self.model.contact_eval(from, t, &y);
                self.sum.switches.push(Switch {
                    t_s: t,
                    from,
                    to,
                    theta_rad: y[TH],
                    omega_rad_s: y[OM],
                    x_c_m: y[XC],
                    fx_n: f.map_or(0.0, |e| e.fx),
                    fz_n: f.map_or(0.0, |e| e.fz),
                });
            }
        }
        if let Some((m, y)) = after {
            for k in 0..4 {
                self.acc[k] += _before[W_PLATE + k];
            }
            self.sum.transitions[from.index()][m.index()] += 1;
            if from == Mode::Flight && guard == 0 {
                let md = self.model;
                self.sum.hops += 1;
                let w = md.approach_velocity(t, _before);
                let sticking = _before[TH].tan().abs() <= md.p.mu && w < 0.0;
                if sticking {
                    self.sum.sticking_landings += 1;
                }
                if self.rec.sequence_cap > 0 && self.sum.landings.len() < self.rec.list_cap() {
                    let lever = y[TH];
                    self.sum.landings.push(Landing {
                        t_s: t,
                        theta_rad: _before[TH],
                        h_c_m: md.h_c(t, _before),
                        w_mps: w,
                        sticking,
                        h_before: md.angular_momentum_about_c(t, _before, lever),
                        h_after: md.angular_momentum_about_c(t, &md.canonical(m, t, y), lever),
                        to: m,
                    });
                }
            }
            if from != Mode::Flight && from != Mode::Pivot && guard == 0 {
                self.sum.jams += 1;
            }
            self.enter(m);
            if self.rec.check_invariants {
                self.check(m, t, y);
            }
        }
    }
}

/// Simulates `model` from `(t0, y0)` in the mode the contact rules choose (C on the
/// plate) or in flight (C above it), up to `t_end`.
pub fn simulate_stick(
    model: &StickModel,
    t0: f64,
    y0: State,
    t_end: f64,
    opts: &Options,
    rec: Recording,
) -> RunSummary {
    let start = if model.h_c(t0, &y0) > 0.0 {
        super::rules::Next::To(Mode::Flight, y0)
    } else {
        model.select_contact(t0, &y0)
    };
    simulate_system(model, model, start, t0, y0, t_end, opts, rec)
}

/// The summary of a run that starts at `t0` in state `y0` and has not moved yet.
fn empty_summary(t0: f64, y0: State) -> RunSummary {
    RunSummary {
        outcome: StickOutcome::Completed,
        end_time_s: t0,
        start_time_s: t0,
        mean_velocity_mps: 0.0,
        mode_time_s: [0.0; 4],
        transitions: [[0; 4]; 4],
        jams: 0,
        hops: 0,
        sticking_landings: 0,
        budget: Budget::default(),
        stats: Stats::default(),
        locate_evals: 0,
        certify: CertifyStats::default(),
        cycles: 0.0,
        sequence: String::new(),
        violations: Violations::default(),
        extents: Extents::default(),
        trace: Vec::new(),
        events: Vec::new(),
        event_count: 0,
        switches: Vec::new(),
        landings: Vec::new(),
        y_end: y0,
        mode_end: Mode::Pivot,
    }
}

/// [`simulate_stick`] with another rule set: `sys` (for example the printed rules of
/// [`super::printed`]) supplies flows, guards and transitions; `model` the geometry
/// and forces the summary is measured with; `start` is the first mode and state.
#[allow(clippy::too_many_arguments)]
pub(crate) fn simulate_system<S: HybridSystem<NSTATE, Mode = Mode, Stop = StickStop>>(
    sys: &S,
    model: &StickModel,
    start: super::rules::Next,
    t0: f64,
    y0: State,
    t_end: f64,
    opts: &Options,
    rec: Recording,
) -> RunSummary {
    let mut watch = Watch {
        model,
        rec,
        sum: empty_summary(t0, y0),
        acc: [0.0; 4],
        last_mode: None,
        next_sample_t: t0,
    };
    let (mode0, ys) = match start {
        super::rules::Next::To(m, y) => (m, model.canonical(m, t0, &y)),
        super::rules::Next::Stop(x) => {
            let mut s = watch.sum;
            s.outcome = StickOutcome::from_stop(x);
            return s;
        }
    };
    let opts = Options {
        record_events: false,
        ..*opts
    };
    let run = simulate(sys, mode0, t0, ys, t_end, &opts, &mut watch);
    let acc = watch.acc;
    let mut s = watch.sum;
    s.outcome = match run.outcome {
        Outcome::Completed => StickOutcome::Completed,
        Outcome::Stopped(x) => StickOutcome::from_stop(x),
        Outcome::Zeno { .. } => StickOutcome::Zeno,
        Outcome::Failed(OdeError::NonFinite { t_s }) => {
            StickOutcome::Invalid(InvalidReason::NonFinite {
                t_s,
                near_vertical: false,
            })
        }
        Outcome::Failed(e) => StickOutcome::Invalid(format!("integration failed: {e}").into()),
    };
    s.end_time_s = run.t_end_s;
    for (m, dt) in &run.mode_time_s {
        s.mode_time_s[m.index()] += dt;
    }
    let dur = run.t_end_s - t0;
    s.mean_velocity_mps = if dur > 0.0 {
        (run.y_end[XC] - y0[XC]) / dur
    } else {
        0.0
    };
    let mut y_end = model.canonical(run.mode_end, run.t_end_s, &run.y_end);
    for k in 0..4 {
        y_end[W_PLATE + k] += acc[k];
    }
    s.budget = model.budget(&y0, &y_end);
    s.stats = run.stats;
    s.locate_evals = run.locate_evals;
    s.certify = run.certify;
    s.cycles = dur / model.period_s;
    s.y_end = y_end;
    s.mode_end = run.mode_end;
    s
}
