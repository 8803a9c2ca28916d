//! A second method for the landing collision: the Newton-Euler impulse equations solved
//! as a linear system, independent of the angular-momentum formula C.15.
//!
//! Unknowns: the impulse `J = (J_x, J_z)` of the plate on C and the rod's rate after,
//! `w+`. Equations: (1, 2) the mass, `m (v_P+ - v_P-) = J`, with C stuck after the
//! impact, `v_P+ = (0, zdot_s) + L w+ (cos, -sin)` (C.3); (3) the massless rod carries
//! no impulsive moment about P, so `J` lies along the rod: `e_r x J = sin J_z - cos J_x
//! = 0`. Solved by Gaussian elimination with partial pivoting.

use crate::physics::stick::{State, StickModel, TH};

/// The Newton-Euler impulse of a sticking landing at `(t, y)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NewtonEuler {
    /// Impulse of the plate on C (N s).
    pub jx: f64,
    /// See `jx`.
    pub jz: f64,
    /// The rod's rate after (rad/s).
    pub omega_after: f64,
}

impl NewtonEuler {
    /// The impulse's component along the rod from C to P (N s): positive = compressive.
    pub fn along_rod(&self, theta: f64) -> f64 {
        let (s, c) = theta.sin_cos();
        self.jx * s + self.jz * c
    }
}

/// The three equations at the landing state `y` (time `t`) as an augmented 3x4 matrix
/// [A | b], unknowns (J_x, J_z, θ'+): what `newton_euler` solves and `at_states.rs`
/// takes the residual of.
pub fn system(m: &StickModel, t: f64, y: &State) -> [[f64; 4]; 3] {
    let (mass, l) = (m.p.mass_kg, m.p.length_m);
    let [_, _, vxp, vzp] = m.tip(y);
    let vs = m.plate(t).1;
    let (s, c) = y[TH].sin_cos();
    // rows: J_x / m - L c w = -vxp ; J_z / m + L s w = vs - vzp ; -c J_x + s J_z = 0
    [
        [1.0 / mass, 0.0, -l * c, -vxp],
        [0.0, 1.0 / mass, l * s, vs - vzp],
        [-c, s, 0.0, 0.0],
    ]
}

/// Solves the three equations at the landing state `y` (time `t`).
pub fn newton_euler(m: &StickModel, t: f64, y: &State) -> NewtonEuler {
    let x = solve3(&mut system(m, t, y));
    NewtonEuler {
        jx: x[0],
        jz: x[1],
        omega_after: x[2],
    }
}

/// Gaussian elimination with partial pivoting on an augmented 3x4 matrix.
fn solve3(a: &mut [[f64; 4]; 3]) -> [f64; 3] {
    for col in 0..3 {
        let piv = (col..3)
            .max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
            .unwrap_or(col);
        a.swap(col, piv);
        let pivot_row = a[col];
        for row in a.iter_mut().skip(col + 1) {
            let f = row[col] / pivot_row[col];
            for (x, p) in row.iter_mut().zip(pivot_row).skip(col) {
                *x -= f * p;
            }
        }
    }
    let mut x = [0.0; 3];
    for row in (0..3).rev() {
        let sum: f64 = (row + 1..3).map(|k| a[row][k] * x[k]).sum();
        x[row] = (a[row][3] - sum) / a[row][row];
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::stick::{authors_scene, NSTATE, OM, VXC, VZC, ZC};

    #[test]
    fn impulse_lies_along_the_rod_and_sticks_c() {
        let m = StickModel::new(authors_scene(10.0));
        let mut y = [0.0; NSTATE];
        y[TH] = 0.3;
        y[ZC] = m.plate(0.01).0;
        y[VXC] = 0.4;
        y[VZC] = -1.0;
        y[OM] = 2.0;
        let ne = newton_euler(&m, 0.01, &y);
        let (s, c) = y[TH].sin_cos();
        assert!((s * ne.jz - c * ne.jx).abs() < 1e-12);
        let [_, _, vxp, vzp] = m.tip(&y);
        let (vxp1, vzp1) = (vxp + ne.jx, vzp + ne.jz); // m = 1 kg
        let l = m.p.length_m;
        assert!((vxp1 - l * ne.omega_after * c).abs() < 1e-12);
        assert!((vzp1 + l * ne.omega_after * s - m.plate(0.01).1).abs() < 1e-12);
    }
}
