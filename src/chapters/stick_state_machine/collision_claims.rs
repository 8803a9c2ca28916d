//! Claims on the collision: C.15 against the Newton-Euler impulse, its axis, and
//! section 4.4's scope (C.15 at every collision), judged on the landing states of the
//! evidence ([`super::at_states::Impact`], which Algorithm 2's claims in
//! `rule_claims.rs` read too).

use super::at_states::Impact;
use super::evidence::Ctx;
use super::rounding::{c15_rate_bound, AXIS_BOUND};
use super::statements::Statements;
use crate::physics::stick::TH;
use crate::report::{Check, Claim};
use serde_json::json;

/// C.15 against the Newton-Euler impulse; the axis of `r x v`.
pub fn c15_claims(d: &Statements, c: &Ctx) -> Vec<Claim> {
    let mut v = Vec::new();
    let states = &c.ev.at.impacts;
    let (mut worst, mut tol, mut within) = (0.0f64, f64::INFINITY, true);
    for at in states {
        let ne = at.ne;
        let ((ux, uz), (rx, rz)) = at.geometry(true);
        let l = at.length_m;
        let om = d.c15_sign * (rx * uz - rz * ux) / (l * l); // C.15: theta'+ = -(r x (v_p - zdot_s k))/L^2
        let scale = ne.omega_after.abs() + 1.0;
        // each landing against its own rounding bound (rounding.rs), reported relative
        let bound = c15_rate_bound(at); // formula: γ_16 T/L + |A^-1| (|r^| + γ_6 (|A^||x^| + |b^|))
        within &= (om - ne.omega_after).abs() <= bound;
        worst = worst.max((om - ne.omega_after).abs() / scale);
        tol = tol.min(bound / scale);
    }
    v.push(Claim::draft(Check::SecondMethod, "c15-angular-momentum", "C.15", "The collision map θ'+ = -(r_P/C x (v_p - z_s' k))/L² (lever at the landing angle) equals the rate after the impact from the Newton-Euler impulse equations (impulse along the massless rod, C stuck on the plate), solved as a linear system at every landing of both evidence runs and their mirror images. Largest |difference| / (|θ'+| + 1 rad/s); each landing is judged against its own rounding bound (the tolerance shown is the smallest, relative).").values(0.0, worst, tol).confirmed_if(!states.is_empty() && within));
    // the axis: r = (L sin, 0, L cos), u = (u_x, 0, u_z): r x u = (0, r_z u_x - r_x u_z, 0)
    let (mut off, mut n) = (0.0f64, 0usize);
    for at in states {
        let ((ux, uz), (rx, rz)) = at.geometry(true);
        let h = [0.0, rz * ux - rx * uz, 0.0];
        let a = d.c15_axis;
        let cross = [
            a[1] * h[2] - a[2] * h[1],
            a[2] * h[0] - a[0] * h[2],
            a[0] * h[1] - a[1] * h[0],
        ];
        let norm = (h[1] * h[1]).sqrt().max(1e-300);
        off = off.max(cross.iter().map(|x| x.abs()).fold(0.0, f64::max) / norm);
        n += 1;
    }
    v.push(c15_every_collision(d, states));
    v.push(Claim::draft(Check::ClosedForm, "c15-axis", "C.15", "As printed: H = ((x_p - x_c)(z_p' - z_c') - (z_p - z_c) x_p') m k, along k, the vertical. Correct: in the x-z plane r x v points along j (out of the plane): r x (v_p - z_s' k) = ((z_p - z_c) x_p' - (x_p - x_c)(z_p' - z_s')) j, so the printed bracket is the component along -j (the formula C.15 uses is right, its axis is not). |axis x (r x v)| / |r x v| at the landing states (0: parallel; its evaluation rounds relatively, so an exact 0 stays exactly 0 and the rounding bound is 0).").values(json!(0.0), json!(off), "0 (rounding bound)").printed_or_corrected(n > 0 && off <= AXIS_BOUND, n > 0));
    v
}

/// Section 4.4 applies C.15 (C stuck, the impulse along the rod) at every collision.
fn c15_every_collision(d: &Statements, states: &[Impact]) -> Claim {
    let (mut infeasible, mut routed, mut judged) = (0usize, 0usize, 0usize);
    // C.15's premise: the plate supplies the impulse that stops C, inside the cone and
    // compressive (formula: |J_x| <= mu J_z, J along the rod towards P)
    let supplied = |at: &Impact| {
        at.ne.jx.abs() <= at.mu * at.ne.jz && at.ne.along_rod(at.y[TH]) > 0.0
    };
    for at in states {
        let (ne, y) = (at.ne, at.y);
        let supplied = supplied(at);
        let sticking = y[TH].tan().abs() <= at.mu && ne.along_rod(y[TH]) > 0.0;
        if d.s44_every_collision || sticking {
            judged += 1;
            infeasible += usize::from(!supplied);
        }
        routed += usize::from(!supplied && !sticking);
    }
    let all_infeasible = states.iter().filter(|at| !supplied(at)).count();
    let printed = judged > 0 && infeasible == 0;
    // corrected: C.15 at the sticking collisions only; every other one is a collision
    // Algorithm 2 sends to its impulse-free branch (|tan θ| > μ or the rod lengthening)
    let corrected = judged > 0 && all_infeasible > 0 && routed == all_infeasible;
    Claim::draft(
        Check::SecondMethod,
        "s44-c15-every-collision",
        "4.4",
        &format!("As printed: \"A collision event happens when the stick exits the flight phase. After collision θ = θ₀ while θ' needs to be evaluated by equating the angular moment H about the point C before and after\" (C.15), for every collision. C.15's premise is an impulse that stops C, along the massless rod, which the plate can supply only inside the friction cone and compressive. Correct: C.15 holds at the sticking collisions (|tan θ| <= μ, the rod shortening); at the others Algorithm 2's impulse-free branch applies (C slides, P keeps its velocity), which section 4.4 does not mention. Evidence: the Newton-Euler impulse (a linear solve, independent of C.15) at every landing of both scenes and their mirror images: collisions{} at which the plate cannot supply it ({all_infeasible} of {}, all of them sent to the impulse-free branch by Algorithm 2's tests).", if d.s44_every_collision { "" } else { " (sticking ones, as stated)" }, states.len()),
    )
    .values(json!(0), json!(infeasible), "exact")
    .printed_or_corrected(printed, corrected)
}
