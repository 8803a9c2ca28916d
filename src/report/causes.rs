//! The document's errors, by cause: which erratum claims report the same error.
//!
//! Several claims can report one error of the document: an algorithm that lost its
//! event dispatch prints several wrong tests, two algorithms print the same line
//! mirrored, one ambiguous vector makes two formulas wrong. "Distinct errata" counts
//! causes, not claims: every erratum claim is listed here under the cause it reports,
//! and an erratum missing from the list counts as a cause of its own (a unit test of
//! the appendix fails on it, so a new erratum gets its line here).

use super::{ChapterReport, Verdict};
use std::collections::BTreeSet;

/// One error of the document and the erratum claims that report it.
#[derive(Debug, Clone, Copy)]
pub struct Cause {
    /// Short kebab-case key.
    pub key: &'static str,
    /// The error, in one line.
    pub what: &'static str,
    /// The ids of the claims that report it (claim ids are unique across the chapters;
    /// chapter ids are named only by the registry).
    pub claims: &'static [&'static str],
}

/// Every cause with more than one claim, and every single-claim erratum, by chapter.
pub const CAUSES: &[Cause] = &[
    Cause {
        key: "sawtooth-stroke-labels",
        what: "3.2.2 labels the slow, long stroke as the fast one (v_l > v_r, t_r > t_l)",
        claims: &["stroke-inequalities"],
    },
    Cause {
        key: "generic-drift-needs-slip",
        what: "3.2.1-3.2.2: asymmetric shaking with Coulomb friction moves the block 'generically'; it does not where the block follows the plate without slipping (an open set of parameters)",
        claims: &["locomotion-needs-slip"],
    },
    Cause {
        key: "window-ratio-not-length",
        what: "3.2.1 bounds the error of a non-integer averaging window by 't2 so much greater than t1'; the window's length in periods, (t2 - t1)/T, sets it",
        claims: &["window-length-not-ratio"],
    },
    Cause {
        key: "c3-relaxation-in-contact",
        what: "C.3 lists the flight's relaxation law among the general kinematics",
        claims: &["c3-relaxation-flight-only"],
    },
    Cause {
        key: "c6-conservation",
        what: "C.6 is called conservation of angular momentum; it is the balance about an accelerating point",
        claims: &["c6-balance-not-conservation"],
    },
    Cause {
        key: "c12-blank",
        what: "the sliding-left angle equation is not printed (after 'from Eqns. C.10, C.4, thus'; the empty C.12 stands in the sliding-right part)",
        claims: &["c12-blank"],
    },
    Cause {
        key: "s43-degrees-of-freedom",
        what: "4.3 gives the pivot two degrees of freedom (the slide has two)",
        claims: &["s43-two-dof-mode"],
    },
    Cause {
        key: "s43-p-vertical",
        what: "4.3 says P moves vertically while C slides",
        claims: &["s43-p-moves-vertically"],
    },
    Cause {
        key: "s44-c15-every-collision",
        what: "4.4 applies C.15 at every collision, also outside the friction cone",
        claims: &["s44-c15-every-collision"],
    },
    Cause {
        key: "c15-axis",
        what: "C.15 puts the angular momentum along k (it is along j)",
        claims: &["c15-axis"],
    },
    Cause {
        key: "t1-slide-right-sign",
        what: "Table 1 gives the right slide v_x < 0",
        claims: &["t1-slide-right-sign"],
    },
    Cause {
        key: "alg1-holding-conditions",
        what: "Algorithm 1 lost the event dispatch and prints the holding conditions of the pivot as its exit tests",
        claims: &[
            "a1-slide-right-test",
            "a1-slide-left-test",
            "a1-flight-test",
            "a1-exits",
        ],
    },
    Cause {
        key: "theta-zero-guard-as-rule",
        what: "the code's guard of the 1/sin(θ) singularity is printed as a rule of the dynamics (|θ| = 0 or F_x = 0 -> FLIGHT)",
        claims: &[
            "a1-vertical-flight",
            "a3-flight-test",
            "a4-flight-test",
        ],
    },
    Cause {
        key: "abort-heights",
        what: "ABORT on z_c < 0 or z_p < 0: heights count from the moving plate",
        claims: &["a1-abort-heights"],
    },
    Cause {
        key: "a2-tan-sign",
        what: "Algorithm 2 tests tan(θ) <= μ without the absolute value",
        claims: &["a2-tan-test"],
    },
    Cause {
        key: "a2-r-cp-direction",
        what: "Algorithm 2 uses r_CP in the opposite sense to C.15 (the authors' fsm.m: C to P), which swaps the shortening branch and the sign of θ'",
        claims: &["a2-shortening-branch", "a2-theta-dot-sign"],
    },
    Cause {
        key: "a2-dead-branch",
        what: "Algorithm 2 tests x_c' just after setting it to 0",
        claims: &["a2-dead-branch"],
    },
    Cause {
        key: "a2-free-landing-order",
        what: "Algorithm 2 tests x_c' before assigning it on the impulse-free branch",
        claims: &["a2-free-landing-order"],
    },
    Cause {
        key: "a2-hinge-test",
        what: "Algorithm 2's hinge test is reversed (μ F_z < |F_x|)",
        claims: &["a2-hinge-test"],
    },
    Cause {
        key: "a2-else-lost",
        what: "Algorithm 2 prints the hinge test and the slide choice as two separate ifs (the else is lost)",
        claims: &["a2-slide-overrides-hinge"],
    },
    Cause {
        key: "a2-tension-flight",
        what: "Algorithm 2 lifts off on any tensile reaction",
        claims: &["a2-tension-flight"],
    },
    Cause {
        key: "alg3-4-no-dispatch",
        what: "Algorithms 3 and 4 (the same lines mirrored) lost the event dispatch: the hinge test and the ABORT also run at a lift-off",
        claims: &[
            "a3-hinge-while-slipping",
            "a4-hinge-while-slipping",
            "a3-abort",
            "a4-abort",
        ],
    },
    Cause {
        key: "hinge-force-missing",
        what: "Algorithms 1-4 'Compute Fx and Fz in the HINGE phase', but section 4.2 gives no formula for the pivot's contact force",
        claims: &["s5-hinge-force-missing"],
    },
    Cause {
        key: "theta-reset-missing",
        what: "section 4.4 resets θ = θ₀ after a collision; Algorithm 2, which executes the collision, never does",
        claims: &["a2-theta-reset-missing"],
    },
    Cause {
        key: "table1-flight-row",
        what: "Table 1's Flight row has three entries for four columns: read as typeset it says v_x = 0",
        claims: &["t1-flight-row"],
    },
    Cause {
        key: "landing-at-lift-off",
        what: "lift-off sets z_c = z_s and Algorithm 2 lands when z_c - z_s = 0: read literally every flight lands at once",
        claims: &["a2-landing-at-once"],
    },
    Cause {
        key: "exceeds-friction-signed",
        what: "'F_x exceeds the frictional force' is printed as F_x > μ F_z; a slip needs |F_x| > μ F_z",
        claims: &["s43-exceeds-friction"],
    },
    Cause {
        key: "slip-stop-abort",
        what: "the ABORT at a slip stop fires where a flight is consistent",
        claims: &["a34-slip-stop-abort"],
    },
    Cause {
        key: "table1-caption-one-mode",
        what: "Table 1's caption promises one mode whose inequalities hold at the present values; at a pivot exit none or several do",
        claims: &["t1-caption-one-mode"],
    },
    Cause {
        key: "self-locking-edge",
        what: "C.9's slide denominator vanishes at tan θ = σ μ inside the allowed range, where no printed rule applies",
        claims: &["c9-self-locking-edge"],
    },
];

/// The cause of claim `claim` of chapter `chapter`: its key in [`CAUSES`]; else, for
/// a claim marked as sharing another's finding, that claim's cause; else the claim's
/// own `chapter/id` (a cause of its own).
pub fn cause_key(chapter: &str, claim: &str, same_as: Option<&str>) -> String {
    let listed = |id: &str| {
        CAUSES
            .iter()
            .find(|c| c.claims.contains(&id))
            .map(|c| c.key.to_string())
    };
    listed(claim)
        .or_else(|| same_as.and_then(listed))
        .or_else(|| same_as.map(|id| format!("{chapter}/{id}")))
        .unwrap_or_else(|| format!("{chapter}/{claim}"))
}

/// The distinct causes of the errata of `reports`.
pub fn causes_of(reports: &[ChapterReport]) -> BTreeSet<String> {
    reports
        .iter()
        .flat_map(|r| {
            r.claims
                .iter()
                .filter(|c| c.verdict == Verdict::Erratum)
                .map(|c| cause_key(&r.chapter, &c.id, c.same_as.as_deref()))
        })
        .collect()
}

/// Whether claim `claim` is listed under a cause.
pub fn is_listed(claim: &str) -> bool {
    CAUSES.iter().any(|c| c.claims.contains(&claim))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_are_unique_and_claims_listed_once() {
        let keys: BTreeSet<&str> = CAUSES.iter().map(|c| c.key).collect();
        assert_eq!(keys.len(), CAUSES.len());
        let claims: Vec<_> = CAUSES.iter().flat_map(|c| c.claims.iter()).collect();
        let unique: BTreeSet<_> = claims.iter().collect();
        assert_eq!(unique.len(), claims.len());
    }

    #[test]
    fn an_unlisted_claim_is_its_own_cause_and_same_as_inherits() {
        assert_eq!(cause_key("x", "y", None), "x/y");
        assert_eq!(cause_key("x", "y", Some("z")), "x/z");
        assert_eq!(
            cause_key("x", "new-claim", Some("a3-abort")),
            "alg3-4-no-dispatch"
        );
        assert_eq!(cause_key("x", "a4-abort", None), "alg3-4-no-dispatch");
    }
}
