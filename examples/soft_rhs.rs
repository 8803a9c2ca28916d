//! The soft-contact stick's right-hand side at a set of states, as JSON: what the SciPy
//! port (`benches/peers/stick_soft_scipy.py --check-rhs FILE`) compares its own
//! right-hand side with, state by state.
//!
//! ```sh
//! cargo run --release --example soft_rhs -- [--eps 0.1] [--scene jamming|authors] > rhs.json
//! python3 benches/peers/stick_soft_scipy.py --check-rhs rhs.json
//! ```
//!
//! The states: every 25th accepted step of a Rosenbrock 2(3) run of two drive periods
//! (flight, the damper's ramp, stick and slide to the right), and each contact state of
//! those again with C's horizontal velocity set to `-0.3, -v_eps/3, +v_eps/3, +0.3` m/s
//! (slides both ways and the smoothed friction's linear range) and with the penetration
//! set to half the damper's ramp. Printed with the scene's parameters and the soft
//! constants, so the port can check its constants too.

#[path = "../benches/peers/soft_states.rs"]
mod soft_states;

use locomotion_workbook::physics::stick::{authors_scene, jamming_scene};

fn arg(args: &[String], name: &str) -> Option<String> {
    let i = args.iter().position(|a| a == name)?;
    args.get(i + 1).cloned()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let eps: f64 = arg(&args, "--eps")
        .and_then(|v| v.parse().ok())
        .unwrap_or(0.1);
    let scene = arg(&args, "--scene").unwrap_or_else(|| "jamming".into());
    let p = match scene.as_str() {
        "jamming" => jamming_scene(9.81),
        "authors" => authors_scene(10.0),
        other => {
            eprintln!("--scene: {other} is not one of jamming, authors");
            std::process::exit(2);
        }
    };
    if !(eps.is_finite() && eps > 0.0 && eps <= 1.0) {
        eprintln!("--eps: {eps} is outside (0, 1]");
        std::process::exit(2);
    }
    println!("{}", soft_states::soft_rhs_states(&p, &scene, eps));
}
