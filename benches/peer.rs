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
//! 3. The soft-contact stick (`physics::stick::soft`, self-locking scene, `eps` = 0.1, two
//!    drive periods from rest): `benches/peers/stick_soft_scipy.py`, a port of the same
//!    right-hand side (checked against the workbook's by `examples/soft_rhs.rs`), under
//!    SciPy's `Radau`, `BDF`, `LSODA` (stiff) and `DOP853`, `RK45` (explicit) at a ladder
//!    of rtol, against the workbook's Rosenbrock 2(3) at a ladder of rtol (the port's
//!    right-hand side is compared with the workbook's first, `peers/soft_states.rs`, and
//!    a mismatch stops the part); atol = rtol
//!    on both sides. Accuracy is the relative
//!    difference of the mean speed from one reference of the same soft model (SciPy's
//!    `Radau` at rtol 1e-12), the same for both sides; the comparison at equal accuracy
//!    takes, for each accuracy, the cheapest run of each side that reaches it (no
//!    interpolation: the ladders are half a decade apart).
//!    Options: `--only stick|block|soft` (one part), `--soft-eps X`, `--soft-cycles N`,
//!    `--soft-ref-rtol X` (the reference's rtol = atol, default 1e-12; Radau completes
//!    there at eps = 0.1 and 0.01 since the root search of C.8 follows `rtsafe`).
//!
//! Prints the wall times (minimum of repeats), their ratio and the difference of the
//! mean speeds.

use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::{Method, StepControl};
use locomotion_workbook::physics::stick::soft::run::{simulate_soft, SoftOutcome};
use locomotion_workbook::physics::stick::{authors_scene, jamming_scene, StickModel, StickParams};
use locomotion_workbook::scenes::block::BlockScene;
use locomotion_workbook::scenes::measure::{drift_block_model, stick_speed, timed};
use std::process::Command;

#[path = "peers/soft_states.rs"]
mod soft_states;

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
            let v: Option<serde_json::Value> = serde_json::from_slice(&o.stdout)
                .map_err(|e| eprintln!("{script}: output is not JSON ({e})"))
                .ok();
            if let Some(e) = v.as_ref().and_then(|v| v.get("error")) {
                eprintln!("{script}: {e}");
                return None;
            }
            v
        }
        Ok(o) => {
            eprintln!(
                "{script} failed: {}{}",
                String::from_utf8_lossy(&o.stdout),
                String::from_utf8_lossy(&o.stderr)
            );
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
    let only: String = arg(&args, "--only", String::new());
    let part = |name: &str| only.is_empty() || only == name;
    println!(
        "rtol = atol = {tol:e} on both sides (stick, block); wall times are the minimum of {repeats} repeats"
    );
    let mut ok = true;
    if part("stick") {
        ok &= stick(&python, tol, repeats);
    }
    if part("block") {
        ok &= block(&python, tol, repeats);
    }
    if part("soft") {
        let eps: f64 = arg(&args, "--soft-eps", 0.1);
        let cycles: f64 = arg(&args, "--soft-cycles", 2.0);
        let ref_rtol: f64 = arg(&args, "--soft-ref-rtol", 1e-12);
        ok &= soft(&python, repeats, eps, cycles, ref_rtol);
    }
    if !ok {
        std::process::exit(1);
    }
}

/// The stick (part 1), DP5 against RK45 and DOP853 against DOP853. Returns whether both peers ran.
fn stick(python: &str, tol: f64, repeats: u32) -> bool {
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
        peer(python, "stick_scipy.py", &stick_args),
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
        peer(python, "stick_scipy.py", &args853),
    );

    ok_stick && ok_853
}

/// The block (part 2). Returns whether the peer ran.
fn block(python: &str, tol: f64, repeats: u32) -> bool {
    let opts = Options {
        control: StepControl::tol(tol, tol),
        ..Options::default()
    };
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
    compare(
        "block",
        (ours.value, wall),
        exact,
        peer(python, "block_scipy.py", &block_args),
    )
}

/// One run of a work-precision ladder: its accuracy on the mean speed and its cost.
#[derive(Debug, Clone)]
struct Point {
    label: String,
    rel: f64,
    wall_s: f64,
    evals: u64,
}

/// The cheapest run of `pts` whose relative difference is at most `target`.
fn cheapest(pts: &[Point], target: f64) -> Option<&Point> {
    pts.iter()
        .filter(|q| q.rel <= target)
        .min_by(|a, b| a.wall_s.total_cmp(&b.wall_s))
}

/// Compares the SciPy port's right-hand side with the workbook's at the states of
/// `soft_states` (`stick_soft_scipy.py --check-rhs`); prints its verdict.
fn check_soft_port(python: &str, p: &StickParams, eps: f64) -> bool {
    let states = soft_states::soft_rhs_states(p, "jamming", eps);
    let file = match tempfile::NamedTempFile::new()
        .and_then(|f| std::fs::write(f.path(), states.to_string()).map(|_| f))
    {
        Ok(f) => f,
        Err(e) => {
            eprintln!("soft: cannot write the states for the check: {e}");
            return false;
        }
    };
    let path = file.path().to_string_lossy().to_string();
    let Some(v) = peer(
        python,
        "stick_soft_scipy.py",
        &["--check-rhs".to_string(), path],
    ) else {
        println!("soft: the port's right-hand side does not match the workbook's (or the check did not run)");
        return false;
    };
    println!(
        "soft: port checked at {} states: right-hand sides agree to {:.1e} of each component's scale, constants to {:.1e} (root searches that ran out of iterations, compared too: {})",
        v["states"], v["rhs_max_difference_over_component_scale"].as_f64().unwrap_or(f64::NAN),
        v["constants_max_relative_difference"].as_f64().unwrap_or(f64::NAN),
        v["states_with_slow_root_solve"]
    );
    true
}

/// The soft-contact stick (part 3): the workbook's Rosenbrock 2(3) against SciPy's stiff
/// methods (and explicit pairs) at equal accuracy. Returns whether the peer ran.
fn soft(python: &str, repeats: u32, eps: f64, cycles: f64, ref_rtol: f64) -> bool {
    // atol = rtol, as the chapter's soft runs (atol = rtol / 1000 runs too since the
    // rtsafe root search: eps = 0.1, rtol 1e-10, 164200 evaluations; before, it stalled)
    const ATOL_RATIO: f64 = 1.0;
    let p = jamming_scene(9.81);
    if !check_soft_port(python, &p, eps) {
        return false;
    }
    let args: Vec<String> = [
        "--scene",
        "jamming",
        "--eps",
        &format!("{eps:e}"),
        "--cycles",
        &format!("{cycles}"),
        "--atol-ratio",
        &format!("{ATOL_RATIO:e}"),
        "--ref-rtol",
        &format!("{ref_rtol:e}"),
        "--repeats",
        &repeats.min(3).to_string(),
        "--methods",
        "Radau,BDF,LSODA,DOP853,RK45",
        "--rtols",
        "1e-3,1e-4,1e-5,1e-6,1e-7,1e-8,1e-9,1e-10",
        "--explicit-rtols",
        "1e-4,1e-8",
        "--max-evals",
        "400000",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let Some(v) = peer(python, "stick_soft_scipy.py", &args) else {
        println!("soft: SciPy peer not available");
        return false;
    };
    let reference = v["reference"]["mean_velocity_mps"]
        .as_f64()
        .unwrap_or(f64::NAN);
    let rel = |x: f64| ((x - reference) / reference).abs(); // formula: |v - v_ref| / |v_ref|
                                                            // below a few times the reference's own uncertainty no accuracy can be told apart
    let uncertainty = v["reference_uncertainty"].as_f64().unwrap_or(f64::INFINITY);
    let floor = 3.0 * uncertainty;
    println!(
        "soft: self-locking scene, eps = {eps}, {cycles} periods from rest, atol = rtol x {ATOL_RATIO:e} on both sides"
    );
    println!(
        "soft: reference (SciPy Radau, rtol = atol = {ref_rtol:e}): {reference:.12e} m/s in {:.3} s ({} evaluations)",
        v["reference"]["wall_s"].as_f64().unwrap_or(f64::NAN),
        v["reference"]["nfev"]
    );
    println!("soft: the reference's uncertainty (against Radau at ten times its rtol): {uncertainty:.1e}; accuracies below {floor:.1e} are not compared");
    // the workbook's ladder: rtol 1e-3 .. 1e-12, half a decade apart (the tight end runs
    // since the root search of C.8 follows rtsafe; before, runs stalled from 1e-10 on)
    let mut ours = Vec::new();
    for k in 6..=24 {
        let rtol = 10f64.powf(-f64::from(k) / 2.0);
        let control = StepControl::tol(rtol, rtol * ATOL_RATIO);
        let run = || simulate_soft(&p, eps, cycles, Method::Rosenbrock23, control, 200_000);
        // a run that stalls (1e5 accepted steps and more near one instant) is not repeated
        let (first, wall1) = timed(1, run);
        let (r, wall) = if first.outcome == SoftOutcome::Completed {
            let (r, wall) = timed(repeats, run);
            (r, wall.min(wall1))
        } else {
            (first, wall1)
        };
        if r.outcome != SoftOutcome::Completed {
            println!("soft: workbook rtol {rtol:.1e}: {:?}", r.outcome);
            continue;
        }
        ours.push(Point {
            label: format!("Rosenbrock23 rtol {rtol:.1e}"),
            rel: rel(r.mean_velocity_mps),
            wall_s: wall,
            evals: r.stats.rhs_evals,
        });
    }
    let mut theirs = Vec::new();
    println!("soft: | run | relative difference | wall time (s) | evaluations |");
    for r in ours.iter() {
        println!(
            "soft: | workbook {} | {:.1e} | {:.3e} | {} |",
            r.label, r.rel, r.wall_s, r.evals
        );
    }
    for r in v["runs"].as_array().into_iter().flatten() {
        let label = format!(
            "{} rtol {:.0e}",
            r["method"].as_str().unwrap_or("?"),
            r["rtol"].as_f64().unwrap_or(f64::NAN)
        );
        let wall = r["wall_s"].as_f64().unwrap_or(f64::NAN);
        let evals = r["nfev"].as_u64().unwrap_or(0);
        if r["method"] == v["reference"]["method"] && r["rtol"] == v["reference"]["rtol"] {
            println!("soft: | SciPy {label} | the reference itself | {wall:.3e} | {evals} |");
            continue;
        }
        match r["relative_difference"].as_f64() {
            Some(e) => {
                println!("soft: | SciPy {label} | {e:.1e} | {wall:.3e} | {evals} |");
                theirs.push(Point {
                    label,
                    rel: e,
                    wall_s: wall,
                    evals,
                });
            }
            None => println!(
                "soft: | SciPy {label} | {} | {wall:.3e} | {evals} |",
                r["status"].as_str().unwrap_or("failed")
            ),
        }
    }
    println!("soft: each SciPy run against the workbook's cheapest run at least as accurate:");
    for t in &theirs {
        if t.rel < floor {
            println!(
                "soft:   SciPy {} ({:.1e}): below the reference's uncertainty",
                t.label, t.rel
            );
            continue;
        }
        match cheapest(&ours, t.rel) {
            Some(o) => println!(
                "soft:   SciPy {} ({:.1e}, {:.3e} s) / workbook {} ({:.1e}, {:.3e} s) = {:.0}",
                t.label,
                t.rel,
                t.wall_s,
                o.label,
                o.rel,
                o.wall_s,
                t.wall_s / o.wall_s
            ),
            None => println!(
                "soft:   SciPy {} ({:.1e}): no workbook run that accurate",
                t.label, t.rel
            ),
        }
    }
    println!("soft: at equal accuracy, the best SciPy choice against the workbook (cheapest run of each reaching it):");
    for target in [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9] {
        if target < floor {
            println!("soft:   {target:.0e}: below the reference's uncertainty");
            continue;
        }
        match (cheapest(&theirs, target), cheapest(&ours, target)) {
            (Some(t), Some(o)) => println!(
                "soft:   {target:.0e}: SciPy {} {:.3e} s ({} evaluations), workbook {} {:.3e} s ({} evaluations): ratio {}",
                t.label, t.wall_s, t.evals, o.label, o.wall_s, o.evals, ratio(t.wall_s / o.wall_s)
            ),
            (t, o) => println!(
                "soft:   {target:.0e}: not reached by {}",
                match (t, o) {
                    (None, None) => "either side",
                    (None, _) => "SciPy",
                    _ => "the workbook",
                }
            ),
        }
    }
    true
}

/// A cost ratio: one decimal below 10, none above.
fn ratio(x: f64) -> String {
    if x < 10.0 {
        format!("{x:.1}")
    } else {
        format!("{x:.0}")
    }
}
