//! Falsification: every non-consistency claim re-judged under a wrong variant of the
//! document's statement (a flipped sign, a swapped inequality, a transposed rule, a
//! coefficient off by 10 %, the other reading). Each mutation must change the verdict.
//!
//! Every claim whose statement prints a number has a mutation that moves that number
//! by 10 % (its description says "10 %"). The claims whose statement prints no number
//! (a sign, a direction, a word, a mode name, the order of two lines) are listed in
//! [`NO_PRINTED_NUMBER`] with the reason; their mutations flip the sign, the inequality
//! or the rule instead. `tests/stick_state_machine.rs` checks that every
//! non-consistency claim is in one of the two groups.

use super::claims;
use super::cycle_report;
use super::evidence::Ctx;
use super::evidence::{collect, Evidence, EVIDENCE_RTOL};
use super::limit_cycle::Analysis;
use super::statements::{Statements, Test, PRINTED};
use crate::chapters::Context;
use crate::numerics::hybrid::Options;
use crate::numerics::ode::{Method, StepControl};
use crate::physics::stick::run::RunSummary;
use crate::physics::stick::StickParams;
use crate::report::{Claim, DocEdit, Falsifiable};

/// What the mutations judge on: the quick evidence with the chapter's default options,
/// the run the claims call "this run" (the authors' scene of the evidence) and the
/// limit-cycle analyses of the two evidence scenes.
pub struct QuickEvidence {
    /// The evidence runs.
    ev: Evidence,
    /// "This run": the authors' evidence run.
    main: RunSummary,
    /// Its parameters.
    p: StickParams,
    /// The limit-cycle analyses (authors', self-locking).
    cycles: [Analysis; 2],
}

/// The chapter's document for the generic judge (`crate::report::falsify`).
pub struct Document;

impl Falsifiable for Document {
    type Statements = Statements;
    type Evidence = QuickEvidence;
    fn printed() -> Statements {
        PRINTED
    }
    fn quick_evidence() -> QuickEvidence {
        let opts = Options {
            method: Method::Dop853,
            control: StepControl::tol(EVIDENCE_RTOL, EVIDENCE_RTOL),
            ..Options::default()
        };
        let ev = collect(&Context::headless(true), &opts);
        let (main, p) = (ev.authors.clone(), ev.params[0]);
        let cycles = cycle_report::scenes(&ev);
        QuickEvidence {
            ev,
            main,
            p,
            cycles,
        }
    }
    fn claims(d: &Statements, q: &QuickEvidence) -> Vec<Claim> {
        let ctx = Ctx {
            ev: &q.ev,
            main: &q.main,
            p: &q.p,
            rtol: EVIDENCE_RTOL,
        };
        let mut all = claims::all(d, &ctx);
        all.extend(cycle_report::claims(&d.cycle, &q.cycles));
        all
    }
    const EDITS: &'static [DocEdit<Statements>] = EDITS;
    const WITHOUT_TEN_PERCENT: &'static [(&'static str, &'static str)] = WITHOUT_TEN_PERCENT;
}

/// The claims without a 10 % mutation: [`NO_PRINTED_NUMBER`] and [`COARSER_THAN_10_PERCENT`].
const WITHOUT_TEN_PERCENT: &[(&str, &str)] = &{
    let mut out = [("", ""); NO_PRINTED_NUMBER.len() + COARSER_THAN_10_PERCENT.len()];
    let mut i = 0;
    while i < out.len() {
        out[i] = if i < NO_PRINTED_NUMBER.len() {
            NO_PRINTED_NUMBER[i]
        } else {
            COARSER_THAN_10_PERCENT[i - NO_PRINTED_NUMBER.len()]
        };
        i += 1;
    }
    out
};

/// Claims of the section whose printed number a 10 % change does not move past the
/// derived tolerance, with the reason (their mutations change it by more).
pub const COARSER_THAN_10_PERCENT: &[(&str, &str)] = &[(
    "floquet-difference-order",
    "the observed order's tolerance is derived from the runs' noise carried into log2 of a ratio of differences (0.66 for the authors' unstable gait, 0.22 for the self-locking one): order 2 -> 2.2 lies inside it; the stated order is moved to 3 instead, and the claim states its tolerance",
)];

/// The non-consistency claims whose statement prints no number a 10 % change could
/// move, with the reason; their mutations flip a sign, an inequality or a rule.
pub const NO_PRINTED_NUMBER: &[(&str, &str)] = &[
    ("c6-balance-not-conservation", "a word: 'conservation' of angular momentum (flipped: 'balance')"),
    ("c12-blank", "nothing is printed: C.12 is blank (flipped: the derived equation printed)"),
    ("s43-p-moves-vertically", "a direction: P moves 'vertically' (flipped: not vertically)"),
    ("c15-axis", "a direction: the axis k (flipped: -j)"),
    ("s44-c15-every-collision", "a scope: every collision (flipped: the sticking ones only)"),
    ("t1-slide-left", "a sign: v_x < 0 (flipped: v_x > 0)"),
    ("t1-slide-right-sign", "a sign: v_x < 0 (flipped: v_x > 0)"),
    ("a1-flight-test", "a sign: F_z > 0 (flipped: F_z < 0)"),
    ("a1-vertical-flight", "an angle of 0 and a mode name: |θ| = 0 -> FLIGHT (10 % of 0 is 0; flipped: the line removed)"),
    ("a1-abort-heights", "a reference level: heights below 0 (flipped: heights from the plate)"),
    ("a2-shortening-branch", "a sign: the product < 0 (flipped: >= 0, and the reading of r_CP that fsm.m rules out)"),
    ("s43-two-dof-mode", "an integer count, 'two degrees of freedom': 10 % of a count is no count (2.2 degrees of freedom means nothing); flipped: one, the pivot's count, which would make the sentence right"),
    ("s43-exceeds-friction", "a comparison, 'exceeds the frictional force' (flipped: |F_x| exceeds it)"),
    ("s5-hinge-force-missing", "nothing is printed: no formula for the hinge force (flipped: F = m (a_P + g e_z) printed)"),
    ("a2-landing-at-once", "an equality with 0, z_c - z_s = 0 (10 % of 0 is 0; flipped: a falling zero after the start)"),
    ("a2-theta-reset-missing", "a missing line, theta <- theta_0 (flipped: the line added)"),
    ("t1-flight-row", "the place of two zeros in a table row (flipped: under F_z and F_x)"),
    ("t1-caption-one-mode", "a phrase, 'for the present values' (flipped: a moment later)"),
    ("a34-slip-stop-abort", "a mode name, ABORT (flipped: the first consistent mode)"),
    ("c9-self-locking-edge", "a missing rule (flipped: a rule printed)"),
    ("a2-dead-branch", "a test of a value just set to 0 (flipped: the branch removed)"),
    ("a2-free-landing-order", "the order of two lines (flipped: assignment first)"),
    ("a2-slide-overrides-hinge", "if versus else (flipped: the else branch, and assert read as a return)"),
    ("a2-tension-flight", "a sign: F_z <= 0 (flipped: flight only if it lifts C)"),
    ("a3-abort", "a sign: the new slide's F_z <= 0 -> ABORT (flipped: FLIGHT)"),
    ("a4-abort", "a sign: the new slide's F_z <= 0 -> ABORT (flipped: FLIGHT)"),
    ("a3-flight-test", "zeros: F_z = 0 or F_x = 0 (flipped: F_x = 0 no longer a lift-off)"),
    ("a4-flight-test", "zeros: F_z = 0 or F_x = 0 (flipped: F_x = 0 no longer a lift-off)"),
    ("phase-sequence-tolerance", "a sequence of mode names (flipped: events at step ends)"),
    ("floquet-saltation", "a method, the saltation term (flipped: left out)"),
];

const fn m(id: &'static str, what: &'static str, f: fn(&mut Statements)) -> DocEdit<Statements> {
    (id, what, f)
}

const LESS_PLUS: Test = Test {
    fx_sign: 1.0,
    greater: false,
    mu_coef: 1.0,
};
const LESS_MINUS: Test = Test {
    fx_sign: -1.0,
    greater: false,
    mu_coef: 1.0,
};

/// Every edit of the chapter's statements (a data table, by part of the document).
const EDITS: &[DocEdit<Statements>] = &[
    // Edits of C.1 to C.15 and the sentences of section 4.
        m(
            "c3-c5-flight-lagrange",
            "C.3 rate k/gamma -> 1.1 k/gamma (10 %)",
            |d| d.flight_rate = 1.1,
        ),
        m(
            "c3-c5-flight-lagrange",
            "C.5 gravity g -> 0.9 g (10 %)",
            |d| d.flight_gravity = 0.9,
        ),
        m(
            "c3-relaxation-flight-only",
            "C.3 rate k/gamma -> 1.1 k/gamma (10 %)",
            |d| d.flight_rate = 1.1,
        ),
        m(
            "c3-relaxation-flight-only",
            "C.3's third row stated for flight only",
            |d| d.c3_general = false,
        ),
        m("c6-pivot-lagrange", "C.6 spring k -> 1.1 k (10 %)", |d| {
            d.c6_spring = 1.1
        }),
        m("c6-pivot-lagrange", "C.6 (g + z_s'') -> (g - z_s'')", |d| {
            d.c6_plate = -1.0
        }),
        m(
            "s5-hinge-force-missing",
            "the hinge force F = m (a_P + g e_z) printed in section 4.2",
            |d| d.hinge_force_printed = true,
        ),
        m("c6-c7-c8-balance", "C.6 spring k -> 1.1 k (10 %)", |d| {
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
            "C.9 mu -> 1.1 mu in the denominator (10 %)",
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
            "C.10 x_p'' = mu F_z/m -> 1.1 mu F_z/m (10 %)",
            |d| d.c10_x = 1.1,
        ),
        m(
            "c10-c13-c14-x-rows",
            "C.14 x_c'' row: -theta'^2 sin -> +theta'^2 sin",
            |d| d.c14_xc_w2 = 1.0,
        ),

    // Edits of section 4.3's sentences and the blank C.12.
        m(
            "s43-two-dof-mode",
            "two degrees of freedom -> one (the pivot's count)",
            |d| d.s43_dof = 1.0,
        ),
        m(
            "s43-exceeds-friction",
            "F_x exceeds the friction -> |F_x| exceeds it",
            |d| d.s43_exceeds_abs = true,
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

    // Edits of C.15 and section 4.4 (the collision).
        m(
            "c15-angular-momentum",
            "C.15 -r x v / L^2 -> -1.1 r x v / L^2 (10 %)",
            |d| d.c15_sign = -1.1,
        ),
        m(
            "c15-angular-momentum",
            "C.15 -r x v / L^2 -> +r x v / L^2",
            |d| d.c15_sign = 1.0,
        ),
        m(
            "s44-c15-every-collision",
            "C.15 at the sticking collisions only",
            |d| d.s44_every_collision = false,
        ),
        m(
            "a2-theta-reset-missing",
            "Algorithm 2 assigns theta <- theta_0 (as section 4.4 says)",
            |d| d.a2_resets_theta = true,
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
            "after collision theta = theta_0 -> 1.1 theta_0 (10 %)",
            |d| d.reset_factor = 1.1,
        ),

    // Edits of Table 1's rows.
        m("t1-slide-left", "Sliding Left v_x < 0 -> v_x > 0", |d| {
            d.t1_left_v = 1.0
        }),
        m(
            "t1-flight-row",
            "Flight row's zeros under F_z and F_x (v_x blank)",
            |d| d.t1_flight_vx_zero = false,
        ),
        m(
            "t1-slide-right-sign",
            "Sliding Right v_x < 0 -> v_x > 0",
            |d| d.t1_right_v = 1.0,
        ),

    // Edits of Algorithm 1 and the 10 % edits of Algorithm 2.
        m(
            "a1-slide-right-test",
            "mu F_z + F_x > 0 -> 1.1 mu F_z + F_x > 0 (10 %)",
            |d| d.a1_right.mu_coef = 1.1,
        ),
        m(
            "a1-slide-left-test",
            "mu F_z - F_x > 0 -> 1.1 mu F_z - F_x > 0 (10 %)",
            |d| d.a1_left.mu_coef = 1.1,
        ),
        m("a1-exits", "mu -> 1.1 mu in both slide tests (10 %)", |d| {
            d.a1_right.mu_coef = 1.1;
            d.a1_left.mu_coef = 1.1;
        }),
        m(
            "a2-tan-test",
            "tan(theta) <= mu -> tan(theta) <= 1.1 mu (10 %)",
            |d| d.a2_tan_mu = 1.1,
        ),
        m(
            "a2-theta-dot-sign",
            "theta' = r_CP x (v_p - v_s)/L^2 -> 1.1 r_CP x (v_p - v_s)/L^2 (10 %)",
            |d| d.a2_theta_sign = 1.1,
        ),
        m(
            "a2-impulse-free-landing",
            "theta' <- -(z_p' - z_s')/(L sin) -> -1.1 (z_p' - z_s')/(L sin) (10 %)",
            |d| d.a2_free_sign = -1.1,
        ),
        m(
            "a2-hinge-test",
            "mu F_z < |F_x| -> 1.1 mu F_z < |F_x| (10 %)",
            |d| d.a2_hinge_mu = 1.1,
        ),
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

    // Edits of Algorithm 2's printed lines.
        m("a2-tan-test", "tan -> |tan|", |d| d.a2_tan_abs = true),
        m(
            "a2-landing-at-once",
            "landing at a falling zero of z_c - z_s after the start",
            |d| d.landing_equality = false,
        ),
        m(
            "a2-shortening-branch",
            "r_CP read from P to C (the reading fsm.m rules out)",
            |d| d.rcp_from_c = false,
        ),
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
        m(
            "a2-theta-dot-sign",
            "r_CP read from P to C (the reading fsm.m rules out)",
            |d| d.rcp_from_c = false,
        ),
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

    // Edits of Algorithms 3 and 4 and of the phase-sequence claim.
        m(
            "a3-hinge-while-slipping",
            "mu F_z >= |F_x| -> 1.1 mu F_z >= |F_x| (10 %)",
            |d| d.slide_hinge_mu = 1.1,
        ),
        m(
            "a4-hinge-while-slipping",
            "mu F_z >= |F_x| -> 1.1 mu F_z >= |F_x| (10 %)",
            |d| d.slide_hinge_mu = 1.1,
        ),
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
        m(
            "t1-caption-one-mode",
            "the caption judges the inequalities a moment later (accelerations)",
            |d| d.caption_present_values = false,
        ),
        m(
            "a34-slip-stop-abort",
            "ABORT at a slip stop -> the first consistent mode",
            |d| d.slip_stop_abort = false,
        ),
        m(
            "c9-self-locking-edge",
            "a rule printed for the slide at tan(theta) = sigma mu",
            |d| d.edge_rule_printed = true,
        ),
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
    // the limit-cycle section (the workbook's statements, `CycleStatements`)
    m(
        "floquet-difference-order",
        "central differences -> forward differences (still stated at order 2)",
        |d| d.cycle.central = false,
    ),
    m(
        "floquet-difference-order",
        "stated order 2 -> 3 (as if the differences were Richardson-extrapolated)",
        |d| d.cycle.order = 3.0,
    ),
    m(
        "floquet-saltation",
        "saltation matrices left out (variational flows and the resets' Jacobians only)",
        |d| d.cycle.saltation = false,
    ),
    m(
        "gait-stability",
        "stated rate |λ|max -> 1.1 |λ|max (10 %)",
        |d| d.cycle.rate_factor = 1.1,
    ),
    m(
        "gait-stability",
        "stated rate |λ|max -> 0.9 |λ|max (10 %)",
        |d| d.cycle.rate_factor = 0.9,
    ),
];
