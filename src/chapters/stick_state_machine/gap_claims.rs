//! Claims on what sections 4 and 5 leave out or leave ambiguous, found by reading them
//! sentence by sentence beside the authors' code (toshankarghosh/toothpicks): the
//! landing test that a lift-off satisfies at once, the slip condition's sign, the ABORT
//! at a slip stop, and the slides' self-locking edge.

use super::evidence::{cone_exterior, cone_interior, Ctx};
use super::statements::Statements;
use crate::physics::stick::Mode;
use crate::report::{Check, Claim};
use serde_json::json;

/// The claims of this file.
pub fn all(d: &Statements, c: &Ctx) -> Vec<Claim> {
    vec![
        landing_at_once(d, c),
        exceeds_friction(d),
        slip_stop_abort(d, c),
        caption_one_mode(d, c),
        self_locking_edge(d, c),
    ]
}

/// Alg. 1 to 4 set `z_c <- z_s` at a lift-off and Alg. 2 lands when `z_c - z_s = 0`.
fn landing_at_once(d: &Statements, c: &Ctx) -> Claim {
    // the printed lift-off's z_c <- z_s leaves h_c = 0 exactly (the workbook's takeoff
    // does the same); the printed landing test is the equality h_c = 0
    let lifts = &c.ev.liftoffs;
    let n = lifts.len();
    let at_once = lifts
        .iter()
        .filter(|(h0, _)| d.landing_equality && *h0 == 0.0)
        .count();
    let later = lifts
        .iter()
        .filter(|(_, landed_later)| *landed_later)
        .count();
    Claim::draft(Check::LiteralExecution, "a2-landing-at-once", "Alg. 1-4, Alg. 2", &format!("As printed: every lift-off sets z_c <- z_s (Alg. 1, 2, 3, 4), and Algorithm 2 lands when z_c - z_s = 0. Read literally, the landing test holds at the first instant of every flight, which then ends at once. Correct: a landing is a falling zero of h_c = z_c - z_s after the flight has begun; the authors' code says so with an offset (fsm.m: yc = ys + delta_h, delta_h = 1e-9 'to ensure that the event function for flight does not start with a negative value'; Event_Flight.m: hc = y1 - ys + 1e-9, direction -1); the workbook counts a guard that starts at 0 as above the plate. Flights of both scenes (lift-off to landing, {n}; each lasted a positive time: {later}) at whose lift-off state the printed landing test holds."))
        .values(json!(0), json!(at_once), "exact")
        .printed_or_corrected(n > 0 && at_once == 0, n > 0 && later == n)
}

/// Section 4.3: the pivot slips when "F_x exceeds the frictional force".
fn exceeds_friction(d: &Statements) -> Claim {
    let slips = |s: &(f64, f64, f64), abs: bool| {
        let (mu, fx, fz) = *s;
        if abs {
            fx.abs() > mu * fz // formula: |F_x| > mu F_z
        } else {
            fx > mu * fz // formula: F_x > mu F_z, as printed
        }
    };
    let (out, inn) = (cone_exterior(), cone_interior());
    let frac = |abs: bool| out.iter().filter(|s| slips(s, abs)).count() as f64 / out.len() as f64;
    let none_inside = |abs: bool| !inn.iter().any(|s| slips(s, abs));
    let stated = frac(d.s43_exceeds_abs);
    Claim::draft(Check::ClosedForm, "s43-exceeds-friction", "4.3", "As printed: \"In the horizontal forces Fx in the hinge mode exceeds the frictional force, the bottom of the stick looses its frictional grip and begins to slide\": F_x > μ F_z, a signed comparison. Correct: |F_x| > μ F_z; a reaction below the cone (F_x < -μ F_z) slips too (to the right; Table 1's Pivot row, |F_x| <= μ F_z, and the authors' Event_Hinge.m, μ F_y - F_x and μ F_y + F_x, have both edges). Closed form over forces outside the cone (F_z = 1 N, F_x = s μ F_z, |s| = 1.05 to 1.5, both signs, μ = 0.1 to 2): fraction at which the stated condition says the pivot slips (must be 1, and 0 inside the cone).")
        .values(json!(1.0), json!(stated), "exact")
        .printed_or_corrected(stated == 1.0 && none_inside(d.s43_exceeds_abs), frac(true) == 1.0 && none_inside(true))
}

/// Alg. 3 and 4 at a slip stop: HINGE if the hinge reaction is inside the cone, else
/// the other slide if its F_z > 0, else ABORT.
fn slip_stop_abort(d: &Statements, c: &Ctx) -> Claim {
    let (mut stops, mut aborts, mut could_go_on, mut to_flight) = (0usize, 0usize, 0usize, 0usize);
    for r in &c.ev.rest {
        for (i, sigma) in [(0usize, 1.0), (1, -1.0)] {
            let e = r.slides[i];
            // a slip stop of this slide: its normal force compressive and its slip
            // decelerating to zero (sigma x_c'' > 0: slide left has x_c' < 0)
            if !(e.fz >= 0.0 && sigma * e.xc_dd > 0.0) {
                continue;
            }
            stops += 1;
            let (h, other) = (r.pivot, r.slides[1 - i]);
            if r.mu * h.fz >= h.fx.abs() || other.fz > 0.0 {
                continue; // HINGE or the other slide: Alg. 3, 4 do not abort
            }
            aborts += 1;
            if let Some(next) = r.chosen {
                could_go_on += 1;
                to_flight += usize::from(next == Mode::Flight);
            }
        }
    }
    let printed_holds = if d.slip_stop_abort {
        could_go_on == 0
    } else {
        true
    };
    Claim::draft(Check::ClosedForm, "a34-slip-stop-abort", "Alg. 3, 4", &format!("As printed (and in the authors' fsm.m, case STUCK): at a slip stop, HINGE if μ F_z >= |F_x|, else the other slide if its F_z > 0, else ABORT. The ABORT is right only where no mode of Table 1 is consistent. Closed form over states at rest on the plate (θ = ±0.1 to ±1.2 rad, θ' = 0 to ±2 sqrt(g/L), 16 plate phases, both scenes) that are slip stops of a slide (its F_z >= 0, the slip decelerating): {stops} slip stops, {aborts} of them reach the ABORT line. Of these, the states at which a mode is consistent (the contact conditions: a slide from rest with F_z >= 0 slipping its own way, or a flight that lifts C), where ABORT stops a run that can go on ({to_flight} of them by a flight)."))
        .values(json!(0), json!(could_go_on), "exact")
        .printed_or_corrected(aborts > 0 && printed_holds, aborts > 0)
}

/// C.9 (C.11) at the slides' self-locking edge `tan(theta) = sigma mu`.
fn self_locking_edge(d: &Statements, c: &Ctx) -> Claim {
    // F_z = Q / (L (sin - sigma mu cos)) at |tan theta| = mu (1 + delta), theta' = 0: a
    // pole grows as 1/delta, a bounded force not at all (`rest_scan::edge_growth`)
    let growth = c.ev.edge_growth;
    // a pole of order one: ratio 1e3 (1/delta) up to O(delta) terms; bounded: ~1
    let unbounded = growth > 100.0;
    Claim::draft(Check::ClosedForm, "c9-self-locking-edge", "4.3, 5", &format!("As printed: a slide runs until an inequality of Table 1 is violated, and Algorithms 3 and 4 handle a slip stop, F_z reaching 0 and a fall. C.9's denominator L(sin θ - μ cos θ) (C.11's for the right slide) vanishes at tan θ = σ μ, inside the range θ in (-π/2, π/2) the document allows: there the slide's normal force grows without bound (the rod along the edge of the friction cone cannot slide), and no printed rule applies. Correct: the slide jams; the workbook stops the slip by an impulse along the rod on the cone's edge, then applies the reaction test. |F_z| at tan θ = μ (1 + 1e-6) over |F_z| at μ (1 + 1e-3), θ' = 0, both scenes (a bounded force: about 1; a pole: 1e3): {growth:.0}."))
        .values(json!("bounded"), json!(growth), "ratio <= 100: bounded")
        .printed_or_corrected(d.edge_rule_printed || !unbounded, unbounded)
}

/// Table 1's caption: "The new state is (the) one in which the inequalities are
/// satisfied for the present values of the state variables".
fn caption_one_mode(d: &Statements, c: &Ctx) -> Claim {
    let (n, mut no_row, mut several, mut none) = (c.ev.rest.len(), 0usize, 0usize, 0usize);
    for r in &c.ev.rest {
        let h = r.pivot;
        // at the present values (h_c = 0, v_x = 0) only the Pivot row can hold: the
        // slides need v_x != 0 and the flight h_c > 0
        if h.fz >= 0.0 && h.fx.abs() <= r.mu * h.fz {
            continue;
        }
        no_row += 1;
        // the modes whose inequalities hold a moment later (the slip's and the foot's
        // accelerations: `try_slide`, `takeoff`)
        let k = r.slide_ok.iter().filter(|&&ok| ok).count() + usize::from(r.flight_ok);
        several += usize::from(k > 1);
        none += usize::from(k == 0);
    }
    let printed = if d.caption_present_values {
        no_row == 0
    } else {
        true
    };
    Claim::draft(Check::ClosedForm, "t1-caption-one-mode", "Table 1", &format!("As printed (Table 1's caption): \"If an inequality is violated, the state transitions to another state. The new state is (the) one in which the inequalities are satisfied for the present values of the state variables.\" At a pivot exit C is on the plate and at rest (h_c = 0, v_x = 0): of Table 1's rows only the Pivot row can hold for these values (the slides need v_x < 0 or > 0, the flight h_c > 0), and it has just been violated. Closed form over states at rest on the plate (θ = ±0.1 to ±1.2 rad, θ' = 0 to ±2 sqrt(g/L), 16 plate phases, both scenes; {n} states): the states whose pivot reaction leaves the cone or turns tensile, where no row holds at the present values. Correct: the next mode is the one whose inequalities hold a moment later (the slip's and the foot's accelerations), and where several do (at {several} of these states) a priority is needed: the workbook takes the slide the reaction drives, then the flight, then the other slide (none holds at {none})."))
        .values(json!(0), json!(no_row), "exact")
        .printed_or_corrected(n > 0 && printed, n > 0 && no_row > 0 && none == 0)
}
