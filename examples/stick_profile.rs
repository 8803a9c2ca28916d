//! A fixed amount of stick simulation for instruction counts under callgrind
//! (`valgrind --tool=callgrind target/release/examples/stick_profile [scene] [certify]`):
//! the benchmark's run (30 drive cycles at rtol = atol = 1e-10, DOP853), repeated 20 times.
//! Instruction counts are repeatable whatever else the machine is doing, so one change can
//! be compared with another on a shared machine; `cargo bench --bench stick` gives the rate.

use locomotion_workbook::numerics::hybrid::Options;
use locomotion_workbook::numerics::ode::{Method, StepControl};
use locomotion_workbook::physics::stick::run::{initial_state, simulate_stick, Recording};
use locomotion_workbook::physics::stick::{authors_scene, jamming_scene, StickModel};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let p = match args.get(1).map(String::as_str) {
        Some("authors") => authors_scene(10.0),
        _ => jamming_scene(9.81),
    };
    let certify = args.get(2).map(String::as_str) != Some("uncertified");
    let model = StickModel::new(p);
    let y0 = initial_state(&model, 0.0, p.static_angle().unwrap_or(p.theta0_rad));
    let opts = Options {
        method: Method::Dop853,
        control: StepControl::tol(1e-10, 1e-10),
        certify,
        ..Options::default()
    };
    let t_end = 30.0 * p.period_s();
    let mut sum = 0.0;
    for _ in 0..20 {
        let s = simulate_stick(&model, 0.0, y0, t_end, &opts, Recording::default());
        sum += s.mean_velocity_mps;
    }
    println!("mean velocity {:.12} m/s", sum / 20.0);
}
