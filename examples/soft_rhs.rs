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

use locomotion_workbook::numerics::ode::{Integrator, Method, OdeSystem, StepControl};
use locomotion_workbook::physics::stick::soft::{SoftStick, SD, STH, SVX};
use locomotion_workbook::physics::stick::{authors_scene, jamming_scene};
use serde_json::{json, Value};

fn arg(args: &[String], name: &str) -> Option<String> {
    let i = args.iter().position(|a| a == name)?;
    args.get(i + 1).cloned()
}

fn record(sys: &SoftStick, t: f64, y: &[f64; 5]) -> Value {
    let f = sys.forces(t, y);
    json!({
        "t_s": t,
        "y": y,
        "rhs": sys.rhs(t, y),
        "theta_dot_rad_s": f.theta_dot,
        "fx_n": f.fx,
        "fz_n": f.fz,
    })
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
    let sys = SoftStick::new(p, eps);
    let y0 = sys.at_rest(0.0, p.static_angle().unwrap_or(p.theta0_rad));
    let t_end = 2.0 * p.period_s();
    let mut integ = Integrator::new(Method::Rosenbrock23, StepControl::tol(1e-8, 1e-8));
    let (mut t, mut y) = (0.0, y0);
    let mut states = vec![record(&sys, t, &y)];
    let mut n = 0u64;
    while t < t_end && n < 200_000 {
        let Ok(s) = integ.step(&sys, t, &y, t_end) else {
            break;
        };
        (t, y) = (s.t1, s.y1);
        n += 1;
        if n % 25 != 0 {
            continue;
        }
        states.push(record(&sys, t, &y));
        if y[SD] < 0.0 {
            // C's velocity x_c' = x_p' - L cos(theta) theta' (C.3): shift x_p' to set it
            let w = sys.forces(t, &y).theta_dot;
            let lcw = p.length_m * y[STH].cos() * w;
            let v_eps = sys.soft.slip_scale_mps;
            for vxc in [-0.3, -v_eps / 3.0, v_eps / 3.0, 0.3] {
                let mut z = y;
                z[SVX] = vxc + lcw;
                states.push(record(&sys, t, &z));
            }
            let mut z = y;
            z[SD] = -0.5 * sys.soft.damping_ramp_m;
            states.push(record(&sys, t, &z));
        }
    }
    let out = json!({
        "scene": scene,
        "eps": eps,
        "params": {
            "length_m": p.length_m,
            "mass_kg": p.mass_kg,
            "k_nm_per_rad": p.stiffness_nm_per_rad,
            "gamma_nms_per_rad": p.damping_nms_per_rad,
            "mu": p.mu,
            "theta0_rad": p.theta0_rad,
            "g_mps2": p.g_mps2,
            "gamma_accel": p.gamma_accel(),
            "frequency_hz": p.frequency_hz(),
            "amplitude_m": p.plate.amplitude_m,
            "theta_start_rad": p.static_angle().unwrap_or(p.theta0_rad),
        },
        "soft": {
            "stiffness_n_per_m": sys.soft.stiffness_n_per_m,
            "damping_ns_per_m": sys.soft.damping_ns_per_m,
            "slip_scale_mps": sys.soft.slip_scale_mps,
            "damping_ramp_m": sys.soft.damping_ramp_m,
        },
        "states": states,
    });
    println!("{out}");
}
