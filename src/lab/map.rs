//! The lab's (theta_0, mu) speed map: chapter 6's map (the late mean speed of C after a
//! start transient, the scene's own cell code, `main_run::map_cell_speed`) on a coarse
//! grid over the chapter's ranges, for the scene of the request with its theta_0 and mu
//! swept. Each map is computed once per scene and kept (the last [`KEPT`] scenes), so a
//! click on the map or a move of the theta_0 or mu slider costs nothing.

use super::api::RunRequest;
use crate::scenes::round;
use crate::scenes::stick::main_run;
use crate::sweep::linspace;
use rayon::prelude::*;
use serde_json::{json, Value};
use std::sync::{Arc, Mutex};

/// Cells per side.
pub const CELLS: usize = 32;
/// The chapter's ranges: theta_0 (rad) and mu.
pub const THETA0_RANGE_RAD: (f64, f64) = (0.05, 0.9);
/// See [`THETA0_RANGE_RAD`].
pub const MU_RANGE: (f64, f64) = (0.1, 0.9);
/// Maps kept.
pub const KEPT: usize = 8;

/// Maps computed so far, by scene key, newest last.
#[derive(Default)]
pub struct MapCache {
    maps: Mutex<Vec<(String, Arc<Value>)>>,
}

/// The key of a request's map: every parameter except theta_0, mu and the duration (the
/// map's runs have their own length), and the integrator's options.
pub fn key(req: &RunRequest) -> String {
    let mut p = req.params;
    p.theta0_rad = 0.0;
    p.mu = 0.0;
    format!("{:?} {:?} {:?}", p, req.opts.method, req.opts.control)
}

impl MapCache {
    /// The map of the request's scene: from the cache, or computed (in parallel, with
    /// no progress bar: the lab's threads never write to the terminal).
    pub fn get(&self, req: &RunRequest) -> Arc<Value> {
        let k = key(req);
        if let Ok(maps) = self.maps.lock() {
            if let Some((_, v)) = maps.iter().find(|(kk, _)| *kk == k) {
                return v.clone();
            }
        }
        let v = Arc::new(compute(req));
        if let Ok(mut maps) = self.maps.lock() {
            if !maps.iter().any(|(kk, _)| *kk == k) {
                maps.push((k, v.clone()));
                if maps.len() > KEPT {
                    maps.remove(0);
                }
            }
        }
        v
    }
}

/// Computes a map: rows of mu (ascending), columns of theta_0 (ascending); `null` where
/// the run did not complete (the stick fell, or the run ended invalid).
pub fn compute(req: &RunRequest) -> Value {
    let started = std::time::Instant::now();
    let ths = linspace(THETA0_RANGE_RAD.0, THETA0_RANGE_RAD.1, CELLS);
    let mus = linspace(MU_RANGE.0, MU_RANGE.1, CELLS);
    let items: Vec<(f64, f64)> = mus
        .iter()
        .flat_map(|&mu| ths.iter().map(move |&th| (th, mu)))
        .collect();
    let speeds: Vec<Option<f64>> = items
        .par_iter()
        .map(|&(th, mu)| {
            let mut p = req.params;
            p.theta0_rad = th;
            p.mu = mu;
            let v = main_run::map_cell_speed(&p, &req.opts);
            v.is_finite().then(|| round(v, 5))
        })
        .collect();
    json!({
        "theta0_rad": ths,
        "mu": mus,
        "speed_mps": speeds.chunks(CELLS).map(|r| r.to_vec()).collect::<Vec<_>>(),
        "compute_ms": round(started.elapsed().as_secs_f64() * 1e3, 3),
    })
}
