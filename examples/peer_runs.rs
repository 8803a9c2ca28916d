//! Runs of the workbook's library for the peer runners in `benches/peers/` (not part of
//! `cargo test`); each prints one JSON object.
//!
//! - `peer_runs stick <jamming|authors> <duration_s> <repeats>`: chapter 6's massless stick
//!   from rest at the static angle, DOP853 at rtol = atol = 1e-10 (the CLI's default),
//!   timed inside the process: the minimum wall time of `repeats` runs and the drive
//!   cycles per second (`benches/peers/heyoka_stick.py`).
//! - `peer_runs painleve`: chapter 8's rod on the scene of cardillo's `Painleve.py`
//!   (`physics::stick_inertia::run::glocker_scene`, 1.5 s), with the state
//!   right after the impact without collision and at the end
//!   (`benches/peers/cardillo_painleve.py`).
//! - `peer_runs toothpick <jamming|authors> <duration_s>`: chapter 8's uniform stick (no tip
//!   mass, 1 kg rod) from rest, mean speed of C with the model's impact law (Darboux-Keller)
//!   and with Moreau-Jean's velocity-level law (`ImpactLaw::VelocityCoulomb`, the law of
//!   time-stepping codes such as MuJoCo) (`benches/peers/mujoco_stick.py`).

use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::{Method, StepControl};
use locomotion_workbook::physics::stick::run::{initial_state, simulate_stick, Recording};
use locomotion_workbook::physics::stick::StickParams;
use locomotion_workbook::physics::stick::{authors_scene, jamming_scene, StickModel};
use locomotion_workbook::physics::stick_inertia::run::{run_from_rest, simulate_inertia};
use locomotion_workbook::physics::stick_inertia::{
    ImpactLaw, InertiaModel, InertiaParams, OM, TH, VXC,
};
use std::time::Instant;

/// DOP853 at rtol = atol (the chapters' default integrator).
fn options(rtol: f64) -> Options {
    Options {
        method: Method::Dop853,
        control: StepControl::tol(rtol, rtol),
        ..Options::default()
    }
}

fn stick(scene: &str, duration_s: f64, repeats: usize) {
    let p = match scene {
        "authors" => authors_scene(10.0),
        _ => jamming_scene(9.81),
    };
    let model = StickModel::new(p);
    let y0 = initial_state(&model, 0.0, p.static_angle().unwrap_or(p.theta0_rad));
    let opts = options(1e-10);
    let (mut best, mut v) = (f64::INFINITY, 0.0);
    for _ in 0..repeats.max(1) {
        let t0 = Instant::now();
        let s = simulate_stick(&model, 0.0, y0, duration_s, &opts, Recording::default());
        best = best.min(t0.elapsed().as_secs_f64());
        v = s.mean_velocity_mps;
    }
    let cycles = duration_s * p.frequency_hz();
    println!(
        "{{\"scene\": \"{scene}\", \"mean_velocity_mps\": {v:.12e}, \"wall_s\": {best:.6e}, \"drive_cycles\": {cycles}, \"cycles_per_s\": {:.1}}}",
        cycles / best
    );
}

/// The state as cardillo writes it: centre (x, z), velocities (vx, vz) and phi' = theta'.
fn centre_json(md: &InertiaModel, y: &[f64; 10]) -> String {
    let g = md.centre(y);
    format!(
        "{{\"x_g_m\": {:.9}, \"z_g_m\": {:.9}, \"vx_g_mps\": {:.9}, \"vz_g_mps\": {:.9}, \"theta_rad\": {:.9}, \"omega_radps\": {:.9}, \"vx_c_mps\": {:.9}}}",
        g[0], g[1], g[2], g[3], y[TH], y[OM], y[VXC]
    )
}

/// The scene of `physics::stick_inertia::run::glocker_scene`, sampled every
/// 1e-4 s: the first sample after the event is in flight (k = gamma = 0: omega constant,
/// G ballistic), so the state right after the impulse follows by undoing gravity over
/// the gap (done by the Python runner).
fn painleve() {
    let th = -(59.0f64).to_radians();
    let mut base = StickParams::new(2.0, 0.0, 0.0, 0.0, 5.0 / 3.0, th, 10.0, 0.0, 30.0)
        .expect("a stick inside the model's domain");
    base.mass_kg = 0.0;
    let md = InertiaModel::new(InertiaParams {
        base,
        rod_mass_kg: 1.0,
        restitution: 0.0,
    });
    let mut y = [0.0; 10];
    y[TH] = th;
    y[VXC] = 30.0;
    let run = simulate_inertia(&md, 0.0, y, 1.5, &options(1e-10), 1e-4);
    let Some(ev) = run.painleve.first() else {
        println!(
            "{{\"error\": \"no Painleve event\", \"outcome\": \"{}\"}}",
            run.outcome.label()
        );
        return;
    };
    let after = run.trace.iter().find(|s| s.t_s > ev.t_s).expect("a sample");
    let end = run.trace.last().expect("a sample");
    let imp = run.impacts.first();
    let samples: Vec<String> = [0.3, 0.6, 0.7, 0.75, 0.8, 0.81, 0.814, 0.8145]
        .iter()
        .filter_map(|&t| run.trace.iter().find(|s| s.t_s >= t - 1e-9))
        .map(|s| {
            format!(
                "{{\"t_s\": {:.6}, \"mode\": \"{}\", \"state\": {}}}",
                s.t_s,
                s.mode.name(),
                centre_json(&md, &s.y)
            )
        })
        .collect();
    println!(
        "{{\"painleve_time_s\": {:.9}, \"theta_rad\": {:.9}, \"mu_p\": {:.9}, \"case\": \"{}\", \"impulse_ns\": {}, \"first_sample_after\": {{\"t_s\": {:.6}, \"mode\": \"{}\", \"state\": {}}}, \"end\": {{\"t_s\": {:.6}, \"mode\": \"{}\", \"state\": {}}}, \"outcome\": \"{}\", \"impacts\": {}, \"samples\": [{}]}}",
        ev.t_s,
        ev.theta_rad,
        ev.mu_p,
        ev.case.name(),
        imp.map_or("null".to_string(), |i| format!("[{:.9}, {:.9}]", i.j_t_ns, i.j_n_ns)),
        after.t_s,
        after.mode.name(),
        centre_json(&md, &after.y),
        end.t_s,
        end.mode.name(),
        centre_json(&md, &end.y),
        run.outcome.label(),
        run.impact_count,
        samples.join(", ")
    );
}

fn toothpick(scene: &str, duration_s: f64) {
    let mut base = match scene {
        "authors" => authors_scene(10.0),
        _ => jamming_scene(9.81),
    };
    base.mass_kg = 0.0;
    let p = InertiaParams {
        base,
        rod_mass_kg: 1.0,
        restitution: 0.0,
    };
    let speed = |law| {
        let mut md = InertiaModel::new(p);
        md.impact_law = law;
        let r = run_from_rest(&md, duration_s, &options(1e-10), 0.0);
        format!(
            "{{\"mean_velocity_mps\": {:.9}, \"outcome\": \"{}\", \"impacts\": {}}}",
            r.mean_velocity_mps,
            r.outcome.label(),
            r.impact_count
        )
    };
    println!(
        "{{\"darboux_keller\": {}, \"velocity_coulomb\": {}}}",
        speed(ImpactLaw::DarbouxKeller),
        speed(ImpactLaw::VelocityCoulomb)
    );
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    match a.get(1).map(String::as_str) {
        Some("stick") => stick(
            a.get(2).map_or("jamming", String::as_str),
            a.get(3).and_then(|s| s.parse().ok()).unwrap_or(1.0),
            a.get(4).and_then(|s| s.parse().ok()).unwrap_or(20),
        ),
        Some("painleve") => painleve(),
        Some("toothpick") => toothpick(
            a.get(2).map_or("jamming", String::as_str),
            a.get(3).and_then(|s| s.parse().ok()).unwrap_or(10.0),
        ),
        _ => {
            eprintln!("usage: peer_runs stick <jamming|authors> <duration_s> <repeats> | painleve | toothpick <jamming|authors> <duration_s>");
            std::process::exit(2);
        }
    }
}
