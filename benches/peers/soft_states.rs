//! The soft-contact stick's right-hand side at a set of states, as JSON (shared by
//! `examples/soft_rhs.rs` and `benches/peer.rs`, which include this file): what the SciPy
//! port's `--check-rhs` compares its own right-hand side with, state by state.

use locomotion_workbook::numerics::ode::{Integrator, Method, OdeSystem, StepControl};
use locomotion_workbook::physics::stick::soft::{SoftStick, SD, STH, SVX};
use locomotion_workbook::physics::stick::StickParams;
use serde_json::{json, Value};

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

/// The scene's parameters, the soft constants and the workbook's right-hand side at every
/// 25th accepted step of a Rosenbrock 2(3) run of two drive periods (rtol = atol = 1e-8)
/// and at each contact state of those again with C's horizontal velocity set to `-0.3,
/// -v_eps/3, +v_eps/3, +0.3` m/s and with the penetration at half the damper's ramp.
pub fn soft_rhs_states(p: &StickParams, scene: &str, eps: f64) -> Value {
    let sys = SoftStick::new(*p, eps);
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
    json!({
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
    })
}
