//! The stick by three methods: event-driven (DOP853 and DP5, a ladder of tolerances),
//! Moreau-Jean time-stepping (a ladder of steps) and soft contact (a ladder of the
//! regularisation `eps`, each integrated by Rosenbrock 2(3) at a converged tolerance),
//! all measured on the stick's mean speed against the event-driven reference.
//!
//! No stepping here: the runs are [`crate::physics::stick::run::simulate_stick`] (via
//! [`super::measure::stick_speed`]), [`simulate_stick_mj`] and
//! [`crate::physics::stick::soft::run::simulate_soft`] (its family given one by one).

use super::measure::{stick_speed, timed};
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::stick::soft::run::{simulate_soft_with, SoftOutcome};
use crate::physics::stick::soft::SoftParams;
use crate::physics::stick::timestepping::simulate_stick_mj;
use crate::physics::stick::{StickModel, StickParams};
use crate::report::{Check, Claim};
use serde_json::{json, Value};

/// One run of a ladder.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rung {
    /// The setting: rtol (event-driven), step h (s, Moreau-Jean) or eps (soft contact).
    pub knob: f64,
    /// Mean speed of C (m/s); NaN when the run failed.
    pub value: f64,
    /// Relative difference from the reference.
    pub rel: f64,
    /// Force (right-hand-side) evaluations.
    pub evals: u64,
    /// Wall time (s).
    pub wall_s: f64,
}

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
    /// Ladders in the order of [`METHODS`].
    pub ladders: Vec<Ladder>,
}

/// The methods, in the order of the ladders.
pub const METHODS: [&str; 4] = [
    "event_dop853",
    "event_dopri5",
    "moreau_jean",
    "soft_contact",
];

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

fn rung(knob: f64, value: f64, evals: u64, wall_s: f64, reference: f64) -> Rung {
    Rung {
        knob,
        value,
        rel: ((value - reference) / reference).abs(), // formula: |v - v_ref| / |v_ref|
        evals,
        wall_s,
    }
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
        timed(1, || stick_speed(&model, cycles, &opts).0)
    };
    let reference = event(Method::Dop853, 1e-13).0.value;
    let mut ladders = Vec::new();
    for (key, method) in [
        ("event_dop853", Method::Dop853),
        ("event_dopri5", Method::Dopri5),
    ] {
        let rungs = plan
            .tols
            .iter()
            .map(|&tol| {
                let (m, wall) = event(method, tol);
                let v = if m.completed { m.value } else { f64::NAN };
                rung(tol, v, m.rhs_evals, wall, reference)
            })
            .collect();
        ladders.push(Ladder {
            method: key,
            knob_name: "rtol",
            rungs,
            note: None,
        });
    }
    let period = p.period_s();
    let (mut ambiguous, mut contact) = (0, 0);
    let rungs = plan
        .mj_steps
        .iter()
        .map(|&n| {
            // diagnose: every local problem's solutions are listed (Painleve-like cases)
            let (r, wall) = timed(1, || simulate_stick_mj(p, cycles, n, true));
            ambiguous += r.ambiguous_steps;
            contact += r.stats.contact_steps;
            let v = if r.completed {
                r.mean_velocity_mps
            } else {
                f64::NAN
            };
            rung(period / f64::from(n), v, r.stats.rhs_evals, wall, reference)
        })
        .collect();
    ladders.push(Ladder {
        method: "moreau_jean",
        knob_name: "h_s",
        rungs,
        note: Some(format!(
            "{ambiguous} of {contact} contact steps over the ladder had more than one solution of the local problem"
        )),
    });
    ladders.push(soft_ladder(p, plan, reference));
    SceneMethods {
        reference_mps: reference,
        cycles,
        ladders,
    }
}

/// The soft-contact ladder of `plan` on scene `p` (Rosenbrock 2(3) at [`SOFT_RTOL`]).
pub fn soft_ladder(p: &StickParams, plan: &Plan, reference: f64) -> Ladder {
    let control = StepControl::tol(SOFT_RTOL, SOFT_RTOL);
    let mut note = None;
    let rungs = plan
        .eps
        .iter()
        .map(|&eps| {
            let soft = (plan.soft_family)(p, eps);
            let (r, wall) = timed(1, || {
                simulate_soft_with(
                    p,
                    soft,
                    plan.cycles,
                    Method::Rosenbrock23,
                    control,
                    SOFT_BUDGET,
                )
            });
            let v = match r.outcome {
                SoftOutcome::Completed => r.mean_velocity_mps,
                SoftOutcome::Failed(e) => {
                    note = Some(format!("ε = {eps}: {e}"));
                    f64::NAN
                }
                SoftOutcome::Budget { t_s } => {
                    note = Some(format!("ε = {eps}: step budget spent at t = {t_s:.4} s"));
                    f64::NAN
                }
            };
            rung(eps, v, r.stats.rhs_evals, wall, reference)
        })
        .collect();
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
                    let mut o = json!({l.knob_name: r.knob, "cost_evaluations": r.evals, "wall_s": r.wall_s});
                    put_finite(&mut o, "relative_difference", r.rel);
                    o
                })
                .collect();
            let mut o = json!({
                "finest_setting": {l.knob_name: f.knob},
                "cost_evaluations": f.evals,
                "wall_s": f.wall_s,
                "completed": l.rungs.iter().all(|r| r.value.is_finite()),
                "ladder": ladder,
            });
            put_finite(&mut o, "mean_velocity_mps", f.value);
            put_finite(&mut o, "relative_difference", f.rel);
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

/// Least-squares slope of ln(rel) against ln(knob) over the rungs: the observed order.
pub fn fitted_order(l: &Ladder) -> f64 {
    let pts: Vec<(f64, f64)> = l
        .rungs
        .iter()
        .filter(|r| r.rel.is_finite() && r.rel > 0.0)
        .map(|r| (r.knob.ln(), r.rel.ln()))
        .collect();
    crate::numerics::fit::slope(&pts) // formula: order = cov(ln knob, ln err) / var(ln knob)
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
    let (f, c) = (l.rungs[n - 1], l.rungs[n - 2]);
    let estimate = (f.value - c.value).abs() / (2f64.powf(p) - 1.0); // formula: Richardson |v_h - v_2h| / (2^p - 1)
    (f.value - reference).abs() / estimate
}

/// The claims on the default scene, with the order the statements assert (`mj_order`:
/// 1; a mutation passes another).
pub fn claims(s: &SceneMethods, mj_order: f64) -> Vec<Claim> {
    let mj = s.ladder("moreau_jean");
    vec![
        // Moreau-Jean is first order (derivation in the chapter); the fit over the
        // ladder scatters by the event-phase term (measured 0.99 to 1.01 over T/2000 ..
        // T/8000): +-0.3 as for the block's first-order methods.
        Claim::draft(
            Check::Convergence,
            "stick-methods-moreau-jean-order",
            "4, 5",
            "Moreau-Jean time-stepping of the stick (the massless rod's balance implicit over each step) converges to the event-driven mean speed at order 1 in the step h (least-squares slope over the ladder)",
        )
        .close(mj_order, fitted_order(mj), 0.3),
        // The finest rung's gap from the reference against its own Richardson estimate:
        // ratio 1 in the asymptotic range; +-0.5 for the O(h) change of the error
        // constant between the last two rungs (a wrong order p changes the ratio by the
        // factor 2^p - 1, 3 for p = 2).
        Claim::draft(
            Check::Convergence,
            "stick-methods-moreau-jean-gap-within-estimate",
            "4, 5",
            "Moreau-Jean's gap from the event-driven speed at its finest step equals its own Richardson error estimate |v_h - v_2h| / (2^p - 1), p = 1 (ratio)",
        )
        .close(1.0, gap_over_estimate(mj, s.reference_mps, mj_order), 0.5),
    ]
}
