//! Criterion benchmarks of the simulators: work per second of each method on the stick
//! (authors' scene, 10 drive cycles per iteration) and on the block benchmark scene
//! (section 3.1.2: block on a vertically vibrating plate, Gamma = 2.5, f = 30 Hz,
//! mu = 0.4, bias b = F/(mu m g) = 0.05, i.e. F = 0.02 m g), 20 drive periods per
//! iteration.
//!
//! `cargo bench --bench numerics` (add `-- --quick` for a short run).

use criterion::{criterion_group, criterion_main, Criterion};
use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::{Method, StepControl};
use locomotion_workbook::scenes::block::BlockScene;
use locomotion_workbook::scenes::measure::{drift_block_model, drift_mj};
use std::hint::black_box;

fn scene() -> BlockScene {
    BlockScene::new(30.0, 2.5, 0.4, 0.05, 9.81)
}

/// Driver options: `method` at the fixed step `h_s` (s), events located.
fn fixed(method: Method, h_s: f64) -> Options {
    Options {
        method,
        control: StepControl::Fixed { h_s },
        ..Options::default()
    }
}

fn block(c: &mut Criterion) {
    let s = scene();
    let period = s.period_s();
    let mut g = c.benchmark_group("block_drift_20_periods");
    g.bench_function("closed_forms_located", |b| {
        b.iter(|| drift_block_model(black_box(&s), &Options::default(), true, 64, 0, 20))
    });
    g.bench_function("dopri5_1e-8_located", |b| {
        let o = Options {
            control: StepControl::tol(1e-8, 1e-8),
            ..Options::default()
        };
        b.iter(|| drift_block_model(black_box(&s), &o, false, 20, 0, 20))
    });
    for (name, method) in [("rk4", Method::Rk4), ("euler", Method::Euler)] {
        let o = fixed(method, period / 160.0);
        g.bench_function(format!("{name}_T/160_located"), |b| {
            b.iter(|| drift_block_model(black_box(&s), &o, false, 20, 0, 20))
        });
    }
    let w = (0.0, 20.0 * period);
    g.bench_function("moreau_jean_T/160", |b| {
        b.iter(|| drift_mj(black_box(&s), 160, w))
    });
    g.finish();
}

fn stick(c: &mut Criterion) {
    use locomotion_workbook::physics::stick::{authors_scene, StickModel};
    use locomotion_workbook::scenes::measure::stick_speed;
    let m = StickModel::new(authors_scene(10.0));
    let mut g = c.benchmark_group("stick_10_cycles");
    for tol in [1e-6, 1e-10] {
        let o = Options {
            control: StepControl::tol(tol, tol),
            ..Options::default()
        };
        g.bench_function(format!("dopri5_{tol:e}_located"), |b| {
            b.iter(|| stick_speed(black_box(&m), 10.0, &o))
        });
    }
    let o = fixed(Method::Rk4, m.period_s / 256.0);
    g.bench_function("rk4_T/256_located", |b| {
        b.iter(|| stick_speed(black_box(&m), 10.0, &o))
    });
    g.finish();
}

criterion_group!(benches, block, stick);
criterion_main!(benches);
