//! The command-line contract of DESIGN.md, checked in-process for every chapter:
//! `list`, `all --quick --json`, `render --check`, exit codes, and one clear stderr line
//! for bad global input. Chapter-specific flags are tested in each chapter's own file.

use common::{assert_bad_input, run};
use locomotion_workbook::chapters::CHAPTERS;
use serde_json::Value;

mod common;

const CONTRACT_KEYS: [&str; 7] = [
    "chapter", "title", "section", "params", "claims", "results", "figures",
];
const CLAIM_KEYS: [&str; 8] = [
    "id",
    "section",
    "statement",
    "expected",
    "computed",
    "tolerance",
    "verdict",
    "check",
];

fn assert_contract(report: &Value) {
    let keys: Vec<&str> = report
        .as_object()
        .expect("object")
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(keys, CONTRACT_KEYS, "report keys");
    for c in report["claims"].as_array().expect("claims array") {
        let ck: Vec<&str> = c.as_object().unwrap().keys().map(String::as_str).collect();
        assert_eq!(ck, CLAIM_KEYS, "claim keys");
        let v = c["verdict"].as_str().unwrap();
        assert!(
            ["confirmed", "erratum", "approximation", "failed"].contains(&v),
            "{v}"
        );
        let k = c["check"].as_str().unwrap();
        assert!(
            locomotion_workbook::report::Check::ALL
                .iter()
                .any(|x| x.as_str() == k),
            "{k}"
        );
    }
    assert!(
        report["params"].is_object()
            && report["results"].is_object()
            && report["figures"].is_array()
    );
}

#[test]
fn list_names_every_chapter_once() {
    let (code, out, err) = run(&["list"]);
    assert_eq!(code, 0);
    assert!(err.is_empty());
    assert_eq!(out.lines().count(), CHAPTERS.len());
    for c in CHAPTERS.iter() {
        assert_eq!(
            out.lines()
                .filter(|l| l.starts_with(&format!("{} ", c.id)))
                .count(),
            1,
            "{}",
            c.id
        );
    }
    let (code, out, _) = run(&["list", "--json"]);
    assert_eq!(code, 0);
    let v: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v.as_array().unwrap().len(), 7);
}

#[test]
fn all_quick_json_is_one_array_of_contract_objects_and_no_claim_fails() {
    let (code, out, err) = run(&["all", "--quick", "--json", "--no-figures"]);
    assert!(err.is_empty(), "stderr: {err}");
    let v: Value = serde_json::from_str(out.trim()).expect("stdout is exactly one JSON value");
    let arr = v.as_array().expect("array");
    assert_eq!(arr.len(), CHAPTERS.len());
    for (r, c) in arr.iter().zip(CHAPTERS.iter()) {
        assert_contract(r);
        assert_eq!(r["chapter"], c.id);
        let failed: Vec<&Value> = r["claims"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["verdict"] == "failed")
            .collect();
        assert!(failed.is_empty(), "{}: failed claims {failed:?}", c.id);
    }
    assert!(
        !out.contains("NaN") && !out.contains("null"),
        "no NaN or null in output"
    );
    assert_eq!(code, 0);
}

#[test]
fn each_chapter_prints_one_json_object_in_quick_mode() {
    for c in CHAPTERS.iter() {
        let (code, out, err) = run(&[c.id, "--quick", "--json", "--no-figures"]);
        assert_eq!(code, 0, "{}: {err}", c.id);
        let v: Value = serde_json::from_str(out.trim()).expect("one JSON object");
        assert_contract(&v);
        assert_eq!(v["chapter"], c.id);
    }
}

#[test]
fn human_output_has_a_table_and_a_summary() {
    let (code, out, _) = run(&["effective-mass", "--quick", "--no-figures"]);
    assert_eq!(code, 0);
    assert!(out.starts_with("== effective-mass"));
    assert!(out.lines().last().unwrap().starts_with("summary: "));
}

#[test]
fn unknown_chapter_is_bad_input() {
    let (code, out, err) = run(&["no-such-chapter"]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(err.contains("no-such-chapter"), "{err}");
}

#[test]
fn bad_gravity_is_rejected_with_one_line_naming_the_flag() {
    for bad in ["NaN", "-9.81", "0", "inf", "abc"] {
        assert_bad_input(
            &["effective-mass", "--g-mps2", bad, "--no-figures"],
            "--g-mps2",
        );
    }
}

#[test]
fn help_teaches_and_exits_zero() {
    let (code, out, _) = run(&["--help"]);
    assert_eq!(code, 0);
    for c in CHAPTERS.iter() {
        assert!(out.contains(c.id), "{} in help", c.id);
    }
    assert!(out.contains("--g-mps2") && out.contains("Exit codes"));
    for c in CHAPTERS.iter() {
        let (code, out, _) = run(&[c.id, "--help"]);
        assert_eq!(code, 0, "{}", c.id);
        assert!(
            out.contains("--quick") && out.contains("--json"),
            "{}",
            c.id
        );
    }
}

#[test]
fn course_text_tables_are_up_to_date() {
    // `workbook render --check` regenerates every table from the chapters (full mode, no
    // figures) and compares: a stale table in chapters/*.md fails here.
    let (code, out, err) = run(&["render", "--check"]);
    assert_eq!(code, 0, "stale course text:\n{out}{err}");
}
