//! What every chapter of the registry (`chapters::CHAPTERS`) gets without a test file of
//! its own: its quick run with default flags, an answer in it, no failed claim, the 10 %
//! rule of its mutations, and a snapshot of its quick summary named by its id
//! (`snapshots/suite__every_chapter__<id>.snap`). A chapter's own `tests/<id>.rs` holds
//! only what is particular to it. This file names no chapter.

use crate::common::quick_reports;
use locomotion_workbook::chapters::CHAPTERS;
use locomotion_workbook::cli::answer;
use locomotion_workbook::report::{Check, Verdict};

/// `workbook all` and a chapter's run open with its answer: a sentence that a rule of
/// `src/cli/lead.rs` says from its results (a text result `reason` is said as it is).
#[test]
fn every_chapter_has_an_answer() {
    for (c, r) in CHAPTERS.iter().zip(quick_reports()) {
        assert!(
            !answer(r).is_empty(),
            "chapter {} ({}): its quick report gives no answer: add a text result `reason` (the answer in one sentence) or a rule to src/cli/lead.rs that reads its results",
            c.number,
            c.id
        );
    }
}

#[test]
fn every_chapter_runs_quick_with_no_failed_claim() {
    let reports = quick_reports();
    assert_eq!(reports.len(), CHAPTERS.len());
    for (c, r) in CHAPTERS.iter().zip(reports) {
        assert_eq!(r.chapter, c.id);
        assert!(!r.claims.is_empty(), "{}: no claim", c.id);
        for claim in &r.claims {
            assert_ne!(claim.verdict, Verdict::Failed, "{}/{}", c.id, claim.id);
        }
    }
}

/// Issue 21: a 10 % error in any printed number must flip its claim. Every document
/// claim (check not `consistency`) has a mutation whose description says "10 %" (that it
/// flips is `falsification::every_mutation_changes_its_claims_verdict`), or is listed
/// with its reason in its chapter's `Document::WITHOUT_TEN_PERCENT` (`mutations.rs`);
/// every listed id is a document claim of the chapter.
#[test]
fn every_document_claim_has_a_10_percent_mutation_or_a_listed_reason() {
    let mut wrong = Vec::new();
    for (c, r) in CHAPTERS.iter().zip(quick_reports()) {
        let listed = c.without_ten_percent();
        for (id, why) in listed {
            let ok = r
                .claims
                .iter()
                .any(|cl| cl.id == *id && cl.check != Check::Consistency);
            if !ok || why.is_empty() {
                wrong.push(format!(
                    "{}/{id}: listed, but no document claim or no reason",
                    c.id
                ));
            }
        }
        let mutations = c.mutations();
        for claim in r.claims.iter().filter(|cl| cl.check != Check::Consistency) {
            let ten = mutations
                .iter()
                .any(|m| m.claim_id == claim.id && m.description.contains("10 %"));
            if !ten && !listed.iter().any(|(id, _)| *id == claim.id) {
                wrong.push(format!(
                    "{}/{}: no 10 % mutation and not listed",
                    c.id, claim.id
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The quick summary of every chapter, one snapshot per id: each claim's verdict and
/// kind of evidence (discrete: no rounding to choose). The chapters' own snapshots of
/// their numbers, at the rounding each number's accuracy allows, are in their test files.
#[test]
fn every_chapter_quick_summary_snapshot() {
    for (c, r) in CHAPTERS.iter().zip(quick_reports()) {
        let lines: String = r
            .claims
            .iter()
            .map(|cl| {
                format!(
                    "{}: {} ({})\n",
                    cl.id,
                    cl.verdict.as_str(),
                    cl.check.as_str()
                )
            })
            .collect();
        let text = format!("{}\n{lines}", r.summary());
        insta::assert_snapshot!(c.id, text);
    }
}
