//! What a chapter needs besides its Rust folder and its registry line, checked for every
//! chapter of the registry (`chapters::CHAPTERS`) on the files, without running it: one
//! line per missing piece, saying what to write or which command makes it. The steps
//! are those of ARCHITECTURE.md, "How to add: a chapter".
//!
//! A chapter needs no test file of its own (`every_chapter.rs` covers its quick run,
//! its claims, the 10 % rule and its snapshot). Also: every `tests/*.rs` file is
//! compiled (a module of `tests/main.rs` or a test target of `Cargo.toml`; with
//! `autotests = false` a file that is neither is silently never built, and its tests
//! never run).

use locomotion_workbook::chapters::{ChapterInfo, CHAPTERS};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn read(path: &Path) -> Option<String> {
    std::fs::read_to_string(root().join(path)).ok()
}

/// The chapter's module name: its id with `_` (`stick-with-inertia` ->
/// `stick_with_inertia`), the name of its folder and of its test file.
fn module(info: &ChapterInfo) -> String {
    info.id.replace('-', "_")
}

/// What `render` generates but is not there yet: the chapter's section of the appendix,
/// its line in the book's table of contents and its row in the README.
fn generated_pieces(info: &ChapterInfo, lesson: &str) -> Vec<String> {
    let mut missing = Vec::new();
    let render = "(run `workbook render`, then write the section's prose)";
    let appendix = read(Path::new("chapters/errata.md")).unwrap_or_default();
    for table in ["summary", "claims"] {
        if !appendix.contains(&format!("<!-- BEGIN generated:{}:{table} -->", info.id)) {
            missing.push(format!(
                "chapters/errata.md: the block {}:{table} of the chapter's section {render}",
                info.id
            ));
        }
    }
    let lists = [
        ("book/SUMMARY.md", format!("]({lesson})")),
        ("README.md", format!("| `workbook {}` |", info.id)),
    ];
    for (file, needle) in lists {
        if !read(Path::new(file)).unwrap_or_default().contains(&needle) {
            missing.push(format!(
                "{file}: the chapter's line (run `workbook render`: the block `chapters` is generated from the registry)"
            ));
        }
    }
    missing
}

/// The lesson's own pieces: the file, its link to its section of the appendix, and the
/// figures it shows.
fn lesson_pieces(info: &ChapterInfo, lesson: &str) -> Vec<String> {
    let Some(text) = read(&info.markdown_path()) else {
        return vec![format!(
            "{lesson}: the lesson (hand-written: the question, the derivations, the figures; `# {}. {}`, with a link to its section of the appendix, errata.md#...)",
            info.number, info.title
        )];
    };
    let mut missing = Vec::new();
    if !text.contains("](errata.md#") {
        missing.push(format!(
            "{lesson}: a link to its section of the appendix (errata.md#...)"
        ));
    }
    for (i, _) in text.match_indices("](../figures/") {
        let path = &text[i + "](../".len()..];
        let path = &path[..path.find(')').unwrap_or(path.len())];
        if !root().join(path).is_file() {
            missing.push(format!(
                "{lesson}: shows {path}, which does not exist (run `workbook {}` and commit its figures)",
                info.id
            ));
        }
    }
    missing
}

/// The Rust piece outside the registry line: its folder. (Test files of its own are
/// optional: `every_chapter.rs` runs every chapter quick, checks its claims and the 10 %
/// rule and snapshots it; a `tests/<id>.rs` that exists, for black-box tests through the
/// command line, must be wired in, which [`every_test_file_is_compiled`] checks for every
/// file of `tests/`; unit tests of its internals, `src/chapters/<id>/tests.rs`, must be
/// declared at the end of its `mod.rs`.)
fn code_pieces(info: &ChapterInfo) -> Vec<String> {
    let m = module(info);
    let mut missing = Vec::new();
    if !root().join(format!("src/chapters/{m}/mod.rs")).is_file() {
        missing.push(format!(
            "src/chapters/{m}/: the chapter's folder, named after its id (ARCHITECTURE.md, the chapter shape)"
        ));
    }
    let test = format!("tests/{m}.rs");
    if read(Path::new(&test)).is_some() && !wired().contains(&m) {
        missing.push(format!(
            "tests/main.rs: the line `mod {m};` ({test} exists but is never compiled)"
        ));
    }
    let folder = format!("src/chapters/{m}");
    let mod_rs = read(Path::new(&format!("{folder}/mod.rs"))).unwrap_or_default();
    let has_unit_tests = root().join(format!("{folder}/tests.rs")).is_file();
    missing.extend(unit_tests_unwired(&folder, &mod_rs, has_unit_tests));
    missing
}

/// A chapter's unit tests (`<folder>/tests.rs`, the tests of its internals) that its
/// `mod.rs` does not declare: never compiled, so never run.
fn unit_tests_unwired(folder: &str, mod_rs: &str, has_unit_tests: bool) -> Option<String> {
    let declared = mod_rs
        .lines()
        .any(|l| l.trim() == "mod tests;" || l.trim() == "#[cfg(test)] mod tests;");
    (has_unit_tests && !declared).then(|| {
        format!(
            "{folder}/mod.rs: the lines `#[cfg(test)]` and `mod tests;` at its end ({folder}/tests.rs exists but is never compiled)"
        )
    })
}

/// The modules of `tests/main.rs` (`mod x;` lines).
fn wired() -> Vec<String> {
    read(Path::new("tests/main.rs"))
        .unwrap_or_default()
        .lines()
        .filter_map(|l| l.trim().strip_prefix("mod ")?.strip_suffix(';'))
        .map(str::to_string)
        .collect()
}

/// Every missing piece of `info`, one line each.
fn missing_pieces(info: &ChapterInfo) -> Vec<String> {
    let lesson = info.markdown_path().display().to_string();
    let mut missing = lesson_pieces(info, &lesson);
    missing.extend(generated_pieces(info, &lesson));
    missing.extend(code_pieces(info));
    missing
}

#[test]
fn every_chapter_of_the_registry_has_all_its_pieces() {
    let missing: Vec<String> = CHAPTERS
        .iter()
        .flat_map(|info| {
            missing_pieces(info)
                .into_iter()
                .map(move |m| format!("chapter {} ({}): {m}", info.number, info.id))
        })
        .collect();
    assert!(
        missing.is_empty(),
        "missing pieces (ARCHITECTURE.md, \"How to add: a chapter\"):\n{}",
        missing.join("\n")
    );
}

/// The files `tests/*.rs` that are neither a module of `tests/main.rs` (among `wired`)
/// nor a test target of `cargo` (the text of Cargo.toml), one line each.
fn unwired_test_files(wired: &[String], cargo: &str) -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir(root().join("tests"))
        .expect("tests/")
        .flatten()
        .filter_map(|e| {
            let p = e.path();
            (p.extension()? == "rs").then(|| p.file_stem()?.to_str().map(String::from))?
        })
        .collect();
    files.sort();
    assert!(files.len() > 10, "{files:?}");
    files
        .iter()
        .filter(|f| f.as_str() != "main")
        .filter(|f| !wired.contains(f) && !cargo.contains(&format!("path = \"tests/{f}.rs\"")))
        .map(|f| format!("tests/{f}.rs: add `mod {f};` to tests/main.rs (or a [[test]] target to Cargo.toml)"))
        .collect()
}

#[test]
fn every_test_file_is_compiled() {
    let cargo = read(Path::new("Cargo.toml")).expect("Cargo.toml");
    let lost = unwired_test_files(&wired(), &cargo);
    assert!(
        lost.is_empty(),
        "test files that are never compiled:\n{}",
        lost.join("\n")
    );
}

#[test]
fn the_checks_name_what_a_new_chapter_lacks() {
    // The check can fail: a chapter 9 with nothing but its registry entry lacks its
    // lesson, its generated lines and blocks and its folder (a test file is optional).
    let nine = ChapterInfo {
        id: "a-new-chapter",
        number: 9,
        ..CHAPTERS[0]
    };
    let missing = missing_pieces(&nine);
    for piece in [
        "chapters/09-a-new-chapter.md: the lesson",
        "chapters/errata.md: the block a-new-chapter:summary",
        "chapters/errata.md: the block a-new-chapter:claims",
        "book/SUMMARY.md",
        "README.md",
        "src/chapters/a_new_chapter/",
    ] {
        assert!(
            missing.iter().any(|m| m.starts_with(piece)),
            "{piece} not named in {missing:#?}"
        );
    }
    assert_eq!(missing.len(), 6, "{missing:#?}");
    assert!(missing_pieces(&CHAPTERS[0]).is_empty());
}

#[test]
fn a_test_file_that_is_not_wired_in_is_named() {
    // A chapter whose test file exists but has no `mod` line in tests/main.rs: a
    // registered chapter's module with its line taken out of the wired list.
    let m = CHAPTERS
        .iter()
        .map(module)
        .find(|m| root().join(format!("tests/{m}.rs")).is_file())
        .expect("a chapter with a test file of its own");
    assert!(wired().contains(&m));
    let unwired = unwired_test_files(&["main".to_string()], "");
    assert!(
        unwired
            .iter()
            .any(|l| l.starts_with(&format!("tests/{m}.rs: add `mod {m};`"))),
        "{unwired:#?}"
    );
}

#[test]
fn unit_tests_that_are_not_declared_are_named() {
    let folder = "src/chapters/a_new_chapter";
    let line = unit_tests_unwired(folder, "mod claims;\nmod evidence;\n", true).expect("named");
    assert!(
        line.starts_with("src/chapters/a_new_chapter/mod.rs: the lines"),
        "{line}"
    );
    assert!(unit_tests_unwired(folder, "mod claims;\n#[cfg(test)]\nmod tests;\n", true).is_none());
    assert!(unit_tests_unwired(folder, "mod claims;\n", false).is_none());
}
