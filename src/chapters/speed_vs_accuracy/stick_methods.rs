//! The stick by three methods: event-driven (DOP853 and DP5, a ladder of tolerances),
//! Moreau-Jean time-stepping (a ladder of steps) and soft contact (a ladder of the
//! regularisation `eps`, each integrated by Rosenbrock 2(3) at a converged tolerance),
//! all measured on the stick's mean speed against the event-driven reference.
//!
//! No stepping here: the runs are [`crate::physics::stick::run::simulate_stick`] (via
//! [`super::measure::stick_speed`]), [`simulate_stick_mj`] and
//! [`crate::physics::stick::soft::run::simulate_soft`] (its family given one by one).

use super::measure::stick_speed;
use crate::ladder::{relative_to, Run, Timing};
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::stick::soft::run::{simulate_soft_with, SoftOutcome};
use crate::physics::stick::soft::SoftParams;
use crate::physics::stick::timestepping::simulate_stick_mj;
use crate::physics::stick::{StickModel, StickParams};
use serde_json::{json, Value};

/// One run of a ladder: its setting (the knob: rtol, step h in s, or eps), the mean
/// speed of C (m/s; NaN when the run failed), its relative difference from the
/// reference (`error`) and its cost (force evaluations, steps, wall time).
pub type Rung = crate::ladder::Rung<f64>;

/// One method's ladder, coarse to fine.
#[derive(Debug, Clone, PartialEq)]
pub struct Ladder {
    /// JSON key: `event_dop853`, `event_dopri5`, `moreau_jean`, `soft_contact`.
    pub method: &'static str,
    /// What the knob is: `rtol`, `h_s` or `eps`.
    pub knob_name: &'static str,
    /// The runs.
    pub rungs: Vec<Rung>,
    /// Why a run did not complete (the last such run), if one did not.
    pub note: Option<String>,
}

/// The four ladders of one scene and their reference.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneMethods {
    /// Event-driven DOP853 at rtol = atol = 1e-13 (m/s).
    pub reference_mps: f64,
    /// Drive cycles of every run.
    pub cycles: f64,
    /// Ladders in the order event-driven DOP853, event-driven DP5, Moreau-Jean, soft
    /// contact (the charts' `STICK_METHODS`, `figures.rs`).
    pub ladders: Vec<Ladder>,
}

/// Tolerance of the soft model's integration: converged in time for this ladder (at
/// eps = 0.003125 the mean speed moves by 1.1e-7 relative from rtol 1e-10 to 1e-11, 3e-7
/// from 1e-9: 1.4 % of its regularisation error 7.8e-5; at eps = 0.0015625 by 1.8e-7
/// from 1e-10 to 1e-12, 0.5 % of 3.7e-5).
pub const SOFT_RTOL: f64 = 1e-10;

/// Step budget of one soft-contact run: the finest rung of the full ladder (eps =
/// 0.00078125, 2 periods) takes 2.8e4 steps; five times that bounds a run to seconds.
pub const SOFT_BUDGET: u64 = 150_000;

/// Sizes of the ladders.
#[derive(Debug, Clone)]
pub struct Plan {
    /// Drive cycles per run.
    pub cycles: f64,
    /// Event-driven tolerances.
    pub tols: Vec<f64>,
    /// Moreau-Jean steps per period (each twice the last).
    pub mj_steps: Vec<u32>,
    /// Regularisations (each half the last).
    pub eps: Vec<f64>,
    /// The soft model's family: its contact constants at `eps`.
    pub soft_family: fn(&StickParams, f64) -> SoftParams,
}

impl Plan {
    /// The quick or the full plan.
    pub fn new(quick: bool) -> Self {
        if quick {
            Plan {
                cycles: 2.0,
                tols: vec![1e-6, 1e-9, 1e-12],
                mj_steps: vec![2000, 4000, 8000],
                // three rungs inside the asymptotic range (local orders 1.05, 1.10)
                eps: vec![0.0125, 0.00625, 0.003125],
                soft_family: SoftParams::regularised,
            }
        } else {
            Plan {
                cycles: 2.0,
                tols: (4..=12).map(|k| 10f64.powi(-k)).collect(),
                mj_steps: vec![500, 1000, 2000, 4000, 8000, 16000, 32000, 64000],
                eps: (0..8).map(|k| 0.1 * 0.5f64.powi(k)).collect(),
                soft_family: SoftParams::regularised,
            }
        }
    }
}

/// Climbs `knobs` once each (wall time of one run); the error is relative to
/// `reference`.
fn climb(knobs: &[f64], reference: f64, run: impl FnMut(&f64) -> Run) -> Vec<Rung> {
    crate::ladder::climb(knobs.iter().copied(), Timing::MinOf(1), relative_to(reference), run)
}

/// Runs the four ladders on scene `p`.
pub fn measure_scene(p: &StickParams, plan: &Plan) -> SceneMethods {
    let model = StickModel::new(*p);
    let cycles = plan.cycles;
    let event = |method: Method, tol: f64| {
        let opts = Options {
            method,
            control: StepControl::tol(tol, tol),
            ..Options::default()
        };
        let m = stick_speed(&model, cycles, &opts).0;
        Run {
            value: if m.completed { m.value } else { f64::NAN },
            ..crate::ladder::Run::from(&m)
        }
    };
    let reference = event(Method::Dop853, 1e-13).value;
    let mut ladders = Vec::new();
    for (key, method) in [
        ("event_dop853", Method::Dop853),
        ("event_dopri5", Method::Dopri5),
    ] {
        ladders.push(Ladder {
            method: key,
            knob_name: "rtol",
            rungs: climb(&plan.tols, reference, |&tol| event(method, tol)),
            note: None,
        });
    }
    ladders.push(mj_ladder(p, plan, reference));
    ladders.push(soft_ladder(p, plan, reference));
    SceneMethods {
        reference_mps: reference,
        cycles,
        ladders,
    }
}

/// The Moreau-Jean ladder of `plan` on scene `p` (steps per period; the knob is the
/// step h in s).
fn mj_ladder(p: &StickParams, plan: &Plan, reference: f64) -> Ladder {
    let period = p.period_s();
    let (mut ambiguous, mut contact) = (0, 0);
    let steps: Vec<f64> = plan
        .mj_steps
        .iter()
        .map(|&n| period / f64::from(n))
        .collect();
    let rungs = climb(&steps, reference, |&h| {
        let n = (period / h).round() as u32; // the steps per period of this rung
        // diagnose: every local problem's solutions are listed (Painleve-like cases)
        let r = simulate_stick_mj(p, plan.cycles, n, true);
        ambiguous += r.ambiguous_steps;
        contact += r.stats.contact_steps;
        Run {
            value: if r.completed {
                r.mean_velocity_mps
            } else {
                f64::NAN
            },
            rhs_evals: r.stats.rhs_evals,
            steps: r.stats.steps,
            completed: r.completed,
        }
    });
    Ladder {
        method: "moreau_jean",
        knob_name: "h_s",
        rungs,
        note: Some(format!(
            "{ambiguous} of {contact} contact steps over the ladder had more than one solution of the local problem"
        )),
    }
}

/// The soft-contact ladder of `plan` on scene `p` (Rosenbrock 2(3) at [`SOFT_RTOL`]).
pub fn soft_ladder(p: &StickParams, plan: &Plan, reference: f64) -> Ladder {
    let control = StepControl::tol(SOFT_RTOL, SOFT_RTOL);
    let mut note = None;
    let rungs = climb(&plan.eps, reference, |&eps| {
        let soft = (plan.soft_family)(p, eps);
        let r = simulate_soft_with(
            p,
            soft,
            plan.cycles,
            Method::Rosenbrock23,
            control,
            SOFT_BUDGET,
        );
        let completed = match r.outcome {
            SoftOutcome::Completed => true,
            SoftOutcome::Failed(e) => {
                note = Some(format!("ε = {eps}: {e}"));
                false
            }
            SoftOutcome::Budget { t_s } => {
                note = Some(format!("ε = {eps}: step budget spent at t = {t_s:.4} s"));
                false
            }
        };
        Run {
            value: if completed {
                r.mean_velocity_mps
            } else {
                f64::NAN
            },
            rhs_evals: r.stats.rhs_evals,
            steps: r.stats.accepted,
            completed,
        }
    });
    Ladder {
        method: "soft_contact",
        knob_name: "eps",
        rungs,
        note,
    }
}

impl SceneMethods {
    /// The ladder of `method`.
    pub fn ladder(&self, method: &str) -> &Ladder {
        self.ladders
            .iter()
            .find(|l| l.method == method)
            .expect("a measured method")
    }

    /// The results object: per method its finest setting, mean speed, relative
    /// difference from the reference and cost, and the whole ladder.
    pub fn to_json(&self) -> Value {
        let mut out = serde_json::Map::new();
        out.insert(
            "reference_mean_velocity_mps".into(),
            json!(self.reference_mps),
        );
        out.insert("cycles".into(), json!(self.cycles));
        for l in &self.ladders {
            let f = l.rungs.last().expect("a rung");
            let ladder: Vec<Value> = l
                .rungs
                .iter()
                .map(|r| {
                    let mut o = json!({l.knob_name: r.setting, "cost_evaluations": r.cost.rhs_evals, "wall_s": r.cost.wall_s});
                    put_finite(&mut o, "relative_difference", r.error);
                    o
                })
                .collect();
            let mut o = json!({
                "finest_setting": {l.knob_name: f.setting},
                "cost_evaluations": f.cost.rhs_evals,
                "wall_s": f.cost.wall_s,
                "completed": l.rungs.iter().all(|r| r.value.is_finite()),
                "ladder": ladder,
            });
            put_finite(&mut o, "mean_velocity_mps", f.value);
            put_finite(&mut o, "relative_difference", f.error);
            if let Some(n) = &l.note {
                o["note"] = json!(n);
            }
            out.insert(l.method.into(), o);
        }
        Value::Object(out)
    }
}

/// Sets `o[key] = x` when `x` is finite (results carry no NaN and no null: a run that
/// did not complete says so in `completed` and `note`).
fn put_finite(o: &mut Value, key: &str, x: f64) {
    if x.is_finite() {
        o[key] = json!(x);
    }
}

/// Least-squares slope of ln(error) against ln(knob) over the rungs: the observed order.
pub fn fitted_order(l: &Ladder) -> f64 {
    crate::ladder::observed_order(&l.rungs, |&knob| knob, |_| true)
}

/// The gap at the finest setting over its Richardson estimate for a method of order
/// `p` whose last two knobs differ by a factor 2: `|v_f - v_2f| / (2^p - 1)` estimates
/// `|v_f - v_exact|` when the error is `C knob^p`, so the ratio is 1 in the
/// asymptotic range.
pub fn gap_over_estimate(l: &Ladder, reference: f64, p: f64) -> f64 {
    let n = l.rungs.len();
    if n < 2 {
        return f64::NAN;
    }
    let (f, c) = (&l.rungs[n - 1], &l.rungs[n - 2]);
    let estimate = (f.value - c.value).abs() / (2f64.powf(p) - 1.0); // formula: Richardson |v_h - v_2h| / (2^p - 1)
    (f.value - reference).abs() / estimate
}
