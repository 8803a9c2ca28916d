//! Falsification: every non-consistency claim re-judged under a wrong variant of the
//! document's statement (a flipped sign, a swapped inequality, a transposed rule, a
//! coefficient off by 10 %, the other reading). Each mutation must change the verdict.

use super::claims;
use super::evidence::Ctx;
use super::evidence::{collect, Evidence, EVIDENCE_RTOL};
use super::statements::{Statements, Test, PRINTED};
use crate::chapters::Context;
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::stick::run::RunSummary;
use crate::physics::stick::StickParams;
use crate::report::{Claim, DocEdit, Mutation};
use std::sync::OnceLock;

/// The quick evidence, computed once per process (the chapter's default options).
fn evidence() -> &'static (Evidence, RunSummary, StickParams) {
    static EV: OnceLock<(Evidence, RunSummary, StickParams)> = OnceLock::new();
    EV.get_or_init(|| {
        let opts = Options {
            method: Method::Dop853,
            control: StepControl::tol(EVIDENCE_RTOL, EVIDENCE_RTOL),
            ..Options::default()
        };
        let ev = collect(&Context::headless(true), &opts);
        let (main, p) = (ev.authors.clone(), ev.params[0]);
        (ev, main, p)
    })
}

/// The claim `id` judged under `d` on the quick evidence.
pub fn judge(id: &str, d: &Statements) -> Claim {
    let (ev, main, p) = evidence();
    claims::all(
        d,
        &Ctx {
            ev,
            main,
            p,
            rtol: EVIDENCE_RTOL,
        },
    )
    .into_iter()
    .find(|c| c.id == id)
    .expect("the mutated claim exists")
}

fn m(id: &'static str, what: &'static str, f: fn(&mut Statements)) -> DocEdit<Statements> {
    (id, what, f)
}

const LESS_PLUS: Test = Test {
    fx_sign: 1.0,
    greater: false,
};
const LESS_MINUS: Test = Test {
    fx_sign: -1.0,
    greater: false,
};

/// Every mutation of the chapter.
pub fn all() -> Vec<Mutation> {
    let mut edits = equation_edits();
    edits.extend(collision_edits());
    edits.extend(table1_edits());
    edits.extend(algorithm_edits());
    edits.extend(slide_algorithm_edits());
    Mutation::from_edits(PRINTED, edits, judge)
}

/// Edits of C.1 to C.15 and the sentences of section 4.
fn equation_edits() -> Vec<DocEdit<Statements>> {
    vec![
        m(
            "c3-c5-flight-closed-form",
            "C.3 rate k/gamma -> 1.1 k/gamma",
            |d| d.flight_rate = 1.1,
        ),
        m("c3-c5-flight-closed-form", "C.5 gravity g -> 0.9 g", |d| {
            d.flight_gravity = 0.9
        }),
        m(
            "c3-relaxation-flight-only",
            "C.3's third row stated for flight only",
            |d| d.c3_general = false,
        ),
        m("c6-pivot-small-motion", "C.6 spring k -> 1.1 k", |d| {
            d.c6_spring = 1.1
        }),
        m("c6-c7-c8-balance", "C.6 (g + z_s'') -> (g - z_s'')", |d| {
            d.c6_plate = -1.0
        }),
        m(
            "c6-balance-not-conservation",
            "'conservation' -> 'balance' of angular momentum",
            |d| d.c6_conservation = false,
        ),
        m(
            "c9-c14-slide-equations",
            "C.11 L(mu cos + sin) -> L(-mu cos + sin)",
            |d| d.c11_mu = -1.0,
        ),
        m(
            "c9-c14-slide-equations",
            "C.9 mu -> 1.1 mu in the denominator",
            |d| d.c9_mu = -1.1,
        ),
        m(
            "c9-c14-slide-equations",
            "C.14 -theta'^2 cos -> +theta'^2 cos",
            |d| d.c14_w2 = 1.0,
        ),
        m(
            "c10-c13-c14-x-rows",
            "C.13 x_p'' = -mu F_z/m -> +mu F_z/m",
            |d| d.c13_x = 1.0,
        ),
        m(
            "c10-c13-c14-x-rows",
            "C.10 x_p'' = mu F_z/m -> 1.1 mu F_z/m",
            |d| d.c10_x = 1.1,
        ),
        m(
            "c10-c13-c14-x-rows",
            "C.14 x_c'' row: -theta'^2 sin -> +theta'^2 sin",
            |d| d.c14_xc_w2 = 1.0,
        ),
        m("c12-blank", "C.12 printed (the derived equation)", |d| {
            d.c12_printed = true
        }),
        m(
            "s43-two-dof-mode",
            "the sentence names the sliding mode",
            |d| d.pivot_two_dof = false,
        ),
        m(
            "s43-p-moves-vertically",
            "P does not move vertically",
            |d| d.s43_p_vertical = false,
        ),
    ]
}

/// Edits of C.15 and section 4.4 (the collision).
fn collision_edits() -> Vec<DocEdit<Statements>> {
    vec![
        m(
            "c15-angular-momentum",
            "C.15 -r x v / L^2 -> +r x v / L^2",
            |d| d.c15_sign = 1.0,
        ),
        m("c15-axis", "axis k -> -j", |d| {
            d.c15_axis = [0.0, -1.0, 0.0]
        }),
        m(
            "c15-theta-reset",
            "after collision theta = theta_0 + 0.01 rad",
            |d| d.reset_offset_rad = 0.01,
        ),
        m(
            "c15-theta-reset",
            "after collision theta = 1.1 theta_0 (0.03 rad in the jamming scene, 0.043 in the authors')",
            |d| d.reset_offset_rad = 0.03,
        ),
    ]
}

/// Edits of Table 1's rows.
fn table1_edits() -> Vec<DocEdit<Statements>> {
    vec![
        m("t1-slide-left", "Sliding Left v_x < 0 -> v_x > 0", |d| {
            d.t1_left_v = 1.0
        }),
        m(
            "t1-slide-right-sign",
            "Sliding Right v_x < 0 -> v_x > 0",
            |d| d.t1_right_v = 1.0,
        ),
    ]
}

/// Edits of Algorithms 1 and 2.
fn algorithm_edits() -> Vec<DocEdit<Statements>> {
    vec![
        m("a1-slide-right-test", "mu F_z + F_x > 0 -> < 0", |d| {
            d.a1_right = LESS_PLUS
        }),
        m("a1-slide-left-test", "mu F_z - F_x > 0 -> < 0", |d| {
            d.a1_left = LESS_MINUS
        }),
        m("a1-flight-test", "F_z > 0 -> F_z < 0", |d| {
            d.a1_flight_positive = false
        }),
        m("a1-exits", "the three tests corrected", |d| {
            d.a1_right = LESS_PLUS;
            d.a1_left = LESS_MINUS;
            d.a1_flight_positive = false;
        }),
        m("a1-vertical-flight", "|theta| = 0 -> FLIGHT removed", |d| {
            d.a1_vertical_flight = false
        }),
        m("a1-abort-heights", "heights from the plate", |d| {
            d.abort_absolute = false
        }),
        m("a2-tan-test", "tan -> |tan|", |d| d.a2_tan_abs = true),
        m("a2-shortening-branch", "r_CP read from P to C", |d| {
            d.rcp_from_c = false
        }),
        m(
            "a2-shortening-branch",
            "impulse when the product is < 0",
            |d| d.a2_impulse_if_nonnegative = false,
        ),
        m(
            "a2-theta-dot-sign",
            "theta' = -r_CP x (v_p - v_s)/L^2",
            |d| d.a2_theta_sign = -1.0,
        ),
        m("a2-theta-dot-sign", "r_CP read from P to C", |d| {
            d.rcp_from_c = false
        }),
        m("a2-hinge-test", "mu F_z < |F_x| -> mu F_z >= |F_x|", |d| {
            d.a2_hinge_lt = false
        }),
        m(
            "a2-slide-overrides-hinge",
            "slide choice as the else branch",
            |d| d.a2_slide_is_else = true,
        ),
        m("a2-slide-overrides-hinge", "assert read as a return", |d| {
            d.last_assert_wins = false
        }),
        m(
            "a2-tension-flight",
            "tension -> flight only if it lifts C",
            |d| d.a2_tension_flight = false,
        ),
        m("a2-dead-branch", "the dead if/else removed", |d| {
            d.a2_dead_branch = false
        }),
        m(
            "a2-impulse-free-landing",
            "theta' <- +(z_p' - z_s')/(L sin)",
            |d| d.a2_free_sign = 1.0,
        ),
        m(
            "a2-free-landing-order",
            "assign x_c' before the test",
            |d| d.a2_test_before_assign = false,
        ),
    ]
}

/// Edits of Algorithms 3 and 4 and of the phase-sequence claim.
fn slide_algorithm_edits() -> Vec<DocEdit<Statements>> {
    vec![
        m(
            "a3-hinge-while-slipping",
            "hinge test only once the slip stopped",
            |d| d.slide_hinge_while_slipping = false,
        ),
        m(
            "a4-hinge-while-slipping",
            "hinge test only once the slip stopped",
            |d| d.slide_hinge_while_slipping = false,
        ),
        m("a3-abort", "F_z <= 0 -> FLIGHT", |d| d.slide_abort = false),
        m("a4-abort", "F_z <= 0 -> FLIGHT", |d| d.slide_abort = false),
        m("a3-flight-test", "F_x = 0 no longer a lift-off", |d| {
            d.slide_flight_on_fx = false
        }),
        m("a4-flight-test", "F_x = 0 no longer a lift-off", |d| {
            d.slide_flight_on_fx = false
        }),
        m(
            "phase-sequence-tolerance",
            "events taken at step ends (no location)",
            |d| d.sequence_located = false,
        ),
    ]
}
