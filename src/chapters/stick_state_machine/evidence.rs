//! The runs and side computations the claims are judged on.

use super::at_states::{self, AtSample, AtStates};
use super::{run_scene, Scene};
use crate::chapters::Context;
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Integrator, Method, StepControl};
use crate::numerics::rounding::{gamma, OWN};
use crate::physics::stick::run::{Recording, RunSummary};
use crate::physics::stick::{
    CollisionAngle, StickModel, StickParams, NSTATE, OM, TH, VXC, VZC, XC, ZC,
};

/// Everything the claims look at.
pub struct Evidence {
    /// The authors' scene, g = 10 unless --g-mps2 (traced).
    pub authors: RunSummary,
    /// The self-locking scene (traced).
    pub jamming: RunSummary,
    /// The authors' scene with the document's collision reset.
    pub authors_reset: RunSummary,
    /// Phase sequences of the authors' and the jamming scene at rtol 1e-8.
    pub loose_sequences: [String; 2],
    /// Phase sequences of the authors' and the jamming scene with events taken at step
    /// ends (not located), at each rtol of [`SEQUENCE_RTOLS`] (for the mutation of
    /// `phase-sequence-tolerance`).
    pub unlocated_sequences: [[String; 2]; 2],
    /// The model's closed-form flight of the authors' stick from a state in the air and
    /// a Dormand-Prince integration of the same equations (`c3-c5-flight-closed-form`).
    pub flight: FlightReference,
    /// Pivot on a still plate from `theta_f + eps`, `theta_f + 2 eps` and `theta_f + 4 eps`
    /// (eps = 1e-4 rad) by Dormand-Prince 5(4), and from `theta_f + eps` by DOP853 (the
    /// runs' error estimate), rtol 1e-12: samples `(t s, theta - theta_f rad)` every
    /// millisecond for 1 s.
    pub pendulum: [Vec<(f64, f64)>; 4],
    /// Authors' start state: pivot normal force (N) and the lift-off's h_c' (m/s).
    pub start_fz_n: f64,
    /// See `start_fz_n`.
    pub start_liftoff_hdot_mps: f64,
    /// The authors' and the jamming scene's parameters.
    pub params: [StickParams; 2],
    /// Duration of the evidence runs (s).
    pub duration_s: f64,
    /// The contact conditions at states at rest on the plate (both scenes).
    pub rest: Vec<super::rest_scan::RestState>,
    /// Per flight of both runs: h_c at its lift-off state (m), and whether it landed
    /// later.
    pub liftoffs: Vec<(f64, bool)>,
    /// The slides' normal force near the self-locking edge: |F_z| at tan = mu (1 +
    /// 1e-6) over |F_z| at mu (1 + 1e-3).
    pub edge_growth: f64,
    /// The model at the recorded states of the authors' and the jamming run (trace
    /// samples, landings, pivot and slide exits), evaluated once.
    pub at: AtStates,
    /// A vertical stick at rest on the authors' plate at Γ = 0.5: per phase `(F_x N,
    /// F_z N)` from the pivot equations and the closed form `m (g + z_s'')` (N).
    pub vertical_pivot: Vec<(f64, f64, f64)>,
}

/// Relative (= absolute) tolerance of the traced evidence runs.
pub const EVIDENCE_RTOL: f64 = 1e-10;

/// The two tolerances at which the phase sequences are compared (the traced runs' and
/// the loose ones').
pub const SEQUENCE_RTOLS: [f64; 2] = [EVIDENCE_RTOL, 1e-8];

/// The phase sequences of the runs of both scenes (`params`, `duration_s` s) with
/// events at step ends, at each of [`SEQUENCE_RTOLS`].
fn unlocated_sequences(params: &[StickParams; 2], duration_s: f64) -> [[String; 2]; 2] {
    let rec = Recording {
        sequence_cap: 100_000, // the phase sequence only: no trace, no checks, default lists
        ..Recording::default()
    };
    let jobs = [(0usize, 0usize), (0, 1), (1, 0), (1, 1)];
    let seqs = crate::sweep::par_map(&jobs, "stick sequences at step ends", |&(k, i)| {
        let opts = Options {
            control: StepControl::tol(SEQUENCE_RTOLS[k], SEQUENCE_RTOLS[k]),
            locate_events: false,
            ..Options::default()
        };
        run_scene(&params[i], duration_s, &opts, rec).sequence
    });
    let mut it = seqs.into_iter();
    let mut next = || it.next().expect("four runs");
    [[next(), next()], [next(), next()]]
}

/// Runs the evidence (a few tenths of a second in release).
pub fn collect(ctx: &Context, opts: &Options) -> Evidence {
    let pa = Scene::Authors.params(ctx.g_mps2);
    let pj = Scene::Jamming.params(ctx.g_mps2);
    let dur = if ctx.quick { 1.0 } else { 5.0 };
    let rec = |p: &StickParams| Recording {
        sequence_cap: 100_000,
        trace_dt_s: p.period_s() / 16.0,
        check_invariants: true,
        grid_only: false,
        list_cap: None,
    };
    let tight = Options {
        control: StepControl::tol(EVIDENCE_RTOL, EVIDENCE_RTOL),
        ..*opts
    };
    let loose = Options {
        control: StepControl::tol(1e-8, 1e-8),
        ..*opts
    };
    let runs: Vec<RunSummary> =
        crate::sweep::par_map(&[0usize, 1, 2, 3, 4], "stick evidence", |&i| match i {
            0 => run_scene(&pa, dur, &tight, rec(&pa)),
            1 => run_scene(&pj, dur, &tight, rec(&pj)),
            2 => {
                let mut p = pa;
                p.collision_angle = CollisionAngle::Reset;
                run_scene(&p, dur, &tight, rec(&p))
            }
            3 => run_scene(&pa, dur, &loose, rec(&pa)),
            _ => run_scene(&pj, dur, &loose, rec(&pj)),
        });
    let mut it = runs.into_iter();
    let (authors, jamming, authors_reset, a_loose, j_loose) = (
        it.next().unwrap(),
        it.next().unwrap(),
        it.next().unwrap(),
        it.next().unwrap(),
        it.next().unwrap(),
    );
    let loose_sequences = [a_loose.sequence, j_loose.sequence];

    let pendulum = [
        pendulum_trace(&pa, PENDULUM_EPS, Method::Dopri5),
        pendulum_trace(&pa, 2.0 * PENDULUM_EPS, Method::Dopri5),
        pendulum_trace(&pa, 4.0 * PENDULUM_EPS, Method::Dopri5),
        pendulum_trace(&pa, PENDULUM_EPS, Method::Dop853),
    ];
    let model = StickModel::new(pa);
    let th = pa.static_angle().unwrap_or(pa.theta0_rad);
    let y0 = crate::physics::stick::run::initial_state(&model, 0.0, th);
    let start_fz_n = model.pivot_eval(0.0, &y0).fz;
    let start_liftoff_hdot_mps = {
        // C's relative velocity if the stick lifted off at t = 0 (flight rate of the rod)
        let w = -model.rate * (th - pa.theta0_rad);
        let [_, _, _, vzp] = model.tip(&y0);
        vzp + pa.length_m * w * th.sin() - model.plate(0.0).1
    };
    let liftoffs = super::rest_scan::liftoff_heights(&[(&authors, &pa), (&jamming, &pj)]);
    let at = at_states::gather(&[(&authors, &pa), (&jamming, &pj)]);
    Evidence {
        authors,
        jamming,
        authors_reset,
        loose_sequences,
        unlocated_sequences: unlocated_sequences(&[pa, pj], dur),
        flight: flight_reference(&pa),
        pendulum,
        start_fz_n,
        start_liftoff_hdot_mps,
        params: [pa, pj],
        duration_s: dur,
        rest: super::rest_scan::rest_states(&[pa, pj]),
        liftoffs,
        edge_growth: super::rest_scan::edge_growth(&[pa, pj]),
        at,
        vertical_pivot: at_states::vertical_pivot(&pa),
    }
}

/// Amplitude of the small-motion pivot runs (rad).
pub const PENDULUM_EPS: f64 = 1e-4;

/// Pivot on a still plate from `theta_f + eps` at rest (`method`, rtol 1e-12, mu huge so
/// that it stays in pivot): `(t, theta - theta_f)` every millisecond over 1 s. (The
/// model caps the step, so at this tolerance the error control never binds: a tighter
/// rtol gives the same trace; the error estimate is the higher-order method.)
pub fn pendulum_trace(base: &StickParams, eps: f64, method: Method) -> Vec<(f64, f64)> {
    let mut p = *base;
    p.plate.amplitude_m = 0.0;
    p.mu = 1e3; // stay in pivot
    let thf = p.static_angle().expect("static angle");
    let model = StickModel::new(p);
    let y0 = crate::physics::stick::run::initial_state(&model, 0.0, thf + eps);
    let rec = Recording {
        sequence_cap: 0,
        trace_dt_s: 1e-3,
        check_invariants: false,
        grid_only: false,
        list_cap: None,
    };
    let s = crate::physics::stick::run::simulate_stick(
        &model,
        0.0,
        y0,
        1.0,
        &Options {
            method,
            control: StepControl::tol(1e-12, 1e-12),
            ..Options::default()
        },
        rec,
    );
    s.trace.iter().map(|x| (x.t_s, x.y[TH] - thf)).collect()
}

/// Largest difference (rad) between two traces of the same times: twice it bounds the
/// integration error of the Dormand-Prince 5(4) trace when the DOP853 trace's error is
/// at most half of it (eighth order against fifth on the same capped steps).
pub fn trace_difference(a: &[(f64, f64)], b: &[(f64, f64)]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x.1 - y.1).abs())
        .fold(0.0, f64::max)
}

/// Largest difference (rad) between a pivot trace and the damped linearised pendulum of
/// C.6 with the document's spring coefficient `spring` (1 as printed):
/// `theta'' = -W0^2 (theta - theta_f) - 2 e theta'`, `W0^2 = (spring k - m g L
/// cos(theta_f)) / (m L^2)`, `e = gamma / (2 m L^2)`.
pub fn pendulum_error(base: &StickParams, trace: &[(f64, f64)], eps: f64, spring: f64) -> f64 {
    let thf = base.static_angle().expect("static angle");
    let (m, l, k, c, g) = (
        base.mass_kg,
        base.length_m,
        base.stiffness_nm_per_rad,
        base.damping_nms_per_rad,
        base.g_mps2,
    );
    let w0sq = (spring * k - m * g * l * thf.cos()) / (m * l * l); // formula: linearised C.6
    let e = c / (2.0 * m * l * l);
    let wd = (w0sq - e * e).max(0.0).sqrt();
    trace
        .iter()
        .map(|&(t, d)| {
            let lin = eps * (-e * t).exp() * ((wd * t).cos() + e / wd * (wd * t).sin()); // formula: damped oscillator
            (d - lin).abs()
        })
        .fold(0.0, f64::max)
}

/// A flight by the model's closed form from a state in the air: every 0.5 ms over
/// 20 ms C's position and the angle `(t s, [x_c m, z_c m, θ rad])`; beside it the same
/// samples from a Dormand-Prince integration of the same equations.
pub struct FlightReference {
    /// The rod's length (m).
    pub length_m: f64,
    /// The closed form's samples.
    pub at: Vec<(f64, [f64; 3])>,
    /// `[x_c m, z_c m, θ rad]` at the times of `at` from [`flight_integrated`] at
    /// rtol [`FLIGHT_RTOL`], with the run's accepted steps; `None` if the integration failed.
    pub integrated: Option<(Vec<[f64; 3]>, u64)>,
    /// The same at rtol [`FLIGHT_RTOL`]/10: the reference run's error estimate.
    pub finer: Option<(Vec<[f64; 3]>, u64)>,
}

/// Tolerance of the Dormand-Prince run the closed-form flight is compared with.
pub const FLIGHT_RTOL: f64 = 1e-12;

/// The model's closed-form flight of `p` from a state in the air (θ₀ + 0.05 rad, C 2 cm
/// up, moving): the angle relaxes within a few γ/k = 1 ms, so samples every 0.5 ms.
pub fn flight_reference(p: &StickParams) -> FlightReference {
    let model = StickModel::new(*p);
    let mut y0 = [0.0; NSTATE];
    y0[TH] = p.theta0_rad + 0.05;
    y0[ZC] = 0.02;
    y0[VXC] = 0.3;
    y0[VZC] = 0.8;
    y0[OM] = -model.rate * 0.05;
    let [xp, zp, vxp, vzp] = model.tip(&y0);
    let at: Vec<(f64, [f64; 3])> = (1..=40)
        .map(|k| {
            let t1 = 0.0005 * k as f64;
            let yc = model.flight_state(0.0, &y0, t1);
            (t1, [yc[XC], yc[ZC], yc[TH]])
        })
        .collect();
    let start = [xp, zp, vxp, vzp, y0[TH]];
    let times: Vec<f64> = at.iter().map(|s| s.0).collect();
    FlightReference {
        length_m: p.length_m,
        integrated: flight_integrated(p, start, model.rate, &times, FLIGHT_RTOL),
        finer: flight_integrated(p, start, model.rate, &times, FLIGHT_RTOL / 10.0),
        at,
    }
}

/// Dormand-Prince at `rtol` (= atol) on `(x_p, z_p, xdot_p, zdot_p, theta)` from `start`
/// with C.3 and C.5, `theta' = -rate (theta - theta_0)`, `zddot_p = -g`: C's position and
/// the angle `[x_c m, z_c m, θ rad]` at `times` (s), and the accepted steps; `None` if a
/// step fails.
fn flight_integrated(
    p: &StickParams,
    start: [f64; 5],
    rate: f64,
    times: &[f64],
    rtol: f64,
) -> Option<(Vec<[f64; 3]>, u64)> {
    let (g, th0, l) = (p.g_mps2, p.theta0_rad, p.length_m);
    let sys = move |_t: f64, u: &[f64; 5]| [u[2], u[3], 0.0, -g, -rate * (u[4] - th0)];
    let mut integ = Integrator::<5>::new(Method::Dopri5, StepControl::tol(rtol, rtol));
    let (mut t, mut u) = (0.0, start);
    let mut out = Vec::with_capacity(times.len());
    for &t1 in times {
        u = integ.integrate(&sys, t, u, t1, |_| {}).ok()?;
        t = t1;
        out.push([u[0] - l * u[4].sin(), u[1] - l * u[4].cos(), u[4]]); // formula: C.1
    }
    Some((out, integ.stats.accepted))
}

/// The largest difference between the closed-form flight and its Dormand-Prince
/// integration, in C's position (m) or the angle (rad); infinite if the integration
/// failed.
pub fn flight_error(f: &FlightReference) -> f64 {
    let Some((dp, _)) = &f.integrated else {
        return f64::INFINITY;
    };
    largest_difference(f.at.iter().map(|s| &s.1), dp)
}

/// The largest component-wise difference of two lists of `[x_c, z_c, θ]`.
fn largest_difference<'a>(a: impl Iterator<Item = &'a [f64; 3]>, b: &[[f64; 3]]) -> f64 {
    a.zip(b)
        .flat_map(|(r, u)| (0..3).map(move |i| (u[i] - r[i]).abs()))
        .fold(0.0, f64::max)
}

/// The error budget of [`flight_error`] from the run itself (m or rad); infinite if an
/// integration failed. Two parts:
/// - the Dormand-Prince run's own error, estimated by the run at a tenth of its
///   tolerance: e(τ) <= |y(τ) - y(τ/10)| + e(τ/10), and with e(τ/10) <= e(τ)/2 (the
///   global error shrinks with the tolerance: about 10^(5/6) = 6.8 times for a fifth-order
///   pair, the assumption this rests on) e(τ) <= 2 |y(τ) - y(τ/10)|, the largest over the
///   samples (the error is a smooth function of t: a sample where the two runs cross
///   must not set it);
/// - rounding, which the difference of the two runs need not show: each accepted step
///   rounds y once where it adds the increment and the increment once relative to it
///   (γ_2 |y| per step, N steps), the closed form and C.1 a few (8) times more, on values
///   no larger than `size` = |x_p| + |z_p| + L + |θ| at the sample: (N γ_2 + γ_8) size.
pub fn flight_budget(f: &FlightReference) -> f64 {
    let (Some((dp, n)), Some((fine, _))) = (&f.integrated, &f.finer) else {
        return f64::INFINITY;
    };
    let estimate = 2.0 * largest_difference(dp.iter(), fine); // formula: e(τ) <= 2 |y(τ) - y(τ/10)|
    let size = f
        .at
        .iter()
        .map(|(_, r)| r[0].abs() + r[1].abs() + 2.0 * f.length_m + r[2].abs()) // |x_p| <= |x_c| + L
        .fold(0.0, f64::max);
    let rounding = (*n as f64 * gamma(2) + gamma(8)) * size; // formula: (N γ_2 + γ_8)(|x_p| + |z_p| + L + |θ|)
    OWN * (estimate + rounding)
}

/// Markdown table of the evidence scenes.
pub fn scenes_table(ev: &Evidence) -> String {
    let mut s = String::from(
        "| scene | outcome | mean speed (m/s) | flight | pivot | slide left | slide right | hops | jams | energy residual / largest term |\n|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for (name, r) in [
        ("authors", &ev.authors),
        ("authors, collision reset", &ev.authors_reset),
        ("jamming", &ev.jamming),
    ] {
        let f = r.phase_fractions();
        s.push_str(&format!(
            "| {name} | {} | {:.4} | {:.3} | {:.3} | {:.3} | {:.3} | {} | {} | {:.0e} |\n",
            r.outcome.label(),
            r.mean_velocity_mps,
            f[0],
            f[1],
            f[2],
            f[3],
            r.hops,
            r.jams,
            // an order of magnitude only: the residual is integration error
            10f64.powf(r.budget.relative_residual().max(1e-16).log10().ceil())
        ));
    }
    s.push_str(&format!(
        "\nEvidence runs last {} s from the static angle.\n",
        ev.duration_s
    ));
    s
}

/// What the checks look at: the evidence runs and this run (with its parameters).
pub struct Ctx<'a> {
    /// The evidence runs.
    pub ev: &'a Evidence,
    /// This run (physical rules).
    pub main: &'a RunSummary,
    /// This run's parameters.
    pub p: &'a StickParams,
    /// This run's relative (= absolute) tolerance (the evidence runs use 1e-10).
    pub rtol: f64,
}

impl Ctx<'_> {
    /// The traced evidence runs with their parameters.
    pub fn runs(&self) -> [(&RunSummary, &StickParams); 2] {
        [
            (&self.ev.authors, &self.ev.params[0]),
            (&self.ev.jamming, &self.ev.params[1]),
        ]
    }

    /// The model at every trace sample of the evidence runs, with its scene's parameters.
    pub fn samples(&self) -> impl Iterator<Item = (&AtSample, &StickParams)> {
        self.ev
            .at
            .samples
            .iter()
            .map(|x| (x, &self.ev.params[x.scene]))
    }
}

/// Contact forces `(mu, F_x, F_z)` strictly inside the friction cone, drawn by a closed
/// form rather than selected from the simulation: F_z = 1 N, F_x = s mu F_z for
/// s = -0.95, -0.9, ..., 0.95, at mu = 0.1, 0.4, 1 and 2. A test of a pivot's exit must
/// fire at none of them (the contact holds there); that a test fires at all of them is
/// algebra, not simulation.
pub fn cone_interior() -> Vec<(f64, f64, f64)> {
    let mut v = Vec::new();
    for mu in [0.1, 0.4, 1.0, 2.0] {
        for k in -19..=19 {
            let s = 0.05 * k as f64;
            v.push((mu, s * mu, 1.0));
        }
    }
    v
}

/// Contact forces `(mu, F_x, F_z)` strictly outside the friction cone, by the same
/// closed form: F_z = 1 N, F_x = s mu F_z for |s| = 1.05, 1.1, ..., 1.5, at mu = 0.1,
/// 0.4, 1 and 2. A correct exit test fires at those beyond its edge; a test whose
/// coefficient of mu is off by 10 % misplaces the edge and misjudges |s| = 1.05.
pub fn cone_exterior() -> Vec<(f64, f64, f64)> {
    let mut v = Vec::new();
    for mu in [0.1, 0.4, 1.0, 2.0] {
        for k in 21..=30 {
            for sign in [-1.0, 1.0] {
                let s = sign * 0.05 * k as f64;
                v.push((mu, s * mu, 1.0));
            }
        }
    }
    v
}

/// Whether the hinge test `keeps` holds at every force of the cone's interior and at
/// none outside it (closed-form samples).
pub fn keeps_cone(keeps: impl Fn(&(f64, f64, f64)) -> bool) -> bool {
    cone_interior().iter().all(&keeps) && !cone_exterior().iter().any(&keeps)
}
