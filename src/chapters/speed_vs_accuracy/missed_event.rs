//! The missed event: a short lift-off that the end-point sign test steps over.
//!
//! Scene: the authors' stick with the document's g = 9.81 m/s^2 (their code uses 10)
//! over 0.4 s. Its ninth hop begins with a lift-off shorter than one DOP853 step: the
//! normal-force guard is positive at both ends of that step, so a search that compares
//! signs at step ends sees nothing, and which tolerances miss it depends on where the
//! steps happen to fall. The certified search (`numerics::events::hidden_crossing`)
//! bounds every guard over every step from its values and rates and finds it at every
//! tolerance with both pairs.

use super::failures::Failure;
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::stick::run::{initial_state, simulate_stick, Recording};
use crate::physics::stick::{authors_scene, StickModel};
use crate::report::{ChapterReport, Check, Claim, Mutation};
use serde_json::json;

/// Simulated time (s).
const DURATION_S: f64 = 0.4;
/// Gravity of the scene (m/s^2): the document's value.
const G_MPS2: f64 = 9.81;
/// The tolerance ladder (rtol = atol).
const RTOLS: [f64; 4] = [1e-8, 1e-9, 1e-10, 1e-12];
/// Phase letters kept per run (the scene has about 60 transitions).
const SEQUENCE_CAP: usize = 400;

/// One run's discrete outcome.
#[derive(Debug, Clone, PartialEq)]
struct Seen {
    method: Method,
    rtol: f64,
    sequence: String,
    hops: usize,
}

fn run(method: Method, rtol: f64, certify: bool) -> Seen {
    let p = authors_scene(G_MPS2);
    let model = StickModel::new(p);
    let y0 = initial_state(&model, 0.0, p.static_angle().unwrap_or(p.theta0_rad));
    let opts = Options {
        method,
        control: StepControl::tol(rtol, rtol),
        certify,
        ..Options::default()
    };
    let rec = Recording {
        sequence_cap: SEQUENCE_CAP,
        ..Recording::default()
    };
    let s = simulate_stick(&model, 0.0, y0, DURATION_S, &opts, rec);
    Seen {
        method,
        rtol,
        sequence: s.sequence,
        hops: s.hops,
    }
}

fn ladder(certify: bool) -> Vec<Seen> {
    [Method::Dop853, Method::Dopri5]
        .into_iter()
        .flat_map(|m| RTOLS.into_iter().map(move |tol| run(m, tol, certify)))
        .collect()
}

/// The claim: every run of the ladder has the reference's phase sequence.
fn judge(runs: &[Seen], reference: &Seen, search: &str) -> Claim {
    let differing: Vec<String> = runs
        .iter()
        .filter(|s| s.sequence != reference.sequence)
        .map(|s| format!("{} at {:e}: {} hops", s.method.name(), s.rtol, s.hops))
        .collect();
    Claim::draft(
        Check::SecondMethod,
        "stick-no-missed-event",
        "4, 5",
        &format!(
            "With the {search} event search, both Dormand-Prince pairs at every rtol from 1e-8 to 1e-12 give the phase sequence of the reference (DP5 at 1e-13, certified) on the authors' stick at g = 9.81 m/s² over 0.4 s, whose ninth hop starts with a lift-off shorter than one step; the computed value lists the runs that differ"
        ),
    )
    .exact(json!([]), json!(differing))
}

/// Adds the claim `stick-no-missed-event`, the result `missed_event` and, for every
/// uncertified run that loses a transition, a failure row.
pub fn build(r: &mut ChapterReport, fails: &mut Vec<Failure>) {
    let reference = run(Method::Dopri5, 1e-13, true);
    let certified = ladder(true);
    r.claim(judge(&certified, &reference, "certified"));
    let blind = ladder(false);
    for s in blind.iter().filter(|s| s.sequence != reference.sequence) {
        fails.push(Failure {
            method: format!("{}-uncertified", s.method.name()),
            scene: format!(
                "stick, authors' scene at g = 9.81, 0.4 s, rtol = {:e}",
                s.rtol
            ),
            symptom: format!(
                "steps over a short lift-off: {} hops against {} (certified search: {})",
                s.hops,
                reference.hops,
                certified
                    .iter()
                    .find(|c| c.method == s.method && c.rtol == s.rtol)
                    .map_or(0, |c| c.hops)
            ),
        });
    }
    let hops = |runs: &[Seen]| -> serde_json::Map<String, serde_json::Value> {
        runs.iter()
            .map(|s| (format!("{}_{:e}", s.method.name(), s.rtol), json!(s.hops)))
            .collect()
    };
    r.result(
        "missed_event",
        json!({
            "reference_hops": reference.hops,
            "certified_hops": hops(&certified),
            "uncertified_hops": hops(&blind),
        }),
    );
}

/// The falsification of `stick-no-missed-event`: the same ladder with the search that
/// compares signs at step ends only. It loses the short lift-off at some tolerances,
/// so the claim's verdict turns to failed.
pub fn mutation() -> Mutation {
    Mutation::new(
        "stick-no-missed-event",
        "event search without certification (signs at step ends only)",
        || {
            let reference = run(Method::Dopri5, 1e-13, true);
            judge(&ladder(false), &reference, "uncertified")
        },
    )
}
