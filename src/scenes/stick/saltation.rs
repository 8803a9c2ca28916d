//! The monodromy of a contact gait without differencing trajectories: the variational
//! equations `Phi' = A(t) Phi` integrated beside the stick's own state by the same hybrid
//! driver, and a saltation matrix at every mode switch.
//!
//! Coordinates `z = (theta, theta', x_c')` in every contact mode (in pivot `x_c' = 0`
//! and its row of `Phi` stays zero). `A = dz'/dz` is the Jacobian of the mode's vector
//! field at one instant, by central differences of the model's flow (an explicit
//! function: error `h^2 f'''`, about 1e-11 at h = 6e-6 of each scale), never of a
//! trajectory. At a switch from mode `-` to mode `+` on the guard `g(t, z) = 0` with the
//! reset `z+ = R(z-)`:
//!
//! `S = DR + (f+ - DR f-) grad(g)^T / (grad(g) . f- + dg/dt)`,
//!
//! where `f-` and `f+` are the vector fields before and after the switch. Every contact
//! switch the stick makes goes through the contact rules, which restart C from rest
//! (`x_c' <- 0`): `DR = diag(1, 1, 0)`. Flights and jams (impulses) are not covered:
//! the run stops with a reason, and the caller reports the method as unavailable.

use super::poincare::{scales, Point};
use crate::numerics::events::Direction;
use crate::numerics::hybrid::{simulate, HybridSystem, Options, Outcome, Transition};
use crate::numerics::trig::sin_cos;
use crate::physics::stick::{
    Mode, State, StickModel, StickStop, NSTATE, OM, ROD_X, ROD_Z, TH, VXC,
};
use nalgebra::{DMatrix, Matrix3, RowVector3, Vector3};

/// Size of the augmented state: the stick's state and the 3 x 3 matrix `Phi`.
const NV: usize = NSTATE + 9;

/// The stick with its variational equations. `saltation: false` drops the saltation
/// term (only `DR` at switches): the wrong monodromy a falsification test feeds in.
pub struct Variational<'a> {
    /// The stick.
    pub model: &'a StickModel,
    /// Apply the saltation matrices (true) or only the resets' Jacobians (false).
    pub saltation: bool,
}

fn head(y: &[f64; NV]) -> State {
    let mut s = [0.0; NSTATE];
    s.copy_from_slice(&y[..NSTATE]);
    s
}

fn phi(y: &[f64; NV]) -> Matrix3<f64> {
    Matrix3::from_row_slice(&y[NSTATE..])
}

fn join(s: &State, p: &Matrix3<f64>) -> [f64; NV] {
    let mut y = [0.0; NV];
    y[..NSTATE].copy_from_slice(s);
    for r in 0..3 {
        for c in 0..3 {
            y[NSTATE + 3 * r + c] = p[(r, c)];
        }
    }
    y
}

/// `y` with `z` written in and the rod's direction made exact.
fn with_z(y: &State, z: Vector3<f64>) -> State {
    let mut y = *y;
    (y[TH], y[OM], y[VXC]) = (z[0], z[1], z[2]);
    (y[ROD_X], y[ROD_Z]) = sin_cos(y[TH]);
    y
}

fn z_of(y: &State) -> Vector3<f64> {
    Vector3::new(y[TH], y[OM], y[VXC])
}

impl Variational<'_> {
    /// Relative step of the central differences: about the cube root of eps.
    const H: f64 = 6e-6;

    fn field(&self, mode: Mode, t: f64, y: &State) -> Vector3<f64> {
        let f = self.model.flow(mode, t, &with_z(y, z_of(y)));
        Vector3::new(f[TH], f[OM], f[VXC])
    }

    /// `A = dz'/dz` at `(t, y)` in `mode`, by central differences of the flow.
    fn a(&self, mode: Mode, t: f64, y: &State) -> Matrix3<f64> {
        let sc = scales(self.model, Mode::SlideRight);
        let mut a = Matrix3::zeros();
        for (j, &scale) in sc.iter().enumerate() {
            let h = Self::H * scale;
            let dz = Vector3::ith(j, h);
            let fp = self.field(mode, t, &with_z(y, z_of(y) + dz));
            let fm = self.field(mode, t, &with_z(y, z_of(y) - dz));
            a.set_column(j, &((fp - fm) / (2.0 * h))); // formula: A_ij = df_i/dz_j
        }
        a
    }

    /// `grad(g)` over `z` and `dg/dt` of guard `i` of `mode` at `(t, y)`.
    fn guard_gradient(&self, mode: Mode, i: usize, t: f64, y: &State) -> (RowVector3<f64>, f64) {
        let m = self.model;
        let sc = scales(m, Mode::SlideRight);
        let g = |t: f64, z: Vector3<f64>| m.guard(mode, i, t, &with_z(y, z));
        let z = z_of(y);
        let mut grad = RowVector3::zeros();
        for (j, &scale) in sc.iter().enumerate() {
            let h = Self::H * scale;
            let dz = Vector3::ith(j, h);
            grad[j] = (g(t, z + dz) - g(t, z - dz)) / (2.0 * h); // formula: dg/dz_j
        }
        let ht = Self::H * m.period_s;
        let gt = (g(t + ht, z) - g(t - ht, z)) / (2.0 * ht); // formula: partial g / partial t
        (grad, gt)
    }

    // ANCHOR: jump
    /// The saltation matrix of the switch `(mode, i)` at `(t, y-)` into `(to, y+)`.
    fn jump(
        &self,
        (mode, i, to): (Mode, usize, Mode),
        t: f64,
        y: (&State, &State),
    ) -> Matrix3<f64> {
        let dr = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.0)); // formula: x_c' <- 0
        if !self.saltation {
            return dr;
        }
        let f_minus = self.field(mode, t, y.0);
        let f_plus = self.field(to, t, y.1);
        let (grad, gt) = self.guard_gradient(mode, i, t, y.0);
        let g_dot = (grad * f_minus)[0] + gt; // formula: dg/dt along the flow before the switch
        dr + (f_plus - dr * f_minus) * grad / g_dot // formula: S = DR + (f+ - DR f-) grad g^T / g'
    }
    // ANCHOR_END: jump
}

impl HybridSystem<NV> for Variational<'_> {
    type Mode = Mode;
    type Stop = StickStop;
    const GUARD_ARGS: usize = crate::physics::stick::FLOW_ARGS;

    fn flow(&self, mode: Mode, t: f64, y: &[f64; NV]) -> [f64; NV] {
        let s = head(y);
        let ds = self.model.flow(mode, t, &s);
        let dphi = self.a(mode, t, &s) * phi(y); // formula: Phi' = A Phi
        join(&ds, &dphi)
    }

    fn guard_count(&self, mode: Mode) -> usize {
        self.model.guard_count(mode)
    }

    fn guard(&self, mode: Mode, i: usize, t: f64, y: &[f64; NV]) -> f64 {
        self.model.guard(mode, i, t, &head(y))
    }

    fn direction(&self, mode: Mode, i: usize) -> Direction {
        self.model.direction(mode, i)
    }

    fn on_event(
        &self,
        mode: Mode,
        i: usize,
        t: f64,
        y: &[f64; NV],
    ) -> Transition<Mode, StickStop, NV> {
        let s = head(y);
        let covered = matches!((mode, i), (Mode::Pivot, 1 | 2)) || (mode != Mode::Pivot && i == 2);
        match self.model.on_event(mode, i, t, &s) {
            Transition::To { mode: to, state } if covered && to != Mode::Flight => {
                let sal = self.jump((mode, i, to), t, (&self.model.canonical(mode, t, &s), &state));
                Transition::To {
                    mode: to,
                    state: join(&state, &(sal * phi(y))), // formula: Phi+ = S Phi-
                }
            }
            Transition::To { mode: to, .. } => Transition::Stop(StickStop::invalid(format!(
                "switch {} -> {} (guard {i}) at t = {t:.6} s: not a contact switch the saltation method covers",
                mode.name(),
                to.name()
            ))),
            Transition::Stop(x) => Transition::Stop(x),
        }
    }

    fn max_step(&self, mode: Mode, t: f64, y: &[f64; NV]) -> f64 {
        self.model.max_step(mode, t, &head(y))
    }
}

/// The monodromy of `P^n` at the section point `x` (a contact mode) from the variational
/// equations and the saltation matrices, restricted to the mode's coordinates; the
/// reason when the method does not apply (flight at the section or in the cycle, a
/// jam, the run ending in another mode).
pub fn monodromy(
    model: &StickModel,
    opts: &Options,
    x: &Point,
    n: usize,
    saltation: bool,
) -> std::result::Result<DMatrix<f64>, String> {
    if x.mode == Mode::Flight {
        return Err("the section point is in flight".into());
    }
    let sys = Variational { model, saltation };
    let y0 = join(&super::poincare::embed(model, x), &Matrix3::identity());
    let t_end = n as f64 * model.period_s;
    let run = simulate(&sys, x.mode, 0.0, y0, t_end, opts, &mut ());
    match run.outcome {
        Outcome::Completed if run.mode_end == x.mode => {
            let p = phi(&run.y_end);
            let d = super::poincare::dim(x.mode);
            Ok(DMatrix::from_fn(d, d, |r, c| p[(r, c)]))
        }
        Outcome::Completed => Err(format!("the cycle ends in {}", run.mode_end.name())),
        Outcome::Stopped(StickStop::Invalid(why)) => Err(why.to_string()),
        o => Err(format!("{o:?}")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::stick::jamming_scene;

    #[test]
    fn the_slip_stop_saltation_is_the_closed_form_of_the_text() {
        // S = DR + (f+ - DR f-) grad g^T / g' with DR = diag(1, 1, 0) and g = -sigma x_c'
        // reduces to the identity on theta, a zero row for x_c' and one correction
        // S[1][2] = (theta''_pivot - theta''_slide) / x_c''_slide (chapter 6, section 8).
        let model = StickModel::new(jamming_scene(9.81));
        let v = Variational {
            model: &model,
            saltation: true,
        };
        let mut y = [0.0; NSTATE];
        y[TH] = 0.36;
        y[OM] = -0.4;
        let t = 0.3 * model.period_s;
        let y = model.canonical(Mode::SlideRight, t, &y);
        let s = v.jump((Mode::SlideRight, 2, Mode::Pivot), t, (&y, &y));
        let (p, sl) = (model.pivot_eval(t, &y), model.slide_eval(-1.0, t, &y));
        let expected = (p.theta_dd - sl.theta_dd) / sl.xc_dd; // formula: closed form of S_stop
        let mut closed = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.0));
        closed[(1, 2)] = expected;
        let err = (s - closed).abs().max();
        assert!(err < 1e-6 * (1.0 + expected.abs()), "{s} vs {closed}");
        assert!(expected.abs() > 1e-3, "a real correction: {expected}");
        // without the saltation term only the reset's Jacobian is left
        let bare = Variational {
            model: &model,
            saltation: false,
        };
        assert_eq!(
            bare.jump((Mode::SlideRight, 2, Mode::Pivot), t, (&y, &y)),
            Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.0))
        );
    }
}
