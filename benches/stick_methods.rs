//! The stick by three methods: criterion timings of Moreau-Jean time-stepping and of the
//! soft-contact stick under Rosenbrock 2(3), beside the event-driven simulator, and (printed
//! once before the benchmarks) the cost ratio of each new method to the event-driven one
//! at matched accuracy on the mean speed (1e-6 and 1e-9 relative, or the best the method
//! reaches on the ladder).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::{Method, StepControl};
use locomotion_workbook::physics::stick::run::{initial_state, simulate_stick, Recording};
use locomotion_workbook::physics::stick::soft::run::simulate_soft;
use locomotion_workbook::physics::stick::timestepping::simulate_stick_mj;
use locomotion_workbook::physics::stick::{jamming_scene, StickModel, StickParams};
use std::hint::black_box;
use std::time::Instant;

const CYCLES: f64 = 2.0;

fn event(p: &StickParams, tol: f64) -> f64 {
    let model = StickModel::new(*p);
    let y0 = initial_state(&model, 0.0, p.static_angle().unwrap_or(p.theta0_rad));
    let opts = Options {
        method: Method::Dop853,
        control: StepControl::tol(tol, tol),
        ..Options::default()
    };
    let t_end = CYCLES * p.period_s();
    simulate_stick(&model, 0.0, y0, t_end, &opts, Recording::default()).mean_velocity_mps
}

/// Minimum wall time of `n` repeats (s) and the value.
fn best<R>(n: u32, mut f: impl FnMut() -> R) -> (f64, R) {
    let mut t = f64::INFINITY;
    let mut out = None;
    for _ in 0..n {
        let s = Instant::now();
        out = Some(black_box(f()));
        t = t.min(s.elapsed().as_secs_f64());
    }
    (t, out.expect("one repeat"))
}

/// Prints the cost ratios at matched accuracy (one run of the ladders).
fn ratios() {
    let p = jamming_scene(9.81);
    let reference = event(&p, 1e-13);
    let rel = |v: f64| ((v - reference) / reference).abs();
    // The cheapest event-driven run (DOP853 ladder) reaching each target.
    let event_cost = |target: f64| {
        [1e-4, 1e-6, 1e-8, 1e-10, 1e-12]
            .iter()
            .map(|&tol| best(20, || event(&p, tol)))
            .find(|(_, v)| rel(*v) <= target)
    };
    println!("stick by three methods, self-locking scene, {CYCLES} periods, reference {reference:.12} m/s");
    let mut mj_best = (f64::INFINITY, f64::NAN, 0);
    for n in [1000u32, 4000, 16000, 64000] {
        let (t, r) = best(3, || simulate_stick_mj(&p, CYCLES, n, false));
        let e = rel(r.mean_velocity_mps);
        println!("  moreau-jean h = T/{n}: rel {e:.2e}, {t:.4e} s");
        if e < mj_best.1 || mj_best.1.is_nan() {
            mj_best = (t, e, n);
        }
    }
    for target in [1e-6, 1e-9] {
        match event_cost(target) {
            Some((te, ve)) => println!(
                "  target {target:e}: event-driven DOP853 {te:.3e} s (rel {:.1e}); moreau-jean does not reach it, its best {:.1e} at T/{} costs {:.3e} s = {:.0} x",
                rel(ve), mj_best.1, mj_best.2, mj_best.0, mj_best.0 / te
            ),
            None => println!("  target {target:e}: not reached by the event-driven ladder"),
        }
    }
    if let Some((te, ve)) = event_cost(mj_best.1) {
        println!(
            "  at moreau-jean's best accuracy {:.1e}: event-driven {te:.3e} s (rel {:.1e}), ratio {:.0} x",
            mj_best.1,
            rel(ve),
            mj_best.0 / te
        );
    }
    println!("  soft contact: no run on the vibrating plate completes (see chapter 7, section 8); no ratio");
}

fn bench(c: &mut Criterion) {
    ratios();
    let p = jamming_scene(9.81);
    let mut g = c.benchmark_group("stick_methods");
    g.throughput(Throughput::Elements(CYCLES as u64));
    g.bench_function("event_dop853_rtol1e-10_2_cycles", |b| {
        b.iter(|| event(black_box(&p), 1e-10))
    });
    g.bench_function("moreau_jean_T_over_8000_2_cycles", |b| {
        b.iter(|| simulate_stick_mj(black_box(&p), CYCLES, 8000, false).mean_velocity_mps)
    });
    // The soft contact where it works: standing on a still plate, eps = 1e-3.
    let still = StickParams::new(0.15, 1.0, 10.0, 0.01, 0.4, 0.3, 9.81, 0.0, 30.0);
    g.bench_function(
        "soft_contact_rosenbrock23_still_plate_eps1e-3_2_cycles",
        |b| {
            b.iter(|| {
                let ctl = StepControl::tol(1e-8, 1e-12);
                simulate_soft(
                    black_box(&still),
                    1e-3,
                    CYCLES,
                    Method::Rosenbrock23,
                    ctl,
                    100_000,
                )
                .stats
                .accepted
            })
        },
    );
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
