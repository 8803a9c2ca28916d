//! Claims on C.15 and on every rule of Algorithms 1 to 4. Rule-level verdicts state
//! their reading: Table 1's caption (an algorithm runs when an inequality of its phase is
//! violated, `OnViolation`) and, for Algorithms 3 and 4, the reading in which the rules
//! run at every instant (`Continuous`); each reading gets its own claim.

use super::evidence::Ctx;
use super::rounding::{c15_rate_bound, free_landing_bound, vertical_pivot_bound};
use super::evidence::{cone_exterior, cone_interior, keeps_cone};
use super::statements::{Statements, Test};
use crate::physics::stick::{Mode, TH, VXC, ZC};
use crate::report::{Check, Claim};
use serde_json::json;

/// The claims of Algorithms 1 to 4 and the phase sequence.
pub fn all(d: &Statements, c: &Ctx) -> Vec<Claim> {
    let mut v = alg1(d, c);
    v.extend(alg2_landing(d, c));
    v.extend(alg2_hinge(d, c));
    for mode in [Mode::SlideRight, Mode::SlideLeft] {
        v.extend(super::slide_rules::alg34(d, c, mode));
    }
    v.push(sequence_claim(d, c));
    v
}

/// Whether the printed test `t` fires for the forces `(fx, fz)` (N) at friction `mu`
/// (1), read to the accuracy `tol_n` (N): at a switch the state lies past the edge
/// `v = 0` by at most the event accuracy, and evaluating `v` again (exact trigonometry
/// instead of the carried one) moves it by rounding, so `v < tol_n` counts as past the
/// edge (`< 0`) and `v > tol_n` as inside it (`> 0`); `tol_n = 0` away from switches.
pub fn fires(t: &Test, mu: f64, fx: f64, fz: f64, tol_n: f64) -> bool {
    let v = t.mu_coef * mu * fz + t.fx_sign * fx; // formula: c mu F_z + s F_x
    if t.greater {
        v > tol_n
    } else {
        v < tol_n
    }
}

/// `t` with its inequality reversed (the correction of Algorithm 1's slide tests).
fn reversed(t: &Test) -> Test {
    Test {
        greater: !t.greater,
        ..*t
    }
}

/// Whether the reversed test `t` is the exit test of its cone edge on the closed-form
/// samples: it fires at none of the cone's interior, and at an exterior force exactly
/// when the force lies beyond the edge `mu F_z + fx_sign F_x = 0` (the true edge,
/// coefficient of mu 1).
fn reversed_is_exit(t: &Test) -> bool {
    let r = reversed(t);
    let inside = cone_interior()
        .iter()
        .all(|s| !fires(&r, s.0, s.1, s.2, 0.0));
    let outside = cone_exterior().iter().all(|s| {
        let beyond = s.0 * s.2 + t.fx_sign * s.1 < 0.0; // formula: mu F_z + s F_x < 0
        fires(&r, s.0, s.1, s.2, 0.0) == beyond
    });
    inside && outside
}

fn frac(a: usize, b: usize) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

fn alg1(d: &Statements, c: &Ctx) -> Vec<Claim> {
    let cone = cone_interior();
    let n = cone.len();
    let mut v = Vec::new();
    let reading = "Evidence: closed form (the cone's interior, |F_x| = s μ F_z with |s| <= 0.95, μ = 0.1 to 2, where the pivot holds and a correct exit test fires at none) and the authors' code as tie-breaker of the reading (toshankarghosh/toothpicks, Event_Hinge.m: the event functions F_y, μ F_y - F_x, μ F_y + F_x are 'positive while the constraint holds' and fsm.m switches to SLIDE_NEG, SLIDE_POS, FLIGHT when one falls through zero): the printed algorithm lost the event dispatch and copied the holding condition as the if-condition.";
    for (id, test, printed, fix) in [
        (
            "a1-slide-right-test",
            d.a1_right,
            "μ F_z + F_x > 0 -> SLIDE RIGHT",
            "μ F_z + F_x < 0 (F_x below the cone)",
        ),
        (
            "a1-slide-left-test",
            d.a1_left,
            "μ F_z - F_x > 0 -> SLIDE LEFT",
            "μ F_z - F_x < 0 (F_x above the cone)",
        ),
    ] {
        let fires = cone
            .iter()
            .filter(|s| fires(&test, s.0, s.1, s.2, 0.0))
            .count();
        let corrected = n > 0 && reversed_is_exit(&test);
        v.push(Claim::draft(Check::ClosedForm, id, "Alg. 1", &format!("As printed: if {printed}. Correct: {fix}. {reading} The correction (the stated inequality reversed, its coefficients kept) must fire at none of the interior and exactly at the forces beyond its edge (|s| = 1.05 to 1.5): a coefficient of μ off by 10 % misplaces the edge. Fraction of the cone's interior at which the stated test fires.")).values(json!(0.0), json!(frac(fires, n)), "0").printed_or_corrected(n > 0 && fires == 0, corrected));
    }
    let fires = cone
        .iter()
        .filter(|s| {
            if d.a1_flight_positive {
                s.2 > 0.0
            } else {
                s.2 < 0.0
            }
        })
        .count();
    v.push(Claim::draft(Check::ClosedForm, "a1-flight-test", "Alg. 1", &format!("As printed: if F_z > 0 -> FLIGHT. Correct: lift off when F_z < 0 (a tensile reaction), and only if the flight moves C away from the plate. {reading} Fraction of the cone's interior (F_z > 0) at which the stated test fires.")).values(json!(0.0), json!(frac(fires, n)), "0").printed_or_corrected(n > 0 && fires == 0, n > 0));
    v.push(alg1_on_violation(d, c));
    // a vertical stick at rest on a plate with Gamma = 0.5: F_z = m (g + z_s''), F_x = 0
    let (mut dev, mut fz_min, mut within) = (0.0f64, f64::INFINITY, true);
    for &(fx, fz, closed) in &c.ev.vertical_pivot {
        dev = dev.max((fz - closed).abs() + fx.abs());
        // each phase against its rounding bound (rounding.rs): 2 γ_2 (1 + γ_2) |m (g + z_s'')|
        within &= (fz - closed).abs() + fx.abs() <= vertical_pivot_bound(closed);
        fz_min = fz_min.min(fz);
    }
    let pivot_ok = within && fz_min > 0.0;
    v.push(Claim::draft(Check::ClosedForm, "a1-vertical-flight", "Alg. 1", "As printed: with |θ| = 0 (and μ F_z + F_x > 0) the HINGE goes to FLIGHT. What the line is for (the authors' code, fsm.m, HINGE, case SLIP_POS: 'if abs(th) < 1e-9 nextPhase = FLIGHT', commented 'to take care of the 1/sin(th) singularity'): a numerical escape taken at a slip exit near the vertical, where the slide's C.14 divides by sin(θ). As a rule of the dynamics, which is how the document prints it, it is wrong: a vertical stick on a plate is an ordinary pivot, F_z = m (g + z_s'') > 0 and F_x = 0 while the plate's acceleration stays below g, and a compressive contact cannot start a flight; only the slides are singular there (the workbook stops such a run as invalid, C.14). Smallest pivot normal force (N) over a cycle of a vertical stick on a plate at Γ = 0.5 (closed form and pivot equations agree within a rounding bound at every phase).").values(json!("F_z > 0: pivot"), json!(fz_min), "sign").printed_or_corrected(!d.a1_vertical_flight && pivot_ok, pivot_ok));
    let (mut fires, mut fires_fix, mut total) = (0usize, 0usize, 0usize);
    for (x, _) in c.samples().filter(|(x, _)| x.mode != Mode::Flight) {
        let (zp, zs) = (x.tip[1], x.plate.0);
        total += 1;
        fires += usize::from(if d.abort_absolute {
            x.y[ZC] < 0.0 || zp < 0.0
        } else {
            zp - zs < 0.0
        });
        fires_fix += usize::from(zp - zs < 0.0);
    }
    v.push(Claim::draft(Check::Simulation, "a1-abort-heights", "Alg. 1-4", "As printed: ABORT if z_c < 0 or z_p < 0. Correct: heights count from the plate, and z_s = δ cos(ω t) is negative half the time: the stick has fallen when z_p - z_s <= 0 (|θ| >= 90 deg). Fraction of contact samples of the (completed) evidence runs at which the stated test fires.").values(json!(0.0), json!(frac(fires, total)), "0").printed_or_corrected(total > 0 && fires == 0, total > 0 && fires_fix == 0));
    v
}

/// Algorithm 1 as a whole under Table 1's reading: executed at every pivot exit.
fn alg1_on_violation(d: &Statements, c: &Ctx) -> Claim {
    let (mut agree, mut agree_fix, mut n) = (0usize, 0usize, 0usize);
    for e in &c.ev.at.pivot_exits {
        let q = &c.ev.params[e.scene];
        let tol = 1e-9 * q.mass_kg * q.g_mps2; // the edge to the event accuracy
        let (to, f) = (e.to, e.pivot);
        let mu = q.mu;
        // the printed lines in order, each assignment overriding the last
        let mut next = None;
        if fires(&d.a1_right, mu, f.fx, f.fz, tol) {
            next = Some(Mode::SlideRight);
        }
        if fires(&d.a1_left, mu, f.fx, f.fz, tol) {
            next = Some(Mode::SlideLeft);
        }
        if if d.a1_flight_positive {
            f.fz > tol
        } else {
            f.fz < tol
        } {
            next = Some(Mode::Flight);
        }
        // corrected: slide right / left beyond the cone's edges, flight if tensile
        // and the flight lifts C
        let mut fixed = None;
        if fires(&reversed(&d.a1_right), mu, f.fx, f.fz, tol) {
            fixed = Some(Mode::SlideRight);
        }
        if fires(&reversed(&d.a1_left), mu, f.fx, f.fz, tol) {
            fixed = Some(Mode::SlideLeft);
        }
        if f.fz < tol && e.lifts {
            fixed = Some(Mode::Flight);
        }
        agree += usize::from(next == Some(to));
        agree_fix += usize::from(fixed == Some(to));
        n += 1;
    }
    Claim::draft(Check::LiteralExecution, "a1-exits", "Alg. 1, Table 1", "Reading: Table 1's caption (HINGE runs when the reaction leaves the cone or turns tensile). Algorithm 1 executed as printed, in order, the last assignment winning, at every pivot exit of both scenes: it must choose the mode the contact conditions chose. The tests are read at the switch state to the event accuracy tol = 1e-9 m g (that state lies past the edge by at most tol): v < tol counts as < 0, v > tol as > 0. As printed, at an exit through the cone's edge F_x = μ F_z the reversed slide-right test and 'F_z > 0 -> FLIGHT' both fire, and FLIGHT wins. The correction reverses the two slide tests (their coefficients kept) and lifts off only when F_z < 0 and the flight lifts C. Exits at which the printed algorithm agrees (of all exits).").values(json!(n), json!(agree), "exact").printed_or_corrected(n > 0 && agree == n, n > 0 && agree_fix == n)
}

fn alg2_landing(d: &Statements, c: &Ctx) -> Vec<Claim> {
    let states = &c.ev.at.impacts;
    let mut v = Vec::new();
    // Each located landing against its rounding budget (StickModel::penetration_budget_m:
    // the event tolerance times |h_c'|, twice the rounding of h_c), not a fixed 1e-12 m.
    let (mut hmax, mut ratio) = (0.0f64, 0.0f64);
    for r in states.iter().filter_map(|at| at.recorded) {
        hmax = hmax.max(r.landing.h_c_m.abs());
        ratio = ratio.max(r.landing.h_c_m.abs() / r.penetration_budget_m);
    }
    v.push(Claim::draft(Check::Consistency, "a2-landing", "Alg. 2", &format!("Landing when z_c - z_s = 0: located on the closed-form flight to rounding level. Largest |h_c| at located landings ({hmax:.1e} m) over its rounding budget (the event tolerance 4 ε max(t, 1) times |h_c'| plus twice the rounding of h_c).")).values(0.0, ratio, 1.0).confirmed_if(ratio <= 1.0 && c.ev.authors.hops > 0));
    let (mut dis, mut dis_fix) = (0usize, 0usize);
    for at in states {
        let ne = at.ne;
        let in_cone = ne.jx.abs() <= at.mu * ne.jz.abs();
        let th = at.y[TH];
        dis += usize::from(
            (if d.a2_tan_abs {
                th.tan().abs()
            } else {
                th.tan()
            } <= d.a2_tan_mu * at.mu)
                != in_cone,
        );
    }
    // the correction |tan(theta)| <= mu (its coefficient kept) at the landings and at
    // landing states turned to angles just inside and outside the cone's edge
    for at in states.iter().chain(&c.ev.at.edge_impacts) {
        let ne = at.ne;
        let in_cone = ne.jx.abs() <= at.mu * ne.jz.abs();
        dis_fix += usize::from((at.y[TH].tan().abs() <= d.a2_tan_mu * at.mu) != in_cone);
    }
    let n = states.len();
    v.push(Claim::draft(Check::SecondMethod, "a2-tan-test", "Alg. 2", "As printed: a sticking impact if tan(θ) <= μ. Correct: |tan(θ)| <= μ: the Newton-Euler impulse lies along the rod, |J_x|/|J_z| = |tan(θ)|. Landings of both scenes and their mirror images (the scenes lean to +x only) at which the stated test disagrees with 'the Newton-Euler impulse lies inside the cone'.").values(json!(0), json!(dis), "exact").printed_or_corrected(n > 0 && dis == 0, n > 0 && dis_fix == 0));
    v.extend(impulse_branch(d, c));
    // after the map: "x_c' <- 0 ... if x_c' > 0 SLIDE RIGHT else SLIDE LEFT"
    let sticking: Vec<_> = c
        .runs()
        .into_iter()
        .flat_map(|(r, _)| r.landings.iter())
        .filter(|l| l.sticking)
        .collect();
    let printed_left = sticking.iter().filter(|l| l.to != Mode::SlideLeft).count();
    let agree = if d.a2_dead_branch {
        printed_left == 0
    } else {
        true
    };
    v.push(Claim::draft(Check::LiteralExecution, "a2-dead-branch", "Alg. 2", "As printed: after the angular-momentum map x_c' <- 0, then if x_c' > 0 SLIDE RIGHT else SLIDE LEFT: a test of a value just set to zero, always SLIDE LEFT (and, read as assignments, it overrides the HINGE just chosen). Correct: HINGE, then Table 1's reaction test. Sticking landings of both scenes that the contact conditions send elsewhere than SLIDE LEFT (literal execution of the branch: all should be SLIDE LEFT).").values(json!(0), json!(printed_left), "exact").printed_or_corrected(!sticking.is_empty() && agree, !sticking.is_empty()));
    v.extend(free_landing(d, c));
    v
}

/// Alg. 2's branch between the angular-momentum map and the impulse-free slide, and its
/// rate, at the sticking candidates among the landing states (|tan θ| <= μ).
fn impulse_branch(d: &Statements, c: &Ctx) -> Vec<Claim> {
    let states = &c.ev.at.impacts;
    let mut v = Vec::new();
    // the impulse branch against the sign of the Newton-Euler impulse, at sticking candidates
    let (mut dis, mut dis_fix, mut dis_th, mut dis_th_fix, mut k) = (0, 0, 0, 0, 0usize);
    for at in states.iter().filter(|at| at.y[TH].tan().abs() <= at.mu) {
        let ne = at.ne;
        let compressive = ne.along_rod(at.y[TH]) > 0.0;
        let ((ux, uz), (rx, rz)) = at.geometry(d.rcp_from_c);
        let dot = ux * rx + uz * rz;
        let impulse = if d.a2_impulse_if_nonnegative {
            dot >= 0.0
        } else {
            dot < 0.0
        };
        dis += usize::from(impulse != compressive);
        let ((_, _), (fx, fz)) = at.geometry(true);
        dis_fix += usize::from((ux * fx + uz * fz < 0.0) != compressive);
        let l = at.length_m;
        let om = d.a2_theta_sign * (rx * uz - rz * ux) / (l * l);
        let om_fix = -d.a2_theta_sign * (fx * uz - fz * ux) / (l * l); // the sign of C.15 added
        let bound = c15_rate_bound(at); // formula: C.15's and the solve's rounding (rounding.rs)
        dis_th += usize::from((om - ne.omega_after).abs() > bound);
        dis_th_fix += usize::from((om_fix - ne.omega_after).abs() > bound);
        k += 1;
    }
    // The reading of r_CP is decided by the authors' code, as for the other claims of
    // Algorithm 2 (toshankarghosh/toothpicks, fsm.m, case FLIGHT, STRIKE_0): `vec_rcp =
    // [sin(th), cos(th), 0]' * L` ("POSITION VECTOR OF THE STICK CP"), i.e. from C to P;
    // `dot(vp_rel, er) < 0` with `er = [sin(th), cos(th)]` is its "CHECK FOR ROD
    // SHORTENING" and leads to the angular-momentum map `cross(vec_rcp, vec_vs - vec_vp)
    // / L^2`; the else branch ("rod not shortening") is the impulse-free slide.
    let reading = if d.rcp_from_c {
        "r_CP read from C to P, as the authors' fsm.m has it (vec_rcp = L (sin θ, cos θ), 'POSITION VECTOR OF THE STICK CP'; dot(vp_rel, er) < 0 is its 'CHECK FOR ROD SHORTENING')"
    } else {
        "r_CP read from P to C (the reading the authors' fsm.m rules out)"
    };
    v.push(Claim::draft(Check::SecondMethod, "a2-shortening-branch", "Alg. 2", &format!("As printed: if (x_p' i + (z_p' - z_s') k) . r_CP < 0 compute the hinge forces without an impulse, else (\"rod not shortening\") apply the angular-momentum map. Reading: {reading}, the tie-breaker as for the other claims. Then a product < 0 is a shortening rod, and the branches are swapped: the Newton-Euler impulse is compressive (the map applies) only when the rod shortens; fsm.m applies the map in that branch (then the hinge-force test) and slides without an impulse in the other. Sticking candidates (|tan| <= μ, both scenes and mirrors) at which the printed branch disagrees with the sign of the Newton-Euler impulse.")).values(json!(0), json!(dis), "exact").printed_or_corrected(k > 0 && dis == 0, k > 0 && dis_fix == 0));
    v.push(Claim::draft(Check::SecondMethod, "a2-theta-dot-sign", "Alg. 2", &format!("As printed: θ' = (r_CP x (v_p - v_s))/L², without the minus sign of C.15. Reading: {reading}. Then the printed rate has the wrong sign: C.15, the Newton-Euler impulse and fsm.m (`cross(vec_rcp, vec_vs - vec_vp) / L^2`, i.e. -(r_CP x (v_p - v_s))/L²) agree on the minus. Sticking candidates at which the stated θ' differs from the Newton-Euler rate by more than a rounding bound (both evaluations' running-error bound at that state).")).values(json!(0), json!(dis_th), "exact").printed_or_corrected(k > 0 && dis_th == 0, k > 0 && dis_th_fix == 0));
    v
}

/// Alg. 2's impulse-free branch (`tan(theta) > mu`).
fn free_landing(d: &Statements, c: &Ctx) -> Vec<Claim> {
    let mut v = Vec::new();
    let (mut res, mut res_fix, mut order_dis, mut n) = (0.0f64, 0.0f64, 0usize, 0usize);
    let (mut within, mut within_fix, mut tol) = (true, true, f64::INFINITY);
    for at in &c.ev.at.impacts {
        let Some(l) = at.recorded.map(|r| r.landing) else {
            continue; // a mirror image
        };
        if l.sticking || l.to == Mode::Flight {
            continue;
        }
        let q = &c.ev.params[at.scene];
        let y = at.y;
        let (vxp, vzp) = at.tip_v_mps;
        let vs = at.plate_v_mps;
        let (s, co) = y[TH].sin_cos();
        let len = q.length_m;
        let om = d.a2_free_sign * (vzp - vs) / (len * s); // theta' <- -(z_p' - z_s')/(L sin)
        let om_fix = -(vzp - vs) / (len * s);
        let xc_new = vxp + (vzp - vs) * co / s; // x_c' <- x_p' + (z_p' - z_s') cot
                                                // C.3: z_c' = z_p' + L theta' sin must equal z_s' (C on the plate)
        let bound = free_landing_bound(at); // formula: γ_8 (|z_p'| + |z_s'| + 2 |z_p' - z_s'|)
        within &= (vzp + len * om * s - vs).abs() <= bound;
        within_fix &= (vzp + len * om_fix * s - vs).abs() <= bound;
        tol = tol.min(bound);
        res = res.max((vzp + len * om * s - vs).abs());
        res_fix = res_fix.max((vzp + len * om_fix * s - vs).abs());
        let tested = if d.a2_test_before_assign {
            y[VXC]
        } else {
            xc_new
        };
        order_dis += usize::from((tested > 0.0) != (xc_new > 0.0));
        n += 1;
    }
    // each landing against its own rounding bound (rounding.rs); the smallest is shown
    v.push(Claim::draft(Check::ClosedForm, "a2-impulse-free-landing", "Alg. 2", "tan(θ) > μ: θ' <- -(z_p' - z_s')/(L sin(θ)), x_c' <- x_p' + (z_p' - z_s') cot(θ): P keeps its velocity and C moves with the plate. Largest |z_c' - z_s'| (m/s) after the stated assignment (C.3) at the impulse-free landings of both scenes, each judged against its own rounding bound (the smallest shown).").values(json!(0.0), json!(res), format!("{tol:.1e} m/s (rounding bound)")).printed_or_corrected(n > 0 && within, n > 0 && within_fix));
    v.push(Claim::draft(Check::LiteralExecution, "a2-free-landing-order", "Alg. 2", "As printed (tan(θ) > μ branch): 'if x_c' > 0 then SLIDE RIGHT, x_c' <- x_p' + (z_p' - z_s') cot(θ)': read in order, the test sees C's velocity in flight, before the assignment. Correct: assign first, then choose the slide the new x_c' points to. Impulse-free landings of both scenes at which the two orders choose different slides (literal execution; Table 1's re-selection then repairs the choice at the same instant, see the table of printed rules).").values(json!(0), json!(order_dis), "exact").printed_or_corrected(n > 0 && order_dis == 0, n > 0));
    v
}

/// Alg. 2's hinge-forces branch.
fn alg2_hinge(d: &Statements, c: &Ctx) -> Vec<Claim> {
    let ps = cone_interior();
    let n = ps.len();
    let mut v = Vec::new();
    let c_mu = d.a2_hinge_mu;
    let hinge = |s: &(f64, f64, f64), lt: bool| {
        let (mu, fx, fz) = *s;
        if lt {
            c_mu * mu * fz < fx.abs()
        } else {
            c_mu * mu * fz >= fx.abs()
        }
    };
    let keeps = ps.iter().filter(|s| hinge(s, d.a2_hinge_lt)).count();
    // the correction (the inequality reversed, its coefficient kept) keeps every force
    // inside the cone and none outside it
    let corrected = n > 0 && keeps_cone(|s| hinge(s, !d.a2_hinge_lt));
    v.push(Claim::draft(Check::ClosedForm, "a2-hinge-test", "Alg. 2", "As printed: if μ F_z < |F_x| then HINGE. Correct: HINGE when |F_x| <= μ F_z (inside the cone), as the authors' code has it (fsm.m, STRIKE_0: |F_x| < μ F_y -> HINGE; STUCK: μ F_y >= |F_x| -> HINGE). Evidence: closed form, the cone's interior (|F_x| = s μ F_z, |s| <= 0.95, μ = 0.1 to 2), not samples the simulator's own guard selected. The correction (the inequality reversed, its coefficient kept) must also choose HINGE at none of the forces outside the cone (|s| = 1.05 to 1.5): a coefficient of μ off by 10 % misplaces the edge. Fraction of the interior at which the stated test chooses HINGE (must be 1).").values(json!(1.0), json!(frac(keeps, n)), "exact").printed_or_corrected(n > 0 && keeps == n, corrected));
    // the block "if hinge then HINGE; if F_x > 0 then SLIDE LEFT else SLIDE RIGHT", executed
    let mut ends_hinge = 0usize;
    for s in &ps {
        let (mu, fx, fz) = *s;
        let h = mu * fz >= fx.abs(); // the corrected hinge test
        let mut next = None;
        if h {
            next = Some(Mode::Pivot);
        }
        let open = d.last_assert_wins || next.is_none();
        if open && (!d.a2_slide_is_else || !h) {
            next = Some(if s.1 > 0.0 {
                Mode::SlideLeft
            } else {
                Mode::SlideRight
            });
        }
        ends_hinge += usize::from(next == Some(Mode::Pivot));
    }
    v.push(Claim::draft(Check::LiteralExecution, "a2-slide-overrides-hinge", "Alg. 2", &format!("As printed: 'if μ F_z < |F_x| then HINGE end if; if F_x > 0 then SLIDE LEFT else SLIDE RIGHT': two separate ifs. Read as assignments (the last wins: {}), the slide choice overwrites HINGE every time. The authors' code decides the reading: fsm.m (STRIKE_0) has one chain, if |F_x| < μ F_y HINGE, elseif F_x > 0 SLIDE_NEG, else SLIDE_POS: the slide choice is the else branch, lost in print. The printed block executed with the corrected hinge test on the cone's interior (|F_x| = s μ F_z, |s| <= 0.95, μ = 0.1 to 2): fraction ending in HINGE (must be 1).", d.last_assert_wins)).values(json!(1.0), json!(frac(ends_hinge, n)), "exact").printed_or_corrected(n > 0 && ends_hinge == n, n > 0));
    // F_x > 0 -> SLIDE LEFT at the pivot exits of both scenes
    let (mut agree, mut exits) = (0usize, 0usize);
    for e in &c.ev.at.pivot_exits {
        let to = e.to;
        if !matches!(to, Mode::SlideLeft | Mode::SlideRight) {
            continue;
        }
        let fx = e.pivot.fx;
        let left = if d.a2_left_if_fx_positive {
            fx > 0.0
        } else {
            fx < 0.0
        };
        agree += usize::from((to == Mode::SlideLeft) == left);
        exits += 1;
    }
    v.push(Claim::draft(Check::Consistency, "a2-slide-direction", "Alg. 2", "If F_x > 0 SLIDE LEFT else SLIDE RIGHT (outside the cone): the tangential force the plate cannot supply drives C the other way; the authors' fsm.m agrees ('elseif Fx > 0 SLIDE_NEG'). Pivot exits of both scenes at which the stated rule picks the slide the simulation took. A consistency check: the workbook's contact rules (`select_contact`) apply this F_x-sign rule themselves, so no document could fail it here.").values(json!(exits), json!(agree), "exact").printed_or_corrected(exits > 0 && agree == exits, false));
    let counter = c.ev.start_fz_n < 0.0 && c.ev.start_liftoff_hdot_mps < 0.0;
    v.push(Claim::draft(Check::Simulation, "a2-tension-flight", "Alg. 2", "As printed: a tensional ground reaction (F_z <= 0) implies FLIGHT. Correct: only if the flight moves C away from the plate; the massless rod released with a loaded spring swings C down at L sin(θ) (k/γ)(θ - θ₀), and the contact goes on as a slide. Authors' start: pivot F_z < 0, and C's velocity relative to the plate in the flight that would follow (m/s).").values(json!("h_c' > 0"), json!(c.ev.start_liftoff_hdot_mps), "sign").printed_or_corrected(!(d.a2_tension_flight && counter), counter));
    v
}

/// The discrete history against the tolerance.
fn sequence_claim(d: &Statements, c: &Ctx) -> Claim {
    let ev = c.ev;
    let [r0, r1] = d.sequence_rtols;
    debug_assert_eq!(d.sequence_rtols, super::evidence::SEQUENCE_RTOLS, "the evidence's");
    let (a, b): ([String; 2], [String; 2]) = if d.sequence_located {
        (
            [ev.authors.sequence.clone(), ev.jamming.sequence.clone()],
            ev.loose_sequences.clone(),
        )
    } else {
        ev.unlocated_sequences.clone().into()
    };
    let describe = |x: &str, y: &str| match x.chars().zip(y.chars()).position(|(p, q)| p != q) {
        None if x.len() == y.len() => format!("identical ({} letters)", x.len()),
        None => format!("differ in length ({} vs {})", x.len(), y.len()),
        Some(i) => format!("differ at letter {i}"),
    };
    let comp: Vec<String> = a.iter().zip(&b).map(|(x, y)| describe(x, y)).collect();
    let same = a == b;
    Claim::draft(Check::Convergence, "phase-sequence-tolerance", "5", &format!("The state machine's phase sequence (authors' and self-locking scene, {} s) is the same at rtol {r0:e} and {r1:e}, events located on the dense output{}: they are located far below any gap between them (the discrete history has converged).", ev.duration_s, if d.sequence_located { "" } else { " (as stated: at step ends)" })).values(json!(["identical", "identical"]), json!(comp), "exact").confirmed_if(same)
}
