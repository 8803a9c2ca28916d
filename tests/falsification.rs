//! Falsification: every claim that is not a consistency check must be movable. For every
//! chapter, the chapter runs in quick mode with the document's statements; then each of
//! the chapter's mutations (a wrong variant of one statement: a flipped sign, a swapped
//! inequality, a coefficient off by 10 %, ...) runs that claim's own check, and its
//! verdict must differ from the claim's verdict under the document. A coverage test
//! fails when some non-consistency claim has no mutation that flips it.

use locomotion_workbook::chapters::{self, Context, CHAPTERS};
use locomotion_workbook::report::{ChapterReport, Check, Verdict};
use std::collections::BTreeMap;
use std::sync::OnceLock;

/// Every chapter's quick report with the document's statements, run once.
fn reports() -> &'static Vec<ChapterReport> {
    static R: OnceLock<Vec<ChapterReport>> = OnceLock::new();
    R.get_or_init(|| {
        CHAPTERS
            .iter()
            .map(|c| chapters::run_default(c.id, &Context::headless(true)).expect("runs"))
            .collect()
    })
}

/// Per (chapter, claim id), the verdicts of every mutation: `(description, verdict)`.
type Mutated = BTreeMap<(String, String), Vec<(String, Verdict)>>;

/// Every mutation of every chapter, run once.
fn mutated() -> &'static Mutated {
    static M: OnceLock<Mutated> = OnceLock::new();
    M.get_or_init(|| {
        let mut out = Mutated::new();
        for c in CHAPTERS.iter() {
            for m in chapters::mutations(c.id) {
                let claim = (m.run)();
                assert_eq!(claim.id, m.claim_id, "{}: mutation ran another claim", c.id);
                out.entry((c.id.to_string(), m.claim_id.to_string()))
                    .or_default()
                    .push((m.description.to_string(), claim.verdict));
            }
        }
        out
    })
}

#[test]
fn every_mutation_changes_its_claims_verdict() {
    let mut wrong = Vec::new();
    for ((chapter, id), runs) in mutated() {
        let r = reports()
            .iter()
            .find(|r| &r.chapter == chapter)
            .expect("chapter");
        let claim = r
            .claims
            .iter()
            .find(|c| &c.id == id)
            .unwrap_or_else(|| panic!("{chapter}: mutation of unknown claim {id}"));
        assert_ne!(
            claim.check,
            Check::Consistency,
            "{chapter}/{id}: a mutated claim must state its kind of evidence"
        );
        for (what, verdict) in runs {
            if *verdict == claim.verdict {
                wrong.push(format!(
                    "{chapter}/{id}: '{what}' left the verdict at {}",
                    verdict.as_str()
                ));
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "mutations that did not move their claim:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn every_non_consistency_claim_has_a_flipping_mutation() {
    let mut missing = Vec::new();
    for r in reports() {
        for c in r.claims.iter().filter(|c| c.check != Check::Consistency) {
            let flips = mutated()
                .get(&(r.chapter.clone(), c.id.clone()))
                .is_some_and(|runs| runs.iter().any(|(_, v)| *v != c.verdict));
            if !flips {
                missing.push(format!("{}/{} ({})", r.chapter, c.id, c.check.as_str()));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "claims that no mutation moves (give them one, or call them consistency):\n{}",
        missing.join("\n")
    );
}

#[test]
fn the_quick_reports_have_no_failed_claim() {
    for r in reports() {
        for c in &r.claims {
            assert_ne!(c.verdict, Verdict::Failed, "{}/{}", r.chapter, c.id);
        }
    }
}

/// Each chapter's claims that carry no 10 % mutation, with the reason (the statement
/// prints no number a 10 % error could move, or the derived tolerance is coarser): the
/// lists live beside the mutations, in each chapter's `mutations.rs`
/// (`Falsifiable::WITHOUT_TEN_PERCENT`), read through the registry.
fn without_ten_percent(chapter: &str) -> &'static [(&'static str, &'static str)] {
    chapters::info(chapter)
        .expect("registered")
        .without_ten_percent()
}

/// Issue 21: a 10 % error in any printed number must flip its claim. Every document
/// claim (check not `consistency`) has a mutation whose description says "10 %" (and
/// flips it: `every_mutation_changes_its_claims_verdict`), or is listed with its reason
/// in its chapter's `mutations.rs`; every listed id is a document claim of the chapter.
#[test]
fn every_document_claim_has_a_10_percent_mutation_or_a_listed_reason() {
    let mut wrong = Vec::new();
    for r in reports() {
        let listed = without_ten_percent(&r.chapter);
        for (id, why) in listed {
            let ok = r
                .claims
                .iter()
                .any(|c| c.id == *id && c.check != Check::Consistency);
            if !ok || why.is_empty() {
                wrong.push(format!(
                    "{}/{id}: listed, but no document claim or no reason",
                    r.chapter
                ));
            }
        }
        for c in r.claims.iter().filter(|c| c.check != Check::Consistency) {
            let ten = mutated()
                .get(&(r.chapter.clone(), c.id.clone()))
                .is_some_and(|runs| runs.iter().any(|(what, _)| what.contains("10 %")));
            let is_listed = listed.iter().any(|(id, _)| *id == c.id);
            if !ten && !is_listed {
                wrong.push(format!(
                    "{}/{}: no 10 % mutation and not listed",
                    r.chapter, c.id
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
