//! One lab run: the chapter's main run (the code of `workbook stick-state-machine`,
//! [`crate::chapters::stick_state_machine::main_run`]) with its trajectory sampled into
//! animation frames. The answer carries the CLI's report (`params` and `results`, the
//! `--json` format without the claims, which judge the document's own scenes) and the
//! CLI's `--events` CSV, so that the page's downloads are the CLI's files.

use super::api::RunRequest;
use crate::chapters::stick_state_machine::{self as ssm, main_run, round};
use crate::physics::stick::run::{RunSummary, Sample};
use crate::physics::stick::{StickModel, StickParams, TH, XC, ZC};
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// Animation frames per drive cycle: enough to see a hop of a fraction of a cycle.
pub const FRAMES_PER_CYCLE: f64 = 40.0;
/// Most frames in one answer (about 0.3 MB of JSON); longer runs are sampled coarser.
pub const MAX_FRAMES: f64 = 4000.0;

/// The interval between frames (s) for a run of `duration_s` at `p`'s frequency.
pub fn frame_dt_s(p: &StickParams, duration_s: f64) -> f64 {
    (p.period_s() / FRAMES_PER_CYCLE).max(duration_s / MAX_FRAMES)
}

/// Runs a validated request; the answer's JSON.
pub fn run(req: &RunRequest) -> Value {
    let started = std::time::Instant::now();
    let p = &req.params;
    let dt = frame_dt_s(p, req.duration_s);
    let (mut main, fired) = reported_run(req, dt);
    let mut report = crate::chapters::info(ssm::ID).expect("registered").report();
    for (key, value) in main_run::params(&req.args, p, req.duration_s) {
        report.param(key, value);
    }
    for (key, value) in main_run::results(&mut main, p, &fired) {
        report.result(key, value);
    }
    let model = StickModel::new(*p);
    let report = report.to_json();
    json!({
        "seq": req.seq,
        // the CLI's `--json` line, for the download (the object, for the page)
        "report_text": report.to_string(),
        "report": report,
        "events_csv": ssm::events_csv(&main),
        "frames": frames(&model, &main, dt),
        "scene": scene_facts(&model),
        "compute_ms": round(started.elapsed().as_secs_f64() * 1e3, 3),
    })
}

/// The run the CLI reports for the request (`main_run::run_main`'s second run), alone:
/// the lab has no claims to judge on the physical run, so it neither runs it twice under
/// `--rules printed` nor keeps a copy of its trace (each trace holds a sample per
/// integration step: one copy fewer halves a run's peak memory, docs/lab.md).
fn reported_run(req: &RunRequest, dt: f64) -> (RunSummary, BTreeMap<&'static str, u64>) {
    let (p, a, rec) = (&req.params, &req.args, main_run::recording(dt));
    match a.rules {
        ssm::Rules::Physical => (
            ssm::run_scene_from(p, a.start, req.duration_s, &req.opts, rec),
            BTreeMap::new(),
        ),
        ssm::Rules::Printed => {
            let printed = crate::physics::stick::printed::Printed::AS_PRINTED;
            ssm::run_printed_from(p, printed, a.start, req.duration_s, &req.opts, rec)
        }
    }
}

/// The fixed facts the page draws with: the rod length, the plate amplitude, the
/// friction cone's half-angle and the static angle.
fn scene_facts(model: &StickModel) -> Value {
    let p = &model.p;
    json!({
        "length_m": p.length_m,
        "plate_amplitude_m": p.plate.amplitude_m,
        "period_s": p.period_s(),
        "mu": p.mu,
        "theta0_rad": p.theta0_rad,
        "static_angle_rad": p.static_angle(),
        "weight_n": p.mass_kg * p.g_mps2,
    })
}

/// The trace thinned to one sample per `dt` (the samples on the grid; the trace also
/// holds every step's end), as columns: time (s), mode letter, theta (rad), x and z of
/// C (m), plate height (m), contact force on C (N, zero in flight), and the energy
/// accumulators (J).
fn frames(model: &StickModel, s: &RunSummary, dt: f64) -> Value {
    let picked: Vec<&Sample> = thin(&s.trace, dt);
    let col = |f: &dyn Fn(&Sample) -> f64| -> Vec<f64> {
        picked.iter().map(|x| round(f(x), 7)).collect()
    };
    let force = |x: &Sample| model.contact_eval(x.mode, x.t_s, &x.y);
    json!({
        "dt_s": dt,
        "t_s": col(&|x| x.t_s),
        "mode": picked.iter().map(|x| x.mode.letter()).collect::<String>(),
        "theta_rad": col(&|x| x.y[TH]),
        "x_c_m": col(&|x| x.y[XC]),
        "z_c_m": col(&|x| x.y[ZC]),
        "plate_z_m": col(&|x| model.plate(x.t_s).0),
        "f_x_n": col(&|x| force(x).map_or(0.0, |e| e.fx)),
        "f_z_n": col(&|x| force(x).map_or(0.0, |e| e.fz)),
    })
}

/// The samples at or just after each multiple of `dt`.
fn thin(trace: &[Sample], dt: f64) -> Vec<&Sample> {
    let mut out = Vec::new();
    let mut next = f64::NEG_INFINITY;
    for x in trace {
        if x.t_s >= next && x.y.iter().all(|v| v.is_finite()) {
            out.push(x);
            next = x.t_s + dt * (1.0 - 1e-9);
        }
    }
    out
}
