//! The peers side by side: the workbook against SciPy's `solve_ivp` on the same scenes.
//!
//! `cargo bench --bench peer` (needs `python3` with SciPy: `pip install scipy`).
//! Options after `--`: `--tol X` (rtol = atol of both sides, default 1e-10),
//! `--repeats N` (default 5), `--python CMD` (default `python3`).
//!
//! 1. The stick (sections 4, 5), authors' scene (L = 0.15 m, m = 1 kg, Gamma = 10,
//!    f = 30 Hz, k = 10 N m/rad, gamma = 0.01 N m s/rad, mu = 0.4, g = 10 m/s^2), 50
//!    drive cycles from rest at the static angle: `benches/peers/stick_scipy.py` is a
//!    line-by-line port of `src/physics/stick` (flight in closed form on both sides,
//!    contact modes by Dormand-Prince 5(4) with events: the workbook's DP5 and SciPy's
//!    RK45, same rtol = atol, same longest step T/14).
//! 2. The block of chapter 7 (`benches/peers/block_scipy.py`), every mode integrated.
//!
//! Prints the wall times (minimum of repeats), their ratio and the difference of the
//! mean speeds.

use locomotion_workbook::chapters::speed_vs_accuracy::block_scene::BlockScene;
use locomotion_workbook::chapters::speed_vs_accuracy::measure::{
    drift_block_model, stick_speed, timed,
};
use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::{Method, StepControl};
use locomotion_workbook::physics::stick::{authors_scene, StickModel};
use std::process::Command;

fn arg<T: std::str::FromStr>(args: &[String], name: &str, default: T) -> T {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn peer(python: &str, script: &str, args: &[String]) -> Option<serde_json::Value> {
    let path = format!("{}/benches/peers/{script}", env!("CARGO_MANIFEST_DIR"));
    match Command::new(python).arg(&path).args(args).output() {
        Ok(o) if o.status.success() => {
            let v: Option<serde_json::Value> = serde_json::from_slice(&o.stdout).ok();
            if let Some(e) = v.as_ref().and_then(|v| v.get("error")) {
                eprintln!("{script}: {e}");
                return None;
            }
            v
        }
        Ok(o) => {
            eprintln!("{script} failed: {}", String::from_utf8_lossy(&o.stderr));
            None
        }
        Err(e) => {
            eprintln!("cannot run {python}: {e}");
            None
        }
    }
}

fn compare(what: &str, ours: (f64, f64), exact: f64, p: Option<serde_json::Value>) -> bool {
    compare_as(what, "RK45", ours, exact, p)
}

fn compare_as(
    what: &str,
    method: &str,
    ours: (f64, f64),
    exact: f64,
    p: Option<serde_json::Value>,
) -> bool {
    let Some(p) = p else {
        println!("{what}: SciPy peer not available");
        return false;
    };
    let (pv, pw) = (
        p["mean_velocity_mps"].as_f64().unwrap_or(f64::NAN),
        p["wall_s"].as_f64().unwrap_or(f64::NAN),
    );
    println!("{what}: SciPy solve_ivp ({method}): mean speed {pv:.12e} m/s in {pw:.3e} s ({} rhs evaluations)", p["rhs_evals"]);
    println!("{what}: speed ratio SciPy / workbook = {:.0}", pw / ours.1);
    println!(
        "{what}: difference of mean speeds = {:.3e} m/s (relative {:.3e}; workbook against its own reference {:.3e})",
        (pv - ours.0).abs(),
        ((pv - ours.0) / exact).abs(),
        ((ours.0 - exact) / exact).abs()
    );
    true
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let tol: f64 = arg(&args, "--tol", 1e-10);
    let repeats: u32 = arg(&args, "--repeats", 5);
    let python: String = arg(&args, "--python", "python3".to_string());
    println!(
        "rtol = atol = {tol:e} on both sides; wall times are the minimum of {repeats} repeats"
    );

    // 1. the stick
    let model = StickModel::new(authors_scene(10.0));
    let p = model.p;
    let cycles = 50.0;
    let opts = Options {
        control: StepControl::tol(tol, tol),
        ..Options::default()
    };
    let (ours, wall) = timed(repeats, || stick_speed(&model, cycles, &opts).0);
    let reference = stick_speed(
        &model,
        cycles,
        &Options {
            control: StepControl::tol(1e-13, 1e-13),
            ..Options::default()
        },
    )
    .0;
    println!("stick: workbook (DP5, events located): mean speed {:.12e} m/s in {wall:.3e} s ({} rhs evaluations, {:.0} cycles/s)", ours.value, ours.rhs_evals, cycles / wall);
    let stick_args: Vec<String> = [
        ("--length-m", p.length_m),
        ("--mass-kg", p.mass_kg),
        ("--k", p.stiffness_nm_per_rad),
        ("--gamma-damper", p.damping_nms_per_rad),
        ("--mu", p.mu),
        ("--theta0-rad", p.theta0_rad),
        (
            "--theta-start-rad",
            p.static_angle().unwrap_or(p.theta0_rad),
        ),
        ("--g-mps2", p.g_mps2),
        ("--gamma", p.gamma_accel()),
        ("--frequency-hz", p.frequency_hz()),
        ("--cycles", cycles),
        ("--tol", tol),
    ]
    .iter()
    .flat_map(|(k, v)| [k.to_string(), format!("{v:.17e}")])
    .chain(["--repeats".to_string(), repeats.min(3).to_string()])
    .collect();
    let ok_stick = compare(
        "stick",
        (ours.value, wall),
        reference.value,
        peer(&python, "stick_scipy.py", &stick_args),
    );

    // 1b. the stick with the best pair on each side: the workbook's default DOP853
    // against SciPy's DOP853, same tolerance and scene.
    let opts853 = Options {
        method: Method::Dop853,
        ..opts
    };
    let (ours853, wall853) = timed(repeats, || stick_speed(&model, cycles, &opts853).0);
    println!("stick: workbook (DOP853, events located): mean speed {:.12e} m/s in {wall853:.3e} s ({} rhs evaluations, {:.0} cycles/s)", ours853.value, ours853.rhs_evals, cycles / wall853);
    let args853: Vec<String> = stick_args
        .iter()
        .cloned()
        .chain(["--method".to_string(), "DOP853".to_string()])
        .collect();
    let ok_853 = compare_as(
        "stick",
        "DOP853",
        (ours853.value, wall853),
        reference.value,
        peer(&python, "stick_scipy.py", &args853),
    );

    // 2. the block
    // b = F/(mu m g) = 0.05: the peer script's default --bias 0.02 is F/(m g), the same force.
    let s = BlockScene::new(30.0, 2.5, 0.4, 0.05, 9.81);
    let (ours, wall) = timed(repeats, || drift_block_model(&s, &opts, false, 20, 10, 40));
    let exact = drift_block_model(&s, &Options::default(), true, 64, 10, 40).value;
    println!("block: workbook (DP5, events located): drift {:.12e} m/s in {wall:.3e} s ({} rhs evaluations)", ours.value, ours.rhs_evals);
    let block_args: Vec<String> = [
        "--tol".to_string(),
        format!("{tol:e}"),
        "--repeats".to_string(),
        repeats.min(3).to_string(),
    ]
    .to_vec();
    let ok_block = compare(
        "block",
        (ours.value, wall),
        exact,
        peer(&python, "block_scipy.py", &block_args),
    );
    if !(ok_stick && ok_853 && ok_block) {
        std::process::exit(1);
    }
}
