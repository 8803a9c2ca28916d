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
pub struct Seen {
    /// The pair.
    pub method: Method,
    /// rtol = atol.
    pub rtol: f64,
    /// The phase letters of the run.
    pub sequence: String,
    /// Hops.
    pub hops: usize,
}

/// The scene's runs: the reference and the tolerance ladder of both pairs, with the
/// certified search and with the search that compares signs at step ends only.
#[derive(Debug, Clone, PartialEq)]
pub struct MissedEvent {
    /// DP5 at 1e-13, certified.
    pub reference: Seen,
    /// The ladder, certified search.
    pub certified: Vec<Seen>,
    /// The ladder, signs at step ends only.
    pub blind: Vec<Seen>,
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

/// Runs the reference and both ladders.
pub fn gather() -> MissedEvent {
    MissedEvent {
        reference: run(Method::Dopri5, 1e-13, true),
        certified: ladder(true),
        blind: ladder(false),
    }
}

impl MissedEvent {
    /// The runs of the ladder whose phase sequence differs from the reference's:
    /// "method at rtol: hops".
    pub fn differing(&self, certified: bool) -> Vec<String> {
        let runs = if certified {
            &self.certified
        } else {
            &self.blind
        };
        runs.iter()
            .filter(|s| s.sequence != self.reference.sequence)
            .map(|s| format!("{} at {:e}: {} hops", s.method.name(), s.rtol, s.hops))
            .collect()
    }

    /// One failure row per uncertified run that loses a transition.
    pub fn failures(&self) -> Vec<Failure> {
        let reference = &self.reference;
        self.blind
            .iter()
            .filter(|s| s.sequence != reference.sequence)
            .map(|s| Failure {
                method: format!("{}-uncertified", s.method.name()),
                scene: format!(
                    "stick, authors' scene at g = 9.81, 0.4 s, rtol = {:e}",
                    s.rtol
                ),
                symptom: format!(
                    "steps over a short lift-off: {} hops against {} (certified search: {})",
                    s.hops,
                    reference.hops,
                    self.certified
                        .iter()
                        .find(|c| c.method == s.method && c.rtol == s.rtol)
                        .map_or(0, |c| c.hops)
                ),
            })
            .collect()
    }

    /// The result `missed_event`: the hops of every run.
    pub fn json(&self) -> serde_json::Value {
        let hops = |runs: &[Seen]| -> serde_json::Map<String, serde_json::Value> {
            runs.iter()
                .map(|s| (format!("{}_{:e}", s.method.name(), s.rtol), json!(s.hops)))
                .collect()
        };
        json!({
            "reference_hops": self.reference.hops,
            "certified_hops": hops(&self.certified),
            "uncertified_hops": hops(&self.blind),
        })
    }
}
