//! The layers of ARCHITECTURE.md, checked on the source text:
//!
//! - `numerics` depends on nothing else in the crate; `physics` on `numerics` only;
//!   neither knows of clap, serde, the file system or printing, and `plot` knows no clap;
//! - `scenes` (the scenes and their standard runs, below the chapters) knows no chapter,
//!   no command line (clap, `flags`, `grammar`, `cli`, `lab`), no figure and no file;
//! - no chapter imports another chapter (shared code moves down: `ladder`, `physics`,
//!   `numerics`, `report`, `plot`);
//! - no import cycle anywhere in the crate: inside every folder (`src/` itself, `cli/`,
//!   `numerics/ode/`, each chapter folder, ...) the modules (besides the folder's
//!   `mod.rs`, which orchestrates them) import each other without a cycle, counting an
//!   import through a re-export (`super::Step` that `mod.rs` took from `step`) as an
//!   import of the module that defines it (`architecture/module_graph.rs`);
//! - claims only compare: no chapter file that drafts a claim constructs a model or runs
//!   a simulation, itself or through a helper of its chapter it calls
//!   (`architecture/claims_purity.rs`).
//!
//! The last rule has a ratchet: the cycles that existed when it was written are listed in
//! [`KNOWN_CYCLES`]; a new cycle fails, and so does a listed one that is gone (the list
//! must shrink with the code).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use module_graph::{crate_cycles, crate_modules};

/// Import cycles still to be taken apart (folder as `src/a/b`, the modules in the cycle,
/// sorted). Issues 20 and 30 of the tracker named them; all are gone.
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
    let forbidden: [(&str, &[&str]); 4] = [
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
        (
            "scenes",
            &[
                "crate::chapters",
                "crate::cli",
                "crate::grammar",
                "crate::flags",
                "crate::lab",
                "crate::plot",
                "crate::render",
                "crate::ladder",
                "clap::",
                "clap ",
                "#[arg(",
                "std::fs",
                "println!",
            ],
        ),
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

/// The strongly connected components with more than one file (Tarjan's algorithm,
/// recursive: a folder has a few dozen modules at most).
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
fn no_import_cycle_anywhere_in_the_crate() {
    let found = crate_cycles(&crate_modules());
    let known: Vec<String> = KNOWN_CYCLES
        .iter()
        .map(|(folder, names)| format!("{folder}: {}", names.join(" <-> ")))
        .collect();
    let new: Vec<_> = found.iter().filter(|c| !known.contains(c)).collect();
    let gone: Vec<_> = known.iter().filter(|c| !found.contains(c)).collect();
    assert!(
        new.is_empty(),
        "import cycles (folder: modules that import each other, directly or in a ring):\n{}",
        new.iter()
            .map(|c| c.as_str())
            .collect::<Vec<_>>()
            .join("\n")
    );
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
    // the report; every layer below knows neither, but the scenes write their runs'
    // numbers as JSON (serde_json, no clap: checked in `lower_layers_know_nothing_above_them`)
    const ALLOWED: [&str; 10] = [
        "scenes",
        "cli",
        "grammar",
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
    // No dependents: the lab (chapter 6's simulator in a browser) finds its chapter in
    // the registry by its flag table and runs the scenes (`src/scenes/`), the benchmarks
    // likewise; a dependent would be listed here as (top-level module, chapter module).
    const DEPENDENTS: [(&str, &str); 0] = [];
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

mod claims_purity;
mod module_graph;

#[test]
fn the_module_graph_follows_re_exports_and_nested_use_trees() {
    use module_graph::{expand_use, synthetic};
    // The checker can fail: a ring through a re-export of the folder's mod.rs (the
    // former numerics/ode ring: step -> dop853 -> step) and a two-module cycle between
    // top-level modules are found; a parent using its child is no cycle.
    let ring = synthetic(&[
        ("", "mod numerics; mod cli; mod lab;"),
        ("numerics", "mod ode;"),
        (
            "numerics/ode",
            "mod step;\nmod dop853;\npub use step::Step;",
        ),
        (
            "numerics/ode/step",
            "use super::{dop853::{self, Lazy}, OdeSystem};",
        ),
        ("numerics/ode/dop853", "use super::Step;"),
        ("cli", "fn f() { crate::lab::run(); }"),
        (
            "lab",
            "use crate::{cli::{Cli, Command as C}, numerics::ode};",
        ),
    ]);
    assert_eq!(
        crate_cycles(&ring),
        ["src: cli <-> lab", "src/numerics/ode: dop853 <-> step"]
            .map(String::from)
            .to_vec()
    );
    let chain = synthetic(&[
        ("", "mod a; mod b;"),
        ("a", "mod x; use x::Y; pub fn g() { crate::b::h() }"),
        ("a/x", "pub struct Y; fn f() { super::g() }"),
        ("b", "pub fn h() {}"),
    ]);
    assert!(crate_cycles(&chain).is_empty());
    let names: Vec<String> = expand_use("crate::{cli::{Cli, Command as C}, lab::{self}}")
        .into_iter()
        .map(|(n, p)| format!("{n}={}", p.join("::")))
        .collect();
    assert_eq!(
        names,
        [
            "Cli=crate::cli::Cli",
            "C=crate::cli::Command",
            "lab=crate::lab"
        ]
    );
}

/// The lines of the registry's macro (`src/chapters/mod.rs`) that declare the chapter
/// modules, and every `pub mod` line inside a chapter folder or file.
fn chapter_module_declarations() -> (Vec<String>, Vec<String>) {
    let reg = std::fs::read_to_string(src().join("chapters").join("mod.rs")).expect("registry");
    let decl = reg
        .lines()
        .map(str::trim)
        .filter(|l| l.contains("mod $module"))
        .map(String::from)
        .collect();
    let mut public = Vec::new();
    for ch in chapter_modules() {
        let dir = src().join("chapters").join(&ch);
        let files = if dir.is_dir() {
            rust_files(&dir)
        } else {
            vec![src().join("chapters").join(format!("{ch}.rs"))]
        };
        for f in files {
            for l in code(&f)
                .lines()
                .filter(|l| l.trim().starts_with("pub mod "))
            {
                public.push(format!("{}: {}", f.display(), l.trim()));
            }
        }
    }
    (decl, public)
}

/// The chapter modules (among `modules`) that `code` names as `chapters::<module>`,
/// also inside a `chapters::{...}` group.
fn chapter_paths(code: &str, modules: &[String]) -> Vec<String> {
    let named = names_after(code, "chapters::");
    modules
        .iter()
        .filter(|m| named.contains(*m))
        .cloned()
        .collect()
}

#[test]
fn chapter_modules_are_private_to_the_crate() {
    // The registry declares every chapter `pub(crate)` and a chapter's files are private
    // (or `pub(super)`/`pub(crate)`): the tests of a chapter's internals are its unit
    // tests (`src/chapters/<module>/tests.rs`); the integration tests, the benchmarks,
    // the examples and the exercises reach a chapter through the registry
    // (`chapters::CHAPTERS`, `run_default`, `mutations`) or its command line, and what
    // they compute with lives below the chapters (`scenes`, `physics`, `numerics`).
    let (decl, public) = chapter_module_declarations();
    assert_eq!(
        decl,
        ["$(pub(crate) mod $module;)*"],
        "the registry's module declaration"
    );
    assert!(
        public.is_empty(),
        "public modules inside chapters:\n{}",
        public.join("\n")
    );
    let modules = chapter_modules();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut bad = Vec::new();
    for dir in ["tests", "benches", "examples"] {
        for f in rust_files(&root.join(dir)) {
            if f.starts_with(root.join("tests").join("architecture"))
                || f.ends_with("tests/architecture.rs")
            {
                continue; // this checker: its test data names chapter paths
            }
            for m in chapter_paths(&code(&f), &modules) {
                bad.push(format!("{} names chapters::{m}", f.display()));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "chapter internals named outside the crate:\n{}",
        bad.join("\n")
    );
    // the reader can fail: a path and a group into a chapter are found, the registry's
    // public items are not
    let m = modules.clone();
    let found = chapter_paths(
        "use locomotion_workbook::chapters::{self, Context, effective_mass::x};\nchapters::vertical_shaking::scene::run()",
        &m,
    );
    assert_eq!(found, ["effective_mass", "vertical_shaking"]);
    assert!(chapter_paths(
        "use locomotion_workbook::chapters::{run_default, CHAPTERS};",
        &m
    )
    .is_empty());
}
