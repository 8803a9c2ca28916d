//! Chladni patterns from a small bias (the remark that closes section 3.1.2): "on a
//! modally vibrating plate that has a large enough vibration amplitude, only a small bias
//! would be needed to guide particles to the mode's nodes".
//!
//! Model (derivation in `chapters/04-vertical-shaking.md`, section "Chladni patterns"):
//! - A square plate of side `L` vibrates in the mode
//!   `w(x, y) = [cos(pi x/L) cos(3 pi y/L) + cos(3 pi x/L) cos(pi y/L)] / 2`, so the
//!   local peak acceleration over g is `Gamma(x, y) = Gamma_0 |w(x, y)|`.
//! - Each grain is the chapter's block (Coulomb friction mu, e = 0) on a locally vertical
//!   plate of that Gamma, pushed by a bias `F = b mu m g` down the amplitude's slope,
//!   along `-grad |w|`. The bias stands for the averaged push of the tilting surface,
//!   which the workbook does not model; the demonstration checks what the chapter's
//!   physics makes of a small bias.
//! - A grain's drift speed `V(Gamma)` is the block model's mean velocity, tabulated over
//!   Gamma and interpolated linearly; the grain moves as
//!   `dx/dt = V(Gamma(x)) (-grad|w| / |grad|w||)`, integrated by RK4 from `numerics`.
//! - Rest: in contact the normal force is `m g (1 - Gamma sin(omega t)) >= m g (1 - Gamma)`,
//!   so friction holds the bias at every instant iff `b <= 1 - Gamma`: grains stop where
//!   `Gamma(x, y) <= 1 - b`, a band around each nodal line that narrows as `Gamma_0` grows.

use super::scene::{run as run_scene, Model, Scene};
use crate::numerics::hybrid::Outcome;
use crate::numerics::ode::{Integrator, Method, StepControl};
use std::f64::consts::PI;

/// Side of the square plate (m).
pub const PLATE_SIDE_M: f64 = 0.2;
/// Peak acceleration over g at the antinodes, `Gamma_0`.
pub const GAMMA0: f64 = 6.0;
/// Bias as a fraction of `mu m g`: small.
pub const BIAS: f64 = 0.05;

/// The mode shape `w` (1 at the largest antinode) and its gradient (1/m) at `(x, y)` (m).
pub fn mode(x_m: f64, y_m: f64) -> (f64, [f64; 2]) {
    let k = PI / PLATE_SIDE_M;
    let (s1x, c1x) = (k * x_m).sin_cos();
    let (s3x, c3x) = (3.0 * k * x_m).sin_cos();
    let (s1y, c1y) = (k * y_m).sin_cos();
    let (s3y, c3y) = (3.0 * k * y_m).sin_cos();
    let w = 0.5 * (c1x * c3y + c3x * c1y); // formula: w = [cos(k x) cos(3 k y) + cos(3 k x) cos(k y)] / 2
    let dx = -0.5 * k * (s1x * c3y + 3.0 * s3x * c1y); // formula: dw/dx
    let dy = -0.5 * k * (3.0 * c1x * s3y + c3x * s1y); // formula: dw/dy
    (w, [dx, dy])
}

/// Local peak acceleration over g at `(x, y)` (m).
pub fn gamma_at(x_m: f64, y_m: f64) -> f64 {
    GAMMA0 * mode(x_m, y_m).0.abs() // formula: Gamma(x, y) = Gamma_0 |w|
}

/// The drift speed table `V(Gamma)` (m/s) of the block with bias `scene.bias`.
#[derive(Debug, Clone)]
pub struct DriftTable {
    /// Gamma values, increasing from 0.
    pub gammas: Vec<f64>,
    /// Mean velocity at each (m/s), from the block model.
    pub speeds_mps: Vec<f64>,
    /// The Gamma values whose block run did not reach its end (a Zeno stop, a failed
    /// step), with the run's outcome: their speed is NaN and the demonstration cannot
    /// vouch for the grains that cross them.
    pub stopped: Vec<(f64, String)>,
}

impl DriftTable {
    /// Runs the block model at `n` values of Gamma from 0 to `GAMMA0` and at the
    /// `extra` values (in parallel).
    pub fn build(
        scene: &Scene,
        n: usize,
        extra: &[f64],
        transient: usize,
        observe: usize,
    ) -> DriftTable {
        let mut gammas = crate::sweep::linspace(0.0, GAMMA0, n);
        gammas.extend_from_slice(extra);
        gammas.sort_by(f64::total_cmp);
        gammas.dedup();
        let runs = crate::sweep::par_map(&gammas, "Chladni drift table", |&g| {
            let st = run_scene(&scene.at_gamma(g), Model::Exact, transient, observe);
            let stop = (st.run.outcome != Outcome::Completed).then(|| format!("{:?}", st.run.outcome));
            (st.cycle_velocity_mps, stop)
        });
        let stopped = gammas
            .iter()
            .zip(&runs)
            .filter_map(|(&g, (_, stop))| stop.clone().map(|s| (g, s)))
            .collect();
        let speeds_mps = runs.into_iter().map(|(v, _)| v).collect();
        DriftTable {
            gammas,
            speeds_mps,
            stopped,
        }
    }

    /// `V(Gamma)` by linear interpolation (m/s); 0 below the table, last value above.
    pub fn speed(&self, gamma: f64) -> f64 {
        let g = &self.gammas;
        match g.partition_point(|&x| x <= gamma) {
            0 => 0.0,
            i if i == g.len() => *self.speeds_mps.last().unwrap_or(&0.0),
            i => {
                let f = (gamma - g[i - 1]) / (g[i] - g[i - 1]);
                self.speeds_mps[i - 1] + f * (self.speeds_mps[i] - self.speeds_mps[i - 1])
            }
        }
    }

    /// The largest speed of the table (m/s).
    pub fn max_speed(&self) -> f64 {
        self.speeds_mps.iter().copied().fold(0.0, f64::max)
    }
}

/// The block's mean velocity at `gamma` with the scene's bias (m/s).
pub fn drift_speed(scene: &Scene, gamma: f64, transient: usize, observe: usize) -> f64 {
    run_scene(&scene.at_gamma(gamma), Model::Exact, transient, observe).cycle_velocity_mps
}

/// The smallest Gamma at which the biased block drifts, located by bisection on
/// `drift_speed > 0` between `lo` (no drift) and `hi` (drift), `iters` halvings.
pub fn drift_threshold(
    scene: &Scene,
    (mut lo, mut hi): (f64, f64),
    iters: usize,
    transient: usize,
    observe: usize,
) -> f64 {
    for _ in 0..iters {
        let mid = 0.5 * (lo + hi);
        if drift_speed(scene, mid, transient, observe) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// `n` grain positions (m), spread over the plate by a fixed low-discrepancy sequence
/// (the R2 sequence: deterministic, no random generator needed).
pub fn initial_grains(n: usize) -> Vec<[f64; 2]> {
    const A1: f64 = 0.754_877_666_246_692_7; // formula: 1/phi_2, phi_2 the plastic number
    const A2: f64 = 0.569_840_290_998_053_3; // formula: 1/phi_2^2
    (0..n)
        .map(|i| {
            let k = i as f64 + 0.5;
            [
                (k * A1).fract() * PLATE_SIDE_M,
                (k * A2).fract() * PLATE_SIDE_M,
            ]
        })
        .collect()
}

/// Where a grain starting at `p0` (m) is after `t_end_s`: RK4 with step `h_s` on
/// `dx/dt = V(Gamma(x)) (-grad|w| / |grad|w||)`, the grain kept on the plate.
pub fn settle(table: &DriftTable, p0: [f64; 2], t_end_s: f64, h_s: f64) -> [f64; 2] {
    let field = |_t: f64, p: &[f64; 2]| -> [f64; 2] {
        let (w, g) = mode(p[0], p[1]);
        let v = table.speed(GAMMA0 * w.abs());
        let (gx, gy) = (w.signum() * g[0], w.signum() * g[1]); // formula: grad |w| = sign(w) grad w
        let norm = gx.hypot(gy);
        if v == 0.0 || norm == 0.0 {
            return [0.0, 0.0];
        }
        [-v * gx / norm, -v * gy / norm] // formula: dx/dt = -V grad|w| / |grad|w||
    };
    let mut integ = Integrator::new(Method::Rk4, StepControl::Fixed { h_s });
    let clamp = |p: [f64; 2]| p.map(|c| c.clamp(0.0, PLATE_SIDE_M));
    match integ.integrate(&field, 0.0, p0, t_end_s, |_| {}) {
        Ok(p) => clamp(p),
        Err(_) => p0, // a fixed-step RK4 on this bounded field cannot fail; keep the grain
    }
}

/// The demonstration's outcome.
#[derive(Debug, Clone)]
pub struct Chladni {
    /// The drift table.
    pub table: DriftTable,
    /// Located drift threshold (Gamma) and the closed form `1 - b`.
    pub threshold: (f64, f64),
    /// Half-width of the bisection's last bracket (Gamma).
    pub threshold_accuracy: f64,
    /// Grains at the start and at the end (m).
    pub grains: (Vec<[f64; 2]>, Vec<[f64; 2]>),
    /// Fraction of the plate's area where grains rest, `Gamma <= 1 - b`.
    pub band_area_fraction: f64,
    /// Fraction of grains in the band at the start and at the end.
    pub in_band: (f64, f64),
    /// Simulated time (s).
    pub t_end_s: f64,
}

/// Runs the demonstration on `scene` (its mu, frequency and g; bias and Gamma are the
/// demonstration's own).
pub fn demonstrate(scene: &Scene, quick: bool, transient: usize, observe: usize) -> Chladni {
    let scene = Scene {
        bias: BIAS,
        ..*scene
    };
    let closed = 1.0 - BIAS; // formula: rest iff b <= 1 - Gamma
    let iters = if quick { 8 } else { 14 };
    let threshold = drift_threshold(&scene, (0.5, 1.0), iters, transient, observe);
    // The located threshold joins the grid, so that the table's zero ends where the
    // block model's does, not at the grid point below it.
    let n_table = if quick { 31 } else { 121 };
    let table = DriftTable::build(&scene, n_table, &[threshold], transient, observe);
    // Time: twice what the slowest useful drift (a tenth of the table's largest) needs
    // to cross half the plate.
    let t_end_s = 2.0 * 0.5 * PLATE_SIDE_M / (0.1 * table.max_speed().max(1e-9));
    let n = if quick { 400 } else { 2500 };
    let start = initial_grains(n);
    let h_s = t_end_s / if quick { 400.0 } else { 2000.0 };
    let end = crate::sweep::par_map(&start, "Chladni grains", |&p| {
        settle(&table, p, t_end_s, h_s)
    });
    // Grains approach the band's edge asymptotically (their speed falls linearly to 0
    // there), so they are counted in the band within 0.01 of Gamma of its edge: about
    // 30 micrometres on the plate (|grad Gamma| ~ Gamma_0 3 pi / L ~ 300 /m).
    let band = |p: &[f64; 2]| gamma_at(p[0], p[1]) <= closed + 0.01;
    let frac = |ps: &[[f64; 2]]| ps.iter().filter(|p| band(p)).count() as f64 / ps.len() as f64;
    // Area fraction of the band on a 400 x 400 grid of cell centres.
    let m = 400;
    let cells = (0..m * m)
        .filter(|k| {
            let x = ((k % m) as f64 + 0.5) / m as f64 * PLATE_SIDE_M;
            let y = ((k / m) as f64 + 0.5) / m as f64 * PLATE_SIDE_M;
            gamma_at(x, y) <= closed
        })
        .count();
    Chladni {
        band_area_fraction: cells as f64 / (m * m) as f64,
        in_band: (frac(&start), frac(&end)),
        table,
        threshold: (threshold, closed),
        threshold_accuracy: 0.25 / f64::from(1u32 << iters), // formula: (1 - 0.5) / 2^iters / 2
        grains: (start, end),
        t_end_s,
    }
}

/// The demonstration's `chladni` result (JSON).
pub fn summary(c: &Chladni) -> serde_json::Value {
    let (located, closed) = c.threshold;
    let (start, end) = c.in_band;
    serde_json::json!({
        "gamma0": GAMMA0,
        "bias": BIAS,
        "drift_threshold_gamma": located,
        "drift_threshold_closed_form": closed,
        "band_area_fraction": c.band_area_fraction,
        "grains_in_band_start": start,
        "grains_in_band_end": end,
        "simulated_time_s": c.t_end_s,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mode_gradient_matches_finite_differences() {
        // Central differences with h = 1e-6 m: truncation ~ k^3 h^2 ~ 1e-8, round-off
        // ~ 1e-16 / 1e-6 = 1e-10 (1/m); 1e-6 relative to |grad| ~ 50 /m is far above both.
        for &(x, y) in &[(0.013, 0.071), (0.1, 0.05), (0.18, 0.12), (0.033, 0.19)] {
            let (_, g) = mode(x, y);
            let h = 1e-6;
            let fx = (mode(x + h, y).0 - mode(x - h, y).0) / (2.0 * h);
            let fy = (mode(x, y + h).0 - mode(x, y - h).0) / (2.0 * h);
            assert!(
                (fx - g[0]).abs() < 1e-6 * g[0].abs().max(1.0),
                "{fx} {}",
                g[0]
            );
            assert!(
                (fy - g[1]).abs() < 1e-6 * g[1].abs().max(1.0),
                "{fy} {}",
                g[1]
            );
        }
    }

    #[test]
    fn interpolation_is_exact_at_nodes_and_linear_between() {
        let t = DriftTable {
            gammas: vec![0.0, 1.0, 2.0],
            speeds_mps: vec![0.0, 0.0, 2e-3],
            stopped: Vec::new(),
        };
        assert_eq!(t.speed(0.5), 0.0);
        assert_eq!(t.speed(2.0), 2e-3);
        assert!((t.speed(1.5) - 1e-3).abs() < 1e-18);
        assert_eq!(t.speed(-1.0), 0.0);
        assert_eq!(t.speed(9.0), 2e-3);
    }
}
