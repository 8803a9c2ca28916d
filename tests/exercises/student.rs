//! YOUR implementations of the course's build exercises (exercise N.5 of each chapter).
//!
//! Fill in one function at a time, then run its check:
//!
//! ```sh
//! cargo test --release --test exercises -- --ignored yours_1_5      # one exercise
//! cargo test --release --test exercises -- --ignored yours          # all of yours
//! ```
//!
//! Each check compares your function with an independent answer (a closed form, or the
//! workbook's own implementation, which you have not read yet, we hope) and prints what
//! is off. The reference solutions are in `solutions.rs` beside this file: the same
//! checks run on them in every `cargo test`, so the checks themselves are known to pass
//! for a correct answer. Try before you look.

use super::build::{Exercises, PivotInputs};

/// Your answers.
pub struct Yours;

impl Exercises for Yours {
    fn is_outside_hull(_v: [f64; 2], _media: &[[f64; 2]]) -> bool {
        todo!("exercise 1.5: locomotion iff v is strictly outside the hull of 1 to 3 media")
    }

    fn rod_impulse_ratio(_theta_rad: f64) -> f64 {
        todo!("exercise 2.5: J_l/J_v of a uniform rod from W = 1/m Id + r_perp r_perp^T / I_G")
    }

    fn mean_friction(_u: f64) -> f64 {
        todo!("exercise 3.5: the period average of -sign(u - cos phi), 0 <= u <= 1")
    }

    fn dither_drift(_b: f64) -> f64 {
        todo!("exercise 3.5: the drift u (units of V) where the mean friction balances the bias b")
    }

    fn landing_phase(_gamma: f64, _takeoff_phase: f64) -> f64 {
        todo!("exercise 4.5: the first phase after take-off where the flying block meets the plate")
    }

    fn sawtooth_drift(_v_slow: f64, _v_fast: f64, _t_slow: f64, _mu_g: f64) -> f64 {
        todo!("exercise 5.5: the block's mean velocity on the sawtooth, simulated event by event")
    }

    fn pivot_reaction(_p: &PivotInputs, _theta: f64, _theta_dot: f64, _a_s: f64) -> [f64; 2] {
        todo!("exercise 6.5: (F_x, F_z) of the plate on C in pivot, from C.6 and C.7")
    }

    fn rk4_step(_f: &dyn Fn(f64, f64) -> f64, _t: f64, _y: f64, _h: f64) -> f64 {
        todo!("exercise 7.5: one classical Runge-Kutta step for y' = f(t, y)")
    }

    fn rod_mobility(_length_m: f64, _rod_kg: f64, _tip_kg: f64, _theta_rad: f64) -> [[f64; 2]; 2] {
        todo!("exercise 8.5: W = (Id + alpha e_theta e_theta^T)/M of the rod's foot")
    }
}
