//! The stick by three methods: criterion timings of Moreau-Jean time-stepping and of the
//! soft-contact stick under Rosenbrock 2(3), beside the event-driven simulator, and (printed
//! once before the benchmarks) the cost ratio of each new method to the event-driven one
//! at matched accuracy on the mean speed (1e-6 and 1e-9 relative, or the best the method
//! reaches on the ladder).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::{Method, StepControl};
use locomotion_workbook::physics::stick::run::{initial_state, simulate_stick, Recording};
use locomotion_workbook::physics::stick::soft::run::{simulate_soft, SoftOutcome};
use locomotion_workbook::physics::stick::timestepping::simulate_stick_mj;
use locomotion_workbook::physics::stick::{jamming_scene, StickModel, StickParams};
use std::hint::black_box;
use std::time::Instant;

const CYCLES: f64 = 2.0;

/// Mean speed (m/s) and force evaluations of an event-driven DOP853 run at rtol = atol = `tol`.
fn event(p: &StickParams, tol: f64) -> (f64, u64) {
    let model = StickModel::new(*p);
    let y0 = initial_state(&model, 0.0, p.static_angle().unwrap_or(p.theta0_rad));
    let opts = Options {
        method: Method::Dop853,
        control: StepControl::tol(tol, tol),
        ..Options::default()
    };
    let t_end = CYCLES * p.period_s();
    let r = simulate_stick(&model, 0.0, y0, t_end, &opts, Recording::default());
    (r.mean_velocity_mps, r.stats.rhs_evals)
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

/// One run of a ladder: its setting, accuracy on the mean speed and cost.
#[derive(Debug, Clone)]
struct Run {
    setting: String,
    rel: f64,
    wall_s: f64,
    evals: u64,
}

/// The cheapest run of `runs` at least as accurate as `target`.
fn cheapest(runs: &[Run], target: f64) -> Option<&Run> {
    runs.iter()
        .filter(|r| r.rel <= target)
        .min_by(|a, b| a.wall_s.total_cmp(&b.wall_s))
}

/// The most accurate run of `runs` (the best the method reaches on its ladder).
fn most_accurate(runs: &[Run]) -> Option<&Run> {
    runs.iter().min_by(|a, b| a.rel.total_cmp(&b.rel))
}

/// Regularisations of the soft-contact ladder (each half the last) and the Rosenbrock
/// tolerances tried at each: the cheapest run reaching an accuracy may be a loose
/// tolerance at a small `eps`.
const SOFT_EPS: [f64; 8] = [
    0.1, 0.05, 0.025, 0.0125, 0.00625, 0.003125, 0.0015625, 0.00078125,
];
const SOFT_RTOLS: [f64; 3] = [1e-6, 1e-8, 1e-10];
/// Accepted steps of one soft-contact run: the finest run takes 28359 (eps = 0.00078125,
/// rtol 1e-10). Every run of the ladder completes since the root search of C.8 follows
/// `rtsafe`; before, tight runs stalled (eps = 0.025, rtol 1e-10: 3e5 steps ended at
/// t = 0.0224 s), and a run that still spent the budget would be reported, not timed.
const SOFT_BUDGET: u64 = 60_000;

/// The three ladders on `p`, against the event-driven reference at rtol 1e-13.
fn ladders(p: &StickParams, reference: f64) -> [Vec<Run>; 3] {
    let rel = |v: f64| ((v - reference) / reference).abs(); // formula: |v - v_ref| / |v_ref|
    let event: Vec<Run> = [1e-4, 1e-6, 1e-8, 1e-10, 1e-12]
        .iter()
        .map(|&tol| {
            let (t, (v, evals)) = best(20, || event(p, tol));
            Run {
                setting: format!("rtol {tol:.0e}"),
                rel: rel(v),
                wall_s: t,
                evals,
            }
        })
        .collect();
    let mj: Vec<Run> = [1000u32, 4000, 16000, 64000]
        .iter()
        .map(|&n| {
            let (t, r) = best(3, || simulate_stick_mj(p, CYCLES, n, false));
            Run {
                setting: format!("h = T/{n}"),
                rel: rel(r.mean_velocity_mps),
                wall_s: t,
                evals: r.stats.rhs_evals,
            }
        })
        .collect();
    let mut soft = Vec::new();
    for eps in SOFT_EPS {
        for rtol in SOFT_RTOLS {
            let ctl = StepControl::tol(rtol, rtol);
            let run = || simulate_soft(p, eps, CYCLES, Method::Rosenbrock23, ctl, SOFT_BUDGET);
            // a run that stalls (see SOFT_BUDGET) is not repeated
            let (t, r) = best(1, run);
            let (t, r) = if r.outcome == SoftOutcome::Completed {
                let (t2, r2) = best(2, run);
                (t.min(t2), r2)
            } else {
                (t, r)
            };
            if r.outcome == SoftOutcome::Completed {
                soft.push(Run {
                    setting: format!("eps {eps}, rtol {rtol:.0e}"),
                    rel: rel(r.mean_velocity_mps),
                    wall_s: t,
                    evals: r.stats.rhs_evals,
                });
            } else {
                println!("  soft contact eps {eps}, rtol {rtol:.0e}: {:?}", r.outcome);
            }
        }
    }
    [event, mj, soft]
}

/// One row of the matched-accuracy table: the event-driven cost at `target` and each
/// other method's cheapest run reaching it.
fn row(what: &str, target: f64, event: &[Run], others: [&[Run]; 2]) {
    let Some(e) = cheapest(event, target) else {
        println!("| {what} | not reached by the event-driven ladder | | | |");
        return;
    };
    let cell = |runs: &[Run]| match cheapest(runs, target) {
        Some(r) => format!(
            "{} ({:.1e}): {:.3e} s, {} evals | {} x",
            r.setting,
            r.rel,
            r.wall_s,
            r.evals,
            ratio(r.wall_s / e.wall_s)
        ),
        None => "not reached | -".to_string(),
    };
    println!(
        "| {what} | {} ({:.1e}): {:.3e} s, {} evals | {} | {} |",
        e.setting,
        e.rel,
        e.wall_s,
        e.evals,
        cell(others[0]),
        cell(others[1])
    );
}

/// Prints the cost ratios at matched accuracy (one run of the ladders), with the load.
fn ratios() {
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    let p = jamming_scene(9.81);
    let reference = event(&p, 1e-13).0;
    println!(
        "stick by three methods, self-locking scene, {CYCLES} periods from rest, reference (event-driven DOP853, rtol 1e-13) {reference:.12} m/s; load average {}",
        load.split_whitespace().take(3).collect::<Vec<_>>().join(" ")
    );
    let [event, mj, soft] = ladders(&p, reference);
    for (name, runs) in [
        ("event-driven DOP853", &event),
        ("Moreau-Jean", &mj),
        ("soft contact + Rosenbrock 2(3)", &soft),
    ] {
        for r in runs.iter() {
            println!(
                "  {name} {}: rel {:.2e}, {:.3e} s, {} evals",
                r.setting, r.rel, r.wall_s, r.evals
            );
        }
    }
    println!("cost at matched accuracy: the cheapest run of each ladder at least as accurate as the target; ratio = its wall time / the event-driven one");
    println!("| target | event-driven DOP853 | Moreau-Jean | ratio | soft contact | ratio |");
    println!("|---|---|---|---|---|---|");
    for target in [1e-3, 1e-4, 1e-6, 1e-9] {
        row(&format!("{target:.0e}"), target, &event, [&mj, &soft]);
    }
    for (name, runs) in [("Moreau-Jean", &mj), ("soft contact", &soft)] {
        if let Some(b) = most_accurate(runs) {
            row(
                &format!("{name}'s best, {:.1e}", b.rel),
                b.rel,
                &event,
                [&mj, &soft],
            );
        }
    }
    // Soft contact's error is not monotone in eps (it changes sign between 0.05 and
    // 0.0125), so its best on the ladder can be a lucky crossing; its accuracy in the
    // tail is that of the smallest eps, the most accurate run there.
    let smallest = SOFT_EPS[SOFT_EPS.len() - 1];
    let tail: Vec<Run> = soft
        .iter()
        .filter(|r| r.setting.starts_with(&format!("eps {smallest},")))
        .cloned()
        .collect();
    if let (Some(b), Some(e)) = (
        most_accurate(&tail),
        most_accurate(&tail).and_then(|b| cheapest(&event, b.rel)),
    ) {
        println!(
            "| soft contact at its smallest eps, {:.1e} | {} ({:.1e}): {:.3e} s, {} evals | | | {} ({:.1e}): {:.3e} s, {} evals | {} x |",
            b.rel, e.setting, e.rel, e.wall_s, e.evals, b.setting, b.rel, b.wall_s, b.evals, ratio(b.wall_s / e.wall_s)
        );
    }
    load_after(&load);
}

/// Prints the load average after the ladders (the machine is shared).
fn load_after(before: &str) {
    let after = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "load average before {} / after {}",
        before
            .split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" "),
        after
            .split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" ")
    );
}

fn bench(c: &mut Criterion) {
    ratios();
    let p = jamming_scene(9.81);
    let mut g = c.benchmark_group("stick_methods");
    g.throughput(Throughput::Elements(CYCLES as u64));
    g.bench_function("event_dop853_rtol1e-10_2_cycles", |b| {
        b.iter(|| event(black_box(&p), 1e-10).0)
    });
    g.bench_function("moreau_jean_T_over_8000_2_cycles", |b| {
        b.iter(|| simulate_stick_mj(black_box(&p), CYCLES, 8000, false).mean_velocity_mps)
    });
    // The soft contact on the vibrating plate: eps = 0.1 (the SciPy peer's setting),
    // Rosenbrock 2(3) at rtol = atol = 1e-8.
    g.bench_function("soft_contact_rosenbrock23_eps0.1_rtol1e-8_2_cycles", |b| {
        b.iter(|| {
            let ctl = StepControl::tol(1e-8, 1e-8);
            simulate_soft(
                black_box(&p),
                0.1,
                CYCLES,
                Method::Rosenbrock23,
                ctl,
                1_000_000,
            )
            .mean_velocity_mps
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

/// A cost ratio: one decimal below 10, none above.
fn ratio(x: f64) -> String {
    if x < 10.0 {
        format!("{x:.1}")
    } else {
        format!("{x:.0}")
    }
}
