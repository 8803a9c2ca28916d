//! Speed of the stick simulator: drive cycles simulated per second on one core, for the
//! default (self-locking) scene and the authors' scene, at rtol = atol = 1e-10
//! (Dormand-Prince 5(4) in contact, closed-form flight). Criterion's throughput is in
//! cycles ("elements") per second.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::StepControl;
use locomotion_workbook::physics::stick::run::{initial_state, simulate_stick, Recording};
use locomotion_workbook::physics::stick::{authors_scene, jamming_scene, StickModel, StickParams};
use std::hint::black_box;

fn bench_scene(c: &mut Criterion, name: &str, p: StickParams) {
    let model = StickModel::new(p);
    let y0 = initial_state(&model, 0.0, p.static_angle().unwrap_or(p.theta0_rad));
    let opts = Options {
        control: StepControl::tol(1e-10, 1e-10),
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
    bench_scene(c, "jamming_30_cycles_rtol1e-10", jamming_scene(9.81));
    bench_scene(c, "authors_30_cycles_rtol1e-10", authors_scene(10.0));
}

criterion_group!(benches, stick);
criterion_main!(benches);
