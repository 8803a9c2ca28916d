//! One notation (issue 12): the text a reader sees in generated output writes the
//! notation page's symbols (`chapters/00-notation.md`: Γ, Γₓ, Γₙ, μ, θ₀, ω, δ_z, π...),
//! not their ASCII spellings (`Gamma_x`, `mu`, `theta_0`).
//!
//! Checked on both forms of the generated output:
//! - `workbook all --quick --json --no-figures`: every string value (claim statements,
//!   expected, computed and tolerance texts, result texts such as the failures table);
//!   JSON keys and claim ids stay ASCII by the contract and are not values looked at;
//! - the generated blocks of `chapters/*.md` and the README (the verdict tables, the
//!   chapters' tables, the findings), which `render --check` (tests/cli.rs) keeps equal
//!   to what the chapters print in full mode. Backticked spans (result keys, claim ids
//!   in the findings) and bold claim ids are skipped there.

use serde_json::Value;

use crate::common;

/// ASCII spellings of the notation page's symbols, as whole words.
const ASCII_SYMBOLS: [&str; 13] = [
    "Gamma", "mu", "mu_eff", "theta", "theta0", "omega", "delta", "delta_x", "delta_z", "pi",
    "eps", "sigma", "J_l",
];

/// The ASCII symbols in `text`: whole words (letters, digits, `_`, inner `-`) equal to
/// one of [`ASCII_SYMBOLS`] or starting with `Gamma_` or `theta_` (`Gamma_x`,
/// `theta_0`). A hyphenated word (a claim id such as `bias-law-mu-eff`) is one word; a
/// minus sign in front (`-mu`) is not part of it; a flag (`--mu`) is skipped.
fn ascii_symbols(text: &str) -> Vec<String> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '-'))
        .filter(|w| !w.starts_with("--")) // a flag (`--mu`) names the flag, not the symbol
        .map(|w| w.trim_matches('-'))
        .filter(|w| ASCII_SYMBOLS.contains(w) || w.starts_with("Gamma_") || w.starts_with("theta_"))
        .map(str::to_string)
        .collect()
}

/// `text` without its backticked spans and `**bold**` spans (keys and claim ids).
fn without_code_and_ids(text: &str) -> String {
    let mut out = String::new();
    for (i, part) in text.split('`').enumerate() {
        if i % 2 == 0 {
            for (j, p) in part.split("**").enumerate() {
                if j % 2 == 0 {
                    out.push_str(p);
                }
            }
        }
    }
    out
}

/// Every string value under `v` with its path, keys excluded.
fn string_values(v: &Value, path: &str, out: &mut Vec<(String, String)>) {
    match v {
        Value::String(s) => out.push((path.to_string(), s.clone())),
        Value::Array(a) => a
            .iter()
            .enumerate()
            .for_each(|(i, x)| string_values(x, &format!("{path}[{i}]"), out)),
        Value::Object(o) => {
            for (k, x) in o {
                // the claim id and the chapter id are identifiers, ASCII by contract
                if k != "id" && k != "chapter" {
                    string_values(x, &format!("{path}.{k}"), out);
                }
            }
        }
        _ => {}
    }
}

/// The bodies of the `<!-- BEGIN generated:NAME -->` blocks of `text`, with their names.
fn generated_blocks(text: &str) -> Vec<(String, String)> {
    let names = locomotion_workbook::render::block_names(text);
    let mut bodies = Vec::new();
    let mut rest = text;
    for name in names {
        let begin = format!("<!-- BEGIN generated:{name} -->");
        let Some(i) = rest.find(&begin) else { break };
        let after = &rest[i + begin.len()..];
        let end = after.find("<!-- END -->").unwrap_or(after.len());
        bodies.push((name, after[..end].to_string()));
        rest = &after[end..];
    }
    bodies
}

#[test]
fn the_scan_finds_ascii_symbols_and_passes_unicode_ones() {
    // The check itself, on planted text: it must catch each ASCII form and let the
    // notation page's forms, identifiers and words that merely contain them pass.
    for bad in [
        "at Gamma_x = 100",
        "F = 0.05 mu m g",
        "theta_0 = 0.3 rad",
        "Gamma = 2.5",
        "(k/gamma)(theta - θ₀)",
        "sin(pi b/2)",
        "L(-mu cos + sin)",
    ] {
        assert!(!ascii_symbols(bad).is_empty(), "missed: {bad}");
    }
    for good in [
        "at Γₓ = 100, F = 0.05 μ m g, θ₀ = 0.3 rad, sin(πb/2)",
        "claim bias-law-mu-eff, key theta0_rad, delta_mechanical, pivot, multiple, mutation",
        "--gamma 2.5 and --mu 0.4",
    ] {
        assert!(ascii_symbols(good).is_empty(), "false alarm: {good}");
    }
    assert!(ascii_symbols(&without_code_and_ids("**arctan-mu**: `mu_eff` and μ")).is_empty());
}

#[test]
fn generated_json_writes_the_notation_pages_symbols() {
    let (code, out, err) = common::run(&["all", "--quick", "--json", "--no-figures"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(out.trim()).expect("one JSON array");
    let mut strings = Vec::new();
    string_values(&v, "", &mut strings);
    assert!(strings.len() > 500, "{} strings", strings.len());
    let bad: Vec<String> = strings
        .iter()
        .filter_map(|(path, s)| {
            let found = ascii_symbols(s);
            (!found.is_empty()).then(|| format!("{path}: {found:?} in {s}"))
        })
        .collect();
    assert!(bad.is_empty(), "ASCII symbols:\n{}", bad.join("\n"));
}

#[test]
fn generated_course_tables_write_the_notation_pages_symbols() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<_> = std::fs::read_dir(root.join("chapters"))
        .expect("chapters/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    files.sort();
    files.push(root.join("README.md"));
    let (mut blocks, mut bad) = (0, Vec::new());
    for f in &files {
        let text = std::fs::read_to_string(f).expect("readable");
        for (name, body) in generated_blocks(&text) {
            blocks += 1;
            for line in body.lines() {
                let found = ascii_symbols(&without_code_and_ids(line));
                if !found.is_empty() {
                    bad.push(format!("{} {name}: {found:?} in {line}", f.display()));
                }
            }
        }
    }
    assert!(blocks >= 25, "{blocks} generated blocks");
    assert!(bad.is_empty(), "ASCII symbols:\n{}", bad.join("\n"));
}

/// The front and back pages cover chapter 8 and chapter 6's limit cycle (issue 31): the
/// notation page defines the symbols those chapters use, the glossary their words, the
/// bibliography their sources, and the closing chapter's argument reaches them.
#[test]
fn front_and_back_pages_cover_the_limit_cycle_and_the_stick_with_inertia() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("chapters");
    let read = |f: &str| std::fs::read_to_string(root.join(f)).expect(f);
    let notation = read("00-notation.md");
    for symbol in [
        "$m_r$",
        "$M = m + m_r$",
        "$l_G",
        "$I_G$, $I_C$",
        "$\\alpha = Ml_G^2/I_G$",
        "$W = ",
        "$D_\\sigma",
        "$\\mu_P(\\theta)",
        "$\\varepsilon = I_Pk/\\gamma^2$",
        "$M = DP^n(s^*)$",
        "$\\lambda_i$",
    ] {
        assert!(notation.contains(symbol), "notation page lacks {symbol}");
    }
    let glossary = read("glossary.md");
    for term in [
        "**Poincaré section**",
        "**Floquet multiplier**",
        "**monodromy matrix**",
        "**saltation matrix**",
        "**Painlevé inconsistent**",
        "**Painlevé indeterminate**",
        "**impact without collision**",
        "**Delassus matrix**",
        "**Darboux-Keller**",
        "| $\\alpha$ |",
    ] {
        assert!(glossary.contains(term), "glossary lacks {term}");
    }
    let bibliography = read("bibliography.md");
    for source in [
        "Stronge", "Glocker", "Génot", "Darboux", "Keller", "Illinois", "139-160",
    ] {
        assert!(bibliography.contains(source), "bibliography lacks {source}");
    }
    assert!(
        !bibliography.contains("open question"),
        "stale pointer to open questions"
    );
    let closing = read("closing.md");
    assert!(
        closing.contains("nine steps") && closing.contains("\n9. **"),
        "closing argument"
    );
    for settled in ["08-stick-with-inertia.md", "#5-the-gait-as-a-limit-cycle"] {
        assert!(
            closing.contains(settled),
            "closing chapter does not reach {settled}"
        );
    }
    assert!(
        !closing.contains("Real sticks have mass along their length")
            && !closing.contains("**The gait as a limit cycle.**"),
        "the closing chapter still lists settled questions as open"
    );
    let preface = read("preface.md");
    for link in ["08-stick-with-inertia.md", "#5-the-gait-as-a-limit-cycle"] {
        assert!(preface.contains(link), "preface does not reach {link}");
    }
}
