//! The runs and side computations the claims are judged on.

use super::{run_scene, scene_params, Scene};
use crate::chapters::Context;
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Integrator, Method, StepControl};
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
    /// Phase sequences at rtol 1e-10 and 1e-8 agree: (authors, jamming).
    pub same_sequence: [bool; 2],
    /// Lengths of the compared sequences.
    pub sequence_len: [usize; 2],
    /// Largest |theta - linearised pendulum| for amplitudes eps and 2 eps (rad).
    pub pendulum_err: [f64; 2],
    /// Largest difference between the closed-form flight and DP5 at rtol 1e-12 (m or rad).
    pub flight_err: f64,
    /// Authors' start state: pivot normal force (N) and the lift-off's h_c' (m/s).
    pub start_fz_n: f64,
    /// See `start_fz_n`.
    pub start_liftoff_hdot_mps: f64,
    /// The authors' and the jamming scene's parameters.
    pub params: [StickParams; 2],
    /// Duration of the evidence runs (s).
    pub duration_s: f64,
}

/// Runs the evidence (a few tenths of a second in release).
pub fn collect(ctx: &Context, opts: &Options) -> Evidence {
    let pa = scene_params(Scene::Authors, ctx.g_mps2);
    let pj = scene_params(Scene::Jamming, ctx.g_mps2);
    let dur = if ctx.quick { 1.0 } else { 5.0 };
    let rec = |p: &StickParams| Recording {
        sequence_cap: 100_000,
        trace_dt_s: p.period_s() / 16.0,
        check_invariants: true,
    };
    let tight = Options {
        control: StepControl::tol(1e-10, 1e-10),
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
    let same_sequence = [
        authors.sequence == a_loose.sequence,
        jamming.sequence == j_loose.sequence,
    ];
    let sequence_len = [authors.sequence.len(), jamming.sequence.len()];

    let eps = 1e-4;
    let pendulum_err = [pendulum_error(&pa, eps), pendulum_error(&pa, 2.0 * eps)];
    let flight_err = flight_error(&pa);
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
    Evidence {
        authors,
        jamming,
        authors_reset,
        same_sequence,
        sequence_len,
        pendulum_err,
        flight_err,
        start_fz_n,
        start_liftoff_hdot_mps,
        params: [pa, pj],
        duration_s: dur,
    }
}

/// Pivot on a still plate from `theta_f + eps` at rest, against the damped linearised
/// pendulum `theta'' = -W0^2 (theta - theta_f) - 2 e theta'`, `W0^2 = (k - m g L
/// cos(theta_f)) / (m L^2)`, `e = gamma / (2 m L^2)`: largest difference over 1 s (rad).
pub fn pendulum_error(base: &StickParams, eps: f64) -> f64 {
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
    };
    let s = crate::physics::stick::run::simulate_stick(
        &model,
        0.0,
        y0,
        1.0,
        &Options {
            control: StepControl::tol(1e-12, 1e-12),
            ..Options::default()
        },
        rec,
    );
    let (m, l, k, c, g) = (
        p.mass_kg,
        p.length_m,
        p.stiffness_nm_per_rad,
        p.damping_nms_per_rad,
        p.g_mps2,
    );
    let w0sq = (k - m * g * l * thf.cos()) / (m * l * l); // formula: linearised C.6
    let e = c / (2.0 * m * l * l);
    let wd = (w0sq - e * e).sqrt();
    s.trace
        .iter()
        .map(|smp| {
            let t = smp.t_s;
            let lin = eps * (-e * t).exp() * ((wd * t).cos() + e / wd * (wd * t).sin()); // formula: damped oscillator
            (smp.y[TH] - thf - lin).abs()
        })
        .fold(0.0, f64::max)
}

/// The closed-form flight against Dormand-Prince at rtol 1e-12 on `(x_p, z_p, xdot_p,
/// zdot_p, theta)` with `theta' = -(k/gamma)(theta - theta_0)`: largest difference in
/// C's position (m) after 20 ms from a state in the air.
pub fn flight_error(p: &StickParams) -> f64 {
    let model = StickModel::new(*p);
    let mut y0 = [0.0; NSTATE];
    y0[TH] = p.theta0_rad + 0.05;
    y0[ZC] = 0.02;
    y0[VXC] = 0.3;
    y0[VZC] = 0.8;
    y0[OM] = -model.rate * 0.05;
    let t1 = 0.02;
    let yc = model.flight_state(0.0, &y0, t1);
    let [xp, zp, vxp, vzp] = model.tip(&y0);
    let (g, rate, th0, l) = (p.g_mps2, model.rate, p.theta0_rad, p.length_m);
    let sys = move |_t: f64, u: &[f64; 5]| [u[2], u[3], 0.0, -g, -rate * (u[4] - th0)];
    let mut integ = Integrator::<5>::new(Method::Dopri5, StepControl::tol(1e-12, 1e-12));
    let u = integ
        .integrate(&sys, 0.0, [xp, zp, vxp, vzp, y0[TH]], t1, |_| {})
        .expect("flight integrates");
    let xc = u[0] - l * u[4].sin();
    let zc = u[1] - l * u[4].cos();
    (xc - yc[XC])
        .abs()
        .max((zc - yc[ZC]).abs())
        .max((u[4] - yc[TH]).abs())
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
