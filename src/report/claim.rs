//! One checked statement of the document: [`Claim`] (built with [`Claim::draft`]), its
//! [`Verdict`], the kind of evidence behind it ([`Check`]) and the falsification
//! [`Mutation`]s that must move it.

use serde::Serialize;
use serde_json::Value;
/// The outcome of checking one claim of the document.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// The document holds: the independent computation agrees within the tolerance.
    Confirmed,
    /// The document is wrong; the claim's statement carries the correction, and the
    /// corrected statement is what the computation confirms.
    Erratum,
    /// True only in a limit, which the statement names; the computation shows both the
    /// agreement in the limit and the departure away from it.
    Approximation,
    /// The workbook's own check broke: a regression, never a finding about the document.
    Failed,
}

impl Verdict {
    /// The lower-case name used in tables and JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Confirmed => "confirmed",
            Verdict::Erratum => "erratum",
            Verdict::Approximation => "approximation",
            Verdict::Failed => "failed",
        }
    }
}

/// The kind of evidence behind a claim's verdict (`"check"` in JSON).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Check {
    /// Compared with a closed form derived independently of the statement.
    ClosedForm,
    /// Compared with a second, independent numerical method.
    SecondMethod,
    /// Compared with a simulation of the model (the workbook's hybrid simulator).
    Simulation,
    /// Compared with the limit of a convergence study (order fits, refinement ladders).
    Convergence,
    /// The document's own rule or algorithm executed as printed.
    LiteralExecution,
    /// Holds by construction of the workbook's computation: a sanity check, never
    /// counted as confirmation of the document.
    Consistency,
}

impl Check {
    /// The snake-case name used in tables and JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            Check::ClosedForm => "closed_form",
            Check::SecondMethod => "second_method",
            Check::Simulation => "simulation",
            Check::Convergence => "convergence",
            Check::LiteralExecution => "literal_execution",
            Check::Consistency => "consistency",
        }
    }

    /// Every kind, in the order of the JSON contract.
    pub const ALL: [Check; 6] = [
        Check::ClosedForm,
        Check::SecondMethod,
        Check::Simulation,
        Check::Convergence,
        Check::LiteralExecution,
        Check::Consistency,
    ];
}

/// A wrong variant of the document's statement, fed to a claim's own check. The
/// falsification tests run it and assert that its verdict differs from the verdict
/// the claim gets under the document's statement: a claim that no mutation can move
/// holds by construction and is a [`Check::Consistency`].
pub struct Mutation {
    /// Id of the claim this mutates (as in the chapter's report).
    pub claim_id: &'static str,
    /// What was changed, e.g. `"coefficient 1/4 -> 0.275"` or `"F_z > 0 -> F_z < 0"`.
    pub description: &'static str,
    /// Runs the claim's check on the wrong statement (quick mode) and returns the claim.
    pub run: Box<dyn Fn() -> Claim + Send + Sync>,
}

/// One wrong variant of a chapter's statements: (claim id, what changed, the edit).
pub type DocEdit<D> = (&'static str, &'static str, fn(&mut D));

impl Mutation {
    /// A mutation of claim `claim_id`.
    pub fn new(
        claim_id: &'static str,
        description: &'static str,
        run: impl Fn() -> Claim + Send + Sync + 'static,
    ) -> Self {
        Mutation {
            claim_id,
            description,
            run: Box::new(run),
        }
    }
}

/// One checked statement of the document.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Claim {
    /// Short kebab-case id, unique within the chapter.
    pub id: String,
    /// Section (or equation, table, algorithm) of the document the claim comes from.
    pub section: String,
    /// What the document says; for an erratum also the correction, for an
    /// approximation also the limit in which it holds.
    pub statement: String,
    /// The value the statement predicts (number, boolean or text).
    pub expected: Value,
    /// The value the workbook computed independently.
    pub computed: Value,
    /// The allowed difference (number) or the kind of comparison (text, e.g. `"exact"`).
    pub tolerance: Value,
    /// The verdict.
    pub verdict: Verdict,
    /// The kind of evidence behind the verdict (the first argument of [`Claim::draft`]:
    /// there is no default).
    pub check: Check,
    /// Id of another claim of the same chapter whose numbers and finding this one
    /// shares (two algorithms printing the same line, judged on the same events): an
    /// erratum counted once among the distinct errata (set with
    /// [`Claim::same_finding_as`]; not in JSON, the statement says so).
    #[serde(skip)]
    pub same_as: Option<String>,
}

/// A claim being built: what the document says and the kind of evidence that will
/// judge it (required: [`Claim::draft`] takes it first), then the numbers
/// ([`ClaimDraft::values`]) and one verdict method. The only ways to finish a claim:
/// [`ClaimDraft::confirmed_if`], [`ClaimDraft::approximation_if`],
/// [`ClaimDraft::printed_or_corrected`] (the one way to make an erratum),
/// [`ClaimDraft::close`] and [`ClaimDraft::exact`].
#[derive(Debug, Clone)]
#[must_use = "a draft is not a claim until a verdict method finishes it"]
pub struct ClaimDraft {
    claim: Claim,
}

impl ClaimDraft {
    /// The value the statement predicts, the value computed independently, and the
    /// allowed difference (number) or kind of comparison (text, e.g. `"exact"`).
    pub fn values(
        mut self,
        expected: impl Into<Value>,
        computed: impl Into<Value>,
        tolerance: impl Into<Value>,
    ) -> ClaimDraft {
        self.claim.expected = finite_or_text(expected.into());
        self.claim.computed = finite_or_text(computed.into());
        self.claim.tolerance = finite_or_text(tolerance.into());
        self
    }

    /// Marks the claim as sharing its numbers and finding with claim `id` of the same
    /// chapter (see [`Claim::same_as`]).
    pub fn same_finding_as(mut self, id: &str) -> ClaimDraft {
        self.claim.same_as = Some(id.to_string());
        self
    }

    fn verdict(mut self, v: Verdict) -> Claim {
        self.claim.verdict = v;
        self.claim
    }

    /// Confirmed when the document's statement `holds` against the evidence, failed
    /// otherwise.
    pub fn confirmed_if(self, holds: bool) -> Claim {
        self.verdict(if holds {
            Verdict::Confirmed
        } else {
            Verdict::Failed
        })
    }

    /// Approximation when the statement, read with the limit it names, `holds`
    /// (agreement in the limit and the departure away from it both measured), failed
    /// otherwise.
    pub fn approximation_if(self, holds: bool) -> Claim {
        self.verdict(if holds {
            Verdict::Approximation
        } else {
            Verdict::Failed
        })
    }

    /// The one way to make an erratum: confirmed when the printed statement holds,
    /// erratum when only the correction holds, failed when neither does. Both checks
    /// are computed, so a document that printed the correction would be confirmed.
    pub fn printed_or_corrected(self, printed_holds: bool, corrected_holds: bool) -> Claim {
        self.verdict(if printed_holds {
            Verdict::Confirmed
        } else if corrected_holds {
            Verdict::Erratum
        } else {
            Verdict::Failed
        })
    }

    /// A numeric claim: confirmed when `|computed - expected| <= tolerance` (all
    /// finite), failed otherwise.
    pub fn close(self, expected: f64, computed: f64, tolerance: f64) -> Claim {
        let holds = is_close(expected, computed, tolerance);
        self.values(expected, computed, tolerance)
            .confirmed_if(holds)
    }

    /// A discrete claim (boolean, label, count): confirmed when equal, failed otherwise.
    pub fn exact<T: Into<Value> + PartialEq + Clone>(self, expected: T, computed: T) -> Claim {
        let holds = expected == computed;
        self.values(expected, computed, "exact").confirmed_if(holds)
    }
}

impl Claim {
    /// Starts a claim of the document's `statement` (`section` names where it is
    /// printed), judged by evidence of kind `check`. Finish it with a verdict method
    /// of [`ClaimDraft`]:
    ///
    /// ```
    /// use locomotion_workbook::report::{Check, Claim, Verdict};
    /// let c = Claim::draft(Check::ClosedForm, "q-ratio", "2", "J_l/J_v = q")
    ///     .close(1.0, 1.0 + 1e-12, 1e-9);
    /// assert_eq!(c.verdict, Verdict::Confirmed);
    /// ```
    pub fn draft(check: Check, id: &str, section: &str, statement: &str) -> ClaimDraft {
        ClaimDraft {
            claim: Claim {
                id: id.to_string(),
                section: section.to_string(),
                statement: statement.to_string(),
                expected: Value::Null,
                computed: Value::Null,
                tolerance: Value::Null,
                verdict: Verdict::Failed,
                check,
                same_as: None,
            },
        }
    }

    /// The claim marked as sharing its numbers and finding with claim `id` (see
    /// [`Claim::same_as`]).
    pub fn same_finding_as(mut self, id: &str) -> Claim {
        self.same_as = Some(id.to_string());
        self
    }
}

/// `|a - b| <= tol`, false when anything is not finite.
pub fn is_close(a: f64, b: f64, tol: f64) -> bool {
    a.is_finite() && b.is_finite() && tol.is_finite() && (a - b).abs() <= tol
}

/// JSON has no NaN: a non-finite number becomes the text `"non-finite: NaN"` so it is
/// visible instead of silently turning into `null`.
pub(super) fn finite_or_text(v: Value) -> Value {
    match v {
        Value::Null => Value::String(super::NON_FINITE.into()),
        other => other,
    }
}
