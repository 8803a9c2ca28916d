//! Soft contact's convergence in the regularisation `eps`: the local orders of its
//! ladder, the asymptotic range chosen from them, the order fitted there, and the two
//! claims (order, and the finest gap against its own Richardson estimate).
//!
//! The expected rate is first order in `eps` (derived in
//! [`crate::physics::stick::soft`]: every error of the normal law is linear in `eps`,
//! and the friction smoothing `v_eps = v_0 eps^2` errs by O(sqrt v_eps) = O(eps) at
//! worst).

use super::stick_methods::{fitted_order, gap_over_estimate, Ladder, SceneMethods};
use serde_json::{json, Value};

/// The order the soft family converges at (module doc of `physics::stick::soft`).
pub const SOFT_ORDER: f64 = 1.0;

/// Spread of local orders inside the asymptotic range: a rung belongs to it while the
/// local order to its finer neighbour lies within this of the finest local order. Its
/// size: past the sign change of the error (which ends the pre-asymptotic rungs of both
/// scenes) the local orders of the self-locking scene drift by 0.09 over four halvings
/// (1.05 .. 1.14); the first rung before the change differs by 0.3.
pub const RANGE_SPREAD: f64 = 0.15;

/// Signed relative error of each rung from the reference (NaN for a failed run).
fn signed(l: &Ladder, reference: f64) -> Vec<f64> {
    l.rungs
        .iter()
        .map(|r| (r.value - reference) / reference) // formula: (v - v_ref) / v_ref
        .collect()
}

/// Local orders `ln(e_i / e_(i+1)) / ln(knob_i / knob_(i+1))` of successive rungs; NaN
/// where a run failed or the error changes sign between them (no power law there).
pub fn local_orders(l: &Ladder, reference: f64) -> Vec<f64> {
    let e = signed(l, reference);
    (1..e.len())
        .map(|i| {
            let (a, b) = (e[i - 1], e[i]);
            if a.is_finite() && b.is_finite() && a * b > 0.0 {
                (a / b).ln() / (l.rungs[i - 1].setting / l.rungs[i].setting).ln() // formula: local order
            } else {
                f64::NAN
            }
        })
        .collect()
}

/// The asymptotic range: the finest rungs, extended towards coarser ones while each
/// new local order lies within [`RANGE_SPREAD`] of the finest local order (the two
/// finest rungs at least, when their local order is finite; none otherwise).
pub fn asymptotic_range(l: &Ladder, reference: f64) -> Ladder {
    let p = local_orders(l, reference);
    let n = l.rungs.len();
    let mut first = n;
    if let Some(&last) = p.last().filter(|x| x.is_finite()) {
        first = n - 2;
        while first > 0 && (p[first - 1] - last).abs() <= RANGE_SPREAD {
            first -= 1;
        }
    }
    Ladder {
        rungs: l.rungs[first..].to_vec(),
        ..l.clone()
    }
}

/// The convergence study of the soft ladder for the results: local orders (finite
/// ones), the asymptotic range, the order fitted there and the finest gap over its
/// Richardson estimate at order 1.
pub fn soft_json(s: &SceneMethods) -> Value {
    let l = s.ladder("soft_contact");
    let p = local_orders(l, s.reference_mps);
    let local: Vec<Value> = p
        .iter()
        .enumerate()
        .filter(|(_, x)| x.is_finite())
        .map(|(i, x)| json!({"eps_coarse": l.rungs[i].setting, "eps_fine": l.rungs[i + 1].setting, "order": x}))
        .collect();
    let range = asymptotic_range(l, s.reference_mps);
    let mut o = json!({ "local_orders": local, "asymptotic_range_rungs": range.rungs.len() });
    if let (Some(a), Some(b)) = (range.rungs.first(), range.rungs.last()) {
        o["asymptotic_range_eps"] = json!([a.setting, b.setting]);
    }
    let fitted = fitted_order(&range);
    if range.rungs.len() >= 3 && fitted.is_finite() {
        o["fitted_order"] = json!(fitted);
    }
    let ratio = gap_over_estimate(&range, s.reference_mps, SOFT_ORDER);
    if ratio.is_finite() {
        o["gap_over_richardson_estimate"] = json!(ratio);
    }
    o
}
