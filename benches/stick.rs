//! Speed of the stick simulator: drive cycles simulated per second on one core, for the
//! default (self-locking) scene and the authors' scene, at rtol = atol = 1e-10, with the
//! chapter's default contact integrator (Dormand-Prince 8(5,3)) and with Dormand-Prince
//! 5(4); flight in closed form; certified event detection (and, for its cost, the default
//! scene once more with the end-point sign test only). Criterion's throughput is in
//! cycles ("elements") per second. Chapter 8's stick with inertia runs in the same binary
//! (group `stick_inertia`): the default scene with a uniform rod of 1 % of the tip mass,
//! the same tolerance and driver, so the two models' speeds are a ratio of one run.
//!
//! Group `reference` is a fixed numeric kernel written here and nothing else (a classical
//! RK4 on the Lorenz system, 20,000 steps of 1e-3 s): no workbook code, so it changes only
//! with the machine's load. The number to compare across commits is the ratio of the
//! chapter 6 run (`stick/jamming_30_cycles_rtol1e-10_dop853`) to it, measured in one run.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::{Method, StepControl};
use locomotion_workbook::physics::stick::run::{initial_state, simulate_stick, Recording};
use locomotion_workbook::physics::stick::{authors_scene, jamming_scene, StickModel, StickParams};
use std::hint::black_box;

fn bench_scene(c: &mut Criterion, name: &str, p: StickParams, method: Method, certify: bool) {
    let model = StickModel::new(p);
    let y0 = initial_state(&model, 0.0, p.static_angle().unwrap_or(p.theta0_rad));
    let opts = Options {
        method,
        control: StepControl::tol(1e-10, 1e-10),
        certify,
        ..Options::default()
    };
    let cycles = 30u64;
    let t_end = cycles as f64 * p.period_s();
    let mut g = c.benchmark_group("stick");
    g.throughput(Throughput::Elements(cycles));
    g.bench_function(name, |b| {
        b.iter(|| {
            let s = simulate_stick(
                &model,
                0.0,
                black_box(y0),
                t_end,
                &opts,
                Recording::default(),
            );
            black_box(s.mean_velocity_mps)
        })
    });
    g.finish();
}

fn stick(c: &mut Criterion) {
    for method in [Method::Dop853, Method::Dopri5] {
        let m = method.name();
        bench_scene(
            c,
            &format!("jamming_30_cycles_rtol1e-10_{m}"),
            jamming_scene(9.81),
            method,
            true,
        );
        bench_scene(
            c,
            &format!("authors_30_cycles_rtol1e-10_{m}"),
            authors_scene(10.0),
            method,
            true,
        );
    }
    // The cost of certified event detection, measured side by side: the default scene
    // with the search that compares guard signs at step ends only.
    bench_scene(
        c,
        "jamming_30_cycles_rtol1e-10_dop853_uncertified",
        jamming_scene(9.81),
        Method::Dop853,
        false,
    );
}

fn stick_inertia(c: &mut Criterion) {
    use locomotion_workbook::physics::stick_inertia::{
        run::{initial_state as start, simulate_inertia},
        InertiaModel, InertiaParams,
    };
    let base = jamming_scene(9.81);
    let p = InertiaParams {
        base,
        rod_mass_kg: 0.01 * base.mass_kg,
        restitution: 0.0,
    };
    let model = InertiaModel::new(p);
    let y0 = start(&model, 0.0, p.static_angle().unwrap_or(base.theta0_rad));
    let opts = Options {
        method: Method::Dop853,
        control: StepControl::tol(1e-10, 1e-10),
        ..Options::default()
    };
    let cycles = 30u64;
    let t_end = cycles as f64 * base.period_s();
    let mut g = c.benchmark_group("stick_inertia");
    g.throughput(Throughput::Elements(cycles));
    g.bench_function("jamming_rod_1pc_30_cycles_rtol1e-10_dop853", |b| {
        b.iter(|| {
            let r = simulate_inertia(&model, 0.0, black_box(y0), t_end, &opts, 0.0);
            black_box(r.mean_velocity_mps)
        })
    });
    g.finish();
}

/// Lorenz flow (sigma = 10, rho = 28, beta = 8/3), dimensionless.
fn lorenz(y: [f64; 3]) -> [f64; 3] {
    [
        10.0 * (y[1] - y[0]),
        y[0] * (28.0 - y[2]) - y[1],
        y[0] * y[1] - 8.0 / 3.0 * y[2],
    ]
}

/// `n` classical RK4 steps of size `h` on the Lorenz system: the fixed reference kernel.
fn lorenz_rk4(mut y: [f64; 3], h: f64, n: usize) -> [f64; 3] {
    let add =
        |a: [f64; 3], b: [f64; 3], s: f64| [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]];
    for _ in 0..n {
        let k1 = lorenz(y);
        let k2 = lorenz(add(y, k1, h / 2.0));
        let k3 = lorenz(add(y, k2, h / 2.0));
        let k4 = lorenz(add(y, k3, h));
        for i in 0..3 {
            y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
    }
    y
}

fn reference(c: &mut Criterion) {
    let mut g = c.benchmark_group("reference");
    g.bench_function("lorenz_rk4_20000_steps", |b| {
        b.iter(|| black_box(lorenz_rk4(black_box([1.0, 1.0, 1.0]), 1e-3, 20_000)))
    });
    g.finish();
}

criterion_group!(benches, reference, stick, stick_inertia);
criterion_main!(benches);
