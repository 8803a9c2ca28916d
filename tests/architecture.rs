//! The layers of ARCHITECTURE.md, checked on the source text:
//!
//! - `numerics` depends on nothing else in the crate; `physics` on `numerics` only;
//!   neither knows of clap, serde, the file system or printing, and `plot` knows no clap;
//! - no chapter imports another chapter (shared code moves down: `ladder`, `physics`,
//!   `numerics`, `report`, `plot`);
//! - inside a chapter folder, the files (besides `mod.rs`, which orchestrates them)
//!   import each other without a cycle.
//!
//! The last rule has a ratchet: the cycles that existed when it was written are listed in
//! [`KNOWN_CYCLES`]; a new cycle fails, and so does a listed one that is gone (the list
//! must shrink with the code).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Cycles inside chapter folders still to be taken apart (chapter, files in the cycle,
/// sorted). Issue 20 of the tracker names them.
const KNOWN_CYCLES: &[(&str, &[&str])] = &[];

/// Every `.rs` file below `dir`.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).expect("read src").flatten() {
        let p = e.path();
        if p.is_dir() {
            out.extend(rust_files(&p));
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
    out.sort();
    out
}

/// The code of a file without its comment lines and its `#[cfg(test)]` tail.
fn code(path: &Path) -> String {
    let text = std::fs::read_to_string(path).expect("read source");
    let text = text.split("#[cfg(test)]").next().unwrap_or("");
    text.lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The names `prefix` is followed by in `code` (`super::claims` gives `claims`), also
/// inside a `prefix{a, b::c}` group.
fn names_after(code: &str, prefix: &str) -> BTreeSet<String> {
    let ident = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect()
    };
    let mut out = BTreeSet::new();
    for (i, _) in code.match_indices(prefix) {
        let rest = &code[i + prefix.len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let body = &group[..group.find('}').unwrap_or(group.len())];
            for item in body.split(',') {
                out.insert(ident(item.trim()));
            }
        } else {
            out.insert(ident(rest));
        }
    }
    out.remove("");
    out
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

#[test]
fn lower_layers_know_nothing_above_them() {
    let forbidden: [(&str, &[&str]); 3] = [
        (
            "numerics",
            &[
                "crate::physics",
                "crate::chapters",
                "crate::plot",
                "crate::report",
                "crate::cli",
                "crate::ladder",
                "clap::",
                "serde",
                "std::fs",
                "println!",
            ],
        ),
        (
            "physics",
            &[
                "crate::chapters",
                "crate::plot",
                "crate::report",
                "crate::cli",
                "crate::ladder",
                "clap::",
                "serde",
                "std::fs",
                "println!",
            ],
        ),
        ("plot", &["crate::chapters", "crate::cli", "clap::"]),
    ];
    let mut bad = Vec::new();
    for (layer, words) in forbidden {
        for f in rust_files(&src().join(layer)) {
            if f.file_name().is_some_and(|n| n == "tests.rs") {
                continue; // unit tests may print
            }
            let c = code(&f);
            for w in words {
                if c.contains(w) {
                    bad.push(format!("{}: {w}", f.display()));
                }
            }
        }
    }
    assert!(bad.is_empty(), "layer violations:\n{}", bad.join("\n"));
}

/// The chapter folders and single-file chapters, by module name.
fn chapter_modules() -> Vec<String> {
    let mut out: Vec<String> = std::fs::read_dir(src().join("chapters"))
        .unwrap()
        .flatten()
        .filter_map(|e| {
            let p = e.path();
            let stem = p.file_stem()?.to_str()?.to_string();
            (stem != "mod").then_some(stem)
        })
        .collect();
    out.sort();
    out
}

#[test]
fn no_chapter_imports_another() {
    let chapters = chapter_modules();
    let mut bad = Vec::new();
    for ch in &chapters {
        let dir = src().join("chapters").join(ch);
        let files = if dir.is_dir() {
            rust_files(&dir)
        } else {
            vec![src().join("chapters").join(format!("{ch}.rs"))]
        };
        for f in files {
            let c = code(&f);
            let is_mod = f.file_name().is_some_and(|n| n == "mod.rs") || !dir.is_dir();
            let mut names = names_after(&c, "crate::chapters::");
            names.extend(names_after(&c, "super::super::"));
            if is_mod {
                names.extend(names_after(&c, "super::"));
            }
            for other in chapters.iter().filter(|o| *o != ch) {
                if names.contains(other) {
                    bad.push(format!("{} imports chapter {other}", f.display()));
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// The import graph of the files of one chapter folder (without `mod.rs`).
fn folder_graph(dir: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let stems: BTreeSet<String> = rust_files(dir)
        .iter()
        .filter(|f| f.parent() == Some(dir))
        .filter_map(|f| f.file_stem()?.to_str().map(String::from))
        .filter(|s| s != "mod")
        .collect();
    stems
        .iter()
        .map(|s| {
            let c = code(&dir.join(format!("{s}.rs")));
            let to = names_after(&c, "super::")
                .into_iter()
                .filter(|n| stems.contains(n) && n != s)
                .collect();
            (s.clone(), to)
        })
        .collect()
}

/// The strongly connected components with more than one file (Tarjan's algorithm,
/// recursive: a chapter folder has a few dozen files at most).
fn cycles(g: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    struct T<'a> {
        g: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'a>(t: &mut T<'a>, v: &'a str) {
        let i = t.index.len();
        t.index.insert(v, i);
        t.low.insert(v, i);
        t.stack.push(v);
        for w in &t.g[v] {
            if !t.index.contains_key(w.as_str()) {
                visit(t, w);
                let lw = t.low[w.as_str()];
                let lv = t.low.get_mut(v).unwrap();
                *lv = (*lv).min(lw);
            } else if t.stack.contains(&w.as_str()) {
                let iw = t.index[w.as_str()];
                let lv = t.low.get_mut(v).unwrap();
                *lv = (*lv).min(iw);
            }
        }
        if t.low[v] == t.index[v] {
            let mut comp = Vec::new();
            while let Some(w) = t.stack.pop() {
                comp.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                comp.sort();
                t.out.push(comp);
            }
        }
    }
    let mut t = T {
        g,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        out: Vec::new(),
    };
    for v in g.keys() {
        if !t.index.contains_key(v.as_str()) {
            visit(&mut t, v);
        }
    }
    t.out
}

#[test]
fn chapter_folders_have_no_new_import_cycle() {
    let mut found: Vec<(String, Vec<String>)> = Vec::new();
    for ch in chapter_modules() {
        let dir = src().join("chapters").join(&ch);
        if dir.is_dir() {
            for c in cycles(&folder_graph(&dir)) {
                found.push((ch.clone(), c));
            }
        }
    }
    let known: Vec<(String, Vec<String>)> = KNOWN_CYCLES
        .iter()
        .map(|(ch, files)| {
            (
                ch.to_string(),
                files.iter().map(|s| s.to_string()).collect(),
            )
        })
        .collect();
    let new: Vec<_> = found.iter().filter(|c| !known.contains(c)).collect();
    let gone: Vec<_> = known.iter().filter(|c| !found.contains(c)).collect();
    assert!(new.is_empty(), "new import cycles: {new:?}");
    assert!(
        gone.is_empty(),
        "cycles taken apart (good): remove them from KNOWN_CYCLES: {gone:?}"
    );
}

#[test]
fn the_cycle_finder_finds_cycles() {
    // The checker itself can fail: a two-file cycle and a three-file ring are found, a
    // chain is not.
    let g = |edges: &[(&str, &str)]| {
        let mut m: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (a, b) in edges {
            m.entry(a.to_string()).or_default().insert(b.to_string());
            m.entry(b.to_string()).or_default();
        }
        m
    };
    assert_eq!(cycles(&g(&[("a", "b"), ("b", "a")])), vec![vec!["a", "b"]]);
    assert_eq!(
        cycles(&g(&[("a", "b"), ("b", "c"), ("c", "a"), ("c", "d")])),
        vec![vec!["a", "b", "c"]]
    );
    assert!(cycles(&g(&[("a", "b"), ("b", "c")])).is_empty());
    assert_eq!(
        names_after("use super::{claims, doc::Doc};\nsuper::x::y", "super::"),
        ["claims", "doc", "x"]
            .iter()
            .map(|s| s.to_string())
            .collect()
    );
}

/// The top-level module of `f` (`cli.rs`, `chapters`, ...), relative to `src/`.
fn top_level(f: &Path) -> String {
    let rel = f.strip_prefix(src()).expect("below src");
    rel.components()
        .next()
        .map(|c| c.as_os_str().to_string_lossy().to_string())
        .unwrap_or_default()
}

#[test]
fn clap_and_serde_stay_in_the_cli_chapter_and_report_layers() {
    // the command line (cli, main, its flag table, render, the lab), the chapters and
    // the report; every layer below knows neither
    const ALLOWED: [&str; 8] = [
        "cli",
        "main.rs",
        "render.rs",
        "flags",
        "lab",
        "chapters",
        "report",
        "lib.rs",
    ];
    let mut bad = Vec::new();
    for f in rust_files(&src()) {
        if ALLOWED.contains(&top_level(&f).as_str()) {
            continue;
        }
        let c = code(&f);
        for w in ["clap::", "clap ", "serde", "#[arg(", "#[command("] {
            if c.contains(w) {
                bad.push(format!("{}: {w}", f.display()));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "clap or serde below the CLI:\n{}",
        bad.join("\n")
    );
}

/// The registry's lines of `src/chapters/mod.rs`: (module, id) of each chapter.
fn registry() -> Vec<(String, String)> {
    let text = std::fs::read_to_string(src().join("chapters").join("mod.rs")).expect("registry");
    text.lines()
        .filter_map(|l| l.trim().strip_prefix("chapter!("))
        .map(|rest| {
            let parts: Vec<&str> = rest.splitn(4, ',').collect();
            let id = parts.get(2).copied().unwrap_or("").trim().trim_matches('"');
            (parts[0].trim().to_string(), id.to_string())
        })
        .collect()
}

/// Whether `code` names module `m` as a path (`m::` or `chapters::m`, not inside a
/// longer identifier).
fn names_module(code: &str, m: &str) -> bool {
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    code.match_indices(m).any(|(i, _)| {
        let before = code[..i].chars().next_back().is_none_or(|c| !ident(c));
        let after = &code[i + m.len()..];
        before && (after.starts_with("::") || code[..i].ends_with("chapters::"))
    })
}

#[test]
fn the_registry_is_the_only_place_outside_a_chapter_that_names_it() {
    // The one dependent by design: the lab is chapter 6's simulator in a browser.
    const DEPENDENTS: [(&str, &str); 1] = [("lab", "stick_state_machine")];
    let reg = registry();
    let modules = chapter_modules();
    assert_eq!(
        reg.len(),
        modules.len(),
        "one registry line per chapter module: {reg:?}"
    );
    let mut bad = Vec::new();
    for f in rust_files(&src()) {
        let rel = f.strip_prefix(src()).unwrap().to_string_lossy().to_string();
        if rel == "chapters/mod.rs" {
            continue; // the registry
        }
        let c = code(&f);
        for (m, id) in &reg {
            let own =
                rel.starts_with(&format!("chapters/{m}/")) || rel == format!("chapters/{m}.rs");
            if own || DEPENDENTS.contains(&(top_level(&f).as_str(), m.as_str())) {
                continue;
            }
            if c.contains(&format!("\"{id}\"")) || names_module(&c, m) {
                bad.push(format!("{rel} names chapter {id}"));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "chapters named outside the registry:\n{}",
        bad.join("\n")
    );
}

#[test]
fn the_registry_reader_sees_the_module_names() {
    assert!(names_module(
        "use crate::chapters::stick_with_inertia;",
        "stick_with_inertia"
    ));
    assert!(names_module(
        "stick_with_inertia::run(a)",
        "stick_with_inertia"
    ));
    assert!(!names_module("rigid::effective_mass(&b)", "effective_mass"));
    assert!(!names_module("my_effective_mass::x", "effective_mass"));
}
