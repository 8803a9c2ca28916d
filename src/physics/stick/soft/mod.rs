//! Regularised (soft) contact for the stick: the plate pushes on C with a stiff spring
//! and damper when C is below it, and friction is Coulomb's law smoothed over a
//! slip-velocity scale. The rod stays massless, so its moment balance about P (C.8) is
//! solved for `theta'` at every right-hand side. An [`OdeSystem`] with `N = 5`.
//!
//! State `y = (x_p, d, x_p', z_p', theta)` (m, m, m/s, m/s, rad) with `d = z_c - z_s` the
//! height of C over the plate (negative: penetration), so that the error control sees
//! the penetration itself, not a small difference of large heights. With
//! `s, c = sin, cos theta`, C's velocity is `x_c' = x_p' - L c theta'`,
//! `d' = z_p' + L s theta' - z_s'` (C.3) and, for `d < 0`,
//!
//! ```text
//! F_z = max(0, -k_n d - r c_n d')               (spring and damper, never pulling)
//! F_x = -mu F_z tanh(x_c' / v_eps)              (Coulomb, smoothed)
//! 0   = k (theta - theta_0) + gamma theta' + L (F_x c - F_z s)        (C.8)
//! ```
//!
//! with the damper ramped in over a small penetration, `r = min(1, -d / delta_r)`, so
//! that the force is continuous in the state at first contact.
//!
//! Both forces depend on `theta'`, so C.8 is a scalar equation `g(theta') = 0`; `g` is
//! linear and increasing where `F_z = 0` (above the rate where the damper would pull)
//! and tends to `-infinity` for `theta' -> -infinity` (for `s > 0`), so a root exists.
//! It is found by bracketing from the free rate `-k (theta - theta_0) / gamma`, splitting
//! the bracket at the rates where `g` changes character (zero slip, `+-3 v_eps`, the
//! damper unloading the foot) and a safeguarded Newton iteration (`rtsafe`). In the
//! self-locking range a slide towards -x can make `g` non-monotone (the soft form of the
//! Painleve case); the root taken is then one inside the first bracket that the search
//! from the free rate meets.
//!
//! The regularisation is one parameter `eps` (dimensionless) with a time scale `tau_0`
//! (a thirtieth of the drive period) and a speed `v_0` = 1 m/s:
//!
//! ```text
//! k_n     = m / (eps tau_0^2)          normal stiffness (N/m)
//! c_n     = m / (eps tau_0)            normal damping (N s/m)
//! v_eps   = v_0 eps^2                  slip-velocity scale of the friction (m/s)
//! delta_r = 0.1 g eps tau_0^2          damper ramp, a tenth of the static penetration (m)
//! ```
//!
//! **Expected rate: first order in `eps`.** The normal law's errors are all linear in
//! `eps`: the contact's damping time `m / c_n = eps tau_0`, its rebound
//! `e ~ k_n m / c_n^2 = eps` (overdamped, `zeta = 1/(2 sqrt eps)`), the static
//! penetration `m g / k_n = eps g tau_0^2`; its slow mode `c_n / k_n = tau_0` does not
//! shrink but only relaxes a penetration that does. Measured with the friction
//! smoothing made negligible (`v_eps` = 1e-6 m/s) the mean speed's error halves with
//! `eps` (local orders 1.00 to 0.98 over eps = 0.1 .. 0.003125), and it is the
//! stiffness that carries it (halving `k_n` alone moves the speed as much as halving
//! `k_n`, `c_n`, `delta_r` together). The smoothed friction errs more slowly: a
//! sticking foot creeps at `v_eps atanh(|F_x| / (mu F_z))` (O(v_eps), with a log near
//! the onset of slip), and at the onset, where the needed friction crosses `mu F_z` at
//! some rate `beta` (N/s), the slip starts inside a layer of duration
//! `~ sqrt(M v_eps / beta)` (M the foot's effective inertia: inertia `M u'` balances
//! the friction deficit `beta s` at slip speed `u ~ v_eps` after a time `s`), so the
//! slip runs shifted by O(sqrt v_eps). Measured with the normal law made stiff
//! (eps = 1e-5 for `k_n`, `c_n`, `delta_r`), the friction's error falls with local
//! orders 0.33, 0.55, 0.66, 0.74, 0.80 in `v_eps` from 5e-4 to 1.6e-5 m/s. With
//! `v_eps` linear in `eps` (this model's first family, `v_eps = 0.1 eps` m/s) that
//! term dominated and the family converged at an apparent order near 0.7; with
//! `v_eps = v_0 eps^2` it is O(eps) at worst, so the sum is first order in `eps`.
//! (The Python port of this model in `benches/peers/` follows these four formulas.)

pub mod run;

use super::{StickModel, StickParams};
use crate::numerics::ode::OdeSystem;

/// Iterations of the root search of C.8 at most: bisection alone halves the bracket
/// (at most ~2^8 wide from the bracket search) to 1e-15 in about 60 steps.
pub const MAX_ROOT_ITERATIONS: u32 = 200;

/// The soft-contact constants (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoftParams {
    /// Normal stiffness k_n (N/m).
    pub stiffness_n_per_m: f64,
    /// Normal damping c_n (N s/m).
    pub damping_ns_per_m: f64,
    /// Slip-velocity scale of the smoothed friction v_eps (m/s).
    pub slip_scale_mps: f64,
    /// Penetration over which the damper is ramped in, `delta_r` (m): the force is
    /// then continuous in the state at first contact (a jump of `c_n d'` there makes
    /// the Rosenbrock method's linearisation useless across it).
    pub damping_ramp_m: f64,
}

impl SoftParams {
    /// The one-parameter family of the module doc: `eps` (1) with `tau_0` = a thirtieth
    /// of the drive period and `v_0` = 1 m/s (`v_eps` = 0.01 m/s at eps = 0.1).
    pub(crate) fn regularised(p: &StickParams, eps: f64) -> Self {
        let tau0 = p.period_s() / 30.0;
        let m = p.mass_kg;
        SoftParams {
            stiffness_n_per_m: m / (eps * tau0 * tau0), // formula: k_n = m / (eps tau_0^2)
            damping_ns_per_m: m / (eps * tau0),         // formula: c_n = m / (eps tau_0)
            slip_scale_mps: SLIP_SPEED_MPS * eps * eps, // formula: v_eps = v_0 eps^2
            // a tenth of the static penetration m g / k_n: at rest the damper is full
            damping_ramp_m: 0.1 * p.g_mps2 * eps * tau0 * tau0, // formula: delta_r = 0.1 m g / k_n
        }
    }

    /// The model's first family, `v_eps = 0.1 eps` m/s (otherwise as
    /// [`SoftParams::regularised`]): its friction error, O(sqrt v_eps) at worst, is then
    /// not first order in `eps` (apparent order near 0.7 measured). Kept as the wrong
    /// variant that the chapter's order claim must reject.
    pub(crate) fn regularised_linear_slip(p: &StickParams, eps: f64) -> Self {
        SoftParams {
            slip_scale_mps: 0.1 * eps, // formula: v_eps = 0.1 eps (m/s)
            ..Self::regularised(p, eps)
        }
    }
}

/// `v_0` (m/s): the speed of the friction smoothing `v_eps = v_0 eps^2`.
pub const SLIP_SPEED_MPS: f64 = 1.0;

/// The stick with soft contact, an [`OdeSystem`] of dimension 5.
#[derive(Debug, Clone, Copy)]
pub struct SoftStick {
    /// The stick.
    pub model: StickModel,
    /// The contact constants.
    pub soft: SoftParams,
}

/// State index: x of P (m).
pub const SX: usize = 0;
/// State index: height of C over the plate, `d = z_c - z_s` (m).
pub const SD: usize = 1;
/// State index: x velocity of P (m/s).
pub const SVX: usize = 2;
/// State index: z velocity of P (m/s).
pub const SVZ: usize = 3;
/// State index: theta (rad).
pub const STH: usize = 4;

/// The rod's rate and the contact force at one state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoftForces {
    /// theta' (rad/s), the root of C.8.
    pub theta_dot: f64,
    /// Horizontal force on C (N).
    pub fx: f64,
    /// Vertical force on C (N).
    pub fz: f64,
    /// Evaluations of the balance `g` spent.
    pub iterations: u32,
}

impl SoftStick {
    /// The soft stick of `p` with regularisation `eps`.
    pub fn new(p: StickParams, eps: f64) -> Self {
        SoftStick {
            model: StickModel::new(p),
            soft: SoftParams::regularised(&p, eps),
        }
    }

    /// The state of the stick standing still on the plate at `t` at angle `theta`, C at
    /// `x = 0` and exactly on the plate.
    pub fn at_rest(&self, t: f64, theta: f64) -> [f64; 5] {
        let (_, vs, _) = self.model.plate(t);
        [self.model.p.length_m * theta.sin(), 0.0, 0.0, vs, theta]
    }

    /// x of C (m).
    pub fn x_c(&self, y: &[f64; 5]) -> f64 {
        y[SX] - self.model.p.length_m * y[STH].sin() // formula: C.1 x_c = x_p - L sin
    }

    /// The forces of the contact law at rod rate `w`: `(F_x, F_z)` (N).
    #[inline]
    fn forces_at(&self, y: &[f64; 5], vs: f64, (s, c): (f64, f64), w: f64) -> (f64, f64) {
        let (l, sp) = (self.model.p.length_m, &self.soft);
        if y[SD] >= 0.0 {
            // Above the plate no force: neither the spring nor the damper acts in flight
            // (a damper there would hand the approaching foot an impulse c_n |d'| eps tau_0
            // = m |d'| that does not vanish with eps).
            return (0.0, 0.0);
        }
        let d_dot = y[SVZ] + l * s * w - vs; // formula: d' = z_p' + L s theta' - z_s'
        let ramp = (-y[SD] / sp.damping_ramp_m).clamp(0.0, 1.0); // formula: r = clamp(-d / delta_r, 0, 1)
        let fz = (-sp.stiffness_n_per_m * y[SD] - ramp * sp.damping_ns_per_m * d_dot).max(0.0); // formula: F_z = max(0, -k_n d - r c_n d')
        let vxc = y[SVX] - l * c * w; // formula: x_c' = x_p' - L c theta'
        let fx = -self.model.p.mu * fz * (vxc / sp.slip_scale_mps).tanh(); // formula: F_x = -mu F_z tanh(x_c'/v_eps)
        (fx, fz)
    }

    /// The balance `g(w) = k (theta - theta_0) + gamma w + L (F_x c - F_z s)` (C.8)
    /// and its derivative in `w` (N m, N m s).
    #[inline]
    pub(crate) fn balance(&self, y: &[f64; 5], vs: f64, (s, c): (f64, f64), w: f64) -> (f64, f64) {
        let p = &self.model.p;
        let (l, sp) = (p.length_m, &self.soft);
        let (fx, fz) = self.forces_at(y, vs, (s, c), w);
        let q = p.stiffness_nm_per_rad * (y[STH] - p.theta0_rad) + p.damping_nms_per_rad * w;
        let g = q + l * (fx * c - fz * s); // formula: C.8
        let dfz = if fz > 0.0 {
            -(-y[SD] / sp.damping_ramp_m).clamp(0.0, 1.0) * sp.damping_ns_per_m * l * s
        } else {
            0.0
        };
        let u = (y[SVX] - l * c * w) / sp.slip_scale_mps;
        let th = u.tanh();
        let dfx = -p.mu * (dfz * th + fz * (1.0 - th * th) * (-l * c / sp.slip_scale_mps));
        (g, p.damping_nms_per_rad + l * (dfx * c - dfz * s))
    }

    /// Rates where the balance `g` changes character (rad/s): zero slip speed of C and
    /// `+-3 v_eps` around it, and the rate where the damper unloads the foot (NaN when
    /// there is none).
    fn split_points(&self, y: &[f64; 5], vs: f64, (s, c): (f64, f64)) -> [f64; 4] {
        let (l, sp) = (self.model.p.length_m, &self.soft);
        let lc = l * c;
        let w0 = y[SVX] / lc; // formula: x_c' = x_p' - L c w = 0
        let dw = 3.0 * sp.slip_scale_mps / lc; // formula: x_c' = -+3 v_eps
        let ramp = (-y[SD] / sp.damping_ramp_m).clamp(0.0, 1.0);
        let wk = if s > 0.0 && ramp > 0.0 {
            let dd_k = -sp.stiffness_n_per_m * y[SD] / (ramp * sp.damping_ns_per_m); // formula: d'_k = -k_n d / (r c_n)
            (dd_k - y[SVZ] + vs) / (l * s) // formula: d' = z_p' + L s w - z_s'
        } else {
            f64::NAN
        };
        [w0, w0 - dw, w0 + dw, wk]
    }

    /// The rod's rate and the contact force at `(t, y)`.
    pub fn forces(&self, t: f64, y: &[f64; 5]) -> SoftForces {
        let p = &self.model.p;
        let (_, vs, _) = self.model.plate(t);
        let sc = y[STH].sin_cos();
        let free = -p.stiffness_nm_per_rad * (y[STH] - p.theta0_rad) / p.damping_nms_per_rad; // formula: C.3 theta' = -(k/gamma)(theta - theta_0)
        let done = |w: f64, iterations| {
            let (fx, fz) = self.forces_at(y, vs, sc, w);
            SoftForces {
                theta_dot: w,
                fx,
                fz,
                iterations,
            }
        };
        if y[SD] >= 0.0 {
            return done(free, 0);
        }
        let (g0, _) = self.balance(y, vs, sc, free);
        if g0 == 0.0 {
            return done(free, 1);
        }
        let (a, b, ga_neg, n) = match self.bracket(y, vs, sc, (free, g0)) {
            Ok(bracket) => bracket,
            Err((w, n)) => return done(w, n),
        };
        let (w, n) = self.safeguarded_newton(y, vs, sc, (a, b, ga_neg), n);
        done(w, n)
    }

    /// A bracket `[a, b]` of the balance's root in the rod rate w, found from the free
    /// rate `free` (where the balance is `g0`): `Ok((a, b, g(a) < 0, evaluations))`, or
    /// `Err((w, evaluations))` when a root was hit exactly or no bracket was found in
    /// 200 doublings (then w is the free rate).
    #[allow(clippy::type_complexity)]
    fn bracket(
        &self,
        y: &[f64; 5],
        vs: f64,
        sc: (f64, f64),
        (free, g0): (f64, f64),
    ) -> std::result::Result<(f64, f64, bool, u32), (f64, u32)> {
        // Bracket: step away from the free rate (downwards when g > 0) doubling the step.
        let dir = if g0 > 0.0 { -1.0 } else { 1.0 };
        let mut step = free.abs().max(1.0);
        let (mut a, mut b) = (free, free + dir * step);
        let mut n = 1;
        while self.balance(y, vs, sc, b).0.signum() == g0.signum() {
            a = b;
            step *= 2.0;
            b = free + dir * step;
            n += 1;
            if n > 200 {
                return Err((free, n));
            }
        }
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        let ga_neg = self.balance(y, vs, sc, a).0 < 0.0;
        // Split the bracket first at the rates where g changes character, so that Newton
        // starts on one smooth piece: where the foot's slip speed is 0 and +-3 v_eps
        // (the friction's tanh from -0.995 to 0.995 lies between), and where the damper
        // unloads the foot (-k_n d - r c_n d' = 0; for s > 0, F_z = 0 beyond it and g has
        // the rod's slope gamma only). A sticking foot's root then lies in a bracket
        // 3 v_eps / (L cos theta) wide instead of one bisected down from ~1 rad/s: the
        // balance evaluations per right-hand side in contact fell from 27-34 to 18-20 on
        // the self-locking scene (eps = 0.0125 and 0.00078, 2 periods, rtol 1e-10).
        for wc in self.split_points(y, vs, sc) {
            if wc > a && wc < b {
                let (gc, _) = self.balance(y, vs, sc, wc);
                n += 1;
                if gc == 0.0 {
                    return Err((wc, n));
                }
                if (gc < 0.0) == ga_neg {
                    a = wc;
                } else {
                    b = wc;
                }
            }
        }
        Ok((a, b, ga_neg, n))
    }

    /// The balance's root in `[a, b]` (`ga_neg`: g(a) < 0), after `n` evaluations:
    /// `(w, evaluations)`.
    fn safeguarded_newton(
        &self,
        y: &[f64; 5],
        vs: f64,
        sc: (f64, f64),
        (mut a, mut b, ga_neg): (f64, f64, bool),
        mut n: u32,
    ) -> (f64, u32) {
        // Safeguarded Newton on [a, b]: a Newton step is taken only when it stays inside
        // the bracket and is at most half the step before last (Numerical Recipes'
        // `rtsafe` rule), otherwise the bracket is bisected. Without the second
        // condition, Newton steps from the flat branch (F_z = 0, slope gamma) and back
        // ping-ponged inside the bracket for all 100 iterations, so the returned rate
        // was off the root by up to 2e-4 rad/s from one evaluation to the next: a
        // right-hand side with noise that stalled the error control at tight rtol.
        let mut w = 0.5 * (a + b);
        let (mut dx, mut dx_old) = (b - a, b - a);
        for _ in 0..MAX_ROOT_ITERATIONS {
            let (g, dg) = self.balance(y, vs, sc, w);
            n += 1;
            if g == 0.0 {
                break;
            }
            if (g < 0.0) == ga_neg {
                a = w;
            } else {
                b = w;
            }
            let newton = w - g / dg; // formula: Newton step on C.8
            let use_newton =
                dg != 0.0 && newton > a && newton < b && (newton - w).abs() <= 0.5 * dx_old.abs();
            dx_old = dx;
            let next = if use_newton { newton } else { 0.5 * (a + b) };
            dx = next - w;
            let tiny = 1e-15 * w.abs().max(1.0);
            w = next;
            if dx.abs() <= tiny || b - a <= tiny {
                break;
            }
        }
        (w, n)
    }
}

impl OdeSystem<5> for SoftStick {
    fn rhs(&self, t: f64, y: &[f64; 5]) -> [f64; 5] {
        let p = &self.model.p;
        let f = self.forces(t, y);
        let (_, vs, _) = self.model.plate(t);
        let s = y[STH].sin();
        [
            y[SVX],
            y[SVZ] + p.length_m * s * f.theta_dot - vs, // formula: d' = z_p' + L s theta' - z_s'
            f.fx * self.model.inv_mass,                 // formula: m x_p'' = F_x
            f.fz * self.model.inv_mass - p.g_mps2,      // formula: m z_p'' = F_z - m g
            f.theta_dot,
        ]
    }
}

#[cfg(test)]
mod tests;
