//! The runs behind the claims, computed once: the exact periodic drift and the sweep
//! of the averaged law's error against Gamma_x, the sticking instants of exact runs,
//! the mean friction at a fixed drift for faster and faster shaking, the drift at small
//! and large forces (the viscous law), and the booktop runs.

use super::drift::{gamma_for_1pct, relative_error, steady_drift, Scene, Steady};
use crate::ladder::WorkPoint;
use crate::numerics::events::illinois;
use crate::numerics::hybrid::Segment;
use crate::physics::block::{
    simulate_block, simulate_block_observed, BlockMode, BlockOptions, BlockParams, Observer,
};
use crate::physics::friction::effective_viscous_coefficient;
use crate::physics::plate::{Axis, Harmonic, PlateMotion};
use crate::sweep::{logspace, par_map};

/// Everything the claims, results and figures read.
#[derive(Debug, Clone)]
pub struct Evidence {
    /// The chapter's scene.
    pub scene: Scene,
    /// Its exact periodic state.
    pub exact: Steady,
    /// The scene of the error sweep (the chapter's bias, or b = 0.01 at zero bias).
    pub err_scene: Scene,
    /// (Gamma_x, relative error of the averaged law, exact drift m/s), Gamma_x 1 to 1000.
    pub sweep: Vec<(f64, f64, f64)>,
    /// The numerical error bound of each exact drift of `sweep` (m/s).
    pub sweep_err_mps: Vec<f64>,
    /// The Gamma_x of 1 % error and its bisection bracket.
    pub g1: (f64, f64),
    /// The sticking instants of exact runs.
    pub sticking: Sticking,
    /// The mean friction at a fixed drift for faster shaking.
    pub fast: FastShaking,
    /// The drift at small and large forces at Gamma_x = 100.
    pub viscous: Viscous,
    /// The booktop runs.
    pub booktop: Booktop,
    /// The block's velocity swing over one steady period at Gamma_x = 10 and 100.
    pub fluctuation: [Fluctuation; 2],
    /// The bias that keeps a drift of 0.1 V at fixed V, 30 x the frequency, and the
    /// bound on its numerical error.
    pub fixed_v_bias: (f64, f64),
}

/// The block's velocity over one period of its exact periodic state.
#[derive(Debug, Clone, Copy)]
pub struct Fluctuation {
    /// Gamma_x of the run.
    pub gamma_x: f64,
    /// Bias of the run (fraction of mu m g).
    pub bias: f64,
    /// (max - min of the block's absolute velocity) / V.
    pub swing_over_v: f64,
    /// Sticking segments seen in the period.
    pub sticks: usize,
    /// Bound on the numerical error of `swing_over_v`: twice the periodic state's
    /// velocity error over V.
    pub err: f64,
}

/// Largest `|a_xp| / (mu g)` over the sticking instants (no bias) of exact runs at
/// Gamma_x = 0.5, 0.9, 1.5 and the chapter's, and the number of sticking segments.
#[derive(Debug, Clone, Copy)]
pub struct Sticking {
    /// Largest |a_support|/(mu g) while stuck.
    pub worst: f64,
    /// How far past the cone's edge a located stick-to-slip may end (relative): the
    /// plate's jerk over the event tolerance, Gamma_x omega t_tol, plus 8 ulps of
    /// Gamma_x (the rounding of the acceleration).
    pub edge_tol: f64,
    /// Sticking segments seen.
    pub segments: usize,
}

/// The bias that keeps a block drifting at `v_target` as the frequency grows.
#[derive(Debug, Clone)]
pub struct FastShaking {
    /// The bias (mean friction / (mu m g)) at each.
    pub biases: Vec<f64>,
    /// The drift held fixed (m/s): 0.1 V.
    pub v_target_mps: f64,
    /// V at the largest factor (m/s).
    pub v_last_mps: f64,
}

/// The drift at small and large forces at Gamma_x = 100.
#[derive(Debug, Clone, Copy)]
pub struct Viscous {
    /// The small bias (fraction of mu m g).
    pub b_small: f64,
    /// Exact c = F/(m v) at the small bias (1/s).
    pub c_exact: f64,
    /// The averaged law's c = 2 mu g/(pi V) (1/s).
    pub c_law: f64,
    /// Linear-law drift over exact drift, minus 1, at b = 0.9.
    pub departure: f64,
    /// Drift ratio when the small force doubles.
    pub doubling: f64,
}

/// The booktop runs.
#[derive(Debug, Clone, Copy)]
pub struct Booktop {
    /// The tilt at which a coin slides on a still book (deg), by bisection.
    pub critical_tilt_deg: f64,
    /// The small tilt of the shaken book: a quarter of arctan(mu) (deg).
    pub small_tilt_deg: f64,
    /// The still book already slides at the small tilt.
    pub still_slides: bool,
    /// The shaken book's scene at the small tilt.
    pub scene: Scene,
    /// Exact drift of the coin on it (m/s, + down the tilt).
    pub drift_mps: f64,
    /// Bound on the numerical error of `drift_mps` (m/s, `drift::numerical_error_mps`).
    pub drift_err_mps: f64,
}

/// The runs of the chapter's scene; `quick` takes 9 instead of 25 sweep points and 12
/// instead of 40 bisection steps.
pub fn gather(scene: &Scene, quick: bool) -> Evidence {
    let exact = steady_drift(scene);
    let err_scene = Scene {
        bias: if scene.bias > 0.0 { scene.bias } else { 0.01 },
        ..*scene
    };
    let gammas = logspace(1.0, 1000.0, if quick { 9 } else { 25 });
    let runs: Vec<(f64, f64, f64, f64)> = par_map(&gammas, "averaged-law error", |&gx| {
        let s = err_scene.at_gamma_x(gx);
        let ex = steady_drift(&s);
        (
            gx,
            relative_error(&s, ex.drift_mps),
            ex.drift_mps,
            ex.err_mps,
        )
    });
    let sweep: Vec<(f64, f64, f64)> = runs.iter().map(|r| (r.0, r.1, r.2)).collect();
    let sweep_err_mps = runs.iter().map(|r| r.3).collect();
    let g1 = gamma_for_1pct(&err_scene, &sweep, if quick { 12 } else { 40 });
    Evidence {
        scene: *scene,
        exact,
        err_scene,
        sweep,
        sweep_err_mps,
        g1,
        sticking: sticking(scene),
        fast: fast_shaking(scene),
        viscous: viscous(scene),
        booktop: booktop_runs(scene),
        // b = 0.5 whatever the chapter's bias: near b = 1 the block sticks at any
        // Gamma_x and the swing law (no sticking) does not apply
        fluctuation: [10.0, 100.0].map(|g| {
            fluctuation(
                &Scene {
                    bias: 0.5,
                    ..*scene
                }
                .at_gamma_x(g),
            )
        }),
        fixed_v_bias: fixed_v_bias(scene),
    }
}

/// Extremes of the block's absolute velocity over the segments of a run (9 samples per
/// segment, its ends included: the extremes sit at the slip reversals) and its
/// sticking segments.
struct Swing<'a> {
    plate: &'a Harmonic,
    lo: f64,
    hi: f64,
    sticks: usize,
}

impl Observer<BlockMode, 4> for Swing<'_> {
    fn segment(&mut self, mode: BlockMode, seg: &Segment<'_, 4>) {
        if mode == BlockMode::Stick && seg.t1 > seg.t0 {
            self.sticks += 1;
        }
        for k in 0..=8 {
            let t = seg.t0 + (seg.t1 - seg.t0) * k as f64 / 8.0;
            let v = seg.eval(t)[1] + self.plate.vx_mps(t);
            (self.lo, self.hi) = (self.lo.min(v), self.hi.max(v));
        }
    }
}

/// One period of the exact periodic state of `scene`, observed.
fn fluctuation(scene: &Scene) -> Fluctuation {
    let steady = steady_drift(scene);
    let plate = scene.plate();
    let mut w = Swing {
        plate: &plate,
        lo: f64::MAX,
        hi: f64::MIN,
        sticks: 0,
    };
    let o = BlockOptions {
        start: (0.0, [0.0, steady.v0_mps - plate.vx_mps(0.0), 0.0, 0.0]),
        transient_periods: 0,
        record_events: false,
        ..BlockOptions::default()
    };
    simulate_block_observed(&scene.params(), &plate, plate.period_s(), &o, &mut w);
    Fluctuation {
        gamma_x: scene.gamma_x(),
        bias: scene.bias,
        swing_over_v: (w.hi - w.lo) / scene.velocity_amplitude_mps(),
        sticks: w.sticks,
        err: 2.0 * steady.err_mps / scene.velocity_amplitude_mps(), // formula: 2 err(v)/V
    }
}

/// The bias that keeps the exact drift at 0.1 V when the frequency is 30 x the
/// scene's and the amplitude 1/30 of it (V = delta_x omega fixed, Gamma_x 30 x), from
/// the scene at Gamma_x >= 10 (so that Gamma_x >= 300, where the averaged law that
/// judges it is within 1e-4), and the bound on its numerical error.
fn fixed_v_bias(scene: &Scene) -> (f64, f64) {
    let scene = &scene.at_gamma_x(scene.gamma_x().max(10.0));
    let s = Scene {
        frequency_hz: 30.0 * scene.frequency_hz,
        amplitude_m: scene.amplitude_m / 30.0,
        ..*scene
    };
    bias_for_drift(&s, 0.1 * scene.velocity_amplitude_mps())
}

/// Largest `|a_xp| / (mu g)` over the sticking instants of a run (11 samples per
/// segment) and the number of sticking segments.
struct StickWatch<'a> {
    plate: &'a Harmonic,
    mu_g: f64,
    worst: f64,
    sticks: usize,
}

impl Observer<BlockMode, 4> for StickWatch<'_> {
    fn segment(&mut self, mode: BlockMode, seg: &Segment<'_, 4>) {
        if mode == BlockMode::Stick && seg.t1 > seg.t0 {
            self.sticks += 1;
            for k in 0..=10 {
                let t = seg.t0 + (seg.t1 - seg.t0) * k as f64 / 10.0;
                self.worst = self.worst.max(self.plate.ax_mps2(t).abs() / self.mu_g);
            }
        }
    }
}

/// Exact runs without bias at Gamma_x = 0.5, 0.9, 1.5 and the chapter's (20 periods).
fn sticking(scene: &Scene) -> Sticking {
    let mut out = Sticking {
        worst: 0.0,
        segments: 0,
        edge_tol: 0.0,
    };
    for gx in [0.5, 0.9, 1.5, scene.gamma_x()] {
        let s = Scene {
            bias: 0.0,
            ..scene.at_gamma_x(gx)
        };
        let plate = s.plate();
        let mut w = StickWatch {
            plate: &plate,
            mu_g: scene.mu * scene.g_mps2,
            worst: 0.0,
            sticks: 0,
        };
        let opts = BlockOptions {
            transient_periods: 0,
            record_events: false,
            ..BlockOptions::default()
        };
        let t_end = 20.0 * plate.period_s();
        simulate_block_observed(&s.params(), &plate, t_end, &opts, &mut w);
        out.worst = out.worst.max(w.worst);
        let t_tol = 4.0 * f64::EPSILON * t_end.max(1.0); // bounds both event tolerances
        let omega = std::f64::consts::TAU * s.frequency_hz;
        // formula: |a'| t_tol/(mu g) = Gamma_x omega t_tol, plus 8 eps Gamma_x
        out.edge_tol = out
            .edge_tol
            .max(gx * omega * t_tol + 8.0 * f64::EPSILON * gx.max(1.0));
        out.segments += w.sticks;
    }
    out
}

/// The bias (fraction of mu g) that makes the exact drift equal `v_target` (m/s), and
/// the bound on its numerical error: the drift's error bound over the drift's secant
/// slope in the bias over [0, 0.999] (smaller than the slope anywhere below b = 0.99,
/// so the bound is conservative), plus the bisection's bracket.
fn bias_for_drift(scene: &Scene, v_target: f64) -> (f64, f64) {
    let f = |b: f64| steady_drift(&Scene { bias: b, ..*scene }).drift_mps - v_target;
    let (a, b) = (0.0, 0.999);
    let (fa, fb) = (f(a), f(b));
    if fa.signum() == fb.signum() {
        return (f64::NAN, f64::NAN);
    }
    let bias = illinois(f, a, b, fa, fb, 1e-12).0;
    let err = steady_drift(&Scene { bias, ..*scene }).err_mps;
    let slope = (fb - fa) / (b - a); // formula: secant d(drift)/db
    (bias, err / slope.abs() + 1e-12) // formula: err(v)/slope + bracket
}

/// The mean friction on a block drifting at 0.1 V at 1, 3, 10, 30 x the frequency
/// (`FastShaking::biases` in that order).
fn fast_shaking(scene: &Scene) -> FastShaking {
    let v_target = 0.1 * scene.velocity_amplitude_mps();
    let factors = [1.0, 3.0, 10.0, 30.0];
    let biases = factors
        .iter()
        .map(|k| {
            let s = Scene {
                frequency_hz: k * scene.frequency_hz,
                ..*scene
            };
            bias_for_drift(&s, v_target).0
        })
        .collect();
    FastShaking {
        biases,
        v_target_mps: v_target,
        v_last_mps: factors[3] * scene.velocity_amplitude_mps(),
    }
}

/// The drift at F = 0.02, 0.04 and 0.9 mu m g at Gamma_x = 100.
fn viscous(scene: &Scene) -> Viscous {
    let fast = scene.at_gamma_x(100.0);
    let drift = |b: f64| steady_drift(&Scene { bias: b, ..fast }).drift_mps;
    let (mu, g) = (scene.mu, scene.g_mps2);
    let b_small = 0.02;
    let v_small = drift(b_small);
    let c_exact = b_small * mu * g / v_small; // formula: c = F/(m v) (per unit mass)
    let c_law = effective_viscous_coefficient(fast.velocity_amplitude_mps(), mu, g);
    let b_big = 0.9;
    let linear_big = b_big * mu * g / c_law;
    Viscous {
        b_small,
        c_exact,
        c_law,
        departure: linear_big / drift(b_big) - 1.0,
        doubling: drift(2.0 * b_small) / v_small,
    }
}

/// The tilt (deg) at which a coin on an unshaken book starts to slide: bisection on the
/// model's outcome (moves or not after 0.1 s).
pub fn critical_tilt_deg(mu: f64, g: f64) -> f64 {
    let still = Harmonic::sine(Axis::X, 0.0, 5.0);
    let slides = |deg: f64| {
        let a = deg.to_radians();
        let p = BlockParams::coulomb(g * a.cos(), mu, g * a.sin());
        let run = simulate_block(
            &p,
            &still,
            0.1,
            &BlockOptions {
                transient_periods: 0,
                record_events: false,
                ..BlockOptions::default()
            },
        );
        run.y_end[0] > 0.0
    };
    let (mut lo, mut hi) = (0.0, 89.9);
    for _ in 0..60 {
        let m = 0.5 * (lo + hi);
        if slides(m) {
            hi = m;
        } else {
            lo = m;
        }
    }
    hi
}

/// Booktop scene at `tilt_deg`: gravity splits into g cos(tilt) normal to the book and a
/// bias g sin(tilt) along it; the book shakes in its own plane.
pub fn booktop(scene: &Scene, tilt_deg: f64) -> Scene {
    let a = tilt_deg.to_radians();
    let g = scene.g_mps2;
    Scene {
        g_mps2: g * a.cos(),
        bias: a.tan() / scene.mu,
        ..*scene
    } // formula: b = tan(alpha)/mu
}

/// The coin on the still book, and on the shaken book at a quarter of arctan(mu).
fn booktop_runs(scene: &Scene) -> Booktop {
    let critical = critical_tilt_deg(scene.mu, scene.g_mps2);
    let small = 0.25 * scene.mu.atan().to_degrees();
    let book = booktop(scene, small);
    let steady = steady_drift(&book);
    Booktop {
        critical_tilt_deg: critical,
        small_tilt_deg: small,
        still_slides: critical < small,
        scene: book,
        drift_mps: steady.drift_mps,
        drift_err_mps: steady.err_mps,
    }
}

/// Work against accuracy: 20 periods from the exact periodic state, on the ladder of
/// tolerances and steps of [`crate::ladder`].
pub fn work_precision(ev: &Evidence, quick: bool) -> Vec<WorkPoint> {
    let (scene, exact) = (&ev.scene, &ev.exact);
    let plate = scene.plate();
    let period = plate.period_s();
    let model = |o: &BlockOptions| {
        let o = BlockOptions {
            start: (0.0, [0.0, exact.v0_mps - plate.vx_mps(0.0), 0.0, 0.0]),
            transient_periods: 0,
            ..*o
        };
        simulate_block(&scene.params(), &plate, 20.0 * period, &o)
    };
    let vamp = scene.velocity_amplitude_mps();
    let scale = if exact.drift_mps.abs() > 1e-12 * vamp {
        exact.drift_mps.abs()
    } else {
        vamp
    };
    crate::ladder::work_precision(&model, exact.drift_mps, scale, quick)
}
