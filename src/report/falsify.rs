//! Falsification, one judge for every chapter: a chapter's document is its statements
//! (data), its evidence (computed once), its claims (pure functions of both) and the
//! wrong variants of its statements ([`DocEdit`]s). [`mutations`] turns the edits into
//! [`Mutation`]s, each judged by the same claim functions on the same quick evidence,
//! which is computed at most once per process.

use super::{Claim, DocEdit, Mutation};
use std::any::{Any, TypeId};
use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

/// A chapter's document as the workbook judges it: the statements, the evidence, the
/// claims as pure functions of both, and the wrong variants of the statements. Each
/// chapter implements it once (its `mutations.rs`: `pub struct Document`), and the
/// registry reads it; nothing else runs a mutation.
pub trait Falsifiable: 'static {
    /// The document's statements as data (`statements.rs`).
    type Statements: Clone + Send + Sync + 'static;
    /// Everything the claims look at, computed once (`evidence.rs`).
    type Evidence: Send + Sync + 'static;
    /// The statements as printed.
    fn printed() -> Self::Statements;
    /// The evidence of the default scene in quick mode (headless, default flags); the
    /// generic code computes it at most once per process.
    fn quick_evidence() -> Self::Evidence;
    /// Every claim of the chapter under `st` on `ev` (the functions `run` uses).
    fn claims(st: &Self::Statements, ev: &Self::Evidence) -> Vec<Claim>;
    /// The wrong variants of the statements: (claim id, what changed, the edit).
    const EDITS: &'static [DocEdit<Self::Statements>];
    /// The document claims that carry no mutation moving a printed number by 10 %:
    /// (claim id, the reason).
    const WITHOUT_TEN_PERCENT: &'static [(&'static str, &'static str)];
}

/// The quick evidence of `F`, computed on first use and kept for the process (one
/// slot per chapter type: a `static` inside a generic function would be one for all).
pub fn quick_evidence<F: Falsifiable>() -> &'static F::Evidence {
    type Slots = Mutex<HashMap<TypeId, &'static (dyn Any + Send + Sync)>>;
    static SLOTS: OnceLock<Slots> = OnceLock::new();
    let slot: &'static (dyn Any + Send + Sync) = *SLOTS
        .get_or_init(Default::default)
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .entry(TypeId::of::<F>())
        .or_insert_with(|| Box::leak(Box::new(OnceLock::<F::Evidence>::new())));
    // the lock is released here: a slow chapter blocks only its own slot
    slot.downcast_ref::<OnceLock<F::Evidence>>()
        .expect("one slot type per chapter type")
        .get_or_init(F::quick_evidence)
}

/// The claim `id` of `F` judged under the statements `st` on the quick evidence.
pub fn judge<F: Falsifiable>(id: &str, st: &F::Statements) -> Claim {
    F::claims(st, quick_evidence::<F>())
        .into_iter()
        .find(|c| c.id == id)
        .unwrap_or_else(|| panic!("an edit names claim {id}, which the chapter does not make"))
}

/// The falsification mutations of `F`: one per edit, each applied to a copy of the
/// printed statements and judged by [`judge`].
pub fn mutations<F: Falsifiable>() -> Vec<Mutation> {
    F::EDITS
        .iter()
        .map(|&(id, what, edit)| {
            Mutation::new(id, what, move || {
                let mut st = F::printed();
                edit(&mut st);
                judge::<F>(id, &st)
            })
        })
        .collect()
}

/// The list of `F`'s claims without a 10 % mutation (for the registry's function table).
pub fn without_ten_percent<F: Falsifiable>() -> &'static [(&'static str, &'static str)] {
    F::WITHOUT_TEN_PERCENT
}
