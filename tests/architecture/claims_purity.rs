//! Claims only compare (issue 30, section 2): a claim is a pure function of the
//! statements and the evidence, and the evidence is computed once (`evidence.rs` and
//! the helpers it calls). The rule, on the source text of every chapter:
//!
//! - a *claims file* is a chapter file that drafts a claim (`Claim::draft`): today every
//!   `claims.rs`, every `*_claims.rs` and chapter 6's `slide_rules.rs`;
//! - its code (comment lines and the `#[cfg(test)]` tail removed) constructs no model
//!   (`Model::new` or a `Model { .. }` literal: `StickModel`, `InertiaModel`, any
//!   `*Model`), runs nothing (no call of a function named `simulate`, `simulate_*` or
//!   `run_*`, the crate's simulation entry points) and names none of the machinery runs
//!   are made of: no ODE integrator (`Integrator`), no hybrid simulation, event location
//!   or time-stepping (`numerics::hybrid`, `numerics::events`,
//!   `numerics::timestepping`), no scene (`crate::scenes`) and no parallel sweep
//!   (`crate::sweep`, `par_map`); the ODE module's data types (`numerics::ode::Method`,
//!   a method's name in a claim) stay allowed;
//! - the same holds one level down, for the body of every function the claims file
//!   names from another module of its chapter (`super::evidence::f`, `evidence::f`),
//!   so that a helper cannot run what the claim may not.
//!
//! Closed forms stay allowed (a formula of `physics`, a fit, arithmetic on the
//! evidence): a claim applies its printed statement to the evidence's raw quantities.

use super::{code, names_after, rust_files, src};
use std::path::Path;

/// Names a claims file, and the functions it calls in its chapter, must not contain.
const FORBIDDEN: [&str; 9] = [
    "Model::new",
    "Model {",
    "Integrator",
    "numerics::hybrid",
    "numerics::events",
    "numerics::timestepping",
    "crate::scenes",
    "crate::sweep",
    "par_map",
];

/// The forbidden names and simulation calls in `code`.
fn violations(code: &str) -> Vec<String> {
    let mut out: Vec<String> = FORBIDDEN
        .iter()
        .filter(|w| code.contains(*w))
        .map(|w| w.to_string())
        .collect();
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let runs = |name: &str| {
        name == "simulate" || name.starts_with("simulate_") || name.starts_with("run_")
    };
    for prefix in ["simulate", "run_"] {
        for (i, _) in code.match_indices(prefix) {
            if code[..i].chars().next_back().is_some_and(ident) {
                continue; // inside a longer identifier
            }
            let name: String = code[i..].chars().take_while(|&c| ident(c)).collect();
            if runs(&name) && code[i + name.len()..].trim_start().starts_with('(') {
                out.push(format!("{name}(...)"));
            }
        }
    }
    out
}

/// The body of `fn name` in `code` (from its first `{` to the matching `}`), if any.
fn fn_body<'a>(code: &'a str, name: &str) -> Option<&'a str> {
    let start = code
        .match_indices(&format!("fn {name}"))
        .find_map(|(i, _)| {
            let after = code[i + 3 + name.len()..].chars().next()?;
            (after == '(' || after == '<').then_some(i)
        })?;
    let open = start + code[start..].find('{')?;
    let mut depth = 0usize;
    for (k, ch) in code[open..].char_indices() {
        match ch {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(&code[open..=open + k]);
                }
            }
            _ => {}
        }
    }
    None
}

/// The violations of the claims file `claims` (code) whose chapter's other modules are
/// `siblings` (module name, code): its own, then those of every sibling function it
/// names.
fn check(claims: &str, siblings: &[(String, String)]) -> Vec<String> {
    let mut out = violations(claims);
    for (module, text) in siblings {
        for f in names_after(claims, &format!("{module}::")) {
            if !f.starts_with(|c: char| c.is_ascii_lowercase()) {
                continue; // a type or a constant
            }
            if let Some(body) = fn_body(text, &f) {
                out.extend(
                    violations(body)
                        .into_iter()
                        .map(|v| format!("{module}::{f}: {v}")),
                );
            }
        }
    }
    out
}

#[test]
fn claims_only_compare() {
    let mut bad = Vec::new();
    let mut files = 0usize;
    for dir in std::fs::read_dir(src().join("chapters"))
        .expect("chapters")
        .flatten()
    {
        let dir = dir.path();
        if !dir.is_dir() {
            continue;
        }
        let modules: Vec<(String, String)> = rust_files(&dir)
            .iter()
            .map(|f| (stem(f), code(f)))
            .collect();
        for (name, text) in modules.iter().filter(|(_, t)| t.contains("Claim::draft")) {
            files += 1;
            let siblings: Vec<_> = modules.iter().filter(|(n, _)| n != name).cloned().collect();
            for v in check(text, &siblings) {
                bad.push(format!("{}/{name}.rs: {v}", dir.display()));
            }
        }
    }
    assert!(files >= 8, "claims files found: {files}");
    assert!(
        bad.is_empty(),
        "claims that construct a model or run something (gather it in the evidence):\n{}",
        bad.join("\n")
    );
}

/// The module name of a file (`claims` for `claims.rs`).
fn stem(f: &Path) -> String {
    f.file_stem()
        .map(|s| s.to_string_lossy().to_string())
        .unwrap_or_default()
}

#[test]
fn the_claims_checker_finds_models_runs_and_helpers() {
    // The checker can fail: a model built in the claim, a run called in it, and a
    // helper of the chapter that integrates are found; a comparison is not.
    let helper = (
        "evidence".to_string(),
        "pub fn error(p: &P) -> f64 { let mut i = Integrator::new(); { 1.0 } }\npub fn ok() -> f64 { 2.0 }".to_string(),
    );
    let bad = "use super::evidence::{error, ok};\nfn c() { let m = StickModel::new(p); let r = run_scene(&p); let s = crate::physics::stick::run::simulate_stick(&m); error(&p) + ok() }";
    assert_eq!(
        check(bad, std::slice::from_ref(&helper)),
        [
            "Model::new",
            "simulate_stick(...)",
            "run_scene(...)",
            "evidence::error: Integrator"
        ]
    );
    let good = "use super::evidence::ok;\nfn c(ev: &E) -> bool { let simulated = |b| b; simulated(ev.a.run_error.max(ok()) <= ev.budget) }";
    assert!(check(good, &[helper]).is_empty());
}
