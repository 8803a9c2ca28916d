//! The peer side by side: the workbook against SciPy's `solve_ivp` on the same scene.
//!
//! `cargo bench --bench peer` (needs `python3` with SciPy: `pip install scipy`).
//! Options after `--`: `--tol X` (rtol = atol of both, default 1e-8), `--repeats N`
//! (default 5), `--python CMD` (default `python3`).
//!
//! Scene: the block benchmark of chapter 7 (block on a plate vibrating vertically,
//! Gamma = 2.5, f = 30 Hz, mu = 0.4, bias 0.02; 10 transient + 40 averaged periods).
//! Both sides integrate every mode with Dormand-Prince 5(4) at the same rtol = atol,
//! guards sampled at least every T/20, events located on the dense output. Prints the
//! wall times (minimum of repeats), their ratio and the difference of the mean drifts.

use locomotion_workbook::chapters::speed_vs_accuracy::block_scene::BlockScene;
use locomotion_workbook::chapters::speed_vs_accuracy::measure::{drift_block_model, timed};
use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::StepControl;
use std::process::Command;

fn arg<T: std::str::FromStr>(args: &[String], name: &str, default: T) -> T {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let tol: f64 = arg(&args, "--tol", 1e-8);
    let repeats: u32 = arg(&args, "--repeats", 5);
    let python: String = arg(&args, "--python", "python3".to_string());
    let (transient, cycles) = (10u32, 40u32);
    let s = BlockScene::new(30.0, 2.5, 0.4, 0.02, 9.81);
    let opts = Options {
        control: StepControl::tol(tol, tol),
        ..Options::default()
    };
    let (ours, wall_ours) = timed(repeats, || {
        drift_block_model(&s, &opts, false, 20, transient, cycles)
    });
    let (exact, wall_exact) = timed(repeats, || {
        drift_block_model(&s, &Options::default(), true, 64, transient, cycles)
    });
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/benches/peers/block_scipy.py");
    let out = Command::new(&python)
        .args([
            script,
            "--tol",
            &tol.to_string(),
            "--repeats",
            &repeats.to_string(),
        ])
        .args([
            "--transient",
            &transient.to_string(),
            "--cycles",
            &cycles.to_string(),
        ])
        .output();
    let peer: Option<serde_json::Value> = match out {
        Ok(o) if o.status.success() => serde_json::from_slice(&o.stdout).ok(),
        Ok(o) => {
            eprintln!("peer failed: {}", String::from_utf8_lossy(&o.stderr));
            None
        }
        Err(e) => {
            eprintln!("cannot run {python}: {e}");
            None
        }
    };
    println!("scene: block on a vertically vibrating plate, Gamma 2.5, 30 Hz, mu 0.4, bias 0.02, {cycles} averaged periods");
    println!("tolerance rtol = atol = {tol:e}, Dormand-Prince 5(4) on both sides, minimum of {repeats} repeats");
    println!(
        "workbook (dopri5, integrated): drift {:.12e} m/s, {:.3e} s, {} rhs evaluations",
        ours.value, wall_ours, ours.rhs_evals
    );
    println!(
        "workbook (closed forms):       drift {:.12e} m/s, {:.3e} s",
        exact.value, wall_exact
    );
    let Some(p) = peer else {
        println!("SciPy peer: not available");
        std::process::exit(1);
    };
    let (pv, pw) = (
        p["mean_velocity_mps"].as_f64().unwrap_or(f64::NAN),
        p["wall_s"].as_f64().unwrap_or(f64::NAN),
    );
    println!(
        "SciPy solve_ivp (RK45):        drift {pv:.12e} m/s, {pw:.3e} s, {} rhs evaluations",
        p["rhs_evals"]
    );
    println!(
        "speed ratio (SciPy / workbook, same method and tolerance): {:.0}",
        pw / wall_ours
    );
    println!(
        "speed ratio (SciPy / workbook closed forms):               {:.0}",
        pw / wall_exact
    );
    println!(
        "difference of mean drifts: {:.3e} m/s (relative {:.3e}; workbook vs closed forms: {:.3e})",
        (pv - ours.value).abs(),
        ((pv - ours.value) / exact.value).abs(),
        ((ours.value - exact.value) / exact.value).abs()
    );
}
