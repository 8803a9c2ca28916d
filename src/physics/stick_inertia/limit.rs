//! The massless limit `m_r -> 0` as a singular perturbation (chapter 8, section 4).
//!
//! With `eps = I_P k / gamma^2` (the rod's time scale `I_P/gamma` against the massless
//! relaxation time `gamma/k`), the flight angle obeys `eps d'' + d' + d = 0` in the slow
//! time `t k/gamma`: the **outer** solution (`eps = 0`) is chapter 6's relaxation (C.3),
//! the **inner** layer after each lift-off lives on the fast time `t gamma/I_P`, where
//! theta' relaxes from its lift-off value to the outer one; it shifts the angle by
//! `O(eps)`. In contact the rod enters at `O(1/alpha) = O(m_r/M)`, also first order in
//! `m_r`. So the mean speed is `v(eps) = v_0 + c_1 eps + c_2 eps^2 + ...`.
//!
//! The full model cannot be run to `eps -> 0`: an impulse at C changes C's velocity by
//! `W P` with `W ~ alpha/M` (`alpha = M l_G^2/I_G ~ 3 M/m_r`), and the rotation it gives,
//! `-l_G (P . e_theta)/I_G`, is a difference of numbers of size `P` divided by `I_G`:
//! the impacts lose about `log10(alpha)` digits. Measured on the self-locking scene: the
//! full model follows `v_0 + c_1 eps` to 1e-10 of `v` down to `alpha = 3e8`, is off by
//! 3e-9 at `alpha = 3e10` and by a factor 2.5 at `alpha = 3e11`.
//!
//! So from `alpha >= ALPHA_SWITCH` on, the speed is the **composite**
//! `v_c(eps) = v_0(M) + (eps/eps_r) delta(eps_r)`, `delta(eps) = v(eps) - v_0(M(eps))`: the
//! outer solution (chapter 6's model with the whole mass `M = m + m_r` at P) plus the
//! first-order correction, its coefficient taken from the full model at a reference rod
//! with `alpha = ALPHA_REF` (where it is exact to rounding). Its error is
//! `c_2 eps (eps - eps_r)`, bounded for `eps <= eps_r` by `|c_2| eps_r^2 x (1 - x)`,
//! `x = eps/eps_r`, with `c_2 eps_r^2` from the second difference of `delta` at
//! `0, eps_r, 2 eps_r`.

use super::run::{run_from_rest, InertiaRun};
use super::{InertiaModel, InertiaParams};
use crate::numerics::hybrid::Options;
use crate::numerics::ode::StepControl;
use crate::physics::stick::run::{initial_state, simulate_stick, Recording};
use crate::physics::stick::{StickModel, StickParams};

/// From this mass parameter `alpha = M l_G^2/I_G` on, the run uses the composite: the
/// impacts' rounding `u alpha` (`u = 2.2e-16`) reaches 2e-7 (1).
pub const ALPHA_SWITCH: f64 = 1e9;
/// The reference rod of the composite has this `alpha` (rounding `u alpha = 2e-10`, and
/// its speed differs from chapter 6's by about `c_1 eps_r`, far above that) (1).
pub const ALPHA_REF: f64 = 1e6;

/// Does the run of `p` take the composite (a rod light enough to lose digits in its
/// impacts, with a tip mass and a damper so that chapter 6's model is the outer one)?
pub fn uses_composite(p: &InertiaParams) -> bool {
    p.rod_mass_kg > 0.0
        && p.base.mass_kg > 0.0
        && p.base.damping_nms_per_rad > 0.0
        && p.geometry().alpha() >= ALPHA_SWITCH
}

/// The massless model of the same stick (chapter 6): its whole mass at P.
pub(crate) fn massless_params(p: &InertiaParams) -> StickParams {
    let mut b = p.base;
    b.mass_kg = p.base.mass_kg + p.rod_mass_kg;
    b
}

/// Chapter 6's mean speed on the same scene (m/s), from its static angle: the outer
/// solution.
pub(crate) fn massless_speed(p: &InertiaParams, duration_s: f64, opts: &Options) -> f64 {
    let b = massless_params(p);
    let md = StickModel::new(b);
    let y0 = initial_state(&md, 0.0, b.static_angle().unwrap_or(b.theta0_rad));
    simulate_stick(&md, 0.0, y0, duration_s, opts, Recording::default()).mean_velocity_mps
}

/// The composite's result.
#[derive(Debug, Clone)]
pub struct Composite {
    /// `v_c(eps)`, the mean speed of C (m/s).
    pub mean_velocity_mps: f64,
    /// The outer solution `v_0`, chapter 6's (m/s).
    pub massless_mps: f64,
    /// Rod mass of the reference (kg), `alpha = ALPHA_REF`.
    pub reference_rod_kg: f64,
    /// `eps / eps_r` (1).
    pub x: f64,
    /// Bound on `|v(eps) - v_c(eps)|` (m/s): the truncation `|c_2| eps_r^2 x (1 - x)`
    /// plus the integration error.
    pub error_bound_mps: f64,
    /// The truncation part `|c_2| eps_r^2 x (1 - x)` (m/s).
    pub truncation_mps: f64,
    /// The integration part (m/s): `v_c` at `rtol` against `v_c` at `rtol/100`, the
    /// difference taken as the error of the `rtol` run (the tighter run's own error is
    /// 100 times smaller at the integrator's order 8 and above, and at worst as large
    /// for the rounding-limited part, hence the factor 2).
    pub integration_mps: f64,
    /// The full model's run at the reference rod.
    pub reference: InertiaRun,
}

/// The composite's parts at one tolerance: `(v_0(M), delta(eps_r), c_2 eps_r^2, the
/// reference run)`.
fn composite_parts(
    p: &InertiaParams,
    duration_s: f64,
    opts: &Options,
) -> (f64, f64, f64, InertiaRun) {
    // alpha -> 3 M/m_r for a light rod (l_G -> L, I_G -> m_r L^2/3); taken from the
    // limit, not from alpha itself, which overflows for m_r near the smallest doubles
    let m_ref = reference_rod_kg(p);
    let at = |m_r: f64| InertiaParams {
        rod_mass_kg: m_r,
        ..*p
    };
    let (p1, p2) = (at(m_ref), at(2.0 * m_ref));
    // the outer solution depends on the total mass M = m + m_r too: the correction is
    // the deviation from chapter 6's model of the same total mass
    let v0 = massless_speed(p, duration_s, opts);
    let r1 = run_from_rest(&InertiaModel::new(p1), duration_s, opts, 0.0);
    let d1 = r1.mean_velocity_mps - massless_speed(&p1, duration_s, opts); // formula: delta(eps_r) = v(eps_r) - v_0(M_r)
    let d2 = run_from_rest(&InertiaModel::new(p2), duration_s, opts, 0.0).mean_velocity_mps
        - massless_speed(&p2, duration_s, opts);
    let c2e2 = 0.5 * (d2 - 2.0 * d1); // formula: c_2 eps_r^2 = (delta(2 eps_r) - 2 delta(eps_r) + delta(0))/2, delta(0) = 0
    (v0, d1, c2e2, r1)
}

/// The reference rod (kg): `alpha(m_ref) ~ ALPHA_REF`.
fn reference_rod_kg(p: &InertiaParams) -> f64 {
    3.0 * (p.base.mass_kg + p.rod_mass_kg) / ALPHA_REF // formula: alpha(m_ref) ~ ALPHA_REF
}

/// The composite for `p` (a rod lighter than the reference) over `duration_s`, at the
/// tolerance of `opts` and, for its integration error, at a tolerance 100 times tighter
/// (100 times looser when that would go below 1e-14).
pub fn composite(p: &InertiaParams, duration_s: f64, opts: &Options) -> Composite {
    let m_ref = reference_rod_kg(p);
    // eps = I_P k/gamma^2 is proportional to m_r (I_P = m_r L^2/3): the ratio is taken
    // from the masses, which stays defined without a spring (k = 0 makes eps 0/0)
    let x = p.rod_mass_kg / m_ref; // formula: x = eps/eps_r = m_r/m_ref
    let (v0, d1, c2e2, r1) = composite_parts(p, duration_s, opts);
    // the second tolerance: 100 times tighter, or, where that is below 1e-14, 100
    // times looser (the difference then over-estimates the error: conservative)
    let mut tight = *opts;
    if let StepControl::Adaptive {
        rtol,
        atol,
        h_max_s,
    } = opts.control
    {
        let f = if rtol * 1e-2 >= 1e-14 { 1e-2 } else { 1e2 };
        tight.control = StepControl::Adaptive {
            rtol: rtol * f,
            atol: atol * f,
            h_max_s,
        };
    }
    let (v0t, d1t, _, _) = composite_parts(p, duration_s, &tight);
    let vc = v0 + x * d1; // formula: v_c = v_0(M) + (eps/eps_r) delta(eps_r)
    let truncation = c2e2.abs() * x * (1.0 - x).abs(); // formula: |c_2 eps (eps - eps_r)|
    let integration = 2.0 * (vc - (v0t + x * d1t)).abs(); // formula: 2 |v_c(rtol) - v_c(rtol/100)|
    Composite {
        mean_velocity_mps: vc,
        massless_mps: v0,
        reference_rod_kg: m_ref,
        x,
        error_bound_mps: truncation + integration,
        truncation_mps: truncation,
        integration_mps: integration,
        reference: r1,
    }
}
