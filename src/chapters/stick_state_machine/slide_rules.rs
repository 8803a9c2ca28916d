//! Claims on Algorithms 3 and 4 (SLIDE RIGHT, SLIDE LEFT) under the one reading the
//! document and the authors' code support: the algorithm runs when an inequality of the
//! slide is violated (Table 1's caption: the slip stops or the normal force reaches
//! zero; `fsm.m` of toshankarghosh/toothpicks switches on the event code). The reading
//! in which the rules run at every instant is excluded and not judged.

use super::at_states::SlideExit;
use super::evidence::{keeps_cone, Ctx};
use super::statements::Statements;
use crate::physics::stick::Mode;
use crate::report::{Check, Claim};
use serde_json::json;

/// Counts at the exits of slide `mode` (slip stops) and at the lift-offs of either
/// slide, under the statements `d`.
struct SlideExits {
    /// Lift-offs at which the stated hinge test fires while C slips.
    lift_hinge: usize,
    /// Slip stops, and those at which the stated rule picks the mode taken.
    stops: usize,
    /// See `stops`.
    stop_agree: usize,
    /// Lift-offs, and those at which the stated line aborts.
    lifts: usize,
    /// See `lifts`.
    lift_abort: usize,
}

/// Algorithm 3 or 4 (slide `mode`, the other slide `other`) executed under Table 1's
/// reading at the slide's violations: its slip stops and the lift-offs of either slide
/// (the two algorithms print the same lines mirrored).
fn slide_exits(d: &Statements, c: &Ctx, mode: Mode, other: Mode) -> SlideExits {
    let hinge_ok = |e: &SlideExit| {
        let (f, mu) = (e.pivot, c.ev.params[e.scene].mu);
        d.slide_hinge_mu * mu * f.fz >= f.fx.abs()
    };
    // The reading in which the rules run at every instant of the slide is not judged:
    // Table 1's caption ("The inequalities are checked for violation. If an inequality
    // is violated, the state transitions") and the authors' event-driven fsm.m (a
    // `switch` on the exit code of the slide's event functions: STUCK, FLIGHT, FALL)
    // both exclude it; an erratum of a rejected reading would count nothing real.
    // Table 1's reading: the algorithm runs at the slide's violations (slip stop, F_z = 0)
    // lift-offs of either slide: the two algorithms print the same lines mirrored
    let ex = c.ev.at.slide_exits.iter().filter(|e| {
        if e.to == Mode::Flight {
            matches!(e.from, Mode::SlideLeft | Mode::SlideRight)
        } else {
            e.from == mode
        }
    });
    let (mut lift_hinge, mut stops, mut stop_agree, mut lifts, mut lift_abort) =
        (0usize, 0usize, 0usize, 0usize, 0usize);
    for e in ex {
        let q = &c.ev.params[e.scene];
        let slipping = e.vxc_mps.abs() > 1e-9;
        if e.to == Mode::Flight {
            lifts += 1;
            lift_hinge += usize::from(slipping && hinge_ok(e) && d.slide_hinge_while_slipping);
            let target = if d.slide_to_other { other } else { mode };
            lift_abort += usize::from(
                e.slide_fz(target) <= 1e-9 * q.mass_kg * q.g_mps2 && d.slide_abort,
            );
        } else if !slipping {
            stops += 1;
            let printed = if hinge_ok(e) {
                Mode::Pivot
            } else if d.slide_to_other {
                other
            } else {
                mode
            };
            stop_agree += usize::from(printed == e.to);
        }
    }
    SlideExits {
        lift_hinge,
        stops,
        stop_agree,
        lifts,
        lift_abort,
    }
}

/// The claims of the algorithm of slide `mode`.
pub fn alg34(d: &Statements, c: &Ctx, mode: Mode) -> Vec<Claim> {
    let (key, alg, name, other) = if mode == Mode::SlideRight {
        ("a3", "Alg. 3", "SLIDE RIGHT", Mode::SlideLeft)
    } else {
        ("a4", "Alg. 4", "SLIDE LEFT", Mode::SlideRight)
    };
    let other_name = if other == Mode::SlideLeft {
        "SLIDE LEFT"
    } else {
        "SLIDE RIGHT"
    };
    let mut v = Vec::new();
    let SlideExits {
        lift_hinge,
        stops,
        stop_agree,
        lifts,
        lift_abort,
    } = slide_exits(d, c, mode, other);
    let c_mu = d.slide_hinge_mu;
    let hinge_test_right = keeps_cone(|s| c_mu * s.0 * s.2 >= s.1.abs()); // formula: c mu F_z >= |F_x|
                                                                          // Alg. 3 and 4 print the same lines mirrored and are judged on the same lift-offs
                                                                          // (of either slide): Alg. 4's claims share Alg. 3's numbers and count once.
    let same = |c: Claim, id: &str| {
        if key == "a4" {
            c.same_finding_as(&format!("a3-{id}"))
        } else {
            c
        }
    };
    let shared = if key == "a4" {
        " The same lift-offs and numbers as Alg. 3's claim: one finding, counted once among the distinct errata."
    } else {
        ""
    };
    v.push(same(Claim::draft(Check::Simulation, &format!("{key}-hinge-while-slipping"), alg, &format!("Reading: Table 1's caption ({name} runs Alg. when an inequality is violated: the slip stops or F_z reaches 0), which the authors' fsm.m confirms (a switch on the event code: STUCK runs the hinge test, FLIGHT does not). As printed, without that dispatch, the hinge test also runs at a lift-off (F_z = 0) while C still slips, and then stops C without an impulse. Lift-offs from either slide (Alg. 3 and 4 print the same lines, mirrored) in both scenes at which the stated test fires while C slips. The correction keeps the test and runs it at slip stops only; as a test it must keep the contact at every force inside the cone and at none outside (closed form, |F_x| = s μ F_z, |s| <= 0.95 and 1.05 to 1.5): a coefficient of μ off by 10 % fails there.{shared}")).values(json!(0), json!(lift_hinge), "0").printed_or_corrected(lift_hinge == 0, hinge_test_right), "hinge-while-slipping"));
    v.push(Claim::draft(Check::Consistency, &format!("{key}-other-slide"), alg, &format!("Reading: Table 1's caption. At a slip stop of {name}: HINGE if the hinge forces are inside the cone, else {other_name} (its F_z > 0), as the authors' fsm.m does (case STUCK). Slip stops of both scenes at which the stated rule picks the mode the contact conditions took. A consistency check: the workbook's contact rules make the same choice at a slip stop (`select_contact`), so no document could fail it here.")).values(json!(stops), json!(stop_agree), "exact").printed_or_corrected(stops > 0 && stop_agree == stops, false));
    v.push(same(Claim::draft(Check::Simulation, &format!("{key}-abort"), alg, &format!("As printed ({name}): if the new slide's F_z <= 0, ABORT. The authors' fsm.m runs this line only at a slip stop (case STUCK, the other slide's F_y <= 0); a lift-off is its own event (FLIGHT). Without the dispatch, as printed, it also runs at a lift-off: there a vanishing normal force is a lift-off (FLIGHT; read as assignments, the later 'F_z = 0 -> FLIGHT' line overrides the ABORT when F_z is exactly 0). Lift-offs from either slide (the same line, mirrored; the simulation continued in flight) at which the stated line aborts.{shared}")).values(json!(0), json!(lift_abort), "0").printed_or_corrected(lifts > 0 && lift_abort == 0, lifts > 0), "abort"));
    v.push(same(
        flight_fx_claim(d, c, key, alg, name, shared),
        "flight-test",
    ));
    v
}

fn flight_fx_claim(
    d: &Statements,
    c: &Ctx,
    key: &str,
    alg: &str,
    name: &str,
    shared: &str,
) -> Claim {
    let (fx0, fz0) = c.ev.at.slide_at_mu0.unwrap_or((f64::NAN, f64::NAN));
    // F_x = sigma mu F_z is exactly 0 at mu = 0 while F_z > 0: a slide, not a lift-off
    let counter = fx0 == 0.0 && fz0 > 0.0;
    Claim::draft(Check::ClosedForm, &format!("{key}-flight-test"), alg, &format!("As printed ({name}): if F_z = 0 or F_x = 0 go to FLIGHT. F_z reaching 0 is a lift-off. F_x = 0 is not: with μ = 0 a slide has F_x = 0 and F_z > 0 throughout (the sampled slide state below, evaluated at μ = 0). The authors' code (toshankarghosh/toothpicks, Event_SlidePos.m and Event_SlideNeg.m) has two FLIGHT events in a slide, the normal force's numerator k(θ - θ₀) + γ θ' and |θ| - 1e-9, commented as the guard of the θ = 0 singularity: 'F_x = 0' is most likely that guard miscopied. Read as the guard it is a numerical escape from C.14's 1/sin(θ), not a rule of the dynamics (the workbook stops such a run as invalid instead); read as printed, a rule on F_x, it is wrong. Normal force (N) of a sampled slide state evaluated with μ = 0, where F_x = 0.{shared}")).values(json!("F_z > 0"), json!(fz0), "sign").printed_or_corrected(!(d.slide_flight_on_fx && counter), counter)
}
