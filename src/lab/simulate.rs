//! One lab run: the scene's main run (the code of `workbook stick-state-machine`,
//! [`crate::scenes::stick::main_run`]) with its trajectory sampled into
//! animation frames. The answer carries the CLI's report (`params` and `results`, the
//! `--json` format without the claims, which judge the document's own scenes) and the
//! CLI's `--events` CSV, so that the page's downloads are the CLI's files. Added for
//! issue 31: the stroboscopic view of the scene ([`cycle_view`], chapter 6's Poincare
//! section and multipliers) and chapter 8's rod with its massless ghost ([`rod_view`]).

use super::api::RunRequest;
use crate::physics::stick::run::{initial_state, simulate_stick, Recording, RunSummary, Sample};
use crate::physics::stick::{StickModel, StickParams, TH, XC, ZC};
use crate::physics::stick_inertia::limit;
use crate::physics::stick_inertia::run::{run_from_rest, InertiaOutcome, InertiaRun};
use crate::physics::stick_inertia::{InertiaModel, InertiaParams};
use crate::scenes::round;
use crate::scenes::stick::{self as scenes, main_run, poincare, Rules};
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// Animation frames per drive cycle: enough to see a hop of a fraction of a cycle.
pub const FRAMES_PER_CYCLE: f64 = 40.0;
/// Most frames in one answer (about 0.3 MB of JSON); longer runs are sampled coarser.
pub const MAX_FRAMES: f64 = 4000.0;
/// Most events and landings a lab run keeps in its lists (the answer shows the counts
/// and the events CSV, whose switches `main_run::recording` caps at 4000).
pub const LIST_CAP: usize = 4000;

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
    let mut report = req.chapter.report();
    for (key, value) in main_run::params(&req.settings, p, req.duration_s) {
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
        "events_csv": scenes::events_csv(&main),
        "frames": frames(&model, &main, dt),
        "scene": scene_facts(&model),
        // added for issue 31: the stroboscopic view and chapter 8's rod
        "cycle": cycle_view(req),
        "rod": rod_view(req, dt),
        "compute_ms": round(started.elapsed().as_secs_f64() * 1e3, 3),
    })
}

/// The run the CLI reports for the request (`main_run::run_main`'s second run), alone:
/// the lab has no claims to judge on the physical run, so it neither runs it twice under
/// `--rules printed` nor keeps a copy of its trace. Its recording keeps the trace's grid
/// samples only (the frames; not every step's end) and at most [`LIST_CAP`] events and
/// landings (the answer uses neither list): a run's memory is bounded by the frames,
/// not by its steps (docs/lab.md).
fn reported_run(req: &RunRequest, dt: f64) -> (RunSummary, BTreeMap<&'static str, u64>) {
    let rec = Recording {
        grid_only: true,
        list_cap: Some(LIST_CAP),
        ..main_run::recording(dt)
    };
    let (p, a) = (&req.params, &req.settings);
    match a.rules {
        Rules::Physical => (
            scenes::run_scene_from(p, a.start, req.duration_s, &req.opts, rec),
            BTreeMap::new(),
        ),
        Rules::Printed => {
            let printed = crate::physics::stick::printed::Printed::AS_PRINTED;
            scenes::run_printed_from(p, printed, a.start, req.duration_s, &req.opts, rec)
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

/// The trace thinned to one sample per `dt` (the samples on the grid; a lab run's trace
/// holds no others, `Recording::grid_only`), as columns: time (s), mode letter, theta (rad), x and z of
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

/// Most drive cycles of the stroboscopic view (the section points of a longer run
/// change by less than the screen's pixel once the orbit has settled).
pub const STROBE_MAX_CYCLES: usize = 120;
/// Largest period whose fixed point the lab looks for (chapter 6 section 5 finds
/// period 1 and 2 on its scenes).
pub const STROBE_MAX_PERIOD: usize = 2;

/// The stroboscopic (Poincare) view of the request's scene: chapter 6's section at
/// plate phase 0 ([`poincare`]), the orbit of the static start for the run's drive
/// cycles, the fixed point of `P^n` (`n` = 1, then 2) found by Newton from the orbit's
/// last point, its Floquet multipliers by central differences, each orbit point's
/// distance to it, and the contraction per cycle measured on the orbit (a second
/// estimate of the leading multiplier's modulus, by simulation alone).
pub fn cycle_view(req: &RunRequest) -> Value {
    let model = StickModel::new(req.params);
    let opts = &req.opts;
    // whole drive cycles f t (f = omega/2 pi carries rounding: 30 Hz is 29.999999999999996)
    let cycles = (req.duration_s * req.params.frequency_hz() * (1.0 + 1e-12)).floor() as usize;
    let Some(x0) = poincare::static_start(&model) else {
        return json!({ "orbit": [], "distance": [], "fixed": null, "ended": "invalid", "observed_ratio": null });
    };
    let mut orbit = vec![x0];
    let mut ended = None;
    for _ in 0..cycles.min(STROBE_MAX_CYCLES) {
        match poincare::strobe(&model, opts, orbit.last().expect("non-empty"), 1) {
            Ok(x) => orbit.push(x),
            Err(o) => {
                ended = Some(o.label());
                break;
            }
        }
    }
    let fixed = if ended.is_none() {
        fixed_point(
            &model,
            opts,
            req.settings.rtol,
            orbit.last().expect("non-empty"),
        )
    } else {
        None
    };
    let dist: Vec<Option<f64>> = orbit
        .iter()
        .map(|x| {
            let d = fixed
                .as_ref()
                .map_or(f64::INFINITY, |(f, _, _)| poincare::distance(&model, x, f));
            d.is_finite().then(|| round(d, 6))
        })
        .collect();
    let point = |x: &poincare::Point| json!({ "mode": x.mode.letter().to_string(), "s": x.s.iter().map(|v| round(*v, 9)).collect::<Vec<_>>() });
    json!({
        "section": "plate phase 0 (t = k T), from the static start",
        "orbit": orbit.iter().map(point).collect::<Vec<_>>(),
        "ended": ended,
        "distance": dist,
        "fixed": fixed.as_ref().map(|(x, n, m)| {
            let lead = poincare::moduli(m).first().copied().unwrap_or(f64::NAN);
            json!({
                "period": n,
                "point": point(x),
                "multipliers": m.iter().map(|z| [round(z.0, 6), round(z.1, 6)]).collect::<Vec<_>>(),
                "leading_modulus": round(lead, 6),
                "stable": lead < 1.0,
            })
        }),
        "observed_ratio": observed_ratio(&dist).map(|r| round(r, 6)),
    })
}

/// A fixed point of `P^n`, its period `n` and its Floquet multipliers `(re, im)`.
type Fixed = (poincare::Point, usize, Vec<(f64, f64)>);

/// The fixed point of `P^n` nearest `x` (n = 1 first) and its multipliers, by Newton
/// with central differences. The difference step `h = 1e-4` (units of the section's
/// scales) carries `rtol / h` of noise from each run; Newton stops at `1e3 rtol`.
fn fixed_point(
    model: &StickModel,
    opts: &crate::numerics::hybrid::Options,
    rtol: f64,
    x: &poincare::Point,
) -> Option<Fixed> {
    let h = 1e-4;
    let tol = (1e3 * rtol).max(1e-11);
    (1..=STROBE_MAX_PERIOD).find_map(|n| {
        let (f, _) = poincare::newton(model, opts, x, n, (h, tol, 8))?;
        let j = poincare::jacobian(model, opts, &f, n, h, poincare::Difference::Central)?;
        Some((f, n, poincare::multipliers(&j)))
    })
}

/// The orbit's contraction per cycle: `10^slope` of the least-squares line through
/// `log10 d_k` against `k` (a rotating approach, complex multipliers, makes single
/// ratios `d_(k+1)/d_k` wander), over the points whose distance to the fixed point
/// lies between 1e-7 (above the runs' rounding) and 1e-2 (inside the linear
/// neighbourhood); `None` with fewer than 8 such points.
pub fn observed_ratio(dist: &[Option<f64>]) -> Option<f64> {
    let pts: Vec<(f64, f64)> = dist
        .iter()
        .enumerate()
        .filter_map(|(k, d)| {
            d.filter(|v| (1e-7..1e-2).contains(v))
                .map(|v| (k as f64, v.log10()))
        })
        .collect();
    if pts.len() < 8 {
        return None;
    }
    // formula: d_k ~ |lambda|^k, so the slope of log10 d_k over k is log10 |lambda|
    Some(10f64.powf(crate::numerics::fit::slope(&pts)))
}

/// Chapter 8's rod (when the request's rod mass is above 0): the rigid rod with its
/// mass ([`crate::physics::stick_inertia`], plastic impacts as chapter 8's default)
/// from rest at its static angle, and beside it the massless model of the same stick,
/// chapter 6's with the whole mass `M = m + m_r` at P (chapter 8's outer solution,
/// [`limit::massless_params`]), both as frames; `null` for the massless rod.
pub fn rod_view(req: &RunRequest, dt: f64) -> Value {
    if req.rod_mass_kg <= 0.0 {
        return Value::Null;
    }
    let ip = InertiaParams {
        base: req.params,
        rod_mass_kg: req.rod_mass_kg,
        restitution: 0.0,
    };
    let model = InertiaModel::new(ip);
    let run = run_from_rest(&model, req.duration_s, &req.opts, dt);
    let geo = model.geo;
    let ghost_p = limit::massless_params(&ip);
    let ghost = StickModel::new(ghost_p);
    let y0 = initial_state(
        &ghost,
        0.0,
        ghost_p.static_angle().unwrap_or(ghost_p.theta0_rad),
    );
    let rec = Recording {
        sequence_cap: 0,
        trace_dt_s: dt,
        check_invariants: false,
        grid_only: true,
        list_cap: Some(LIST_CAP),
    };
    let g = simulate_stick(&ghost, 0.0, y0, req.duration_s, &req.opts, rec);
    let reason = match &run.outcome {
        InertiaOutcome::Invalid(w) => Some(w.clone()),
        _ => None,
    };
    json!({
        "rod_mass_kg": req.rod_mass_kg,
        "tip_mass_kg": req.params.mass_kg,
        "total_kg": geo.total_kg,
        "l_g_m": geo.l_g_m,
        "alpha": round(geo.alpha(), 6),
        "outcome": run.outcome.label(),
        "outcome_reason": reason,
        "mean_velocity_mps": run.mean_velocity_mps.is_finite().then_some(run.mean_velocity_mps),
        "impacts": run.impact_count,
        "painleve_events": run.painleve.len(),
        "frames": rod_frames(&model, &run, dt),
        "ghost": {
            "mass_kg": ghost_p.mass_kg,
            "outcome": g.outcome.label(),
            "mean_velocity_mps": g.mean_velocity_mps.is_finite().then_some(g.mean_velocity_mps),
            "frames": frames(&ghost, &g, dt),
        },
    })
}

/// The rod's trace as the same columns as [`frames`] (its samples are on the grid).
fn rod_frames(model: &InertiaModel, r: &InertiaRun, dt: f64) -> Value {
    use crate::physics::stick_inertia as si;
    let picked: Vec<&si::run::Sample> = r
        .trace
        .iter()
        .filter(|x| x.y.iter().all(|v| v.is_finite()))
        .collect();
    let col = |f: &dyn Fn(&si::run::Sample) -> f64| -> Vec<f64> {
        picked.iter().map(|x| round(f(x), 7)).collect()
    };
    let force = |x: &si::run::Sample| model.contact_eval(x.mode, x.t_s, &x.y);
    json!({
        "dt_s": dt,
        "t_s": col(&|x| x.t_s),
        "mode": picked.iter().map(|x| x.mode.letter()).collect::<String>(),
        "theta_rad": col(&|x| x.y[si::TH]),
        "x_c_m": col(&|x| x.y[si::XC]),
        "z_c_m": col(&|x| x.y[si::ZC]),
        "plate_z_m": col(&|x| model.plate(x.t_s).0),
        "f_x_n": col(&|x| force(x).map_or(0.0, |e| e.fx)),
        "f_z_n": col(&|x| force(x).map_or(0.0, |e| e.fz)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lab::api::parse_run;

    /// A request for the jamming scene with `over` merged in.
    fn request(over: serde_json::Value) -> RunRequest {
        let mut b = json!({
            "scene": "jamming", "theta0_rad": 0.3, "mu": 0.4, "gamma": 3, "frequency_hz": 30,
            "stiffness": 10, "damping": 0.01, "length_m": 0.15, "mass_kg": 1, "duration_s": 2,
        });
        for (k, v) in over.as_object().expect("an object") {
            b[k] = v.clone();
        }
        parse_run(b.to_string().as_bytes()).expect("a valid request")
    }

    #[test]
    fn the_stroboscope_finds_the_published_multipliers_and_the_orbit_shrinks_at_that_rate() {
        // chapter 6, section 5: |lambda| = 0.8906 (self-locking, stable) and 1.014
        // (authors', unstable), from the variational flows and saltation matrices; the
        // lab's come from Newton and central differences of the map, and the orbit's own
        // contraction (simulation alone) is a third estimate
        let c = cycle_view(&request(json!({"duration_s": 4})));
        let f = &c["fixed"];
        assert_eq!(f["period"], 1, "{c}");
        let lead = f["leading_modulus"].as_f64().expect("modulus");
        assert!((lead - 0.8906).abs() < 1e-3, "{lead}");
        assert_eq!(f["stable"], true);
        let seen = c["observed_ratio"].as_f64().expect("a contraction");
        assert!((seen - lead).abs() < 0.02 * lead, "{seen} vs {lead}");
        assert_eq!(c["orbit"].as_array().expect("orbit").len(), 121);
        let a = cycle_view(&request(json!({
            "scene": "authors", "theta0_rad": 0.4280861692, "gamma": 10
        })));
        let lead = a["fixed"]["leading_modulus"].as_f64().expect("modulus");
        assert!((lead - 1.014).abs() < 2e-3, "{lead}");
        assert_eq!(a["fixed"]["stable"], false);
    }

    #[test]
    fn the_contraction_of_a_rotating_geometric_sequence_is_its_ratio() {
        // d_k = 0.9^k (1 + 0.3 cos k): single ratios wander by 30 %, the fit does not
        let d: Vec<Option<f64>> = (0..200)
            .map(|k| Some(0.9f64.powi(k) * (1.0 + 0.3 * (k as f64).cos())))
            .collect();
        let r = observed_ratio(&d).expect("enough points");
        assert!((r - 0.9).abs() < 2e-3, "{r}");
        assert_eq!(observed_ratio(&[Some(1e-3); 5]), None);
    }

    #[test]
    fn the_rod_tends_to_its_massless_ghost_linearly_in_its_mass() {
        // chapter 8, section 4: v(eps) = v_0 + c_1 eps + O(eps^2), eps ~ m_r: the gap to
        // the ghost (chapter 6 with all the mass at P) halves with the rod's mass
        let gap = |m_r: f64| {
            let r = rod_view(&request(json!({"rod_mass_kg": m_r})), 1.0 / 1200.0);
            assert_eq!(r["outcome"], "completed", "{m_r}");
            let v = r["mean_velocity_mps"].as_f64().expect("v");
            let g = r["ghost"]["mean_velocity_mps"].as_f64().expect("ghost v");
            (v - g, g)
        };
        let (d1, g) = gap(1e-4);
        let (d2, _) = gap(2e-4);
        assert!(d1.abs() < 1e-3 * g.abs(), "{d1} of {g}");
        assert!((d2 / d1 - 2.0).abs() < 0.1, "{d2} / {d1}");
        let (d, g) = gap(0.5);
        assert!(
            d.abs() > 0.1 * g.abs(),
            "a heavy rod walks differently: {d} of {g}"
        );
        assert_eq!(rod_view(&request(json!({})), 1e-3), Value::Null);
    }

    #[test]
    fn the_rods_frames_follow_its_run() {
        let req = request(json!({"rod_mass_kg": 0.5}));
        let j = run(&req);
        let f = &j["rod"]["frames"];
        let t: Vec<f64> = serde_json::from_value(f["t_s"].clone()).expect("times");
        let x: Vec<f64> = serde_json::from_value(f["x_c_m"].clone()).expect("x_c");
        // 40 frames a drive cycle over 2 s at 30 Hz, from 0
        assert!((2399..=2402).contains(&t.len()), "{}", t.len());
        assert_eq!(t[0], 0.0);
        let fz: Vec<f64> = serde_json::from_value(f["f_z_n"].clone()).expect("f_z");
        let modes = f["mode"].as_str().expect("modes");
        assert_eq!(modes.len(), t.len());
        // in contact the plate pushes (F_z >= 0), in flight there is no force
        for (c, fz) in modes.chars().zip(&fz) {
            assert!(if c == 'F' { *fz == 0.0 } else { *fz >= -1e-6 }, "{c} {fz}");
        }
        let n = t.len() - 1;
        let v = j["rod"]["mean_velocity_mps"].as_f64().expect("v");
        let v_frames = (x[n] - x[0]) / (t[n] - t[0]);
        assert!((v_frames - v).abs() < 2e-3 * v.abs(), "{v_frames} vs {v}");
    }
}
