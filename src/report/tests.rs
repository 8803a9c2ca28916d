//! Unit tests of the report module.
use super::*;

#[test]
fn verdict_follows_the_check() {
    let c = |id| Claim::draft(Check::ClosedForm, id, "2", "x is one");
    let ok = c("a").close(1.0, 1.0 + 1e-13, 1e-12);
    assert_eq!(ok.verdict, Verdict::Confirmed);
    let bad = c("b").close(1.0, 1.1, 1e-12);
    assert_eq!(bad.verdict, Verdict::Failed);
    let nan = c("c").close(1.0, f64::NAN, 1e-12);
    assert_eq!(nan.verdict, Verdict::Failed);
    assert_eq!(nan.computed, Value::String("non-finite".into()));
    let e = c("d")
        .values(1.0, 2.0, 0.1)
        .printed_or_corrected(false, true);
    assert_eq!(e.verdict, Verdict::Erratum);
}

#[test]
fn json_has_exactly_the_contract_keys() {
    let mut r = ChapterReport::new("x", "T", "1");
    r.param("mu", 0.4);
    r.result("ratio", 0.6);
    r.claim(Claim::draft(Check::ClosedForm, "k", "1", "s").exact(true, true));
    r.table("t", "|a|".into());
    let j = r.to_json();
    let keys: Vec<&String> = j.as_object().unwrap().keys().collect();
    assert_eq!(
        keys,
        ["chapter", "title", "section", "params", "claims", "results", "figures"]
    );
    let ck: Vec<&String> = j["claims"][0].as_object().unwrap().keys().collect();
    assert_eq!(
        ck,
        [
            "id",
            "section",
            "statement",
            "expected",
            "computed",
            "tolerance",
            "verdict",
            "check"
        ]
    );
}

#[test]
fn nan_results_fail_loudly() {
    let mut r = ChapterReport::new("x", "T", "1");
    r.result("speed_mps", f64::NAN);
    assert!(r.has_failures());
    assert_eq!(r.results["speed_mps"], Value::String("non-finite".into()));
    assert!(!r.to_json().to_string().contains("NaN"));
}

#[test]
fn numbers_format_stably() {
    assert_eq!(fmt_num(0.6), "0.6");
    assert_eq!(fmt_num(45.0), "45");
    assert_eq!(fmt_num(0.599999999999), "0.6");
    assert_eq!(fmt_num(1.23456e-7), "1.235e-7");
    assert_eq!(fmt_num(-0.00001), "-1.000e-5");
    assert_eq!(fmt_num(1234.5678), "1235");
    assert_eq!(fmt_num(1.23456), "1.235");
}

#[test]
fn consistency_checks_are_counted_apart_from_confirmations() {
    let mut r = ChapterReport::new("x", "T", "1");
    r.claim(Claim::draft(Check::ClosedForm, "a", "1", "s").exact(1, 1));
    r.claim(Claim::draft(Check::Consistency, "b", "1", "s").exact(1, 1));
    r.claim(
        Claim::draft(Check::Simulation, "c", "1", "s")
            .values(1.0, 1.0, 0.1)
            .printed_or_corrected(false, true),
    );
    assert_eq!(r.confirmed(), 1);
    assert_eq!(r.consistency_checks(), 1);
    assert_eq!(
        r.summary(),
        "3 claims: 1 confirmed (+1 consistency checks), 1 erratum, 0 approximation, 0 failed; by check: closed_form 1, simulation 1, consistency 1"
    );
    let table = summary_table(std::slice::from_ref(&r));
    let all = table.lines().find(|l| l.starts_with("all ")).unwrap();
    let cols: Vec<&str> = all.split_whitespace().collect();
    assert_eq!(cols, ["all", "3", "1", "1", "1", "0", "0"]);
    let f = findings_markdown(std::slice::from_ref(&r));
    assert!(f.starts_with("`workbook all` checks 3 claims: 1 confirmed (+1 consistency checks"));
    assert!(f.contains("`x` / `c` (section 1, simulation)"));
}

#[test]
fn a_draft_keeps_its_kind_of_evidence_and_makes_errata_one_way() {
    let d = || Claim::draft(Check::SecondMethod, "x", "4", "x = 1").values(1.0, 1.1, 0.01);
    let c = d().printed_or_corrected(false, true);
    assert_eq!(
        (c.verdict, c.check),
        (Verdict::Erratum, Check::SecondMethod)
    );
    assert_eq!(
        d().printed_or_corrected(true, true).verdict,
        Verdict::Confirmed
    );
    assert_eq!(
        d().printed_or_corrected(false, false).verdict,
        Verdict::Failed
    );
    assert_eq!(d().approximation_if(true).verdict, Verdict::Approximation);
    assert_eq!(d().confirmed_if(false).verdict, Verdict::Failed);
    let nan = Claim::draft(Check::ClosedForm, "y", "2", "y = 0").close(0.0, f64::NAN, 1.0);
    assert_eq!(nan.verdict, Verdict::Failed);
    assert_eq!(nan.computed, serde_json::Value::String("non-finite".into()));
    let e = Claim::draft(Check::Simulation, "z", "5", "mode").exact("flight", "flight");
    assert_eq!(
        (e.verdict, e.tolerance.as_str()),
        (Verdict::Confirmed, Some("exact"))
    );
    assert_eq!(
        Claim::draft(Check::Simulation, "w", "5", "w")
            .same_finding_as("z")
            .confirmed_if(true)
            .same_as
            .as_deref(),
        Some("z")
    );
}
