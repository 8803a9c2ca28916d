//! Falsification: every claim that is not a consistency check must be movable. For every
//! chapter, the chapter runs in quick mode with the document's statements; then each of
//! the chapter's mutations (a wrong variant of one statement: a flipped sign, a swapped
//! inequality, a coefficient off by 10 %, ...) runs that claim's own check, and its
//! verdict must differ from the claim's verdict under the document. A coverage test
//! fails when some non-consistency claim has no mutation that flips it. The mutations
//! come from each chapter's `Document` (`report::Falsifiable`) through the registry;
//! this file names no chapter. (The quick runs' own checks, the 10 % rule and the
//! snapshots are in `every_chapter.rs`.)

use crate::common::quick_reports as reports;
use locomotion_workbook::chapters::{self, CHAPTERS};
use locomotion_workbook::report::{Check, Verdict};
use std::collections::BTreeMap;
use std::sync::OnceLock;

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
